"""`tmm assign`: what each student of a roster is given — the assignment (задание на курсовой
проект): the variant's row of Table 1.2 for sheets 3 and 4, the crank speed and moment from the
roster where given, the dates — and, with ``--assign-variants``, distinct variants given out
reproducibly from a seed and written back into a copy of the roster.

Nothing is typeset here (render/assignment does that); nothing is written (the command does).
"""

from __future__ import annotations

import datetime as _dt
import random
import re
from pathlib import Path

from ..errors import TmmError
from ..records import record


@record
class Assignment:
    """One student's assignment."""

    student: str
    group: str
    fname: str  # the student's file name (names.file_name)
    variant: object  # variants.Variant
    crank_rpm: float | None
    torque_nm: float | None
    line: int  # the roster line
    drawn: bool = False  # the variant was given out by --assign-variants


@record
class AssignmentSet:
    """The group's assignments and what they share."""

    items: tuple  # Assignment, in roster order
    bad: tuple  # teacher.roster.BadRow: rows that get no assignment, with the reason
    issued: _dt.date
    due: _dt.date | None = None
    seed: int | None = None
    repeats: int = 0  # students who share a variant because the group outnumbers the table


def parse_date(text: str, what: str = "--due") -> _dt.date:
    """A date as teachers write it: 2026-05-15, 15.05.2026 or 15.05.26.

    >>> parse_date("2026-05-15"), parse_date("15.05.2026"), parse_date("1.3.26")
    (datetime.date(2026, 5, 15), datetime.date(2026, 5, 15), datetime.date(2026, 3, 1))
    """
    t = str(text).strip()
    try:
        m = re.fullmatch(r"(\d{4})-(\d{1,2})-(\d{1,2})", t)
        if m:
            return _dt.date(int(m.group(1)), int(m.group(2)), int(m.group(3)))
        m = re.fullmatch(r"(\d{1,2})\.(\d{1,2})\.(\d{2}|\d{4})", t)
        if m:
            year = int(m.group(3))
            return _dt.date(year + 2000 if year < 100 else year, int(m.group(2)), int(m.group(1)))
    except ValueError:
        pass
    raise TmmError(f"{what} '{t[:20]}' is not a date; write it as 15.05.2026 or 2026-05-15")


def give_variants(taken: list[int | None], table: list[int], seed: int) -> tuple[list[int], int]:
    """Variants for the students in roster order: a student who has one keeps it; the others draw,
    in a shuffle of `seed`, from the variants nobody has, each once; only when the group outnumbers
    the table does a variant go to a second student (a fresh shuffle of the whole table). Returns
    (the variants, how many students share one). The same roster and seed give the same variants.

    >>> give_variants([None, 17, None, None], list(range(1, 69)), seed=1)[0] == give_variants([None, 17, None, None], list(range(1, 69)), seed=1)[0]
    True
    >>> v, repeats = give_variants([None] * 5, [1, 2, 3], seed=7)
    >>> sorted(v[:3]), repeats
    ([1, 2, 3], 2)
    """
    rng = random.Random(seed)
    kept = [t for t in taken if t is not None]
    pool = [n for n in sorted(table) if n not in set(kept)]
    rng.shuffle(pool)
    out = []
    for t in taken:
        if t is not None:
            out.append(t)
            continue
        if not pool:
            pool = sorted(table)
            rng.shuffle(pool)
        out.append(pool.pop())
    counts: dict[int, int] = {}
    for n in out:
        counts[n] = counts.get(n, 0) + 1
    repeats = sum(c - 1 for c in counts.values() if c > 1)
    return out, repeats


def plan_assignments(roster: str | Path, *, variants_file=None, crank_rpm=None, torque_nm=None, assign: bool = False,
                     seed: int | None = None, issued: _dt.date | None = None, due: _dt.date | None = None) -> AssignmentSet:
    """The assignments of a roster. Without `assign` every row needs its variant (a row without
    one is a bad row); with it, the rows without a variant get one (:func:`give_variants`) —
    `seed` makes the draw reproducible (default 0)."""
    from ..variants import load_table
    from .roster import jobs_from_roster

    table = load_table(variants_file)
    plan = jobs_from_roster(roster, crank_rpm, torque_nm, variants_file, need_variant=not assign)
    jobs = list(plan.jobs)
    seed = 0 if seed is None else int(seed)
    repeats = 0
    drawn = [not j.variant for j in jobs]
    if assign:
        numbers, repeats = give_variants([int(j.variant) if j.variant else None for j in jobs], sorted(table), seed)
    else:
        numbers = [int(j.variant) for j in jobs]
    items = tuple(Assignment(j.label, j.group, j.fname, table[n], j.crank_rpm, j.torque_nm, j.line, d)
                  for j, n, d in zip(jobs, numbers, drawn))
    return AssignmentSet(items, tuple(plan.bad), issued or _dt.date.today(), due, seed if assign else None, repeats)


def roster_with_variants(roster: str | Path, items) -> bytes:
    """A copy of the roster with each student's variant filled in (a `variant` column added when
    it had none): the same columns, rows and separator, UTF-8 with a BOM, cells safe for a
    spreadsheet. Rows without an assignment (bad rows) are copied as they were."""
    from ..inputs.tables import delimiter, read_text, rows
    from ..limits import ROSTER_BYTES, ROSTER_ROWS
    from ..render.data.csv import safe_cell
    from .roster import _header_key

    src = read_text(roster, f"roster {roster}", ROSTER_BYTES)
    lines = rows(src.text, ROSTER_ROWS, f"roster {roster}")
    first = next((i for i, r in enumerate(lines) if r), 0)
    header = list(lines[first]) if lines else []
    keys = [_header_key(h) for h in header]
    if "variant" in keys:
        col = keys.index("variant")
    else:
        col = len(header)
        header.append("вариант" if any(re.search("[а-яё]", h.lower()) for h in header) else "variant")
    by_line = {a.line: a.variant.number for a in items}
    out_rows = [header]
    for lineno, raw in enumerate(lines[first + 1:], start=first + 2):
        if not raw:
            continue
        row = list(raw) + [""] * max(0, len(header) - len(raw))
        if lineno in by_line:
            row[col] = str(by_line[lineno])
        out_rows.append(row)
    import csv
    import io

    buf = io.StringIO()
    w = csv.writer(buf, delimiter=delimiter(src.text), lineterminator="\r\n")
    for r in out_rows:
        w.writerow([safe_cell(c) for c in r])
    return buf.getvalue().encode("utf-8-sig")


def assignment_file(fname: str) -> str:
    """assignment-Иванов_И._И.pdf."""
    return f"assignment-{fname}.pdf"


MERGED = "assignments.pdf"
ROSTER_COPY = "roster-with-variants.csv"
