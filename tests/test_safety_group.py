"""Issue 7, the hostile class list: `tmm check` reads only inside --answers-dir and never shows a
foreign file; the summaries neutralise formulas; names map to files by one shared rule."""

import csv
import io
import json

import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli


def run(*args, **kw):
    return CliRunner().invoke(cli, [str(a) for a in args], **kw)


@pytest.fixture(scope="module")
def answers17(tmp_path_factory):
    """A complete, correct answers file for variant 17 at 95 rpm (from the exported JSON)."""
    out = tmp_path_factory.mktemp("a17")
    res = run("project", "--variant", 17, "--crank-rpm", 95, "--json", "--no-plots", "--out", out)
    doc = json.loads(res.output)
    st = doc["gears"]["planetary"]["stages"][0]
    values = dict(n_motor_rpm=doc["gears"]["motor"]["n_rpm"], z_sun=st["z_sun"], z_planet=st["z_planet"],
                  z_ring=st["z_ring"], planets=st["planets"], z1=doc["gears"]["spur"]["z1"], z2=doc["gears"]["spur"]["z2"],
                  eps_alpha=doc["gears"]["spur"]["eps_alpha"], r0_mm=doc["cam"]["r0_mm"], e_mm=doc["cam"]["e_mm"])
    return "".join(f"{k} = {v}\n" for k, v in values.items())


def _group(tmp_path, roster_text, files=None, *extra):
    ans = tmp_path / "answers"
    ans.mkdir(exist_ok=True)
    for name, text in (files or {}).items():
        (ans / name).write_text(text)
    roster = tmp_path / "roster.csv"
    roster.write_text(roster_text)
    res = run("check", "--roster", roster, "--answers-dir", ans, "--out", tmp_path / "o", "--json", *extra)
    assert res.exit_code in (0, 1), res.stderr
    return res, {s["student"]: s for s in json.loads(res.output)["students"]}


def test_check_never_reads_outside_the_answers_folder(tmp_path, answers17):
    secret = tmp_path / "secret"
    secret.mkdir()
    (secret / "creds.csv").write_text("key,value\nPASSWORD_hunter2,1\n")
    (secret / "full.toml").write_text(answers17)
    (tmp_path / "answers").mkdir()
    (tmp_path / "answers" / "Linked.toml").symlink_to(secret / "full.toml")
    roster = ("student,variant,crank_rpm\n"
              "../secret/creds,17,95\n"
              f"{secret / 'full'},17,95\n"
              "Linked,17,95\n")
    res, by = _group(tmp_path, roster)
    assert "hunter2" not in res.output and "PASSWORD" not in res.output
    assert not any(s["passed"] for s in by.values())
    assert "link" in by["Linked"]["error"]
    for s in by.values():
        assert s["error"], s
    text = (tmp_path / "o" / "check.csv").read_text() + (tmp_path / "o" / "check.md").read_text()
    assert "hunter2" not in text


def test_names_map_to_files_by_the_shared_rule(tmp_path, answers17):
    """Unicode NFC, control characters gone, long names cut, case collisions reported."""
    from tmm_cli.inputs.names import file_name

    nfd = "Петро\u0301в"  # combining accent: NFC keeps one spelling
    long = "Я" * 300
    files = {f"{file_name('Иванов И. И.')}.toml": answers17, f"{file_name(long)}.toml": answers17,
             f"{file_name(nfd)}.toml": answers17}
    roster = ("student;variant;crank_rpm\n"
              "Иванов И. И.;17;95\n"
              f"{long};17;95\n"
              f"{nfd};17;95\n"
              "ИВАНОВ И. И.;17;95\n"
              "Tab\tName\x07;17;95\n")
    res, by = _group(tmp_path, roster, files)
    assert by["Иванов И. И."]["passed"]
    assert by["Я" * 100]["passed"]  # shown cut to 100 characters, file name to 64
    assert [s for s in by if s.startswith("Петро")] and all(by[s]["passed"] for s in by if s.startswith("Петро"))
    assert "same file name" in by["ИВАНОВ И. И."]["error"]
    assert "Tab Name" in by and "no answers file Tab_Name.toml" in by["Tab Name"]["error"]


def test_a_hundred_character_name_does_not_stop_the_class(tmp_path, answers17):
    res, by = _group(tmp_path, "student,variant,crank_rpm\n" + "x" * 300 + ",17,95\nB,17,95\n", {"B.toml": answers17})
    assert by["B"]["passed"] and "no answers file" in by["x" * 100]["error"]


HOSTILE = ['=HYPERLINK("http://x","y")', "+1+1", "-2+3", "@SUM(A1)", "\tTab", "Form\ffeed", "Line\u2028sep"]


def test_summary_and_check_csv_neutralise_formulas(tmp_path):
    roster = tmp_path / "roster.csv"
    with open(roster, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(["student", "variant", "crank_rpm"])
        for i, name in enumerate(HOSTILE):
            w.writerow([name, 17 if i else "=1+2", 95])
    res = run("batch", "--roster", roster, "--no-plots", "--jobs", 1, "--report", "none", "--out", tmp_path / "o",
              "--lang", "en", "--csv-locale", "en")
    assert res.exit_code == 1, res.stderr  # the '=1+2' variant row fails
    data = (tmp_path / "o" / "summary.csv").read_text(encoding="utf-8")
    assert len(data.splitlines()) == 1 + len(HOSTILE)  # no name splits a row, even for str.splitlines
    rows = list(csv.DictReader(io.StringIO(data, newline="")))
    for r in rows:
        for key, cell in r.items():
            assert cell[:1] not in ("=", "+", "@", "\t", "\r"), (key, cell)
            if cell.startswith("-"):  # only a number may start with a minus
                float(cell)
    e = [float(r["e_mm"]) for r in rows if r["status"] == "ok"]
    assert e and all(x < 0 for x in e)  # a negative number stays a number
    res = run("check", "--roster", roster, "--answers-dir", tmp_path, "--out", tmp_path / "o", "--csv-locale", "en")
    for cell in [c for r in csv.reader(io.StringIO((tmp_path / "o" / "check.csv").read_text(), newline="")) for c in r]:
        assert cell[:1] not in ("=", "+", "-", "@", "\t", "\r"), cell


def test_student_named_like_a_variant_folder_gets_its_own(tmp_path):
    roster = tmp_path / "roster.csv"
    roster.write_text("student,variant\nvariant-40,17\nsummary.csv,3\n")
    out = tmp_path / "o"
    res = run("batch", "--roster", roster, "--no-plots", "--jobs", 1, "--report", "none", "--out", out, "--lang", "en")
    assert res.exit_code == 0, res.stderr
    assert not (out / "variant-40").exists() and (out / "student-variant-40" / "variant-17" / "results.json").is_file()
    assert (out / "summary.csv").is_file() and (out / "student-summary.csv" / "variant-03").is_dir()


def test_rerun_with_another_roster_leaves_only_its_folders(tmp_path):
    out = tmp_path / "o"
    r1, r2 = tmp_path / "r1.csv", tmp_path / "r2.csv"
    r1.write_text("student,variant\nAnna,1\nBoris,2\n")
    r2.write_text("student,variant\nVera,3\n")
    (out / "Anna").mkdir(parents=True)
    (out / "Anna" / "feedback.txt").write_text("the teacher's own note")
    (out / "mine").mkdir()
    args = ("--no-plots", "--jobs", 1, "--report", "none", "--out", out, "--lang", "en")
    assert run("batch", "--roster", r1, *args).exit_code == 0
    assert (out / "Boris" / "variant-02" / "results.json").is_file()
    assert run("batch", "--roster", r2, *args).exit_code == 0
    rows = list(csv.DictReader((out / "summary.csv").open(encoding="utf-8")))
    assert [r["student"] for r in rows] == ["Vera"]
    assert not (out / "Boris").exists() and not (out / "Anna" / "variant-01").exists()
    assert (out / "Anna" / "feedback.txt").read_text() == "the teacher's own note" and (out / "mine").is_dir()
    assert run("batch", "--variants", "5", *args).exit_code == 0
    assert not (out / "Vera").exists() and (out / "variant-05" / "results.json").is_file()


def test_a_foreign_summary_csv_is_refused_before_any_work(tmp_path):
    out = tmp_path / "o"
    out.mkdir()
    (out / "summary.csv").write_text("my marks")
    res = run("batch", "--variants", "1-2", "--no-plots", "--out", out)
    assert res.exit_code == 2 and "summary.csv" in res.stderr and len(res.stderr.strip().splitlines()) == 1
    assert sorted(p.name for p in out.iterdir()) == ["summary.csv"]
    assert (out / "summary.csv").read_text() == "my marks"


def test_a_foreign_check_csv_is_refused_before_any_work(tmp_path):
    out = tmp_path / "o"
    out.mkdir()
    (out / "check.md").write_text("my notes")
    (tmp_path / "r.csv").write_text("student,variant\nA,17\n")
    res = run("check", "--roster", tmp_path / "r.csv", "--answers-dir", tmp_path, "--out", out)
    assert res.exit_code == 2 and "check.md" in res.stderr and len(res.stderr.strip().splitlines()) == 1
    assert sorted(p.name for p in out.iterdir()) == ["check.md"] and (out / "check.md").read_text() == "my notes"


def test_answers_file_found_whatever_its_case_or_normal_form(tmp_path, answers17):
    import unicodedata

    nfd = unicodedata.normalize("NFD", "Йодов")  # macOS keeps file names decomposed
    res, by = _group(tmp_path, "student,variant,crank_rpm\nIvanov,17,95\nЙодов,17,95\n",
                     {"ivanov.TOML": answers17, f"{nfd}.toml": answers17})
    assert by["Ivanov"]["passed"] and by["Йодов"]["passed"]


def test_an_empty_roster_is_one_line(tmp_path):
    (tmp_path / "r.csv").write_text("student,variant\n\n")
    res = run("check", "--roster", tmp_path / "r.csv", "--answers-dir", tmp_path, "--out", tmp_path / "o")
    assert res.exit_code == 2 and "no students" in res.stderr and not (tmp_path / "o").exists()
