"""Rich tables of sheet 2 for a mechanism file: the applied forces, the reactions and the balancing
moment of every position (with Zhukovsky's), the force polygons of one position, the reduced
quantities and the flywheel."""

from __future__ import annotations

import math

import numpy as np

from ...i18n.lang import pick
from ...i18n.numbers import num
from ...linkage.sheet2 import Sheet2
from .mechanism import _table

RU_SYMBOLS = {"Fc": "Fпс", "Mc": "Mпс"}


def symbol(sym: str, lang: str) -> str:
    """A force's symbol as the reader's book writes it: 'Fc' → 'Fпс' in Russian (сила полезного
    сопротивления); 'MΦ2' stays."""
    if lang == "ru":
        for en, ru in RU_SYMBOLS.items():
            if sym.startswith(en):
                return ru + sym[len(en):]
    return sym


def _deg(x: float) -> float:
    return math.degrees(x) % 360.0


def forces_table(s: Sheet2, lang: str):
    """|Φ|, M_Φ, G and the load at every position."""
    ld = s.loading
    cols = [("№", "right"), ("φ, °", "right")]
    for f in ld.forces:
        cols.append((f"{symbol(f.symbol, lang)}, " + pick(lang, "N", "Н"), "right"))
    for c in ld.couples:
        cols.append((f"{symbol(c.symbol, lang)}, " + pick(lang, "N·m", "Н·м"), "right"))
    t = _table(pick(lang, "Applied forces: inertia Φ = −m·a_S, moments M_Φ = −J_S·ε, weights G, the resistance "
                          "(magnitudes; moments ccw positive)",
                    "Внешние силы: силы инерции Φ = −m·a_S, моменты M_Φ = −J_S·ε, силы тяжести G, сила полезного "
                    "сопротивления (модули; моменты — против часовой стрелки положительны)"), *cols)
    for p in s.sheet1.cycle.positions:
        i = p.index
        row = [p.label, num(_deg(p.phi), lang, decimals=1)]
        row += [num(abs(complex(f.f[i])), lang, decimals=1) for f in ld.forces]
        row += [num(float(c.m[i]), lang, decimals=2) for c in ld.couples]
        t.add_row(*row, style="bold" if p.index == s.force_position else None)
    return t


def reactions_table(s: Sheet2, lang: str):
    """|R| of every pair, M_b by the force analysis and by Zhukovsky's lever, their difference."""
    ks = s.forces
    cols = [("№", "right")] + [(f"{r.label}, " + pick(lang, "N", "Н"), "right") for r in ks.reactions]
    nm = pick(lang, "N·m", "Н·м")
    cols += [(f"M_b, {nm}" if lang != "ru" else f"M_ур, {nm}", "right"),
             (pick(lang, f"M_b Zhuk., {nm}", f"M_ур Жук., {nm}"), "right"), ("Δ, %", "right")]
    t = _table(pick(lang, "Reactions in the pairs (Rij: link i on link j) and the balancing moment on the crank",
                    "Реакции в кинематических парах (Rij — действие звена i на звено j) и уравновешивающий момент"),
               *cols)
    diff = s.difference_pct()
    for p in s.sheet1.cycle.positions:
        i = p.index
        row = [p.label] + [num(abs(complex(r.force[i])), lang, decimals=1) for r in ks.reactions]
        row += [num(float(s.balancing[i]), lang, decimals=3), num(float(s.lever.balancing[i]), lang, decimals=3),
                num(float(diff[i]), lang, decimals=2)]
        t.add_row(*row, style="bold" if p.index == s.force_position else None)
    t.caption = pick(lang, "M_b: the motor's moment on the crank, counter-clockwise positive; Δ = (M_b − M_b,Zhuk.)/M_b",
                     "M_ур — момент двигателя на кривошипе, против часовой стрелки положителен; "
                     "Δ = (M_ур − M_ур,Жук.)/M_ур")
    t.caption_justify = "left"
    return t


def polygons_table(s: Sheet2, lang: str):
    """The force polygons of one position: each vector, its length at μ_F and its magnitude."""
    p = s.sheet1.cycle.positions[s.force_position]
    t = _table(pick(lang, f"Force polygons, position {p.label} (φ = {num(_deg(p.phi), lang, decimals=2)}°)",
                    f"Планы сил, положение {p.label} (φ = {num(_deg(p.phi), lang, decimals=2)}°)"),
               (pick(lang, "Vector", "Вектор"), "left"), (pick(lang, "Length, mm", "Длина, мм"), "right"),
               (pick(lang, "Magnitude, N", "Модуль, Н"), "right"), (pick(lang, "Found", "Как найден"), "left"))
    how = {"applied": pick(lang, "applied", "задан"), "later": pick(lang, "from the group before", "из расчёта предыдущей группы"),
           "unknown": pick(lang, "from this polygon", "из этого плана")}
    for pg in s.polygons:
        what = pick(lang, "the crank", "кривошип") if pg.group == 0 else pick(lang, f"group {pg.group}", f"группа {pg.group}")
        t.add_row(f"[bold]{what}: μ_F = {num(pg.scale, lang, sig=3)} " + pick(lang, "N/mm", "Н/мм") + "[/]", "", "", "")
        for v in pg.vectors:
            t.add_row(symbol(v.symbol, lang), num(abs(v.value) / pg.scale, lang, decimals=1),
                      num(abs(v.value), lang, decimals=1), how[v.kind])
    return t


def reduced_table(s: Sheet2, lang: str):
    """M_r, J_r, A_r, ΔT at the positions (from the fine grid)."""
    d = s.dynamics
    nm, j = pick(lang, "N·m", "Н·м"), pick(lang, "J", "Дж")
    t = _table(pick(lang, "Reduced to the crank (moments and works in its sense of rotation)",
                    "Приведённые к кривошипу величины (моменты и работы — в направлении его вращения)"),
               ("№", "right"), (f"M_r, {nm}" if lang != "ru" else f"M_пр, {nm}", "right"),
               (pick(lang, "J_r, kg·m²", "J_пр, кг·м²"), "right"), (f"A_r, {j}" if lang != "ru" else f"A_с, {j}", "right"),
               (f"A_d, {j}" if lang != "ru" else f"A_д, {j}", "right"), (f"ΔT, {j}", "right"))
    for p in s.sheet1.cycle.positions:
        i = p.index
        at = lambda y: float(np.interp(p.travel, d.travel, y))  # noqa: E731 (the grid holds every position's travel)
        t.add_row(p.label, num(d.sense * float(s.reduced_moment[i]), lang, decimals=3),
                  num(float(s.reduced_inertia[i]), lang, decimals=5), num(at(d.A_r), lang, decimals=2),
                  num(at(d.A_d), lang, decimals=2), num(at(d.dT), lang, decimals=2))
    return t


def flywheel_table(s: Sheet2, lang: str):
    d, fw = s.dynamics, s.flywheel
    nm, kg = pick(lang, "N·m", "Н·м"), pick(lang, "kg·m²", "кг·м²")
    rad = pick(lang, "rad/s", "рад/с")
    t = _table(pick(lang, "Dynamics and the flywheel", "Динамика машины и маховик"),
               (pick(lang, "Quantity", "Величина"), "left"), (pick(lang, "Value", "Значение"), "right"),
               (pick(lang, "Note", "Примечание"), "left"))
    t.add_row(pick(lang, "Driving moment M_d (constant)", "Движущий момент M_д (постоянный)"),
              f"{num(d.M_d, lang, decimals=3)} {nm}",
              pick(lang, "A_d = −A_r over a turn; ", "A_д = −A_с за цикл; ") +
              (pick(lang, "counter-clockwise", "против часовой стрелки") if d.sense > 0 else
               pick(lang, "clockwise", "по часовой стрелке")))
    t.add_row(pick(lang, "Work of the resistance per turn A_r", "Работа сил сопротивления за цикл A_с"),
              f"{num(d.A_r[-1], lang, decimals=2)} " + pick(lang, "J", "Дж"), "")
    t.add_row(pick(lang, "J of the crank and the rotor (first group)", "J кривошипа и ротора (первая группа)"),
              f"{num(d.J_first, lang, sig=4)} {kg}", "")
    t.add_row(pick(lang, "Reduced J_r over the turn", "Приведённый момент инерции J_пр за цикл"),
              f"{num(d.J_r.min(), lang, sig=4)} … {num(d.J_r.max(), lang, sig=4)} {kg}", "")
    t.add_row(pick(lang, "Change of kinetic energy ΔT", "Изменение кинетической энергии ΔT"),
              f"{num(d.dT.min(), lang, decimals=2)} … {num(d.dT.max(), lang, decimals=2)} " + pick(lang, "J", "Дж"), "")
    t.add_row(pick(lang, "Mean crank speed ω_m", "Средняя угловая скорость кривошипа ω_ср"),
              f"{num(d.omega_mean, lang, sig=5)} {rad}", "")
    if fw is None:
        return t
    me, wi = fw.mertsalov, fw.wittenbauer
    t.add_row(pick(lang, "Allowed δ", "Допускаемый коэффициент δ"), num(fw.delta, lang, sig=4),
              f"ω_max = {num(fw.omega_max, lang, sig=5)}, ω_min = {num(fw.omega_min, lang, sig=5)} {rad}")
    t.add_row(pick(lang, "Mertsalov: ΔT_I swing", "Мерцалов: размах ΔT_I"),
              f"{num(me.dT_I[me.i_max] - me.dT_I[me.i_min], lang, decimals=2)} " + pick(lang, "J", "Дж"),
              pick(lang, "ΔT_I = ΔT − J_II·ω_m²/2", "ΔT_I = ΔT − J_II·ω²_ср/2"))
    t.add_row(pick(lang, "Mertsalov: J_I, first group", "Мерцалов: J_I первой группы"), f"{num(me.J_I, lang, sig=4)} {kg}",
              "J_I = ΔT_I,max−min/(δ·ω_m²)")
    t.add_row(pick(lang, "[bold]Flywheel J_fl (Mertsalov)[/]", "[bold]Момент инерции маховика J_м (Мерцалов)[/]"),
              f"[bold]{num(fw.J, lang, sig=4)} {kg}[/]", pick(lang, "J_I − J_crank − J_rotor", "J_I − J_кр − J_рот"))
    t.add_row(pick(lang, "Flywheel J_fl (Wittenbauer)", "J_м по Виттенбауэру"), f"{num(max(wi.J_fl, 0.0), lang, sig=4)} {kg}",
              pick(lang, "energy–mass diagram", "диаграмма энергомасс"))
    t.add_row(pick(lang, "δ with the flywheel", "δ с маховиком"), num(fw.delta_actual, lang, sig=4), "")
    if fw.size is not None:
        z = fw.size
        mm = pick(lang, "mm", "мм")
        kind = pick(lang, "steel disc", "стальной диск") if z.kind == "disc" else pick(lang, "steel rim", "стальной обод")
        dims = f"D = {num(z.D * 1000, lang, decimals=0)} {mm}, b = {num(z.b * 1000, lang, decimals=0)} {mm}"
        if z.h is not None:
            dims += f", h = {num(z.h * 1000, lang, decimals=0)} {mm}"
        t.add_row(pick(lang, f"Flywheel: {kind}", f"Маховик: {kind}"), dims,
                  f"m = {num(z.m, lang, decimals=1)} " + pick(lang, "kg", "кг"))
    return t


def print_dynamics(console, s: Sheet2, lang: str) -> None:
    for table in (forces_table(s, lang), reactions_table(s, lang), polygons_table(s, lang), reduced_table(s, lang),
                  flywheel_table(s, lang)):
        console.print(table)
