"""The checks of a design: its ratio by (2.1) and, apart from it, read off the velocity pictures
(2.3), with the conditions of §2.1.3 for every stage.
"""

from __future__ import annotations

import math
from fractions import Fraction

from ...records import record
from .conditions import PlanetaryDesign, Stage, StageChecks, check_stage

# ----------------------------------------------------------------------------------------------
# the checks: (2.1) and the velocity pictures (2.3)


@record
class VelocityStage:
    """Linear-velocity picture of one stage in module units (radius r = z/2 per module).

    Points: A — sun/planet mesh at r_A = r_k; C — planet centre at r_C = r_k + r_c; B — the
    planet c′ / ring mesh at r_B = r_n (zero velocity). Velocities are drawn lengths (scale μ):
    v_A = ω_k·r_A·μ; the planet's line runs from (r_B, 0) through (r_A, v_A); v_C on it at r_C.
    φ_k, φ_H — angles of the sun's and carrier's lines to the vertical (radius) axis.
    """

    r_sun: float
    r_planet: float
    r_planet2: float
    r_ring: float
    r_a: float
    r_c: float
    r_b: float
    v_a: float
    v_c: float
    phi_k_deg: float
    phi_h_deg: float
    ratio: float  # tg φ_k / tg φ_H


@record
class VelocityPicture:
    """The linear-velocity picture of all stages and the angular-velocity picture (pole at
    distance ``pole_mm`` from the line on which the rays of each link cut segments ok, oh)."""

    stages: tuple[VelocityStage, ...]
    pole: float
    ok: float  # segment of the driving sun k
    oh: float  # segment of the output carrier H
    ratio: float  # ok/oh


def velocity_picture(stages: tuple[Stage, ...], v_a_first: float | None = None, pole: float | None = None) -> VelocityPicture:
    """Build the velocity pictures from the geometry and read the ratio off them, (2.3):
    i = tg φ_k / tg φ_H = ok/oh. Nothing here uses (2.1).

    Drawing choices (the ratio does not depend on them): V_A of the first stage is drawn
    max(r_A·tg 60°, r_max/2) long; the pole of the angular picture is 0.8·r_max from its line, or
    closer so that the picture (from c to k) is at most 1.5·r_max wide.

    >>> v = velocity_picture((Stage(40, 25, None, 90, 5),))
    >>> round(v.ratio, 12), round(v.stages[0].ratio, 12)
    (3.25, 3.25)
    """
    out = []
    r_max = max(max(s.z_ring, s.z_sun + 2 * s.z_planet) / 2 for s in stages)
    r_a0 = stages[0].z_sun / 2
    if v_a_first is None:
        v_a_first = max(r_a0 * math.tan(math.radians(60)), r_max / 2)
    omega = v_a_first / r_a0  # drawn length per unit radius: the sun's line through O
    for s in stages:
        rk, rc, rc2, rn = s.z_sun / 2, s.z_planet / 2, s.zc2 / 2, s.z_ring / 2
        r_a, r_c, r_b = rk, rk + rc, rn
        v_a = omega * r_a
        # planet block's line: zero at r_b, v_a at r_a (a straight line through both points)
        v_c = v_a * (r_b - r_c) / (r_b - r_a)
        phi_k = math.atan2(v_a, r_a)
        phi_h = math.atan2(v_c, r_c)
        out.append(VelocityStage(rk, rc, rc2, rn, r_a, r_c, r_b, v_a, v_c, math.degrees(phi_k), math.degrees(phi_h),
                                 math.tan(phi_k) / math.tan(phi_h)))
        omega = v_c / r_c  # the next stage's sun turns with this carrier
    if pole is None:
        width = math.tan(math.radians(out[0].phi_k_deg)) + max(s.v_a / (s.r_b - s.r_a) for s in out)
        pole = min(0.8 * r_max, 1.5 * r_max / width)
    ok = pole * math.tan(math.radians(out[0].phi_k_deg))
    oh = pole * math.tan(math.radians(out[-1].phi_h_deg))
    return VelocityPicture(tuple(out), pole, ok, oh, ok / oh)


@record
class DesignChecks:
    """The five conditions for the carried design, and the two ratio checks."""

    ratio: float
    ratio_fraction: Fraction
    target: float
    ratio_error_pct: float
    tolerance_pct: float
    ratio_ok: bool
    stages: tuple[StageChecks, ...]
    ratio_formula_21: tuple[float, ...]  # per stage, by (2.1): 1 − (−1)^a·z_c·z_n/(z_k·z_c′)
    ratio_formula_21_total: float
    velocity: VelocityPicture

    @property
    def ok(self) -> bool:
        return self.ratio_ok and all(s.ok for s in self.stages)


def ratio_21(stage: Stage, a: int = 1) -> float:
    """(2.1): i_kH^n = 1 − (−1)^a·(z_c·z_n)/(z_k·z_c′), a = number of external meshes (1 here).

    >>> ratio_21(Stage(40, 25, None, 90, 5))
    3.25
    """
    return 1 - (-1) ** a * (stage.z_planet * stage.z_ring) / (stage.z_sun * stage.zc2)


def check_design(design: PlanetaryDesign, tol_pct: float) -> DesignChecks:
    """All conditions of §2.1.3 and both ratio checks for a design."""
    per = tuple(ratio_21(s) for s in design.stages)
    tot = math.prod(per)
    err = design.ratio_error_pct
    return DesignChecks(
        ratio=design.ratio, ratio_fraction=design.ratio_fraction, target=design.target, ratio_error_pct=err,
        tolerance_pct=tol_pct, ratio_ok=abs(err) <= tol_pct * (1 + 1e-9) + 1e-9,
        stages=tuple(check_stage(s) for s in design.stages), ratio_formula_21=per, ratio_formula_21_total=tot,
        velocity=velocity_picture(design.stages),
    )
