"""Positions of the crank and of the class II groups in closed form (the group's vector loop).

Planar vectors are complex numbers x + iy [m]; every function takes numpy arrays (one entry per
crank angle) or scalars. The closed forms are the standard ones of TMM textbooks (Artobolevsky;
Frolov; Pozhbelko, part 1: the analytical kinematics of the groups of kinds 1–3), written here
with complex numbers (a reconstruction, not a copy of one book's notation):

- crank: A = O + r·e^{iφ};
- RRR (kind 1): B on both circles |B − A| = l1, |B − C| = l2 (circle–circle);
- RRP (kind 2): B on the circle |B − A| = l and on the guide line (circle–line);
- RPR (kind 3): the slotted link through C points at the block's joint A (line through a point).

Each group also has an assembly margin [m]: positive while the group can be assembled, zero at a
dead point (links in line), negative where it cannot be (see :mod:`.assembly`).
"""

from __future__ import annotations

import numpy as np


def crank_position(pivot: complex, length: float, phi):
    """The crank's joint A = O + r·e^{iφ} [m] for crank angle(s) φ [rad] from +x, counter-clockwise.

    >>> complex(crank_position(0j, 0.1, np.pi / 2)).imag
    0.1
    """
    return pivot + length * np.exp(1j * np.asarray(phi, dtype=float))


def rrr_margin(a, c, l1: float, l2: float):
    """Assembly margin of an RRR group [m]: min(l1 + l2 − |AC|, |AC| − |l1 − l2|).

    >>> float(rrr_margin(0j, 0.3 + 0j, 0.2, 0.15))   # 0.35 − 0.30 and 0.30 − 0.05
    0.04999999999999999
    """
    d = np.abs(np.asarray(c) - np.asarray(a))
    return np.minimum(l1 + l2 - d, d - abs(l1 - l2))


def rrr_position(a, c, l1: float, l2: float, branch: int):
    """The joint B of an RRR group with |AB| = l1, |BC| = l2 [m] (kind 1, circle–circle).

    With d = |AC|, the foot of B on AC lies p = (d² + l1² − l2²)/(2d) from A and B is
    h = √(l1² − p²) off the line: B = A + (p + i·branch·h)·(C − A)/d, branch +1 putting B left of
    the directed line A → C, −1 right of it. NaN where the group cannot be assembled.

    >>> b = complex(rrr_position(0j, 0.5 + 0j, 0.3, 0.4, +1))   # the 3-4-5 triangle
    >>> round(b.real, 12), round(b.imag, 12)
    (0.18, 0.24)
    """
    a, c = np.asarray(a), np.asarray(c)
    ac = c - a
    d = np.abs(ac)
    p = (d * d + l1 * l1 - l2 * l2) / (2.0 * d)
    with np.errstate(invalid="ignore"):
        h = np.sqrt(l1 * l1 - p * p)
    return a + (p + 1j * branch * h) * ac / d


def line_coordinates(z, through: complex, unit: complex):
    """(t, h) of point(s) z in the frame of a line through `through` along `unit` [m]:
    t along the line, h to its left.

    >>> [float(x) for x in line_coordinates(1 + 2j, 0j, 1j)]
    [2.0, -1.0]
    """
    w = (np.asarray(z) - through) * np.conj(unit)
    return w.real, w.imag


def rrp_margin(a, through: complex, unit: complex, length: float):
    """Assembly margin of an RRP group [m]: l − |h|, h the distance from A to the guide line.

    >>> float(rrp_margin(0.1j, 0j, 1 + 0j, 0.25))
    0.15
    """
    _, h = line_coordinates(a, through, unit)
    return length - np.abs(h)


def rrp_position(a, through: complex, unit: complex, length: float, branch: int):
    """The slider's joint B of an RRP group and its place s on the guide [m] (kind 2, circle–line).

    B = P + s·e on the guide through P along e, |B − A| = l: s = t + branch·√(l² − h²), where t
    and h are A's coordinates along and across the guide; branch +1 puts B ahead of the foot of
    the perpendicular from A (along e), −1 behind it. For the central crank-slider
    (P = O, e = +x, A = r·e^{iφ}) this is the textbook x_B = r·cos φ + √(l² − r²·sin² φ).

    >>> b, s = rrp_position(0.06j, 0j, 1 + 0j, 0.25, +1)   # crank at 90°: x_B = √(l² − r²)
    >>> round(float(s), 12), round(complex(b).imag, 12)
    (0.24269322199, 0.0)
    """
    t, h = line_coordinates(a, through, unit)
    with np.errstate(invalid="ignore"):
        s = t + branch * np.sqrt(length * length - h * h)
    return through + s * unit, s


def rpr_position(a, c, offset: float = 0.0):
    """The slotted link of an RPR group: the block's place t along the slot [m] and the slot's
    direction θ from +x [rad] (kind 3).

    The link turns about C and the block on the joint A slides along its slot, the line
    C + d·n + t·u at the distance d (`offset`) from C, u = e^{iθ} pointing from the foot of the
    perpendicular from C towards the block and n = i·u: A − C = (t + i·d)·u, so
    t = √(|CA|² − d²) and θ = arg(A − C) − arctan(d/t). With d = 0 the link points from C at A
    (t = ρ = |CA|); its angle as named AC (from A towards C) is then θ + π.

    >>> rho, theta = rpr_position(0.1j, -0.04j)
    >>> round(float(rho), 12), round(float(np.degrees(theta)), 12)
    (0.14, 90.0)
    >>> t, theta = rpr_position(0.3 + 0.4j, 0j, 0.3)   # |CA| = 0.5, d = 0.3: t = 0.4
    >>> round(float(t), 12), round(float(np.degrees(theta)), 9)   # u = (0.3 + 0.4i)/(0.4 + 0.3i)
    (0.4, 16.260204708)
    """
    r = np.asarray(a) - np.asarray(c)
    if offset == 0.0:
        return np.abs(r), np.angle(r)
    with np.errstate(invalid="ignore"):
        t = np.sqrt(np.abs(r) ** 2 - offset * offset)
    return t, np.angle(r / (t + 1j * offset))


def rpr_margin(a, c, offset: float = 0.0):
    """Assembly margin of an RPR group [m]: |CA| − |d| (the block's joint cannot come nearer the
    pivot than the slot's offset; at |CA| = |d| the slot's direction is undefined).

    >>> float(rpr_margin(0.5j, 0j, 0.3))
    0.2
    """
    return np.abs(np.asarray(a) - np.asarray(c)) - abs(offset)
