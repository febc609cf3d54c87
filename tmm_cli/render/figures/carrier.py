"""The figure of `tmm carrier` (seed 004): the nominal polygon of the bores seen from the end of the
carrier's axis X (Y right, Z up, so counter-clockwise is the seed's positive sense), each bore's
error vector on both cheeks magnified, the magnification and a scale bar printed.

Everything drawn is read from the fit; the magnification is chosen here (a round number that makes
the largest error vector about a fifth of the radius). matplotlib is imported inside the function.
"""

from __future__ import annotations

import math

from ...accuracy.carrier import CarrierFit
from ...accuracy.measurements import nominal_bores
from ...i18n import tr
from ...i18n.numbers import num
from .kit import decimal_commas

C_LEFT = "#1f77b4"
C_RIGHT = "#d62728"
GREY = "#9a9a9a"
MM = 1e3
UM = 1e6


def nice_below(x: float) -> float:
    """The largest of 1, 2, 5 × 10ⁿ not above x (x > 0).

    >>> [nice_below(v) for v in (7.3, 1999.0, 0.04)]
    [5.0, 1000.0, 0.02]
    """
    e = math.floor(math.log10(x))
    for m in (5.0, 2.0, 1.0):
        if m * 10.0**e <= x * (1 + 1e-12):
            return float(m * 10.0**e) if e >= 0 else round(m * 10.0**e, -e)
    return 10.0 ** (e - 1)  # pragma: no cover - x is below 1·10ᵉ only through rounding


def magnification(fit: CarrierFit) -> tuple[float, float]:
    """(k, largest error [m]): k makes the largest error vector at most 0.35·R long on the figure."""
    nominal = nominal_bores(fit.z_c, fit.radius)
    largest = 0.0
    for b, (y0, z0) in zip(fit.bores, nominal):
        largest = max(largest, math.hypot(b.y - y0, b.z - z0), math.hypot(b.y_prime - y0, b.z_prime - z0))
    if largest <= 0.0:
        return 1.0, 0.0
    return nice_below(0.35 * fit.radius / largest), largest


def carrier_figure(fit: CarrierFit, lang: str):
    """The figure 'carrier' (a matplotlib Figure)."""
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    R = fit.radius * MM
    k, largest = magnification(fit)
    nominal = nominal_bores(fit.z_c, fit.radius) * MM
    fig = Figure(figsize=(8.0, 8.6), layout="constrained")
    ax = fig.subplots()
    ax.set_aspect("equal")
    t = [2 * math.pi * i / 360 for i in range(361)]
    ax.plot([R * math.cos(a) for a in t], [R * math.sin(a) for a in t], color=GREY, lw=0.8, ls=(0, (10, 3, 2, 3)))
    poly = list(nominal) + [nominal[0]]
    ax.plot([p[0] for p in poly], [p[1] for p in poly], color=GREY, lw=0.8)
    ax.plot([0], [0], "+", color="k", ms=12, mew=1.0)
    ax.annotate("X", (0, 0), xytext=(6, 4), textcoords="offset points", fontsize=10)
    tips = {C_LEFT: [], C_RIGHT: []}
    for b, (y0, z0) in zip(fit.bores, nominal):
        ax.plot([y0], [z0], "o", ms=7, mfc="white", mec="k", zorder=3)
        for (y, z), color in (((b.y, b.z), C_LEFT), ((b.y_prime, b.z_prime), C_RIGHT)):
            tip = (y0 + k * (y * MM - y0), z0 + k * (z * MM - z0))
            tips[color].append(tip)
            if math.hypot(tip[0] - y0, tip[1] - z0) > 1e-9 * R:
                ax.annotate("", xy=tip, xytext=(y0, z0), zorder=4,
                            arrowprops=dict(arrowstyle="-|>", color=color, lw=1.6, shrinkA=0, shrinkB=0,
                                            mutation_scale=14))
        out = 1.0 + 0.1
        ax.annotate(str(b.bore), (y0 * out, z0 * out), ha="center", va="center", fontsize=12, weight="bold")
    for color, pts in tips.items():  # each cheek's polygon as magnified
        pts = pts + pts[:1]
        ax.plot([p[0] for p in pts], [p[1] for p in pts], color=color, lw=0.8, ls="--", alpha=0.6, zorder=2)
    # the axes of the frame
    ax.annotate("", xy=(0.3 * R, 0), xytext=(0, 0), arrowprops=dict(arrowstyle="->", color="k", lw=0.8))
    ax.annotate("", xy=(0, 0.3 * R), xytext=(0, 0), arrowprops=dict(arrowstyle="->", color="k", lw=0.8))
    ax.annotate("Y", (0.3 * R, 0), xytext=(2, -12), textcoords="offset points", fontsize=10)
    ax.annotate("Z", (0, 0.3 * R), xytext=(-12, 2), textcoords="offset points", fontsize=10)
    lim = 1.35 * R
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_xlabel(tr(lang, "Y, mm"))
    ax.set_ylabel(tr(lang, "Z, mm"))
    ax.grid(alpha=0.25)
    # scale bar: a round number of micrometres, about the largest error
    if largest > 0:
        bar_um = nice_below(max(largest * UM, 1e-3))
        bar = k * bar_um / 1e3  # mm on the figure
        x0, y0 = -lim + 0.08 * R, -lim + 0.1 * R
        ax.plot([x0, x0 + bar], [y0, y0], color="k", lw=2.5, solid_capstyle="butt")
        for x in (x0, x0 + bar):
            ax.plot([x, x], [y0 - 0.02 * R, y0 + 0.02 * R], color="k", lw=1.0)
        ax.annotate(f"{num(bar_um, lang, sig=3)} " + tr(lang, "µm") + f"  (×{num(k, lang, sig=6)})",
                    (x0, y0), xytext=(0, 6), textcoords="offset points", ha="left", va="bottom", fontsize=10)
    title = tr(lang, "Planet carrier: bore position errors, {z_c} bores, R = {R} mm").format(z_c=fit.z_c, R=num(R, lang, sig=6))
    sub = tr(lang, "error vectors magnified ×{k} (least squares over {used} measurements); seen from the end of X").format(k=num(k, lang, sig=6), used=fit.used)
    ax.set_title(title + "\n" + sub, fontsize=11)
    handles = [Line2D([], [], color=C_LEFT, lw=1.6, marker=">", ms=6),
               Line2D([], [], color=C_RIGHT, lw=1.6, marker=">", ms=6),
               Line2D([], [], color="k", lw=0, marker="o", mfc="white", ms=7)]
    labels = [tr(lang, "left cheek $P_i$"), tr(lang, "right cheek $P'_i$"),
              tr(lang, "nominal centre")]
    ax.legend(handles, labels, loc="upper right", fontsize=9, framealpha=0.9)
    decimal_commas(fig, lang)
    return fig


def carrier_figures(fit: CarrierFit, lang: str) -> dict:
    """Figures by name: 'carrier'."""
    return {"carrier": carrier_figure(fit, lang)}
