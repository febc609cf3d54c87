"""`tmm linkage MECH.toml`: the JSON of issue 24, the files, --plan, --positions, and bad input as one
line in the user's language with exit status 2 and nothing written."""

import json
import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
CYRILLIC = re.compile("[А-Яа-яЁё]")
ENGLISH = re.compile(r"\b[A-Za-z]{2,} [A-Za-z]{2,} [A-Za-z]{2,}\b")


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])


def test_json_of_the_shaper(tmp_path):
    r = run("linkage", EXAMPLES / "shaper.toml", "--json", "--no-plots", "--out", tmp_path)
    assert r.exit_code == 0, r.output
    doc = json.loads(r.stdout)
    assert doc["time_ratio"] == pytest.approx(1.552149656, rel=1e-9)
    assert doc["stroke_m"] == pytest.approx(1 / 3, rel=1e-12)
    assert doc["structure"]["formula"] == "I(0,1) → II(2,3) → II(4,5)"
    assert [p["label"] for p in doc["positions"]][:9] == ["0", "1", "2", "3", "4", "5", "6", "7", "7′"]
    assert set(doc["positions"][0]["points"]["C"]) == {"x", "y", "vx", "vy", "ax", "ay"}
    assert sorted(p.name for p in (tmp_path / "linkage").iterdir() if not p.name.startswith(".")) == [
        "linkage.json", "linkage_curve.csv", "linkage_dynamics.csv"]  # the file has masses: sheet 2 too
    assert json.loads((tmp_path / "linkage" / "linkage.json").read_text(encoding="utf-8")) == doc
    r = run("linkage", EXAMPLES / "shaper.toml", "--json", "--no-plots", "--no-forces", "--out", tmp_path)
    assert r.exit_code == 0 and "dynamics" not in json.loads(r.stdout)
    assert sorted(p.name for p in (tmp_path / "linkage").iterdir() if not p.name.startswith(".")) == [
        "linkage.json", "linkage_curve.csv"]  # sheet 2's file of the run before is gone (the manifest owns it)


def test_tables_figures_and_the_plan_position(tmp_path):
    r = run("linkage", EXAMPLES / "four_bar.toml", "--plan", "6'", "--out", tmp_path, "--lang", "ru")
    assert r.exit_code == 0, r.output
    assert "Планы скоростей и ускорений, положение 6′" in r.stdout
    assert "Формула строения: I(0,1) → II(2,3)" in r.stdout
    names = {p.name for p in (tmp_path / "linkage").iterdir()}
    assert {"linkage_mechanism.png", "linkage_diagrams.png", "linkage_velocity_plan.png",
            "linkage_acceleration_plan.png", "linkage_velocity_plan_2.png"} <= names
    doc = json.loads((tmp_path / "linkage" / "linkage.json").read_text(encoding="utf-8"))
    assert doc["plans"][0]["position"] == "6′"


def test_positions_option_overrides_the_file(tmp_path):
    r = run("linkage", EXAMPLES / "compressor.toml", "--positions", "24", "--json", "--no-plots", "--out", tmp_path)
    assert r.exit_code == 0, r.output
    assert len(json.loads(r.stdout)["positions"]) == 24


def test_the_whitworth_options_still_work(tmp_path):
    r = run("linkage", "--r1", 0.10, "--h", 0.04, "--r2", 0.08, "--r3", 0.30, "--b", -0.04, "--rpm", 60, "--json",
            "--no-plots", "--out", tmp_path)
    assert r.exit_code == 0 and json.loads(r.stdout)["time_ratio"] == pytest.approx(1.70995278172)


def _bad(tmp_path):
    (tmp_path / "bad.toml").write_text("[frame]\nO = [0, 0]\n[crank]\npivot = \"O\"\njoint = \"A\"\nlength = -1\n"
                                       "rpm = 60\n", encoding="utf-8")
    (tmp_path / "short.toml").write_text(
        "[frame]\nO = [0, 0]\nC = [0.4, 0]\n[crank]\npivot = \"O\"\njoint = \"A\"\nlength = 0.1\nrpm = 60\n"
        "[[group]]\nkind = \"RRR\"\njoints = [\"A\", \"B\", \"C\"]\nlengths = [0.25, 0.2]\nbranch = \"left\"\n",
        encoding="utf-8")
    (tmp_path / "broken.toml").write_text("[frame\n", encoding="utf-8")
    (tmp_path / "latin1.toml").write_bytes("name = \"é\"\n".encode("latin-1"))
    (tmp_path / "big.toml").write_text("# " + "x" * 300_000 + "\n", encoding="utf-8")
    (tmp_path / "misplaced.toml").write_text(
        "[frame]\nO = [0, 0]\n[crank]\npivot = \"O\"\njoint = \"A\"\nlength = 0.1\nrpm = 60\npositions = 12\n",
        encoding="utf-8")


CASES = {
    "a negative length": (["{t}/bad.toml"], "'crank.length' = -1; длина должна лежать в (0, 100] м"),
    "cannot be assembled": (["{t}/short.toml"], "группу 1 (RRR A-B-C) нельзя собрать при φ = 180,0°: |AC| = 0,5 м, "
                                                "а AB + BC = 0,45 м; сделайте AB + BC длиннее 0,5 м"),
    "not TOML": (["{t}/broken.toml"], "— не TOML"),
    "not UTF-8": (["{t}/latin1.toml"], "— не текст в UTF-8"),
    "too big": (["{t}/big.toml"], "больше 256 КиБ"),
    "missing": (["{t}/nope.toml"], "не существует; укажите файл TOML с описанием механизма"),
    "misplaced key": (["{t}/misplaced.toml"], "'positions' прочитан как 'crank.positions'"),
    "with Whitworth options": ([str(EXAMPLES / "shaper.toml"), "--r1", "0.1"], "уже описывает механизм; уберите --r1"),
    "--plan without a file": (["--plan", "3", "--r1", "0.1"], "--plan требует файла механизма"),
    "unknown plan position": ([str(EXAMPLES / "shaper.toml"), "--plan", "13"], "--plan 13: такого положения нет"),
    "a mechanism file as --input": (["--input", str(EXAMPLES / "shaper.toml")], "— файл механизма; запустите tmm "
                                                                                "linkage"),
    "--positions out of range": ([str(EXAMPLES / "shaper.toml"), "--positions", "1"],
                                 "--positions = 1; задайте целое число положений кривошипа от 2 до 360"),
}


@pytest.mark.parametrize("case", list(CASES))
def test_bad_input_is_one_line_in_the_users_language(case, tmp_path):
    _bad(tmp_path)
    args, fragment = CASES[case]
    args = [a.replace("{t}", str(tmp_path)) for a in args]
    ru = run("linkage", *args, "--out", tmp_path / "o", "--lang", "ru")
    assert ru.exit_code == 2, (case, ru.output)
    lines = ru.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("tmm: ошибка: "), (case, ru.stderr)
    line = lines[0].replace(str(tmp_path), "").replace(str(EXAMPLES), "")
    assert fragment in line, (case, line)
    ours = re.sub(r"\((Expected|tmm linkage)[^;]*\)|tmm linkage \S+", "", line)  # the TOML parser's words; commands
    assert not ENGLISH.search(ours), (case, line)
    en = run("linkage", *args, "--out", tmp_path / "o", "--lang", "en")
    assert en.exit_code == 2 and en.stderr.startswith("tmm: error: ") and not CYRILLIC.search(
        en.stderr.replace("ошибка", "")), (case, en.stderr)
    assert not (tmp_path / "o").exists() or not [p for p in (tmp_path / "o").rglob("*") if p.is_file()]
