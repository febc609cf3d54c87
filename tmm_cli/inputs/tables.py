"""Reading and writing the teacher's tables: rosters, answers files, summaries.

Reading: the bytes are decoded as Excel and editors really save them: UTF-8 with or without a
BOM, UTF-16 (with a BOM, "Unicode text"), or cp1251 (Excel under a Russian locale); the encoding
used is returned so the output can say it. The separator is ',' or ';'. A file over its size
limit, or one that is not text, is refused with one line before it is parsed.

Writing: every cell a spreadsheet would run as a formula (=, +, -, @, tab, CR first) gets a
leading apostrophe (OWASP, "CSV injection"); control characters go; line separators that would
split a row become spaces. Numbers stay numbers: they are written from numeric values, never
from text, with a decimal comma under the Russian CSV locale (and ';' between cells).
"""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path

from ..errors import TmmError
from ..records import record

ENCODING_NAMES = {"utf-8": "UTF-8", "utf-8-sig": "UTF-8 (BOM)", "utf-16": "UTF-16", "cp1251": "cp1251 (Windows Cyrillic)"}


@record
class TextFile:
    path: Path
    text: str
    encoding: str  # key of ENCODING_NAMES

    @property
    def encoding_name(self) -> str:
        return ENCODING_NAMES.get(self.encoding, self.encoding)


def decode(raw: bytes, what: str) -> tuple[str, str]:
    """(text, encoding) of a file's bytes: UTF-16 by its BOM, UTF-8 (BOM or not), else cp1251.

    >>> decode("студент".encode("cp1251"), "roster")
    ('студент', 'cp1251')
    >>> decode("\\ufeffстудент".encode("utf-8"), "roster")
    ('студент', 'utf-8-sig')
    >>> decode("студент".encode("utf-16"), "roster")
    ('студент', 'utf-16')
    """
    if raw[:2] in (b"\xff\xfe", b"\xfe\xff"):
        try:
            text, enc = raw.decode("utf-16"), "utf-16"
        except UnicodeDecodeError:
            raise TmmError(f"{what} starts like UTF-16 but cannot be decoded; save it again as CSV UTF-8") from None
    elif raw[:3] == b"\xef\xbb\xbf":
        try:
            text, enc = raw[3:].decode("utf-8"), "utf-8-sig"
        except UnicodeDecodeError:
            raise TmmError(f"{what} starts like UTF-8 but cannot be decoded; save it again as CSV UTF-8") from None
    else:
        try:
            text, enc = raw.decode("utf-8"), "utf-8"
        except UnicodeDecodeError:
            try:
                text, enc = raw.decode("cp1251"), "cp1251"
            except UnicodeDecodeError:
                raise TmmError(f"{what} is neither UTF-8 nor cp1251 text; save it as CSV UTF-8") from None
    if "\x00" in text:
        raise TmmError(f"{what} is not a text file (it holds NUL bytes); save it as CSV UTF-8")
    return text, enc


def read_text(path: str | Path, what: str, max_bytes: int) -> TextFile:
    """Read a small text file: size limit first (one stat, nothing read), then :func:`decode`."""
    from .files import read_file

    p = Path(path)
    raw = read_file(p, what, max_bytes)  # a regular file (a FIFO is refused, not waited on), size first
    text, enc = decode(raw, what)
    return TextFile(p, text, enc)


def delimiter(text: str) -> str:
    """',' or ';' (what a spreadsheet saves under a Russian locale), from the first non-empty line.

    >>> delimiter("student;variant\\nA;1")
    ';'
    """
    for line in io.StringIO(text):
        if line.strip():
            return ";" if line.count(";") > line.count(",") else ","
    return ","


def rows(text: str, max_rows: int, what: str) -> list[list[str]]:
    """CSV rows of `text` (quoted cells may hold the separator); at most `max_rows` non-empty rows.

    Rows are split by the csv module on CR/LF only, so a form feed or U+2028 inside a name never
    splits a row.
    """
    reader = csv.reader(io.StringIO(text, newline=""), delimiter=delimiter(text))
    out = []
    filled = 0  # counted as they come: a file of blank lines stays linear
    try:
        for row in reader:
            if any(c.strip() for c in row):
                out.append(row)
                filled += 1
            else:
                out.append([])  # keep line numbers
            if filled > max_rows:
                raise TmmError(f"{what} has more than {max_rows} rows, over the limit; split it (limits: docs/limits.md)")
    except csv.Error as exc:
        raise TmmError(f"{what} line {reader.line_num} is not valid CSV ({exc}); check the quotes") from None
    return out


def whole_number(text) -> int | None:
    """A cell's whole number in ASCII digits (at most 9), or None: «¹⁷» and «²» are digits to
    str.isdigit() but not to int(), and a row of them is one bad row, not a crash.

    >>> whole_number("17"), whole_number("¹⁷"), whole_number("٣"), whole_number("")
    (17, None, None, None)
    """
    text = str(text)
    return int(text) if 0 < len(text) <= 9 and text.isascii() and text.isdigit() else None


def parse_number(raw, where: str) -> int | float:
    """A number from a cell: decimal comma or dot; finite; never echoes the cell itself.

    >>> parse_number("48,9", "x"), parse_number("17", "x"), parse_number(-3.5, "x")
    (48.9, 17, -3.5)
    """
    if isinstance(raw, bool):
        raise TmmError(f"{where} is not a number; write a plain number")
    if isinstance(raw, int):
        if abs(raw) > 10**15:
            raise TmmError(f"{where} is a number too large to be an answer; write a plain number")
        return raw
    if isinstance(raw, float):
        value = raw
        text = repr(raw)
    else:
        text = str(raw).strip().replace(",", ".").replace("\u2212", "-")
        if len(text) > 40:
            raise TmmError(f"{where} is not a number; write a plain number")
        try:
            value = float(text)
        except ValueError:
            raise TmmError(f"{where} is not a number; write a plain number (decimal comma or dot)") from None
    if not math.isfinite(value) or abs(value) > 1e15:
        raise TmmError(f"{where} is not a finite number of sensible size; write a plain number")
    if isinstance(raw, str) and value.is_integer() and "." not in text and "e" not in text.lower():
        return int(value)
    return value


# writing -------------------------------------------------------------------------------------


