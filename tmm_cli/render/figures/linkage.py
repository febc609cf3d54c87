"""Figures of sheet 1 (the slotted-link mechanism), matplotlib Figure objects (no pyplot).

- linkage_mechanism: the mechanism at the N crank positions with the ram's path, the strokes;
- linkage_diagrams: the ram's x_C, v_C, a_C against the crank angle from position 0;
- linkage_velocity_plan, linkage_acceleration_plan: the plans at `--at` (poles p and π, points
  labelled as in a Russian TMM textbook), beside the mechanism in that position.

Everything drawn is read from the result object; nothing is recomputed here. matplotlib is
imported inside :func:`linkage_figures` only.
"""

from __future__ import annotations

import math
import re

import numpy as np

from ...i18n import tr
from ...i18n.numbers import num
from ...linkage.analysis import LinkageResult, State

C_WORK = "#1f77b4"
C_RET = "#d62728"
C_AT = "#2ca02c"
GREY = "#9a9a9a"


def _tex(name: str) -> str:
    """'a^k_A4A2' -> '$a^{k}_{A_4A_2}$' (mathtext with real subscripts)."""
    m = re.fullmatch(r"([a-z])(?:\^(\w|τ))?_(\w+)", name)
    if not m:
        return name
    base, sup, sub = m.groups()
    sub = re.sub(r"([A-Z])(\d)", r"\1_\2", sub)
    sup = {"τ": r"\tau"}.get(sup, sup)
    return f"${base}" + (f"^{{{sup}}}" if sup else "") + f"_{{{sub}}}$"


def _pt_label(name: str) -> str:
    """Plan point names as mathtext: 'a4' -> '$a_4$', 'π' -> '$\\pi$'."""
    if name == "π":
        return r"$\pi$"
    m = re.fullmatch(r"([a-z])(\d)", name)
    return f"${m.group(1)}_{m.group(2)}$" if m else f"${name}$"


def _mm(p) -> tuple[float, float]:
    return (float(p[0]) * 1000.0, float(p[1]) * 1000.0)


def _ground(ax, x: float, y: float, size: float) -> None:
    """A fixed pivot: a small triangle with a hatched base (mm)."""
    from matplotlib.patches import Polygon

    ax.add_patch(Polygon([(x, y), (x - size, y - 1.6 * size), (x + size, y - 1.6 * size)], closed=True, fill=False, lw=1.0, zorder=4))
    base = y - 1.6 * size
    ax.plot([x - 1.6 * size, x + 1.6 * size], [base, base], color="k", lw=1.0, zorder=4)
    for t in np.linspace(-1.4, 1.4, 6):
        ax.plot([x + t * size, x + (t - 0.4) * size], [base, base - 0.6 * size], color="k", lw=0.6, zorder=4)


def _mechanism(ax, r: LinkageResult, s: State, color="k", lw=1.8, ls="-", labels=True, slider=True, scale=1.0):
    """The mechanism in the state `s`: crank, slotted link, block, rod, ram (mm)."""
    from matplotlib.patches import Rectangle

    g = r.geometry
    o41 = (-g.c * 1000, -g.h * 1000)
    a, b = _mm(s.a), _mm(s.b)
    c = (s.x_c * 1000, g.b * 1000)
    u = (math.sin(s.link), math.cos(s.link))
    reach = max(s.rho, g.r2) * 1000 * 1.04
    end = (o41[0] + reach * u[0], o41[1] + reach * u[1])
    ax.plot([0, a[0]], [0, a[1]], color=color, lw=lw, ls=ls, zorder=5)
    ax.plot([o41[0], end[0]], [o41[1], end[1]], color=color, lw=lw, ls=ls, zorder=5)
    ax.plot([b[0], c[0]], [b[1], c[1]], color=color, lw=lw, ls=ls, zorder=5)
    blk = 0.09 * g.r1 * 1000 * scale
    ang = -math.degrees(s.link) + 90.0  # the block lies along the link
    ax.add_patch(Rectangle((a[0] - blk, a[1] - blk / 2), 2 * blk, blk, angle=ang, rotation_point="center",
                           fill=True, fc="white", ec=color, lw=lw * 0.7, ls=ls, zorder=6))
    for p in (a, b, (0.0, 0.0), o41):
        ax.plot(*p, "o", ms=4 * scale, mfc="white", mec=color, zorder=7)
    if slider:
        w, hgt = 0.35 * g.r1 * 1000 * scale, 0.16 * g.r1 * 1000 * scale
        ax.add_patch(Rectangle((c[0] - w / 2, c[1] - hgt / 2), w, hgt, fill=True, fc="white", ec=color, lw=lw * 0.7, ls=ls, zorder=6))
        ax.plot(*c, "o", ms=4 * scale, mfc="white", mec=color, zorder=7)
    if labels:
        off = 0.08 * g.r1 * 1000
        ax.annotate("$A$", a, xytext=(6, 4), textcoords="offset points", fontsize=11, zorder=8)
        ax.annotate("$B$", b, xytext=(6, 4), textcoords="offset points", fontsize=11, zorder=8)
        ax.annotate("$C$", c, xytext=(-4, 8), textcoords="offset points", fontsize=11, ha="right", zorder=8)
        ax.annotate("$O_{21}$", (0, 0), xytext=(7, -2), textcoords="offset points", fontsize=11, zorder=8)
        ax.annotate("$O_{41}$", o41, xytext=(7, -4), textcoords="offset points", fontsize=11, zorder=8)
        _ground(ax, 0.0, -off * 0.3, off * 0.7)
        _ground(ax, o41[0], o41[1] - off * 0.3, off * 0.7)


def _guide(ax, r: LinkageResult, x0: float, x1: float) -> None:
    y = r.geometry.b * 1000
    ax.plot([x0, x1], [y, y], color="k", lw=0.8, ls=(0, (12, 3, 2, 3)), zorder=2)


def _arc(ax, radius: float, start: float, sweep: float, **kw):
    t = start + np.linspace(0.0, sweep, 200)
    return ax.plot(radius * np.sin(t), radius * np.cos(t), **kw)


def _mechanism_figure(Figure, r: LinkageResult, lang: str):
    g = r.geometry
    r1 = g.r1 * 1000
    fig = Figure(figsize=(12, 8), layout="constrained")
    ax = fig.subplots()
    ax.set_aspect("equal")
    # paths: crank circle, B's path, the ram's path on the guide
    _arc(ax, r1, 0.0, 2 * math.pi, color=GREY, lw=0.8, ls="--")
    bpath = r.curve.b * 1000
    ax.plot(bpath[:, 0], bpath[:, 1], color=GREY, lw=0.8, ls="--")
    xmin, xmax = r.x_min * 1000, r.x_max * 1000
    y_guide = g.b * 1000
    lo = min(xmin, float(bpath[:, 0].min()), -r1) - 0.15 * r1
    hi = max(xmax, float(bpath[:, 0].max()), r1) + 0.15 * r1
    side = 1.0 if g.b >= 0 else -1.0  # labels and the stroke's dimension go on the side away from the crank
    _guide(ax, r, lo, hi)
    ax.plot([xmin, xmax], [y_guide, y_guide], color="k", lw=3.5, solid_capstyle="butt", zorder=3)
    # the N positions
    n = len(r.positions)
    c_labels = []
    for k, s in enumerate(r.positions):
        a, b = _mm(s.a), _mm(s.b)
        c = (s.x_c * 1000, y_guide)
        o41 = (-g.c * 1000, -g.h * 1000)
        u = (math.sin(s.link), math.cos(s.link))
        reach = max(s.rho, g.r2) * 1000
        ax.plot([0, a[0]], [0, a[1]], color=GREY, lw=0.7, zorder=2)
        ax.plot([o41[0], o41[0] + reach * u[0]], [o41[1], o41[1] + reach * u[1]], color=GREY, lw=0.7, zorder=2)
        ax.plot([b[0], c[0]], [b[1], c[1]], color=GREY, lw=0.7, zorder=2)
        for p in (a, b, c):
            ax.plot(*p, "o", ms=2.5, color="k", zorder=3)
        ra = math.hypot(*a) or 1.0
        ax.annotate(str(k), a, xytext=(a[0] / ra * 12, a[1] / ra * 12), textcoords="offset points", ha="center",
                    va="center", fontsize=8, color="k")
        rb = math.hypot(b[0] - o41[0], b[1] - o41[1]) or 1.0
        ax.annotate(str(k), b, xytext=((b[0] - o41[0]) / rb * 10, (b[1] - o41[1]) / rb * 10), textcoords="offset points",
                    ha="center", va="center", fontsize=7, color="#555555")
        c_labels.append((c[0], k))
    # labels of C below the guide, stacked where they crowd
    c_labels.sort()
    rows: list[float] = []
    span = max(xmax - xmin, 1e-9)
    for x, k in c_labels:
        row = 0
        while row < len(rows) and x - rows[row] < 0.06 * span:
            row += 1
        if row == len(rows):
            rows.append(x)
        else:
            rows[row] = x
        ax.annotate(str(k), (x, y_guide), xytext=(0, side * (10 + 9 * row)), textcoords="offset points", ha="center",
                    va="bottom" if side > 0 else "top", fontsize=7)
    # position 0 (start of the working stroke) bold, the other dead position dashed
    _mechanism(ax, r, r.positions[0], color="k", lw=1.8)
    other = r.dead_state
    _mechanism(ax, r, other, color="k", lw=1.2, ls="--", labels=False)
    a2 = _mm(other.a)
    ra = math.hypot(*a2) or 1.0
    ax.annotate("0′", a2, xytext=(a2[0] / ra * 12 + 8, a2[1] / ra * 12), textcoords="offset points", ha="center", va="center", fontsize=8)
    # strokes on the crank circle
    _arc(ax, 1.28 * r1, r.dead[0], r.working_rad, color=C_WORK, lw=2.0)
    _arc(ax, 1.18 * r1, r.dead[1], r.return_rad, color=C_RET, lw=2.0)
    mid_w = r.dead[0] + r.working_rad / 2
    mid_r = r.dead[1] + r.return_rad / 2
    for rad, mid in ((1.62 * r1, mid_w), (1.58 * r1, mid_r)):
        ax.plot(rad * math.sin(mid), rad * math.cos(mid), alpha=0.0)  # keep the labels inside the axes
    ax.text(1.45 * r1 * math.sin(mid_w), 1.45 * r1 * math.cos(mid_w),
            tr(lang, "working stroke") + "\n" + tr(lang, "$\\varphi_w$") + f" = {num(math.degrees(r.working_rad), lang, decimals=1)}°",
            color=C_WORK, ha="center", va="center", fontsize=9)
    ax.text(1.40 * r1 * math.sin(mid_r), 1.40 * r1 * math.cos(mid_r),
            tr(lang, "return stroke") + "\n" + tr(lang, "$\\varphi_r$") + f" = {num(math.degrees(r.return_rad), lang, decimals=1)}°",
            color=C_RET, ha="center", va="center", fontsize=9)
    # direction of rotation: φ21 grows (clockwise on the page)
    from matplotlib.patches import FancyArrowPatch

    t0, t1 = math.radians(-35), math.radians(35)
    rr = 0.35 * r1
    ax.add_patch(FancyArrowPatch((rr * math.sin(t0), rr * math.cos(t0)), (rr * math.sin(t1), rr * math.cos(t1)),
                                 connectionstyle="arc3,rad=-0.35", arrowstyle="-|>", mutation_scale=12, color="k", lw=1.0))
    ax.text(0, rr * 1.25, r"$\omega_{21}$", ha="center", va="bottom", fontsize=11)
    # stroke H dimension above the guide
    yd = y_guide + side * (0.25 * r1 + 0.12 * r1 * len(rows))
    ax.annotate("", (xmin, yd), (xmax, yd), arrowprops=dict(arrowstyle="<|-|>", lw=0.8, color="k", shrinkA=0, shrinkB=0))
    for x in (xmin, xmax):
        ax.plot([x, x], [y_guide, yd + side * 0.05 * r1], color="k", lw=0.5)
    ax.text((xmin + xmax) / 2, yd + side * 0.04 * r1, f"$H$ = {num(r.stroke * 1000, lang, decimals=2)} " + tr(lang, "mm"),
            ha="center", va="bottom" if side > 0 else "top", fontsize=10)
    ax.plot([xmin, xmax], [yd + side * 0.3 * r1] * 2, alpha=0.0)  # room for the text
    regime = tr(lang, "Whitworth mechanism (the link turns fully)") \
        if r.regime == "whitworth" else tr(lang, "crank-shaper (the link swings)")
    ax.set_title(tr(lang, "Mechanism in {n} positions: {regime}; K = {time_ratio}").format(n=n, regime=regime, time_ratio=num(r.time_ratio, lang, decimals=4)), fontsize=11)
    ax.set_xlabel("x, " + tr(lang, "mm"))
    ax.set_ylabel("y, " + tr(lang, "mm"))
    ax.grid(alpha=0.2)
    ax.margins(0.06)
    box = ax.dataLim
    fig.set_size_inches(12, min(12.0, max(5.0, 11 * box.height / max(box.width, 1e-9) + 1.3)))
    return fig


def _diagrams_figure(Figure, r: LinkageResult, lang: str):
    c = r.curve
    fig = Figure(figsize=(9, 9.5), layout="constrained")
    axes = fig.subplots(3, 1, sharex=True)
    x = np.degrees(c.phi_from_start)
    w = math.degrees(r.working_rad)
    n = len(r.positions)
    pos_x = [360.0 * k / n for k in range(n)]
    series = [
        (c.x_c * 1000, r"$x_C$, " + tr(lang, "mm"), [s.x_c * 1000 for s in r.positions]),
        (c.v_c, r"$v_C$, " + tr(lang, "m/s"), [s.v_c for s in r.positions]),
        (c.a_c, r"$a_C$, " + tr(lang, "m/s²"), [s.a_c for s in r.positions]),
    ]
    at_x = math.degrees((r.at.phi - r.dead[0]) % (2 * math.pi))
    for k, (ax, (y, label, pts)) in enumerate(zip(axes, series)):
        ax.axvspan(0, w, color=C_WORK, alpha=0.06, lw=0)
        ax.axvspan(w, 360, color=C_RET, alpha=0.06, lw=0)
        ax.axvline(w, color="k", lw=0.6, ls=":")
        ax.axvline(at_x, color=C_AT, lw=0.8, ls="--")
        ax.plot(x, y, color="k", lw=1.4)
        ax.plot(pos_x, pts, "o", ms=3.5, color="tab:orange")
        if k:
            ax.axhline(0, color="k", lw=0.5)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
        if k == 0:
            for px, py, i in zip(pos_x, pts, range(n)):
                ax.annotate(str(i), (px, py), xytext=(0, 6), textcoords="offset points", ha="center", fontsize=7)
            ax.text(w / 2, 0.97, tr(lang, "working stroke"), transform=ax.get_xaxis_transform(),
                    ha="center", va="top", fontsize=8, color=C_WORK)
            ax.text((w + 360) / 2, 0.97, tr(lang, "return stroke"), transform=ax.get_xaxis_transform(),
                    ha="center", va="top", fontsize=8, color=C_RET)
            ax.text(at_x, 0.03, f" $\\varphi_{{21}}$ = {num(math.degrees(r.at.phi), lang, decimals=1)}°", transform=ax.get_xaxis_transform(),
                    fontsize=8, color=C_AT)
    axes[-1].set_xlim(0, 360)
    axes[-1].set_xticks(np.arange(0, 361, 30))
    start = num(math.degrees(r.dead[0]), lang, decimals=2)
    axes[-1].set_xlabel(tr(lang, "crank angle from position 0 ($\\varphi_{{21}}$ = {start}°), °").format(start=start))
    rpm = num(r.rpm, lang, sig=4)
    fig.suptitle(tr(lang, "Ram C: position, velocity, acceleration (n21 = {rpm} rpm)").format(rpm=rpm), fontsize=11)
    return fig


PLAN_STYLE = {
    # kind of segment -> colour, line style
    "abs": ("k", "-"),
    "rel": ("#1f77b4", "-"),
    "cor": ("#d62728", "-"),
    "n": ("#2ca02c", "--"),
    "t": ("#ff7f0e", "--"),
}


def _seg_kind(name: str) -> str:
    if "^k" in name:
        return "cor"
    if "^r" in name:
        return "rel"
    if "^n" in name:
        return "n"
    if "^τ" in name:
        return "t"
    if name in ("v_A4A2", "v_CB"):
        return "rel"
    return "abs"


def _nice(x: float) -> float:
    if x <= 0:
        return 1.0
    e = math.floor(math.log10(x))
    for m in (1, 2, 5, 10):
        if m * 10 ** e >= x:
            return m * 10 ** e
    return 10 ** (e + 1)  # pragma: no cover


def _plan_figure(Figure, r: LinkageResult, plan, lang: str):
    velocity = plan.kind == "velocity"
    unit = tr(lang, "m/s") if velocity else tr(lang, "m/s²")
    fig = Figure(figsize=(12, 7), layout="constrained")
    grid = fig.add_gridspec(2, 2, width_ratios=[1, 1.3], height_ratios=[1.1, 1])
    ax_m, ax_t, ax = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[1, 0]), fig.add_subplot(grid[:, 1])
    ax_t.axis("off")
    # the mechanism at the plan's position
    ax_m.set_aspect("equal")
    g = r.geometry
    _arc(ax_m, g.r1 * 1000, 0.0, 2 * math.pi, color=GREY, lw=0.8, ls="--")
    _guide(ax_m, r, min(r.x_min * 1000, -g.r1 * 1000) - 20, max(r.x_max * 1000, g.r1 * 1000) + 20)
    _mechanism(ax_m, r, r.at, color="k", lw=1.6)
    ax_m.set_title(tr(lang, "Mechanism at $\\varphi_{{21}}$ = {phi}°").format(phi=num(math.degrees(r.at.phi), lang, decimals=2)), fontsize=10)
    ax_m.set_xlabel("x, " + tr(lang, "mm"))
    ax_m.grid(alpha=0.2)
    ax_m.margins(0.08)

    pts = plan.points
    drawn = []
    for a, b, name in plan.segments:
        if plan.length(a, b) < 1e-12:
            continue
        if not velocity and r.eps == 0.0 and name == "a^n_A2":
            continue  # n1 coincides with a2 for a uniform crank: πa2 is drawn instead
        colour, ls = PLAN_STYLE[_seg_kind(name)]
        ax.annotate("", xy=pts[b], xytext=pts[a], zorder=4,
                    arrowprops=dict(arrowstyle="-|>", color=colour, lw=1.4, ls=ls, shrinkA=0, shrinkB=0, mutation_scale=12))
        drawn.append((name, a, b, colour))
    used = {p for p in pts if velocity or r.eps != 0.0 or p != "n1"}  # every point, also where vectors vanish
    xy = np.array([pts[p] for p in used])
    centre = xy.mean(axis=0)
    size = float(np.max(np.ptp(xy, axis=0))) or 1.0
    placed: list[tuple[float, float]] = []
    for p in sorted(used, key=lambda q: q not in ("p", "π")):
        x, y = pts[p]
        if any(math.hypot(x - qx, y - qy) < 0.015 * size for qx, qy in placed):
            continue  # coincides with a point already labelled
        group = [q for q in used if math.hypot(pts[q][0] - x, pts[q][1] - y) < 0.015 * size]
        label = ", ".join(_pt_label(q) for q in sorted(group, key=lambda q: q not in ("p", "π")))
        d = np.array([x, y]) - centre
        nd = float(np.hypot(*d)) or 1.0
        ax.annotate(label, (x, y), xytext=(d[0] / nd * 12, d[1] / nd * 12), textcoords="offset points", ha="center",
                    va="center", fontsize=13, zorder=6)
        ax.plot(x, y, "o", ms=3, color="k", zorder=5)
        placed.append((x, y))
    ax.set_aspect("equal")
    ax.axis("off")
    pad = 0.12 * size
    ax.set_xlim(xy[:, 0].min() - pad, xy[:, 0].max() + pad)
    ax.set_ylim(xy[:, 1].min() - 2.2 * pad, xy[:, 1].max() + pad)
    # scale bar
    bar = _nice(size / 4)
    x0, y0 = xy[:, 0].min(), xy[:, 1].min() - 1.6 * pad
    ax.plot([x0, x0 + bar], [y0, y0], color="k", lw=2)
    ax.text(x0 + bar / 2, y0 + 0.2 * pad, f"{num(bar, lang, sig=3)} {unit}", ha="center", va="bottom", fontsize=9)
    # magnitudes
    lines = [f"{_tex(name)} = {num(plan.length(a, b), lang, decimals=4)} {unit}" for name, a, b, _ in drawn]
    if not velocity:
        lines.append(r"$a^k_{A_4A_2} = 2\,\omega_4\,v_{A_4A_2}$")
    ax_t.text(0.02, 0.98, "\n".join(lines), transform=ax_t.transAxes, ha="left", va="top", fontsize=10, linespacing=1.5)
    phi = num(math.degrees(r.at.phi), lang, decimals=2)
    if velocity:
        title = tr(lang, "Velocity plan (pole p), $\\varphi_{{21}}$ = {phi}°").format(phi=phi)
    else:
        title = tr(lang, "Acceleration plan (pole π), $\\varphi_{{21}}$ = {phi}°").format(phi=phi)
    ax.set_title(title, fontsize=11)
    return fig


def linkage_figures(result: LinkageResult, lang: str) -> dict:
    """Figures 'linkage_mechanism', 'linkage_diagrams', 'linkage_velocity_plan', 'linkage_acceleration_plan'."""
    from matplotlib.figure import Figure

    return {
        "linkage_mechanism": _mechanism_figure(Figure, result, lang),
        "linkage_diagrams": _diagrams_figure(Figure, result, lang),
        "linkage_velocity_plan": _plan_figure(Figure, result, result.plans.velocity, lang),
        "linkage_acceleration_plan": _plan_figure(Figure, result, result.plans.acceleration, lang),
    }
