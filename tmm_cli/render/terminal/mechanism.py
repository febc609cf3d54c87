"""Rich tables of sheet 1 for a mechanism file: the structure as the textbook writes it, the main
results, the positions (the output, the links' ω and ε, the points' speeds) and the plans' vectors."""

from __future__ import annotations

import math

import numpy as np

from ...linkage.positions import output_coordinate
from ...linkage.sheet1 import Sheet1
from ...i18n.lang import pick
from ...i18n.numbers import num

PATTERN_RU = str.maketrans({"R": "В", "P": "П"})  # вращательная, поступательная


def _table(title: str, *cols: tuple[str, str], min_width: int | None = None):
    from rich.table import Table

    t = Table(title=title, header_style="bold", title_justify="left", min_width=min_width)
    for name, justify in cols:
        t.add_column(name, justify=justify, overflow="fold")
    return t


def pattern(p: str, lang: str) -> str:
    """'RRP' or 'ВВП'."""
    return p.translate(PATTERN_RU) if lang == "ru" else p


def _deg(x: float) -> float:
    return math.degrees(x) % 360.0


def structure_table(s: Sheet1, lang: str):
    st = s.structure
    t = _table(pick(lang, f"Structure: W = 3n − 2p5 − p4 = 3·{st.n} − 2·{st.p5} − {st.p4} = {st.dof}",
                    f"Структурный анализ: W = 3n − 2p5 − p4 = 3·{st.n} − 2·{st.p5} − {st.p4} = {st.dof}"),
               (pick(lang, "Member", "Звено структуры"), "left"), (pick(lang, "Links", "Звенья"), "left"),
               (pick(lang, "Pairs (links)", "Пары (звенья)"), "left"), (pick(lang, "Class, order, kind", "Класс, порядок, вид"), "left"))
    for g in st.groups:
        pairs = ", ".join(f"{p.joint} {pattern(p.kind, lang)}({p.links[0]}–{p.links[1]})" for p in g.pairs)
        if g.index == 0:
            what = pick(lang, "class I mechanism (frame and crank)", "механизм I класса (стойка и кривошип)")
        else:
            what = pick(lang, f"group of class II, order 2, kind {g.kind} ({pattern(g.pattern, lang)})",
                        f"группа II класса, 2-го порядка, {g.kind}-го вида ({pattern(g.pattern, lang)})")
        links = ", ".join(str(n) for n in g.links)
        t.add_row(g.formula, links, pairs, what)
    t.caption = pick(lang, f"Structural formula: {st.formula}; the mechanism is of class {st.mechanism_class}",
                     f"Формула строения: {st.formula}; механизм {st.mechanism_class}-го класса")
    t.caption_justify = "left"
    return t


def links_table(s: Sheet1, lang: str):
    m = s.mechanism
    kinds = {"crank": pick(lang, "crank", "кривошип"), "bar": pick(lang, "bar", "стержень"),
             "slider": pick(lang, "slider", "ползун"), "block": pick(lang, "block", "камень кулисы"),
             "slotted": pick(lang, "slotted link", "кулиса")}
    t = _table(pick(lang, f"{m.name or 'Mechanism'}: links", f"{m.name or 'Механизм'}: звенья"),
               ("№", "right"), (pick(lang, "Link", "Звено"), "left"), (pick(lang, "Kind", "Вид"), "left"),
               (pick(lang, "Size", "Размер"), "right"))
    t.add_row("0", pick(lang, "frame", "стойка"), ", ".join(m.frame), "")
    size = {m.links[0].name: m.crank.length}
    for g in m.groups:
        for name, length in zip(g.links, g.lengths):
            size[name] = length
    for ln in m.links:
        mm = num(size[ln.name] * 1000, lang, decimals=1) + " " + pick(lang, "mm", "мм") if ln.name in size else ""
        t.add_row(str(ln.number), ln.name, kinds[ln.kind], mm)
    return t


def results_table(s: Sheet1, lang: str):
    m, c = s.mechanism, s.cycle
    mm = pick(lang, "mm", "мм")
    t = _table(pick(lang, "Main results", "Основные результаты"), (pick(lang, "Quantity", "Величина"), "left"),
               (pick(lang, "Value", "Значение"), "right"), (pick(lang, "Note", "Примечание"), "left"))
    rpm = num(m.crank.rpm, lang, sig=5) + " " + pick(lang, "rpm", "об/мин")
    sense = pick(lang, "counter-clockwise", "против часовой стрелки") if m.crank.sense > 0 else \
        pick(lang, "clockwise", "по часовой стрелке")
    t.add_row(pick(lang, "Crank speed n₁, ω₁", "Частота вращения кривошипа n₁, ω₁"),
              f"{rpm}; {num(abs(m.crank.omega), lang, sig=5)} " + pick(lang, "rad/s", "рад/с"), sense)
    out = m.output
    if c.stroke is not None:
        if out.kind == "slider":
            t.add_row(pick(lang, f"Stroke H of the slider {out.link}", f"Ход ползуна {out.link} H"),
                      num(c.stroke * 1000, lang, decimals=2) + " " + mm, "")
        else:
            t.add_row(pick(lang, f"Swing ψ of the rocker {out.link}", f"Размах коромысла {out.link} ψ"),
                      num(math.degrees(c.stroke), lang, decimals=3) + "°", "")
        t.add_row(pick(lang, "Time ratio K", "Коэффициент изменения средней скорости K"),
                  num(c.time_ratio, lang, decimals=5), pick(lang, "K = φ_w/φ_r", "K = φ_р.х/φ_х.х"))
        t.add_row(pick(lang, "Working stroke φ_w", "Рабочий ход φ_р.х"), num(math.degrees(c.working), lang, decimals=3) + "°", "")
        t.add_row(pick(lang, "Return stroke φ_r", "Холостой ход φ_х.х"), num(math.degrees(c.returning), lang, decimals=3) + "°", "")
        ext = [p for p in c.positions if p.extreme]
        t.add_row(pick(lang, "Extreme positions", "Крайние положения"),
                  "; ".join(f"{p.label}: φ = {num(_deg(p.phi), lang, decimals=3)}°" for p in ext),
                  pick(lang, "start / end of the working stroke", "начало / конец рабочего хода"))
    else:
        t.add_row(pick(lang, "Output link", "Выходное звено"), out.link,
                  pick(lang, "turns fully: no extreme positions", "вращается полностью: крайних положений нет"))
    t.add_row(pick(lang, "Position 0", "Положение 0"), f"φ = {num(_deg(c.start), lang, decimals=3)}°", "")
    for p in c.pressure:
        g = m.groups[p.group - 1]
        t.add_row(pick(lang, f"Largest pressure angle, group {p.group} ({g.kind})",
                       f"Наибольший угол давления, группа {p.group} ({pattern(g.kind, lang)})"),
                  num(math.degrees(p.worst), lang, decimals=2) + "°",
                  f"φ = {num(_deg(p.phi), lang, decimals=1)}°" if p.worst > 0 else "")
    return t


def positions_table(s: Sheet1, lang: str):
    m, c = s.mechanism, s.cycle
    k = c.kin
    slider = m.output.kind == "slider"
    turning = [ln for ln in m.links if ln.kind in ("bar", "slotted")]
    s_col = ("s, " + pick(lang, "mm", "мм")) if slider else ("ψ, °")
    v_col = ("v, " + pick(lang, "m/s", "м/с")) if slider else ("ω, " + pick(lang, "rad/s", "рад/с"))
    a_col = ("a, " + pick(lang, "m/s²", "м/с²")) if slider else ("ε, " + pick(lang, "rad/s²", "рад/с²"))
    cols = [("№", "right"), ("φ, °", "right"), (s_col, "right"), (v_col, "right"), (a_col, "right")]
    for ln in turning:
        cols += [(f"ω{ln.number}, " + pick(lang, "rad/s", "рад/с"), "right"),
                 (f"ε{ln.number}, " + pick(lang, "rad/s²", "рад/с²"), "right")]
    t = _table(pick(lang, f"Positions (0: start of the working stroke); output {m.output.link}",
                    f"Положения (0 — начало рабочего хода); выходное звено {m.output.link}"), *cols)
    cv = c.curve
    for p in c.positions:
        i = p.index
        sv = float(np.interp(p.travel, cv.travel, cv.s))
        q, qd, qdd = (float(x[i]) for x in output_coordinate(m, k))
        row = [p.label, num(_deg(p.phi), lang, decimals=2),
               num(sv * 1000, lang, decimals=2) if slider else num(math.degrees(sv), lang, decimals=3),
               num(c.direction * qd, lang, decimals=4), num(c.direction * qdd, lang, decimals=3)]
        for ln in turning:
            row += [num(float(k.omega[ln.name][i]), lang, decimals=4), num(float(k.epsilon[ln.name][i]), lang, decimals=3)]
        t.add_row(*row, style="bold" if p.extreme else None)
    return t


def speeds_table(s: Sheet1, lang: str):
    """|v| and |a| of every moving joint and named point, per position."""
    m, c = s.mechanism, s.cycle
    k = c.kin
    names = [n for n in m.joint_names if n not in m.frame]
    cols = [("№", "right")] + [(f"v_{n}", "right") for n in names] + [(f"a_{n}", "right") for n in names]
    t = _table(pick(lang, "Speeds [m/s] and accelerations [m/s²] of the points",
                    "Скорости [м/с] и ускорения [м/с²] точек"), *cols)
    for p in c.positions:
        i = p.index
        t.add_row(p.label, *[num(abs(complex(k.v[n][i])), lang, decimals=4) for n in names],
                  *[num(abs(complex(k.a[n][i])), lang, decimals=3) for n in names])
    return t


def plans_table(s: Sheet1, lang: str, which: int = 0):
    pl = s.plans[which]
    t = _table(pick(lang, f"Velocity and acceleration plans, position {pl.position.label} "
                          f"(φ = {num(_deg(pl.position.phi), lang, decimals=2)}°)",
                    f"Планы скоростей и ускорений, положение {pl.position.label} "
                    f"(φ = {num(_deg(pl.position.phi), lang, decimals=2)}°)"),
               (pick(lang, "Vector", "Вектор"), "left"), (pick(lang, "On the plan", "На плане"), "left"),
               (pick(lang, "Direction", "Направление"), "left"), (pick(lang, "Length, mm", "Длина, мм"), "right"),
               (pick(lang, "Magnitude", "Модуль"), "right"))
    for plan, unit, su in ((pl.velocity, pick(lang, "m/s", "м/с"), pick(lang, "(m/s)/mm", "(м/с)/мм")),
                           (pl.acceleration, pick(lang, "m/s²", "м/с²"), pick(lang, "(m/s²)/mm", "(м/с²)/мм"))):
        mu = "μ_v" if plan.kind == "velocity" else "μ_a"
        t.add_row(f"[bold]{mu} = {num(plan.scale, lang, sig=3)} {su}[/]", "", "", "", "")
        for v in plan.vectors:
            line = pick(lang, "guide", "направляющей") if v.line == "guide" else v.line
            t.add_row(v.symbol, v.start + v.end, f"{v.relation} {line}".strip(),
                      num(v.magnitude / plan.scale, lang, decimals=1), num(v.magnitude, lang, sig=4) + " " + unit)
    return t


def print_mechanism(console, s: Sheet1, lang: str) -> None:
    tables = [links_table(s, lang), structure_table(s, lang), results_table(s, lang), positions_table(s, lang),
              speeds_table(s, lang)]
    tables += [plans_table(s, lang, j) for j in range(len(s.plans))]
    for table in tables:
        console.print(table)
