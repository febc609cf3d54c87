"""Zhukovsky's rigid lever: the balancing moment from the velocity plan turned through 90°.

N. E. Zhukovsky's theorem (Artobolevsky, "Теорема Н. Е. Жуковского о жёстком рычаге"; Frolov,
"Силовой анализ механизмов"): turn the velocity plan through 90° (here counter-clockwise: the tip
of the point P goes to i·v_P), apply every force of the mechanism at the image of its point,
parallel to itself; the plan is then a rigid lever pivoted at the pole, in equilibrium. A force's
moment about the pole, (i·v) × F = −F·v, is minus its power; a couple M on a link is carried
over as two forces M/l across the link at its two ends, whose moment on the lever is −M·ω. The
balancing moment is replaced by the force F_b at the crank's pin a, across OA:
ΣM_p(F) + M_p(F_b) = 0 with M_p(F_b) = −M_b·ω₁, so M_b = ΣM_p(F)/ω₁.

The numbers are those of the exact plans (:mod:`.chain`), so the lever gives the force analysis's
M_b to rounding; on paper the difference is the drawing's error (the book asks for < 1 %).
"""

from __future__ import annotations

import numpy as np

from ..records import record
from .chain import Kinematics
from .forces import Loading
from .mechanism import Mechanism
from .motion import cross


@record(eq=False)
class LeverForce:
    """One force on the lever: applied at the turned velocity image of its point."""

    symbol: str  # 'Φ2', 'G3', 'Fc', or 'MΦ2′' / 'MΦ2″' for the two forces of a couple
    point: str  # the name of the mechanism's point (its image on the lever is i·v)
    lever: np.ndarray  # the image: i·v_P (complex) [m/s]; on the drawing /μ_v [mm]
    force: np.ndarray  # the force, parallel to itself (complex) [N]
    moment: np.ndarray  # its moment about the pole, (i·v) × F = −F·v [N·m/s = W]


@record(eq=False)
class Lever:
    """Zhukovsky's lever at the kinematics' angles."""

    forces: tuple[LeverForce, ...]
    balancing_force: np.ndarray  # F_b at the crank's pin, across OA (complex) [N]
    balancing: np.ndarray  # M_b = ΣM_p/ω₁ [N·m], counter-clockwise positive

    @property
    def moment_sum(self):
        """Σ of the forces' moments about the pole [W]."""
        return sum((f.moment for f in self.forces), np.zeros(self.balancing.shape))


def lever_moment(v, f):
    """The moment [W] about the pole of the force F [N] applied at the image i·v of a point moving
    at v [m/s]: (i·v) × F = −F·v.

    >>> float(lever_moment(2.0 + 0j, 3.0 + 0j))   # the force along the velocity: minus its power
    -6.0
    """
    return cross(1j * np.asarray(v), f)


def couple_as_forces(x, y, m):
    """A couple M [N·m] on a link as two forces ±M/l across the link at its points x and y
    (the first at x): (x − y) × F = M. Returns F at x (−F acts at y), complex [N].

    >>> complex(couple_as_forces(1 + 0j, 0j, 5.0))   # M = 5 N·m on a 1 m link: 5 N up at x
    5j
    """
    d = np.asarray(x) - np.asarray(y)
    return 1j * d / np.abs(d) ** 2 * m


def pair_arm(mech: Mechanism) -> float:
    """The arm l [m] of the pair of forces that replaces the couple on a slider turning with its
    moving guide: the slider's pin B and the point Q (:func:`pair_point`) of the slider at l along the
    guide (a link without an axis has no second joint; any l gives the same moments, −M·ω, so the
    mechanism's size is taken, which keeps Q off b on the lever)."""
    return mech.scale_m


PAIR_LETTERS = "QUZ"  # a slider's second point: letters the note gives no other meaning (K, L, M, N, T, V, W have one)


def pair_point(mech: Mechanism, pin: str) -> str:
    """The name of the second point of a slider's pair (its couple as two forces, at its pin and at
    this point): a letter no joint or point of the mechanism has — not 'B′', which names a PRP's block
    — Q for the first such slider, U for the next (in the links' order).

    >>> from types import SimpleNamespace as NS
    >>> m = NS(joint_names=("O", "A", "Q", "B"), points=(NS(name="S3"),),
    ...        links=(NS(axis=("O", "A"), pins=("O", "A")), NS(axis=None, pins=("B",)), NS(axis=None, pins=("C",))))
    >>> pair_point(m, "B"), pair_point(m, "C")
    ('U', 'Z')
    """
    taken = set(mech.joint_names) | {p.name for p in mech.points}
    free = [ch for ch in PAIR_LETTERS if ch not in taken]
    pins = [ln.pins[0] for ln in mech.links if ln.axis is None]
    k = pins.index(pin) if pin in pins else len(free)
    return free[k] if k < len(free) else pin + "″"


def _ends(mech: Mechanism, kin: Kinematics, link: str):
    """Two points of a turning link and their names: its axis' ends (the slotted link: its pivot
    and its point under the block; a block: its joint and its point over the slotted link's pivot)."""
    ln = mech.link(link)
    if ln.axis is None:  # a slider turning with its moving guide: its pin B and Q at l along the guide
        pin = ln.pins[0]
        unit = np.exp(1j * kin.angle[link])
        return (pin, kin.z[pin]), (pair_point(mech, pin), kin.z[pin] + pair_arm(mech) * unit)
    a, b = ln.axis
    return (a, kin.z[a]), (b, kin.z[b])


def lever(mech: Mechanism, loading: Loading, kin: Kinematics) -> Lever:
    """Zhukovsky's lever for the applied forces and couples at the kinematics' angles."""
    out: list[LeverForce] = []
    for f in loading.forces:
        v, _ = kin.body_point(f.link, f.z)
        out.append(LeverForce(f.symbol, f.point, 1j * v, f.f, lever_moment(v, f.f)))
    for c in loading.couples:
        (na, za), (nb, zb) = _ends(mech, kin, c.link)
        force = couple_as_forces(za, zb, c.m)
        for name, z, sign, tick in ((na, za, 1.0, "′"), (nb, zb, -1.0, "″")):
            v, _ = kin.body_point(c.link, z)
            out.append(LeverForce(c.symbol + tick, name, 1j * v, sign * force, lever_moment(v, sign * force)))
    total = sum((f.moment for f in out), np.zeros(kin.phi.shape))
    crank = mech.crank
    r = kin.z[crank.joint] - kin.z[crank.pivot]
    w1 = kin.omega1
    # the balancing force across OA at a: (i·v_A) × F_b = −ω₁·r·F, F_b = F·i·r/|r|
    f_b = total / (w1 * np.abs(r)) * 1j * r / np.abs(r)
    return Lever(tuple(out), f_b, cross(r, f_b))
