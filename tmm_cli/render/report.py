"""The project's documents: JSON objects, the terminal report, report.md and the typeset note.

Every document reads the same result objects: the JSON comes from ``cam_to_json`` and
``gears_to_json``; report.md and note.pdf are the explanatory note (render/note), with the very
figures saved beside them.
"""

from __future__ import annotations

import io
from pathlib import Path

from .. import __version__
from ..variants import Variant
from .i18n import note_text, pick


def _head(v: Variant) -> dict:
    return {"tool": f"tmm {__version__}", "variant": v.number, "input": v.as_input_dict()}


def cam_document(v: Variant, cam, lang: str) -> dict:
    """The JSON of `tmm cam`: variant, input row, cam."""
    from .cam_json import cam_to_json

    return {**_head(v), "cam": cam_to_json(cam, lang)}


def gears_document(v: Variant, gears, lang: str) -> dict:
    """The JSON of `tmm gears`: variant, input row, gears."""
    from .gears_json import gears_to_json

    return {**_head(v), "gears": gears_to_json(gears, lang)}


def project_document(result, lang: str) -> dict:
    """The JSON of `tmm project` (= results.json): the union of the cam and gears documents."""
    from .cam_json import cam_to_json
    from .gears_json import gears_to_json

    notes = result.notes
    return {
        **_head(result.variant),
        "gears": gears_to_json(result.gears, lang),
        "cam": cam_to_json(result.cam, lang),
        "assumptions": [note_text(n, lang) for n in notes if n.level == "assumption"],
        "warnings": [note_text(n, lang) for n in notes if n.level == "warning"],
    }


def print_project(console, result, lang: str) -> None:
    """The terminal report in the order of the explanatory note: input, sheet 4, sheet 3, notes."""
    from .cam_tables import print_cam, print_cam_input
    from .gears_tables import print_gears
    from .table_model import Heading

    v = result.variant
    console.print(Heading(pick(lang, f"TMM course project — variant {v.number}", f"Курсовой проект по ТММ — вариант {v.number}")))
    print_cam_input(console, result.cam, lang)
    console.print(Heading(pick(lang, "Sheet 4 — gear drive", "Лист 4 — синтез зубчатых механизмов")))
    print_gears(console, result.gears, lang)
    console.print(Heading(pick(lang, "Sheet 3 — cam mechanism", "Лист 3 — синтез кулачкового механизма")))
    print_cam(console, result.cam, lang, include_input=False)
    print_notes(console, result.notes, lang)


def print_notes(console, notes, lang: str) -> None:
    """All assumptions, then all warnings, in one panel at the end of a report."""
    if not notes:
        return
    from .table_model import NoteBlock

    assumptions = [n for n in notes if n.level == "assumption"]
    warnings = [n for n in notes if n.level == "warning"]
    lines = [("ℹ", note_text(n, lang)) for n in assumptions]
    lines += [("✖" if "_fail_" in n.code else "⚠", note_text(n, lang)) for n in warnings]  # "_fail_": a condition
    # the carried (student's) design breaks, in red
    title = pick(lang, f"Assumptions ({len(assumptions)}) and warnings ({len(warnings)})",
                 f"Допущения ({len(assumptions)}) и предупреждения ({len(warnings)})")
    console.print(NoteBlock(title, lines))


def terminal_text(result, lang: str, width: int = 110) -> str:
    """The terminal report as plain text (what `print_project` shows, without colours)."""
    from rich.console import Console

    console = Console(record=True, width=width, file=io.StringIO(), color_system=None, highlight=False)
    print_project(console, result, lang)
    return console.export_text()


FIGURE_TITLES = {
    "gears_planetary": ("Planetary reducer: scheme and velocity pictures", "Планетарный редуктор: схема и планы скоростей"),
    "gears_assembly": ("Planets placed at 2β = 360°/k", "Расстановка сателлитов"),
    "gears_mesh": ("Spur pair and its mesh", "Простая передача и картина зацепления"),
    "cam_motion": ("Follower motion diagrams", "Диаграммы движения толкателя"),
    "cam_zone": ("Zone of the cam centre", "Зона положения центра кулачка"),
    "cam_profile": ("Cam profile", "Профиль кулачка"),
    "cam_pressure_angle": ("Pressure angle over the cam turn", "Угол давления за оборот кулачка"),
    "cam_profile_scaled": ("Cam profile at its standard scale", "Профиль кулачка в стандартном масштабе"),
}


def report_tables_markdown(result, lang: str) -> str:
    """The terminal report's tables and notes as Markdown (same objects, no terminal layout)."""
    from .table_model import MarkdownSink

    sink = MarkdownSink()
    print_project(sink, result, lang)
    return "\n\n".join(p for p in sink.parts[1:] if p) + "\n"  # [0] repeats the report's title


def markdown_report(result, lang: str, figure_files: list[str]) -> str:
    """report.md: the explanatory note as Markdown (headings, tables, figures with captions)."""
    from .note import markdown_note

    return markdown_note(result, lang, figure_files)


# Figures that depend only on the planetary reducer, i.e. on design_gears' inputs other than the
# cam speed; a batch with one crank speed draws them once per worker process (see figure_cache).
REDUCER_FIGURES = ("gears_planetary", "gears_assembly")


def _reducer_key(gears, lang: str, fmt: str) -> tuple:
    return (gears.crank_rpm, gears.motor_rpm, gears.tolerance_pct, gears.forced_ratio, gears.forced_planets, lang, fmt)


def write_project_folder(result, folder: Path, lang: str, *, fmt: str = "png", plots: bool = True,
                         report: str | None = "md", figure_cache: dict | None = None, title=None,
                         note_template: str | None = None, sheets: bool = False):
    """Write results.json, cam_profile.csv, the figures and the report into `folder`, atomically.

    `report`: "md" writes report.md, "pdf" the typeset note (note.pdf, its source note.typ and
    note-style.typ, and SVG copies of the figures it embeds), None neither. The note is written
    last; if typst fails (a broken `note_template`, the text of a style file), every other file
    still comes out, the note's files do not, and the TmmError is raised after the folder is in
    place (exit 2).

    `title` (a :class:`tmm_cli.titleblock.TitleFields`, default empty) fills the drawing sheets'
    title blocks and the note's title page.

    `figure_cache` (a dict the caller keeps between calls, as `tmm batch` does) lets variants
    that share a reducer reuse its two drawings instead of drawing them again.
    `sheets` adds the A1 drawings sheet3.dxf/.pdf and sheet4.dxf/.pdf (render/sheets).
    Returns (the JSON document, the sorted list of file names written).
    """
    from .cam_json import profile_csv
    from .files import save_figures, staged_dir, staged_names, write_json, write_text

    doc = project_document(result, lang)
    # the project owns its folder: nothing of an earlier run (other options) stays beside it
    with staged_dir(folder, owns=("*",)) as tmp:
        write_json(tmp / "results.json", doc)
        write_text(tmp / "cam_profile.csv", profile_csv(result.cam))
        figures, files = {}, []
        if plots:
            from .cam_figures import cam_figures
            from .gears_figures import gears_figures

            cached = {}
            if figure_cache is not None and report != "pdf":
                key = _reducer_key(result.gears, lang, fmt)
                if key not in figure_cache:
                    reducer = gears_figures(result.gears, lang, names=REDUCER_FIGURES)
                    figure_cache[key] = {n: save_figures(tmp, {n: f}, fmt)[0].read_bytes() for n, f in reducer.items()}
                cached = figure_cache[key]
                for name, data in cached.items():
                    (tmp / f"{name}.{fmt}").write_bytes(data)
            names = [n for n in ("gears_planetary", "gears_assembly", "gears_mesh") if n not in cached]
            if figure_cache is None and report != "pdf":  # one project: sheet 4 and sheet 3 drawn side by side
                from .figure_kit import save_side_by_side

                figures = save_side_by_side(tmp, fmt, lambda: gears_figures(result.gears, lang, names=names),
                                            lambda: cam_figures(result.cam, lang), save_figures)
            else:
                figures = {**gears_figures(result.gears, lang, names=names), **cam_figures(result.cam, lang)}
                save_figures(tmp, figures, fmt)
            files = [f"{n}.{fmt}" for n in (*REDUCER_FIGURES, "gears_mesh") if n in cached or n in figures]
            files += [f"{n}.{fmt}" for n in figures if n.startswith("cam_")]
        # --- the report: Markdown or the typeset note (issue 11) ------------------------------------
        note_error = None
        if report == "md":
            write_text(tmp / "report.md", markdown_report(result, lang, files))
        elif report == "pdf":
            note_error = _write_note(tmp, result, lang, title, figures, fmt, note_template)
        # --- the A1 drawing sheets 3 and 4 (issue 10): DXF + PDF from one ezdxf model ---------
        if sheets:
            from .sheets import write_sheets

            write_sheets(tmp, result, lang, title)
        # ----------------------------------------------------------------------------------------
        written = staged_names(tmp)
    if note_error is not None:
        raise note_error
    return doc, written


def _write_note(tmp: Path, result, lang: str, title, figures: dict, fmt: str, template: str | None):
    """The note into the staging folder; returns the TmmError of a failed note (its files removed)."""
    from ..errors import TmmError
    from .note import NOTE_FIGURES, write_note

    made, files = [], {}
    for name in NOTE_FIGURES:
        if name in figures:
            path = tmp / f"{name}.svg"
            if fmt != "svg":
                figures[name].savefig(path, format="svg")
                made.append(path)
            files[name] = path.name
        elif (tmp / f"{name}.svg").exists():  # drawn once per batch worker (figure cache)
            files[name] = f"{name}.svg"
    try:
        write_note(tmp, result, lang, title, files, template)
    except TmmError as exc:
        for path in made:
            path.unlink(missing_ok=True)
        return exc
    return None
