"""The indicator diagrams of sheet 2: for every gas load (a ``[[load]]`` with ``head``) the gauge
pressure p against the piston's travel s — the table of the file, one polyline a row (a stroke) —
with the scales it is drawn at and the piston's place in each position of sheet 1.

The course draws the indicator diagram of each cylinder beside the mechanism (Artobolevsky, «Теория
механизмов и машин», §«Индикаторная диаграмма»; Frolov, «Силовой анализ механизмов»): p against s at
μ_p, μ_s, and reads the piston force F = p·A from it at μ_F = μ_p·A [N/mm] (the same ordinate). The
numbers here are what sheet 2 draws; the sheet computes nothing.

Strokes (the rows) in the cycle's order from the dead centre nearest the head: 2 rows — the stroke
away from the head, then back to it (a compressor, a pump and a two-stroke engine alike: the file
does not say which machine it is); 4 rows — a four-stroke engine: expansion, exhaust, intake,
compression (issue 34).
"""

from __future__ import annotations

import numpy as np

from ..records import record
from .gas import GasLoad, piston, state
from .scales import drafting_scale

INDICATOR_S_MM = 150.0  # the stroke H at most this long on the drawing
INDICATOR_P_MM = 40.0  # the largest |p| at most this high
STROKES = {2: ("away", "back"), 4: ("expansion", "exhaust", "intake", "compression")}


@record(eq=False)
class Indicator:
    """One piston's indicator diagram as sheet 2 draws it."""

    link: str  # the piston's link (its joint's name)
    number: int  # its link number
    area: float  # A [m²]
    stroke: float  # H [m]
    travel: tuple[float, ...]  # s/H of the table
    pressure: tuple[tuple[float, ...], ...]  # [MPa], one row a stroke, in the cycle's order
    strokes: tuple[str, ...]  # each row's stroke: 'away'/'back', or expansion … compression
    mu_s: float  # [m/mm]
    mu_p: float  # [MPa/mm]
    marks: tuple[tuple[str, int, float], ...]  # (position label, row, s/H) at sheet 1's positions

    @property
    def mu_F(self) -> float:
        """μ_F = μ_p·A [N/mm]: the piston force F = p·A read on the same ordinate."""
        return self.mu_p * 1.0e6 * self.area

    def row_mm(self, j: int) -> np.ndarray:
        """Row j's polyline [drawing mm from the origin: s/μ_s, p/μ_p], in the order the piston
        moves (away from the head: s growing; towards it: s falling)."""
        s = np.asarray(self.travel) * self.stroke / self.mu_s
        p = np.asarray(self.pressure[j]) / self.mu_p
        pts = np.column_stack([s, p])
        return pts if _away(self.strokes[j]) else pts[::-1]

    def pressure_at(self, j: int, x: float) -> float:
        """p [MPa] of row j at s/H = x (linear between the table's entries, as the force)."""
        return float(np.interp(x, self.travel, self.pressure[j]))


def _away(stroke: str) -> bool:
    """Does the piston move away from the head on this stroke?"""
    return stroke in ("away", "expansion", "intake")


def stroke_names(rows: int) -> tuple[str, ...]:
    """The strokes of a diagram of `rows` rows (see the module's text).

    >>> stroke_names(2), stroke_names(4)[1]
    (('away', 'back'), 'exhaust')
    """
    return STROKES[rows]


def indicators(mech, gas: tuple[GasLoad, ...], positions, kin) -> tuple[Indicator, ...]:
    """The indicator diagrams of the gas loads, the `positions` (with `kin`, the kinematics at them:
    the cycle's, a two-turn cycle's as turned) marked on them at the stroke :func:`.gas.state` says
    acts. One μ_s and one μ_p for all the pistons: their diagrams compare at a glance."""
    if not gas:
        return ()
    pistons = [piston(gl, mech) for gl in gas]
    mu_s = drafting_scale(max(p.stroke for p in pistons), INDICATOR_S_MM)
    mu_p = drafting_scale(max(abs(v) for gl in gas for row in gl.pressure for v in row), INDICATOR_P_MM)
    out = []
    for gl, pst in zip(gas, pistons):
        x, row, _ = state(gl, pst, mech, kin)
        marks = tuple((p.label, int(r), float(xx)) for p, r, xx in zip(positions, row, x))
        out.append(Indicator(gl.link, mech.link(gl.link).number, gl.area, pst.stroke, tuple(gl.travel),
                             tuple(tuple(r) for r in gl.pressure), stroke_names(len(gl.pressure)), mu_s, mu_p, marks))
    return tuple(out)
