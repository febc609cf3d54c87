"""The records of a check (a row per answer, a student's report, the group's) and the comparison of
one answer with one value, shared by the check and the modules that accept other designs."""

from __future__ import annotations

import math
from dataclasses import field

from ..i18n.lang import note_text
from ..notes import Note
from ..records import record
from .keys import ANSWER_KEYS, KEYS_BY_NAME, REQUIRED, SHEETS, AnswerKey, resolve_key

PASS_STATUSES = ("pass", "pass (book)", "pass (valid alternative)", "pass (book roller)", "pass (book roller, undercuts)",
                 "pass (other swing)")


@record
class Place:
    """Where the book explains a quantity: its section, the steps of the procedure, the equation
    or table; or a page of this project's docs for what lies beyond the book."""

    section: str = ""
    steps: str = ""
    eq: str = ""
    table: str = ""
    doc: str = ""


@record
class CheckRow:
    key: str
    expected: object  # the value compared with (see `basis`)
    given: object
    deviation_pct: float | None
    status: str  # PASS_STATUSES, "fail", "missing", "unknown key", "not computed", "unreadable", "duplicate", "not checked"
    deviation: float | None = None  # given − expected, in the key's unit
    tolerance_pct: float | None = None  # None: must match exactly
    tolerance: float | None = None  # the same in the key's unit (e: per cent of r0)
    basis: str = "program"  # program | book_vertex | book_roller | other_swing | student_set | variant
    written: str = ""  # the name the student wrote (r_0 for r0_mm)
    cause: Note | None = None  # the likely cause of a failure, or a remark on a pass (diagnose.py)
    place: Place | None = None  # where to look in the book
    program: object = None  # the program's own value when `expected` is another design's

    @property
    def passed(self) -> bool:
        return self.status in PASS_STATUSES

    def to_json(self, lang: str = "en") -> dict:
        out = {k: v for k, v in self.__dict__.items() if k not in ("cause", "place")}
        out["cause"] = None if self.cause is None else {"code": self.cause.code, "text": note_text(self.cause, lang)}
        out["place"] = None if self.place is None else {k: v for k, v in self.place.__dict__.items() if v}
        return out


@record
class CheckReport:
    label: str
    variant: int
    rtol_pct: float
    rows: tuple[CheckRow, ...]
    error: str = ""
    notes: tuple = ()  # Note objects the comparison rests on (e.g. the assumed crank speed)
    required: tuple[str, ...] = ()  # the keys this variant requires (see REQUIRED)
    group: str = ""
    findings: tuple = ()  # Note objects about the whole answer (a valid alternative reducer, a shift that fails)
    fname: str = ""  # the student's file name (roster), for the feedback file and the group page
    answers_file: str = ""  # the answers file read (its name)
    line: int = 0  # the roster line
    set_ratio_error_pct: float | None = None  # the ratio error of the student's own tooth set (when complete)
    ratio_tolerance_pct: float = 5.0  # the reducer's ratio tolerance in force

    @property
    def passed(self) -> bool:
        return not self.error and bool(self.rows) and all(r.passed for r in self.rows)

    @property
    def missing(self) -> tuple[str, ...]:
        return tuple(r.key for r in self.rows if r.status == "missing")

    def to_json(self, lang: str = "en") -> dict:
        return {
            "student": self.label,
            "group": self.group,
            "variant": self.variant,
            "rtol_pct": self.rtol_pct,
            "passed": self.passed,
            "error": self.error or None,
            "answers_file": self.answers_file or None,
            "required": list(self.required),
            "missing": list(self.missing),
            "assumptions": [note_text(n, lang) for n in self.notes],
            "findings": [{"code": n.code, "text": note_text(n, lang)} for n in self.findings],
            "set_ratio_error_pct": self.set_ratio_error_pct,
            "ratio_tolerance_pct": self.ratio_tolerance_pct,
            "file_name": self.fname or None,
            "rows": [r.to_json(lang) for r in self.rows],
        }


@record
class GroupReport:
    reports: tuple[CheckReport, ...] = field(default=())
    roster_encoding: str = ""
    roster_delimiter: str = ","
    unmatched: tuple = ()  # (file name, the roster name it most resembles or "") of answers files no student has

    @property
    def all_passed(self) -> bool:
        return all(r.passed for r in self.reports)

    def to_json(self, lang: str = "en") -> dict:
        return {"all_passed": self.all_passed, "students": [r.to_json(lang) for r in self.reports],
                "unmatched_files": [{"file": f, "closest_student": s or None} for f, s in self.unmatched]}

    def keys(self) -> list[str]:
        """The keys the group's students were checked on: in `tmm check --keys` order, then others."""
        seen = {r.key for rep in self.reports for r in rep.rows}
        order = [k.key for k in ANSWER_KEYS if k.key in seen]
        return order + sorted(seen - set(order))


def csv_delimiter(lines: list[str]) -> str:
    """',' or ';' (what a spreadsheet saves under a Russian locale), from the first non-empty line."""
    from ..inputs.tables import delimiter

    return delimiter("\n".join(lines))


def lookup(doc: dict, path: tuple):
    """The value at `path` in the project document, or None."""
    cur = doc
    for part in path:
        try:
            cur = cur[part]
        except (KeyError, IndexError, TypeError):
            return None
    return cur


_lookup = lookup


def required_keys(doc: dict, sheets=SHEETS) -> tuple[str, ...]:
    """The keys required for `sheets` that this variant computes (see REQUIRED)."""
    return tuple(k for sheet in sorted(sheets) for k in REQUIRED[sheet] if lookup(doc, KEYS_BY_NAME[k].path) is not None)


def resolved(answers: dict) -> dict:
    """The answers by answer key (the first of two names of one key wins; unknown names left out)."""
    out: dict = {}
    for written, value in answers.items():
        key = resolve_key(written)
        if key is not None and key not in out:
            out[key] = value
    return out


def _scale(doc: dict, spec: AnswerKey, expected) -> float:
    return abs(float(lookup(doc, spec.scale_path) or 0.0)) if spec.scale_path else abs(float(expected))


def _deviation_pct(doc: dict, spec: AnswerKey, expected, given) -> float:
    """Signed deviation of `given` from `expected` in per cent of the key's scale."""
    scale = _scale(doc, spec, expected)
    diff = float(given) - float(expected)
    return 100.0 * diff / scale if scale > 0 else (0.0 if diff == 0 else math.inf)


def row_against(doc: dict, spec: AnswerKey, expected, given, rtol_pct: float, *, basis: str = "program",
                written: str = "", program=None, pass_status: str = "pass") -> CheckRow:
    """One answer compared with one value: exactly (whole numbers, the variant's data) or within
    `rtol_pct` per cent of the key's scale."""
    diff = float(given) - float(expected)
    if spec.kind in ("int", "input"):
        ok = diff == 0
        dev = None if expected == 0 else 100.0 * diff / abs(float(expected))
        return CheckRow(spec.key, expected, given, dev, pass_status if ok else "fail", diff, None, None, basis, written,
                        program=program)
    dev = _deviation_pct(doc, spec, expected, given)
    ok = abs(dev) <= rtol_pct + 1e-9
    tol = rtol_pct / 100.0 * _scale(doc, spec, expected)
    return CheckRow(spec.key, expected, given, dev if math.isfinite(dev) else None, pass_status if ok else "fail", diff,
                    rtol_pct, tol, basis, written, program=program)


