"""The blocking-contour checks of a shifted external pair, each with its number and verdict.

A blocking contour (Болотовский И. А. и др., «Справочник по геометрическому расчёту эвольвентных
зубчатых и червячных передач», 1986) bounds the shifts (x1, x2) a pair may take. Instead of reading
a chart the program computes the lines that bound it, for the pair at hand:

* undercut: x ≥ x_min = h_a*(17 − z)/17 on each gear;
* tip thickness: s_a ≥ 0.25·m on each gear (the limit this program uses; s_a ≤ 0 is a pointed tooth,
  an error);
* transverse contact ratio: ε_α ≥ 1.2 (recommended) and ≥ 1.05 (hard limit);
* no fillet interference: on each gear the contact must start beyond the lower limit point of the
  involute cut by the rack (roll length N1P1 ≥ ρ_l1 on gear 1, N2P2 ≥ ρ_l2 on gear 2, and both ≥ 0);
* planetary mechanisms: neighbouring with the real tip circles, d_a,planet < 2a_w·sin(π/k).
"""

from __future__ import annotations

import math

from ..notes import Note
from ..records import record
from .shifted import PairGeometry

SA_MIN_FACTOR = 0.25
"""Smallest tip thickness s_a ≥ 0.25·m (the usual limit for hardened gears is 0.4·m; 0.25·m is the
limit for unhardened ones, Болотовский, 1986)."""
EPS_MIN = 1.2
EPS_HARD = 1.05
_TOL = 1e-9


@record
class Check:
    """One line of the contour: ``value`` against ``limit``; ``gear`` is 1 or 2 within the pair (None
    for the pair as a whole); ``hard`` marks a failed hard limit (ε_α < 1.05)."""

    code: str  # "undercut" | "tip_thickness" | "eps_alpha" | "interference" | "neighbours"
    gear: int | None
    value: float
    limit: float
    ok: bool
    hard: bool = False


@record
class PairChecks:
    """All checks of one pair plus the per-gear verdicts (True means the defect is present)."""

    checks: tuple[Check, ...]
    undercut: tuple[bool, bool]
    interference: tuple[bool, bool]
    pointed: tuple[bool, bool]  # s_a below the limit 0.25·m
    sa_min_mm: float
    eps_alpha: float

    @property
    def eps_ok(self) -> bool:
        return self.eps_alpha >= EPS_MIN - _TOL

    @property
    def eps_hard_ok(self) -> bool:
        return self.eps_alpha >= EPS_HARD - _TOL

    @property
    def ok(self) -> bool:
        return all(c.ok for c in self.checks)


def check_pair(g: PairGeometry) -> PairChecks:
    """The blocking-contour checks of a pair.

    Seed 000's first pair 30/48, x = −0.4/0.4, m = 5: every line holds.

    >>> from .shifted import pair_geometry
    >>> c = check_pair(pair_geometry(30, 48, 5, -0.4, 0.4))
    >>> c.ok, c.undercut, c.interference, c.pointed, round(c.eps_alpha, 3)
    (True, (False, False), (False, False), (False, False), 1.704)

    A 10-tooth zero pinion is undercut and its mate's tip digs into its fillet:

    >>> c = check_pair(pair_geometry(10, 40, 5, 0.0, 0.0))
    >>> c.undercut, c.interference
    ((True, False), (True, False))
    """
    checks: list[Check] = []
    m = g.m_mm
    sa_min = SA_MIN_FACTOR * m
    undercut, interference, pointed = [], [], []
    for j in range(2):
        x, xmin = g.x[j], g.x_min[j]
        ok = x >= xmin - _TOL
        undercut.append(not ok)
        checks.append(Check("undercut", j + 1, x, xmin, ok))
    for j in range(2):
        ok = g.sa_mm[j] >= sa_min - _TOL
        pointed.append(not ok)
        checks.append(Check("tip_thickness", j + 1, g.sa_mm[j], sa_min, ok))
    checks.append(Check("eps_alpha", None, g.eps_alpha, EPS_MIN, g.eps_alpha >= EPS_MIN - _TOL,
                        hard=g.eps_alpha < EPS_HARD - _TOL))
    for j in range(2):
        limit = max(g.rho_l_mm[j], 0.0)
        ok = g.rho_contact_mm[j] >= limit - 1e-9 * max(1.0, m)
        interference.append(not ok)
        checks.append(Check("interference", j + 1, g.rho_contact_mm[j], limit, ok))
    return PairChecks(tuple(checks), tuple(undercut), tuple(interference), tuple(pointed), sa_min, g.eps_alpha)


def check_neighbours(a_w_mm: float, planets: int, da_planet_mm: float) -> Check:
    """Neighbouring of k planets with the real tip circles: d_a < 2a_w·sin(π/k) (the planets'
    tip circles must not touch).

    >>> c = check_neighbours(195.0, 3, 257.0)
    >>> round(c.limit, 3), c.ok
    (337.75, True)
    """
    limit = 2 * a_w_mm * math.sin(math.pi / planets) if planets >= 2 else math.inf
    return Check("neighbours", None, da_planet_mm, limit, da_planet_mm < limit - _TOL)


def pair_notes(tag: str, pc: PairChecks, teeth: tuple[int, int], m: float) -> list[Note]:
    """Warnings (:class:`~tmm_cli.notes.Note`) for the failed lines of a pair; ``tag`` names it ("1-2")."""
    notes = []
    for c in pc.checks:
        if c.ok:
            continue
        z = teeth[c.gear - 1] if c.gear else None
        if c.code == "eps_alpha":
            notes.append(Note.make("shift_eps_hard" if c.hard else "shift_eps_low", pair=tag, eps=f"{c.value:.3f}"))
        elif c.code == "undercut":
            notes.append(Note.make("shift_undercut", pair=tag, z=z, x=f"{c.value:.3f}", xmin=f"{c.limit:.3f}"))
        elif c.code == "tip_thickness":
            notes.append(Note.make("shift_tip_thin", pair=tag, z=z, sa=f"{c.value:.3f}", limit=f"{c.limit:.3f}",
                                   sam=f"{c.value / m:.3f}"))
        elif c.code == "interference":
            notes.append(Note.make("shift_interference", pair=tag, z=z, rho=f"{c.value:.3f}", limit=f"{c.limit:.3f}"))
    return notes
