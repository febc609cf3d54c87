"""`tmm linkage` from the command line: the JSON interface, the files, TOML input, hostile input,
and the exported files checked independently (recomputed here, not by the code under test)."""

import csv
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli
from tmm_cli.output.folder import MANIFEST
from cli_helpers import assert_one_line_error

ACCEPT = ["--r1", "0.10", "--h", "0.04", "--c", "0", "--r2", "0.08", "--r3", "0.30", "--b", "-0.04"]
KEYS = {"phi_deg", "link_angle_deg", "rho_m", "x_c_m", "omega_link_rad_s", "eps_link_rad_s2", "v_rel_m_s",
        "a_cor_m_s2", "v_c_m_s", "a_c_m_s2"}


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])


def files_under(path: Path):
    return sorted(p.relative_to(path) for p in path.rglob("*")) if path.exists() else []




def test_json_acceptance(tmp_path):
    res = run("linkage", *ACCEPT, "--rpm", "60", "--json", "--no-plots", "--out", tmp_path)
    assert res.exit_code == 0, res.output
    doc = json.loads(res.stdout)
    assert doc["time_ratio"] == pytest.approx(1.709953, abs=5e-7)
    assert doc["stroke_m"] == pytest.approx(0.16, abs=1e-12)
    assert doc["regime"] == "whitworth"
    assert len(doc["dead_positions_deg"]) == 2
    assert len(doc["positions"]) == 12
    for p in doc["positions"] + [doc["at"]]:
        assert set(p) == KEYS
    assert doc["at"]["phi_deg"] == pytest.approx(45.0)
    assert doc["positions"][0]["phi_deg"] == pytest.approx(doc["dead_positions_deg"][0])
    assert doc["positions"][0]["v_c_m_s"] == pytest.approx(0.0, abs=1e-9)
    steps = np.diff([p["phi_deg"] for p in doc["positions"]]) % 360
    assert np.allclose(steps, 30.0)
    assert doc["closure_residual_m"] < 1e-12
    assert sorted(p.name for p in (tmp_path / "linkage").iterdir() if not p.name.startswith(".")) == ["linkage.json", "linkage_curve.csv"]
    assert json.loads((tmp_path / "linkage" / "linkage.json").read_text(encoding="utf-8")) == doc


def test_json_numbers_recomputed_independently(tmp_path):
    """From the exported positions alone: A from φ21, O41A = ρ·u(φ41), B on the link, |BC| = r3,
    v_C = v_B + ... through the rod; and ω4 from the velocity of A projected on the link's normal."""
    r1, h, c, r2, r3, b = 0.10, 0.04, 0.0, 0.08, 0.30, -0.04
    res = run("linkage", *ACCEPT, "--omega", "5", "--positions", "24", "--json", "--no-plots", "--out", tmp_path)
    doc = json.loads(res.stdout)
    for p in doc["positions"]:
        phi, link = math.radians(p["phi_deg"]), math.radians(p["link_angle_deg"])
        a = np.array([r1 * math.sin(phi), r1 * math.cos(phi)])
        u, n = np.array([math.sin(link), math.cos(link)]), np.array([math.cos(link), -math.sin(link)])
        o41 = np.array([-c, -h])
        assert np.linalg.norm(o41 + p["rho_m"] * u - a) < 1e-9
        bb = o41 + r2 * u
        assert math.hypot(bb[0] - p["x_c_m"], bb[1] - b) == pytest.approx(r3, abs=1e-9)
        va = 5.0 * r1 * np.array([math.cos(phi), -math.sin(phi)])
        assert p["v_rel_m_s"] == pytest.approx(float(va @ u), abs=1e-9)
        assert p["omega_link_rad_s"] == pytest.approx(float(va @ n) / p["rho_m"], abs=1e-9)
        assert p["a_cor_m_s2"] == pytest.approx(2 * p["omega_link_rad_s"] * p["v_rel_m_s"], abs=1e-9)
        # the rod is rigid: B and C have equal velocity components along BC
        vb = p["omega_link_rad_s"] * r2 * n
        rod = (bb - np.array([p["x_c_m"], b])) / r3
        assert float(vb @ rod) == pytest.approx(p["v_c_m_s"] * rod[0], abs=1e-9)
        assert -180.0 < p["link_angle_deg"] <= 180.0 and 0.0 <= p["phi_deg"] < 360.0


def test_curve_csv_differences(tmp_path):
    res = run("linkage", *ACCEPT, "--rpm", "30", "--no-plots", "--out", tmp_path, "--lang", "en")
    assert res.exit_code == 0, res.output
    rows = list(csv.DictReader((tmp_path / "linkage" / "linkage_curve.csv").open(encoding="utf-8")))
    assert len(rows) == 721
    t = np.array([[float(r[k]) for k in ("phi_from_start_deg", "x_c_m", "v_c_m_s", "a_c_m_s2")] for r in rows])
    omega = 30 * math.pi / 30
    dt = math.radians(0.5) / omega
    v_fd = (t[2:, 1] - t[:-2, 1]) / (2 * dt)
    a_fd = (t[2:, 2] - t[:-2, 2]) / (2 * dt)
    assert np.max(np.abs(v_fd - t[1:-1, 2])) < 1e-4 * np.max(np.abs(t[:, 2]))
    assert np.max(np.abs(a_fd - t[1:-1, 3])) < 1e-3 * np.max(np.abs(t[:, 3]))
    assert t[0, 1] == pytest.approx(t[-1, 1], abs=1e-12)  # one full turn
    assert np.ptp(t[:, 1]) == pytest.approx(0.16, abs=1e-6)


def test_figures_and_tables(tmp_path):
    res = run("linkage", *ACCEPT, "--rpm", "60", "--at", "120", "--out", tmp_path, "--lang", "ru", "--format", "svg")
    assert res.exit_code == 0, res.output
    names = sorted(p.name for p in (tmp_path / "linkage").iterdir() if p.name != MANIFEST)
    assert names == ["linkage.json", "linkage_acceleration_plan.svg", "linkage_curve.csv", "linkage_diagrams.svg",
                     "linkage_mechanism.svg", "linkage_velocity_plan.svg"]
    assert "1,709953" in res.output and "Витворта" in res.output and "План" in res.output
    svg = (tmp_path / "linkage" / "linkage_acceleration_plan.svg").read_text(encoding="utf-8")
    assert "План ускорений" in svg or "<path" in svg


def test_rerun_replaces_own_files_keeps_users(tmp_path):
    folder = tmp_path / "linkage"
    assert run("linkage", *ACCEPT, "--rpm", "60", "--out", tmp_path, "--format", "pdf").exit_code == 0
    (folder / "my_notes.txt").write_text("mine", encoding="utf-8")
    (folder / "linkage_mine.png").write_bytes(b"mine")
    assert run("linkage", *ACCEPT, "--rpm", "60", "--out", tmp_path, "--no-plots").exit_code == 0
    names = sorted(p.name for p in folder.iterdir() if p.name != MANIFEST)
    assert "my_notes.txt" in names and "linkage_mine.png" in names  # never ours, never touched
    assert not any(n.endswith(".pdf") for n in names)  # the figures of the earlier run are gone


def test_crank_shaper_and_eps(tmp_path):
    res = run("linkage", "--r1", "0.1", "--h", "0.3", "--r2", "0.5", "--r3", "0.2", "--b", "0.22", "--omega", "4",
              "--eps-crank", "3", "--positions", "8", "--json", "--no-plots", "--out", tmp_path)
    assert res.exit_code == 0, res.output
    doc = json.loads(res.stdout)
    beta = math.asin(1 / 3)
    assert doc["regime"] == "crank_shaper"
    assert doc["time_ratio"] == pytest.approx((math.pi + 2 * beta) / (math.pi - 2 * beta), rel=1e-9)
    assert doc["stroke_m"] == pytest.approx(2 * 0.5 / 3, rel=1e-9)
    assert len(doc["positions"]) == 8
    assert doc["input"]["eps_crank_rad_s2"] == 3.0
    assert any("ε21" in n for n in doc["notes"])


# --- TOML input ---------------------------------------------------------------------------------


def test_toml_single(tmp_path):
    f = tmp_path / "m.toml"
    f.write_text("r1 = 0.10\nh = 0.04\nc = 0.0\nr2 = 0.08\nr3 = 0.30\nb = -0.04\nrpm = 60\npositions = 6\n", encoding="utf-8")
    res = run("linkage", "--input", f, "--json", "--no-plots", "--out", tmp_path / "o")
    assert res.exit_code == 0, res.output
    doc = json.loads(res.stdout)
    assert doc["time_ratio"] == pytest.approx(1.709953, abs=5e-7) and len(doc["positions"]) == 6
    # an option beats the file; --omega on the command line beats rpm in the file
    res = run("linkage", "--input", f, "--r2", "0.05", "--omega", "1", "--json", "--no-plots", "--out", tmp_path / "o")
    doc = json.loads(res.stdout)
    assert doc["stroke_m"] == pytest.approx(0.10, abs=1e-12) and doc["input"]["omega_rad_s"] == 1.0


def test_toml_variants(tmp_path):
    f = tmp_path / "dept.toml"
    f.write_text("rpm = 60\nc = 0\n[variants.1]\nr1 = 0.10\nh = 0.04\nr2 = 0.08\nr3 = 0.30\nb = -0.04\n"
                 "[variants.2]\nr1 = 0.1\nh = 0.3\nr2 = 0.5\nr3 = 0.2\nb = 0.22\n", encoding="utf-8")
    res = run("linkage", "--input", f, "--variant", "2", "--json", "--no-plots", "--out", tmp_path / "o")
    assert res.exit_code == 0, res.output
    assert json.loads(res.stdout)["regime"] == "crank_shaper"
    assert_one_line_error(run("linkage", "--input", f, "--out", tmp_path / "o"), "--variant", "1, 2")
    assert_one_line_error(run("linkage", "--input", f, "--variant", "7", "--out", tmp_path / "o"), "no variant 7")


@pytest.mark.parametrize("text, words", [
    ("r1 = 0,10\n", ["not valid TOML", "decimal dot"]),
    ("r1 = 0.1\nlength = 3\n", ["unknown key 'length'"]),
    ("r1 = \"0.1\"\n", ["'r1' must be a number"]),
    ("positions = 12.5\n", ["whole number"]),
    ("r1 = true\n", ["must be a number"]),
])
def test_toml_bad(tmp_path, text, words):
    f = tmp_path / "bad.toml"
    f.write_text(text, encoding="utf-8")
    out = tmp_path / "o"
    assert_one_line_error(run("linkage", "--input", f, "--out", out), *words)
    assert files_under(out) == []


def test_toml_too_big_and_missing(tmp_path):
    f = tmp_path / "big.toml"
    f.write_text("# " + "x" * 70000 + "\n", encoding="utf-8")
    assert_one_line_error(run("linkage", "--input", f, "--out", tmp_path / "o"), "64 KiB")
    assert_one_line_error(run("linkage", "--input", tmp_path / "none.toml", "--out", tmp_path / "o"), "does not exist")
    assert files_under(tmp_path / "o") == []


# --- hostile input: one line, exit 2, no files ----------------------------------------------------


@pytest.mark.parametrize("args, words", [
    (["--r1", "0"], ["--r1", "positive"]),
    (["--r1", "-0.1"], ["--r1", "positive"]),
    (["--h", "0"], ["--h", "positive"]),
    (["--r3", "0.01"], ["rod cannot reach", "--r3"]),
    (["--b", "1.0"], ["rod cannot reach"]),
    (["--h", "0.3", "--r2", "0.3"], ["block leaves", "--r2"]),
    (["--h", "0.1"], ["passes through"]),
    (["--r1", "abc"], ["--r1"]),
    (["--positions", "1"], ["--positions"]),
    (["--positions", "abc"], ["--positions"]),
    (["--wheel", "3"], ["--wheel"]),
    (["--rpm", "-5"], ["positive crank speed"]),
    (["--rpm", "0"], ["positive crank speed"]),
    (["--omega", "3"], ["once"]),
    (["--r1", "nan"], ["--r1"]),
    (["--at", "inf"], ["--at"]),
    (["--variant", "3"], ["--input"]),
    (["--format", "bmp"], ["--format"]),
])
def test_hostile_input(tmp_path, args, words):
    base = dict(zip(ACCEPT[::2], ACCEPT[1::2]))
    base["--rpm"] = "60"
    for k, v in zip(args[::2], args[1::2]):
        base[k] = v
    flat = [x for kv in base.items() for x in kv]
    out = tmp_path / "o"
    res = run("linkage", *flat, "--out", out)
    assert_one_line_error(res, *words)
    assert files_under(out) == []


def test_missing_dimensions_and_speed(tmp_path):
    assert_one_line_error(run("linkage", "--r1", "0.1", "--out", tmp_path / "o"), "--h M", "--r2 M", "--b M")
    assert_one_line_error(run("linkage", *ACCEPT, "--out", tmp_path / "o"), "--rpm")
    assert files_under(tmp_path / "o") == []


def test_help_imports_only_click():
    code = ("import sys, tmm_cli.cli; tmm_cli.cli.cli(['linkage', '--help'], standalone_mode=False); "
            "print(sorted(m for m in ('numpy', 'scipy', 'matplotlib', 'rich', 'tmm_cli.linkage.geometry') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip().splitlines()[-1] == "[]"
    assert "--eps-crank" in out and "--input" in out


def test_figures_are_figure_objects_with_textbook_labels():
    from matplotlib.figure import Figure

    from tmm_cli.linkage.analysis import analyse
    from tmm_cli.linkage.geometry import make_geometry
    from tmm_cli.render.figures.linkage import linkage_figures

    r = analyse(make_geometry(0.10, 0.04, 0.0, 0.08, 0.30, -0.04), omega=2 * math.pi, eps=3.0)
    figs = linkage_figures(r, "ru")
    assert list(figs) == ["linkage_mechanism", "linkage_diagrams", "linkage_velocity_plan", "linkage_acceleration_plan"]
    assert all(isinstance(f, Figure) for f in figs.values())

    def texts(fig):
        return {t.get_text() for ax in fig.axes for t in ax.texts} | {ax.get_title() for ax in fig.axes}

    vel, acc = texts(figs["linkage_velocity_plan"]), texts(figs["linkage_acceleration_plan"])
    assert {"$p$", "$a_2$", "$a_4$", "$b$", "$c$"} <= {s for t in vel for s in t.split(", ")}
    assert {r"$\pi$", "$n_1$", "$a_2$", "$k$", "$a_4$", "$n_4$", "$b$", "$n_5$", "$c$"} <= {s for t in acc for s in t.split(", ")}
    assert any("План скоростей" in t for t in vel) and any("План ускорений" in t for t in acc)
    assert any("$a^{k}_{A_4A_2}$" in t for t in acc)  # the Coriolis acceleration, mathtext subscripts
