"""Sheet 1 of a mechanism file as the reader gets it: the JSON keys of issue 24, the CSV, the tables in
both languages, the figures (every label inside its figure)."""

import io
import json
import math
import tomllib
from pathlib import Path

import pytest

from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.render.data.mechanism import curve_csv, mechanism_document

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
NAMES = ("compressor", "four_bar", "shaper", "whitworth")


def sheet(name):
    path = EXAMPLES / f"{name}.toml"
    return analyse_mechanism(parse_mechanism(tomllib.loads(path.read_text(encoding="utf-8")), path.name))


@pytest.mark.parametrize("name", NAMES)
def test_json_has_the_keys_of_the_issue(name):
    s = sheet(name)
    doc = json.loads(json.dumps(mechanism_document(s, "en")))
    assert {"positions", "stroke_m", "time_ratio", "structure"} <= set(doc)
    joints = set(s.mechanism.joint_names)
    links = {ln.name for ln in s.mechanism.links}
    for i, p in enumerate(doc["positions"]):
        assert set(p) == {"index", "label", "phi_deg", "points", "links"} and p["index"] == i
        assert 0.0 <= p["phi_deg"] < 360.0
        assert set(p["points"]) == joints and set(p["links"]) == links
        for pt in p["points"].values():
            assert set(pt) == {"x", "y", "vx", "vy", "ax", "ay"}
        for ln in p["links"].values():
            assert set(ln) == {"angle_deg", "omega", "epsilon"} and 0.0 <= ln["angle_deg"] < 360.0
    assert doc["positions"][0]["label"] == "0"
    assert doc["structure"]["dof"] == 1
    if s.mechanism.output.kind == "slider":
        assert doc["stroke_m"] == pytest.approx(s.cycle.stroke, rel=1e-11)
    else:
        assert doc["stroke_m"] is None and doc["swing_deg"] == pytest.approx(math.degrees(s.cycle.stroke), rel=1e-11)


def test_json_numbers_are_the_models():
    s = sheet("shaper")
    doc = mechanism_document(s, "en")
    p = doc["positions"][3]
    k = s.cycle.kin
    assert p["points"]["C"]["vx"] == pytest.approx(k.v["C"][3].real, rel=1e-11)
    assert p["links"]["AO2"]["epsilon"] == pytest.approx(k.epsilon["AO2"][3], rel=1e-11)
    assert p["phi_deg"] == pytest.approx(math.degrees(s.cycle.positions[3].phi) % 360, abs=1e-9)


def test_curve_csv_has_every_point_and_link():
    s = sheet("four_bar")
    text = curve_csv(s)
    head, *rows = text.strip().splitlines()
    cols = head.split(",")
    assert len(rows) == 721 and cols[:5] == ["travel_deg", "phi_deg", "s", "v", "a"]
    assert "S2_x_m" in cols and "BC_omega" in cols
    assert all(len(r.split(",")) == len(cols) for r in rows)


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_tables_print_in_both_languages(lang):
    from rich.console import Console

    from tmm_cli.render.terminal.mechanism import print_mechanism

    buf = io.StringIO()
    print_mechanism(Console(file=buf, width=160), sheet("shaper"), lang)
    text = buf.getvalue()
    if lang == "ru":
        assert "Формула строения: I(0,1) → II(2,3) → II(4,5)" in text and "ВПВ" in text and "1,55215" in text
    else:
        assert "Structural formula: I(0,1) → II(2,3) → II(4,5)" in text and "RPR" in text and "1.55215" in text
    assert "7′" in text and "μ_v" in text


@pytest.mark.parametrize("name", ["shaper", "four_bar"])
def test_figures_keep_their_labels_inside(name):
    from tmm_cli.render.figures.mechanism import mechanism_figures

    figs = mechanism_figures(sheet(name), "ru")
    assert set(figs) == {"linkage_mechanism", "linkage_diagrams", "linkage_velocity_plan", "linkage_acceleration_plan",
                         "linkage_velocity_plan_2", "linkage_acceleration_plan_2"}
    for fname, fig in figs.items():
        fig.savefig(io.BytesIO(), format="png", dpi=40)
        renderer = fig.canvas.get_renderer()
        bb = fig.get_tightbbox(renderer)  # what is drawn, in inches
        w, h = fig.get_size_inches()
        assert bb.x0 >= -0.02 and bb.y0 >= -0.02 and bb.x1 <= w + 0.02 and bb.y1 <= h + 0.02, (fname, bb, (w, h))
