"""`tmm note`: recompile an edited explanatory note (note.typ → note.pdf) with tmm's typst."""

from __future__ import annotations

from pathlib import Path

import click

from .options import CONTEXT


@click.command("note", context_settings=CONTEXT)
@click.argument("path", required=False, default=".", metavar="[FOLDER|FILE.typ]")
def note_cmd(path):
    """Recompile the note after editing it: note.typ → note.pdf (default: in the current folder)."""
    from ..render.note import recompile

    pdf = recompile(Path(path))
    click.echo(str(pdf))
