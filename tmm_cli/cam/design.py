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

import numpy as np

from ..errors import TmmError
from ..notes import Note
from ..records import record
from ..variants import Variant
from .drawing import ProfileDrawing, profile_drawing
from .motion import LAYOUT_B_MM, LAYOUT_Y_S_MAX_MM, Motion, follower_motion
from .profile import ROLLER_LIMIT, ROLLER_RULE, Profile, cam_profile
from .sizing import (
    Sizing,
    centre_from_r0_l_oc,
    centre_on_offset_line,
    centre_on_pivot_circle,
    far_point_canonical,
    nearest_centre_where,
    place_centre,
    size_cam,
)

BOOK_VERTEX_TOL_DEG = 0.05  # the book's vertex is reported as over the limit beyond this
ROLLER_TIGHT = 0.8  # a roller above this share of ρ_min is flagged as tight
NU_TOL_DEG = 0.01  # a pressure angle above ν_max by more than this fails the check
SMALL_CAM_SHARE = 0.25  # r0 < l_BC/4: a cam much smaller than its rocker (sanity remark)
SMALL_ROLLER_MM = 3.0  # a roller under 3 mm is hard to make (sanity remark)
LONG_STROKE_M = 0.2  # Table 1.2's strokes are 20…130 mm; 0.25 m (variant 65) is odd
R0_MAX_MM = 5000.0  # a student's r0 above 5 m is a typo


@record
class CamChoice:
    """The student's say over the design, in millimetres (None: the program decides).

    r0_mm — base radius of the pitch curve; offset_mm — e of a translating follower (sign as in
    the output: e > 0 axis to the right of O); l_oc_mm — distance cam centre to rocker pivot;
    swing — "same" | "opposite" (the rocker's turn on the rise relative to the cam); roller_mm.
    """

    r0_mm: float | None = None
    offset_mm: float | None = None
    l_oc_mm: float | None = None
    swing: str | None = None
    roller_mm: float | None = None

    @property
    def given(self) -> bool:
        return any(x is not None for x in (self.r0_mm, self.offset_mm, self.l_oc_mm, self.swing, self.roller_mm))

    @property
    def options(self) -> str:
        """The choice as the command-line options that give it, e.g. '--r0 60 --offset -10'."""
        out = []
        for name, val in (("r0", self.r0_mm), ("offset", self.offset_mm), ("l-oc", self.l_oc_mm), ("roller", self.roller_mm)):
            if val is not None:
                out.append(f"--{name} {val:g}")
        if self.swing is not None:
            out.append(f"--swing {self.swing}")
        return " ".join(out)


@record
class CamChecks:
    """The conditions a carried (or the student's) cam must meet, as computed for the output.

    nu_*: largest pressure angle on the phase [deg] and whether it is limited (force closure
    does not limit the return); undercut: roller ≥ ρ_lim; pivot: l_OC ≤ the radius the cam body
    sweeps (force closure: the working profile's largest radius r_far − r_р; groove: its outer
    wall r_far + r_р); None for a translating follower.
    """

    nu_max_deg: float
    nu_rise_deg: float
    nu_return_deg: float
    return_limited: bool
    roller_m: float
    rho_limit_m: float
    l_oc_m: float | None
    body_m: float | None

    @property
    def nu_rise_ok(self) -> bool:
        return self.nu_rise_deg <= self.nu_max_deg + NU_TOL_DEG

    @property
    def nu_return_ok(self) -> bool:
        return (not self.return_limited) or self.nu_return_deg <= self.nu_max_deg + NU_TOL_DEG

    @property
    def undercut_ok(self) -> bool:
        return self.roller_m < self.rho_limit_m

    @property
    def pivot_ok(self) -> bool | None:
        return None if self.l_oc_m is None else self.l_oc_m > self.body_m

    @property
    def ok(self) -> bool:
        return self.nu_rise_ok and self.nu_return_ok and self.undercut_ok and self.pivot_ok is not False


@record
class BookRollerFix:
    """Where the book's 0.2·r0 roller would undercut: the smallest cam of the same zone that keeps
    it (certified, :mod:`tmm_cli.cam.book_roller`), as the options that carry it [m]."""

    r0_m: float
    e_m: float | None
    l_oc_m: float | None
    centre: tuple[float, float]  # zone frame
    certified: bool
    rel_tol: float
    cells: int


@record
class PivotConflict:
    """The program's first cam, not carried: its body reaches the rocker pivot C (l_OC ≤ the radius
    the body sweeps), so the other swing or a centre farther out was carried (``CamResult.pivot_move``)
    [m]."""

    swing: str  # "same" | "opposite"
    r0_m: float
    l_oc_m: float
    body_m: float


@record(eq=False)
class CamResult:
    """Everything sheet 3 needs, in SI (m, rad, s); mm/deg only in names that say so."""

    variant: Variant
    step_deg: float
    motion: Motion
    sizing: Sizing
    profile: Profile
    notes: tuple[Note, ...]
    drawing: ProfileDrawing  # scale of the profile drawing, Table 1.1, (1.26)–(1.27)
    checks: CamChecks | None = None  # the carried design's conditions (pressure angle, undercut, pivot)
    choice: CamChoice | None = None  # the student's overrides (None: the program's own design)
    own: Sizing | None = None  # the program's own sizing, when the student's choice replaced it
    pivot_move: str | None = None  # "swing" | "centre": moved off the rocker pivot (program design)
    book_roller_fix: BookRollerFix | None = None  # the smallest cam keeping the book's 0.2·r0 roller
    pivot_conflict: PivotConflict | None = None  # the smaller cam not carried because it reaches the pivot


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
    def source(self) -> str:
        """'student' when any override was given, else 'program'."""
        return "student" if (self.choice is not None and self.choice.given) else "program"

    @property
    def warnings(self) -> tuple[Note, ...]:
        return tuple(n for n in self.notes if n.level == "warning")


def _mm(x: float | None) -> float | None:
    return None if x is None else round(x * 1000.0, 2)


def _num(name: str, x) -> float | None:
    if x is None:
        return None
    try:
        v = float(x)
    except (TypeError, ValueError):
        raise TmmError(f"--{name} '{x}' is not a number; give millimetres, e.g. --{name} 40") from None
    if not math.isfinite(v):
        raise TmmError(f"--{name} {x} is not a finite number; give millimetres, e.g. --{name} 40")
    return v


def check_choice(variant: Variant, choice: CamChoice) -> CamChoice:
    """Out-of-range overrides raise TmmError (one line, exit 2); returns the choice as floats."""
    r0, e, loc, roller = (_num(n, x) for n, x in (("r0", choice.r0_mm), ("offset", choice.offset_mm),
                                                   ("l-oc", choice.l_oc_mm), ("roller", choice.roller_mm)))
    kind = "rocker" if variant.is_rocker else "translating follower"
    if variant.is_rocker and e is not None:
        raise TmmError(f"--offset is for a translating follower; variant {variant.number} has a rocker: give --l-oc (and --swing) instead")
    if not variant.is_rocker and (loc is not None or choice.swing is not None):
        opt = "--l-oc" if loc is not None else "--swing"
        raise TmmError(f"{opt} is for a rocker; variant {variant.number} has a {kind}: give --offset instead")
    if choice.swing is not None and choice.swing not in ("same", "opposite"):
        raise TmmError(f"--swing '{choice.swing}' is unknown; use 'same' or 'opposite'")
    if r0 is not None and not 0.0 < r0 <= R0_MAX_MM:
        raise TmmError(f"--r0 {r0:g} mm is out of range; give a base radius above 0 and at most {R0_MAX_MM:g} mm")
    if roller is not None and roller <= 0.0:
        raise TmmError(f"--roller {roller:g} mm is out of range; give a roller radius above 0 mm")
    if r0 is not None and roller is not None and roller >= r0:
        raise TmmError(f"--roller {roller:g} mm is not smaller than r0 = {r0:g} mm: the working profile would have no base circle; "
                       "take a roller below r0 (the book: 0.2·r0)")
    if r0 is not None and e is not None and abs(e) >= r0:
        raise TmmError(f"|--offset {e:g}| mm is not smaller than --r0 {r0:g} mm: the follower axis would miss the base circle; "
                       "take |e| < r0")
    if loc is not None and loc <= 0.0:
        raise TmmError(f"--l-oc {loc:g} mm is out of range; give the distance from the cam centre to the rocker pivot, above 0 mm")
    return CamChoice(r0, e, loc, choice.swing, roller)


def _sigma(swing: str | None) -> int | None:
    return None if swing is None else (1 if swing == "same" else -1)


def _student_sizing(v: Variant, program, z: Sizing, c: CamChoice) -> Sizing:
    """The program's sizing moved to the student's centre (see :class:`CamChoice` for the rules
    when only one of r0, e / l_OC is given)."""
    r0 = None if c.r0_mm is None else c.r0_mm / 1000.0
    if v.is_rocker:
        loc = None if c.l_oc_mm is None else c.l_oc_mm / 1000.0
        if r0 is not None and loc is not None:
            o = centre_from_r0_l_oc(z, r0, loc)
        elif loc is not None:
            o = centre_on_pivot_circle(z, loc)
            if o is None:
                raise TmmError(f"no cam centre at l_OC = {c.l_oc_mm:g} mm keeps the pressure angle within ν_max = {v.nu_max_deg:g}°; "
                               "give --r0 as well (the program then checks your choice) or another --l-oc")
        elif r0 is not None:
            o = np.asarray(z.centre_canonical) * (r0 / z.r0_m)
        else:
            return z
    else:
        e = None if c.offset_mm is None else c.offset_mm / 1000.0
        if r0 is not None and e is not None:
            x = -e if v.ccw else e
            o = np.array([x, -math.sqrt(r0 * r0 - e * e)])
        elif e is not None:
            o = centre_on_offset_line(z, e)
            if o is None:
                raise TmmError(f"no cam centre with e = {c.offset_mm:g} mm keeps the pressure angle within ν_max = {v.nu_max_deg:g}°; "
                               "give --r0 as well (the program then checks your choice) or a smaller |--offset|")
            if math.hypot(*o) <= abs(e):
                raise TmmError(f"with e = {c.offset_mm:g} mm the zone's nearest centre lies on the follower axis; give --r0 as well")
        elif r0 is not None:
            o = np.asarray(z.centre_canonical) * (r0 / z.r0_m)
        else:
            return z
    return place_centre(z, program, o, l_bc_m=v.l_bc_m, origin="student")


def _checks(v: Variant, z: Sizing, p: Profile) -> CamChecks:
    body = None
    if v.is_rocker:
        body = p.r_far_m + (p.roller_m if z.closure == "form" else -p.roller_m)
    return CamChecks(
        nu_max_deg=v.nu_max_deg,
        nu_rise_deg=z.nu_rise_max_deg,
        nu_return_deg=z.nu_return_max_deg,
        return_limited=z.closure == "form",
        roller_m=p.roller_m,
        rho_limit_m=p.roller_max_m,
        l_oc_m=z.l_oc_m,
        body_m=body,
    )


def _pivot_clear_fn(v: Variant, program, z: Sizing):
    """ok(points) for centres (canonical frame) that keep the pivot out of the cam's sweep with
    any roller the rule can carry: |OC| > |O B_far| (force closure: the working profile lies
    inside the pitch curve) or |OC| > |O B_far| + 0.2·r0 (groove: its outer wall)."""
    mirror = np.array([1.0, 1.0]) if z.ccw else np.array([-1.0, 1.0])
    c = np.asarray(z.pivot) * mirror
    bf = far_point_canonical(program, rocker=True, l_bc_m=v.l_bc_m, sigma=z.sigma)
    k = ROLLER_RULE if z.closure == "form" else 0.0

    def ok(pts):
        pts = np.atleast_2d(pts)
        r = np.hypot(pts[:, 0], pts[:, 1])
        return np.hypot(*(pts - c).T) > np.hypot(*(pts - bf).T) + k * r + 1e-9 * r

    return ok


def _carry_clear_of_pivot(v: Variant, program, z: Sizing, p: Profile):
    """Program design only: when the rocker's pivot lies inside the circle the cam sweeps, carry
    the other swing direction if its smallest cam clears the pivot, else the zone's centre nearest
    to B0 (either swing) that clears it. Returns (sizing, profile, move, before) or None."""
    ch = _checks(v, z, p)
    if ch.pivot_ok is not False:
        return None
    other = size_cam(program, rocker=True, l_bc_m=v.l_bc_m, nu_max_deg=v.nu_max_deg, closure=v.closure, ccw=v.ccw,
                     sigma=-z.sigma)
    from dataclasses import replace

    other = replace(other, r0_other_swing_m=z.r0_m)
    po = cam_profile(program, other, rocker=True, l_bc_m=v.l_bc_m)
    if _checks(v, other, po).pivot_ok:
        return other, po, "swing", ch
    best = None
    for zz in (z, other):
        o = nearest_centre_where(zz, _pivot_clear_fn(v, program, zz))
        if o is not None and (best is None or math.hypot(*o) < best[0]):
            best = (math.hypot(*o), zz, o)
    if best is None:
        return None
    moved = place_centre(best[1], program, best[2] * 1.0005, l_bc_m=v.l_bc_m, origin="pivot")
    pm = cam_profile(program, moved, rocker=True, l_bc_m=v.l_bc_m)
    if not _checks(v, moved, pm).ok:
        return None
    return moved, pm, "centre", ch


def _notes(v: Variant, m: Motion, z: Sizing, p: Profile, ch: CamChecks, *, choice: CamChoice | None,
           own: Sizing | None, own_roller_m: float | None, move: tuple[str, CamChecks, Sizing] | None) -> list[Note]:
    notes: list[Note] = [Note.make(f"cam_scheme_{v.scheme}", "assumption")]
    student = choice is not None and choice.given
    if v.is_rocker and z.r0_other_swing_m is not None:
        notes.append(Note.make(f"cam_swing_{z.swing}", "assumption", r0_mm=_mm(z.r0_m), other_mm=_mm(z.r0_other_swing_m)))
    elif v.is_rocker:
        notes.append(Note.make(f"cam_swing_{z.swing}_given", "assumption", r0_mm=_mm(z.r0_min_m or z.r0_m)))
    if move is not None:
        kind, before, zb = move
        notes.append(
            Note.make(
                f"cam_pivot_moved_{kind}",
                "assumption",
                swing_before=zb.swing,
                r0_before_mm=_mm(zb.r0_m),
                l_oc_before_mm=_mm(before.l_oc_m),
                body_before_mm=_mm(before.body_m),
                r0_mm=_mm(z.r0_m),
                l_oc_mm=_mm(z.l_oc_m),
                body_mm=_mm(ch.body_m),
            )
        )
    if z.origin != "student":
        notes.append(
            Note.make(
                "cam_true_minimum",
                "assumption",
                r0_mm=_mm(z.r0_min_m or z.r0_m),
                book_r0_mm=_mm(z.book_r0_m),
                diff_pct=round((z.book_r0_m / (z.r0_min_m or z.r0_m) - 1.0) * 100.0, 2),
            )
        )
    else:
        geo = "rocker" if v.is_rocker else "offset"
        notes.append(
            Note.make(
                f"cam_student_{geo}",
                "assumption",
                options=choice.options,
                r0_mm=_mm(z.r0_m),
                geo_mm=_mm(z.l_oc_m if v.is_rocker else z.e_m),
                own_r0_mm=_mm(own.r0_m),
                own_geo_mm=_mm(own.l_oc_m if v.is_rocker else own.e_m),
                book_r0_mm=_mm(z.book_r0_m),
            )
        )
    book_nu = z.book_nu_rise_max_deg if z.closure == "force" else max(z.book_nu_rise_max_deg, z.book_nu_return_max_deg)
    if book_nu > v.nu_max_deg + BOOK_VERTEX_TOL_DEG and z.origin != "student":
        notes.append(
            Note.make(
                "cam_book_vertex_over",
                nu_deg=round(book_nu, 2),
                nu_max_deg=v.nu_max_deg,
                book_r0_mm=_mm(z.book_r0_m),
                r0_mm=_mm(z.r0_min_m or z.r0_m),
            )
        )
    # the pressure angle on every constrained phase
    for phase, nu, ok in (("rise", ch.nu_rise_deg, ch.nu_rise_ok), ("return", ch.nu_return_deg, ch.nu_return_ok)):
        if not ok:
            notes.append(Note.make(f"cam_fail_nu_{phase}", nu_deg=round(nu, 2), nu_max_deg=v.nu_max_deg,
                                   r0_min_mm=_mm((own or z).r0_m)))
    if z.closure == "force":
        notes.append(Note.make("cam_force_return", "assumption", nu_return_deg=round(z.nu_return_max_deg, 1)))
    # the roller
    where = "convex"
    rho, phi_at = p.rho_min_convex_m, p.phi_rho_min_convex_deg
    if z.closure == "form" and p.rho_min_concave_m is not None and p.rho_min_concave_m < rho:
        where, rho, phi_at = "concave", p.rho_min_concave_m, p.phi_rho_min_concave_deg
    if p.roller_rule == "book":
        notes.append(Note.make("cam_roller_rule", "assumption", roller_mm=_mm(p.roller_m), ratio=ROLLER_RULE,
                               working_min_mm=_mm(p.working_min_radius_m)))
    elif p.roller_rule == "limited":
        notes.append(
            Note.make(
                f"cam_roller_limited_{'undercut' if p.roller_book_m >= rho else 'tight'}",
                "assumption",
                roller_mm=_mm(p.roller_m),
                book_mm=_mm(p.roller_book_m),
                rho_mm=_mm(rho),
                phi_deg=round(phi_at, 1),
                share=ROLLER_LIMIT,
                working_min_mm=_mm(p.working_min_radius_m),
            )
        )
    else:
        notes.append(Note.make("cam_roller_student", "assumption", roller_mm=_mm(p.roller_m), book_mm=_mm(p.roller_book_m),
                               limit_mm=_mm(ROLLER_LIMIT * rho), working_min_mm=_mm(p.working_min_radius_m),
                               own_mm=_mm(own_roller_m)))
    if not ch.undercut_ok:
        notes.append(Note.make(f"cam_fail_undercut_{where}", roller_mm=_mm(p.roller_m), rho_mm=_mm(rho),
                               phi_deg=round(phi_at, 1), limit_mm=_mm(ROLLER_LIMIT * rho)))
    elif p.roller_m > ROLLER_TIGHT * p.roller_max_m * (1.0 + 1e-9):
        notes.append(Note.make("cam_roller_tight", roller_mm=_mm(p.roller_m), rho_mm=_mm(p.roller_max_m)))
    if ch.pivot_ok is False:
        # the cam body (force closure: the working profile D1; groove: its outer wall D2) must
        # clear the rocker pivot C, or the rocker has to be mounted beside the cam plane
        code = f"cam_fail_pivot_{z.closure}" if student else f"cam_pivot_inside_{z.closure}"
        notes.append(Note.make(code, l_oc_mm=_mm(ch.l_oc_m), body_mm=_mm(ch.body_m)))
    # sanity remarks: legal but odd numbers
    if v.is_rocker and z.r0_m < SMALL_CAM_SHARE * v.l_bc_m:
        notes.append(Note.make("cam_small_vs_rocker", r0_mm=_mm(z.r0_m), l_bc_mm=_mm(v.l_bc_m),
                               ratio=round(v.l_bc_m / z.r0_m, 1)))
    if p.roller_m * 1000.0 < SMALL_ROLLER_MM:
        notes.append(Note.make("cam_roller_small", roller_mm=_mm(p.roller_m), min_mm=SMALL_ROLLER_MM))
    if not v.is_rocker and v.stroke >= LONG_STROKE_M:
        notes.append(Note.make("cam_stroke_long", s_mm=_mm(v.stroke), r0_mm=_mm(z.r0_m)))
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


def design_cam(variant: Variant, step_deg: float = 10.0, choice: CamChoice | None = None) -> CamResult:
    """Design the cam mechanism of one Table 1.2 row (sheet 3, book section 1).

    `step_deg` is the step of the book's motion table (§1.2: 10°, halved on short phases).
    `choice`: the student's overrides (:class:`CamChoice`); the program then carries them, checks
    the pressure angle on every constrained phase, the undercut and the pivot, and reports each
    failed condition as a warning (the design is still computed and drawn). When only --r0 is
    given, the centre moves along the ray from B0 through the program's centre; only --offset
    (--l-oc): the zone's centre on that axis (circle) nearest to B0.
    Raises TmmError for a step outside (0, 30] degrees or an out-of-range override.
    """
    try:
        step = float(step_deg)
    except (TypeError, ValueError):
        raise TmmError(f"table step '{step_deg}' is not a number; give degrees, e.g. 10") from None
    if not (math.isfinite(step) and 0.0 < step <= 30.0):
        raise TmmError(f"table step {step_deg}° is out of range; give a step above 0 and at most 30 degrees (the book uses 10)")
    choice = check_choice(variant, choice) if choice is not None and choice.given else None
    motion = follower_motion(variant, step)
    program = motion.program
    rocker = variant.is_rocker
    sizing = size_cam(
        program,
        rocker=rocker,
        l_bc_m=variant.l_bc_m,
        nu_max_deg=variant.nu_max_deg,
        closure=variant.closure,
        ccw=variant.ccw,
        sigma=_sigma(choice.swing if choice else None),
    )
    own, own_roller, move, pivot_move, conflict = None, None, None, None, None
    if choice is None:
        profile = cam_profile(program, sizing, rocker=rocker, l_bc_m=variant.l_bc_m)
        if rocker:
            moved = _carry_clear_of_pivot(variant, program, sizing, profile)
            if moved is not None:
                before = sizing
                sizing, profile, pivot_move, ch_before = moved
                move = (pivot_move, ch_before, before)
                conflict = PivotConflict(before.swing, before.r0_m, ch_before.l_oc_m, ch_before.body_m)
    else:
        own = sizing
        own_roller = cam_profile(program, sizing, rocker=rocker, l_bc_m=variant.l_bc_m).roller_m
        sizing = _student_sizing(variant, program, sizing, choice)
        if choice.roller_mm is not None and choice.roller_mm / 1000.0 >= sizing.r0_m:
            raise TmmError(f"--roller {choice.roller_mm:g} mm is not smaller than r0 = {sizing.r0_m * 1000:.2f} mm: "
                           "the working profile would have no base circle; take a roller below r0 (the book: 0.2·r0)")
        profile = cam_profile(program, sizing, rocker=rocker, l_bc_m=variant.l_bc_m,
                              roller_m=None if choice.roller_mm is None else choice.roller_mm / 1000.0)
    checks = _checks(variant, sizing, profile)
    fix = _book_roller_fix(variant, program, sizing, profile)
    drawing = profile_drawing(motion, sizing, profile)
    notes = _notes(variant, motion, sizing, profile, checks, choice=choice, own=own, own_roller_m=own_roller, move=move)
    if fix is not None:
        geo = "rocker" if rocker else "offset"
        r0_up = _mm_up(fix.r0_m)
        notes.append(Note.make(f"cam_book_roller_fix_{geo}", "assumption", r0_mm=r0_up,
                               roller_mm=math.floor(ROLLER_RULE * r0_up * 100.0 + 1e-9) / 100.0,
                               geo_mm=_mm(fix.l_oc_m if rocker else fix.e_m), swing=sizing.swing or "",
                               tol_pct=round(fix.rel_tol * 100, 2), book_mm=_mm(profile.roller_book_m),
                               proven="" if fix.certified else "?"))
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
    return CamResult(variant=variant, step_deg=step, motion=motion, sizing=sizing, profile=profile, notes=tuple(notes),
                     drawing=drawing, checks=checks, choice=choice, own=own, pivot_move=pivot_move,
                     book_roller_fix=fix, pivot_conflict=conflict)


def _mm_up(x: float) -> float:
    """Millimetres rounded up to 0.01 mm (a suggested r0 must not fall below the proven bound)."""
    return math.ceil(x * 1000.0 * 100.0 - 1e-9) / 100.0


def _book_roller_fix(v: Variant, program, z: Sizing, p: Profile) -> BookRollerFix | None:
    """When the book's 0.2·r0 roller would undercut the carried cam: the smallest cam of the same
    pressure-angle zone (same swing) that keeps it, moved out by the search's 0.1 % so the options
    shown reproduce a working cam."""
    if p.roller_book_m < p.roller_max_m:
        return None
    from .book_roller import smallest_r0_for_roller

    f = smallest_r0_for_roller(program, z, rocker=v.is_rocker, l_bc_m=v.l_bc_m, ratio=ROLLER_RULE)
    if f is None:
        return None
    o = np.asarray(f.centre_canonical) * (1.0 + f.rel_tol)
    moved = place_centre(z, program, o, l_bc_m=v.l_bc_m, origin="student")
    return BookRollerFix(r0_m=moved.r0_m, e_m=moved.e_m, l_oc_m=moved.l_oc_m, centre=moved.centre,
                         certified=f.certified, rel_tol=f.rel_tol, cells=f.cells)
