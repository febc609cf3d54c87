"""`tmm variants`: Table 1.2, or one row explained."""

from __future__ import annotations

import click

from .emit import console_for
from .options import (
    CONTEXT,
    lang_option,
    resolve_lang,
    variant_row,
    variants_file_option,
)


@click.group("variants", invoke_without_command=True, context_settings=CONTEXT)
@variants_file_option
@lang_option
@click.pass_context
def variants_cmd(ctx, variants_file, lang):
    """List Table 1.2 (the 68 variants of sheet 3); `tmm variants show N` explains one row."""
    ctx.obj = {"variants_file": variants_file, "lang": lang}
    if ctx.invoked_subcommand is None:
        from ..render.terminal.variants import print_variant_table
        from ..variants import load_table

        lang = resolve_lang(lang)
        print_variant_table(console_for(lang), load_table(variants_file), lang)


@variants_cmd.command("show", context_settings=CONTEXT)
@click.argument("number")
@variants_file_option
@lang_option
@click.pass_context
def variants_show(ctx, number, variants_file, lang):
    """Show one variant with the meaning of each field."""
    from ..render.terminal.variants import print_variant_detail

    variants_file = variants_file or ctx.obj.get("variants_file")
    lang = resolve_lang(lang or ctx.obj.get("lang"))
    print_variant_detail(console_for(lang), variant_row(number, variants_file), lang)
