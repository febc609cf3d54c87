"""check.csv: one line per checked value of every student — the value, the student's, the deviation
(absolute and per cent), the tolerance, the verdict, what it was compared with, where to look and
the likely cause — and a line for a student who could not be checked. A spreadsheet opens it safely
(render/data/csv.py)."""

from __future__ import annotations

from ...i18n.lang import note_text, pick
from ..feedback.words import basis_word, place_text, status_word, symbol


def check_header(lang: str) -> list[str]:
    return [pick(lang, "student", "студент"), pick(lang, "group", "группа"), pick(lang, "variant", "вариант"),
            pick(lang, "verdict", "итог"), pick(lang, "key", "ключ"), pick(lang, "value", "величина"),
            pick(lang, "given", "ответ"), pick(lang, "expected", "верно"), pick(lang, "deviation", "отклонение"),
            pick(lang, "deviation, %", "отклонение, %"), pick(lang, "tolerance, %", "допуск, %"),
            pick(lang, "tolerance", "допуск (абс.)"), pick(lang, "result", "результат"),
            pick(lang, "compared with", "сравнение с"), pick(lang, "where to look", "где смотреть"),
            pick(lang, "comment", "комментарий")]


NUMERIC = {2, 6, 7, 8, 9, 10, 11}


def check_rows(group, lang: str) -> list[list]:
    from ...i18n.help_ru import error_text

    body = []
    for rep in group.reports:
        verdict = (pick(lang, "error", "ошибка") if rep.error else
                   pick(lang, "passed", "зачтено") if rep.passed else pick(lang, "not passed", "не зачтено"))
        lead = [rep.label, rep.group, rep.variant or "", verdict]
        if rep.error or not rep.rows:
            body.append(lead + ["", "", "", "", "", "", "", "", "", "", "", error_text(rep.error, lang)])
            continue
        for r in rep.rows:
            name = symbol(r.key, lang) if r.status != "unknown key" else (r.written or r.key)
            body.append(lead + [r.key if r.status != "unknown key" else (r.written or r.key), name,
                                r.given if isinstance(r.given, (int, float)) else ("" if r.given is None else str(r.given)),
                                r.expected, r.deviation, r.deviation_pct, r.tolerance_pct, r.tolerance,
                                status_word(r.status, lang), basis_word(r.basis, lang), place_text(r.place, lang),
                                note_text(r.cause, lang) if r.cause is not None else ""])
    return body


def check_csv(group, lang: str, csv_locale: str) -> bytes:
    """check.csv: ';' and a BOM for a Russian spreadsheet, ',' for an English one; no formulas."""
    from .csv import csv_encoding, csv_text

    return csv_text(check_header(lang), check_rows(group, lang), NUMERIC, csv_locale).encode(csv_encoding(csv_locale))


def check_json(group, lang: str) -> bytes:
    """check.json: the group's check as data (what `tmm check --json` prints); the group page of a
    later `tmm batch` into the same folder reads it."""
    import json

    return (json.dumps(group.to_json(lang), ensure_ascii=False, indent=1) + "\n").encode("utf-8")
