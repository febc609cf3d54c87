"""Checking a student's numbers against the computed project (`tmm check`).

The expected values are read from the project's JSON document (the content of results.json),
so the check compares against exactly what `tmm project` reports. Integers (tooth numbers,
planets, motor speed) must match exactly; graphical quantities (r0, e, l_OC, ε_α, pressure
angles …) within a relative tolerance, 3 % by default.
"""

from __future__ import annotations

import csv
import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from .errors import TmmError
from .render.i18n import note_text


@dataclass(frozen=True)
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
    _k("x1", ("gears", "spur", "x1"), "float", "spur shift coefficient x1 (0 for the book's pair)", "коэффициент смещения x1"),
    _k("x2", ("gears", "spur", "x2"), "float", "spur shift coefficient x2 (0 for the book's pair)", "коэффициент смещения x2"),
    _k("a_w_mm", ("gears", "spur", "a_w_mm"), "float", "spur working centre distance a_w [mm]", "межосевое расстояние a_w [мм]"),
    _k("alpha_w_deg", ("gears", "spur", "alpha_w_deg"), "float", "spur working pressure angle α_w [deg]", "угол зацепления α_w [°]"),
    _k("r0_mm", ("cam", "r0_mm"), "float", "cam base radius r0 [mm] (the book's vertex is accepted too)",
       "минимальный радиус кулачка r_0 [мм] (принимается и вершина по пособию)", book_path=("cam", "book_vertex", "r0_mm")),
    _k("e_mm", ("cam", "e_mm"), "float", "offset e [mm] (tolerance relative to r0; the book's vertex accepted)",
       "эксцентриситет e [мм] (допуск от r_0; принимается и вершина по пособию)", ("cam", "r0_mm"), ("cam", "book_vertex", "e_mm")),
    _k("l_oc_mm", ("cam", "l_oc_mm"), "float", "centre distance l_OC [mm] (the book's vertex accepted)",
       "межцентровое расстояние l_OC [мм] (принимается и вершина по пособию)", book_path=("cam", "book_vertex", "l_oc_mm")),
    _k("roller_mm", ("cam", "roller_mm"), "float", "roller radius r_p [mm]", "радиус ролика r_p [мм]"),
    _k("nu_rise_deg", ("cam", "pressure_angle_max_deg", "rise"), "float", "max pressure angle on rise [deg]", "максимальный угол давления на удалении [°]"),
    _k("nu_return_deg", ("cam", "pressure_angle_max_deg", "return"), "float", "max pressure angle on return [deg]", "максимальный угол давления на возвращении [°]"),
    _k("psi_rise_deg", ("cam", "psi_deg", "rise"), "float", "profile angle ψ_у [deg]", "профильный угол удаления ψ_у [°]"),
    _k("psi_far_dwell_deg", ("cam", "psi_deg", "far_dwell"), "float", "profile angle ψ_дс [deg]", "профильный угол дальнего стояния ψ_дс [°]"),
    _k("psi_return_deg", ("cam", "psi_deg", "return"), "float", "profile angle ψ_в [deg]", "профильный угол возвращения ψ_в [°]"),
)
KEYS_BY_NAME = {k.key: k for k in ANSWER_KEYS}


@dataclass(frozen=True)
class CheckRow:
    key: str
    expected: object
    given: object
    deviation_pct: float | None
    status: str  # "pass", "pass (book)", "fail", "unknown key", "not computed"


@dataclass(frozen=True)
class CheckReport:
    label: str
    variant: int
    rtol_pct: float
    rows: tuple[CheckRow, ...]
    error: str = ""
    notes: tuple = ()  # Note objects the comparison rests on (e.g. the assumed crank speed)

    @property
    def passed(self) -> bool:
        return not self.error and bool(self.rows) and all(r.status.startswith("pass") for r in self.rows)

    def to_json(self) -> dict:
        return {
            "student": self.label,
            "variant": self.variant,
            "rtol_pct": self.rtol_pct,
            "passed": self.passed,
            "error": self.error or None,
            "assumptions": [note_text(n, "en") for n in self.notes],
            "rows": [r.__dict__ for r in self.rows],
        }


@dataclass(frozen=True)
class GroupReport:
    reports: tuple[CheckReport, ...] = field(default=())

    @property
    def all_passed(self) -> bool:
        return all(r.passed for r in self.reports)

    def to_json(self) -> dict:
        return {"all_passed": self.all_passed, "students": [r.to_json() for r in self.reports]}


def _number(raw, where: str):
    if isinstance(raw, bool):
        raise TmmError(f"{where}: '{raw}' is not a number")
    if isinstance(raw, (int, float)):
        return raw
    text = str(raw).strip().replace(",", ".")
    try:
        value = float(text)
    except ValueError:
        raise TmmError(f"{where}: '{raw}' is not a number; write a plain number") from None
    return int(value) if value.is_integer() and "." not in text and "e" not in text.lower() else value


def csv_delimiter(lines: list[str]) -> str:
    """',' or ';' (what a spreadsheet saves under a Russian locale), from the first non-empty line."""
    first = next((ln for ln in lines if ln.strip()), "")
    return ";" if first.count(";") > first.count(",") else ","


def read_answers(path: str | Path) -> dict[str, object]:
    """Read a student's answers: TOML (`r0_mm = 41.2`) or CSV (`key,value` rows)."""
    p = Path(path)
    try:
        raw = p.read_bytes()
    except OSError as exc:
        raise TmmError(f"answers file {p} cannot be read ({exc.strerror or exc.__class__.__name__}); check the path") from None
    text = raw.decode("utf-8-sig", errors="replace")
    if p.suffix.lower() == ".csv":
        lines = text.splitlines()
        rows = list(csv.reader(lines, delimiter=csv_delimiter(lines)))
        if rows and [c.strip().lower() for c in rows[0][:2]] == ["key", "value"]:
            rows = rows[1:]
        answers = {}
        for i, r in enumerate(rows, start=1):
            if not r or not "".join(r).strip():
                continue
            if len(r) < 2:
                raise TmmError(f"answers file {p} line {i}: expected key,value")
            answers[r[0].strip()] = _number(r[1], f"answers file {p} line {i} ({r[0].strip()})")
        return answers
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise TmmError(f"answers file {p} is not valid TOML ({exc}); write lines like r0_mm = 41.2, with a dot for decimals") from None
    return {k: (_number(v, f"answers file {p} ({k})") if not isinstance(v, dict) else v) for k, v in data.items()}


def _lookup(doc: dict, path: tuple):
    cur = doc
    for part in path:
        try:
            cur = cur[part]
        except (KeyError, IndexError, TypeError):
            return None
    return cur


def compare(doc: dict, answers: dict, rtol_pct: float) -> tuple[CheckRow, ...]:
    """Compare answers with a project JSON document; one row per given key, unknown keys flagged."""
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
        rows.append(CheckRow(key, expected, given, dev, status))
    return tuple(rows)


def _deviation_pct(doc: dict, spec: AnswerKey, expected, given) -> float:
    """Signed deviation of `given` from `expected` in per cent of the key's scale."""
    scale = abs(float(_lookup(doc, spec.scale_path) or 0.0)) if spec.scale_path else abs(float(expected))
    diff = float(given) - float(expected)
    return 100.0 * diff / scale if scale > 0 else (0.0 if diff == 0 else math.inf)


def check_one(variant, answers: dict, *, crank_rpm=None, torque_nm=None, rtol_pct: float = 3.0, label: str = "", lang: str = "en") -> CheckReport:
    """Run the project for the variant and compare the answers with it."""
    from .project import run_project
    from .render.report import project_document

    if not answers:
        raise TmmError("the answers file has no values; write lines like r0_mm = 41.2 (see `tmm check --keys`)")
    result = run_project(variant, crank_rpm=crank_rpm, torque_nm=torque_nm)
    doc = project_document(result, lang)
    rows = accept_valid_reducer(compare(doc, answers, rtol_pct), answers, result.gears)
    # the tooth numbers depend on the crank speed: say when the book's 220 rpm was assumed
    notes = tuple(n for n in result.gears.notes if n.code == "crank_default")
    return CheckReport(label=label or f"variant {variant.number}", variant=variant.number, rtol_pct=rtol_pct,
                       rows=rows, notes=notes)


STAGE_KEYS = (("z_sun", "z_planet", "z_planet2", "z_ring", "planets"), ("z_sun_2", "z_planet_2", None, "z_ring_2", "planets_2"))


def accept_valid_reducer(rows: tuple[CheckRow, ...], answers: dict, gears) -> tuple[CheckRow, ...]:
    """Tooth numbers that differ from the carried reducer but satisfy all five conditions of
    §2.1.3 (ratio within the tolerance, coaxiality, assembly, neighbouring, Table 2.2), with the
    largest number of planets the set admits, pass as "pass (valid set)": the book's hand procedure and the
    search may rightly give different sets (e.g. variant 17 at 95 rpm: 18/47/112 by the book,
    17/46/109 by the search)."""
    from .gears.planetary import PlanetaryDesign, Stage, check_design

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


def check_group(roster, answers_dir, *, variants_file=None, crank_rpm=None, torque_nm=None, rtol_pct: float = 3.0) -> GroupReport:
    """Check every student of a roster against STUDENT.toml / STUDENT.csv in `answers_dir`."""
    from .batch import jobs_from_roster
    from .variants import get_variant

    d = Path(answers_dir)
    if not d.is_dir():
        raise TmmError(f"answers folder {d} does not exist; give the folder with one file per student")
    jobs, bad = jobs_from_roster(roster, crank_rpm, torque_nm)
    reports = [CheckReport(label=b["student"], variant=0, rtol_pct=rtol_pct, rows=(), error=b["error"]) for b in bad]
    for job in jobs:
        try:
            v = get_variant(job.variant, variants_file)
            candidates = [d / f"{job.label}.toml", d / f"{job.label}.csv", d / f"{job.folder}.toml", d / f"{job.folder}.csv"]
            found = next((c for c in candidates if c.is_file()), None)
            if found is None:
                raise TmmError(f"no answers file {job.label}.toml or .csv in {d}")
            reports.append(check_one(v, read_answers(found), crank_rpm=job.crank_rpm, torque_nm=job.torque_nm,
                                     rtol_pct=rtol_pct, label=job.label))
        except TmmError as exc:
            number = int(job.variant) if job.variant.isdigit() else 0
            reports.append(CheckReport(label=job.label, variant=number, rtol_pct=rtol_pct, rows=(), error=str(exc)))
    return GroupReport(tuple(reports))
