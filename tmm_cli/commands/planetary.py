"""`tmm planetary`: planetary synthesis with different meshing angles, shifted gears (seed 000: Kavetsky, 2010)."""

from __future__ import annotations

import click

from .emit import emit
from .options import (
    CONTEXT,
    force_option,
    format_option,
    json_option,
    lang_option,
    no_plots_option,
    resolve_lang,
)


@click.command("planetary", context_settings=CONTEXT)
@click.option("--ratio", "ratio", required=True, metavar="A/B",
              help="Ratio i = i_1H^(4) of the AA̅ mechanism as a fraction, 0 < i < 1, e.g. 1/10.")
@click.option("--c", "c_text", required=True, metavar="P/Q",
              help="C = cos α_w12/cos α_w34 as a fraction, 1 < C < 1/(1 − i), e.g. 26/25.")
@click.option("--planets", type=int, default=3, show_default=True, metavar="K", help="Number of planets k.")
@click.option("--module", "module_mm", type=float, default=5.0, show_default=True, metavar="MM", help="Module m [mm].")
@click.option("--x1", type=float, default=0.0, show_default=True, metavar="X", help="Shift of the sun 1.")
@click.option("--x2", type=float, default=0.0, show_default=True, metavar="X", help="Shift of the planet (x3 = x2).")
@click.option("--z-min", "z_min", type=int, default=18, show_default=True, metavar="Z", help="Fewest teeth of any wheel.")
@click.option("--z-max", "z_max", type=int, default=180, show_default=True, metavar="Z", help="Most teeth of any wheel.")
@click.option("--family", "multiple", type=int, default=None, metavar="K",
              help="Take the K-th multiple of the smallest tooth set (default: the smallest within the limits).")
@click.option("--out", type=click.Path(file_okay=False), default=None, metavar="DIR",
              help="Output folder (default ./tmm-out); files go to DIR/planetary/.")
@format_option
@no_plots_option
@json_option
@force_option
@lang_option
def planetary_cmd(ratio, c_text, planets, module_mm, x1, x2, z_min, z_max, multiple, out, fmt, no_plots, as_json, force, lang):
    """Planetary mechanism AA̅ with shifted gears and different meshing angles (S. N. Kavetsky, 2010).

    Tooth numbers from the ratio i and C = cos α_w12/cos α_w34, the common centre distance,
    the working angles and shifts of both stages, the blocking-contour checks, the velocity
    picture and a figure of the mechanism.

    Source: S. N. Kavetsky, “The procedure of synthesis of the planetary mechanism AA̅ with regard to the
    meshing angles of the first and second stages”, Vestnik NTU «KhPI», thematic issue “Machine science
    and CAD”, 2010. Example (the article's):

    \b
    tmm planetary --ratio 1/10 --c 26/25 --planets 3 --module 5 --x1 -0.4 --x2 0.4
    """
    from pathlib import Path

    from ..gears.aa_bar import feasible_c_examples, parse_fraction, synthesize
    from ..output.folder import ensure_writable_dir
    from ..render.data.planetary import planetary_to_json

    lang = resolve_lang(lang)
    i = parse_fraction(ratio, "the ratio i", "--ratio 1/10")
    c = parse_fraction(c_text, "C", "--c 26/25")
    design = synthesize(i, c, planets, module_mm, x1, x2, z_min=z_min, z_max=z_max, multiple=multiple)
    examples = feasible_c_examples(i, design.planets, z_min, z_max) if i < 1 else ()
    doc = planetary_to_json(design, lang, examples)
    folder = (Path(out) if out else Path("tmm-out")) / "planetary"
    ensure_writable_dir(folder.parent)

    def figures():
        from ..render.figures.planetary import planetary_figures

        return planetary_figures(design, lang)

    def show(console):
        from ..render.terminal.planetary import print_planetary

        print_planetary(console, design, lang, examples)

    emit(folder, {"planetary.json": doc}, None if no_plots else figures, fmt, doc if as_json else None, show,
          design.notes, lang, owns=("planetary*.*",), writer="planetary", force=force)
