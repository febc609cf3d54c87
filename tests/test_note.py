"""The explanatory note as documents: note.pdf (typst) and note.docx (Word) from one model.

CI compiles a sample of cases (every scheme and law, the double-row and two-stage reducers, a
rocker, English) and reads them back: the PDF with pypdf (the ГОСТ 7.32 parts, the page, the fonts,
the numbers), the DOCX with python-docx (styles, fields, tables, equations, pictures) and the OOXML
validator. `pytest -m slow` does it for every variant (test_every_variants_note_pdf_and_docx).
The reasoning and the substitutions of every variant's note are checked in test_note_claims.py.
"""

from __future__ import annotations

import re
import zipfile
from pathlib import Path

import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli
from tmm_cli.i18n.numbers import num
from tmm_cli.inputs.titleblock import TitleFields
from tmm_cli.output.folder import MANIFEST
from tmm_cli.project import run_project
from tmm_cli.render.note import NOTE_FIGURES, markdown_note, write_note
from tmm_cli.variants import load_table

pypdf = pytest.importorskip("pypdf")

CI_CASES = [(1, None), (2, 60.0), (3, 40.0), (7, None), (8, None), (17, None)]
MM = 72 / 25.4


def _text(pdf: Path) -> str:
    return "\n".join(page.extract_text() for page in pypdf.PdfReader(pdf).pages).replace("\xa0", " ").replace("\u202f", " ")


def _squash(s: str) -> str:
    return re.sub(r"\s+", "", s)


@pytest.fixture(scope="module")
def table():
    return load_table()


def _check_pdf(folder: Path, r, lang: str = "ru") -> str:
    pdf = folder / "note.pdf"
    assert pdf.read_bytes()[:5] == b"%PDF-"
    reader = pypdf.PdfReader(pdf)
    text = _text(pdf)
    flat = _squash(text)
    r0 = num(r.cam.sizing.r0_m * 1000, lang, decimals=2)
    assert r0 in text
    for stage in r.gears.planetary.stages:
        assert "/".join(map(str, stage.teeth)) in flat
    assert not re.search(r"[^\W_]_[^\W_(]|[^\W_]_\(", text) and "--" not in text  # no typst or terminal syntax (blanks ___ are lines to fill)
    # the book's equations are cited "[1, формула (1.9)]", never used as the note's own numbers
    if lang == "ru":
        assert "[1,формула(1.5)]" in flat
        for part in ("ЗАДАНИЕ", "РЕФЕРАТ", "СОДЕРЖАНИЕ", "ВВЕДЕНИЕ", "ЗАКЛЮЧЕНИЕ", "СПИСОКИСПОЛЬЗОВАННЫХИСТОЧНИКОВ",
                     "ПРИЛОЖЕНИЕА", "Таблица1–", "Пожбелко,В.И."):
            assert part in flat, part
        # the note's formulas numbered (1), (2), … once each
        numbers = [int(n) for n in re.findall(r"\((\d{1,3})\)\s*$", text, flags=re.M)]
        assert numbers[:3] == [1, 2, 3] and len(numbers) == len(set(numbers))
    # ГОСТ 7.32 page: A4; the title page has no number, the next pages their number at the bottom
    box = reader.pages[0].mediabox
    assert abs(float(box.width) - 210 * MM) < 1 and abs(float(box.height) - 297 * MM) < 1
    assert not re.search(r"^\s*1\s*$", reader.pages[0].extract_text(), flags=re.M)
    assert reader.pages[1].extract_text().strip().endswith("2")
    # the fonts tmm ships, embedded: Liberation Serif for the text, STIX Math for the formulas, and
    # nothing else (typst takes a glyph the fonts lack silently from a font of its own, e.g. "⁻")
    fonts = pdf_fonts(reader)
    assert any("LiberationSerif" in f for f in fonts) and any("STIX" in f for f in fonts), fonts
    assert all(re.search(r"LiberationSerif|STIXMath", f) for f in fonts), fonts
    return text


def pdf_fonts(reader) -> set[str]:
    """Every font of the PDF by name (subset prefix dropped), those of the figures' forms included."""
    fonts, seen = set(), set()

    def visit(resources):
        resources = resources.get_object() if resources is not None else None
        if not resources:
            return
        for f in (resources.get("/Font") or {}).values():
            fonts.add(str(f.get_object().get("/BaseFont")).split("+")[-1])
        for x in (resources.get("/XObject") or {}).values():
            ref = getattr(x, "idnum", None)
            if ref in seen:
                continue
            seen.add(ref)
            x = x.get_object()
            if x.get("/Subtype") == "/Form":
                visit(x.get("/Resources"))

    for page in reader.pages:
        visit(page.get("/Resources"))
    return fonts


@pytest.mark.parametrize("number,crank", CI_CASES)
def test_note_compiles_and_reads_right(table, tmp_path, number, crank):
    r = run_project(table[number], crank_rpm=crank)
    write_note(tmp_path, r, "ru", TitleFields(student="Иванов И. И.", group="П-243"), {})
    text = _check_pdf(tmp_path, r)
    assert "Иванов И. И." in text


def test_note_in_english(table, tmp_path):
    r = run_project(table[4], crank_rpm=60.0)
    write_note(tmp_path, r, "en", TitleFields(), {})
    text = _text(tmp_path / "note.pdf")
    assert "CONCLUSION" in text and not re.search(r"[^\W_]_[^\W_]", text) and "--" not in text
    assert num(r.cam.sizing.r0_m * 1000, "en", decimals=2) in text
    assert not re.search(r"[А-Яа-я]{4,}", text.replace("Пожбелко", "")), "Russian words in the English note"
    fonts = pdf_fonts(pypdf.PdfReader(tmp_path / "note.pdf"))
    assert all(re.search(r"LiberationSerif|STIXMath", f) for f in fonts), fonts


def test_the_page_is_gost(table, tmp_path):
    """Margins 30/15/20/20 mm: the text of a chapter page starts 30 mm from the left and reaches 15 mm
    from the right (justified), the page number sits in the bottom margin, centred."""
    r = run_project(table[17])
    write_note(tmp_path, r, "ru", TitleFields(), {})
    page = pypdf.PdfReader(tmp_path / "note.pdf").pages[6]
    xs, num_pos = [], []

    def visit(text, cm, tm, font, size):
        if text.strip():
            x, y = tm[4] * cm[0] + cm[4], tm[5] * cm[3] + cm[5]
            xs.append(x)
            if text.strip().isdigit() and y < 20 * MM:
                num_pos.append((x, y))

    page.extract_text(visitor_text=visit)
    assert min(xs) == pytest.approx(30 * MM, abs=1.0)
    assert num_pos and abs(num_pos[-1][0] - (30 + 165 / 2) * MM) < 4 * MM


def test_figures_are_referenced_then_placed_below_with_their_number(table, tmp_path):
    """With figure files present, note.typ embeds each once, after the paragraph that refers to it."""
    r = run_project(table[2], crank_rpm=60.0)
    svg = '<svg xmlns="http://www.w3.org/2000/svg" width="100" height="60"><rect width="100" height="60"/></svg>'
    files = {}
    for name in NOTE_FIGURES:
        (tmp_path / f"note_{name}.svg").write_text(svg)
        files[name] = (f"note_{name}.svg", None, 16.5, 10.0)
    write_note(tmp_path, r, "ru", TitleFields(), files)
    src = (tmp_path / "note.typ").read_text()
    embedded = re.findall(r'image\("([^"]+)"', src)
    assert sorted(embedded) == sorted(f"note_{n}.svg" for n in NOTE_FIGURES)
    for name in NOTE_FIGURES:
        label = "fig-" + name.replace("_", "-")
        ref = src.index(f"#ref(<{label}>")
        assert ref < src.index(f"<{label}>\n")  # the first reference comes before the figure
    text = _text(tmp_path / "note.pdf")
    for k in range(1, len(NOTE_FIGURES) + 1):
        assert f"Рисунок {k} –" in text


def test_markdown_is_the_same_note(table):
    r = run_project(table[17])
    md = markdown_note(r, "ru", [f"{n}.png" for n in NOTE_FIGURES])
    assert md.startswith("# ") and "```" not in md
    assert "\n## 1 Синтез кулачкового механизма" in md and "\n### 1.1 Исходные данные" in md
    assert "\n## 2 Синтез зубчатых механизмов" in md and "\n## Заключение" in md
    for k, n in enumerate(NOTE_FIGURES, 1):
        assert f"({n}.png)" in md and f"*Рисунок {k} – " in md
    assert "k<sub>φ</sub>" in md and "[1, формула (1.5)]" in md
    assert "(--" not in md and "--torque" not in md


# --- DOCX ---------------------------------------------------------------------------------------


def _check_docx(path: Path, r) -> None:
    import docx
    from docx.oxml.ns import qn
    from docx.shared import Mm

    d = docx.Document(str(path))
    sec = d.sections[0]
    assert (round(sec.page_width / Mm(1)), round(sec.page_height / Mm(1))) == (210, 297)
    assert [round(x / Mm(1)) for x in (sec.left_margin, sec.right_margin, sec.top_margin, sec.bottom_margin)] == [30, 15, 20, 20]
    assert sec.different_first_page_header_footer  # no number on the title page
    normal = d.styles["Normal"]
    assert normal.font.name == "Times New Roman" and normal.font.size.pt == 14
    assert abs(normal.paragraph_format.first_line_indent.cm - 1.25) < 0.01
    styles = [p.style.style_id for p in d.paragraphs]
    assert styles.count("Heading1") >= 3 and styles.count("Heading2") >= 10 and "Caption" in styles
    xml = d.element.xml
    assert 'TOC \\o "1-2"' in xml and " PAGE " in d.sections[0].footer._element.xml and "NUMPAGES" in xml
    assert "SEQ Таблица" in xml
    body = d.element.body
    assert len(list(body.iter(qn("m:oMathPara")))) >= 40 and len(list(body.iter(qn("m:f")))) > 30
    headers = [t for t in d.tables if t._tbl.find(".//" + qn("w:tblHeader")) is not None]
    assert len(headers) >= 5  # the data tables repeat their header row on every page
    text = "\n".join(p.text for p in d.paragraphs).replace("\u2060", "")  # the units' word joiners
    assert "ЗАКЛЮЧЕНИЕ" in text and "СПИСОК ИСПОЛЬЗОВАННЫХ ИСТОЧНИКОВ" in text and "Пожбелко" in text
    assert "/".join(map(str, r.gears.planetary.stages[0].teeth)) in text
    with zipfile.ZipFile(path) as z:
        names = z.namelist()
        assert "word/document.xml" in names and "word/stylesWithEffects.xml" not in names
        for n in names:
            if n.endswith(".xml") or n.endswith(".rels"):
                from lxml import etree

                etree.fromstring(z.read(n))  # well-formed


def _audit(path: Path) -> None:
    audit = pytest.importorskip("openxml_audit")
    result = audit.OpenXmlValidator(file_format=audit.FileFormat.OFFICE_2019).validate(str(path))
    assert result.is_valid, [str(e) for e in result.errors][:5]


def test_docx_opens_clean_with_figures(table, tmp_path):
    """note.docx of variant 3 with the note's own figures: SVG for Word 2016+, a 300 dpi PNG beside it."""
    from tmm_cli.render.figures.note import save_note_figure
    from tmm_cli.render.figures.note_scales import figure_size_cm

    r = run_project(table[3])
    files = {}
    for name in ("cam_zone", "gears_mesh"):
        save_note_figure(tmp_path, r, "ru", name, raster=True)
        files[name] = (f"note_{name}.svg", f"note_{name}.png", *figure_size_cm(name, r.gears))
    write_note(tmp_path, r, "ru", TitleFields(student="Сидоров С. С."), files, docx=True, pdf=False)
    path = tmp_path / "note.docx"
    _check_docx(path, r)
    _audit(path)
    with zipfile.ZipFile(path) as z:
        media = [n for n in z.namelist() if n.startswith("word/media/")]
        assert sum(n.endswith(".svg") for n in media) == 2 and sum(n.endswith(".png") for n in media) == 2
        doc = z.read("word/document.xml").decode()
        assert doc.count("svgBlip") == 2
        from PIL import Image
        import io

        png = next(n for n in media if n.endswith(".png"))
        assert Image.open(io.BytesIO(z.read(png))).info["dpi"][0] >= 299


def test_note_of_a_shifted_spur_pair_compiles(table, tmp_path):
    """--shift 0.3,-0.3 (beyond the book): the pair's geometry as a table, its formulas typeset."""
    r = run_project(table[17], shift=(0.3, -0.3))
    write_note(tmp_path, r, "ru", TitleFields(), {})
    assert "Геометрия простой передачи со смещением" in _text(tmp_path / "note.pdf")


@pytest.mark.parametrize("number,crank", [(2, 60.0), (8, 40.0)])
def test_docx_of_other_reducers(table, tmp_path, number, crank):
    r = run_project(table[number], crank_rpm=crank)
    write_note(tmp_path, r, "ru", TitleFields(), {}, docx=True, pdf=False)
    _check_docx(tmp_path / "note.docx", r)


@pytest.mark.slow
def test_every_variants_note_pdf_and_docx(table, tmp_path):
    """`pytest -m slow`: every variant's note compiles and reads right, and its DOCX opens clean."""
    for number in sorted(table):
        r = run_project(table[number])
        folder = tmp_path / f"v{number}"
        folder.mkdir()
        write_note(folder, r, "ru", TitleFields(), {}, docx=True)
        _check_pdf(folder, r)
        _check_docx(folder / "note.docx", r)
        _audit(folder / "note.docx")


# --- the command line ------------------------------------------------------------------------------


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])


def test_project_writes_the_note_by_default(tmp_path):
    res = run("project", "--variant", 5, "--out", tmp_path, "--no-plots", "--lang", "ru", "--student", "Петров П. П.")
    assert res.exit_code == 0, res.output
    folder = tmp_path / "variant-05"
    assert {"note.pdf", "note.typ", "note-style.typ", "results.json"} <= {p.name for p in folder.iterdir()}
    assert "Петров П. П." in (folder / "note.typ").read_text()


def test_report_pdf_docx_and_md(tmp_path):
    res = run("project", "--variant", 5, "--out", tmp_path, "--no-plots", "--no-sheets", "--report", "pdf,docx,md",
              "--lang", "ru")
    assert res.exit_code == 0, res.output
    names = {p.name for p in (tmp_path / "variant-05").iterdir()}
    assert {"note.pdf", "note.docx", "report.md"} <= names and not any(n.endswith(".png") for n in names)
    res = run("project", "--variant", 5, "--out", tmp_path / "o", "--no-plots", "--report", "pdf,odt", "--lang", "ru")
    assert res.exit_code == 2 and "формат отчёта 'odt' неизвестен" in res.stderr


def test_report_md_is_markdown(tmp_path):
    res = run("project", "--variant", 5, "--out", tmp_path, "--no-plots", "--report", "md", "--lang", "ru")
    assert res.exit_code == 0, res.output
    names = {p.name for p in (tmp_path / "variant-05").iterdir()} - {MANIFEST}
    assert "report.md" in names and "note.pdf" not in names


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
    mine.write_text(default_template().replace("upper(meta.doc-kind)", 'upper("Записка кафедры")'), encoding="utf-8")
    res = run("project", "--variant", 5, "--out", tmp_path / "o", "--no-plots", "--note-template", mine)
    assert res.exit_code == 0, res.output
    assert "ЗАПИСКА КАФЕДРЫ" in _text(tmp_path / "o" / "variant-05" / "note.pdf")


def test_a_font_tmm_does_not_ship_is_refused(tmp_path):
    from tmm_cli.render.note import default_template

    mine = tmp_path / "dept.typ"
    mine.write_text(default_template().replace('font: "Liberation Serif"', 'font: "Comic Sans MS"'), encoding="utf-8")
    res = run("project", "--variant", 5, "--out", tmp_path / "o", "--no-plots", "--note-template", mine, "--lang", "ru")
    assert res.exit_code == 2 and "comic sans ms" in res.stderr and "Liberation Serif" in res.stderr
    assert not (tmp_path / "o" / "variant-05" / "note.pdf").exists()


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
    src.write_text(src.read_text(encoding="utf-8").replace('#structural("Заключение"', '#structural("Выводы студента"'),
                   encoding="utf-8")
    res = run("note", folder)
    assert res.exit_code == 0, res.output
    assert "ВЫВОДЫ СТУДЕНТА" in _text(folder / "note.pdf")
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


def test_tmm_note_to_docx_from_the_results(tmp_path):
    assert run("project", "--variant", 8, "--out", tmp_path, "--no-plots", "--crank-rpm", 60, "--lang", "ru").exit_code == 0
    folder = tmp_path / "variant-08"
    res = run("note", folder, "--to", "docx", "--lang", "ru")
    assert res.exit_code == 0, res.output
    import docx

    from docx.oxml.ns import qn

    # the paragraphs' text with their formulas' (a value said after its symbol is inside the formula)
    text = "\n".join("".join(t.text or "" for t in p._p.iter(qn("w:t"), qn("m:t")))
                     for p in docx.Document(str(folder / "note.docx")).paragraphs).replace("\u2060", "")
    assert "60 об/мин" in text.replace("\xa0", " ")  # the run's own crank speed, from results.json
    assert not [p for p in folder.iterdir() if p.name.startswith(".tmm-note-")]
