"""Sheet 1 «Кинематический анализ рычажного механизма» of a mechanism file (issue 24).

Fields: the scheme of the mechanism in all positions at a ГОСТ 2.302 scale (μ_l of the core) with
the traced paths of the named points, the kinematic diagrams s, v, a of the output link at their
scales, the velocity and the acceleration plans of two positions at μ_v, μ_a, and a table of the
main results. Everything is read from :class:`~tmm_cli.linkage.sheet1.Sheet1`: nothing is computed
a second time (the drawing only scales and places the core's arrays).
"""

from __future__ import annotations

import math

import numpy as np

from ...i18n import tr
from ...i18n.numbers import num
from ...linkage.sheet1 import Sheet1
from ...linkage.vector_plans import Plan
from .cam_sheet import table
from .paper import Sheet, gost_label

# field boxes (x0, y0, x1, y1) on the A1 sheet [mm]; the frame is 20…836 × 5…589, the title block
# 651…836 × 5…60
BOX_SCHEME = (22.0, 232.0, 372.0, 587.0)
BOX_DIAGRAMS = (22.0, 7.0, 372.0, 230.0)
BOX_PLANS = (((374.0, 300.0, 604.0, 587.0), (606.0, 300.0, 834.0, 587.0)),
             ((374.0, 62.0, 604.0, 298.0), (606.0, 62.0, 834.0, 298.0)))
BOX_TABLE = (374.0, 7.0, 649.0, 60.0)
H = 3.5
H_SMALL = 2.5
MM = 1000.0  # real millimetres per metre


def _sub(name: str) -> str:
    """A joint or plan label with its digits as a subscript: 'O41' → 'O_{41}', 'a3' → 'a_{3}'."""
    head = name.rstrip("0123456789")
    tail = name[len(head):]
    return f"{head}_{{{tail}}}" if head and tail else name


def _label(label: str) -> str:
    """A position's label with an apostrophe for the prime ('7′' → "7'"): the drawing fonts have no ′."""
    return label.replace("′", "'")


def _deg(x: float) -> float:
    return math.degrees(x) % 360.0


# ----------------------------------------------------------------------------------------------
# field 1: the scheme in all positions


def _scheme_field(sh: Sheet, s: Sheet1, lang: str):
    m, c = s.mechanism, s.cycle
    curve = c.curve.kin
    zs = np.concatenate([curve.z[n] for n in m.joint_names]) * MM
    lo, hi = complex(zs.real.min(), zs.imag.min()), complex(zs.real.max(), zs.imag.max())
    factor = 1.0 / (s.scheme_scale * MM)  # paper mm per real mm
    try:
        label = gost_label(factor)
    except ValueError:
        label = ""
    x0, y0, x1, y1 = BOX_SCHEME
    mid_box = np.array([(x0 + x1) / 2, (y0 + y1) / 2 - 6.0])
    mid = (lo + hi) / 2
    origin = mid_box - factor * np.array([mid.real, mid.imag])
    mu = num(s.scheme_scale, lang, sig=3)
    scale_text = (tr(lang, "M") + f" {label}; " if label else "") + f"μ_{{l}} = {mu} " + tr(lang, "m/mm")
    f = sh.add_field("scheme", BOX_SCHEME, tr(lang, "Scheme of the mechanism in its positions"),
                     origin=tuple(origin), scale=factor, scale_label=label, scale_text=scale_text)
    unit = 1.0 / factor  # one paper millimetre in real millimetres

    def xy(z):
        z = np.asarray(z) * MM
        return np.column_stack([np.real(z), np.imag(z)]) if np.ndim(z) else np.array([[z.real, z.imag]])

    # the guides (axis lines across the field)
    for g in m.groups:
        if g.guide is None:
            continue
        p, e = g.guide.through * MM, g.guide.unit
        span = max(hi.real - lo.real, hi.imag - lo.imag) * 0.6 + 20 * unit
        centre = p + ((mid - p) * e.conjugate()).real * e
        f.poly(np.array([[(centre - span * e).real, (centre - span * e).imag],
                         [(centre + span * e).real, (centre + span * e).imag]]), "Осевые")
    # the paths: of the joints thin, of the named points (centres of mass) dashed
    hang = {j for g in m.groups for j in g.known}
    for n in m.joint_names:
        if n in m.frame:
            continue
        mass = n not in hang and not any(n in g.new for g in m.groups) and n != m.crank.joint
        f.poly(xy(curve.z[n]), "Тонкие", "DASHED" if mass else None)
    ends = [p.index for p in c.positions if p.extreme == "end"]
    for p in c.positions:
        if p.index == 0:
            continue
        _links(f, s, p.index, "Тонкие", "DASHED" if p.index in ends else None, unit, 0.7)
    _links(f, s, 0, "Основные", None, unit, 1.0)
    # fixed pivots, the position numbers at the crank pin, the joints' names in position 0
    for name in m.frame:
        if any(name in ln.pins for ln in m.links):
            q = f.p(*(xy(m.frame[name])[0]))
            sh.line((q[0], q[1] - 1.5), (q[0] - 2.5, q[1] - 5.0), "Основные")
            sh.line((q[0], q[1] - 1.5), (q[0] + 2.5, q[1] - 5.0), "Основные")
            sh.line((q[0] - 4.5, q[1] - 5.0), (q[0] + 4.5, q[1] - 5.0), "Основные")
            for k in range(5):
                xx = q[0] - 4.5 + 2.2 * k
                sh.line((xx, q[1] - 5.0), (xx - 1.5, q[1] - 6.8), "Тонкие")
    o = f.p(*(xy(m.frame[m.crank.pivot])[0]))
    for p in c.positions:
        a = f.p(*(xy(c.kin.z[m.crank.joint][p.index])[0]))
        d = np.array(a) - np.array(o)
        d = d / (np.hypot(*d) or 1.0)
        sh.text(a[0] + 4.5 * d[0], a[1] + 4.5 * d[1], _label(p.label), H_SMALL, align="center", valign="middle")
    pts = {n: np.array(f.p(*(xy(c.kin.z[n][0])[0]))) for n in m.joint_names}
    centre = np.mean(list(pts.values()), axis=0)
    for n, q in pts.items():
        d = q - centre
        d = d / (np.hypot(*d) or 1.0)
        sh.text(q[0] + 5.0 * d[0], q[1] + 5.0 * d[1], _sub(n), H, align="center", valign="middle")
    # the sense of rotation
    r = 0.45 * m.crank.length * MM * factor
    a0, a1 = (200.0, 250.0) if m.crank.sense > 0 else (250.0, 200.0)
    sh.arc(o, r, min(a0, a1), max(a0, a1), "Тонкие")
    tip = np.array(o) + r * np.array([math.cos(math.radians(a1)), math.sin(math.radians(a1))])
    tangent = np.array([-math.sin(math.radians(a1)), math.cos(math.radians(a1))]) * m.crank.sense
    sh.arrow(tip, tangent, "Тонкие", 3.0, 1.0)
    q = np.array(o) + 1.5 * r * np.array([math.cos(math.radians(225)), math.sin(math.radians(225))])
    sh.text(q[0], q[1], "ω_{1}", H, align="center", valign="middle")
    return f


def _links(f, s: Sheet1, i: int, layer: str, linetype, unit: float, size: float) -> None:
    """The mechanism at position i: bars as lines, the slotted link to its farthest reach,
    blocks and sliders as rectangles, pins as small circles [field units: real mm]."""
    m, k = s.mechanism, s.cycle.kin
    z = {n: complex(x[i]) * MM for n, x in k.z.items()}
    hang = {j for g in m.groups for j in g.known}
    on_link = {}
    for p in m.points:
        on_link.setdefault(p.link, []).append(p.name)
    for ln in m.links:
        if ln.kind in ("crank", "bar"):
            a, b = ln.axis
            ends = [z[a], z[b]] + [z[p] for p in on_link.get(ln.name, []) if p in hang]
            d = (z[b] - z[a]) / abs(z[b] - z[a])
            t = [((e - z[a]) * d.conjugate()).real for e in ends]
            p0, p1 = z[a] + min(t) * d, z[a] + max(t) * d
            f.poly([[p0.real, p0.imag], [p1.real, p1.imag]], layer, linetype)
            for e in ends:
                if abs(((e - z[a]) * d.conjugate()).imag) > 1e-6:
                    f.poly([[z[a].real, z[a].imag], [e.real, e.imag], [z[b].real, z[b].imag]], layer, linetype)
        elif ln.kind == "slotted":
            a, cpin = ln.axis
            block = m.links[ln.number - 2].name
            reach = max(float(np.max(s.cycle.curve.kin.slide[block][0])) * MM,
                        *(abs(z[p] - z[cpin]) for p in on_link.get(ln.name, []) if p in hang))
            d = (z[a] - z[cpin]) / abs(z[a] - z[cpin])
            tip = z[cpin] + (reach + 4.0 * unit) * d
            f.poly([[z[cpin].real, z[cpin].imag], [tip.real, tip.imag]], layer, linetype)
        elif ln.kind in ("block", "slider"):
            angle = float(k.angle[ln.name][i]) if ln.kind == "block" else m.groups[ln.group - 1].guide.angle
            w, h = (6.0, 3.5) if ln.kind == "block" else (9.0, 5.0)
            e = complex(math.cos(angle), math.sin(angle))
            corners = [z[ln.name] + unit * size * (sx * w / 2 + 1j * sy * h / 2) * e
                       for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
            f.poly([[q.real, q.imag] for q in corners], layer, linetype, closed=True)
    for n in m.joint_names:
        if n in m.frame or n == m.crank.joint or any(n in g.new for g in m.groups) or n in hang:
            f.circle((z[n].real, z[n].imag), 1.2 * size * unit, layer)


# ----------------------------------------------------------------------------------------------
# field 2: the kinematic diagrams of the output link


def _diagrams_field(sh: Sheet, s: Sheet1, lang: str):
    m, c, sc = s.mechanism, s.cycle, s.scales
    cv = c.curve
    slider = m.output.kind == "slider"
    f = sh.add_field("diagrams", BOX_DIAGRAMS, tr(lang, "Kinematic diagrams of the output link {link}").format(link=m.output.link))
    x0 = BOX_DIAGRAMS[0] + 22.0
    length = sc.axis_mm
    top = f.inner[3]
    names = ("S", "V", "a") if slider else ("ψ", "ω", "ε")
    units = (tr(lang, "m/mm"), tr(lang, "(m/s)/mm"), tr(lang, "(m/s²)/mm")) if slider \
        else (tr(lang, "rad/mm"), tr(lang, "(rad/s)/mm"), tr(lang, "(rad/s²)/mm"))
    series = ((cv.s, sc.s), (cv.v, sc.v), (cv.a, sc.a))
    y = top
    evens = [p for p in c.positions if p.label.isdigit()]
    for name, unit, (vals, mu) in zip(names, units, series):
        ys = np.asarray(vals) / mu
        up, down = max(float(ys.max()), 0.0), max(float(-ys.min()), 0.0)
        y0 = y - up - 8.0
        sh.line((x0, y0), (x0 + length + 4, y0), "Основные")
        sh.arrow((x0 + length + 6, y0), (1, 0), "Основные", 3.5, 1.2)
        sh.line((x0, y0 - down - 2), (x0, y0 + up + 4), "Основные")
        sh.arrow((x0, y0 + up + 6), (0, 1), "Основные", 3.5, 1.2)
        sh.text(x0 - 1.5, y0 + up + 6, name, H, align="right", valign="top")
        sh.text(x0 + length + 3, y0 - 1.5, "φ", H, valign="top")
        xs = x0 + np.asarray(cv.travel) / sc.phi
        keep = slice(None, None, 2)
        sh.poly(np.column_stack([xs[keep], (y0 + ys)[keep]]), "Основные")
        for p in evens:
            xx = x0 + p.travel / sc.phi
            sh.line((xx, y0 - 1.0), (xx, y0 + 1.0), "Тонкие")
            if name == names[-1]:
                sh.text(xx, y0 - down - 3.0, _label(p.label), H_SMALL, align="center", valign="top")
        for p in c.positions:
            if p.extreme == "end":
                xx = x0 + p.travel / sc.phi
                sh.line((xx, y0 - down), (xx, y0 + up), "Тонкие", "DASHED")
        sh.text(x0 + length + 10, y0 + up * 0.5 + 3.0, f"μ_{{{name}}} = {num(mu, lang, sig=3)} {unit}", H_SMALL,
                width=BOX_DIAGRAMS[2] - (x0 + length + 10) - 2, max_lines=2)
        y = y0 - down - 10.0
    mu_phi = num(math.degrees(sc.phi), lang, sig=3)
    sh.text(x0, max(y, BOX_DIAGRAMS[1] + 3.0), f"μ_{{φ}} = {mu_phi} °/" + tr(lang, "mm") +
            tr(lang, "; positions from position 0"), H_SMALL)
    return f


# ----------------------------------------------------------------------------------------------
# fields 3–6: the plans


def _plan_field(sh: Sheet, plan: Plan, box, label: str, lang: str):
    velocity = plan.kind == "velocity"
    pts = {n: plan.mm(n) for n in plan.points}
    zs = np.array(list(pts.values()))
    lo, hi = complex(zs.real.min(), zs.imag.min()), complex(zs.real.max(), zs.imag.max())
    x0, y0, x1, y1 = box
    mid_box = np.array([(x0 + x1) / 2, (y0 + y1) / 2 - 8.0])
    mid = (lo + hi) / 2
    factor = 1.0 / plan.scale  # paper mm per (m/s) or (m/s²)
    origin = mid_box - np.array([mid.real, mid.imag])
    unit_text = tr(lang, "(m/s)/mm") if velocity else tr(lang, "(m/s²)/mm")
    mu = f"μ_{{{'v' if velocity else 'a'}}} = {num(plan.scale, lang, sig=3)} {unit_text}"
    heading = (tr(lang, "Velocity plan, position {label}").format(label=label) if velocity else
               tr(lang, "Acceleration plan, position {label}").format(label=label))
    f = sh.add_field(f"{plan.kind}_plan_{label}", box, heading, origin=tuple(origin), scale=factor, scale_text=mu)

    def at(label_):
        z = pts[label_]
        return np.array([origin[0] + z.real, origin[1] + z.imag])

    drawn = set()
    for v in plan.vectors:
        a, b = at(v.start), at(v.end)
        d = b - a
        if np.hypot(*d) < 0.3 or (v.start, v.end) in drawn:
            continue
        drawn.add((v.start, v.end))
        absolute = v.start == plan.pole
        dashed = "^n" in v.symbol or "^τ" in v.symbol
        sh.line(a, b, "Основные" if absolute else "Тонкие", "DASHED" if dashed else None)
        sh.arrow(b, d, "Основные" if absolute else "Тонкие", min(3.5, 0.4 * np.hypot(*d)), 1.0)
    placed, named = [], set()
    for n in sorted(pts, key=lambda q: q != plan.pole):
        q = at(n)
        if n in named or any(np.hypot(*(q - r)) < 2.5 for r in placed):
            continue
        group = [g for g in pts if g not in named and np.hypot(*(at(g) - q)) < 2.5]
        named.update(group)
        group.sort(key=lambda g: g != plan.pole)
        text = ", ".join(_sub(g) for g in group)
        if plan.pole in group and plan.at_pole:
            text += ", " + ", ".join(_sub(g) for g in plan.at_pole)
        others = [at(g) for g in pts if g not in group]
        push = sum(((q - r) / max(np.hypot(*(q - r)), 1e-6) ** 2 for r in others), np.zeros(2))
        if np.hypot(*push) < 1e-9:
            push = np.array([0.0, 1.0])
        d = push / np.hypot(*push)
        sh.text(q[0] + 4.0 * d[0], q[1] + 4.0 * d[1], text, H, align="left" if d[0] > 0.5 else "right" if d[0] < -0.5
                else "center", valign="bottom" if d[1] > 0.5 else "top" if d[1] < -0.5 else "middle")
        placed.append(q)
    return f


# ----------------------------------------------------------------------------------------------
# the results table and the sheet


def _results(sh: Sheet, s: Sheet1, lang: str) -> None:
    m, c, st = s.mechanism, s.cycle, s.structure
    rows = [(tr(lang, "Structural formula; W"), f"{st.formula}; W = {st.dof}"),
            (tr(lang, "Crank speed n_{1}"),
             f"{num(m.crank.rpm, lang, sig=5)} " + tr(lang, "rpm"))]
    if c.stroke is not None:
        if m.output.kind == "slider":
            rows.append((tr(lang, "Stroke H"), f"{num(c.stroke * MM, lang, decimals=2)} " + tr(lang, "mm")))
        else:
            rows.append((tr(lang, "Swing ψ"), f"{num(math.degrees(c.stroke), lang, decimals=2)}°"))
        rows.append((tr(lang, "Time ratio K"), num(c.time_ratio, lang, decimals=4)))
    worst = max(c.pressure, key=lambda p: p.worst)
    rows.append((tr(lang, "Largest pressure angle"),
                 f"{num(math.degrees(worst.worst), lang, decimals=1)}°"))
    table(sh, BOX_TABLE, tr(lang, "Main results"), rows, col1=0.55, h=H_SMALL)


def sheet1(s: Sheet1, lang: str, title) -> Sheet:
    """Build sheet 1 of a mechanism (no file written)."""
    sh = Sheet(lang)
    sh.frame()
    scheme = _scheme_field(sh, s, lang)
    _diagrams_field(sh, s, lang)
    for j, pl in enumerate(s.plans[:2]):
        _plan_field(sh, pl.velocity, BOX_PLANS[j][0], _label(pl.position.label), lang)
        _plan_field(sh, pl.acceleration, BOX_PLANS[j][1], _label(pl.position.label), lang)
    _results(sh, s, lang)
    sh.title_block(title, name=tr(lang, "Kinematic analysis of the lever mechanism"),
                   designation=title.designation_for(1, 0), scale=scheme.scale_label)
    return sh
