"""The plans' positions are general ones (review finding B6): the velocity and acceleration plans of
sheet 1 (and the force analysis of sheet 2, made in the first) are drawn where the groups' vector
equations can be seen and checked — not where a plan collapses to a line or a moving joint's tip falls
on the pole (the Scotch yoke at φ = 90°: the block does not slide in the slot, and the yoke stands).
Each stays the position nearest the middle of its stroke unless that one is degenerate."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest

from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.render.data.mechanism import mechanism_document

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"

# the examples' plan positions: unchanged where the middle of the stroke gives general plans; the
# central crank-sliders (compressor, the V compressor: v_BA = 0 at φ = 90°), the Scotch yoke and the
# four-bar's return stroke (its velocity plan 0,9 mm wide in position 9) take the next position
PLAN_POSITIONS = {"compressor": ("4", "10"), "four_bar": ("3", "10"), "rocking_block": ("4", "10"),
                  "scotch_yoke": ("4", "10"), "shaper": ("4", "10"), "shaper_offset": ("4", "10"),
                  "tangent": ("4", "10"), "v_compressor": ("4", "10"), "whitworth": ("4", "10")}


def _doc(name):
    m = parse_mechanism(tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8")), f"{name}.toml")
    return m, mechanism_document(analyse_mechanism(m), "en")


@pytest.mark.parametrize("name", sorted(PLAN_POSITIONS))
def test_the_examples_plan_positions(name):
    _, doc = _doc(name)
    assert tuple(p["position"] for p in doc["plans"]) == PLAN_POSITIONS[name]


def test_the_scotch_yokes_plans_show_the_block_sliding_and_the_yoke_accelerating():
    """Independently of the plans' code: the block slides in the slot at r·ω·|cos φ| (the slot ⊥ the
    guide), and the yoke (x = r·cos φ) accelerates at r·ω²·|cos φ|; both at least 2 mm on the plans."""
    m, doc = _doc("scotch_yoke")
    r, w = m.crank.length, abs(m.crank.omega)
    phis = {p["label"]: math.radians(p["phi_deg"]) for p in doc["positions"]}
    for pl in doc["plans"]:
        phi = phis[pl["position"]]
        assert r * w * abs(math.cos(phi)) / pl["velocity"]["scale"] >= 2.0
        assert r * w * w * abs(math.cos(phi)) / pl["acceleration"]["scale"] >= 2.0
        lengths = {v["symbol"]: v["length_mm"] for v in pl["velocity"]["vectors"] + pl["acceleration"]["vectors"]}
        assert lengths["v_A3A2"] >= 2.0 and lengths["a^r_A3A2"] >= 2.0
        assert min(lengths[s] for s in lengths if s in ("v_Y", "a_Y", "v_A3", "a_A3")) >= 2.0


def test_the_note_says_why_the_plans_are_not_in_the_middle():
    from dataclasses import replace

    from tmm_cli.linkage.sheet2 import analyse_sheet2
    from tmm_cli.linkage.sheet2_file import parse_sheet2
    from tmm_cli.project import run_project
    from tmm_cli.render.note import build_note
    from tmm_cli.render.note.model import _texts
    from tmm_cli.variants import get_variant

    m, _ = _doc("scotch_yoke")
    s2 = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m, "scotch_yoke.toml"))
    doc = build_note(replace(run_project(get_variant("17")), linkage=s2), "ru", {})
    text = " ".join(t for b in doc.blocks for t in _texts(b))
    assert "Планы построены для положения 4" in text
    assert ("ближайшего к середине рабочего хода, в котором планы не вырождены (в середине хода, в положении 3, "
            "план скоростей вырождается в отрезок прямой") in text
