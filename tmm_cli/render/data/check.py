"""check.csv: one line per checked value of every student — the value, the student's, the deviation
(absolute and per cent), the tolerance, the verdict, what it was compared with, where to look and
the likely cause — and a line for a student who could not be checked. A spreadsheet opens it safely
(render/data/csv.py)."""

from __future__ import annotations

from ...i18n import tr, trc
from ...i18n.lang import note_text
from ..feedback.words import basis_word, place_text, status_word, symbol


def check_header(lang: str) -> list[str]:
    return [tr(lang, 'student'), tr(lang, 'group'), tr(lang, 'variant'),
            tr(lang, 'verdict'), tr(lang, 'key'), tr(lang, 'value'),
            trc(lang, "check", "given"), tr(lang, 'expected'), tr(lang, 'deviation'),
            tr(lang, 'deviation, %'), tr(lang, 'tolerance, %'),
            tr(lang, 'tolerance'), tr(lang, 'result'),
            tr(lang, 'compared with'), tr(lang, 'where to look'),
            tr(lang, 'comment')]


NUMERIC = {2, 6, 7, 8, 9, 10, 11}


def check_rows(group, lang: str) -> list[list]:
    from ...i18n.errors import error_text

    body = []
    for rep in group.reports:
        verdict = (tr(lang, 'error') if rep.error else
                   tr(lang, 'passed') if rep.passed else tr(lang, 'not passed'))
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
