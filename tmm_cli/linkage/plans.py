"""The velocity plan and the acceleration plan at one crank position, as vectors (no drawing).

The graphical method of a Russian TMM textbook (план скоростей, план ускорений), written out as
vector sums; each point of a plan is the tip of a vector drawn from the pole (p for velocities,
π for accelerations). Links numbered as in seed 003: 2 crank, 3 block, 4 slotted link, 5 rod,
6 ram. A2 is the crank pin (the block turns on it, so A3 moves with A2), A4 the point of the link
under the block.

Velocities:  v_A2 = ω2 × O21A (pa2 ⊥ O21A);  v_A4 = v_A2 + v_A4A2 (pa4 ⊥ O41A, a2a4 ∥ link);
             v_B = v_A4·O41B/O41A (pb, similarity);  v_C = v_B + v_CB (pc ∥ guide, bc ⊥ BC).
Accelerations: a_A2 = a^n_A2 + a^τ_A2 (πn1 ∥ AO21, n1a2 ⊥ O21A, zero for a uniform crank);
             a_A4 = a_A2 + a^k_A4A2 + a^r_A4A2 (a2k the Coriolis 2·ω4 × v_A4A2, ka4 ∥ link)
                  = a^n_A4 + a^τ_A4 (πn4 ∥ AO41 of length ω4²·O41A, n4a4 ⊥ link);
             a_B = a_A4·O41B/O41A (πb);  a_C = a_B + a^n_CB + a^τ_CB (bn5 ∥ CB of length ω5²·r3,
             n5c ⊥ BC, πc ∥ guide).
Vectors in SI (m/s, m/s²) in the article's frame (x right, y up).
"""

from __future__ import annotations

import math

from ..records import record
from .geometry import Geometry, positions
from .kinematics import motion, transfer

Vec = tuple[float, float]


@record
class Plan:
    """A vector polygon: the tips of its vectors (pole at the origin) and the segments drawn.

    `points` maps a label ('p', 'a2', 'a4', ...) to its place; `segments` lists
    (from, to, name) where name is the vector's symbol (e.g. 'v_A4A2').
    """

    kind: str  # 'velocity' or 'acceleration'
    points: dict[str, Vec]
    segments: tuple[tuple[str, str, str], ...]

    def vector(self, start: str, end: str) -> Vec:
        (x0, y0), (x1, y1) = self.points[start], self.points[end]
        return (x1 - x0, y1 - y0)

    def length(self, start: str, end: str) -> float:
        return math.hypot(*self.vector(start, end))


@record
class Plans:
    phi: float  # crank angle φ21 [rad]
    velocity: Plan
    acceleration: Plan


def _v(x) -> Vec:
    return (float(x[0]), float(x[1]))


def plans(g: Geometry, phi: float, omega: float, eps: float = 0.0) -> Plans:
    """Both plans at crank angle φ21 [rad] for a crank at ω21 [rad/s], ε21 [rad/s²].

    >>> from .geometry import make_geometry
    >>> g = make_geometry(0.10, 0.04, 0.0, 0.08, 0.30, -0.04)
    >>> pl = plans(g, 0.0, 10.0)
    >>> round(pl.velocity.length("p", "a2"), 12), round(pl.velocity.length("p", "c"), 9)   # ω·r1; v_C
    (1.0, 0.571428571)
    """
    import numpy as np

    pos = positions(g, phi)
    tr = transfer(g, pos)
    m = motion(tr, omega, eps)
    link, rho = float(pos.link), float(pos.rho)
    u = np.array([math.sin(link), math.cos(link)])
    n = np.array([math.cos(link), -math.sin(link)])
    e = np.array([math.cos(phi), -math.sin(phi)])  # direction of the crank pin's velocity
    a_pt = pos.a
    b_pt = pos.b
    c_pt = np.array([float(pos.x_c), g.b])
    w4 = float(m.omega_link)
    v_rel, a_rel = float(m.v_rel), float(m.a_rel)
    w5 = float(m.omega_rod)

    # velocity plan (pole p)
    va2 = omega * g.r1 * e
    va4 = w4 * rho * n
    vb = w4 * g.r2 * n
    vc = np.array([float(m.v_c), 0.0])
    velocity = Plan(
        "velocity",
        {"p": (0.0, 0.0), "a2": _v(va2), "a4": _v(va4), "b": _v(vb), "c": _v(vc)},
        (
            ("p", "a2", "v_A2"),
            ("a2", "a4", "v_A4A2"),
            ("p", "a4", "v_A4"),
            ("p", "b", "v_B"),
            ("b", "c", "v_CB"),
            ("p", "c", "v_C"),
        ),
    )

    # acceleration plan (pole π)
    an_a2 = -omega * omega * a_pt  # towards O21
    aa2 = an_a2 + eps * g.r1 * e
    k = aa2 - 2.0 * w4 * v_rel * n  # a^k_A4A2 = 2·ω4 × v_A4A2, v_A4A2 = −v_rel·u
    aa4 = k - a_rel * u  # a^r_A4A2 = −(d²ρ/dt²)·u
    n4 = -w4 * w4 * rho * u  # a^n_A4, towards O41
    ab = aa4 * (g.r2 / rho)
    n5 = ab + w5 * w5 * (b_pt - c_pt)  # a^n_CB, from C towards B
    ac = np.array([float(m.a_c), 0.0])
    points = {"π": (0.0, 0.0), "n1": _v(an_a2), "a2": _v(aa2), "k": _v(k), "a4": _v(aa4), "n4": _v(n4),
              "b": _v(ab), "n5": _v(n5), "c": _v(ac)}
    segs = [("π", "n1", "a^n_A2")]
    if eps != 0.0:
        segs.append(("n1", "a2", "a^τ_A2"))
    segs += [
        ("π", "a2", "a_A2"),
        ("a2", "k", "a^k_A4A2"),
        ("k", "a4", "a^r_A4A2"),
        ("π", "n4", "a^n_A4"),
        ("n4", "a4", "a^τ_A4"),
        ("π", "a4", "a_A4"),
        ("π", "b", "a_B"),
        ("b", "n5", "a^n_CB"),
        ("n5", "c", "a^τ_CB"),
        ("π", "c", "a_C"),
    ]
    acceleration = Plan("acceleration", points, tuple(segs))
    return Plans(float(phi), velocity, acceleration)
