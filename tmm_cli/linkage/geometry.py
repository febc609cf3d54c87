"""Positions of the slotted-link (Whitworth) quick-return mechanism from its two vector loops.

Seed 003, first article (Goban, Monková, Šmeringaiová), Fig. 1 and eqs. (1)–(3), in the article's
frame: origin at the crank centre O21, x to the right, y up. Links: 1 frame, 2 crank O21A = r1,
3 block (slider) at A, 4 slotted link (кулиса) pivoted at O41 = (−c, −h), 5 rod BC = r3,
6 ram, C on the line y = b. B lies on the link at r2 from O41, on the side of the block; C is
left of B (as the article draws it, eq. (3) with the minus sign).

Angles are measured as the article measures them: from +y towards +x (clockwise on the page), so
A = (r1·sin φ21, r1·cos φ21) and the unit vector of the link is u = (sin φ41, cos φ41).

Loop 1 (crank, link):  O21A = O21O41 + ρ·u(φ41)          -> φ41, ρ
Loop 2 (link, rod, ram): O41B + BC = O41C, C on y = b     -> x_C, rod angle ψ

The article writes φ41 = arctg((c + r1·sin φ21)/(h + r1·cos φ21)); that puts the link on the
wrong side wherever h + r1·cos φ21 < 0. Here φ41 comes from atan2 of the whole vector O41A and is
kept on a continuous branch: near the direction O41→O21 when the link oscillates (crank-shaper,
√(c² + h²) > r1), near the crank angle when it turns fully (Whitworth, √(c² + h²) < r1).
SI units throughout: metres and radians.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import TmmError
from ..limits import LINKAGE_LENGTH_M
from ..records import record

WHITWORTH = "whitworth"
CRANK_SHAPER = "crank_shaper"


@record
class Geometry:
    """The mechanism's dimensions [m], the article's symbols (seed 003, Fig. 1)."""

    r1: float  # crank O21A
    h: float  # the link's pivot O41 lies h below O21
    c: float  # ... and c to the left of it (negative: to the right)
    r2: float  # O41B on the link
    r3: float  # rod BC
    b: float  # the ram's guide is the line y = b

    @property
    def d0(self) -> float:
        """Distance O21O41 = √(c² + h²) [m]."""
        return math.hypot(self.c, self.h)

    @property
    def regime(self) -> str:
        """'whitworth' (the link turns fully, O41 inside the crank circle) or 'crank_shaper'."""
        return WHITWORTH if self.d0 < self.r1 else CRANK_SHAPER

    @property
    def rho_min(self) -> float:
        """Smallest distance O41A of the block from the link's pivot: |√(c² + h²) − r1| [m]."""
        return abs(self.d0 - self.r1)

    @property
    def rho_max(self) -> float:
        """Largest distance O41A: √(c² + h²) + r1 [m] (the slot must be at least this long)."""
        return self.d0 + self.r1

    @property
    def swing_half_rad(self) -> float:
        """Half the link's swing, asin(r1/√(c² + h²)) [rad] (crank-shaper); π for a turning link.

        >>> round(math.degrees(Geometry(0.1, 0.2, 0.0, 0.5, 0.2, 0.2).swing_half_rad), 6)
        30.0
        """
        if self.regime == WHITWORTH:
            return math.pi
        return math.asin(self.r1 / self.d0)

    @property
    def link_axis_rad(self) -> float:
        """φ41 of the line O41→O21, atan2(c, h) [rad]: the middle of the link's swing."""
        return math.atan2(self.c, self.h)

    def y_b_range(self) -> tuple[float, float]:
        """Lowest and highest y of B over a crank turn [m], exactly (from the link's angle range)."""
        if self.regime == WHITWORTH:
            return -self.h - self.r2, -self.h + self.r2
        lo, hi = self.link_axis_rad - self.swing_half_rad, self.link_axis_rad + self.swing_half_rad
        cos_ends = (math.cos(lo), math.cos(hi))
        cmax = 1.0 if lo <= 0.0 <= hi else max(cos_ends)
        cmin = min(cos_ends)  # |φ41| < π on the swing, so cos has no interior minimum
        return -self.h + self.r2 * cmin, -self.h + self.r2 * cmax

    def rod_reach(self) -> float:
        """Largest |b − y_B| over a turn [m]; the rod reaches the guide only while it is below r3."""
        lo, hi = self.y_b_range()
        return max(abs(self.b - lo), abs(self.b - hi))


LENGTH_MAX_M = LINKAGE_LENGTH_M[1]  # every length and offset [m]: a shaping machine's links are well below a metre


def _finite(name: str, value) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise TmmError(f"{name} is {value!r}; give a number in metres") from None
    if not math.isfinite(x):
        raise TmmError(f"{name} is {value}; give a finite number in metres")
    return x


def make_geometry(r1, h, c, r2, r3, b) -> Geometry:
    """Check the dimensions [m] and return the :class:`Geometry`; TmmError if it cannot close.

    The mechanism closes for every crank angle when: r1, h, r2, r3 > 0; the crank circle does not
    pass through the link's pivot (ρ would vanish and the link's angle be undefined); in the
    crank-shaper regime the block stays on the link O41B (√(c² + h²) + r1 ≤ r2); and the rod
    reaches the ram's guide in every position, |b − y_B| < r3 (at equality the rod stands
    across the guide and the ram's speed is infinite).

    >>> make_geometry(0.10, 0.04, 0.0, 0.08, 0.30, -0.04).regime
    'whitworth'
    >>> make_geometry(0.10, 0.0, 0.0, 0.08, 0.30, -0.04)
    Traceback (most recent call last):
    ...
    tmm_cli.errors.TmmError: --h is 0 m; lengths must be positive (the link's pivot O41 lies h below the crank centre)
    """
    r1, h, c, r2, r3, b = (_finite(f"--{n}", v) for n, v in zip(("r1", "h", "c", "r2", "r3", "b"), (r1, h, c, r2, r3, b)))
    what = {
        "r1": "the crank O21A",
        "h": "the link's pivot O41 lies h below the crank centre",
        "r2": "the link's arm O41B",
        "r3": "the rod BC",
    }
    for name, value in (("r1", r1), ("h", h), ("r2", r2), ("r3", r3)):
        if value <= 0:
            raise TmmError(f"--{name} is {value:g} m; lengths must be positive ({what[name]})")
        if value < LINKAGE_LENGTH_M[0]:
            raise TmmError(f"--{name} is {value:g} m, below the shortest length of {LINKAGE_LENGTH_M[0]:g} m (0.1 mm); "
                           "give metres (e.g. 0.1 for a 100 mm crank)")
    for name, value in (("r1", r1), ("h", h), ("c", c), ("r2", r2), ("r3", r3), ("b", b)):
        if abs(value) > LENGTH_MAX_M:
            raise TmmError(f"--{name} is {value:g} m, over the limit of {LENGTH_MAX_M:g} m; give metres "
                           "(e.g. 0.1 for a 100 mm crank)")
    g = Geometry(r1, h, c, r2, r3, b)
    if abs(g.d0 - r1) <= 1e-9 * r1:
        raise TmmError(
            f"the crank circle passes through the link's pivot O41 (√(c² + h²) = r1 = {r1:g} m): the block would "
            "run into the pivot and the link's angle is undefined; change --h or --c"
        )
    if g.regime == CRANK_SHAPER and g.rho_max > r2 * (1 + 1e-12):
        raise TmmError(
            f"the block leaves the slotted link: it reaches {g.rho_max:.6g} m from O41 (√(c² + h²) + r1) but the "
            f"link O41B is only r2 = {r2:g} m long; make --r2 at least {g.rho_max:.6g} m or shorten --r1"
        )
    reach = g.rod_reach()
    if reach >= r3:
        raise TmmError(
            f"the rod cannot reach the ram's guide: B comes {reach:.6g} m from the line y = b = {b:g} m but the rod "
            f"BC is r3 = {r3:g} m; make --r3 longer than {reach:.6g} m or move the guide (--b)"
        )
    return g


def _wrap(x):
    """Angle(s) folded into [−π, π)."""
    return (np.asarray(x) + math.pi) % (2 * math.pi) - math.pi


def link_angle(g: Geometry, phi):
    """φ41 [rad] for crank angle(s) φ21 [rad], on the continuous branch (seed 003, eq. (1) corrected).

    The article's arctg((c + r1·sin φ21)/(h + r1·cos φ21)) is replaced by atan2 of the vector
    O41A = (c + r1·sin φ21, h + r1·cos φ21), folded to within ±π of a reference that moves
    continuously: the crank angle itself when the link turns fully, the line O41O21 when it swings.

    >>> g = make_geometry(0.10, 0.04, 0.0, 0.08, 0.30, -0.04)
    >>> round(math.degrees(float(link_angle(g, math.radians(180.0)))), 9)   # arctg would give 0°
    180.0
    """
    phi = np.asarray(phi, dtype=float)
    raw = np.arctan2(g.c + g.r1 * np.sin(phi), g.h + g.r1 * np.cos(phi))
    ref = phi if g.regime == WHITWORTH else g.link_axis_rad
    return ref + _wrap(raw - ref)


@record
class Positions:
    """Positions of the mechanism at crank angles `phi` (arrays, or 0-d arrays for one angle)."""

    phi: np.ndarray  # φ21 [rad]
    link: np.ndarray  # φ41 [rad], continuous branch
    rho: np.ndarray  # O41A, the block's place on the link [m]
    a: np.ndarray  # A, shape (..., 2) [m]
    b: np.ndarray  # B, shape (..., 2) [m]
    x_c: np.ndarray  # ram point C = (x_c, g.b) [m]
    psi: np.ndarray  # rod angle: B − C = r3·(cos ψ, sin ψ), ψ in (−π/2, π/2) [rad]
    residual: float  # largest loop-closure error over the given angles [m]


def positions(g: Geometry, phi) -> Positions:
    """Solve both vector loops at crank angle(s) φ21 [rad] (seed 003, eqs. (1)–(3)).

    x_C = x_B − √(r3² − (b − y_B)²) is eq. (3) with φ41 from :func:`link_angle`.

    >>> p = positions(make_geometry(0.10, 0.04, 0.0, 0.08, 0.30, -0.04), math.radians(90 + math.degrees(math.asin(0.4))))
    >>> round(float(p.x_c), 12), round(float(p.rho), 12)   # link horizontal: B = (r2, −h), C = B − (r3, 0)
    (-0.22, 0.091651513899)
    """
    phi = np.asarray(phi, dtype=float)
    link = link_angle(g, phi)
    su, cu = np.sin(link), np.cos(link)
    ax, ay = g.r1 * np.sin(phi), g.r1 * np.cos(phi)
    sx, sy = ax + g.c, ay + g.h  # O41A
    rho = np.hypot(sx, sy)
    bx, by = -g.c + g.r2 * su, -g.h + g.r2 * cu
    dy = by - g.b
    sin_psi = dy / g.r3
    psi = np.arcsin(sin_psi)
    x_c = bx - np.sqrt(g.r3 * g.r3 - dy * dy)
    res1 = np.hypot(sx - rho * su, sy - rho * cu)  # O41A − ρ·u
    res2 = np.abs(np.hypot(bx - x_c, dy) - g.r3)  # |BC| − r3
    residual = float(max(np.max(res1, initial=0.0), np.max(res2, initial=0.0)))
    return Positions(phi, link, rho, np.stack([ax, ay], axis=-1), np.stack([bx, by], axis=-1), x_c, psi, residual)
