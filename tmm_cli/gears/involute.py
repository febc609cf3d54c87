"""Involute helpers: inv α, its inverse, the involute curve, shifted-gear centre distance.

Sources: the textbook §2.1.1 (involute as the path of a point of a line rolling on the base
circle) and seed 000 (planetary synthesis with shifted gears: inv α = tan α − α, α_w from x_Σ,
a_w). Angles are in radians inside; ``_deg`` names mark degrees at the edges.
"""

from __future__ import annotations

import math

import numpy as np

ALPHA_DEG = 20.0
"""Standard profile angle α [deg] (§2.1)."""


def inv(alpha: float) -> float:
    """Involute function inv α = tan α − α [rad] (seed 000).

    >>> round(inv(math.radians(20.0)), 6)
    0.014904
    """
    return math.tan(alpha) - alpha


def inv_inverse(value: float, tol: float = 1e-15) -> float:
    """The angle α ∈ [0, π/2) [rad] with inv α = ``value`` (Newton's method; seed 000's ``Ainv``).

    d(inv α)/dα = tan² α, so Newton converges from the cubic start α ≈ (3·inv)^(1/3).

    >>> round(math.degrees(inv_inverse(inv(math.radians(25.371)))), 6)
    25.371
    """
    if value < 0:
        raise ValueError("inv α is non-negative for 0 ≤ α < π/2")
    if value == 0:
        return 0.0
    # start: inv α ≈ α³/3 for small α; never start beyond the asymptote
    a = min((3.0 * value) ** (1.0 / 3.0), 1.5)
    for _ in range(60):
        t = math.tan(a)
        step = (t - a - value) / (t * t)
        a_new = a - step
        if a_new <= 0:
            a_new = a / 2
        elif a_new >= math.pi / 2:
            a_new = (a + math.pi / 2) / 2
        if abs(a_new - a) < tol:
            return a_new
        a = a_new
    return a


def working_angle(z1: int, z2: int, x_sum: float, alpha_deg: float = ALPHA_DEG) -> float:
    """Working pressure angle α_w [rad] of an external pair from x_Σ = x1 + x2 (seed 000, step 1).

    inv α_w = 2·x_Σ·tan α/(z1 + z2) + inv α.

    >>> round(math.degrees(working_angle(30, 48, 0.0)), 9)
    20.0
    """
    alpha = math.radians(alpha_deg)
    return inv_inverse(2.0 * x_sum * math.tan(alpha) / (z1 + z2) + inv(alpha))


def centre_distance_mm(m_mm: float, z1: int, z2: int, alpha_w: float, alpha_deg: float = ALPHA_DEG) -> float:
    """Centre distance a_w = m(z1 + z2)/2 · cos α / cos α_w [mm] (seed 000, step 2).

    >>> round(centre_distance_mm(5, 30, 48, working_angle(30, 48, -0.4 + 0.4)), 9)
    195.0
    """
    return m_mm * (z1 + z2) / 2.0 * math.cos(math.radians(alpha_deg)) / math.cos(alpha_w)


def shift_sum_for_distance(m_mm: float, z1: int, z2: int, a_w_mm: float, alpha_deg: float = ALPHA_DEG) -> tuple[float, float]:
    """(α_w [rad], x_Σ) of a pair that must run at the centre distance a_w (seed 000, step 3).

    cos α_w = m(z1 + z2)/2 · cos α / a_w;  x_Σ = (inv α_w − inv α)(z1 + z2)/(2 tan α).
    Seed 000's worked example: z3 = 48, z4 = 27 at a_w = 195 mm, m = 5 → α_w = 25.371°, x_Σ = 1.7,
    so with x3 = x2 = 0.4 the fourth wheel gets x4 = 1.3.

    >>> aw, xs = shift_sum_for_distance(5, 48, 27, 195.0)
    >>> round(math.degrees(aw), 3), round(xs, 1), round(xs - 0.4, 1)
    (25.371, 1.7, 1.3)
    """
    alpha = math.radians(alpha_deg)
    cos_aw = m_mm * (z1 + z2) / 2.0 * math.cos(alpha) / a_w_mm
    if not 0.0 < cos_aw <= 1.0:
        raise ValueError("centre distance too small for these tooth numbers")
    aw = math.acos(cos_aw)
    return aw, (inv(aw) - inv(alpha)) * (z1 + z2) / (2.0 * math.tan(alpha))


def involute_xy(r_base: float, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Points of the involute of a circle of radius ``r_base`` for roll angles ``t`` [rad].

    Starts at (r_base, 0) and unwinds counter-clockwise: x = r_b(cos t + t sin t),
    y = r_b(sin t − t cos t) (§2.1.1, Fig. 2.1: the tangent's length equals the rolled arc r_b·t).

    >>> x, y = involute_xy(1.0, np.array([0.0]))
    >>> float(x[0]), float(y[0])
    (1.0, 0.0)
    """
    t = np.asarray(t, dtype=float)
    return r_base * (np.cos(t) + t * np.sin(t)), r_base * (np.sin(t) - t * np.cos(t))


def roll_angle_at_radius(r_base: float, r: float) -> float:
    """Roll angle t [rad] at which the involute reaches radius r: t = √(r² − r_b²)/r_b."""
    return math.sqrt(max(r * r - r_base * r_base, 0.0)) / r_base


def flank_construction(z: int, m_mm: float, ra_mm: float, x: float = 0.0, alpha_deg: float = ALPHA_DEG,
                       steps: int = 4) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The involute construction of one flank (§2.1.1, Fig. 2.1): the base circle divided from
    the flank's start, the lines rolled off it (each tangent at its base point, as long as the arc
    rolled, r_b·t), and their ends — the points of the involute.

    The tooth is the one centred on the +x axis (as ``figures.gears.tooth_outline`` draws it), the
    flank its upper one: it leaves the base circle at the polar angle θ_b = ψ + inv α with
    ψ = (π/2 + 2x·tg α)/z (half the tooth's angular thickness on the pitch circle) and unwinds
    clockwise. Roll angles t_k = k·t_a/steps, k = 0 … steps, t_a the roll angle at the tip r_a.

    Returns (t [rad], base points T_k (steps+1, 2), involute points P_k (steps+1, 2)) [mm].

    >>> t, T, P = flank_construction(20, 10.0, 110.0)
    >>> rb = 100.0 * math.cos(math.radians(20.0))
    >>> bool(np.allclose(np.hypot(*(P - T).T), rb * t))  # each line is as long as the arc rolled
    True
    >>> round(float(np.hypot(*P[-1])), 9)  # the last point is on the tip circle
    110.0
    """
    alpha = math.radians(alpha_deg)
    r = m_mm * z / 2.0
    rb = r * math.cos(alpha)
    psi = (math.pi / 2 + 2 * x * math.tan(alpha)) / z
    theta_b = psi + inv(alpha)
    t = np.linspace(0.0, roll_angle_at_radius(rb, ra_mm), steps + 1)
    ix, iy = involute_xy(rb, t)  # counter-clockwise from (r_b, 0); the flank is its mirror image
    c, s = math.cos(theta_b), math.sin(theta_b)
    P = np.column_stack([c * ix + s * iy, s * ix - c * iy])
    T = rb * np.column_stack([np.cos(theta_b - t), np.sin(theta_b - t)])
    return t, T, P
