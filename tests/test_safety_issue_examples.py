"""Acceptance audit of issue 7 ("nothing lost, nothing leaked, nothing hangs"): the issue's own
examples, with its literal inputs, driven through the CLI — exit status, the one stderr line and
the files left behind. The classes are covered more widely (hypothesis, signals with the time to
stop, concurrent batches) in test_safety_files.py, test_safety_group.py and
test_safety_signals.py; this file pins the examples as the issue states them.
"""

import csv
import io
import json
import os
from pathlib import Path

import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])


def one_line_error(res, *words):
    assert res.exit_code == 2, (res.exit_code, res.output)
    err = res.stderr.strip()
    assert "Traceback" not in res.output and "internal error" not in err
    assert len(err.splitlines()) == 1 and err.startswith("tmm: error:"), err
    for w in words:
        assert w in err, (w, err)
    return err


# --- Data loss --------------------------------------------------------------------------------

def test_data_loss_user_files_in_the_output_folder_are_kept(tmp_path, monkeypatch):
    """`mkdir -p tmm-out/variant-17 && echo x > tmm-out/variant-17/notes.txt && tmm project --variant 17`."""
    monkeypatch.chdir(tmp_path)
    folder = tmp_path / "tmm-out" / "variant-17"
    folder.mkdir(parents=True)
    mine = {"notes.txt": "x\n", "drawing.dwg": "dwg", "cam_profile.png.bak": "bak", "gears_old.txt": "g"}
    for name, text in mine.items():
        (folder / name).write_text(text)
    for _ in range(2):  # a re-run removes only what tmm wrote
        res = run("project", "--variant", 17, "--no-plots", "--lang", "en")
        assert res.exit_code == 0, res.output
    for name, text in mine.items():
        assert (folder / name).read_text() == text
    assert (folder / "results.json").exists()


def test_data_loss_cam_out_dot_keeps_cam_notes(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "cam_notes.txt").write_text("mine")
    for _ in range(2):
        res = run("cam", "--variant", 17, "--out", ".", "--no-plots", "--lang", "en")
        assert res.exit_code == 0, res.output
    assert (tmp_path / "cam_notes.txt").read_text() == "mine"


def test_data_loss_symlinked_variant_folder_deletes_nothing_elsewhere(tmp_path):
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    (elsewhere / "thesis.docx").write_text("years of work")
    (elsewhere / "cam_profile.png").write_text("not ours")
    out = tmp_path / "out"
    out.mkdir()
    os.symlink(elsewhere, out / "variant-17")
    res = run("project", "--variant", 17, "--out", out, "--no-plots", "--lang", "en")
    one_line_error(res, "variant-17")  # refused: the folder is a link out of the output tree
    assert sorted(p.name for p in elsewhere.iterdir()) == ["cam_profile.png", "thesis.docx"]
    assert (elsewhere / "thesis.docx").read_text() == "years of work"
    assert (elsewhere / "cam_profile.png").read_text() == "not ours"


def test_data_loss_failed_run_leaves_no_empty_folders(tmp_path):
    """`--out newdir/deep/er` with a bad crank speed."""
    res = run("project", "--variant", 17, "--crank-rpm", -5, "--out", tmp_path / "newdir" / "deep" / "er")
    one_line_error(res, "crank")
    assert not (tmp_path / "newdir").exists()


# --- Security ---------------------------------------------------------------------------------

def test_security_check_never_reads_nor_echoes_files_outside_the_answers_folder(tmp_path):
    secret = tmp_path / "secret"
    secret.mkdir()
    (secret / "creds.csv").write_text("r0_mm,SECRET_7731\n")
    (secret / "abs.toml").write_text("r0_mm = 48.86\n# SECRET_ABS\n")
    answers = tmp_path / "answers"
    answers.mkdir()
    os.symlink(secret / "creds.csv", answers / "linked.csv")
    roster = tmp_path / "roster.csv"
    roster.write_text(f"student,variant,crank_rpm\n../secret/creds,17,95\n{secret / 'abs'},17,95\nlinked,17,95\n",
                      encoding="utf-8")
    out = tmp_path / "o"
    res = run("check", "--roster", roster, "--answers-dir", answers, "--out", out, "--json", "--lang", "en")
    everything = res.output + "".join(p.read_text(encoding="utf-8") for p in out.rglob("*") if p.is_file())
    assert "SECRET" not in everything
    doc = json.loads(res.stdout)
    assert doc["all_passed"] is False and not any(s["passed"] for s in doc["students"])


def test_security_grading_only_r0_mm_does_not_pass(tmp_path):
    f = tmp_path / "a.toml"
    f.write_text("r0_mm = 48.86\n")
    res = run("check", "--variant", 17, "--answers", f, "--json", "--lang", "en")
    doc = json.loads(res.stdout)
    assert res.exit_code == 1 and doc["passed"] is False and doc["missing"]
    assert set(doc["required"]) >= {"r0_mm", "z1", "z2", "z_sun", "n_motor_rpm"}


def test_security_a_csv_with_the_key_twice_is_refused(tmp_path):
    f = tmp_path / "a.csv"
    f.write_text("key,value\nr0_mm,10\nr0_mm,48.86\n")
    one_line_error(run("check", "--variant", 17, "--answers", f), "r0_mm", "twice")


@pytest.mark.parametrize("rtol", ["inf", "nan", "-1", "1e9"])
def test_security_rtol_must_be_finite_and_sensible(tmp_path, rtol):
    f = tmp_path / "a.toml"
    f.write_text("r0_mm = 48.86\n")
    one_line_error(run("check", "--variant", 17, "--answers", f, "--rtol", rtol), "--rtol")


def test_security_formula_cells_neutralised_and_rows_never_split(tmp_path):
    names = ['=HYPERLINK("http://x","y")', "+1+1", "-2+3", "@SUM(A1)", "line\u2028sep", "form\ffeed"]
    roster = tmp_path / "roster.csv"
    with open(roster, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(["student", "variant", "crank_rpm"])
        for n in names:
            w.writerow([n, 17, 95])
    (tmp_path / "answers").mkdir()
    res = run("check", "--roster", roster, "--answers-dir", tmp_path / "answers", "--out", tmp_path / "o",
              "--csv-locale", "en", "--lang", "en")
    assert res.exit_code == 1
    data = (tmp_path / "o" / "check.csv").read_text(encoding="utf-8")
    rows = list(csv.reader(io.StringIO(data, newline="")))
    assert len(data.splitlines()) == len(rows)  # no U+2028 / form feed splits a line
    for cell in (c for r in rows for c in r):
        assert cell[:1] not in ("=", "+", "-", "@", "\t", "\r"), cell
        assert "\u2028" not in cell and "\f" not in cell


# --- Errors that must be one line, exit 2 ------------------------------------------------------

@pytest.mark.parametrize("encoding", ["cp1251", "utf-16"])
def test_errors_cp1251_and_utf16_rosters_are_read(tmp_path, encoding):
    roster = tmp_path / "roster.csv"
    roster.write_bytes("student,variant,crank_rpm\nПетрова А.А.,17,95\n".encode(encoding))
    (tmp_path / "answers").mkdir()
    res = run("check", "--roster", roster, "--answers-dir", tmp_path / "answers", "--out", tmp_path / "o",
              "--json", "--lang", "en")
    assert res.exit_code == 1, res.output  # no answers file: not passed, but read and reported
    assert json.loads(res.stdout)["students"][0]["student"] == "Петрова А.А."


def test_errors_a_300_character_name_does_not_stop_the_class(tmp_path):
    roster = tmp_path / "roster.csv"
    roster.write_text("student,variant,crank_rpm\n" + "Я" * 300 + ",17,95\nIvanov,17,95\n", encoding="utf-8")
    answers = tmp_path / "answers"
    answers.mkdir()
    (answers / "Ivanov.toml").write_text("r0_mm = 48.86\n")
    res = run("check", "--roster", roster, "--answers-dir", answers, "--out", tmp_path / "o", "--json", "--lang", "en")
    assert res.exit_code == 1, res.output
    students = json.loads(res.stdout)["students"]
    assert len(students) == 2 and students[1]["student"] == "Ivanov" and students[1]["rows"]


@pytest.mark.parametrize("content", ["x = " + "[" * 5000 + "]" * 5000 + "\n", "r0_mm = " + "9" * 5000 + "\n"])
def test_errors_deeply_nested_toml_and_5000_digit_integer(tmp_path, content):
    f = tmp_path / "a.toml"
    f.write_text(content)
    one_line_error(run("check", "--variant", 17, "--answers", f), "TOML")


@pytest.mark.parametrize("args, words", [
    (("gears", "--variant", 17, "--torque", "1e308"), ["--torque"]),
    (("gears", "--variant", 17, "--planets", "99999999999999999999"), ["--planets"]),
    (("gears", "--variant", 17, "--crank-rpm", 95, "--tolerance", "1e6"), ["--tolerance"]),
    (("cam", "--variant", 17, "--step", "1e-9"), ["--step"]),
    (("batch", "--variants", "1-10000000", "--no-plots"), ["10000000"]),
])
def test_hangs_finish_with_one_line(tmp_path, args, words):
    res = run(*args, "--out", tmp_path / "o")
    one_line_error(res, *words)
    assert not (tmp_path / "o").exists()


def test_errors_json_never_prints_bare_nan_or_infinity(tmp_path):
    for args in (("cam", "--variant", 17), ("gears", "--variant", 17), ("project", "--variant", 3)):
        res = run(*args, "--json", "--no-plots", "--out", tmp_path, "--lang", "en")
        assert res.exit_code == 0
        json.loads(res.stdout, parse_constant=lambda c: pytest.fail(f"bare {c} in {args}"))


def test_must_hold_limits_are_documented():
    text = (Path(__file__).resolve().parents[1] / "docs" / "limits.md").read_text(encoding="utf-8")
    for word in ("--step", "--tolerance", "--planets", "roster", "answers"):
        assert word in text, word
