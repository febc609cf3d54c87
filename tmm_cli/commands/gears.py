"""`tmm gears`: sheet 4, the gear drive (book §2)."""

from __future__ import annotations

import click

from .emit import emit, figure_names
from .options import (
    CONTEXT,
    crank_option,
    force_option,
    format_option,
    gear_design_options,
    json_option,
    lang_option,
    no_plots_option,
    out_option,
    ratio_value,
    resolve_lang,
    sheets_option,
    shift_value,
    title_block,
    title_options,
    torque_option,
    variant_folder,
    variant_option,
    variant_row,
    variants_file_option,
)


@click.command("gears", context_settings=CONTEXT)
@variant_option
@variants_file_option
@crank_option
@torque_option
@gear_design_options
@out_option
@format_option
@no_plots_option
@json_option
@force_option
@sheets_option
@title_options
@lang_option
def gears_cmd(variant, variants_file, crank_rpm, torque_nm, ratio, tolerance_pct, planets, stiffness, shift, a_w_mm, select, out, fmt, no_plots, as_json, force, sheets, lang, **title_kw):
    """Sheet 4: motor, ratio split, planetary reducer synthesis, spur pair to the cam."""
    title = title_block(title_kw)
    from ..gears.design import design_gears
    from ..output.folder import ensure_writable_dir
    from ..render.data.project import gears_document

    lang = resolve_lang(lang)
    v = variant_row(variant, variants_file)
    folder = variant_folder(out, v.number)
    ensure_writable_dir(folder.parent)
    result = design_gears(
        v.n_cam_rpm, crank_rpm=crank_rpm, torque_nm=torque_nm, ratio=ratio_value(ratio),
        tolerance_pct=tolerance_pct, planets=planets, stiffness=stiffness, shift=shift_value(shift), a_w_mm=a_w_mm, select=select,
    )
    doc = gears_document(v, result, lang)

    def figures(names=None):
        from ..render.figures.gears import gears_figures

        return gears_figures(result, lang, names=names)

    def show(console):
        from ..render.terminal.gears import print_gears

        print_gears(console, result, lang)

    def sheet(tmp):
        from ..render.sheets import save_sheet, sheet4

        save_sheet(sheet4(result, v.number, lang, title), tmp, "sheet4")

    emit(folder, {"gears.json": doc}, None if no_plots else figures, fmt, doc if as_json else None, show,
          result.notes, lang, owns=("gears_*.*", "sheet4.*"), extra=sheet if sheets else None,
          figure_names=figure_names("gears"), writer="gears", force=force)
