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

On paper the course works the lever in one way, which :func:`lever_table` gives for one position
and both the sheet and the note print: the plan drawn at μ [(m/s)/mm] (:func:`lever_scale`), each
force's arm h [mm] about the pole p on that drawing, its moment ±F·h [N·mm] (counter-clockwise
positive), the balancing force F_ур = |ΣF·h|/(pa) at the crank's point a across pa, and
M_ур = F_ур·l_OA, compared with the force analysis's M_ур.
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


# the digits the lever's table is read with (sheet 2 and the note print the same): forces [N] and
# arms [mm] to 0.01, moments F·h [N·mm] to 0.1, pa [mm] and F_ур [N] to 0.01, M_ур [N·m] to 0.001
DECIMALS = {"force": 2, "arm": 2, "moment": 1, "pa": 2, "balancing_force": 2, "balancing": 3}

LEVER_MM = 180.0  # the lever's drawing at most this large [mm]: larger only crowds its field (at 220 mm
# the V compressor's lever of position 4 had no room on sheet 2 beside its indicator diagrams)
ROUND_MU = (1.0, 2.0, 2.5, 4.0, 5.0)  # a drafter's round scales ×10ⁿ


@record
class LeverTerm:
    """One force of the lever's table: its moment about the pole p of the drawn lever."""

    symbol: str  # as :class:`LeverForce`
    point: str
    force: float  # |F| [N]
    arm: float  # h [mm] on the lever drawn at the table's μ: the distance from p to the force's line
    moment: float  # ±F·h [N·mm], counter-clockwise positive
    sign: int  # +1 counter-clockwise, −1 clockwise, 0 (the line through p)


@record
class LeverTable:
    """Zhukovsky's lever of one position as the course works it on paper (one table for the sheet
    and the note)."""

    position: int  # list index of the position
    scale: float  # μ [(m/s)/mm] of the drawn lever (the arms' scale)
    terms: tuple[LeverTerm, ...]
    total: float  # ΣF·h [N·mm]
    pa: float  # the crank point's image, (pa) = ω₁·l_OA/μ [mm]
    crank: float  # l_OA [m]
    balancing_force: float  # F_ур = |ΣF·h|/(pa) [N], across pa at a
    balancing: float  # M_ур = F_ур·l_OA [N·m] (its size)
    sense: int  # the sense of M_ур by the lever: +1 counter-clockwise, −1 clockwise
    kinetostatic: float  # M_ур by the force analysis [N·m], counter-clockwise positive

    @property
    def difference_pct(self) -> float:
        """Δ = (|M_ур| − |M_ур by the lever|)/|M_ур|·100 [%] (0 where M_ур is 0)."""
        k = abs(self.kinetostatic)
        return 0.0 if k == 0.0 else 100.0 * (k - self.balancing) / k


def lever_scale(mu_v: float, points) -> float:
    """The scale μ [(m/s)/mm] of the lever's drawing: the velocity plan (drawn at μ_v; `points` its
    and the forces' points [mm from the pole]) turned and drawn at the smallest round μ from μ_v/4
    to μ_v at which its longest side is at most LEVER_MM; μ_v itself when none (the lever may be
    drawn at any scale: only the arms' ratios count).

    >>> lever_scale(0.01, [0j, 78j])   # 195 mm at 0,004, 156 mm at 0,005
    0.005
    >>> lever_scale(0.02, [0j, 200 + 0j])
    0.02
    """
    z = np.asarray(list(points), complex)
    size = float(max(np.ptp(z.real), np.ptp(z.imag), 1e-12))
    for mu in sorted(float(f"{c * 10.0 ** e:.6g}") for c in ROUND_MU for e in range(-9, 10)):
        if mu_v / 4.0 * (1 - 1e-9) <= mu <= mu_v * (1 + 1e-9) and size * mu_v / mu <= LEVER_MM:
            return mu
    return mu_v


def lever_table(mech: Mechanism, kin: Kinematics, lv: Lever, i: int, mu: float, kinetostatic: float) -> LeverTable:
    """The lever of position i drawn at μ [(m/s)/mm]: each force's arm h = |M_p|/(μ·F) [mm] and
    moment M_p/μ = ±F·h [N·mm] (M_p [W] its moment about the pole), ΣF·h, (pa) = |ω₁|·l_OA/μ [mm],
    F_ур = |ΣF·h|/(pa) [N] (the lever's equilibrium F_ур·(pa) = |ΣF·h|, F_ур across pa),
    M_ур = F_ур·l_OA [N·m]; the force analysis's M_ур beside it.

    >>> from types import SimpleNamespace as N
    >>> f = LeverForce("F", "B", np.array([2j]), np.array([-10 + 0j]), np.array([20.0]))
    >>> lv = Lever((f,), np.array([-20j]), np.array([-2.0]))   # as lever() finds them
    >>> t = lever_table(N(crank=N(length=0.1)), N(omega1=10.0), lv, 0, 0.01, -2.0)
    >>> t.terms[0].arm, t.terms[0].moment, t.pa, t.total / t.pa, t.balancing_force, t.balancing, t.sense
    (200.0, 2000.0, 100.0, 20.0, 20.0, 2.0, -1)
    """
    terms = []
    biggest = max((abs(complex(f.force[i])) for f in lv.forces), default=0.0)
    largest = max((abs(float(f.moment[i])) for f in lv.forces), default=0.0) / mu
    for f in lv.forces:
        size = abs(complex(f.force[i]))
        if size <= 1e-12 * max(biggest, 1e-300):
            continue
        m = float(f.moment[i]) / mu  # [W]/[(m/s)/mm] = [N·mm]
        sign = 0 if abs(m) <= 1e-12 * largest else int(np.sign(m))  # a line through p to rounding: no sense
        terms.append(LeverTerm(f.symbol, f.point, size, abs(m) / size, m, sign))
    total = sum(t.moment for t in terms)
    l1 = mech.crank.length
    pa = abs(kin.omega1) * l1 / mu
    mb = float(lv.balancing[i])  # the lever's own F_ур and M_ур (:func:`lever`): |ΣF·h|/(pa) and F_ур·l_OA
    return LeverTable(i, mu, tuple(terms), total, pa, l1, abs(complex(lv.balancing_force[i])), abs(mb),
                      1 if mb > 0 else -1 if mb < 0 else 0, float(kinetostatic))


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
