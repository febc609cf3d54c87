"""Ticks copied from an axis's first tick (figure_kit.copying_ticks) draw what matplotlib's own new
ticks draw, under any tick parameters, and live on their own; the kept font height metrics are
matplotlib's (pixel and extent comparisons, no timing)."""

import numpy as np
import pytest
from matplotlib.axis import XAxis, YAxis
from matplotlib.backends.backend_agg import RendererAgg

from tmm_cli.render.figures import agg
from tmm_cli.render.figures.kit import copying_ticks, new_figure


def _needs(hook: str):
    """Skip where this matplotlib has no such hook (render/figures/agg.py: tested range, detection)."""
    return pytest.mark.skipif(hook not in agg.hooks(), reason=f"no {hook} hook on this matplotlib")

SETUPS = {
    "plain": lambda ax: None,
    "grid": lambda ax: ax.grid(alpha=0.3),
    "params": lambda ax: ax.tick_params(labelsize=7, direction="in", length=6, width=1.5, colors="tab:red", pad=6),
    "rotated": lambda ax: ax.tick_params(axis="x", labelrotation=35, top=True, labeltop=True),
    "minor": lambda ax: (ax.minorticks_on(), ax.grid(which="both", alpha=0.2)),
    "set_ticks": lambda ax: ax.set_xticks(np.arange(0, 361, 30)),
}


def _figure(setup, copying: bool):
    fig = new_figure(4, 3)
    ax = fig.add_subplot()
    if not copying:  # matplotlib's own axes classes: every tick made anew
        ax.xaxis.__class__, ax.yaxis.__class__ = XAxis, YAxis
    ax.plot(np.linspace(0, 360, 40), np.sin(np.linspace(0, 6, 40)) * 1e3)
    SETUPS[setup](ax)
    top = ax.secondary_xaxis("top", functions=(lambda d: d / 2, lambda t: 2 * t))
    if copying:
        copying_ticks(top)
    ax.set_xlabel("φ, °")
    fig.canvas.draw()
    return np.asarray(fig.canvas.buffer_rgba()).copy(), ax  # figures of a size share one renderer


@_needs("copied_ticks")
@pytest.mark.parametrize("setup", sorted(SETUPS))
def test_copied_ticks_draw_the_pixels_of_new_ticks(setup):
    (a, ax), (b, _) = (_figure(setup, c) for c in (True, False))
    assert type(ax.xaxis).__name__ == "CopyingXAxis" and len(ax.xaxis.majorTicks) > 3
    assert (a != b).any(axis=2).sum() == 0


@_needs("copied_ticks")
def test_a_copied_tick_lives_on_its_own():
    _, ax = _figure("plain", True)
    first, other = ax.xaxis.majorTicks[:2]
    for name in ("tick1line", "tick2line", "gridline", "label1", "label2"):
        a, b = getattr(first, name), getattr(other, name)
        assert a is not b and a._callbacks is not b._callbacks
    other.label1.set_fontsize(21)
    other.tick1line.set_markersize(9)
    assert first.label1.get_fontsize() != 21 and first.tick1line.get_markersize() != 9
    assert other.get_loc() != first.get_loc()


@_needs("height_metrics")
@pytest.mark.parametrize("size, weight, lines", [(8, "normal", 1), (12, "bold", 2), (6.5, "normal", 3)])
def test_kept_font_heights_are_matplotlibs(size, weight, lines):
    fig = new_figure(3, 2)
    text = fig.text(0.1, 0.5, "\n".join(["Вариант 17: φ, °"] * lines), fontsize=size, weight=weight)
    mine = fig.canvas.get_renderer()
    assert hasattr(mine, "_get_font_height_metrics")
    theirs = RendererAgg(*fig.canvas.get_width_height(physical=True), fig.dpi)
    assert np.allclose(text.get_window_extent(mine).extents, text.get_window_extent(theirs).extents, rtol=0, atol=1e-9)


def test_a_formula_is_kerned_the_same_whatever_was_drawn_before():
    """The kept mathtext fontsets kern at the formula's own size: a formula drawn again after
    texts of other sizes in the same font (which move FreeType's size) draws the same pixels; it
    once came out a pixel wider or narrower, batch rows differing with the rows drawn before."""
    from tmm_cli.render.figures.kit import mt

    def formula(tail: str):  # a new string (parsed anew: parses are kept by string), the same ink
        fig = new_figure(4, 0.8)
        fig.text(0.02, 0.3, mt("AVATAR To Wa LT, l_BC = 80 mm, rocker CB₀") + tail, fontsize=9)
        fig.canvas.draw()
        return np.asarray(fig.canvas.buffer_rgba()).copy()

    first = formula("")
    other = new_figure(4, 2)
    other.text(0.02, 0.6, mt("AVATAR To Wa LT, l_BC, CB₀ ∂"), fontsize=23)
    other.text(0.02, 0.2, "AVATAR To Wa LT BC", fontsize=17)
    other.canvas.draw()
    again = formula(" ")
    assert (first != again).any(axis=2).sum() == 0
    assert (first[..., 0] < 128).sum() > 100  # ink was drawn
