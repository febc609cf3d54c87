"""note.docx's title page and task as a norm-controller reads them (review finding C19):

- the title page has «студент группы» with the group or a blank for it under «Автор работы», as the PDF
  (typst) title page has it;
- in the ЗАДАНИЕ a symbol and its value never part: «n_к = 1100 об/мин» stays on one line. LibreOffice
  breaks a line after an inline formula whatever space follows it, so the sign, the number and its unit
  join the formula (read back from the DOCX's XML; and, where LibreOffice is installed, from its PDF).
"""

from __future__ import annotations

import re
import shutil
import subprocess
import zipfile

import pytest

from cli_helpers import run

SOFFICE = shutil.which("soffice") or shutil.which("libreoffice")


@pytest.fixture(scope="module")
def note(tmp_path_factory):
    base = tmp_path_factory.mktemp("docx_task")
    res = run("project", "--variant", "52", "--report", "docx", "--no-sheets", "--no-plots", "--lang", "ru",
              "--out", base)
    assert res.exit_code == 0, res.output
    return base, next(base.glob("variant-*")) / "note.docx"


def _paragraphs(path):
    xml = zipfile.ZipFile(path).read("word/document.xml").decode("utf-8")
    return [p for p in re.findall(r"<w:p[ >].*?</w:p>", xml, re.S)]


def _text(p: str) -> str:
    return "".join(re.findall(r"<(?:w|m):t(?: [^>]*)?>([^<]*)</(?:w|m):t>", p))


def test_the_title_page_has_the_students_group(note):
    _, path = note
    texts = [_text(p) for p in _paragraphs(path)]
    author = next(i for i, t in enumerate(texts) if t.startswith("Автор работы"))
    assert texts[author + 1].startswith("студент группы") and "____" in texts[author + 1], texts[author:author + 3]


def test_the_tasks_values_are_inside_their_formulas(note):
    _, path = note
    task = next(p for p in _paragraphs(path) if "частота вращения кулачка" in _text(p))
    maths = [_text(m) for m in re.findall(r"<m:oMath>.*?</m:oMath>", task, re.S)]
    assert any(re.fullmatch(r"nк\s*=\s*1100\u00a0об/мин", m) for m in maths), maths
    outside = re.sub(r"<m:oMath>.*?</m:oMath>", "", task, flags=re.S)
    assert not re.search(r"<w:t[^>]*>[\s\u00a0]*=", outside)  # no text run starts with the sign


@pytest.mark.skipif(SOFFICE is None, reason="LibreOffice (soffice) is not installed")
def test_libreoffice_keeps_the_symbol_with_its_value(note):
    pypdf = pytest.importorskip("pypdf")
    base, path = note
    subprocess.run([SOFFICE, f"-env:UserInstallation=file://{base / 'profile'}", "--headless", "--convert-to", "pdf",
                    "--outdir", str(base / "lo"), str(path)], check=True, capture_output=True, timeout=300)
    pages = [p.extract_text() or "" for p in pypdf.PdfReader(str(base / "lo" / "note.pdf")).pages]
    assert "студент группы" in pages[0]
    task = pages[1]
    assert re.search(r"nк[ \u00a0]*=[ \u00a0]*1100[ \u00a0]*об/мин", task), task[:800]
    assert not re.search(r"\n[ \u00a0]*=", task), task[:800]  # no line of the task starts with «=»
