"""Rich tables of sheet 2 for a mechanism file: the applied forces, the reactions and the balancing
moment of every position (with Zhukovsky's), the force polygons of one position, the reduced
quantities and the flywheel."""

from __future__ import annotations

import math

import numpy as np

from ...i18n import N_, tr
from ...i18n.numbers import num, small_pct
from ...linkage.sheet2 import Sheet2
from .mechanism import _table


def symbol(sym: str, lang: str) -> str:
    """A force's symbol as the reader's book writes it: 'Fc' (the useful resistance) is 'Fпс' in
    Russian (сила полезного сопротивления), 'Mc' 'Mпс'; 'MΦ2′' keeps its tick; the rest stay."""
    for base in (N_("Fc"), N_("Mc")):
        if sym.startswith(base):
            return tr(lang, base) + sym[len(base):]
    return sym


def _deg(x: float) -> float:
    return math.degrees(x) % 360.0


def forces_table(s: Sheet2, lang: str):
    """|Φ|, M_Φ, G and the load at every position."""
    ld = s.loading
    cols = [("№", "right"), ("φ, °", "right")]
    for f in ld.forces:
        cols.append((f"{symbol(f.symbol, lang)}, " + tr(lang, "N"), "right"))
    for c in ld.couples:
        cols.append((f"{symbol(c.symbol, lang)}, " + tr(lang, "N·m"), "right"))
    t = _table(tr(lang, "Applied forces: inertia Φ = −m·a_S, moments M_Φ = −J_S·ε, weights G, the resistance (magnitudes; moments ccw positive)"), *cols)
    for p in s.positions:  # the cycle's: two turns of them for a four-stroke engine
        i = p.index
        row = [p.label, num(_deg(p.phi), lang, decimals=1)]
        row += [num(abs(complex(f.f[i])), lang, decimals=1) for f in ld.forces]
        row += [num(float(c.m[i]), lang, decimals=2) for c in ld.couples]
        t.add_row(*row, style="bold" if p.index == s.force_position else None)
    return t


def reactions_table(s: Sheet2, lang: str):
    """|R| of every pair, M_b by the force analysis and by Zhukovsky's lever, their difference."""
    ks = s.forces
    cols = [("№", "right")] + [(f"{r.label}, " + tr(lang, "N"), "right") for r in ks.reactions]
    nm = tr(lang, "N·m")
    cols += [(tr(lang, "M_b, {nm}").format(nm=nm), "right"),
             (tr(lang, "M_b Zhuk., {nm}").format(nm=nm), "right"), ("Δ, %", "right")]
    t = _table(tr(lang, "Reactions in the pairs (Rij: link i on link j) and the balancing moment on the crank"),
               *cols)
    diff = s.difference_pct()
    for p in s.positions:  # the cycle's: two turns of them for a four-stroke engine
        i = p.index
        row = [p.label] + [num(abs(complex(r.force[i])), lang, decimals=1) for r in ks.reactions]
        row += [num(float(s.balancing[i]), lang, decimals=3), num(float(s.lever.balancing[i]), lang, decimals=3),
                small_pct(float(diff[i]), lang, minus="-").removeprefix("= ")]
        t.add_row(*row, style="bold" if p.index == s.force_position else None)
    t.caption = (tr(lang, "M_b: the consumer's moment on the crank (an engine: the gas forces drive), counter-clockwise "
                    "positive; Δ = (M_b − M_b,Zhuk.)/M_b") if s.is_engine else
                 tr(lang, "M_b: the motor's moment on the crank, counter-clockwise positive; Δ = (M_b − M_b,Zhuk.)/M_b"))
    t.caption_justify = "left"
    return t


def lever_table(s: Sheet2, lang: str):
    """Zhukovsky's lever of the force position as sheet 2 and the note give it (:meth:`Sheet2.lever_table`):
    each force's F, its arm h about the pole and ±F·h, ΣF·h, F_ур and M_ур."""
    from ...linkage.zhukovsky import DECIMALS as D

    lt = s.lever_table()
    p = s.sheet1.cycle.positions[s.force_position]
    t = _table(tr(lang, "Zhukovsky's lever, position {label} (μ_v = {mu} (m/s)/mm): moments about the pole p").format(
        label=p.label, mu=num(lt.scale, lang, sig=3)),
        (tr(lang, "Force"), "left"), (tr(lang, "Point"), "left"), ("F, " + tr(lang, "N"), "right"),
        ("h, " + tr(lang, "mm"), "right"), ("±F·h, " + tr(lang, "N·mm"), "right"))
    for x in lt.terms:
        t.add_row(symbol(x.symbol, lang), x.point, num(x.force, lang, decimals=D["force"]),
                  num(x.arm, lang, decimals=D["arm"]), num(x.moment, lang, decimals=D["moment"]))
    t.add_row("Σ", "", "", "", num(lt.total, lang, decimals=D["moment"]), style="bold")
    t.caption = tr(lang, "F_b = |ΣF·h|/(pa) = {total}/{pa} = {fb} N; M_b = F_b·l_1 = {mb} N·m; force analysis: {mk} N·m; "
                         "Δ {d} %").format(
        total=num(abs(lt.total), lang, decimals=D["moment"]), pa=num(lt.pa, lang, decimals=D["pa"]),
        fb=num(lt.balancing_force, lang, decimals=D["balancing_force"]), mb=num(lt.balancing, lang, decimals=D["balancing"]),
        mk=num(lt.kinetostatic, lang, decimals=D["balancing"]), d=small_pct(lt.difference_pct, lang, minus="-"))
    t.caption_justify = "left"
    return t


def polygons_table(s: Sheet2, lang: str):
    """The force polygons of one position: each vector, its length at μ_F and its magnitude."""
    p = s.sheet1.cycle.positions[s.force_position]
    t = _table(tr(lang, "Force polygons, position {label} (φ = {v}°)").format(label=p.label, v=num(_deg(p.phi), lang, decimals=2)),
               (tr(lang, "Vector"), "left"), (tr(lang, "Length, mm"), "right"),
               (tr(lang, "Magnitude, N"), "right"), (tr(lang, "Found"), "left"))
    how = {"applied": tr(lang, "applied"), "later": tr(lang, "from the group before"),
           "unknown": tr(lang, "from this polygon")}
    for pg in s.polygons:
        what = tr(lang, "the crank") if pg.group == 0 else tr(lang, "group {group}").format(group=pg.group)
        t.add_row(f"[bold]{what}: μ_F = {num(pg.scale, lang, sig=3)} " + tr(lang, "N/mm") + "[/]", "", "", "")
        for v in pg.vectors:
            t.add_row(symbol(v.symbol, lang), num(abs(v.value) / pg.scale, lang, decimals=1),
                      num(abs(v.value), lang, decimals=1), how[v.kind])
    return t


def reduced_table(s: Sheet2, lang: str):
    """M_r, J_r, A_r, ΔT at the positions (from the fine grid)."""
    d = s.dynamics
    nm, j = tr(lang, "N·m"), tr(lang, "J")
    t = _table(tr(lang, "Reduced to the crank (moments and works in its sense of rotation)"),
               ("№", "right"), (tr(lang, "M_r, {nm}").format(nm=nm), "right"),
               (tr(lang, "J_r, kg·m²"), "right"), (tr(lang, "A_r, {j}").format(j=j), "right"),
               (tr(lang, "A_d, {j}").format(j=j), "right"), (f"ΔT, {j}", "right"))
    for p in s.positions:  # the cycle's: two turns of them for a four-stroke engine
        i = p.index
        at = lambda y: float(np.interp(p.travel, d.travel, y))  # noqa: E731 (the grid holds every position's travel)
        t.add_row(p.label, num(d.sense * float(s.reduced_moment[i]), lang, decimals=3),
                  num(float(s.reduced_inertia[i]), lang, decimals=5), num(at(d.A_r), lang, decimals=2),
                  num(at(d.A_d), lang, decimals=2), num(at(d.dT), lang, decimals=2))
    return t


def flywheel_table(s: Sheet2, lang: str):
    d, fw = s.dynamics, s.flywheel
    nm, kg = tr(lang, "N·m"), tr(lang, "kg·m²")
    rad = tr(lang, "rad/s")
    t = _table(tr(lang, "Dynamics and the flywheel"),
               (tr(lang, "Quantity"), "left"), (tr(lang, "Value"), "right"),
               (tr(lang, "Note"), "left"))
    t.add_row(*((tr(lang, "Consumer's resisting moment M_c (constant)"), f"{num(-d.M_d, lang, decimals=3)} {nm}")
                if s.is_engine else
                (tr(lang, "Driving moment M_d (constant)"), f"{num(d.M_d, lang, decimals=3)} {nm}")),
              (tr(lang, "A_d = −A_r over a turn; ") if s.turns == 1 else
               tr(lang, "A_d = −A_r over the cycle of two turns (720°); ")) +
              (tr(lang, "counter-clockwise") if d.sense > 0 else
               tr(lang, "clockwise")))
    t.add_row(tr(lang, "Work of the resistance per turn A_r") if s.turns == 1 else
              tr(lang, "Work of the resistance per cycle (two turns) A_r"),
              f"{num(d.A_r[-1], lang, decimals=2)} " + tr(lang, "J"), "")
    t.add_row(tr(lang, "J of the crank and the rotor (first group)"),
              f"{num(d.J_first, lang, sig=4)} {kg}", "")
    t.add_row(tr(lang, "Reduced J_r over the turn"),
              f"{num(d.J_r.min(), lang, sig=4)} … {num(d.J_r.max(), lang, sig=4)} {kg}", "")
    t.add_row(tr(lang, "Change of kinetic energy ΔT"),
              f"{num(d.dT.min(), lang, decimals=2)} … {num(d.dT.max(), lang, decimals=2)} " + tr(lang, "J"), "")
    t.add_row(tr(lang, "Mean crank speed ω_m"),
              f"{num(d.omega_mean, lang, sig=5)} {rad}", "")
    if fw is None:
        return t
    me, wi = fw.mertsalov, fw.wittenbauer
    t.add_row(tr(lang, "Allowed δ"), num(fw.delta, lang, sig=4),
              f"ω_max = {num(fw.omega_max, lang, sig=5)}, ω_min = {num(fw.omega_min, lang, sig=5)} {rad}")
    t.add_row(tr(lang, "Mertsalov: ΔT_I swing"),
              f"{num(me.dT_I[me.i_max] - me.dT_I[me.i_min], lang, decimals=2)} " + tr(lang, "J"),
              tr(lang, "ΔT_I = ΔT − J_II·ω_m²/2"))
    t.add_row(tr(lang, "Mertsalov: J_I, first group"), f"{num(me.J_I, lang, sig=4)} {kg}",
              "J_I = ΔT_I,max−min/(δ·ω_m²)")
    t.add_row(tr(lang, "[bold]Flywheel J_fl (Mertsalov)[/]"),
              f"[bold]{num(fw.J, lang, sig=4)} {kg}[/]", tr(lang, "J_I − J_crank − J_rotor"))
    t.add_row(tr(lang, "Flywheel J_fl (Wittenbauer)"), f"{num(max(wi.J_fl, 0.0), lang, sig=4)} {kg}",
              tr(lang, "energy–mass diagram"))
    t.add_row(tr(lang, "δ with the flywheel"), num(fw.delta_actual, lang, sig=4), "")
    if fw.size is not None:
        z = fw.size
        mm = tr(lang, "mm")
        kind = tr(lang, "steel disc") if z.kind == "disc" else tr(lang, "steel rim")
        dims = f"D = {num(z.D * 1000, lang, decimals=0)} {mm}, b = {num(z.b * 1000, lang, decimals=0)} {mm}"
        if z.h is not None:
            dims += f", h = {num(z.h * 1000, lang, decimals=0)} {mm}"
        t.add_row(tr(lang, "Flywheel: {kind}").format(kind=kind), dims,
                  f"m = {num(z.m, lang, decimals=1)} " + tr(lang, "kg"))
    return t


def print_dynamics(console, s: Sheet2, lang: str) -> None:
    for table in (forces_table(s, lang), reactions_table(s, lang), lever_table(s, lang), polygons_table(s, lang),
                  reduced_table(s, lang),
                  flywheel_table(s, lang)):
        console.print(table)
