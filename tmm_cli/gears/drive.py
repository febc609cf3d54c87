"""Motor speed, ratios, scheme choice and motor power (§2.2, Fig. 2.4, §2.6).

Speeds are in rpm at the edges (``_rpm``); angular speeds in rad/s inside; power in kW as the
book writes (2.6).
"""

from __future__ import annotations

import math

from ..errors import TmmError
from ..records import record

MOTOR_RPM = (720, 920, 1420, 2880)
"""Standard motor speeds n_d [rpm] of §2.2."""

DEFAULT_CRANK_RPM = 220.0
"""The book's own crank speed (§2.2, §2.4), used when the student gives none."""

ETA_LINKAGE = 0.8
"""η2 of the linkage, 'approximately 0.8' (§2.6)."""

ETA_SINGLE = 0.96
"""η1 of scheme 1 or 2 with the sun k driving (§2.6)."""

RATED_POWER_KW = (0.09, 0.12, 0.18, 0.25, 0.37, 0.55, 0.75, 1.1, 1.5, 2.2, 3.0, 4.0, 5.5, 7.5, 11.0,
                  15.0, 18.5, 22.0, 30.0, 37.0, 45.0, 55.0, 75.0, 90.0, 110.0)
"""Rated powers of general-purpose induction motors (IEC 60072 / GOST series) [kW]."""


def choose_motor_rpm(crank_rpm: float) -> int:
    """The smallest standard n_d with n_d ≥ 3·n_cr (§2.2), so that i_pl ≥ 3.

    >>> choose_motor_rpm(220), choose_motor_rpm(67), choose_motor_rpm(300), choose_motor_rpm(960)
    (720, 720, 920, 2880)
    """
    if not crank_rpm > 0 or not math.isfinite(crank_rpm):
        raise TmmError(f"crank speed must be a positive number of rpm, got {crank_rpm:g}; "
                       "give the crank speed of your linkage (sheet 1), e.g. --crank-rpm 220")
    for n in MOTOR_RPM:
        if n >= 3 * crank_rpm:
            return n
    raise TmmError(f"crank speed {crank_rpm:g} rpm is too high: no standard motor (720, 920, 1420, 2880 rpm) "
                   f"has n_d ≥ 3·n_cr = {3 * crank_rpm:g} rpm; use a crank speed of at most 960 rpm")


@record
class SchemeInfo:
    """One scheme of Fig. 2.4 (ratio range, efficiency range, formula, coaxiality)."""

    number: int
    key: str  # "1", "2", "1+1" (= Fig. 2.4 scheme 3), "4", "5"
    i_min: float
    i_max: float
    eta_min: float
    eta_max: float
    formula: str
    coaxial: str


SCHEMES: tuple[SchemeInfo, ...] = (
    SchemeInfo(1, "1", 3, 8, 0.96, 0.98, "i = 1 + z_n/z_k", "z_k + z_c = z_n − z_c"),
    SchemeInfo(2, "2", 8, 16, 0.95, 0.97, "i = 1 + (z_c/z_k)·(z_n/z_c′)", "z_k + z_c = z_n − z_c′"),
    SchemeInfo(3, "1+1", 8, 64, 0.92, 0.96, "i = (1 + z_n1/z_k1)·(1 + z_n2/z_k2)",
               "z_k1 + z_c1 = z_n1 − z_c1; z_k2 + z_c2 = z_n2 − z_c2"),
    SchemeInfo(4, "4", 30, 1600, 0.1, 0.9, "i = 1/(1 − (z_c/z_k)·(z_n/z_c′))", "z_k − z_c = z_n − z_c′"),
    SchemeInfo(5, "5", 20, 1600, 0.2, 0.96, "i = (1 + z_n/z_k)/(1 − (z_n/z_c)·(z_c′/z_k′))",
               "z_k + z_c = z_n − z_c = z_k′ − z_c′"),
)
"""Fig. 2.4. The book's two-stage recommendation for i_pl > 16 is its scheme 3 (two scheme-1 stages)."""


def choose_scheme(i_pl: float) -> str:
    """Scheme key by §2.2 with the overlaps at 8 and 16 read as i ≤ 8 → "1", 8 < i ≤ 16 → "2", else "1+1".

    >>> choose_scheme(3.25), choose_scheme(8.0), choose_scheme(10.6), choose_scheme(16.0), choose_scheme(16.4)
    ('1', '1', '2', '2', '1+1')
    """
    if i_pl <= 8:
        return "1"
    if i_pl <= 16:
        return "2"
    return "1+1"


def scheme_reason(key: str) -> str:
    """A code for why the scheme was chosen (rendered by messages_gears)."""
    return {"1": "le8", "2": "8to16", "1+1": "gt16"}[key]


def eta_planetary(key: str) -> float:
    """η1 used in (2.6): 0.96 for schemes 1 and 2 (§2.6); 0.96² ≈ 0.92 for two stages in series
    (the lower end of Fig. 2.4 scheme 3's 0.96 … 0.92).

    >>> eta_planetary("1"), round(eta_planetary("1+1"), 4)
    (0.96, 0.9216)
    """
    return ETA_SINGLE ** 2 if key == "1+1" else ETA_SINGLE


def omega_rad_s(n_rpm: float) -> float:
    """ω = π·n/30 [rad/s]."""
    return math.pi * n_rpm / 30.0


@record
class MotorPower:
    """(2.6): N = M·ω_cr/(η1·η2)·10⁻³ [kW] and the next standard rating."""

    torque_nm: float
    omega_cr_rad_s: float
    eta1: float
    eta2: float
    power_kw: float
    rated_kw: float | None  # None if above the series


def motor_power(torque_nm: float, crank_rpm: float, eta1: float, eta2: float = ETA_LINKAGE) -> MotorPower:
    """Required motor power by (2.6) and the next rated power of the standard series.

    >>> p = motor_power(100.0, 220.0, 0.96)
    >>> round(p.power_kw, 3), p.rated_kw
    (3.0, 3.0)
    """
    if not math.isfinite(torque_nm) or torque_nm < 0:
        raise TmmError(f"mean reduced moment must be a non-negative number of N·m, got {torque_nm:g}; "
                       "give M from sheet 2, e.g. --torque 100")
    w = omega_rad_s(crank_rpm)
    n = torque_nm * w / (eta1 * eta2) * 1e-3
    rated = next((r for r in RATED_POWER_KW if r >= n - 1e-9), None)
    return MotorPower(torque_nm, w, eta1, eta2, n, rated)


def rotation(sign: float) -> str:
    """'ccw' for positive speeds (Table 1.2's convention), 'cw' for negative."""
    return "ccw" if sign > 0 else "cw"
