"""Checking a student's numbers against the computed project (`tmm check`).

The expected values are read from the project's JSON document (the content of results.json),
so the check compares against exactly what `tmm project` reports. Integers (tooth numbers,
planets, motor speed) must match exactly; graphical quantities (r0, e, l_OC, ε_α, pressure
angles …) within a relative tolerance, 3 % by default. A different design that the book's method
allows passes too, marked as such: the book's two-line cam vertex, the book's roller, the other
swing of a rocker, and a planetary set that meets every condition of §2.1.3 (a *valid
alternative*; what derives from it is checked against it).

Every row says what it was compared with, the deviation, the tolerance, and — in :mod:`.diagnose`
— where the book explains it and the likely cause of a failure. One bad cell fails that key only;
one student whose check breaks fails that student only; the group is always checked to the end.
"""

from __future__ import annotations

import os
from pathlib import Path

from ..errors import TmmError
from ..i18n import tr
from ..inputs.tables import whole_number
from ..notes import Note
from .answers import Unreadable, read_answers  # noqa: F401  (read_answers: the public reader)
from .keys import ANSWER_KEYS, KEYS_BY_NAME, REQUIRED, SHEETS, resolve_key, suggest_key  # noqa: F401
from .rows import (  # noqa: F401  (the records, here for the commands and renderers that name them)
    PASS_STATUSES,
    CheckReport,
    CheckRow,
    GroupReport,
    Place,
    csv_delimiter,
    lookup,
    required_keys,
    resolved,
    row_against,
)

def compare(doc: dict, answers: dict, rtol_pct: float, required=()) -> tuple[CheckRow, ...]:
    """Compare answers with a project JSON document: one row per given key (unknown keys with the
    nearest key as a suggestion, a cell that is not a number as "unreadable", a key given twice
    under two names as "duplicate"), then one "missing" row per required key not given."""
    rows = []
    first: dict[str, str] = {}
    for written, given in answers.items():
        key = resolve_key(written)
        if key is None:
            hint = suggest_key(written)
            cause = Note.make("key_suggest", key=hint) if hint else Note.make("key_unknown")
            rows.append(CheckRow(written, None, given.raw if isinstance(given, Unreadable) else given, None, "unknown key",
                                 written=written, cause=cause))
            continue
        spec = KEYS_BY_NAME[key]
        expected = lookup(doc, spec.path)
        if key in first:
            rows.append(CheckRow(key, expected, given.raw if isinstance(given, Unreadable) else given, None, "duplicate",
                                 written=written, cause=Note.make("key_duplicate", first=first[key], written=written)))
            continue
        first[key] = written
        if isinstance(given, Unreadable):
            rows.append(CheckRow(key, expected, given.raw, None, "unreadable", written=written,
                                 cause=Note.make("cell_unreadable", raw=given.raw) if given.raw
                                 else Note.make("cell_not_number")))
            continue
        if expected is None:
            rows.append(CheckRow(key, None, given, None, "not computed", written=written))
            continue
        rows.append(row_against(doc, spec, expected, given, rtol_pct, basis="variant" if spec.kind == "input" else "program",
                                written=written))
    for key in required:
        if key not in first:
            rows.append(CheckRow(key, lookup(doc, KEYS_BY_NAME[key].path), None, None, "missing"))
    return tuple(rows)


def check_one(variant, answers: dict, *, crank_rpm=None, torque_nm=None, rtol_pct: float = 3.0, label: str = "",
              lang: str = "en", sheets=SHEETS, group: str = "") -> CheckReport:
    """Run the project for the variant and compare the answers with it; the keys `sheets`
    require (REQUIRED) and the student omitted fail as "missing".

    The student's shifts x1, x2 are carried (the spur pair is recomputed with them); shifts that
    make no pair fail x1 and x2 with the reason, and the quantities that depend on them are "not
    checked", the rest is checked against the unshifted pair.
    """
    from ..limits import RTOL_PCT, check_range
    from ..project import run_project
    from ..render.data.project import project_document
    from .alternatives import accept_book_cam, accept_valid_reducer
    from .diagnose import diagnose

    rtol_pct = check_range(rtol_pct, *RTOL_PCT, "--rtol", " per cent")
    if not answers:
        raise TmmError("the answers file has no values; write lines like r0_mm = 41.2 (see `tmm check --keys`)")
    by_key = resolved(answers)
    shift = student_shift(by_key)
    shift_error = ""
    try:
        result = run_project(variant, crank_rpm=crank_rpm, torque_nm=torque_nm, shift=shift)
    except (TmmError, ArithmeticError, ValueError) as exc:
        if shift is None:
            raise
        from ..i18n.errors import error_text

        shift_error = error_text(str(exc), lang) if isinstance(exc, TmmError) else \
            tr(lang, "the pair's geometry cannot be computed")
        result = run_project(variant, crank_rpm=crank_rpm, torque_nm=torque_nm, shift=None)
    doc = project_document(result, lang)
    required = required_keys(doc, sheets)
    rows = compare(doc, answers, rtol_pct, required)
    findings: list[Note] = []
    if shift_error:
        rows = _shift_failed(rows, shift, shift_error)
        findings.append(Note.make("shift_impossible", x1=shift[0], x2=shift[1], reason=shift_error))
    rows, found, reducer = accept_valid_reducer(rows, by_key, result.gears, doc, rtol_pct)
    findings += found
    rows = accept_book_cam(rows, by_key, result.cam, rtol_pct)
    rows = diagnose(rows, doc, by_key, result)
    # the tooth numbers depend on the crank speed: say when the book's 220 rpm was assumed
    notes = tuple(n for n in result.gears.notes if n.code == "crank_default")
    return CheckReport(label=label or f"variant {variant.number}", variant=variant.number, rtol_pct=rtol_pct,
                       rows=rows, notes=notes, required=required, group=group, findings=tuple(findings),
                       set_ratio_error_pct=None if reducer is None or reducer.ratio_error_pct is None
                       else round(reducer.ratio_error_pct, 4),
                       ratio_tolerance_pct=result.gears.tolerance_pct)


SHIFT_DEPENDENT = ("a_w_mm", "alpha_w_deg", "eps_alpha")


def _shift_failed(rows, shift, reason: str) -> tuple[CheckRow, ...]:
    """x1, x2 that make no pair fail with the reason; what depends on them is not checked."""
    out = []
    for r in rows:
        if r.key in ("x1", "x2") and r.status not in ("unreadable", "duplicate", "unknown key"):
            r = CheckRow(r.key, None, r.given, None, "fail", written=r.written,
                         cause=Note.make("shift_impossible", x1=shift[0], x2=shift[1], reason=reason))
        elif r.key in SHIFT_DEPENDENT and r.status not in ("unreadable", "duplicate", "unknown key"):
            r = CheckRow(r.key, None, r.given, None, "not checked", written=r.written,
                         cause=Note.make("depends_on_shift"))
        out.append(r)
    return tuple(out)


def student_shift(answers: dict) -> tuple[float, float] | None:
    """The spur pair's shifts the student chose (answers x1, x2; a missing or unreadable one is 0),
    or None for the book's zero pair: the project is then recomputed with those shifts, as
    ``tmm gears --shift x1,x2`` does, so a_w_mm, alpha_w_deg, a_mm and eps_alpha are checked for
    the student's own pair (the shift is a design choice, not a result to match)."""
    def value(k):
        v = answers.get(k)
        return float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else 0.0

    x1, x2 = value("x1"), value("x2")
    return None if x1 == 0.0 and x2 == 0.0 else (x1, x2)


def answers_file(answers_dir: Path, fname: str) -> Path | None:
    """The student's answers file ``<fname>.toml`` or ``<fname>.csv`` inside `answers_dir`, or None.

    `fname` comes from :func:`tmm_cli.inputs.names.file_name` (one path component, no '..'); a candidate
    that is a symbolic link or resolves outside `answers_dir` is refused, so the check never
    reads a file outside the folder the teacher named.
    """
    from ..inputs.names import collision_key

    root = Path(answers_dir).resolve()
    by_key = None
    for ext in (".toml", ".csv"):
        cand = Path(answers_dir) / f"{fname}{ext}"
        if not os.path.lexists(cand):
            if by_key is None:  # Ivanov.toml saved as ivanov.TOML: accept one file that differs only in case
                by_key = {}
                with os.scandir(answers_dir) as it:
                    for i, entry in enumerate(it):
                        if i >= 10000:
                            break
                        by_key.setdefault(collision_key(entry.name), []).append(entry.name)
            same = by_key.get(collision_key(cand.name), [])
            if len(same) != 1:
                continue
            cand = Path(answers_dir) / same[0]
        if os.path.islink(cand) or cand.resolve().parent != root:
            raise TmmError(f"answers file {cand.name} is a link or lies outside {answers_dir}; "
                           f"put the student's own file there")
        if not cand.is_file():
            raise TmmError(f"answers file {cand.name} is not a regular file")
        return cand
    return None


ANSWER_SUFFIXES = (".toml", ".csv")


def unmatched_files(answers_dir: Path, used: set[str], names: dict[str, str]) -> tuple[tuple[str, str], ...]:
    """The answers files (``*.toml``, ``*.csv``) in `answers_dir` that no student of the roster
    owns: (file name, the student whose file name it most resembles, or ""). `used` holds the
    file names the check read, `names` maps each student's file name to the student."""
    import difflib

    from ..inputs.names import collision_key

    out = []
    used_keys = {collision_key(n) for n in used}
    stems = {collision_key(f): s for f, s in names.items()}
    with os.scandir(answers_dir) as it:
        for i, entry in enumerate(it):
            if i >= 10000:
                break
            name = entry.name
            if name.startswith(".") or os.path.splitext(name)[1].lower() not in ANSWER_SUFFIXES:
                continue
            if collision_key(name) in used_keys:
                continue
            stem = collision_key(os.path.splitext(name)[0])
            close = difflib.get_close_matches(stem, list(stems), n=1, cutoff=0.6)
            out.append((name, stems[close[0]] if close else ""))
    return tuple(sorted(out))


def check_group(roster, answers_dir, *, variants_file=None, crank_rpm=None, torque_nm=None, rtol_pct: float = 3.0,
                sheets=SHEETS, lang: str = "en") -> GroupReport:
    """Check every student of a roster against ``<file name>.toml`` / ``.csv`` in `answers_dir`
    (the name-to-file rule of :func:`tmm_cli.inputs.names.file_name`, as `tmm batch` names folders).

    A student whose check cannot run (no file, an unreadable file, a bug) gets that reason and the
    others are checked; files in `answers_dir` that belong to nobody are listed.
    """
    from ..limits import RTOL_PCT, check_range
    from ..variants import get_variant
    from .roster import jobs_from_roster

    rtol_pct = check_range(rtol_pct, *RTOL_PCT, "--rtol", " per cent")
    d = Path(answers_dir)
    if not d.is_dir():
        raise TmmError(f"answers folder {d} does not exist; give the folder with one file per student")
    plan = jobs_from_roster(roster, crank_rpm, torque_nm, variants_file)
    reports = [(b.job.line, CheckReport(label=b.job.label, variant=whole_number(b.job.variant) or 0,
                                        rtol_pct=rtol_pct, rows=(), error=b.reason, group=b.job.group, line=b.job.line))
               for b in plan.bad]
    used: set[str] = set()
    for b in plan.bad:  # a row that cannot run still owns its file: it is not "unmatched"
        from ..inputs.names import file_name

        fn = file_name(b.job.label)
        used.update(f"{fn}{ext}" for ext in ANSWER_SUFFIXES if fn)
    for job in plan.jobs:
        number = whole_number(job.variant) or 0
        found = None
        try:
            v = get_variant(job.variant, variants_file)
            found = answers_file(d, job.fname)
            if found is None:
                raise TmmError(f"no answers file {job.fname}.toml or {job.fname}.csv in {d}")
            used.add(found.name)
            rep = check_one(v, read_answers(found), crank_rpm=job.crank_rpm, torque_nm=job.torque_nm, rtol_pct=rtol_pct,
                            label=job.label, sheets=sheets, group=job.group, lang=lang)
            from dataclasses import replace

            reports.append((job.line, replace(rep, fname=job.fname, answers_file=found.name, line=job.line)))
        except TmmError as exc:
            reports.append((job.line, CheckReport(label=job.label, variant=number, rtol_pct=rtol_pct, rows=(),
                                                  error=str(exc), group=job.group, fname=job.fname, line=job.line,
                                                  answers_file=found.name if found else "")))
        except Exception as exc:  # a bug must not stop the group's check: this student's row says it
            from ..output.interrupt import received

            if os.environ.get("TMM_DEBUG") or received() is not None:  # a signal's error is an interruption
                raise
            reports.append((job.line, CheckReport(label=job.label, variant=number, rtol_pct=rtol_pct, rows=(),
                                                  error=f"internal error {exc.__class__.__name__}: {exc}", group=job.group,
                                                  fname=job.fname, line=job.line,
                                                  answers_file=found.name if found else "")))
    reports.sort(key=lambda lr: lr[0])  # roster order
    unmatched = unmatched_files(d, used, {j.fname: j.label for j in plan.jobs})
    return GroupReport(tuple(r for _, r in reports), plan.encoding, plan.delimiter, unmatched)
