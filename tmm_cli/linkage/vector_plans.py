"""The velocity plan and the acceleration plan of one position, as vectors (no drawing).

The graphical method of every TMM textbook (план скоростей, план ускорений; Artobolevsky;
Frolov; Pozhbelko, part 1), group by group in the order of the structural formula. Each point
of a plan is the tip of a vector from the pole (p for velocities, π for accelerations), labelled
with the small letter of its joint; fixed joints lie at the pole. The vector equations, with the
labels of the plans (link numbers as in :mod:`.mechanism`; the crank is link 1):

- crank O–A:   v_A = ω1 × OA (⊥ OA);  a_A = aⁿ_A (∥ AO, ω1²·l_OA) [+ aτ_A ⊥ OA if ε1 ≠ 0]
- RRR A–B–C:   v_B = v_A + v_BA (⊥ AB) = v_C + v_BC (⊥ BC);
               a_B = a_A + aⁿ_BA + aτ_BA = a_C + aⁿ_BC + aτ_BC  (points n2, n3: aⁿ = v²/l)
- RRP A–B:     v_B = v_A + v_BA (⊥ AB), v_B ∥ guide;  a_B = a_A + aⁿ_BA + aτ_BA ∥ guide; on a guide of
               a moving link k, Bk its point under the slider: v_B = v_A + v_BA = v_Bk + v_BBk (∥ guide),
               a_B = a_A + aⁿ_BA + aτ_BA = a_Bk + aᵏ_BBk + aʳ_BBk, aᵏ_BBk = 2·ω_k × v_BBk
- RPR A–C:     the point A3 of the slotted link 3 under the block 2 (A2 = A):
               v_A3 = v_A2 + v_A3A2 (∥ CA) = v_C + v_A3C (⊥ CA);
               a_A3 = a_A2 + aᵏ_A3A2 + aʳ_A3A2 (∥ CA) = a_C + aⁿ_A3C + aτ_A3C,
               aᵏ_A3A2 = 2·ω3 × v_A3A2 (Coriolis; point k); a slot offset from C: the
               relative vectors ∥ the slot (its line 'guide': the block's guide), not ∥ CA
- a point D of a link: by similarity (v_D = v_B + ω × BD), the vector pd / πd.

The values are the exact ones of :mod:`.chain` (the plans are their drawing); the scales μ_v,
μ_a are round numbers with the longest vector at most :data:`.scales.PLAN_MM` long.
"""

from __future__ import annotations

import numpy as np

from ..records import record
from .chain import Kinematics
from .mechanism import Mechanism
from .positions import Cycle, Position
from .scales import PLAN_MM, drafting_scale


@record
class PlanVector:
    """One vector of a plan: from point `start` to point `end` (plan labels)."""

    start: str
    end: str
    symbol: str  # 'v_A', 'v_BA', 'a^n_BA', 'a^τ_BA', 'a^k_A3A2', 'a^r_A3A2', 'a_B'
    value: complex  # [m/s] or [m/s²]
    relation: str  # '⊥' or '∥': how its line is drawn …
    line: str  # … to this line: 'AB' (a link; ∥ 'BA' also says the sense B → A) or 'guide'
    known: bool  # its magnitude is known before the plan is drawn (ω·l, ω²·l, 2ω·v_rel)

    @property
    def magnitude(self) -> float:
        return abs(self.value)


@record
class Equation:
    """One vector equation of the plan: `lhs` = sum of each entry of `sides` (all equal)."""

    group: int  # 0 the crank
    lhs: str  # 'v_B'
    sides: tuple[tuple[str, ...], ...]  # (('v_A', 'v_BA'), ('v_C', 'v_BC'))


@record
class Plan:
    """A velocity or acceleration plan: the points (tips from the pole) and the vectors drawn."""

    kind: str  # 'velocity' | 'acceleration'
    pole: str  # 'p' | 'π'
    points: dict[str, complex]  # label → tip [m/s or m/s²]; the pole at 0
    at_pole: tuple[str, ...]  # the labels of the fixed joints (drawn at the pole)
    vectors: tuple[PlanVector, ...]
    equations: tuple[Equation, ...]
    scale: float  # μ [(m/s)/mm] or [(m/s²)/mm]

    def mm(self, label: str) -> complex:
        """The point's place on the drawing [mm] from the pole."""
        return self.points[label] / self.scale


@record
class Plans:
    position: Position
    velocity: Plan
    acceleration: Plan


def _lc(name: str) -> str:
    return name.lower()


class _Draft:
    def __init__(self, kind: str, pole: str):
        self.kind, self.pole = kind, pole
        self.points: dict[str, complex] = {pole: 0j}
        self.vectors: list[PlanVector] = []
        self.equations: list[Equation] = []

    def add(self, start, end, symbol, value, relation, line, known, tip=None):
        if tip is not None:
            self.points[end] = complex(tip)
        self.vectors.append(PlanVector(start, end, symbol, complex(value), relation, line, known))


def _scale(plan_points: dict[str, complex], room_mm: float) -> float:
    return drafting_scale(max(abs(z) for z in plan_points.values()), room_mm)


def plans_at(mech: Mechanism, kin: Kinematics, position: Position, room_mm: float = PLAN_MM) -> Plans:
    """Both plans of one position; `kin` holds that position alone (``Cycle.kin.at(i)``)."""
    z = {n: complex(x[0]) for n, x in kin.z.items()}
    v = {n: complex(x[0]) for n, x in kin.v.items()}
    a = {n: complex(x[0]) for n, x in kin.a.items()}
    w = {n: float(x[0]) for n, x in kin.omega.items()}
    fixed = set(mech.frame)  # their plan points are the poles
    lab = {n: (("p", "π") if n in fixed else (_lc(n), _lc(n))) for n in z}
    V, A = _Draft("velocity", "p"), _Draft("acceleration", "π")
    one_slot = sum((g.kind == "RPR") + sum(gd.moving for gd in g.guides) +
                   (g.kind in ("RRP", "RPP") and g.guide.moving) for g in mech.groups) == 1  # its Coriolis point is k
    c = mech.crank
    o, ja = c.pivot, c.joint
    V.add("p", _lc(ja), f"v_{ja}", v[ja], "⊥", o + ja, True, v[ja])
    if kin.eps1 == 0.0:
        A.add("π", _lc(ja), f"a_{ja}", a[ja], "∥", ja + o, True, a[ja])
    else:
        an = -kin.omega1 ** 2 * (z[ja] - z[o])
        A.add("π", "n1", f"a^n_{ja}", an, "∥", ja + o, True, an)
        A.add("n1", _lc(ja), f"a^τ_{ja}", a[ja] - an, "⊥", o + ja, False, a[ja])
        A.add("π", _lc(ja), f"a_{ja}", a[ja], "", "", False)
        A.equations.append(Equation(0, f"a_{ja}", ((f"a^n_{ja}", f"a^τ_{ja}"),)))
    V.equations.append(Equation(0, f"v_{ja}", ((f"ω1×{o}{ja}",),)))
    _group_points(mech, 0, z, v, a, lab, V, A)
    for g in mech.groups:
        n2, n3 = g.numbers
        l1, l2 = g.links
        if g.kind == "RRR":
            ja, jb, jc = g.joints
            V.add(lab[ja][0], _lc(jb), f"v_{jb}{ja}", v[jb] - v[ja], "⊥", ja + jb, False, v[jb])
            V.add(lab[jc][0], _lc(jb), f"v_{jb}{jc}", v[jb] - v[jc], "⊥", jb + jc, False)  # = pb if C is fixed
            V.add("p", _lc(jb), f"v_{jb}", v[jb], "", "", False)
            V.equations.append(Equation(g.index, f"v_{jb}", ((f"v_{ja}", f"v_{jb}{ja}"), (f"v_{jc}", f"v_{jb}{jc}"))))
            na = a[ja] - w[l1] ** 2 * (z[jb] - z[ja])
            nc = a[jc] - w[l2] ** 2 * (z[jb] - z[jc])
            A.add(lab[ja][1], f"n{n2}", f"a^n_{jb}{ja}", na - a[ja], "∥", jb + ja, True, na)
            A.add(f"n{n2}", _lc(jb), f"a^τ_{jb}{ja}", a[jb] - na, "⊥", ja + jb, False, a[jb])
            A.add(lab[jc][1], f"n{n3}", f"a^n_{jb}{jc}", nc - a[jc], "∥", jb + jc, True, nc)
            A.add(f"n{n3}", _lc(jb), f"a^τ_{jb}{jc}", a[jb] - nc, "⊥", jb + jc, False)
            A.add("π", _lc(jb), f"a_{jb}", a[jb], "", "", False)
            A.equations.append(Equation(g.index, f"a_{jb}", ((f"a_{ja}", f"a^n_{jb}{ja}", f"a^τ_{jb}{ja}"),
                                                            (f"a_{jc}", f"a^n_{jb}{jc}", f"a^τ_{jb}{jc}"))))
        elif g.kind == "PRP":
            _prp_plans(mech, kin, g, z, v, a, w, lab, V, A, one_slot)
        elif g.kind == "RPP":
            _rpp_plans(mech, kin, g, z, v, a, w, lab, V, A, one_slot)
        elif g.kind == "RRP" and g.guide.moving:
            ja, jb = g.joints
            gl = g.guide.link
            pg = f"{jb}{mech.link(gl).number}"  # the guide's point under the slider
            vg, ag = (complex(x[0]) for x in kin.body_point(gl, kin.z[jb]))
            wg = w[gl]
            vr = v[jb] - vg  # v_BBk: the slider along the guide
            cor = 2j * wg * vr  # aᵏ_BBk = 2·ω_k × v_BBk
            V.add("p", _lc(pg), f"v_{pg}", vg, "", "", True, vg)
            V.add(lab[ja][0], _lc(jb), f"v_{jb}{ja}", v[jb] - v[ja], "⊥", ja + jb, False, v[jb])
            V.add(_lc(pg), _lc(jb), f"v_{jb}{pg}", vr, "∥", "guide", False)
            V.add("p", _lc(jb), f"v_{jb}", v[jb], "", "", False)
            V.equations.append(Equation(g.index, f"v_{jb}", ((f"v_{ja}", f"v_{jb}{ja}"), (f"v_{pg}", f"v_{jb}{pg}"))))
            na = a[ja] - w[l1] ** 2 * (z[jb] - z[ja])
            kl = "k" if one_slot else f"k{n3}"
            A.add("π", _lc(pg), f"a_{pg}", ag, "", "", True, ag)
            A.add(lab[ja][1], f"n{n2}", f"a^n_{jb}{ja}", na - a[ja], "∥", jb + ja, True, na)
            A.add(f"n{n2}", _lc(jb), f"a^τ_{jb}{ja}", a[jb] - na, "⊥", ja + jb, False, a[jb])
            A.add(_lc(pg), kl, f"a^k_{jb}{pg}", cor, "⊥", "guide", True, ag + cor)
            A.add(kl, _lc(jb), f"a^r_{jb}{pg}", a[jb] - ag - cor, "∥", "guide", False)
            A.add("π", _lc(jb), f"a_{jb}", a[jb], "", "", False)
            A.equations.append(Equation(g.index, f"a_{jb}", ((f"a_{ja}", f"a^n_{jb}{ja}", f"a^τ_{jb}{ja}"),
                                                            (f"a_{pg}", f"a^k_{jb}{pg}", f"a^r_{jb}{pg}"))))
        elif g.kind == "RRP":
            ja, jb = g.joints
            V.add(lab[ja][0], _lc(jb), f"v_{jb}{ja}", v[jb] - v[ja], "⊥", ja + jb, False, v[jb])
            V.add("p", _lc(jb), f"v_{jb}", v[jb], "∥", "guide", False)
            V.equations.append(Equation(g.index, f"v_{jb}", ((f"v_{ja}", f"v_{jb}{ja}"),)))
            na = a[ja] - w[l1] ** 2 * (z[jb] - z[ja])
            A.add(lab[ja][1], f"n{n2}", f"a^n_{jb}{ja}", na - a[ja], "∥", jb + ja, True, na)
            A.add(f"n{n2}", _lc(jb), f"a^τ_{jb}{ja}", a[jb] - na, "⊥", ja + jb, False, a[jb])
            A.add("π", _lc(jb), f"a_{jb}", a[jb], "∥", "guide", False)
            A.equations.append(Equation(g.index, f"a_{jb}", ((f"a_{ja}", f"a^n_{jb}{ja}", f"a^τ_{jb}{ja}"),)))
        else:
            ja, jc = g.joints
            p3 = f"{ja}{n3}"  # the point of the slotted link under the block
            p2 = f"{ja}{n2}"
            v3, a3 = (complex(x[0]) for x in kin.body_point(l2, kin.z[ja]))
            w3 = w[l2]
            vr = v3 - v[ja]  # v_A3A2
            cor = 2j * w3 * vr  # aᵏ_A3A2 = 2·ω3 × v_A3A2
            slot = jc + ja if g.offset == 0.0 else "guide"  # the block's relative motion: along the slot
            V.add(lab[ja][0], _lc(p3), f"v_{p3}{p2}", vr, "∥", slot, False, v3)
            V.add(lab[jc][0], _lc(p3), f"v_{p3}{jc}", v3 - v[jc], "⊥", jc + ja, False)  # = pa3 if C is fixed
            V.add("p", _lc(p3), f"v_{p3}", v3, "", "", False)
            V.equations.append(Equation(g.index, f"v_{p3}", ((f"v_{p2}", f"v_{p3}{p2}"), (f"v_{jc}", f"v_{p3}{jc}"))))
            kpt = a[ja] + cor
            kl = "k" if one_slot else f"k{n3}"
            nc = a[jc] - w3 ** 2 * (z[ja] - z[jc])
            A.add(lab[ja][1], kl, f"a^k_{p3}{p2}", cor, "⊥", slot, True, kpt)
            A.add(kl, _lc(p3), f"a^r_{p3}{p2}", a3 - kpt, "∥", slot, False, a3)
            A.add(lab[jc][1], f"n{n3}", f"a^n_{p3}{jc}", nc - a[jc], "∥", ja + jc, True, nc)
            A.add(f"n{n3}", _lc(p3), f"a^τ_{p3}{jc}", a3 - nc, "⊥", jc + ja, False)
            A.add("π", _lc(p3), f"a_{p3}", a3, "", "", False)
            A.equations.append(Equation(g.index, f"a_{p3}", ((f"a_{p2}", f"a^k_{p3}{p2}", f"a^r_{p3}{p2}"),
                                                            (f"a_{jc}", f"a^n_{p3}{jc}", f"a^τ_{p3}{jc}"))))
        _group_points(mech, g.index, z, v, a, lab, V, A)
    at_pole = tuple(_lc(n) for n in mech.frame)
    vel = Plan("velocity", "p", V.points, at_pole, tuple(V.vectors), tuple(V.equations), _scale(V.points, room_mm))
    acc = Plan("acceleration", "π", A.points, at_pole, tuple(A.vectors), tuple(A.equations), _scale(A.points, room_mm))
    return Plans(position, vel, acc)


def _slide_plans(kin, link, num: int, point: str, zp: complex, vp: complex, ap: complex, V: _Draft, A: _Draft,
                 kl: str, first: bool):
    """The point `point` (at zp with vp, ap) sliding along a guide or a slot of the link `link`
    (numbered `num`; None: a fixed guide): from that link's point under it (its label
    `point` + num, found by similarity) the relative vector ∥ the guide and, where it turns, the
    Coriolis one (2ω × v_rel, point `kl`) ⊥ it; from the pole along the guide when it is fixed.
    `first`: this side draws the point's tip. Returns the equation's sides (velocity, acceleration)."""
    if link is None:
        V.add("p", _lc(point), f"v_{point}", vp, "∥", "guide", False, vp if first else None)
        A.add("π", _lc(point), f"a_{point}", ap, "∥", "guide", False, ap if first else None)
        return None, None
    under = f"{point}{num}"
    vg, ag = (complex(x[0]) for x in kin.body_point(link, np.array([zp])))
    wg = float(kin.omega[link][0])
    vr = vp - vg
    cor = 2j * wg * vr
    V.add("p", _lc(under), f"v_{under}", vg, "", "", True, vg)
    V.add(_lc(under), _lc(point), f"v_{point}{under}", vr, "∥", "guide", False, vp if first else None)
    A.add("π", _lc(under), f"a_{under}", ag, "", "", True, ag)
    A.add(_lc(under), kl, f"a^k_{point}{under}", cor, "⊥", "guide", True, ag + cor)
    A.add(kl, _lc(point), f"a^r_{point}{under}", ap - ag - cor, "∥", "guide", False, ap if first else None)
    return (f"v_{under}", f"v_{point}{under}"), (f"a_{under}", f"a^k_{point}{under}", f"a^r_{point}{under}")


def _prp_plans(mech, kin, g, z, v, a, w, lab, V: _Draft, A: _Draft, one_slot: bool):
    """PRP: v_B = v_B1 + v_BB1 (∥ G1) = v_B2 + v_BB2 (∥ G2), B1, B2 the guides' links' points at B
    (a fixed guide: v_B ∥ it); the accelerations with the Coriolis terms of the turning guides."""
    (jb,) = g.joints
    sides_v, sides_a = [], []
    for i, gd in enumerate(g.guides):
        num = mech.link(gd.link).number if gd.moving else 0
        kl = "k" if one_slot else f"k{g.numbers[i]}"
        sv, sa = _slide_plans(kin, gd.link, num, jb, z[jb], v[jb], a[jb], V, A, kl, i == 0)
        if sv is not None:
            sides_v.append(sv)
            sides_a.append(sa)
    if len(sides_v) == 2:
        V.add("p", _lc(jb), f"v_{jb}", v[jb], "", "", False)
        A.add("π", _lc(jb), f"a_{jb}", a[jb], "", "", False)
    V.equations.append(Equation(g.index, f"v_{jb}", tuple(sides_v)))
    A.equations.append(Equation(g.index, f"a_{jb}", tuple(sides_a)))


def _rpp_plans(mech, kin, g, z, v, a, w, lab, V: _Draft, A: _Draft, one_slot: bool):
    """RPP: the yoke's point A3 under the block: v_A3 = v_A2 + v_A3A2 (∥ slot; A2 = A)
    = v_Ag + v_A3Ag (∥ guide; Ag the guide's link's point, the pole for a fixed guide), the
    accelerations with the Coriolis terms where the yoke turns; Y by similarity."""
    ja, jy = g.joints
    n2, n3 = g.numbers
    yoke = g.links[1]
    p3 = f"{ja}{n3}"
    v3, a3 = (complex(x[0]) for x in kin.body_point(yoke, kin.z[ja]))
    wy = float(kin.omega[yoke][0])
    vr = v3 - v[ja]  # v_A3A2
    cor = 2j * wy * vr
    kl = "k" if one_slot else f"k{n2}"
    V.add(lab[ja][0], _lc(p3), f"v_{p3}{ja}{n2}", vr, "∥", "slot", False, v3)
    side_a_v = (f"v_{ja}", f"v_{p3}{ja}{n2}")
    A.add(lab[ja][1], kl, f"a^k_{p3}{ja}{n2}", cor, "⊥", "slot", True, a[ja] + cor)
    A.add(kl, _lc(p3), f"a^r_{p3}{ja}{n2}", a3 - a[ja] - cor, "∥", "slot", False, a3)
    side_a_a = (f"a_{ja}", f"a^k_{p3}{ja}{n2}", f"a^r_{p3}{ja}{n2}")
    gd = g.guide
    num = mech.link(gd.link).number if gd.moving else 0
    sv, sa = _slide_plans(kin, gd.link, num, p3, z[ja], v3, a3, V, A, "k" if one_slot else f"k{n3}", False)
    if sv is None:
        V.equations.append(Equation(g.index, f"v_{p3}", (side_a_v,)))
        A.equations.append(Equation(g.index, f"a_{p3}", (side_a_a,)))
    else:
        V.add("p", _lc(p3), f"v_{p3}", v3, "", "", False)
        A.add("π", _lc(p3), f"a_{p3}", a3, "", "", False)
        V.equations.append(Equation(g.index, f"v_{p3}", (side_a_v, sv)))
        A.equations.append(Equation(g.index, f"a_{p3}", (side_a_a, sa)))
    V.add("p", _lc(jy), f"v_{jy}", v[jy], "", "", False, v[jy])  # the yoke's joint by similarity
    A.add("π", _lc(jy), f"a_{jy}", a[jy], "", "", False, a[jy])


def _group_points(mech: Mechanism, group: int, z, v, a, lab, V: _Draft, A: _Draft):
    """Named points of the group's links, by similarity (their tips from the pole)."""
    group_of = {ln.name: ln.group for ln in mech.links}
    for pt in mech.points:
        if group_of[pt.link] == group:
            V.add("p", _lc(pt.name), f"v_{pt.name}", v[pt.name], "", "", False, v[pt.name])
            A.add("π", _lc(pt.name), f"a_{pt.name}", a[pt.name], "", "", False, a[pt.name])


def nearest_even(cycle: Cycle, travel: float) -> int:
    """The list index of the evenly spaced position nearest the crank travel `travel` from
    position 0 [rad] (measured round the turn: 350° is 20° from 10°)."""
    evens = [p for p in cycle.positions if p.extreme is None or p.label.isdigit()]

    def gap(p):
        d = float(np.remainder(p.travel - travel, 2.0 * np.pi))
        return min(d, 2.0 * np.pi - d)
    return min(evens, key=gap).index


DEGENERATE_MM = 2.0  # a plan narrower than this, or a moving point's vector shorter, shows no construction


@record
class Degeneracy:
    """Why the plans of a position cannot show their groups' construction: the `plan` ('velocity' or
    'acceleration') collapses to a line (`point` None), or the vector of the moving joint `point` is
    shorter than :data:`DEGENERATE_MM` at the plan's scale (its tip lies at the pole)."""

    plan: str
    point: str | None


def degeneracy(mech: Mechanism, pl: Plans, limit_mm: float = DEGENERATE_MM) -> Degeneracy | None:
    """None when both plans of `pl` can be drawn and checked, else the first reason they cannot.

    A plan whose points all lie within a strip narrower than `limit_mm` [mm] at its scale is a line:
    the directions of its vector equations (⊥ a link, ∥ a guide) cannot be seen to meet. A moving
    joint (or named point) whose vector is shorter than `limit_mm` lies at the pole: the triangle of
    its group collapses (e.g. the Scotch yoke at φ = 90°: the block does not slide, v_A3A2 = 0, and the
    yoke's acceleration is 0). The textbooks build the plans in a general position for this reason
    (Artobolevsky, ch. 3: «в произвольном положении»).

    >>> from types import SimpleNamespace as N
    >>> flat = N(kind="velocity", scale=0.01, points={"p": 0j, "a": 0.5j, "b": 0.5j}, at_pole=("p",))
    >>> good = N(kind="acceleration", scale=0.1, points={"π": 0j, "a": -5j, "b": 3 + 0j}, at_pole=("π",))
    >>> m = N(joint_names=("O", "A", "B"), frame={"O": 0j}, points=())
    >>> degeneracy(m, N(velocity=flat, acceleration=good))
    Degeneracy(plan='velocity', point=None)
    >>> degeneracy(m, N(velocity=good, acceleration=good)) is None
    True
    """
    moving = [n for n in (*mech.joint_names, *(pt.name for pt in mech.points)) if n not in mech.frame]
    for plan in (pl.velocity, pl.acceleration):
        tips = np.array([complex(z) / plan.scale for z in plan.points.values()])
        xy = np.c_[tips.real, tips.imag]
        xy = xy - xy.mean(axis=0)
        if len(xy) < 3 or float(np.abs(xy @ np.linalg.svd(xy, full_matrices=False)[2][1]).max()) < limit_mm:
            return Degeneracy(plan.kind, None)
        for n in moving:
            tip = plan.points.get(_lc(n))
            if tip is not None and abs(complex(tip)) / plan.scale < limit_mm:
                return Degeneracy(plan.kind, n)
    return None


def _on_stroke(cycle: Cycle, p: Position, working: bool | None) -> bool:
    """Whether the evenly spaced position `p` lies strictly inside the working (True) or the return
    (False) stroke; `working` None: within a quarter turn of anything (an output turning fully)."""
    if working is None or cycle.working is None:
        return True
    t = float(np.remainder(p.travel - cycle.lead, 2.0 * np.pi))
    return 1e-9 < t < cycle.working - 1e-9 if working else cycle.working + 1e-9 < t < 2.0 * np.pi - 1e-9


def _general_near(cycle: Cycle, travel: float, working: bool | None) -> int:
    """The list index of the evenly spaced position nearest the crank travel `travel` [rad] on its
    stroke whose plans are not degenerate (:func:`degeneracy`); the nearest itself when all are."""
    evens = [p for p in cycle.positions if (p.extreme is None or p.label.isdigit()) and _on_stroke(cycle, p, working)]

    def rank(p):  # of two as near, the one after the target (further into the stroke)
        d = float(np.remainder(p.travel - travel, 2.0 * np.pi))
        return round(min(d, 2.0 * np.pi - d), 9), d > np.pi
    if not evens:
        return nearest_even(cycle, travel)
    ranked = sorted(evens, key=rank)
    for p in ranked:
        if degeneracy(cycle.mechanism, plans(cycle, p.index)) is None:
            return p.index
    return ranked[0].index


def middle_of_working(cycle: Cycle) -> int | None:
    """The list index of the evenly spaced position nearest the middle of the working stroke
    (counted from its start extreme), None when the output turns fully."""
    return None if cycle.working is None else nearest_even(cycle, cycle.lead + 0.5 * cycle.working)


def default_plan_positions(cycle: Cycle) -> tuple[int, int]:
    """The positions of the two plans a sheet shows (list indices): the evenly spaced positions
    nearest the middle of the working and of the return stroke, both counted from the extreme
    position where the working stroke starts (whatever position 0 is: ``crank.start_deg``); without
    extreme positions, the positions a quarter and three quarters of a turn from position 0. A
    position whose plans are degenerate (:func:`degeneracy`: the Scotch yoke's and the central
    crank-slider's middle of the stroke) gives way to the next nearest on the same stroke. The file's
    `plan` key, if given, is the first."""
    if cycle.working is None:
        targets = ((0.5 * np.pi, None), (1.5 * np.pi, None))
    else:
        targets = ((cycle.lead + 0.5 * cycle.working, True),
                   (cycle.lead + cycle.working + 0.5 * cycle.returning, False))
    picks = [_general_near(cycle, t, w) for t, w in targets]
    given = cycle.mechanism.plan
    if given is not None:
        i = cycle.index(given)
        if i is not None:
            picks[0] = i
    return picks[0], picks[1]


def plans(cycle: Cycle, index: int, room_mm: float = PLAN_MM) -> Plans:
    """Both plans of the cycle's position number `index` (a list index)."""
    return plans_at(cycle.mechanism, cycle.kin.at(index), cycle.positions[index], room_mm)



def book_symbols(mech: Mechanism) -> dict[str, str]:
    """The relative vectors the plans name by a joint alone — a slider on a moving guide 'v_BB3', a
    PRP's block 'v_BB3' (and their 'a^k_…', 'a^r_…') — in the book's form, each point with the number
    of its link, as 'v_A3A2' of a block in a slot: 'v_B5B3' (the point B of slider 5 relative to the
    point B3 of the guide's link 3). What the sheets and the note write; the JSON and the equations
    keep the plans' own symbols (they are keys). Kinematics of a point on a moving link: the relative
    and the Coriolis accelerations of a point of one link relative to the coincident point of the
    other (Artobolevsky, «Теория механизмов и машин», the velocity and acceleration plans of a
    rocker mechanism).

    >>> from .mechanism_file import parse_mechanism
    >>> m = parse_mechanism({"frame": {"O": [0, 0], "C": [0, -0.3]}, "crank": {"pivot": "O", "joint": "A",
    ...     "length": 0.1, "rpm": 60}, "group": [{"kind": "RPR", "joints": ["A", "C"]},
    ...     {"kind": "PRP", "joints": ["B"], "guides": [{"link": ["C", "A"], "angle_deg": 0.0},
    ...     {"through": [0.0, 0.22], "angle_deg": 0.0}]}]}, "t")
    >>> book_symbols(m)["a^k_BB3"]
    'a^k_B4B3'
    """
    out: dict[str, str] = {}
    for g in mech.groups:
        if g.kind == "RRP" and g.guide is not None and g.guide.moving:
            jb = g.joints[1]
            pairs = [(f"{jb}{mech.link(g.guide.link).number}", f"{jb}{g.numbers[1]}")]
        elif g.kind == "PRP":
            jb = g.joints[0]
            pairs = [(f"{jb}{mech.link(gd.link).number}", f"{jb}{n}") for gd, n in zip(g.guides, g.numbers)
                     if gd.moving]
        else:
            continue
        for under, mine in pairs:
            for head in ("v_", "a^k_", "a^r_"):
                out[f"{head}{jb}{under}"] = f"{head}{mine}{under}"
    return out


def book_symbol(mech: Mechanism, symbol: str) -> str:
    """`symbol` as the sheets and the note write it (:func:`book_symbols`)."""
    return book_symbols(mech).get(symbol, symbol)
