"""Drawing scales chosen as a drafter chooses them: a round number, the drawing fits its room.

A scale μ is "so many units per millimetre of the drawing" ((m/s)/mm for a velocity plan,
m/mm for the scheme). The drafter takes the smallest value of the series 1, 2, 2.5, 4, 5 × 10ᵏ
(the ratios of ГОСТ 2.302's drawing scales) with which the largest quantity still fits the room.
"""

from __future__ import annotations

import math

from ..records import record

SERIES = (1.0, 2.0, 2.5, 4.0, 5.0)
PLAN_MM = 100.0  # the longest vector of a plan
SCHEME_MM = 250.0  # the larger side of the scheme in all positions
DIAGRAM_AXIS_MM = 180.0  # the crank-angle axis of the diagrams: one turn
DIAGRAM_HEIGHT_MM = 30.0  # the largest ordinate of a diagram (each side of the axis): three fit a sheet field


def drafting_scale(value: float, room_mm: float) -> float:
    """The smallest round μ of the series with |value|/μ ≤ room_mm [units per mm].

    >>> drafting_scale(0.377, 100.0), drafting_scale(4.0, 100.0), drafting_scale(0.0, 100.0)
    (0.004, 0.04, 1.0)
    """
    need = abs(value) / room_mm
    if not math.isfinite(need) or need <= 0.0:
        return 1.0
    k = math.floor(math.log10(need))
    for decade in (k, k + 1):
        for m in SERIES:
            mu = m * 10.0 ** decade
            if mu >= need * (1 - 1e-12):
                return float(f"{mu:.6g}")
    raise AssertionError("unreachable")  # pragma: no cover


@record
class DiagramScales:
    """The scales of the kinematic diagrams s(φ), v(φ), a(φ) of the output link."""

    phi: float  # μ_φ [rad/mm]: one crank turn on DIAGRAM_AXIS_MM
    s: float  # μ_s [m/mm] (a rocker: [rad/mm])
    v: float  # μ_v [(m/s)/mm] ([(rad/s)/mm])
    a: float  # μ_a [(m/s²)/mm] ([(rad/s²)/mm])
    axis_mm: float
    height_mm: float


def diagram_scales(s_max: float, v_max: float, a_max: float, axis_mm: float = DIAGRAM_AXIS_MM,
                   height_mm: float = DIAGRAM_HEIGHT_MM) -> DiagramScales:
    """Scales of the three diagrams from the largest |s|, |v|, |a| over the turn.

    >>> d = diagram_scales(0.16, 0.86, 6.7)
    >>> round(math.degrees(d.phi), 9), d.s, d.v, d.a
    (2.0, 0.01, 0.04, 0.25)
    """
    return DiagramScales(2.0 * math.pi / axis_mm, drafting_scale(s_max, height_mm), drafting_scale(v_max, height_mm),
                         drafting_scale(a_max, height_mm), axis_mm, height_mm)
