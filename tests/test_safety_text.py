"""Issue 30: a student's text is text. A name, a group, a mechanism's name, an answers key or an
edited folder reaches every document as the characters typed — never as typst code or math, a
Markdown link, HTML, a terminal escape or a DXF code — and every typst compile is a sandbox
(no packages, nothing from $HOME, a wall-clock limit). Each case of the issue, driven through the
CLI or the typesetter, asserting what the reader of the document would see."""

import os
import re
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli

pypdf = pytest.importorskip("pypdf")
EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"


def run(*args, **kw):
    return CliRunner().invoke(cli, [str(a) for a in args], **kw)


def one_line_error(res, *words, code=2):
    assert res.exit_code == code, (res.exit_code, res.output, res.stderr)
    err = res.stderr.strip()
    assert "Traceback" not in res.output + err and "internal error" not in err
    assert len(err.splitlines()) == 1 and err.startswith("tmm: error:"), err
    for w in words:
        assert w in err, (w, err)
    return err


def pdf_text(pdf: Path) -> str:
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(pdf).pages)
    return " ".join(text.replace("\xa0", " ").split())


def pdf_outline(pdf: Path) -> list[str]:
    def walk(items):
        for it in items:
            if isinstance(it, list):
                yield from walk(it)
            else:
                yield it.title
    return list(walk(pypdf.PdfReader(pdf).outline))


def md_html(body: str) -> str:
    """Markdown as a CommonMark reader (with raw HTML on, GitHub's tables) renders it."""
    from markdown_it import MarkdownIt

    return MarkdownIt("commonmark", {"html": True, "linkify": False}).enable("table").render(body)


def md_safe(body: str) -> bool:
    page = md_html(body)
    return "<img" not in page and "<script" not in page and "<a " not in page


def red_text(pdf: Path) -> bool:
    """Any text filled red (typst's `red`, 1 0.25 0.21 rg, in a page's content)."""
    reader = pypdf.PdfReader(pdf)
    return any(b" rg" in p.get_contents().get_data() and re.search(rb"1 0\.2\d+ 0\.2\d+ rg", p.get_contents().get_data())
               for p in reader.pages)


HOSTILE_STUDENT = 'X $#text(fill: red)[INJ] #read("note-style.typ").slice(0,40)$ Y'


# --- typst code through a name -----------------------------------------------------------------------


def test_a_name_with_typst_code_is_set_as_typed(tmp_path):
    res = run("project", "-v", 3, "--student", HOSTILE_STUDENT, "--group", "G_{x}^{2} a///b /*c*/",
              "--report", "pdf", "--no-plots", "--no-sheets", "--out", tmp_path, "--lang", "en")
    assert res.exit_code == 0, res.stderr
    folder = tmp_path / "variant-03"
    text = pdf_text(folder / "note.pdf")
    assert HOSTILE_STUDENT in text  # the characters typed, "$", "#", "[" and the quotes included
    assert "G_{x}^{2} a///b /*c*/" in text  # no comment swallowed the rest
    style_head = (folder / "note-style.typ").read_text(encoding="utf-8")[:40]
    assert " ".join(style_head.split()) not in text.replace(HOSTILE_STUDENT, "")  # no file was read into it
    assert not red_text(folder / "note.pdf")


def test_a_mechanism_name_with_lines_and_math_makes_no_chapter(tmp_path):
    mech = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    hostile = r'name = "M\n\n= HEADING $x^$ [/x] #import \"@local/evil:0.1.0\""'
    mech = re.sub(r'(?m)^name = .*$', lambda m: hostile, mech, count=1)
    assert "HEADING" in mech
    (tmp_path / "m.toml").write_text(mech, encoding="utf-8")
    plain = run("project", "-v", 17, "--mechanism", EXAMPLES / "four_bar.toml", "--report", "pdf,md", "--no-plots",
                "--no-sheets", "--out", tmp_path / "a", "--lang", "en")
    assert plain.exit_code == 0, plain.stderr
    res = run("project", "-v", 17, "--mechanism", tmp_path / "m.toml", "--report", "pdf,md,docx", "--no-plots",
              "--no-sheets", "--out", tmp_path / "b", "--lang", "en")
    assert res.exit_code == 0, res.stderr
    pdf = tmp_path / "b" / "variant-17" / "note.pdf"
    assert pdf_outline(pdf) == pdf_outline(tmp_path / "a" / "variant-17" / "note.pdf")
    assert 'M = HEADING $x^$ [/x] #import "@local/evil:0.1.0"' in pdf_text(pdf)  # the line break folded to a space


# --- typst's own escape: no comment from "//" or "/*" ---------------------------------------------------


def test_escape_leaves_no_comment():
    from tmm_cli.render.note.typst import escape

    for text in ("a///b", "a//b", "x/", "/*", "a/*b*/c"):
        out = escape(text)
        assert "//" not in out and "/*" not in out, out


@pytest.mark.parametrize("name", ["Petrov P./", "a///b"])
def test_assign_with_a_slash_name_writes_every_pdf(tmp_path, name):
    roster = tmp_path / "r.csv"
    roster.write_text(f"student,variant,group\n{name},3,G/*\nIvanov I.,4,G1\n", encoding="utf-8")
    res = run("assign", "--roster", roster, "--out", tmp_path / "o", "--teacher", "T//x", "--lang", "en")
    assert res.exit_code == 0, res.stderr
    pdfs = sorted((tmp_path / "o").rglob("*.pdf"))
    assert len(pdfs) >= 3, pdfs  # two students and the merged file
    merged = max(pdfs, key=lambda p: len(pypdf.PdfReader(p).pages))
    text = pdf_text(merged)
    assert name in text and "G/*" in text and "T//x" in text


# --- typst as a sandbox ---------------------------------------------------------------------------------


def _evil_package(home: Path) -> None:
    pkg = home / ".local" / "share" / "typst" / "packages" / "local" / "evil" / "0.1.0"
    pkg.mkdir(parents=True)
    (pkg / "typst.toml").write_text('[package]\nname = "evil"\nversion = "0.1.0"\nentrypoint = "lib.typ"\n')
    (pkg / "secret.txt").write_text("SECRET-FROM-HOME")
    (pkg / "lib.typ").write_text('#let x = read("secret.txt")\n')


def test_typst_loads_no_package_from_home(tmp_path, monkeypatch):
    from tmm_cli.errors import TmmError
    from tmm_cli.render.note import typeset

    home = tmp_path / "home"
    _evil_package(home)
    monkeypatch.setenv("HOME", str(home))
    monkeypatch.delenv("XDG_DATA_HOME", raising=False)
    typeset._close_child()  # a child started before the HOME above would not see it
    doc = tmp_path / "doc"
    doc.mkdir()
    (doc / "a.typ").write_text('#let p = "@local/" + "evil:0.1.0"\n#import p: x\n#x\n')  # past any text scan
    with pytest.raises(TmmError) as e:
        typeset.typeset(doc, "a.typ", "a.pdf")
    assert "evil" in str(e.value) and not (doc / "a.pdf").exists()
    (doc / "b.typ").write_text('#import "@preview/cetz:0.2.2": *\nx\n')  # no network: fails at once
    with pytest.raises(TmmError):
        typeset.typeset(doc, "b.typ", "b.pdf")
    assert not (home / ".cache").exists()


def test_tmm_note_refuses_a_package_import_in_one_line(tmp_path):
    (tmp_path / "note.typ").write_text('#import "@preview/cetz:0.2.2": *\nHello\n')
    one_line_error(run("note", tmp_path, "--lang", "en"), "note.typ:1", "@preview/cetz:0.2.2", "packages off")
    assert not (tmp_path / "note.pdf").exists()


def test_a_compile_past_the_time_limit_is_one_line(tmp_path, monkeypatch):
    from tmm_cli import limits

    monkeypatch.setattr(limits, "TYPST_SECONDS", 3.0)
    (tmp_path / "note.typ").write_text("#for a in range(100000) {for b in range(100000) {}}\n")
    err = one_line_error(run("note", tmp_path, "--lang", "en"), "note.typ", "longer than the limit of 3 s")
    assert "Traceback" not in err and not (tmp_path / "note.pdf").exists()


# --- Markdown, HTML, the terminal ------------------------------------------------------------------------

XSS_NAME = "<img src=x onerror=alert(1)>[PASSED](javascript:alert(2)) a///b"
XSS_GROUP = "<script>alert(3)</script>"


def _check_folder(tmp_path: Path) -> Path:
    answers = tmp_path / "answers"
    answers.mkdir()
    roster = tmp_path / "roster.csv"
    roster.write_text(f'student,variant,group\n"{XSS_NAME}",3,{XSS_GROUP}\nIvanov,3,G1\n', encoding="utf-8")
    from tmm_cli.inputs.names import file_name

    (answers / f"{file_name(XSS_NAME)}.toml").write_text("r0_mm = 40\n", encoding="utf-8")
    (answers / "Ivanov.toml").write_text('"x///y" = 1\n"<script>k</script>" = 2\nr0_mm = 3\n', encoding="utf-8")
    (answers / "\x1b[2J\x1b[Hx.toml").write_text("r0_mm = 1\n", encoding="utf-8")
    return roster


def test_check_feedback_pdf_with_hostile_names_and_keys(tmp_path):
    roster = _check_folder(tmp_path)
    res = run("check", "--roster", roster, "--answers-dir", tmp_path / "answers", "--out", tmp_path / "o",
              "--feedback", "pdf", "--lang", "en")
    assert res.exit_code in (0, 1), res.stderr
    out = tmp_path / "o"
    assert {"check.csv", "check.md", "group.html"} <= {p.name for p in out.iterdir()}
    pdfs = sorted((out / "feedback").glob("*.pdf"))
    assert len(pdfs) == 2
    texts = " ".join(pdf_text(p) for p in pdfs)
    assert XSS_NAME in texts and XSS_GROUP in texts and "x///y" in texts and "<script>k</script>" in texts
    import html as _html

    for md in (out / "feedback").glob("*.md"):
        page = md_html(md.read_text(encoding="utf-8"))
        assert md_safe(md.read_text(encoding="utf-8")), page
    page = md_html((out / "feedback" / "check-Ivanov.md").read_text(encoding="utf-8"))
    assert _html.escape("<script>k</script>", quote=False) in page and "x///y" in page
    html = (out / "group.html").read_text(encoding="utf-8")
    assert "\x1b" not in html and "<script>alert" not in html
    assert "\x1b" not in res.output  # the screen is not cleared: the file's name is shown with its codes
    assert "\\x1b[2J" in res.output


def test_report_md_with_a_hostile_mechanism_name(tmp_path):
    mech = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    mech = re.sub(r'(?m)^name = .*$', lambda m: f'name = "{XSS_NAME} A $x^$ B"', mech, count=1)
    (tmp_path / "m.toml").write_text(mech, encoding="utf-8")
    res = run("project", "-v", 17, "--mechanism", tmp_path / "m.toml", "--report", "md", "--no-plots", "--no-sheets",
              "--out", tmp_path, "--lang", "en")
    assert res.exit_code == 0, res.stderr
    body = (tmp_path / "variant-17" / "report.md").read_text(encoding="utf-8")
    assert md_safe(body) and "$x^$" in md_html(body)


def test_a_chain_with_markup_names_prints_them(tmp_path):
    src = (EXAMPLES / "chain-radial-1.toml").read_text(encoding="utf-8")
    src = re.sub(r'(?m)^name = "([^"]*)"', lambda m: 'name = "[/x] [bold]\\u001b]8;;http://e\\u001b\\\\"', src, count=2)
    (tmp_path / "c.toml").write_text(src, encoding="utf-8")
    res = run("chain", tmp_path / "c.toml", "--lang", "en")
    assert res.exit_code == 0, (res.output, res.stderr)
    assert "[/x]" in res.output and "\x1b" not in res.output


def test_an_error_naming_a_file_shows_its_control_characters(tmp_path):
    bad = tmp_path / "a\nb\x1b[2J.toml"
    bad.write_text("= = =\n")
    res = run("check", "-v", 3, "--answers", bad, "--lang", "en")
    err = one_line_error(res)
    assert "\x1b" not in err and "\\x1b[2J" in err and len(err.splitlines()) == 1


# --- DXF and Word ------------------------------------------------------------------------------------------


def test_title_block_text_is_literal_in_the_dxf_and_the_word_note(tmp_path):
    ezdxf = pytest.importorskip("ezdxf")
    docx = pytest.importorskip("docx")
    student, group = "%%uIvanov A $sqrt(2)+1$ ^J", "G_{x}^{2}"
    res = run("project", "-v", 3, "--student", student, "--group", group, "--report", "docx", "--no-plots",
              "--out", tmp_path, "--lang", "en")
    assert res.exit_code == 0, res.stderr
    folder = tmp_path / "variant-03"
    shown = [e.plain_text() for e in ezdxf.readfile(folder / "sheet3.dxf").modelspace().query("TEXT MTEXT")]
    assert student in shown and any(group in t for t in shown), [t for t in shown if "Ivanov" in t or "G" in t]
    d = docx.Document(folder / "note.docx")
    body = "\n".join(p.text for p in d.paragraphs).replace("\u2060", "")
    assert f"Student: {student}, group {group}." in body
    xml = d.element.xml
    assert "oMath" not in xml.split("Student:")[1].split("Topic")[0]  # no Word equation in the task's line


# --- crashes and trust ---------------------------------------------------------------------------------------


@pytest.mark.parametrize("command", ["batch", "check", "assign"])
def test_a_superscript_variant_is_one_bad_row(tmp_path, command):
    roster = tmp_path / "r.csv"
    roster.write_text("student,variant\nA,¹⁷\nB,²\nC,3\n", encoding="utf-8")
    (tmp_path / "ans").mkdir()
    args = {"batch": ("batch", "--roster", roster, "--no-plots", "--report", "none", "--jobs", 1),
            "check": ("check", "--roster", roster, "--answers-dir", tmp_path / "ans"),
            "assign": ("assign", "--roster", roster)}[command]
    res = run(*args, "--out", tmp_path / "o", "--lang", "en")
    assert res.exit_code in (0, 1), (res.output, res.stderr)
    assert "internal error" not in res.output + res.stderr
    assert "variant ¹⁷ is not in the table" in res.output + res.stderr


def test_a_mechanism_name_that_is_broken_math_draws_and_typesets(tmp_path):
    mech = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    mech = re.sub(r'(?m)^name = .*$', lambda m: r'name = "A $\\undefinedmacro{x}$ $x^$ B"', mech, count=1)
    (tmp_path / "m.toml").write_text(mech, encoding="utf-8")
    res = run("linkage", tmp_path / "m.toml", "--out", tmp_path / "l", "--lang", "en")
    assert res.exit_code == 0, res.stderr
    res = run("project", "-v", 17, "--mechanism", tmp_path / "m.toml", "--report", "md,docx", "--no-sheets",
              "--out", tmp_path / "p", "--lang", "en")
    assert res.exit_code == 0, res.stderr
    docx = pytest.importorskip("docx")
    body = "\n".join(p.text for p in docx.Document(tmp_path / "p" / "variant-17" / "note.docx").paragraphs).replace("\u2060", "")
    assert r"A $\undefinedmacro{x}$ $x^$ B" in body


def test_docx_with_a_broken_math_name(tmp_path):
    res = run("project", "-v", 3, "--student", "A $x^$ B", "--report", "docx", "--no-plots", "--no-sheets",
              "--out", tmp_path, "--lang", "en")
    assert res.exit_code == 0, res.stderr


@pytest.mark.parametrize("content", ["a = " + "[" * 5000 + "]" * 5000 + "\n",
                                     'name = "x"\n[[link]]\nname = "A"\nnominal = ' + "9" * 50000 + "\n"])
def test_tmm_chain_on_hostile_toml_is_one_line(tmp_path, content):
    f = tmp_path / "c.toml"
    f.write_text(content)
    one_line_error(run("chain", f, "--lang", "en"), "c.toml")


@pytest.mark.skipif(os.name != "posix", reason="symbolic links")
def test_a_symlinked_figure_never_reaches_the_note(tmp_path):
    secret = tmp_path / "secret.svg"
    secret.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">'
                      '<text x="10" y="50">TOPSECRET</text></svg>')
    res = run("project", "-v", 3, "--out", tmp_path / "o", "--format", "svg", "--no-sheets", "--lang", "en")
    assert res.exit_code == 0, res.stderr
    folder = tmp_path / "o" / "variant-03"
    for f in folder.glob("note_*.svg"):
        f.unlink()
        f.symlink_to(secret)
    run("note", folder, "--lang", "en")
    run("project", "-v", 3, "--out", tmp_path / "o", "--format", "svg", "--no-sheets", "--force", "--lang", "en")
    assert "TOPSECRET" not in pdf_text(folder / "note.pdf")


@pytest.mark.parametrize("patch, words", [
    (("options", "step_deg", 0.0001), "step_deg"),
    (("options", "tolerance_pct", 1e9), "tolerance_pct"),
    (("options", "cam_choice", {"evil": 1}), "cam_choice"),
    (("options", "planets", 10**5000 // 10**4990), "planets"),
    (("input", "n_cam_rpm", 1e12), "n_cam_rpm"),
])
def test_note_to_docx_holds_results_json_to_the_options_limits(tmp_path, patch, words):
    import json

    res = run("project", "-v", 3, "--out", tmp_path, "--no-plots", "--report", "md", "--no-sheets", "--lang", "en")
    assert res.exit_code == 0, res.stderr
    src = tmp_path / "variant-03" / "results.json"
    data = json.loads(src.read_text(encoding="utf-8"))
    part, key, value = patch
    data[part][key] = value
    src.write_text(json.dumps(data), encoding="utf-8")
    one_line_error(run("note", src.parent, "--to", "docx", "--lang", "en"), "results.json", words)
    assert not (src.parent / "note.docx").exists()


def test_check_does_not_pass_the_right_set_times_ten_thousand(tmp_path):
    import json

    res = run("project", "-v", 3, "--out", tmp_path, "--no-plots", "--report", "md", "--no-sheets", "--json")
    st = json.loads(res.stdout)["gears"]["planetary"]["stages"][0]
    answers = tmp_path / "a.toml"
    answers.write_text(f"z_sun = {st['z_sun'] * 10000}\nz_planet = {st['z_planet'] * 10000}\n"
                       f"z_ring = {st['z_ring'] * 10000}\nplanets = {st['planets']}\n")
    res = run("check", "-v", 3, "--answers", answers, "--json", "--sheet", 4)
    rows = {r["key"]: r for r in json.loads(res.stdout)["rows"]}
    assert not rows["z_sun"]["status"].startswith("pass"), rows["z_sun"]
    assert rows["z_sun"]["cause"]["code"] == "set_too_large"


def test_a_failed_rerun_keeps_the_good_note(tmp_path):
    out = tmp_path / "o"
    res = run("project", "-v", 3, "--out", out, "--no-plots", "--no-sheets", "--lang", "en")
    assert res.exit_code == 0, res.stderr
    folder = out / "variant-03"
    before = {n: (folder / n).read_bytes() for n in ("note.pdf", "note.typ", "note-style.typ")}
    bad = tmp_path / "bad.typ"
    bad.write_text('#let note(meta, body) = { panic("no") }\n')
    one_line_error(run("project", "-v", 3, "--out", out, "--no-plots", "--no-sheets", "--note-template", bad,
                       "--lang", "en"), "could not be typeset")
    assert {n: (folder / n).read_bytes() for n in before} == before
    assert run("note", folder).exit_code == 0  # and it still compiles


@pytest.mark.parametrize("ratio", ["1/" + "9" * 5000, "9" * 5000, "¹/2", "13/٤"])
def test_a_ratio_of_5000_digits_or_superscripts_is_one_line(ratio):
    err = one_line_error(run("gears", "-v", 3, "--ratio", ratio, "--lang", "en"), "cannot read the ratio")
    assert len(err) < 300
