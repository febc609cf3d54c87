"""The four acceleration laws of Fig. 1.9 (§1.5), normalised to a unit stroke over a unit phase.

For a phase of angle φ_phase and t = φ/φ_phase ∈ [0, 1], the rise displacement is h·f(t); the
return is h·(1 − f(t)) over φ_return (METHOD.md, "Inputs"). Derivatives are with respect to t:
f' = df/dt, f'' = d²f/dt², f''' = d³f/dt³ (dimensionless).

Law numbers as in Table 1.2:

1. constant acceleration (parabolic):  f = 2t² (t ≤ ½), 1 − 2(1 − t)²
2. linearly decreasing acceleration:   f = 3t² − 2t³          (a ∝ 1 − 2t)
3. cosine acceleration (harmonic):     f = (1 − cos πt)/2
4. sine acceleration (cycloidal):      f = t − sin(2πt)/(2π)

Because the same f is used on rise and return, the peak accelerations scale as 1/φ_phase²,
which is the book's (1.7): |a_return,max / a_rise,max| = (φ_rise/φ_return)².

>>> law_max(1)[:2]
(2.0, 4.0)
"""

from __future__ import annotations

import math

import numpy as np

LAW_NUMBERS = (1, 2, 3, 4)


def _check(law: int) -> None:
    if law not in LAW_NUMBERS:
        from ..errors import TmmError

        raise TmmError(f"acceleration law {law} is unknown; use 1, 2, 3 or 4 (Fig. 1.9)")


def law_values(law: int, t) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Normalised f, f', f'', f''' of law `law` at t ∈ [0, 1] (Fig. 1.9) [-].

    Values of t outside [0, 1] are clipped. Law 1's acceleration jumps at t = ½ (f'' = +4 for
    t < ½, −4 for t ≥ ½); its jerk f''' is 0 inside each half (a Dirac pulse at the jumps is not
    represented).

    >>> [round(float(x), 12) for x in law_values(3, 0.5)]
    [0.5, 1.570796326795, 0.0, -15.50313834015]
    >>> [round(float(x), 12) for x in law_values(2, 1.0)]
    [1.0, 0.0, -6.0, -12.0]
    """
    _check(law)
    t = np.clip(np.asarray(t, dtype=float), 0.0, 1.0)
    if law == 1:
        first = t < 0.5
        f = np.where(first, 2.0 * t**2, 1.0 - 2.0 * (1.0 - t) ** 2)
        f1 = np.where(first, 4.0 * t, 4.0 * (1.0 - t))
        f2 = np.where(first, 4.0, -4.0)
        f3 = np.zeros_like(t)
    elif law == 2:
        f = 3.0 * t**2 - 2.0 * t**3
        f1 = 6.0 * t - 6.0 * t**2
        f2 = 6.0 - 12.0 * t
        f3 = np.full_like(t, -12.0)
    elif law == 3:
        pt = math.pi * t
        f = 0.5 * (1.0 - np.cos(pt))
        f1 = 0.5 * math.pi * np.sin(pt)
        f2 = 0.5 * math.pi**2 * np.cos(pt)
        f3 = -0.5 * math.pi**3 * np.sin(pt)
    else:
        w = 2.0 * math.pi * t
        f = t - np.sin(w) / (2.0 * math.pi)
        f1 = 1.0 - np.cos(w)
        f2 = 2.0 * math.pi * np.sin(w)
        f3 = 4.0 * math.pi**2 * np.cos(w)
    return f, f1, f2, f3


def law_max(law: int) -> tuple[float, float, float]:
    """Exact maxima (max f', max |f''|, max |f'''| away from jumps) of a law [-].

    Law 1: f'max = 2, f''max = 4; law 2: 1.5, 6; law 3: π/2, π²/2; law 4: 2, 2π.

    >>> [round(x, 9) for x in law_max(3)]
    [1.570796327, 4.934802201, 15.50313834]
    >>> [round(x, 9) for x in law_max(4)]
    [2.0, 6.283185307, 39.478417604]
    """
    _check(law)
    return {
        1: (2.0, 4.0, 0.0),
        2: (1.5, 6.0, 12.0),
        3: (math.pi / 2, math.pi**2 / 2, math.pi**3 / 2),
        4: (2.0, 2.0 * math.pi, 4.0 * math.pi**2),
    }[law]


def law_impacts(law: int) -> str:
    """Kind of impact (§1.2): "soft" where the acceleration jumps, "none" for law 4.

    Velocity is continuous in all four laws (no hard impact); the acceleration jumps at the phase
    ends for laws 1–3 (and at mid-phase for law 1), so they give soft impacts.

    >>> law_impacts(4), law_impacts(1)
    ('none', 'soft')
    """
    _check(law)
    return "none" if law == 4 else "soft"
