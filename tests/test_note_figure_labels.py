"""The note's figures keep their labels apart (issue 32): the «μ_ε = 400 (рад/с²)/мм» box hid the
return's ε peak (Figure 1, v52), «к кривошипу» touched its panel's border (Figure 5), «N2», «P2» and
«α_w = 20°» overlapped and the points were named without subscripts (Figure 7); and the name of the
ε axis ran past the figure's left edge beside «−40000» (Figure 1 of 33 variants: now in thousands).

Read from matplotlib's renderer (tests/figure_labels.py: each label's box as drawn), not from
pixels: on the figures of the motion diagrams, the planetary reducer and the mesh no two labels of a
panel overlap, every label stays inside its panel, and a boxed scale μ covers no point of a curve.
A representative dozen of variants here; all 68 with ``pytest -m slow``."""

from __future__ import annotations

import re

import pytest

from figure_labels import (
    boxed_labels_on_curves,
    labels,
    labels_leaving_their_panel,
    overlapping_labels,
    texts_leaving_the_figure,
)
from tmm_cli.project import run_project
from tmm_cli.variants import get_variant

FIGURES = ("cam_motion", "gears_planetary", "gears_mesh")
DOZEN = ("1", "3", "8", "17", "23", "29", "39", "45", "52", "57", "61", "68")  # laws, rockers, both senses
REST = tuple(str(v) for v in range(1, 69) if str(v) not in DOZEN)


def _problems(variant: str) -> list[str]:
    from tmm_cli.render.figures.note import note_figure, note_style

    r = run_project(get_variant(variant))
    out = []
    with note_style():
        for name in FIGURES:
            fig = note_figure(r, "ru", name)
            fig.canvas.draw()
            out += [f"{name}: overlap {a!r} / {b!r}" for a, b in overlapping_labels(fig)]
            out += [f"{name}: {t!r} leaves its panel" for t in labels_leaving_their_panel(fig)]
            # nothing cut at the figure's edge («ε, рад/с²» beside «−40000» ran past it on 33 variants)
            out += [f"{name}: {t!r} runs past the figure's edge" for t in texts_leaving_the_figure(fig)]
            # the scales' boxes on the diagrams and the reducer; on the mesh the gears' outlines fill
            # the panel (its μ_l takes the corner that covers least, α_w's box is translucent)
            if name != "gears_mesh":
                out += [f"{name}: {t!r} hides {n} points of a curve" for t, n in boxed_labels_on_curves(fig)]
            if name == "gears_mesh":  # the points named as the book does: N₁, P₂ … as subscripts
                names = [t.get_text() for ax in fig.axes for t in labels(ax)]
                plain = [n for n in names if re.fullmatch(r"[NPUO][12]", n)]
                out += [f"mesh: point {n!r} without its subscript" for n in plain]
                # the zones' ends always in the zoomed window (N₁, N₂ only when they fall inside it)
                assert {"$P_1$", "$P_2$", "$U_1$", "$U_2$", "$P$"} <= set(names), names
                legend = [t.get_text() for t in fig.legends[0].get_texts()]
                assert any("$P_1U_2$" in t for t in legend), legend
                assert not [t for t in legend if re.search(r"\b[PU][12][PU][12]\b", t)], legend
            fig.clf()
    return out


@pytest.mark.parametrize("variant", DOZEN)
def test_the_labels_of_the_notes_figures_stand_apart(variant):
    assert _problems(variant) == []


@pytest.mark.slow
@pytest.mark.parametrize("variant", REST)
def test_the_labels_of_the_notes_figures_stand_apart_on_every_variant(variant):
    assert _problems(variant) == []
