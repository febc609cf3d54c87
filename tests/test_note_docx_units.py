"""note.docx keeps a unit on one line (issue 32: «рад/ с» split in a narrow table column): a word
joiner U+2060 after every slash of a unit in the program's text — table headers, cells, paragraphs
— read back from the DOCX's XML. LibreOffice 7.4 honours U+2060 (checked by converting a DOCX with a
1,25 cm column: «рад/|с²» without it, «ε,|рад/с²» with it); the list of sources keeps its addresses
as they are."""

from __future__ import annotations

import zipfile
from pathlib import Path

import pytest
from lxml import etree

from cli_helpers import run

ROOT = Path(__file__).resolve().parents[1]
W = "{http://schemas.openxmlformats.org/wordprocessingml/2006/main}"
WJ = "\u2060"


@pytest.fixture(scope="module")
def body(tmp_path_factory):
    """The paragraphs of note.docx of variant 17 with the shaper (sheets 1–2's tables too), each as
    (inside a table, its runs' texts)."""
    base = tmp_path_factory.mktemp("docx")
    res = run("project", "--variant", "17", "--mechanism", str(ROOT / "docs/examples/shaper.toml"), "--report", "docx",
              "--no-sheets", "--no-plots", "--lang", "ru", "--out", base)
    assert res.exit_code == 0, res.output
    docx = next(base.glob("variant-*")) / "note.docx"
    with zipfile.ZipFile(docx) as z:
        root = etree.fromstring(z.read("word/document.xml"))
    out = []
    for p in root.iter(W + "p"):
        in_table = any(a.tag == W + "tc" for a in p.iterancestors())
        out.append((in_table, [t.text or "" for t in p.iter(W + "t")]))
    return out


def _slashes(text: str):
    """(what follows each slash standing between two characters)."""
    return [text[i + 1] for i in range(1, len(text) - 1) if text[i] == "/" and not text[i - 1].isspace()
            and text[i + 1] != " "]


def test_no_unit_breaks_after_its_slash(body):
    joined = {"table": 0, "text": 0}
    for in_table, runs in body:
        whole = "".join(runs)
        if "://" in whole:  # a source's address: as it is (checked below)
            continue
        for run_text in runs:
            after = _slashes(run_text)
            assert all(c == WJ for c in after), (in_table, run_text)
            joined["table" if in_table else "text"] += len(after)
    # the units of the tables' headers (рад/с, (м/с)/мм …) and of the text are there, joined
    assert joined["table"] >= 10 and joined["text"] >= 10, joined
    texts = ["".join(r) for _, r in body]
    assert any("рад/" + WJ + "с" in t for t in texts)
    assert any("(м/" + WJ + "с)/" + WJ + "мм" in t for t in texts)


def test_the_sources_are_written_as_they_are(body):
    """The list of sources takes no joiner (its entries are copied into other lists; an address in
    one would carry it), though a source written with a unit-like slash would get one in the text."""
    from tmm_cli.render.note.docx import no_break_after_slash

    texts = ["".join(r) for _, r in body]
    start = max(i for i, t in enumerate(texts) if t.upper().startswith("СПИСОК"))
    listed = [t for t in texts[start + 1:] if t[:1].isdigit() and ". " in t[:4]]
    assert listed and not [t for t in listed if WJ in t]
    assert no_break_after_slash("Ч. 2/В. И.") != "Ч. 2/В. И."  # the list is skipped, not the pattern
