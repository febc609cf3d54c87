"""Sheet 4 end to end: motor, ratios, scheme, planetary synthesis, spur pair, power, notes.

:func:`design_gears` is the one entry point the CLI calls; it returns a frozen
:class:`GearsResult` and raises :class:`~tmm_cli.errors.TmmError` for bad input.
"""

from __future__ import annotations

import math
import re
from fractions import Fraction
from typing import TYPE_CHECKING

from ..errors import TmmError
from ..notes import Note
from ..records import record
from . import drive
from .drive import SCHEMES, MotorPower, SchemeInfo
from .planetary.book import BookDerivation, PrintedCheck, book_derivation, check_printed
from .planetary.conditions import PlanetaryDesign
from .planetary.search import (
    SELECT_RULES,
    SELECT_SLACK,
    STAGE_RANGE_1,
    Z_MAX,
    SearchResult,
    _NoCandidates,
    _NoPlanets,
    closest_ratio,
    search_designs,
)
from .planetary.velocity import DesignChecks, check_design
from .spur import SpurGeometry, design_spur

if TYPE_CHECKING:  # the mesh stiffness (seed 002) is loaded only when asked for (--stiffness)
    from .stiffness import SpurPairStiffness

_RATIO_RE = re.compile(r"^\s*([0-9]{1,9})\s*(?:/\s*([0-9]{1,9})\s*)?$")  # ASCII digits, at most 9: int() never refuses


def parse_ratio(text: str) -> tuple[int, int]:
    """Parse a forced ratio "p/q" (or a whole number "p") into positive integers (p, q).

    >>> parse_ratio("13/4"), parse_ratio(" 53 / 5 "), parse_ratio("11")
    ((13, 4), (53, 5), (11, 1))
    """
    m = _RATIO_RE.match(text or "")
    if not m:
        text = text if len(text or "") <= 40 else text[:40] + "…"
        raise TmmError(f"cannot read the ratio {text!r}: write it as a fraction of two positive whole numbers, "
                       "e.g. --ratio 13/4")
    p = int(m.group(1))
    q = int(m.group(2)) if m.group(2) is not None else 1
    if p == 0 or q == 0:
        raise TmmError(f"the ratio {text!r} has a zero in it: write it as a fraction of two positive whole numbers, "
                       "e.g. --ratio 13/4")
    return p, q


@record
class Directions:
    """Senses of rotation ('cw'/'ccw'): the cam's from the sign of n_k (Table 1.2); the spur pair
    is an external mesh (i_12 < 0), so the motor turns the other way; schemes 1, 2 and 1+1 have
    i_pl > 0, so the crank turns with the motor."""

    cam: str
    motor: str
    crank: str
    i_spur_signed: float  # −z2/z1
    i_planetary_signed: float  # +i


@record
class GearsResult:
    """Everything sheet 4 needs.

    Speeds [rpm]; ``i_spur`` = n_d/|n_k| (required), ``i_planetary`` = n_d/n_cr (required);
    ``planetary`` is the carried design (= ``search.carried``), ``checks`` its five conditions and
    two ratio checks, ``derivation`` the book's hand procedure, ``printed`` the recheck of the
    book's printed answer when the derivation is the book's own example. ``spur_stiffness`` is
    the spur pair's mesh stiffness by seed 002 — beyond the course, informative, with its own
    assumption notes (not in ``notes``).
    """

    cam_rpm: float
    crank_rpm: float
    crank_rpm_assumed: bool
    torque_nm: float | None
    tolerance_pct: float
    motor_rpm: int
    motor_candidates: tuple[int, ...]
    i_spur: float
    i_planetary: float
    scheme: str
    scheme_reason: str
    schemes: tuple[SchemeInfo, ...]
    eta1: float
    eta2: float
    power: MotorPower | None
    directions: Directions
    forced_ratio: tuple[int, int] | None
    forced_planets: int | None
    search: SearchResult
    planetary: PlanetaryDesign
    checks: DesignChecks
    derivation: BookDerivation | None
    printed: PrintedCheck | None
    spur: SpurGeometry
    crank_rpm_actual: float
    cam_rpm_actual: float
    notes: tuple[Note, ...]
    spur_stiffness: SpurPairStiffness | None = None  # beyond the course (seed 002), informative


def _aa_bar_hint(i_pl: float, err_pct: float) -> list[Note]:
    """When the zero-gear reducer misses the ratio by 1 % or more, point to `tmm planetary`: the AA̅
    mechanism with shifted gears (seed 000) driven at its carrier, if one fits more exactly."""
    if abs(err_pct) < 1.0:
        return []
    from .aa_bar import suggest_for_reducer

    s = suggest_for_reducer(i_pl, tolerance_pct=min(0.5, abs(err_pct) / 2))
    if s is None:
        return []
    return [Note.make("aa_bar_hint", "assumption", i=f"{s.i}", c=f"{s.c}", teeth="/".join(map(str, s.teeth)),
                      err=f"{s.ratio_error_pct:+.2f}", ratio=f"{1 / float(s.i):.4f}", aw34=f"{s.alpha_w34_deg:.2f}",
                      x1=f"{s.x1:g}", x2=f"{s.x2:g}")]


def _spur_shift_notes(spur: SpurGeometry) -> list[Note]:
    """Notes of the shifted spur pair (beyond the book): what was applied, the blocking-contour
    failures, and for z < 17 the shift that removes undercut."""
    from .blocking import pair_notes
    from .shifted import Z_UNDERCUT, auto_shift, x_min_undercut

    notes: list[Note] = []
    if spur.shifted:
        notes.append(Note.make(f"spur_shifted_{spur.shift_rule}", "assumption", x1=f"{spur.x1:.4f}",
                               x2=f"{spur.x2:.4f}", aw=f"{spur.a_w_mm:.3f}", alpha_w=f"{spur.alpha_w_deg:.3f}"))
        notes += pair_notes("z1-z2", spur.blocking, (spur.z1, spur.z2), spur.m_mm)
    else:
        for z in (spur.z1, spur.z2):
            if z < Z_UNDERCUT:
                x1, x2 = auto_shift(spur.z1, spur.z2, spur.ha_star)
                notes.append(Note.make("spur_shift_suggest", "warning", z=z, x=f"{x_min_undercut(z, spur.ha_star):.4f}",
                                       x1=f"{x1:.4f}", x2=f"{x2:.4f}"))
                break
    return notes


def _fmt_teeth(t: tuple[int, ...]) -> str:
    return "/".join(str(v) for v in t)


def design_teeth_text(design: PlanetaryDesign) -> str:
    """'40/25/90' or '20/64/42/126' or '17/34/85 + 43/21/85'."""
    return " + ".join(_fmt_teeth(s.teeth) for s in design.stages)


RATIO_REMARK_PCT = 3.0  # a carried ratio error above 3 % gets a sanity remark (legal within 5 %)


def _selection_notes(search: SearchResult, design: PlanetaryDesign) -> list[Note]:
    """The selection rule in words: which set is carried and the smallest beside it."""
    sm = search.smallest or design
    if search.select == "smallest":
        return [Note.make("select_smallest", "assumption", teeth=design_teeth_text(design), size=design.size,
                          slack=SELECT_SLACK)]
    if sm == design:
        return [Note.make("select_accurate_same", "assumption", teeth=design_teeth_text(design), size=design.size,
                          err=f"{design.ratio_error_pct:+.2f}", slack=SELECT_SLACK)]
    return [Note.make("select_accurate_other", "assumption", teeth=design_teeth_text(design), size=design.size,
                      err=f"{design.ratio_error_pct:+.2f}", k=design.planets, s_teeth=design_teeth_text(sm),
                      s_size=sm.size, s_err=f"{sm.ratio_error_pct:+.2f}", s_k=sm.planets, slack=SELECT_SLACK,
                      n=search.n_sets, zmax=Z_MAX)]


def _larger_better_notes(search, design: PlanetaryDesign, err: float) -> list[Note]:
    """Why an inexact ratio is carried although a more accurate or exact set exists: those are
    larger than the selection rule admits; name them and how to carry them (issue 8)."""
    if search is None or search.select != "accurate" or design != search.carried or abs(err) < 0.005:
        return []
    more, exact = getattr(search, "more_accurate", None), getattr(search, "exact", None)
    if more is None and exact is None:
        return []
    fr = None
    if exact is not None:
        from fractions import Fraction

        fr = Fraction(search.target).limit_denominator(1000)
    parts = {"teeth": design_teeth_text(design), "size": design.size, "err": f"{err:+.2f}", "slack": SELECT_SLACK,
             "limit": (search.smallest or design).size + SELECT_SLACK}
    if more is not None and exact is not None and more != exact:
        return [Note.make("select_larger_both", "assumption", m_teeth=design_teeth_text(more), m_size=more.size,
                          m_err=f"{more.ratio_error_pct:+.2f}", e_teeth=design_teeth_text(exact), e_size=exact.size,
                          ratio=f"{fr.numerator}/{fr.denominator}", **parts)]
    one = exact or more
    if exact is not None:
        return [Note.make("select_larger_exact", "assumption", e_teeth=design_teeth_text(one), e_size=one.size,
                          ratio=f"{fr.numerator}/{fr.denominator}", **parts)]
    return [Note.make("select_larger_more", "assumption", m_teeth=design_teeth_text(one), m_size=one.size,
                      m_err=f"{one.ratio_error_pct:+.2f}", **parts)]


def _check_inputs(n_cam_rpm, crank_rpm, torque_nm, tolerance_pct, planets):
    try:
        cam = float(n_cam_rpm)
    except (TypeError, ValueError):
        cam = math.nan
    if not math.isfinite(cam) or cam == 0:
        raise TmmError(f"cam speed must be a non-zero number of rpm, got {n_cam_rpm!r}; take n_k from Table 1.2")
    if crank_rpm is not None and (not math.isfinite(crank_rpm) or crank_rpm <= 0):
        raise TmmError(f"crank speed must be a positive number of rpm, got {crank_rpm:g}; "
                       "give the crank speed of your linkage (sheet 1), e.g. --crank-rpm 220")
    if not math.isfinite(tolerance_pct) or tolerance_pct < 0:
        raise TmmError(f"ratio tolerance must be a non-negative percentage, got {tolerance_pct:g}; "
                       "the book uses 5, e.g. --tolerance 5")
    if torque_nm is not None and (not math.isfinite(torque_nm) or torque_nm < 0):
        raise TmmError(f"mean reduced moment must be a non-negative number of N·m, got {torque_nm:g}; "
                       "give M from sheet 2, e.g. --torque 100")
    if planets is not None and (int(planets) != planets or planets < 1):
        raise TmmError(f"number of planets must be a whole number ≥ 1, got {planets!r}; e.g. --planets 3")


def design_gears(n_cam_rpm: float, crank_rpm: float | None = None, torque_nm: float | None = None,
                 ratio: tuple[int, int] | None = None, tolerance_pct: float = 5.0,
                 planets: int | None = None, stiffness: bool = True, shift=None,
                 a_w_mm: float | None = None, select: str = "accurate") -> GearsResult:
    """Sheet 4: motor speed (§2.2), ratios, scheme (Fig. 2.4), planetary synthesis (§2.1.3,
    §2.4/§2.5), spur pair (§2.3), power (§2.6); with ``stiffness`` also the spur pair's mesh
    stiffness beyond the course (seed 002, :func:`~tmm_cli.gears.stiffness.spur_pair_stiffness`),
    loaded by the motor torque N/ω_d when ``torque_nm`` is given. ``shift`` ("auto" or (x1, x2)) and
    ``a_w_mm`` shift the spur pair (beyond the book, gears/shifted.py); the default is the book's zero pair.
    ``select``: "accurate" (default: the most accurate ratio among the sets at most one tooth larger
    than the smallest) or "smallest" (the smallest reducer).

    The book's §2.4 example (n_cr = 220 rpm, the fraction 13/4):

    >>> r = design_gears(600, 220, ratio=(13, 4))
    >>> r.motor_rpm, r.scheme, r.planetary.stages[0].teeth, r.planetary.planets
    (720, '1', (40, 25, 90), 5)
    """
    _check_inputs(n_cam_rpm, crank_rpm, torque_nm, tolerance_pct, planets)
    if select not in SELECT_RULES:
        raise TmmError(f"selection rule '{select}' is unknown; use --select accurate or --select smallest")
    notes: list[Note] = []
    assumed = crank_rpm is None
    n_cr = float(drive.DEFAULT_CRANK_RPM if assumed else crank_rpm)
    if assumed:
        notes.append(Note.make("crank_default", "assumption", rpm=drive.DEFAULT_CRANK_RPM))
    n_d = drive.choose_motor_rpm(n_cr)
    notes.append(Note.make("motor_choice", "assumption", n_d=n_d, three_ncr=f"{3 * n_cr:g}"))
    i_spur = n_d / abs(n_cam_rpm)
    i_pl = n_d / n_cr
    scheme = drive.choose_scheme(i_pl)
    planets = int(planets) if planets is not None else None

    forced = None
    if ratio is not None:
        p, q = int(ratio[0]), int(ratio[1])
        if p <= 0 or q <= 0:
            raise TmmError(f"the ratio {p}/{q} must have positive numerator and denominator, e.g. --ratio 13/4")
        forced = Fraction(p, q)
        err = (float(forced) / i_pl - 1) * 100
        if abs(err) > tolerance_pct * (1 + 1e-9) + 1e-9:
            near = min((Fraction(a, b) for b in range(1, 11) for a in [round(i_pl * b)] if a > b),
                       key=lambda f: abs(float(f) - i_pl))
            raise TmmError(f"the forced ratio {p}/{q} = {float(forced):.4g} is {err:+.2f} % off the required "
                           f"i_pl = n_d/n_cr = {n_d}/{n_cr:g} = {i_pl:.4g}, outside ±{tolerance_pct:g} %; "
                           f"use a fraction near it (e.g. {near}) or widen --tolerance")
        if forced <= 1:
            raise TmmError(f"the forced ratio {p}/{q} must be greater than 1 for a reducer, e.g. --ratio 13/4")

    try:
        search = search_designs(scheme, i_pl, tolerance_pct, forced, planets, select=select)
    except _NoCandidates:
        if forced is not None:
            raise TmmError(f"no tooth numbers of scheme {scheme} with at most {Z_MAX} teeth (Table 2.2 kept) give "
                           f"exactly {forced.numerator}/{forced.denominator}; use a simpler fraction or drop --ratio "
                           "to let the program search") from None
        c = closest_ratio(scheme, i_pl)
        need = abs(c.ratio_error_pct)
        raise TmmError(f"no scheme-{scheme} reducer with at most {Z_MAX} teeth per wheel is within ±{tolerance_pct:g} % "
                       f"of i_pl = {i_pl:.4g}; the closest is {design_teeth_text(c)} with i = {c.ratio:.4g} "
                       f"({c.ratio_error_pct:+.2f} %): use --tolerance {math.ceil(need * 100) / 100:g} or more"
                       + ("" if need < 50 else " (or a higher crank speed)")) from None
    except _NoPlanets as e:
        raise TmmError(f"no scheme-{scheme} reducer within ±{tolerance_pct:g} % of i_pl = {i_pl:.4g}"
                       + (f" giving exactly {forced}" if forced is not None else "")
                       + f" can take {planets} planets (assembly and neighbouring); the most is {e.most}: "
                       f"use --planets {e.most} or fewer, or widen --tolerance") from None

    design = search.carried
    checks = check_design(design, tolerance_pct)

    # the book's hand procedure and its printed answers
    deriv = book_derivation(scheme, i_pl, tolerance_pct, forced)
    printed = None
    if deriv is not None and scheme in ("1", "2"):
        printed = check_printed(scheme, deriv.stages[0].fraction, deriv.stages[0])
    if printed is not None:
        tt = _fmt_teeth(printed.stage.teeth)
        if printed.coaxial_ok and printed.ratio_ok:
            notes.append(Note.make("book_printed_ok", "assumption", section=printed.section, teeth=tt,
                                   k=printed.stage.planets))
        else:
            notes.append(Note.make("book_printed_wrong", "warning", section=printed.section, teeth=tt,
                                   lhs=printed.coaxial_lhs, rhs=printed.coaxial_rhs, ratio=f"{printed.ratio:.3f}",
                                   fraction=f"{printed.fraction}", target=f"{float(printed.fraction):.3g}",
                                   procedure=_fmt_teeth(deriv.stages[0].chosen.teeth),
                                   size=deriv.stages[0].chosen.size))
    if deriv is None:
        notes.append(Note.make("book_no_derivation", "warning", scheme=scheme))
    else:
        bt = " + ".join(_fmt_teeth(s.chosen.teeth) for s in deriv.stages)
        code = "book_vs_search_same" if deriv.size == design.size else (
            "book_vs_search_smaller" if design.size < deriv.size else "book_vs_search_book_smaller")
        if design.size > deriv.size and (search.smallest or design).size <= deriv.size:
            code = "book_vs_search_accurate"  # the search has one as small; the carried one is more accurate
        notes.append(Note.make(code, "assumption", book=bt, book_size=deriv.size, found=design_teeth_text(design),
                               size=design.size))

    # the carried design
    if search.select == "smallest" or (search.smallest or design) == design:  # else select_accurate_other says it
        notes.append(Note.make(f"carried_{search.rule}", "assumption", teeth=design_teeth_text(design), size=design.size,
                               k=design.planets, n=search.n_sets, zmax=Z_MAX,
                               any_teeth=design_teeth_text(search.smallest_any), any_size=search.smallest_any.size,
                               any_k=search.smallest_any.planets))
    notes.extend(_selection_notes(search, design))
    if scheme == "1+1":
        notes.append(Note.make("two_stage_order", "assumption"))
        r1, r2 = (s.ratio for s in design.stages)
        lo_r, hi_r = STAGE_RANGE_1
        code = "two_stage_range_ok" if search.stage_range_ok else "two_stage_range_outside"
        notes.append(Note.make(code, "assumption" if search.stage_range_ok else "warning", i1=f"{r1:.3f}",
                               i2=f"{r2:.3f}", lo=f"{lo_r:g}", hi=f"{hi_r:g}"))
    if forced is not None:
        notes.append(Note.make("forced_ratio", "assumption", fraction=f"{forced}", value=f"{float(forced):.4g}"))
    if design.planets < 3:
        notes.append(Note.make("few_planets", "warning", k=design.planets))
    for j, sc in enumerate(checks.stages, 1):
        if sc.k_max != sc.k_max_book:
            notes.append(Note.make("assembly_forms_differ", "warning" if sc.stage.planets > sc.k_max_book else "assumption",
                                   stage=j, exact=sc.k_max, book=sc.k_max_book, t=sc.assembly_t, g=sc.assembly_g,
                                   n=sc.assembly_book_n))
    err = design.ratio_error_pct
    n_cr_actual = n_d / design.ratio
    notes += _aa_bar_hint(i_pl, err)
    # a warning only outside the tolerance in force (a forced fraction); within it the error is said, not flagged
    outside = abs(err) > tolerance_pct * (1 + 1e-9) + 1e-9
    notes.append(Note.make("ratio_error", "warning" if outside else "assumption", i=f"{design.ratio:.4f}",
                           target=f"{i_pl:.4f}", err=f"{err:+.2f}", tol=f"{tolerance_pct:g}",
                           rpm=f"{n_cr_actual:.1f}", want=f"{n_cr:g}"))

    if abs(err) > RATIO_REMARK_PCT:
        notes.append(Note.make("ratio_error_large", "warning", err=f"{err:+.2f}", limit=f"{RATIO_REMARK_PCT:g}",
                               rpm=f"{n_cr_actual:.1f}", want=f"{n_cr:g}"))
    notes += _larger_better_notes(search, design, err)

    # spur pair
    spur = design_spur(n_d, n_cam_rpm, shift=shift, a_w_mm=a_w_mm)
    cam_actual = n_d * spur.z1 / spur.z2
    if spur.multiplier:
        notes.append(Note.make("spur_multiplier", "assumption", z1=spur.z1, z2=spur.z2))
    notes.append(Note.make("spur_ratio", "assumption", z1=spur.z1, z2=spur.z2, i=f"{spur.i_actual:.4f}",
                           target=f"{i_spur:.4f}", err=f"{(spur.i_actual / i_spur - 1) * 100:+.2f}",
                           rpm=f"{cam_actual:.1f}", want=f"{abs(n_cam_rpm):g}"))
    zmin = min(spur.z1, spur.z2)
    zero_pair = spur.x1 == 0 and spur.x2 == 0  # also --shift auto for two gears of 17 teeth or more
    if zmin < spur.z_min_undercut and zero_pair:
        # z = 17 is the book's own smallest gear (§2.3): said, as an assumption, not flagged as a warning
        # (it was on every row of a group's summary and hid the undercuts that matter)
        notes.append(Note.make("undercut", "assumption" if zmin >= 17 else "warning", z=zmin,
                               zmin=f"{spur.z_min_undercut:.2f}",
                               x=f"{(spur.z_min_undercut - zmin) / spur.z_min_undercut:.4f}"))
    notes += _spur_shift_notes(spur)
    if spur.eps_alpha < 1.2 and zero_pair:  # a shifted pair has its own blocking-contour notes
        notes.append(Note.make("eps_low", "warning", eps=f"{spur.eps_alpha:.3f}"))

    # power
    eta1 = drive.eta_planetary(scheme)
    notes.append(Note.make("efficiency", "assumption", eta1=f"{eta1:.4g}", eta2=f"{drive.ETA_LINKAGE:g}",
                           scheme=scheme))
    power = None
    if torque_nm is not None:
        power = drive.motor_power(float(torque_nm), n_cr, eta1)
        if power.rated_kw is None:
            notes.append(Note.make("power_above_series", "warning", kw=f"{power.power_kw:.1f}",
                                   top=f"{drive.RATED_POWER_KW[-1]:g}"))

    # beyond the course: mesh stiffness of the spur pair (seed 002), informative
    spur_stiff = None
    if stiffness and zero_pair:  # seed 002's model is for zero gears
        motor_torque = None if power is None else power.power_kw * 1e3 / drive.omega_rad_s(n_d)
        from .stiffness import spur_pair_stiffness

        spur_stiff = spur_pair_stiffness(spur.z1, spur.z2, spur.m_mm, motor_torque)

    sign = 1 if n_cam_rpm > 0 else -1
    directions = Directions(cam=drive.rotation(sign), motor=drive.rotation(-sign), crank=drive.rotation(-sign),
                            i_spur_signed=-spur.i_actual, i_planetary_signed=design.ratio)
    return GearsResult(
        cam_rpm=float(n_cam_rpm), crank_rpm=n_cr, crank_rpm_assumed=assumed,
        torque_nm=None if torque_nm is None else float(torque_nm), tolerance_pct=float(tolerance_pct),
        motor_rpm=n_d, motor_candidates=drive.MOTOR_RPM, i_spur=i_spur, i_planetary=i_pl, scheme=scheme,
        scheme_reason=drive.scheme_reason(scheme), schemes=SCHEMES, eta1=eta1, eta2=drive.ETA_LINKAGE, power=power,
        directions=directions, forced_ratio=None if forced is None else (forced.numerator, forced.denominator),
        forced_planets=planets, search=search, planetary=design, checks=checks, derivation=deriv, printed=printed,
        spur=spur, crank_rpm_actual=n_cr_actual, cam_rpm_actual=cam_actual, notes=tuple(notes),
        spur_stiffness=spur_stiff,
    )
