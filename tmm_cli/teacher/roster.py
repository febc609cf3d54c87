"""The group to run: a list of variants or a class roster read into jobs, with the rows that cannot run."""

from __future__ import annotations

import re
from pathlib import Path

from .. import limits
from ..errors import TmmError
from ..inputs.names import collision_key, display_name, file_name
from ..inputs.tables import whole_number
from ..records import record

# ROSTER header names (English and what Russian teachers write) -> our keys
HEADER_ALIASES = {
    "student": ("student", "студент", "фио", "ф.и.о.", "ф. и. о.", "фамилия"),
    "variant": ("variant", "вариант", "вар", "вар."),
    "group": ("group", "группа"),
    "crank_rpm": ("crank_rpm", "n_кр", "n_kr", "nкр", "n кр"),
    "torque": ("torque", "torque_nm", "момент", "m_пр"),
    "mechanism": ("mechanism", "mechanism_file", "механизм", "файл механизма"),
}


ROSTER_COLUMNS = ("student", "variant", "group", "crank_rpm", "torque", "mechanism")


@record
class BatchJob:
    """One row of work: who, which variant (as given), the per-student inputs, its folder."""

    label: str
    variant: str
    crank_rpm: float | None = None
    torque_nm: float | None = None
    folder: str = ""  # relative to the output folder: variant-17 or Ivanov/variant-17
    group: str = ""
    fname: str = ""  # the student's file name (names.file_name), '' for a --variants run
    line: int = 0  # the roster line (rows are reported in roster order)
    mechanism: str = ""  # the student's mechanism file (absolute), '' for none: sheet 4's M and n_cr from it


@record
class BadRow:
    """A roster row that cannot run, and why."""

    job: BatchJob
    reason: str


@record
class Roster:
    jobs: list
    bad: list  # of BadRow
    path: Path
    encoding: str  # e.g. "cp1251 (Windows Cyrillic)"
    delimiter: str


def parse_variant_spec(spec: str, known: set[int] | None = None) -> list[int]:
    """'1-68', '3,17,40', '1-4,17' -> sorted unique variant numbers, all in `known` (the table).

    The numbers outside the table are refused before anything is expanded or run, so
    ``1-10000000`` costs nothing.

    >>> parse_variant_spec("3,17,1-2")
    [1, 2, 3, 17]
    >>> parse_variant_spec("1-99", set(range(1, 69)))
    Traceback (most recent call last):
    tmm_cli.errors.TmmError: --variants 1-99: 69-99 not in the table (it has variants 1-68); give numbers from 1 to 68
    """
    spec = str(spec)
    if len(spec) > limits.VARIANT_SPEC_CHARS:
        raise TmmError(f"--variants is {len(spec)} characters long, over {limits.VARIANT_SPEC_CHARS}; give ranges like 1-68")
    ranges = []
    for part in spec.split(","):
        part = part.strip()
        m = re.fullmatch(r"(\d{1,9})\s*-\s*(\d{1,9})", part)
        if m:
            lo, hi = int(m.group(1)), int(m.group(2))
            if lo > hi:
                raise TmmError(f"--variants range '{part}' runs backwards; write it as {hi}-{lo}")
            ranges.append((lo, hi))
        elif re.fullmatch(r"\d{1,9}", part):
            ranges.append((int(part), int(part)))
        else:
            shown = part if len(part) <= 20 and part.isprintable() else part[:20].encode("unicode_escape").decode() + "…"
            raise TmmError(f"--variants '{spec[:40]}' is not a list like 1-68 or 3,17,40; fix '{shown}'")
    if known is not None:
        lo_t, hi_t = min(known), max(known)
        outside = []
        for lo, hi in ranges:
            if hi < lo_t or lo > hi_t:
                outside.append((lo, hi))
            else:
                if lo < lo_t:
                    outside.append((lo, lo_t - 1))
                if hi > hi_t:
                    outside.append((hi_t + 1, hi))
        if outside:
            text = ", ".join(f"{a}" if a == b else f"{a}-{b}" for a, b in outside[:5])
            raise TmmError(f"--variants {spec[:40]}: {text} not in the table (it has variants {lo_t}-{hi_t}); "
                           f"give numbers from {lo_t} to {hi_t}")
        numbers = sorted({n for lo, hi in ranges for n in known if lo <= n <= hi})
        gaps = sorted({n for lo, hi in ranges if lo == hi for n in (lo,)} - set(numbers))
        if gaps:
            raise TmmError(f"--variants: variant {gaps[0]} is not in the table; choose from {lo_t} to {hi_t}")
    else:
        if sum(hi - lo + 1 for lo, hi in ranges) > limits.VARIANT_SPEC_COUNT:
            raise TmmError(f"--variants asks for over {limits.VARIANT_SPEC_COUNT} variants; give a shorter list")
        numbers = sorted({n for lo, hi in ranges for n in range(lo, hi + 1)})
    if len(numbers) > limits.VARIANT_SPEC_COUNT:
        raise TmmError(f"--variants asks for {len(numbers)} variants, over {limits.VARIANT_SPEC_COUNT}; split the batch")
    return numbers


def jobs_from_spec(spec: str, crank_rpm: float | None, torque_nm: float | None, variants_file=None) -> list[BatchJob]:
    from ..variants import load_table

    numbers = parse_variant_spec(spec, set(load_table(variants_file)))
    return [BatchJob(label=f"variant {n}", variant=str(n), crank_rpm=crank_rpm, torque_nm=torque_nm, folder=f"variant-{n:02d}")
            for n in numbers]


def _header_key(cell: str) -> str:
    from ..inputs.names import clean_text

    h = clean_text(cell).lower()
    h = re.split(r"\s*[\[(]|,\s", h)[0].strip()
    for key, names in HEADER_ALIASES.items():
        if h in names:
            return key
    return h


def _opt(raw: str, name: str, default, lo, hi):
    raw = (raw or "").strip()
    if not raw:
        return default
    from ..inputs.tables import parse_number

    value = parse_number(raw, name)
    return limits.check_range(value, lo, hi, name)


def _mechanism_path(raw: str, roster: Path) -> str:
    """The absolute path of a roster row's mechanism file ('' for an empty cell), refused when it
    leads outside the roster's folder (``../``, an absolute path, a link out) or does not exist."""
    raw = (raw or "").strip()
    if not raw:
        return ""
    root = roster.resolve().parent
    shown = raw if len(raw) <= 60 and raw.isprintable() else raw[:60].encode("unicode_escape").decode() + "…"
    try:
        target = (root / raw).resolve()
    except (OSError, RuntimeError, ValueError):
        raise TmmError(f"the mechanism file {shown} does not exist (a path relative to the roster's folder)") from None
    if not target.is_relative_to(root):
        raise TmmError(f"the mechanism file {shown} lies outside the roster's folder; put it beside the roster or below it")
    if not target.is_file():
        raise TmmError(f"the mechanism file {shown} does not exist (a path relative to the roster's folder)")
    return str(target)


def jobs_from_roster(path: str | Path, crank_rpm: float | None, torque_nm: float | None, variants_file=None,
                     need_variant: bool = True) -> Roster:
    """Read a roster (student,variant[,group][,crank_rpm][,torque][,mechanism], English or Russian headers).

    A `mechanism` cell names the student's mechanism file, relative to the roster's folder and
    inside it (sheet 4 then takes the driving moment and the crank speed from it: the row's own
    crank_rpm and torque must stay empty).

    A bad row (no name, a variant not in the table, a value out of range, two names sharing one
    file name) is returned with its reason among `bad`; a file without the student and variant
    columns, over the size limits, or not text, is an error for the whole roster. With
    `need_variant` False (`tmm assign --assign-variants`) the variant column may be missing or
    empty: such a row is a job with the variant "" (the variants are given out afterwards).
    """
    from ..inputs.tables import delimiter, read_text, rows
    from ..variants import load_table

    src = read_text(path, f"roster {path}", limits.ROSTER_BYTES)
    table = load_table(variants_file)
    lines = rows(src.text, limits.ROSTER_ROWS, f"roster {path}")
    first = next((i for i, r in enumerate(lines) if r), None)
    header = [_header_key(h) for h in (lines[first] if first is not None else [])]
    missing = [c for c in (("student", "variant") if need_variant else ("student",)) if c not in header]
    if missing:
        raise TmmError(f"roster {path} has no column(s) {', '.join(missing)}; the header must be "
                       f"student,variant[,group][,crank_rpm][,torque][,mechanism] (or студент;вариант;группа;n_кр;момент;"
                       f"механизм)")
    col = {k: header.index(k) for k in ROSTER_COLUMNS if k in header}
    jobs: list[BatchJob] = []
    bad: list[BadRow] = []
    seen: dict[str, tuple[int, str]] = {}
    for lineno, raw in enumerate(lines[first + 1:], start=first + 2):
        if not raw:
            continue
        cell = {k: (raw[i] if i < len(raw) else "").strip() for k, i in col.items()}
        student = display_name(cell["student"])
        group = display_name(cell.get("group", ""))
        label = student or f"line {lineno}"
        variant = cell.get("variant", "")[:10]
        try:
            if not student:
                raise TmmError("the student column is empty")
            if not variant and need_variant:
                raise TmmError("the variant column is empty")
            pending = not variant  # given out later (tmm assign --assign-variants)
            if not pending and whole_number(variant) not in table:
                raise TmmError(f"variant {variant} is not in the table; choose a variant from {min(table)} to {max(table)}")
            mechanism = _mechanism_path(cell.get("mechanism", ""), Path(path))
            if mechanism:
                given = [k for k in ("crank_rpm", "torque") if (cell.get(k) or "").strip()]
                if given:
                    raise TmmError(f"the row gives a mechanism file and {' and '.join(given)}; the mechanism gives "
                                   f"sheet 4 its moment and crank speed: leave {' and '.join(given)} empty")
                crank, torque = None, None
            else:
                crank = _opt(cell.get("crank_rpm"), "crank_rpm", crank_rpm, *limits.CRANK_RPM)
                torque = _opt(cell.get("torque"), "torque", torque_nm, *limits.TORQUE_NM)
            fname = file_name(student)
            if not fname:
                raise TmmError("the name has no letter or digit to name a file by")
            key = collision_key(fname)
            if key in seen:
                line0, name0 = seen[key]
                raise TmmError(f"'{student}' gives the same file name '{fname}' as '{name0}' on line {line0} "
                               f"(names differing only in case or punctuation share one file); make the names differ")
            seen[key] = (lineno, student)
        except TmmError as exc:
            bad.append(BadRow(BatchJob(label=label, variant=variant, group=group, line=lineno),
                              f"roster line {lineno}: {exc}"))
            continue
        if pending:  # no variant yet
            jobs.append(BatchJob(label=student, variant="", crank_rpm=crank, torque_nm=torque, folder="", group=group,
                                 fname=fname, line=lineno, mechanism=mechanism))
            continue
        n = int(variant)
        jobs.append(BatchJob(label=student, variant=str(n), crank_rpm=crank, torque_nm=torque,
                             folder=f"{fname}/variant-{n:02d}", group=group, fname=fname, line=lineno,
                             mechanism=mechanism))
    if not jobs and not bad:
        raise TmmError(f"roster {path} has a header but no students; add one row per student")
    return Roster(jobs, bad, Path(path), src.encoding_name, delimiter(src.text))
