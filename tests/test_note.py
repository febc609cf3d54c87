"""The explanatory note (issue 11): it compiles, reads as a document and cites only the book.

A CI subset of cases (every scheme, every law, the scheme-2 and two-stage reducers at crank 60 and
40 rpm, an undercut rocker) is compiled here without figures and its text read back with pypdf;
`python bench/note_all.py` runs the same checks on all 68 variants and the scheme cases.
"""

import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli
from tmm_cli.project import run_project
from tmm_cli.render.note import NOTE_FIGURES, markdown_note, write_note
from tmm_cli.i18n.numbers import num
from tmm_cli.inputs.titleblock import TitleFields
from tmm_cli.variants import load_table
from tmm_cli.output.folder import MANIFEST

pypdf = pytest.importorskip("pypdf")

# The equation numbers of the textbook (seed 001): (1.1)–(1.28) in section 1, (2.1)–(2.5) in
# section 2; checked against the seed text below when it is at hand.
BOOK_EQUATIONS = {f"1.{i}" for i in range(1, 29)} | {f"2.{i}" for i in range(1, 6)}
SEED = next(iter(sorted(Path("/work/shared/seeds").glob("001_*.txt"))), None) if Path("/work/shared/seeds").is_dir() else None

CI_CASES = [(1, None), (2, 60.0), (3, 40.0), (7, None), (8, None)]


def _text(pdf: Path) -> str:
    return "\n".join(page.extract_text() for page in pypdf.PdfReader(pdf).pages).replace("\xa0", " ")


def _squash(s: str) -> str:
    return re.sub(r"\s+", "", s)


@pytest.mark.skipif(SEED is None, reason="the textbook's text (/work/shared/seeds) is not here")
def test_book_equation_list_matches_the_seed():
    text = SEED.read_text(encoding="utf-8")
    found = set(re.findall(r"\\quad \(([12]\.\d{1,2})\)\$\$", text)) | set(re.findall(r"\(([12]\.\d{1,2})\)\$\$", text))
    assert found == BOOK_EQUATIONS


@pytest.fixture(scope="module")
def table():
    return load_table()


@pytest.mark.parametrize("number,crank", CI_CASES)
def test_note_compiles_and_reads_right(table, tmp_path, number, crank):
    r = run_project(table[number], crank_rpm=crank)
    write_note(tmp_path, r, "ru", TitleFields(student="Иванов И. И.", group="П-243"), {})
    assert (tmp_path / "note.pdf").read_bytes()[:5] == b"%PDF-"
    text = _text(tmp_path / "note.pdf")
    flat = _squash(text)
    # the variant's r0 and tooth numbers, with a decimal comma
    r0 = num(r.cam.sizing.r0_m * 1000, "ru", decimals=2)
    assert "," in r0 and r0 in text
    for stage in r.gears.planetary.stages:
        assert "/".join(map(str, stage.teeth)) in flat
    # no terminal syntax
    assert "_" not in text and "--" not in text
    # every equation number cited is one of the book's
    cited = set(re.findall(r"\((\d+\.\d+)\)", text))
    assert cited and cited <= BOOK_EQUATIONS, sorted(cited - BOOK_EQUATIONS)
    # the document's parts
    for word in ("Содержание", "Синтез кулачкового механизма", "Синтез зубчатых механизмов", "Заключение",
                 "Список литературы", "Таблица 1 –", "Пожбелко"):
        assert word.replace(" ", "") in flat, word


def test_note_in_english(table, tmp_path):
    r = run_project(table[4], crank_rpm=60.0)
    write_note(tmp_path, r, "en", TitleFields(), {})
    text = _text(tmp_path / "note.pdf")
    assert "Conclusion" in text.title() or "CONCLUSION" in text
    assert "_" not in text and "--" not in text
    assert num(r.cam.sizing.r0_m * 1000, "en", decimals=2) in text
    assert not re.search(r"[А-Яа-я]{4,}", text.replace("Пожбелко", "")), "Russian words in the English note"


def test_every_figure_is_referenced_and_every_reference_exists(table, tmp_path):
    """With figure files present, note.typ embeds each and the text refers to each by number."""
    r = run_project(table[2], crank_rpm=60.0)
    svg = '<svg xmlns="http://www.w3.org/2000/svg" width="100" height="60"><rect width="100" height="60"/></svg>'
    files = {}
    for name in NOTE_FIGURES:
        (tmp_path / f"{name}.svg").write_text(svg)
        files[name] = f"{name}.svg"
    write_note(tmp_path, r, "ru", TitleFields(), files)
    src = (tmp_path / "note.typ").read_text()
    embedded = set(re.findall(r'image\("([^"]+)"', src))
    assert embedded == {f"{n}.svg" for n in NOTE_FIGURES}
    labels = set(re.findall(r"<(fig-[a-z-]+)>", src))
    refs = set(re.findall(r"@(fig-[a-z-]+)\[\]", src))
    assert labels == refs == {"fig-" + n.replace("_", "-") for n in NOTE_FIGURES}
    text = _text(tmp_path / "note.pdf")
    for k in range(1, len(NOTE_FIGURES) + 1):
        assert f"Рисунок {k} –" in text


def test_markdown_is_a_document(table):
    r = run_project(table[17])
    md = markdown_note(r, "ru", [f"{n}.png" for n in NOTE_FIGURES])
    assert "```" not in md and "cam_motion\n" not in md
    assert md.startswith("# ")
    assert "\n## 1 Синтез кулачкового механизма" in md and "\n### 1.1 Исходные данные" in md
    assert "\n## 2 Синтез зубчатых механизмов" in md and "\n## Заключение" in md
    assert "| Величина | Значение | Содержание |" in md
    for k, n in enumerate(NOTE_FIGURES, 1):
        assert f"({n}.png)" in md and f"*Рисунок {k} – " in md
    assert "k<sub>φ</sub>" in md and "(1.9)" in md
    assert "(--" not in md and "--torque" not in md


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])


def test_project_writes_the_note_by_default(tmp_path):
    res = run("project", "--variant", 5, "--out", tmp_path, "--no-plots", "--lang", "ru", "--student", "Петров П. П.")
    assert res.exit_code == 0, res.output
    folder = tmp_path / "variant-05"
    assert {"note.pdf", "note.typ", "note-style.typ", "results.json"} <= {p.name for p in folder.iterdir()}
    assert "Петров П. П." in (folder / "note.typ").read_text()


def test_report_md_is_markdown(tmp_path):
    res = run("project", "--variant", 5, "--out", tmp_path, "--no-plots", "--report", "md", "--lang", "ru")
    assert res.exit_code == 0, res.output
    names = {p.name for p in (tmp_path / "variant-05").iterdir()} - {MANIFEST}
    assert "report.md" in names and "note.pdf" not in names
    assert "```" not in (tmp_path / "variant-05" / "report.md").read_text()


def test_broken_template_leaves_no_note_but_the_rest(tmp_path):
    bad = tmp_path / "style.typ"
    bad.write_text("#let note(meta, body) = { body\n", encoding="utf-8")  # unclosed brace
    out = tmp_path / "o"
    res = run("project", "--variant", 5, "--out", out, "--no-plots", "--note-template", bad)
    assert res.exit_code == 2
    assert "Traceback" not in res.output
    assert len(res.stderr.strip().splitlines()) == 1 and "note" in res.stderr
    names = {p.name for p in (out / "variant-05").iterdir()} - {MANIFEST}
    assert {"results.json", "cam_profile.csv"} <= names
    assert not names & {"note.pdf", "note.typ", "note-style.typ"}


def test_broken_template_removes_the_notes_figures(tmp_path, table):
    r = run_project(table[5])
    from tmm_cli.errors import TmmError
    from tmm_cli.render.project import write_project_folder

    with pytest.raises(TmmError):
        write_project_folder(r, tmp_path / "v", "ru", report="pdf", note_template="#let note(meta) = [",
                             plots=False)
    names = {p.name for p in (tmp_path / "v").iterdir()} - {MANIFEST}
    assert names == {"results.json", "cam_profile.csv"}


def test_missing_template_is_refused_before_writing(tmp_path):
    res = run("project", "--variant", 5, "--out", tmp_path / "o", "--no-plots", "--note-template", tmp_path / "nope.typ")
    assert res.exit_code == 2 and len(res.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "o").exists()


def test_a_department_template_is_used(tmp_path):
    from tmm_cli.render.note import default_template

    mine = tmp_path / "dept.typ"
    mine.write_text(default_template().replace('meta.contents-title', '"ОГЛАВЛЕНИЕ КАФЕДРЫ"'), encoding="utf-8")
    res = run("project", "--variant", 5, "--out", tmp_path / "o", "--no-plots", "--note-template", mine)
    assert res.exit_code == 0, res.output
    assert "ОГЛАВЛЕНИЕ КАФЕДРЫ" in _text(tmp_path / "o" / "variant-05" / "note.pdf")


def test_hostile_title_fields_stay_text(tmp_path, table):
    r = run_project(table[5])
    odd = 'Иванов "И." #panic() [x] $y$ \\ <z> @w // --q'
    write_note(tmp_path, r, "ru", TitleFields(student=odd, group="#1", teacher="*t*", org="_a_, b"), {})
    text = _text(tmp_path / "note.pdf")
    assert _squash(odd) in _squash(text) and "#1" in text and "*t*" in text and "_a_" in text


def test_tmm_note_recompiles_an_edited_note(tmp_path):
    assert run("project", "--variant", 5, "--out", tmp_path, "--no-plots", "--lang", "ru").exit_code == 0
    folder = tmp_path / "variant-05"
    src = folder / "note.typ"
    src.write_text(src.read_text(encoding="utf-8").replace("Заключение", "Выводы студента"), encoding="utf-8")
    res = run("note", folder)
    assert res.exit_code == 0, res.output
    assert "Выводы студента" in _text(folder / "note.pdf")
    # a broken edit: one line with the place, the old PDF kept, no temporary file left
    before = (folder / "note.pdf").read_bytes()
    src.write_text(src.read_text(encoding="utf-8") + "\n$n1$\n", encoding="utf-8")
    res = run("note", src)
    assert res.exit_code == 2 and len(res.stderr.strip().splitlines()) == 1
    assert "note.typ:" in res.stderr and "n1" in res.stderr
    assert (folder / "note.pdf").read_bytes() == before
    assert not [p for p in folder.iterdir() if p.name.startswith(".") and p.name != MANIFEST]
    res = run("note", tmp_path / "nowhere")
    assert res.exit_code == 2 and "no " in res.stderr
