"""The linkage result as plain JSON data and the dense curve as CSV (machine-readable, SI units).

Frame and signs as in seed 003: origin at the crank centre O21, x right, y up; φ21 and φ41
measured from +y towards +x (φ21 grows with time, so positive ω4 turns the link the same way);
φ21 in [0, 360)°, φ41 in (−180, 180]°; ρ = O41A; v_rel = dρ/dt (+ away from O41);
a_cor = 2·ω4·v_rel; x_C, v_C, a_C along +x.
"""

from __future__ import annotations

import io
import math

from ...i18n.lang import note_text
from ...linkage.analysis import LinkageResult, State

POSITION_KEYS = ("phi_deg", "link_angle_deg", "rho_m", "x_c_m", "omega_link_rad_s", "eps_link_rad_s2",
                 "v_rel_m_s", "a_cor_m_s2", "v_c_m_s", "a_c_m_s2")
CONVENTIONS = ("origin O21, x right, y up (Goban, Monkova, Smeringaiova, The numerical and computer aided confrontation of "
               "kinematic analysis of mechanism, 2010, Fig. 1); phi21 and phi41 from +y towards +x, phi21 grows with "
               "time; O41 = (-c, -h); rho = O41A; v_rel = d(rho)/dt; a_cor = 2*omega_link*v_rel; SI units")


def _f(x) -> float | None:
    x = float(x)
    if not math.isfinite(x):
        return None
    return float(f"{x:.12g}")


def state_json(s: State) -> dict:
    """One crank position with the keys of the interface (POSITION_KEYS)."""
    values = (math.degrees(s.phi), math.degrees(s.link), s.rho, s.x_c, s.omega_link, s.eps_link, s.v_rel, s.a_cor,
              s.v_c, s.a_c)
    return {k: _f(v) for k, v in zip(POSITION_KEYS, values)}


def _plan_json(plan) -> dict:
    return {
        "points": {name: [_f(x), _f(y)] for name, (x, y) in plan.points.items()},
        "vectors": {name: {"from": a, "to": b, "vector": [_f(c) for c in plan.vector(a, b)], "magnitude": _f(plan.length(a, b))}
                    for a, b, name in plan.segments},
    }


def linkage_document(r: LinkageResult, lang: str) -> dict:
    """Everything `tmm linkage --json` prints and linkage.json holds."""
    g = r.geometry
    return {
        "input": {
            "r1_m": g.r1, "h_m": g.h, "c_m": g.c, "r2_m": g.r2, "r3_m": g.r3, "b_m": g.b,
            "rpm": _f(r.rpm), "omega_rad_s": _f(r.omega), "eps_crank_rad_s2": r.eps,
            "positions": len(r.positions), "at_deg": _f(math.degrees(r.plans.phi)),
        },
        "conventions": CONVENTIONS,
        "regime": r.regime,
        "stroke_m": _f(r.stroke),
        "time_ratio": _f(r.time_ratio),
        "dead_positions_deg": [_f(math.degrees(x)) for x in r.dead],
        "working_stroke_deg": _f(math.degrees(r.working_rad)),
        "return_stroke_deg": _f(math.degrees(r.return_rad)),
        "working_direction": "+x" if r.working_direction > 0 else "-x",
        "x_c_min_m": _f(r.x_min),
        "x_c_max_m": _f(r.x_max),
        "rod_angle_max_deg": _f(math.degrees(r.rod_angle_max)),
        "period_s": _f(r.period),
        "closure_residual_m": r.residual,
        "positions": [state_json(s) for s in r.positions],
        "at": state_json(r.at),
        "plans": {"velocity": _plan_json(r.plans.velocity), "acceleration": _plan_json(r.plans.acceleration)},
        "notes": [note_text(n, lang) for n in r.notes],
    }


def curve_csv(r: LinkageResult) -> str:
    """The dense curve (every 0.5° of crank angle from the start of the working stroke) as CSV."""
    c = r.curve
    buf = io.StringIO()
    buf.write(",".join(("phi_from_start_deg",) + POSITION_KEYS) + "\n")
    cols = (c.phi_from_start, c.phi, c.link, c.rho, c.x_c, c.omega_link, c.eps_link, c.v_rel, c.a_cor, c.v_c, c.a_c)
    for i in range(len(c.phi)):
        row = [float(col[i]) for col in cols]
        row[0], row[1], row[2] = math.degrees(row[0]), math.degrees(row[1]), math.degrees(row[2])
        buf.write(",".join(f"{x:.12g}" for x in row) + "\n")
    return buf.getvalue()
