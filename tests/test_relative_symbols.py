"""Issue 34 review C15: a block's relative velocity and acceleration on a guide are written in one form
everywhere — both points with the numbers of their links, as the book writes v_A3A2 of a block in a
slot: the slider B (link 5) on the guide of link 3 is v_B5B3, a^k_B5B3, a^r_B5B3 (not v_BB3 beside
v_A3A2) — on sheet 1, in the note's chapter 1, in the plan figures and the terminal; the JSON keeps the
plans' own symbols (v_BB3: a key of the equations).

The expected forms are built here from the files: a group's links are numbered 2k, 2k+1 (k its place
in the structural formula); the RRP's slider is 2k+1; a PRP's block on its first guide 2k, on its
second 2k+1; the guide's link numbered by the group that made it (a slotted link of an RPR: 2k+1)."""

from __future__ import annotations

import re
import tomllib
from dataclasses import replace
from pathlib import Path

import pytest

from sheet_check import all_texts
from test_sheets import TITLE
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2
from tmm_cli.render.data.mechanism import mechanism_document
from tmm_cli.render.sheets.linkage_sheet import sheet1

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"


def _data(name):
    return tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))


def _expected(d) -> dict[str, str]:
    """{JSON suffix: book suffix} of the sliding points, from the file alone."""
    number = {}  # a link by its two joints → its number
    out = {}
    for k, g in enumerate(d["group"], start=1):
        if g["kind"] == "RPR":
            a, c = g["joints"]
            number[frozenset((a, c))] = 2 * k + 1
        if g["kind"] == "RRR":
            a, b, c = g["joints"]
            number[frozenset((a, b))], number[frozenset((b, c))] = 2 * k, 2 * k + 1
        if g["kind"] == "RRP":
            a, b = g["joints"]
            number[frozenset((a, b))] = 2 * k
            gd = g["guide"]
            if "link" in gd:
                n = number[frozenset(gd["link"])]
                out[f"{b}{b}{n}"] = f"{b}{2 * k + 1}{b}{n}"
        if g["kind"] == "PRP":
            (b,) = g["joints"]
            for j, gd in enumerate(g["guides"]):
                if "link" in gd:
                    n = number[frozenset(gd["link"])]
                    out[f"{b}{b}{n}"] = f"{b}{2 * k + j}{b}{n}"
    return out


CASES = {"rocking_block": {"BB3": "B5B3"}, "tangent": {"BB3": "B4B3"}}


@pytest.mark.parametrize("name", sorted(CASES))
def test_the_expected_forms_from_the_files(name):
    assert _expected(_data(name)) == CASES[name]


@pytest.mark.parametrize("name", sorted(CASES))
def test_sheet_1_and_the_json(name):
    d = _data(name)
    m = parse_mechanism(d, f"{name}.toml")
    s1 = analyse_mechanism(m, None, f"{name}.toml")
    texts = " | ".join(all_texts(sheet1(s1, "ru", TITLE).doc))
    doc = mechanism_document(s1, "ru")
    symbols = {v["symbol"] for pl in doc["plans"] for k in ("velocity", "acceleration") for v in pl[k]["vectors"]}
    for old, new in _expected(d).items():
        assert {f"v_{old}", f"a^k_{old}", f"a^r_{old}"} <= symbols  # the JSON as it was
        for head in ("v", "ak", "ar"):
            assert re.search(rf"\b{head}{new} = \d", texts), (head + new, texts[:300])
            assert f"{head}{old} =" not in texts
        assert "vA3A2 = " in texts  # the block in the slot: the same form


@pytest.mark.parametrize("name", sorted(CASES))
def test_the_plan_figures_and_the_terminal(name):
    from rich.console import Console

    from tmm_cli.render.figures.mechanism import plan_figure
    from tmm_cli.render.terminal.mechanism import plans_table

    d = _data(name)
    m = parse_mechanism(d, f"{name}.toml")
    s1 = analyse_mechanism(m, None, f"{name}.toml")
    (old, new), = _expected(d).items()
    fig = plan_figure(s1, s1.plans[0], "acceleration", "ru")
    texts = " ".join(t.get_text() for t in fig.findobj(lambda a: hasattr(a, "get_text")))
    pts = re.sub(r"([A-Z])(\d)", r"\1_{\2}", new)  # 'B5B3' → 'B_{5}B_{3}' (mathtext)
    assert f"a^{{k}}_{{{pts}}}" in texts and f"a^{{r}}_{{{pts}}}" in texts
    con = Console(width=200, record=True)
    con.print(plans_table(s1, "ru"))
    out = con.export_text()
    assert f"v_{new}" in out and f"a^k_{new}" in out and f"v_{old} " not in out


def test_the_note():
    from tmm_cli.project import run_project
    from tmm_cli.render.note import build_note
    from tmm_cli.render.note.markdown import markdown
    from tmm_cli.variants import get_variant

    base = run_project(get_variant("17"))
    for name in sorted(CASES):
        d = _data(name)
        m = parse_mechanism(d, name)
        s2 = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m))
        text = markdown(build_note(replace(base, linkage=s2), "ru", {}), "t")
        (old, new), = _expected(d).items()
        a, b = re.findall(r"[A-Z]\d+", new)
        book = f"{a[0]}<sub>{a[1:]}</sub> {b[0]}<sub>{b[1:]}</sub>"  # as Markdown writes v_(B_5 B_3)
        for head, sup in (("v", ""), ("a", "<sup>k</sup>"), ("a", "<sup>r</sup>")):
            assert f"{head}<sub>{book}</sub>{sup}" in text, (name, head, sup)
        assert f"<sub>{old[0]} {b[0]}<sub>{b[1:]}</sub></sub>" not in text  # not v_(B B_3)
        assert "v<sub>A<sub>3</sub> A<sub>2</sub></sub>" in text  # the block in the slot, the same form
