"""The typst writer: a :class:`~.model.Document` as note.typ (compiled to note.pdf with the style
of note-style.typ).

Plain text is escaped, inline math kept (its ``/`` kept on the line), references become typst
references to labels, so that a student who inserts a figure, a table or a formula gets the
numbers right after recompiling.
"""

from __future__ import annotations

import re

from ...i18n import tr
from .model import (
    ABSTRACT_COUNTS,
    APPENDIX_COUNT,
    SCI_EXPONENT,
    SUPER_DIGITS,
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
    escape_all,
    plain,
    split_math,
    text_runs,
)

_SPECIAL = re.compile(r"([\\#*_`$@<>\[\]~])")
# a "/" that could make a comment with a neighbour: beside another "/", or at either end of
# the piece (the text around it is not known here: «x/» before the "*" of "*{name}*" would open "/*")
_SLASH = re.compile(r"^/|/$|/(?=/)|(?<=/)/")  # after the others are escaped: a "*" is "\\*" then

# "1,458·10⁻⁴" (model.SCI_EXPONENT): a superscript scaled from the font's own digits and minus
_SCI_MATH = re.compile(r'"([^"\\]*·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+[^"\\]*)"')


def sci_text(markup: str) -> str:
    """A power of ten in text markup as a superscript.

    >>> sci_text("1,458·10⁻⁴ с/мм")
    '1,458·10#super(typographic: false)[−4] с/мм'
    """
    return SCI_EXPONENT.sub(lambda m: f"#super(typographic: false)[{m[1].translate(SUPER_DIGITS)}]", markup)


def sci_math(math: str) -> str:
    """A power of ten inside a math string as one piece of text with a superscript (one piece, so
    that a fraction takes the whole number).

    >>> sci_math('k = "1,458·10⁻⁴"/30')
    'k = #[1,458·10#super(typographic: false)[−4]]/30'
    """
    def sub(m):
        return "#[" + sci_text(_SPECIAL.sub(r"\\\1", m[1])) + "]"
    return _SCI_MATH.sub(sub, math)


def escape(text: str, start: bool = True) -> str:
    """Plain text for typst markup: special characters escaped, no accidental list or heading.

    >>> escape("a_b #1 *x* [y] <z> 2 - 3")
    'a\\\\_b \\\\#1 \\\\*x\\\\* \\\\[y\\\\] \\\\<z\\\\> 2 - 3'
    >>> escape("- item"), escape("1. item"), escape("48.86")
    ('\\\\- item', '1\\\\. item', '48.86')
    >>> print(escape("a///b */ м/с x/"))
    a\\/\\/\\/b \\*/ м/с x\\/

    A "/" that could open a comment is escaped (beside another "/", or at an end of the piece: a
    "*" is escaped itself); one inside a word, as in «м/с», stays as typed for the student who edits note.typ. A person's text is not program text:
    :func:`~.model.escape_all` (through :func:`~.model.literal`) escapes it whole.
    """
    out = _SLASH.sub(r"\\/", _SPECIAL.sub(r"\\\1", text))
    out = sci_text(out.replace("--", "-\u200b-"))
    if not start:
        return out
    m = re.match(r"(\s*)(\d+)\.(?=\s|$)", out)
    if m:  # "1. " would start a numbered list ("48.86" would not)
        out = out[:m.end() - 1] + "\\." + out[m.end():]
    elif re.match(r"\s*[-+=]", out):  # a list, a heading or a term
        lead = len(out) - len(out.lstrip())
        out = out[:lead] + "\\" + out[lead:]
    return out


def string(text: str) -> str:
    """A typst string literal (its text shown as given: a string is never markup).

    >>> print(string('a"b' + chr(92) + chr(10) + 'c'))
    "a\\"b\\\\\\nc"
    """
    text = plain(text)
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n").replace("\r", "\\r") + '"'


def literal_text(text: str) -> str:
    """A person's text in typst markup: the characters given, nothing read as markup."""
    return escape_all(text)


# a derivative written (d γ)/(d φ) (one fraction in the tree: Word's stacked dγ/dφ) reads dγ/dφ on the line
DIFFERENTIAL = re.compile(r"\((d(?:\^\d)? [^()/\"]+)\)/\((d [^()/\"]+)\)")


def inline_math(math: str) -> str:
    """Inline math keeps a/b on the line: every / outside strings becomes \\/; a derivative's
    parentheses go, as typst drops them from a fraction.

    >>> print(inline_math("ω = ω_k (d γ)/(d φ)"), inline_math("ε = ω_k^2 (d^2 γ)/(d φ^2)"))
    ω = ω_k d γ\\/d φ ε = ω_k^2 d^2 γ\\/d φ^2

    >>> print(inline_math('a/b + "°/мм"'))
    a\\/b + "°/мм"
    """
    math = DIFFERENTIAL.sub(r"\1/\2", sci_math(math))
    out, quoted = [], False
    for i, ch in enumerate(math):
        if ch == '"' and (i == 0 or math[i - 1] != "\\"):
            quoted = not quoted
        if ch == "/" and not quoted and (i == 0 or math[i - 1] != "\\"):
            out.append("\\/")
        else:
            out.append(ch)
    return "".join(out)


WORD_JOINER = "\u2060"

_UNIT_DOT = re.compile(r"[^\W\d_]+(?:·[^\W\d_]+)+(?P<semi>;?)")


def unit_dot(text: str) -> str:
    """A unit with a product dot in text («Н·м», «кг·м²») boxed whole: a justified line stretched
    the gap after a bare «·» as after a word (typst takes U+00B7 for a justifiable mark: the reader
    saw «14,37 Н· м»), and a box of the dot alone lets the line break beside it. A number's
    «·10⁻⁴» is left as it is; a «;» after the box is escaped (typst would swallow it as the end
    of the embedded expression).

    >>> print(unit_dot("M = 14,37 Н·м; J = 2 кг·м², 1,5·10⁻⁴ с"))
    M = 14,37 #box[Н·м]\\; J = 2 #box[кг·м²], 1,5·10⁻⁴ с
    """
    return _UNIT_DOT.sub(lambda m: "#box[" + m.group(0).rstrip(";") + "]" + ("\\;" if m.group("semi") else ""), text)


def unit_on_one_line(text: str) -> str:
    """A header's unit kept on one line: no break after a slash of its text («рад/с», not «рад/ с»),
    by a word joiner after it (the math is left as it is).

    >>> unit_on_one_line("$ω$, рад/с") == "$ω$, рад/" + WORD_JOINER + "с"
    True
    >>> unit_on_one_line("$a/b$") == "$a/b$"
    True
    """
    return "".join(f"${piece}$" if is_math else piece.replace("/", "/" + WORD_JOINER)
                   for is_math, piece in split_math(text))


SHORT_TABLE_ROWS = 10  # a table this short is kept on one page


def label(kind: str, name: str) -> str:
    return f"{kind}-{name.replace('_', '-')}"


class TypstWriter:
    def __init__(self, doc: Document):
        self.doc = doc

    # -- inline ------------------------------------------------------------------------------------
    def inline(self, text: str) -> str:
        def ref(kind, name, number):
            if kind == "app":
                return number  # the appendix letter (typst has no counter for it)
            if f"{kind}:{name}" not in self.doc.numbers:
                return "?"
            return f"#ref(<{label(kind, name)}>, supplement: none)"

        def cite(n, where):
            return f"[{n}, {where}]" if where else f"[{n}]"

        out = []
        first = True
        for is_math, piece in split_math(text):
            if is_math:
                out.append("$" + inline_math(piece) + "$")
            else:
                # a person's text is set as given; references and citations become markup; the rest is
                # escaped text
                for j, (given, run) in enumerate(text_runs(piece)):
                    if given:
                        out.append(literal_text(run))
                        continue
                    parts = re.split(r"(\{(?:fig|tab|eq|app|cite):[^{}]*\})", run)
                    for k, part in enumerate(parts):
                        if k % 2:
                            resolved = self.doc.resolve(part, ref=ref, cite=cite)
                            out.append(resolved if resolved.startswith("#ref") else unit_dot(escape(resolved, start=False)))
                        elif k and part.startswith(";") and out[-1].startswith("#"):
                            # typst ends an embedded expression at a ";" and swallows it: «таблице 6; звенья»
                            out.append("\\;" + unit_dot(escape(part[1:], start=False)))
                        else:
                            out.append(unit_dot(escape(part, start=first and j == 0 and k == 0)))
            first = False
        return "".join(out)

    # -- blocks ------------------------------------------------------------------------------------
    def block(self, b) -> list[str]:
        if isinstance(b, Heading):
            return self.heading(b)
        if isinstance(b, Paragraph):
            text = self.inline(b.text)
            return [text if b.indent else f"#par(first-line-indent: 0pt)[{text}]", ""]
        if isinstance(b, Formula):
            return self.formula(b)
        if isinstance(b, ListBlock):
            mark = "+" if b.ordered else "-"
            return [f"{mark} {self.inline(t)}" for t in b.items] + [""]
        if isinstance(b, Table):
            return self.table(b)
        if isinstance(b, Figure):
            cap = self.inline(b.caption)
            return [f"#figure(image({string(b.file)}, width: {b.width_cm:.2f}cm), caption: [{cap}]) <{label('fig', b.name)}>", ""]
        if isinstance(b, TitlePage):
            return ["#title-page(meta)", ""]
        if isinstance(b, TaskSheet):
            return self.task(b)
        if isinstance(b, Abstract):
            return self.abstract(b)
        if isinstance(b, Contents):
            return ["#contents()", ""]
        if isinstance(b, PageBreak):
            return ["#pagebreak()", ""]
        if isinstance(b, ReferenceList):
            out = []
            for i, src in enumerate(self.doc.references(), 1):
                out += [f"{i}\\. {escape(src.text, start=False)}", ""]
            return out
        raise TypeError(b)

    def heading(self, b: Heading) -> list[str]:
        lab = f" <{label('sec', b.label)}>" if b.label and b.kind == "chapter" else ""
        if b.kind == "structural":
            return [f"#structural({string(b.text)}, outlined: {'true' if b.outlined else 'false'})", ""]
        if b.kind == "appendix":
            return [f"#appendix({string(b.number)}, {string(b.status)})[{self.inline(b.text)}]", ""]
        return [f"#heading(level: {b.level})[{self.inline(b.text)}]{lab}", ""]

    def formula(self, b: Formula) -> list[str]:
        body = sci_math(b.math)
        if b.numbered:
            lab = f" <{label('eq', b.label)}>" if b.label else ""
            lines = [f"$ {body} $" + lab]
        else:
            lines = [f"#unnumbered($ {body} $)"]
        if b.where:
            items = ", ".join(f"([${inline_math(w.symbol)}$], [{self.inline(w.meaning)}])" for w in b.where)
            lines.append(f"#where({items})")
        return lines + [""]

    def table(self, b: Table) -> list[str]:
        n = len(b.header)
        cols = "(" + ", ".join(f"{w:g}fr" if w else "auto" for w in b.widths) + ",)" if b.widths else f"({'auto, ' * n})"
        align = "(" + ", ".join(a + " + horizon" for a in (b.align or ["left"] + ["center"] * (n - 1))) + ",)"
        header = "(" + ", ".join(f"[{self.inline(unit_on_one_line(h))}]" for h in b.header) + ",)"
        lines = [f"#gtable({string(label('tab', b.name))}, [{self.inline(b.caption)}], {cols}, {align}, {header}, ("]
        for row in b.rows:
            lines.append("  " + ", ".join(f"[{self.inline(c)}]" for c in row) + ",")
        short = ", breakable: false" if len(b.rows) <= SHORT_TABLE_ROWS else ""
        lines.append(f"){short}) <{label('tab', b.name)}>")
        return lines + [""]

    def task(self, b: TaskSheet) -> list[str]:
        out = [f"#structural({string(b.title)}, outlined: false)", ""]
        for line in b.lines:
            out += [f"#par(first-line-indent: 0pt)[{self.inline(line)}]", ""]
        out += [self.inline(c) for c in b.contents[:1]] + [""]
        out += [f"+ {self.inline(c)}" for c in b.contents[1:]] + [""]
        return out

    def abstract(self, b: Abstract) -> list[str]:
        c = self.doc.counts()
        lang = self.doc.lang
        head = tr(lang, ABSTRACT_COUNTS).format(
            pages="#context counter(page).final().first()", figures=c["figures"], tables=c["tables"], sources=c["sources"])
        if c["appendices"]:
            head += tr(lang, APPENDIX_COUNT).format(appendices=c["appendices"])
        title = string(tr(lang, "Abstract").upper())
        out = [f"#structural({title}, outlined: false)", "", head, "",
               "#par(justify: false)[#text(hyphenate: false)[" + ", ".join(escape(k, start=False) for k in b.keywords).upper() + "]]", ""]
        out += [self.inline(t) + "\n" for t in b.text]
        return out


def note_source(doc: Document, meta: dict, style_file: str) -> str:
    """The text of note.typ: the style's import, the title page fields, the body."""
    doc.number()

    def value(x):
        if isinstance(x, list):
            return "(" + "".join(string(s) + ", " for s in x) + ")"
        return string(str(x))

    fields = ",\n".join(f"  {k}: {value(v)}" for k, v in meta.items())
    head = (f"// The explanatory note written by tmm. Edit the text freely and recompile in this folder:\n"
            f"//   tmm note        (or: typst compile --font-path <tmm's fonts> note.typ, see docs/note.md)\n"
            f"// The style (page, fonts, headings, the title page) is in {style_file}.\n"
            f"#import \"{style_file}\": *\n"
            f"#let meta = (\n{fields},\n)\n"
            f"#show: note.with(meta)\n")
    w = TypstWriter(doc)
    lines = [head]
    for b in doc.blocks:
        lines += w.block(b)
    return "\n".join(lines).rstrip() + "\n"
