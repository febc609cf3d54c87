"""Powers of the applied forces, from the kinematics alone: the balancing moment by the power
balance, the reduced moment and the reduced moment of inertia.

The standard reduction to the crank (Artobolevsky, "Приведение сил и масс"; Frolov, "Динамика
машин"; METHOD.md "Sheets 1 and 2"):

- the power balance of the whole mechanism with d'Alembert's forces,
  Σ(F·v_F + M·ω) + M_b·ω₁ = 0, gives the balancing moment M_b without any reaction;
- the reduced moment of the forces F_k, M_k is M_r = Σ(F_k·v_k + M_k·ω_k)/ω₁;
- the reduced moment of inertia is J_r = Σ(m·v_S² + J_S·ω²)/ω₁² (the links' kinetic energy
  equals J_r·ω₁²/2).

All moments counter-clockwise positive, ω₁ signed (negative for a crank turning clockwise); a
force's power is F·v = Re(F̄·v) with v the velocity of the link's point where it acts.
"""

from __future__ import annotations

import numpy as np

from .chain import Kinematics
from .forces import AppliedCouple, AppliedForce, Loading
from .masses import centre_motion


def dot(f, v):
    """The planar dot product F·v = Re(F̄·v) of complex vectors.

    >>> float(dot(3 + 4j, 2 - 1j))
    2.0
    """
    return (np.conj(f) * v).real


def force_power(kin: Kinematics, force: AppliedForce):
    """F·v [W] of a force at the point of its link where it acts."""
    v, _ = kin.body_point(force.link, force.z)
    return dot(force.f, v)


def couple_power(kin: Kinematics, couple: AppliedCouple):
    """M·ω [W] of a couple on a link turning at ω."""
    return couple.m * kin.omega[couple.link]


def total_power(kin: Kinematics, loading: Loading, kinds=None):
    """Σ(F·v + M·ω) [W] of the applied forces and couples (of the given kinds only, if given)."""
    total = np.zeros(kin.phi.shape)
    for f in loading.forces:
        if kinds is None or f.kind in kinds:
            total = total + force_power(kin, f)
    for c in loading.couples:
        if kinds is None or c.kind in kinds:
            total = total + couple_power(kin, c)
    return total


def balancing_moment_by_power(kin: Kinematics, loading: Loading):
    """M_b = −Σ(F·v + M·ω)/ω₁ [N·m]: the moment the motor applies to the crank, from the power
    balance of every applied force with d'Alembert's inertia forces (no reaction does work in
    frictionless pairs)."""
    return -total_power(kin, loading) / kin.omega1


def reduced_moment(kin: Kinematics, loading: Loading):
    """M_r = Σ(F·v + M·ω)/ω₁ [N·m] of the resistance and the weights (no inertia), ccw positive:
    the moment on the crank doing the same work as they do."""
    return total_power(kin, loading, ("load", "weight")) / kin.omega1


def reduced_inertia(kin: Kinematics, masses, extra: float = 0.0):
    """J_r = Σ(m·v_S² + J_S·ω²)/ω₁² + extra [kg·m²] (extra: a rotor's inertia reduced to the crank).

    For the central crank-slider with a massless rod and a slider of mass m at φ = 90°, v_B = ω·r:
    J_r = m·r².

    >>> from .mechanism_file import parse_mechanism
    >>> from .chain import solve
    >>> from .masses import Mass
    >>> mech = parse_mechanism({"frame": {"O": [0, 0]}, "crank": {"pivot": "O", "joint": "A",
    ...     "length": 0.1, "omega": 10.0}, "group": [{"kind": "RRP", "joints": ["A", "B"],
    ...     "length": 0.3, "guide": {"through": [0, 0], "angle_deg": 0}, "branch": "ahead"}]})
    >>> slider = Mass("B", 3, 2.0, 0.0, "B", None, "B")
    >>> round(float(reduced_inertia(solve(mech, [np.pi / 2]), [slider])[0]), 15)
    0.02
    """
    total = np.full(kin.phi.shape, float(extra))
    w1 = kin.omega1
    for ms in masses:
        _, v, _ = centre_motion(kin, ms)
        total = total + (ms.m * np.abs(v) ** 2 + ms.J * kin.omega[ms.link] ** 2) / (w1 * w1)
    return total
