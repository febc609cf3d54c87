"""Figures of sheet 1 for a mechanism file, matplotlib Figure objects (no pyplot).

- linkage_mechanism: the scheme in all positions (position 0 bold, the other extreme position
  dashed), the paths of the joints and the traced paths of the named points (centres of mass);
- linkage_diagrams: s, v, a of the output link against the crank angle from position 0, with
  their scales μ_φ, μ_s, μ_v, μ_a;
- linkage_velocity_plan, linkage_acceleration_plan (and ``…_2`` for the second position): the
  plan drawn in millimetres at its scale μ, points labelled as in the book, the mechanism in that
  position and the table of the vectors.

Everything drawn is read from :class:`~tmm_cli.linkage.sheet1.Sheet1`; nothing is recomputed.
"""

from __future__ import annotations

import math
import re

import numpy as np

from ...linkage.chain import slider_pose, slot_axis
from ...linkage.sheet1 import Sheet1
from ...linkage.vector_plans import Plan, Plans, book_symbol
from .kit import decimal_commas, literal_text, new_figure, suptitle, title_height
from ...i18n import tr
from ...i18n.numbers import num

GREY = "#9a9a9a"
C_WORK = "#1f77b4"
C_RET = "#d62728"
PATH = "#6a3d9a"
VECTOR_STYLE = {  # kind → colour, line style
    "abs": ("k", "-"), "rel": ("#1f77b4", "-"), "cor": ("#d62728", "-"), "n": ("#2ca02c", "--"), "t": ("#ff7f0e", "--"),
}
MM = 1000.0


def joint_tex(name: str) -> str:
    """'O41' → 'O_{41}', 'S2' → 'S_2' (mathtext, without the dollars)."""
    m = re.fullmatch(r"([^\d]+?)(\d+)", name)
    if not m:
        return name
    sub = m.group(2)
    return f"{m.group(1)}_{{{sub}}}" if len(sub) > 1 else f"{m.group(1)}_{sub}"


def symbol_tex(symbol: str) -> str:
    """'a^k_A3A2' → '$a^{k}_{A_3A_2}$', 'v_BA' → '$v_{BA}$', 'a^τ_BC' → '$a^{\\tau}_{BC}$'."""
    m = re.fullmatch(r"([a-zω])(?:\^(\w|τ))?_(.+)", symbol)
    if not m:
        return symbol
    base, sup, sub = m.groups()
    sub = re.sub(r"([A-Za-z])(\d+)", lambda g: f"{g.group(1)}_{{{g.group(2)}}}", sub)
    sup = {"τ": r"\tau"}.get(sup, sup)
    return f"${base}" + (f"^{{{sup}}}" if sup else "") + f"_{{{sub}}}$"


def line_tex(line: str) -> str:
    """A line through joints: 'O2A' → '$O_2A$'."""
    return "$" + re.sub(r"([A-Za-z])(\d+)", lambda g: f"{g.group(1)}_{{{g.group(2)}}}", line) + "$"


def label_tex(label: str) -> str:
    """A position's label: '7′' → "$7'$" (the prime of mathtext; DejaVu's ′ is a hairline)."""
    return f"${label.replace('′', chr(39))}$" if "′" in label else label


def point_tex(label: str) -> str:
    """A plan point: 'π' → '$\\pi$', 'a3' → '$a_3$', 's2' → '$s_2$'."""
    if label == "π":
        return r"$\pi$"
    return f"${joint_tex(label)}$"


def _kind(symbol: str, start: str) -> str:
    if "^k" in symbol:
        return "cor"
    if "^n" in symbol:
        return "n"
    if "^τ" in symbol:
        return "t"
    if "^r" in symbol or start not in ("p", "π"):
        return "rel"
    return "abs"


# --- the mechanism ------------------------------------------------------------------------------


def _hangers(s: Sheet1) -> set[str]:
    """Named points a later group hangs on (drawn as part of their link)."""
    known = {j for g in s.mechanism.groups for j in g.known}
    return {p.name for p in s.mechanism.points if p.name in known}


def _ground(ax, x: float, y: float, size: float) -> None:
    """A fixed pivot: a small triangle on a hatched base [mm]."""
    from matplotlib.patches import Polygon

    ax.add_patch(Polygon([(x, y), (x - size, y - 1.6 * size), (x + size, y - 1.6 * size)], closed=True, fill=False,
                         lw=0.9, zorder=4))
    base = y - 1.6 * size
    ax.plot([x - 1.6 * size, x + 1.6 * size], [base, base], color="k", lw=0.9, zorder=4)
    for t in np.linspace(-1.4, 1.4, 6):
        ax.plot([x + t * size, x + (t - 0.4) * size], [base, base - 0.6 * size], color="k", lw=0.5, zorder=4)


def _block(ax, centre: complex, angle: float, length: float, height: float, color, lw, ls, z=6):
    from matplotlib.patches import Rectangle

    ax.add_patch(Rectangle((centre.real - length / 2, centre.imag - height / 2), length, height,
                           angle=math.degrees(angle), rotation_point="center", fill=True, fc="white", ec=color, lw=lw,
                           ls=ls, zorder=z))


def span_mm(s: Sheet1) -> float:
    """The larger side of the box of every joint's path [mm]: sizes the blocks and pivots."""
    k = s.cycle.curve.kin
    z = np.concatenate([k.z[n] for n in s.mechanism.joint_names]) * MM
    return max(float(np.ptp(z.real)), float(np.ptp(z.imag)))


def _riders(m, link: str) -> list[str]:
    """The sliders whose guide rides on the link (drawn long enough to carry them)."""
    return [g.joints[1] for g in m.groups if g.guide is not None and g.guide.link == link]


def draw_mechanism(ax, s: Sheet1, i: int, color="k", lw=1.6, ls="-", labels=True, size: float = 1.0, kin=None):
    """The mechanism at position `i` of the cycle (or of `kin`) [mm]."""
    m = s.mechanism
    k = kin if kin is not None else s.cycle.kin
    z = {n: complex(x[i]) * MM for n, x in k.z.items()}
    hang = _hangers(s)
    unit = size * 0.06 * span_mm(s)
    on_link = {}
    for p in m.points:
        on_link.setdefault(p.link, []).append(p.name)
    for ln in m.links:
        if ln.kind in ("crank", "bar"):
            a, b = ln.axis
            ends = [z[a], z[b]] + [z[p] for p in on_link.get(ln.name, []) if p in hang]
            d = (z[b] - z[a]) / abs(z[b] - z[a])
            t = [((e - z[a]) * d.conjugate()).real for e in ends]
            far = [e for e in ends if abs(((e - z[a]) * d.conjugate()).imag) > 1e-9 * unit]
            ax.plot([z[a].real + min(t) * d.real, z[a].real + max(t) * d.real],
                    [z[a].imag + min(t) * d.imag, z[a].imag + max(t) * d.imag], color=color, lw=lw, ls=ls, zorder=5,
                    solid_capstyle="round")
            for e in far:  # a point off the axis: the link is a plate (a triangle to it)
                ax.plot([z[a].real, e.real, z[b].real], [z[a].imag, e.imag, z[b].imag], color=color, lw=lw, ls=ls,
                        zorder=5)
        elif ln.kind == "slotted":
            a, c = ln.axis
            rho_max = max([float(np.max(s.cycle.curve.kin.slide[m.links[ln.number - 2].name][0])) * MM,
                           *(abs(z[p] - z[c]) for p in on_link.get(ln.name, []) if p in hang),
                           *(float(np.max(np.abs(s.cycle.curve.kin.z[j] - s.cycle.curve.kin.z[c]))) * MM
                             for j in _riders(m, ln.name))])
            d = (z[a] - z[c]) / abs(z[a] - z[c])
            tip = z[c] + 1.06 * rho_max * d
            if m.groups[ln.group - 1].offset != 0.0:  # an offset slot: the arm from the pivot to it, then the slot
                foot, d = (complex(x[i]) for x in slot_axis(m, k, ln.name))
                foot = foot * MM
                tip = foot + 1.06 * rho_max * d
                ax.plot([z[c].real, foot.real], [z[c].imag, foot.imag], color=color, lw=lw, ls=ls, zorder=5)
                ax.plot([foot.real, tip.real], [foot.imag, tip.imag], color=color, lw=lw, ls=ls, zorder=5)
            else:
                ax.plot([z[c].real, tip.real], [z[c].imag, tip.imag], color=color, lw=lw, ls=ls, zorder=5)
        elif ln.kind == "block":
            _block(ax, z[ln.name], float(k.angle[ln.name][i]), 0.5 * unit, 0.25 * unit, color, lw * 0.7, ls)
        elif ln.kind == "slider":
            g = m.groups[ln.group - 1]
            if g.kind == "RRP" and not g.guide.moving:
                _block(ax, z[ln.name], g.guide.angle, 0.7 * unit, 0.35 * unit, color, lw * 0.7, ls)
            else:  # on a moving guide (drawn from its point on the link), a PRP's block, an RPP's block or yoke
                centre, angle, segs = slider_pose(m, k, ln.name, i)
                for p0, p1 in segs:
                    ax.plot([p0.real * MM, p1.real * MM], [p0.imag * MM, p1.imag * MM], color=color, lw=lw * 0.8,
                            ls=ls, zorder=4)
                _block(ax, centre * MM, angle, 0.7 * unit, 0.35 * unit, color, lw * 0.7, ls)
    for n in m.joint_names:
        if n in m.frame or n == m.crank.joint or any(n in g.new for g in m.groups) or n in hang:
            ax.plot(z[n].real, z[n].imag, "o", ms=4 * size, mfc="white", mec=color, zorder=7)
        else:  # a centre of mass
            ax.plot(z[n].real, z[n].imag, "o", ms=3.2 * size, color=color, zorder=7)
    if labels:
        centre = np.mean([v for v in z.values()])
        for n in m.joint_names:
            d = z[n] - centre
            d = d / abs(d) if abs(d) > 1e-9 else 1j
            ax.annotate(f"${joint_tex(n)}$", (z[n].real, z[n].imag), xytext=(7 * d.real, 7 * d.imag),
                        textcoords="offset points", ha="left" if d.real > 0.3 else "right" if d.real < -0.3 else "center",
                        va="bottom" if d.imag > 0.3 else "top" if d.imag < -0.3 else "center", fontsize=10, zorder=8)


def _guides(ax, s: Sheet1, lo: complex, hi: complex) -> None:
    """Each slider's guide as a dash-dot line across the drawing [mm]."""
    for _, gd in s.mechanism.guided():
        if gd.moving:  # it turns with its link: drawn with the link in each position
            continue
        p, e = gd.through * MM, gd.unit
        ts = [((c - p) * e.conjugate()).real for c in (lo, hi, complex(lo.real, hi.imag), complex(hi.real, lo.imag))]
        a, b = p + min(ts) * e, p + max(ts) * e
        ax.plot([a.real, b.real], [a.imag, b.imag], color="k", lw=0.7, ls=(0, (12, 3, 2, 3)), zorder=1)


def scheme_figure(s: Sheet1, lang: str):
    m, c = s.mechanism, s.cycle
    curve = c.curve.kin
    zs = {n: curve.z[n] * MM for n in m.joint_names}
    allz = np.concatenate(list(zs.values()))
    lo, hi = complex(allz.real.min(), allz.imag.min()), complex(allz.real.max(), allz.imag.max())
    span = max(hi.real - lo.real, hi.imag - lo.imag)
    pad = 0.08 * span
    width = 11.0
    aspect = (hi.imag - lo.imag + 2 * pad) / (hi.real - lo.real + 2 * pad)
    top = title_height(2, 11)
    height = min(13.0, max(4.5, (width - 0.9) * aspect + top + 0.7))
    fig = new_figure(width, height)
    ax = fig.add_axes((0.75 / width, 0.7 / height, 1 - 0.95 / width, 1 - (top + 0.8) / height))
    ax.set_aspect("equal", adjustable="box")
    _guides(ax, s, lo - pad * (1 + 1j), hi + pad * (1 + 1j))
    hang = _hangers(s)
    for n in m.joint_names:  # the paths: joints grey dashed, named points (centres of mass) coloured
        if n in m.frame:
            continue
        is_mass = n not in hang and not any(n in g.new for g in m.groups) and n != m.crank.joint
        ax.plot(zs[n].real, zs[n].imag, color=PATH if is_mass else GREY, lw=1.0 if is_mass else 0.7,
                ls="-" if is_mass else "--", zorder=2)
    for p in c.positions:  # every position thin
        if p.index != 0:
            draw_mechanism(ax, s, p.index, color=GREY, lw=0.6, labels=False, size=0.6)
    for p in c.positions:  # its number at the crank pin and at the output's joint
        a = complex(c.kin.z[m.crank.joint][p.index]) * MM
        o = m.frame[m.crank.pivot] * MM
        d = (a - o) / abs(a - o)
        ax.annotate(label_tex(p.label), (a.real, a.imag), xytext=(11 * d.real, 11 * d.imag), textcoords="offset points",
                    ha="center", va="center", fontsize=7, color="k")
    ends = [p for p in c.positions if p.extreme and p.index != 0]
    for p in ends:
        draw_mechanism(ax, s, p.index, color="k", lw=1.1, ls="--", labels=False, size=0.9)
    draw_mechanism(ax, s, 0, color="k", lw=1.8, labels=True)
    unit = 0.06 * span
    for n in m.frame:
        if any(n in ln.pins for ln in m.links):
            z = m.frame[n] * MM
            _ground(ax, z.real, z.imag - 0.1 * unit, 0.25 * unit)
    _rotation_arrow(ax, s)
    ax.set_xlabel("x, " + tr(lang, "mm"))
    ax.set_ylabel("y, " + tr(lang, "mm"))
    ax.grid(alpha=0.2)
    ax.set_xlim(lo.real - pad, hi.real + pad)
    ax.set_ylim(lo.imag - pad, hi.imag + pad)
    mu = num(s.scheme_scale, lang, sig=3)
    first, last = c.working_start(), c.working_end()
    if first is not None and first.index != 0:  # crank.start_deg: position 0 is not an extreme
        extreme = "; " + tr(lang, "the extreme positions {start} (start of the working stroke) and {end} (its end) — "
                                  "dashed").format(start=label_tex(first.label), end=label_tex(last.label))
    else:
        extreme = "; " + tr(lang, "the other extreme position {label} — dashed").format(label=label_tex(last.label)) \
            if last is not None else ""
    title = tr(lang, "{name} in {n} positions (position 0 bold{extreme})\n"
                     "scale of the sheet μ_l = {mu} m/mm; coloured: the paths of the named points")
    title = title.replace("μ_l", r"$\mu_l$").format(  # the name: a person's text, never mathtext
        name=literal_text(m.name) if m.name else tr(lang, "Mechanism"), n=len(c.positions), extreme=extreme, mu=mu)
    suptitle(fig, title, fontsize=11)
    decimal_commas(fig, lang)
    return fig


def _rotation_arrow(ax, s: Sheet1) -> None:
    from matplotlib.patches import FancyArrowPatch

    m = s.mechanism
    o = m.frame[m.crank.pivot] * MM
    r = 0.45 * m.crank.length * MM
    a0, a1 = (math.radians(200), math.radians(250)) if m.crank.sense > 0 else (math.radians(250), math.radians(200))
    p0, p1 = o + r * complex(math.cos(a0), math.sin(a0)), o + r * complex(math.cos(a1), math.sin(a1))
    ax.add_patch(FancyArrowPatch((p0.real, p0.imag), (p1.real, p1.imag), connectionstyle=f"arc3,rad={0.3 * m.crank.sense}",
                                 arrowstyle="-|>", mutation_scale=10, color="k", lw=0.9, zorder=8))
    q = o + 1.5 * r * complex(math.cos(math.radians(225)), math.sin(math.radians(225)))
    ax.text(q.real, q.imag, r"$\omega_1$", ha="center", va="center", fontsize=10)


# --- the diagrams -------------------------------------------------------------------------------


def diagrams_figure(s: Sheet1, lang: str):
    m, c, sc = s.mechanism, s.cycle, s.scales
    cv = c.curve
    slider = m.output.kind == "slider"
    width, height = 9.0, 9.5
    top = title_height(2, 11)
    fig = new_figure(width, height)
    left, right, bottom = 0.95, 0.25, 0.7
    h = (height - top - bottom - 2 * 0.35) / 3
    axes = [fig.add_axes((left / width, (bottom + (2 - j) * (h + 0.35)) / height, 1 - (left + right) / width, h / height))
            for j in range(3)]
    x = np.degrees(cv.travel)
    if slider:
        series = [(cv.s * MM, "s, " + tr(lang, "mm"), sc.s, tr(lang, "m/mm")),
                  (cv.v, "v, " + tr(lang, "m/s"), sc.v, tr(lang, "(m/s)/mm")),
                  (cv.a, "a, " + tr(lang, "m/s²"), sc.a, tr(lang, "(m/s²)/mm"))]
    else:
        series = [(cv.s, "ψ, " + tr(lang, "rad"), sc.s, tr(lang, "rad/mm")),
                  (cv.v, "ω, " + tr(lang, "rad/s"), sc.v, tr(lang, "(rad/s)/mm")),
                  (cv.a, "ε, " + tr(lang, "rad/s²"), sc.a, tr(lang, "(rad/s²)/mm"))]
    names = ("s", "v", "a")
    evens = [p for p in c.positions if p.label.isdigit()]
    for j, (ax, (y, label, mu, unit)) in enumerate(zip(axes, series)):
        if c.working is not None:
            for working, colour in ((True, C_WORK), (False, C_RET)):  # from the working stroke's start extreme
                for lo, hi in c.stroke_spans(working):
                    ax.axvspan(math.degrees(lo), math.degrees(hi), color=colour, alpha=0.06, lw=0)
        for p in c.positions:
            if p.extreme:
                ax.axvline(math.degrees(p.travel), color="k", lw=0.6, ls=":")
        ax.plot(x, y, color="k", lw=1.4)
        ys = [float(np.interp(p.travel, cv.travel, y)) for p in evens]
        ax.plot([math.degrees(p.travel) for p in evens], ys, "o", ms=3, color="tab:orange")
        ax.axhline(0, color="k", lw=0.5)
        ax.set_ylabel(label)
        ax.set_xlim(0, 360)
        ax.set_xticks([math.degrees(p.travel) for p in evens] + [360.0])
        ax.set_xticklabels([p.label for p in evens] + ["0"] if j == 2 else [])
        ax.grid(alpha=0.3)
        mu_tex = {"s": r"$\mu_s$", "v": r"$\mu_v$", "a": r"$\mu_a$"}[names[j]]
        ax.set_title(f"{mu_tex} = {num(mu, lang, sig=3)} {unit}", fontsize=9, loc="right", pad=3)
    if c.working is not None:
        w_lo, w_hi = max(c.stroke_spans(True), key=lambda sp: sp[1] - sp[0])
        r_lo, r_hi = max(c.stroke_spans(False), key=lambda sp: sp[1] - sp[0])
        axes[0].text(math.degrees(w_lo + w_hi) / 2, 0.96, tr(lang, "working stroke"),
                     transform=axes[0].get_xaxis_transform(), ha="center", va="top", fontsize=8, color=C_WORK)
        axes[0].text(math.degrees(r_lo + r_hi) / 2, 0.96, tr(lang, "return stroke"),
                     transform=axes[0].get_xaxis_transform(), ha="center", va="top", fontsize=8, color=C_RET)
    mu_phi = num(math.degrees(sc.phi), lang, sig=3)
    axes[-1].set_xlabel(tr(lang, "positions of the crank from position 0 (μ_φ = {mu_phi}°/mm)").format(mu_phi=mu_phi).replace("μ_φ", r"$\mu_\varphi$"))
    what = m.output.link
    rpm = num(m.crank.rpm, lang, sig=4)
    title = tr(lang, "Kinematic diagrams of the output link {what} (n₁ = {rpm} rpm)").format(what=what, rpm=rpm)
    suptitle(fig, title, fontsize=11)
    decimal_commas(fig, lang)
    return fig


# --- the plans ----------------------------------------------------------------------------------


def away(z: complex, others, centre: complex) -> complex:
    """A unit direction from z away from the other points (their pull falls off as 1/distance),
    else away from the centre: where a label of z crowds nothing."""
    push = sum(((z - q) / abs(z - q) ** 2 for q in others), 0j)
    if abs(push) < 1e-12:
        push = z - centre
    return push / abs(push) if abs(push) > 1e-12 else 1j


def _nice_bar(x: float) -> float:
    e = math.floor(math.log10(x))
    for f in (1, 2, 5, 10):
        if f * 10 ** e >= x:
            return f * 10 ** e
    return 10 ** (e + 1)  # pragma: no cover


def plan_figure(s: Sheet1, pl: Plans, kind: str, lang: str):
    plan: Plan = pl.velocity if kind == "velocity" else pl.acceleration
    velocity = kind == "velocity"
    unit = tr(lang, "m/s") if velocity else tr(lang, "m/s²")
    pts = {n: plan.mm(n) for n in plan.points}
    xy = np.array(list(pts.values()))
    ext_w, ext_h = max(float(np.ptp(xy.real)), 1.0), max(float(np.ptp(xy.imag)), 1.0)
    height = 7.5
    top = title_height(1, 11)
    plan_h = height - top - 0.3
    plan_w = min(9.0, max(4.0, plan_h * (ext_w + 0.3 * max(ext_w, ext_h)) / (ext_h + 0.45 * max(ext_w, ext_h))))
    left = 5.0
    width = left + plan_w + 0.2
    fig = new_figure(width, height)
    ax_m = fig.add_axes((0.2 / width, 0.45, (left - 0.4) / width, 0.5 - top / height))
    ax_t = fig.add_axes((0.1 / width, 0.02, (left - 0.2) / width, 0.40))
    ax = fig.add_axes((left / width, 0.1 / height, plan_w / width, plan_h / height))
    ax_t.axis("off")
    ax_m.set_aspect("equal", adjustable="box")
    draw_mechanism(ax_m, s, pl.position.index, color="k", lw=1.4)
    ax_m.axis("off")
    mu_l = s.scheme_scale
    ax_m.set_title(tr(lang, "position {label}").format(label=label_tex(pl.position.label)) +
                   f", φ = {num(math.degrees(pl.position.phi), lang, decimals=1)}°".replace("φ", r"$\varphi$"), fontsize=10)
    del mu_l
    drawn = set()
    for v in plan.vectors:
        a, b = pts[v.start], pts[v.end]
        if abs(b - a) < 1e-9 or (v.start, v.end) in drawn:
            continue
        drawn.add((v.start, v.end))
        colour, ls = VECTOR_STYLE[_kind(v.symbol, v.start)]
        ax.annotate("", xy=(b.real, b.imag), xytext=(a.real, a.imag), zorder=4,
                    arrowprops=dict(arrowstyle="-|>", color=colour, lw=1.3, ls=ls, shrinkA=0, shrinkB=0, mutation_scale=11))
    size = max(float(np.max(np.abs(xy))), 1e-9)
    centre = xy.mean()
    placed: list[complex] = []
    pole = plan.pole
    for n in sorted(pts, key=lambda q: q != pole):
        z = pts[n]
        if any(abs(z - q) < 0.02 * size for q in placed):
            continue
        group = [q for q in pts if abs(pts[q] - z) < 0.02 * size]
        group.sort(key=lambda q: q != pole)
        names = [point_tex(q) for q in group]
        if pole in group:
            names += [f"${joint_tex(f)}$" for f in plan.at_pole]
        d = away(z, [q for q in xy if abs(q - z) >= 0.02 * size], centre)
        text = ", ".join(names)
        ax.annotate(text, (z.real, z.imag), xytext=(12 * d.real, 12 * d.imag), textcoords="offset points",
                    ha="left" if d.real > 0.5 else "right" if d.real < -0.5 else "center",
                    va="bottom" if d.imag > 0.5 else "top" if d.imag < -0.5 else "center", fontsize=12, zorder=6)
        ax.plot(z.real, z.imag, "o", ms=2.8, color="k", zorder=5)
        placed.append(z)
    ax.set_aspect("equal", adjustable="box")
    pad = 0.15 * max(float(np.ptp(xy.real)), float(np.ptp(xy.imag)), 1.0)
    ax.set_xlim(xy.real.min() - pad, xy.real.max() + pad)
    ax.set_ylim(xy.imag.min() - 2 * pad, xy.imag.max() + pad)
    ax.axis("off")
    bar = _nice_bar(0.25 * max(ext_w, ext_h))
    x0, y0 = xy.real.min(), xy.imag.min() - 1.5 * pad
    ax.plot([x0, x0 + bar], [y0, y0], color="k", lw=2)
    ax.text(x0 + bar / 2, y0 + 0.25 * pad, f"{num(bar, lang, sig=3)} " + tr(lang, "mm") +
            f" = {num(bar * plan.scale, lang, sig=3)} {unit}", ha="center", va="bottom", fontsize=9)
    mu = num(plan.scale, lang, sig=3)
    scale_unit = tr(lang, "(m/s)/mm") if velocity else tr(lang, "(m/s²)/mm")
    mu_tex = r"$\mu_v$" if velocity else r"$\mu_a$"
    lines = [f"{mu_tex} = {mu} {scale_unit}"]
    for v in plan.vectors:
        if v.magnitude == 0.0 and v.start in ("p", "π"):
            continue
        where = f"  {v.relation} {line_tex(v.line)}" if v.line and v.line not in ("guide", "slot") else (
            f"  {v.relation or '∥'} " + tr(lang, v.line) if v.line in ("guide", "slot") else "")
        lines.append(f"{symbol_tex(book_symbol(s.mechanism, v.symbol))} = {num(v.magnitude, lang, sig=4)} {unit}"
                     f"  ({num(v.magnitude / plan.scale, lang, decimals=1)} " + tr(lang, "mm") + f"){where}")
    cols = 2 if len(lines) > 11 else 1
    per = math.ceil(len(lines) / cols)
    for j in range(cols):
        ax_t.text(0.01 + 0.5 * j, 0.98, "\n".join(lines[j * per:(j + 1) * per]), transform=ax_t.transAxes, ha="left",
                  va="top", fontsize=8.5 if cols == 1 else 7.5, linespacing=1.45)
    label = pl.position.label
    label = label_tex(label)
    title = (tr(lang, "Velocity plan (pole p), position {label}").format(label=label)
             if velocity else
             tr(lang, "Acceleration plan (pole π), position {label}").format(label=label))
    suptitle(fig, title, fontsize=11)
    return fig


FIGURES = ("linkage_mechanism", "linkage_diagrams", "linkage_velocity_plan", "linkage_acceleration_plan",
           "linkage_velocity_plan_2", "linkage_acceleration_plan_2")


def mechanism_figures(s: Sheet1, lang: str, names=None) -> dict:
    """The figures of :data:`FIGURES` (those of a second plan position only if there is one)."""
    want = set(names) if names is not None else set(FIGURES)
    out = {}
    if "linkage_mechanism" in want:
        out["linkage_mechanism"] = scheme_figure(s, lang)
    if "linkage_diagrams" in want:
        out["linkage_diagrams"] = diagrams_figure(s, lang)
    for j, pl in enumerate(s.plans):
        tail = "" if j == 0 else f"_{j + 1}"
        for kind in ("velocity", "acceleration"):
            name = f"linkage_{kind}_plan{tail}"
            if name in want:
                out[name] = plan_figure(s, pl, kind, lang)
    return out
