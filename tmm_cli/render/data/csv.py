"""CSV a spreadsheet opens safely: no formula injection, numbers from numeric values with the reader's decimal sign and separator."""

from __future__ import annotations

import csv
import io
import math

from ...inputs.names import clean_text

_FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


def safe_cell(value) -> str:
    """A text cell that no spreadsheet runs as a formula and that never splits a row.

    >>> [safe_cell(s) for s in ("=HYPERLINK(\\"http://x\\",\\"y\\")", "+1+1", "-2+3", "@SUM(A1)", "Ivanov")]
    ['\\'=HYPERLINK("http://x","y")', "'+1+1", "'-2+3", "'@SUM(A1)", 'Ivanov']
    >>> safe_cell("A\\u2028B\\fC\\x00D")
    'A B CD'
    """
    text = "" if value is None else str(value)
    if text[:1] in _FORMULA_START:
        text = "'" + text
    cleaned = clean_text(text)
    if cleaned[:1] in _FORMULA_START:
        cleaned = "'" + cleaned
    return cleaned


def number_cell(value, locale: str) -> str:
    """A numeric cell: '' for none or non-finite, 6 significant digits, ',' decimal under ru.

    >>> number_cell(-20.6512, "ru"), number_cell(3, "en"), number_cell(float("nan"), "en")
    ('-20,6512', '3', '')
    """
    if value is None or value == "" or isinstance(value, bool):
        return ""
    if isinstance(value, int):
        return str(value)
    x = float(value)
    if not math.isfinite(x):
        return ""
    text = f"{x:.6g}"
    return text.replace(".", ",") if locale == "ru" else text


def csv_text(header: list[str], body: list[list], numeric: set[int], locale: str) -> str:
    """The CSV document: ';' and decimal commas under ru, ','  and dots under en.

    `numeric` holds the indices of numeric columns (written by :func:`number_cell`); every other
    cell goes through :func:`safe_cell`.
    """
    buf = io.StringIO()
    w = csv.writer(buf, delimiter=";" if locale == "ru" else ",", lineterminator="\r\n")
    w.writerow([safe_cell(h) for h in header])
    for row in body:
        w.writerow([number_cell(v, locale) if i in numeric and not isinstance(v, str) else safe_cell(v)
                    for i, v in enumerate(row)])
    return buf.getvalue()


def csv_encoding(locale: str) -> str:
    """Excel under a Russian locale reads UTF-8 only with a BOM; plain UTF-8 for the en locale."""
    return "utf-8-sig" if locale == "ru" else "utf-8"
