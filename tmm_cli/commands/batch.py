"""`tmm batch`: teachers run many variants or a class roster in parallel."""

from __future__ import annotations

from pathlib import Path

import click

from ..errors import TmmError
from .emit import console_for, print_kept
from .options import (
    CONTEXT,
    crank_option,
    force_option,
    format_option,
    lang_option,
    no_plots_option,
    out_option,
    resolve_lang,
    sheets_option,
    title_block,
    torque_option,
    variants_file_option,
)


@click.command("batch", context_settings=CONTEXT)
@click.option("--variants", "variants_spec", default=None, metavar="LIST", help="Variants, e.g. 1-68 or 3,17,40.")
@click.option("--roster", type=click.Path(dir_okay=False), default=None, metavar="FILE", help="CSV with columns student,variant[,crank_rpm][,torque][,mechanism] (a mechanism file beside the roster).")
@variants_file_option
@crank_option
@torque_option
@out_option
@format_option
@click.option("--jobs", "-j", type=int, default=None, metavar="N", help="Parallel worker processes (default: number of cores).")
@no_plots_option
@click.option("--report", "report", default="md", show_default=True, metavar="md|pdf|docx[,…]|none",
              help="Per-variant report format.")
@click.option("--csv-locale", type=click.Choice(["ru", "en"]), default=None, help="summary.csv for a Russian (';', decimal comma) or English spreadsheet (default: from --lang).")
@sheets_option
@click.option("--teacher", "title_teacher", default=None, metavar="TEXT", help="Teacher's name (or in tmm.toml).")
@click.option("--org", "title_org", default=None, metavar="TEXT", help="University and department (or in tmm.toml).")
@force_option
@lang_option
def batch_cmd(variants_spec, roster, variants_file, crank_rpm, torque_nm, out, fmt, jobs, no_plots, report, csv_locale, sheets,
              title_teacher, title_org, force, lang):
    """Teachers: run many variants or a class roster in parallel and write summary.csv."""
    from ..output.folder import ensure_writable_dir
    from ..render.terminal.batch import print_batch, print_batch_intro
    from ..teacher.batch import run_batch
    from ..teacher.roster import jobs_from_roster, jobs_from_spec

    lang = resolve_lang(lang)
    title = title_block({"title_teacher": title_teacher, "title_org": title_org})  # tmm.toml, then the options
    from ..render.project import report_formats

    report = None if report == "none" else ",".join(sorted(report_formats(report)))
    if (variants_spec is None) == (roster is None):
        raise TmmError("give exactly one of --variants (e.g. 1-68) or --roster FILE")
    out_dir = ensure_writable_dir(Path(out) if out else Path("tmm-out"))
    console = console_for(lang)
    if variants_spec is not None:  # the whole list is checked against the table before any work
        rows, bad = jobs_from_spec(variants_spec, crank_rpm, torque_nm, variants_file), []
        print_batch_intro(console, lang, default_crank=crank_rpm is None)
    else:
        plan = jobs_from_roster(roster, crank_rpm, torque_nm, variants_file)
        rows, bad = plan.jobs, plan.bad
        print_batch_intro(console, lang, roster=plan)
    from ..render.terminal import escape

    summary = run_batch(
        rows, bad, out_dir, variants_file=variants_file, lang=lang, fmt=fmt,
        plots=not no_plots, report=report, jobs_n=jobs, progress=True,
        csv_locale=csv_locale, sheets=sheets, title=title, force=force,
        say=lambda text: console.print("[cyan]ℹ[/] " + escape(text)),
    )
    print_batch(console, summary, out_dir, lang)
    print_kept(console, list(summary.kept) + [k for r in summary.rows for k in r.get("kept", ())], lang)
    return 1 if summary.failed else 0
