"""Rich tables for `tmm check`: one student's comparison, a group's verdicts, the answer keys."""

from __future__ import annotations

from ...i18n.lang import pick

STATUS = {
    "pass": ("[green]pass[/]", "[green]верно[/]"),
    "pass (book)": ("[green]pass[/] (the book's vertex)", "[green]верно[/] (вершина по пособию)"),
    "pass (valid set)": ("[green]pass[/] (another set meeting all five conditions)",
                         "[green]верно[/] (другой набор, удовлетворяющий всем пяти условиям)"),
    "pass (book roller)": ("[green]pass[/] (the book's roller 0.2·r0)", "[green]верно[/] (ролик 0,2·r0 по пособию)"),
    "pass (book roller, undercuts)": ("[green]pass[/] (the book's roller 0.2·r0; it undercuts this cam: r_p ≥ ρ_min of the pitch curve)",
                                      "[green]верно[/] (ролик 0,2·r0 по пособию; он подрезает этот профиль: r_р ≥ ρ_min центрового профиля)"),
    "pass (other swing)": ("[green]pass[/] (the smallest cam of the other swing; its pivot lies inside the swept circle — see the note)",
                           "[green]верно[/] (наименьший кулачок при другом направлении качания; ось коромысла внутри "
                           "описываемой кулачком окружности — см. примечание)"),
    "fail": ("[red]FAIL[/]", "[red]НЕВЕРНО[/]"),
    "unknown key": ("[yellow]unknown key[/]", "[yellow]неизвестный ключ[/]"),
    "not computed": ("[yellow]not computed for this variant[/]", "[yellow]не вычисляется для варианта[/]"),
    "missing": ("[red]missing[/] (required)", "[red]нет ответа[/] (обязательный)"),
}
# the per-key verdict in check.csv / check.md and the group table
SHORT = {"pass": ("pass", "верно"), "pass (book)": ("pass (book)", "верно (пособие)"),
         "pass (valid set)": ("pass (valid set)", "верно (другой набор)"), "fail": ("FAIL", "НЕВЕРНО"),
         "pass (book roller)": ("pass (book roller)", "верно (ролик по пособию)"),
         "pass (book roller, undercuts)": ("pass (book roller, undercuts)", "верно (ролик по пособию, подрез)"),
         "pass (other swing)": ("pass (other swing)", "верно (другое качание)"),
         "unknown key": ("unknown key", "неизвестный ключ"), "not computed": ("not computed", "не вычисляется"),
         "missing": ("missing", "нет ответа")}


def _val(v) -> str:
    if v is None:
        return "—"
    if isinstance(v, float):
        return f"{v:.4g}"
    return str(v)


def print_keys(console, lang: str, keys, required: dict) -> None:
    """`tmm check --keys`: the answer keys `keys` (AnswerKey records) and the sheet that requires each
    (`required`: sheet -> its keys)."""
    from rich.table import Table

    t = Table(title=pick(lang, "Answer keys for `tmm check`", "Ключи ответов для `tmm check`"), header_style="bold")
    t.add_column(pick(lang, "Key", "Ключ"))
    t.add_column(pick(lang, "Compared", "Сравнение"))
    t.add_column(pick(lang, "Required", "Обязателен"))
    t.add_column(pick(lang, "Meaning", "Смысл"))
    for k in keys:
        sheet = next((s for s, names in required.items() if k.key in names), "")
        req = pick(lang, f"sheet {sheet}", f"лист {sheet}") if sheet else "—"
        t.add_row(k.key, pick(lang, "exact", "точно") if k.kind == "int" else pick(lang, "within tolerance", "с допуском"),
                  req, pick(lang, k.en, k.ru))
    console.print(t)
    console.print(pick(lang, "A required key is needed when the variant computes it (z_planet2: scheme 2; *_2: a two-stage "
                             "reducer; e_mm: translating follower; l_oc_mm: rocker); a missing one fails the check. "
                             "--sheet 3 or --sheet 4 checks one sheet.",
                       "Обязательный ключ нужен, если он вычисляется для варианта (z_planet2 — схема 2; *_2 — двухступенчатый "
                       "редуктор; e_mm — поступательный толкатель; l_oc_mm — коромысло); без него проверка не пройдена. "
                       "--sheet 3 или --sheet 4 проверяет один лист."))
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
    from ...i18n.lang import note_text

    for note in report.notes:
        console.print(f"[cyan]ℹ[/] {note_text(note, lang)}")
    n_pass = sum(r.status.startswith("pass") for r in report.rows)
    verdict = (pick(lang, "[green]PASSED[/]", "[green]ЗАЧТЕНО[/]") if report.passed
               else pick(lang, "[red]NOT PASSED[/]", "[red]НЕ ЗАЧТЕНО[/]"))
    console.print(pick(lang, f"Verdict: {verdict} ({n_pass} of {len(report.rows)} values correct)",
                       f"Итог: {verdict} (верно {n_pass} из {len(report.rows)})"))


def _keys_of(group) -> list[str]:
    """The keys of the group's columns: the answer keys in `tmm check --keys` order, then others."""
    return group.keys()


def _verdict(rep, lang: str) -> str:
    if rep.error:
        return pick(lang, "error", "ошибка")
    return pick(lang, "passed", "зачтено") if rep.passed else pick(lang, "not passed", "не зачтено")


def group_table(group, lang: str) -> tuple[list[str], list[list]]:
    """The rows of check.csv / check.md: one per student, the verdict and pass/fail per key."""
    keys = _keys_of(group)
    header = [pick(lang, "student", "студент"), pick(lang, "group", "группа"), pick(lang, "variant", "вариант"),
              pick(lang, "verdict", "итог"), pick(lang, "correct", "верно"), pick(lang, "of", "из")] + keys + [
              pick(lang, "missing", "нет ответа"), pick(lang, "error", "ошибка")]
    body = []
    for rep in group.reports:
        by = {r.key: r.status for r in rep.rows}
        good = sum(r.status.startswith("pass") for r in rep.rows)
        body.append([rep.label, rep.group, rep.variant or "", _verdict(rep, lang), good if not rep.error else "",
                     len(rep.rows) if not rep.error else ""]
                    + [pick(lang, *SHORT[by[k]]) if k in by else "" for k in keys]
                    + [" ".join(rep.missing), rep.error])
    return header, body


def group_csv(group, lang: str, csv_locale: str) -> bytes:
    """check.csv: ';' and a BOM for a Russian spreadsheet, ',' for an English one; no formulas."""
    from ..data.csv import csv_encoding, csv_text

    header, body = group_table(group, lang)
    return csv_text(header, body, {2, 4, 5}, csv_locale).encode(csv_encoding(csv_locale))


def _md_cell(v) -> str:
    from ..data.csv import safe_cell

    return safe_cell(v).replace("|", "\\|").replace("*", "\\*").replace("_", "\\_").replace("`", "\\`") \
        .replace("<", "&lt;").replace(">", "&gt;").replace("[", "\\[")


def group_markdown(group, lang: str, rtol_pct: float, sheets) -> str:
    """check.md: the group's verdicts as a Markdown table, readable as it is and in any viewer."""
    from ...i18n.numbers import num

    header, body = group_table(group, lang)
    n_pass = sum(rep.passed for rep in group.reports)
    title = pick(lang, "Group check", "Проверка группы")
    lines = [f"# {title}", "",
             pick(lang, f"Tolerance {num(rtol_pct, lang)} %, sheets {', '.join(sorted(sheets))}; passed {n_pass} of {len(group.reports)}.",
                  f"Допуск {num(rtol_pct, lang)} %, листы {', '.join(sorted(sheets))}; зачтено {n_pass} из {len(group.reports)}."), ""]
    if group.roster_encoding:
        lines += [pick(lang, f"Roster read as {group.roster_encoding}.", f"Список прочитан в кодировке {group.roster_encoding}."), ""]
    lines.append("| " + " | ".join(_md_cell(h) for h in header) + " |")
    lines.append("|" + "---|" * len(header))
    for row in body:
        lines.append("| " + " | ".join(_md_cell(v) for v in row) + " |")
    return "\n".join(lines) + "\n"


def print_group(console, group, lang: str) -> None:
    from rich.markup import escape
    from rich.table import Table

    from ...i18n.errors import error_text

    t = Table(title=pick(lang, "Group check", "Проверка группы"), header_style="bold")
    for head in (pick(lang, "Student", "Студент"), pick(lang, "Variant", "Вариант"), pick(lang, "Correct", "Верно"),
                 pick(lang, "Wrong or missing", "Неверно или нет ответа"), pick(lang, "Verdict", "Итог")):
        t.add_column(head)
    for rep in group.reports:
        if rep.error:
            t.add_row(escape(rep.label), str(rep.variant or "—"), "—", "—", f"[red]{escape(error_text(rep.error, lang))}[/]")
            continue
        good = sum(r.status.startswith("pass") for r in rep.rows)
        wrong = ", ".join(r.key + (pick(lang, " (missing)", " (нет)") if r.status == "missing" else "")
                          for r in rep.rows if not r.status.startswith("pass")) or "—"
        verdict = pick(lang, "[green]passed[/]", "[green]зачтено[/]") if rep.passed else pick(lang, "[red]not passed[/]", "[red]не зачтено[/]")
        t.add_row(escape(rep.label), str(rep.variant), f"{good}/{len(rep.rows)}", escape(wrong), verdict)
    console.print(t)
