"""Sheet 2's output: the JSON keys of issue 25 and their signs, the dynamics CSV, the tables in both
languages, the figures (everything drawn inside them), the A1 sheet 2 read back from the DXF, the
command's files and errors."""

import io
import json
import math
import tomllib
from pathlib import Path

import ezdxf
import numpy as np
import pytest
from click.testing import CliRunner

from test_sheets import FRAME, TITLE, check_layout, reopen

from tmm_cli.cli import cli
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2
from tmm_cli.render.data.dynamics import add_sheet2, dynamics_csv
from tmm_cli.render.data.mechanism import mechanism_document

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
NAMES = ("compressor", "four_bar", "shaper")
_CACHE = {}


def sheet2(name):
    if name not in _CACHE:
        path = EXAMPLES / f"{name}.toml"
        m = parse_mechanism(tomllib.loads(path.read_text(encoding="utf-8")), path.name)
        _CACHE[name] = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m, path.name))
    return _CACHE[name]


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])


@pytest.mark.parametrize("name", NAMES)
def test_json_keys_and_signs(name):
    s = sheet2(name)
    doc = add_sheet2(mechanism_document(s.sheet1, "en"), s)
    json.dumps(doc, allow_nan=False)
    labels = {r.label for r in s.forces.reactions}
    for p in doc["positions"]:
        assert {"balancing_moment_Nm", "zhukovsky_moment_Nm", "reactions", "reduced"} <= set(p)
        assert set(p["reactions"]) == labels and all(len(v) == 2 for v in p["reactions"].values())
        assert set(p["reduced"]) == {"inertia_kgm2", "moment_Nm"}
        assert p["zhukovsky_moment_Nm"] == pytest.approx(p["balancing_moment_Nm"], abs=1e-9)
    d = doc["dynamics"]
    assert {"drive_moment_Nm", "flywheel_inertia_kgm2", "flywheel_inertia_wittenbauer_kgm2", "omega_mean", "omega_max",
            "omega_min", "delta"} <= set(d)
    # counter-clockwise positive: the shaper's crank turns clockwise, its motor's moment is negative
    sense = s.sheet1.mechanism.crank.sense
    assert math.copysign(1.0, d["drive_moment_Nm"]) == sense and d["motor_moment_Nm"] > 0
    assert d["omega_max"] > d["omega_mean"] > d["omega_min"]
    assert (d["omega_max"] - d["omega_min"]) / d["omega_mean"] == pytest.approx(d["delta"])
    # the reduced moment of a position times ω₁ is the power of the load and the weights: resisting overall
    assert np.mean([p["reduced"]["moment_Nm"] for p in doc["positions"]]) * sense < 0


def test_reactions_are_of_the_earlier_link_on_the_later():
    s = sheet2("compressor")
    doc = add_sheet2(mechanism_document(s.sheet1, "en"), s)
    i = s.force_position
    p = doc["positions"][i]
    # the frame on the crank balances the rod's pull on it and the crank's own forces
    r01, r12 = complex(*p["reactions"]["R01"]), complex(*p["reactions"]["R12"])
    crank_forces = sum(complex(*f["force"]) for k, f in p["applied_forces"].items() if k.endswith("1"))
    assert abs(r01 - r12 + crank_forces) < 1e-6 * abs(r01)


def test_dynamics_csv():
    s = sheet2("four_bar")
    head, *rows = dynamics_csv(s).strip().splitlines()
    cols = head.split(",")
    assert cols[:8] == ["travel_deg", "phi_deg", "M_r_Nm", "A_r_J", "A_d_J", "dT_J", "J_r_kgm2", "J_II_kgm2"]
    assert len(rows) == 721 and "omega_rad_s" in cols
    last = dict(zip(cols, map(float, rows[-1].split(","))))
    assert last["travel_deg"] == pytest.approx(360.0) and abs(last["dT_J"]) < 1e-9


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_tables_in_both_languages(lang):
    from rich.console import Console

    from tmm_cli.render.terminal.dynamics import print_dynamics

    buf = io.StringIO()
    print_dynamics(Console(file=buf, width=200), sheet2("shaper"), lang)
    text = buf.getvalue()
    if lang == "ru":
        assert "Реакции в кинематических парах" in text and "Мерцалов" in text and "Fпс" in text and "μ_F" in text
        assert "71,620" in text  # M_д
    else:
        assert "Reactions in the pairs" in text and "Mertsalov" in text and "Fc" in text and "71.620" in text


@pytest.mark.parametrize("name", ["shaper", "four_bar"])
def test_figures_draw_inside(name):
    from tmm_cli.render.figures.dynamics import dynamics_figures

    figs = dynamics_figures(sheet2(name), "ru")
    assert set(figs) == {"linkage_forces", "linkage_lever", "linkage_dynamics", "linkage_wittenbauer"}
    for fname, fig in figs.items():
        fig.savefig(io.BytesIO(), format="png", dpi=40)
        bb = fig.get_tightbbox(fig.canvas.get_renderer())
        w, h = fig.get_size_inches()
        assert bb.x0 >= -0.05 and bb.y0 >= -0.05 and bb.x1 <= w + 0.05 and bb.y1 <= h + 0.05, (fname, bb, (w, h))


@pytest.mark.parametrize("name", NAMES)
def test_sheet2_layout_scales_and_texts(name, tmp_path):
    from tmm_cli.render.sheets.dynamics_sheet import sheet2 as build

    s = sheet2(name)
    doc = reopen(build(s, "ru", TITLE), tmp_path, "sheet2")
    fl = check_layout(doc)
    for pg in s.polygons:
        if len(s.polygons) <= 3:
            assert fl[f"polygon_{pg.group}"]["scale"] == pytest.approx(1.0 / pg.scale)
    assert {"lever", "dynamics_diagrams", "wittenbauer"} <= set(fl)  # J_r(φ) is the fourth of the diagrams
    mtexts = " ".join(e.text for e in doc.modelspace().query("MTEXT"))
    assert "J\\S^ пр;" in mtexts
    for e in doc.modelspace().query("TEXT"):
        x, y = e.dxf.insert[0], e.dxf.insert[1]
        assert FRAME[0] <= x <= FRAME[2] and FRAME[1] <= y <= FRAME[3], e.dxf.text
    texts = " ".join(e.dxf.text for e in doc.modelspace().query("TEXT"))
    assert "РЫЧАГ ЖУКОВСКОГО" in texts and "ДИАГРАММА ЭНЕРГОМАСС" in texts and "ТММ.02.00.00.00" in texts


def test_command_writes_sheet2_and_its_figures(tmp_path):
    r = run("linkage", EXAMPLES / "compressor.toml", "--sheets", "--out", tmp_path, "--lang", "en")
    assert r.exit_code == 0, r.output
    names = {p.name for p in (tmp_path / "linkage").iterdir()}
    assert {"sheet1.dxf", "sheet2.dxf", "sheet2.pdf", "linkage_forces.png", "linkage_lever.png", "linkage_dynamics.png",
            "linkage_wittenbauer.png", "linkage_dynamics.csv"} <= names
    assert "Dynamics and the flywheel" in r.stdout and "Zhuk." in r.stdout
    texts = " ".join(e.dxf.text for e in ezdxf.readfile(tmp_path / "linkage" / "sheet2.dxf").modelspace().query("TEXT"))
    assert "FORCE ANALYSIS" in texts.upper()


def test_a_bad_mass_is_one_line_and_nothing_is_written(tmp_path):
    text = (EXAMPLES / "compressor.toml").read_text(encoding="utf-8").replace("m = 2.4", "m = -2.4")
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    for lang, fragment in (("en", "'mass[2].m' is -2.4; a mass must lie in [0, 100000] kg"),
                           ("ru", "'mass[2].m' = -2,4; масса должна лежать в [0, 100000] кг")):
        r = run("linkage", path, "--out", tmp_path / "o", "--lang", lang)
        assert r.exit_code == 2 and len(r.stderr.strip().splitlines()) == 1, r.stderr
        assert fragment in r.stderr, r.stderr
    assert not (tmp_path / "o").exists()
    # sheet 1 alone does not read the sheet-2 tables
    r = run("linkage", path, "--no-forces", "--no-plots", "--out", tmp_path / "o")
    assert r.exit_code == 0, r.output
