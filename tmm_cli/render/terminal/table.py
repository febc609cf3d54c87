"""Tables, headings and note blocks that are rendered only when somebody reads them.

The table printers (cam_tables, gears_tables) build these plain objects and hand them to
``console.print``. A rich Console renders them through ``__rich__`` (rich is imported then and
only then); :class:`MarkdownSink` turns the same objects into Markdown for report.md without
laying out a single terminal table. So ``tmm project --json`` writes its report without paying
for the terminal report it does not print.
"""

from __future__ import annotations

import re

# rich markup as the printers write it: [bold], [/], [green], [bold green], [/green], [dim], [yellow]
_MARKUP = re.compile(r"\[/?(?:bold|dim|italic|green|red|yellow|cyan|bold green|bold red)?\]")


def plain(text: str) -> str:
    """`text` without rich markup.

    >>> plain("[bold]z_k = 40[/], [green]✓[/green]")
    'z_k = 40, ✓'
    """
    return _MARKUP.sub("", str(text))


class Table:
    """A titled table of text cells (rich markup allowed); the subset of rich.table.Table we use."""

    def __init__(self, title: str = "", header_style: str | None = "bold", title_style: str | None = None):
        self.title = title
        self.header_style = header_style
        self.title_style = title_style
        self.columns: list[tuple[str, str]] = []
        self.rows: list[tuple[tuple[str, ...], str | None]] = []

    def add_column(self, name: str, justify: str = "left") -> None:
        self.columns.append((name, justify))

    def add_row(self, *cells, style: str | None = None) -> None:
        self.rows.append((tuple(str(c) for c in cells), style))

    def __rich__(self):
        from rich.table import Table as RichTable

        t = RichTable(title=self.title or None, header_style=self.header_style, title_justify="left",
                      title_style=self.title_style)
        for name, justify in self.columns:
            t.add_column(name, justify=justify, overflow="fold")
        for cells, style in self.rows:
            t.add_row(*cells, style=style)
        return t

    def markdown(self) -> str:
        def cell(text: str, bold: bool = False) -> str:
            text = plain(text).replace("\\", "\\\\").replace("|", "\\|").replace("*", "\\*").replace("\n", " ")
            return f"**{text}**" if bold and text.strip() else text

        align = {"left": ":---", "right": "---:", "center": ":---:"}
        lines = []
        if self.title:
            lines += [f"**{cell(self.title)}**", ""]
        lines.append("| " + " | ".join(cell(n) or " " for n, _ in self.columns) + " |")
        lines.append("|" + "|".join(align.get(j, "---") for _, j in self.columns) + "|")
        for cells, style in self.rows:
            lines.append("| " + " | ".join(cell(c, bool(style and "bold" in style)) for c in cells) + " |")
        return "\n".join(lines)


class Heading(str):
    """A section heading: a rule across the terminal, a ``##`` heading in Markdown."""

    def __rich__(self):
        from rich.rule import Rule

        return Rule(str(self))

    def markdown(self) -> str:
        return f"## {plain(self)}"


class NoteBlock:
    """The assumptions and warnings of a run: a panel in the terminal, a list in Markdown."""

    def __init__(self, title: str, lines: list[tuple[str, str]]):
        self.title = title
        self.lines = lines  # (mark, sentence)

    def __rich__(self):
        from rich.panel import Panel

        from . import escape

        colour = {"ℹ": "cyan", "⚠": "yellow", "✖": "bold red"}
        # a sentence may hold a person's text (a mechanism's name): its markup and controls are text
        body = "\n".join(f"[{colour[mark]}]{mark} {escape(text)}[/]" if mark == "✖"
                         else f"[{colour.get(mark, 'white')}]{mark}[/] {escape(text)}" for mark, text in self.lines)
        return Panel(body, title=self.title, expand=False)

    def markdown(self) -> str:
        from ..note.model import md_text

        return "\n".join([f"**{self.title}**", ""] + [f"- {mark} {md_text(text)}" for mark, text in self.lines])


class MarkdownSink:
    """Stands in for a rich Console: keeps what the printers hand it and writes it as Markdown."""

    def __init__(self):
        self.parts: list[str] = []

    def print(self, *objects, **_) -> None:
        for obj in objects:
            if hasattr(obj, "markdown"):
                self.parts.append(obj.markdown())
            else:
                self.parts.append(plain(str(obj)).strip())

    def text(self) -> str:
        return "\n\n".join(p for p in self.parts if p) + "\n"
