"""`tmm synth TASK.toml`: the synthesis of a lever mechanism from the task of sheet 1 — the stroke H,
the time ratio K, the rocker's swing ψ (issue 33, docs/synthesis.md) — written as a mechanism file
ready for `tmm linkage`, with the derivation, a figure of the construction and the check by
`tmm linkage`'s own analysis.

Only click is imported at module level (``tmm --help`` stays instant); the core and the renderers
are imported inside the command.
"""

from __future__ import annotations

from pathlib import Path

import click

from ..errors import TmmError
from .emit import emit
from .options import CONTEXT, force_option, format_option, json_option, lang_option, no_plots_option, resolve_lang



@click.command("synth", context_settings=CONTEXT)
@click.argument("task_file", type=click.Path(dir_okay=False), metavar="TASK.toml")
@json_option
@force_option
@no_plots_option
@click.option("--out", type=click.Path(file_okay=False), default=None, metavar="DIR",
              help="Output folder (default ./tmm-out/synth): DIR/NAME.toml (NAME: the task file's name), NAME.json and "
                   "the figure of the construction NAME_construction.png.")
@format_option
@lang_option
def synth_cmd(task_file, as_json, force, no_plots, out, fmt, lang):
    """Sheet 1's synthesis: the link lengths of a lever mechanism from its stroke, time ratio and swing.

    TASK.toml gives type = "crank-slider" (stroke with lambda, or time_ratio with offset, or lambda
    with offset), "crank-rocker" (rocker, swing_deg, time_ratio and frame or min_transmission_deg) or
    "slotted-link" (stroke, time_ratio, frame, rod_ratio), and optionally rpm, sense, start_deg and the
    sheet-2 tables (docs/synthesis.md). The mechanism file written is ready for `tmm linkage`; the run
    checks it with tmm linkage's own H, K, ψ and smallest transmission angle. Examples:

    \b
        tmm synth docs/examples/synth_rocker.toml
        tmm synth docs/examples/synth_shaper.toml --out my && tmm linkage my/synth_shaper.toml
    """
    lang = resolve_lang(lang)
    from ..inputs.mechanism import read_mechanism_tables
    from ..linkage.synthesis_file import synthesised_file
    from ..linkage.synthesis_task import parse_task, synthesise

    path = Path(task_file)
    task = parse_task(read_mechanism_tables(path), str(path))
    syn = synthesise(task, str(path))
    from ..i18n import tr
    from ..render.terminal.synth import MECHANISM_NAMES

    result = synthesised_file(syn, task, str(path), tr(lang, MECHANISM_NAMES[task.type]))

    from ..output.folder import ensure_writable_dir
    from ..render.data.synth import synth_document

    folder = Path(out) if out else Path("tmm-out") / "synth"
    name = f"{path.stem}.toml"
    data, figure = f"{path.stem}.json", f"{path.stem}_construction"
    try:
        same = (folder / name).resolve() == path.resolve()
    except OSError:
        same = False
    if same:
        raise TmmError(f"--out {folder} would put the mechanism file over the task {path}; give another --out")
    ensure_writable_dir(folder)
    doc = synth_document(result, lang)
    owns = (name, data) + tuple(f"{figure}.{ext}" for ext in ("png", "svg", "pdf"))

    def figures(which=None):
        from ..render.figures.synth import construction_figure

        return {figure: construction_figure(result, lang)}

    def show(console):
        from ..render.terminal.synth import print_synth

        print_synth(console, result, lang)

    emit(folder, {name: result.text, data: doc}, None if no_plots else figures, fmt, doc if as_json else None, show,
         result.notes, lang, owns=owns, writer="synth", force=force)
