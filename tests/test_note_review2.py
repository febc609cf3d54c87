"""The second review's findings on the notes of issue 34's mechanisms (/work/review/findings2.md), read
from the note's text:

- C10: a rocker's working stroke is its swing — the note says «рабочее качание» (and «холостое
  качание» on the return) of the press feeder's rocker and of a four-bar's output rocker, and keeps
  «рабочий ход» for a slider. Figure 3 (the reduced moments against φ) shades the output's working
  stroke: with several loads, each on its own stroke, its axis says whose (link 3's, the ram's).
- C7: a four-stroke engine's ΔT_I extremes and its speed's change are «за цикл из двух оборотов», a
  one-turn machine's «за оборот».
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

from tmm_cli.project import analyse_linkage, run_project
from tmm_cli.render.note import build_note
from tmm_cli.render.note.markdown import markdown
from tmm_cli.variants import get_variant

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"


def _note(name: str) -> str:
    tables = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
    s2 = analyse_linkage(tables, f"{name}.toml")
    r = run_project(get_variant("17"), linkage=s2, linkage_name=f"{name}.toml")
    return markdown(build_note(r, "ru", {}), name)


@pytest.mark.parametrize("name, swings, strokes", [("press_feeder", 1, 1), ("four_bar", 1, 0)])
def test_a_rocker_swings_a_slider_strokes(name, swings, strokes):
    text = _note(name)
    said = re.findall(r"В положении \S+ (?:звено \d+ \([^)]*\)|выходное коромысло|механизм) совершает "
                      r"(рабоч\w+ \w+|холост\w+ \w+)", text)
    assert sum(w.endswith("качание") for w in said) == swings, said
    assert sum(w.endswith("ход") for w in said) == strokes, said
    assert not re.search(r"(коромысло|кулиса)[^.]*совершает рабочий ход", text)


def test_the_figure_says_whose_working_stroke_it_shades():
    from tmm_cli.render.figures.note import _dynamics

    for name, whose in (("press_feeder", "рабочий ход выходного звена 3 затенён"), ("shaper", "рабочий ход затенён")):
        tables = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
        fig = _dynamics(analyse_linkage(tables, f"{name}.toml"), "ru")
        assert fig.axes[-1].get_xlabel().endswith(whose), fig.axes[-1].get_xlabel()


@pytest.mark.parametrize("name, cycle", [("engine_4stroke", "за цикл из двух оборотов"), ("shaper", "за оборот")])
def test_the_flywheels_extremes_are_over_the_cycle(name, cycle):
    text = _note(name)
    said = re.findall(r"(?:^|\n)За (цикл из двух оборотов|оборот) \S*Δ", text)
    assert said == [cycle[3:]], said
    assert f"кривошипа {cycle} изменяется" in text
