"""Can every group be assembled at every crank angle? If not: where, and which link is too short.

Each group's assembly margin (:mod:`.groups`) is sampled over the turn and its local minima are
refined by golden-section search, so a failure narrower than the grid is still found; the message
names the crank angle of the worst place and the length that would be needed. A margin of zero is
a dead point (two links in line, the speeds infinite) and is refused too.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import TmmError
from ..records import record
from .chain import guide_frame, solve
from .groups import rpr_margin, rrp_margin, rrr_margin
from .mechanism import Group, Mechanism

GRID = 720  # samples per turn
GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0
TOLERANCE = 1e-9  # of the mechanism's size: a margin below this is a dead point


@record
class Margin:
    """The smallest assembly margin of a group over the turn and where it occurs."""

    group: int
    margin: float  # [m]
    phi: float  # crank angle [rad], in [0, 2π)


def golden_min(f, lo, hi, iterations: int = 60):
    """Minimise f (vectorised) on each bracket [lo, hi]; returns (x, f(x)) arrays.

    >>> x, fx = golden_min(lambda t: (t - 0.3) ** 2, np.array([0.0]), np.array([1.0]))
    >>> round(float(x[0]), 9), float(fx[0]) < 1e-17
    (0.3, True)
    """
    lo, hi = np.asarray(lo, dtype=float).copy(), np.asarray(hi, dtype=float).copy()
    x1, x2 = hi - GOLDEN * (hi - lo), lo + GOLDEN * (hi - lo)
    f1, f2 = f(x1), f(x2)
    for _ in range(iterations):
        left = f1 < f2  # the minimum lies in [lo, x2]
        hi = np.where(left, x2, hi)
        lo = np.where(left, lo, x1)
        nx1, nx2 = np.where(left, hi - GOLDEN * (hi - lo), x2), np.where(left, x1, lo + GOLDEN * (hi - lo))
        fn = f(np.where(left, nx1, nx2))
        f2, f1 = np.where(left, f1, fn), np.where(left, fn, f2)
        x1, x2 = nx1, nx2
    x = 0.5 * (lo + hi)
    return x, f(x)


def group_margin(mech: Mechanism, g: Group, phi):
    """The assembly margin [m] of group g at crank angle(s) φ (the groups before it placed)."""
    k = solve(mech, phi, upto=g.index - 1)
    if g.kind == "RRR":
        return rrr_margin(k.z[g.joints[0]], k.z[g.joints[2]], *g.lengths)
    if g.kind == "RRP":
        if g.guide.moving:
            through, unit = guide_frame(mech, g, k)
            return rrp_margin(k.z[g.joints[0]], through, unit, g.lengths[0])
        return rrp_margin(k.z[g.joints[0]], g.guide.through, g.guide.unit, g.lengths[0])
    if g.kind == "PRP":  # the guides must cross: the sine of their angle, times the mechanism's size
        e1, e2 = (np.exp(1j * np.angle(_guide_unit(mech, g, k, gd))) for gd in g.guides)
        return np.abs((np.conj(e1) * e2).imag) * mech.scale_m
    if g.kind == "RPP":  # the slot crosses the guide at slot_deg, checked when read
        return np.full(k.phi.shape, abs(math.sin(g.slot)) * mech.scale_m)
    if g.offset != 0.0:
        return rpr_margin(k.z[g.joints[0]], k.z[g.joints[1]], g.offset)
    return np.abs(k.z[g.joints[0]] - k.z[g.joints[1]])


def _guide_unit(mech, g, k, gd):
    from .chain import _guide_line

    return np.zeros(k.phi.shape, dtype=complex) + _guide_line(mech, g, k.z, k.angle, gd)[1]


def smallest_margin(mech: Mechanism, g: Group) -> Margin:
    """The group's smallest margin over a turn: grid, then golden-section search at each dip."""
    step = 2.0 * math.pi / GRID
    grid = np.arange(GRID) * step
    m = group_margin(mech, g, grid)
    dips = np.nonzero((m <= np.roll(m, 1)) & (m <= np.roll(m, -1)))[0]
    x, fx = golden_min(lambda t: group_margin(mech, g, t), grid[dips] - step, grid[dips] + step)
    i = int(np.argmin(fx))
    return Margin(g.index, float(fx[i]), float(np.mod(x[i], 2.0 * math.pi)))


def _failure(mech: Mechanism, g: Group, worst: Margin) -> str:
    deg = math.degrees(worst.phi)
    where = f"group {g.index} ({g.label}) cannot be assembled at φ = {deg:.1f}°"
    if g.kind == "RRR":
        ja, jb, jc = g.joints
        l1, l2 = g.lengths
        k = solve(mech, [worst.phi], upto=g.index - 1)
        d = float(abs(k.z[jc][0] - k.z[ja][0]))
        if l1 + l2 - d <= d - abs(l1 - l2):
            return (f"{where}: |{ja}{jc}| = {d:.7g} m but {ja}{jb} + {jb}{jc} = {l1 + l2:.7g} m; make {ja}{jb} + "
                    f"{jb}{jc} longer than {d:.7g} m")
        short, long_ = (f"{ja}{jb}", f"{jb}{jc}") if l1 < l2 else (f"{jb}{jc}", f"{ja}{jb}")
        return (f"{where}: |{ja}{jc}| = {d:.7g} m but |{ja}{jb} − {jb}{jc}| = {abs(l1 - l2):.7g} m; {short} is too "
                f"short beside {long_}: make it longer than {max(l1, l2) - d:.7g} m")
    if g.kind == "RRP":
        ja, jb = g.joints
        h = g.lengths[0] - worst.margin
        return (f"{where}: {ja} comes {h:.7g} m from the guide of {jb} but {ja}{jb} = {g.lengths[0]:.7g} m; make "
                f"{ja}{jb} longer than {h:.7g} m")
    if g.kind in ("PRP", "RPP"):
        return (f"{where}: the guides of {g.joints[0]} run parallel there (they do not cross); turn one of "
                "them")
    ja, jc = g.joints
    if g.offset != 0.0:
        d = abs(g.offset) + worst.margin
        return (f"{where}: the block's joint {ja} comes {d:.7g} m from the pivot {jc} but the slot passes "
                f"{abs(g.offset):.7g} m from it; make the offset smaller than {d:.7g} m or move {jc}")
    return (f"{where}: the block's joint {ja} passes through the pivot {jc} of the slotted link (its angle is "
            f"undefined); move {jc} off the path of {ja}")


def check_assembly(mech: Mechanism, source: str = "mechanism") -> tuple[Margin, ...]:
    """Each group's smallest assembly margin; TmmError (naming the group, the crank angle and the
    link to lengthen) if some group cannot be assembled, or reaches a dead point, in a turn."""
    tol = TOLERANCE * mech.scale_m
    out = []
    for g in mech.groups:
        worst = smallest_margin(mech, g)
        if worst.margin <= tol:
            raise TmmError(f"{source}: {_failure(mech, g, worst)}")
        out.append(worst)
    return tuple(out)
