"""The figure of `tmm synth`: the construction of the synthesis — the mechanism in its two extreme
positions (placed by `tmm linkage`'s own solution of the file written), the angle θ between the
crank's positions, and per type the locus circle (crank-rocker), the crank circle and the guide
(crank-slider), the arc of B with its sagitta and the ram's guide (slotted link). In mm."""

from __future__ import annotations

import math

import numpy as np

from ...i18n import N_, tr
from ...i18n.numbers import num
from ...linkage.chain import solve
from ...linkage.synthesis import RockerSynthesis, SliderSynthesis
from ...records import record
from .kit import decimal_commas, mt, new_figure, suptitle, title_height

MM = 1000.0
C_EXT = "k"  # the extreme position where the working stroke starts
C_EXT2 = "#1f77b4"  # the other extreme position
C_CONS = "#d62728"  # the construction: θ, the locus
GREY = "#9a9a9a"
TITLES = {"crank-slider": N_("Synthesis of the crank-slider mechanism"),
          "crank-rocker": N_("Synthesis of the crank-rocker mechanism"),
          "slotted-link": N_("Synthesis of the slotted-link mechanism of a shaper")}


def _seg(ax, p, q, **kw):
    ax.plot([p.real, q.real], [p.imag, q.imag], **kw)


def _arc(ax, centre, radius, a0, a1, label=None, color=C_CONS, lw=1.0, ls="-", fontsize=10):
    """An arc from angle a0 to a1 [rad] (the shorter way), with a label at its middle."""
    d = (a1 - a0 + math.pi) % (2 * math.pi) - math.pi
    t = np.linspace(a0, a0 + d, 60)
    ax.plot(centre.real + radius * np.cos(t), centre.imag + radius * np.sin(t), color=color, lw=lw, ls=ls)
    if label:
        mid = centre + 1.25 * radius * np.exp(1j * (a0 + d / 2))
        ax.text(mid.real, mid.imag, label, color=color, ha="center", va="center", fontsize=fontsize)


def _circle(ax, centre, radius, **kw):
    t = np.linspace(0, 2 * math.pi, 240)
    ax.plot(centre.real + radius * np.cos(t), centre.imag + radius * np.sin(t), **kw)


def _dot(ax, z, name, offset=(6, 6), fixed=False):
    ax.plot([z.real], [z.imag], marker="^" if fixed else "o", ms=6 if fixed else 4, color="k", mfc="white", zorder=6)
    if name:
        ax.annotate(mt(name), (z.real, z.imag), xytext=offset, textcoords="offset points", fontsize=10, zorder=7)


def _positions(result):
    """Every joint [mm, complex] at the two extreme positions (start and end of the working stroke)."""
    mech, c = result.mechanism, result.cycle
    k = solve(mech, list(c.extremes))
    return [{n: complex(k.z[n][i]) * MM for n in mech.joint_names} for i in range(2)]


def _box(ax, z, size, color):
    from matplotlib.patches import Rectangle

    ax.add_patch(Rectangle((z.real - size, z.imag - 0.6 * size), 2 * size, 1.2 * size, fill=True, fc="white", ec=color,
                           lw=1.2, zorder=5))


@record(eq=False)
class _Recorded:
    """What the figure reads of a project's mechanism whose file records its synthesis."""

    task: object
    synthesis: object
    mechanism: object
    cycle: object


def recorded_construction_figure(sheet1, lang: str, size_mm: tuple[float, float]):
    """The construction of the synthesis a project's mechanism file records (the note's figure
    «Синтез механизма», issue 33), drawn at the note's size without a title (the caption is the note's)."""
    from ...linkage.synthesis_file import recorded_synthesis

    rec = recorded_synthesis(sheet1.mechanism)
    return construction_figure(_Recorded(rec.task, rec.synthesis, sheet1.mechanism, sheet1.cycle), lang,
                               size_in=(size_mm[0] / 25.4, size_mm[1] / 25.4), title=False)


def construction_figure(result, lang: str, size_in: tuple[float, float] = (9.0, 7.5), title: bool = True):
    syn = result.synthesis
    pos = _positions(result)
    allz = np.array([z for p in pos for z in p.values()])
    span = max(float(np.ptp(allz.real)), float(np.ptp(allz.imag)), 1e-9)
    top = title_height(2, 11) if title else 0.0
    fig = new_figure(*size_in)
    ax = fig.add_axes((0.1, 0.1, 0.87, 1 - (top + 0.25 + 0.5) / size_in[1]))
    ax.set_aspect("equal", adjustable="datalim")
    unit = 0.03 * span
    colors = (C_EXT, C_EXT2)
    theta_txt = "θ = " + num(math.degrees(syn.theta), lang, decimals=2) + "°"
    if isinstance(syn, SliderSynthesis):
        o = pos[0]["O"]
        _circle(ax, o, syn.crank * MM, color=GREY, lw=0.7, ls="--")
        xs = [p["B"].real for p in pos]
        y = pos[0]["B"].imag
        _seg(ax, complex(min(xs + [o.real]) - 2 * unit, y), complex(max(xs) + 3 * unit, y), color=GREY, lw=0.8,
             ls="-.")
        for p, col in zip(pos, colors):
            _seg(ax, p["O"], p["A"], color=col, lw=2.0)
            _seg(ax, p["A"], p["B"], color=col, lw=1.4)
            _box(ax, p["B"], unit, col)
        if syn.theta > 1e-9:
            b1, b2 = pos[0]["B"], pos[1]["B"]
            _seg(ax, o, b1, color=C_CONS, lw=0.7, ls=":")
            _seg(ax, o, b2, color=C_CONS, lw=0.7, ls=":")
            _arc(ax, o, 0.6 * syn.near * MM, np.angle(b1 - o), np.angle(b2 - o), theta_txt)
        _dot(ax, o, "O", fixed=True)
        far_first = abs(pos[0]["B"] - o) >= abs(pos[1]["B"] - o)  # B₁ the far extreme position, as the derivation
        for i, p in enumerate(pos if far_first else pos[::-1], 1):
            _dot(ax, p["A"], f"A_{i}")
            _dot(ax, p["B"], f"B_{i}", offset=(6, 10))
        b1, b2 = pos[0]["B"], pos[1]["B"]
        h = "H = " + num(abs(b1 - b2), lang, decimals=1) + " " + tr(lang, "mm")
        yy = y - 3 * unit
        ax.annotate("", (b1.real, yy), (b2.real, yy), arrowprops={"arrowstyle": "<->", "lw": 0.8})
        ax.plot([b1.real], [yy - 4 * unit], alpha=0.0)  # room for the label inside the axes
        ax.text((b1.real + b2.real) / 2, yy - unit, h, ha="center", va="top", fontsize=10)
    elif isinstance(syn, RockerSynthesis):
        a, d = pos[0]["A"], pos[0]["D"]
        centre, c1, c2 = syn.centre * MM, syn.C1 * MM, syn.C2 * MM
        cs = [p["C"] for p in pos]
        if sum(min(abs(z - w.conjugate()) for w in (c1, c2)) for z in cs) < sum(min(abs(z - w) for w in (c1, c2))
                                                                             for z in cs):
            centre, c1, c2 = centre.conjugate(), c1.conjugate(), c2.conjugate()  # the file was written mirrored
        _circle(ax, centre, syn.radius * MM, color=C_CONS, lw=0.8, ls="--")
        _circle(ax, a, syn.crank * MM, color=GREY, lw=0.7, ls="--")
        _seg(ax, c1, c2, color=C_CONS, lw=0.7, ls=":")
        _seg(ax, a, c1, color=C_CONS, lw=0.7, ls=":")
        _seg(ax, a, c2, color=C_CONS, lw=0.7, ls=":")
        _arc(ax, a, 0.3 * abs(c1 - a), np.angle(c1 - a), np.angle(c2 - a), theta_txt)
        _arc(ax, d, syn.rocker * MM, np.angle(c1 - d), np.angle(c2 - d), None, color=GREY, lw=0.7)
        _arc(ax, d, 0.35 * syn.rocker * MM, np.angle(c1 - d), np.angle(c2 - d),
             "ψ = " + num(math.degrees(syn.swing), lang, decimals=2) + "°", color=C_EXT2)
        for p, col in zip(pos, colors):
            _seg(ax, p["A"], p["B"], color=col, lw=2.0)
            _seg(ax, p["B"], p["C"], color=col, lw=1.4)
            _seg(ax, p["C"], p["D"], color=col, lw=1.4)
        _seg(ax, a, d, color="k", lw=0.6, ls="-.")
        _dot(ax, a, "A", fixed=True, offset=(-14, -12))
        _dot(ax, d, "D", fixed=True, offset=(6, -12))
        for p in pos:  # B₁ with C₁ (folded), B₂ with C₂ (extended), as the derivation
            _dot(ax, p["B"], "B_1" if abs(p["C"] - c1) <= abs(p["C"] - c2) else "B_2")
        _dot(ax, c1, "C_1", offset=(-16, 6))
        _dot(ax, c2, "C_2", offset=(6, 6))
        ax.text(centre.real, centre.imag, mt(tr(lang, "locus of θ")), color=C_CONS, fontsize=9, ha="center")
    else:
        o1, o2 = pos[0]["O1"], pos[0]["O2"]
        _circle(ax, o1, syn.crank * MM, color=GREY, lw=0.7, ls="--")
        half = syn.theta / 2.0
        up = math.pi / 2.0
        _arc(ax, o2, syn.link * MM, up - half - 0.05, up + half + 0.05, None, color=GREY, lw=0.7)
        _arc(ax, o2, 0.25 * syn.link * MM, up - half, up + half,
             "ψ = θ = " + num(math.degrees(syn.theta), lang, decimals=2) + "°", color=C_CONS)
        b1, b2 = pos[0]["B"], pos[1]["B"]
        _seg(ax, b1, b2, color=C_CONS, lw=0.7, ls=":")  # the chord; the sagitta from it to the arc's top
        top_b = o2 + 1j * syn.link * MM
        chord_mid = complex(o2.real, b1.imag)
        _seg(ax, chord_mid, top_b, color=C_CONS, lw=0.9)
        ax.text(max(b1.real, b2.real) + 3 * unit, (top_b.imag + chord_mid.imag) / 2,
                "f = " + num(syn.sagitta * MM, lang, decimals=1) + " " + tr(lang, "mm"), color=C_CONS, fontsize=9,
                va="center")
        yg = pos[0]["C"].imag
        xs = [p["C"].real for p in pos] + [p["B"].real for p in pos]
        _seg(ax, complex(min(xs) - 3 * unit, yg), complex(max(xs) + 3 * unit, yg), color=GREY, lw=0.8, ls="-.")
        for p, col in zip(pos, colors):
            _seg(ax, p["O1"], p["A"], color=col, lw=2.0)
            _seg(ax, p["O2"], p["B"], color=col, lw=1.4)
            _seg(ax, p["B"], p["C"], color=col, lw=1.2)
            _box(ax, p["C"], unit, col)
        _dot(ax, o1, "O_1", fixed=True)
        _dot(ax, o2, "O_2", fixed=True)
        for i, p in enumerate(pos, 1):
            _dot(ax, p["A"], f"A_{i}")
            _dot(ax, p["B"], f"B_{i}", offset=(6, 8))
        c1, c2 = pos[0]["C"], pos[1]["C"]
        yy = yg + 3 * unit
        ax.annotate("", (c1.real, yy), (c2.real, yy), arrowprops={"arrowstyle": "<->", "lw": 0.8})
        ax.plot([c1.real], [yy + 4 * unit], alpha=0.0)  # room for the label inside the axes
        ax.text((c1.real + c2.real) / 2, yy + unit, "H = " + num(abs(c1 - c2), lang, decimals=1) + " " + tr(lang, "mm"),
                ha="center", va="bottom", fontsize=10)
    ax.set_xlabel("x, " + tr(lang, "mm"))
    ax.set_ylabel("y, " + tr(lang, "mm"))
    ax.grid(alpha=0.2)
    ax.margins(0.08)
    if title:
        suptitle(fig, tr(lang, TITLES[result.task.type]) + "\n" + tr(
            lang, "the extreme positions: black — start of the working stroke, blue — its end"), fontsize=11)
    decimal_commas(fig, lang)
    return fig
