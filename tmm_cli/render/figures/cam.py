"""The four fields of sheet 3 as matplotlib figures (no pyplot, no global state).

matplotlib is imported inside :func:`cam_figures` only, so importing this module stays cheap.
"""

from __future__ import annotations

import math

import numpy as np

from ...cam.design import CamResult
from ...i18n import tr, trc
from .kit import (
    bare_xaxis,
    bottom_legend,
    copying_ticks,
    decimal_commas,
    fmt,
    legend_height,
    mt,
    new_figure,
    suptitle,
    title_height,
)

C_RISE = "#1f77b4"
C_RET = "#d62728"
C_DWELL = "#7f7f7f"
C_ZONE = "#2ca02c"
C_BOOK = "#9467bd"


def _phase_marks(ax, r: CamResult, lang: str, labels: bool = False) -> None:
    """The four phases as faint bands over the whole height, dotted lines at their bounds, and
    (`labels`) their names at the top: one collection for the bands and one line for the bounds
    (a zero-length phase adds neither a band nor a second line at its bound)."""
    from matplotlib.collections import PolyCollection
    from matplotlib.lines import Line2D

    v = r.variant
    bounds = [0.0, v.phi_rise_deg, v.phi_rise_deg + v.phi_far_dwell_deg, v.phi_working_deg, 360.0]
    names = [trc(lang, "figure, short", "rise"), trc(lang, "figure, short", "far dwell"), trc(lang, "figure, short", "return"), trc(lang, "figure, short", "near dwell")]
    colors = [C_RISE, C_DWELL, C_RET, C_DWELL]
    bands, band_colors = [], []
    for i in range(4):
        a, b = bounds[i], bounds[i + 1]
        if b - a <= 0:
            continue
        bands.append([(a, 0.0), (b, 0.0), (b, 1.0), (a, 1.0), (a, 0.0)])  # as axvspan's Rectangle
        band_colors.append(colors[i])
        if labels and b - a >= 25:
            ax.text((a + b) / 2, 0.97, names[i], transform=ax.get_xaxis_transform(), ha="center", va="top", fontsize=8, color=colors[i])
    ax.add_collection(PolyCollection(bands, facecolors=band_colors, alpha=0.06, linewidths=0, zorder=1,
                                     transform=ax.get_xaxis_transform()), autolim=False)
    xs = sorted(set(bounds[1:4]))
    ax.add_artist(Line2D(np.repeat(xs, 3), np.tile([0.0, 1.0, np.nan], len(xs)), color="k", lw=0.6, ls=":",
                         transform=ax.get_xaxis_transform()))


def _motion_figure(r: CamResult, lang: str):
    v, m = r.variant, r.motion
    f = fmt(lang)
    W, H = 9.0, 9.5
    fig = new_figure(W, H)
    top = title_height(2) + 0.62  # two-line title, then the time axis with its label
    fig.subplots_adjust(left=0.95 / W, right=1 - 0.2 / W, bottom=0.5 / H, top=1 - top / H, hspace=0.055)
    axes = fig.subplots(3, 1)
    for ax in axes[:-1]:  # the upper panels show the bottom panel's φ scale as grid lines only
        ax.sharex(axes[-1])
        bare_xaxis(ax, np.arange(0, 361, 30), grid_alpha=0.3)
    deg = np.degrees(m.phi)
    rows = [(x.phi_deg, x) for x in m.table]
    if v.is_rocker:
        l_mm = v.l_bc_m * 1000
        series = [
            (np.degrees(m.s), "γ, °", mt(tr(lang, "γ (S_B = γ·l_BC, l_BC = {l_mm} mm)").format(l_mm=f(l_mm))), [math.degrees(x.s) for _, x in rows]),
            (m.v, tr(lang, "ω, rad/s"), "ω = dγ/dt", [x.v for _, x in rows]),
            (m.a, tr(lang, "ε, rad/s²"), "ε = dω/dt", [x.a for _, x in rows]),
        ]
    else:
        series = [
            (m.s * 1000, tr(lang, "S, mm"), "S", [x.s * 1000 for _, x in rows]),
            (m.v, tr(lang, "V, m/s"), "V = dS/dt", [x.v for _, x in rows]),
            (m.a, tr(lang, "a, m/s²"), "a = dV/dt", [x.a for _, x in rows]),
        ]
    xs = [p for p, _ in rows]
    for k, (ax, (y, ylabel, name, pts)) in enumerate(zip(axes, series)):
        _phase_marks(ax, r, lang, labels=(k == 0))
        # break the line at jumps of the acceleration so that it is drawn as a step
        yy = np.array(y, dtype=float)
        if k == 2:
            jump = np.abs(np.diff(yy)) > 0.2 * (np.abs(yy).max() + 1e-30)
            yy = yy.copy()
            xx = deg.copy()
            ins = np.nonzero(jump)[0] + 1
            xx = np.insert(xx, ins, np.nan)
            yy = np.insert(yy, ins, np.nan)
            ax.plot(xx, yy, color="k", lw=1.4, label=name)
        else:
            ax.plot(deg, yy, color="k", lw=1.4, label=name)
        ax.plot(xs, pts, "o", ms=3, color="tab:orange", label=tr(lang, "table positions"))
        ax.axhline(0, color="k", lw=0.5)
        ax.set_ylabel(ylabel)
        (ax.grid if k == 2 else ax.yaxis.grid)(alpha=0.3)  # ax.grid would make a Tick on a bare x axis
        ax.legend(loc="lower right" if k == 0 else "upper right", fontsize=8, framealpha=0.85)
    axes[-1].set_xlabel(tr(lang, "cam angle φ, °"))
    axes[-1].set_xlim(0, 360)
    axes[-1].set_xticks(np.arange(0, 361, 30))
    w = m.omega
    top = axes[0].secondary_xaxis("top", functions=(lambda d: np.radians(d) / w * 1000.0, lambda t: np.degrees(np.asarray(t) / 1000.0 * w)))
    copying_ticks(top)
    top.set_xlabel(tr(lang, "time t, ms"))
    law = tr(lang, "law {law}").format(law=v.law)
    suptitle(fig, mt(tr(lang, "Variant {number}: follower motion diagrams\n({law}, n_k = {n_cam_rpm} rpm)").format(number=v.number, law=law, n_cam_rpm=f(v.n_cam_rpm, minus='−'))))
    return fig


def _zone_figure(r: CamResult, lang: str):
    from matplotlib.patches import Polygon

    v, z = r.variant, r.sizing
    zn = z.zone
    f = fmt(lang)
    fig = new_figure(8.5, 9.5)
    ax = fig.add_axes((0, 0, 1, 1))  # placed below, once the legend's size is known
    k = 1000.0
    b, d = zn.b * k, zn.d * k
    rise = zn.phase == 0
    ret = zn.phase == 2
    o = np.array(z.centre) * k
    bv = np.array(z.book_centre) * k
    pts = [b, d, o[None], bv[None], np.zeros((1, 2))]
    if z.pivot is not None:
        pts.append(np.array(z.pivot)[None] * k)
    allp = np.concatenate(pts)
    lo, hi = allp.min(axis=0), allp.max(axis=0)
    span0 = max(hi - lo) + 1e-9
    lo = np.minimum(lo, o - np.array([0.0, 0.45 * span0]))  # show the zone below the centre
    span = max(hi - lo) * 1.12 + 1e-9
    mid = (lo + hi) / 2
    xlim = (mid[0] - span / 2, mid[0] + span / 2)
    ylim = (mid[1] - span / 2, mid[1] + span / 2)

    ax.add_patch(Polygon(zn.polygon * k, closed=True, facecolor=C_ZONE, alpha=0.15, edgecolor=C_ZONE, lw=1.0, label=mt(tr(lang, "feasible zone (ν ≤ ν_max everywhere)"))))
    ax.plot(b[rise, 0], b[rise, 1], color="k", lw=1.2, label=tr(lang, "roller-centre path B"))
    ax.plot(d[rise, 0], d[rise, 1], color=C_RISE, lw=1.6, label=tr(lang, "D-curve, rise"))
    ls = "-" if z.closure == "form" else "--"
    lab = tr(lang, "D-curve, return") + ("" if z.closure == "form" else tr(lang, " (not constrained)"))
    ax.plot(d[ret, 0], d[ret, 1], color=C_RET, lw=1.4, ls=ls, label=lab)
    # a few segments B_i D_i
    seg = np.concatenate([idx[:: max(1, len(idx) // 8)] for idx in (np.nonzero(rise)[0], np.nonzero(ret)[0])])
    ax.add_collection(_segments(np.stack([b[seg], d[seg]], axis=1), color="0.5", lw=0.6), autolim=False)
    # the book's bounding lines
    for L in zn.lines:
        p0 = np.array(L.point) * k
        dd = np.array(L.direction)
        t = np.linspace(-3 * span, 3 * span, 2)
        ax.plot(p0[0] + t * dd[0], p0[1] + t * dd[1], color=C_BOOK, lw=1.0, ls="-.")
        # label the line where it enters the window
        q = p0 + np.linspace(-3 * span, 3 * span, 400)[:, None] * dd
        inside = np.nonzero((xlim[0] + 0.04 * span < q[:, 0]) & (q[:, 0] < xlim[1] - 0.2 * span)
                            & (ylim[0] + 0.04 * span < q[:, 1]) & (q[:, 1] < ylim[1] - 0.04 * span))[0]
        if len(inside):
            qx, qy = q[inside[0]]
            ax.text(qx, qy, " " + tr(lang, "line ") + L.name, color=C_BOOK, fontsize=11, weight="bold", va="bottom")
    ax.plot([], [], color=C_BOOK, lw=1.0, ls="-.", label=mt(tr(lang, "book's bounding lines (ν_max)")))
    ax.plot([0, o[0]], [0, o[1]], color="k", lw=1.0, ls="--")
    ax.plot(*o, marker="*", ms=16, color=C_ZONE, mec="k", ls="none", zorder=5, label=mt(tr(lang, "chosen centre O: r_0 = {v} mm").format(v=f(z.r0_m * k, decimals=2))))
    book_nu = f(max(z.book_nu_rise_max_deg, z.book_nu_return_max_deg if z.closure == "form" else 0), decimals=1)
    ax.plot(*bv, marker="X", ms=10, color=C_BOOK, mec="k", ls="none", label=mt(tr(lang, "book's vertex: r_0 = {v} mm, ν ≤ {book_nu}°").format(v=f(z.book_r0_m * k, decimals=2), book_nu=book_nu)))
    ax.plot(0, 0, "o", color="k", ms=5)
    ax.annotate("B₀", (0, 0), textcoords="offset points", xytext=(6, 4), fontsize=11)
    ax.annotate("O", o, textcoords="offset points", xytext=(8, -12), fontsize=11)
    ax.text(o[0] / 2, o[1] / 2, " " + mt(f"r_0 = {f(z.r0_m * k, decimals=1)}"), fontsize=9, rotation=0, ha="left")
    if z.pivot is not None:
        c = np.array(z.pivot) * k
        ax.plot(*c, "s", color="k", ms=6)
        ax.annotate("C", c, textcoords="offset points", xytext=(6, 6), fontsize=11)
        ax.plot([o[0], c[0]], [o[1], c[1]], color="tab:brown", lw=1.2, label=mt(tr(lang, "l_OC = {v} mm").format(v=f(z.l_oc_m * k, decimals=2))))
        ax.plot([c[0], 0], [c[1], 0], color="k", lw=2.0, alpha=0.6, label=mt(tr(lang, "rocker CB₀, l_BC = {v} mm").format(v=f(v.l_bc_m * k))))
    else:
        ax.axvline(0, color="k", lw=0.8, ls=":")
        ax.plot([o[0], 0], [o[1], o[1]], color="tab:brown", lw=1.4, label=tr(lang, "offset e = {f} mm").format(f=_signed(f, z.e_m * k)))
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_aspect("equal", adjustable="box")
    ax.grid(alpha=0.3)
    ax.set_xlabel(tr(lang, "x, mm (B₀ at the origin)"))
    ax.set_ylabel(tr(lang, "y, mm (rise direction at B₀ = +y)"))
    rot = tr(lang, "cam turns counter-clockwise") if v.ccw else tr(lang, "cam turns clockwise")
    suptitle(fig, mt(tr(lang, "Variant {number}: zone of the cam centre, ν_max = {nu_max_deg}°\n({rot})").format(number=v.number, nu_max_deg=f(v.nu_max_deg), rot=rot)))
    _square_with_legend(fig, ax)
    return fig


def _profile_figure(r: CamResult, lang: str):
    from matplotlib.collections import PatchCollection
    from matplotlib.patches import Circle, FancyArrowPatch

    v, z, p = r.variant, r.sizing, r.profile
    k = 1000.0
    f = fmt(lang)
    fig = new_figure(8.5, 9.5)
    ax = fig.add_axes((0, 0, 1, 1))  # placed below, once the legend's size is known
    P = p.pitch * k
    th = np.linspace(0, 2 * math.pi, 361)
    r0 = z.r0_m * k
    rp = p.roller_m * k
    ax.plot(r0 * np.cos(th), r0 * np.sin(th), color="0.4", lw=0.8, ls="--", label=mt(tr(lang, "base circle r_0 = {r0} mm").format(r0=f(r0, decimals=2))))
    ax.plot(P[:, 0], P[:, 1], color=C_RISE, lw=1.2, ls="-.", label=tr(lang, "pitch curve T"))
    ax.plot(p.inner[:, 0] * k, p.inner[:, 1] * k, color="k", lw=1.8, label=mt(tr(lang, "working profile D1 (roller r_р = {rp} mm)").format(rp=f(rp, decimals=2))))
    if p.outer is not None:
        ax.plot(p.outer[:, 0] * k, p.outer[:, 1] * k, color="k", lw=1.8, ls="-", alpha=0.7)
        ax.plot([], [], color="k", lw=1.8, alpha=0.7, label=tr(lang, "groove side D2"))
    # inverted follower positions and rollers at the table positions
    n = len(p.phi) - 1
    idxs = [int(round(math.radians(row.phi_deg) / (2 * math.pi) * n)) % n for row in r.motion.table]
    idxs = idxs[:: max(1, len(idxs) // 8)]
    stem = 0.45 * r0
    # the rollers and the follower links as two collections
    ax.add_collection(PatchCollection([Circle(P[i], rp) for i in idxs], facecolors="none", edgecolors="tab:orange",
                                      linewidths=0.9), autolim=False)
    c = P[idxs]
    far = p.pivot_path[idxs] * k if p.pivot_path is not None else c + stem * np.asarray(p.axis_dir)[idxs]
    near = c if p.pivot_path is None else far
    far = far if p.pivot_path is None else c
    ax.add_collection(_segments(np.stack([near, far], axis=1), color="tab:brown", lw=1.0, alpha=0.8), autolim=False)
    if p.pivot_path is not None:
        ax.plot(near[:, 0], near[:, 1], "s", color="tab:brown", ms=3)
    ax.plot([], [], color="tab:orange", lw=0.9, label=tr(lang, "roller at table positions"))
    ax.plot([], [], color="tab:brown", lw=1.0, label=tr(lang, "follower in inverted motion"))
    if p.pivot_path is not None:
        pp = p.pivot_path * k
        ax.plot(pp[:, 0], pp[:, 1], color="tab:brown", lw=0.6, ls=":", label=mt(tr(lang, "pivot circle l_OC = {v} mm").format(v=f(z.l_oc_m * k, decimals=2))))
    else:
        e = abs(z.e_m) * k
        if e > 1e-6:
            ax.plot(e * np.cos(th), e * np.sin(th), color="tab:brown", lw=0.6, ls=":", label=tr(lang, "offset circle |e| = {e} mm").format(e=f(e, decimals=2)))
        # the follower axis in the drawn position (start of rise)
        ax.plot([z.e_m * k, z.e_m * k], [P[0, 1] - 0.2 * r0, P[0, 1] + stem], color="tab:brown", lw=1.6)
    ax.plot([0], [0], "+", color="k", ms=12, mew=1.5)
    ax.annotate("O", (0, 0), textcoords="offset points", xytext=(-12, -14), fontsize=11)
    b0 = P[0]
    ax.plot([0, b0[0]], [0, b0[1]], color="0.2", lw=0.9)
    ax.annotate(mt(f"r_0 = {f(r0, decimals=1)}"), b0 / 2, textcoords="offset points", xytext=(4, 0), fontsize=9)
    ax.annotate("B₀", b0, textcoords="offset points", xytext=(6, -12), fontsize=11)
    # rotation arrow outside the cam
    R = 1.12 * np.max(np.hypot(P[:, 0], P[:, 1])) + rp
    a0, a1 = (math.radians(200), math.radians(250)) if v.ccw else (math.radians(250), math.radians(200))
    arr = FancyArrowPatch((R * math.cos(a0), R * math.sin(a0)), (R * math.cos(a1), R * math.sin(a1)), connectionstyle=f"arc3,rad={0.2 if v.ccw else -0.2}", arrowstyle="-|>", mutation_scale=18, lw=1.6, color="k")
    ax.add_patch(arr)
    am = math.radians(225)
    ax.text(1.12 * R * math.cos(am), 1.12 * R * math.sin(am), mt("ω_k"), fontsize=12, ha="center", va="center")
    lim = 1.3 * R + stem * 0.2
    ax.set_xlim(-lim, lim)
    top = max(lim, float(P[:, 1].max() + stem + rp))
    ax.set_ylim(-lim, top * 1.02)
    if p.pivot_path is not None:
        pp = p.pivot_path * k
        m = float(np.abs(pp).max()) * 1.08
        ax.set_xlim(-max(lim, m), max(lim, m))
        ax.set_ylim(-max(lim, m), max(top, m))
    ax.set_aspect("equal", adjustable="box")
    ax.grid(alpha=0.25)
    ax.set_xlabel(tr(lang, "x, mm (cam frame, centre O at the origin)"))
    ax.set_ylabel("y, " + tr(lang, "mm"))
    mm = tr(lang, "mm")
    dims = f"e = {_signed(f, z.e_m * k)} {mm}" if not v.is_rocker else f"l_OC = {f(z.l_oc_m * k, decimals=2)} {mm}, l_BC = {f(v.l_bc_m * k)} {mm}"
    uc = tr(lang, " — UNDERCUT") if p.undercut else ""
    suptitle(fig, mt(tr(lang, "Variant {number}: cam profile{uc}\nr_0 = {r0} mm, {dims}").format(number=v.number, uc=uc, r0=f(r0, decimals=2), dims=dims)))
    _square_with_legend(fig, ax)
    return fig


def _pressure_figure(r: CamResult, lang: str):
    v, z, p = r.variant, r.sizing, r.profile
    f = fmt(lang)
    W, H = 9.0, 4.8
    fig = new_figure(W, H)
    fig.subplots_adjust(left=0.6 / W, right=1 - 0.2 / W, bottom=0.5 / H, top=1 - (title_height(1) + 0.12) / H)
    ax = fig.subplots()
    deg = np.degrees(p.phi)
    ph = r.motion.program.phase_index(p.phi)
    _phase_marks(ax, r, lang, labels=True)
    rise = np.where(ph == 0, p.nu_deg, np.nan)
    ret = np.where(ph == 2, p.nu_deg, np.nan)
    dwell = np.where((ph == 1) | (ph == 3), p.nu_deg, np.nan)
    ax.plot(deg, rise, color=C_RISE, lw=1.8, label=tr(lang, "rise, max {nu_rise_max_deg}°").format(nu_rise_max_deg=f(z.nu_rise_max_deg, decimals=2)))
    lab = tr(lang, "return, max {nu_return_max_deg}°").format(nu_return_max_deg=f(z.nu_return_max_deg, decimals=2))
    if z.closure == "force":
        lab += tr(lang, " (spring: not limited)")
    ax.plot(deg, ret, color=C_RET, lw=1.8, ls="-" if z.closure == "form" else "--", label=lab)
    ax.plot(deg, dwell, color=C_DWELL, lw=1.0, ls=":", label=tr(lang, "dwells (no motion)"))
    ax.axhline(v.nu_max_deg, color="k", lw=1.2, ls="-.", label=mt(f"ν_max = {f(v.nu_max_deg)}°"))
    ax.set_xlim(0, 360)
    ax.set_xticks(np.arange(0, 361, 30))
    ax.set_ylim(0, max(90.0 if z.closure == "force" else v.nu_max_deg * 1.35, float(np.nanmax(p.nu_deg)) * 1.08))
    ax.set_xlabel(tr(lang, "cam angle φ, °"))
    ax.set_ylabel(tr(lang, "pressure angle ν, °"))
    ax.grid(alpha=0.3)
    ax.legend(loc="upper right", fontsize=8, framealpha=0.9)
    suptitle(fig, tr(lang, "Variant {number}: pressure angle over the cam turn").format(number=v.number))
    return fig


MM_PER_INCH = 25.4
SCALED_MARGIN_MM = (8.0, 8.0, 22.0, 12.0)  # left, right, bottom (scale bar), top (title) on paper
SCALED_MIN_WIDTH_MM = 120.0  # room for the 50 mm bar and its labels
CHECK_BAR_MM = 50.0


def scaled_layout(r: CamResult) -> dict:
    """Paper size [mm] and axes limits [real mm] of the true-to-scale profile (§1.4, Table 1.1).

    The axes fill the figure; 1 mm of paper is k_Sk·1000 mm of the cam on both axes.
    """
    d = r.drawing
    f = d.k_sk * 1000.0  # real mm per paper mm
    x0, x1, y0, y1 = (c * 1000.0 for c in d.bbox_m)
    ml, mr, mb, mt = SCALED_MARGIN_MM
    w_in = (x1 - x0) / f
    extra = max(0.0, SCALED_MIN_WIDTH_MM - (w_in + ml + mr)) / 2.0
    ml, mr = ml + extra, mr + extra
    width = w_in + ml + mr
    height = (y1 - y0) / f + mb + mt
    return {
        "paper_mm": (width, height),
        "xlim": (x0 - ml * f, x0 - ml * f + width * f),
        "ylim": (y0 - mb * f, y0 - mb * f + height * f),
        "real_mm_per_paper_mm": f,
    }


def _scaled_profile_figure(r: CamResult, lang: str):
    """The cam at its standard scale: printed at 100 %, 1 mm on paper = k_Sk m of the cam."""
    from matplotlib.patches import Circle

    v, z, p, d = r.variant, r.sizing, r.profile, r.drawing
    lay = scaled_layout(r)
    w_mm, h_mm = lay["paper_mm"]
    f = lay["real_mm_per_paper_mm"]
    (xa, xb), (ya, yb) = lay["xlim"], lay["ylim"]
    fm = fmt(lang)
    fig = new_figure(w_mm / MM_PER_INCH, h_mm / MM_PER_INCH)
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0))
    ax.set_axis_off()
    k = 1000.0
    P = p.pitch * k
    th = np.linspace(0, 2 * math.pi, 721)
    r0, rp = z.r0_m * k, p.roller_m * k
    ax.plot(r0 * np.cos(th), r0 * np.sin(th), color="0.5", lw=0.4, ls="--")
    ax.plot(P[:, 0], P[:, 1], color="0.3", lw=0.4, ls="-.")
    ax.plot(p.inner[:, 0] * k, p.inner[:, 1] * k, color="k", lw=0.9)
    if p.outer is not None:
        ax.plot(p.outer[:, 0] * k, p.outer[:, 1] * k, color="k", lw=0.9)
    ax.add_patch(Circle(P[0], rp, fill=False, color="k", lw=0.5))
    c = 3.0 * f  # centre marks 3 mm on paper
    for q in (np.zeros(2), P[0]):
        ax.plot([q[0] - c, q[0] + c], [q[1], q[1]], color="k", lw=0.3)
        ax.plot([q[0], q[0]], [q[1] - c, q[1] + c], color="k", lw=0.3)
    ax.plot([0, P[0, 0]], [0, P[0, 1]], color="0.3", lw=0.3)
    if p.pivot_path is not None:  # rocker CB0 at the start of the rise (C may lie off the sheet)
        q = p.pivot_path[0] * k
        ax.plot([q[0], P[0, 0]], [q[1], P[0, 1]], color="0.3", lw=0.5)
        ax.plot(*q, "s", color="0.3", ms=2)
    else:  # follower axis at B0, offset e from O
        ax.plot([z.e_m * k, z.e_m * k], [P[0, 1] - 2 * rp, d.bbox_m[3] * k], color="0.3", lw=0.5, ls="-.")
    ax.text(0, 0, " O", fontsize=7, ha="left", va="top")
    ax.text(*P[0], " B₀", fontsize=7, ha="left", va="bottom")

    # scale bar: 50 mm on paper, ticks every 10 mm, in the bottom strip
    bx, by = xa + 8.0 * f, ya + 12.0 * f
    ax.plot([bx, bx + CHECK_BAR_MM * f], [by, by], color="k", lw=1.0, solid_capstyle="butt")
    for i in range(0, int(CHECK_BAR_MM) + 1, 10):
        ax.plot([bx + i * f, bx + i * f], [by, by + (2.0 if i % 50 else 3.0) * f], color="k", lw=0.5)
    mm = tr(lang, "mm")
    ax.text(bx + CHECK_BAR_MM * f / 2, by - 1.5 * f, f"{CHECK_BAR_MM:g} {mm}", fontsize=6, ha="center", va="top")
    ax.text(bx, by - 6.0 * f, tr(lang, "print at 100 % (no fit to page): the bar must measure 50 mm"), fontsize=5, ha="left", va="top")
    m_sign = tr(lang, "M")
    ax.text(bx + (CHECK_BAR_MM + 6.0) * f, by, f"{m_sign} {d.scale}", fontsize=12, weight="bold", ha="left", va="bottom")
    ax.text(bx + (CHECK_BAR_MM + 6.0) * f, by - 1.5 * f, mt(f"k_Sk = {fm(d.k_sk)} ") + tr(lang, "m/mm"), fontsize=6, ha="left", va="top")
    dims = f"r_0 = {fm(r0, decimals=2)}, r_р = {fm(rp, decimals=2)}, " + (f"l_OC = {fm(z.l_oc_m * k, decimals=2)}, l_BC = {fm(v.l_bc_m * k)}" if v.is_rocker else f"e = {_signed(fm, z.e_m * k)}") + f" {mm}"
    dims += "\n" + (tr(lang, "cam turns counter-clockwise") if v.ccw else tr(lang, "cam turns clockwise"))
    fig.suptitle(
        mt(tr(lang, "Variant {number}: cam profile at {m_sign} {scale} (Table 1.1)\n{dims}").format(number=v.number, m_sign=m_sign, scale=d.scale, dims=dims)),
        y=1.0 - 1.5 / h_mm, va="top", fontsize=6.5,
    )
    ax.set_xlim(xa, xb)
    ax.set_ylim(ya, yb)
    ax.set_aspect("equal", adjustable="box")
    return fig


def cam_figures(result: CamResult, lang: str, names=None) -> dict:
    """Figures "cam_motion", "cam_zone", "cam_profile", "cam_pressure_angle" and "cam_profile_scaled".

    "cam_profile_scaled" is the profile at its standard scale (Table 1.1): a figure whose page is
    the drawing itself, so a PDF/SVG printed at 100 % gives M exactly (check bar 50 mm).
    `names` limits the drawing to some of them (all five by default).
    """
    makers = {
        "cam_motion": _motion_figure,
        "cam_zone": _zone_figure,
        "cam_profile": _profile_figure,
        "cam_pressure_angle": _pressure_figure,
        "cam_profile_scaled": _scaled_profile_figure,
    }
    figs = {name: make(result, lang) for name, make in makers.items() if names is None or name in names}
    for fig in figs.values():
        decimal_commas(fig, lang)
    return figs


def _segments(segs, **kw):
    """Straight segments (N, 2, 2) as one LineCollection drawn as so many separate Line2Ds would be
    (each blended on its own, so crossings look the same; Line2D's caps and joins)."""
    from matplotlib.collections import LineCollection

    return LineCollection(segs, capstyle="projecting", joinstyle="round", zorder=2, **kw)


def _signed(f, x: float) -> str:
    """+1,25 / −1,25 / 0,00: an offset with its sign (the book's e > 0 is to the right of O)."""
    text = f(x, decimals=2, minus="−")
    return text if text.startswith("−") or set(text) <= set("0,.") else "+" + text


def _square_with_legend(fig, ax, ncol: int = 2, fontsize: float = 8.0) -> None:
    """Place the (equal-aspect) axes between the title and a legend block at the bottom."""
    W, H = fig.get_size_inches()
    handles, labels = ax.get_legend_handles_labels()
    lines = fig.get_suptitle().count("\n") + 1
    bottom = legend_height(len(labels), ncol, fontsize) + 0.5  # + the x label and tick labels
    top = title_height(lines) + 0.1
    ax.set_position((0.85 / W, bottom / H, 1 - 1.05 / W, 1 - (bottom + top) / H))
    bottom_legend(fig, handles, labels, ncol, fontsize)
