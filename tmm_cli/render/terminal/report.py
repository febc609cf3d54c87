"""The terminal report of `tmm project` in the order of the note, its notes, and the same tables as Markdown."""

from __future__ import annotations

import io

from ...i18n import tr

from ...i18n.lang import note_text


def print_project(console, result, lang: str) -> None:
    """The terminal report in the order of the explanatory note: input, sheet 4, sheet 3, notes."""
    from .cam import print_cam, print_cam_input
    from .gears import print_gears
    from .table import Heading

    v = result.variant
    console.print(Heading(tr(lang, "TMM course project — variant {number}").format(number=v.number)))
    print_cam_input(console, result.cam, lang)
    console.print(Heading(tr(lang, "Sheet 4 — gear drive")))
    print_gears(console, result.gears, lang)
    console.print(Heading(tr(lang, "Sheet 3 — cam mechanism")))
    print_cam(console, result.cam, lang, include_input=False)
    print_notes(console, tuple(result.notes) + mechanism_name_notes(result, lang), lang)


def mechanism_name_notes(result, lang: str) -> tuple:
    """The warning of a mechanism's name not in the letters of `lang` (with --mechanism)."""
    from ...i18n.lang import name_script_notes

    linkage = getattr(result, "linkage", None)
    if linkage is None:
        return ()
    s1 = getattr(linkage, "sheet1", linkage)
    return name_script_notes(s1.mechanism.name, lang)


def print_notes(console, notes, lang: str) -> None:
    """All assumptions, then all warnings, in one panel at the end of a report."""
    if not notes:
        return
    from .table import NoteBlock

    assumptions = [n for n in notes if n.level == "assumption"]
    warnings = [n for n in notes if n.level == "warning"]
    lines = [("ℹ", note_text(n, lang)) for n in assumptions]
    lines += [("✖" if "_fail_" in n.code else "⚠", note_text(n, lang)) for n in warnings]  # "_fail_": a condition
    # the carried (student's) design breaks, in red
    title = tr(lang, "Assumptions ({assumptions}) and warnings ({warnings})").format(assumptions=len(assumptions), warnings=len(warnings))
    console.print(NoteBlock(title, lines))


def terminal_text(result, lang: str, width: int = 110) -> str:
    """The terminal report as plain text (what `print_project` shows, without colours)."""
    from rich.console import Console

    console = Console(record=True, width=width, file=io.StringIO(), color_system=None, highlight=False)
    print_project(console, result, lang)
    return console.export_text()


def report_tables_markdown(result, lang: str) -> str:
    """The terminal report's tables and notes as Markdown (same objects, no terminal layout)."""
    from .table import MarkdownSink

    sink = MarkdownSink()
    print_project(sink, result, lang)
    return "\n\n".join(p for p in sink.parts[1:] if p) + "\n"  # [0] repeats the report's title
