"""The figures' cheaper artists draw what the artists they replace drew: the bare x axis of the
motion diagram's upper panels (grid lines and tick marks, no Tick objects), hidden axes instead of
empty tick lists, segment collections instead of one Line2D per segment; and no figure lost a legend
entry on the way (pixel comparisons, no timing)."""

import numpy as np
import pytest
from matplotlib.lines import Line2D

from tmm_cli.project import run_project
from tmm_cli.render.figures.cam import _segments, cam_figures
from tmm_cli.render.figures.kit import bare_xaxis, hide_axis, new_figure
from tmm_cli.render.figures.gears import gears_figures
from tmm_cli.variants import get_variant


def _pixels(fig):
    fig.canvas.draw()
    return np.asarray(fig.canvas.buffer_rgba()).copy()


def _panel(ax):
    x = np.linspace(0, 360, 50)
    ax.plot(x, np.sin(np.radians(x)), color="k")
    ax.axvspan(30, 150, color="#1f77b4", alpha=0.06, lw=0)
    ax.set_xlim(0, 360)


def test_bare_xaxis_draws_the_grid_and_tick_marks_of_a_real_axis():
    ticks = np.arange(0, 361, 30)
    figs = []
    for bare in (False, True):
        fig = new_figure(4, 3)
        top, bottom = fig.subplots(2, 1)
        for ax in (top, bottom):
            _panel(ax)
        if bare:
            top.sharex(bottom)
            bare_xaxis(top, ticks, grid_alpha=0.3)
            top.yaxis.grid(alpha=0.3)
            bottom.grid(alpha=0.3)
        else:
            top.sharex(bottom)
            for ax in (top, bottom):
                ax.grid(alpha=0.3)
            top.xaxis.set_tick_params(labelbottom=False)
        bottom.set_xticks(ticks)
        figs.append(fig)
    real, bare = (_pixels(f) for f in figs)
    assert (real != bare).any(axis=2).sum() == 0
    assert not figs[1].axes[0].xaxis.get_visible()


def test_hide_axis_draws_what_an_empty_tick_list_drew():
    figs = []
    for hidden in (False, True):
        fig = new_figure(3, 3)
        ax = fig.add_subplot()
        _panel(ax)
        ax.set_title("t", y=1.0)
        if hidden:
            hide_axis(ax.xaxis, ax.yaxis)
        else:
            ax.set_xticks([])
            ax.set_yticks([])
        figs.append(fig)
    assert (_pixels(figs[0]) != _pixels(figs[1])).any(axis=2).sum() == 0


def test_segment_collection_blends_each_segment_like_a_line():
    rng = np.random.default_rng(3)
    segs = rng.uniform(0, 1, (12, 2, 2))  # crossing segments: a merged path would blend crossings once
    figs = []
    for merged in (False, True):
        fig = new_figure(3, 3)
        ax = fig.add_axes((0.05, 0.05, 0.9, 0.9))
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        if merged:
            ax.add_collection(_segments(segs, color="tab:brown", lw=1.0, alpha=0.8), autolim=False)
        else:
            for s in segs:
                ax.plot(s[:, 0], s[:, 1], color="tab:brown", lw=1.0, alpha=0.8)
        figs.append(fig)
    diff = np.abs(_pixels(figs[0]).astype(int) - _pixels(figs[1]).astype(int))
    assert diff.max() <= 2  # the same strokes; alpha rounding may differ by one or two levels


LEGEND_ENTRIES = {  # (translating follower, rocker)
    "cam_zone": (8, 9),
    "cam_profile": (6, 7),
    "cam_pressure_angle": (4, 4),
    "gears_mesh": (8, 8),
}


@pytest.fixture(scope="module")
def drawn():
    out = {}
    for key, v in (("translating", "17"), ("rocker", "40")):
        r = run_project(get_variant(v, None))
        for lang in ("ru", "en"):
            figs = {**cam_figures(r.cam, lang, names=("cam_motion", "cam_zone", "cam_profile", "cam_pressure_angle")),
                    **gears_figures(r.gears, lang, names=("gears_mesh",))}
            out[key, lang] = figs
    return out


@pytest.mark.parametrize("key", ["translating", "rocker"])
@pytest.mark.parametrize("lang", ["ru", "en"])
def test_every_legend_entry_is_there(drawn, key, lang):
    figs = drawn[key, lang]
    col = 0 if key == "translating" else 1
    for name, counts in LEGEND_ENTRIES.items():
        fig = figs[name]
        legends = list(fig.legends) + [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None]
        labels = [t.get_text() for leg in legends for t in leg.get_texts()]
        assert len(labels) == counts[col] and all(labels), (name, labels)
    # the motion diagrams: a legend of the curve and the table positions on each of the three panels
    motion = figs["cam_motion"]
    assert [len(ax.get_legend().get_texts()) for ax in motion.axes] == [2, 2, 2]
    # the upper panels keep the phi grid of the bottom one (bare axes: grid lines and tick marks only)
    bottom_ticks = list(motion.axes[-1].get_xticks())
    for ax in motion.axes[:-1]:
        grid = [a for a in ax.get_children() if isinstance(a, Line2D) and a.get_marker() == "" and a.get_alpha() == 0.3]
        assert len(grid) == 1 and list(np.unique(grid[0].get_xdata()[~np.isnan(grid[0].get_xdata())])) == bottom_ticks
