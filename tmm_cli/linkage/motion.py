"""Velocities and accelerations of the crank and of the class II groups, exactly.

The loop equations of :mod:`.groups` differentiated once and twice with respect to time (the
analytical form of the velocity and acceleration plans of every TMM textbook: Artobolevsky;
Frolov; Pozhbelko, part 1; a reconstruction in complex numbers). A point P of a link turning at
ω, ε whose point R is known moves as

    v_P = v_R + iω·(P − R),        a_P = a_R + (iε − ω²)·(P − R)

(iω·r is ω × r; −ω²·r the normal and iε·r the tangential acceleration of the plans). Each
group gives two complex (four real) equations linear in its two unknown scalars, solved by
:func:`solve2`. No finite differences anywhere. Units: m, m/s, m/s², rad/s, rad/s²;
counter-clockwise positive.
"""

from __future__ import annotations

import numpy as np


def cross(u, w):
    """The planar cross product u × w = Im(ū·w) (scalar)."""
    return (np.conj(u) * w).imag


def solve2(u1, u2, w):
    """The reals x, y with x·u1 + y·u2 = w for complex u1, u2, w (Cramer's rule).

    >>> [float(x) for x in solve2(1 + 0j, 1j, 2 + 3j)]
    [2.0, 3.0]
    """
    det = cross(u1, u2)
    return cross(w, u2) / det, cross(u1, w) / det


def rigid(r, v_base, a_base, omega, eps):
    """Velocity and acceleration of the point base + r of a link turning at ω, ε [rad/s, rad/s²].

    >>> rigid(0.1 + 0j, 0j, 0j, 10.0, 0.0)   # v = ω·r upwards, a = ω²·r towards the centre
    (1j, (-10+0j))
    """
    return v_base + 1j * omega * r, a_base + (1j * eps - omega * omega) * r


def rrr_motion(a, b, c, va, vc, aa, ac):
    """RRR (kind 1): ω, ε of AB and BC, and v_B, a_B.

    v_B = v_A + iω2·(B − A) = v_C + iω3·(B − C); the same with a_B = a_A + (iε2 − ω2²)(B − A)
    = a_C + (iε3 − ω3²)(B − C): the plans' v_B = v_A + v_BA = v_C + v_BC and
    a_B = a_A + aⁿ_BA + aτ_BA = a_C + aⁿ_BC + aτ_BC.

    >>> w2, w3, e2, e3, vb, ab = rrr_motion(0j, 0.3j, 0.4 + 0.3j, 1 + 0j, 0j, 0j, 0j)
    >>> round(float(w2), 12), abs(round(float(w3), 12))   # A moves across AB: AB turns, B stands
    (3.333333333333, 0.0)
    """
    ra, rc = b - a, b - c
    w2, w3 = solve2(1j * ra, -1j * rc, vc - va)
    vb = va + 1j * w2 * ra
    e2, e3 = solve2(1j * ra, -1j * rc, ac - aa + w2 * w2 * ra - w3 * w3 * rc)
    ab = aa + (1j * e2 - w2 * w2) * ra
    return w2, w3, e2, e3, vb, ab


def rrp_motion(a, b, unit: complex, va, aa):
    """RRP (kind 2) on a fixed guide along `unit`: ω, ε of AB, the slider's ṡ, s̈ along the guide,
    and v_B = ṡ·e, a_B = s̈·e.

    v_B = v_A + iω2·(B − A) with v_B ∥ guide; a_B = a_A + (iε2 − ω2²)(B − A) with a_B ∥ guide.

    >>> w2, e2, ds, dds, vb, ab = rrp_motion(0.06j, 0.2427 + 0j, 1 + 0j, -0.06 + 0j, -0.06j)
    >>> abs(round(float(w2), 12)), round(float(ds), 12)   # crank at 90°, ω1 = 1: AB only shifts
    (0.0, -0.06)
    """
    r = b - a
    ds, w2 = solve2(unit + 0 * r, -1j * r, va)
    dds, e2 = solve2(unit + 0 * r, -1j * r, aa - w2 * w2 * r)
    return w2, e2, ds, dds, ds * unit, dds * unit


def rrp_moving_motion(a, b, unit, va, aa, vg, ag, wg):
    """RRP (kind 2) whose guide rides on a link turning at ω_g: ω, ε of AB, the slider's ṡ, s̈
    along the guide (relative to it), v_B, a_B.

    B = P + s·e with e turning at ω_g; B_g the guide's point under the slider (v_Bg, a_Bg):
    v_B = v_Bg + ṡ·e = v_A + iω2·(B − A), and
    a_B = a_Bg + s̈·e + 2ω_g·ṡ·ie (Coriolis) = a_A + (iε2 − ω2²)(B − A). With ω_g = 0 and the
    guide at rest this is :func:`rrp_motion`.

    >>> w2, e2, ds, dds, vb, ab = rrp_moving_motion(0j, 0.1 + 0j, 1 + 0j, 0j, 0j, -0.1j, -0.1 + 0j, -1.0)
    >>> round(float(ds), 12) + 0.0, round(float(w2), 12)   # the guide along AB turns about A: AB with it, no slide
    (0.0, -1.0)
    """
    r = b - a
    ds, w2 = solve2(unit + 0 * r, -1j * r, va - vg)
    dds, e2 = solve2(unit + 0 * r, -1j * r, aa - w2 * w2 * r - ag - 2j * wg * ds * unit)
    return w2, e2, ds, dds, vg + ds * unit, ag + dds * unit + 2j * wg * ds * unit


def rpr_motion(a, c, va, vc, aa, ac, offset: float = 0.0):
    """RPR (kind 3): ω, ε of the slotted link and the block's ṫ, ẗ along its slot (+ away from
    the foot of the perpendicular from C, i.e. from C when the slot passes through it).

    A − C = (t + i·d)·u, u = e^{iθ} (:func:`.groups.rpr_position`), differentiated:
    v_A − v_C = (ṫ − dω)·u + tω·iu and
    a_A − a_C = (ẗ − dε − tω²)·u + (tε + 2ṫω − dω²)·iu, where 2ṫω is the Coriolis acceleration
    2ω × v_rel (v_rel = ṫ·u, the block relative to the slot). So ω = Im(ū·Δv)/t,
    ṫ = Re(ū·Δv) + dω, ε = (Im(ū·Δa) − 2ṫω + dω²)/t, ẗ = Re(ū·Δa) + dε + tω². With d = 0 this
    is the slotted link through its pivot: t = ρ, ρ̈ = Re(ū·Δa) + ρω², ε = (Im(ū·Δa) − 2ρ̇ω)/ρ.

    >>> w, e, dr, ddr = rpr_motion(0.14j, 0j, -1 + 0j, 0j, -7.142857j, 0j)
    >>> round(float(w), 9), round(float(dr), 9)   # A at the top, moving left: the link turns ccw
    (7.142857143, 0.0)
    """
    r = a - c
    if offset == 0.0:
        t = np.abs(r)
        u = r / t
    else:
        t = np.sqrt(np.abs(r) ** 2 - offset * offset)
        u = r / (t + 1j * offset)
    dv = (va - vc) * np.conj(u)
    da = (aa - ac) * np.conj(u)
    w = dv.imag / t
    if offset == 0.0:
        return w, (da.imag - 2.0 * dv.real * w) / t, dv.real, da.real + t * w * w
    dt = dv.real + offset * w
    e = (da.imag - 2.0 * dt * w + offset * w * w) / t
    return w, e, dt, da.real + offset * e + t * w * w
