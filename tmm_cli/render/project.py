"""The project folder of one variant: results.json, cam_profile.csv, the figures, the note (or
report.md) and the drawing sheets, staged and moved in at once.

Every document reads the same result objects: the JSON comes from ``cam_to_json`` and
``gears_to_json``; report.md and note.pdf are the explanatory note (render/note), with the very
figures saved beside them.
"""

from __future__ import annotations

from pathlib import Path

from .data.project import project_document
from .figures.pipeline import (
    ALL_FIGURES,
    _figure_task,
    _from_cache,
    _largest_first,
    prepare_figures,
)


def markdown_report(result, lang: str, figure_files: list[str]) -> str:
    """report.md: the explanatory note as Markdown (headings, tables, figures with captions)."""
    from .note import markdown_note

    return markdown_note(result, lang, figure_files)


REPORTS = ("md", "pdf", "docx")


def report_formats(report) -> frozenset:
    """"pdf", "md", "docx", "pdf,docx" (or a set of them, or None) as a set of formats.

    >>> sorted(report_formats("pdf,docx")), sorted(report_formats(None))
    (['docx', 'pdf'], [])
    """
    if report is None:
        return frozenset()
    if isinstance(report, str):
        report = [p.strip() for p in report.split(",") if p.strip()]
    out = frozenset(report)
    bad = sorted(out - set(REPORTS))
    if bad:
        from ..errors import TmmError

        raise TmmError(f"report format '{bad[0]}' is unknown; use md, pdf, docx or a list of them, e.g. pdf,docx")
    return out


def write_project_folder(result, folder: Path, lang: str, *, fmt: str = "png", plots: bool = True,
                         report: str | None = "md", figure_cache: dict | None = None, title=None,
                         note_template: str | None = None, sheets: bool = False, meanwhile=None,
                         shared_figures=None, writer: str = "project", force: bool = False, kept: list | None = None,
                         root: Path | None = None):
    """Write results.json, cam_profile.csv, the figures and the report into `folder`, atomically.

    `report`: "md" writes report.md, "pdf" the typeset note (note.pdf, its source note.typ and
    note-style.typ, and the note's own figures note_*.svg it embeds), "docx" note.docx; a list
    ("pdf,docx") writes each, None none. The note is written last; if it fails (a broken
    `note_template`, the text of a style file), every other file still comes out, the note's files
    do not, and the TmmError is raised after the folder is in place (exit 2).

    `title` (a :class:`tmm_cli.inputs.titleblock.TitleFields`, default empty) fills the drawing sheets'
    title blocks and the note's title page.

    `figure_cache` (a dict the caller keeps between calls, as `tmm batch` does) lets variants
    that share a reducer reuse its two drawings instead of drawing them again; `shared_figures`
    (render/figures/shared.py) shares them between the batch's worker processes too.
    `sheets` adds the A1 drawings sheet3.dxf/.pdf and sheet4.dxf/.pdf (render/sheets).
    `meanwhile` (no arguments) runs in this process while a forked child starts on the figures,
    before this process takes its share (`tmm project` renders its terminal report there).
    `writer` names the command in the folder's manifest ("project", or "batch" for a batch's row,
    whose folder must lie inside `root` through real folders only); a file the user changed since
    is kept and the new version written beside it, or replaced after a backup with `force`
    (output/folder.py): each such file is appended to `kept`.
    Returns (the JSON document, the sorted list of file names written).
    """
    from ..output.folder import final_names, staged_dir, staged_names, write_text
    from .data.cam import profile_csv
    from .data.jsontext import write_json
    from .note import note_figures

    reports = report_formats(report)
    typeset = reports & {"pdf", "docx"}
    doc = project_document(result, lang)
    # the project owns its folder: nothing of an earlier run (other options) stays beside it
    found: list = []
    spare: list = []  # a note that fails keeps the folder's last good one (note.pdf, note.typ, its style, figures)
    with staged_dir(folder, owns=("*",), writer=writer, force=force, kept=found, root=root, spare=spare) as tmp:
        svg: set = set()
        cached, finish_cached = set(), lambda: None
        if plots and figure_cache is not None:
            cached, finish_cached = _from_cache(tmp, result, lang, fmt, svg, figure_cache, shared_figures)
        names = [n for n in ALL_FIGURES if n not in cached] if plots else []
        files = [f"{n}.{fmt}" for n in ALL_FIGURES] if plots else []
        # the note's own figures, drawn for the page (render/figures/note.py): SVG for note.typ,
        # and a 300 dpi PNG for note.docx
        note_figs = list(note_figures(result)) if plots and typeset else []
        # Two processes (one project, not a batch worker): a forked child writes the sheets, then
        # both draw figures from one queue, each figure once; the report waits for the last
        # figure, not for the sheets. Inside a batch worker (or without fork) the same tasks run
        # here one by one.
        from .figures.kit import SharedWork, can_fork

        parallel = figure_cache is None and can_fork() and (len(names) + len(note_figs) > 1 or (sheets and (names or typeset)))
        # the note's figures first: the note is typeset while the screen figures are still drawn
        draw = [_note_figure_task(tmp, result, lang, n, "docx" in reports) for n in note_figs]
        draw += [_figure_task(tmp, result, lang, fmt, n, svg) for n in _largest_first(names, svg)]
        later = []
        if sheets:  # the A1 drawing sheets 3 and 4 (issue 10): DXF + PDF from one ezdxf model
            from .sheets import write_sheets

            later.append(lambda: write_sheets(tmp, result, lang, title))
            if result.linkage is not None:  # and sheets 1–2 of the mechanism file (tmm project --mechanism)
                later.append(lambda: _write_linkage_sheets(tmp, result.linkage, lang, title, result.variant.number))
        if parallel and (names or note_figs):
            prepare_figures(svg, note=bool(note_figs))
        with SharedWork(draw, later, fork=parallel) as work:
            # what needs no figure, here while the child starts on them (the queue balances the rest)
            write_json(tmp / "results.json", doc)
            write_text(tmp / "cam_profile.csv", profile_csv(result.cam))
            if result.linkage is not None:
                _write_linkage_data(tmp, result.linkage, lang)
            if "md" in reports:  # names the figure files, which need not exist yet
                write_text(tmp / "report.md", markdown_report(result, lang, files))
            if meanwhile is not None:
                meanwhile()
            # --- the note (issues 11, 20): built now, typeset once its own figures are drawn --------
            note_error, note = None, None
            if typeset:
                note, note_error = _prepare_note(tmp, result, lang, title, note_template, reports, note_figs)
                work.run_until(range(len(note_figs)))
                if note is not None and "pdf" in reports:
                    note_error = _finish_note(tmp, note, title, reports, pdf=True, docx=False)
            work.wait_shared()  # every figure is there
            finish_cached()  # and those another batch worker was drawing
            if note is not None and note_error is None and "docx" in reports:
                note_error = _finish_note(tmp, note, title, reports, pdf=False, docx=True)
            if typeset:
                _tidy_note_figures(tmp, reports, note_error)
            if note_error is not None:
                spare += list(NOTE_KEPT)
        # ----------------------------------------------------------------------------------------
        written = staged_names(tmp)
    if kept is not None:
        kept.extend(found)
    if note_error is not None:
        raise note_error
    return doc, final_names(written, found)


def _write_linkage_data(tmp: Path, s2, lang: str) -> None:
    """linkage.json (sheets 1–2, as `tmm linkage MECH.toml` writes it) and linkage_dynamics.csv."""
    from ..i18n.lang import note_text
    from ..output.folder import write_text
    from .data.dynamics import add_sheet2, dynamics_csv
    from .data.jsontext import write_json
    from .data.mechanism import mechanism_document

    doc = add_sheet2(mechanism_document(s2.sheet1, lang), s2)
    doc["notes"] += [note_text(n, lang) for n in s2.notes]
    write_json(tmp / "linkage.json", doc)
    write_text(tmp / "linkage_dynamics.csv", dynamics_csv(s2))


def _write_linkage_sheets(tmp: Path, s2, lang: str, title, variant: int) -> list[str]:
    from ..inputs.titleblock import TitleFields
    from .sheets import save_sheet
    from .sheets.dynamics_sheet import sheet2
    from .sheets.linkage_sheet import sheet1

    title = title or TitleFields()
    return (save_sheet(sheet1(s2.sheet1, lang, title, variant), tmp, "sheet1")
            + save_sheet(sheet2(s2, lang, title, variant), tmp, "sheet2"))


def _note_files(result, note_figs) -> dict:
    from .figures.note_scales import figure_size_cm
    from .note import note_figure_file

    files = {}
    for name in note_figs:
        w, h = figure_size_cm(name, result.gears, result.linkage)
        files[name] = (note_figure_file(name, "svg"), note_figure_file(name, "png"), w, h)
    return files


def _prepare_note(tmp: Path, result, lang: str, title, template: str | None, reports, note_figs):
    """The note's document (and note.typ) before its figures are drawn: (document, None) or
    (None, the TmmError of a failed note)."""
    from ..errors import TmmError
    from .note import prepare_note

    try:
        return prepare_note(tmp, result, lang, title, _note_files(result, note_figs), template,
                            pdf="pdf" in reports, docx="docx" in reports), None
    except TmmError as exc:
        return None, exc


def _finish_note(tmp: Path, doc, title, reports, pdf: bool, docx: bool):
    """note.pdf (typst) or note.docx; the TmmError of a failed note (its files removed), else None."""
    from ..errors import TmmError
    from .note import finish_note

    try:
        finish_note(tmp, doc, title, pdf=pdf, docx=docx)
    except TmmError as exc:
        return exc
    return None


# the files of a note: kept as they were when a new note fails
NOTE_KEPT = ("note.typ", "note-style.typ", "note.pdf", "note.docx", "note_*.svg", "note_*.png")


def _tidy_note_figures(tmp: Path, reports, note_error) -> None:
    """The PNGs serve note.docx only, the SVGs note.typ only; a failed note takes its figures along."""
    from .note import LINKAGE_NOTE_FIGURES, NOTE_FIGURES, note_figure_file

    for name in LINKAGE_NOTE_FIGURES + NOTE_FIGURES:
        (tmp / note_figure_file(name, "png")).unlink(missing_ok=True)
        if note_error is not None or "pdf" not in reports:
            (tmp / note_figure_file(name, "svg")).unlink(missing_ok=True)


def _note_figure_task(tmp: Path, result, lang: str, name: str, raster: bool):
    def task():
        from .figures.note import save_note_figure

        save_note_figure(tmp, result, lang, name, raster=raster)

    return task
