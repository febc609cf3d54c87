"""The Markdown writer: the note as report.md (headings, tables, formulas as text with
<sub>/<sup>, figures with their captions), readable on GitHub or in any editor."""

from __future__ import annotations

import re

from ...i18n import tr
from .mathsyntax import parse, to_text
from .model import (
    Abstract,
    Contents,
    Document,
    Figure,
    Formula,
    Heading,
    ListBlock,
    PageBreak,
    Paragraph,
    ReferenceList,
    Table,
    TaskSheet,
    TitlePage,
    md_text,
    split_math,
    text_runs,
)


def _inline(doc: Document, text: str, cell: bool = False) -> str:
    """Markdown of inline markup: math as text, a person's text as typed (model.md_text: no
    Markdown, no HTML), the program's text with its emphasis characters escaped; in a
    table `cell`, every "|" too."""
    special = r"([*_`\\|])" if cell else r"([*_`\\])"
    out = []
    for is_math, piece in split_math(doc.resolve(text)):
        if is_math:
            math = to_text(parse(piece))
            out.append(math.replace("|", "\\|") if cell else math)
            continue
        for given, run in text_runs(piece):
            out.append(md_text(run) if given else re.sub(special, r"\\\1", run))
    return "".join(out).replace("\n", " ") if cell else "".join(out)


def _table(doc: Document, b: Table, word: str) -> list[str]:
    cell = lambda c: _inline(doc, c, cell=True)  # noqa: E731
    out = [f"*{word} {b.number} – {_inline(doc, b.caption)}*", ""]
    out.append("| " + " | ".join(cell(h) for h in b.header) + " |")
    out.append("|" + "|".join(["---"] * len(b.header)) + "|")
    out += ["| " + " | ".join(cell(c) for c in row) + " |" for row in b.rows]
    return out + [""]


def markdown(doc: Document, title: str, figure_file=lambda f: f.file) -> str:
    """The document as Markdown; `figure_file(figure)` names the image a reader opens (the PNG)."""
    doc.number()
    lang = doc.lang
    fig_word, tab_word = tr(lang, "Figure"), tr(lang, "Table")
    out = [f"# {title}", ""]
    for b in doc.blocks:
        if isinstance(b, Heading):
            if b.kind == "chapter":
                out += ["#" * (b.level + 1) + f" {b.number} {_inline(doc, b.text)}", ""]
            elif b.kind == "appendix":
                app = tr(lang, "Appendix")
                out += [f"## {app} {b.number} ({b.status}). {_inline(doc, b.text)}", ""]
            else:
                out += [f"## {_inline(doc, b.text)}", ""]
        elif isinstance(b, Paragraph):
            out += [_inline(doc, b.text), ""]
        elif isinstance(b, Formula):
            tail = f" ({b.number})" if b.numbered else ""
            out += [f"> {to_text(parse(b.math))}{tail}", ""]
            if b.where:
                word = tr(lang, "where")
                out += [word + " " + "; ".join(f"{to_text(parse(w.symbol))} – {_inline(doc, w.meaning)}"
                                               for w in b.where) + ".", ""]
        elif isinstance(b, ListBlock):
            out += [(f"{i}. " if b.ordered else "- ") + _inline(doc, t) for i, t in enumerate(b.items, 1)] + [""]
        elif isinstance(b, Table):
            out += _table(doc, b, tab_word)
        elif isinstance(b, Figure):
            cap = _inline(doc, b.caption)
            out += [f"![{cap}]({figure_file(b)})", "", f"*{fig_word} {b.number} – {cap}*", ""]
        elif isinstance(b, TaskSheet):
            out += [f"## {b.title}", ""] + [_inline(doc, x) + "  " for x in b.lines] + [""]
            out += [_inline(doc, b.contents[0]), ""] + [f"{i}. {_inline(doc, x)}" for i, x in enumerate(b.contents[1:], 1)] + [""]
        elif isinstance(b, Abstract):
            c = doc.counts()
            head = tr(lang, "Explanatory note: {figures} fig., {tables} tables, {sources} sources.").format(
                figures=c["figures"], tables=c["tables"], sources=c["sources"])
            out += ["## " + tr(lang, "Abstract"), "", head, "", ", ".join(b.keywords).upper(), ""]
            out += [_inline(doc, t) + "\n" for t in b.text]
        elif isinstance(b, ReferenceList):
            out += [f"{i}. {src.text}" for i, src in enumerate(doc.references(), 1)] + [""]
        elif isinstance(b, (TitlePage, Contents, PageBreak)):
            continue
    return "\n".join(out).rstrip() + "\n"
