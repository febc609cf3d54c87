"""`tmm assign`'s table: who got which variant (and which were drawn), the rows that got nothing."""

from __future__ import annotations

from ...i18n import ntr, tr
from ...i18n.numbers import num


def print_assignments(console, plan, lang: str) -> None:
    """`plan`: a teacher.assign.AssignmentSet, read by its fields."""
    from . import escape
    from rich.table import Table

    from ...i18n.errors import error_text

    t = Table(title=tr(lang, 'Assignments'), header_style="bold")
    for head in (tr(lang, 'Student'), tr(lang, 'Group'), tr(lang, 'Variant'),
                 tr(lang, "n_cr, rpm"), tr(lang, "M, N·m")):
        t.add_column(head)
    for a in plan.items:
        mark = " *" if a.drawn else ""
        t.add_row(escape(a.student), escape(a.group), f"{a.variant.number}{mark}",
                  "—" if a.crank_rpm is None else num(a.crank_rpm, lang, sig=6, sci=False),
                  "—" if a.torque_nm is None else num(a.torque_nm, lang, sig=6, sci=False))
    console.print(t)
    if plan.seed is not None:
        drawn = sum(a.drawn for a in plan.items)
        text = ntr(lang, "* {n} variant drawn with --seed {seed} (the same seed gives the same variants); the others kept "
                         "the roster's.", "* {n} variants drawn with --seed {seed} (the same seed gives the same variants); "
                                          "the others kept the roster's.", drawn)
        console.print("[cyan]ℹ[/] " + text.format(n=drawn, seed=plan.seed))
    if plan.repeats:
        console.print("[yellow]![/] " + tr(lang, 'The group outnumbers the table: {n} students share a variant.').format(n=plan.repeats))
    for b in plan.bad:
        console.print(f"[red]✘[/] {escape(b.job.label)}: {escape(error_text(b.reason, lang))}")
