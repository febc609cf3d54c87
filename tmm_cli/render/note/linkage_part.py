"""The chapter on the lever mechanism's structure and kinematics (sheet 1), from a Sheet1.

The standard method of a TMM textbook (Artobolevsky; METHOD.md "Sheets 1 and 2"): Chebyshev's
formula and the Assur groups; the positions, the stroke and the time ratio K; the velocity and the
acceleration plans of one position, group by group in the order of the structural formula, each
vector equation written out and each magnitude substituted; the table of all positions. Every
number is read from the result (:class:`~tmm_cli.linkage.sheet1.Sheet1`); the plans' magnitudes
are the exact ones the plans are drawn from, their segments the drawing's. The decisions the text
states are recorded as claims that the tests check.
"""

from __future__ import annotations

import math
import re

from ...i18n import N_
from ...linkage.positions import PRESSURE_WARN_DEG, displacement, output_coordinate
from ...linkage.scales import PLAN_MM, SCHEME_MM
from ...linkage.vector_plans import DEGENERATE_MM, book_symbols, degeneracy, middle_of_working, plans as plans_of
from ...linkage.roles import link_roles
from ..terminal.mechanism import ROLE_WORDS, pattern
from .ctx import Ctx, V, sheet1_of
from .model import Heading, literal
from .synthesis_part import chapter_title, synthesis_section

_PAIR = {"R": N_("revolute"), "P": N_("prismatic")}
_NAME = re.compile(r"[^\W\d_]\d*['′]*")


def linkage_chapter(c: Ctx) -> None:
    s = sheet1_of(c.r)
    if s is None:
        return
    c.doc.add(Heading(1, chapter_title(c, s), "chapter", "linkage"))
    synthesis_section(c, s)  # «Синтез механизма» when the file records its task (tmm synth, issue 33)
    _structure(c, s)
    _positions(c, s)
    if s.plans:
        _plans(c, s, s.plans[0])
    _table(c, s)


# --- names as math -----------------------------------------------------------------------------------


def pm(name: str) -> str:
    """A joint's or a point's name inside typst math, as the book writes it: 'A', "B'", 'O1' → 'O_1'
    (typst would read O1 as a variable's name); anything else upright, as a string."""
    m = _NAME.fullmatch(name)
    if not m:
        return '"' + name.replace('"', "") + '"'
    letter, digits, primes = name[0], name[1:].rstrip("'′"), name[1:][len(name[1:].rstrip("'′")):]
    return letter + primes + (f"_{digits}" if digits else "")


def jm(name: str) -> str:
    """A joint's name in the text, as inline math ($O_1$)."""
    return "$" + pm(name) + "$"


def sub(*names: str) -> str:
    """A subscript of joint names: '_A' or '_(O1 A)'."""
    body = " ".join(pm(n) for n in names)
    return "_" + (body if len(names) == 1 and len(body) == 1 else "(" + body + ")")


def label_math(label: str) -> str:
    """A plan point's label: 'p', 'π', 'a3' → 'a_3', 'n2' → 'n_2'."""
    m = re.fullmatch(r"([^\W\d_])(\d+)", label)
    if m:
        return f"{m[1]}_{m[2]}"
    return label if _NAME.fullmatch(label) else '"' + label.replace('"', "") + '"'


def _split_points(text: str, names: list[str]) -> list[str]:
    """'A3A2' → ['A3', 'A2'] by the longest known name first."""
    out, i = [], 0
    by_len = sorted(names, key=len, reverse=True)
    while i < len(text):
        for n in by_len:
            if text.startswith(n, i):
                out.append(n)
                i += len(n)
                break
        else:
            return [text]
    return out


class _Sym:
    """The plans' vector symbols ('v_A3A2', 'a^n_BA') as typst math."""

    def __init__(self, mech):
        names = list(mech.joint_names)
        for g in mech.groups:
            if g.kind in ("RPR", "RPP"):
                names += [f"{g.joints[0]}{n}" for n in g.numbers]
            # the points of the guides' links under a block (b3 of a slider on the slotted link 3, …)
            point = {"RRP": g.joints[-1], "PRP": g.joints[0], "RPP": f"{g.joints[0]}{g.numbers[1]}"}.get(g.kind)
            for gd in ((g.guide,) if g.guide is not None else ()) + g.guides:
                if gd.moving and point is not None:
                    names.append(f"{point}{mech.link(gd.link).number}")
        self.book = book_symbols(mech)  # 'v_BB3' → 'v_B5B3': both points with their links' numbers
        for core, book in self.book.items():
            a, b = core.partition("_")[2], book.partition("_")[2]
            k = 0
            while k < min(len(a), len(b)) and a[-1 - k] == b[-1 - k]:
                k += 1
            names.append(b[:len(b) - k])  # 'B5': the point of the sliding link
        self.names = names

    def parts(self, symbol: str) -> tuple[str, str, list[str]]:
        head, _, pts = self.book.get(symbol, symbol).partition("_")
        base, _, sup = head.partition("^")
        return base, sup, _split_points(pts, self.names)

    def vec(self, symbol: str) -> str:
        base, sup, pts = self.parts(symbol)
        return f"arrow({base})" + (f"^{sup}" if sup else "") + sub(*pts)

    def mag(self, symbol: str) -> str:
        base, sup, pts = self.parts(symbol)
        return base + (f"^{sup}" if sup else "") + sub(*pts)


# --- 1 structure -------------------------------------------------------------------------------------


def _lengths(m) -> dict[str, float]:
    size = {m.links[0].name: m.crank.length}
    for g in m.groups:
        for name, length in zip(g.links, g.lengths):
            size[name] = length
    return size


def role_name(c: Ctx, s, link: str) -> str:
    """A link by its role and name, the one name it has everywhere in the note: «кулиса Y»,
    «кулисный камень B», «коромысло DB» (the words of Table 1, :func:`~tmm_cli.linkage.roles.link_roles`)."""
    return f"{c.t(ROLE_WORDS[link_roles(s)[link]])} {link}"


def role_genitive(c: Ctx, s, link: str, named: bool = True) -> str:
    """The same name in the genitive, for «ход ползуна B», «ход кулисы Y» (en: "slider B"); without
    the link's name where a symbol follows («ход ползуна H»)."""
    role = link_roles(s)[link]
    word = {"crank": c.tc("genitive", "crank"), "rocker": c.tc("genitive", "rocker"),
            "coupler": c.tc("genitive", "connecting rod"), "slider": c.tc("genitive", "slider"),
            "slotted": c.tc("genitive", "slotted link"), "block": c.tc("genitive", "slotted-link block")}[role]
    return f"{word} {link}" if named else word


def _link_words(c: Ctx, s) -> str:
    roles = link_roles(s)
    return ", ".join(f"{ln.number} — {c.t(ROLE_WORDS[roles[ln.name]])} {ln.name}" for ln in s.mechanism.links)


def _structure(c: Ctx, s) -> None:
    t, n = c.t, c.n
    m, st = s.mechanism, s.structure
    c.doc.add(Heading(2, t("Structure of the mechanism")))
    name = literal(m.name) if m.name else t("Mechanism")  # a person's text: set as typed
    c.p(t("The mechanism «{name}» consists of the frame 0 and {count} moving links: {links}. The links and the "
          "kinematic pairs are given in Tables {{tab:linkage_links}} and {{tab:linkage_groups}}.").format(
        name=name, count=st.n, links=_link_words(c, s)))
    mm = t("mm")
    size = _lengths(m)
    rows = [["0", t("frame"), t("fixed joints {joints}").format(joints=", ".join(m.frame)), "—"]]
    roles = link_roles(s)
    for ln in m.links:
        rows.append([str(ln.number), ln.name, t(ROLE_WORDS[roles[ln.name]]),
                     n(size[ln.name] * 1000) if ln.name in size else "—"])
    c.table("linkage_links", t("Links of the mechanism"), ["№", t("Link"), t("Kind"), f"$l$, {mm}"], rows,
            align=["center", "center", "left", "center"], widths=[0.5, 1.0, 2.2, 1.0])
    c.p(t("Every kinematic pair of the mechanism is a lower pair of class 5 (a revolute or a prismatic pair), there are no "
          "higher pairs. The degree of freedom by Chebyshev's formula {cite:artobolevsky}:"))
    c.formula(c.calc("W = 3 n - 2 p_5 - p_4", "3 dot {0} - 2 dot {1} - {2}",
                     [V(st.n, exact=True), V(st.p5, exact=True), V(st.p4, exact=True)], V(st.dof, exact=True)),
              where=["W", "n", "p_5", "p_4"])
    if st.dof == 1:
        c.p(t("One degree of freedom: the position of the crank 1 determines the positions of all links."))
    c.doc.claim(kind="linkage_dof", n=st.n, p5=st.p5, p4=st.p4, dof=st.dof)
    c.p(t("The mechanism is formed by attaching Assur groups to the class I mechanism (the frame 0 with the crank 1) "
          "{cite:artobolevsky}; they are given in Table {tab:linkage_groups} in the order of attachment."))
    rows = []
    for g in st.groups:
        pairs = ", ".join(f"{p.joint} ({p.links[0]}–{p.links[1]}, {c.t(_PAIR[p.kind])})" for p in g.pairs)
        if g.index == 0:
            what = t("class I mechanism")
        else:
            what = t("class II, order 2, kind {kind} ({pattern})").format(kind=g.kind, pattern=pattern(g.pattern, c.lang))
        rows.append([g.formula, ", ".join(str(x) for x in g.links), pairs, what])
    c.table("linkage_groups", t("Structural groups of the mechanism"),
            [t("Member"), t("Links"), t("Kinematic pairs (links, kind)"), t("Class, order, kind")], rows,
            align=["center", "center", "left", "left"], widths=[0.9, 0.7, 2.6, 1.8])
    formula = " arrow.r ".join(f'"{_roman(g.klass)}"({",".join(str(x) for x in g.links)})' for g in st.groups)
    c.p(t("The structural formula of the mechanism:"))
    c.formula(formula, numbered=False)
    c.p(t("The highest class of its groups is {klass}: the mechanism is of class {klass}.").format(
        klass=_roman(st.mechanism_class)))
    c.doc.claim(kind="linkage_class", classes=tuple(g.klass for g in st.groups), mechanism_class=st.mechanism_class)


def _roman(k: int) -> str:
    return {1: "I", 2: "II", 3: "III", 4: "IV"}[k]


# --- 2 positions ---------------------------------------------------------------------------------------


def _deg(x: float) -> float:
    d = math.degrees(x) % 360.0
    return 0.0 if d >= 360.0 - 5e-10 else d


def _positions(c: Ctx, s) -> None:
    t, n = c.t, c.n
    m, cy = s.mechanism, s.cycle
    cr = m.crank
    c.doc.add(Heading(2, t("Positions of the mechanism")))
    sense = t("counter-clockwise") if cr.sense > 0 else t("clockwise")
    c.p(t("The crank {crank} of length $l{sub} = {length}$ m turns {sense} at $n_1 = {rpm}$ rpm; its angular "
          "speed is taken constant:").format(crank=m.links[0].name, sub=sub(cr.pivot, cr.joint),
                                             length=c.q(cr.length), sense=sense, rpm=c.q(cr.rpm, sig=6)))
    c.formula(c.calc("ω_1 = (π n_1)/30", "(π dot {0})/30", [V(cr.rpm, exact=True)], V(abs(cr.omega), sig=4),
                     t("rad/s")), where=["ω_1", "n_1"])
    out = m.output
    slider = out.kind == "slider"
    what = role_name(c, s, out.link)  # the output link by its role, as in Table 1 (кулиса Y, кулисный камень B, …)
    rule = cy.start_rule
    if rule == "gas":  # a piston of an engine or a compressor: its dead centre nearest the cylinder's head
        text = t("The output link is {what}, the piston of a cylinder. Position 0 is its dead centre nearest the "
                 "cylinder head, where its indicator diagram begins (the piston then moves away from the head); the "
                 "gas force acts on both strokes. The crank angle of position 0 is $φ_0 = {start}°$.")
    elif rule == "working":
        text = t("The output link is {what}. Position 0 is its extreme position where the working stroke begins; the "
                 "working stroke is the slower one (it takes the larger crank angle). The crank angle of position 0 "
                 "is $φ_0 = {start}°$.")
    elif rule == "load":
        text = t("The output link is {what}. Position 0 is its extreme position where the working stroke begins; the "
                 "working stroke is the one on which the useful resistance acts. The crank angle of position 0 is "
                 "$φ_0 = {start}°$.")
    elif rule == "far":
        text = t("The output link is {what}. Both of its strokes take the same crank angle; position 0 is its extreme "
                 "position farthest from the crank's pivot (the outer dead centre), $φ_0 = {start}°$.")
    elif rule == "given":
        text = t("The output link is {what}. Position 0 is given by the task: $φ_0 = {start}°$.")
    else:
        text = t("The output link is {what}; it turns fully and has no extreme positions. Position 0 is taken at "
                 "$φ_0 = {start}°$.")
    first, last = cy.working_start(), cy.working_end()
    if rule == "given" and first is not None and first.index != 0:  # position 0 is not an extreme
        text += t(" The working stroke runs from the extreme position {start} to {end}; the output's displacement is "
                  "counted from {start}.").format(start=first.label, end=last.label)
        c.doc.claim(kind="linkage_working_extremes", start=first.label, end=last.label)
    c.p(text.format(what=what, start=c.q(_deg(cy.start), decimals=2)))
    c.doc.claim(kind="linkage_position0", rule=rule, phi0_deg=_deg(cy.start))
    step = 360.0 / m.positions
    primes = [p for p in cy.positions if not p.label.isdigit()]
    extra = ""
    if primes:
        extra = t(" The extreme positions of the output link that fall between them are added as {labels}.").format(
            labels=", ".join(p.label for p in primes))
    c.p(t("The crank's turn is divided into {count} positions every {step}°, numbered 0, 1, 2, … in the sense of its "
          "rotation.{extra} The scale of the scheme in all positions is $μ_l = {mu_l}$ m/mm, the round value with "
          "which it takes at most {room} mm.").format(count=m.positions, step=n(round(step, 2)), extra=extra,
                                                      mu_l=c.q(s.scheme_scale, sig=3), room=n(SCHEME_MM)))
    loads = m.extra.get("load")
    if isinstance(loads, list) and any(isinstance(x, dict) and "head" in x and isinstance(x.get("pressure"), list)
                                       and len(x["pressure"]) == 4 for x in loads):  # a four-stroke engine
        c.p(t("The engine is a four-stroke one: its working cycle takes two turns of the crank. The kinematics repeat "
              "every turn, so this chapter and sheet 1 take the positions of one turn; the force analysis and the "
              "dynamics (chapter 2) take both turns, the positions of the second turn numbered on, {a} … {b}.")
            .format(a=m.positions, b=2 * m.positions - 1))
    if cy.stroke is not None and cy.working is not None:
        first = next(p for p in cy.positions if p.extreme == "start")
        last = next(p for p in cy.positions if p.extreme == "end")
        wk, rt = math.degrees(cy.working), math.degrees(cy.returning)
        if slider:
            c.p(t("The stroke of the {whose} (the distance between its extreme positions {a} and {b}):").format(
                whose=role_genitive(c, s, out.link), a=first.label, b=last.label))
            mm = t("mm")
            c.formula(f"H = {c.q(cy.stroke * 1000, decimals=2)} {c.u(mm)}",
                      where=[("H", t("the stroke of the {whose}, mm").format(whose=role_genitive(c, s, out.link)))])
        else:
            c.p(t("The swing of the rocker (the angle between its extreme positions {a} and {b}):").format(
                a=first.label, b=last.label))
            c.formula(f"ψ = {c.qd(math.degrees(cy.stroke), decimals=2)}", where=["ψ"])
        c.p(t("From position {a} to position {b} the crank turns by the angle of the working stroke "
              "$φ_\"р.х\" = {wk}°$; the return stroke takes the rest of the turn, and the time ratio (the ratio of "
              "the mean speeds of the output link on the return and on the working stroke) is").format(
            a=first.label, b=last.label, wk=c.q(wk, decimals=2)))
        c.formula(c.calc('φ_"х.х" = 360 degree - φ_"р.х"', "{0} - {1}", [V(360, exact=True, deg=True),
                                                                         V(wk, decimals=2, deg=True)],
                         V(rt, decimals=2, deg=True)), where=['φ_"р.х"', 'φ_"х.х"'])
        c.formula(c.calc('K = φ_"р.х"/φ_"х.х"', "{0}/{1}", [V(wk, decimals=2), V(rt, decimals=2)],
                         V(cy.time_ratio, decimals=3)), where=["K"])
        c.doc.claim(kind="linkage_time_ratio", working_deg=wk, return_deg=rt, K=cy.time_ratio)
    for p in cy.pressure:
        g = m.groups[p.group - 1]
        worst = math.degrees(p.worst)
        if g.kind == "RPR" and not g.offset:  # a slot through the pivot; with an offset d, arctan(|d|/t)
            c.p(t("In group {group} ({kind}) the block acts on the slotted link at right angles to it: its pressure "
                  "angle is 0°.").format(group=p.group, kind=pattern(g.kind, c.lang)))
        else:
            ok = worst <= PRESSURE_WARN_DEG
            verdict = (t("within the usual limit of {limit}°") if ok else
                       t("above the usual limit of {limit}°: the group transmits motion poorly there")).format(
                limit=n(PRESSURE_WARN_DEG))
            c.p(t("The largest pressure angle of group {group} ({kind}) over the turn is {angle}° at $φ = {phi}°$, "
                  "{verdict}.").format(group=p.group, kind=pattern(g.kind, c.lang), angle=n(worst, decimals=2),
                                       phi=c.q(round(_deg(p.phi), 1) % 360.0, decimals=1), verdict=verdict))
        c.doc.claim(kind="linkage_pressure", group=p.group, worst_deg=worst, limit_deg=PRESSURE_WARN_DEG,
                    ok=worst <= PRESSURE_WARN_DEG)


# --- 3 the plans of one position ---------------------------------------------------------------------------


class _Plans:
    """What the plans' formulas need: the plan vectors by symbol, the numbers as printed."""

    def __init__(self, c: Ctx, s, pl):
        self.c, self.s, self.pl = c, s, pl
        self.m = s.mechanism
        self.sym = _Sym(self.m)
        i = pl.position.index
        k = s.cycle.kin
        self.z = {nm: complex(x[i]) for nm, x in k.z.items()}
        self.w = {nm: float(x[i]) for nm, x in k.omega.items()}
        self.e = {nm: float(x[i]) for nm, x in k.epsilon.items()}
        self.vel = {v.symbol: v for v in pl.velocity.vectors}
        self.acc = {v.symbol: v for v in pl.acceleration.vectors}

    def seg(self, v) -> str:
        return "(" + label_math(v.start) + " " + label_math(v.end) + ")"

    def tiny(self, x: float, plan=None) -> bool:
        """Zero to rounding (a plan's point on another: v_BA of a crank-slider at 90°)."""
        ref = max(abs(z) for z in plan.points.values()) if plan is not None else abs(self.m.crank.omega)
        return abs(x) <= 1e-9 * ref

    def measured(self, plan, vec, unit: str, mu: str) -> str:
        """``v_(B A) = (a b) μ_v = 3,6 · 0,01 = 0,036 м/с``: a magnitude read from the plan."""
        c = self.c
        if self.tiny(vec.magnitude, plan):
            return f"{self.sym.mag(vec.symbol)} = 0"
        return c.calc(self.sym.mag(vec.symbol), self.seg(vec) + f" {mu} = {{0}} dot {{1}}",
                      [V(vec.magnitude / plan.scale, decimals=1), V(plan.scale, exact=True)],
                      V(vec.magnitude, sig=4), unit)

    def drawn(self, plan, vec) -> str:
        """``(p a) = v_A/μ_v = 0,6283/0,01 = 62,83 мм``: a known vector's segment on the plan."""
        c = self.c
        mu = "μ_v" if plan.kind == "velocity" else "μ_a"
        if self.tiny(vec.magnitude, plan):
            return self.seg(vec) + " = 0"
        return c.calc(self.seg(vec) + " = " + self.sym.mag(vec.symbol) + "/" + mu, "{0}/{1}",
                      [V(vec.magnitude, sig=4), V(plan.scale, exact=True)],
                      V(vec.magnitude / plan.scale, decimals=1), c.t("mm"))


def _middle_of_working(cy, pos) -> bool:
    """Whether `pos` is the evenly spaced position nearest the middle of the working stroke."""
    return middle_of_working(cy) == pos.index


def _general_position(c: Ctx, middle: str, why) -> str:
    """Why the plans stand beside the middle of the working stroke: its plans are degenerate
    (:func:`~tmm_cli.linkage.vector_plans.degeneracy`)."""
    t = c.t
    if why.point is None:
        reason = (t("the velocity plan collapses to a straight line less than {mm} mm wide") if why.plan == "velocity"
                  else t("the acceleration plan collapses to a straight line less than {mm} mm wide"))
    else:
        reason = (t("the point {p} of the velocity plan lies within {mm} mm of its pole")
                  if why.plan == "velocity" else
                  t("the point {p} of the acceleration plan lies within {mm} mm of its pole"))
    reason = reason.format(p=_lc_math(why.point or ""), mm=c.n(DEGENERATE_MM))
    return t("the position nearest the middle of the working stroke in which the plans are not degenerate (in the "
             "middle, position {middle}, {reason}, and the groups' vector equations could not be checked on "
             "such plans)").format(middle=middle, reason=reason)


def _lc_math(name: str) -> str:
    return "$" + pm(name).lower() + "$"


def _sense(c: Ctx, x: float) -> str:
    return c.t("counter-clockwise") if x > 0 else c.t("clockwise")


def _plans(c: Ctx, s, pl) -> None:
    t = c.t
    m = s.mechanism
    P = _Plans(c, s, pl)
    pos = pl.position
    c.doc.add(Heading(2, t("Velocity and acceleration plans of position {label}").format(label=pos.label)))
    middle = _middle_of_working(s.cycle, pos)
    mid = middle_of_working(s.cycle)
    why = (degeneracy(m, plans_of(s.cycle, mid)) if not middle and s.mechanism.plan is None and mid is not None
           and pos.index == s.plans[0].position.index else None)
    where = (t("in the middle of the working stroke") if middle else
             t("the position the task names") if s.mechanism.plan is not None else
             _general_position(c, s.cycle.positions[mid].label, why) if why is not None else
             t("the position chosen for the plans"))
    c.p(t("The plans are built for position {label} ($φ = {phi}°$), {where}, by the vector equations of the groups in "
          "the order of the structural formula {{cite:artobolevsky}}: the velocities from the pole $p$, the "
          "accelerations from the pole $π$; the points of the fixed joints lie at the poles. The vectors of both plans "
          "are given in Table {{tab:linkage_plans}}.").format(label=pos.label, phi=c.q(_deg(pos.phi), decimals=2),
                                                              where=where))
    c.doc.claim(kind="linkage_plan_position", label=pos.label, middle=middle)
    ms, ms2, rad_s, rad_s2 = t("m/s"), t("m/s²"), t("rad/s"), t("rad/s²")
    cr = m.crank
    o, a = cr.pivot, cr.joint
    vp, ap = pl.velocity, pl.acceleration
    # --- velocities
    c.p(t("The velocity of the crank pin {a} is perpendicular to the crank and directed in the sense of its "
          "rotation:").format(a=jm(a)))
    va = P.vel[f"v_{a}"]
    c.formula(c.calc(f"v_{pm(a)} = ω_1 l{sub(o, a)}", "{0} dot {1}", [V(abs(cr.omega), sig=4), V(cr.length, exact=True)],
                     V(va.magnitude, sig=4), ms),
              where=[(f"v_{pm(a)}", t("the velocity of the crank pin {a}, m/s").format(a=jm(a))),
                     (f"l{sub(o, a)}", t("the length of the crank, m"))])
    c.p(t("The scale of the velocity plan is the round value with which its longest vector is at most {room} mm "
          "long:").format(room=c.n(PLAN_MM)))
    mu_v = t("(m/s)/mm")
    c.formula(f"μ_v = {c.q(vp.scale)} {c.u(mu_v)}", P.drawn(vp, va), *_points_line(c, P, 0, vp, ms, "μ_v"),
              where=["μ_v"])
    for g in m.groups:
        _group_velocity(c, P, g)
    # --- accelerations
    c.p(t("The crank turns at a constant speed ($ε_1 = 0$), so the acceleration of {a} is its normal acceleration, "
          "directed from {a} to {o}:").format(a=jm(a), o=jm(o)) if P.s.cycle.kin.eps1 == 0 else
        t("The acceleration of {a} has a normal and a tangential component:").format(a=jm(a)))
    if f"a_{a}" in P.acc and P.acc[f"a_{a}"].relation:
        aa = P.acc[f"a_{a}"]
        c.formula(c.calc(f"a_{pm(a)} = a^n_{pm(a)} = ω_1^2 l{sub(o, a)}", "{0}^2 dot {1}",
                         [V(abs(cr.omega), sig=4), V(cr.length, exact=True)], V(aa.magnitude, sig=4), ms2),
                  where=[(f"a_{pm(a)}", t("the acceleration of the crank pin {a}, m/s²").format(a=jm(a)))])
    else:
        an = P.acc[f"a^n_{a}"]
        at = P.acc[f"a^τ_{a}"]
        aa = P.acc[f"a_{a}"]
        c.formula(c.calc(f"a^n_{pm(a)} = ω_1^2 l{sub(o, a)}", "{0}^2 dot {1}",
                         [V(abs(cr.omega), sig=4), V(cr.length, exact=True)], V(an.magnitude, sig=4), ms2),
                  c.calc(f"a^τ_{pm(a)} = ε_1 l{sub(o, a)}", "{0} dot {1}",
                         [V(abs(P.s.cycle.kin.eps1), sig=4), V(cr.length, exact=True)], V(at.magnitude, sig=4), ms2),
                  where=[(f"a_{pm(a)}", t("the acceleration of the crank pin {a}, m/s²").format(a=jm(a)))])
    c.p(t("The scale of the acceleration plan, chosen the same way:"))
    mu_a = t("(m/s²)/mm")
    c.formula(f"μ_a = {c.q(ap.scale)} {c.u(mu_a)}", P.drawn(ap, aa), *_points_line(c, P, 0, ap, ms2, "μ_a"),
              where=["μ_a"])
    for g in m.groups:
        _group_acceleration(c, P, g)
    c.p(t("The angular velocities and accelerations of the links in position {label} (counter-clockwise positive):").format(
        label=pos.label))
    rows = []
    for ln in m.links:
        w, e = c.zero(P.w[ln.name], "rad/s"), c.zero(P.e[ln.name], "rad/s²")
        rows.append([str(ln.number), ln.name, c.n(w, sig=4), c.n(e, sig=4),
                     (_sense(c, w) if w != 0.0 else "—") + " / " + (_sense(c, e) if e != 0.0 else "—")])
    c.table("linkage_omega", t("Angular velocities and accelerations of the links, position {label}").format(label=pos.label),
            ["№", t("Link"), f"$ω$, {rad_s}", f"$ε$, {rad_s2}", t("Sense of ω / of ε")], rows,
            align=["center", "center", "right", "right", "left"], widths=[0.4, 0.8, 1.0, 1.0, 3.2])
    _vector_table(c, P)
    if c.has("linkage_plans"):
        from ..figures.note_scales import linkage_layout

        layout = linkage_layout(s)
        stacked = bool(layout.get("stacked"))
        if layout.get("own"):  # drawn at μ_v and μ_a above, the scales of the segments
            c.p(t("The plans are shown in Figure {fig:linkage_plans} at the scales $μ_v$ and $μ_a$ above (written on "
                  "it): the normal components dashed green, the tangential ones dashed orange, the relative ones "
                  "blue, the Coriolis ones red."))
        else:
            c.p(t("The plans are shown in Figure {fig:linkage_plans}, each at a scale of its own that fits the page "
                  "(written on it): the normal components dashed green, the tangential ones dashed orange, the "
                  "relative ones blue, the Coriolis ones red."))
        c.fig("linkage_plans", (t("Velocity plan (above) and acceleration plan (below) of position {label}") if stacked
                                else t("Velocity plan (left) and acceleration plan (right) of position {label}")).format(
            label=pos.label))


def _points_line(c: Ctx, P: _Plans, g_index: int, plan, unit: str, mu: str) -> list[str]:
    """The named points of the group's links, read from the plan (by similarity)."""
    group_of = {ln.name: ln.group for ln in P.m.links}
    vecs = P.vel if plan.kind == "velocity" else P.acc
    base = "v" if plan.kind == "velocity" else "a"
    out = []
    for pt in P.m.points:
        if group_of[pt.link] == g_index:
            out.append(P.measured(plan, vecs[f"{base}_{pt.name}"], unit, mu))
    return out


def _eq(P: _Plans, plan, group: int) -> list[str]:
    out = []
    for eq in plan.equations:
        if eq.group == group:
            sides = [" + ".join(P.sym.vec(x) for x in side) for side in eq.sides]
            out.append(P.sym.vec(eq.lhs) + " = " + " = ".join(sides))
    return out


def _omega_line(c: Ctx, P: _Plans, link: str, vec, length: float, exact: bool, l_sym: str) -> str:
    num = P.m.link(link).number
    if P.tiny(P.w[link]):
        return f"ω_{num} = 0"
    return c.calc(f"ω_{num} = {P.sym.mag(vec.symbol)}/{l_sym}", "{0}/{1}",
                  [V(vec.magnitude, sig=4), V(length, exact=exact, sig=9 if exact else 5)], V(abs(P.w[link]), sig=5), c.t("rad/s"))


def _eps_line(c: Ctx, P: _Plans, link: str, vec, length: float, exact: bool, l_sym: str) -> str:
    num = P.m.link(link).number
    if P.tiny(P.e[link], P.pl.acceleration):
        return f"ε_{num} = 0"
    return c.calc(f"ε_{num} = {P.sym.mag(vec.symbol)}/{l_sym}", "{0}/{1}",
                  [V(vec.magnitude, sig=4), V(length, exact=exact, sig=9 if exact else 5)], V(abs(P.e[link]), sig=5), c.t("rad/s²"))


def _group_velocity(c: Ctx, P: _Plans, g) -> None:
    t = c.t
    ms = t("m/s")
    vp = P.pl.velocity
    n2, n3 = g.numbers
    c.p(t("Group {index} (links {n2}, {n3}; {kind}):").format(index=g.index, n2=n2, n3=n3,
                                                              kind=pattern(g.kind, c.lang)))
    fixed = [j for j in g.known if j in P.m.frame]
    zero = [f"arrow(v){sub(j)} = 0" for j in fixed]
    if g.kind == "RPR":
        zero.insert(0, f"arrow(v){sub(g.joints[0] + str(n2))} = arrow(v){sub(g.joints[0])}")
    c.formula(*(_eq(P, vp, g.index) + zero))
    lines = []
    if g.kind in ("PRP", "RPP"):
        _sliding_group(c, P, g, vp, ms, "μ_v")
        return
    if g.kind == "RRR":
        ja, jb, jc = g.joints
        v1, v2 = P.vel[f"v_{jb}{ja}"], P.vel[f"v_{jb}{jc}"]
        lines += [P.measured(vp, v1, ms, "μ_v"), P.measured(vp, v2, ms, "μ_v"),
                  P.measured(vp, P.vel[f"v_{jb}"], ms, "μ_v")]
        lines += [_omega_line(c, P, g.links[0], v1, g.lengths[0], True, "l" + sub(ja, jb)),
                  _omega_line(c, P, g.links[1], v2, g.lengths[1], True, "l" + sub(jb, jc))]
    elif g.kind == "RRP":
        ja, jb = g.joints
        v1 = P.vel[f"v_{jb}{ja}"]
        lines += [P.measured(vp, v1, ms, "μ_v"), P.measured(vp, P.vel[f"v_{jb}"], ms, "μ_v")]
        if g.guide.moving:
            kn = P.m.link(g.guide.link).number
            lines.append(P.measured(vp, P.vel[f"v_{jb}{jb}{kn}"], ms, "μ_v"))
            c.p(t("The {what} ({n3}) slides along a guide of link {k}, which turns: {bk} is the point of link {k} under "
                  "it (found on the plan by similarity), its velocity relative to that point is along the guide, "
                  "and it turns with link {k} ($ω_{n3} = ω_{k}$).").format(
                what=role_name(c, P.s, g.links[1]), k=kn, bk=jm(f"{jb}{kn}"), n3=n3))
        lines += [_omega_line(c, P, g.links[0], v1, g.lengths[0], True, "l" + sub(ja, jb))]
    else:
        ja, jc = g.joints
        p3, p2 = f"{ja}{n3}", f"{ja}{n2}"
        rel, rot = P.vel[f"v_{p3}{p2}"], P.vel[f"v_{p3}{jc}"]
        rho = abs(P.z[ja] - P.z[jc])
        lines += [P.measured(vp, rel, ms, "μ_v"), P.measured(vp, rot, ms, "μ_v"),
                  P.measured(vp, P.vel[f"v_{p3}"], ms, "μ_v")]
        lines += [_omega_line(c, P, g.links[1], rot, rho, False, "l" + sub(jc, ja)),
                  f"ω_{n2} = ω_{n3}"]
    points = _points_line(c, P, g.index, vp, ms, "μ_v")
    lines += points
    if points:
        c.p(t("The points {points} of the group's links are found on the plan by similarity: the figure of a link's "
              "points on the plan is similar to the link itself.").format(
            points=", ".join(jm(pt.name) for pt in P.m.points if P.m.link(pt.link).group == g.index)))
    if g.kind == "RPR":
        c.p(t("Here $l{l}$ is the distance from the pivot {c} to the block in this position; the block {n2} turns "
              "together with the slotted link {n3}.").format(l=sub(g.joints[1], g.joints[0]), c=jm(g.joints[1]),
                                                             n2=n2, n3=n3))
    if g.kind == "RPR" and g.offset != 0.0:
        c.p(t("The slot of link {n3} passes {d} mm from its pivot {c} (not through it): the block's velocity relative "
              "to the slot, and later its relative and Coriolis accelerations, are along and across the slot, while "
              "the turning about {c} stays perpendicular to the line from {c} to {a}.").format(
            n3=n3, d=c.n(abs(g.offset) * 1000.0, sig=4), c=jm(g.joints[1]), a=jm(g.joints[0])))
    c.formula(*lines)


def _sliding_group(c: Ctx, P: _Plans, g, plan, unit: str, mu: str) -> None:
    """The plan of a PRP or an RPP group (kinds 4, 5): its blocks only slide, so the plan gives the
    relative velocities (accelerations) along the guides and slots; the Coriolis accelerations, where a
    guide or the yoke turns, are known beforehand, 2·ω·v_rel. The blocks turn with their guides' links."""
    t = c.t
    n2, n3 = g.numbers
    symbols = [x for eq in plan.equations if eq.group == g.index for side in eq.sides for x in side]
    symbols += [eq.lhs for eq in plan.equations if eq.group == g.index]
    vecs = [v for v in plan.vectors if v.symbol in dict.fromkeys(symbols)]
    known, lines = [], []
    turning = {}  # the Coriolis vectors' symbols → the link whose ω makes them
    if g.kind == "PRP":
        (jb,) = g.joints
        for gd in g.guides:
            if gd.moving:
                turning[f"a^k_{jb}{jb}{P.m.link(gd.link).number}"] = gd.link
    else:
        ja = g.joints[0]
        p3 = f"{ja}{n3}"
        turning[f"a^k_{p3}{ja}{n2}"] = g.links[1]
        if g.guide.moving:
            turning[f"a^k_{p3}{p3}{P.m.link(g.guide.link).number}"] = g.guide.link
    still = {sym: ln for sym, ln in turning.items() if _never_turns(P, ln)}  # a translating yoke: no Coriolis term
    for v in dict((v.symbol, v) for v in vecs).values():
        if v.symbol in still:
            continue
        if v.symbol in turning:
            rel = P.vel["v_" + v.symbol[4:]]
            num = P.m.link(turning[v.symbol]).number
            w = abs(P.w[P.m.links[num - 1].name])
            known.append(c.calc(f"{P.sym.mag(v.symbol)} = 2 ω_{num} {P.sym.mag(rel.symbol)}", "2 dot {0} dot {1}",
                                [V(w, sig=5), V(0.0 if P.tiny(rel.magnitude, P.pl.velocity) else rel.magnitude, sig=4)],
                                V(0.0 if P.tiny(v.magnitude, plan) else v.magnitude, sig=4), unit))
            known.append(P.drawn(plan, v))
        elif v.start == "p" and v.known or v.start == "π" and v.known:
            continue  # a guide's point found by similarity
        else:
            lines.append(P.measured(plan, v, unit, mu))
    moving = sorted({P.m.link(ln).number for sym, ln in turning.items() if sym not in still})
    if known:
        c.p((t("A block slides along the turning guide of link {k}, so its acceleration relative to the guide has a "
               "Coriolis component (the relative velocity turned by 90° in the sense of $ω_{k}$). The known "
               "components and their segments on the plan:") if len(moving) == 1 else
             t("The blocks slide along turning guides, so their accelerations relative to them have Coriolis "
               "components (the relative velocity turned by 90° in the sense of the guide's ω). The known components "
               "and their segments on the plan:")).format(k=moving[0] if moving else ""))
        c.formula(*known)
    if plan.kind == "velocity":
        same = [f"{q}_{n} = {q}_{P.m.link(gd.link).number}" if gd.moving else f"{q}_{n} = 0"
                for q in ("ω",) for n, gd in zip((n2, n3), g.guides or (g.guide, g.guide))]
        if g.kind == "PRP":
            c.p(t("Links {n2} and {n3} of the group only slide: each turns with the link of its guide (on a fixed guide "
                  "it does not turn).").format(n2=n2, n3=n3))
        else:
            c.p(t("The block {n2} only slides in the slot of the yoke {n3} and turns with it; the yoke slides along its "
                  "guide and turns with the guide's link.").format(n2=n2, n3=n3))
    else:
        if still and g.kind == "RPP":
            c.p(t("The yoke's guide is fixed: the yoke {n3} translates ($ω_{n3} = 0$), so the block's acceleration "
                  "relative to it has no Coriolis component.").format(n3=n3))
        same = [f"{q}_{n} = {q}_{P.m.link(gd.link).number}" if gd.moving else f"{q}_{n} = 0"
                for q in ("ε",) for n, gd in zip((n2, n3), g.guides or (g.guide, g.guide))]
        c.p(t("From the plan:"))
    c.formula(*(lines + same))


def _never_turns(P: _Plans, link: str) -> bool:
    """Whether `link` does not turn over the whole cycle (a yoke on a fixed guide: ω ≡ 0)."""
    import numpy as np

    w = np.asarray(P.s.cycle.kin.omega[link], dtype=float)
    return float(np.max(np.abs(w))) <= 1e-9 * abs(P.m.crank.omega)


def _group_acceleration(c: Ctx, P: _Plans, g) -> None:
    t = c.t
    ms2 = t("m/s²")
    ap = P.pl.acceleration
    n2, n3 = g.numbers
    c.p(t("Group {index} (links {n2}, {n3}; {kind}):").format(index=g.index, n2=n2, n3=n3,
                                                              kind=pattern(g.kind, c.lang)))
    fixed = [j for j in g.known if j in P.m.frame]
    zero = [f"arrow(a){sub(j)} = 0" for j in fixed]
    if g.kind == "RPR":
        zero.insert(0, f"arrow(a){sub(g.joints[0] + str(n2))} = arrow(a){sub(g.joints[0])}")
    c.formula(*(_eq(P, ap, g.index) + zero))
    if g.kind in ("PRP", "RPP"):
        _sliding_group(c, P, g, ap, ms2, "μ_a")
        return
    known, lines = [], []
    rad = "ω"
    if g.kind in ("RRR", "RRP"):
        ja, jb = g.joints[0], g.joints[1]
        an = P.acc[f"a^n_{jb}{ja}"]
        w = abs(P.w[g.links[0]]) if not P.tiny(P.w[g.links[0]]) else 0.0
        known.append(c.calc(f"{P.sym.mag(an.symbol)} = {rad}_{n2}^2 l{sub(ja, jb)}", "{0}^2 dot {1}",
                            [V(w, sig=5), V(g.lengths[0], exact=True)], V(an.magnitude if w else 0.0, sig=4), ms2))
        known.append(P.drawn(ap, an))
        at = P.acc[f"a^τ_{jb}{ja}"]
        lines += [P.measured(ap, at, ms2, "μ_a")]
        eps = [_eps_line(c, P, g.links[0], at, g.lengths[0], True, "l" + sub(ja, jb))]
        if g.kind == "RRR":
            jc = g.joints[2]
            an2 = P.acc[f"a^n_{jb}{jc}"]
            w3 = abs(P.w[g.links[1]]) if not P.tiny(P.w[g.links[1]]) else 0.0
            known.append(c.calc(f"{P.sym.mag(an2.symbol)} = {rad}_{n3}^2 l{sub(jb, jc)}", "{0}^2 dot {1}",
                                [V(w3, sig=5), V(g.lengths[1], exact=True)], V(an2.magnitude if w3 else 0.0, sig=4), ms2))
            known.append(P.drawn(ap, an2))
            at2 = P.acc[f"a^τ_{jb}{jc}"]
            lines += [P.measured(ap, at2, ms2, "μ_a")]
            eps.append(_eps_line(c, P, g.links[1], at2, g.lengths[1], True, "l" + sub(jb, jc)))
        if g.kind == "RRP" and g.guide.moving:
            kn = P.m.link(g.guide.link).number
            rel, cor = P.vel[f"v_{jb}{jb}{kn}"], P.acc[f"a^k_{jb}{jb}{kn}"]
            wk = abs(P.w[g.guide.link]) if not P.tiny(P.w[g.guide.link]) else 0.0
            c.p(t("The {what} ({n3}) moves along the turning guide of link {k}: the acceleration of {b} relative to {bk} "
                  "has a Coriolis component across the guide (the relative velocity turned by 90° in the sense of "
                  "$ω_{k}$).").format(what=role_name(c, P.s, g.links[1]), n3=n3, k=kn, b=jm(jb), bk=jm(f"{jb}{kn}")))
            known.append(c.calc(f"{P.sym.mag(cor.symbol)} = 2 ω_{kn} {P.sym.mag(rel.symbol)}", "2 dot {0} dot {1}",
                                [V(wk, sig=5), V(0.0 if P.tiny(rel.magnitude, P.pl.velocity) else rel.magnitude, sig=4)],
                                V(0.0 if P.tiny(cor.magnitude, ap) else cor.magnitude, sig=4), ms2))
            known.append(P.drawn(ap, cor))
            lines.append(P.measured(ap, P.acc[f"a^r_{jb}{jb}{kn}"], ms2, "μ_a"))
        lines += [P.measured(ap, P.acc[f"a_{jb}"], ms2, "μ_a")] + eps
    else:
        ja, jc = g.joints
        p3, p2 = f"{ja}{n3}", f"{ja}{n2}"
        rho = abs(P.z[ja] - P.z[jc])
        w = abs(P.w[g.links[1]]) if not P.tiny(P.w[g.links[1]]) else 0.0
        rel = P.vel[f"v_{p3}{p2}"]
        cor = P.acc[f"a^k_{p3}{p2}"]
        an = P.acc[f"a^n_{p3}{jc}"]
        c.p(t("The block slides along the turning slotted link, so the acceleration of {a3} relative to {a2} has a "
              "Coriolis component, perpendicular to the slotted link (the relative velocity turned by 90° in the "
              "sense of $ω_{n3}$). The known components and their segments on the plan:").format(
            a3=jm(f"{ja}{n3}"), a2=jm(f"{ja}{n2}"), n3=n3))
        known.append(c.calc(f"{P.sym.mag(cor.symbol)} = 2 ω_{n3} {P.sym.mag(rel.symbol)}", "2 dot {0} dot {1}",
                            [V(w, sig=5), V(0.0 if P.tiny(rel.magnitude, P.pl.velocity) else rel.magnitude, sig=4)],
                            V(0.0 if P.tiny(cor.magnitude, ap) else cor.magnitude, sig=4), ms2))
        known.append(P.drawn(ap, cor))
        known.append(c.calc(f"{P.sym.mag(an.symbol)} = ω_{n3}^2 l{sub(jc, ja)}", "{0}^2 dot {1}",
                            [V(w, sig=5), V(rho, sig=5)], V(an.magnitude if w else 0.0, sig=4), ms2))
        known.append(P.drawn(ap, an))
        ar, at = P.acc[f"a^r_{p3}{p2}"], P.acc[f"a^τ_{p3}{jc}"]
        lines += [P.measured(ap, ar, ms2, "μ_a"), P.measured(ap, at, ms2, "μ_a"),
                  P.measured(ap, P.acc[f"a_{p3}"], ms2, "μ_a"),
                  _eps_line(c, P, g.links[1], at, rho, False, "l" + sub(jc, ja)), f"ε_{n2} = ε_{n3}"]
    lines += _points_line(c, P, g.index, ap, ms2, "μ_a")
    if g.kind != "RPR":
        c.p(t("The known components and their segments on the plan:"))
    c.formula(*known)
    c.p(t("From the plan:"))
    c.formula(*lines)


def _vector_table(c: Ctx, P: _Plans) -> None:
    t = c.t
    rows = []
    for plan, unit, kind in ((P.pl.velocity, t("m/s"), "m/s"), (P.pl.acceleration, t("m/s²"), "m/s²")):
        for v in plan.vectors:
            if v.magnitude / plan.scale < 0.05 and not v.relation:
                continue
            line = (t("guide") if v.line == "guide" else t("slot") if v.line == "slot" else
                    " ".join(_split_points(v.line, P.sym.names)))
            rows.append([f"${P.sym.vec(v.symbol)}$", f"${label_math(v.start)} {label_math(v.end)}$",
                         f"{v.relation} {line}".strip() or "—", c.n(v.magnitude / plan.scale, decimals=1),
                         c.nz(v.magnitude, kind, sig=4) + "\u00a0" + unit])
    c.table("linkage_plans", t("Vectors of the velocity plan ($μ_v = {mu_v}$ (m/s)/mm) and of the acceleration plan "
                               "($μ_a = {mu_a}$ (m/s²)/mm), position {label}").format(
        mu_v=c.q(P.pl.velocity.scale), mu_a=c.q(P.pl.acceleration.scale), label=P.pl.position.label),
        [t("Vector"), t("On the plan"), t("Direction"), t("Length, mm"), t("Magnitude")], rows,
        align=["center", "center", "center", "right", "right"], widths=[1.2, 1.0, 1.2, 1.0, 1.4])


# --- 4 the table of all positions ------------------------------------------------------------------------


def position_rows(s):
    """(label, φ°, s, v, a, {link: (ω, ε)}) per position: the output's displacement from the extreme
    position where the working stroke starts, along it [m or rad], its velocity and acceleration, the turning links' ω and ε."""
    m, cy = s.mechanism, s.cycle
    k = cy.kin
    q, qd, qdd = output_coordinate(m, k)
    s_out = displacement(m, cy.extremes, cy.direction, q)
    rows = []
    for p in cy.positions:
        i = p.index
        links = {ln.name: (float(k.omega[ln.name][i]), float(k.epsilon[ln.name][i])) for ln in m.links}
        rows.append((p.label, _deg(p.phi), float(s_out[i]), cy.direction * float(qd[i]),
                     cy.direction * float(qdd[i]), links))
    return rows


def _table(c: Ctx, s) -> None:
    t, n = c.t, c.n
    m = s.mechanism
    slider = m.output.kind == "slider"
    c.doc.add(Heading(2, t("Kinematics of the mechanism in all positions")))
    turning = [ln for ln in m.links if ln.kind in ("bar", "slotted") and not (not slider and ln.name == m.output.link)]
    mm, ms, ms2, rs, rs2 = t("mm"), t("m/s"), t("m/s²"), t("rad/s"), t("rad/s²")
    first = s.cycle.working_start()
    moved = first is not None and first.index != 0  # crank.start_deg: s counts from the working stroke's start
    if slider:
        head = ["№", "$φ$, °", f"$s$, {mm}", f"$v$, {ms}", f"$a$, {ms2}"]
        what = (t("the displacement $s$ of the {whose} from the extreme position {start} where the working "
                  "stroke starts, its velocity $v$ and acceleration $a$ (positive along the working stroke)") if moved
                else t("the displacement $s$ of the {whose} from position 0, its velocity $v$ and acceleration "
                       "$a$ (positive along the working stroke)")).format(whose=role_genitive(c, s, m.output.link),
                                                                          start=first.label if moved else "")
    else:
        head = ["№", "$φ$, °", "$ψ$, °", f"$ω$, {rs}", f"$ε$, {rs2}"]
        what = (t("the angle $ψ$ of the rocker {link} from the extreme position {start} where the working stroke "
                  "starts, its angular velocity $ω$ and acceleration $ε$ (positive along the working stroke)") if moved
                else t("the angle $ψ$ of the rocker {link} from position 0, its angular velocity $ω$ and acceleration "
                       "$ε$ (positive along the working stroke)")).format(link=m.output.link,
                                                                          start=first.label if moved else "")
    for ln in turning:
        head += [f"$ω_{ln.number}$, {rs}", f"$ε_{ln.number}$, {rs2}"]
    c.p(t("Table {{tab:linkage_positions}} gives, for every position, the crank angle $φ$, {what}, and the angular "
          "velocities and accelerations of the links (counter-clockwise positive); the extreme positions are marked "
          "with a prime.").format(what=what) if any(not p.label.isdigit() for p in s.cycle.positions) else
        t("Table {{tab:linkage_positions}} gives, for every position, the crank angle $φ$, {what}, and the angular "
          "velocities and accelerations of the links (counter-clockwise positive).").format(what=what))
    rows = []
    for label, phi, d, v, a, links in position_rows(s):
        row = [label, n(phi, decimals=2), n(d * 1000, decimals=2) if slider else n(math.degrees(d), decimals=2),
               n(v, decimals=3), n(a, decimals=2)]
        for ln in turning:
            w, e = links[ln.name]
            row += [n(w, decimals=3), n(e, decimals=2)]
        rows.append(row)
    widths = [0.45, 0.8, 0.85, 0.8, 0.75] + [1.0] * (len(head) - 5)
    c.table("linkage_positions", t("Kinematics of the mechanism in its positions"), head, rows,
            align=["center"] + ["right"] * (len(head) - 1), widths=widths)
