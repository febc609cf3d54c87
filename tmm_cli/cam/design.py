"""Sheet 3 in one call: diagrams (§1.2), main dimensions (§1.3), profile (§1.4) and the notes.

>>> from tmm_cli.variants import Variant
>>> r = design_cam(Variant(1, 1, None, 25.0, 800.0, 0.05, 1, 100.0, 20.0, 100.0))
>>> r.closure, r.follower, r.profile.undercut
('force', 'translating', False)
>>> r.sizing.nu_rise_max_deg <= 25.01
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import TmmError
from ..notes import Note
from ..variants import Variant
from .drawing import ProfileDrawing, profile_drawing
from .motion import LAYOUT_B_MM, LAYOUT_Y_S_MAX_MM, Motion, follower_motion
from .profile import ROLLER_RULE, Profile, cam_profile
from .sizing import Sizing, size_cam

BOOK_VERTEX_TOL_DEG = 0.05  # the book's vertex is reported as over the limit beyond this
ROLLER_TIGHT = 0.8  # a roller above this share of ρ_min is flagged as tight


@dataclass(frozen=True, eq=False)
class CamResult:
    """Everything sheet 3 needs, in SI (m, rad, s); mm/deg only in names that say so."""

    variant: Variant
    step_deg: float
    motion: Motion
    sizing: Sizing
    profile: Profile
    notes: tuple[Note, ...]
    drawing: ProfileDrawing  # scale of the profile drawing, Table 1.1, (1.26)–(1.27)

    @property
    def scheme(self) -> int:
        return self.variant.scheme

    @property
    def law(self) -> int:
        return self.variant.law

    @property
    def closure(self) -> str:
        return self.variant.closure

    @property
    def follower(self) -> str:
        return self.variant.follower

    @property
    def warnings(self) -> tuple[Note, ...]:
        return tuple(n for n in self.notes if n.level == "warning")


def _mm(x: float | None) -> float | None:
    return None if x is None else round(x * 1000.0, 2)


def _notes(v: Variant, m: Motion, z: Sizing, p: Profile) -> list[Note]:
    notes: list[Note] = [Note.make(f"cam_scheme_{v.scheme}", "assumption")]
    if v.is_rocker:
        notes.append(
            Note.make(
                f"cam_swing_{z.swing}",
                "assumption",
                r0_mm=_mm(z.r0_m),
                other_mm=_mm(z.r0_other_swing_m),
            )
        )
    notes.append(
        Note.make(
            "cam_true_minimum",
            "assumption",
            r0_mm=_mm(z.r0_m),
            book_r0_mm=_mm(z.book_r0_m),
            diff_pct=round((z.book_r0_m / z.r0_m - 1.0) * 100.0, 2),
        )
    )
    book_nu = z.book_nu_rise_max_deg if z.closure == "force" else max(z.book_nu_rise_max_deg, z.book_nu_return_max_deg)
    if book_nu > v.nu_max_deg + BOOK_VERTEX_TOL_DEG:
        notes.append(
            Note.make(
                "cam_book_vertex_over",
                nu_deg=round(book_nu, 2),
                nu_max_deg=v.nu_max_deg,
                book_r0_mm=_mm(z.book_r0_m),
                r0_mm=_mm(z.r0_m),
            )
        )
    worst = z.nu_rise_max_deg if z.closure == "force" else max(z.nu_rise_max_deg, z.nu_return_max_deg)
    if worst > v.nu_max_deg + 0.01:  # guard; the sizing re-solves until this cannot happen
        notes.append(Note.make("cam_pressure_over", nu_deg=round(worst, 3), nu_max_deg=v.nu_max_deg))
    if z.closure == "force":
        notes.append(Note.make("cam_force_return", "assumption", nu_return_deg=round(z.nu_return_max_deg, 1)))
    notes.append(
        Note.make(
            "cam_roller_rule",
            "assumption",
            roller_mm=_mm(p.roller_m),
            ratio=ROLLER_RULE,
            working_min_mm=_mm(p.working_min_radius_m),
        )
    )
    where = "convex"
    rho, phi_at = p.rho_min_convex_m, p.phi_rho_min_convex_deg
    if z.closure == "form" and p.rho_min_concave_m is not None and p.rho_min_concave_m < rho:
        where, rho, phi_at = "concave", p.rho_min_concave_m, p.phi_rho_min_concave_deg
    if p.undercut:
        if p.r0_for_rule_m is not None:
            fix = _mm(p.fix_l_oc_m if v.is_rocker else p.fix_e_m)
            notes.append(
                Note.make(
                    f"cam_undercut_{where}_fix_{'rocker' if v.is_rocker else 'offset'}",
                    roller_mm=_mm(p.roller_m),
                    rho_mm=_mm(rho),
                    phi_deg=round(phi_at, 1),
                    r0_fix_mm=_mm(p.r0_for_rule_m),
                    fix_mm=fix,
                )
            )
        else:
            notes.append(
                Note.make(f"cam_undercut_{where}", roller_mm=_mm(p.roller_m), rho_mm=_mm(rho), phi_deg=round(phi_at, 1))
            )
    elif p.roller_m > ROLLER_TIGHT * p.roller_max_m:
        notes.append(Note.make("cam_roller_tight", roller_mm=_mm(p.roller_m), rho_mm=_mm(p.roller_max_m)))
    if v.is_rocker:
        # the cam body (force closure: the working profile D1; groove: its outer wall D2) must
        # clear the rocker pivot C, or the rocker has to be mounted beside the cam plane
        body = p.r_far_m + (p.roller_m if z.closure == "form" else -p.roller_m)
        if z.l_oc_m <= body:
            notes.append(Note.make(f"cam_pivot_inside_{z.closure}", l_oc_mm=_mm(z.l_oc_m), body_mm=_mm(body)))
    s = m.scales
    notes.append(
        Note.make(
            "cam_layout",
            "assumption",
            b_mm=LAYOUT_B_MM,
            y_mm=LAYOUT_Y_S_MAX_MM,
            h_v_mm=s.h_v_mm,
            h_a_mm=s.h_a_mm,
        )
    )
    return notes


def design_cam(variant: Variant, step_deg: float = 10.0) -> CamResult:
    """Design the cam mechanism of one Table 1.2 row (sheet 3, book section 1).

    `step_deg` is the step of the book's motion table (§1.2: 10°, halved on short phases).
    Raises TmmError for a step outside (0, 30] degrees.
    """
    try:
        step = float(step_deg)
    except (TypeError, ValueError):
        raise TmmError(f"table step '{step_deg}' is not a number; give degrees, e.g. 10") from None
    if not (math.isfinite(step) and 0.0 < step <= 30.0):
        raise TmmError(f"table step {step_deg}° is out of range; give a step above 0 and at most 30 degrees (the book uses 10)")
    motion = follower_motion(variant, step)
    sizing = size_cam(
        motion.program,
        rocker=variant.is_rocker,
        l_bc_m=variant.l_bc_m,
        nu_max_deg=variant.nu_max_deg,
        closure=variant.closure,
        ccw=variant.ccw,
    )
    profile = cam_profile(motion.program, sizing, rocker=variant.is_rocker, l_bc_m=variant.l_bc_m)
    drawing = profile_drawing(motion, sizing, profile)
    notes = _notes(variant, motion, sizing, profile)
    notes.append(
        Note.make(
            "cam_drawing_scale" if drawing.fits else "cam_drawing_too_big",
            "assumption" if drawing.fits else "warning",
            scale=drawing.scale,
            k_sk=drawing.k_sk,
            field_mm=drawing.field_mm,
            width_mm=round(drawing.extent_mm[0], 1),
            height_mm=round(drawing.extent_mm[1], 1),
        )
    )
    for phase, st in (("rise", motion.table_step_rise_deg), ("return", motion.table_step_return_deg)):
        if st < step:
            notes.append(Note.make(f"cam_step_halved_{phase}", "assumption", step_deg=st))
    return CamResult(variant=variant, step_deg=step, motion=motion, sizing=sizing, profile=profile, notes=tuple(notes), drawing=drawing)
