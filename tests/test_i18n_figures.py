"""Figures as a Russian reader sees them: book symbols with real subscripts (mathtext, never an
underscore in the text), decimal commas in texts and tick labels under ru, points under en."""

import re

import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg

from tmm_cli.gears.design import design_gears
from tmm_cli.project import run_project
from tmm_cli.render.figures.cam import cam_figures
from tmm_cli.render.figures.kit import mt
from tmm_cli.render.figures.gears import gears_figures
from tmm_cli.variants import get_variant

MATH = re.compile(r"\$[^$]*\$")
REFS = re.compile(r"\(\d+\.\d+\)|(табл|рис|п)\. \d+\.\d+|§\d+(\.\d+)*")


def _figures(lang, more=True):
    out = {}
    r = run_project(get_variant("17", None))  # a translating follower
    out.update({f"17/{k}": f for k, f in {**gears_figures(r.gears, lang), **cam_figures(r.cam, lang)}.items()})
    if more:  # a rocker's cam, a two-stage reducer
        out.update({f"40/{k}": f for k, f in cam_figures(run_project(get_variant("40", None)).cam, lang).items()
                    if k != "cam_profile_scaled"})
        out.update({f"s11/{k}": f for k, f in gears_figures(design_gears(-1000, crank_rpm=40), lang,
                                                             names=("gears_planetary",)).items()})
    for f in out.values():
        FigureCanvasAgg(f)
        f.canvas.draw()
    return out


@pytest.fixture(scope="module")
def ru():
    return _figures("ru")


@pytest.fixture(scope="module")
def en():
    return _figures("en", more=False)


def _texts(fig):
    """Every text a reader sees: titles, labels, annotations, legend entries, tick labels."""
    out = [fig.get_suptitle()] if fig.get_suptitle() else []
    out += [t.get_text() for t in fig.texts]
    for leg in fig.legends:
        out += [t.get_text() for t in leg.get_texts()]
    for ax in fig.axes:
        out += [ax.get_title(loc) for loc in ("left", "center", "right")]
        out += [ax.get_xlabel(), ax.get_ylabel()]
        out += [t.get_text() for t in ax.texts]
        if ax.get_legend() is not None:
            out += [t.get_text() for t in ax.get_legend().get_texts()]
    return [t for t in out if t]


def _ticks(fig):
    labels = []
    for ax in fig.axes:
        for sub in [ax, *getattr(ax, "child_axes", [])]:
            labels += [t.get_text() for t in sub.get_xticklabels() + sub.get_yticklabels()]
    return [t for t in labels if t]


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_no_underscore_outside_mathtext(request, lang):
    bad = []
    for name, fig in request.getfixturevalue(lang).items():
        for text in _texts(fig):
            if "_" in MATH.sub("", text):
                bad.append((name, text))
    assert not bad


def test_book_symbols_are_subscripts(ru):
    titles = " ".join(ru["17/gears_planetary"].get_suptitle().split())
    sub = "\\text"
    assert f"$i_{sub}{{пл}}$" in titles and f"$n_{sub}{{кр}}$" in titles
    texts = " ".join(_texts(ru["17/cam_pressure_angle"]))
    assert f"$ν_{sub}{{max}}$" in texts


def test_decimal_comma_under_ru_point_under_en(ru, en):
    for name, fig in ru.items():
        for label in _ticks(fig):
            assert "." not in label, (name, label)
        for text in _texts(fig):
            plain = REFS.sub("", MATH.sub("", text))  # "(2.1)", "табл. 1.1" are references, not numbers
            assert not re.search(r"\d\.\d", plain), (name, text)
    assert any(re.search(r"\d\.\d", " ".join(_texts(f))) for f in en.values())
    # the pressure-angle legend: "max 25,00°" under ru
    assert any(re.search(r"max \d+,\d\d°", t) for t in _texts(ru["17/cam_pressure_angle"]))


def test_mt_leaves_words_alone():
    sub = "\\text"
    assert mt("phase_angle and ν_max") == f"phase_angle and $ν_{sub}{{max}}$"
    assert mt("z_c′") == f"$z_{sub}{{c′}}$"


def test_a_text_subscript_draws_the_pixels_of_mathregular():
    """mt() writes x_\\text{…} (parsed twice as fast) where matplotlib has it: the same pixels as
    x_\\mathregular{…}, Cyrillic, Latin, Greek and primes alike, at the figures' sizes."""
    import numpy as np

    from tmm_cli.render.figures.kit import new_figure

    pixels = []
    for command in ("\\mathregular", "\\text"):
        fig = new_figure(5, 1)
        for k, size in enumerate((8, 12)):
            fig.text(0.02, 0.1 + 0.45 * k, f"$i_{command}{{пл}}$ = $ν_{command}{{max}}$, $z_{command}{{c′}}$, "
                     f"$φ_{command}{{α1}}$, $l_{command}{{OC}}$ мм", fontsize=size)
        fig.canvas.draw()
        pixels.append(np.asarray(fig.canvas.buffer_rgba()).copy())
    assert (pixels[0] != pixels[1]).any(axis=2).sum() == 0
    assert (pixels[0][..., 0] < 128).sum() > 200  # ink was drawn
