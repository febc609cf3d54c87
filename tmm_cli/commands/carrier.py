"""`tmm carrier CARD --radius MM`: the planet bores of a carrier from the plant's measurement card,
by least squares over every measurement (seed 004; docs/accuracy.md).

Only click is imported at module level (``tmm --help`` stays instant); the core and the renderers
are imported inside the command.
"""

from __future__ import annotations

from pathlib import Path

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

FIGURES = ("carrier",)
DATA_FILES = ("carrier.json",)
# exactly the names this command writes: older copies of them are replaced, nothing else is touched
OWNS = DATA_FILES + tuple(f"{name}.{ext}" for name in FIGURES for ext in ("png", "svg", "pdf"))


@click.command("carrier", context_settings=CONTEXT)
@click.argument("card", type=click.Path(dir_okay=False), metavar="CARD")
@click.option("--radius", "radius_mm", type=float, required=True, metavar="MM",
              help="Nominal radius of the bore circle from the drawing [mm].")
@click.option("--tol-radial", "tol_radial_um", type=float, default=None, metavar="UM",
              help="Tolerance on the radial error of a bore [µm]: a verdict per bore.")
@click.option("--tol-tangential", "tol_tangential_um", type=float, default=None, metavar="UM",
              help="Tolerance on the tangential error of a bore [µm]: a verdict per bore.")
@click.option("--exclude", multiple=True, metavar="NAME",
              help="Leave a measurement out of the fit, e.g. --exclude h3 (repeatable).")
@json_option
@force_option
@no_plots_option
@click.option("--out", type=click.Path(file_okay=False), default=None, metavar="DIR",
              help="Output folder (default ./tmm-out); files go to DIR/carrier/.")
@format_option
@lang_option
def carrier_cmd(card, radius_mm, tol_radial_um, tol_tangential_um, exclude, as_json, force, no_plots, out, fmt, lang):
    """Planet carrier: bore positions from the plant's measurement card (Leontiev, Nasonov, Bedny, 2012).

    CARD is a CSV file, one row per bore: bore,R,R_prime,h,h_prime,s[,e] in millimetres (docs/accuracy.md).
    All measurements are fitted at once by nonlinear least squares; the plants' chord-only estimate is
    shown beside the result, and a misread gauge is named. Example:

    \b
        tmm carrier docs/examples/carrier-5.csv --radius 125
    """
    from ..accuracy.card import parse_card
    from ..accuracy.carrier import fit_carrier
    from ..inputs.tables import read_text
    from ..limits import CARD_BYTES

    lang = resolve_lang(lang)
    text = read_text(card, str(card), CARD_BYTES).text
    parsed = parse_card(text, str(card))
    fit = fit_carrier(parsed, radius_mm * 1e-3, exclude=tuple(exclude),
                      tol_radial=None if tol_radial_um is None else tol_radial_um * 1e-6,
                      tol_tangential=None if tol_tangential_um is None else tol_tangential_um * 1e-6)

    from ..output.folder import ensure_writable_dir
    from ..render.data.carrier import carrier_document

    folder = (Path(out) if out else Path("tmm-out")) / "carrier"
    ensure_writable_dir(folder.parent)
    doc = carrier_document(fit, Path(card).name, lang)

    def figures(names=None):
        from ..render.figures.carrier import carrier_figures

        return carrier_figures(fit, lang)

    def show(console):
        from ..render.terminal.carrier import print_carrier

        print_carrier(console, fit, lang)

    emit(folder, {"carrier.json": doc}, None if no_plots else figures, fmt, doc if as_json else None, show,
         fit.notes, lang, owns=OWNS, writer="carrier", force=force)
