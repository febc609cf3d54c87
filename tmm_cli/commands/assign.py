"""`tmm assign`: teachers give out the assignments of a roster (one A4 PDF each and one to print)."""

from __future__ import annotations

from pathlib import Path

import click

from .emit import console_for, print_files
from .options import (
    CONTEXT,
    crank_option,
    lang_option,
    resolve_lang,
    title_block,
    torque_option,
    variants_file_option,
)


@click.command("assign", context_settings=CONTEXT)
@click.option("--roster", type=click.Path(dir_okay=False), required=True, metavar="FILE",
              help="CSV with columns student[,variant][,group][,crank_rpm][,torque].")
@click.option("--out", type=click.Path(file_okay=False), default=None, metavar="DIR",
              help="Folder for assignment-NAME.pdf and assignments.pdf (default ./tmm-out).")
@click.option("--due", default=None, metavar="DATE", help="Due date of the project, e.g. 15.05.2026.")
@click.option("--issued", default=None, metavar="DATE", help="Date the assignment is issued (default: today).")
@click.option("--assign-variants", "assign", is_flag=True,
              help="Give distinct variants to the students without one, and write roster-with-variants.csv.")
@click.option("--seed", type=int, default=None, metavar="N", help="Seed of --assign-variants: the same seed, the same variants (default 0).")
@click.option("--teacher", "title_teacher", default=None, metavar="TEXT", help="Teacher's name (or in tmm.toml).")
@click.option("--org", "title_org", default=None, metavar="TEXT", help="University and department (or in tmm.toml).")
@variants_file_option
@crank_option
@torque_option
@lang_option
def assign_cmd(roster, out, due, issued, assign, seed, title_teacher, title_org, variants_file, crank_rpm, torque_nm, lang):
    """Teachers: the assignment of every student of a roster (A4 PDF each, and one merged to print)."""
    from ..errors import TmmError
    from ..output.folder import (
        ensure_writable_dir,
        read_manifest,
        refuse_foreign,
        staged_dir,
        write_owned,
    )
    from ..render.assignment import write_assignments
    from ..render.terminal.assign import print_assignments
    from ..teacher.assign import (
        MERGED,
        ROSTER_COPY,
        assignment_file,
        parse_date,
        plan_assignments,
        roster_with_variants,
    )

    lang = resolve_lang(lang)
    if seed is not None and not assign:
        raise TmmError("--seed goes with --assign-variants (it draws the variants); add --assign-variants or drop --seed")
    title = title_block({"title_teacher": title_teacher, "title_org": title_org})
    out_dir = ensure_writable_dir(Path(out) if out else Path("tmm-out"))
    plan = plan_assignments(roster, variants_file=variants_file, crank_rpm=crank_rpm, torque_nm=torque_nm, assign=assign,
                            seed=seed, issued=parse_date(issued, "--issued") if issued else None,
                            due=parse_date(due) if due else None)
    if not plan.items:
        raise TmmError(f"roster {roster}: no student can be given an assignment; fix the rows listed")
    names = [assignment_file(a.fname) for a in plan.items]
    if out_dir.is_dir():  # a file of the teacher's own under one of our names is refused before any work
        refuse_foreign(out_dir, names + [MERGED] + ([ROSTER_COPY] if assign else []), read_manifest(out_dir)["files"])
    with staged_dir(out_dir, owns=("assignment-*.pdf", MERGED)) as tmp:
        written = write_assignments(tmp, plan.items, lang, names, MERGED, teacher=title.teacher, org=title.org,
                                    issued=plan.issued, due=plan.due)
    if assign:
        write_owned(out_dir, ROSTER_COPY, roster_with_variants(roster, plan.items))
        written.append(ROSTER_COPY)
    console = console_for(lang)
    print_assignments(console, plan, lang)
    print_files(console, out_dir, [MERGED] + ([ROSTER_COPY] if assign else []) + [pick_names(names)], lang)
    return 1 if plan.bad else 0


def pick_names(names: list[str]) -> str:
    """assignment-A.pdf … assignment-Z.pdf (the first and the last of many)."""
    return names[0] if len(names) == 1 else f"{names[0]} … {names[-1]}"
