"""The section «Синтез механизма» that opens chapter 1 when the mechanism file records its task
(`tmm synth`, issue 33): the task, θ from K, the lengths by the construction of the type, each
formula with its substitution. Called from one line of :func:`.linkage_part.linkage_chapter`.

The numbers are the synthesis the file records, done again from its [synthesis] table
(:func:`tmm_cli.linkage.synthesis_file.recorded_synthesis`); when the file's lengths are no longer
the synthesis's (edited after `tmm synth`), the section says so and shows no derivation.
"""

from __future__ import annotations

import math

from ...linkage.synthesis import RockerSynthesis, SliderSynthesis, rocker_construction_frame
from ...linkage.synthesis_file import changed_lengths, recorded_synthesis
from .ctx import Ctx, V
from .model import Heading


def chapter_title(c: Ctx, s) -> str:
    """Chapter 1's title: the synthesis named too when the file records it (and still has its lengths)."""
    rec = recorded_synthesis(s.mechanism)
    if rec is not None and rec.matches:
        return c.t("Synthesis, structural and kinematic analysis of the lever mechanism")
    return c.t("Structural and kinematic analysis of the lever mechanism")


def synthesis_section(c: Ctx, s) -> None:
    rec = recorded_synthesis(s.mechanism)
    if rec is None:
        return
    t = c.t
    c.doc.add(Heading(2, t("Synthesis of the mechanism")))
    c.doc.claim(kind="linkage_synthesis", type=rec.task.type, matches=rec.matches)
    if not rec.matches:
        _edited(c, rec, s.mechanism)
        return
    syn, mm = rec.synthesis, t("mm")
    if isinstance(syn, SliderSynthesis):
        _slider(c, syn, mm)
    elif isinstance(syn, RockerSynthesis):
        _rocker(c, syn, mm)
    else:
        _slotted(c, syn, mm, "rod_ratio" not in rec.task.values)
    if isinstance(syn, RockerSynthesis):
        c.p(t("The mechanism with these lengths is analysed below; the rocker's swing and the time ratio found there "
              "are those of the task."))
    else:
        c.p(t("The mechanism with these lengths is analysed below; the stroke and the time ratio found there are those "
              "of the task."))


SYMBOLS = {"l_OA": "l_(O A)", "l_AB": "l_(A B)", "l_BC": "l_(B C)", "l_CD": "l_(C D)", "l_AD": "l_(A D)",
           "l_O1A": "l_(O_1 A)", "l_O1O2": "l_(O_1 O_2)", "l_O2B": "l_(O_2 B)"}


def _task_data(c: Ctx, task) -> str:
    """The task's data as the note writes them: «$H = 100$ мм, $K = 1,2$, …»."""
    v, mm = task.values, c.t("mm")
    frame = "l_(A D)" if task.type == "crank-rocker" else "l_(O_1 O_2)"
    keys = (("stroke", "H", 1000.0, mm), ("rocker", "l_(C D)", 1000.0, mm), ("swing_deg", "ψ", None, "°"),
            ("time_ratio", "K", 1.0, ""), ("lambda", "λ", 1.0, ""), ("offset", "e", 1000.0, mm),
            ("frame", frame, 1000.0, mm), ("min_transmission_deg", 'γ_"min" >=', None, "°"),
            ("rod_ratio", "l_(B C)/l_(O_2 B)", 1.0, ""))
    out = []
    for key, sym, scale, unit in keys:
        if key not in v:
            continue
        if scale is None:
            out.append(f"${sym} = {c.qd(v[key], sig=6)}$" if "=" not in sym else f"${sym} {c.qd(v[key], sig=6)}$")
        else:
            out.append(f"${sym} = {c.q(v[key] * scale, sig=6)}$" + (f" {unit}" if unit else ""))
    return ", ".join(out)


def _edited(c: Ctx, rec, mech) -> None:
    """The file's lengths are no longer the synthesis': say which, and give the task's data."""
    t = c.t
    diffs = "; ".join(t("${sym} = {file}$ mm in the file, {syn} mm by the synthesis").format(
        sym=SYMBOLS[name], file=c.q(a * 1000, decimals=2), syn=c.n(b * 1000, decimals=2)) for name, a, b in
        changed_lengths(mech, rec))
    c.p(t("The mechanism was found by synthesis from the task {data}; its lengths were changed afterwards "
          "({diffs}). The synthesis is therefore not repeated here; the analysis below is of the lengths the file "
          "gives.").format(data=_task_data(c, rec.task), diffs=diffs or t("its frame or guide")))


def _theta(c: Ctx, syn) -> None:
    c.p(c.t("The angle between the crank's positions at the two extreme positions of the output link follows from "
            "the time ratio {cite:artobolevsky}:"))
    c.formula(c.calc("θ = 180 degree dot (K - 1)/(K + 1)", '"180°" dot ({0} - 1)/({0} + 1)',
                     [_given(syn.time_ratio)], V(math.degrees(syn.theta), decimals=3, deg=True)),
              where=[("θ", c.t("the angle between the crank's positions at the extreme positions of the output link")),
                     ("K", c.t("the time ratio of the output link's strokes"))])


def _given(x: float) -> V:
    """A datum of the task, printed as given (up to 9 significant digits)."""
    return V(x, exact=True, sig=9)


def _mm(x: float, **kw) -> V:
    return V(x * 1000.0, decimals=kw.get("decimals", 2))


def _slider(c: Ctx, syn, mm: str) -> None:
    t = c.t
    h = syn.stroke * 1000.0
    if syn.mode == "lambda":
        c.p(t("The task gives the stroke of the slider $H = {h}$ mm and the ratio $λ = l_(O A)/l_(A B) = {lam}$; the "
              "mechanism is central (the guide passes through the crank's centre O), so the stroke is twice the crank:"
              ).format(h=c.q(h, sig=6), lam=c.q(syn.lam, sig=6)))
        c.formula(c.calc("l_(O A) = H/2", "{0}/2", [_given(h)], _mm(syn.crank), mm),
                  c.calc("l_(A B) = l_(O A)/λ", "{0}/{1}", [_mm(syn.crank), _given(syn.lam)], _mm(syn.rod), mm))
        return
    if syn.mode == "time_ratio":
        c.p(t("The task gives the stroke of the slider $H = {h}$ mm, the time ratio $K = {k}$ and the offset of the "
              "guide $e = {e}$ mm.").format(h=c.q(h, sig=6), k=c.q(syn.time_ratio, sig=6),
                                              e=c.q(syn.offset * 1000, sig=6)))
        _theta(c, syn)
        c.p(t("In the extreme positions the crank and the rod lie in line: $O B_1 = l_(A B) + l_(O A)$, "
              "$O B_2 = l_(A B) - l_(O A)$; the stroke $B_1 B_2 = H$ is seen from O at the angle θ and lies at the "
              "distance e from O. The law of cosines and the area of the triangle $O B_1 B_2$ give"))
        half = math.degrees(syn.theta / 2.0)
        c.formula(c.calc('l_(O A) = 1/2 sqrt(H^2 - 2 H e "tg"(θ/2))', '1/2 sqrt({0}^2 - 2 dot {0} dot {1} dot "tg" {2})',
                         [_given(h), _given(syn.offset * 1000), V(half, decimals=3, deg=True)],
                         _mm(syn.crank), mm))
        c.formula(c.calc('l_(A B) = 1/2 sqrt(H^2 + 2 H e "ctg"(θ/2))', '1/2 sqrt({0}^2 + 2 dot {0} dot {1} dot "ctg" {2})',
                         [_given(h), _given(syn.offset * 1000), V(half, decimals=3, deg=True)],
                         _mm(syn.rod), mm))
        return
    c.p(t("The task gives the stroke of the slider $H = {h}$ mm, the ratio $λ = {lam}$ and the offset of the guide "
          "$e = {e}$ mm. The crank is the root of the stroke's equation (the positions of B in the extreme positions, "
          "$l_(A B) = l_(O A)/λ$):").format(h=c.q(h, sig=6), lam=c.q(syn.lam, sig=6), e=c.q(syn.offset * 1000, sig=6)))
    c.formula(f"H = sqrt((l_(A B) + l_(O A))^2 - e^2) - sqrt((l_(A B) - l_(O A))^2 - e^2) => l_(O A) = "
              f"{c.q(syn.crank * 1000, decimals=2)} {c.u(mm)}")
    c.formula(c.calc("l_(A B) = l_(O A)/λ", "{0}/{1}", [_mm(syn.crank), _given(syn.lam)], _mm(syn.rod), mm))
    c.p(t("The angle between the crank's positions in the extreme positions is then θ = {theta}°, and the time ratio "
          "K = {k}.").format(theta=c.n(math.degrees(syn.theta), decimals=3), k=c.n(syn.time_ratio, decimals=4)))


def _rocker_frame(syn) -> dict:
    """The construction's points [mm] in the derivation's frame (origin D, y along the bisector)."""
    return {k: z * 1000.0 for k, z in rocker_construction_frame(syn).items()}


def _rocker(c: Ctx, syn, mm: str) -> None:
    t = c.t
    psi = math.degrees(syn.swing)
    given = t("The task gives the rocker $l_(C D) = {c}$ mm, its swing $ψ = {psi}$ and the time ratio $K = {k}$").format(
        c=c.q(syn.rocker * 1000, sig=6), psi=c.qd(psi, sig=6), k=c.q(syn.time_ratio, sig=6))
    if syn.mode == "frame":
        given += t(", and the frame $l_(A D) = {d}$ mm").format(d=c.q(syn.frame * 1000, sig=6))
    if syn.gamma_task is not None:
        given += t("; the smallest transmission angle must be $γ_\"min\" >= {g}$").format(
            g=c.qd(math.degrees(syn.gamma_task), sig=6))
    c.p(given + ".")
    _theta(c, syn)
    chord = 2.0 * syn.rocker * math.sin(syn.swing / 2.0)
    pts = _rocker_frame(syn)
    c1, c2, a, o = pts["C1"], pts["C2"], pts["A"], pts["O"]
    c.p(t("The rocker is drawn in its extreme positions $C_1 D$ and $C_2 D$ (Figure {fig:linkage_synthesis}); the "
          "coordinates below have the origin at D and the y axis along the bisector of the swing. The chord between "
          "the rocker's ends and the radius of the circle through $C_1$, $C_2$ on which the chord subtends the angle "
          "θ (the locus of the crank's centre A):") if c.has("linkage_synthesis") else
        t("The rocker is drawn in its extreme positions $C_1 D$ and $C_2 D$; the coordinates below have the origin at "
          "D and the y axis along the bisector of the swing. The chord between the rocker's ends and the radius of "
          "the circle through $C_1$, $C_2$ on which the chord subtends the angle θ (the locus of the crank's centre A):"))
    half = V(psi / 2.0, decimals=3, deg=True)
    c.formula(c.calc("C_1 C_2 = 2 l_(C D) sin(ψ/2)", "2 dot {0} dot sin {1}", [_given(syn.rocker * 1000), half],
                     _mm(chord, decimals=3), mm),
              c.calc("R = (C_1 C_2)/(2 sin θ)", "{0}/(2 dot sin {1})",
                     [_mm(chord, decimals=3), V(math.degrees(syn.theta), decimals=3, deg=True)], _mm(syn.radius, decimals=3), mm))
    c.formula(c.calc("y_C = l_(C D) cos(ψ/2)", "{0} dot cos {1}", [_given(syn.rocker * 1000), half],
                     V(c1.imag, decimals=3), mm),
              c.calc("abs(x_C) = l_(C D) sin(ψ/2)", "{0} dot sin {1}", [_given(syn.rocker * 1000), half],
                     V(abs(c1.real), decimals=3), mm))
    below = o.imag < c1.imag
    c.formula(c.calc("y_O = y_C - R cos θ" if below else "y_O = y_C + R cos θ",
                     "{0} - {1} dot cos {2}" if below else "{0} + {1} dot cos {2}",
                     [V(c1.imag, decimals=3), _mm(syn.radius, decimals=3), V(math.degrees(syn.theta), decimals=3, deg=True)],
                     V(o.imag, decimals=3), mm),
              where=[("y_O", t("the ordinate of the locus circle's centre O (on the bisector)"))])
    phi = math.degrees(math.atan2(a.imag - o.imag, a.real - o.real))
    if syn.mode == "frame":
        c.p(t("The crank's centre A is where the circle of radius $l_(A D)$ about D meets the locus (of the two "
              "points, the one with the larger smallest transmission angle); it lies on the locus at the polar angle "
              "$φ_A = {phi}$ from O:").format(phi=c.qd(phi, decimals=3)))
    else:
        c.p(t("The crank's centre A is taken at the point of the locus where the smallest transmission angle over the "
              "turn is largest (the textbooks leave the point to the designer; the program searches the locus for it): "
              "at the polar angle $φ_A = {phi}$ from O:").format(phi=c.qd(phi, decimals=3)))
    phv = V(phi, decimals=3, deg=True)
    c.formula(c.calc("x_A = R cos φ_A", "{0} dot cos {1}", [_mm(syn.radius, decimals=3), phv], V(a.real, decimals=3), mm),
              c.calc("y_A = y_O + R sin φ_A", "{0} + {1} dot sin {2}", [V(o.imag, decimals=3), _mm(syn.radius, decimals=3), phv],
                     V(a.imag, decimals=3), mm))
    a1, a2 = abs(a - c1), abs(a - c2)
    xa, ya = V(a.real, decimals=3), V(a.imag, decimals=3)
    c.formula(c.calc("A C_1 = sqrt((x_A - x_(C_1))^2 + (y_A - y_C)^2)", "sqrt(({0} - ({1}))^2 + ({2} - {3})^2)",
                     [xa, V(c1.real, decimals=3), ya, V(c1.imag, decimals=3)], V(a1, decimals=3), mm))
    c.formula(c.calc("A C_2 = sqrt((x_A - x_(C_2))^2 + (y_A - y_C)^2)", "sqrt(({0} - ({1}))^2 + ({2} - {3})^2)",
                     [xa, V(c2.real, decimals=3), ya, V(c2.imag, decimals=3)], V(a2, decimals=3), mm))
    c.formula(c.calc("l_(A D) = sqrt(x_A^2 + y_A^2)", "sqrt(({0})^2 + {1}^2)" if a.imag >= 0 else
                     "sqrt(({0})^2 + ({1})^2)", [xa, ya], _mm(syn.frame), mm))
    c.p(t("In the extreme positions the crank and the coupler lie in line ($A C_1 = l_(B C) - l_(A B)$, "
          "$A C_2 = l_(B C) + l_(A B)$), so"))
    c.formula(c.calc("l_(A B) = (A C_2 - A C_1)/2", "({0} - {1})/2", [V(a2, decimals=3), V(a1, decimals=3)],
                     _mm(syn.crank), mm),
              c.calc("l_(B C) = (A C_2 + A C_1)/2", "({0} + {1})/2", [V(a2, decimals=3), V(a1, decimals=3)],
                     _mm(syn.coupler), mm))
    c.p(t("The transmission angle γ is extreme when the crank lies along the frame ($B D = l_(A D) minus.plus l_(A B)$); "
          "the angles μ between the coupler and the rocker there:"))
    bc, ad, ab = (_mm(x) for x in (syn.coupler, syn.frame, syn.crank))
    cd = _given(syn.rocker * 1000)
    mus = []
    for sign, name in (("-", "μ_1"), ("+", "μ_2")):
        bd = syn.frame - syn.crank if sign == "-" else syn.frame + syn.crank
        cos_mu = (syn.coupler ** 2 + syn.rocker ** 2 - bd ** 2) / (2.0 * syn.coupler * syn.rocker)
        mus.append(math.degrees(math.acos(max(-1.0, min(1.0, cos_mu)))))
        c.formula(c.calc(f"cos {name} = (l_(B C)^2 + l_(C D)^2 - (l_(A D) {sign} l_(A B))^2)/(2 l_(B C) l_(C D))",
                         f"({{0}}^2 + {{1}}^2 - ({{2}} {sign} {{3}})^2)/(2 dot {{0}} dot {{1}})", [bc, cd, ad, ab],
                         V(cos_mu, decimals=4)))
    gamma = math.degrees(syn.gamma_min)
    text = t("whence $μ_1 = {m1}$, $μ_2 = {m2}$; the transmission angle is μ or 180° − μ, whichever is acute, so the "
             "smallest over the turn is $γ_\"min\" = {g}$").format(m1=c.qd(mus[0], decimals=2),
                                                                    m2=c.qd(mus[1], decimals=2),
                                                                    g=c.qd(gamma, decimals=2))
    if syn.gamma_task is not None:
        text += t(", not less than the task's {gt}°").format(gt=c.n(math.degrees(syn.gamma_task), sig=6))
    c.p(text + ".")
    c.fig("linkage_synthesis", t("The synthesis of the crank-rocker mechanism: the rocker's extreme positions, the "
                                 "angle θ and the locus of the crank's centre"))


def _slotted(c: Ctx, syn, mm: str, assumed: bool) -> None:
    t = c.t
    c.p(t("The task gives the stroke of the ram $H = {h}$ mm, the time ratio $K = {k}$ and the distance between the "
          "crank's centre and the slotted link's pivot $l_(O_1 O_2) = {d}$ mm.").format(
        h=c.q(syn.stroke * 1000, sig=6), k=c.q(syn.time_ratio, sig=6), d=c.q(syn.frame * 1000, sig=6)))
    _theta(c, syn)
    half = V(math.degrees(syn.theta / 2.0), decimals=3, deg=True)
    c.p(t("In its extreme positions the slotted link is tangent to the crank circle, so the link swings by the angle "
          "between the crank's extreme positions:"))
    c.formula(f"ψ = θ = {c.leaf(V(math.degrees(syn.theta), decimals=3, deg=True))}")
    c.p(t("and the crank is"))
    c.formula(c.calc("l_(O_1 A) = l_(O_1 O_2) sin(θ/2)", "{0} dot sin {1}", [_given(syn.frame * 1000), half],
                     _mm(syn.crank), mm))
    c.p(t("The point B of the link moves on an arc whose chord is the stroke of the ram:"))
    link, sag = V(syn.link * 1000.0, decimals=3), V(syn.sagitta * 1000.0, decimals=3)
    c.formula(c.calc("l_(O_2 B) = H/(2 sin(ψ/2))", "{0}/(2 dot sin {1})", [_given(syn.stroke * 1000), half], link, mm))
    c.p(t("The sagitta of that arc (the height of the arc over its chord):"))
    c.formula(c.calc("f = l_(O_2 B) (1 - cos(ψ/2))", "{0} dot (1 - cos {1})", [link, half], sag, mm),
              where=[("f", t("the sagitta of the arc of B"))])
    c.p(t("The ram's guide passes through the middle of the sagitta, at the height above $O_2$"))
    c.formula(c.calc("h = l_(O_2 B) - f/2", "{0} - {1}/2", [link, sag], _mm(syn.guide), mm))
    if assumed:
        c.p(t("The task does not give the ratio of the rod to the slotted link; it is assumed $k = {k}$, within the "
              "usual {lo} … {hi} of shaper schemes:").format(k=c.q(syn.rod_ratio, sig=6), lo=c.n(0.25), hi=c.n(0.35)))
    else:
        c.p(t("The task gives the ratio of the rod to the slotted link $k = {k}$ (within the usual {lo} … {hi} of "
              "shaper schemes):").format(k=c.q(syn.rod_ratio, sig=6), lo=c.n(0.25), hi=c.n(0.35)))
    c.formula(c.calc("l_(B C) = k l_(O_2 B)", "{0} dot {1}", [_given(syn.rod_ratio), link], _mm(syn.rod), mm),
              where=[("k", t("the ratio of the rod to the slotted link"))])
    c.p(t("The rod then leans from the guide by at most $α_\"max\" = {a}$, where $sin α_\"max\" = f/(2 l_(B C))$.").format(
        a=c.qd(math.degrees(syn.rod_angle), decimals=2)))
