"""The force analysis (kinetostatics) group by group, from the last group to the crank.

The textbook method (Artobolevsky, "Кинетостатика плоских механизмов"; Frolov, "Силовой анализ
механизмов"; METHOD.md "Sheets 1 and 2"): every Assur group is statically determinate. With the
applied forces and d'Alembert's inertia forces (:mod:`.forces`) and the reactions of the groups
already solved (those hanging on this group's links, taken with the opposite sign), each group
gives its pair reactions; the crank comes last and gives the balancing moment M_b, the moment the
motor must apply to it. Frictionless pairs: a pin transmits a force through its centre, a slide a
force perpendicular to it (and a moment).

- RRR A–B–C (links 2 = AB, 3 = BC): the outer reactions split along and across their links,
  R₁₂ = Rⁿ₁₂ + Rτ₁₂, R₀₃ = Rⁿ₀₃ + Rτ₀₃; the moments of links 2 and 3 about B give the tangential
  components, Rτ₁₂ = M₂(B)/l_AB and Rτ₀₃ = M₃(B)/l_BC (the moments of the known forces about B);
  the force polygon of the group, Rτ₁₂ + ΣF₂ + ΣF₃ + Rτ₀₃ + Rⁿ₀₃ + Rⁿ₁₂ = 0, the normal ones;
  link 3's polygon the inner reaction R₂₃ = −(R₀₃ + ΣF₃).
- RRP A–B (bar 2, slider 3 on a fixed guide): Rτ₁₂ from link 2's moment about B; the group's
  polygon gives Rⁿ₁₂ and the guide's R₀₃ ⊥ guide; the slider's, R₂₃.
- RPR A–C (block 2 on A, slotted link 3 about C): the block presses across the slot, R₂₃ = N·n
  (n ⊥ the slot) with the couple M₂₃ of the slide (the block's own moment about A); link 3's
  moment about C gives N = −(M₃(C) + M₂₃)/ρ; then R₁₂ = N·n − ΣF₂, R₀₃ = −(ΣF₃ + N·n).
- The crank: M_b = −M₁(O), the moment about its pivot of every force on it; R₀₁ = −ΣF₁.

Reactions are named as in the book, R_ij = the force of link i on link j (0 the frame), i the
earlier of the pair's links; arrays over the kinematics' angles, complex vectors [N].
"""

from __future__ import annotations

import numpy as np

from ..records import record
from .chain import Kinematics, guide_frame
from .forces import Loading
from .mechanism import Mechanism, Pair
from .motion import cross, solve2


@record(eq=False)
class Reaction:
    """The reaction in one kinematic pair: the force of link `pair.links[0]` on `pair.links[1]`."""

    pair: Pair
    label: str  # 'R12', 'R03' (R4,10 when a number has two digits)
    at: np.ndarray  # where it acts: the pin's centre, or for a slide the joint of its block (complex) [m]
    force: np.ndarray  # complex [N]
    normal: np.ndarray | None  # RRR, RRP outer pins: the component along the group's link (complex) [N]
    tangential: np.ndarray | None  # … and across it [N]
    couple: np.ndarray | None  # a slide: the moment it transmits (of links[0] on links[1]) [N·m]


@record(eq=False)
class Kinetostatics:
    """The force analysis at the kinematics' angles."""

    loading: Loading
    reactions: tuple[Reaction, ...]  # in the mechanism's pair order (the crank's first)
    balancing: np.ndarray  # M_b [N·m]: the motor's moment on the crank, counter-clockwise positive

    def reaction(self, label: str) -> Reaction:
        for r in self.reactions:
            if r.label == label:
                return r
        raise KeyError(label)


def pair_label(pair: Pair) -> str:
    """'R12' for the force of link 1 on link 2 ('R4,10' when a number has two digits).

    >>> pair_label(Pair("A", "R", (1, 2), 1)), pair_label(Pair("E", "R", (4, 10), 5))
    ('R12', 'R4,10')
    """
    i, j = pair.links
    return f"R{i}{j}" if i < 10 and j < 10 else f"R{i},{j}"


class _Body:
    """The known forces on one link while the groups are solved: forces at points and couples."""

    def __init__(self, shape):
        self.points: list[tuple[np.ndarray, np.ndarray]] = []  # (z, F)
        self.couple = np.zeros(shape)

    def force(self, z, f):
        self.points.append((z, f))

    def resultant(self, shape):
        return sum((f for _, f in self.points), np.zeros(shape, dtype=complex))

    def moment(self, about, shape):
        """Σ (z − P) × F + ΣM about the point P [N·m]."""
        total = self.couple.copy()
        for z, f in self.points:
            total = total + cross(z - about, f)
        return total + np.zeros(shape)


def rrr_reactions(a, b, c, f2, f3, m2_b, m3_b):
    """An RRR group's reactions (Artobolevsky's method of tangential and normal components).

    a, b, c: the joints (complex) [m]; f2, f3: the resultants of the known forces on links 2 = AB
    and 3 = BC [N]; m2_b, m3_b: their moments about B [N·m]. Returns (Rⁿ₁₂, Rτ₁₂, Rⁿ₀₃, Rτ₀₃, R₂₃)
    as complex vectors: the force of A's carrier on link 2 split along and across AB, that of
    C's carrier on link 3 along and across CB, and the force of link 2 on link 3.

    A force of 10 N down at the middle of AB (A = 0, B = (1, 1), C = (2, 0), both pinned to the
    frame): BC is a strut, its force along CB; the moments about A, 0.5·10 = (B × R₀₃), give
    R₀₃ = 2.5·(−1, 1) N, and A takes the rest, (2.5, 7.5) N; the strut has no tangential part:

    >>> rn12, rt12, rn03, rt03, r23 = rrr_reactions(0j, 1 + 1j, 2 + 0j, -10j, 0j, 5.0, 0.0)
    >>> [(round(float(x.real), 12), round(float(x.imag), 12)) for x in (rn12 + rt12, rn03 + rt03, r23)]
    [(2.5, 7.5), (-2.5, 2.5), (2.5, -2.5)]
    >>> float(abs(rt03))
    0.0
    """
    l2, l3 = np.abs(b - a), np.abs(b - c)
    u, w = (b - a) / l2, (b - c) / l3
    t2, t3 = m2_b / l2, m3_b / l3  # (A − B) × Rτ·iu = −l·Rτ: the moment about B balances
    n2, n3 = solve2(u, w, -(f2 + f3 + 1j * t2 * u + 1j * t3 * w))
    r03 = (n3 + 1j * t3) * w
    return n2 * u, 1j * t2 * u, n3 * w, 1j * t3 * w, -(r03 + f3)


def rrp_reactions(a, b, unit, f2, f3, m2_b):
    """An RRP group's reactions: bar 2 = AB, slider 3 on the fixed guide along `unit`.

    Returns (Rⁿ₁₂, Rτ₁₂, R₀₃, R₂₃): the force on link 2 at A split along and across AB, the
    guide's force on the slider (⊥ the guide) and the force of the bar on the slider.

    A crank-slider at φ = 90° (A = (0, 0.06), l = 0.25, B on the x axis) with 100 N on the slider
    along +x: the massless rod is a two-force member (no tangential part), pulling along BA, and
    the guide takes R₀₃ = −100·tg β with tg β = 0.06/√(0.25² − 0.06²):

    >>> b = complex(np.sqrt(0.25 ** 2 - 0.06 ** 2), 0.0)
    >>> rn12, rt12, r03, r23 = rrp_reactions(0.06j, b, 1 + 0j, 0j, 100 + 0j, 0.0)
    >>> float(abs(rt12)), round(float(r03.imag), 9), round(-100 * 0.06 / float(b.real), 9)
    (0.0, -24.722569303, -24.722569303)
    """
    l2 = np.abs(b - a)
    u = (b - a) / l2
    t2 = m2_b / l2
    n2, n = solve2(u + 0 * f2, 1j * unit + 0 * f2, -(f2 + f3 + 1j * t2 * u))
    r03 = n * 1j * unit
    return n2 * u, 1j * t2 * u, r03, -(r03 + f3)


def rpr_reactions(a, c, f2, f3, m2_a, m3_c, unit=None):
    """An RPR group's reactions: block 2 on the joint A, slotted link 3 turning about C.

    Returns (R₁₂, R₂₃, M₂₃, R₀₃): the force on the block at A, the block's force on the slotted
    link (⊥ the slot) and the moment the slide transmits, the force on link 3 at C.

    A slotted link straight up from C = 0 to A = (0, 0.2) with 10 N·m counter-clockwise on it
    needs the block to push it with 50 N towards +x:

    >>> r12, r23, m23, r03 = rpr_reactions(0.2j, 0j, 0j, 0j, 0.0, 10.0)
    >>> [(round(float(x.real), 12), round(float(x.imag), 12) + 0.0) for x in (r12, r23, r03)], m23
    ([(50.0, 0.0), (50.0, 0.0), (-50.0, 0.0)], 0.0)

    An offset slot (`unit`: the slot's direction u) takes the pressure along n = i·u with the arm
    cross(A − C, n) = t about C, the block's place along the slot from the foot of the perpendicular.

    >>> r12, r23, m23, r03 = rpr_reactions(0.3 + 0.4j, 0j, 0j, 0j, 0.0, 10.0, (0.3 + 0.4j) / (0.4 + 0.3j))
    >>> round(float(abs(r23)), 9)   # t = 0.4: N = 10/0.4
    25.0
    """
    r = a - c
    if unit is None:
        rho = np.abs(r)
        n = 1j * r / rho
    else:
        n = 1j * unit
        rho = cross(r, n)
    m23 = m2_a
    big_n = -(m3_c + m23) / rho  # ρ·N + M₃(C) + M₂₃ = 0
    r23 = big_n * n
    return r23 - f2, r23, m23, -(f3 + r23)


def prp_reactions(e1, e2, f2, f3):
    """A PRP group's reactions: block 2 on the guide G1 (along e1), block 3 on G2 (along e2), pinned
    together at B. The guides press across themselves, N1·n1 and N2·n2 (n = i·e), with the slides'
    couples (each block's own moment about B); the polygon of the group gives N1, N2, block 3's
    the pin's R₂₃ = −(N2·n2 + F₃).

    Two blocks on perpendicular guides (x and y) carrying 10 N along +x on block 3 only: the
    guide of block 2 (along y) takes it, R₂₃ passes it on.

    >>> r12, r23, r03 = prp_reactions(1j, 1 + 0j, 0j, 10 + 0j)
    >>> [complex(round(x.real, 12) + 0.0, round(x.imag, 12) + 0.0) for x in (r12, r23, r03)]
    [(-10+0j), (-10+0j), 0j]
    """
    n1, n2 = 1j * e1, 1j * e2
    a, b = solve2(n1 + 0 * f2, n2 + 0 * f2, -(f2 + f3))
    r03 = b * n2
    return a * n1, -(r03 + f3), r03


def rpp_reactions(a, y, es, eg, f2, f3, m2_a, m3_y):
    """An RPP group's reactions: block 2 hinged at A in the slot (along es) of the yoke 3, which
    slides on its guide (along eg) at Y.

    Returns (R₁₂, R₂₃, M₂₃, R₀₃, M₀₃): the pin's force on the block at A; the block's pressure on
    the yoke, across the slot, with the slide's couple M₂₃ (the block's moment about A); the guide's
    force on the yoke, across the guide, at Y with its couple M₀₃ (the yoke's moments about Y).

    A Scotch yoke (slot ⊥ guide along x) with 100 N against +x on the yoke: the block pushes it
    with 100 N along +x; the guide takes the moment of that push about Y:

    >>> r12, r23, m23, r03, m03 = rpp_reactions(0.05 + 0.05j, 0.05 + 0j, 1j, 1 + 0j, 0j, -100 + 0j, 0.0, 0.0)
    >>> round(float(r23.real), 12), round(float(abs(r23.imag)), 12), round(float(abs(r03)), 12), round(float(m03), 12)
    (100.0, 0.0, 0.0, 5.0)
    """
    ns, ng = 1j * es, 1j * eg
    m23 = m2_a
    p, q = solve2(ns + 0 * f3, ng + 0 * f3, -f3)
    r23, r03 = p * ns, q * ng
    m03 = -(m3_y + cross(a - y, r23) + m23)
    return r23 - f2, r23, m23, r03, m03


def kinetostatics(mech: Mechanism, loading: Loading, kin: Kinematics) -> Kinetostatics:
    """The reactions of every pair and the balancing moment, group by group from the last."""
    shape = kin.phi.shape
    bodies = {ln.number: _Body(shape) for ln in mech.links}
    for f in loading.forces:
        bodies[f.number].force(f.z, f.f)
    for c in loading.couples:
        bodies[c.number].couple = bodies[c.number].couple + c.m
    z = kin.z
    solved: dict[Pair, Reaction] = {}

    def give(pair: Pair, at, force, normal=None, tangential=None, couple=None):
        """Record the reaction; an outer pair's opposite loads the earlier link (not the frame),
        to be solved with its own group."""
        solved[pair] = Reaction(pair, pair_label(pair), at, force, normal, tangential, couple)
        earlier = pair.links[0]
        if 0 < earlier < 2 * pair.group:
            bodies[earlier].force(at, -force)
            if couple is not None:
                bodies[earlier].couple = bodies[earlier].couple - couple

    for g in reversed(mech.groups):
        n2, n3 = g.numbers
        b2, b3 = bodies[n2], bodies[n3]
        pa, pb, pc = g.pairs
        if g.kind == "RRR":
            ja, jb, jc = g.joints
            rn12, rt12, rn03, rt03, r23 = rrr_reactions(z[ja], z[jb], z[jc], b2.resultant(shape), b3.resultant(shape),
                                                        b2.moment(z[jb], shape), b3.moment(z[jb], shape))
            give(pb, z[jb], r23)
            give(pa, z[ja], rn12 + rt12, rn12, rt12)
            give(pc, z[jc], rn03 + rt03, rn03, rt03)
        elif g.kind == "RRP":
            ja, jb = g.joints
            unit = g.guide.unit if not g.guide.moving else guide_frame(mech, g, kin)[1]
            rn12, rt12, r03, r23 = rrp_reactions(z[ja], z[jb], unit, b2.resultant(shape), b3.resultant(shape),
                                                 b2.moment(z[jb], shape))
            give(pb, z[jb], r23)
            give(pc, z[jb], r03, couple=-b3.moment(z[jb], shape))
            give(pa, z[ja], rn12 + rt12, rn12, rt12)
        elif g.kind == "PRP":
            (jb,) = g.joints
            e1, e2 = np.exp(1j * kin.angle[g.links[0]]), np.exp(1j * kin.angle[g.links[1]])
            r12, r23, r03 = prp_reactions(e1, e2, b2.resultant(shape), b3.resultant(shape))
            give(pb, z[jb], r23)
            give(pc, z[jb], r03, couple=-b3.moment(z[jb], shape))
            give(pa, z[jb], r12, couple=-b2.moment(z[jb], shape))
        elif g.kind == "RPP":
            ja, jy = g.joints
            es, eg = np.exp(1j * kin.angle[g.links[0]]), np.exp(1j * kin.angle[g.links[1]])
            r12, r23, m23, r03, m03 = rpp_reactions(z[ja], z[jy], es, eg, b2.resultant(shape), b3.resultant(shape),
                                                    b2.moment(z[ja], shape), b3.moment(z[jy], shape))
            give(pb, z[ja], r23, couple=m23)
            give(pc, z[jy], r03, couple=m03)
            give(pa, z[ja], r12)
        else:
            ja, jc = g.joints
            unit = None if g.offset == 0.0 else np.exp(1j * kin.angle[g.links[1]])
            r12, r23, m23, r03 = rpr_reactions(z[ja], z[jc], b2.resultant(shape), b3.resultant(shape),
                                               b2.moment(z[ja], shape), b3.moment(z[jc], shape), unit)
            give(pb, z[ja], r23, couple=m23)
            give(pa, z[ja], r12)
            give(pc, z[jc], r03)
    crank = bodies[1]
    pivot = z[mech.crank.pivot]
    balancing = -crank.moment(pivot, shape)
    give(mech.pairs[0], pivot, -crank.resultant(shape))
    reactions = tuple(solved[p] for p in mech.pairs)
    return Kinetostatics(loading, reactions, balancing)
