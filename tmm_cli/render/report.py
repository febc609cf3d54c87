"""The project's documents: JSON objects, the terminal report and the Markdown / PDF report.

Every document reads the same result objects: the JSON comes from ``cam_to_json`` and
``gears_to_json``; the Markdown and PDF reports embed the very tables printed in the terminal
(recorded from rich) and the very figures saved beside them.
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
    lines = [("ℹ", note_text(n, lang)) for n in assumptions] + [("⚠", note_text(n, lang)) for n in warnings]
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
    """A Markdown report: the terminal report's tables as Markdown tables and every figure linked."""
    v = result.variant
    title = pick(lang, f"TMM course project, variant {v.number}", f"Курсовой проект по ТММ, вариант {v.number}")
    parts = [f"# {title}", "", pick(lang, f"Computed by tmm {__version__}.", f"Рассчитано программой tmm {__version__}."), ""]
    parts += [report_tables_markdown(result, lang).rstrip(), ""]
    if figure_files:
        parts += ["## " + pick(lang, "Figures", "Рисунки"), ""]
        for name in figure_files:
            stem = Path(name).stem
            title = pick(lang, *FIGURE_TITLES[stem]) if stem in FIGURE_TITLES else stem
            parts += [f"### {title}", "", f"![{title}]({name})", ""]
    return "\n".join(parts)


_PDF_SAFE = str.maketrans({"ℹ": "i", "━": "─", "┃": "│", "┏": "┌", "┓": "┐", "┗": "└", "┛": "┘", "┳": "┬",
                          "┻": "┴", "╋": "┼", "┣": "├", "┫": "┤", "┡": "├", "┩": "┤", "╇": "┼"})


def pdf_report(path: Path, result, lang: str, figures: dict) -> None:
    """One printable PDF: the text report on A4 pages, then every figure on its own page."""
    from matplotlib.backends.backend_pdf import PdfPages
    from matplotlib.figure import Figure

    # DejaVu Sans Mono lacks "ℹ" and the heavy box-drawing lines: use "i" and the light ones
    lines = terminal_text(result, lang, width=110).translate(_PDF_SAFE).splitlines()
    per_page = 80
    with PdfPages(path) as pdf:
        for start in range(0, max(len(lines), 1), per_page):
            fig = Figure(figsize=(8.27, 11.69))
            fig.text(0.04, 0.97, "\n".join(lines[start:start + per_page]), family="DejaVu Sans Mono",
                     fontsize=5.6, va="top", ha="left")
            pdf.savefig(fig)
        for fig in figures.values():
            pdf.savefig(fig)


# Figures that depend only on the planetary reducer, i.e. on design_gears' inputs other than the
# cam speed; a batch with one crank speed draws them once per worker process (see figure_cache).
REDUCER_FIGURES = ("gears_planetary", "gears_assembly")


def _reducer_key(gears, lang: str, fmt: str) -> tuple:
    return (gears.crank_rpm, gears.motor_rpm, gears.tolerance_pct, gears.forced_ratio, gears.forced_planets, lang, fmt)


def write_project_folder(result, folder: Path, lang: str, *, fmt: str = "png", plots: bool = True,
                         report: str | None = "md", figure_cache: dict | None = None, title=None):
    """Write results.json, cam_profile.csv, the figures and the report into `folder`, atomically.

    `title` (a :class:`tmm_cli.titleblock.TitleFields`, default empty) fills the drawing sheets'
    title blocks and the note's title page.

    `figure_cache` (a dict the caller keeps between calls, as `tmm batch` does) lets variants
    that share a reducer reuse its two drawings instead of drawing them again.
    Returns (the JSON document, the sorted list of file names written).
    """
    from .cam_json import profile_csv
    from .files import save_figures, staged_dir, write_json, write_text

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
        if report == "md":
            write_text(tmp / "report.md", markdown_report(result, lang, files))
        elif report == "pdf":
            pdf_report(tmp / "report.pdf", result, lang, figures)
        written = sorted(p.name for p in tmp.iterdir())
    return doc, written
