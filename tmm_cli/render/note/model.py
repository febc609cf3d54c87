"""The explanatory note as a document: what it says, once; the writers say how it looks.

The chapter builders (:mod:`.cam_part`, :mod:`.gears_part`, :mod:`.front`) fill a
:class:`Document` with blocks; three writers walk it — :mod:`.typst` (note.typ → note.pdf),
:mod:`.docx` (note.docx) and :mod:`.markdown` (report.md) — the way ezdxf's drawing add-on has one
frontend walking a drawing and one backend per medium.

Text is written in a small inline markup, the same for every writer:

- plain text (Unicode; the builders put a no-break space between a number and its unit);
- ``$…$`` inline math in the typst subset of :mod:`.mathsyntax`;
- ``{fig:name}``, ``{tab:name}``, ``{eq:name}``, ``{app:name}`` — the number of a figure, table,
  formula or appendix (letter) defined anywhere in the document;
- ``{cite:key}`` and ``{cite:key:формула (1.20)}`` — a source of the list of references:
  "[1]", "[1, формула (1.20)]"; sources are numbered in the order of their first citation;
- :func:`literal` — a person's text (a student's name, a group, a mechanism's name): the one way
  user text enters a document. It is kept encoded (hex between two private-use marks), so no
  markup rule of any writer — ``$…$``, a reference, typst, Markdown, Word — can see into it;
  each writer decodes it (:func:`text_runs`) and sets it as the characters typed. A writer that
  forgot would print hex, never markup.

Numbers of figures, tables and formulas are the note's own sequence (1), (2), …; in an appendix
"А.1". :meth:`Document.number` assigns them (the writers call it); the typst writer leaves the
counting to typst, so that a student's edits renumber, and uses the same labels.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ...i18n import N_, tr

REF = re.compile(r"\{(fig|tab|eq|app):([a-z0-9_]+)\}")
CITE = re.compile(r"\{cite:([a-z0-9_]+)(?::([^{}]*))?\}")
MATH = re.compile(r"(\$[^$]*\$)")
# a person's text: hex of its UTF-8 between U+E000 and U+E001 (see literal())
_LIT_OPEN, _LIT_CLOSE = "\ue000", "\ue001"
LITERAL = re.compile("\ue000((?:[0-9a-f]{2})*)\ue001")


def literal(text) -> str:
    """A person's text as a piece of inline markup that every writer sets as the characters given.

    >>> literal("A $x$") == literal("A $x$") and "$" not in literal("A $x$")
    True
    >>> text_runs("name: " + literal("#x [y]") + ".")
    [(False, 'name: '), (True, '#x [y]'), (False, '.')]
    """
    return _LIT_OPEN + str(text).encode("utf-8", "surrogatepass").hex() + _LIT_CLOSE


def text_runs(piece: str) -> list[tuple[bool, str]]:
    """[(is_literal, text)] of a piece of markup text: a person's text decoded, the rest as it is."""
    out = []
    pos = 0
    for m in LITERAL.finditer(piece):
        if m.start() > pos:
            out.append((False, piece[pos:m.start()]))
        out.append((True, bytes.fromhex(m.group(1)).decode("utf-8", "replace")))
        pos = m.end()
    if pos < len(piece):
        out.append((False, piece[pos:]))
    return out


# ASCII punctuation: the characters a markup may give a meaning (typst, CommonMark); a person's text
# has every one of them escaped with a backslash, which both typst and CommonMark read as the character
PUNCT = re.compile(r"([!-/:-@\[-`{-~])")


def escape_all(text: str) -> str:
    r"""A person's text for typst markup or Markdown: every ASCII punctuation character escaped,
    so nothing in it is markup (no code, math, comment, label, list, heading, link, HTML).

    >>> print(escape_all("a///b $x$ #f() <i>"))
    a\/\/\/b \$x\$ \#f\(\) \<i\>
    """
    return PUNCT.sub(r"\\\1", text)


# Markdown (CommonMark, GitHub's): the characters that open emphasis, code, links, images, HTML,
# entities, math, strikethrough or a table cell anywhere in a line
_MD_INLINE = re.compile(r"([\\`*_\[\]<>&~|!#$@])")


def md_text(text: str) -> str:
    r"""A person's text for Markdown: set as typed, never as markup — no emphasis, link, image,
    HTML, entity, math, table cell; no list, heading or quote where it starts; no autolink.

    >>> print(md_text("<img src=x>[PASSED](javascript:alert(2)) a_b*"))
    \<img src=x\>\[PASSED\](javascript:alert(2)) a\_b\*
    >>> print(md_text("1. - http://x www.y"))
    1\. - http\://x www\.y
    """
    out = _MD_INLINE.sub(r"\\\1", text)
    out = re.sub(r"(?i)(https?|ftp|mailto)(:)", r"\1\\\2", out)  # GitHub's autolinks
    out = re.sub(r"(?i)\b(www)\.", r"\1\\.", out)
    m = re.match(r"(\s*\d+)([.)])", out)
    if m:  # "1." would start a numbered list
        return m.group(1) + "\\" + out[m.end(1):]
    m = re.match(r"\s*[-+=>]", out)
    if m:  # a list, a setext heading, a quote
        return out[:m.end() - 1] + "\\" + out[m.end() - 1:]
    return out


def plain(text: str) -> str:
    """The markup text with a person's text decoded (for a writer that shows text as it is)."""
    return LITERAL.sub(lambda m: bytes.fromhex(m.group(1)).decode("utf-8", "replace"), text)

# ГОСТ 7.32 letters of appendices (Ё, З, Й, О, Ч, Ь, Ы, Ъ are not used)
# ГОСТ 7.32: the appendices are lettered in the alphabet of the note, without the letters that read as
# digits or as other letters (Ё З Й О Ч Ъ Ы Ь; I O)
APPENDIX_LETTERS = N_("ABCDEFGHJKLMNPQRSTUVWXYZ")
# the abstract's first line (ГОСТ 7.32: the pages, figures, tables, sources and appendices), typst and docx
ABSTRACT_COUNTS = N_("Explanatory note: {pages} p., {figures} fig., {tables} tables, {sources} sources")
APPENDIX_COUNT = N_(", {appendices} app.")


# --- blocks ---------------------------------------------------------------------------------------


@dataclass
class Heading:
    """A heading. ``kind``: "chapter" (numbered 1, 1.1 …), "structural" (РЕФЕРАТ, ВВЕДЕНИЕ,
    ЗАКЛЮЧЕНИЕ …: centred capitals, no number, a new page), "appendix" (ПРИЛОЖЕНИЕ А, its status
    and title)."""

    level: int
    text: str
    kind: str = "chapter"
    label: str | None = None
    status: str = ""  # appendix: «обязательное» / «справочное»
    outlined: bool = True  # listed in the contents (РЕФЕРАТ and СОДЕРЖАНИЕ are not)
    number: str = ""  # assigned by Document.number()


@dataclass
class Paragraph:
    text: str
    indent: bool = True


@dataclass
class WhereItem:
    symbol: str  # typst math
    meaning: str  # inline markup


@dataclass
class Formula:
    """A display formula: typst math, one line or several joined by ``\\``; ``where`` explains the
    symbols it brings in (ГОСТ 7.32: «где» …)."""

    math: str
    label: str | None = None
    numbered: bool = True
    where: list[WhereItem] = field(default_factory=list)
    number: str = ""


@dataclass
class ListBlock:
    items: list[str]
    ordered: bool = False


@dataclass
class Table:
    """«Таблица N – Название» above, header repeated (with «Продолжение таблицы N») on every page."""

    name: str
    caption: str
    header: list[str]
    rows: list[list[str]]
    align: list[str] | None = None  # "left" | "center" | "right" per column
    widths: list[float] | None = None  # relative widths (None: auto)
    number: str = ""


@dataclass
class Figure:
    """«Рисунок N – Название» below the picture, placed after the paragraph that first refers to it."""

    name: str
    file: str  # the vector file the typst note embeds (SVG)
    caption: str
    width_cm: float
    height_cm: float
    raster: str | None = None  # the ≥ 300 dpi PNG the DOCX embeds beside the SVG
    number: str = ""


@dataclass
class TitlePage:
    """ГОСТ 7.32 title page: the fields of the title block, words decided by the builder."""

    fields: dict


@dataclass
class TaskSheet:
    """The task (задание): who, the topic, the variant's data, what the project must hold."""

    title: str
    lines: list[str]  # "label: value" lines
    contents: list[str]  # the first line introduces the list that follows


@dataclass
class Abstract:
    """Реферат: the counts (pages from the writer; figures, tables, sources, appendices from the
    document), the key words and a short text."""

    keywords: list[str]
    text: list[str]


@dataclass
class Contents:
    """Содержание (the writers build it: typst's outline, Word's TOC field)."""


@dataclass
class PageBreak:
    pass


@dataclass
class ReferenceList:
    """The list of sources, in the order of their first citation (the writers print
    :meth:`Document.references`)."""


@dataclass
class Source:
    """One entry of the list of references, in ГОСТ 7.0.100 form."""

    key: str
    text: str


# --- the document ---------------------------------------------------------------------------------


@dataclass
class Document:
    lang: str
    blocks: list = field(default_factory=list)
    sources: dict[str, str] = field(default_factory=dict)  # key -> ГОСТ 7.0.100 entry (all known)
    cited: list[str] = field(default_factory=list)  # keys in order of first citation
    numbers: dict[str, str] = field(default_factory=dict)  # "fig:name" -> "1"
    claims: list = field(default_factory=list)  # the decisions the text states (checked by the tests)

    # -- building ---------------------------------------------------------------------------------
    def add(self, block):
        self.blocks.append(block)
        if isinstance(block, (Paragraph, ListBlock, Table, Figure, Formula, TaskSheet, Abstract)):
            for text in _texts(block):
                for m in CITE.finditer(text):
                    if m.group(1) not in self.cited:
                        self.cited.append(m.group(1))
        return block

    def claim(self, **kw) -> None:
        """A decision the text states: kind, what was chosen, among what, by which rule."""
        self.claims.append(kw)

    # -- numbering --------------------------------------------------------------------------------
    def number(self) -> None:
        """Number figures, tables, formulas and appendices in the order of the document."""
        counts = {"fig": 0, "tab": 0, "eq": 0}
        chapter = [0, 0, 0]
        appendix = None
        letters = tr(self.lang, APPENDIX_LETTERS)
        n_app = 0
        self.numbers = {}
        for b in self._walk():
            if isinstance(b, Heading):
                if b.kind == "appendix":
                    appendix = letters[n_app]
                    n_app += 1
                    b.number = appendix
                    counts = {"fig": 0, "tab": 0, "eq": 0}
                    if b.label:
                        self.numbers["app:" + b.label] = appendix
                elif b.kind == "chapter":
                    chapter[b.level - 1] += 1
                    chapter[b.level:] = [0] * (len(chapter) - b.level)
                    b.number = ".".join(str(x) for x in chapter[:b.level])
                continue
            kind = {Figure: "fig", Table: "tab", Formula: "eq"}.get(type(b))
            if kind is None or (kind == "eq" and not b.numbered):
                continue
            counts[kind] += 1
            b.number = f"{appendix}.{counts[kind]}" if appendix else str(counts[kind])
            name = b.name if kind != "eq" else b.label
            if name:
                self.numbers[f"{kind}:{name}"] = b.number

    def _walk(self):
        yield from self.blocks

    def source_number(self, key: str) -> int:
        return self.cited.index(key) + 1

    def references(self) -> list[Source]:
        return [Source(k, self.sources[k]) for k in self.cited]

    def counts(self) -> dict[str, int]:
        """Figures, tables, sources, appendices (the реферат's line; pages come from the writer)."""
        return {"figures": sum(isinstance(b, Figure) for b in self.blocks),
                "tables": sum(isinstance(b, Table) for b in self._walk()),
                "sources": len(self.cited),
                "appendices": sum(isinstance(b, Heading) and b.kind == "appendix" for b in self.blocks)}

    # -- inline markup ----------------------------------------------------------------------------
    def resolve(self, text: str, ref=None, cite=None) -> str:
        """The markup with references and citations replaced (math and plain text left)."""
        def _ref(m):
            key = f"{m.group(1)}:{m.group(2)}"
            if ref is not None:
                return ref(m.group(1), m.group(2), self.numbers.get(key, "?"))
            return self.numbers.get(key, "?")

        def _cite(m):
            n = self.source_number(m.group(1)) if m.group(1) in self.cited else 0
            if cite is not None:
                return cite(n, m.group(2))
            return f"[{n}, {m.group(2)}]" if m.group(2) else f"[{n}]"

        return CITE.sub(_cite, REF.sub(_ref, text))


def _texts(block) -> list[str]:
    if isinstance(block, Paragraph):
        return [block.text]
    if isinstance(block, ListBlock):
        return list(block.items)
    if isinstance(block, Table):
        return [block.caption, *block.header, *(c for row in block.rows for c in row)]
    if isinstance(block, Figure):
        return [block.caption]
    if isinstance(block, Formula):
        return [w.meaning for w in block.where]
    if isinstance(block, TaskSheet):
        return [*block.lines, *block.contents]
    if isinstance(block, Abstract):
        return list(block.text)
    return []


# A number's power of ten as tmm_cli.i18n.numbers writes it, "1,458·10⁻⁴": the writers set the
# exponent as a true superscript (not every font has the superscript characters: the bundled serif
# lacks "⁻" and "⁰", STIX Math the digits, and typst would take them silently from a font of its own)
SCI_EXPONENT = re.compile(r"(?<=·10)([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)")
SUPER_DIGITS = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "−0123456789")


# a unit right after an inline formula («$b = 240$ мм»): the space before it does not break
UNIT_AFTER_MATH = re.compile(r"^ (?=(?:мм|м|Н|кН|об/мин|рад|кг|кВт|Вт|Дж|мин|°|%|mm|m|N|kN|rpm|rad|kg|kW|W|J|min)"
                             r"(?![^\W\d_]))")


def split_math(text: str) -> list[tuple[bool, str]]:
    """[(is_math, piece)] of an inline markup text.

    A relation after a symbol stays on its line with its value (``$m$ = 20 мм`` never breaks at the
    "="): the spaces around it are no-break spaces.

    >>> split_math("угол $ν_max$ = 25°")
    [(False, 'угол '), (True, 'ν_max'), (False, '\xa0=\xa025°')]
    >>> split_math("$b = 240$ мм, $k$ мало")
    [(True, 'b = 240'), (False, '\xa0мм, '), (True, 'k'), (False, ' мало')]
    """
    out = []
    for part in MATH.split(text):
        if not part:
            continue
        if len(part) >= 2 and part.startswith("$") and part.endswith("$"):
            out.append((True, part[1:-1]))
        else:
            if out and out[-1][0]:
                part = re.sub(r"^ ([=≤≥<>≈≠]) ", "\u00a0\\1\u00a0", part)
                part = UNIT_AFTER_MATH.sub("\u00a0", part)  # «$b = 240$ мм»: the unit stays with its formula
            out.append((False, part))
    return out


def all_math(doc: Document) -> list[tuple[str, str]]:
    """Every formula of the document: ("display" | "inline", typst math) — for the tests."""
    out = []
    for b in doc._walk():
        if isinstance(b, Formula):
            out.append(("display", b.math))
            for w in b.where:
                out.append(("inline", w.symbol))
                out += [("inline", m) for is_m, m in split_math(w.meaning) if is_m]
        for text in _texts(b):
            out += [("inline", m) for is_m, m in split_math(text) if is_m]
    return out
