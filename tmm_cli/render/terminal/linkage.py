"""Rich tables of sheet 1 (the slotted-link mechanism): input, main results, positions, plans."""

from __future__ import annotations

import math

from ...i18n.lang import pick
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
    mm = pick(lang, "mm", "мм")
    t = _table(pick(lang, "Slotted-link mechanism: input (Goban, Monková, Šmeringaiová, 2010, Fig. 1)", "Кулисный механизм: исходные данные (Goban, Monková, Šmeringaiová, 2010, рис. 1)"),
               (pick(lang, "Quantity", "Величина"), "left"), (pick(lang, "Value", "Значение"), "right"),
               (pick(lang, "Meaning", "Смысл"), "left"))
    rows = [
        ("r1 = O21A", _mm(g.r1, lang) + " " + mm, pick(lang, "crank", "кривошип")),
        ("h", _mm(g.h, lang) + " " + mm, pick(lang, "O41 below O21", "O41 ниже O21")),
        ("c", _mm(g.c, lang) + " " + mm, pick(lang, "O41 left of O21", "O41 левее O21")),
        ("r2 = O41B", _mm(g.r2, lang) + " " + mm, pick(lang, "slotted link to B", "кулиса до точки B")),
        ("r3 = BC", _mm(g.r3, lang) + " " + mm, pick(lang, "rod", "шатун")),
        ("b", _mm(g.b, lang) + " " + mm, pick(lang, "ram guide y = b", "направляющая ползуна y = b")),
        ("n21", num(r.rpm, lang, sig=5) + " " + pick(lang, "rpm", "об/мин"), pick(lang, "crank speed", "частота вращения кривошипа")),
        ("ω21", num(r.omega, lang, sig=5) + " " + pick(lang, "rad/s", "рад/с"), "ω21 = π·n21/30"),
    ]
    if r.eps:
        rows.append(("ε21", num(r.eps, lang, sig=5) + " " + pick(lang, "rad/s²", "рад/с²"), pick(lang, "crank", "кривошип")))
    for row in rows:
        t.add_row(*row)
    return t


def _main_table(r: LinkageResult, lang: str):
    mm = pick(lang, "mm", "мм")
    t = _table(pick(lang, "Main results", "Основные результаты"),
               (pick(lang, "Quantity", "Величина"), "left"), (pick(lang, "Value", "Значение"), "right"),
               (pick(lang, "Note", "Примечание"), "left"))
    regime = pick(lang, "Whitworth (link turns fully)", "Витворта (кулиса вращается)") if r.regime == "whitworth" \
        else pick(lang, "crank-shaper (link swings)", "с качающейся кулисой")
    direction = pick(lang, "ram moves right (+x)", "ползун движется вправо (+x)") if r.working_direction > 0 \
        else pick(lang, "ram moves left (−x)", "ползун движется влево (−x)")
    t.add_row(pick(lang, "Mechanism", "Механизм"), regime, "√(c² + h²) " + ("<" if r.regime == "whitworth" else ">") + " r1")
    t.add_row(pick(lang, "Stroke H", "Ход ползуна H"), _mm(r.stroke, lang) + " " + mm,
              f"x_C: {_mm(r.x_min, lang)} … {_mm(r.x_max, lang)} {mm}")
    t.add_row(pick(lang, "Time ratio K", "Коэффициент изменения средней скорости K"), num(r.time_ratio, lang, decimals=6), pick(lang, "K = φ_w/φ_r", "K = φ_р.х/φ_х.х"))
    t.add_row(pick(lang, "Working stroke φ_w", "Рабочий ход φ_р.х"), num(math.degrees(r.working_rad), lang, decimals=3) + "°", direction)
    t.add_row(pick(lang, "Return stroke φ_r", "Холостой ход φ_х.х"), num(math.degrees(r.return_rad), lang, decimals=3) + "°", "")
    t.add_row(pick(lang, "Dead positions φ21", "Крайние положения φ21"),
              "; ".join(num(math.degrees(x), lang, decimals=3) + "°" for x in r.dead),
              pick(lang, "start of working / return stroke", "начало рабочего / холостого хода"))
    t.add_row(pick(lang, "Largest rod angle to the guide", "Наибольший угол шатуна к направляющей"),
              num(math.degrees(r.rod_angle_max), lang, decimals=2) + "°", "")
    t.add_row(pick(lang, "Loop closure error", "Невязка замыкания контуров"), num(r.residual, lang, sig=2) + " " + pick(lang, "m", "м"), "")
    return t


def _row(label: str, s: State, lang: str) -> list[str]:
    return [label, num(math.degrees(s.phi), lang, decimals=2), num(math.degrees(s.link), lang, decimals=2), _mm(s.rho, lang),
            _mm(s.x_c, lang), num(s.omega_link, lang, decimals=4), num(s.eps_link, lang, decimals=3),
            num(s.v_rel, lang, decimals=4), num(s.a_cor, lang, decimals=4), num(s.v_c, lang, decimals=4),
            num(s.a_c, lang, decimals=4)]


def _positions_table(r: LinkageResult, lang: str):
    cols = [("№", "right"), ("φ21, °", "right"), ("φ41, °", "right"), ("ρ, " + pick(lang, "mm", "мм"), "right"),
            ("x_C, " + pick(lang, "mm", "мм"), "right"), ("ω4, " + pick(lang, "rad/s", "рад/с"), "right"),
            ("ε4, " + pick(lang, "rad/s²", "рад/с²"), "right"), ("v_rel, " + pick(lang, "m/s", "м/с"), "right"),
            ("a_k, " + pick(lang, "m/s²", "м/с²"), "right"), ("v_C, " + pick(lang, "m/s", "м/с"), "right"),
            ("a_C, " + pick(lang, "m/s²", "м/с²"), "right")]
    t = _table(pick(lang, "Crank positions (0 = start of the working stroke)", "Положения кривошипа (0 — начало рабочего хода)"), *cols)
    for k, s in enumerate(r.positions):
        t.add_row(*_row(str(k), s, lang))
    t.add_row(*_row(pick(lang, "at", "расч."), r.at, lang), style="bold")
    return t


def _plans_table(r: LinkageResult, lang: str):
    t = _table(pick(lang, f"Velocity and acceleration plans at φ21 = {num(math.degrees(r.at.phi), lang, decimals=2)}°",
                    f"Планы скоростей и ускорений при φ21 = {num(math.degrees(r.at.phi), lang, decimals=2)}°"),
               (pick(lang, "Vector", "Вектор"), "left"), (pick(lang, "On the plan", "На плане"), "left"),
               (pick(lang, "Magnitude", "Модуль"), "right"), min_width=64)
    for plan, unit in ((r.plans.velocity, pick(lang, "m/s", "м/с")), (r.plans.acceleration, pick(lang, "m/s²", "м/с²"))):
        for a, b, name in plan.segments:
            t.add_row(name, a + b, num(plan.length(a, b), lang, decimals=4) + " " + unit)
    return t


def print_linkage(console, r: LinkageResult, lang: str) -> None:
    for table in (_input_table(r, lang), _main_table(r, lang), _positions_table(r, lang), _plans_table(r, lang)):
        console.print(table)
