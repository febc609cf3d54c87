"""The gears result as plain JSON-ready Python (the object under the "gears" key)."""

from __future__ import annotations

from fractions import Fraction

from ...i18n import tr
from ...i18n.lang import note_text


def _r(x: float, nd: int = 6) -> float:
    return float(round(float(x), nd))


def _frac(f: Fraction | None) -> str | None:
    return None if f is None else f"{f.numerator}/{f.denominator}"


def _stage(s) -> dict:
    return {"z_sun": s.z_sun, "z_planet": s.z_planet, "z_planet2": s.z_planet2, "z_ring": s.z_ring,
            "planets": s.planets, "ratio": _r(s.ratio), "ratio_fraction": _frac(s.ratio_fraction),
            "gamma1": s.gamma1, "gamma2": s.gamma2, "size": s.size}


def _design(d) -> dict:
    return {"scheme": d.scheme, "stages": [_stage(s) for s in d.stages], "ratio": _r(d.ratio),
            "ratio_error_pct": _r(d.ratio_error_pct, 4), "size": d.size, "planets": d.planets}


def _stage_checks(c) -> dict:
    return {
        "coaxial": {"lhs": c.coaxial_lhs, "rhs": c.coaxial_rhs, "ok": c.coaxial_ok},
        "assembly": {"exact": {"t": c.assembly_t, "g": c.assembly_g, "ok": c.assembly_exact_ok,
                               "k_admitted": list(c.assembly_ks_exact)},
                     "book": {"n": c.assembly_book_n, "d": c.assembly_book_d, "ok": c.assembly_book_ok,
                              "k_admitted": list(c.assembly_ks_book)},
                     "forms_differ": c.assembly_forms_differ},
        "neighbouring": {"sin_pi_over_k": _r(c.neighbour_sin), "q": _r(c.neighbour_q), "ok": c.neighbour_ok,
                         "k_limit": c.neighbour_limit},
        "interference": [{"what": i.what, "symbol": i.symbol, "value": i.value, "limit": i.limit, "ok": i.ok}
                         for i in c.interference],
        "k_max": c.k_max, "k_max_book": c.k_max_book, "ok": c.ok,
    }


def _book(d) -> dict | None:
    if d is None:
        return None
    stages = []
    for s in d.stages:
        stages.append({
            "scheme": s.scheme, "fraction": _frac(s.fraction), "reduced": _frac(s.reduced),
            "x1_range": list(s.x1_range) if s.x1_range else None,
            "x2_range": list(s.x2_range) if s.x2_range else None,
            "rows": [{"table": r.table, "x": r.x, "A": r.a, "B": r.b, "D": r.d, "E": r.e,
                      "y_min": _frac(r.y_min), "teeth": list(r.teeth), "gamma1": r.gamma1, "gamma2": r.gamma2}
                     for r in s.rows],
            "chosen": {"table": s.chosen.table, "x": s.chosen.x, "teeth": list(s.chosen.teeth),
                       "y_min": _frac(s.chosen.y_min), "size": s.chosen.size},
            "assembly_n": s.assembly_n, "assembly_c": s.assembly_c, "assembly_k": list(s.assembly_ks[:12]),
            "neighbour_q": _r(s.neighbour_q), "neighbour_limit": s.neighbour_limit,
            "k_max_book_form": s.k_max, "k_max_exact": s.k_max_exact,
        })
    return {"scheme": d.scheme, "fraction_rule": d.fraction_rule, "stages": stages, "size": d.size,
            "tried": [{"fraction": f, "size": n} for f, n in d.tried],
            "convergents": [_frac(f) for f in d.convergents]}


def _pair(t, scale: float = 1.0, nd: int = 6) -> list[float]:
    return [_r(v * scale, nd) for v in t]


def _stiffness(st, lang: str) -> dict | None:
    from ...i18n.messages_gears import MESSAGES, PAPER

    """The spur pair's mesh stiffness (Tarasik's paper, `tmm gears --stiffness`): beyond the course, informative; lengths in mm."""
    if st is None:
        return None
    s = st.mesh
    return {
        "informative": True,
        "beyond_course": True,
        "method": "variable-section cantilever bending + Nakhatakyan contact, c = c_b*c_H/(c_b + c_H)",
        "source": tr(lang, MESSAGES[PAPER]),
        "b_w_mm": _r(s.b_w_m * 1e3), "psi_m": st.psi_m, "load": st.load,
        "torque1_nm": _r(s.torque1_nm), "force_n": _r(s.force_n, 3), "line_load_n_per_mm": _r(s.line_load_n_per_m * 1e-3),
        "e_pa": s.e_pa, "nu": s.nu,
        "s_a_mm": _pair(s.s_a_m, 1e3), "s_d_mm": _pair(s.s_d_m, 1e3), "s_b_mm": _pair(s.s_b_m, 1e3),
        "rho_mm": _pair(s.rho_m, 1e3), "j_d_m4": [float(f"{v:.6e}") for v in s.j_d_m4],
        "y_bend_um": _pair(s.y_bend_m, 1e6, 9), "y_contact_um": _r(s.y_contact_m * 1e6, 9),
        "c_bend_nm_per_rad": _r(s.c_bend, 1), "c_contact_nm_per_rad": _r(s.c_contact, 1), "c_nm_per_rad": _r(s.c, 1),
        "k_bend_n_per_m": _r(s.k_bend, 0), "k_contact_n_per_m": _r(s.k_contact, 0), "k_n_per_m": _r(s.k, 0),
        "c_spec_n_per_mm_um": {"bend": _r(s.c_spec_bend, 4), "contact": _r(s.c_spec_contact, 4), "mesh": _r(s.c_spec, 4)},
        "reduced_to": "gear 1 (motor) shaft",
        "notes": [note_text(n, lang) for n in st.notes],
    }


def _spur_shift(sp) -> dict:
    """Profile-shift keys of the spur pair (beyond the book; a zero pair by default): x1, x2, a_w_mm,
    alpha_w_deg beside the other spur keys, and the full shifted geometry with its blocking-contour checks."""
    from .planetary import pair_to_json

    return {"x1": _r(sp.x1), "x2": _r(sp.x2), "a_w_mm": _r(sp.a_w_mm), "alpha_w_deg": _r(sp.alpha_w_deg),
            "shift_rule": sp.shift_rule,
            "shifted": pair_to_json(sp.pair, sp.blocking) if sp.pair is not None else None}


def gears_to_json(result, lang: str) -> dict:
    """JSON-serialisable dict of a :class:`~tmm_cli.gears.design.GearsResult` (plain types only)."""
    r = result
    d = r.planetary
    sp = r.spur
    ch = r.checks
    vel = ch.velocity
    printed = None
    if r.printed is not None:
        p = r.printed
        printed = {"section": p.section, "teeth": list(p.stage.teeth), "planets": p.stage.planets,
                   "fraction": _frac(p.fraction), "coaxial_lhs": p.coaxial_lhs, "coaxial_rhs": p.coaxial_rhs,
                   "coaxial_ok": p.coaxial_ok, "ratio": _r(p.ratio), "ratio_ok": p.ratio_ok}
    return {
        "crank_rpm": r.crank_rpm,
        "crank_rpm_assumed": r.crank_rpm_assumed,
        "crank_rpm_actual": _r(r.crank_rpm_actual, 4),
        "cam_rpm": r.cam_rpm,
        "cam_rpm_actual": _r(r.cam_rpm_actual, 4),
        "motor": {
            "n_rpm": r.motor_rpm,
            "candidates_rpm": list(r.motor_candidates),
            "power_kw": None if r.power is None else _r(r.power.power_kw, 6),
            "rated_kw": None if r.power is None else r.power.rated_kw,
            "torque_nm": r.torque_nm,
            "eta1": _r(r.eta1), "eta2": _r(r.eta2),
        },
        "directions": {"cam": r.directions.cam, "motor": r.directions.motor, "crank": r.directions.crank},
        "i_spur": _r(r.i_spur),
        "i_planetary": _r(r.i_planetary),
        "tolerance_pct": r.tolerance_pct,
        "forced_ratio": None if r.forced_ratio is None else f"{r.forced_ratio[0]}/{r.forced_ratio[1]}",
        "forced_planets": r.forced_planets,
        "planetary": {
            **_design(d),
            "scheme_reason": r.scheme_reason,
            "size_measure": "max(z_k + 2*z_c, z_n)",
            "z_max": r.search.z_max,
            "selection_rule": r.search.rule,
            "candidates": r.search.n_sets,
            "alternatives": [{**_design(a), "carried": a == d} for a in r.search.alternatives],
            "smallest_any": _design(r.search.smallest_any),
            "select": r.search.select,
            "select_rule": ("the most accurate ratio among the sets at most 1 tooth larger than the smallest"
                            if r.search.select == "accurate" else "the smallest reducer"),
            "smallest": None if r.search.smallest is None else _design(r.search.smallest),
            "stage_range": [3.0, 8.0] if r.scheme == "1+1" else None,
            "stage_range_ok": r.search.stage_range_ok,
        },
        "checks": {
            "ok": ch.ok,
            "ratio": {"value": _r(ch.ratio), "fraction": _frac(ch.ratio_fraction), "target": _r(ch.target),
                      "error_pct": _r(ch.ratio_error_pct, 4), "tolerance_pct": ch.tolerance_pct, "ok": ch.ratio_ok},
            "stages": [_stage_checks(c) for c in ch.stages],
            "ratio_formula_2_1": _r(ch.ratio_formula_21_total),
            "ratio_velocity_2_3": _r(vel.ratio),
            "velocity": {"phi_k_deg": [_r(v.phi_k_deg, 4) for v in vel.stages],
                         "phi_h_deg": [_r(v.phi_h_deg, 4) for v in vel.stages],
                         "ok_segment": _r(vel.ok, 4), "oh_segment": _r(vel.oh, 4)},
        },
        "book": _book(r.derivation),
        "book_printed": printed,
        "spur": {
            "z1": sp.z1, "z2": sp.z2, "m_mm": sp.m_mm, "alpha_deg": sp.alpha_deg, "a_mm": _r(sp.a_mm),
            "i_required": _r(sp.i_d), "i_actual": _r(sp.i_actual), "multiplier": sp.multiplier,
            "d_mm": [_r(sp.d1_mm), _r(sp.d2_mm)], "db_mm": [_r(sp.db1_mm), _r(sp.db2_mm)],
            "da_mm": [_r(sp.da1_mm), _r(sp.da2_mm)], "df_mm": [_r(sp.df1_mm), _r(sp.df2_mm)],
            "p_mm": _r(sp.p_mm), "pb_mm": _r(sp.pb_mm), "s_mm": _r(sp.s_mm), "e_mm": _r(sp.e_mm),
            "tau_deg": [_r(sp.tau1_deg), _r(sp.tau2_deg)], "h_mm": _r(sp.h_mm), "hd_mm": _r(sp.hd_mm),
            "c_mm": _r(sp.c_mm), "check_ok": sp.check_ok,
            "eps_alpha": _r(sp.eps_alpha),
            "g_alpha_mm": _r(sp.g_alpha_mm),
            "line_of_action_mm": {"N1N2": _r(sp.n1n2_mm), "P": _r(sp.pole_mm), "P1": _r(sp.p1_mm),
                                  "U1": _r(sp.u1_mm), "U2": _r(sp.u2_mm), "P2": _r(sp.p2_mm)},
            "phi_alpha_deg": [_r(sp.phi_alpha1_deg), _r(sp.phi_alpha2_deg)],
            "stiffness": _stiffness(getattr(r, "spur_stiffness", None), lang),
            **_spur_shift(sp),
        },
        "warnings": [note_text(n, lang) for n in r.notes if n.level == "warning"],
        "assumptions": [note_text(n, lang) for n in r.notes if n.level == "assumption"],
    }
