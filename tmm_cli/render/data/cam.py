"""The cam result as plain JSON data (the "cam" object) and the profile as CSV for CAD/CNC.

Coordinates: the cam's frame at the start of the rise, cam centre at the origin, +y the
follower's rise direction at B0, x to the right; points in the order of cam angle from the start
of the rise; the cam turns as `rotation` says. Lengths in mm, angles in degrees.
"""

from __future__ import annotations

import io
import math

import numpy as np

from ...cam.design import CamResult
from ...cam.profile import ROLLER_LIMIT
from ...i18n.lang import note_text
from ..terminal.variants import law_words, scheme_words


def _f(x, nd: int = 4):
    if x is None:
        return None
    x = float(x)
    if not math.isfinite(x):
        return None
    return round(x, nd)


def _mm(x, nd: int = 4):
    return None if x is None else _f(float(x) * 1000.0, nd)


def _pt_mm(p, nd: int = 4):
    return None if p is None else [_mm(p[0], nd), _mm(p[1], nd)]


def _curve_mm(arr, nd: int = 4) -> list[list[float]] | None:
    if arr is None:
        return None
    return [[round(x, nd), round(y, nd)] for x, y in (np.asarray(arr, dtype=float) * 1000.0).tolist()]


def _follower_geometry(result: CamResult) -> dict:
    """The follower at the start of the rise (φ = 0) in the curve frame [mm], for inverting the motion.

    With this, the pitch curve alone gives the mechanism back: at cam angle φ the cam has turned by
    φ in the sense of `rotation`, so the roller centre in the fixed frame (= the curve frame at
    φ = 0) is R(±φ)·P(φ) (+ for "ccw"). Translating: B moves on the line through `axis_point_mm`
    along `rise_direction` (the axis, offset e from the cam centre). Rocker: B turns about the
    fixed pivot `pivot_mm` (|pivot| = l_OC, |B0 − pivot| = l_BC); `rocker_turns_on_rise` says
    which way CB turns while the follower rises.
    """
    z = result.sizing
    b0 = result.profile.pitch[0]
    out = {
        "b0_mm": _pt_mm(b0),
        "rise_direction": [0.0, 1.0],
        "axis_point_mm": None,
        "pivot_mm": None,
        "rocker_turns_on_rise": None,
    }
    if z.rocker:
        o = z.centre
        out["pivot_mm"] = _pt_mm((z.pivot[0] - o[0], z.pivot[1] - o[1]))
        same = z.swing == "same"
        out["rocker_turns_on_rise"] = ("ccw" if z.ccw else "cw") if same else ("cw" if z.ccw else "ccw")
    else:
        out["axis_point_mm"] = _pt_mm((z.e_m, 0.0))
    return out


def _drawing(result: CamResult) -> dict:
    """The profile drawing scale, Table 1.1, and the sizes at it, (1.26)–(1.27) [mm]."""
    d = result.drawing
    w, h = d.extent_mm
    x0, x1, y0, y1 = d.bbox_m
    return {
        "scale": d.scale,
        "k_sk_m_per_mm": d.k_sk,
        "k_s_m_per_mm": _f(d.k_s, 10),
        "k_s_prime_m_per_mm": _f(d.k_s_prime, 10),
        "k_s_prime_rule": "k_S' = k_S (the sizing of §1.3 drawn in the displacement diagram's scale)",
        "field_mm": d.field_mm,
        "fits": d.fits,
        "extent_mm": [_f(w, 3), _f(h, 3)],
        "bbox_real_mm": [_mm(x0, 3), _mm(x1, 3), _mm(y0, 3), _mm(y1, 3)],
        "sizes_mm": {s.name: _f(s.drawn_mm, 3) for s in d.sizes},
        "sizes_at_k_s_mm": {s.name: _f(s.at_k_s_mm, 3) for s in d.sizes},
        "sizes_formula": {s.name: s.formula for s in d.sizes},
        "stroke_is": "S_B,max = gamma_max*l_BC (roller-centre arc, 1.6)" if result.variant.is_rocker else "S_max",
        "displacements_mm": [
            {"position": p.index, "phi_deg": _f(p.phi_deg, 3), "y_s_mm": _f(p.y_s_mm, 3), "y_sk_mm": _f(p.y_sk_mm, 3), "chord_mm": _f(p.chord_mm, 3)}
            for p in d.positions
        ],
    }


def cam_to_json(result: CamResult, lang: str) -> dict:
    """The JSON object of sheet 3 (no numpy types; mm and degrees)."""
    v, m, z, p = result.variant, result.motion, result.sizing, result.profile
    rocker = v.is_rocker
    mx, sc = m.maxima, m.scales
    l = v.l_bc_m
    unit_s, unit_v, unit_a = ("rad", "rad/s", "rad/s^2") if rocker else ("m", "m/s", "m/s^2")
    table = []
    for row in m.table:
        item = {
            "position": row.index,
            "phi_deg": _f(row.phi_deg, 3),
            "t_s": _f(row.t_s, 7),
            "phase": row.phase,
        }
        if rocker:
            item.update(
                {
                    "gamma_deg": _f(math.degrees(row.s), 5),
                    "omega_rad_s": _f(row.v, 5),
                    "epsilon_rad_s2": _f(row.a, 3),
                    "s_b_m": _f(row.s_b_m, 7),
                    "v_b_m_s": _f(row.v_b_m_s, 5),
                    "a_b_m_s2": _f(row.a_b_m_s2, 3),
                }
            )
        else:
            item.update({"s_m": _f(row.s, 7), "v_m_s": _f(row.v, 5), "a_m_s2": _f(row.a, 3)})
        table.append(item)
    warnings = [note_text(n, lang) for n in result.notes if n.level == "warning"]
    assumptions = [note_text(n, lang) for n in result.notes if n.level == "assumption"]
    return {
        "scheme": v.scheme,
        "scheme_text": scheme_words(v.scheme, lang),
        "law": v.law,
        "law_text": law_words(v.law, lang),
        "closure": v.closure,
        "follower": v.follower,
        "rotation": "ccw" if v.ccw else "cw",
        "n_cam_rpm": v.n_cam_rpm,
        "omega_cam_rad_s": _f(m.omega, 6),
        "nu_max_deg": v.nu_max_deg,
        "s_max_mm": None if rocker else _mm(v.stroke),  # the stroke of Table 1.2 (schemes 1, 2)
        "gamma_max_deg": v.stroke if rocker else None,  # the rocker swing (schemes 3, 4)
        "phases_deg": {
            "rise": v.phi_rise_deg,
            "far_dwell": v.phi_far_dwell_deg,
            "return": v.phi_return_deg,
            "near_dwell": v.phi_near_dwell_deg,
            "working": v.phi_working_deg,
        },
        "r0_mm": _mm(z.r0_m),
        "e_mm": _mm(z.e_m),
        "e_sign": "e > 0: follower axis to the right of the cam centre (follower above the cam, +y = rise)",
        "l_oc_mm": _mm(z.l_oc_m),
        "l_bc_mm": _mm(l),
        "swing": z.swing,
        "r0_other_swing_mm": _mm(z.r0_other_swing_m),
        "roller_mm": _mm(p.roller_m),
        "roller_rule": {"book": "0.2*r0 (1.28)", "limited": "0.8*rho_min (0.2*r0 would undercut or exceed 0.8*rho_min)", "student": "student (--roller)"}[p.roller_rule],
        "roller_rule_applied": p.roller_rule,
        "roller_book_mm": _mm(p.roller_book_m),
        "roller_limit_share": ROLLER_LIMIT,
        "roller_max_mm": _mm(p.roller_max_m),
        "pressure_angle_max_deg": {"rise": _f(z.nu_rise_max_deg, 4), "return": _f(z.nu_return_max_deg, 4)},
        "pressure_angle_design_deg": _f(z.nu_design_deg, 4),
        "psi_deg": {
            "rise": _f(p.psi_rise_deg, 4),
            "far_dwell": _f(p.psi_far_deg, 4),
            "return": _f(p.psi_return_deg, 4),
            "near_dwell": _f(p.psi_near_deg, 4),
            "working": _f(p.psi_working_deg, 4),
        },
        "rho_min_mm": _mm(p.rho_min_convex_m),
        "rho_min_at_deg": _f(p.phi_rho_min_convex_deg, 2),
        "rho_min_concave_mm": _mm(p.rho_min_concave_m),
        "undercut": p.undercut,
        "undercut_fix": _fix(result),
        "far_dwell_radius_mm": _mm(p.r_far_m),
        "working_profile_min_radius_mm": _mm(p.working_min_radius_m),
        "centre_mm": _pt_mm(z.centre),
        "pivot_mm": _pt_mm(z.pivot),
        "zone_frame": "B0 at the origin, +y = rise direction at B0",
        "book_vertex": {
            "r0_mm": _mm(z.book_r0_m),
            "e_mm": _mm(z.book_e_m),
            "l_oc_mm": _mm(z.book_l_oc_m),
            "centre_mm": _pt_mm(z.book_centre),
            "pressure_angle_max_deg": {"rise": _f(z.book_nu_rise_max_deg, 3), "return": _f(z.book_nu_return_max_deg, 3)},
        },
        "motion": {
            "units": {"s": unit_s, "v": unit_v, "a": unit_a},
            "period_s": _f(m.period_s, 7),
            "v_rise_max": _f(mx.v_rise_max, 6),
            "v_rise_max_at_deg": _f(mx.phi_v_rise_max_deg, 3),
            "v_return_min": _f(mx.v_return_min, 6),
            "v_return_min_at_deg": _f(mx.phi_v_return_min_deg, 3),
            "a_rise_max": _f(mx.a_rise_max, 4),
            "a_rise_min": _f(mx.a_rise_min, 4),
            "a_return_max": _f(mx.a_return_max, 4),
            "a_return_min": _f(mx.a_return_min, 4),
            "accel_ratio": _f(mx.accel_ratio, 9),
            "accel_ratio_book_1_7": _f(mx.accel_ratio_book, 9),
            "table_step_deg": {"rise": m.table_step_rise_deg, "return": m.table_step_return_deg},
            "table": table,
        },
        "scales": {
            "b_mm": sc.b_mm,
            "y_s_max_mm": sc.y_s_max_mm,
            "h_v_mm": sc.h_v_mm,
            "h_a_mm": sc.h_a_mm,
            "k_phi_deg_per_mm": _f(sc.k_phi_deg_mm, 8),
            "k_t_s_per_mm": _f(sc.k_t_s_mm, 10),
            "k_s": _f(sc.k_s, 10),
            "k_v": _f(sc.k_v, 8),
            "k_a": _f(sc.k_a, 6),
            "k_s_unit": "rad/mm" if rocker else "m/mm",
            "k_v_unit": "rad/s per mm" if rocker else "m/s per mm",
            "k_a_unit": "rad/s^2 per mm" if rocker else "m/s^2 per mm",
            "k_gamma_deg_per_mm": _f(sc.k_gamma_deg_mm, 8),
            "k_s_b_m_per_mm": _f(sc.k_s_b, 10),
            "k_v_b_m_s_per_mm": _f(sc.k_v_b, 8),
            "k_a_b_m_s2_per_mm": _f(sc.k_a_b, 6),
            "y_v_max_mm": _f(sc.y_v_max_mm, 3),
            "y_a_rise_max_mm": _f(sc.y_a_rise_max_mm, 3),
            "y_a_return_max_mm": _f(sc.y_a_return_max_mm, 3),
        },
        "drawing": _drawing(result),
        "curve_frame": "cam frame at the start of the rise: cam centre at the origin, +y = rise direction at B0",
        "pitch_curve_step_deg": _f(math.degrees(float(p.phi[1] - p.phi[0])), 6),
        "pitch_curve_mm": _curve_mm(p.pitch),
        "follower_in_curve_frame": _follower_geometry(result),
        "working_profile_mm": _curve_mm(p.inner),
        "groove_outer_profile_mm": _curve_mm(p.outer),
        "design_source": result.source,
        "student_choice": _choice(result),
        "program_design": _own(result),
        "pivot_move": result.pivot_move,
        "checks": _checks(result),
        "warnings": warnings,
        "assumptions": assumptions,
    }


def _fix(result: CamResult) -> dict | None:
    """Where the book's 0.2·r0 roller would undercut: the smallest cam keeping it (certified)."""
    f = result.book_roller_fix
    if f is None:
        return None
    return {"r0_mm": _mm(f.r0_m), "e_mm": _mm(f.e_m), "l_oc_mm": _mm(f.l_oc_m), "centre_mm": _pt_mm(f.centre),
            "roller_rule": "0.2*r0 (1.28)", "certified": f.certified, "rel_tol": f.rel_tol, "cells": f.cells,
            "meaning": "smallest r0 in the pressure-angle zone at which the book's roller does not undercut"}


def _choice(result: CamResult) -> dict | None:
    """The student's overrides as given (mm), or None for the program's own design."""
    c = result.choice
    if c is None or not c.given:
        return None
    return {"r0_mm": c.r0_mm, "offset_mm": c.offset_mm, "l_oc_mm": c.l_oc_mm, "swing": c.swing, "roller_mm": c.roller_mm,
            "options": c.options}


def _own(result: CamResult) -> dict | None:
    """The program's own sizing beside the student's choice (mm), or None."""
    z = result.own
    if z is None:
        return None
    return {"r0_mm": _mm(z.r0_m), "e_mm": _mm(z.e_m), "l_oc_mm": _mm(z.l_oc_m), "swing": z.swing,
            "pressure_angle_max_deg": {"rise": _f(z.nu_rise_max_deg, 4), "return": _f(z.nu_return_max_deg, 4)}}


def _checks(result: CamResult) -> dict | None:
    """The carried design's conditions: ν on every constrained phase, undercut, pivot."""
    ch = result.checks
    if ch is None:
        return None
    return {
        "pressure_angle_ok": {"rise": ch.nu_rise_ok, "return": ch.nu_return_ok},
        "return_limited": ch.return_limited,
        "undercut_ok": ch.undercut_ok,
        "pivot_ok": ch.pivot_ok,
        "pivot_body_radius_mm": _mm(ch.body_m),
        "all_ok": ch.ok,
    }


def profile_csv(result: CamResult) -> str:
    """Dense profile for CAD/CNC: cam angle, pitch curve, working profile(s) [mm], in the cam frame."""
    p = result.profile
    buf = io.StringIO()
    head = ["phi_deg", "pitch_x_mm", "pitch_y_mm", "inner_x_mm", "inner_y_mm"]
    if p.outer is not None:
        head += ["outer_x_mm", "outer_y_mm"]
    head += ["pressure_angle_deg"]
    buf.write(",".join(head) + "\n")
    mm = [(np.asarray(a, dtype=float) * 1000.0).tolist() for a in (p.pitch, p.inner, p.outer) if a is not None]
    nu = np.asarray(p.nu_deg, dtype=float).tolist()
    for i, phi in enumerate(np.asarray(p.phi, dtype=float).tolist()):
        cols = [f"{math.degrees(phi):.2f}"]
        cols += [f"{c:.4f}" for curve in mm for c in curve[i]]
        cols.append(f"{nu[i]:.3f}")
        buf.write(",".join(cols) + "\n")
    return buf.getvalue()
