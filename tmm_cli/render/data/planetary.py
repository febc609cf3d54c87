"""JSON-ready dicts for shifted pairs, their blocking-contour checks, and the AA̅ synthesis
(`tmm planetary --json`). Plain numbers only; lengths in mm, angles in degrees."""

from __future__ import annotations

from fractions import Fraction

from ...i18n.lang import note_text


def _r(x: float, nd: int = 6) -> float:
    return float(round(float(x), nd))


def _rr(t, nd: int = 6) -> list[float]:
    return [_r(v, nd) for v in t]


def _frac(f: Fraction) -> str:
    return f"{f.numerator}/{f.denominator}"


def check_to_json(c) -> dict:
    return {"code": c.code, "gear": c.gear, "value": _r(c.value), "limit": _r(c.limit) if c.limit != float("inf") else None,
            "ok": c.ok, "hard": c.hard}


def pair_to_json(g, checks) -> dict:
    """One shifted pair (:class:`~tmm_cli.gears.shifted.PairGeometry`) with its checks."""
    return {
        "teeth": list(g.z), "x": _rr(g.x), "x_sum": _r(g.x_sum), "alpha_w_deg": _r(g.alpha_w_deg), "a_mm": _r(g.a_mm),
        "a_w_mm": _r(g.a_w_mm), "y": _r(g.y), "dy": _r(g.dy),
        "d_mm": _rr(g.d_mm), "db_mm": _rr(g.db_mm), "dw_mm": _rr(g.dw_mm), "da_mm": _rr(g.da_mm), "df_mm": _rr(g.df_mm),
        "s_mm": _rr(g.s_mm), "s_w_mm": _rr(g.sw_mm), "s_a_mm": _rr(g.sa_mm), "s_a_min_mm": _r(checks.sa_min_mm),
        "p_mm": _r(g.p_mm), "pb_mm": _r(g.pb_mm), "pw_mm": _r(g.pw_mm),
        "line_of_action_mm": {"N1N2": _r(g.n1n2_mm), "P": _r(g.pole_mm), "P1": _r(g.p1_mm), "P2": _r(g.p2_mm)},
        "g_alpha_mm": _r(g.g_alpha_mm), "eps_alpha": _r(g.eps_alpha),
        "x_min": _rr(g.x_min), "rho_lower_limit_mm": _rr(g.rho_l_mm), "rho_contact_mm": _rr(g.rho_contact_mm),
        "undercut": list(checks.undercut), "interference": list(checks.interference), "pointed": list(checks.pointed),
        "eps_ok": checks.eps_ok, "eps_hard_ok": checks.eps_hard_ok, "ok": checks.ok,
        "checks": [check_to_json(c) for c in checks.checks],
    }


def planetary_to_json(d, lang: str, examples=()) -> dict:
    """The `tmm planetary --json` object (:class:`~tmm_cli.gears.aa_bar.AABarDesign`)."""
    v = d.velocity
    lo, hi = d.c_feasible
    return {
        "mechanism": "AA-bar (two external meshes, linked planet Z3 = Z2, wheel 4 fixed, carrier H out)",
        "source": ("Kavetsky S. N. The procedure of synthesis of the planetary mechanism AA-bar with regard to the meshing angles of the first and second stages. Vestnik NTU KhPI, thematic issue Machine science and CAD, 2010"),
        "ratio": {"fraction": _frac(d.i), "value": _r(float(d.i), 12)},
        "c": {"fraction": _frac(d.c), "value": _r(float(d.c), 12), "from_angles": _r(d.c_check, 9)},
        "c_feasible": {"min": _frac(lo), "max": _frac(hi), "max_value": _r(float(hi), 9),
                       "rule": "1 < C < 1/(1 - i)",
                       "examples": [{"c": _frac(c), "teeth": list(t)} for c, t in examples]},
        "planets": d.planets, "module_mm": d.module_mm, "alpha_deg": d.alpha_deg, "ha_star": d.ha_star,
        "c_star": d.c_star, "z_limits": [d.z_min, d.z_max],
        "multiples": {"assembly": d.div.m_assembly, "coaxiality": d.div.m_coaxial, "ratio": d.div.m_ratio,
                      "z1_min": d.div.z1_step},
        "teeth": list(d.teeth),
        "family": list(d.family),
        "family_multiple": d.multiple,
        "ratio_check": {"formula": "1 - Z2*Z4/(Z1*Z3)", "fraction": _frac(d.ratio_check),
                        "value": _r(float(d.ratio_check), 12), "velocity_picture": _r(v.ratio, 9)},
        "a_w_mm": _r(d.a_w_mm),
        "alpha_w_deg": _rr(d.alpha_w_deg),
        "x": _rr(d.x),
        "x_sum": _rr(d.x_sum),
        "planet_da_mm": _r(d.da_planet_mm),
        "pairs": [dict(pair="1-2", **pair_to_json(d.pair12, d.checks12)),
                  dict(pair="3-4", **pair_to_json(d.pair34, d.checks34))],
        "neighbours": {"da_planet_mm": _r(d.neighbours.value), "limit_mm": _r(d.neighbours.limit)
                       if d.neighbours.limit != float("inf") else None,
                       "rule": "d_a < 2 a_w sin(pi/k)", "ok": d.neighbours.ok},
        "velocity": {"omega_h_rad_s": 1.0, "r_w1_mm": _r(v.r_w1_mm), "r_w4_mm": _r(v.r_w4_mm), "a_w_mm": _r(v.a_w_mm),
                     "v_c_mm_s": _r(v.v_c), "v_p12_mm_s": _r(v.v_p12), "phi_1_deg": _r(v.phi_1_deg),
                     "phi_h_deg": _r(v.phi_h_deg), "ratio": _r(v.ratio, 9)},
        "warnings": [note_text(n, lang) for n in d.notes if n.level == "warning"],
        "assumptions": [note_text(n, lang) for n in d.notes if n.level == "assumption"],
    }
