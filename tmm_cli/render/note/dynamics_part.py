"""The chapter on the force analysis and the dynamics of the lever mechanism (sheet 2), from the
:class:`~tmm_cli.linkage.sheet2.Sheet2` of ``tmm project --mechanism`` (``ProjectResult.linkage``).

Nothing is computed anew: every number is read from the result (the applied forces, the reactions,
Zhukovsky's lever, the reduced quantities, the flywheel); the substitutions only show how the
printed numbers follow from each other (the tests recompute them). What the chapter states as a
decision (the motor drives or brakes the crank in the position, a flywheel is needed or not) is a
claim (:meth:`~.model.Document.claim`) that the tests check.
"""

from __future__ import annotations

import math

import numpy as np

from ...i18n import N_
from ...i18n.numbers import small_pct
from .ctx import NBSP, Ctx, V, mq
from .model import Heading

# the kinds of Assur groups as the book writes them (В — a turning pair, П — a sliding pair)
_KIND = {"RRR": N_("RRR"), "RRP": N_("RRP"), "RPR": N_("RPR"), "PRP": N_("PRP"), "RPP": N_("RPP")}


def dynamics_chapter(c: Ctx) -> None:
    """Sheet 2's chapter; nothing without a mechanism file."""
    s = getattr(c.r, "linkage", None)
    if s is None:
        return
    c.doc.add(Heading(1, c.t("Force analysis and dynamics of the lever mechanism"), "chapter", "dynamics"))
    _loads(c, s)
    _groups(c, s)
    _lever(c, s)
    _reduction(c, s)
    _flywheel(c, s)


# --- symbols ----------------------------------------------------------------------------------------


def _split(sym: str) -> tuple[str, str]:
    """'MΦ3′' → ('MΦ', '3′'): the letters of a book's symbol and its number (with a tick)."""
    k = 0
    while k < len(sym) and not sym[k].isdigit():
        k += 1
    return sym[:k], sym[k:]


def fsym(c: Ctx, sym: str) -> str:
    """A force's or couple's symbol of :mod:`tmm_cli.linkage.forces` as typst math: 'Φ2' → Φ_2,
    'MΦ3' → M_(Φ 3), 'Fc' → F_"пс", 'Rτ34' → R_34^τ, a lever's 'MΦ3′' → M_(Φ 3)^prime."""
    tick = ""
    for mark, word in (("″", '^"″"'), ("′", '^"′"')):
        if sym.endswith(mark):
            sym, tick = sym[:-1], word
    if sym in ("Fc", "Mc") or sym[:2] in ("Fc", "Mc") and sym[2:].isdigit():  # Fc3, Mc5 of several loads
        name = c.t(sym[:2])  # the book's Fпс, Mпс
        return f'{name[0]}_"{name[1:]}{sym[2:]}"' + tick
    letters, number = _split(sym)
    if letters == "MΦ":
        return f"M_(Φ {number})" + tick
    if letters in ("Rτ", "Rn"):
        return f"R_({number.replace(',', ' ')})^{'τ' if letters == 'Rτ' else 'n'}"
    if letters == "R":
        return f"R_({number.replace(',', ' ')})"
    return f"{letters}_{number}" + tick if number else letters + tick


def vsym(c: Ctx, sym: str) -> str:
    """A force as a vector in typst math: 'Rτ12' → arrow(R)_(12)^τ (the letter under the arrow, as the
    book writes a vector equation)."""
    text = fsym(c, sym)
    base, sep, rest = text.partition("_")
    return f"arrow({base})" + (sep + rest if sep else "")


def pt(name: str) -> str:
    """A point's name as typst math: 'A' → A, 'O2' → O_2, 'S3' → S_3."""
    letters, number = _split(name)
    if len(letters) == 1 and letters.isalpha() and (number.isdigit() or not number):
        return f"{letters}_{number}" if number else letters
    return f'"{name}"'


def seg(a: str, b: str) -> str:
    """A length's subscript: l_(A B), or l_("O2A") when a name is not one letter."""
    if len(a) == 1 and len(b) == 1 and a.isalpha() and b.isalpha():
        return f"l_({a} {b})"
    return f'l_"{a}{b}"'


def _neg(sub: str, vals: list, k: int) -> str:
    """`sub` with the leaf {k} in parentheses when its value is negative (a − (−b))."""
    v = vals[k]
    if v.x < 0:
        return sub.replace("{%d}" % k, "({%d})" % k)
    return sub


# --- 1. the loads of the position -----------------------------------------------------------------------


def _position(s):
    return s.sheet1.cycle.positions[s.force_position]


def _loads(c: Ctx, s) -> None:
    from ...linkage.forces import G
    from ...linkage.masses import centre_motion

    t, n = c.t, c.n
    mech = s.sheet1.mechanism
    kin = s.sheet1.cycle.kin
    i = s.force_position
    p = _position(s)
    w1 = abs(kin.omega1)
    c.doc.add(Heading(2, t("Loads of the mechanism in the position of the force analysis")))
    c.p(t("The force analysis is made for position {label} of the crank ($φ = {phi}$), the position of the velocity "
          "and acceleration plans of sheet 1. By d'Alembert's principle every moving link carries, beside the real "
          "forces, the inertia force $Φ = -m a_S$ at its centre of mass and the inertia moment $M_Φ = -J_S ε$, and is "
          "then in equilibrium {{cite:artobolevsky}}. The crank turns uniformly at its mean speed ($ε_1 = 0$); the "
          "friction in the pairs is neglected.").format(label=p.label, phi=c.qd(math.degrees(p.phi) % 360, decimals=2)))
    c.formula(c.calc("ω_1 = (π n_1)/30", "(π dot {0})/30", [V(mech.crank.rpm, sig=6, exact=True)],
                     V(w1, sig=4), t("rad/s")), where=["ω_1", "n_1"])
    # the masses
    rows = []
    for ms in s.input.masses:
        ln = mech.link(ms.link)
        rows.append([str(ms.number), _link_name(c, ln), n(ms.m, sig=4, sci=False), n(ms.J, sig=4, sci=False) if ms.J > 0 else "—",
                     f"${pt(ms.label)}$"])
    if rows:
        c.p(t("The masses of the links, their moments of inertia about the centres of mass and the centres are given in "
              "Table {tab:dyn_masses}; the links not listed are taken massless."))
        c.table("dyn_masses", t("Masses of the links"),
                [t("Link"), t("Name"), "$m$, " + t("kg"), "$J_S$, " + t("kg·m²"), t("Centre of mass")], rows,
                align=["center", "left", "right", "right", "center"], widths=[0.7, 2.2, 1, 1.1, 1.2])
    forces, couples = s.loading.forces, s.loading.couples
    weights = [f for f in forces if f.kind == "weight"]
    inertia = [f for f in forces if f.kind == "inertia"]
    moments = [m for m in couples if m.kind == "inertia"]
    mass_of = {ms.number: ms for ms in s.input.masses}
    if weights:
        c.p(t("The weights of the links act at their centres of mass downwards:"))
        c.formula("G_i = m_i g", where=["G_i", "m_i", "g"])
        c.formula(*[c.calc(f"G_{f.number} = m_{f.number} g", "{0} dot {1}",
                           [V(mass_of[f.number].m, exact=True), V(G, exact=True)], V(abs(complex(f.f[i])), sig=4),
                           t("N")) for f in weights])
    if inertia:
        c.p(t("The inertia forces act at the centres of mass against their accelerations $a_S$ (taken from the "
              "acceleration plan of sheet 1):"))
        c.formula("Φ_i = m_i a_(S i)", where=["Φ_i", "a_(S i)"])
        lines = []
        for f in inertia:
            ms = mass_of[f.number]
            a = c.zero(abs(complex(centre_motion(kin, ms)[2][i])), "m/s²")
            lines.append(c.calc(f"Φ_{f.number} = m_{f.number} a_(S {f.number})", "{0} dot {1}",
                                [V(ms.m, exact=True), V(a, sig=4)], V(abs(complex(f.f[i])) if a else 0.0, sig=4),
                                t("N")))
        c.formula(*lines)
    if moments:
        c.p(t("The inertia moments act against the angular accelerations $ε$ of the links:"))
        c.formula("M_(Φ i) = J_(S i) ε_i", where=["M_(Φ i)", "J_(S i)", "ε_i"])
        lines = []
        for m in moments:
            ms = mass_of[m.number]
            eps = c.zero(abs(float(kin.epsilon[m.link][i])), "rad/s²")
            lines.append(c.calc(f"M_(Φ {m.number}) = J_(S {m.number}) ε_{m.number}", "{0} dot {1}",
                                [V(ms.J, exact=True), V(eps, sig=4)], V(abs(float(m.m[i])) if eps else 0.0, sig=4),
                                t("N·m")))
        c.formula(*lines)
    _load(c, s)
    _gas(c, s)
    # all the applied forces of the position
    rows = []
    for f in forces:
        rows.append([f"${fsym(c, f.symbol)}$", _kind(c, f, s), str(f.number), f"${pt(f.point)}$",
                     c.nf(abs(complex(f.f[i]))) + " " + t("N")])
    for m in couples:
        rows.append([f"${fsym(c, m.symbol)}$", _kind(c, m, s), str(m.number), "—",
                     c.nz(float(m.m[i]), "N·m", decimals=2) + " " + t("N·m")])
    c.p(t("The forces and moments applied to the links in position {label} are collected in Table {{tab:dyn_loads}} "
          "(a moment is positive counter-clockwise).").format(label=p.label))
    c.table("dyn_loads", t("Forces and moments applied to the links, position {label}").format(label=p.label),
            [t("Symbol"), t("Kind"), t("Link"), t("Point"), t("Value")], rows,
            align=["center", "left", "center", "center", "right"], widths=[1.3, 2.0, 0.7, 0.8, 1.2])


def _kind(c: Ctx, f, s) -> str:
    """The kind of an applied force or couple as the book names it: a gas force (P3, P5) by the sign
    of its power in the position, «движущая сила» where it drives the crank, «сила сопротивления»
    where it resists; the table's load is the useful resistance."""
    gas = {gl.link: gl for gl in s.input.gas}
    if f.kind == "load" and f.link in gas:
        from ...linkage.gas import gas_pressure, piston, state

        gl, mech = gas[f.link], s.sheet1.mechanism
        kin = s.kin.at(s.force_position)  # the crank angle as turned: a four-stroke's rows depend on the turn
        pst = piston(gl, mech)
        _, row, _ = state(gl, pst, mech, kin)
        p = c.zero(float(gas_pressure(gl, pst, mech, kin)[0]) * gl.area, "N")  # the force away from the head
        drives = p * (1.0 if int(row[0]) % 2 == 0 else -1.0)  # rows 0, 2: away from the head, it drives (at a dead
        if drives > 0:                                     # centre: on the stroke that begins there)
            return c.t("driving force (gas pressure)")
        if drives < 0:
            return c.t("resistance force (gas pressure)")
        return c.t("gas pressure force")
    return {"inertia": c.t("inertia"), "weight": c.t("weight"), "load": c.t("useful resistance")}[f.kind]


def _link_name(c: Ctx, ln) -> str:
    from ...linkage.roles import link_roles
    from ..terminal.mechanism import ROLE_WORDS

    role = link_roles(c.r.linkage.sheet1)[ln.name]
    ends = ln.axis if ln.axis is not None and ln.kind not in ("slider", "block") else (ln.name,)
    return c.t(ROLE_WORDS[role]) + " " + "".join(ends)


def _load(c: Ctx, s) -> None:
    from ...linkage.loads import progress, table_value

    t, n = c.t, c.n
    ld, st = s.input.load, s.stroke
    if s.input.tables != ((ld,) if ld is not None else ()):  # several table loads, or one off the output
        _several_loads(c, s)
        return
    if ld is None or st is None:
        return
    mech = s.sheet1.mechanism
    i = s.force_position
    kin = s.sheet1.cycle.kin
    _, fraction, working = progress(st, mech, kin)
    f, on = float(fraction[i]), bool(working[i])
    sym = fsym(c, "Fc" if ld.kind == "force" else "Mc")
    unit = t("N") if ld.kind == "force" else t("N·m")
    what = (t("The useful resistance ${sym}$ acts on the output link ({what}) along its guide against the working "
              "stroke; its diagram (Table {{tab:dyn_load}}) gives it against the share of the working stroke covered; "
              "it is linear between these points and zero on the return stroke.") if ld.kind == "force" else
            t("The useful resistance moment ${sym}$ acts on the output rocker against its working swing; its diagram "
              "(Table {{tab:dyn_load}}) gives it against the share of the swing covered; it is linear between these "
              "points and zero on the return stroke."))
    from .linkage_part import role_name

    c.p(what.format(sym=sym, what=role_name(c, s.sheet1, mech.output.link)))
    if ld.direction is not None:
        c.p(t("Its direction is its own, fixed at {deg}° from the $x$ axis (not along the guide): its part across the "
              "guide does no work but loads the pairs.").format(deg=n(math.degrees(ld.direction), decimals=1)))
    share = t("Share of the working stroke") if ld.kind == "force" else t("Share of the working swing")
    c.table("dyn_load", t("Diagram of the useful resistance"), [share] + [n(x, sig=3) for x in ld.stroke],
            [[f"${sym}$, {unit}"] + [n(y, sig=5) for y in ld.values]],
            align=["left"] + ["center"] * len(ld.stroke), widths=[2.2] + [1.0] * len(ld.stroke))
    value = float(table_value(ld, f)) if on else 0.0
    c.doc.claim(kind="linkage_load_at_position", label=_position(s).label, working=on, share=f, value=value)
    if on:
        text = (t("In position {label} the crank is on the working stroke and the output has covered the share {share} of "
                  "it, so ${sym} = {value}$ {unit}.") if ld.kind == "force" else
                t("In position {label} the output rocker is on its working swing and has covered the share {share} of "
                  "it, so ${sym} = {value}$ {unit}."))
        c.p(text.format(label=_position(s).label, share=n(f, decimals=3), sym=sym, value=c.q(value, decimals=1),
                        unit=unit))
    elif ld.kind == "moment":
        c.p(t("In position {label} the output rocker is on its return swing: ${sym} = 0$.").format(
            label=_position(s).label, sym=sym))
    else:
        c.p(t("In position {label} the crank is on the return stroke: ${sym} = 0$.").format(
            label=_position(s).label, sym=sym))


def _load_symbol(s, ld) -> str:
    """The symbol of a table load in the loading (Fc, Mc; of several, Fc3, Mc5 by the link's number)."""
    from ...linkage.forces import load_symbol

    return load_symbol(s.sheet1.mechanism, ld, len(s.input.tables))


def _several_loads(c: Ctx, s) -> None:
    """The table loads, each on its own link and over its own working stroke: each one's diagram,
    where its working stroke starts and how long it is, and its value in the position."""
    from ...linkage.loads import progress, table_value

    t, n = c.t, c.n
    mech = s.sheet1.mechanism
    i = s.force_position
    kin = s.sheet1.cycle.kin
    label = _position(s).label
    c.p(t("The useful resistances act each on its own link and each over that link's own working stroke: a load's "
          "diagram gives it against the share of its link's stroke (or swing) covered since the link left the extreme "
          "position where its working stroke starts; it is linear between the points of the diagram, opposes the "
          "working motion and is zero on that link's return stroke. Each link's extreme positions are where its "
          "velocity is zero; its working stroke is the one its file's table names (away from or towards the crank's "
          "pivot), else the slower one."))
    for ld, st in zip(s.input.tables, s.strokes):
        if st is None:
            continue
        ln = mech.link(ld.link)
        sym = fsym(c, _load_symbol(s, ld))
        unit = t("N") if ld.kind == "force" else t("N·m")
        lead = math.degrees(st.lead)
        where = (t("position 0") if lead < 1e-6 else
                 t("{lead}° of the crank's turn after position 0").format(lead=n(lead, decimals=2)))
        if ld.kind == "force":
            c.p(t("The force ${sym}$ acts on the {link} (link {number}) along its guide against its working stroke. That "
                  "stroke starts at the crank angle $φ$ = {start}° ({where}), lasts {work}° of the turn and moves the "
                  "slider by $H$ = {length} mm.").format(
                sym=sym, link=_link_name(c, ln), number=ln.number, start=n(math.degrees(st.origin) % 360.0, decimals=2),
                where=where,
                work=n(math.degrees(st.working), decimals=2), length=n(st.length * 1e3, decimals=2)))
            if ld.direction is not None:
                c.p(t("Its direction is its own, fixed at {deg}° from the $x$ axis (not along the guide): its part across "
                      "the guide does no work but loads the pairs.").format(deg=n(math.degrees(ld.direction), decimals=1)))
        else:
            c.p(t("The moment ${sym}$ acts on the {link} (link {number}) against its working swing. That swing starts at "
                  "the crank angle $φ$ = {start}° ({where}), lasts {work}° of the turn and turns the link by $ψ$ = "
                  "{length}°.").format(
                sym=sym, link=_link_name(c, ln), number=ln.number, start=n(math.degrees(st.origin) % 360.0, decimals=2),
                where=where,
                work=n(math.degrees(st.working), decimals=2), length=n(math.degrees(st.length), decimals=2)))
        share = t("Share of the working stroke") if ld.kind == "force" else t("Share of the working swing")
        c.table(f"dyn_load_{ln.number}", t("Diagram of the useful resistance ${sym}$").format(sym=sym),
                [share] + [n(x, sig=3) for x in ld.stroke], [[f"${sym}$, {unit}"] + [n(y, sig=5) for y in ld.values]],
                align=["left"] + ["center"] * len(ld.stroke), widths=[2.2] + [1.0] * len(ld.stroke))
        _, fraction, working = progress(st, mech, kin)
        f, on = float(fraction[i]), bool(working[i])
        value = float(table_value(ld, f)) if on else 0.0
        c.doc.claim(kind="linkage_load_at_position", label=label, working=on, share=f, value=value, link=ld.link)
        if on:  # a rocker's stroke is its swing (рабочее качание)
            text = (t("In position {label} the {link} (link {number}) is on its working stroke and has covered the share "
                      "{share} of it, so ${sym} = {value}$ {unit}.") if ld.kind == "force" else
                    t("In position {label} the {link} (link {number}) is on its working swing and has covered the share "
                      "{share} of it, so ${sym} = {value}$ {unit}."))
            c.p(text.format(label=label, link=_link_name(c, ln), number=ln.number, share=n(f, decimals=3), sym=sym,
                            value=c.q(value, decimals=1), unit=unit))
        else:
            text = (t("In position {label} the {link} (link {number}) is on its return stroke: ${sym} = 0$.")
                    if ld.kind == "force" else
                    t("In position {label} the {link} (link {number}) is on its return swing: ${sym} = 0$."))
            c.p(text.format(label=label, link=_link_name(c, ln), number=ln.number, sym=sym))


def _gas(c: Ctx, s) -> None:
    """The gas forces from the indicator diagrams ([[load]] with head)."""
    from ...linkage.gas import gas_pressure, piston, state

    t, n = c.t, c.n
    gas = s.input.gas
    if not gas:
        return
    mech = s.sheet1.mechanism
    i = s.force_position
    kin = s.kin.at(i)  # the crank angle as turned: a four-stroke's rows depend on the turn
    c.p(t("The gas force on a piston is $P = p A$ along its cylinder, away from the cylinder head, on both strokes: "
          "$p$ the gauge pressure of the indicator diagram against the piston's travel $s/H$ from the dead centre "
          "nearest the head (the first row while the piston moves away from the head, the second while it comes back), "
          "$A$ the piston's area. It drives the crank where the piston moves away from the head and resists where it "
          "comes back."))
    if s.turns > 1:  # a four-stroke engine: why its cycle takes two turns
        per = s.sheet1.mechanism.positions  # the regular positions a turn (the second turn numbered on from it)
        c.p(t("The piston of a four-stroke engine makes four strokes in its working cycle — expansion (the working "
              "stroke), exhaust, intake and compression — a stroke each half turn of the crank, so the cycle, and with "
              "it the gas force and the reduced moment, repeats only after two turns of the crank (720°). Its "
              "indicator diagram has four rows, in the cycle's order from the dead centre nearest the head; the "
              "kinematics and the reduced moment of inertia repeat every turn, the gas force does not. The positions, "
              "the diagrams, the change of the kinetic energy and the flywheel are therefore taken over the two turns: "
              "the positions of the second turn are numbered on, {a} … {b}, and the angle $Δ φ$ runs from 0 to 720°.")
            .format(a=per, b=2 * per - 1))
    strokes = (t("expansion (away from the head)"), t("exhaust (towards the head)"), t("intake (away from the head)"),
               t("compression (towards the head)"))
    if c.has("linkage_indicator"):
        c.p(t("The indicator diagrams of the tables below, each stroke with its number in the order of the cycle and the "
              "force $P = p A$ on the right-hand axis, are shown in Figure {fig:linkage_indicator}; sheet 2 draws them "
              "at the scales it states."))
        c.fig("linkage_indicator", t("Indicator diagrams of the pistons: gauge pressure against the piston's travel from "
                                     "the dead centre nearest the head"))
    for gl in gas:
        ln = mech.link(gl.link)
        sym = fsym(c, f"P{ln.number}")
        pst = piston(gl, mech)
        names = (t("away from the head"), t("towards the head")) if gl.turns == 1 else strokes
        c.table(f"dyn_gas_{ln.number}", t("Indicator diagram of the piston {p} (gauge pressure, MPa; area {a} m²)").format(
            p=gl.link, a=n(gl.area, sig=4)), ["$s/H$"] + [n(x, sig=3) for x in gl.travel],
            [[name] + [n(y, sig=4) for y in row] for name, row in zip(names, gl.pressure)],
            align=["left"] + ["center"] * len(gl.travel), widths=[2.2] + [0.9] * len(gl.travel))
        x, row, _ = state(gl, pst, mech, kin)
        p = float(gas_pressure(gl, pst, mech, kin)[0]) / 1.0e6
        if gl.turns == 1:
            c.p(t("In position {label} the piston {p} is at $s/H$ = {x}, moving {way}: $p$ = {pr} MPa,").format(
                label=_position(s).label, p=gl.link, x=n(float(x[0]), decimals=3), pr=n(p, sig=4),
                way=t("away from the head") if int(row[0]) == 0 else t("towards the head")))
        else:
            c.p(t("In position {label} (the first turn of the cycle) the piston {p} is at $s/H$ = {x}, the stroke "
                  "{stroke}: $p$ = {pr} MPa,").format(label=_position(s).label, p=gl.link, x=n(float(x[0]), decimals=3),
                                                       pr=n(p, sig=4), stroke=strokes[int(row[0])]))
        c.formula(c.calc(f"{sym} = p A", "{0} dot 10^6 dot {1}", [V(p, sig=6), V(gl.area, exact=True)],
                         V(p * 1.0e6 * gl.area, sig=4), t("N")), numbered=False)


# --- 2. the groups ----------------------------------------------------------------------------------


def known_moment(s, number: int, about: complex, i: int) -> float:
    """Σ of the moments [N·m] about the point `about` of the known forces on the link `number` in
    position `i`: its applied forces and couples and the reactions of the groups solved before it
    (taken with the opposite sign), as the force analysis loads the link."""
    from ...linkage.motion import cross

    forces, couples = s.loading.on(number)
    total = sum(float(cross(complex(f.z[i]) - about, complex(f.f[i]))) for f in forces)
    total += sum(float(m.m[i]) for m in couples)
    for r in s.forces.reactions:
        if r.pair.links[0] == number and 0 < number < 2 * r.pair.group:
            total += float(cross(complex(r.at[i]) - about, -complex(r.force[i])))
            if r.couple is not None:
                total -= float(r.couple[i])
    return total


def _groups(c: Ctx, s) -> None:
    t, n = c.t, c.n
    mech = s.sheet1.mechanism
    kin = s.sheet1.cycle.kin
    i = s.force_position
    z = {k: complex(v[i]) for k, v in kin.z.items()}
    N = t("N")
    c.doc.add(Heading(2, t("Force analysis of the groups")))
    c.p(t("The mechanism is analysed group by group from the last attached to the crank, each group with the forces "
          "applied to it and the reactions of the groups already solved taken with the opposite sign "
          "{cite:artobolevsky}. $R_(i j)$ is the force of link $i$ on link $j$ (0 the frame); a pin transmits a force "
          "through its centre, a slide a force across the guide. The force polygons are drawn on sheet 2."))
    first = True
    for g in reversed(mech.groups):
        n2, n3 = g.numbers
        pa, pb, pc = g.pairs
        ra, rb, rc = (s.forces.reaction(_label(q)) for q in g.pairs)
        head = t("Group {index} ({kind}: links {n2} and {n3})").format(index=g.index, kind=t(_KIND[g.kind]), n2=n2,
                                                                        n3=n3)
        c.p(head + (t(" is solved first.") if first else t(" is solved next.")), indent=True)
        first = False
        poly = f"dyn_poly_{g.index}"  # the label of the group's force polygon, which the text refers to
        if g.kind == "PRP":
            (jb,) = g.joints
            c.p(t("Unknown are the two guides' reactions ${a}$ and ${c}$, each across its guide, the slides' couples "
                  "(each block's own moment about ${B}$: a block cannot turn on its guide) and the inner reaction ${b}$ "
                  "of the pin ${B}$. The moments of each block about ${B}$ give the couples:").format(
                a=fsym(c, ra.label), b=fsym(c, rb.label), c=fsym(c, rc.label), B=pt(jb)))
            c.formula(*[_couple_line(c, s, r, n, z[jb], jb) for r, n in ((ra, n2), (rc, n3))],
                      where=[_sum_where(c, jb), ("M_(i j)", t("the couple of the slide, the moment of link $i$ on "
                                                              "link $j$, N·m (counter-clockwise positive)"))])
            c.p(t("The force polygon of the group gives the two guides' reactions, the polygon of link {n3} the "
                  "pin's:").format(n3=n3))
            c.formula(f"{vsym(c, ra.label)} + Σ arrow(F)^(({n2})) + Σ arrow(F)^(({n3})) + {vsym(c, rc.label)} = 0; "
                      f"quad {vsym(c, rb.label)} = -({vsym(c, rc.label)} + Σ arrow(F)^(({n3})))", label=poly)
        elif g.kind == "RPP":
            ja, jy = g.joints
            c.p(t("Unknown are the reaction ${a}$ of the pin ${A}$ on the block, the block's pressure ${b}$ on the yoke "
                  "across its slot and the guide's reaction ${c}$ across the guide, with the slides' couples. The "
                  "polygon of the yoke {n3} gives ${b}$ and ${c}$ (their directions are known), the polygon of the "
                  "block {n2} gives ${a}$:").format(a=fsym(c, ra.label), b=fsym(c, rb.label), c=fsym(c, rc.label),
                                                   A=pt(ja), n2=n2, n3=n3))
            c.formula(f"{vsym(c, rb.label)} + Σ arrow(F)^(({n3})) + {vsym(c, rc.label)} = 0; quad "
                      f"{vsym(c, ra.label)} = {vsym(c, rb.label)} - Σ arrow(F)^(({n2}))", label=poly)
            c.p(t("The couples follow from the moments of the block about ${A}$ and of the yoke about ${Y}$:").format(
                A=pt(ja), Y=pt(jy)))
            c.formula(_couple_line(c, s, rb, n2, z[ja], ja, own=True), _yoke_couple_line(c, s, g, rb, rc, z),
                      where=[_sum_where(c, ja), ("M_(i j)", t("the couple of the slide, the moment of link $i$ on "
                                                              "link $j$, N·m (counter-clockwise positive)"))])
        elif g.kind in ("RRR", "RRP"):
            ja, jb = g.joints[0], g.joints[1]
            l2 = abs(z[jb] - z[ja])
            m2 = known_moment(s, n2, z[jb], i)
            unknown = (t("Unknown are the reactions ${a}$ at ${A}$ and ${c}$ at ${C}$ (each in size and direction) and "
                         "the inner reaction ${b}$. The outer ones are split into components along the links, "
                         "$R^n$, and across them, $R^τ$; the moments of links {n2} and {n3} about ${B}$ give the "
                         "tangential components:") if g.kind == "RRR" else
                       t("Unknown are the reaction ${a}$ at ${A}$ (in size and direction), the guide's reaction ${c}$ "
                         "across the guide and the inner reaction ${b}$. ${a}$ is split into the components along "
                         "the link, $R^n$, and across it, $R^τ$; the moment of link {n2} about ${B}$ gives the "
                         "tangential one:"))
            c.p(unknown.format(a=fsym(c, ra.label), b=fsym(c, rb.label), c=fsym(c, rc.label), A=pt(ja), B=pt(jb),
                               C=pt(g.joints[-1]), n2=n2, n3=n3))
            lines = [c.calc(f"{fsym(c, 'Rτ' + ra.label[1:])} = abs(Σ M_({pt(jb)})^(({n2})))/{seg(ja, jb)}", "{0}/{1}",
                            [V(abs(m2), sig=5), V(l2, sig=4)], V(abs(complex(ra.tangential[i])), sig=4), N)]
            if g.kind == "RRR":
                jc = g.joints[2]
                l3 = abs(z[jb] - z[jc])
                m3 = known_moment(s, n3, z[jb], i)
                lines.append(c.calc(f"{fsym(c, 'Rτ' + rc.label[1:])} = abs(Σ M_({pt(jb)})^(({n3})))/{seg(jc, jb)}",
                                    "{0}/{1}", [V(abs(m3), sig=5), V(l3, sig=4)],
                                    V(abs(complex(rc.tangential[i])), sig=4), N))
            c.formula(*lines, where=[_sum_where(c, jb)])
            if g.kind == "RRR":
                eq = (f"{vsym(c, 'Rτ' + ra.label[1:])} + Σ arrow(F)^(({n2})) + Σ arrow(F)^(({n3})) + "
                        f"{vsym(c, 'Rτ' + rc.label[1:])} + {vsym(c, 'Rn' + rc.label[1:])} + "
                        f"{vsym(c, 'Rn' + ra.label[1:])} = 0")
                c.p(t("The normal components close the force polygon of the group; the inner reaction follows from "
                      "the polygon of link {n3}, ${b} = -({c} + Σ arrow(F)^(({n3})))$:").format(
                    n3=n3, b=vsym(c, rb.label), c=vsym(c, rc.label)))
            else:
                eq = (f"{vsym(c, 'Rτ' + ra.label[1:])} + Σ arrow(F)^(({n2})) + Σ arrow(F)^(({n3})) + "
                        f"{vsym(c, rc.label)} + {vsym(c, 'Rn' + ra.label[1:])} = 0")
                c.p(t("The normal component and the guide's reaction close the force polygon of the group; the inner "
                      "reaction follows from the polygon of link {n3}, ${b} = -({c} + Σ arrow(F)^(({n3})))$:").format(
                    b=vsym(c, rb.label), c=vsym(c, rc.label), n3=n3))
            c.formula(eq, label=poly)
            couple = c.zero(float(rc.couple[i]) if rc.couple is not None else 0.0, "N·m")
            if g.kind == "RRP" and (g.guide.moving or couple != 0.0):  # the guide holds the slider against turning
                c.p(t("The guide's reaction ${c}$ comes with the couple of the slide, from the moments of link {n3} "
                      "about ${B}$:").format(c=fsym(c, rc.label), n3=n3, B=pt(jb)))
                c.formula(_couple_line(c, s, rc, n3, z[jb], jb),
                          where=[("M_(i j)", t("the couple of the slide, the moment of link $i$ on link $j$, N·m "
                                               "(counter-clockwise positive)"))])
        else:
            ja, jc = g.joints
            rho = abs(z[ja] - z[jc])
            m3 = known_moment(s, n3, z[jc], i)
            if g.offset == 0.0:
                c.p(t("Unknown are the reaction ${a}$ on the block at ${A}$, the block's pressure ${b}$ on the slotted link "
                      "(across the slot: the slide is frictionless) and the reaction ${c}$ at the pivot ${C}$. The moments "
                      "of link {n3} about ${C}$ give the pressure of the block, ${l}$ being the distance from the pivot "
                      "to the block:").format(l=seg(jc, ja), a=fsym(c, ra.label), b=fsym(c, rb.label), c=fsym(c, rc.label),
                                              A=pt(ja), C=pt(jc), n3=n3))
            else:  # the arm is not the distance to the block: it is said below
                c.p(t("Unknown are the reaction ${a}$ on the block at ${A}$, the block's pressure ${b}$ on the slotted link "
                      "(across the slot: the slide is frictionless) and the reaction ${c}$ at the pivot ${C}$. The moments "
                      "of link {n3} about ${C}$ give the pressure of the block.").format(
                    a=fsym(c, ra.label), b=fsym(c, rb.label), c=fsym(c, rc.label), A=pt(ja), C=pt(jc), n3=n3))
            mb = float(rb.couple[i]) if rb.couple is not None else 0.0
            arm_sym = seg(jc, ja)
            if g.offset != 0.0:  # an offset slot: the pressure's arm about C is the block's place along the slot
                arm_sym, d = "h", abs(g.offset)
                arm = math.sqrt(max(rho * rho - d * d, 0.0))
                c.p(t("The slot passes {d} mm from the pivot ${C}$: the arm $h$ of the pressure about ${C}$ is the "
                      "block's distance along the slot from the foot of the perpendicular:").format(
                    d=c.n(d * 1000.0, sig=4), C=pt(jc)))
                c.formula(c.calc(f"h = sqrt({seg(jc, ja)}^2 - d^2)", "sqrt({0}^2 - {1}^2)", [V(rho, sig=5), V(d, sig=4)],
                                 V(arm, sig=5), t("m")), numbered=False)
                rho = arm
            if abs(mb) > 1e-9 * max(1.0, abs(m3)):
                line = c.calc(f"{fsym(c, rb.label)} = abs(Σ M_({pt(jc)})^(({n3})) + M_({n2} {n3}))/{arm_sym}",
                              "abs({0} + {1})/{2}", [V(m3, sig=5), V(mb, sig=5), V(rho, sig=4)],
                              V(abs(complex(rb.force[i])), sig=4), N)
            else:
                line = c.calc(f"{fsym(c, rb.label)} = abs(Σ M_({pt(jc)})^(({n3})))/{arm_sym}", "{0}/{1}",
                              [V(abs(m3), sig=5), V(rho, sig=4)], V(abs(complex(rb.force[i])), sig=4), N)
            c.formula(line, where=[_sum_where(c, jc)])
            c.p(t("The polygons of the block and of the slotted link give the other two:"))
            c.formula(f"{vsym(c, ra.label)} = {vsym(c, rb.label)} - Σ arrow(F)^(({n2})); quad "
                      f"{vsym(c, rc.label)} = -({vsym(c, rb.label)} + Σ arrow(F)^(({n3})))", label=poly)
        _group_table(c, s, g, poly)
    _crank(c, s)
    _reactions_table(c, s)


def _couple_sym(r) -> str:
    """The couple of a slide's reaction 'R34' as typst math: M_(34)."""
    return f"M_({r.label[1:].replace(',', ' ')})"


def _couple_line(c: Ctx, s, r, block: int, about: complex, joint: str, own: bool = False) -> str:
    """The couple of a slide from the moments of its block `block` about `joint`: the guide's link on
    the block holds it against the block's own moment, M_kn = −Σ M^(n); the block on the guide's
    link (`own`, the pair's first link) passes its own moment on, M_nk = Σ M^(n)."""
    i = s.force_position
    total = c.zero(known_moment(s, block, about, i), "N·m")
    value = c.zero(float(r.couple[i]) if r.couple is not None else 0.0, "N·m")
    lhs = f"{_couple_sym(r)} = {'' if own else '-'}Σ M_({pt(joint)})^(({block}))"
    if total == 0.0 and value == 0.0:
        return lhs + " = 0"
    vals = [_small(total, 5)]
    sub = "{0}" if own else _neg("-{0}", vals, 0)
    return c.calc(lhs, sub, vals, _small(value, 4), c.t("N·m"))


def _small(x: float, sig: int) -> V:
    """`x` to `sig` significant digits in decimals (0,0006849, not 6,849·10⁻⁴, among the other decimals)."""
    if x == 0.0 or abs(x) >= 1e-3:
        return V(x, sig=sig)
    return V(x, decimals=sig - 1 - math.floor(math.log10(abs(x))))


def _yoke_couple_line(c: Ctx, s, g, rb, rc, z) -> str:
    """An RPP yoke's guide couple from the yoke's moments about Y: its loads, the block's pressure
    R23 at A and the slide's couple M23, M_03 = −(Σ M_Y^(3) + M_23)."""
    from ...linkage.motion import cross

    i = s.force_position
    ja, jy = g.joints
    n3 = g.numbers[1]
    loads = known_moment(s, n3, z[jy], i) + float(cross(z[ja] - z[jy], complex(rb.force[i])))
    m23 = c.zero(float(rb.couple[i]) if rb.couple is not None else 0.0, "N·m")
    value = c.zero(float(rc.couple[i]) if rc.couple is not None else 0.0, "N·m")
    lhs = f"{_couple_sym(rc)} = -(Σ M_({pt(jy)})^(({n3})) + {_couple_sym(rb)})"
    vals = [V(c.zero(loads, "N·m"), sig=5), V(m23, sig=5)]
    return c.calc(lhs, _neg("-({0} + {1})", vals, 1), vals, V(value, sig=4), c.t("N·m"))


def _sum_where(c: Ctx, joint: str):
    return (f"Σ M_({pt(joint)})^((k))", c.t("the sum of the moments about the point ${p}$ of the known forces on link "
                                           "$k$, N·m").format(p=pt(joint)))


def _label(pair) -> str:
    from ...linkage.kinetostatics import pair_label

    return pair_label(pair)


def _group_table(c: Ctx, s, g, poly: str) -> None:
    """The reactions of one group found: their components and sizes."""
    t, n = c.t, c.n
    i = s.force_position
    parts = []
    for q in g.pairs:
        r = s.forces.reaction(_label(q))
        if r.tangential is not None:
            parts.append(f"${fsym(c, 'Rτ' + r.label[1:])} = {mq(c.nf(abs(complex(r.tangential[i]))))}$")
            parts.append(f"${fsym(c, 'Rn' + r.label[1:])} = {mq(c.nf(abs(complex(r.normal[i]))))}$")
        parts.append(f"${fsym(c, r.label)} = {mq(c.nf(abs(complex(r.force[i]))))}$")
    c.p(t("The group's reactions from its polygons ({{eq:{poly}}}), N: {list}.").format(poly=poly,
                                                                                     list=", ".join(parts)))


def _crank(c: Ctx, s) -> None:
    """The crank's equation of moments about its pivot with every reaction on it: R21 of the first
    group's link and, where several groups hang on the crank pin (a V compressor), R41, … each with
    its arm and its sign (counter-clockwise positive), the couple of a slide on the crank, and the
    crank's own loads where they have a moment: M_ур = −Σ M_O."""
    from ...linkage.motion import cross

    t = c.t
    mech = s.sheet1.mechanism
    kin = s.sheet1.cycle.kin
    i = s.force_position
    r01 = s.forces.reaction(_label(mech.pairs[0]))
    on_crank = [r for r in s.forces.reactions if r.pair.links[0] == 1]  # R12, R14, …: their opposites act on it
    zo = complex(kin.z[mech.crank.pivot][i])
    mb = float(s.balancing[i])
    terms, vals, where, names = [], [], ['M_"ур"'], []
    total = 0.0
    for r in on_crank:
        k = r.pair.links[1]
        moment = float(cross(complex(r.at[i]) - zo, -complex(r.force[i])))  # the moment of R_k1 about O
        size = abs(complex(r.force[i]))
        h = abs(moment) / size if size > 0 else 0.0
        sym = fsym(c, f"R{k}1") if k < 10 else fsym(c, f"R{k},1")
        hs = f"h_({k}1)" if k < 10 else f"h_({k},1)"
        names.append((vsym(c, f"R{k}1" if k < 10 else f"R{k},1"), vsym(c, r.label), k))
        total += moment
        if c.zero(moment, "N·m") == 0.0:
            continue
        terms.append(("-" if moment > 0 else "+", f"{sym} {hs}", "{%d} dot {%d}" % (len(vals), len(vals) + 1)))
        vals += [V(size, sig=5), V(h, decimals=4 - math.floor(math.log10(h)) if h > 0 else 4)]  # 5 digits, no 10⁻⁴
        where.append((hs, t("the arm of ${r}$ about the crank's pivot, m").format(r=sym)))
        if r.couple is not None and c.zero(float(r.couple[i]), "N·m") != 0.0:  # a slide on the crank: its couple
            mk = -float(r.couple[i])
            total += mk
            msym = f"M_({k} 1)"
            terms.append(("-" if mk > 0 else "+", msym, "{%d}" % len(vals)))
            vals.append(V(abs(mk), sig=5))
            where.append((msym, t("the moment of the slide's couple on the crank, N·m")))
    own = known_moment(s, 1, zo, i) - total  # the crank's own weight, inertia force and moment
    if c.zero(own, "N·m") != 0.0:
        sm = f"Σ M_({pt(mech.crank.pivot)})^((1))"
        terms.append(("-" if own > 0 else "+", sm, "{%d}" % len(vals)))
        vals.append(V(abs(own), sig=5))
        where.append((sm, t("the moment about the crank's pivot of the crank's own loads (its weight and inertia "
                            "force), N·m")))
    reactions = ", ".join(t("${r} = -{q}$ of link {k}").format(r=a, q=b, k=k) for a, b, k in names)
    c.p(t("The crank comes last. On it act the reactions {reactions}, its own loads and the balancing moment "
          "$M_\"ур\"$ of the motor; the frame's reaction ${r01}$ closes its polygon. From the equation of its moments "
          "about ${O}$ (counter-clockwise positive), $M_\"ур\" + Σ M_({O}) = 0$:").format(
        reactions=reactions, r01=vsym(c, r01.label), O=pt(mech.crank.pivot)))
    if not terms:
        c.formula('M_"ур" = 0', where=where)
    else:
        lhs = "M_\"ур\" = " + " ".join((sg if k or sg == "-" else "") + " " + body
                                        for k, (sg, body, _) in enumerate(terms)).strip()
        sub = " ".join((sg if k or sg == "-" else "") + " " + leaf for k, (sg, _, leaf) in enumerate(terms)).strip()
        c.formula(c.calc(lhs, sub, vals, V(mb, sig=4), t("N·m")), where=where)
    w = kin.omega1
    drives = mb * w > 0
    sense = t("counter-clockwise") if mb > 0 else t("clockwise")
    if s.is_engine:  # an engine: the gas drives, the consumer's moment resists
        c.p((t("The balancing moment turns {sense}, the way the crank turns: in this position the crank (with the "
               "energy stored in the flywheel) drives the mechanism.") if drives else
             t("The balancing moment turns {sense}, against the crank's rotation: in this position the gas forces "
               "drive the crank and the consumer brakes it.")).format(sense=sense))
    else:
        c.p((t("The balancing moment turns {sense}, the way the crank turns: in this position the motor drives the "
               "mechanism.") if drives else
             t("The balancing moment turns {sense}, against the crank's rotation: in this position the mechanism drives "
               "the crank and the motor brakes it.")).format(sense=sense))
    c.doc.claim(kind="linkage_balancing_sense", moment=mb, omega=w, drives=drives)


def _reactions_table(c: Ctx, s) -> None:
    t, n = c.t, c.n
    i = s.force_position
    rows = []
    for r in s.forces.reactions:
        what = t("pin") if r.pair.kind == "R" else t("slide")
        rows.append([f"${fsym(c, r.label)}$", f"${pt(r.pair.joint)}$", what, c.nf(abs(complex(r.force[i]))) + NBSP + t("N")])
    for r in s.forces.reactions:  # the slides' couples, each beside its reaction's pair
        couple = c.zero(float(r.couple[i]), "N·m") if r.couple is not None else 0.0
        if couple != 0.0:
            rows.append([f"${_couple_sym(r)}$", f"${pt(r.pair.joint)}$", t("couple of the slide"),
                         c.n(couple, decimals=2 if abs(couple) >= 0.01 else None, sig=3, sci=False) + NBSP + t("N·m")])
    # the balancing moment in the same table, each value with its own unit (the column holds N and N·m)
    rows.append(['$M_"ур"$', "—", "—", c.qty(float(s.balancing[i]), t("N·m"), decimals=2)])
    c.p(t("The reactions of the pairs in position {label} are given in Table {{tab:dyn_reactions}}.").format(
        label=_position(s).label))
    c.table("dyn_reactions", t("Reactions in the kinematic pairs and the balancing moment, position {label}").format(
        label=_position(s).label), [t("Pair"), t("Joint"), t("Kind"), t("Magnitude")], rows,
        align=["center", "center", "left", "right"], widths=[1, 0.8, 1.2, 1.3])


# --- 3. Zhukovsky's lever -----------------------------------------------------------------------------


def _lever(c: Ctx, s) -> None:
    """Zhukovsky's lever as sheet 2 draws it: one table (:meth:`Sheet2.lever_table`) of the forces'
    arms h and moments ±F·h about the pole, F_ур and M_ур — the same numbers as the sheet's."""
    from ...linkage.zhukovsky import DECIMALS as D

    t, n = c.t, c.n
    lt = s.lever_table()
    plan = s.sheet1.plans[0]
    c.doc.add(Heading(2, t("Balancing moment by Zhukovsky's lever")))
    c.p(t("The balancing moment is checked by N. E. Zhukovsky's theorem {{cite:artobolevsky}}: the velocity plan of "
          "position {label}, turned through 90° and drawn at $μ_v = {mu}$ (m/s)/mm (as on sheet 2), has every force "
          "applied at the image of its point, parallel to itself (an inertia moment as two forces $M_Φ/l$ across its "
          "link at the link's ends); the plan, a rigid lever pivoted at the pole $p$, is in equilibrium with the "
          "balancing force $F_\"ур\"$ at the image $a$ of the crank pin, across $p a$. The arms $h$ of the forces "
          "about $p$ are determined from the coordinates of the turned plan's points (Table {{tab:dyn_lever}}).")
        .format(label=plan.position.label, mu=c.q(lt.scale, sig=3)))
    _pairs(c, s)
    rows = [[f"${fsym(c, x.symbol)}$", f"${pt(x.point)}$", n(x.force, decimals=D["force"]),
             n(x.arm, decimals=D["arm"]), n(x.moment, decimals=D["moment"])] for x in lt.terms]
    rows.append([t("Sum"), "", "", "", n(lt.total, decimals=D["moment"])])
    c.table("dyn_lever", t("Moments of the forces about the pole of the turned velocity plan (counter-clockwise "
                           "positive)"),
            [t("Force"), t("Point"), "$F$, " + t("N"), "$h$, " + t("mm"), "$F h$, " + t("N·mm")], rows,
            align=["center", "center", "right", "right", "right"], widths=[1, 0.8, 1.1, 1, 1.3])
    c.p(t("The balancing force from the equilibrium of the lever, $F_\"ур\" dot p a = abs(Σ F_i h_i)$, and the "
          "balancing moment:"))
    c.formula(c.calc('F_"ур" = abs(Σ F_i h_i)/(p a)', "{0}/{1}",
                     [V(abs(lt.total), decimals=D["moment"]), V(lt.pa, decimals=D["pa"])],
                     V(lt.balancing_force, decimals=D["balancing_force"]), t("N")),
              c.calc('M_"ур"^"Ж" = F_"ур" l_1', "{0} dot {1}",
                     [V(lt.balancing_force, decimals=D["balancing_force"]), V(lt.crank, exact=True)],
                     V(lt.balancing, decimals=D["balancing"]), t("N·m")),
              where=[('F_"ур"', t("the balancing force at the crank pin, N")),
                     ("p a", t("the image of the crank pin's velocity on the plan, mm")),
                     ("l_1", t("the length of the crank, m"))])
    mb = lt.kinetostatic
    diff = lt.difference_pct
    c.p(t("Its difference from the moment of the force analysis, $M_\"ур\"$ = {mb}:").format(
        mb=c.qty(mb, t("N·m"), decimals=D["balancing"])))
    rel, val = small_pct(diff, c.lang).split(" ", 1)  # to its digits; below 10⁻⁹ % a bound (rounding is no value)
    c.formula('Δ = (abs(M_"ур") - M_"ур"^"Ж")/abs(M_"ур") dot 100 ' + rel + " "
              + ("10^(-9)" if rel == "<" else mq(val)) + " " + c.u("%"))
    ok = abs(diff) < 1.0
    c.p((t("The two agree within 1 %, as required: both rest on the same exact velocity and acceleration plans, so "
           "they differ by the computer's rounding only.") if ok else
         t("The two differ by more than 1 % ({diff}).")).format(diff=c.pct_digits(abs(diff))))
    c.doc.claim(kind="linkage_zhukovsky", kinetostatic=mb, lever=lt.sense * lt.balancing, diff_pct=diff, ok=ok)


def _pairs(c: Ctx, s) -> None:
    """Where a couple stands on a link without a second joint (a slider turning with its moving
    guide), the point B′ of its pair: what it is, its distance along the guide and the pair's
    force M/l with the substitution (the lever's table names B′)."""
    from ...linkage.zhukovsky import pair_arm

    t = c.t
    mech = s.sheet1.mechanism
    kin = s.sheet1.cycle.kin
    i = s.force_position
    forces = s.lever.forces
    for k, f in enumerate(forces):
        if f.point in kin.z or k == 0 or not f.symbol.endswith("″"):
            continue
        first = forces[k - 1]
        base = f.symbol[:-1]
        couple = next((m for m in s.loading.couples if m.symbol == base), None)
        if couple is None:
            continue
        m = abs(float(couple.m[i]))
        size = abs(complex(f.force[i]))
        l = pair_arm(mech)
        from .linkage_part import role_name

        c.p(t("The {what} ({n}) turns with its moving guide and has no second joint, so its couple ${m}$ is replaced "
              "by a pair of forces across the guide: ${f1}$ at its pin ${a}$ and ${f2}$ at the point ${b}$ — the "
              "point of link {n} (of its guide line) at the distance $l = {l}$ m from ${a}$ along the guide. "
              "On the lever ${b}$ is drawn at its image ${img}$, the end of the ray $p {img}$ of its velocity "
              "$v_{bb} = v_{aa} + ω_{n} times {ab}$. The forces of the pair:").format(
                  what=role_name(c, s.sheet1, couple.link), img=f.point.lower(),
                  n=mech.link(couple.link).number, m=fsym(c, base), f1=fsym(c, first.symbol), f2=fsym(c, f.symbol),
                  a=pt(first.point), b=pt(f.point), l=c.q(l, sig=4), bb=pt(f.point), aa=pt(first.point),
                  ab=pt(first.point) + " " + pt(f.point)))
        c.formula(c.calc(f"{fsym(c, first.symbol)} = {fsym(c, f.symbol)} = {fsym(c, base)}/l", "{0}/{1}",
                         [V(m, sig=5), V(l, sig=4)], V(size, sig=4), t("N")))


# --- 4. the reduction to the crank, the driving moment --------------------------------------------------


def _reduction(c: Ctx, s) -> None:
    from ...linkage.loads import table_integral

    t, n = c.t, c.n
    d = s.dynamics
    positions = s.positions  # the cycle's: a four-stroke engine's two turns of them
    c.doc.add(Heading(2, t("Dynamic model: reduced moment and reduced moment of inertia")))
    gas = bool(s.input.gas)  # gas forces drive on one stroke and resist on the other: M_пр is not of resistances only
    c.p(t("The mechanism is replaced by its dynamic model: the crank with the reduced moment of the driving and "
          "resisting gas forces, the useful resistance and the weights and the reduced moment of inertia of all the "
          "links {cite:artobolevsky}, found from the equality of powers and of kinetic energies:") if gas else
        t("The mechanism is replaced by its dynamic model: the crank with the reduced moment of the resistance forces "
          "and weights and the reduced moment of inertia of all the links {cite:artobolevsky}, found from the "
          "equality of powers and of kinetic energies:"))
    m_pr = ('M_"пр"', t("the reduced moment of the gas forces (driving and resisting), the useful resistance and the "
                        "weights, N·m")) if gas else 'M_"пр"'
    c.formula('M_"пр" = 1/ω_1 Σ (F_i v_i cos α_i + M_i ω_i)',
              where=[m_pr, ("F_i, v_i", t("a force and the velocity of its point, N, m/s")),
                     ("α_i", t("the angle between them")), ("M_i, ω_i", t("a moment and the angular velocity of its "
                                                                        "link, N·m, rad/s"))])
    c.formula('J_"пр" = Σ (m_i (v_(S i)/ω_1)^2 + J_(S i) (ω_i/ω_1)^2) + J_"рот"',
              where=['J_"пр"', ("v_(S i)", t("the velocity of the centre of mass of link $i$, m/s")),
                     ('J_"рот"', t("the moment of inertia of the rotor and the gears reduced to the crank, kg·m²"))])
    sense = t("counter-clockwise") if d.sense > 0 else t("clockwise")
    c.p(t("Here the moments and works are taken positive when they drive the crank (it turns {sense}); $Δ φ$ is the "
          "angle the crank has turned from position 0 (not the crank angle $φ$ from the axis $x$ of Table "
          "{{tab:linkage_positions}}). The values at the positions (from the grid of every 0,5° on "
          "which the works are computed) are given in Table {{tab:dyn_reduced}}.").format(sense=sense))
    # a machine-motor (the gas forces do positive work over the cycle): the gas forces drive, their work is
    # A_д (of the indicator diagram), and the constant moment is the consumer's resisting moment M_с (the book's roles)
    motor = gas and float(d.A_r[-1]) > 0.0
    work = 'A_"д"' if motor and not s.input.tables else 'A_"с"'
    rows = []
    for p in positions:
        k = p.index
        at = lambda y: float(np.interp(p.travel, d.travel, y))  # noqa: E731
        rows.append([p.label, n(math.degrees(p.travel), decimals=1), n(d.sense * float(s.reduced_moment[k]), decimals=2),
                     n(float(s.reduced_inertia[k]), sig=5), n(at(d.A_r), decimals=2), n(at(d.dT), decimals=2)])
    rows.append(["0", n(math.degrees(float(d.travel[-1])), decimals=1), n(float(d.M_r[-1]), decimals=2), n(float(d.J_r[-1]), sig=5), n(float(d.A_r[-1]), decimals=2),
                 n(float(d.dT[-1]), decimals=2)])
    c.table("dyn_reduced", t("Reduced moment, reduced moment of inertia, work of the gas forces, resistances and "
                             "weights and change of the kinetic energy") if gas else
            t("Reduced moment, reduced moment of inertia, work of the resistances and change of the kinetic energy"),
            ["№", "$Δ φ$, °", '$M_"пр"$, ' + t("N·m"), '$J_"пр"$, ' + t("kg·m²"), f"${work}$, " + t("J"),
             "$Δ T$, " + t("J")], rows,
            align=["center"] + ["right"] * 5, widths=[0.6, 0.8, 1.1, 1.2, 1.1, 1.1])
    # the work of the resistances over the cycle
    ld, st = s.input.load, s.stroke
    a_c = float(d.A_r[-1])
    if s.input.tables != ((ld,) if ld is not None else ()):  # several table loads, or one off the output
        _several_works(c, s)
    elif ld is not None and st is not None:
        area = float(table_integral(ld, 1.0))
        if ld.kind == "force" and ld.direction is not None:
            from ...linkage.loads import _along

            k = _along(ld, st)
            c.p(t("The work of the resistances over a cycle: the weights do none (their centres come back), the useful "
                  "resistance of its own direction does work by its part along the guide, $cos α$ of it ($α$ the "
                  "angle between the force and the working motion), over the area $S_F$ under its diagram times the "
                  "stroke $H$:"))
            c.formula(c.calc('A_"с" = H S_F cos α', "{0} dot {1} dot ({2})", [V(st.length, sig=5), V(area, sig=6),
                                                                             V(k, sig=6)], V(a_c, sig=5), t("J")),
                      where=['A_"с"', ("H", t("the stroke of the output link, m")),
                             ("S_F", t("the area under the diagram of the useful resistance against the share of the "
                                       "stroke, N"))])
        elif ld.kind == "force":
            c.p(t("The work of the resistances over a cycle: the weights do none (their centres come back), the useful "
                  "resistance takes the area $S_F$ under its diagram times the stroke $H$:"))
            c.formula(c.calc('A_"с" = -H S_F', "-{0} dot {1}", [V(st.length, sig=5), V(area, sig=6)], V(a_c, sig=5),
                             t("J")),
                      where=['A_"с"', ("H", t("the stroke of the output link, m")),
                             ("S_F", t("the area under the diagram of the useful resistance against the share of the "
                                       "stroke, N"))])
        else:
            c.p(t("The work of the resistances over a cycle: the weights do none (their centres come back), the useful "
                  "resistance takes the area $S_M$ under its diagram times the swing $ψ$ of the rocker:"))
            c.formula(c.calc('A_"с" = -ψ S_M', "-{0} dot {1}", [V(st.length, sig=5), V(area, sig=6)], V(a_c, sig=5),
                             t("J")),
                      where=['A_"с"', ("ψ", t("the swing of the output rocker, rad")),
                             ("S_M", t("the area under the diagram of the resistance moment against the share of the "
                                       "swing, N·m"))])
    if s.input.gas:
        from ...linkage.gas import _row_integral, piston

        works = []
        for gl in s.input.gas:
            ln = s.sheet1.mechanism.link(gl.link)
            h = piston(gl, s.sheet1.mechanism).stroke
            areas = [float(_row_integral(gl.travel, row, 1.0)) for row in gl.pressure]
            if gl.turns == 1 and s.turns == 1:
                s1, s2 = areas
                c.p(t("The gas force on the piston {p} does over a cycle the work of its indicator diagram: the area "
                      "between its rows times the piston's area and stroke (positive where the expansion's row lies "
                      "higher):").format(p=gl.link))
                c.formula(c.calc(f'A_(P {ln.number}) = A H (S_1 - S_2) dot 10^6', "{0} dot {1} dot ({2} - {3}) dot 10^6",
                                 [V(gl.area, exact=True), V(h, sig=6), V(s1, sig=6), V(s2, sig=6)],
                                 V(gl.area * h * (s1 - s2) * 1.0e6, sig=5), t("J")), numbered=False)
                works.append((f"A_(P {ln.number})", gl.area * h * (s1 - s2) * 1.0e6))
            elif gl.turns == 1:  # a one-turn diagram in a cycle of two turns: it works twice
                s1, s2 = areas
                c.p(t("The gas force on the piston {p} repeats its one-turn indicator diagram twice in the cycle of two "
                      "turns: twice the area between its rows times the piston's area and stroke:").format(p=gl.link))
                c.formula(c.calc(f'A_(P {ln.number}) = 2 A H (S_1 - S_2) dot 10^6',
                                 "2 dot {0} dot {1} dot ({2} - {3}) dot 10^6",
                                 [V(gl.area, exact=True), V(h, sig=6), V(s1, sig=6), V(s2, sig=6)],
                                 V(2.0 * gl.area * h * (s1 - s2) * 1.0e6, sig=5), t("J")), numbered=False)
                works.append((f"A_(P {ln.number})", 2.0 * gl.area * h * (s1 - s2) * 1.0e6))
            else:
                s1, s2, s3, s4 = areas
                c.p(t("The gas force on the piston {p} does over its cycle of two turns the work of its indicator "
                      "diagram: the area of its loop — under the rows of expansion and intake (away from the head) less "
                      "under those of exhaust and compression (towards it) — times the piston's area and stroke:")
                    .format(p=gl.link))
                # each area after the first with its own sign folded into the operator: «− 0,0126», not «+ −0,0126»
                signs = [(1 if k % 2 == 0 else -1) * (1 if a >= 0 else -1) for k, a in enumerate(areas)]
                terms = "{2}" if s1 >= 0 else "-{2}"
                terms += "".join(f" {'+' if sg > 0 else '-'} {{{k + 2}}}" for k, sg in enumerate(signs[1:], start=1))
                c.formula(c.calc(f'A_(P {ln.number}) = A H (S_1 - S_2 + S_3 - S_4) dot 10^6',
                                 "{0} dot {1} dot (" + terms + ") dot 10^6",
                                 [V(gl.area, exact=True), V(h, sig=6)] + [V(abs(a), sig=6) for a in areas],
                                 V(gl.area * h * (s1 - s2 + s3 - s4) * 1.0e6, sig=5), t("J")), numbered=False)
                works.append((f"A_(P {ln.number})", gl.area * h * (s1 - s2 + s3 - s4) * 1.0e6))
        if ld is None:  # the gas forces alone: their works are A_с, driving on one stroke, resisting on the other
            c.p(t("The weights do no work over a cycle (their centres come back), so the work of the applied forces "
                  "over the cycle is the gas forces' (negative: over the cycle they take work from the motor):")
                if a_c < 0 else
                t("The weights do no work over a cycle (their centres come back), so the work of the applied forces "
                  "over the cycle is the gas forces' (positive: over the cycle they drive the machine):"))
            vals = [V(w, sig=5) for _, w in works]
            what = (t("the work of the gas forces, the driving forces of the engine, over a cycle, J") if motor else
                    t("the work of the gas forces, the resistances and the weights over a cycle, J"))
            if len(works) == 1:  # one term: «A_с = A_P3 = 700,04 J», not «= 700,04 = 700,04»
                c.formula(c.calc(f"{work} = {works[0][0]}", None, (), V(a_c, sig=5), t("J")), where=[(work, what)])
            else:
                sub = " + ".join("({%d})" % k if w < 0 and k else "{%d}" % k for k, (_, w) in enumerate(works))
                c.formula(c.calc(f"{work} = " + " + ".join(sym for sym, _ in works), sub, vals, V(a_c, sig=5), t("J")),
                          where=[(work, what)])
    m = abs(d.M_d)
    cycle = "2 π" if s.turns == 1 else "4 π"  # the cycle of a four-stroke engine: two turns, 4π rad
    if motor:
        c.p(t("The machine is an engine: over the cycle the gas forces, its driving forces, do the positive work "
              "${a}$ of the indicator diagram. The machine it drives (the consumer: a pump, a generator) resists with "
              "a constant moment reduced to the crank, $M_\"с\"$; over a steady cycle its work equals the driving "
              "work, so").format(a=work))
        c.formula(c.calc(f'M_"с" = abs({work})/({cycle})', "{0}/(%s)" % cycle, [V(abs(a_c), sig=6)], V(m, sig=5),
                         t("N·m")),
                  where=[('M_"с"', t("the consumer's resisting moment reduced to the crank, constant, N·m"))])
        c.p(t("It acts against the crank's rotation: in the sign of Table {{tab:dyn_reduced}} it is $-M_\"с\"$ = {mm}. "
              "The gear mechanism of sheet 4 passes this moment from the crank to the consumer.").format(
            mm=c.qty(-m, t("N·m"), sig=5)))
        c.doc.claim(kind="linkage_drive_moment", moment=m, work=a_c)
        c.p(t("The consumer's work grows linearly against the rotation, $A_\"с\" = -M_\"с\" Δ φ$ ($Δ φ$ in rad), and "
              "the kinetic energy of the machine changes by $Δ T = {a} + A_\"с\" = {a} - M_\"с\" Δ φ$ (Table "
              "{{tab:dyn_reduced}}); over the cycle $Δ T$ comes back to zero.").format(a=work))
    else:
        c.p(t("Over a steady cycle the driving work equals the resistance work, so the constant driving moment of the "
              "motor reduced to the crank is"))
        c.formula(c.calc(f'M_"д" = abs(A_"с")/({cycle})', "{0}/(%s)" % cycle, [V(abs(a_c), sig=6)], V(m, sig=5),
                         t("N·m")), where=['M_"д"'])
        c.p(t("This is the mean reduced moment $M$ = {m} by which the power of the motor is chosen in the chapter on the "
              "gear mechanisms.").format(m=c.qty(m, t("N·m"), sig=5)))
        c.doc.claim(kind="linkage_drive_moment", moment=m, work=a_c)
        c.p(t("The driving work grows linearly, $A_\"д\" = M_\"д\" Δ φ$, and the kinetic energy of the machine changes by "
              "$Δ T = A_\"д\" + A_\"с\"$ (Table {tab:dyn_reduced}); over the cycle $Δ T$ comes back to zero."))
    if c.has("linkage_dynamics") and s.turns > 1:
        c.p(t("The diagrams of $M_\"пр\"$ and $M_\"д\"$, of $Δ T$ (with $Δ T_\"I\"$ of the flywheel's calculation) and of "
              "$J_\"пр\"$ over the cycle of two turns (0 … 720°) are shown in Figure {fig:linkage_dynamics}."))
        c.fig("linkage_dynamics", t("Reduced moments, change of the kinetic energy and reduced moment of inertia over "
                                    "the cycle of two turns"))
    elif c.has("linkage_dynamics"):
        c.p(t("The diagrams of $M_\"пр\"$ and $M_\"д\"$, of $Δ T$ (with $Δ T_\"I\"$ of the flywheel's calculation) and of "
              "$J_\"пр\"$ over the crank's turn are shown in Figure {fig:linkage_dynamics}."))
        c.fig("linkage_dynamics", t("Reduced moments, change of the kinetic energy and reduced moment of inertia over "
                                    "the crank's turn"))


def _several_works(c: Ctx, s) -> None:
    """Each table load's work over a cycle, −(its link's stroke or swing)·(the area under its diagram)
    (cos α of it for a force of its own direction): every one takes its own area on its own stroke."""
    from ...linkage.loads import _along, table_integral

    t = c.t
    mech = s.sheet1.mechanism
    c.p(t("The work of the resistances over a cycle: the weights do none (their centres come back); each useful "
          "resistance takes the area under its diagram times its own link's stroke $H$ (a moment: times its swing $ψ$, "
          "rad), a force of its own direction only by its part along the guide, $cos α$ of it ($α$ the angle between "
          "the force and the working motion):"))
    lines = []
    for ld, st in zip(s.input.tables, s.strokes):
        if st is None:
            continue
        k = mech.link(ld.link).number
        area = float(table_integral(ld, 1.0))
        along = _along(ld, st)
        work = along * st.length * area
        if ld.kind == "moment":
            lines.append(c.calc(f'A_("с{k}") = -ψ_{k} S_(M {k})', "-{0} dot {1}", [V(st.length, sig=5), V(area, sig=6)],
                                V(work, sig=5), t("J")))
        elif ld.direction is not None:
            lines.append(c.calc(f'A_("с{k}") = H_{k} S_(F {k}) cos α_{k}', "{0} dot {1} dot ({2})",
                                [V(st.length, sig=5), V(area, sig=6), V(along, sig=6)], V(work, sig=5), t("J")))
        else:
            lines.append(c.calc(f'A_("с{k}") = -H_{k} S_(F {k})', "-{0} dot {1}", [V(st.length, sig=5), V(area, sig=6)],
                                V(work, sig=5), t("J")))
    c.formula(*lines, where=[("H_i, ψ_i", t("the stroke of link i, m, or its swing, rad")),
                             ("S_(F i), S_(M i)", t("the area under the diagram of its useful resistance against the share "
                                                    "of its stroke, N or N·m"))])
    if s.input.gas:
        c.p(t("With the gas forces' works below, their sum is the work of the resistances over the cycle, "
              '$A_"с"$ = {a} J.').format(a=c.n(float(s.dynamics.A_r[-1]), sig=5)))
    else:
        c.p(t('Their sum is the work of the resistances over the cycle, $A_"с"$ = {a} J.').format(
            a=c.n(float(s.dynamics.A_r[-1]), sig=5)))


# --- 5. the flywheel --------------------------------------------------------------------------------


def _flywheel(c: Ctx, s) -> None:
    t, n = c.t, c.n
    d, fw = s.dynamics, s.flywheel
    if fw is None:
        c.p(t("The allowed coefficient of speed fluctuation is not given: the flywheel is not computed."))
        return
    me, wi = fw.mertsalov, fw.wittenbauer
    c.doc.add(Heading(2, t("Moment of inertia of the flywheel")))
    c.p(t("The flywheel keeps the crank speed within the allowed coefficient of speed fluctuation "
          "$δ = (ω_max - ω_min)/ω_1 = {delta}$. By N. I. Mertsalov's method {{cite:artobolevsky}} the links are split "
          "into the first group of constant reduced inertia $J_\"I\"$ (the crank, the rotor and the flywheel) and the "
          "second, $J_\"II\" (φ) = J_\"пр\" - J_\"кр\" - J_\"рот\"$; the kinetic energy of the second group is taken at "
          "the mean speed, and the first group's changes by").format(delta=c.q(fw.delta, sig=4)))
    c.formula('Δ T_"I" = Δ T - (J_"II" ω_1^2)/2',
              where=[('Δ T_"I"', t("the change of the kinetic energy of the first group, J")),
                     ('J_"II"', t("the reduced moment of inertia of the second group, kg·m²"))])
    hi, lo = float(me.dT_I[me.i_max]), float(me.dT_I[me.i_min])
    deg = lambda k: c.qd(math.degrees(float(d.travel[k])), decimals=1)  # noqa: E731
    text = (t("Over the turn $Δ T_\"I\"$ is largest at $Δ φ = {phi_max}$ and smallest at $Δ φ = {phi_min}$; the moment "
              "of inertia the first group needs and the flywheel's:") if s.turns == 1 else
            t("Over the cycle of two turns $Δ T_\"I\"$ is largest at $Δ φ = {phi_max}$ and smallest at $Δ φ = {phi_min}$; "
              "the moment of inertia the first group needs and the flywheel's:"))
    c.p(text.format(phi_max=deg(me.i_max), phi_min=deg(me.i_min)))
    vals = [V(hi, sig=6), V(lo, sig=6), V(fw.delta, exact=True), V(fw.omega_mean, sig=5)]
    c.formula(c.calc('J_"I" = (Δ T_("I" max) - Δ T_("I" min))/(δ ω_1^2)', _neg("({0} - {1})/({2} dot {3}^2)", vals, 1),
                     vals, V(me.J_I, sig=5), t("kg·m²")))
    j_crank = d.J_first - d.J_rotor
    vals = [V(me.J_I, sig=6), V(j_crank, sig=4), V(d.J_rotor, exact=True)]
    c.formula(c.calc('J_"м" = J_"I" - J_"кр" - J_"рот"', "{0} - {1} - {2}", vals, V(me.J_fl, sig=5), t("kg·m²")),
              where=[('J_"м"', t("the moment of inertia of the flywheel, kg·m²")),
                     ('J_"кр"', t("the moment of inertia of the crank about its axis, kg·m²"))])
    needed = me.J_fl > 0
    c.doc.claim(kind="linkage_flywheel", needed=needed, J_fl=me.J_fl, J_I=me.J_I, delta=fw.delta)
    # Wittenbauer
    c.p(t("The energy–mass diagram of F. Wittenbauer, $Δ T$ against $J_\"пр\"$, checks it: the tangents to the curve "
          "at the slopes $\"tg\" ψ_max = ω_max^2/2$ and $\"tg\" ψ_min = ω_min^2/2$, $ω_(max, min) = ω_1 (1 ± δ/2)$, "
          "cut the segment $k l$ on the axis of $Δ T$:"))
    c.formula(c.calc('ω_max = ω_1 (1 + δ/2)', "{0} dot (1 + {1}/2)", [V(fw.omega_mean, sig=6), V(fw.delta, exact=True)],
                     V(fw.omega_max, sig=5), t("rad/s")),
              c.calc('ω_min = ω_1 (1 - δ/2)', "{0} dot (1 - {1}/2)", [V(fw.omega_mean, sig=6), V(fw.delta, exact=True)],
                     V(fw.omega_min, sig=5), t("rad/s")))
    vals = [V(wi.c_max, sig=6), V(wi.c_min, sig=6), V(wi.slope_max, sig=6), V(wi.slope_min, sig=6)]
    c.formula(c.calc('J_"м"^"В" = (k l)/("tg" ψ_max - "tg" ψ_min)', _neg("({0} - {1})/({2} - {3})", vals, 1), vals,
                     V(wi.J_fl, sig=5), t("kg·m²")),
              where=[("k l", t("the segment between the tangents on the axis of $Δ T$, J"))])
    if needed and wi.J_fl > 0:
        diff = 100.0 * (me.J_fl - wi.J_fl) / wi.J_fl
        c.p(t("The two differ by {diff}: Mertsalov's method neglects the change of the second group's energy with the "
              "speed. The flywheel of Mertsalov's method is taken, $J_\"м\"$ = {j}.").format(
            diff=c.pct(abs(diff)), j=c.qty(me.J_fl, t("kg·m²"), sig=5)))
        c.doc.claim(kind="linkage_flywheel_methods", diff_pct=diff, mertsalov=me.J_fl, wittenbauer=wi.J_fl)
    elif not needed:
        c.p(t("$J_\"м\" <= 0$: the crank, the rotor and the links alone keep the speed within $δ$, no flywheel is "
              "needed."))
    if fw.size is not None:
        _size(c, fw)
    c.p((t("With the flywheel the crank speed changes over the turn between {w_min} and {w_max} rad/s: "
           "$δ = {delta}$.") if s.turns == 1 else
         t("With the flywheel the crank speed changes over the cycle of two turns between {w_min} and {w_max} rad/s: "
           "$δ = {delta}$.")).format(w_min=n(float(fw.omega.min()), decimals=4), w_max=n(float(fw.omega.max()), decimals=4),
                                  delta=c.q(fw.delta_actual, sig=3)))
    c.doc.claim(kind="linkage_delta_actual", delta=fw.delta, actual=fw.delta_actual)


def _size(c: Ctx, fw) -> None:
    t = c.t
    z = fw.size
    rho = c.r.linkage.input.dynamics.density
    psi_b = z.b / z.D
    mm = t("mm")
    if z.kind == "disc":
        c.p(t("The flywheel is a solid steel disc of width $b = ψ_b D$ ($ψ_b = {psi}$, $ρ = {rho}$ kg/m³): "
              "$J_\"м\" = m D^2/8$, $m = ρ π D^2 b/4$, so").format(psi=c.q(psi_b, sig=3), rho=c.q(rho, sig=4)))
        c.formula(c.calc('D = ((32 J_"м")/(π ρ ψ_b))^(1/5)', "((32 dot {0})/(π dot {1} dot {2}))^(1/5)",
                         [V(z.J, sig=6), V(rho, exact=True), V(psi_b, sig=4)], V(z.D, sig=4), t("m")),
                  where=[("D", t("the diameter of the flywheel, m")), ("ψ_b", t("the ratio of its width to the diameter")),
                         ("ρ", t("the density of steel, kg/m³"))])
        c.formula(c.calc("b = ψ_b D", "{0} dot {1}", [V(psi_b, sig=4), V(z.D, sig=5)], V(z.b, sig=4), t("m")),
                  c.calc("m = (ρ π D^2 b)/4", "({0} dot π dot {1}^2 dot {2})/4",
                         [V(rho, exact=True), V(z.D, sig=5), V(z.b, sig=5)], V(z.m, sig=4), t("kg")))
    else:
        psi_h = z.h / z.b
        c.p(t("The flywheel is a steel rim of width $b = ψ_b D$ and thickness $h = ψ_h b$ at the mean diameter $D$ "
              "($ψ_b = {psi}$, $ψ_h = {psi_h}$, $ρ = {rho}$ kg/m³): $J_\"м\" = m D^2/4$, $m = ρ π D b h$, so").format(
            psi=c.q(psi_b, sig=3), psi_h=c.q(psi_h, sig=3), rho=c.q(rho, sig=4)))
        c.formula(c.calc('D = ((4 J_"м")/(π ρ ψ_b^2 ψ_h))^(1/5)', "((4 dot {0})/(π dot {1} dot {2}^2 dot {3}))^(1/5)",
                         [V(z.J, sig=6), V(rho, exact=True), V(psi_b, sig=4), V(psi_h, sig=4)], V(z.D, sig=4), t("m")),
                  where=[("D", t("the mean diameter of the rim, m")), ("ψ_b", t("the ratio of its width to the diameter")),
                         ("ψ_h", t("the ratio of its thickness to the width")), ("ρ", t("the density of steel, kg/m³"))])
        c.formula(c.calc("b = ψ_b D", "{0} dot {1}", [V(psi_b, sig=4), V(z.D, sig=5)], V(z.b, sig=4), t("m")),
                  c.calc("h = ψ_h b", "{0} dot {1}", [V(psi_h, sig=4), V(z.b, sig=5)], V(z.h, sig=4), t("m")),
                  c.calc("m = ρ π D b h", "{0} dot π dot {1} dot {2} dot {3}",
                         [V(rho, exact=True), V(z.D, sig=5), V(z.b, sig=5), V(z.h, sig=5)], V(z.m, sig=4), t("kg")))
    dims = t("$D$ = {d}, $b$ = {b}").format(d=c.qty(z.D * 1000, mm, decimals=0), b=c.qty(z.b * 1000, mm, decimals=0))
    if z.h is not None:
        dims += t(", $h$ = {h}").format(h=c.qty(z.h * 1000, mm, decimals=0))
    c.p(t("The flywheel: {dims}, mass {m}.").format(dims=dims, m=c.qty(z.m, t("kg"), decimals=1)))
