"""A small document model and its two writers, typst source and Markdown — kept for the teacher's
feedback and assignment sheets (render/feedback, render/assignment), which are written with it.
The explanatory note itself is the richer model of :mod:`.model` (three writers); moving these two
small documents onto it is left for later.


Text is written in a mini markup: plain text with inline typst math between ``$…$`` and
references ``{fig:name}`` / ``{tab:name}`` to figures and tables added anywhere in the document.
Display formulas are typst math. The typst writer escapes the plain text and keeps the math; the
Markdown writer turns the math into text with ``<sub>``/``<sup>`` (GitHub renders them).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ...i18n import tr
from .model import md_text, text_runs
from .typst import escape, inline_math, literal_text, string

_REF = re.compile(r"\{(fig|tab):([a-z0-9_]+)\}")
# the escaping of the note's typst writer (one rule for every typst text tmm writes)
typst_escape, typst_string, inline_slashes = escape, string, inline_math


def split_long(math: str, limit: int = 72) -> str:
    """A display formula too wide for the line breaks into lines at its "; quad" joints."""
    if "; quad" in math and len(math_to_text(math, html=False)) > limit:
        return math.replace("; quad ", " \\ ")
    return math


_NBSP = re.compile(r"(рис\.|табл\.|п\.|§|Fig\.|Table|Figure|рисунке|рисунок|таблице|таблица) ")


# --- math (typst subset) to Markdown text ------------------------------------------------------

_WORDS = {"thin": " ", "space": " ", "quad": "  ", "dot": "·", "times": "×", "approx": "≈", "thick": " ",
          "med": " ", "plus.minus": "±", "dots": "…", "dots.h": "…", "infinity": "∞", "lt.eq": "≤", "gt.eq": "≥",
          "sqrt": "√", "arrow.r": "→", "gcd": "gcd", "sin": "sin", "cos": "cos", "tan": "tan", "max": "max",
          "min": "min", "ln": "ln", "log": "log", "pi": "π", "mod": "mod", "eq.not": "≠", "degree": "°"}


_TOKEN = re.compile(r"[A-Za-z]+|\d+|.")
_NAME = re.compile(r"[A-Za-z]+(\.[a-z]+)*")


def _group(s: str, i: int) -> tuple[str, int]:
    """The operand of _ or ^ starting at s[i]: (…), "…" or one word/char; returns (text, next index)."""
    if i >= len(s):
        return "", i
    if s[i] == "(":
        depth, j = 0, i
        while j < len(s):
            depth += s[j] == "("
            depth -= s[j] == ")"
            if depth == 0:
                break
            j += 1
        return s[i + 1:j], j + 1
    if s[i] == '"':
        j = s.index('"', i + 1)
        return s[i:j + 1], j + 1
    m = _TOKEN.match(s, i)
    return m.group(0), m.end()


def math_to_text(s: str, html: bool = True) -> str:
    """Typst math (the subset the note uses) as readable text.

    >>> math_to_text('k_φ = φ_"р"/b = 210/240 = "0,875" thin "°/мм"')
    'k<sub>φ</sub> = φ<sub>р</sub>/b = 210/240 = 0,875 °/мм'
    >>> math_to_text('z_(c′) dot h_a^* ', html=False)
    'z_c′ · h_a^*'
    """
    out: list[str] = []
    i = 0
    while i < len(s):
        ch = s[i]
        if ch in "_^":
            body, i = _group(s, i + 1)
            inner = math_to_text(body, html)
            if html:
                tag = "sub" if ch == "_" else "sup"
                out.append(f"<{tag}>{inner}</{tag}>")
            else:
                out.append(ch + inner)
            continue
        if ch == '"':
            j = s.index('"', i + 1)
            out.append(s[i + 1:j])
            i = j + 1
            continue
        if s.startswith("abs(", i):
            body, i = _group(s, i + 3)
            out.append("|" + math_to_text(body, html) + "|")
            continue
        m = _NAME.match(s, i)
        if m and len(m.group(0)) > 1 and m.group(0) in _WORDS:
            out.append(_WORDS[m.group(0)])
            i += len(m.group(0))
            continue
        if m and len(m.group(0)) > 1 and m.group(0).split(".")[0] in _WORDS:
            w = m.group(0).split(".")[0]
            out.append(_WORDS[w])
            i += len(w)
            continue
        if m:
            out.append(m.group(0))
            i += len(m.group(0))
            continue
        out.append(ch)
        i += 1
    text = re.sub(r" °(?!/)", "°", re.sub(r"  +", " ", "".join(out)).strip())
    return re.sub(r"(?<=[\s(\d])-(?=[\s\d(])", "−", text)


# --- the model ---------------------------------------------------------------------------------


@dataclass
class Doc:
    """Blocks of the note in order; figures and tables get their numbers as they are added."""

    lang: str
    blocks: list[tuple] = field(default_factory=list)
    numbers: dict[str, int] = field(default_factory=dict)
    counts: dict[str, int] = field(default_factory=lambda: {"fig": 0, "tab": 0})
    equations: list[str] = field(default_factory=list)  # the book's equation numbers cited, in order

    def h(self, level: int, text: str, numbered: bool = True) -> None:
        self.blocks.append(("h", level, text, numbered))

    def p(self, text: str) -> None:
        self.blocks.append(("p", text))
        self.equations += re.findall(r"\((\d\.\d{1,2})\)", _REF.sub("", re.sub(r"\$[^$]*\$", "", text)))

    def formula(self, math: str, number: str | None = None) -> None:
        self.blocks.append(("f", math, number))
        if number:
            self.equations.append(number)

    def where(self, text: str) -> None:
        self.blocks.append(("where", text))

    def items(self, texts: list[str]) -> None:
        if texts:
            self.blocks.append(("list", list(texts)))

    def figure(self, name: str, file: str, caption: str, width: str = "100%") -> None:
        self.counts["fig"] += 1
        self.numbers["fig:" + name] = self.counts["fig"]
        self.blocks.append(("fig", name, file, caption, width))

    def table(self, name: str, caption: str, header: list[str], rows: list[list[str]],
              align: str | None = None, widths: list[str] | None = None) -> None:
        self.counts["tab"] += 1
        self.numbers["tab:" + name] = self.counts["tab"]
        self.blocks.append(("tab", name, caption, header, rows, align, widths))

    def raw(self, typst: str, markdown: str = "") -> None:
        self.blocks.append(("raw", typst, markdown))

    # -- writers ---------------------------------------------------------------------------------

    def _drop_missing(self, text: str) -> str:
        """Remove references to figures that were not drawn (`--no-plots`), with their words."""
        def gone(m):
            return "" if f"fig:{m.group('name')}" not in self.numbers else m.group(0)

        text = re.sub(r"\s*\((?:рисунок|рисунки|Figure|Figures) \{fig:(?P<name>\w+)\}\)", gone, text)
        text = re.sub(r"(?:,? (?:на|see|in|на рисунке|see Figure))? ?(?:на рисунке|рисунок|Figure) \{fig:(?P<name>\w+)\}",
                      gone, text)
        return _REF.sub(lambda m: m.group(0) if f"{m.group(1)}:{m.group(2)}" in self.numbers else "", text)

    def _inline_typst(self, text: str) -> str:
        text = self._drop_missing(text)
        parts = re.split(r"(\$[^$]*\$)", text)
        out = []
        for part in parts:
            if part.startswith("$") and part.endswith("$") and len(part) >= 2:
                out.append(inline_slashes(part))
                continue
            for given, run in text_runs(part):
                first = not out
                if given:  # a person's text: the characters given
                    out.append(literal_text(run))
                    continue
                run = _NBSP.sub("\\1\u00a0", run)
                pieces = _REF.split(run)
                # split gives [text, kind, name, text, kind, name, ...]
                for k in range(0, len(pieces), 3):
                    out.append(typst_escape(pieces[k], start=first and k == 0))
                    if k + 2 < len(pieces):
                        kind, name = pieces[k + 1], pieces[k + 2]
                        out.append(f"@{kind}-{name.replace('_', '-')}[]")
        return "".join(out)

    def _inline_md(self, text: str) -> str:
        def ref(m):
            n = self.numbers.get(f"{m.group(1)}:{m.group(2)}")
            return str(n) if n else "?"

        parts = re.split(r"(\$[^$]*\$)", _REF.sub(ref, self._drop_missing(text)))
        out = []
        for part in parts:
            if part.startswith("$") and part.endswith("$") and len(part) >= 2:
                out.append(math_to_text(part[1:-1]))
            else:
                out += [md_text(run) if given else re.sub(r"([*_`\\])", r"\\\1", run)
                        for given, run in text_runs(part)]
        return "".join(out)

    def to_typst(self, preamble: str) -> str:
        lines = [preamble.rstrip(), ""]
        for b in self.blocks:
            kind = b[0]
            if kind == "h":
                _, level, text, numbered = b
                opt = "" if numbered else ", numbering: none"
                lines += [f"#heading(level: {level}{opt})[{self._inline_typst(text)}]", ""]
            elif kind == "p":
                lines += [self._inline_typst(b[1]), ""]
            elif kind == "f":
                _, math, number = b
                num = typst_string(number) if number else "none"
                lines += [f"#formula($ {split_long(math)} $, {num})", ""]
            elif kind == "where":
                lines += [f"#where[{self._inline_typst(b[1])}]", ""]
            elif kind == "list":
                lines += [f"- {self._inline_typst(t)}" for t in b[1]] + [""]
            elif kind == "fig":
                _, name, file, caption, width = b
                label = "fig-" + name.replace("_", "-")
                lines += [f"#figure(image({typst_string(file)}, width: {width}),",
                          f"  caption: [{self._inline_typst(caption)}]) <{label}>", ""]
            elif kind == "tab":
                _, name, caption, header, rows, align, widths = b
                label = "tab-" + name.replace("_", "-")
                ncol = len(header)
                cols = "(" + ", ".join(widths) + ",)" if widths else str(ncol)
                al = align or ("left" + ", right" * (ncol - 1))
                lines.append(f"#figure(caption: [{self._inline_typst(caption)}], table(columns: {cols}, "
                             f"align: ({al},),")
                lines.append("  table.header(" + ", ".join(f"[{self._inline_typst(h)}]" for h in header) + "),")
                for row in rows:
                    lines.append("  " + ", ".join(f"[{self._inline_typst(c)}]" for c in row) + ",")
                lines += [f")) <{label}>", ""]
            elif kind == "raw":
                lines += [b[1], ""]
        return "\n".join(lines)

    def to_markdown(self, title: str) -> str:
        out = [f"# {title}", ""]
        counters = [0, 0, 0]
        for b in self.blocks:
            kind = b[0]
            if kind == "h":
                _, level, text, numbered = b
                number = ""
                if numbered:
                    counters[level - 1] += 1
                    counters[level:] = [0] * (len(counters) - level)
                    number = ".".join(str(x) for x in counters[:level]) + " "
                out += ["#" * (level + 1) + " " + number + self._inline_md(text), ""]
            elif kind == "p":
                out += [self._inline_md(b[1]), ""]
            elif kind == "f":
                _, math, number = b
                tail = f" ({number})" if number else ""
                out += [f"> {math_to_text(math)}{tail}", ""]
            elif kind == "where":
                out += [self._inline_md(b[1]), ""]
            elif kind == "list":
                out += [f"- {self._inline_md(t)}" for t in b[1]] + [""]
            elif kind == "fig":
                _, name, file, caption, _width = b
                n = self.numbers["fig:" + name]
                word = tr(self.lang, "Figure")
                out += [f"![{self._inline_md(caption)}]({file})", "", f"*{word} {n} – {self._inline_md(caption)}*", ""]
            elif kind == "tab":
                _, name, caption, header, rows, _align, _w = b
                n = self.numbers["tab:" + name]
                word = tr(self.lang, "Table")
                out += [f"*{word} {n} – {self._inline_md(caption)}*", ""]
                cell = lambda c: re.sub(r"(?<!\\)\|", r"\\|", self._inline_md(c)).replace("\n", " ")  # noqa: E731
                out.append("| " + " | ".join(cell(h) for h in header) + " |")
                out.append("|" + "|".join(["---"] * len(header)) + "|")
                for row in rows:
                    out.append("| " + " | ".join(cell(c) for c in row) + " |")
                out.append("")
            elif kind == "raw" and b[2]:
                out += [b[2], ""]
        return "\n".join(out).rstrip() + "\n"
