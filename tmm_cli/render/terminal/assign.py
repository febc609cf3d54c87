"""`tmm assign`'s table: who got which variant (and which were drawn), the rows that got nothing."""

from __future__ import annotations

from ...i18n.lang import pick
from ...i18n.numbers import num


def print_assignments(console, plan, lang: str) -> None:
    """`plan`: a teacher.assign.AssignmentSet, read by its fields."""
    from rich.markup import escape
    from rich.table import Table

    from ...i18n.help_ru import error_text

    t = Table(title=pick(lang, "Assignments", "Задания"), header_style="bold")
    for head in (pick(lang, "Student", "Студент"), pick(lang, "Group", "Группа"), pick(lang, "Variant", "Вариант"),
                 "n_cr, rpm" if lang != "ru" else "n_кр, об/мин", "M, N·m" if lang != "ru" else "M, Н·м"):
        t.add_column(head)
    for a in plan.items:
        mark = " *" if a.drawn else ""
        t.add_row(escape(a.student), escape(a.group), f"{a.variant.number}{mark}",
                  "—" if a.crank_rpm is None else num(a.crank_rpm, lang, sig=6, sci=False),
                  "—" if a.torque_nm is None else num(a.torque_nm, lang, sig=6, sci=False))
    console.print(t)
    if plan.seed is not None:
        from ...i18n.numbers import plural

        n = plural(sum(a.drawn for a in plan.items), lang, {"one": "variant", "other": "variants"} if lang != "ru" else
                   {"one": "вариант", "few": "варианта", "many": "вариантов", "other": "варианта"})
        console.print("[cyan]ℹ[/] " + pick(lang, f"* {n} drawn with --seed {plan.seed} (the same seed gives the same "
                                                 "variants); the others kept the roster's.",
                                           f"* {n} выдано по --seed {plan.seed} (тот же seed — те же варианты); "
                                           "у остальных оставлены варианты из списка."))
    if plan.repeats:
        console.print("[yellow]![/] " + pick(lang, f"The group outnumbers the table: {plan.repeats} students share a variant.",
                                             f"Студентов больше, чем вариантов в таблице: {plan.repeats} получили повторяющийся вариант."))
    for b in plan.bad:
        console.print(f"[red]✘[/] {escape(b.job.label)}: {escape(error_text(b.reason, lang))}")
