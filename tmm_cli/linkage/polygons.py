"""The force polygons of one position: each group's forces laid head to tail, closing at zero.

As the book draws them (Artobolevsky, "Кинетостатика"; METHOD.md "Sheets 1 and 2"): for an RRR
group Rτ₁₂, the forces on link 2, the forces on link 3, Rτ₀₃, then the two normal components that
close the polygon, Rⁿ₀₃ and Rⁿ₁₂; for an RRP group Rτ₁₂, the forces, R₀₃ ⊥ the guide and Rⁿ₁₂; for
an RPR group the forces, then R₀₃ and R₁₂; for the crank its forces and R₀₁. The forces of the
groups solved before appear with the opposite sign (link 3 carrying group 2 feels R₄₃ = −R₃₄).
Inner reactions (R₂₃) are not part of a group's polygon; they are in the reactions' table. The
scale μ_F [N/mm] is a drafter's round number with the longest vector at most 100 mm.
"""

from __future__ import annotations

import numpy as np

from ..records import record
from .forces import Loading
from .kinetostatics import Kinetostatics, pair_label
from .mechanism import Mechanism, Pair
from .scales import PLAN_MM, drafting_scale


@record
class PolygonVector:
    symbol: str  # 'Φ2', 'G2', 'Rτ12', 'Rn12', 'R03', 'R43' (a reaction of a later group, reversed)
    value: complex  # [N]
    kind: str  # 'applied' | 'later' (from a group solved before) | 'unknown' (found by this polygon)


@record
class ForcePolygon:
    group: int  # 0: the crank
    vectors: tuple[PolygonVector, ...]  # head to tail from the polygon's start
    scale: float  # μ_F [N/mm]

    @property
    def closure(self) -> complex:
        """The sum of the vectors [N]: zero when the polygon closes."""
        return sum((v.value for v in self.vectors), 0j)


def _reversed(pair: Pair) -> str:
    return pair_label(Pair(pair.joint, pair.kind, (pair.links[1], pair.links[0]), pair.group))


def _known(mech: Mechanism, loading: Loading, ks: Kinetostatics, number: int, i: int) -> list[PolygonVector]:
    forces, _ = loading.on(number)
    out = [PolygonVector(f.symbol, complex(f.f[i]), "applied") for f in forces]
    for r in ks.reactions:  # the opposite of a later group's reaction on this link
        if r.pair.links[0] == number and r.pair.group * 2 > number:
            out.append(PolygonVector(_reversed(r.pair), -complex(r.force[i]), "later"))
    return out


def force_polygons(mech: Mechanism, ks: Kinetostatics, i: int, room_mm: float = PLAN_MM) -> tuple[ForcePolygon, ...]:
    """The polygons of the position number `i` (an index into the kinetostatics' arrays), the last
    group first (the order of the force analysis), the crank last."""
    loading = ks.loading
    out = []

    def unknown(symbol: str, value) -> PolygonVector:
        return PolygonVector(symbol, complex(value[i]), "unknown")

    for g in reversed(mech.groups):
        n2, n3 = g.numbers
        known = _known(mech, loading, ks, n2, i) + _known(mech, loading, ks, n3, i)
        pa, _, pc = g.pairs
        ra, rc = ks.reaction(pair_label(pa)), ks.reaction(pair_label(pc))
        if g.kind == "RRR":
            vecs = [unknown("Rτ" + ra.label[1:], ra.tangential)] + known + [
                unknown("Rτ" + rc.label[1:], rc.tangential), unknown("Rn" + rc.label[1:], rc.normal),
                unknown("Rn" + ra.label[1:], ra.normal)]
        elif g.kind == "RRP":
            vecs = [unknown("Rτ" + ra.label[1:], ra.tangential)] + known + [
                unknown(rc.label, rc.force), unknown("Rn" + ra.label[1:], ra.normal)]
        else:
            vecs = known + [unknown(rc.label, rc.force), unknown(ra.label, ra.force)]
        out.append(ForcePolygon(g.index, tuple(vecs), _scale(vecs, room_mm)))
    r01 = ks.reaction(pair_label(mech.pairs[0]))
    vecs = _known(mech, loading, ks, 1, i) + [unknown(r01.label, r01.force)]
    out.append(ForcePolygon(0, tuple(vecs), _scale(vecs, room_mm)))
    return tuple(out)


def _scale(vecs, room_mm: float) -> float:
    """μ_F: the longest side of the polygon's box at most `room_mm` (the box of the running sums)."""
    tips = np.cumsum([0j] + [v.value for v in vecs])
    extent = max(float(np.ptp(tips.real)), float(np.ptp(tips.imag)), max((abs(v.value) for v in vecs), default=0.0))
    return drafting_scale(extent, room_mm)
