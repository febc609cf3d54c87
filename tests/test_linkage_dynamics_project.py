"""The course project as one chain (issue 25): `tmm project --mechanism` gives sheet 4 the driving
moment and the crank speed of sheets 1–2 and says so; `tmm batch` reads a `mechanism` column of the
roster (a path inside the roster's folder)."""

import csv
import json
import shutil
import tomllib
from pathlib import Path

import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli
from tmm_cli.errors import TmmError
from tmm_cli.project import analyse_linkage, run_project
from tmm_cli.variants import get_variant

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])


def tables(name):
    return tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))


def test_sheet4_takes_the_mechanisms_moment_and_speed():
    s2 = analyse_linkage(tables("shaper"), "shaper.toml")
    v = get_variant("17")
    with_file = run_project(v, linkage=s2, linkage_name="shaper.toml")
    by_hand = run_project(v, crank_rpm=60.0, torque_nm=abs(s2.dynamics.M_d))
    assert with_file.gears == by_hand.gears  # the same sheet 4 as giving the numbers by hand
    assert with_file.gears.torque_nm == pytest.approx(71.6197243913529, rel=1e-9)  # 450 J a turn / 2π
    assert with_file.notes[0].code == "project_mechanism_motor"
    assert not with_file.gears.crank_rpm_assumed


def test_project_command_with_a_mechanism(tmp_path):
    r = run("project", "-v", 17, "--mechanism", EXAMPLES / "four_bar.toml", "--no-plots", "--report", "md", "--no-sheets",
            "--out", tmp_path, "--lang", "en")
    assert r.exit_code == 0, r.output
    folder = tmp_path / "variant-17"
    doc = json.loads((folder / "results.json").read_text(encoding="utf-8"))
    assert doc["gears"]["crank_rpm"] == pytest.approx(120.0)
    assert doc["mechanism"]["dynamics"]["motor_moment_Nm"] == pytest.approx(4.033282633778, rel=1e-9)
    assert any("from the mechanism file four_bar.toml" in a for a in doc["assumptions"])
    linkage = json.loads((folder / "linkage.json").read_text(encoding="utf-8"))
    assert linkage["dynamics"]["drive_moment_Nm"] == doc["mechanism"]["dynamics"]["drive_moment_Nm"]
    assert (folder / "linkage_dynamics.csv").is_file()


def test_project_refuses_both_ways_and_a_file_without_load(tmp_path):
    r = run("project", "-v", 17, "--mechanism", EXAMPLES / "shaper.toml", "--crank-rpm", 60, "--out", tmp_path)
    assert r.exit_code == 2 and "drop --crank-rpm" in r.stderr
    r = run("project", "-v", 17, "--mechanism", EXAMPLES / "whitworth.toml", "--out", tmp_path, "--lang", "ru")
    assert r.exit_code == 2 and "нет таблицы [load]" in r.stderr, r.stderr
    assert not (tmp_path / "variant-17").exists()
    with pytest.raises(TmmError, match="has no \\[load\\]"):
        analyse_linkage(tables("whitworth"), "whitworth.toml")


def _roster(folder: Path, rows):
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "roster.csv"
    with open(path, "w", encoding="utf-8", newline="") as f:
        w = csv.writer(f)
        w.writerow(["student", "variant", "crank_rpm", "mechanism"])
        w.writerows(rows)
    return path


def test_roster_mechanism_column(tmp_path):
    from tmm_cli.teacher.roster import jobs_from_roster

    (tmp_path / "class" / "mech").mkdir(parents=True)
    shutil.copy(EXAMPLES / "shaper.toml", tmp_path / "class" / "mech" / "ivanov.toml")
    shutil.copy(EXAMPLES / "four_bar.toml", tmp_path / "outside.toml")
    path = _roster(tmp_path / "class", [
        ["Иванов И. И.", 17, "", "mech/ivanov.toml"],
        ["Петров П. П.", 18, "", "../outside.toml"],
        ["Сидоров С. С.", 19, "", str(tmp_path / "outside.toml")],
        ["Козлов К. К.", 20, "", "mech/nope.toml"],
        ["Орлов О. О.", 21, "100", "mech/ivanov.toml"],
        ["Белов Б. Б.", 22, "100", ""],
    ])
    plan = jobs_from_roster(path, None, None)
    jobs = {j.label: j for j in plan.jobs}
    assert jobs["Иванов И. И."].mechanism == str((tmp_path / "class" / "mech" / "ivanov.toml").resolve())
    assert jobs["Иванов И. И."].crank_rpm is None and jobs["Белов Б. Б."].mechanism == ""
    reasons = {b.job.label: b.reason for b in plan.bad}
    assert "lies outside the roster's folder" in reasons["Петров П. П."]
    assert "lies outside the roster's folder" in reasons["Сидоров С. С."]
    assert "does not exist" in reasons["Козлов К. К."]
    assert "leave crank_rpm empty" in reasons["Орлов О. О."]
    from tmm_cli.i18n.errors import translate_error

    for reason in reasons.values():
        assert translate_error(reason) != reason and "список группы, строка" in translate_error(reason)


def test_batch_runs_a_roster_with_mechanisms(tmp_path):
    (tmp_path / "class").mkdir()
    shutil.copy(EXAMPLES / "shaper.toml", tmp_path / "class" / "shaper.toml")
    path = _roster(tmp_path / "class", [["Иванов И. И.", 17, "", "shaper.toml"], ["Петров П. П.", 18, "", ""]])
    r = run("batch", "--roster", path, "--no-plots", "--report", "none", "--jobs", 1, "--out", tmp_path / "out")
    assert r.exit_code == 0, r.output
    with_file = json.loads(next((tmp_path / "out").rglob("variant-17/results.json")).read_text(encoding="utf-8"))
    without = json.loads(next((tmp_path / "out").rglob("variant-18/results.json")).read_text(encoding="utf-8"))
    assert with_file["gears"]["crank_rpm"] == pytest.approx(60.0) and "mechanism" in with_file
    assert without["gears"]["crank_rpm_assumed"] and "mechanism" not in without


def test_project_sheets_share_one_designation_scheme(tmp_path):
    """With --mechanism the four sheets carry the project's variant in ТММ.<sheet>.<variant>.00.00
    (sheets 1–2 said 00, sheets 3–4 the variant; teacher's review)."""
    import ezdxf

    r = run("project", "-v", 17, "--mechanism", EXAMPLES / "four_bar.toml", "--no-plots", "--report", "md",
            "--out", tmp_path, "--lang", "ru")
    assert r.exit_code == 0, r.output
    folder = tmp_path / "variant-17"
    for n in (1, 2, 3, 4):
        texts = {e.dxf.text for e in ezdxf.readfile(folder / f"sheet{n}.dxf").modelspace().query("TEXT")}
        assert f"ТММ.0{n}.17.00.00" in texts, n
