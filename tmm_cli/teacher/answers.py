"""Reading a student's answers file: TOML (``r0_mm = 41.2``) or CSV (``key,value`` rows, ',' or ';').

A file that cannot be read as a whole (not text, too large, not TOML, a key twice) is an error for
that student. One bad cell is not: a value that is not a number (``1²``, ``сорок``) comes back as an
:class:`Unreadable` and becomes that key's failed row, the student's other answers are checked.

Keys are kept as the student wrote them (``r_0``, ``φ_у``); :mod:`.keys` reads them.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

from ..errors import TmmError
from ..records import record

# a written key: no spaces, separators or quotes, at most 40 characters, at least one letter
_KEY = re.compile(r"[^\s=,;\"#\[\]]{1,40}")
# a line of the simple form students write when TOML refuses it: key = number (comma or dot) # comment
_LINE = re.compile(r"\s*(?P<key>[^\s=#\"]{1,40})\s*=\s*(?P<value>[^#]*?)\s*(?:#.*)?")


@record
class Unreadable:
    """An answer cell that is not a number: what the student wrote (cut short) and why."""

    raw: str
    reason: str


def _answer_key(raw: str, where: str) -> str:
    from ..inputs.names import clean_text

    key = clean_text(raw)  # one line, no control characters (docs/limits.md)
    if not _KEY.fullmatch(key) or not any(ch.isalpha() for ch in key):
        raise TmmError(f"{where}: the key is not a name like r0_mm (letters, digits, '_'); see `tmm check --keys`")
    return key


# a cell that is shown back to the student when it is not a number: a number-like attempt only
# (digits, signs, separators, superscripts, a unit); anything else (a formula, prose) is never echoed
_SHOWN = re.compile(r"[0-9.,+\-−eE ²³¹⁰⁴⁵⁶⁷⁸⁹·×*/^()°a-zA-Zа-яА-Я]{1,20}")


def _cell(raw, where: str):
    """A number, or an Unreadable saying why not (what the student wrote, when it is a short
    number-like text; '' otherwise: the file's content is never echoed)."""
    from ..inputs.tables import parse_number

    try:
        return parse_number(raw, where)
    except TmmError as exc:
        text = str(raw).strip()
        shown = text if _SHOWN.fullmatch(text) and sum(ch.isdigit() for ch in text) >= 1 \
            and not text[:1] in "=+-@" else ""
        return Unreadable(shown, str(exc))


def read_answers(path: str | Path) -> dict[str, object]:
    """Read a student's answers: TOML (`r0_mm = 41.2`) or CSV (`key,value` rows, ',' or ';').

    UTF-8, UTF-16 or cp1251; at most ANSWERS_BYTES and ANSWERS_ROWS keys; a key written twice or a
    nested table is an error; a value that is not a finite number is an :class:`Unreadable` (that
    key fails, the rest is checked). A TOML file that is not valid TOML but has only lines
    ``key = number`` (a decimal comma, a key in the book's letters such as ``φ_у``) is read line
    by line. Errors name the line and the key, never the content of the file.
    """
    from ..inputs.tables import read_text, rows
    from ..limits import ANSWERS_BYTES, ANSWERS_ROWS

    p = Path(path)
    src = read_text(p, f"answers file {p.name}", ANSWERS_BYTES)
    what = f"answers file {p.name}"
    if p.suffix.lower() == ".csv":
        lines = rows(src.text, ANSWERS_ROWS, what)
        answers: dict[str, object] = {}
        first_line: dict[str, int] = {}
        header_done = False
        for i, r in enumerate(lines, start=1):
            if not r:
                continue
            if not header_done:
                header_done = True
                if [c.strip().lower() for c in r[:2]] in (["key", "value"], ["ключ", "значение"]):
                    continue
            if len(r) < 2:
                raise TmmError(f"{what} line {i}: expected key,value")
            key = _answer_key(r[0], f"{what} line {i}")
            if key in answers:
                raise TmmError(f"{what} line {i}: key {key} appears twice (first on line {first_line[key]}); keep one")
            answers[key] = _cell(r[1], f"{what} line {i} ({key})")
            first_line[key] = i
        return answers
    try:
        data = tomllib.loads(src.text)
    except tomllib.TOMLDecodeError as exc:
        data = _simple_lines(src.text, what, ANSWERS_ROWS)
        if data is None:
            raise TmmError(f"{what} is not valid TOML ({exc}); write lines like r0_mm = 41.2, with a dot for decimals") from None
    except (RecursionError, ValueError, MemoryError):
        raise TmmError(f"{what} is not valid TOML (too deeply nested or a number too long); write lines like r0_mm = 41.2") from None
    if len(data) > ANSWERS_ROWS:
        raise TmmError(f"{what} has {len(data)} keys, over the limit of {ANSWERS_ROWS}; write only the answers")
    answers = {}
    for k, v in data.items():
        key = _answer_key(k, what)
        if isinstance(v, (dict, list)):
            raise TmmError(f"{what} ({key}): write a plain number, not a table or list")
        answers[key] = _cell(v, f"{what} ({key})")
    return answers


def _simple_lines(text: str, what: str, max_rows: int) -> dict | None:
    """`key = number` lines that TOML refused (a decimal comma, an unquoted key in Cyrillic or Greek
    letters); None when some line is of another form (then the TOML error stands)."""
    out: dict[str, str] = {}
    first: dict[str, int] = {}
    for i, line in enumerate(text.splitlines(), start=1):
        if not line.strip() or line.strip().startswith("#"):
            continue
        m = _LINE.fullmatch(line)
        if m is None:
            return None
        key = m.group("key").strip().strip('"')
        if key in out:
            raise TmmError(f"{what} line {i}: key {key} appears twice (first on line {first[key]}); keep one")
        value = m.group("value").strip()
        if len(value) >= 2 and value[0] == value[-1] and value[0] in "\"'":
            value = value[1:-1]
        out[key] = value
        first[key] = i
        if len(out) > max_rows:
            raise TmmError(f"{what} has {len(out)} keys, over the limit of {max_rows}; write only the answers")
    return out
