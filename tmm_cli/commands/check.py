"""`tmm check`: teachers compare a student's numbers with the computed ones."""

from __future__ import annotations

from pathlib import Path

import click

from ..errors import TmmError
from .emit import console_for, print_files, print_json, print_kept
from .options import (
    CONTEXT,
    crank_option,
    json_option,
    lang_option,
    resolve_lang,
    torque_option,
    variant_row,
    variants_file_option,
)


@click.command("check", context_settings=CONTEXT)
@click.option("--variant", "-v", "variant", default=None, metavar="N", help="Variant number (one student).")
@click.option("--answers", type=click.Path(dir_okay=False), default=None, metavar="FILE", help="The student's numbers (TOML or CSV, keys in `tmm check --keys`).")
@click.option("--roster", type=click.Path(dir_okay=False), default=None, metavar="FILE", help="Class roster CSV (student,variant[,crank_rpm][,torque]).")
@click.option("--answers-dir", type=click.Path(file_okay=False), default=None, metavar="DIR", help="Folder with one answers file per student (STUDENT.toml or STUDENT.csv).")
@variants_file_option
@crank_option
@torque_option
@click.option("--rtol", "rtol_pct", type=float, default=3.0, show_default=True, metavar="PCT", help="Tolerance for graphical quantities [%].")
@click.option("--keys", "show_keys", is_flag=True, help="List the answer keys and exit.")
@click.option("--sheet", "sheet", type=click.Choice(["3", "4", "all"]), default="all", show_default=True, help="Which sheet's required keys a student must give.")
@click.option("--out", type=click.Path(file_okay=False), default=None, metavar="DIR", help="Group check: folder for check.csv, check.md, group.html and the feedback (default ./tmm-out).")
@click.option("--csv-locale", type=click.Choice(["ru", "en"]), default=None, help="check.csv for a Russian (';', decimal comma) or English spreadsheet (default: from --lang).")
@click.option("--feedback", type=click.Choice(["md", "pdf", "none"]), default="md", show_default=True,
              help="Group check: each student's feedback feedback/check-NAME.md (pdf: also as PDF).")
@json_option
@lang_option
def check_cmd(variant, answers, roster, answers_dir, variants_file, crank_rpm, torque_nm, rtol_pct, show_keys, sheet, out, csv_locale,
              feedback, as_json, lang):
    """Teachers: check a student's numbers against the computed ones."""
    from ..render.terminal.check import print_check, print_group, print_keys
    from ..teacher.check import SHEETS, check_group, check_one, read_answers
    from ..teacher.group import GROUP_FILES

    lang = resolve_lang(lang)
    console = console_for(lang)
    if show_keys:
        from ..teacher.check import ANSWER_KEYS, REQUIRED

        print_keys(console, lang, ANSWER_KEYS, REQUIRED)
        return 0
    sheets = SHEETS if sheet == "all" else (sheet,)
    if roster is not None or answers_dir is not None:
        if roster is None or answers_dir is None:
            raise TmmError("group check needs both --roster FILE and --answers-dir DIR")
        from ..output.folder import ensure_writable_dir, read_manifest, refuse_foreign
        from ..teacher.group import write_group_check

        out_dir = ensure_writable_dir(Path(out) if out else Path("tmm-out"))
        if out_dir.is_dir():  # a check.csv of the teacher's own is refused before any work
            refuse_foreign(out_dir, list(GROUP_FILES), read_manifest(out_dir)["files"])
        group = check_group(roster, answers_dir, variants_file=variants_file, crank_rpm=crank_rpm, torque_nm=torque_nm,
                            rtol_pct=rtol_pct, sheets=sheets, lang=lang)
        kept: list = []  # a check.csv the teacher edited is kept, the new one written beside it
        failed: list = []  # a feedback PDF typst could not set (the others and the group's files are written)
        written = write_group_check(out_dir, group, lang, csv_locale or lang, rtol_pct, sheets, pdf=feedback == "pdf",
                                    feedback=feedback != "none", kept=kept, failed=failed)
        _say_failed(failed, lang)
        if as_json:
            print_json(group.to_json(lang))
            print_kept(None, kept, lang)
        else:
            from ..render.terminal import escape

            from ..i18n import tr

            console.print("[cyan]ℹ[/] " + escape(tr(lang, "Roster {roster}: read as {roster_encoding}.").format(roster=roster, roster_encoding=group.roster_encoding)))
            print_group(console, group, lang)
            print_files(console, out_dir, written, lang)
            print_kept(console, kept, lang)
        return 0 if group.all_passed else 1
    if variant is None or answers is None:
        raise TmmError("give --variant N and --answers FILE (or --roster FILE with --answers-dir DIR)")
    v = variant_row(variant, variants_file)
    report = check_one(v, read_answers(answers), crank_rpm=crank_rpm, torque_nm=torque_nm, rtol_pct=rtol_pct, sheets=sheets,
                       lang=lang)
    if as_json:
        print_json(report.to_json(lang))
    else:
        print_check(console, report, lang)
    return 0 if report.passed else 1


def _say_failed(failed: list, lang: str) -> None:
    """One line on stderr per feedback PDF that was not written."""
    import click

    from ..i18n import tr
    from ..i18n.errors import error_text
    from ..inputs.names import visible

    for name, why in failed:
        click.echo("tmm: " + visible(tr(lang, "{name} was not written ({why}); the Markdown feedback is there").format(
            name=name, why=error_text(why, lang))), err=True)
