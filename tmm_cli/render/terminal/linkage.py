"""Rich tables of sheet 1 (the slotted-link mechanism): input, main results, positions, plans."""

from __future__ import annotations

import math

from ...i18n import tr
from ...i18n.numbers import num
from ...linkage.analysis import LinkageResult, State


def _table(title: str, *cols: tuple[str, str], min_width: int | None = None):
    from rich.table import Table

    t = Table(title=title, header_style="bold", title_justify="left", min_width=min_width)
    for name, justify in cols:
        t.add_column(name, justify=justify, overflow="fold")
    return t


def _mm(x: float, lang: str) -> str:
    return num(x * 1000.0, lang, decimals=2)


def _input_table(r: LinkageResult, lang: str):
    g = r.geometry
    mm = tr(lang, "mm")
    t = _table(tr(lang, "Slotted-link mechanism: input (Goban, Monková, Šmeringaiová, 2010, Fig. 1)"),
               (tr(lang, "Quantity"), "left"), (tr(lang, "Value"), "right"),
               (tr(lang, "Meaning"), "left"))
    rows = [
        ("r1 = O21A", _mm(g.r1, lang) + " " + mm, tr(lang, "crank")),
        ("h", _mm(g.h, lang) + " " + mm, tr(lang, "O41 below O21")),
        ("c", _mm(g.c, lang) + " " + mm, tr(lang, "O41 left of O21")),
        ("r2 = O41B", _mm(g.r2, lang) + " " + mm, tr(lang, "slotted link to B")),
        ("r3 = BC", _mm(g.r3, lang) + " " + mm, tr(lang, "rod")),
        ("b", _mm(g.b, lang) + " " + mm, tr(lang, "ram guide y = b")),
        ("n21", num(r.rpm, lang, sig=5) + " " + tr(lang, "rpm"), tr(lang, "crank speed")),
        ("ω21", num(r.omega, lang, sig=5) + " " + tr(lang, "rad/s"), "ω21 = π·n21/30"),
    ]
    if r.eps:
        rows.append(("ε21", num(r.eps, lang, sig=5) + " " + tr(lang, "rad/s²"), tr(lang, "crank")))
    for row in rows:
        t.add_row(*row)
    return t


def _main_table(r: LinkageResult, lang: str):
    mm = tr(lang, "mm")
    t = _table(tr(lang, "Main results"),
               (tr(lang, "Quantity"), "left"), (tr(lang, "Value"), "right"),
               (tr(lang, "Note"), "left"))
    regime = tr(lang, "Whitworth (link turns fully)") if r.regime == "whitworth" \
        else tr(lang, "crank-shaper (link swings)")
    direction = tr(lang, "ram moves right (+x)") if r.working_direction > 0 \
        else tr(lang, "ram moves left (−x)")
    t.add_row(tr(lang, "Mechanism"), regime, "√(c² + h²) " + ("<" if r.regime == "whitworth" else ">") + " r1")
    t.add_row(tr(lang, "Stroke H"), _mm(r.stroke, lang) + " " + mm,
              f"x_C: {_mm(r.x_min, lang)} … {_mm(r.x_max, lang)} {mm}")
    t.add_row(tr(lang, "Time ratio K"), num(r.time_ratio, lang, decimals=6), tr(lang, "K = φ_w/φ_r"))
    t.add_row(tr(lang, "Working stroke φ_w"), num(math.degrees(r.working_rad), lang, decimals=3) + "°", direction)
    t.add_row(tr(lang, "Return stroke φ_r"), num(math.degrees(r.return_rad), lang, decimals=3) + "°", "")
    t.add_row(tr(lang, "Dead positions φ21"),
              "; ".join(num(math.degrees(x), lang, decimals=3) + "°" for x in r.dead),
              tr(lang, "start of working / return stroke"))
    t.add_row(tr(lang, "Largest rod angle to the guide"),
              num(math.degrees(r.rod_angle_max), lang, decimals=2) + "°", "")
    t.add_row(tr(lang, "Loop closure error"), num(r.residual, lang, sig=2) + " " + tr(lang, "m"), "")
    return t


def _row(label: str, s: State, lang: str) -> list[str]:
    return [label, num(math.degrees(s.phi), lang, decimals=2), num(math.degrees(s.link), lang, decimals=2), _mm(s.rho, lang),
            _mm(s.x_c, lang), num(s.omega_link, lang, decimals=4), num(s.eps_link, lang, decimals=3),
            num(s.v_rel, lang, decimals=4), num(s.a_cor, lang, decimals=4), num(s.v_c, lang, decimals=4),
            num(s.a_c, lang, decimals=4)]


def _positions_table(r: LinkageResult, lang: str):
    cols = [("№", "right"), ("φ21, °", "right"), ("φ41, °", "right"), ("ρ, " + tr(lang, "mm"), "right"),
            ("x_C, " + tr(lang, "mm"), "right"), ("ω4, " + tr(lang, "rad/s"), "right"),
            ("ε4, " + tr(lang, "rad/s²"), "right"), ("v_rel, " + tr(lang, "m/s"), "right"),
            ("a_k, " + tr(lang, "m/s²"), "right"), ("v_C, " + tr(lang, "m/s"), "right"),
            ("a_C, " + tr(lang, "m/s²"), "right")]
    t = _table(tr(lang, "Crank positions (0 = start of the working stroke)"), *cols)
    for k, s in enumerate(r.positions):
        t.add_row(*_row(str(k), s, lang))
    t.add_row(*_row(tr(lang, "at"), r.at, lang), style="bold")
    return t


def _plans_table(r: LinkageResult, lang: str):
    t = _table(tr(lang, "Velocity and acceleration plans at φ21 = {phi}°").format(phi=num(math.degrees(r.at.phi), lang, decimals=2)),
               (tr(lang, "Vector"), "left"), (tr(lang, "On the plan"), "left"),
               (tr(lang, "Magnitude"), "right"), min_width=64)
    for plan, unit in ((r.plans.velocity, tr(lang, "m/s")), (r.plans.acceleration, tr(lang, "m/s²"))):
        for a, b, name in plan.segments:
            t.add_row(name, a + b, num(plan.length(a, b), lang, decimals=4) + " " + unit)
    return t


def print_linkage(console, r: LinkageResult, lang: str) -> None:
    for table in (_input_table(r, lang), _main_table(r, lang), _positions_table(r, lang), _plans_table(r, lang)):
        console.print(table)
