"""note.docx as LibreOffice shows it (issue 31): the real program converts the DOCX of a few notes to
PDF, and the PDF's text is read back.

What a student would hand in: the title page on one page, the contents filled before any update,
the abstract's page count, no «¿» (LibreOffice's mark of a formula it cannot read), every
formula's result visible (a formula wider than its cell is cut at the margin), the headings in the
serif face. Word cannot run here; both read the same OMML and fields.

Skipped, with the reason, where LibreOffice (``soffice``) is not installed
(``apt-get install libreoffice-writer-nogui``). The four notes are made without figures and
converted in one LibreOffice run (about 15 s in all).
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

from cli_helpers import run

pypdf = pytest.importorskip("pypdf")
SOFFICE = shutil.which("soffice") or shutil.which("libreoffice")
pytestmark = pytest.mark.skipif(SOFFICE is None, reason="LibreOffice (soffice) is not installed: "
                                "apt-get install libreoffice-writer-nogui")

ROOT = Path(__file__).resolve().parents[1]
CASES = {"23": ["--variant", "23"], "29": ["--variant", "29"], "61": ["--variant", "61"],
         "shaper": ["--variant", "17", "--mechanism", str(ROOT / "docs/examples/shaper.toml")]}


@pytest.fixture(scope="module")
def converted(tmp_path_factory):
    """{case: (folder of the project, LibreOffice's PDF of its note.docx)}."""
    base = tmp_path_factory.mktemp("office")
    docs, out = [], {}
    for name, args in CASES.items():
        res = run("project", *args, "--report", "pdf,docx", "--no-sheets", "--no-plots", "--lang", "ru",
                  "--out", base / name)
        assert res.exit_code == 0, res.output
        folder = next((base / name).glob("variant-*"))
        doc = base / f"note-{name}.docx"
        shutil.copy(folder / "note.docx", doc)
        docs.append(str(doc))
        out[name] = (folder, base / "lo" / f"note-{name}.pdf")
    subprocess.run([SOFFICE, f"-env:UserInstallation=file://{base / 'profile'}", "--headless", "--convert-to", "pdf",
                    "--outdir", str(base / "lo"), *docs], check=True, capture_output=True, timeout=300)
    return out


def pages(pdf: Path) -> list[str]:
    return [p.extract_text() or "" for p in pypdf.PdfReader(str(pdf)).pages]


def squeeze(text: str) -> str:
    """Text without any space (LibreOffice's math sets its own spaces) and with one minus."""
    return re.sub(r"\s+", "", text).replace("-", "−")


def results(typ: str) -> list[str]:
    """The printed result of every display formula of note.typ: the number after its last «=»."""
    out = []
    for line in typ.splitlines():
        if not line.startswith("$ ") or "#" in line:
            continue
        for piece in line.strip("$ ").split(" \\ "):
            tail = piece.rsplit(" = ", 1)
            if len(tail) == 2:
                m = re.match(r'"?([−\-]?[\d  ]+(?:,\d+)?)', tail[1].strip())
                if m and re.search(r"\d", m[1]):
                    out.append(m[1])
    return out


@pytest.mark.parametrize("name", list(CASES))
def test_libreoffice_shows_the_note_whole(converted, name):
    folder, pdf = converted[name]
    assert pdf.is_file(), f"LibreOffice wrote no PDF for {name}"
    text = pages(pdf)
    year = re.search(r"\b20\d\d\b", text[0])
    # the title page on one page: the year on page 1, the task on page 2
    assert year, text[0][-300:]
    assert "ЗАДАНИЕ" in text[1] and not text[1].strip().startswith(year[0])
    whole = "\n".join(text)
    assert "¿" not in whole  # LibreOffice's mark of a formula it could not read
    # the contents before any update: entries with their pages, not the prompt to update
    toc = next(t for t in text if "СОДЕРЖАНИЕ" in t)
    assert "Обновите поле" not in toc
    assert re.search(r"ВВЕДЕНИЕ\s*\.{5,}\s*\d+", toc), toc[:400]
    assert len(re.findall(r"\.{5,}\s*\d+", toc)) >= 8
    # the abstract's page count is LibreOffice's own count (a field), the title page counted once
    m = re.search(r"Пояснительная записка (\d+) с\.", whole)
    assert m and int(m[1]) == len(text), (m and m[1], len(text))
    # not far from the typst layout's count (the same fonts, page and spacing)
    typst_pages = len(pypdf.PdfReader(str(folder / "note.pdf")).pages)
    assert abs(len(text) - typst_pages) <= max(3, typst_pages // 8), (len(text), typst_pages)
    # every formula's result is on the page (a formula cut at the margin loses it)
    flat = squeeze(whole)
    wanted = results((folder / "note.typ").read_text(encoding="utf-8"))
    assert len(wanted) > 20
    missing = [r for r in wanted if squeeze(r) not in flat]
    assert not missing, missing
    # no unit broken after its slash («рад/ с», issue 32): the DOCX's word joiners hold in LibreOffice
    broken = [ln for ln in whole.splitlines() if re.search(r"\S/\s*$", ln)]
    assert not broken, broken


def test_the_headings_are_in_the_serif_face(converted):
    """No theme font: every font LibreOffice embedded is a serif (Liberation Serif for Times New
    Roman) or its math fonts — no sans-serif heading."""
    _, pdf = converted["23"]
    fonts = set()
    for page in pypdf.PdfReader(str(pdf)).pages:
        res = page.get("/Resources") or {}
        for f in (res.get("/Font") or {}).values():
            fonts.add(str(f.get_object().get("/BaseFont")))
    assert any("LiberationSerif" in f or "Times" in f for f in fonts), fonts
    assert not [f for f in fonts if "Sans" in f and "OpenSymbol" not in f], fonts
