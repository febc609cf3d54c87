"""The flywheel for an allowed coefficient of speed fluctuation δ: by N. I. Mertsalov's method and
by F. Wittenbauer's energy–mass diagram; the crank's speed with it; a steel disc's or rim's size.

The regulation of a machine's motion (Artobolevsky, "Регулирование хода машин: маховик"; Frolov,
"Динамика машин"; METHOD.md "Sheets 1 and 2"), δ = (ω_max − ω_min)/ω_m with ω_m = (ω_max + ω_min)/2:

- Mertsalov (Мерцалов; the brief's "Merkalov"): the links split into the first group of constant
  reduced inertia J_I (the crank, the rotor, the flywheel) and the second, J_II(φ). Its kinetic
  energy is taken at the mean speed, T_II ≈ J_II(φ)·ω_m²/2, so the first group's energy changes
  by ΔT_I(φ) = ΔT(φ) − T_II(φ) + const and J_I = (max ΔT_I − min ΔT_I)/(δ·ω_m²); the flywheel is
  J_fl = J_I − J_crank − J_rotor.
- Wittenbauer (Виттенбауэр): the curve of ΔT(φ) against J_r(φ), with T = (J_fl + J_r)·ω²/2.
  The speed stays within ω_min … ω_max when the curve lies between the two lines through the
  origin of the true axes (J = −J_fl, T = 0) of slopes tg ψ_max = ω_max²/2 and tg ψ_min = ω_min²/2
  (the book's ω_m²(1 ± δ)/2 to first order in δ); the tangents to the curve at those slopes cut
  the ΔT axis at c_max = max(ΔT − tg ψ_max·J_r) and c_min = min(ΔT − tg ψ_min·J_r), and
  J_fl = (c_max − c_min)/(tg ψ_max − tg ψ_min). It keeps T_II's change with the speed that
  Mertsalov neglects, so it is the more exact one; both agree as δ → 0.
- The speed with a flywheel J: ω(φ) = √(2·(T₀ + ΔT(φ))/(J + J_r(φ))), T₀ chosen so that
  (ω_max + ω_min)/2 = ω_m.
"""

from __future__ import annotations

import math

import numpy as np

from ..records import record
from .dynamics import Dynamics
from .sheet2_file import DynamicsSpec


@record(eq=False)
class Mertsalov:
    J_I: float  # the first group's moment of inertia needed [kg·m²]
    J_fl: float  # the flywheel's, J_I − J_crank − J_rotor (≤ 0: none is needed) [kg·m²]
    dT_I: np.ndarray  # ΔT_I(φ) = ΔT − J_II·ω_m²/2 [J]
    i_max: int  # the grid index of its largest value
    i_min: int  # … and of its smallest


@record(eq=False)
class Wittenbauer:
    J_fl: float  # [kg·m²] (≤ 0: none is needed)
    slope_max: float  # tg ψ_max = ω_max²/2 [J/(kg·m²)]
    slope_min: float  # tg ψ_min = ω_min²/2
    c_max: float  # the upper tangent's ΔT at J_r = 0 [J]
    c_min: float  # the lower tangent's
    i_max: int  # where the upper tangent touches the curve (grid index)
    i_min: int  # … the lower one


@record
class FlywheelSize:
    kind: str  # 'disc' | 'rim'
    J: float  # [kg·m²]
    D: float  # the disc's diameter, or the rim's mean diameter [m]
    b: float  # width [m]
    h: float | None  # the rim's radial thickness [m]
    m: float  # [kg]


@record(eq=False)
class Flywheel:
    delta: float
    omega_mean: float  # ω_m [rad/s]
    omega_max: float  # ω_m·(1 + δ/2)
    omega_min: float  # ω_m·(1 − δ/2)
    mertsalov: Mertsalov
    wittenbauer: Wittenbauer
    J: float  # the flywheel chosen: Mertsalov's, at least 0 [kg·m²]
    size: FlywheelSize | None  # None when no flywheel is needed
    omega: np.ndarray  # the crank's speed over the turn with it [rad/s]

    @property
    def delta_actual(self) -> float:
        """(ω_max − ω_min)/ω_m of the speed with the chosen flywheel."""
        return float((self.omega.max() - self.omega.min()) / self.omega_mean)


def mertsalov(dT, J_II, omega_m: float, delta: float, J_first: float) -> Mertsalov:
    """Mertsalov's flywheel: J_I = (max ΔT_I − min ΔT_I)/(δ·ω_m²), ΔT_I = ΔT − J_II·ω_m²/2.

    A machine whose energy swings by 100 J with constant inertia (J_II = 0) at ω_m = 10 rad/s and
    δ = 0.1 needs J_I = 100/(0.1·100) = 10 kg·m²; with a 2 kg·m² crank, a flywheel of 8:

    >>> m = mertsalov(np.array([0.0, 60.0, -40.0, 0.0]), np.zeros(4), 10.0, 0.1, 2.0)
    >>> round(m.J_I, 12), round(m.J_fl, 12), m.i_max, m.i_min
    (10.0, 8.0, 1, 2)
    """
    dT_I = np.asarray(dT) - np.asarray(J_II) * omega_m ** 2 / 2.0
    i_max, i_min = int(np.argmax(dT_I)), int(np.argmin(dT_I))
    J_I = float(dT_I[i_max] - dT_I[i_min]) / (delta * omega_m ** 2)
    return Mertsalov(J_I, J_I - J_first, dT_I, i_max, i_min)


def wittenbauer(dT, J_r, omega_m: float, delta: float) -> Wittenbauer:
    """Wittenbauer's flywheel from the energy–mass curve (J_r(φ), ΔT(φ)): the tangents of slopes
    ω_max²/2 and ω_min²/2, ω_max,min = ω_m·(1 ± δ/2), and J_fl = (c_max − c_min)/(tg ψ_max − tg ψ_min).

    With constant J_r it is Mertsalov's, J_fl = ΔT's swing/(δ·ω_m²) − J_r:

    >>> w = wittenbauer(np.array([0.0, 60.0, -40.0, 0.0]), np.full(4, 2.0), 10.0, 0.1)
    >>> round(w.J_fl, 9), round(w.slope_max - w.slope_min, 12)   # ω_max² − ω_min² = 2δ·ω_m²
    (8.0, 10.0)
    """
    dT, J_r = np.asarray(dT), np.asarray(J_r)
    k_max = (omega_m * (1.0 + delta / 2.0)) ** 2 / 2.0
    k_min = (omega_m * (1.0 - delta / 2.0)) ** 2 / 2.0
    upper, lower = dT - k_max * J_r, dT - k_min * J_r
    i_max, i_min = int(np.argmax(upper)), int(np.argmin(lower))
    c_max, c_min = float(upper[i_max]), float(lower[i_min])
    return Wittenbauer((c_max - c_min) / (k_max - k_min), k_max, k_min, c_max, c_min, i_max, i_min)


def speed(dT, J_r, J: float, omega_m: float) -> np.ndarray:
    """ω(φ) = √(2·(T₀ + ΔT)/(J + J_r)) [rad/s] with T₀ such that (ω_max + ω_min)/2 = ω_m (found by
    bisection: the mean of the extremes grows with T₀).

    >>> w = speed(np.array([0.0, 60.0, -40.0, 0.0]), np.full(4, 2.0), 8.0, 10.0)   # J = 10 in all
    >>> round(float(w.max() + w.min()) / 2, 9), round(float((w.max() - w.min()) / 10.0), 4)
    (10.0, 0.1)
    """
    dT, J_r = np.asarray(dT, dtype=float), np.asarray(J_r, dtype=float)
    total = J + J_r

    def mean(t0):
        w = np.sqrt(2.0 * (t0 + dT) / total)
        return 0.5 * (w.max() + w.min())

    lo = float(np.max(-dT))  # T₀ + ΔT ≥ 0 everywhere
    hi = lo + float(np.max(total)) * omega_m ** 2 + 1.0
    while mean(hi) < omega_m:
        hi = 2.0 * hi + 1.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mean(mid) < omega_m:
            lo = mid
        else:
            hi = mid
        if hi - lo <= 1e-15 * hi:
            break
    return np.sqrt(2.0 * (0.5 * (lo + hi) + dT) / total)


def flywheel_size(J: float, kind: str, width_ratio: float, rim_ratio: float, density: float) -> FlywheelSize:
    """A steel flywheel of moment of inertia J [kg·m²] (the standard design formulas):

    - a solid disc: J = m·D²/8, m = ρ·π·D²·b/4, b = ψ_b·D, so D = (32·J/(π·ρ·ψ_b))^(1/5);
    - a rim (обод, its mass at the mean diameter D): J = m·D²/4, m = ρ·π·D·b·h, b = ψ_b·D,
      h = ψ_h·b, so D = (4·J/(π·ρ·ψ_b²·ψ_h))^(1/5).

    >>> s = flywheel_size(1.0, "disc", 0.2, 1.0, 7800.0)
    >>> round(s.D, 4), round(s.b, 4), round(s.m, 2), round(s.m * s.D ** 2 / 8, 12)
    (0.3656, 0.0731, 59.86, 1.0)
    >>> r = flywheel_size(1.0, "rim", 0.2, 1.0, 7800.0)
    >>> round(r.m * r.D ** 2 / 4, 12), round(r.h / r.b, 12)
    (1.0, 1.0)
    """
    if kind == "disc":
        d = (32.0 * J / (math.pi * density * width_ratio)) ** 0.2
        b = width_ratio * d
        return FlywheelSize(kind, J, d, b, None, density * math.pi * d * d * b / 4.0)
    d = (4.0 * J / (math.pi * density * width_ratio ** 2 * rim_ratio)) ** 0.2
    b = width_ratio * d
    h = rim_ratio * b
    return FlywheelSize(kind, J, d, b, h, density * math.pi * d * b * h)


def flywheel(dyn: Dynamics, spec: DynamicsSpec) -> Flywheel:
    """Both methods for the file's δ; the flywheel chosen is Mertsalov's (the course's method),
    Wittenbauer's beside it; the speed over the turn and the size with the chosen one."""
    w_m, delta = dyn.omega_mean, spec.delta
    me = mertsalov(dyn.dT, dyn.J_II, w_m, delta, dyn.J_first)
    wi = wittenbauer(dyn.dT, dyn.J_r, w_m, delta)
    J = max(me.J_fl, 0.0)
    size = flywheel_size(J, spec.flywheel, spec.width_ratio, spec.rim_ratio, spec.density) if J > 0.0 else None
    omega = speed(dyn.dT, dyn.J_r, J, w_m)
    return Flywheel(delta, w_m, w_m * (1.0 + delta / 2.0), w_m * (1.0 - delta / 2.0), me, wi, J, size, omega)
