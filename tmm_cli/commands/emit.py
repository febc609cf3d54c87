"""The common last step of a command: write the files atomically, then print the JSON alone or the
tables, the notes and the list of files written."""

from __future__ import annotations

from pathlib import Path

import click


def console_for(lang: str):
    """A rich console; 120 columns when the output is a file or a pipe (rich would assume 80)."""
    from rich.console import Console

    console = Console(highlight=False)
    if not console.is_terminal:
        console = Console(highlight=False, width=120)
    return console


def print_json(obj) -> None:
    from ..render.data.jsontext import json_text

    click.echo(json_text(obj))  # strict JSON: never a bare NaN or Infinity


def print_notes(console, notes, lang: str) -> None:
    from ..render.terminal.report import print_notes

    print_notes(console, notes, lang)


def print_files(console, folder: Path, names: list[str], lang: str) -> None:
    from ..render.terminal import escape

    from ..i18n import tr

    if names:
        console.print(tr(lang, "Files written to ") + f"[bold]{escape(str(folder))}[/]: " + escape(", ".join(names)))


def kept_lines(kept, lang: str) -> list[str]:
    """One sentence per file of the user's met where a run writes (output/folder.Kept)."""
    from ..i18n import tr

    lines = []
    for k in kept:
        path = str(Path(k.folder) / k.name)
        if k.beside:
            lines.append(tr(lang, "{path} was changed since tmm wrote it: kept as it is; the new version is {new} "
                                  "(--force replaces the file, keeping a copy as .bak)").format(path=path, new=k.beside))
        else:
            lines.append(tr(lang, "{path} was changed since tmm wrote it: kept as {bak}, then replaced (--force)"
                            ).format(path=path, bak=k.backup))
    return lines


def print_kept(console, kept, lang: str) -> None:
    """Say which of the user's files were kept (on the console, or on stderr under --json)."""
    if console is None:
        for line in kept_lines(kept, lang):
            click.echo("tmm: " + line, err=True)
        return
    from ..render.terminal import escape

    for line in kept_lines(kept, lang):
        console.print("[yellow]⚠[/] " + escape(line))


def emit(folder: Path, files: dict, figures, fmt: str, json_doc, show, notes, lang: str, owns=(), extra=None,
          figure_names=(), writer: str | None = None, force: bool = False) -> None:
    """Write `files` (name -> JSON object or text) and the figures atomically, then either print
    `json_doc` alone or the tables (`show(console)`), the notes and the list of files.

    `figures(names=None)` draws the figures (a dict name -> Figure); given their `figure_names`,
    they are drawn and saved one by one over two processes where a fork is possible, as
    `tmm project` does. `writer` is the command's name in the folder's manifest; a file the user
    changed is kept (or replaced after a backup with `force`) and the run says so."""
    from ..output.folder import final_names, staged_dir, staged_names, write_text
    from ..render.data.jsontext import write_json

    kept: list = []
    with staged_dir(folder, owns, writer=writer, force=force, kept=kept) as tmp:
        for name, content in files.items():
            (write_text if isinstance(content, str) else write_json)(tmp / name, content)
        if figures is not None:
            save_figures_forked(tmp, figures, figure_names, fmt)
        if extra is not None:  # e.g. the A1 drawing sheet (--sheets)
            extra(tmp)
        written = staged_names(tmp)
    written = final_names(written, kept)
    if json_doc is not None:
        print_json(json_doc)
        print_kept(None, kept, lang)
        return
    console = console_for(lang)
    show(console)
    print_notes(console, notes, lang)
    print_files(console, folder, written, lang)
    print_kept(console, kept, lang)


def figure_names(sheet: str) -> tuple:
    from ..render.figures.pipeline import CAM_FIGURES, GEAR_FIGURES

    return CAM_FIGURES if sheet == "cam" else GEAR_FIGURES


def save_figures_forked(tmp: Path, figures, names, fmt: str) -> None:
    from ..render.figures.kit import SharedWork, can_fork
    from ..render.figures.save import save_figures

    if len(names) < 2 or not can_fork():
        save_figures(tmp, figures(), fmt)
        return
    from ..render.figures.pipeline import _largest_first, prepare_figures

    prepare_figures(set())
    tasks = [lambda n=n: save_figures(tmp, figures([n]), fmt) for n in _largest_first(names, set())]
    with SharedWork(tasks) as work:
        work.wait_shared()
