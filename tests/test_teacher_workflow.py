"""Issue 9, the teacher's group workflow: rosters and answers as teachers have them (encodings,
separators, Russian headers), check.csv / check.md, warnings by name in summary.csv, the CSV
locale, the shipped examples."""

import csv
import io
import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from tmm_cli.teacher.roster import jobs_from_roster
from tmm_cli.cli import cli

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"


def run(*args, **kw):
    return CliRunner().invoke(cli, [str(a) for a in args], **kw)


ROSTER_RU = "ФИО;вариант;группа;n_кр;момент\nИванов И. И.;17;П-243;95;120,5\nПетрова А. А.;3;П-243;;\n"
ROSTER_EN = "student,variant,group,crank_rpm,torque\nИванов И. И.,17,П-243,95,120.5\nПетрова А. А.,3,П-243,,\n"


@pytest.mark.parametrize("text", [ROSTER_RU, ROSTER_EN, ROSTER_RU.replace("ФИО", "Студент")])
@pytest.mark.parametrize("encoding, name", [("utf-8", "UTF-8"), ("utf-8-sig", "UTF-8 (BOM)"), ("cp1251", "cp1251"),
                                            ("utf-16", "UTF-16")])
def test_roster_as_teachers_save_it(tmp_path, text, encoding, name):
    p = tmp_path / "r.csv"
    p.write_bytes(text.replace("\n", "\r\n").encode(encoding))
    plan = jobs_from_roster(p, None, None)
    assert plan.encoding.startswith(name) and plan.bad == []
    a, b = plan.jobs
    assert (a.label, a.variant, a.group, a.crank_rpm, a.torque_nm) == ("Иванов И. И.", "17", "П-243", 95.0, 120.5)
    assert (b.label, b.variant, b.crank_rpm, b.torque_nm) == ("Петрова А. А.", "3", None, None)
    assert a.folder == "Иванов_И._И/variant-17"
    assert plan.delimiter == (";" if ";" in text.splitlines()[0] else ",")


@pytest.mark.parametrize("raw, words", [
    (b"student,variant\nA\x98\x98,1\n\xff\xfe\xfd", ["neither UTF-8 nor cp1251"]),
    (b"\xff\xfes\x00t\x00\x00\xd8", ["UTF-16"]),
    (b"student,variant\x00\x00\x00\n", ["not a text file"]),
])
def test_undecodable_roster_is_one_line(tmp_path, raw, words):
    p = tmp_path / "r.csv"
    p.write_bytes(raw)
    for args in (("batch", "--roster", p), ("check", "--roster", p, "--answers-dir", tmp_path)):
        res = run(*args, "--out", tmp_path / "o")
        assert res.exit_code == 2 and "internal error" not in res.stderr
        err = res.stderr.strip()
        assert len(err.splitlines()) == 1 and all(w in err for w in words), err
    assert not (tmp_path / "o").exists()


def test_batch_says_the_encoding_and_writes_the_group_and_title(tmp_path):
    p = tmp_path / "r.csv"
    p.write_bytes(ROSTER_RU.encode("cp1251"))
    res = run("batch", "--roster", p, "--no-plots", "--jobs", 1, "--report", "none", "--out", tmp_path / "o", "--lang", "ru")
    assert res.exit_code == 0, res.stderr
    assert "cp1251" in res.output and "220" not in res.output.split("\n")[0]
    raw = (tmp_path / "o" / "summary.csv").read_bytes()
    assert raw.startswith(b"\xef\xbb\xbf")  # Excel under a Russian locale needs the BOM
    rows = list(csv.DictReader(io.StringIO(raw.decode("utf-8-sig"), newline=""), delimiter=";"))
    assert rows[0]["студент"] == "Иванов И. И." and rows[0]["группа"] == "П-243" and rows[0]["статус"] == "готово"
    assert "," in rows[0]["r0, мм"] and "." not in rows[0]["r0, мм"]  # decimal comma
    assert float(rows[0]["r0, мм"].replace(",", ".")) > 0


def test_summary_flags_warnings_by_name_and_csv_locale_en(tmp_path):
    res = run("batch", "--variants", "1,17", "--no-plots", "--jobs", 1, "--report", "none", "--out", tmp_path,
              "--lang", "ru", "--csv-locale", "en")
    assert res.exit_code == 0, res.stderr
    lines = res.output.splitlines()
    assert "220" in lines[0] and sum("220" in ln and "n_кр" in ln for ln in lines) == 1  # said once, at the top
    raw = (tmp_path / "summary.csv").read_text(encoding="utf-8")
    rows = list(csv.DictReader(io.StringIO(raw, newline="")))
    assert list(rows[0])[:3] == ["студент", "группа", "вариант"]
    v1 = rows[0]
    doc = json.loads((tmp_path / "variant-01" / "results.json").read_text())
    # the flags come from the same warnings the JSON lists
    assert v1["подрезание"] == str(int(any("подрез" in w.lower() for w in doc["warnings"])))
    names = v1["предупреждения"]
    if v1["подрезание"] == "1":
        assert "подрезание" in names
    if v1["ошибка i"] == "1":
        assert "ошибка передаточного отношения" in names
    assert float(v1["r0, мм"]) == pytest.approx(doc["cam"]["r0_mm"], rel=1e-5)  # en locale: a dot
    res = run("batch", "--variants", "17", "--crank-rpm", 95, "--no-plots", "--report", "none", "--out", tmp_path, "--lang", "en")
    assert "220" not in res.output


def test_variant_list_out_of_range_is_refused_before_any_work(tmp_path):
    res = run("batch", "--variants", "1-99", "--out", tmp_path / "o")
    assert res.exit_code == 2 and "69-99" in res.stderr and len(res.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "o").exists()


def test_the_shipped_examples_work_as_documented(tmp_path):
    """docs/teachers.md: the roster and answers/ named after its students."""
    roster = EXAMPLES / "roster.csv"
    students = [r["student"] for r in csv.DictReader(roster.open(encoding="utf-8"))]
    from tmm_cli.inputs.names import file_name

    names = {p.stem for p in (EXAMPLES / "answers").iterdir()}
    assert {file_name(s) for s in students} == names
    res = run("check", "--roster", roster, "--answers-dir", EXAMPLES / "answers", "--out", tmp_path, "--lang", "en")
    assert res.exit_code == 1, res.stderr
    assert "Ivanov" in res.output and "check.csv" in res.output
    lines = list(csv.DictReader((tmp_path / "check.csv").open(encoding="utf-8")))  # one line per checked value
    verdict = {r["student"]: r["verdict"] for r in lines}
    result = {(r["student"], r["key"]): r["result"] for r in lines}
    assert verdict == {"Ivanov": "passed", "Petrova": "not passed", "Sidorov": "not passed"}
    assert result["Petrova", "z_ring"] == "wrong" and result["Sidorov", "eps_alpha"] == "missing (required)"
    md = (tmp_path / "check.md").read_text(encoding="utf-8")
    assert md.startswith("# Group check") and md.count("\n| ") == 4
    res = run("check", "--variant", 17, "--crank-rpm", 95, "--answers", EXAMPLES / "answers-Ivanov.toml")
    assert res.exit_code == 0, res.output


def test_answers_in_cp1251_and_utf16(tmp_path):
    text = "ключ;значение\r\nr0_mm;48,9\r\ne_mm;−20,6\r\n"
    for enc in ("cp1251", "utf-16", "utf-8-sig"):
        f = tmp_path / f"a-{enc}.csv"
        f.write_bytes((text if enc != "cp1251" else text.replace("−", "-")).encode(enc))
        res = run("check", "--variant", 17, "--answers", f, "--sheet", 3, "--json")
        assert res.exit_code == 0, (enc, res.stderr)
        assert json.loads(res.output)["passed"]


def test_roster_rows_without_crank_speed_are_counted_once(tmp_path):
    roster = tmp_path / "r.csv"
    roster.write_text("student,variant,crank_rpm\nA,1,95\nB,2,\nC,3,\n")
    res = run("batch", "--roster", roster, "--no-plots", "--jobs", 1, "--report", "none", "--out", tmp_path / "o", "--lang", "ru")
    assert res.exit_code == 0, res.stderr
    assert sum("2 строки без n_кр" in ln for ln in res.output.splitlines()) == 1
