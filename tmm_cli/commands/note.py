"""`tmm note`: recompile an edited explanatory note (note.typ → note.pdf) with tmm's typst, or write
the note for Word (note.docx) again from the project's results."""

from __future__ import annotations

from pathlib import Path

import click

from .options import CONTEXT, lang_option, resolve_lang, title_block, title_options


@click.command("note", context_settings=CONTEXT)
@click.argument("path", required=False, default=".", metavar="[FOLDER|FILE.typ]")
@click.option("--to", "to", type=click.Choice(["pdf", "docx"]), default="pdf", show_default=True,
              help="Write the note as: pdf (compile note.typ) or docx (Word, from the same text as tmm project writes it).")
@title_options
@lang_option
def note_cmd(path, to, lang, **title_kw):
    """Recompile the note after editing it: note.typ → note.pdf (default: in the current folder)."""
    if to == "pdf":
        from ..render.note import recompile

        pdf = recompile(Path(path))
        click.echo(str(pdf))
        return
    from ..render.note import rewrite_docx

    out = rewrite_docx(Path(path), resolve_lang(lang), title_block(title_kw))
    click.echo(str(out))
