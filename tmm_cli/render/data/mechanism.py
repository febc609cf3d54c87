"""Sheet 1 of a mechanism file as plain JSON data and its dense curve as CSV (SI units).

Frame: x right, y up [m]; angles from +x, counter-clockwise [deg]; ω, ε counter-clockwise
positive. The keys of issue 24: ``positions`` (each ``index``, ``label``, ``phi_deg``, ``points``
— every joint and named point ``{x, y, vx, vy, ax, ay}`` — and ``links`` — every moving link
``{angle_deg, omega, epsilon}``), ``stroke_m``, ``time_ratio``, ``structure``; the rest beside
them. Sheet 2 adds its keys to the same entries.
"""

from __future__ import annotations

import io
import math

import numpy as np

from ...linkage.sheet1 import Sheet1
from ...linkage.vector_plans import Plan
from ...i18n.lang import note_text

CONVENTIONS = ("x right, y up [m]; angles from +x counter-clockwise [deg]; omega, epsilon counter-clockwise positive "
               "[rad/s, rad/s^2]; a link XY's angle is the direction X -> Y; SI units")


def _f(x) -> float | None:
    x = float(x)
    if not math.isfinite(x):
        return None
    return float(f"{x:.12g}")


def _deg(x: float) -> float:
    """An angle in degrees in [0, 360)."""
    d = math.degrees(float(x)) % 360.0
    return 0.0 if d >= 360.0 - 5e-13 else d


def positions_json(s: Sheet1) -> list[dict]:
    """The `positions` list: one entry per position, in the order of crank travel."""
    k = s.cycle.kin
    names = s.mechanism.joint_names
    out = []
    for p in s.cycle.positions:
        i = p.index
        points = {n: {"x": _f(k.z[n][i].real), "y": _f(k.z[n][i].imag), "vx": _f(k.v[n][i].real),
                      "vy": _f(k.v[n][i].imag), "ax": _f(k.a[n][i].real), "ay": _f(k.a[n][i].imag)} for n in names}
        links = {ln.name: {"angle_deg": _f(_deg(k.angle[ln.name][i])), "omega": _f(k.omega[ln.name][i]),
                           "epsilon": _f(k.epsilon[ln.name][i])} for ln in s.mechanism.links}
        out.append({"index": i, "label": p.label, "phi_deg": _f(_deg(p.phi)), "points": points, "links": links})
    return out


def structure_json(s: Sheet1) -> dict:
    st = s.structure
    groups = []
    for g in st.groups:
        entry = {"index": g.index, "class": g.klass, "order": g.order, "kind": g.kind, "pattern": g.pattern,
                 "links": list(g.links), "formula": g.formula,
                 "pairs": [{"joint": p.joint, "kind": p.kind, "links": list(p.links)} for p in g.pairs]}
        groups.append(entry)
    return {"moving_links": st.n, "p5": st.p5, "p4": st.p4, "dof": st.dof, "class": st.mechanism_class,
            "formula": st.formula, "groups": groups}


def _plan_json(plan: Plan) -> dict:
    return {
        "scale": _f(plan.scale),
        "pole": plan.pole,
        "at_pole": list(plan.at_pole),
        "points": {n: [_f(z.real), _f(z.imag)] for n, z in plan.points.items()},
        "vectors": [{"from": v.start, "to": v.end, "symbol": v.symbol, "vector": [_f(v.value.real), _f(v.value.imag)],
                     "magnitude": _f(v.magnitude), "length_mm": _f(v.magnitude / plan.scale),
                     "direction": f"{v.relation} {v.line}".strip()} for v in plan.vectors],
    }


def mechanism_document(s: Sheet1, lang: str) -> dict:
    """Everything `tmm linkage MECH.toml --json` prints and linkage.json holds."""
    m, c = s.mechanism, s.cycle
    slider = m.output.kind == "slider"
    return {
        "name": m.name,
        "conventions": CONVENTIONS,
        "crank": {"pivot": m.crank.pivot, "joint": m.crank.joint, "length_m": m.crank.length, "rpm": _f(m.crank.rpm),
                  "omega_rad_s": _f(m.crank.omega), "sense": "ccw" if m.crank.sense > 0 else "cw"},
        "structure": structure_json(s),
        "output": {"kind": m.output.kind, "link": m.output.link, "joint": m.output.joint},
        "stroke_m": _f(c.stroke) if slider and c.stroke is not None else None,
        "swing_deg": _f(math.degrees(c.stroke)) if not slider and c.stroke is not None else None,
        "time_ratio": _f(c.time_ratio) if c.time_ratio is not None else None,
        "working_stroke_deg": _f(math.degrees(c.working)) if c.working is not None else None,
        "return_stroke_deg": _f(math.degrees(c.returning)) if c.returning is not None else None,
        "position_0": {"phi_deg": _f(_deg(c.start)), "rule": c.start_rule},
        "extreme_positions": [p.label for p in (c.working_start(), c.working_end()) if p is not None],  # start, end
        "pressure_angles": [{"group": p.group, "max_deg": _f(math.degrees(p.worst)), "at_phi_deg": _f(_deg(p.phi))}
                            for p in c.pressure],
        "positions": positions_json(s),
        "plans": [{"position": pl.position.label, "velocity": _plan_json(pl.velocity),
                   "acceleration": _plan_json(pl.acceleration)} for pl in s.plans],
        "diagram_scales": {"phi_rad_per_mm": _f(s.scales.phi), "s": _f(s.scales.s), "v": _f(s.scales.v),
                           "a": _f(s.scales.a)},
        "notes": [note_text(n, lang) for n in c.notes],
    }


def curve_csv(s: Sheet1) -> str:
    """The dense curve (every 0.5° of crank turn from position 0): the output's s, v, a, every
    point's x, y and every link's angle, ω, ε."""
    c = s.cycle.curve
    k = c.kin
    names = s.mechanism.joint_names
    links = [ln.name for ln in s.mechanism.links]
    head = ["travel_deg", "phi_deg", "s", "v", "a"]
    cols = [np.degrees(c.travel), np.degrees(np.remainder(k.phi, 2 * np.pi)), c.s, c.v, c.a]
    for n in names:
        head += [f"{n}_x_m", f"{n}_y_m"]
        cols += [k.z[n].real, k.z[n].imag]
    for n in links:
        head += [f"{n}_angle_deg", f"{n}_omega", f"{n}_epsilon"]
        cols += [np.degrees(k.angle[n]), k.omega[n], k.epsilon[n]]
    buf = io.StringIO()
    buf.write(",".join(head) + "\n")
    table = np.column_stack(cols)
    for row in table:
        buf.write(",".join(f"{x:.12g}" for x in row) + "\n")
    return buf.getvalue()
