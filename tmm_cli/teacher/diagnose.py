"""Where to look and what probably went wrong: the book's place for every checked value, and the
likely cause of each failure, read from the numbers themselves (a sign flipped, a ratio inverted,
the phase angle given for the profile angle, a value that follows another wrong one …).

The causes are :class:`~tmm_cli.notes.Note` objects (a code and its numbers); their sentences live in
``i18n/messages_check.py``, so a student reads them in Russian or English.
"""

from __future__ import annotations

from dataclasses import replace

from ..notes import Note
from .rows import CheckRow, Place

# the book's place of each key; (translating, rocker) where the two differ
_PLACES = {
    "n_motor_rpm": Place("2.2"),
    "i_spur": Place("2.2", "1"),
    "i_planetary": Place("2.2", "2"),
    "i_kh": Place("2.4", "6", "2.1"),
    "ratio_error_pct": Place("2.1.3", "1"),
    "z1": Place("2.3", "1–2", table="2.2"),
    "z2": Place("2.3", "1–2", table="2.2"),
    "a_mm": Place("2.3", "4"),
    "eps_alpha": Place("2.3"),
    "x1": Place(doc="docs/shifted-gears.md"),
    "x2": Place(doc="docs/shifted-gears.md"),
    "a_w_mm": Place(doc="docs/shifted-gears.md"),
    "alpha_w_deg": Place(doc="docs/shifted-gears.md"),
    "roller_mm": Place("1.4", "", "1.28"),
    "phi_rise_deg": Place("1.5", table="1.2"),
    "phi_far_dwell_deg": Place("1.5", table="1.2"),
    "phi_return_deg": Place("1.5", table="1.2"),
    "nu_max_deg": Place("1.5", table="1.2"),
    "n_cam_rpm": Place("1.5", table="1.2"),
}
_CAM_PLACES = {  # key -> (translating follower, rocker)
    "r0_mm": (Place("1.3.1", "3–5", "1.22"), Place("1.3.2", "2–4", "1.25")),
    "e_mm": (Place("1.3.1", "5", "1.23"), Place("1.3.1", "5", "1.23")),
    "l_oc_mm": (Place("1.3.2", "4", "1.25"), Place("1.3.2", "4", "1.25")),
    "nu_rise_deg": (Place("1.3.1", "6", "1.19"), Place("1.3.2", "5", "1.19")),
    "nu_return_deg": (Place("1.3.1", "6", "1.19"), Place("1.3.2", "5", "1.19")),
    "psi_rise_deg": (Place("1.4.1", "6"), Place("1.4.2", "6")),
    "psi_far_dwell_deg": (Place("1.4.1", "6"), Place("1.4.2", "6")),
    "psi_return_deg": (Place("1.4.1", "6"), Place("1.4.2", "6")),
}
_SET_KEYS = ("z_sun", "z_planet", "z_planet2", "z_ring", "planets", "z_sun_2", "z_planet_2", "z_ring_2", "planets_2")


def place_of(key: str, rocker: bool, scheme: str) -> Place | None:
    """The book's place of `key` for this mechanism (a rocker's sizing is §1.3.2, a translating
    follower's §1.3.1; a double-row reducer's synthesis is §2.5, a single-row one's §2.4).

    >>> place_of("r0_mm", False, "1"), place_of("z_ring", True, "2").section
    (Place(section='1.3.1', steps='3–5', eq='1.22', table='', doc=''), '2.5')
    """
    if key in _CAM_PLACES:
        return _CAM_PLACES[key][1 if rocker else 0]
    if key in _SET_KEYS:
        if key.startswith("planets"):
            return Place("2.5" if scheme == "2" else "2.4", "3–5", "2.4, 2.5")
        return Place("2.5" if scheme == "2" else "2.4", "2", "2.1", table="2.2")
    return _PLACES.get(key)


def diagnose(rows: tuple[CheckRow, ...], doc: dict, answers: dict, result) -> tuple[CheckRow, ...]:
    """Every row with its place in the book; each failure without a cause gets the likely one,
    each pass against another design a remark."""
    rocker = bool(result.variant.is_rocker)
    scheme = result.gears.scheme
    status = {r.key: r.status for r in rows}
    out = []
    for r in rows:
        place = r.place or place_of(r.key, rocker, scheme)
        cause = r.cause
        if cause is None and r.status == "fail":
            cause = _cause(r, doc, answers, result, status)
        elif cause is None and r.status == "missing":
            cause = Note.make("missing_required")
        elif cause is None and r.status == "pass (book)":
            cause = Note.make("remark_book_vertex", program=_num(r.program))
        elif cause is None and r.status == "pass (other swing)":
            cause = Note.make("remark_other_swing", program=_num(r.program))
        elif cause is None and r.status == "pass (book roller, undercuts)":
            cause = Note.make("remark_roller_undercuts", program=_num(r.program))
        out.append(replace(r, place=place, cause=cause))
    return tuple(out)


def _num(x):
    return None if x is None else round(float(x), 4)


def _near(a, b, rel: float) -> bool:
    try:
        a, b = float(a), float(b)
    except (TypeError, ValueError):
        return False
    return abs(a - b) <= rel * max(abs(b), 1e-12)


def _failed(status: dict, key: str) -> bool:
    return status.get(key) in ("fail", "missing", "unreadable")


def _cause(r: CheckRow, doc: dict, answers: dict, result, status: dict) -> Note | None:
    """The likely cause of the failed row `r` (None: nothing better to say than the deviation)."""
    from ..gears.drive import MOTOR_RPM

    k, g, e = r.key, r.given, r.expected
    tol = (r.tolerance_pct or 3.0) / 100.0
    small = r.deviation is not None and r.deviation < 0
    v = result.variant
    gears = result.gears
    if k == "r0_mm":
        if v.closure == "force":
            return Note.make("cause_r0_small_force" if small else "cause_r0_large")
        return Note.make("cause_r0_small_form" if small else "cause_r0_large")
    if k == "e_mm" and e and float(g) * float(e) < 0 and _near(abs(float(g)), abs(float(e)), tol):
        return Note.make("cause_e_sign")
    if k in ("e_mm", "l_oc_mm", "roller_mm", "nu_rise_deg", "nu_return_deg") and _failed(status, "r0_mm"):
        if k == "roller_mm" and isinstance(answers.get("r0_mm"), (int, float)) and _near(g, 0.2 * float(answers["r0_mm"]), tol):
            return Note.make("follows_your_r0", key="r_0")
        if k != "roller_mm":
            return Note.make("follows_your_r0", key="r_0")
    if k == "e_mm":
        return Note.make("cause_e_value")
    if k == "l_oc_mm":
        return Note.make("cause_l_oc")
    if k == "roller_mm":
        return Note.make("cause_roller_rule")
    if k in ("nu_rise_deg", "nu_return_deg"):
        if _near(g, v.nu_max_deg, 0.005):
            return Note.make("cause_nu_is_limit", nu_max=float(v.nu_max_deg))
        return Note.make("cause_nu")
    if k in ("psi_rise_deg", "psi_far_dwell_deg", "psi_return_deg"):
        phase = {"psi_rise_deg": v.phi_rise_deg, "psi_far_dwell_deg": v.phi_far_dwell_deg,
                 "psi_return_deg": v.phi_return_deg}[k]
        if _near(g, phase, 0.005):
            return Note.make("cause_psi_is_phi", phi=float(phase))
        return Note.make("cause_psi")
    if k == "n_motor_rpm":
        n3 = 3 * gears.crank_rpm
        if float(g) < n3:
            return Note.make("cause_motor_below", n3=round(n3, 1), crank=round(gears.crank_rpm, 1))
        if int(float(g)) in MOTOR_RPM:
            return Note.make("cause_motor_not_smallest", n3=round(n3, 1), crank=round(gears.crank_rpm, 1))
        return Note.make("cause_motor_standard")
    if k in ("i_spur", "i_planetary"):
        if e and _near(float(g) * float(e), 1.0, tol):
            return Note.make("cause_ratio_inverted_spur" if k == "i_spur" else "cause_ratio_inverted_planetary")
        motor = answers.get("n_motor_rpm")
        if isinstance(motor, (int, float)) and _failed(status, "n_motor_rpm"):
            return Note.make("follows_your_motor", n=motor)
        if k == "i_planetary" and not gears.crank_rpm_assumed and _near(g, gears.motor_rpm / 220.0, tol):
            return Note.make("cause_crank_220", crank=round(gears.crank_rpm, 1))
        return Note.make("cause_i_spur" if k == "i_spur" else "cause_i_planetary")
    if k in ("i_kh", "ratio_error_pct"):
        return Note.make("cause_i_kh" if k == "i_kh" else "cause_ratio_error")
    if k in ("z1", "z2"):
        z1, z2 = answers.get("z1"), answers.get("z2")
        ez1, ez2 = doc["gears"]["spur"]["z1"], doc["gears"]["spur"]["z2"]
        if z1 == ez2 and z2 == ez1 and ez1 != ez2:
            return Note.make("cause_spur_swapped_multiplier" if doc["gears"]["spur"].get("multiplier") else "cause_spur_swapped")
        return Note.make("cause_spur_rule")
    if k == "a_mm":
        z1, z2 = answers.get("z1"), answers.get("z2")
        if isinstance(z1, (int, float)) and isinstance(z2, (int, float)) and _near(g, 10.0 * (z1 + z2), 1e-6):
            return Note.make("follows_your_teeth", key="z1, z2")
        return Note.make("cause_a")
    if k == "eps_alpha":
        if _failed(status, "z1") or _failed(status, "z2"):
            return Note.make("follows_your_teeth", key="z1, z2")
        return Note.make("cause_eps")
    if k in _SET_KEYS:
        return Note.make("cause_set_incomplete")
    if r.basis == "variant":
        return Note.make("cause_input", variant=v.number, value=e)
    if k in ("a_w_mm", "alpha_w_deg"):
        return Note.make("cause_shifted")
    return None
