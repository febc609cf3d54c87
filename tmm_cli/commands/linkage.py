"""`tmm linkage`: sheet 1 — the kinematics of a lever mechanism described in a TOML file
(``tmm linkage MECH.toml``, issue 24), or of the slotted-link (Whitworth) quick-return mechanism of
seed 003 given by its options (``--r1 … --b``).

Only click is imported at module level (``tmm --help`` stays instant); the core and the renderers
are imported inside the command.
"""

from __future__ import annotations

from pathlib import Path

import click

from ..errors import TmmError
from .emit import emit
from .options import (
    CONTEXT,
    force_option,
    format_option,
    json_option,
    lang_option,
    no_plots_option,
    resolve_lang,
    sheets_option,
    title_block,
    title_options,
)

FIGURES = ("linkage_mechanism", "linkage_diagrams", "linkage_velocity_plan", "linkage_acceleration_plan",
           "linkage_velocity_plan_2", "linkage_acceleration_plan_2")
FIGURES2 = ("linkage_forces", "linkage_lever", "linkage_dynamics", "linkage_wittenbauer")  # sheet 2
DATA_FILES = ("linkage.json", "linkage_curve.csv")
# exactly the names this command writes: older copies of them are replaced, nothing else is touched
OWNS = DATA_FILES + tuple(f"{name}.{ext}" for name in FIGURES for ext in ("png", "svg", "pdf"))
OWNS_MECHANISM = OWNS + ("linkage_dynamics.csv", "sheet1.dxf", "sheet1.pdf", "sheet2.dxf", "sheet2.pdf") + tuple(
    f"{name}.{ext}" for name in FIGURES2 for ext in ("png", "svg", "pdf"))
WHITWORTH_OPTIONS = ("r1", "h", "c", "r2", "r3", "b", "rpm", "omega", "eps_crank", "at", "input", "variant")


def _metres(name: str, help_text: str):
    return click.option(f"--{name}", name, type=float, default=None, metavar="M", help=help_text)


@click.command("linkage", context_settings=CONTEXT)
@click.argument("mechanism_file", required=False, type=click.Path(dir_okay=False), metavar="[MECH.toml]")
@click.option("--plan", "plan", default=None, metavar="N",
              help="With MECH.toml: the position of the velocity and acceleration plans, e.g. 3 or 7' (default: the "
                   "middle of the working stroke).")
@click.option("--no-forces", "no_forces", is_flag=True,
              help="With MECH.toml: sheet 1 only, even when the file gives masses or a load (sheet 2: the force "
                   "analysis and the flywheel).")
@_metres("r1", "Crank O21A [m].")
@_metres("h", "The slotted link's pivot O41 lies h below the crank centre O21 [m].")
@_metres("c", "... and c to the left of it [m] (default 0; negative: to the right).")
@_metres("r2", "O41B: the point B of the link that drives the rod [m].")
@_metres("r3", "Rod BC [m].")
@_metres("b", "The ram's guide is the line y = b [m] (y up from O21).")
@click.option("--rpm", type=float, default=None, metavar="N", help="Crank speed n21 [rpm] (φ21 grows with time).")
@click.option("--omega", type=float, default=None, metavar="RAD_S", help="Crank speed ω21 [rad/s], instead of --rpm.")
@click.option("--eps-crank", "eps_crank", type=float, default=None, metavar="RAD_S2", help="Crank angular acceleration ε21 [rad/s²] (default 0: uniform).")
@click.option("--positions", "n_positions", type=int, default=None, metavar="N", help="Number of crank positions, from the start of the working stroke (default 12).")
@click.option("--at", "at_deg", type=float, default=None, metavar="DEG", help="Crank angle φ21 [deg], 0…360, of the velocity and acceleration plans (default 45, the article's).")
@click.option("--input", "input_file", type=click.Path(dir_okay=False), default=None, metavar="FILE", help="TOML file with the same keys (r1, h, c, r2, r3, b, rpm, …); options beat it.")
@click.option("--variant", default=None, metavar="N", help="With --input holding [variants.N] tables: the variant to take.")
@json_option
@force_option
@no_plots_option
@click.option("--out", type=click.Path(file_okay=False), default=None, metavar="DIR", help="Output folder (default ./tmm-out); files go to DIR/linkage/.")
@format_option
@sheets_option
@title_options
@lang_option
def linkage_cmd(mechanism_file, plan, no_forces, r1, h, c, r2, r3, b, rpm, omega, eps_crank, n_positions, at_deg, input_file,
                variant, as_json, force, no_plots, out, fmt, sheets, lang, **title_kw):
    """Sheets 1 and 2: a lever mechanism — structure, positions, plans, diagrams; forces and the flywheel.

    MECH.toml describes the mechanism as the structural formula builds it: the frame, the crank and
    class II groups RRR, RRP, RPR (docs/mechanism.md; examples in docs/examples/); with masses and a
    load it also gets sheet 2 — the force analysis, Zhukovsky's lever, the flywheel (docs/dynamics.md).
    Without it, the options describe the slotted-link (Whitworth) mechanism of J. Goban, K. Monková,
    A. Šmeringaiová, “The numerical and computer aided confrontation of kinematic analysis of
    mechanism” (2010): origin at the crank centre O21, x right, y up; φ21 from +y towards +x. Examples:

    \b
        tmm linkage docs/examples/shaper.toml --plan 3
        tmm linkage docs/examples/compressor.toml --sheets
        tmm linkage --r1 0.10 --h 0.04 --c 0 --r2 0.08 --r3 0.30 --b -0.04 --rpm 60
    """
    if mechanism_file is not None:
        given = {"r1": r1, "h": h, "c": c, "r2": r2, "r3": r3, "b": b, "rpm": rpm, "omega": omega,
                 "eps_crank": eps_crank, "at": at_deg, "input": input_file, "variant": variant}
        extra = [f"--{k.replace('_', '-')}" for k in WHITWORTH_OPTIONS if given[k] is not None]
        if extra:
            raise TmmError(f"{mechanism_file} describes the mechanism; drop {', '.join(extra)} (the options of the "
                           "Whitworth mechanism)")
        _mechanism(mechanism_file, plan, n_positions, as_json, no_plots, out, fmt, lang, sheets, title_block(title_kw),
                   no_forces, force)
        return
    if no_forces:
        raise TmmError("--no-forces needs a mechanism file (tmm linkage MECH.toml --no-forces)")
    if plan is not None:
        raise TmmError("--plan needs a mechanism file (tmm linkage MECH.toml --plan N); for the Whitworth options use --at DEG")
    if sheets or any(v is not None for v in title_kw.values()):
        raise TmmError("the A1 sheet 1 needs a mechanism file: tmm linkage MECH.toml --sheets (the Whitworth "
                       "mechanism is docs/examples/whitworth.toml)")
    given = {"r1": r1, "h": h, "c": c, "r2": r2, "r3": r3, "b": b, "rpm": rpm, "omega": omega,
             "eps_crank": eps_crank, "positions": n_positions, "at": at_deg}
    values = {}
    if input_file is not None:
        from ..inputs.files import read_file
        from ..linkage.inputs import MAX_BYTES, parse_input

        raw = read_file(input_file, f"linkage input {input_file}", MAX_BYTES)  # a regular file, size first
        values = parse_input(raw, input_file, variant)
    elif variant is not None:
        raise TmmError("--variant needs --input FILE with [variants.N] tables")
    values.update({k: v for k, v in given.items() if v is not None})
    if "rpm" in given and rpm is not None and omega is None:
        values.pop("omega", None)  # an --rpm on the command line beats an omega in the file
    if omega is not None and rpm is None:
        values.pop("rpm", None)
    missing = [k for k in ("r1", "h", "r2", "r3", "b") if k not in values]
    if missing:
        raise TmmError("give " + ", ".join(f"--{k} M" for k in missing) + " (metres; or put them in --input FILE)")
    if "rpm" in values and "omega" in values:
        raise TmmError("give the crank speed once: --rpm N or --omega RAD_S, not both")
    if "rpm" not in values and "omega" not in values:
        raise TmmError("give the crank speed: --rpm N (or --omega RAD_S)")

    import math

    from ..linkage.analysis import analyse
    from ..linkage.geometry import make_geometry

    lang = resolve_lang(lang)
    from ..limits import LINKAGE_OMEGA, LINKAGE_RPM, check_range

    which = "--rpm" if "rpm" in values else "--omega"
    given_speed = float(values["rpm"] if "rpm" in values else values["omega"])
    if not (math.isfinite(given_speed) and given_speed > 0):
        raise TmmError(f"{which} is {values.get('rpm', values.get('omega'))}; give a positive crank speed (φ21 grows with time)")
    if "rpm" in values:  # checked before any work: --rpm 1e160 gave a table of nulls
        speed = check_range(given_speed, *LINKAGE_RPM, "--rpm [rpm]") * math.pi / 30.0
    else:
        speed = check_range(given_speed, *LINKAGE_OMEGA, "--omega [rad/s]")
    geom = make_geometry(values["r1"], values["h"], values.get("c", 0.0), values["r2"], values["r3"], values["b"])
    result = analyse(geom, speed, float(values.get("eps_crank", 0.0)), int(values.get("positions", 12)),
                     float(values.get("at", 45.0)))

    from ..output.folder import ensure_writable_dir
    from ..render.data.linkage import curve_csv, linkage_document

    folder = (Path(out) if out else Path("tmm-out")) / "linkage"
    ensure_writable_dir(folder.parent)
    doc = linkage_document(result, lang)

    def figures():
        from ..render.figures.linkage import linkage_figures

        return linkage_figures(result, lang)

    def show(console):
        from ..render.terminal.linkage import print_linkage

        print_linkage(console, result, lang)

    emit(folder, {"linkage.json": doc, "linkage_curve.csv": curve_csv(result)}, None if no_plots else figures,
          fmt, doc if as_json else None, show, result.notes, lang, owns=OWNS, writer="linkage", force=force)


def _mechanism(path, plan, n_positions, as_json, no_plots, out, fmt, lang, sheets, title, no_forces=False,
               force=False) -> None:
    """`tmm linkage MECH.toml`: read, analyse, write and show sheet 1 of the mechanism, and sheet 2
    when the file gives masses or a load (unless --no-forces)."""
    import dataclasses

    from ..inputs.mechanism import read_mechanism_tables
    from ..linkage.mechanism_file import parse_mechanism
    from ..linkage.sheet1 import analyse_mechanism

    lang = resolve_lang(lang)
    mech = parse_mechanism(read_mechanism_tables(path), str(path))
    if n_positions is not None:
        if not 2 <= n_positions <= 360:
            raise TmmError(f"--positions is {n_positions}; give a whole number of crank positions from 2 to 360 "
                           "(the book uses 12)")
        mech = dataclasses.replace(mech, positions=n_positions)
    inp = None
    if not no_forces:
        from ..linkage.sheet2_file import parse_sheet2

        inp = parse_sheet2(mech, str(path))  # its errors before the kinematics' work
        if not inp.has_forces:
            inp = None
    sheet = analyse_mechanism(mech, plan, str(path))
    s2 = None
    if inp is not None:
        from ..linkage.sheet2 import analyse_sheet2

        s2 = analyse_sheet2(sheet, inp, str(path))

    from ..output.folder import ensure_writable_dir
    from ..render.data.mechanism import curve_csv, mechanism_document

    folder = (Path(out) if out else Path("tmm-out")) / "linkage"
    ensure_writable_dir(folder.parent)
    doc = mechanism_document(sheet, lang)
    files = {"linkage.json": doc, "linkage_curve.csv": curve_csv(sheet)}
    names = tuple(n for n in FIGURES if not n.endswith("_2") or len(sheet.plans) > 1)
    from ..i18n.lang import name_script_notes

    notes = tuple(sheet.cycle.notes) + name_script_notes(mech.name, lang)
    if s2 is not None:
        from ..i18n.lang import note_text
        from ..render.data.dynamics import add_sheet2, dynamics_csv

        add_sheet2(doc, s2)
        doc["notes"] += [note_text(n, lang) for n in s2.notes]
        files["linkage_dynamics.csv"] = dynamics_csv(s2)
        names += tuple(n for n in FIGURES2 if n != "linkage_wittenbauer" or s2.flywheel is not None)
        notes += s2.notes

    def figures(which=None):
        from ..render.figures.mechanism import mechanism_figures

        out_figs = mechanism_figures(sheet, lang, which)
        if s2 is not None:
            from ..render.figures.dynamics import dynamics_figures

            out_figs.update(dynamics_figures(s2, lang, which))
        return out_figs

    def show(console):
        from ..render.terminal.mechanism import print_mechanism

        print_mechanism(console, sheet, lang)
        if s2 is not None:
            from ..render.terminal.dynamics import print_dynamics

            print_dynamics(console, s2, lang)

    def a1(tmp):
        from ..render.sheets import save_sheet
        from ..render.sheets.linkage_sheet import sheet1

        save_sheet(sheet1(sheet, lang, title), tmp, "sheet1")
        if s2 is not None:
            from ..render.sheets.dynamics_sheet import sheet2

            save_sheet(sheet2(s2, lang, title), tmp, "sheet2")

    emit(folder, files, None if no_plots else figures, fmt, doc if as_json else None, show, notes, lang,
         owns=OWNS_MECHANISM, extra=a1 if sheets else None, figure_names=names, writer="linkage", force=force)
