"""`tmm cam`: sheet 3, the cam mechanism (book §1)."""

from __future__ import annotations

import click

from .emit import emit, figure_names
from .options import (
    CONTEXT,
    cam_choice,
    cam_choice_options,
    force_option,
    format_option,
    json_option,
    lang_option,
    no_plots_option,
    out_option,
    resolve_lang,
    sheets_option,
    step_option,
    title_block,
    title_options,
    variant_folder,
    variant_option,
    variant_row,
    variants_file_option,
)


@click.command("cam", context_settings=CONTEXT)
@variant_option
@variants_file_option
@out_option
@format_option
@no_plots_option
@json_option
@force_option
@step_option
@cam_choice_options
@sheets_option
@title_options
@lang_option
def cam_cmd(variant, variants_file, out, fmt, no_plots, as_json, force, step_deg, sheets, lang, **title_kw):
    """Sheet 3: follower diagrams, main dimensions, cam profile, pressure angle."""
    choice = cam_choice(title_kw)
    title = title_block(title_kw)
    from ..cam.design import design_cam
    from ..output.folder import ensure_writable_dir
    from ..render.data.cam import profile_csv
    from ..render.data.project import cam_document

    lang = resolve_lang(lang)
    v = variant_row(variant, variants_file)
    folder = variant_folder(out, v.number)
    ensure_writable_dir(folder.parent)
    result = design_cam(v, step_deg=step_deg, choice=choice)
    doc = cam_document(v, result, lang)

    def figures(names=None):
        from ..render.figures.cam import cam_figures

        return cam_figures(result, lang, names=names)

    def show(console):
        from ..render.terminal.cam import print_cam

        print_cam(console, result, lang)

    def sheet(tmp):
        from ..render.sheets import save_sheet, sheet3

        save_sheet(sheet3(result, lang, title), tmp, "sheet3")

    emit(folder, {"cam.json": doc, "cam_profile.csv": profile_csv(result)}, None if no_plots else figures,
          fmt, doc if as_json else None, show, result.notes, lang, owns=("cam_*.*", "sheet3.*"),
          extra=sheet if sheets else None, figure_names=figure_names("cam"), writer="cam", force=force)
