"""Sheet 3's minimum-radius construction, its letters and its caption (review findings B10, C22), read
back from the DXF:

- a force-closed rocker (the book's construction of §1.3 with the line through B0, the book's «C»)
  has its pivot C in the same view: the line takes the book's other name of the second line, B, so no
  letter names two things (the DXF of v39 had two TEXT «C»); a translating follower keeps the book's C;
- the position numbers left out are said in drawing language («Позиции … не обозначены»), not «нет места».
"""

from __future__ import annotations

import functools

import pytest

from sheet_check import all_texts
from tmm_cli.cam.design import design_cam
from tmm_cli.inputs.titleblock import TitleFields
from tmm_cli.render.sheets import sheet3
from tmm_cli.variants import load_table

V = load_table()
ROCKERS = [n for n, v in V.items() if v.is_rocker and v.closure == "force"]


@functools.lru_cache(maxsize=4)
def _texts(number, lang="ru"):
    return all_texts(sheet3(design_cam(V[number]), lang, TitleFields()).doc)


@pytest.mark.parametrize("number", ROCKERS[::4] + [39])
def test_a_force_closed_rockers_letters_name_one_thing_each(number):
    texts = _texts(number)
    singles = [t.strip() for t in texts if len(t.strip()) == 1]
    assert singles.count("C") == 1, singles  # the pivot alone
    assert singles.count("A") == 1 and singles.count("B") == 1, singles  # the book's two lines
    assert any(t.startswith("A, B — лучи пособия") for t in texts), [t for t in texts if "лучи" in t]
    assert design_cam(V[number]).sizing.zone.lines[1].name == "B"


def test_a_translating_follower_keeps_the_books_line_c():
    number = next(n for n, v in V.items() if not v.is_rocker and v.closure == "force")
    assert [L.name for L in design_cam(V[number]).sizing.zone.lines] == ["A", "C"]
    assert any(t.startswith("A, C — лучи пособия") for t in _texts(number))


def test_the_positions_left_out_are_said_in_drawing_language():
    for number in (39, 52, 8, 3, 7, 20, 25):  # a larger zone (issue 32's layout) leaves fewer out
        texts = _texts(number)
        assert not any("нет места" in t or "не пронумерованы" in t for t in texts)
        said = [t for t in texts if "не обозначены" in t]
        if said:
            assert said[0].startswith("Позиции ") and said[0].rstrip(".").endswith("не обозначены")
            return
    pytest.fail("no variant among 39, 52, 8, 3, 7, 20, 25 leaves a position number out")
