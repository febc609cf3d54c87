"""`tmm project`: the whole course project for one variant — sheets 3 and 4, the note, the drawing sheets."""

from __future__ import annotations

import click

from ..errors import TmmError
from .emit import console_for, print_files, print_kept
from .options import (
    CONTEXT,
    cam_choice,
    cam_choice_options,
    crank_option,
    force_option,
    format_option,
    gear_design_options,
    json_option,
    lang_option,
    mechanism_option,
    no_plots_option,
    out_option,
    ratio_value,
    resolve_lang,
    shift_value,
    step_option,
    title_block,
    title_options,
    torque_option,
    variant_folder,
    variant_option,
    variant_row,
    variants_file_option,
)


@click.command("project", context_settings=CONTEXT)
@variant_option
@variants_file_option
@crank_option
@torque_option
@mechanism_option
@gear_design_options
@out_option
@format_option
@no_plots_option
@json_option
@force_option
@click.option("--report", "report", default="pdf", show_default=True, metavar="md|pdf|docx[,…]",
              help="pdf: the explanatory note (note.pdf and its source note.typ); docx: the note for Word (note.docx); "
                   "md: report.md; several with commas, e.g. pdf,docx.")
@click.option("--note-template", "note_template", type=click.Path(dir_okay=False), default=None, metavar="FILE",
              help="A typst style file replacing the note's (see docs/note.md).")
@step_option
@click.option("--no-sheets", is_flag=True, help="Do not write the A1 drawing sheets sheet3/sheet4 (.dxf, .pdf).")
@cam_choice_options
@title_options
@lang_option
def project_cmd(variant, variants_file, crank_rpm, torque_nm, mechanism_file, ratio, tolerance_pct, planets, stiffness, shift, a_w_mm, select, out, fmt, no_plots, as_json, force, report, note_template, step_deg, no_sheets, lang, **title_kw):
    """The whole project for one variant: sheet 4 then sheet 3, figures, results.json, the note and the drawing sheets."""
    from ..render.project import report_formats

    report = report_formats(report)
    choice = cam_choice(title_kw)
    title = title_block(title_kw)
    template = None
    if note_template is not None:
        from ..render.note import read_template

        template = read_template(note_template)
    from ..output.folder import ensure_writable_dir
    from ..project import run_project
    from ..render.project import write_project_folder

    lang = resolve_lang(lang)
    v = variant_row(variant, variants_file)
    linkage, linkage_name = None, ""
    if mechanism_file is not None:
        given = [name for name, value in (("--crank-rpm", crank_rpm), ("--torque", torque_nm)) if value is not None]
        if given:
            raise TmmError(f"--mechanism gives sheet 4 its moment and crank speed; drop {', '.join(given)}")
        from pathlib import Path

        from ..inputs.mechanism import read_mechanism_tables
        from ..project import analyse_linkage

        linkage = analyse_linkage(read_mechanism_tables(mechanism_file), str(mechanism_file))
        linkage_name = Path(mechanism_file).name
    folder = variant_folder(out, v.number)
    ensure_writable_dir(folder.parent)
    result = run_project(
        v, crank_rpm=crank_rpm, torque_nm=torque_nm, step_deg=step_deg,
        ratio=ratio_value(ratio), tolerance_pct=tolerance_pct, planets=planets, stiffness=stiffness,
        shift=shift_value(shift), a_w_mm=a_w_mm, select=select, cam_choice=choice, linkage=linkage,
        linkage_name=linkage_name,
    )
    console = None if as_json else console_for(lang)
    shown: list[str] = []

    def render_report() -> None:
        """The terminal report, rendered into a string while the figures are drawn (≈ 0.3 s),
        printed once the folder is in place (nothing is printed for a run that fails)."""
        from ..render.terminal.report import print_project

        if console.legacy_windows:  # the old Windows console takes no ANSI text: printed afterwards
            return
        with console.capture() as capture:
            print_project(console, result, lang)
        shown.append(capture.get())

    kept: list = []
    doc, written = write_project_folder(result, folder, lang, fmt=fmt, plots=not no_plots, report=report, title=title,
                                        note_template=template, sheets=not no_sheets,
                                        meanwhile=None if as_json else render_report, force=force, kept=kept)
    if as_json:  # the very text of results.json (encoding 180 kB of JSON twice costs ~0.1 s)
        from ..output.folder import final_names

        click.echo((folder / final_names(["results.json"], kept)[0]).read_text(encoding="utf-8"), nl=False)
        print_kept(None, kept, lang)
        return
    if shown:
        console.file.write(shown[0])
        console.file.flush()
    else:
        from ..render.terminal.report import print_project

        print_project(console, result, lang)
    print_files(console, folder, written, lang)
    print_kept(console, kept, lang)
