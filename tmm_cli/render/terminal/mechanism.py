"""Rich tables of sheet 1 for a mechanism file: the structure as the textbook writes it, the main
results, the positions (the output, the links' ω and ε, the points' speeds) and the plans' vectors."""

from __future__ import annotations

import math

import numpy as np

from . import escape
from ...linkage.positions import output_coordinate
from ...linkage.sheet1 import Sheet1
from ...linkage.vector_plans import book_symbol
from ...i18n import N_, tr
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
    t = _table(tr(lang, "Structure: W = 3n − 2p5 − p4 = 3·{n} − 2·{p5} − {p4} = {dof}").format(n=st.n, p5=st.p5, p4=st.p4, dof=st.dof),
               (tr(lang, "Member"), "left"), (tr(lang, "Links"), "left"),
               (tr(lang, "Pairs (links)"), "left"), (tr(lang, "Class, order, kind"), "left"))
    for g in st.groups:
        pairs = ", ".join(f"{p.joint} {pattern(p.kind, lang)}({p.links[0]}–{p.links[1]})" for p in g.pairs)
        if g.index == 0:
            what = tr(lang, "class I mechanism (frame and crank)")
        else:
            what = tr(lang, "group of class II, order 2, kind {kind} ({pattern})").format(kind=g.kind, pattern=pattern(g.pattern, lang))
        links = ", ".join(str(n) for n in g.links)
        t.add_row(g.formula, links, pairs, what)
    t.caption = tr(lang, "Structural formula: {formula}; the mechanism is of class {mechanism_class}").format(formula=st.formula, mechanism_class=st.mechanism_class)
    t.caption_justify = "left"
    return t


# the links' roles (linkage/roles.py) as the course names them
ROLE_WORDS = {"crank": N_("crank"), "rocker": N_("rocker"), "coupler": N_("connecting rod"), "slider": N_("slider"),
              "slotted": N_("slotted link"), "block": N_("slotted-link block")}


def role_words(s: Sheet1, lang: str) -> dict[str, str]:
    """Link name → its role's word in `lang` («кривошип», «коромысло», «шатун», …)."""
    from ...linkage.roles import link_roles

    return {name: tr(lang, ROLE_WORDS[role]) for name, role in link_roles(s).items()}


def links_table(s: Sheet1, lang: str):
    m = s.mechanism
    kinds = role_words(s, lang)
    t = _table(tr(lang, "{name}: links").format(name=escape(m.name) if m.name else tr(lang, "Mechanism")),
               ("№", "right"), (tr(lang, "Link"), "left"), (tr(lang, "Kind"), "left"),
               (tr(lang, "Size"), "right"))
    t.add_row("0", tr(lang, "frame"), ", ".join(m.frame), "")
    size = {m.links[0].name: m.crank.length}
    for g in m.groups:
        for name, length in zip(g.links, g.lengths):
            size[name] = length
    for ln in m.links:
        mm = num(size[ln.name] * 1000, lang, decimals=1) + " " + tr(lang, "mm") if ln.name in size else ""
        t.add_row(str(ln.number), ln.name, kinds[ln.name], mm)
    return t


def results_table(s: Sheet1, lang: str):
    m, c = s.mechanism, s.cycle
    mm = tr(lang, "mm")
    t = _table(tr(lang, "Main results"), (tr(lang, "Quantity"), "left"),
               (tr(lang, "Value"), "right"), (tr(lang, "Note"), "left"))
    rpm = num(m.crank.rpm, lang, sig=5) + " " + tr(lang, "rpm")
    sense = tr(lang, "counter-clockwise") if m.crank.sense > 0 else \
        tr(lang, "clockwise")
    t.add_row(tr(lang, "Crank speed n₁, ω₁"),
              f"{rpm}; {num(abs(m.crank.omega), lang, sig=5)} " + tr(lang, "rad/s"), sense)
    out = m.output
    if c.stroke is not None:
        if out.kind == "slider":
            t.add_row(tr(lang, "Stroke H of the slider {link}").format(link=out.link),
                      num(c.stroke * 1000, lang, decimals=2) + " " + mm, "")
        else:
            t.add_row(tr(lang, "Swing ψ of the rocker {link}").format(link=out.link),
                      num(math.degrees(c.stroke), lang, decimals=3) + "°", "")
        t.add_row(tr(lang, "Time ratio K"),
                  num(c.time_ratio, lang, decimals=5), tr(lang, "K = φ_w/φ_r"))
        t.add_row(tr(lang, "Working stroke φ_w"), num(math.degrees(c.working), lang, decimals=3) + "°", "")
        t.add_row(tr(lang, "Return stroke φ_r"), num(math.degrees(c.returning), lang, decimals=3) + "°", "")
        ext = [p for p in (c.working_start(), c.working_end()) if p is not None]
        t.add_row(tr(lang, "Extreme positions"),
                  "; ".join(f"{p.label}: φ = {num(_deg(p.phi), lang, decimals=3)}°" for p in ext),
                  tr(lang, "start / end of the working stroke"))
    else:
        t.add_row(tr(lang, "Output link"), out.link,
                  tr(lang, "turns fully: no extreme positions"))
    t.add_row(tr(lang, "Position 0"), f"φ = {num(_deg(c.start), lang, decimals=3)}°", "")
    for p in c.pressure:
        g = m.groups[p.group - 1]
        t.add_row(tr(lang, "Largest pressure angle, group {group} ({kind})").format(group=p.group, kind=pattern(g.kind, lang)),
                  num(math.degrees(p.worst), lang, decimals=2) + "°",
                  f"φ = {num(_deg(p.phi), lang, decimals=1)}°" if p.worst > 0 else "")
    return t


def positions_table(s: Sheet1, lang: str):
    m, c = s.mechanism, s.cycle
    k = c.kin
    slider = m.output.kind == "slider"
    turning = [ln for ln in m.links if ln.kind in ("bar", "slotted")]
    s_col = ("s, " + tr(lang, "mm")) if slider else ("ψ, °")
    v_col = ("v, " + tr(lang, "m/s")) if slider else ("ω, " + tr(lang, "rad/s"))
    a_col = ("a, " + tr(lang, "m/s²")) if slider else ("ε, " + tr(lang, "rad/s²"))
    cols = [("№", "right"), ("φ, °", "right"), (s_col, "right"), (v_col, "right"), (a_col, "right")]
    for ln in turning:
        cols += [(f"ω{ln.number}, " + tr(lang, "rad/s"), "right"),
                 (f"ε{ln.number}, " + tr(lang, "rad/s²"), "right")]
    first, last = c.working_start(), c.working_end()
    if first is None or first.index == 0:
        title = tr(lang, "Positions (0: start of the working stroke); output {link}").format(link=m.output.link)
    else:  # crank.start_deg puts position 0 elsewhere: s counts from the working stroke's start
        title = tr(lang, "Positions (0: φ = {phi}°; the working stroke runs {start} → {end}, s from {start}); "
                         "output {link}").format(phi=num(_deg(c.start), lang, decimals=3), start=first.label,
                                                 end=last.label, link=m.output.link)
    t = _table(title, *cols)
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
    t = _table(tr(lang, "Speeds [m/s] and accelerations [m/s²] of the points"), *cols)
    for p in c.positions:
        i = p.index
        t.add_row(p.label, *[num(abs(complex(k.v[n][i])), lang, decimals=4) for n in names],
                  *[num(abs(complex(k.a[n][i])), lang, decimals=3) for n in names])
    return t


def plans_table(s: Sheet1, lang: str, which: int = 0):
    pl = s.plans[which]
    t = _table(tr(lang, "Velocity and acceleration plans, position {label} (φ = {phi}°)").format(label=pl.position.label, phi=num(_deg(pl.position.phi), lang, decimals=2)),
               (tr(lang, "Vector"), "left"), (tr(lang, "On the plan"), "left"),
               (tr(lang, "Direction"), "left"), (tr(lang, "Length, mm"), "right"),
               (tr(lang, "Magnitude"), "right"))
    for plan, unit, su in ((pl.velocity, tr(lang, "m/s"), tr(lang, "(m/s)/mm")),
                           (pl.acceleration, tr(lang, "m/s²"), tr(lang, "(m/s²)/mm"))):
        mu = "μ_v" if plan.kind == "velocity" else "μ_a"
        t.add_row(f"[bold]{mu} = {num(plan.scale, lang, sig=3)} {su}[/]", "", "", "", "")
        for v in plan.vectors:
            line = tr(lang, "guide") if v.line == "guide" else tr(lang, "slot") if v.line == "slot" else v.line
            t.add_row(book_symbol(s.mechanism, v.symbol), v.start + v.end, f"{v.relation} {line}".strip(),
                      num(v.magnitude / plan.scale, lang, decimals=1), num(v.magnitude, lang, sig=4) + " " + unit)
    return t


def print_mechanism(console, s: Sheet1, lang: str) -> None:
    tables = [links_table(s, lang), structure_table(s, lang), results_table(s, lang), positions_table(s, lang),
              speeds_table(s, lang)]
    tables += [plans_table(s, lang, j) for j in range(len(s.plans))]
    for table in tables:
        console.print(table)
