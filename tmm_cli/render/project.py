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
from ..i18n.lang import note_text, pick


def _head(v: Variant) -> dict:
    return {"tool": f"tmm {__version__}", "variant": v.number, "input": v.as_input_dict()}


def cam_document(v: Variant, cam, lang: str) -> dict:
    """The JSON of `tmm cam`: variant, input row, cam."""
    from .data.cam import cam_to_json

    return {**_head(v), "cam": cam_to_json(cam, lang)}


def gears_document(v: Variant, gears, lang: str) -> dict:
    """The JSON of `tmm gears`: variant, input row, gears."""
    from .data.gears import gears_to_json

    return {**_head(v), "gears": gears_to_json(gears, lang)}


def project_document(result, lang: str) -> dict:
    """The JSON of `tmm project` (= results.json): the union of the cam and gears documents."""
    from .data.cam import cam_to_json
    from .data.gears import gears_to_json

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
    from .terminal.cam import print_cam, print_cam_input
    from .terminal.gears import print_gears
    from .terminal.table import Heading

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
    from .terminal.table import NoteBlock

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
    from .terminal.table import MarkdownSink

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


GEAR_FIGURES = ("gears_planetary", "gears_assembly", "gears_mesh")
CAM_FIGURES = ("cam_motion", "cam_zone", "cam_profile", "cam_pressure_angle", "cam_profile_scaled")
ALL_FIGURES = GEAR_FIGURES + CAM_FIGURES  # sheet 4 first, as in the report

# Rough time [s] of drawing and saving each figure (PNG at 120 dpi, its SVG copy for the note),
# variant 17: only to draw the long ones first.
_COST = {"gears_planetary": (0.45, 0.2), "gears_assembly": (0.25, 0.1), "gears_mesh": (0.6, 0.35),
         "cam_motion": (0.65, 0.15), "cam_zone": (0.45, 0.2), "cam_profile": (0.3, 0.15),
         "cam_pressure_angle": (0.2, 0.1), "cam_profile_scaled": (0.1, 0.05)}


def _largest_first(names, svg) -> list:
    """The figures to draw, the longest first (so that the last ones, taken by whichever process
    is free, are short).

    >>> _largest_first(["cam_profile_scaled", "gears_assembly", "gears_mesh"], set())
    ['gears_mesh', 'gears_assembly', 'cam_profile_scaled']
    """
    def cost(n):
        png, copy = _COST.get(n, (0.4, 0.2))
        return png + (copy if n in svg else 0.0)

    return sorted(names, key=cost, reverse=True)


def _figure_task(tmp: Path, result, lang: str, fmt: str, name: str, svg):
    return lambda: _draw_and_save(tmp, result, lang, fmt, [name], svg)


def prepare_figures(svg) -> None:
    """What every process that draws needs, built once before a fork: the figure modules, mathtext
    and the fonts, the SVG backend if the note wants SVG copies (`svg` true)."""
    from .figures import cam as cam_figures, gears as gears_figures  # noqa: F401
    from .figures.kit import _warm_up

    _warm_up()
    if svg:
        import matplotlib.backends.backend_svg  # noqa: F401
    calm_collector()


def calm_collector() -> None:
    """Python's cycle collector, told what lives to the end: everything loaded so far (the modules,
    matplotlib's fonts and grammar) is frozen out of its scans (`gc.freeze`, as Python's manual
    advises before a fork), and it runs after 10 000 new objects instead of 700. A figure is
    thousands of small objects in cycles; with the defaults the collector took ≈ 10 % of drawing
    time, walking the whole heap again and again (≈ 0.15 s per variant, ≈ 0.07 s after this)."""
    import gc

    gc.freeze()
    gc.set_threshold(10_000, 50, 100)


def _draw_and_save(tmp: Path, result, lang: str, fmt: str, names, svg) -> None:
    """Draw the figures `names` once and save each as `fmt`, and as SVG too if it is in `svg`."""
    from .figures.cam import cam_figures
    from ..output.folder import save_figures
    from .figures.gears import gears_figures

    gear = [n for n in names if n in GEAR_FIGURES]
    cam = [n for n in names if n in CAM_FIGURES]
    figs = {**(gears_figures(result.gears, lang, names=gear) if gear else {}),
            **(cam_figures(result.cam, lang, names=cam) if cam else {})}
    save_figures(tmp, figs, fmt)
    for name, fig in figs.items():
        if name in svg:
            fig.savefig(tmp / f"{name}.svg", format="svg")  # the same drawn figure, another renderer


def _mesh_key(gears, lang: str, fmt: str) -> tuple:
    return ("mesh", repr(gears.spur), gears.directions, lang, fmt)


def _from_cache(tmp: Path, result, lang: str, fmt: str, svg, cache: dict, shared=None):
    """Write the figures a batch worker drew already for another variant (the reducer's two,
    which depend only on the reducer; the spur mesh, which depends only on the spur pair and
    the senses of rotation); draw and keep them on a miss.

    `shared` (a :class:`~tmm_cli.render.figures.shared.SharedFigures`, the batch's workers' common
    folder) is asked on a miss: a drawing another worker published is taken from it; one another
    worker is drawing now is put off to the end of the row. Returns (the names written or put
    off, a function that writes the put-off ones: call it once the row's other figures are done).
    """
    written, later = set(), []

    def draw(group):
        _draw_and_save(tmp, result, lang, fmt, group, svg)
        paths = [f"{n}.{fmt}" for n in group] + [f"{n}.svg" for n in group if n in svg]
        return {p: (tmp / p).read_bytes() for p in paths}

    def write(entry):
        for p, data in entry.items():
            (tmp / p).write_bytes(data)

    for group, key in ((REDUCER_FIGURES, _reducer_key(result.gears, lang, fmt)),
                       (("gears_mesh",), _mesh_key(result.gears, lang, fmt))):
        key = (*key, tuple(sorted(n for n in group if n in svg)))
        written.update(group)
        entry = cache.pop(key, None)
        if entry is None and shared is not None:
            entry = shared.get(key)
            if entry is None and not shared.claim(key):  # another worker draws it right now
                later.append((group, key))
                continue
            if entry is None:
                entry = draw(group)
                shared.put(key, entry)
            else:
                write(entry)
        elif entry is None:
            entry = draw(group)
        else:
            write(entry)
        cache[key] = entry  # the most recently used last (the batch drops the oldest)

    def finish() -> None:
        for group, key in later:
            entry = shared.wait(key)
            if entry is None:  # the other worker failed or was stopped: draw it here
                entry = draw(group)
            else:
                write(entry)
            cache[key] = entry

    return written, finish


def write_project_folder(result, folder: Path, lang: str, *, fmt: str = "png", plots: bool = True,
                         report: str | None = "md", figure_cache: dict | None = None, title=None,
                         note_template: str | None = None, sheets: bool = False, meanwhile=None,
                         shared_figures=None):
    """Write results.json, cam_profile.csv, the figures and the report into `folder`, atomically.

    `report`: "md" writes report.md, "pdf" the typeset note (note.pdf, its source note.typ and
    note-style.typ, and SVG copies of the figures it embeds), None neither. The note is written
    last; if typst fails (a broken `note_template`, the text of a style file), every other file
    still comes out, the note's files do not, and the TmmError is raised after the folder is in
    place (exit 2).

    `title` (a :class:`tmm_cli.inputs.titleblock.TitleFields`, default empty) fills the drawing sheets'
    title blocks and the note's title page.

    `figure_cache` (a dict the caller keeps between calls, as `tmm batch` does) lets variants
    that share a reducer reuse its two drawings instead of drawing them again; `shared_figures`
    (render/shared_figures) shares them between the batch's worker processes too.
    `sheets` adds the A1 drawings sheet3.dxf/.pdf and sheet4.dxf/.pdf (render/sheets).
    `meanwhile` (no arguments) runs in this process while a forked child starts on the figures,
    before this process takes its share (`tmm project` renders its terminal report there).
    Returns (the JSON document, the sorted list of file names written).
    """
    from .data.cam import profile_csv
    from ..output.folder import staged_dir, staged_names, write_json, write_text
    from .note import NOTE_FIGURES

    doc = project_document(result, lang)
    # the project owns its folder: nothing of an earlier run (other options) stays beside it
    with staged_dir(folder, owns=("*",)) as tmp:
        svg = set(NOTE_FIGURES) if report == "pdf" and fmt != "svg" else set()  # SVG copies for the note
        cached, finish_cached = set(), lambda: None
        if plots and figure_cache is not None:
            cached, finish_cached = _from_cache(tmp, result, lang, fmt, svg, figure_cache, shared_figures)
        names = [n for n in ALL_FIGURES if n not in cached] if plots else []
        files = [f"{n}.{fmt}" for n in ALL_FIGURES] if plots else []
        # Two processes (one project, not a batch worker): a forked child writes the sheets, then
        # both draw figures from one queue, each figure once (PNG and the note's SVG from the same
        # drawn figure); the report waits for the last figure, not for the sheets. Inside a batch
        # worker (or without fork) the same tasks run here one by one.
        from .figures.kit import SharedWork, can_fork

        parallel = figure_cache is None and can_fork() and (len(names) > 1 or (sheets and (names or report == "pdf")))
        draw = [_figure_task(tmp, result, lang, fmt, n, svg) for n in _largest_first(names, svg)]
        later = []
        if sheets:  # the A1 drawing sheets 3 and 4 (issue 10): DXF + PDF from one ezdxf model
            from .sheets import write_sheets

            later.append(lambda: write_sheets(tmp, result, lang, title))
        if parallel and names:
            prepare_figures(svg)
        with SharedWork(draw, later, fork=parallel) as work:
            # what needs no figure, here while the child starts on them (the queue balances the rest)
            write_json(tmp / "results.json", doc)
            write_text(tmp / "cam_profile.csv", profile_csv(result.cam))
            if report == "md":  # names the figure files, which need not exist yet
                write_text(tmp / "report.md", markdown_report(result, lang, files))
            if meanwhile is not None:
                meanwhile()
            work.wait_shared()  # every figure is there
            finish_cached()  # and those another batch worker was drawing
            # --- the typeset note (issue 11) embeds the figures' SVG copies --------------------------
            note_error = None
            if report == "pdf":
                note_error = _write_note(tmp, result, lang, title, fmt, note_template)
        # ----------------------------------------------------------------------------------------
        written = staged_names(tmp)
    if note_error is not None:
        raise note_error
    return doc, written


def _write_note(tmp: Path, result, lang: str, title, fmt: str, template: str | None):
    """The note into the staging folder; returns the TmmError of a failed note (its files removed).

    The figures it embeds are the SVG files beside it, saved from the figures drawn once for the
    PNGs (or the figures themselves under ``--format svg``); a figure not drawn (``--no-plots``)
    is left out.
    """
    from ..errors import TmmError
    from .note import NOTE_FIGURES, write_note

    files = {name: f"{name}.svg" for name in NOTE_FIGURES if (tmp / f"{name}.svg").exists()}
    made = [tmp / f for f in files.values()] if fmt != "svg" else []
    try:
        write_note(tmp, result, lang, title, files, template)
    except TmmError as exc:
        for path in made:
            path.unlink(missing_ok=True)
        return exc
    return None
