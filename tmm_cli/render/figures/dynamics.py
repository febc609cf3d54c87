"""Figures of sheet 2 for a mechanism file, matplotlib Figure objects (no pyplot).

- linkage_forces: the force analysis of one position — each group (the last first) and the crank
  drawn apart with their forces, and under each its force polygon at μ_F;
- linkage_lever: Zhukovsky's lever — the velocity plan of that position turned through 90°, every
  force at its point, the balancing force at a, the moments' table;
- linkage_dynamics: M_r and M_d, A_r and A_d, ΔT (with Mertsalov's ΔT_I), J_r against the crank's
  travel from position 0, at their scales;
- linkage_wittenbauer: the energy–mass diagram ΔT(J_r) with the tangents at ψ_max, ψ_min.

Everything drawn is read from :class:`~tmm_cli.linkage.sheet2.Sheet2`; nothing is recomputed.
"""

from __future__ import annotations

import math

import numpy as np

from ...i18n import tr
from ...i18n.numbers import num, small_pct
from ...linkage.chain import slider_pose, slot_axis
from ...linkage.sheet2 import Sheet2
from ...linkage.zhukovsky import DECIMALS as LEVER_DECIMALS
from ..terminal.dynamics import symbol as book_symbol
from .kit import decimal_commas, mt, new_figure, suptitle, title_height
from .mechanism import _block, joint_tex, label_tex, span_mm
from ..terminal.mechanism import pattern

MM = 1000.0
C_APPLIED = "#1f77b4"
C_LATER = "#2ca02c"
C_UNKNOWN = "#d62728"
FIGURES2 = ("linkage_forces", "linkage_lever", "linkage_dynamics", "linkage_wittenbauer")


TOKENS = {"ΔT_I": r"$\Delta T_I$", "ω²_max": r"$\omega^2_{max}$", "ω²_min": r"$\omega^2_{min}$",
          "ω_max²": r"$\omega^2_{max}$", "ω_min²": r"$\omega^2_{min}$", "μ_φ": r"$\mu_\varphi$", "μ_v": r"$\mu_v$"}


def title_tex(text: str) -> str:
    """A title's book symbols as mathtext (:func:`.kit.mt`, and the few it does not know)."""
    for plain, tex in TOKENS.items():
        text = text.replace(plain, "\x00" + str(list(TOKENS).index(plain)) + "\x00")
    text = mt(text)
    for j, tex in enumerate(TOKENS.values()):
        text = text.replace(f"\x00{j}\x00", tex)
    return text


def force_tex(sym: str, lang: str) -> str:
    """'Φ2' → '$\\Phi_{2}$', 'Rτ12' → '$R^{\\tau}_{12}$', 'MΦ2′' → "$M_{\\Phi 2}'$", 'Fc' → '$F_{пс}$'."""
    sym = book_symbol(sym, lang)
    tick = ""
    if sym[-1] in "′″":
        tick = "'" if sym[-1] == "′" else "''"
        sym = sym[:-1]
    greek = {"Φ": r"\Phi", "τ": r"\tau"}
    if sym.startswith("MΦ"):
        return f"$M_{{\\Phi{sym[2:]}}}{tick}$"
    if sym.startswith(("Rτ", "Rn")):
        sup = greek.get(sym[1], sym[1])
        return f"$R^{{{sup}}}_{{{sym[2:]}}}{tick}$"
    head = greek.get(sym[0], sym[0])
    tail = sym[1:]
    return f"${head}_{{{tail}}}{tick}$" if tail else f"${head}{tick}$"


# --- the force analysis of one position -----------------------------------------------------------


def _group_links(s: Sheet2, group: int):
    m = s.sheet1.mechanism
    return [ln for ln in m.links if ln.group == group]


def _draw_links(ax, s: Sheet2, links, i: int, unit: float) -> list[complex]:
    """The links at position i [mm]; returns the points drawn (for the view's limits)."""
    m = s.sheet1.mechanism
    k = s.sheet1.cycle.kin
    z = {n: complex(x[i]) * MM for n, x in k.z.items()}
    pts = []
    for ln in links:
        if ln.kind in ("crank", "bar"):
            a, b = ln.axis
            ends = [z[a], z[b]] + [z[p.name] for p in m.points if p.link == ln.name]
            d = (z[b] - z[a]) / abs(z[b] - z[a])
            t = [((e - z[a]) * d.conjugate()).real for e in ends]
            p0, p1 = z[a] + min(t) * d, z[a] + max(t) * d
            ax.plot([p0.real, p1.real], [p0.imag, p1.imag], color="k", lw=2.0, solid_capstyle="round", zorder=3)
            for e in ends:
                if abs(((e - z[a]) * d.conjugate()).imag) > 1e-6:
                    ax.plot([z[a].real, e.real, z[b].real], [z[a].imag, e.imag, z[b].imag], color="k", lw=2.0, zorder=3)
            pts += ends
        elif ln.kind == "slotted":
            a, c = ln.axis
            far = [z[p.name] for p in m.points if p.link == ln.name] + [z[a]] + [
                z[g.joints[1]] for g in m.groups if g.guide is not None and g.guide.link == ln.name]
            reach = max(abs(e - z[c]) for e in far)
            d = (z[a] - z[c]) / abs(z[a] - z[c])
            tip = z[c] + 1.08 * reach * d
            foot = z[c]
            if m.groups[ln.group - 1].offset != 0.0:  # an offset slot: the arm from the pivot to it, then the slot
                foot, d = (complex(x[i]) for x in slot_axis(m, k, ln.name))
                foot = foot * MM
                tip = foot + 1.08 * reach * d
                ax.plot([z[c].real, foot.real], [z[c].imag, foot.imag], color="k", lw=2.0, zorder=3)
            ax.plot([foot.real, tip.real], [foot.imag, tip.imag], color="k", lw=2.0, zorder=3)
            pts += [z[c], tip]
        elif ln.kind == "block":
            _block(ax, z[ln.name], float(k.angle[ln.name][i]), 0.5 * unit, 0.25 * unit, "k", 1.2, "-", z=4)
            pts.append(z[ln.name])
        elif ln.kind == "slider":
            centre, angle, segs = slider_pose(m, k, ln.name, i)
            for p0, p1 in segs:
                ax.plot([p0.real * MM, p1.real * MM], [p0.imag * MM, p1.imag * MM], color="k", lw=1.6, zorder=3)
            _block(ax, centre * MM, angle, 0.7 * unit, 0.35 * unit, "k", 1.2, "-", z=4)
            pts.append(centre * MM)
    names = {n for ln in links for n in ln.pins} | {p.name for p in m.points if any(p.link == ln.name for ln in links)}
    for n in names:
        ax.plot(z[n].real, z[n].imag, "o", ms=3.5, mfc="white", mec="k", zorder=6)
        ax.annotate(f"${joint_tex(n)}$", (z[n].real, z[n].imag), xytext=(-9, 6), textcoords="offset points",
                    fontsize=9, zorder=7)
    return pts


def _arrows(ax, items, size_mm: float, biggest: float) -> list[complex]:
    """Arrows (point [mm], force [N], colour, label) scaled so the biggest is `size_mm` long."""
    tips = []
    for z, f, colour, label in items:
        if abs(f) < 1e-9 * biggest:
            continue
        v = f / biggest * size_mm
        ax.annotate("", xy=(z.real + v.real, z.imag + v.imag), xytext=(z.real, z.imag), zorder=5,
                    arrowprops=dict(arrowstyle="-|>", color=colour, lw=1.2, shrinkA=0, shrinkB=0, mutation_scale=9))
        tip = z + v
        ax.annotate(label, (tip.real, tip.imag), xytext=(3, 3), textcoords="offset points", fontsize=8.5, color=colour,
                    zorder=7)
        tips.append(tip)
    return tips


def _lever_arrows(ax, items, span: float, biggest: float):
    """The lever's force arrows (point, force, colour, label), not to scale (as the book draws
    them): from 0.08 to 0.3 of the plan's span by the force's size, so that a small force shows;
    returns (tail, tip, label, colour) of each drawn."""
    out = []
    for z, f, colour, label in items:
        if abs(f) < 1e-9 * biggest:
            continue
        v = f / abs(f) * span * (0.08 + 0.22 * math.sqrt(abs(f) / biggest))
        ax.annotate("", xy=(z.real + v.real, z.imag + v.imag), xytext=(z.real, z.imag), zorder=5,
                    arrowprops=dict(arrowstyle="-|>", color=colour, lw=1.2, shrinkA=0, shrinkB=0, mutation_scale=9))
        out.append((z, z + v, label, colour))
    return out


def _hits(box, a, b) -> bool:
    """Whether the segment a–b (display px) crosses the box (x0, y0, x1, y1)."""
    x0, y0, x1, y1 = box
    t0, t1 = 0.0, 1.0
    d = b - a
    for p, q in ((-d[0], a[0] - x0), (d[0], x1 - a[0]), (-d[1], a[1] - y0), (d[1], y1 - a[1])):
        if abs(p) < 1e-12:
            if q < 0:
                return False
            continue
        r = q / p
        if p < 0:
            t0 = max(t0, r)
        else:
            t1 = min(t1, r)
        if t0 > t1:
            return False
    return True


def _place_names(fig, ax, names, segs) -> None:
    """Each name (anchor [data], text, colour, size) at the first of 8 directions × 3 distances
    around its anchor where it overlaps no name placed before and crosses no segment [data];
    else where it touches fewest."""
    ax.apply_aspect()
    r = fig.canvas.get_renderer()
    tr_ = ax.transData
    lines = [(tr_.transform((a.real, a.imag)), tr_.transform((b.real, b.imag))) for a, b in segs]
    placed = []
    dirs = [(1, 1), (-1, 1), (1, -1), (-1, -1), (1, 0), (-1, 0), (0, 1), (0, -1)]
    ha = {1: "left", 0: "center", -1: "right"}
    va = {1: "bottom", 0: "center", -1: "top"}
    for z, text, colour, size in names:
        best = None
        for dist in (3, 7, 12, 18):
            for dx, dy in dirs:
                t = ax.annotate(text, (z.real, z.imag), xytext=(dx * dist, dy * dist), textcoords="offset points",
                                ha=ha[dx], va=va[dy], fontsize=size, color=colour, zorder=7)
                e = t.get_window_extent(r).expanded(1.08, 1.15)
                box = (e.x0, e.y0, e.x1, e.y1)
                cost = sum(1 for p in placed if not (box[2] <= p[0] or p[2] <= box[0] or box[3] <= p[1] or p[3] <= box[1]))
                cost = 3 * cost + sum(1 for a, b in lines if _hits(box, a, b))
                if best is None or cost < best[0]:
                    if best is not None:
                        best[1].remove()
                    best = (cost, t, box)
                else:
                    t.remove()
                if cost == 0:
                    break
            if best[0] == 0:
                break
        placed.append(best[2])


def _group_items(s: Sheet2, group: int, i: int, lang: str):
    """What acts on the group's links at position i: applied forces, the groups' before, the reactions found."""
    numbers = {ln.number for ln in _group_links(s, group)}
    items = []
    for f in s.loading.forces:
        if f.number in numbers:
            items.append((complex(f.z[i]) * MM, complex(f.f[i]), C_APPLIED, force_tex(f.symbol, lang)))
    for r in s.forces.reactions:
        a, b = r.pair.links
        if a in numbers and b not in numbers:  # a later group's reaction, reversed
            items.append((complex(r.at[i]) * MM, -complex(r.force[i]), C_LATER, f"$R_{{{b}{a}}}$"))
        elif b in numbers and a not in numbers:
            items.append((complex(r.at[i]) * MM, complex(r.force[i]), C_UNKNOWN, f"$R_{{{r.label[1:]}}}$"))
    return items


def _polygon(ax, pg, lang: str) -> None:
    colours = {"applied": C_APPLIED, "later": C_LATER, "unknown": C_UNKNOWN}
    tip = 0j
    pts = [0j]
    tips = np.cumsum([0j] + [v.value / pg.scale for v in pg.vectors])
    span = max(float(np.ptp(tips.real)), float(np.ptp(tips.imag)), 1.0)
    short = []
    for v in pg.vectors:
        d = v.value / pg.scale
        if abs(d) <= 0.06 * span:
            short.append(v)
        if abs(d) > 1e-6:
            ax.annotate("", xy=((tip + d).real, (tip + d).imag), xytext=(tip.real, tip.imag), zorder=4,
                        arrowprops=dict(arrowstyle="-|>", color=colours[v.kind], lw=1.3, shrinkA=0, shrinkB=0,
                                        mutation_scale=10))
            mid = tip + d / 2
            n = 1j * d / abs(d)
            if abs(d) > 0.06 * span:
                ax.annotate(force_tex(v.symbol, lang), (mid.real, mid.imag), xytext=(9 * n.real, 9 * n.imag),
                            textcoords="offset points", ha="center", va="center", fontsize=8.5, color=colours[v.kind])
        tip = tip + d
        pts.append(tip)
    xy = np.array(pts)
    span = max(float(np.ptp(xy.real)), float(np.ptp(xy.imag)), 1.0)
    pad = 0.15 * span
    ax.set_xlim(xy.real.min() - pad, xy.real.max() + pad)
    ax.set_ylim(xy.imag.min() - pad, xy.imag.max() + pad)
    ax.set_aspect("equal", adjustable="box")
    ax.plot(0, 0, "o", ms=3, color="k")
    ax.axis("off")
    mu = num(pg.scale, lang, sig=3)
    ax.set_title(r"$\mu_F$ = " + f"{mu} " + tr(lang, "N/mm"), fontsize=9)
    if short:
        unit = tr(lang, "N")
        text = tr(lang, "short: ") + ", ".join(
            f"{force_tex(v.symbol, lang)} = {num(abs(v.value), lang, decimals=1)} {unit}" for v in short)
        ax.text(0.5, -0.02, text, transform=ax.transAxes, ha="center", va="top", fontsize=7.5, wrap=True)


def forces_figure(s: Sheet2, lang: str):
    i = s.force_position
    p = s.sheet1.cycle.positions[i]
    cols = len(s.polygons)
    width = 4.4 * cols
    top = title_height(2, 11)
    height = 8.6
    fig = new_figure(width, height)
    unit = 0.06 * span_mm(s.sheet1)
    for j, pg in enumerate(s.polygons):
        ax = fig.add_axes((j / cols + 0.01, 0.50, 1 / cols - 0.02, 0.5 - (top + 0.15) / height))
        bx = fig.add_axes((j / cols + 0.01, 0.03, 1 / cols - 0.02, 0.42))
        group = pg.group
        links = _group_links(s, group)
        pts = _draw_links(ax, s, links, i, unit)
        items = _group_items(s, group, i, lang)
        biggest = max((abs(f) for _, f, _, _ in items), default=1.0) or 1.0
        size = 0.45 * max(max(abs(a - b) for a in pts for b in pts), unit * 3)
        pts += _arrows(ax, items, size, biggest)
        moments = [force_tex(c.symbol, lang) + f" = {num(float(c.m[i]), lang, decimals=2)} " + tr(lang, "N·m")
                   for c in s.loading.couples if c.number in {ln.number for ln in links} and float(c.m[i]) != 0.0]
        if group == 0:
            moments.append(tr(lang, "$M_b$") +
                           f" = {num(float(s.balancing[i]), lang, decimals=2)} " + tr(lang, "N·m"))
        if moments:
            ax.text(0.0, 0.0, "\n".join(moments), transform=ax.transAxes, ha="left", va="bottom", fontsize=8,
                    color=C_APPLIED if group else C_UNKNOWN)
        xy = np.array(pts)
        pad = 0.12 * max(float(np.ptp(xy.real)), float(np.ptp(xy.imag)), 1.0)
        ax.set_xlim(xy.real.min() - pad, xy.real.max() + pad)
        ax.set_ylim(xy.imag.min() - pad, xy.imag.max() + pad)
        ax.set_aspect("equal", adjustable="box")
        ax.axis("off")
        name = tr(lang, "the crank with the frame") if group == 0 else tr(lang, "group {group} ({kind})").format(group=group, kind=pattern(s.sheet1.mechanism.groups[group - 1].kind, lang))
        ax.set_title(name, fontsize=10)
        _polygon(bx, pg, lang)
    phi = num(math.degrees(p.phi) % 360.0, lang, decimals=1)
    mb = num(float(s.balancing[i]), lang, decimals=2)
    title = tr(lang, "Force analysis, position {label} (φ = {phi}°): groups (forces not to scale) and force polygons\nblue — applied, green — from the groups before, red — found; M_b = {mb} N·m").format(label=label_tex(p.label), phi=phi, mb=mb)
    suptitle(fig, title_tex(title), fontsize=11)
    return fig


# --- Zhukovsky's lever ----------------------------------------------------------------------------


def lever_figure(s: Sheet2, lang: str):
    i = s.force_position
    pl = s.sheet1.plans[0]
    plan = pl.velocity
    mu = s.lever_scale()  # the lever's μ (its table's arms are at it)
    p = pl.position
    width, height = 12.0, 7.5
    top = title_height(2, 11)
    fig = new_figure(width, height)
    ax = fig.add_axes((0.02, 0.03, 0.6, 1 - (top + 0.1) / height))
    tx = fig.add_axes((0.63, 0.03, 0.36, 1 - (top + 0.1) / height))
    tx.axis("off")
    turned = {n: 1j * z / mu for n, z in plan.points.items()}  # the plan turned 90° ccw [mm]
    for v in plan.vectors:
        a, b = turned[v.start], turned[v.end]
        if abs(b - a) > 1e-6:
            ax.plot([a.real, b.real], [a.imag, b.imag], color="#9a9a9a", lw=0.8, zorder=2)
    rays = []
    for f in s.lever.forces:  # B′ of a slider's pair (its couple as forces at B and B′): b′ and its ray p b′
        if f.point.lower() not in turned and f.point not in turned:
            z = complex(f.lever[i]) / mu
            turned[f.point.lower()] = z
            rays.append(f.point.lower())
            ax.plot([0.0, z.real], [0.0, z.imag], color="#9a9a9a", lw=0.8, zorder=2)
    pts = list(turned.values())
    segs = [(turned[v.start], turned[v.end]) for v in plan.vectors] + [(0j, turned[n]) for n in rays]
    for n, z in turned.items():
        ax.plot(z.real, z.imag, "o", ms=2.5, color="#666666", zorder=3)
    lv = s.lever
    items = [(complex(f.lever[i]) / mu, complex(f.force[i]), C_APPLIED, force_tex(f.symbol, lang)) for f in lv.forces]
    a_pt = 1j * complex(s.sheet1.cycle.kin.v[s.sheet1.mechanism.crank.joint][i]) / mu
    items.append((a_pt, complex(lv.balancing_force[i]), C_UNKNOWN, tr(lang, "$F_b$")))
    biggest = max((abs(f) for _, f, _, _ in items), default=1.0) or 1.0
    span = max(float(np.ptp(np.real(pts))), float(np.ptp(np.imag(pts))), 1.0)
    arrows = _lever_arrows(ax, items, span, biggest)
    pts += [tip for _, tip, _, _ in arrows]
    segs += [(tail, tip) for tail, tip, _, _ in arrows]
    xy = np.array(pts)
    pad = 0.1 * span
    ax.set_xlim(xy.real.min() - pad, xy.real.max() + pad)
    ax.set_ylim(xy.imag.min() - pad, xy.imag.max() + pad)
    ax.set_aspect("equal", adjustable="box")
    ax.axis("off")
    # the names where they overlap no other name and no line: the points', then the forces' at their tips
    names = [(z, r"$p$" if n == plan.pole else f"${joint_tex(n)}$", "#555555", 9) for n, z in turned.items()]
    names += [(tip, label, colour, 8.5) for _, tip, label, colour in arrows]
    _place_names(fig, ax, names, segs)
    # the lever's table (Sheet2.lever_table), as sheet 2 and the note give it: ±F·h about p, F_ур, M_ур
    lt = s.lever_table()
    d = LEVER_DECIMALS
    nm, nmm, n_ = tr(lang, "N·m"), tr(lang, "N·mm"), tr(lang, "N")
    lines = [tr(lang, "moments about the pole p, ±F·h, N·mm (F, N; h, mm):")]
    for x in lt.terms:
        sign = "−" if x.sign < 0 else ""
        lines.append(f"{force_tex(x.symbol, lang)}: {sign}{num(x.force, lang, decimals=d['force'])}·"
                     f"{num(x.arm, lang, decimals=d['arm'])} = {num(x.moment, lang, decimals=d['moment'], minus='−')}")
    lines.append(f"ΣF·h = {num(lt.total, lang, decimals=d['moment'], minus='−')} {nmm}")
    lines.append(tr(lang, "$F_b$") + f" = |ΣF·h|/(pa) = {num(lt.balancing_force, lang, decimals=d['balancing_force'])} {n_}")
    lines.append(tr(lang, "$M_b$") + " = " + tr(lang, "$F_b$") + r"$\cdot l_1$" +
                 f" = {num(lt.balancing, lang, decimals=d['balancing'])} {nm}")
    lines.append(tr(lang, "force analysis: ") + f"{num(lt.kinetostatic, lang, decimals=d['balancing'], minus='−')} {nm}; "
                 f"Δ {small_pct(lt.difference_pct, lang)} %")
    tx.text(0.0, 0.98, "\n".join(lines), transform=tx.transAxes, ha="left", va="top", fontsize=8.5, linespacing=1.5)
    mu_t = num(mu, lang, sig=3)
    title = tr(lang, "Zhukovsky's lever, position {label}: the velocity plan turned 90° counter-clockwise (μ_v = {mu_t} (m/s)/mm), forces at their points").format(label=label_tex(p.label), mu_t=mu_t)
    suptitle(fig, title_tex(title), fontsize=11)
    return fig


# --- the dynamics diagrams ------------------------------------------------------------------------


def dynamics_figure(s: Sheet2, lang: str):
    d, fw, sc = s.dynamics, s.flywheel, s.scales
    c = s.sheet1.cycle
    width, height = 9.0, 11.0
    top = title_height(2, 11)
    fig = new_figure(width, height)
    left, right, bottom, gap = 1.0, 0.25, 0.7, 0.4
    h = (height - top - bottom - 3 * gap) / 4
    axes = [fig.add_axes((left / width, (bottom + (3 - j) * (h + gap)) / height, 1 - (left + right) / width, h / height))
            for j in range(4)]
    x = np.degrees(d.travel)
    nm, jj, kg = tr(lang, "N·m"), tr(lang, "J"), tr(lang, "kg·m²")
    ax = axes[0]
    ax.plot(x, d.M_r, color="k", lw=1.4, label=tr(lang, "$M_r$"))
    ax.axhline(d.M_d, color=C_UNKNOWN, lw=1.2, label=tr(lang, "$M_d$") + f" = {num(d.M_d, lang, decimals=2)}")
    ax.set_ylabel(f"M, {nm}")
    ax.set_title(r"$\mu_M$ = " + f"{num(sc.M, lang, sig=3)} {nm}/" + tr(lang, "mm"), fontsize=9, loc="right", pad=3)
    ax = axes[1]
    ax.plot(x, d.A_r, color="k", lw=1.4, label=tr(lang, "$A_r$"))
    ax.plot(x, d.A_d, color=C_UNKNOWN, lw=1.2, label=tr(lang, "$A_d$"))
    ax.set_ylabel(f"A, {jj}")
    ax.set_title(r"$\mu_A$ = " + f"{num(sc.A, lang, sig=3)} {jj}/" + tr(lang, "mm"), fontsize=9, loc="right", pad=3)
    ax = axes[2]
    ax.plot(x, d.dT, color="k", lw=1.4, label=r"$\Delta T$")
    if fw is not None:
        me = fw.mertsalov
        ax.plot(x, me.dT_I - me.dT_I[0], color=C_APPLIED, lw=1.2, ls="--", label=r"$\Delta T_I$")
        for j_, mark in ((me.i_max, "v"), (me.i_min, "^")):
            ax.plot(x[j_], me.dT_I[j_] - me.dT_I[0], mark, color=C_APPLIED, ms=6)
    ax.set_ylabel(f"ΔT, {jj}")
    ax.set_title(r"$\mu_T$ = " + f"{num(sc.T, lang, sig=3)} {jj}/" + tr(lang, "mm"), fontsize=9, loc="right", pad=3)
    ax = axes[3]
    ax.plot(x, d.J_r, color="k", lw=1.4, label=tr(lang, "$J_r$"))
    ax.axhline(d.J_first, color="#9a9a9a", lw=0.9, ls=":", label=tr(lang, "$J_{crank}+J_{rotor}$"))
    ax.set_ylabel(f"J, {kg}")
    ax.set_title(r"$\mu_J$ = " + f"{num(sc.J, lang, sig=3)} {kg}/" + tr(lang, "mm"), fontsize=9, loc="right", pad=3)
    evens = [p for p in s.positions if p.label.isdigit()]  # the cycle's: a four-stroke engine's two turns
    end = 360.0 * s.turns
    for j, ax in enumerate(axes):
        for turn in range(s.turns):
            for lo, hi in c.stroke_spans():  # the working stroke, from its start extreme
                ax.axvspan(math.degrees(lo) + 360.0 * turn, math.degrees(hi) + 360.0 * turn, color=C_APPLIED,
                           alpha=0.05, lw=0)
            if turn:  # the end of a turn within the cycle
                ax.axvline(360.0 * turn, color="k", lw=0.8, ls="--")
        ax.axhline(0, color="k", lw=0.5)
        ax.set_xlim(0, end)
        ax.set_xticks([math.degrees(p.travel) for p in evens] + [end])
        ax.set_xticklabels([p.label for p in evens] + ["0"] if j == 3 else [])
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="best", frameon=False, ncol=2)
    mu_phi = num(math.degrees(sc.phi), lang, sig=3)
    axes[-1].set_xlabel(title_tex(tr(lang, "positions of the crank from position 0 (μ_φ = {mu_phi}°/mm)").format(mu_phi=mu_phi)))
    title = tr(lang, "Dynamics reduced to the crank: M_r and M_d, the works, ΔT (ΔT_I: Mertsalov), J_r\n(moments and works in the crank's sense of rotation)")
    suptitle(fig, title_tex(title), fontsize=11)
    decimal_commas(fig, lang)
    return fig


def wittenbauer_figure(s: Sheet2, lang: str):
    d, fw = s.dynamics, s.flywheel
    wi = fw.wittenbauer
    width, height = 8.0, 7.5
    top = title_height(3, 11)
    fig = new_figure(width, height)
    ax = fig.add_axes((1.0 / width, 0.8 / height, 1 - 1.3 / width, 1 - (top + 1.0) / height))
    ax.plot(d.J_r, d.dT, color="k", lw=1.4)
    for p in s.positions:  # the cycle's: a four-stroke engine's two turns
        if p.label.isdigit():
            jr, dt = (float(np.interp(p.travel, d.travel, y)) for y in (d.J_r, d.dT))
            ax.plot(jr, dt, "o", ms=3, color="tab:orange")
            ax.annotate(p.label, (jr, dt), xytext=(4, 4), textcoords="offset points", fontsize=8)
    lo, hi = 0.0, float(d.J_r.max()) * 1.1
    xs = np.array([lo, hi])
    for slope, cc, j_, colour, name in ((wi.slope_max, wi.c_max, wi.i_max, C_UNKNOWN, r"$\psi_{max}$"),
                                        (wi.slope_min, wi.c_min, wi.i_min, C_APPLIED, r"$\psi_{min}$")):
        ax.plot(xs, cc + slope * xs, color=colour, lw=1.1)
        ax.plot(d.J_r[j_], d.dT[j_], "o", color=colour, ms=5)
        ax.plot(0, cc, "s", color=colour, ms=5)
        ax.annotate(name, (hi, cc + slope * hi), xytext=(-30, 4), textcoords="offset points", color=colour, fontsize=10)
    ax.annotate("k", (0, wi.c_max), xytext=(5, 3), textcoords="offset points", fontsize=10)
    ax.annotate("l", (0, wi.c_min), xytext=(5, -12), textcoords="offset points", fontsize=10)
    ax.plot([0, 0], [wi.c_min, wi.c_max], color="k", lw=2.0)
    ax.set_xlim(lo - 0.02 * hi, hi)
    ax.axhline(0, color="k", lw=0.5)
    ax.grid(alpha=0.3)
    ax.set_xlabel(title_tex(tr(lang, "J_r, kg·m²")))
    ax.set_ylabel(tr(lang, "ΔT, J"))
    kg = tr(lang, "kg·m²")
    tg_max, tg_min = num(wi.slope_max, lang, sig=5), num(wi.slope_min, lang, sig=5)
    jw = num(max(wi.J_fl, 0.0), lang, sig=4)
    title = tr(lang, "Wittenbauer's energy–mass diagram: tg ψ_max = ω_max²/2 = {tg_max}, tg ψ_min = ω_min²/2 = {tg_min}\nJ_fl = kl/(tg ψ_max − tg ψ_min) = {jw} {kg} (Mertsalov: {J} {kg})\nδ = {delta}, ω_m = {omega_mean} rad/s").format(tg_max=tg_max, tg_min=tg_min, jw=jw, kg=kg, J=num(fw.J, lang, sig=4), delta=num(fw.delta, lang, sig=3), omega_mean=num(d.omega_mean, lang, sig=5))
    suptitle(fig, title_tex(title), fontsize=10.5)
    decimal_commas(fig, lang)
    return fig


def dynamics_figures(s: Sheet2, lang: str, names=None) -> dict:
    """The figures of :data:`FIGURES2` (Wittenbauer's only with a flywheel computed)."""
    want = set(names) if names is not None else set(FIGURES2)
    out = {}
    if "linkage_forces" in want:
        out["linkage_forces"] = forces_figure(s, lang)
    if "linkage_lever" in want:
        out["linkage_lever"] = lever_figure(s, lang)
    if "linkage_dynamics" in want:
        out["linkage_dynamics"] = dynamics_figure(s, lang)
    if "linkage_wittenbauer" in want and s.flywheel is not None:
        out["linkage_wittenbauer"] = wittenbauer_figure(s, lang)
    return out
