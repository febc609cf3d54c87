"""Figures of `tmm planetary` (seed 000): the AA̅ mechanism (kinematic scheme and a front view with
the real working and tip circles) and its velocity picture. Drawn from the design object only;
matplotlib is imported inside the functions."""

from __future__ import annotations

import math

import numpy as np

from ...i18n import tr
from ...i18n.numbers import num

C_SUN = "#1f77b4"
C_PLANET = "#d62728"
C_WHEEL4 = "#444444"
C_CARRIER = "#2ca02c"


def _circle(ax, centre, r, **kw):
    t = np.linspace(0, 2 * math.pi, 361)
    ax.plot(centre[0] + r * np.cos(t), centre[1] + r * np.sin(t), **kw)


def _bar(ax, x, y0, y1, col, lw=2.4, tick=None):
    tick = tick if tick is not None else 0.03 * abs(y1 - y0) + 1.0
    ax.plot([x, x], [y0, y1], color=col, lw=lw, solid_capstyle="butt")
    for y in (y0, y1):
        ax.plot([x - tick, x + tick], [y, y], color=col, lw=lw)


def _scheme(ax, d, lang):
    """Side view: sun 1 on the input shaft, the planet block (2 = 3) on the carrier H, wheel 4 fixed."""
    p12, p34 = d.pair12, d.pair34
    aw = d.a_w_mm
    r1, r2, r3, r4 = p12.dw_mm[0] / 2, p12.dw_mm[1] / 2, p34.dw_mm[0] / 2, p34.dw_mm[1] / 2
    gap = 0.35 * aw
    x1, x4, xh = 0.0, gap, 1.9 * gap
    for sg in (1, -1):
        _bar(ax, x1, 0, sg * r1, C_SUN)
        _bar(ax, x4, sg * 0.12 * aw, sg * r4, C_WHEEL4)
        # the planet: one gear, wide enough for both meshes
        yc = sg * aw
        _bar(ax, x1, yc - r2, yc + r2, C_PLANET)
        _bar(ax, x4, yc - r3, yc + r3, C_PLANET)
        ax.plot([x1, x4], [yc, yc], color=C_PLANET, lw=5, solid_capstyle="butt", alpha=0.6)
        # carrier: planet axle to the carrier arm, arm down to the output shaft
        ax.plot([x1 - 0.25 * gap, xh], [yc, yc], color=C_CARRIER, lw=1.6)
        ax.plot([xh, xh], [0, yc], color=C_CARRIER, lw=1.8)
        # wheel 4 is fixed: a hub down to the frame with hatching
        yb = sg * 0.12 * aw
        ax.plot([x4, x4 + 0.35 * gap], [yb, yb], color=C_WHEEL4, lw=2.0)
        for hx in np.linspace(x4 + 0.1 * gap, x4 + 0.35 * gap, 5):
            ax.plot([hx, hx - 0.06 * gap], [yb, yb - sg * 0.05 * aw], color=C_WHEEL4, lw=0.8)
    ax.plot([-0.6 * gap, x1], [0, 0], color=C_SUN, lw=3)
    ax.plot([xh, xh + 0.6 * gap], [0, 0], color=C_CARRIER, lw=3)
    ax.plot([-0.7 * gap, xh + 0.7 * gap], [0, 0], color="0.5", lw=0.7, ls=(0, (10, 3, 2, 3)))
    for x, y, text, col in ((x1, 0.5 * r1, "1", C_SUN), (x1, aw + 0.55 * r2, "2", C_PLANET), (x4, aw + 0.55 * r3, "3", C_PLANET),
                            (x4, 0.6 * r4, "4", C_WHEEL4), (xh, 0.5 * aw, "H", C_CARRIER)):
        ax.annotate(text, (x, y), xytext=(-7, 0), textcoords="offset points", color=col, fontsize=12,
                    fontweight="bold", ha="right", va="center")
    ax.annotate(tr(lang, "in"), (-0.6 * gap, 0), xytext=(0, 6), textcoords="offset points", fontsize=9)
    ax.annotate(tr(lang, "out"), (xh + 0.6 * gap, 0), xytext=(-20, 6), textcoords="offset points", fontsize=9)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_ylabel(tr(lang, "radius, mm (working circles)"))
    z = d.teeth
    ax.set_title(tr(lang, "Kinematic scheme: Z1 = {z}, Z2 = Z3 = {z2}, Z4 = {z3}, k = {planets}").format(z=z[0], z2=z[1], z3=z[3], planets=d.planets), fontsize=10)


def _front(ax, d, lang):
    """Front view at true scale: working and tip circles of the sun, wheel 4 and the k planets."""
    p12, p34 = d.pair12, d.pair34
    aw = d.a_w_mm
    k = d.planets
    _circle(ax, (0, 0), p12.dw_mm[0] / 2, color=C_SUN, lw=1.2)
    _circle(ax, (0, 0), p12.da_mm[0] / 2, color=C_SUN, lw=0.8, ls=":")
    _circle(ax, (0, 0), p34.dw_mm[1] / 2, color=C_WHEEL4, lw=1.2, ls="--")
    _circle(ax, (0, 0), p34.da_mm[1] / 2, color=C_WHEEL4, lw=0.8, ls=":")
    _circle(ax, (0, 0), aw, color=C_CARRIER, lw=0.7, ls=(0, (8, 3, 2, 3)))
    for j in range(k):
        th = math.pi / 2 + 2 * math.pi * j / k
        c = (aw * math.cos(th), aw * math.sin(th))
        _circle(ax, c, p12.dw_mm[1] / 2, color=C_PLANET, lw=1.2)
        _circle(ax, c, p34.dw_mm[0] / 2, color=C_PLANET, lw=1.0, ls="--")
        _circle(ax, c, d.da_planet_mm / 2, color=C_PLANET, lw=0.8, ls=":")
        ax.plot([0, c[0]], [0, c[1]], color=C_CARRIER, lw=2.0)
        ax.plot(*c, "o", color="k", ms=3)
    ax.plot(0, 0, "k+", ms=8)
    nb = d.neighbours
    mm = tr(lang, "mm")
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    lim = aw + d.da_planet_mm / 2 + 5
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_title(tr(lang, "Front view, a_w = {a_w_mm} {mm}; neighbouring d_a = {value} < 2a_w·sin(π/k) = {limit} {mm}").format(a_w_mm=num(d.a_w_mm, lang, decimals=3), mm=mm, value=num(nb.value, lang, decimals=2), limit=num(nb.limit, lang, decimals=2))
                 + ("" if nb.ok else " ✗"), fontsize=10)


def _mechanism_figure(d, lang):
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    fig = Figure(figsize=(14, 7.5), layout="constrained")
    ax0, ax1 = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    _scheme(ax0, d, lang)
    _front(ax1, d, lang)
    a12, a34 = d.alpha_w_deg
    shifts = ("; " if lang == "ru" else ", ").join(num(v, lang, decimals=3, minus='−') for v in d.x)  # list sep.
    fig.suptitle(tr(lang, "Planetary mechanism AA̅ (Kavetsky, 2010): i = {i}, C = {c}; $\\alpha_{{w12}}$ = {a12}°, "
                          "$\\alpha_{{w34}}$ = {a34}°; x = {x}").format(
        i=d.i, c=d.c, a12=num(a12, lang, decimals=3), a34=num(a34, lang, decimals=3), x=shifts), fontsize=11)
    handles = [
        Line2D([], [], color=C_SUN, label=tr(lang, "sun 1: working circle $d_{w1}$")),
        Line2D([], [], color=C_PLANET, label=tr(lang, "planet: $d_{w2}$ (mesh 1-2)")),
        Line2D([], [], color=C_PLANET, ls="--", label=tr(lang, "planet: $d_{w3}$ (mesh 3-4)")),
        Line2D([], [], color=C_WHEEL4, ls="--", label=tr(lang, "wheel 4 (fixed): $d_{w4}$")),
        Line2D([], [], color="0.3", ls=":", label=tr(lang, "tip circles $d_a$")),
        Line2D([], [], color=C_CARRIER, lw=2, label=tr(lang, "carrier H")),
    ]
    fig.legend(handles=handles, loc="outside lower center", ncol=3, fontsize=9, frameon=False)
    return fig


def _velocity_figure(d, lang):
    from matplotlib.figure import Figure
    from matplotlib.patches import Arc

    v = d.velocity
    fig = Figure(figsize=(8.5, 8), layout="constrained")
    ax = fig.add_subplot(1, 1, 1)
    slope = v.v_c / (v.a_w_mm - v.r_w4_mm)  # planet: v = slope·(r − r_w4)
    r_lo = v.a_w_mm - d.da_planet_mm / 2
    r_hi = v.r_planet_top_mm
    ax.plot([0, v.v_p12], [0, v.r_w1_mm], color=C_SUN, lw=2)
    ax.plot([slope * (r_lo - v.r_w4_mm), slope * (r_hi - v.r_w4_mm)], [r_lo, r_hi], color=C_PLANET, lw=2)
    ax.plot([0, v.v_c], [0, v.a_w_mm], color=C_CARRIER, lw=2)
    for vx, ry in ((v.v_p12, v.r_w1_mm), (v.v_c, v.a_w_mm)):
        ax.annotate("", (vx, ry), xytext=(0, ry), arrowprops=dict(arrowstyle="-|>", color="0.35", lw=0.8,
                                                                  shrinkA=0, shrinkB=0))
    for vx, ry, name in ((0.0, v.r_w4_mm, "$P_{34}$"), (v.v_p12, v.r_w1_mm, "$P_{12}$"), (v.v_c, v.a_w_mm, "C")):
        ax.plot(vx, ry, "o", color="k", ms=3.5)
        ax.annotate(name, (vx, ry), xytext=(6, -12 if name == "$P_{34}$" else 3), textcoords="offset points", fontsize=10)
    ax.annotate("1", (0.5 * v.v_p12, 0.5 * v.r_w1_mm), xytext=(6, 0), textcoords="offset points", color=C_SUN,
                fontsize=11, fontweight="bold")
    ax.annotate("2 = 3", (slope * (r_hi - v.r_w4_mm) * 0.85, v.r_w4_mm + (r_hi - v.r_w4_mm) * 0.85), xytext=(6, 0),
                textcoords="offset points", color=C_PLANET, fontsize=11, fontweight="bold")
    ax.annotate("H", (0.6 * v.v_c, 0.6 * v.a_w_mm), xytext=(-12, 4), textcoords="offset points", color=C_CARRIER,
                fontsize=11, fontweight="bold")
    r_arc = 0.45 * v.r_w1_mm
    ax.add_patch(Arc((0, 0), 2 * r_arc, 2 * r_arc, theta1=90 - v.phi_1_deg, theta2=90, color=C_SUN, lw=1))
    ax.add_patch(Arc((0, 0), 1.4 * r_arc, 1.4 * r_arc, theta1=90 - v.phi_h_deg, theta2=90, color=C_CARRIER, lw=1))
    ax.annotate(r"$\varphi_1$", (0, r_arc), xytext=(-4, 0), textcoords="offset points", fontsize=9, color=C_SUN, ha="right")
    ax.annotate(r"$\varphi_H$", (0, 0.7 * r_arc), xytext=(-4, 0), textcoords="offset points", fontsize=9, color=C_CARRIER,
                ha="right")
    ax.axvline(0, color="k", lw=0.8)
    ax.axhline(0, color="0.5", lw=0.7, ls=(0, (10, 3, 2, 3)))
    up = v.r_w1_mm >= v.r_w4_mm
    for r, name, va in ((v.r_w1_mm, "$r_{w1}$", "bottom" if up else "top"),
                        (v.r_w4_mm, "$r_{w4}$", "top" if up else "bottom"), (v.a_w_mm, "$a_w$", "center")):
        ax.axhline(r, color="0.8", lw=0.5)
        ax.annotate(f"{name} = {num(r, lang, decimals=2)}", (0, r), xytext=(-6, 0), textcoords="offset points",
                    fontsize=8, ha="right", va=va, color="0.3")
    ax.set_aspect("equal", adjustable="datalim")
    ax.plot([-0.35 * v.v_c, 1.3 * max(v.v_c, slope * (r_hi - v.r_w4_mm))], [0, 0], alpha=0)  # x data extent
    ax.set_xticks([])
    ax.set_xlabel(tr(lang, "linear velocity ($\\omega_H$ = 1 rad/s, mm/s)"))
    ax.set_ylabel(tr(lang, "radius, mm"))
    ax.set_title(tr(lang, "Velocity picture: $i = \\tan\\varphi_1/\\tan\\varphi_H$ = {ratio} (1 − Z2·Z4/(Z1·Z3) = {ratio_check})").format(ratio=num(v.ratio, lang, decimals=6), ratio_check=d.ratio_check), fontsize=10)
    return fig


def planetary_figures(d, lang: str) -> dict:
    """{"planetary_mechanism": Figure, "planetary_velocity": Figure}."""
    return {"planetary_mechanism": _mechanism_figure(d, lang), "planetary_velocity": _velocity_figure(d, lang)}
