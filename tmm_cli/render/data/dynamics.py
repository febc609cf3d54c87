"""Sheet 2 of a mechanism file as plain JSON data (added to sheet 1's document) and its dense
curve as CSV (SI units).

Signs: moments and angles counter-clockwise positive; the balancing moment is the one the motor
applies to the crank; a reaction ``Rij`` is the force of link i on link j (0 the frame), i the
earlier of the pair's links. Per position (issue 25): ``balancing_moment_Nm``,
``zhukovsky_moment_Nm``, ``reactions`` {Rij: [Rx, Ry]}, ``reduced`` {inertia_kgm2, moment_Nm};
beside them the applied forces and the reactions' parts. Top level: ``dynamics`` (the driving
moment, the flywheel by Mertsalov and by Wittenbauer, the speeds, δ) and ``forces`` (the position
of the polygons, their scales and vectors).
"""

from __future__ import annotations

import io
import math

import numpy as np

from ...linkage.sheet2 import Sheet2

CONVENTIONS = ("moments counter-clockwise positive [N*m]; forces [N] as [Fx, Fy]; Rij = the force of link i on link "
               "j (0 the frame); balancing_moment_Nm: the motor's moment on the crank; reduced moment and inertia "
               "to the crank (M_r = sum(F*v + M*omega)/omega1 of the load and the weights)")


def _f(x) -> float | None:
    x = float(x)
    if not math.isfinite(x):
        return None
    return float(f"{x:.12g}")


def _xy(z) -> list:
    z = complex(z)
    return [_f(z.real), _f(z.imag)]


def _position_entry(s: Sheet2, i: int) -> dict:
    ks = s.forces
    reactions = {r.label: _xy(r.force[i]) for r in ks.reactions}
    parts = {}
    for r in ks.reactions:
        part = {"joint": r.pair.joint, "pair": r.pair.kind, "links": list(r.pair.links)}
        if r.normal is not None:
            part["normal"] = _xy(r.normal[i])
            part["tangential"] = _xy(r.tangential[i])
        if r.couple is not None:
            part["couple_Nm"] = _f(r.couple[i])
        parts[r.label] = part
    forces = {f.symbol: {"at": f.point, "force": _xy(f.f[i])} for f in s.loading.forces}
    moments = {c.symbol: _f(c.m[i]) for c in s.loading.couples}
    return {
        "balancing_moment_Nm": _f(s.balancing[i]),
        "zhukovsky_moment_Nm": _f(s.lever.balancing[i]),
        "power_balance_moment_Nm": _f(s.power_balance[i]),
        "zhukovsky_difference_pct": _f(s.difference_pct()[i]),
        "reactions": reactions,
        "reaction_parts": parts,
        "applied_forces": forces,
        "applied_moments_Nm": moments,
        "reduced": {"inertia_kgm2": _f(s.reduced_inertia[i]), "moment_Nm": _f(s.reduced_moment[i])},
    }


def _polygons(s: Sheet2) -> list:
    return [{"group": pg.group, "scale_N_per_mm": _f(pg.scale),
             "vectors": [{"symbol": v.symbol, "force": _xy(v.value), "magnitude": _f(abs(v.value)),
                          "length_mm": _f(abs(v.value) / pg.scale), "kind": v.kind} for v in pg.vectors]}
            for pg in s.polygons]


def dynamics_json(s: Sheet2) -> dict:
    """The top-level ``dynamics`` entry."""
    d, fw = s.dynamics, s.flywheel
    out = {
        "drive_moment_Nm": _f(d.drive_moment_ccw),
        "motor_moment_Nm": _f(abs(d.M_d)),
        "sense": "ccw" if d.sense > 0 else "cw",
        "resistance_work_J": _f(d.A_r[-1]),
        "crank_rotor_inertia_kgm2": _f(d.J_first),
        "rotor_inertia_kgm2": _f(d.J_rotor),
        "reduced_inertia_min_kgm2": _f(d.J_r.min()),
        "reduced_inertia_max_kgm2": _f(d.J_r.max()),
        "energy_change_min_J": _f(d.dT.min()),
        "energy_change_max_J": _f(d.dT.max()),
        "omega_mean": _f(d.omega_mean),
        "grid_step_deg": _f(math.degrees(d.travel[1] - d.travel[0])),
        "delta": None, "omega_max": None, "omega_min": None,
        "flywheel_inertia_kgm2": None, "flywheel_inertia_wittenbauer_kgm2": None,
    }
    if fw is not None:
        out.update({
            "delta": _f(fw.delta), "omega_max": _f(fw.omega_max), "omega_min": _f(fw.omega_min),
            "flywheel_inertia_kgm2": _f(fw.J),
            "flywheel_inertia_wittenbauer_kgm2": _f(max(fw.wittenbauer.J_fl, 0.0)),
            "mertsalov": {"first_group_inertia_kgm2": _f(fw.mertsalov.J_I), "flywheel_kgm2": _f(fw.mertsalov.J_fl),
                          "energy_swing_J": _f(fw.mertsalov.dT_I[fw.mertsalov.i_max] - fw.mertsalov.dT_I[fw.mertsalov.i_min]),
                          "at_max_deg": _f(math.degrees(d.travel[fw.mertsalov.i_max])),
                          "at_min_deg": _f(math.degrees(d.travel[fw.mertsalov.i_min]))},
            "wittenbauer": {"flywheel_kgm2": _f(fw.wittenbauer.J_fl), "tan_psi_max": _f(fw.wittenbauer.slope_max),
                            "tan_psi_min": _f(fw.wittenbauer.slope_min), "c_max_J": _f(fw.wittenbauer.c_max),
                            "c_min_J": _f(fw.wittenbauer.c_min),
                            "touch_max_deg": _f(math.degrees(d.travel[fw.wittenbauer.i_max])),
                            "touch_min_deg": _f(math.degrees(d.travel[fw.wittenbauer.i_min]))},
            "delta_actual": _f(fw.delta_actual),
            "flywheel": None if fw.size is None else {
                "kind": fw.size.kind, "diameter_m": _f(fw.size.D), "width_m": _f(fw.size.b),
                "thickness_m": _f(fw.size.h) if fw.size.h is not None else None, "mass_kg": _f(fw.size.m)},
        })
    return out


def _more_turns(doc: dict, s: Sheet2) -> None:
    """A cycle of several turns (issue 34): the positions list every turn's in the order the crank
    turns — each turn's kinematics the first's, `label` numbered on, `phi_deg` running on past 360°
    as the crank has turned (a turn's crank angle + 360° a turn: 0 … 720), `travel_deg` the travel
    from position 0 and `turn` (1, 2); the top level says the cycle's `turns`."""
    import copy

    first = doc["positions"]
    out = []
    for p in s.positions:
        turn = int(p.index // len(first))
        entry = copy.deepcopy(first[p.index % len(first)])
        entry.update({"index": p.index, "label": p.label, "turn": turn + 1,
                      "phi_deg": _f(entry["phi_deg"] + 360.0 * turn), "travel_deg": _f(math.degrees(p.travel))})
        out.append(entry)
    doc["positions"] = out
    doc["cycle"] = {"turns": s.turns, "cycle_deg": 360 * s.turns, "positions_per_turn": len(first)}


def add_sheet2(doc: dict, s: Sheet2) -> dict:
    """Sheet 1's document with sheet 2's keys added (the same dict, returned)."""
    if s.turns > 1:  # a four-stroke engine: the positions of every turn of its cycle, numbered on
        _more_turns(doc, s)
    for entry, p in zip(doc["positions"], s.positions):
        entry.update(_position_entry(s, p.index))
    doc["dynamics"] = dynamics_json(s)
    doc["forces"] = {"conventions": CONVENTIONS, "gravity": s.input.gravity,
                     "position": s.positions[s.force_position].label, "polygons": _polygons(s),
                     "masses": [{"link": m.link, "number": m.number, "m_kg": m.m, "J_kgm2": m.J, "centre": m.label}
                                for m in s.input.masses],
                     "load": None if s.input.load is None else {"link": s.input.load.link, "kind": s.input.load.kind,
                                                                 "stroke": list(s.input.load.stroke),
                                                                 "values": list(s.input.load.values)}}
    if s.input.load is not None and s.input.load.direction is not None:  # a force of its own direction
        doc["forces"]["load"]["direction_deg"] = math.degrees(s.input.load.direction)
    if s.turns > 1:  # the force analysis' position lies in the cycle's first turn
        doc["forces"]["turn"] = 1
    tables = s.input.tables
    if tables != ((s.input.load,) if s.input.load is not None else ()):  # several table loads, each on its own link
        doc["forces"]["loads"] = [_table_load(s, ld, st) for ld, st in zip(tables, s.strokes)]
    if s.input.gas:  # the gas loads: each piston's indicator diagram and dead centres
        from ...linkage.gas import piston

        m = s.sheet1.mechanism
        doc["forces"]["gas"] = [
            {"link": g.link, "symbol": f"P{m.link(g.link).number}", "head": [g.head.real, g.head.imag],
             "area_m2": g.area, "travel": list(g.travel), "pressure_MPa": [list(r) for r in g.pressure],
             "stroke_m": piston(g, m).stroke, "near_dead_centre_deg": math.degrees(piston(g, m).near) % 360.0,
             "far_dead_centre_deg": math.degrees(piston(g, m).far) % 360.0} for g in s.input.gas]
        for entry, g in zip(doc["forces"]["gas"], s.input.gas):
            if g.turns > 1:  # a four-stroke: where its expansion (the first row) begins, as turned from position 0
                entry["turns"] = g.turns
                entry["strokes"] = ["expansion", "exhaust", "intake", "compression"]
                entry["cycle_start_travel_deg"] = _f(math.degrees(m.crank.sense * (g.origin - s.sheet1.cycle.start)))
    return doc


def _table_load(s: Sheet2, ld, st) -> dict:
    """One of several table loads: its diagram and its own link's working stroke (where it starts, how
    long it lasts, the stroke or the swing)."""
    number = s.sheet1.mechanism.link(ld.link).number
    out = {"link": ld.link, "number": number, "kind": ld.kind, "symbol": ("Fc" if ld.kind == "force" else "Mc") +
           (str(number) if len(s.input.tables) > 1 else ""), "stroke": list(ld.stroke), "values": list(ld.values),
           "working": ld.working}
    if ld.direction is not None:
        out["direction_deg"] = math.degrees(ld.direction)
    if st is not None:
        out.update({"working_start_deg": math.degrees(st.origin) % 360.0, "working_stroke_deg": math.degrees(st.working),
                    "stroke_m": st.length if st.kind == "slider" else None,
                    "swing_deg": math.degrees(st.length) if st.kind == "rocker" else None,
                    "direction": st.direction})
    return out


def dynamics_csv(s: Sheet2) -> str:
    """The dynamics over the cycle (every 0.5° from position 0; a four-stroke engine's 720°): M_r, the works, ΔT, J_r, J_II,
    Mertsalov's ΔT_I and the speed with the flywheel (moments and works in the sense of rotation)."""
    d, fw = s.dynamics, s.flywheel
    k = s.curve_kin()  # a four-stroke engine's: both turns
    head = ["travel_deg", "phi_deg", "M_r_Nm", "A_r_J", "A_d_J", "dT_J", "J_r_kgm2", "J_II_kgm2"]
    cols = [np.degrees(d.travel), np.degrees(np.remainder(k.phi, 2 * np.pi)), d.M_r, d.A_r, d.A_d, d.dT, d.J_r, d.J_II]
    if fw is not None:
        head += ["dT_I_J", "omega_rad_s"]
        cols += [fw.mertsalov.dT_I, fw.omega]
    buf = io.StringIO()
    buf.write(",".join(head) + "\n")
    for row in np.column_stack(cols):
        buf.write(",".join(f"{x:.12g}" for x in row) + "\n")
    return buf.getvalue()
