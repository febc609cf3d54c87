"""Rich tables for `tmm check`: one student's comparison with what to correct, a group's verdicts,
the answer keys."""

from __future__ import annotations

from ...i18n.lang import pick
from ..feedback.words import (
    STATUS,  # noqa: F401  (the verdict words, for callers that list them)
    deviation_text,
    passed,
    place_text,
    row_sentence,
    status_word,
    symbol,
    tolerance_text,
    value_text,
)

_COLOUR = {"fail": "red", "missing": "red", "unreadable": "red", "duplicate": "red", "unknown key": "yellow",
           "not checked": "yellow", "not computed": "yellow"}


def _coloured(status: str, lang: str) -> str:
    from rich.markup import escape

    colour = "green" if status.startswith("pass") else _COLOUR.get(status, "yellow")
    return f"[{colour}]{escape(status_word(status, lang))}[/]"


def print_keys(console, lang: str, keys, required: dict) -> None:
    """`tmm check --keys`: the answer keys `keys` (AnswerKey records), the names a student may write
    them under, and the sheet that requires each (`required`: sheet -> its keys)."""
    from rich.table import Table

    t = Table(title=pick(lang, "Answer keys for `tmm check`", "Ключи ответов для `tmm check`"), header_style="bold")
    t.add_column(pick(lang, "Key", "Ключ"))
    t.add_column(pick(lang, "Also written", "Можно писать"))
    t.add_column(pick(lang, "Compared", "Сравнение"))
    t.add_column(pick(lang, "Required", "Обязателен"))
    t.add_column(pick(lang, "Meaning", "Смысл"))
    for k in keys:
        sheet = next((s for s, names in required.items() if k.key in names), "")
        req = pick(lang, f"sheet {sheet}", f"лист {sheet}") if sheet else "—"
        how = {"int": pick(lang, "exact", "точно"), "input": pick(lang, "Table 1.2", "табл. 1.2")}.get(
            k.kind, pick(lang, "within tolerance", "с допуском"))
        t.add_row(k.key, ", ".join(k.aliases[:4]), how, req, pick(lang, k.en, k.ru))
    console.print(t)
    console.print(pick(lang, "A required key is needed when the variant computes it (z_planet2: scheme 2; *_2: a two-stage "
                             "reducer; e_mm: translating follower; l_oc_mm: rocker); a missing one fails the check. "
                             "--sheet 3 or --sheet 4 checks one sheet. A key may be written as in the book (r_0, z_1, "
                             "u_1H, φ_у …); a misspelt one gets a suggestion.",
                       "Обязательный ключ нужен, если он вычисляется для варианта (z_planet2 — схема 2; *_2 — двухступенчатый "
                       "редуктор; e_mm — поступательный толкатель; l_oc_mm — коромысло); без него проверка не пройдена. "
                       "--sheet 3 или --sheet 4 проверяет один лист. Ключ можно писать как в пособии (r_0, z_1, u_1H, "
                       "φ_у …); для ключа с опечаткой предлагается верный."))
    console.print(pick(lang, "TOML example:  r0_mm = 41.5   z_sun = 40   eps_alpha = 1.58",
                       "Пример TOML:  r0_mm = 41.5   z_sun = 40   eps_alpha = 1.58"))


def _who(report, lang: str) -> str:
    return "" if report.label == f"variant {report.variant}" else f"{report.label}, "


def print_check(console, report, lang: str) -> None:
    """One student: every checked value (yours, right, deviation, tolerance, result, where to look),
    then what to correct in sentences, the remarks and the verdict."""
    from rich.markup import escape
    from rich.table import Table

    from ...i18n.lang import note_text

    who = escape(_who(report, lang))
    t = Table(title=pick(lang, f"Check — {who}variant {report.variant}, tolerance {report.rtol_pct:g} %",
                         f"Проверка — {who}вариант {report.variant}, допуск {report.rtol_pct:g} %".replace(".", ",")),
              header_style="bold")
    heads = (pick(lang, "Value", "Величина"), pick(lang, "Yours", "Ответ"), pick(lang, "Right", "Верно"),
             pick(lang, "Deviation", "Отклонение"), pick(lang, "Tolerance", "Допуск"), pick(lang, "Result", "Итог"),
             pick(lang, "Where to look", "Где смотреть"))
    for i, head in enumerate(heads):
        t.add_column(head, justify="right" if i in (1, 2, 3) else "left", overflow="fold")
    for r in report.rows:
        name = symbol(r.key, lang) if r.status != "unknown key" else (r.written or r.key)
        if r.written and r.written not in (r.key, name) and r.status != "unknown key":
            name += f" ({r.written})"
        t.add_row(escape(name), escape(value_text(r.given, r.key, lang)), value_text(r.expected, r.key, lang),
                  deviation_text(r, lang), tolerance_text(r, lang), _coloured(r.status, lang), place_text(r.place, lang))
    console.print(t)
    for note in report.notes:
        console.print(f"[cyan]ℹ[/] {escape(note_text(note, lang))}")
    bad = [r for r in report.rows if not passed(r)]
    if bad:
        console.print(pick(lang, "[bold]What to correct[/]", "[bold]Что исправить[/]"))
        for r in bad:
            console.print(f"  [red]✘[/] {escape(row_sentence(r, lang))}")
    remarks = [r for r in report.rows if passed(r) and r.status != "pass" and r.cause is not None]
    from ..feedback.words import findings_lines

    for line in findings_lines(report.findings, lang):
        console.print(f"  [cyan]ℹ[/] {escape(line)}")
    for r in remarks:
        if not any(r.cause == n for n in report.findings):
            console.print(f"  [green]✔[/] {escape(row_sentence(r, lang))}")
    n_pass = sum(passed(r) for r in report.rows)
    verdict = (pick(lang, "[green]PASSED[/]", "[green]ЗАЧТЕНО[/]") if report.passed
               else pick(lang, "[red]NOT PASSED[/]", "[red]НЕ ЗАЧТЕНО[/]"))
    console.print(pick(lang, f"Verdict: {verdict} ({n_pass} of {len(report.rows)} values correct)",
                       f"Итог: {verdict} (верно {n_pass} из {len(report.rows)})"))


def _verdict(rep, lang: str) -> str:
    if rep.error:
        return pick(lang, "error", "ошибка")
    return pick(lang, "passed", "зачтено") if rep.passed else pick(lang, "not passed", "не зачтено")


def group_table(group, lang: str) -> tuple[list[str], list[list]]:
    """The rows of check.md: one per student, the verdict and the result of every key."""
    keys = group.keys()
    header = [pick(lang, "student", "студент"), pick(lang, "group", "группа"), pick(lang, "variant", "вариант"),
              pick(lang, "verdict", "итог"), pick(lang, "correct", "верно"), pick(lang, "of", "из")] + keys + [
              pick(lang, "missing", "нет ответа"), pick(lang, "error", "ошибка")]
    body = []
    from ...i18n.errors import error_text

    for rep in group.reports:
        by = {r.key: r.status for r in rep.rows}
        good = sum(passed(r) for r in rep.rows)
        body.append([rep.label, rep.group, rep.variant or "", _verdict(rep, lang), good if not rep.error else "",
                     len(rep.rows) if not rep.error else ""]
                    + [status_word(by[k], lang) if k in by else "" for k in keys]
                    + [" ".join(rep.missing), error_text(rep.error, lang) if rep.error else ""])
    return header, body


def group_markdown(group, lang: str, rtol_pct: float, sheets) -> str:
    """check.md (see render/feedback.group_markdown)."""
    from ..feedback import group_markdown as md

    return md(group, lang, rtol_pct, sheets, group_table(group, lang))


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
        good = sum(passed(r) for r in rep.rows)
        wrong = ", ".join((symbol(r.key, lang) if r.status != "unknown key" else (r.written or r.key))
                          + (pick(lang, " (missing)", " (нет)") if r.status == "missing" else "")
                          for r in rep.rows if not passed(r)) or "—"
        verdict = pick(lang, "[green]passed[/]", "[green]зачтено[/]") if rep.passed else pick(lang, "[red]not passed[/]", "[red]не зачтено[/]")
        t.add_row(escape(rep.label), str(rep.variant), f"{good}/{len(rep.rows)}", escape(wrong), verdict)
    console.print(t)
    for f, near in group.unmatched:
        hint = pick(lang, f" — perhaps {near}?", f" — возможно, это {near}?") if near else ""
        console.print("[yellow]![/] " + escape(pick(lang, f"Answers file {f} matches no student on the roster",
                                                    f"Файл ответов {f} не соответствует ни одному студенту списка") + hint))
