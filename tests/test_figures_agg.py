"""The matplotlib hooks of render/figures/agg.py: used only on the tested range where feature
detection finds them, each switchable; without them (plain matplotlib, as on a release outside
the range) every figure is still drawn, its texts in place; the hooks other than text_bitmaps
draw matplotlib's own pixels."""

import io
import os
import subprocess
import sys

import matplotlib
import numpy as np
import pytest
from matplotlib.text import Text

from tmm_cli.render.figures import agg


@pytest.fixture
def hooks_back():
    """Whatever a test sets with agg.use(), the hooks of this process afterwards (ask for it before
    monkeypatch: it must put them back after agg.TESTED is restored)."""
    before = agg.hooks()
    yield
    assert agg.use(before) == before


@pytest.fixture(scope="module")
def variant17():
    from tmm_cli.project import run_project
    from tmm_cli.variants import get_variant

    return run_project(get_variant(17))


def _figures(result, lang="ru"):
    from tmm_cli.render.figures.cam import cam_figures
    from tmm_cli.render.figures.gears import gears_figures

    return {**gears_figures(result.gears, lang), **cam_figures(result.cam, lang)}


def _pixels(fig):
    fig.canvas.draw()
    return np.asarray(fig.canvas.buffer_rgba())[..., :3].copy()


def test_the_hooks_found_on_this_matplotlib():
    """What detection finds, by release: the text bitmaps, the formula cache, the copied ticks and
    the shared SVG text from 3.8.4; the glyph bitmaps, the shared fontsets and the kept height
    metrics where matplotlib ≥ 3.11 has the parts they replace; nothing outside the tested range."""
    v = matplotlib.__version_info__
    found = agg.available()
    if not agg.in_tested_range():
        assert found == frozenset()
    elif (v.major, v.minor) >= (3, 11):
        assert found == frozenset(agg.HOOKS)
    else:
        assert found == {"text_bitmaps", "formula_cache", "copied_ticks", "svg_text"}
    assert agg.hooks() == found  # the tests run with everything this matplotlib allows


def test_outside_the_tested_range_matplotlib_draws_alone(hooks_back, monkeypatch):
    from matplotlib.backends.backend_agg import RendererAgg
    from matplotlib.figure import Figure
    from matplotlib.mathtext import MathTextParser

    from tmm_cli.render.figures.kit import new_figure

    v = matplotlib.__version_info__
    monkeypatch.setattr(agg, "TESTED", ((v.major, v.minor, v.micro + 1), (99, 0, 0)))  # a release not compared
    assert not agg.in_tested_range() and agg.available() == frozenset()
    assert agg.use(agg.HOOKS) == frozenset()
    fig = new_figure(2, 1)
    ax = fig.add_subplot()
    fig.canvas.draw()
    assert type(fig) is Figure and type(fig.canvas.get_renderer()) is RendererAgg
    assert type(ax.xaxis).__name__ == "XAxis"
    assert MathTextParser._parse_cached.cache_info().maxsize == 50  # matplotlib's own cache


def test_without_hooks_every_figure_is_drawn_with_its_texts_in_place(variant17, hooks_back, tmp_path):
    """The fallback, forced in this process: each figure of a project comes out (a PNG the size of
    the hooked one), and every text — titles, labels, tick values, legends, formulas — has ink within
    a pixel of where the hooked canvas puts it."""
    from PIL import Image

    hooked = _figures(variant17)
    agg.use(())
    plain = _figures(variant17)
    assert plain.keys() == hooked.keys()
    for name in hooked:
        a, b = _pixels(hooked[name]), _pixels(plain[name])
        assert a.shape == b.shape, name
        plain[name].savefig(tmp_path / f"{name}.png", dpi=120)
        size = np.array(Image.open(tmp_path / f"{name}.png").size)
        assert np.abs(size - plain[name].get_size_inches() * 120).max() <= 1, name
        texts = [t for t in plain[name].findobj(Text) if t.get_visible() and t.get_text().strip() and _on_canvas(t)]
        renderer = plain[name].canvas.get_renderer()
        drawn = 0
        for t in texts:
            box = t.get_window_extent(renderer)
            inks = [_ink_box(img, box) for img in (a, b)]
            if inks[0] is None:  # not drawn by the hooked canvas either (a tick beyond the limits, white)
                continue
            assert inks[1] is not None, (name, t.get_text())  # drawn without the hooks too
            assert np.abs(np.subtract(inks[0], inks[1])).max() <= 1, (name, t.get_text(), inks)
            drawn += 1
        assert drawn > 5, name


def _on_canvas(text) -> bool:
    """Whether a text's box lies on the canvas (tick labels beyond the limits are laid out too)."""
    canvas = text.figure.canvas
    box = text.get_window_extent(canvas.get_renderer())
    w, h = canvas.get_width_height(physical=True)
    return box.x0 >= 0 and box.y0 >= 0 and box.x1 <= w and box.y1 <= h and box.width > 0


def _ink_box(img, box):
    """(row0, col0, row1, col1) of the dark pixels inside `box` (display coordinates), or None."""
    h = img.shape[0]
    y0, y1 = max(0, int(h - box.y1) - 2), int(h - box.y0) + 2
    x0, x1 = max(0, int(box.x0) - 2), int(box.x1) + 2
    ink = np.argwhere(img[y0:y1, x0:x1].min(axis=2) < 100)
    return None if len(ink) == 0 else (*ink.min(axis=0), *ink.max(axis=0))


def test_hooks_but_the_text_bitmaps_draw_matplotlibs_own_pixels(variant17, hooks_back):
    """The glyph bitmaps, the formula cache, the shared fontsets, the kept height metrics and the
    copied ticks are only cheaper: a project's figures come out pixel for pixel as without them."""
    every = agg.hooks()
    if every <= {"text_bitmaps"}:
        pytest.skip("no hook besides the text bitmaps on this matplotlib")
    hooked = {n: _pixels(f) for n, f in _figures(variant17).items()}
    agg.use(every & {"text_bitmaps"})
    for name, fig in _figures(variant17).items():
        assert (hooked[name] != _pixels(fig)).any(axis=2).sum() == 0, name


def test_shared_svg_text_writes_matplotlibs_own_svg(variant17, hooks_back, tmp_path):
    """The note's SVG copies with one TextToPath and one metrics table for every SVG renderer are
    matplotlib's own files, byte for byte (ids and date fixed)."""
    from tmm_cli.render.figures.agg import share_svg_text

    if "svg_text" not in agg.hooks():
        pytest.skip("no svg_text hook on this matplotlib")

    def svgs():
        out = {}
        with matplotlib.rc_context({"svg.hashsalt": "tmm"}):
            for name, fig in _figures(variant17).items():
                buf = io.BytesIO()
                fig.savefig(buf, format="svg", metadata={"Date": None})
                out[name] = buf.getvalue()
        return out

    agg.use(agg.hooks() - {"svg_text"})
    share_svg_text()  # nothing: the hook is off
    from matplotlib.backends.backend_svg import RendererSVG

    assert "_text2path" not in RendererSVG.__dict__ and not agg._SVG_TEXT
    theirs = svgs()
    agg.use(agg.hooks() | {"svg_text"})
    share_svg_text()
    ours = svgs()
    assert len(agg._SVG_TEXT) == 1 and agg._SVG_METRICS  # shared, and used
    assert ours == theirs


def test_text_bitmaps_are_matplotlibs_pixels_before_3_11(hooks_back):
    """Up to 3.10 matplotlib drew a plain text as one bitmap at a whole pixel too: the kept bitmaps
    are its pixels exactly (from 3.11 they are within a pixel: test_figures_fixed_layout)."""
    if "text_bitmaps" not in agg.hooks() or matplotlib.__version_info__[:2] >= (3, 11):
        pytest.skip("matplotlib 3.8.4–3.10 with the text bitmaps")
    from tmm_cli.render.figures.kit import new_figure

    def draw():
        fig = new_figure(3, 2)
        fig.text(0.05, 0.8, "Зона зацепления, мм", fontsize=11)
        fig.text(0.02, 0.1, "S, мм", rotation=90, fontsize=10)
        fig.add_subplot().plot([0, 1], [2, 3])
        return _pixels(fig)

    hooked = draw()
    agg.use(agg.hooks() - {"text_bitmaps"})
    assert (hooked != draw()).any(axis=2).sum() == 0


@pytest.mark.parametrize("asked, expected", [("off", set()), ("text_bitmaps, copied_ticks", {"text_bitmaps", "copied_ticks"}),
                                             ("", None)])
def test_tmm_mpl_hooks_chooses_by_hand(asked, expected):
    env = {**os.environ, "TMM_MPL_HOOKS": asked, "MPLBACKEND": "Agg"}
    code = ("import io; from tmm_cli.render.figures import agg; from tmm_cli.render.figures.kit import new_figure, mt; "
            "f = new_figure(1, 1); f.text(0.1, 0.5, mt('i_пл')); f.savefig(io.BytesIO(), format='png'); "
            "print(','.join(sorted(agg.hooks())), ','.join(sorted(agg.available())))")
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True).stdout.split(" ")
    on, found = (set(filter(None, x.strip().split(","))) for x in out)
    assert on == (found if expected is None else expected & found)
