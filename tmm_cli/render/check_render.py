"""Rich tables for `tmm check`: one student's comparison, a group's verdicts, the answer keys."""

from __future__ import annotations

from .i18n import pick

STATUS = {
    "pass": ("[green]pass[/]", "[green]верно[/]"),
    "pass (book)": ("[green]pass[/] (the book's vertex)", "[green]верно[/] (вершина по пособию)"),
    "pass (valid set)": ("[green]pass[/] (another set meeting all five conditions)",
                         "[green]верно[/] (другой набор, удовлетворяющий всем пяти условиям)"),
    "fail": ("[red]FAIL[/]", "[red]НЕВЕРНО[/]"),
    "unknown key": ("[yellow]unknown key[/]", "[yellow]неизвестный ключ[/]"),
    "not computed": ("[yellow]not computed for this variant[/]", "[yellow]не вычисляется для варианта[/]"),
}


def _val(v) -> str:
    if v is None:
        return "—"
    if isinstance(v, float):
        return f"{v:.4g}"
    return str(v)


def print_keys(console, lang: str) -> None:
    from rich.table import Table

    from ..check import ANSWER_KEYS

    t = Table(title=pick(lang, "Answer keys for `tmm check`", "Ключи ответов для `tmm check`"), header_style="bold")
    t.add_column(pick(lang, "Key", "Ключ"))
    t.add_column(pick(lang, "Compared", "Сравнение"))
    t.add_column(pick(lang, "Meaning", "Смысл"))
    for k in ANSWER_KEYS:
        t.add_row(k.key, pick(lang, "exact", "точно") if k.kind == "int" else pick(lang, "within tolerance", "с допуском"), pick(lang, k.en, k.ru))
    console.print(t)
    console.print(pick(lang, "TOML example:  r0_mm = 41.5   z_sun = 40   eps_alpha = 1.58",
                       "Пример TOML:  r0_mm = 41.5   z_sun = 40   eps_alpha = 1.58"))


def print_check(console, report, lang: str) -> None:
    from rich.table import Table

    who = "" if report.label == f"variant {report.variant}" else f"{report.label}, "
    t = Table(title=pick(lang, f"Check — {who}variant {report.variant}, tolerance {report.rtol_pct:g} %",
                         f"Проверка — {who}вариант {report.variant}, допуск {report.rtol_pct:g} %"), header_style="bold")
    for i, head in enumerate((pick(lang, "Key", "Ключ"), pick(lang, "Expected", "Расчёт"), pick(lang, "Given", "Ответ"),
                              pick(lang, "Deviation, %", "Отклонение, %"), pick(lang, "Result", "Итог"))):
        t.add_column(head, justify="left" if i in (0, 4) else "right")
    for r in report.rows:
        dev = "—" if r.deviation_pct is None else f"{r.deviation_pct:+.2f}"
        t.add_row(r.key, _val(r.expected), _val(r.given), dev, pick(lang, *STATUS[r.status]))
    console.print(t)
    from .i18n import note_text

    for note in report.notes:
        console.print(f"[cyan]ℹ[/] {note_text(note, lang)}")
    n_pass = sum(r.status.startswith("pass") for r in report.rows)
    verdict = (pick(lang, "[green]PASSED[/]", "[green]ЗАЧТЕНО[/]") if report.passed
               else pick(lang, "[red]NOT PASSED[/]", "[red]НЕ ЗАЧТЕНО[/]"))
    console.print(pick(lang, f"Verdict: {verdict} ({n_pass} of {len(report.rows)} values correct)",
                       f"Итог: {verdict} (верно {n_pass} из {len(report.rows)})"))


def print_group(console, group, lang: str) -> None:
    from rich.table import Table

    t = Table(title=pick(lang, "Group check", "Проверка группы"), header_style="bold")
    for head in (pick(lang, "Student", "Студент"), pick(lang, "Variant", "Вариант"), pick(lang, "Correct", "Верно"),
                 pick(lang, "Wrong", "Неверно"), pick(lang, "Verdict", "Итог")):
        t.add_column(head)
    for rep in group.reports:
        if rep.error:
            t.add_row(rep.label, str(rep.variant or "—"), "—", "—", f"[red]{rep.error}[/]")
            continue
        good = sum(r.status.startswith("pass") for r in rep.rows)
        wrong = ", ".join(r.key for r in rep.rows if not r.status.startswith("pass")) or "—"
        verdict = pick(lang, "[green]passed[/]", "[green]зачтено[/]") if rep.passed else pick(lang, "[red]not passed[/]", "[red]не зачтено[/]")
        t.add_row(rep.label, str(rep.variant), f"{good}/{len(rep.rows)}", wrong, verdict)
    console.print(t)
