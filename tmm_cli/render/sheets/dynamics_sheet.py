"""Sheet 2 «Силовой расчёт рычажного механизма и расчёт маховика» of a mechanism file (issue 25).

Fields: the groups of one position (the last first, the crank last) at a ГОСТ 2.302 scale with the
forces on them (arrows not to scale, as the book draws them), under each its force polygon at μ_F;
Zhukovsky's lever (the velocity plan of that position turned through 90°, at μ_v) with the forces;
the diagrams M_r and M_d, A_r and A_d, ΔT (with Mertsalov's ΔT_I) at their scales; the energy–mass
diagram (Wittenbauer) with its tangents and the segment kl; J_r(φ); the main results. Everything is
read from :class:`~tmm_cli.linkage.sheet2.Sheet2` (the drawing only scales and places its numbers).
"""

from __future__ import annotations

import math

import numpy as np

from ...i18n import tr
from ...i18n.numbers import num
from ...linkage.polygons import force_polygons
from ...linkage.scales import drafting_scale
from ...linkage.sheet2 import Sheet2
from .cam_sheet import table
from .linkage_sheet import _label, _sub
from .paper import Sheet, fit_scale

BOX_GROUPS = (22.0, 395.0, 420.0, 587.0)
BOX_POLYGONS = (22.0, 232.0, 420.0, 393.0)
BOX_DIAGRAMS = (22.0, 7.0, 420.0, 230.0)
BOX_LEVER = (422.0, 300.0, 834.0, 587.0)
BOX_WITT = (422.0, 62.0, 640.0, 298.0)
BOX_INERTIA = (642.0, 62.0, 834.0, 298.0)
BOX_TABLE = (422.0, 7.0, 649.0, 60.0)
H = 3.5
H_SMALL = 2.5
MM = 1000.0
ARROW_MM = 32.0  # the longest force arrow on a group's or the lever's drawing


def symbol(sym: str, lang: str) -> str:
    """A force's symbol in the sheet's markup: 'Φ2' → 'Φ_{2}', 'Rτ12' → 'R^{τ}_{12}', 'Fc' → 'F_{пс}'."""
    tick = ""
    if sym[-1] in "′″":
        tick, sym = ("'" if sym[-1] == "′" else "''"), sym[:-1]
    if sym in ("Fc", "Mc"):
        return (tr(lang, "F_{c}") if sym == "Fc" else tr(lang, "M_{c}")) + tick
    if sym.startswith("MΦ"):
        return f"M_{{Φ{sym[2:]}}}" + tick
    if sym.startswith(("Rτ", "Rn")):
        return f"R^{{{sym[1]}}}_{{{sym[2:]}}}" + tick
    return f"{sym[0]}_{{{sym[1:]}}}" + tick if len(sym) > 1 else sym + tick


def _arrow(sh: Sheet, a, b, layer="Основные", label: str | None = None, h: float = H_SMALL):
    a, b = np.asarray(a, float), np.asarray(b, float)
    d = b - a
    n = float(np.hypot(*d))
    if n < 0.3:
        return
    sh.line(a, b, layer)
    sh.arrow(b, d, layer, min(3.5, 0.4 * n), 1.0)
    if label:
        u = d / n
        side = np.array([-u[1], u[0]])
        q = b + 1.5 * u + 1.5 * side
        sh.text(q[0], q[1], label, h, align="left" if u[0] >= -0.3 else "right", valign="middle")


# ----------------------------------------------------------------------------------------------
# the groups and their polygons


def _group_links(s: Sheet2, group: int):
    return [ln for ln in s.sheet1.mechanism.links if ln.group == group]


def _group_points(s: Sheet2, group: int, i: int) -> dict[str, complex]:
    """Every point of the group's links at position i [real mm], and where its forces act."""
    m, k = s.sheet1.mechanism, s.sheet1.cycle.kin
    names = set()
    for ln in _group_links(s, group):
        names |= set(ln.axis or ()) | set(ln.pins) | {p.name for p in m.points if p.link == ln.name}
    pts = {n: complex(k.z[n][i]) * MM for n in names}
    return pts


def _forces_on(s: Sheet2, group: int, i: int, lang: str):
    """(point [real mm], force [N], label) of every force on the group's links."""
    numbers = {ln.number for ln in _group_links(s, group)}
    out = []
    for f in s.loading.forces:
        if f.number in numbers and abs(complex(f.f[i])) > 0:
            out.append((complex(f.z[i]) * MM, complex(f.f[i]), symbol(f.symbol, lang)))
    for r in s.forces.reactions:
        a, b = r.pair.links
        if a in numbers and b not in numbers:
            out.append((complex(r.at[i]) * MM, -complex(r.force[i]), f"R_{{{b}{a}}}"))
        elif b in numbers and a not in numbers:
            out.append((complex(r.at[i]) * MM, complex(r.force[i]), f"R_{{{r.label[1:]}}}"))
    return out


def _draw_group(sh: Sheet, f, s: Sheet2, group: int, i: int, lang: str) -> None:
    m, k = s.sheet1.mechanism, s.sheet1.cycle.kin
    z = {n: complex(x[i]) * MM for n, x in k.z.items()}
    unit = 1.0 / f.scale  # one paper millimetre in real millimetres
    for ln in _group_links(s, group):
        if ln.kind in ("crank", "bar"):
            a, b = ln.axis
            ends = [z[a], z[b]] + [z[p.name] for p in m.points if p.link == ln.name]
            d = (z[b] - z[a]) / abs(z[b] - z[a])
            t = [((e - z[a]) * d.conjugate()).real for e in ends]
            p0, p1 = z[a] + min(t) * d, z[a] + max(t) * d
            f.poly([[p0.real, p0.imag], [p1.real, p1.imag]], "Основные")
        elif ln.kind == "slotted":
            a, c = ln.axis
            far = [z[p.name] for p in m.points if p.link == ln.name] + [z[a]]
            reach = max(abs(e - z[c]) for e in far) + 4.0 * unit
            d = (z[a] - z[c]) / abs(z[a] - z[c])
            tip = z[c] + reach * d
            f.poly([[z[c].real, z[c].imag], [tip.real, tip.imag]], "Основные")
        else:
            angle = float(k.angle[ln.name][i]) if ln.kind == "block" else m.groups[ln.group - 1].guide.angle
            w, hh = (6.0, 3.5) if ln.kind == "block" else (9.0, 5.0)
            e = complex(math.cos(angle), math.sin(angle))
            corners = [z[ln.name] + unit * (sx * w / 2 + 1j * sy * hh / 2) * e for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
            f.poly([[q.real, q.imag] for q in corners], "Основные", closed=True)
    pts = _group_points(s, group, i)
    for n, q in pts.items():
        p = f.p(q.real, q.imag)
        sh.circle(p, 1.0, "Основные")
        sh.text(p[0] - 2.0, p[1] + 2.0, _sub(n), H_SMALL, align="right", valign="bottom")
    items = _forces_on(s, group, i, lang)
    biggest = max((abs(v) for _, v, _ in items), default=1.0) or 1.0
    for q, v, label in items:
        a = np.array(f.p(q.real, q.imag))
        d = v / biggest * ARROW_MM
        _arrow(sh, a, a + np.array([d.real, d.imag]), "Тонкие", label)


def _group_fields(sh: Sheet, s: Sheet2, lang: str) -> None:
    i = s.force_position
    groups = [pg.group for pg in s.polygons]
    n = len(groups)
    x0, y0, x1, y1 = BOX_GROUPS
    w = (x1 - x0) / n
    extents = []
    for g in groups:
        pts = np.array(list(_group_points(s, g, i).values()))
        extents.append((float(np.ptp(pts.real)), float(np.ptp(pts.imag))))
    ext = (max(e[0] for e in extents) + 1.0, max(e[1] for e in extents) + 1.0)
    label, factor = fit_scale(ext, (w - 2 * ARROW_MM - 8.0, y1 - y0 - 2 * ARROW_MM - 22.0))
    mu = num(1.0 / (factor * MM), lang, sig=3)
    for j, g in enumerate(groups):
        box = (x0 + j * w + (1.0 if j else 0.0), y0, x0 + (j + 1) * w - 1.0, y1)
        pts = np.array(list(_group_points(s, g, i).values()))
        mid = complex((pts.real.min() + pts.real.max()) / 2, (pts.imag.min() + pts.imag.max()) / 2)
        centre = np.array([(box[0] + box[2]) / 2, (box[1] + box[3]) / 2 - 8.0])
        origin = centre - factor * np.array([mid.real, mid.imag])
        kind = "" if g == 0 else s.sheet1.mechanism.groups[g - 1].kind
        heading = tr(lang, "The crank") if g == 0 else tr(lang, "Group {g} ({kind})").format(g=g, kind=kind)
        f = sh.add_field(f"group_{g}", box, heading, origin=tuple(origin), scale=factor, scale_label=label,
                         scale_text=tr(lang, "M") + f" {label}; μ_{{l}} = {mu} " + tr(lang, "m/mm"))
        _draw_group(sh, f, s, g, i, lang)
        if g == 0:  # the balancing moment the crank's field is about
            mb = tr(lang, "M_{b}") + f" = {num(float(s.balancing[i]), lang, decimals=2)} " + tr(lang, "N·m")
            sh.text(box[0] + 2.0, box[1] + 3.0, mb, H_SMALL)


def _polygon_fields(sh: Sheet, s: Sheet2, lang: str) -> None:
    i = s.force_position
    n = len(s.polygons)
    x0, y0, x1, y1 = BOX_POLYGONS
    w = (x1 - x0) / n
    room = min(100.0, w - 24.0, y1 - y0 - 36.0)
    polygons = s.polygons if room >= 100.0 else force_polygons(s.sheet1.mechanism, s.forces, i, room)
    for j, pg in enumerate(polygons):
        box = (x0 + j * w + (1.0 if j else 0.0), y0, x0 + (j + 1) * w - 1.0, y1)
        tips = np.cumsum([0j] + [v.value / pg.scale for v in pg.vectors])
        mid = complex((tips.real.min() + tips.real.max()) / 2, (tips.imag.min() + tips.imag.max()) / 2)
        centre = np.array([(box[0] + box[2]) / 2, (box[1] + box[3]) / 2 - 8.0])
        origin = centre - np.array([mid.real, mid.imag])
        heading = tr(lang, "Force polygon of the crank") if pg.group == 0 else tr(
            lang, "Force polygon of group {group}").format(group=pg.group)
        sh.add_field(f"polygon_{pg.group}", box, heading,
                         origin=tuple(origin), scale=1.0 / pg.scale,
                         scale_text=f"μ_{{F}} = {num(pg.scale, lang, sig=3)} " + tr(lang, "N/mm"))
        span = max(float(np.ptp(tips.real)), float(np.ptp(tips.imag)), 1.0)
        for v, a, b in zip(pg.vectors, tips[:-1], tips[1:]):
            pa, pb = np.array([origin[0] + a.real, origin[1] + a.imag]), np.array([origin[0] + b.real, origin[1] + b.imag])
            layer = "Тонкие" if v.kind == "unknown" else "Основные"
            _arrow(sh, pa, pb, layer)
            if abs(b - a) > 0.08 * span:
                mid_v = (pa + pb) / 2
                d = (pb - pa) / np.hypot(*(pb - pa))
                q = mid_v + 2.5 * np.array([-d[1], d[0]])
                sh.text(q[0], q[1], symbol(v.symbol, lang), H_SMALL, align="center", valign="middle")
        short = [v for v, a, b in zip(pg.vectors, tips[:-1], tips[1:]) if abs(b - a) <= 0.08 * span]
        if short:
            text = tr(lang, "short: ") + "; ".join(
                f"{symbol(v.symbol, lang)} = {num(abs(v.value), lang, decimals=1)}" for v in short)
            sh.text(box[0] + 2.0, box[1] + 2.5, text, H_SMALL, width=box[2] - box[0] - 4.0, max_lines=2, valign="bottom")


# ----------------------------------------------------------------------------------------------
# Zhukovsky's lever


def _lever_field(sh: Sheet, s: Sheet2, lang: str) -> None:
    i = s.force_position
    plan = s.sheet1.plans[0].velocity
    mu = drafting_scale(max(abs(z) for z in plan.points.values()), 200.0)  # the lever drawn larger than the plan
    turned = {n: 1j * z / mu for n, z in plan.points.items()}  # [paper mm] from the pole
    zs = np.array(list(turned.values()))
    x0, y0, x1, y1 = BOX_LEVER
    mid = complex((zs.real.min() + zs.real.max()) / 2, (zs.imag.min() + zs.imag.max()) / 2)
    centre = np.array([(x0 + x1) / 2 - 40.0, (y0 + y1) / 2 - 8.0])
    origin = centre - np.array([mid.real, mid.imag])
    label = _label(s.sheet1.cycle.positions[i].label)
    sh.add_field("lever", BOX_LEVER, tr(lang, "Zhukovsky's lever, position {label}").format(label=label),
                     origin=tuple(origin), scale=1.0 / mu,
                     scale_text=f"μ_{{v}} = {num(mu, lang, sig=3)} " + tr(lang, "(m/s)/mm") +
                     tr(lang, "; the plan turned 90° counter-clockwise"))

    def at(z):
        return np.array([origin[0] + z.real, origin[1] + z.imag])

    for v in plan.vectors:
        a, b = at(turned[v.start]), at(turned[v.end])
        if np.hypot(*(b - a)) > 0.3:
            sh.line(a, b, "Тонкие")
    placed = []
    for n, z in turned.items():
        q = at(z)
        if any(np.hypot(*(q - r)) < 2.5 for r in placed):
            continue
        placed.append(q)
        sh.text(q[0] - 1.5, q[1] - 1.5, "p" if n == plan.pole else _sub(n), H_SMALL, align="right", valign="top")
    lv = s.lever
    items = [(complex(x.lever[i]) / mu, complex(x.force[i]), symbol(x.symbol, lang)) for x in lv.forces]
    a_pt = 1j * complex(s.sheet1.cycle.kin.v[s.sheet1.mechanism.crank.joint][i]) / mu
    items.append((a_pt, complex(lv.balancing_force[i]), tr(lang, "F_{b}")))
    biggest = max((abs(v) for _, v, _ in items), default=1.0) or 1.0
    for z, v, lab in items:
        if abs(v) <= 1e-9 * biggest:
            continue
        a = at(z)
        d = v / biggest * ARROW_MM
        _arrow(sh, a, a + np.array([d.real, d.imag]), "Основные" if lab.startswith("F_{") else "Тонкие", lab)
    nm = tr(lang, "N·m")
    lines = [tr(lang, "Σ M_{p}(F) = ") + f"{num(float(lv.moment_sum[i]), lang, decimals=2)} " +
             tr(lang, "W"),
             tr(lang, "M_{b} = ΣM_{p}/ω_{1} = ") +
             f"{num(float(lv.balancing[i]), lang, decimals=3)} {nm}",
             tr(lang, "force analysis: ") + f"{num(float(s.balancing[i]), lang, decimals=3)} {nm}",
             f"Δ = {num(float(s.difference_pct()[i]), lang, decimals=4)} %"]
    y = y1 - 30.0
    for text in lines:
        sh.text(x1 - 95.0, y, text, H_SMALL, width=92.0)
        y -= 6.0


# ----------------------------------------------------------------------------------------------
# the diagrams


def _axes(sh: Sheet, x0: float, y0: float, length: float, up: float, down: float, name: str) -> None:
    sh.line((x0, y0), (x0 + length + 4, y0), "Основные")
    sh.arrow((x0 + length + 6, y0), (1, 0), "Основные", 3.5, 1.2)
    sh.line((x0, y0 - down - 2), (x0, y0 + up + 4), "Основные")
    sh.arrow((x0, y0 + up + 6), (0, 1), "Основные", 3.5, 1.2)
    sh.text(x0 - 1.5, y0 + up + 6, name, H, align="right", valign="top")
    sh.text(x0 + length + 3, y0 - 1.5, "φ", H, valign="top")


def _diagrams_field(sh: Sheet, s: Sheet2, lang: str) -> None:
    d, fw, sc = s.dynamics, s.flywheel, s.scales
    c = s.sheet1.cycle
    sh.add_field("dynamics_diagrams", BOX_DIAGRAMS, tr(lang, "Diagrams of the reduced moments, works and energy"))
    x0 = BOX_DIAGRAMS[0] + 24.0
    length = sc.axis_mm
    xs = x0 + d.travel / sc.phi
    keep = slice(None, None, 2)
    y = BOX_DIAGRAMS[3] - 14.0
    series = [("M", sc.M, tr(lang, "N·m/mm"), [(d.M_r, tr(lang, "M_{r}"), None),
                                                          (np.full(d.travel.shape, d.M_d), tr(lang, "M_{d}"), None)]),
              ("A", sc.A, tr(lang, "J/mm"), [(d.A_r, tr(lang, "A_{r}"), None),
                                                       (d.A_d, tr(lang, "A_{d}"), None)]),
              ("ΔT", sc.T, tr(lang, "J/mm"), [(d.dT, "ΔT", None)] + (
                  [(fw.mertsalov.dT_I - fw.mertsalov.dT_I[0], "ΔT_{I}", "DASHED")] if fw is not None else []))]
    evens = [p for p in c.positions if p.label.isdigit()]
    for name, mu, unit, curves in series:
        ys = [np.asarray(v) / mu for v, _, _ in curves]
        up = max(max(float(v.max()) for v in ys), 0.0)
        down = max(max(float(-v.min()) for v in ys), 0.0)
        y0 = y - up - 6.0
        _axes(sh, x0, y0, length, up, down, name)
        for v, label in zip(ys, curves):
            sh.poly(np.column_stack([xs[keep], (y0 + v)[keep]]), "Основные", label[2])
            j = int(np.argmax(np.abs(v)))
            above = v[j] >= 0
            sh.text(xs[j] + 1.5, y0 + float(v[j]) + (1.5 if above else -1.5), label[1], H_SMALL,
                    valign="bottom" if above else "top")
        for p in evens:
            xx = x0 + p.travel / sc.phi
            sh.line((xx, y0 - 1.0), (xx, y0 + 1.0), "Тонкие")
            if name == "ΔT":
                sh.text(xx, y0 - down - 3.0, _label(p.label), H_SMALL, align="center", valign="top")
        sh.text(x0 + length + 14.0, y0 + up * 0.5 + 3.0, f"μ_{{{name}}} = {num(mu, lang, sig=3)} {unit}", H_SMALL,
                width=BOX_DIAGRAMS[2] - (x0 + length + 14) - 2, max_lines=2)
        y = y0 - down - 9.0
    mu_phi = num(math.degrees(sc.phi), lang, sig=3)
    sh.text(x0, max(y, BOX_DIAGRAMS[1] + 3.0), f"μ_{{φ}} = {mu_phi} °/" + tr(lang, "mm") +
            tr(lang, "; positions from position 0; moments and works in the crank's sense of rotation"), H_SMALL,
            width=BOX_DIAGRAMS[2] - x0 - 2.0, max_lines=2)


def _wittenbauer_field(sh: Sheet, s: Sheet2, lang: str) -> None:
    d, fw = s.dynamics, s.flywheel
    wi = fw.wittenbauer
    x0, y0, x1, y1 = BOX_WITT
    mu_j = drafting_scale(float(d.J_r.max()), x1 - x0 - 40.0)
    lo, hi = min(float(d.dT.min()), wi.c_min), max(float(d.dT.max()), wi.c_max)
    mu_t = drafting_scale(hi - lo, y1 - y0 - 50.0)
    kg, j = tr(lang, "kg·m²/mm"), tr(lang, "J/mm")
    sh.add_field("wittenbauer", BOX_WITT, tr(lang, "Energy–mass diagram (Wittenbauer)"),
                 scale_text=f"μ_{{J}} = {num(mu_j, lang, sig=3)} {kg}; μ_{{T}} = {num(mu_t, lang, sig=3)} {j}")
    ox = x0 + 14.0
    oy = y0 + 22.0 + (-lo) / mu_t

    def p(jj, tt):
        return (ox + jj / mu_j, oy + tt / mu_t)

    sh.line((ox, oy + lo / mu_t - 2), (ox, oy + hi / mu_t + 6), "Основные")
    sh.arrow((ox, oy + hi / mu_t + 8), (0, 1), "Основные", 3.5, 1.2)
    sh.text(ox + 2, oy + hi / mu_t + 8, "ΔT", H, valign="top")
    right = ox + float(d.J_r.max()) / mu_j * 1.1 + 4
    sh.line((ox, oy), (right, oy), "Основные")
    sh.arrow((right + 2, oy), (1, 0), "Основные", 3.5, 1.2)
    sh.text(right, oy - 2.0, tr(lang, "J_{r}"), H, align="right", valign="top")
    sh.poly(np.array([p(a, b) for a, b in zip(d.J_r[::2], d.dT[::2])]), "Основные")
    jmax = float(d.J_r.max()) * 1.1
    for slope, cc, name in ((wi.slope_max, wi.c_max, "ψ_{max}"), (wi.slope_min, wi.c_min, "ψ_{min}")):
        sh.line(p(0.0, cc), p(jmax, cc + slope * jmax), "Тонкие")
        q = p(jmax, cc + slope * jmax)
        sh.text(q[0] + 1.0, q[1], name, H_SMALL, valign="middle")
    k_, l_ = p(0.0, wi.c_max), p(0.0, wi.c_min)
    sh.line(k_, l_, "Основные")
    sh.text(k_[0] - 1.5, k_[1], "k", H, align="right", valign="middle")
    sh.text(l_[0] - 1.5, l_[1], "l", H, align="right", valign="middle")
    kgm = tr(lang, "kg·m²")
    sh.text(x0 + 3.0, y0 + 10.0, f"tg ψ_{{max}} = {num(wi.slope_max, lang, sig=5)}; tg ψ_{{min}} = "
            f"{num(wi.slope_min, lang, sig=5)}", H_SMALL, width=x1 - x0 - 6.0)
    sh.text(x0 + 3.0, y0 + 4.0, tr(lang, "J_{fl} = kl·μ_{T}/(tg ψ_{max} − tg ψ_{min}) = ") +
            f"{num(max(wi.J_fl, 0.0), lang, sig=4)} {kgm}", H_SMALL, width=x1 - x0 - 6.0)


def _inertia_field(sh: Sheet, s: Sheet2, lang: str) -> None:
    d = s.dynamics
    x0, y0, x1, y1 = BOX_INERTIA
    length = x1 - x0 - 40.0
    mu_phi = 2.0 * math.pi / length
    mu_j = drafting_scale(float(d.J_r.max()), 80.0)
    sh.add_field("inertia", BOX_INERTIA, tr(lang, "Reduced moment of inertia"),
                 scale_text=f"μ_{{J}} = {num(mu_j, lang, sig=3)} " + tr(lang, "kg·m²/mm") +
                 f"; μ_{{φ}} = {num(math.degrees(mu_phi), lang, sig=3)} °/" + tr(lang, "mm"))
    ox, oy = x0 + 18.0, y0 + 40.0
    up = float(d.J_r.max()) / mu_j
    _axes(sh, ox, oy, length, up, 0.0, tr(lang, "J_{r}"))
    xs = ox + d.travel / mu_phi
    sh.poly(np.column_stack([xs[::2], (oy + d.J_r / mu_j)[::2]]), "Основные")
    sh.line((ox, oy + d.J_first / mu_j), (ox + length, oy + d.J_first / mu_j), "Тонкие", "DASHED")
    for p in s.sheet1.cycle.positions:
        if p.label.isdigit():
            xx = ox + p.travel / mu_phi
            sh.line((xx, oy - 1.0), (xx, oy + 1.0), "Тонкие")
            sh.text(xx, oy - 3.0, _label(p.label), H_SMALL, align="center", valign="top")
    sh.text(x0 + 3.0, y0 + 10.0, tr(lang, "dashed: the crank and the rotor, ") +
            f"{num(d.J_first, lang, sig=4)} " + tr(lang, "kg·m²"), H_SMALL, width=x1 - x0 - 6.0)


def _results(sh: Sheet, s: Sheet2, lang: str) -> None:
    d, fw = s.dynamics, s.flywheel
    nm, kg = tr(lang, "N·m"), tr(lang, "kg·m²")
    i = s.force_position
    rows = [(tr(lang, "Driving moment M_{d}"), f"{num(d.M_d, lang, decimals=2)} {nm}"),
            (tr(lang, "M_{{b}}, position {label}; Zhukovsky").format(label=_label(s.sheet1.cycle.positions[i].label)),
             f"{num(float(s.balancing[i]), lang, decimals=2)}; {num(float(s.lever.balancing[i]), lang, decimals=2)} {nm}")]
    if fw is not None:
        rows += [(tr(lang, "δ; ω_{max}, ω_{min}, rad/s"),
                  f"{num(fw.delta, lang, sig=3)}; {num(fw.omega_max, lang, sig=4)}, {num(fw.omega_min, lang, sig=4)}"),
                 (tr(lang, "Flywheel J_{fl} (Mertsalov)"), f"{num(fw.J, lang, sig=4)} {kg}"),
                 (tr(lang, "J_{fl} (Wittenbauer)"),
                  f"{num(max(fw.wittenbauer.J_fl, 0.0), lang, sig=4)} {kg}")]
        if fw.size is not None:
            dims = f"D = {num(fw.size.D * MM, lang, decimals=0)}, b = {num(fw.size.b * MM, lang, decimals=0)}"
            if fw.size.h is not None:
                dims += f", h = {num(fw.size.h * MM, lang, decimals=0)}"
            rows.append((tr(lang, "Flywheel, mm; mass"),
                         f"{dims}; {num(fw.size.m, lang, decimals=1)} " + tr(lang, "kg")))
    table(sh, BOX_TABLE, tr(lang, "Main results"), rows, col1=0.5, h=H_SMALL)


def sheet2(s: Sheet2, lang: str, title) -> Sheet:
    """Build sheet 2 of a mechanism (no file written)."""
    sh = Sheet(lang)
    sh.frame()
    _group_fields(sh, s, lang)
    _polygon_fields(sh, s, lang)
    _lever_field(sh, s, lang)
    _diagrams_field(sh, s, lang)
    if s.flywheel is not None:
        _wittenbauer_field(sh, s, lang)
    _inertia_field(sh, s, lang)
    _results(sh, s, lang)
    scale = next((f.scale_label for f in sh.fields if f.name.startswith("group_")), "")
    sh.title_block(title, name=tr(lang, "Force analysis of the lever mechanism and the flywheel"),
                   designation=title.designation_for(2, 0), scale=scale)
    return sh
