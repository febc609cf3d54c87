"""The note's own figures: drawn for the page, not the screen PNGs shrunk.

16,5 cm wide (the text width) and printed at their natural size, so every text is ≥ 10 pt on paper
(:func:`legible` enforces it); Liberation Serif, the note's font, also in the formulas; each plan
and diagram at a round scale μ (:mod:`.note_scales`), written on it. Saved as SVG with the text
kept as text (the typst note embeds them as vectors, and their words stay searchable), and for the
DOCX also as a 300 dpi PNG.

The screen figures of render/figures/cam.py and gears.py stay as they are; the gear pictures
reuse their drawing helpers on the note's axes.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ...i18n import tr, trc
from ...i18n.numbers import num
from . import note_scales as S

MM = 1 / 25.4
MIN_PT = 10.0
DPI_RASTER = 300
FONT_DIR = Path(__file__).resolve().parents[1] / "note" / "fonts"
C_RISE, C_RET, C_DWELL, C_ZONE, C_BOOK = "#1f77b4", "#d62728", "#7f7f7f", "#2ca02c", "#9467bd"

RC = {
    "font.family": ["Liberation Serif"], "font.size": MIN_PT, "axes.labelsize": MIN_PT, "xtick.labelsize": MIN_PT,
    "ytick.labelsize": MIN_PT, "legend.fontsize": MIN_PT, "axes.titlesize": MIN_PT,
    "mathtext.fontset": "custom", "mathtext.rm": "Liberation Serif", "mathtext.it": "Liberation Serif:italic",
    "mathtext.bf": "Liberation Serif:bold", "mathtext.sf": "Liberation Serif", "mathtext.cal": "Liberation Serif:italic",
    "mathtext.tt": "Liberation Serif", "mathtext.bfit": "Liberation Serif:bold:italic", "mathtext.default": "it",
    "svg.fonttype": "none", "svg.hashsalt": "tmm-note", "axes.unicode_minus": True, "axes.linewidth": 0.6,
    "xtick.major.width": 0.6, "ytick.major.width": 0.6, "lines.linewidth": 1.0, "legend.frameon": False,
    "legend.handlelength": 2.2, "axes.formatter.use_locale": False,
}
_FONTS_ADDED = []


def _fonts() -> None:
    if _FONTS_ADDED:
        return
    from matplotlib import font_manager

    for f in sorted(FONT_DIR.glob("LiberationSerif-*.ttf")):
        font_manager.fontManager.addfont(str(f))
    _FONTS_ADDED.append(True)


def _new(size_mm: tuple[float, float]):
    from .kit import new_figure

    return new_figure(size_mm[0] * MM, size_mm[1] * MM)  # the kit's figure: copied ticks, cheap PNG


def _axes(fig, box: S.Box, size_mm):
    W, H = size_mm
    return fig.add_axes((box.left / W, box.bottom / H, box.width / W, box.height / H))


def _limits(ax, x: S.Axis, y: S.Axis) -> None:
    ax.set_xlim(x.lo, x.hi)
    ax.set_ylim(y.lo, y.hi)


def _mu(ax, text: str, where: str = "upper left"):
    """The scale written on the plan or diagram, in a white box: in the corner `where`, or in the
    first other corner where it hides no curve and no label (placed by kit.settle once the
    figure is drawn)."""
    from .kit import corner_places

    places = corner_places(where)
    t = ax.annotate(text, places[0]["xy"], xycoords="axes fraction", xytext=places[0]["xyann"],
                    textcoords="offset points", ha=places[0]["ha"], va=places[0]["va"], fontsize=MIN_PT, zorder=20,
                    bbox=dict(boxstyle="square,pad=0.25", fc="white", ec="0.6", lw=0.5))
    t._tmm_places = places
    return t


def _n(x, lang, **kw) -> str:
    return num(x, lang, minus="−", **kw)


def _mus(mu: float, lang: str) -> str:
    """A scale value as printed: 0,0005 rather than 5·10⁻⁴."""
    text = f"{mu:.6f}".rstrip("0").rstrip(".")
    return text.replace(".", ",") if lang == "ru" else text


def _phases(ax, r, lang: str, mu_phi: float, labels: bool = True) -> None:
    """The phase bands of the screen figures; a phase named only where its name fits its band."""
    from .cam import C_DWELL as CD, C_RET as CR, C_RISE as CRI, _phase_marks

    _phase_marks(ax, r, lang, labels=False)
    if not labels:
        return
    v = r.variant
    bounds = [0.0, v.phi_rise_deg, v.phi_rise_deg + v.phi_far_dwell_deg, v.phi_working_deg, 360.0]
    names = [tr(lang, "rise"), tr(lang, "far dwell"),
             tr(lang, "return"), tr(lang, "near dwell")]
    short = [trc(lang, "phase, short", "rise"), trc(lang, "phase, short", "far dwell"),
             trc(lang, "phase, short", "return"), trc(lang, "phase, short", "near dwell")]
    for i, col in enumerate((CRI, CD, CR, CD)):
        width_mm = (bounds[i + 1] - bounds[i]) / mu_phi
        for name in (names[i], short[i]):
            if width_mm >= 2.0 * len(name) + 3:  # ≈ 2 mm a letter at 10 pt
                ax.text((bounds[i] + bounds[i + 1]) / 2, 0.97, name, transform=ax.get_xaxis_transform(), ha="center",
                        va="top", fontsize=MIN_PT, color=col)
                break


def legible(fig) -> None:
    """No text under 10 pt at print size (the figure is printed at its natural size)."""
    from matplotlib.text import Text

    for t in fig.findobj(Text):
        if t.get_text() and t.get_fontsize() < MIN_PT:
            t.set_fontsize(MIN_PT)


def _legend_below(fig, ax, handles, ncol: int = 2) -> None:
    fig.legend(handles=handles, loc="lower center", bbox_to_anchor=(0.5, 0.0), ncol=ncol, fontsize=MIN_PT,
               frameon=False, columnspacing=1.4, handletextpad=0.5, borderaxespad=0.3)


# ------------------------------------------------------------------------------------------------
# the cam


def _motion(r, lang: str):
    from .kit import mt

    v, m = r.variant, r.motion
    sc = S.motion_scales(r)
    size = S.MOTION["size"]
    fig = _new(size)
    left, width = S.MOTION["x"]
    ph, gap, bottom = S.MOTION["panel"], S.MOTION["gap"], S.MOTION["bottom"]
    deg = np.degrees(m.phi)
    rows = list(m.table)
    mm = tr(lang, "mm")
    if v.is_rocker:
        series = [(np.degrees(m.s), "γ, °", [math.degrees(x.s) for x in rows], sc.s, "μ_γ", "°/" + mm),
                  (m.v, tr(lang, "ω, rad/s"), [x.v for x in rows], sc.v, "μ_ω", tr(lang, "(rad/s)/mm")),
                  (m.a, tr(lang, "ε, rad/s²"), [x.a for x in rows], sc.a, "μ_ε", tr(lang, "(rad/s²)/mm"))]
    else:
        series = [(m.s * 1000, "S, " + mm, [x.s * 1000 for x in rows], sc.s, "μ_S", mm + "/" + mm),
                  (m.v, tr(lang, "V, m/s"), [x.v for x in rows], sc.v, "μ_V", tr(lang, "(m/s)/mm")),
                  (m.a, tr(lang, "a, m/s²"), [x.a for x in rows], sc.a, "μ_a", tr(lang, "(m/s²)/mm"))]
    xs = [x.phi_deg for x in rows]
    axes = []
    for k, (y, ylabel, pts, axis, sym, unit) in enumerate(series):
        box = S.Box(left, bottom + (2 - k) * (ph + gap), width, ph)
        ax = _axes(fig, box, size)
        axes.append(ax)
        _phases(ax, r, lang, sc.phi.mu, labels=(k == 0))
        yy = np.array(y, dtype=float)
        xx = deg.copy()
        if k == 2:  # the acceleration as a step where it jumps
            jump = np.abs(np.diff(yy)) > 0.2 * (np.abs(yy).max() + 1e-30)
            ins = np.nonzero(jump)[0] + 1
            xx, yy = np.insert(xx, ins, np.nan), np.insert(yy, ins, np.nan)
        ax.plot(xx, yy, color="k", lw=1.2)
        ax.plot(xs, pts, "o", ms=2.6, color="tab:orange")
        ax.axhline(0, color="k", lw=0.5)
        ax.set_xlim(sc.phi.lo, sc.phi.hi)
        ax.set_ylim(axis.lo, axis.hi)
        ax.set_xticks(np.arange(0, 361, 30))
        _thousands(ax, ylabel, axis, lang)
        ax.grid(alpha=0.3, lw=0.4)
        if k < 2:
            ax.tick_params(labelbottom=False)
        _mu(ax, mt(f"{sym} = {_mus(axis.mu, lang)} {unit}"), "upper right" if k != 0 else "lower right")
    axes[-1].set_xlabel(mt(tr(lang, "cam angle φ, °   (μ_φ = {mu} °/mm)").format(mu=_mus(sc.phi.mu, lang))))
    w = m.omega
    top = axes[0].secondary_xaxis("top", functions=(lambda d: np.radians(d) / w * 1000.0,
                                                     lambda t: np.degrees(np.asarray(t) / 1000.0 * w)))
    top.set_xlabel(tr(lang, "time t, ms"))
    return fig


def _thousands(ax, ylabel: str, axis: S.Axis, lang: str) -> None:
    """The diagram's name on its y axis; values of 10 000 and more in thousands, «ε·10⁻³, рад/с²»
    (the ГОСТ 2.319 way of a factor in the axis' name): «−40000» and the name ran past the figure's
    left edge (the 17 mm margin holds four digits and a minus)."""
    from matplotlib.ticker import FuncFormatter

    if max(abs(axis.lo), abs(axis.hi)) < 9999.5:
        ax.set_ylabel(ylabel)
        return
    head, _, unit = ylabel.partition(", ")
    factor = r"$\cdot\mathrm{10}^{\mathrm{-3}}$"  # mathtext: Liberation Serif has no superscript minus
    ax.set_ylabel(f"{head}{factor}, {unit}" if unit else head + factor)
    ax.yaxis.set_major_formatter(FuncFormatter(lambda x, pos: num(x / 1000.0, lang, minus="−", sig=6)))


def _plan_frame(ax, xa, ya, lang: str, grid: float) -> None:
    """A plan in millimetres of the mechanism: its round limits, a light grid, the axes' names and μ_l."""
    from .kit import mt

    _limits(ax, xa, ya)
    ax.grid(alpha=grid, lw=0.4)
    mm = tr(lang, "mm")
    ax.set_xlabel("x, " + mm)
    ax.set_ylabel("y, " + mm)
    _mu(ax, mt(f"μ_l = {_mus(xa.mu / 1000, lang)} " + tr(lang, "m/mm")))


def _zone(r, lang: str):
    from matplotlib.lines import Line2D
    from matplotlib.patches import Polygon

    from .cam import _segments
    from .kit import mt

    v, z = r.variant, r.sizing
    zn = z.zone
    size = S.PLAN["size"]
    fig = _new(size)
    ax = _axes(fig, S.PLAN["box"], size)
    xa, ya = S.zone_scales(r)
    k = 1000.0
    b, d = zn.b * k, zn.d * k
    rise, ret = zn.phase == 0, zn.phase == 2
    o = np.array(z.centre) * k
    bv = np.array(z.book_centre) * k
    ax.add_patch(Polygon(zn.polygon * k, closed=True, facecolor=C_ZONE, alpha=0.15, edgecolor=C_ZONE, lw=0.8))
    ax.plot(b[rise, 0], b[rise, 1], color="k", lw=1.0)
    ax.plot(d[rise, 0], d[rise, 1], color=C_RISE, lw=1.3)
    ax.plot(d[ret, 0], d[ret, 1], color=C_RET, lw=1.2, ls="-" if z.closure == "form" else "--")
    seg = np.concatenate([idx[:: max(1, len(idx) // 8)] for idx in (np.nonzero(rise)[0], np.nonzero(ret)[0])])
    ax.add_collection(_segments(np.stack([b[seg], d[seg]], axis=1), color="0.5", lw=0.5), autolim=False)
    span = max(xa.hi - xa.lo, ya.hi - ya.lo)
    for L in zn.lines:
        p0 = np.array(L.point) * k
        dd = np.array(L.direction)
        t = np.linspace(-3 * span, 3 * span, 2)
        ax.plot(p0[0] + t * dd[0], p0[1] + t * dd[1], color=C_BOOK, lw=0.9, ls="-.")
    ax.plot([0, o[0]], [0, o[1]], color="k", lw=0.9, ls="--")
    ax.plot(*o, marker="*", ms=11, color=C_ZONE, mec="k", ls="none", zorder=5)
    ax.plot(*bv, marker="X", ms=8, color=C_BOOK, mec="k", ls="none", zorder=5)
    ax.plot(0, 0, "o", color="k", ms=4)
    ax.annotate(mt("B_0"), (0, 0), textcoords="offset points", xytext=(6, 4))
    ax.annotate("O", o, textcoords="offset points", xytext=(8, -12))
    if z.pivot is not None:
        c = np.array(z.pivot) * k
        ax.plot(*c, "s", color="k", ms=5)
        ax.annotate("C", c, textcoords="offset points", xytext=(6, 6))
        ax.plot([o[0], c[0]], [o[1], c[1]], color="tab:brown", lw=1.1)
        ax.plot([c[0], 0], [c[1], 0], color="k", lw=1.8, alpha=0.6)
    else:
        ax.axvline(0, color="k", lw=0.7, ls=":")
        ax.plot([o[0], 0], [o[1], o[1]], color="tab:brown", lw=1.2)
    ax.set_aspect("auto")
    _plan_frame(ax, xa, ya, lang, 0.25)
    handles = [
        Polygon([[0, 0]], facecolor=C_ZONE, alpha=0.3, edgecolor=C_ZONE, label=tr(lang, "zone of admissible centres")),
        Line2D([], [], color="k", lw=1.0, label=tr(lang, "path of the roller centre B")),
        Line2D([], [], color=C_RISE, lw=1.3, label=tr(lang, "points D, rise")),
        Line2D([], [], color=C_RET, lw=1.2, ls="-" if z.closure == "form" else "--",
               label=tr(lang, "points D, return") + ("" if z.closure == "form" else tr(lang, " (free)"))),
        Line2D([], [], color=C_BOOK, lw=0.9, ls="-.", label=tr(lang, "bounding lines of the textbook")),
        Line2D([], [], marker="*", ms=11, color=C_ZONE, mec="k", ls="none", label=mt(tr(lang, "centre O taken, r_0 = {r0} mm").format(r0=_n(z.r0_m * k, lang, decimals=2)))),
        Line2D([], [], marker="X", ms=8, color=C_BOOK, mec="k", ls="none", label=mt(tr(lang, "vertex of the textbook, r_0 = {r0} mm").format(r0=_n(z.book_r0_m * k, lang, decimals=2)))),
    ]
    _legend_below(fig, ax, handles)
    return fig


def _profile(r, lang: str):
    from matplotlib.collections import PatchCollection
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle, FancyArrowPatch

    from .cam import _segments
    from .kit import mt

    v, z, p = r.variant, r.sizing, r.profile
    k = 1000.0
    size = S.PLAN["size"]
    fig = _new(size)
    ax = _axes(fig, S.PLAN["box"], size)
    xa, ya = S.profile_scales(r)
    P = p.pitch * k
    th = np.linspace(0, 2 * math.pi, 361)
    r0, rp = z.r0_m * k, p.roller_m * k
    ax.plot(r0 * np.cos(th), r0 * np.sin(th), color="0.4", lw=0.7, ls="--")
    ax.plot(P[:, 0], P[:, 1], color=C_RISE, lw=1.0, ls="-.")
    ax.plot(p.inner[:, 0] * k, p.inner[:, 1] * k, color="k", lw=1.6)
    if p.outer is not None:
        ax.plot(p.outer[:, 0] * k, p.outer[:, 1] * k, color="k", lw=1.6, alpha=0.7)
    n = len(p.phi) - 1
    idxs = [int(round(math.radians(row.phi_deg) / (2 * math.pi) * n)) % n for row in r.motion.table]
    idxs = idxs[:: max(1, len(idxs) // 8)]
    ax.add_collection(PatchCollection([Circle(P[i], rp) for i in idxs], facecolors="none", edgecolors="tab:orange",
                                      linewidths=0.8), autolim=False)
    stem = 0.45 * r0
    c = P[idxs]
    if p.pivot_path is not None:
        piv = p.pivot_path[idxs] * k
        ax.add_collection(_segments(np.stack([piv, c], axis=1), color="tab:brown", lw=0.9, alpha=0.8), autolim=False)
        ax.plot(piv[:, 0], piv[:, 1], "s", color="tab:brown", ms=2.5)
        pp = p.pivot_path * k
        ax.plot(pp[:, 0], pp[:, 1], color="tab:brown", lw=0.5, ls=":")
    else:
        far = c + stem * np.asarray(p.axis_dir)[idxs]
        ax.add_collection(_segments(np.stack([c, far], axis=1), color="tab:brown", lw=0.9, alpha=0.8), autolim=False)
        e = abs(z.e_m) * k
        if e > 1e-6:
            ax.plot(e * np.cos(th), e * np.sin(th), color="tab:brown", lw=0.5, ls=":")
    ax.plot([0], [0], "+", color="k", ms=10, mew=1.2)
    ax.annotate("O", (0, 0), textcoords="offset points", xytext=(-11, -13))
    b0 = P[0]
    ax.plot([0, b0[0]], [0, b0[1]], color="0.2", lw=0.8)
    ax.annotate(mt("B_0"), b0, textcoords="offset points", xytext=(6, -12))
    R = 0.98 * min(xa.hi, ya.hi)
    a0, a1 = (math.radians(200), math.radians(250)) if v.ccw else (math.radians(250), math.radians(200))
    ax.add_patch(FancyArrowPatch((R * math.cos(a0), R * math.sin(a0)), (R * math.cos(a1), R * math.sin(a1)),
                                 connectionstyle=f"arc3,rad={0.2 if v.ccw else -0.2}", arrowstyle="-|>",
                                 mutation_scale=14, lw=1.2, color="k"))
    am = math.radians(225)
    ax.text(0.9 * R * math.cos(am), 0.9 * R * math.sin(am), mt("ω_k"), ha="center", va="center")
    _plan_frame(ax, xa, ya, lang, 0.2)
    handles = [
        Line2D([], [], color="k", lw=1.6, label=mt(tr(lang, "working profile (roller r_р = {r} mm)").format(r=_n(rp, lang, decimals=2)))),
        Line2D([], [], color=C_RISE, lw=1.0, ls="-.", label=tr(lang, "pitch profile")),
        Line2D([], [], color="0.4", lw=0.7, ls="--", label=mt(tr(lang, "base circle r_0 = {r0} mm").format(r0=_n(r0, lang, decimals=2)))),
        Line2D([], [], color="tab:orange", lw=0.8, label=tr(lang, "roller in the positions of the table")),
        Line2D([], [], color="tab:brown", lw=0.9, label=tr(lang, "follower in the inverted motion")),
    ]
    _legend_below(fig, ax, handles)
    return fig


def _pressure(r, lang: str):
    from .kit import mt

    v, z, p = r.variant, r.sizing, r.profile
    size = S.PRESSURE["size"]
    fig = _new(size)
    ax = _axes(fig, S.PRESSURE["box"], size)
    xa, ya = S.pressure_scales(r)
    deg = np.degrees(p.phi)
    ph = r.motion.program.phase_index(p.phi)
    _phases(ax, r, lang, xa.mu)
    ax.plot(deg, np.where(ph == 0, p.nu_deg, np.nan), color=C_RISE, lw=1.5)
    ax.plot(deg, np.where(ph == 2, p.nu_deg, np.nan), color=C_RET, lw=1.5, ls="-" if z.closure == "form" else "--")
    ax.plot(deg, np.where((ph == 1) | (ph == 3), p.nu_deg, np.nan), color=C_DWELL, lw=0.9, ls=":")
    ax.axhline(v.nu_max_deg, color="k", lw=1.0, ls="-.")
    ax.annotate(mt(f"ν_max = {_n(v.nu_max_deg, lang)}°"), (345, v.nu_max_deg), xytext=(0, 3), textcoords="offset points",
                ha="right", va="bottom", bbox=dict(boxstyle="square,pad=0.1", fc="white", ec="none", alpha=0.8))
    _limits(ax, xa, ya)
    ax.set_xticks(np.arange(0, 361, 30))
    ax.set_xlabel(mt(tr(lang, "cam angle φ, °   (μ_φ = {mu} °/mm)").format(mu=_mus(xa.mu, lang))))
    ax.set_ylabel(tr(lang, "pressure angle ν, °"))
    ax.grid(alpha=0.3, lw=0.4)
    _mu(ax, mt(f"μ_ν = {_mus(ya.mu, lang)} °/" + tr(lang, "mm")), "lower right")
    return fig


# ------------------------------------------------------------------------------------------------
# the gears


def _planetary(g, lang: str):
    from .gears import _angular, _scheme, _velocity
    from .kit import mt

    sc = S.planetary_scales(g)
    size = S.PLANETARY["size"]
    fig = _new(size)
    ax_s = _axes(fig, S.PLANETARY["scheme"], size)
    ax_v = _axes(fig, S.PLANETARY["velocity"], size)
    ax_a = _axes(fig, S.PLANETARY["angular"], size)
    _scheme(ax_s, g, lang)
    _velocity(ax_v, g, lang, (sc.y.lo, sc.y.hi))
    _angular(ax_a, g, lang, y0=0.0)
    for ax in (ax_s, ax_v, ax_a):
        ax.set_title("")
        ax.set_aspect("auto")
    ax_s.set_ylabel("")
    ax_s.tick_params(labelleft=False, left=False)
    ax_v.set_xlabel("")
    ax_s.set_ylim(sc.y.lo, sc.y.hi)  # radii to scale; the axial lengths of a kinematic scheme are not
    _limits(ax_v, sc.x_velocity, sc.y)
    _limits(ax_a, sc.x_angular, sc.y_angular)
    for ax in (ax_v, ax_a):
        ax.set_xticks([])
        ax.set_yticks([])
    for st in g.checks.velocity.stages:
        for ry in (st.r_a, st.r_c, st.r_b):
            ax_s.axhline(ry, color="0.75", lw=0.5, ls=":", zorder=0)
    # drop the helpers' long captions: the note's text quotes the ratios
    for t in list(ax_a.texts):
        if "=" in t.get_text():
            t.remove()
    # the planetary's module is not chosen by the book's synthesis: drawn with sheet 4's module, the
    # scales stated at it (as sheet 4 does)
    _mu(ax_s, mt(f"μ_l = {_mus(sc.mu_l / 1000, lang)} " + tr(lang, "m/mm") + " " + module_text(sc.module_mm, lang)))
    _mu(ax_v, mt(f"μ_V = {_n(sc.mu_v, lang, sig=3)} " + tr(lang, "(m/s)/mm")))
    _mu(ax_a, mt(f"μ_ω = {_n(sc.mu_omega, lang, sig=3)} " + tr(lang, "(rad/s)/mm")), "upper right")
    return fig


def module_text(m: float, lang: str) -> str:
    """«(m = 2 мм)»: the reducer's module of the drawing, written as sheet 4 writes it."""
    return tr(lang, "(m = {m} mm)").format(m=num(m, lang, sig=3))


def _assembly(g, lang: str):
    from .gears import _assembly_stage
    from .kit import mt

    d = g.planetary
    n = len(d.stages)
    mu = S.assembly_scale(g)
    mu_l = S.assembly_mu_l(g)
    w_cm, h_cm = S.figure_size_cm("gears_assembly", g)
    size = (w_cm * 10, h_cm * 10)
    fig = _new(size)
    side = S.assembly_side(g)
    x0 = (size[0] - n * side - (n - 1) * 8) / 2
    for j, (st, ch) in enumerate(zip(d.stages, g.checks.stages)):
        ax = _axes(fig, S.Box(x0 + j * (side + 8), 2.0, side, side), size)
        title = (tr(lang, "Stage {j}").format(j=j + 1) + ": " if n > 1 else "") + "/".join(map(str, st.teeth)) + f", k = {st.planets}"
        _assembly_stage(ax, st, ch, lang, title)
        ax.set_title(title, y=1.0, pad=4)
        ax.set_xlim(-mu * side / 2, mu * side / 2)
        ax.set_ylim(-mu * side / 2, mu * side / 2)
    _mu(fig.axes[0], mt(f"μ_l = {_mus(mu_l / 1000, lang)} " + tr(lang, "m/mm") + " " + module_text(S.drawing_module(g), lang)),
        "lower left")
    return fig


def _mesh(g, lang: str):
    from matplotlib.lines import Line2D

    from .gears import C_PLANET, C_SUN, _draw_mesh, pair_names
    from .kit import mt

    sp = g.spur
    size = S.MESH["size"]
    fig = _new(size)
    ax = _axes(fig, S.MESH["box"], size)
    xa, ya = S.mesh_scales(g)
    _draw_mesh(ax, sp, lang, zoom=True, motor_sense=g.directions.motor)
    ax.set_aspect("auto")
    _plan_frame(ax, xa, ya, lang, 0.15)
    handles = [
        Line2D([], [], color="0.3", ls="-", label=mt(tr(lang, "pitch circles d"))),
        Line2D([], [], color="0.3", ls="--", label=mt(tr(lang, "base circles d_b"))),
        Line2D([], [], color="0.3", ls=":", label=mt(tr(lang, "tip circles d_a"))),
        Line2D([], [], color="0.3", ls="-.", label=mt(tr(lang, "root circles d_f"))),
        Line2D([], [], color="#ff7f0e", lw=5, alpha=0.75, label=pair_names(tr(lang, "two-pair zones P1U2, U1P2"))),
        Line2D([], [], color="#2ca02c", lw=5, alpha=0.75, label=pair_names(tr(lang, "single-pair mesh U2U1"))),
        Line2D([], [], color=C_SUN, lw=2.4, label=tr(lang, "active profiles, gear 1")),
        Line2D([], [], color=C_PLANET, lw=2.4, label=tr(lang, "active profiles, gear 2")),
    ]
    _legend_below(fig, ax, handles)
    return fig


# ------------------------------------------------------------------------------------------------
# the lever mechanism (sheet 1)


def _linkage_plans(s1, lang: str):
    """The velocity and the acceleration plan of the first plan position, each at its own round
    scale (written on it), the vectors coloured by kind as on the screen figures."""
    from .kit import mt
    from .mechanism import VECTOR_STYLE, _kind, away, joint_tex, point_tex

    pl = s1.plans[0]
    layout = S.linkage_layout(s1)
    size = layout["size"]
    fig = _new(size)
    for kind in ("velocity", "acceleration"):
        plan = pl.velocity if kind == "velocity" else pl.acceleration
        box = layout[kind]
        ax = _axes(fig, box, size)
        x, y = S.linkage_plan_axes(plan, box)
        _limits(ax, x, y)
        ax.set_aspect("equal", adjustable="box")
        ax.axis("off")
        pts = plan.points
        drawn = set()
        for v in plan.vectors:
            a, b = pts[v.start], pts[v.end]
            if abs(b - a) <= 0.3 * x.mu or (v.start, v.end) in drawn:  # shorter than 0,3 mm: not drawn
                continue
            drawn.add((v.start, v.end))
            colour, ls = VECTOR_STYLE[_kind(v.symbol, v.start)]
            ax.annotate("", xy=(b.real, b.imag), xytext=(a.real, a.imag), zorder=4,
                        arrowprops=dict(arrowstyle="-|>", color=colour, lw=0.9, ls=ls, shrinkA=0, shrinkB=0,
                                        mutation_scale=8))
        zs = list(pts.values())
        centre = sum(zs) / len(zs)
        placed: list[complex] = []
        for name in sorted(pts, key=lambda q: q != plan.pole):
            z = pts[name]
            if any(abs(z - q) < 1.5 * x.mu for q in placed):
                continue
            group = sorted((q for q in pts if abs(pts[q] - z) < 1.5 * x.mu), key=lambda q: q != plan.pole)
            names = [point_tex(q) for q in group]
            if plan.pole in group:
                names += [f"${joint_tex(f)}$" for f in plan.at_pole]
            d = away(z, [q for q in zs if abs(q - z) >= 1.5 * x.mu], centre)
            ax.annotate(", ".join(names), (z.real, z.imag), xytext=(7 * d.real, 7 * d.imag), textcoords="offset points",
                        ha="left" if d.real > 0.5 else "right" if d.real < -0.5 else "center",
                        va="bottom" if d.imag > 0.5 else "top" if d.imag < -0.5 else "center", fontsize=MIN_PT,
                        zorder=6)
            ax.plot(z.real, z.imag, "o", ms=2.0, color="k", zorder=5)
            placed.append(z)
        unit = tr(lang, "(m/s)/mm") if kind == "velocity" else tr(lang, "(m/s²)/mm")
        sym = "μ_v" if kind == "velocity" else "μ_a"
        _mu(ax, mt(f"{sym} = {_mus(x.mu, lang)} ") + unit)
    return fig


# sheet 2 (tmm project --mechanism)


def _dynamics(s2, lang: str):
    """M_пр and M_д, ΔT and ΔT_I (Mertsalov), J_пр over the cycle from position 0 (a four-stroke
    engine's two turns, 0 … 720°, as sheet 2's `dynamics_figure`), each at its round μ; the positions
    of the crank marked on the axis."""
    from .kit import mt

    d, fw = s2.dynamics, s2.flywheel
    c = s2.sheet1.cycle
    sc = S.dynamics_scales(s2)
    size = S.DYNAMICS["size"]
    fig = _new(size)
    left, width = S.DYNAMICS["x"]
    ph, gap, bottom = S.DYNAMICS["panel"], S.DYNAMICS["gap"], S.DYNAMICS["bottom"]
    x = np.degrees(d.travel)
    nm, jj, kg, mm = tr(lang, "N·m"), tr(lang, "J"), tr(lang, "kg·m²"), tr(lang, "mm")
    axes = []
    for k in range(3):
        box = S.Box(left, bottom + (2 - k) * (ph + gap), width, ph)
        axes.append(_axes(fig, box, size))
    ax = axes[0]
    ax.plot(x, d.M_r, color="k", lw=1.2, label=mt(trc(lang, "note figure, dynamics", "M_r")))
    engine = s2.is_engine  # the consumer's resisting moment M_с, drawn with its sign
    sym = "−" + mt(trc(lang, "note figure, dynamics", "M_c")) if engine else mt(trc(lang, "note figure, dynamics", "M_d"))
    ax.axhline(d.M_d, color=C_RET, lw=1.2, label=sym + " = " + _n(d.M_d, lang, decimals=2) + " " + nm)
    ax.set_ylabel(mt(f"M, {nm}"))
    _limits(ax, sc.phi, sc.M)
    _mu(ax, mt(f"μ_M = {_mus(sc.M.mu, lang)} {nm}/{mm}"), "lower left")
    ax = axes[1]
    ax.plot(x, d.dT, color="k", lw=1.2, label="Δ$T$")
    if fw is not None:
        me = fw.mertsalov
        t1 = me.dT_I - me.dT_I[0]
        ax.plot(x, t1, color=C_RISE, lw=1.1, ls="--", label="Δ" + mt("T_I"))  # I: the first group (Mertsalov)
        for j, mark in ((me.i_max, "v"), (me.i_min, "^")):
            ax.plot(x[j], t1[j], mark, color=C_RISE, ms=5)
    ax.set_ylabel(mt(f"ΔT, {jj}"))
    _limits(ax, sc.phi, sc.T)
    _mu(ax, mt(f"μ_T = {_mus(sc.T.mu, lang)} {jj}/{mm}"), "lower left")
    ax = axes[2]
    ax.plot(x, d.J_r, color="k", lw=1.2, label=mt(trc(lang, "note figure, dynamics", "J_r")))
    ax.set_ylabel(mt(f"J, {kg}"))
    _limits(ax, sc.phi, sc.J)
    _mu(ax, mt(f"μ_J = {_mus(sc.J.mu, lang)} {kg}/{mm}"), "upper left")
    end = 360.0 * s2.turns
    ticks = [(math.degrees(p.travel), p.label) for p in s2.positions if p.label.isdigit()] + [(end, "0")]
    for k, ax in enumerate(axes):
        for turn in range(s2.turns):  # the cycle's turns (a four-stroke engine's two)
            for lo, hi in c.stroke_spans():  # the working stroke, from its start extreme
                ax.axvspan(math.degrees(lo) + 360.0 * turn, math.degrees(hi) + 360.0 * turn, color=C_RISE,
                           alpha=0.06, lw=0)
            if turn:  # the end of a turn within the cycle
                ax.axvline(360.0 * turn, color="k", lw=0.8, ls="--")
        ax.axhline(0, color="k", lw=0.5)
        ax.set_xticks([t for t, _ in ticks])
        ax.set_xticklabels([lab for _, lab in ticks] if k == 2 else [])
        ax.grid(alpha=0.3, lw=0.4)
        # a two-turn ΔT comes back to 0 at the right: its μ box takes the upper right, the legend the middle
        where = "upper center" if k == 1 and s2.turns > 1 else "upper right"
        ax.legend(loc=where, ncol=2, fontsize=MIN_PT, frameon=True, framealpha=0.9, edgecolor="0.6")
    if len(s2.input.tables) > 1 and c.stroke_spans():  # several loads, each its own stroke: say whose is shaded
        number = s2.sheet1.mechanism.link(s2.sheet1.mechanism.output.link).number
        axes[-1].set_xlabel(mt(tr(lang, "positions of the crank; φ from position 0 (μ_φ = {mu} °/mm), the working stroke "
                                  "of the output link {number} shaded").format(mu=_mus(sc.phi.mu, lang), number=number)))
    else:
        axes[-1].set_xlabel(mt(tr(lang, "positions of the crank; φ from position 0 (μ_φ = {mu} °/mm), the working "
                                  "stroke shaded").format(mu=_mus(sc.phi.mu, lang))))
    return fig


def _indicator(s2, lang: str):
    """Each piston's indicator diagram (issue 34): p against s from the dead centre nearest the head,
    a line a stroke with its arrow and number, the force F = p·A on the right-hand axis, sheet 1's
    positions as points; the numbers of `Sheet2.indicators` (the sheet's), at round scales of its
    own (the axes carry the units)."""
    from .kit import mt

    inds = s2.indicators
    size = S.indicator_size(len(inds))
    fig = _new(size)
    left, width = S.INDICATOR["x"]
    ph, gap, bottom = S.INDICATOR["panel"], S.INDICATOR["gap"], S.INDICATOR["bottom"]
    mm, mpa = tr(lang, "mm"), tr(lang, "MPa")
    colours = (C_RISE, C_RET, C_ZONE, C_BOOK)
    for k, ind in enumerate(inds):
        box = S.Box(left, bottom + (len(inds) - 1 - k) * (ph + gap), width, ph)
        ax = _axes(fig, box, size)
        H = ind.stroke * 1000.0
        p_all = [v for row in ind.pressure for v in row]
        sx = S.fit_axis(0.0, H, width, pad=0.03)
        sy = S.fit_axis(min(p_all), max(p_all), ph)
        _limits(ax, sx, sy)
        for j, st in enumerate(ind.strokes):
            s = np.asarray(ind.travel) * H
            p = np.asarray(ind.pressure[j])
            if not (st in ("away", "expansion", "intake")):
                s, p = s[::-1], p[::-1]
            words = {"away": tr(lang, "away from the head"), "back": tr(lang, "towards the head"),
                     "expansion": tr(lang, "expansion"), "exhaust": tr(lang, "exhaust"), "intake": tr(lang, "intake"),
                     "compression": tr(lang, "compression")}[st]
            col = colours[j % len(colours)]
            ax.plot(s, p, color=col, lw=1.3, label=f"{j + 1} — {words}")
            m = len(s) // 2
            a, b = (s[m - 1], p[m - 1]), (s[m], p[m])
            ax.annotate("", xy=((a[0] + b[0]) / 2 + (b[0] - a[0]) * 0.2, (a[1] + b[1]) / 2 + (b[1] - a[1]) * 0.2),
                        xytext=((a[0] + b[0]) / 2, (a[1] + b[1]) / 2),
                        arrowprops=dict(arrowstyle="-|>", color=col, lw=1.2, mutation_scale=12))
        for label, row, x in ind.marks:
            if label.isdigit():
                y = ind.pressure_at(row, x)
                ax.plot(x * H, y, "o", ms=2.5, color="k", zorder=5)
        ax.axhline(0.0, color="k", lw=0.5)
        ax.set_xlabel(mt(f"s, {mm}"))
        ax.set_ylabel(mt(f"p, {mpa}"))
        twin = ax.twinx()
        f = ind.area * 1.0e6
        twin.set_ylim(sy.lo * f, sy.hi * f)
        twin.set_ylabel(mt("F = pA, " + tr(lang, "N")))
        ax.grid(alpha=0.3, lw=0.4)
        ax.legend(loc="upper right", fontsize=MIN_PT, frameon=True, framealpha=0.9, edgecolor="0.6")
        _mu(ax, tr(lang, "piston {n}; A = {a} m²; H = {h} mm").format(n=ind.number, a=_n(ind.area, lang, sig=4),
                                                                      h=_n(H, lang, sig=4)), "upper left")
    return fig


MAKERS = {"cam_motion": ("cam", _motion), "cam_zone": ("cam", _zone), "cam_profile": ("cam", _profile),
          "cam_pressure_angle": ("cam", _pressure), "gears_planetary": ("gears", _planetary),
          "gears_assembly": ("gears", _assembly), "gears_mesh": ("gears", _mesh),
          "linkage_plans": ("linkage", lambda s2, lang: _linkage_plans(s2.sheet1, lang)),
          "linkage_dynamics": ("linkage", _dynamics), "linkage_indicator": ("linkage", _indicator),
          "linkage_synthesis": ("linkage", lambda s2, lang: _synthesis(s2.sheet1, lang))}


def _synthesis(s1, lang: str):
    """The construction of the synthesis the mechanism file records (tmm synth, issue 33)."""
    from .note_scales import SYNTHESIS
    from .synth import recorded_construction_figure

    return recorded_construction_figure(s1, lang, SYNTHESIS["size"])


def note_figure(result, lang: str, name: str):
    """One note figure (a matplotlib Figure); call inside :func:`note_style`."""
    part, _ = MAKERS[name]
    return note_figure_of(name, {"cam": result.cam, "gears": result.gears, "linkage": result.linkage}[part], lang)


def note_figure_of(name: str, part, lang: str):
    """The note figure `name` from its chapter's result alone (the cam's, the gears', the linkage's):
    drawn, its tick labels with decimal commas, every text legible, the labels settled."""
    from .kit import decimal_commas, settle

    fig = MAKERS[name][1](part, lang)
    decimal_commas(fig, lang)
    legible(fig)
    settle(fig)
    return fig


def note_style():
    """The rc settings of the note's figures (Liberation Serif, 10 pt, SVG text as text)."""
    import matplotlib

    _fonts()
    return matplotlib.rc_context(RC)


def save_note_figure(folder: Path, result, lang: str, name: str, raster: bool = False) -> list[Path]:
    """Draw the note figure `name` and save it as note_<name>.svg (and a 300 dpi PNG for the DOCX)."""
    with note_style():
        fig = note_figure(result, lang, name)
        out = [Path(folder) / f"note_{name}.svg"]
        fig.savefig(out[0], format="svg", metadata={"Date": None})
        if raster:
            out.append(Path(folder) / f"note_{name}.png")
            fig.savefig(out[1], format="png", dpi=DPI_RASTER, metadata={"Software": None})
    return out
