"""Checking a student's numbers against the computed project (`tmm check`).

The expected values are read from the project's JSON document (the content of results.json),
so the check compares against exactly what `tmm project` reports. Integers (tooth numbers,
planets, motor speed) must match exactly; graphical quantities (r0, e, l_OC, ε_α, pressure
angles …) within a relative tolerance, 3 % by default.
"""

from __future__ import annotations

import math
import os
import re
import tomllib
from dataclasses import field
from pathlib import Path

from ..errors import TmmError
from ..i18n.lang import note_text
from ..records import record


@record
class AnswerKey:
    key: str
    path: tuple  # path into the project JSON document
    kind: str  # "int" exact, "float" within tolerance
    en: str
    ru: str
    scale_path: tuple | None = None  # tolerance relative to this value instead (e.g. e relative to r0)
    book_path: tuple | None = None  # the book's graphical answer, also accepted (status "pass (book)")


def _k(key, path, kind, en, ru, scale_path=None, book_path=None):
    return AnswerKey(key, tuple(path), kind, en, ru, None if scale_path is None else tuple(scale_path),
                     None if book_path is None else tuple(book_path))


ANSWER_KEYS: tuple[AnswerKey, ...] = (
    _k("n_motor_rpm", ("gears", "motor", "n_rpm"), "int", "motor speed n_d [rpm]", "частота вращения двигателя n_д [об/мин]"),
    _k("i_spur", ("gears", "i_spur"), "float", "spur-pair ratio i_d", "передаточное отношение простой передачи"),
    _k("i_planetary", ("gears", "i_planetary"), "float", "planetary ratio i_pl", "передаточное отношение планетарного редуктора"),
    _k("z_sun", ("gears", "planetary", "stages", 0, "z_sun"), "int", "sun teeth z_k (stage 1)", "число зубьев центрального колеса z_k"),
    _k("z_planet", ("gears", "planetary", "stages", 0, "z_planet"), "int", "planet teeth z_c (stage 1)", "число зубьев сателлита z_c"),
    _k("z_planet2", ("gears", "planetary", "stages", 0, "z_planet2"), "int", "second planet row z_c′ (scheme 2)", "число зубьев второго венца сателлита z_c′"),
    _k("z_ring", ("gears", "planetary", "stages", 0, "z_ring"), "int", "ring teeth z_n (stage 1)", "число зубьев корончатого колеса z_n"),
    _k("planets", ("gears", "planetary", "stages", 0, "planets"), "int", "number of planets k (stage 1)", "число сателлитов k"),
    _k("z_sun_2", ("gears", "planetary", "stages", 1, "z_sun"), "int", "sun teeth, stage 2", "z_k второй ступени"),
    _k("z_planet_2", ("gears", "planetary", "stages", 1, "z_planet"), "int", "planet teeth, stage 2", "z_c второй ступени"),
    _k("z_ring_2", ("gears", "planetary", "stages", 1, "z_ring"), "int", "ring teeth, stage 2", "z_n второй ступени"),
    _k("planets_2", ("gears", "planetary", "stages", 1, "planets"), "int", "planets, stage 2", "число сателлитов второй ступени"),
    _k("z1", ("gears", "spur", "z1"), "int", "spur pinion teeth z1", "число зубьев шестерни z1"),
    _k("z2", ("gears", "spur", "z2"), "int", "spur wheel teeth z2", "число зубьев колеса z2"),
    _k("a_mm", ("gears", "spur", "a_mm"), "float", "spur centre distance a [mm]", "межосевое расстояние a [мм]"),
    _k("eps_alpha", ("gears", "spur", "eps_alpha"), "float", "transverse contact ratio ε_α", "коэффициент перекрытия ε_α"),
    _k("x1", ("gears", "spur", "x1"), "float", "spur shift x1 (the pair is recomputed with the given x1, x2; 0: the book's)", "коэффициент смещения x1 (пара пересчитывается с заданными x1, x2)"),
    _k("x2", ("gears", "spur", "x2"), "float", "spur shift x2 (the pair is recomputed with the given x1, x2; 0: the book's)", "коэффициент смещения x2 (пара пересчитывается с заданными x1, x2)"),
    _k("a_w_mm", ("gears", "spur", "a_w_mm"), "float", "spur working centre distance a_w [mm]", "межосевое расстояние a_w [мм]"),
    _k("alpha_w_deg", ("gears", "spur", "alpha_w_deg"), "float", "spur working pressure angle α_w [deg]", "угол зацепления α_w [°]"),
    _k("r0_mm", ("cam", "r0_mm"), "float", "cam base radius r0 [mm] (the book's vertex is accepted too)",
       "минимальный радиус кулачка r_0 [мм] (принимается и вершина по пособию)", book_path=("cam", "book_vertex", "r0_mm")),
    _k("e_mm", ("cam", "e_mm"), "float", "offset e [mm] (tolerance relative to r0; the book's vertex accepted)",
       "эксцентриситет e [мм] (допуск от r_0; принимается и вершина по пособию)", ("cam", "r0_mm"), ("cam", "book_vertex", "e_mm")),
    _k("l_oc_mm", ("cam", "l_oc_mm"), "float", "centre distance l_OC [mm] (the book's vertex accepted)",
       "межцентровое расстояние l_OC [мм] (принимается и вершина по пособию)", book_path=("cam", "book_vertex", "l_oc_mm")),
    _k("roller_mm", ("cam", "roller_mm"), "float", "roller radius r_p [mm] (the book's 0.2·r0 accepted, marked)", "радиус ролика r_p [мм] (принимается и 0,2·r0 по пособию)"),
    _k("nu_rise_deg", ("cam", "pressure_angle_max_deg", "rise"), "float", "max pressure angle on rise [deg]", "максимальный угол давления на удалении [°]"),
    _k("nu_return_deg", ("cam", "pressure_angle_max_deg", "return"), "float", "max pressure angle on return [deg]", "максимальный угол давления на возвращении [°]"),
    _k("psi_rise_deg", ("cam", "psi_deg", "rise"), "float", "profile angle ψ_у [deg]", "профильный угол удаления ψ_у [°]"),
    _k("psi_far_dwell_deg", ("cam", "psi_deg", "far_dwell"), "float", "profile angle ψ_дс [deg]", "профильный угол дальнего стояния ψ_дс [°]"),
    _k("psi_return_deg", ("cam", "psi_deg", "return"), "float", "profile angle ψ_в [deg]", "профильный угол возвращения ψ_в [°]"),
)
KEYS_BY_NAME = {k.key: k for k in ANSWER_KEYS}

# The keys a student must give for each sheet (those the variant computes: z_planet2 only for
# scheme 2, the stage-2 keys only for a two-stage reducer, e_mm for a translating follower,
# l_oc_mm for a rocker). A missing required key fails the check.
REQUIRED = {
    "4": ("n_motor_rpm", "z_sun", "z_planet", "z_planet2", "z_ring", "planets",
          "z_sun_2", "z_planet_2", "z_ring_2", "planets_2", "z1", "z2", "eps_alpha"),
    "3": ("r0_mm", "e_mm", "l_oc_mm"),
}
SHEETS = ("3", "4")
_KEY = re.compile(r"[A-Za-z_][A-Za-z0-9_]{0,39}")


@record
class CheckRow:
    key: str
    expected: object
    given: object
    deviation_pct: float | None
    status: str  # "pass", "pass (book)", "pass (valid set)", "fail", "missing", "unknown key", "not computed"


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

    @property
    def passed(self) -> bool:
        return not self.error and bool(self.rows) and all(r.status.startswith("pass") for r in self.rows)

    @property
    def missing(self) -> tuple[str, ...]:
        return tuple(r.key for r in self.rows if r.status == "missing")

    def to_json(self) -> dict:
        return {
            "student": self.label,
            "variant": self.variant,
            "rtol_pct": self.rtol_pct,
            "passed": self.passed,
            "error": self.error or None,
            "required": list(self.required),
            "missing": list(self.missing),
            "assumptions": [note_text(n, "en") for n in self.notes],
            "rows": [r.__dict__ for r in self.rows],
        }


@record
class GroupReport:
    reports: tuple[CheckReport, ...] = field(default=())
    roster_encoding: str = ""
    roster_delimiter: str = ","

    @property
    def all_passed(self) -> bool:
        return all(r.passed for r in self.reports)

    def to_json(self) -> dict:
        return {"all_passed": self.all_passed, "students": [r.to_json() for r in self.reports]}

    def keys(self) -> list[str]:
        """The keys the group's students were checked on: in `tmm check --keys` order, then others."""
        seen = {r.key for rep in self.reports for r in rep.rows}
        order = [k.key for k in ANSWER_KEYS if k.key in seen]
        return order + sorted(seen - set(order))


def csv_delimiter(lines: list[str]) -> str:
    """',' or ';' (what a spreadsheet saves under a Russian locale), from the first non-empty line."""
    from ..inputs.tables import delimiter

    return delimiter("\n".join(lines))


def _answer_key(raw: str, where: str) -> str:
    key = raw.strip()
    if not _KEY.fullmatch(key):
        raise TmmError(f"{where}: the key is not a name like r0_mm (letters, digits, '_'); see `tmm check --keys`")
    return key


def read_answers(path: str | Path) -> dict[str, object]:
    """Read a student's answers: TOML (`r0_mm = 41.2`) or CSV (`key,value` rows, ',' or ';').

    UTF-8, UTF-16 or cp1251; at most ANSWERS_BYTES and ANSWERS_ROWS keys; a key twice, a value that
    is not a finite number, or a nested table is an error. Errors name the line and the key,
    never the content of the file.
    """
    from ..inputs.tables import parse_number, read_text, rows
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
            answers[key] = parse_number(r[1], f"{what} line {i} ({key})")
            first_line[key] = i
        return answers
    try:
        data = tomllib.loads(src.text)
    except tomllib.TOMLDecodeError as exc:
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
        answers[key] = parse_number(v, f"{what} ({key})")
    return answers


def _lookup(doc: dict, path: tuple):
    cur = doc
    for part in path:
        try:
            cur = cur[part]
        except (KeyError, IndexError, TypeError):
            return None
    return cur


def required_keys(doc: dict, sheets=SHEETS) -> tuple[str, ...]:
    """The keys required for `sheets` that this variant computes (see REQUIRED)."""
    return tuple(k for sheet in sorted(sheets) for k in REQUIRED[sheet] if _lookup(doc, KEYS_BY_NAME[k].path) is not None)


def compare(doc: dict, answers: dict, rtol_pct: float, required=()) -> tuple[CheckRow, ...]:
    """Compare answers with a project JSON document: one row per given key (unknown keys flagged),
    then one "missing" row per required key not given."""
    rows = []
    for key, given in answers.items():
        spec = KEYS_BY_NAME.get(key)
        if spec is None:
            rows.append(CheckRow(key, None, given, None, "unknown key"))
            continue
        expected = _lookup(doc, spec.path)
        if expected is None or isinstance(given, dict):
            rows.append(CheckRow(key, expected, given, None, "not computed"))
            continue
        if spec.kind == "int":
            ok = float(given) == float(expected)
            dev = None if expected == 0 else 100.0 * (float(given) - float(expected)) / abs(float(expected))
            rows.append(CheckRow(key, expected, given, dev, "pass" if ok else "fail"))
            continue
        dev = _deviation_pct(doc, spec, expected, given)
        status = "pass" if abs(dev) <= rtol_pct + 1e-9 else "fail"
        book = _lookup(doc, spec.book_path) if spec.book_path else None
        if status == "fail" and book is not None and abs(_deviation_pct(doc, spec, book, given)) <= rtol_pct + 1e-9:
            status = "pass (book)"  # the student followed the book's two-line construction
        rows.append(CheckRow(key, expected, given, None if not math.isfinite(dev) else dev, status))
    for key in required:
        if key not in answers:
            rows.append(CheckRow(key, _lookup(doc, KEYS_BY_NAME[key].path), None, None, "missing"))
    return tuple(rows)


def _deviation_pct(doc: dict, spec: AnswerKey, expected, given) -> float:
    """Signed deviation of `given` from `expected` in per cent of the key's scale."""
    scale = abs(float(_lookup(doc, spec.scale_path) or 0.0)) if spec.scale_path else abs(float(expected))
    diff = float(given) - float(expected)
    return 100.0 * diff / scale if scale > 0 else (0.0 if diff == 0 else math.inf)


def check_one(variant, answers: dict, *, crank_rpm=None, torque_nm=None, rtol_pct: float = 3.0, label: str = "",
              lang: str = "en", sheets=SHEETS, group: str = "") -> CheckReport:
    """Run the project for the variant and compare the answers with it; the keys `sheets`
    require (REQUIRED) and the student omitted fail as "missing"."""
    from ..limits import RTOL_PCT, check_range
    from ..project import run_project
    from ..render.data.project import project_document

    rtol_pct = check_range(rtol_pct, *RTOL_PCT, "--rtol", " per cent")
    if not answers:
        raise TmmError("the answers file has no values; write lines like r0_mm = 41.2 (see `tmm check --keys`)")
    shift = student_shift(answers)
    result = run_project(variant, crank_rpm=crank_rpm, torque_nm=torque_nm, shift=shift)
    doc = project_document(result, lang)
    required = required_keys(doc, sheets)
    rows = accept_valid_reducer(compare(doc, answers, rtol_pct, required), answers, result.gears)
    rows = accept_book_cam(rows, answers, result.cam, rtol_pct)
    # the tooth numbers depend on the crank speed: say when the book's 220 rpm was assumed
    notes = tuple(n for n in result.gears.notes if n.code == "crank_default")
    return CheckReport(label=label or f"variant {variant.number}", variant=variant.number, rtol_pct=rtol_pct,
                       rows=rows, notes=notes, required=required, group=group)


def student_shift(answers: dict) -> tuple[float, float] | None:
    """The spur pair's shifts the student chose (answers x1, x2; a missing one is 0), or None for
    the book's zero pair: the project is then recomputed with those shifts, as
    ``tmm gears --shift x1,x2`` does, so a_w_mm, alpha_w_deg, a_mm and eps_alpha are checked for
    the student's own pair (the shift is a design choice, not a result to match)."""
    x1, x2 = answers.get("x1"), answers.get("x2")
    if x1 is None and x2 is None:
        return None
    x1, x2 = float(x1 or 0.0), float(x2 or 0.0)
    return None if x1 == 0.0 and x2 == 0.0 else (x1, x2)


BOOK_ROLLER_KEYS = ("r0_mm", "l_oc_mm", "e_mm", "roller_mm")


def accept_book_cam(rows: tuple[CheckRow, ...], answers: dict, cam, rtol_pct: float) -> tuple[CheckRow, ...]:
    """Cam answers that follow the book where the program carries a safer design (issue 8).

    * ``roller_mm`` = 0.2·r0 (1.28) for the carried r0, its book vertex, or the student's own r0
      when that passed: "pass (book roller)" — the program carries min(0.2·r0, 0.8·ρ_min), and
      the report marks when the book's roller undercuts (see the cam's warning);
    * a rocker whose smallest cam (the book's swing choice, METHOD.md) put the pivot inside the
      swept circle, so the program carried the other swing: r0_mm / l_oc_mm of that smallest cam
      or of its book vertex pass as "pass (other swing)", the roller 0.2·r0 of it too.
    """
    failed = {r.key for r in rows if r.status == "fail"} & set(BOOK_ROLLER_KEYS)
    if not failed:
        return rows
    from ..cam.design import CamChoice, design_cam
    from ..cam.profile import ROLLER_RULE

    z, p = cam.sizing, cam.profile

    def near(given, values, scale=None) -> bool:
        for v in values:
            if v is None:
                continue
            sc = abs(scale if scale is not None else v)
            if sc > 0 and abs(float(given) - v) <= (rtol_pct + 1e-9) / 100.0 * sc:
                return True
        return False

    other = None
    if cam.source == "program" and cam.pivot_move == "swing" and z.swing in ("same", "opposite"):
        other = design_cam(cam.variant, step_deg=cam.step_deg,
                           choice=CamChoice(swing="same" if z.swing == "opposite" else "opposite"))
    # (r0 [mm], the largest roller without undercut [mm]) of each design a student may have drawn
    designs = [(z.r0_m * 1e3, p.roller_max_m * 1e3), (z.book_r0_m * 1e3, p.roller_max_m * 1e3)]
    if other is not None:
        oz, op = other.sizing, other.profile
        designs += [(oz.r0_m * 1e3, op.roller_max_m * 1e3), (oz.book_r0_m * 1e3, op.roller_max_m * 1e3)]
    status = {r.key: r.status for r in rows}
    given_r0 = answers.get("r0_mm")
    if given_r0 is not None and status.get("r0_mm", "").startswith("pass"):
        designs.append((float(given_r0), (other.profile if status["r0_mm"] == "pass (other swing)" else p).roller_max_m * 1e3))
    out = []
    for r in rows:
        st = r.status
        if st == "fail" and other is not None and r.key == "r0_mm" and near(r.given, (other.sizing.r0_m * 1e3, other.sizing.book_r0_m * 1e3)):
            st = "pass (other swing)"
        elif st == "fail" and other is not None and r.key == "l_oc_mm" and near(
                r.given, (other.sizing.l_oc_m and other.sizing.l_oc_m * 1e3, other.sizing.book_l_oc_m and other.sizing.book_l_oc_m * 1e3)):
            st = "pass (other swing)"
        elif st == "fail" and r.key == "roller_mm":
            hits = [lim for r0, lim in designs if near(r.given, (ROLLER_RULE * r0,))]
            if hits:
                st = "pass (book roller)" if any(float(r.given) < lim for lim in hits) else "pass (book roller, undercuts)"
        out.append(r if st == r.status else CheckRow(r.key, r.expected, r.given, r.deviation_pct, st))
    return tuple(out)


STAGE_KEYS = (("z_sun", "z_planet", "z_planet2", "z_ring", "planets"), ("z_sun_2", "z_planet_2", None, "z_ring_2", "planets_2"))


def accept_valid_reducer(rows: tuple[CheckRow, ...], answers: dict, gears) -> tuple[CheckRow, ...]:
    """Tooth numbers that differ from the carried reducer but satisfy all five conditions of
    §2.1.3 (ratio within the tolerance, coaxiality, assembly, neighbouring, Table 2.2), with the
    largest number of planets the set admits, pass as "pass (valid set)": the book's hand procedure and the
    search may rightly give different sets (e.g. variant 17 at 95 rpm: 18/47/112 by the book,
    17/46/109 by the search)."""
    from ..gears.planetary.conditions import PlanetaryDesign, Stage
    from ..gears.planetary.velocity import check_design

    failed = {r.key for r in rows if r.status == "fail"}
    n_stages = 2 if gears.scheme == "1+1" else 1
    used = [k for keys in STAGE_KEYS[:n_stages] for k in keys if k]
    if not failed & set(used):
        return rows
    stages = []
    for keys in STAGE_KEYS[:n_stages]:
        zs, zp, zp2, zn, kk = keys
        need = [zs, zp, zn, kk] + ([zp2] if gears.scheme == "2" else [])
        if any(not isinstance(answers.get(k), int) for k in need):
            return rows  # the student's reducer is incomplete: compare number by number only
        stages.append(Stage(answers[zs], answers[zp], answers.get(zp2) if gears.scheme == "2" else None,
                            answers[zn], answers[kk]))
    if not all(s.z_sun > 0 and s.z_planet > 0 and s.z_ring > 0 and s.planets > 0 for s in stages):
        return rows
    checks = check_design(PlanetaryDesign(gears.scheme, tuple(stages), target=gears.i_planetary), gears.tolerance_pct)
    # the number of planets must be the largest the set admits (exact assembly, or the book's form)
    if not checks.ok or any(s.planets not in (c.k_max, c.k_max_book) for s, c in zip(stages, checks.stages)):
        return rows
    return tuple(CheckRow(r.key, r.expected, r.given, r.deviation_pct, "pass (valid set)")
                 if r.key in used and r.status == "fail" else r for r in rows)


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


def check_group(roster, answers_dir, *, variants_file=None, crank_rpm=None, torque_nm=None, rtol_pct: float = 3.0,
                sheets=SHEETS) -> GroupReport:
    """Check every student of a roster against ``<file name>.toml`` / ``.csv`` in `answers_dir`
    (the name-to-file rule of :func:`tmm_cli.inputs.names.file_name`, as `tmm batch` names folders)."""
    from ..variants import get_variant
    from .roster import jobs_from_roster

    d = Path(answers_dir)
    if not d.is_dir():
        raise TmmError(f"answers folder {d} does not exist; give the folder with one file per student")
    plan = jobs_from_roster(roster, crank_rpm, torque_nm, variants_file)
    reports = [(b.job.line, CheckReport(label=b.job.label, variant=int(b.job.variant) if str(b.job.variant).isdigit() else 0,
                                        rtol_pct=rtol_pct, rows=(), error=b.reason, group=b.job.group))
               for b in plan.bad]
    for job in plan.jobs:
        try:
            v = get_variant(job.variant, variants_file)
            found = answers_file(d, job.fname)
            if found is None:
                raise TmmError(f"no answers file {job.fname}.toml or {job.fname}.csv in {d}")
            reports.append((job.line, check_one(v, read_answers(found), crank_rpm=job.crank_rpm, torque_nm=job.torque_nm,
                                                rtol_pct=rtol_pct, label=job.label, sheets=sheets, group=job.group)))
        except TmmError as exc:
            number = int(job.variant) if job.variant.isdigit() else 0
            reports.append((job.line, CheckReport(label=job.label, variant=number, rtol_pct=rtol_pct, rows=(),
                                                  error=str(exc), group=job.group)))
    reports.sort(key=lambda lr: lr[0])  # roster order
    return GroupReport(tuple(r for _, r in reports), plan.encoding, plan.delimiter)
