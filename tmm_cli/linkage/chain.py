"""The whole mechanism at given crank angles: the crank, then each group in the formula's order.

Positions by :mod:`.groups`, velocities and accelerations by :mod:`.motion`, named points by the
rigid-body formulas; every quantity is an array with one entry per crank angle. Planar vectors
are complex numbers x + iy. The crank turns at the mechanism's mean ω1 (or the `omega` given) with
angular acceleration ε1 (0: uniform); the angles φ are crank angles from +x, counter-clockwise.
"""

from __future__ import annotations

import math

import numpy as np

from ..records import record
from .groups import crank_position, rpr_position, rrp_position, rrr_position
from .mechanism import Mechanism
from .motion import rigid, rpr_motion, rrp_motion, rrp_moving_motion, rrr_motion, solve2


@record(eq=False)
class Kinematics:
    """Every joint, point and moving link at M crank angles (arrays of shape (M,); SI units).

    Points (`z`, `v`, `a`) are complex: x + iy. Links (`angle`, `omega`, `epsilon`) are real,
    counter-clockwise positive; a link named XY has the angle of the direction X → Y, in
    (−π, π]. `slide` holds, per slider or block link, its sliding coordinate and its first two
    time derivatives: a slider's place s along its guide from the guide's `through` point, a
    block's distance ρ from the slotted link's pivot (+ away from it).
    """

    phi: np.ndarray  # crank angle [rad]
    omega1: float  # crank ω [rad/s]
    eps1: float  # crank ε [rad/s²]
    z: dict[str, np.ndarray]  # [m]
    v: dict[str, np.ndarray]  # [m/s]
    a: dict[str, np.ndarray]  # [m/s²]
    angle: dict[str, np.ndarray]  # [rad]
    omega: dict[str, np.ndarray]  # [rad/s]
    epsilon: dict[str, np.ndarray]  # [rad/s²]
    slide: dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]]  # [m, m/s, m/s²]
    base: dict[str, str]  # link → a pin of it (the reference of :meth:`body_point`)

    def body_point(self, link: str, z):
        """Velocity and acceleration [m/s, m/s²] of the point of `link` that is at `z` now
        (e.g. the point of a slotted link under its block: the plans' A3)."""
        r = np.asarray(z) - self.z[self.base[link]]
        b = self.base[link]
        return rigid(r, self.v[b], self.a[b], self.omega[link], self.epsilon[link])

    def at(self, k: int) -> "Kinematics":
        """The same record for the single angle number k (arrays of shape (1,))."""
        s = slice(k, k + 1)
        return Kinematics(
            self.phi[s], self.omega1, self.eps1, {n: x[s] for n, x in self.z.items()},
            {n: x[s] for n, x in self.v.items()}, {n: x[s] for n, x in self.a.items()},
            {n: x[s] for n, x in self.angle.items()}, {n: x[s] for n, x in self.omega.items()},
            {n: x[s] for n, x in self.epsilon.items()}, {n: tuple(q[s] for q in x) for n, x in self.slide.items()},
            self.base)


def slot_axis(mech: Mechanism, kin: Kinematics, link: str):
    """(foot, u) of a slotted link over the angles of `kin`: the foot of the perpendicular from
    its pivot C to its slot [m] and the slot's unit direction towards the block — the slot is
    foot + t·u (foot = C when the slot passes through the pivot)."""
    ln = mech.link(link)
    g = mech.groups[ln.group - 1]
    ja, jc = g.joints
    if g.offset == 0.0:
        r = kin.z[ja] - kin.z[jc]
        return kin.z[jc], r / np.abs(r)
    u = np.exp(1j * kin.angle[link])
    return kin.z[jc] + 1j * g.offset * u, u


def _link_direction(mech: Mechanism, z, angle, link: str, base: str, toward: str):
    """The unit direction of a link's frame for its points and guides: base → toward, or, on a
    slotted link whose slot is offset from its pivot, the slot's direction u."""
    ln = mech.link(link)
    if ln.kind == "slotted" and mech.groups[ln.group - 1].offset != 0.0:
        return np.exp(1j * angle[link])
    d = z[toward] - z[base]
    return d / np.abs(d)


def _guide_line(mech: Mechanism, g, z, angle, gd=None):
    """(through, unit) of the group's guide (or of the Guide `gd`) with the positions `z` (arrays
    for a moving guide)."""
    gd = g.guide if gd is None else gd
    if not gd.moving:
        return gd.through, gd.unit
    d = _link_direction(mech, z, angle, gd.link, gd.base, gd.toward)
    return z[gd.base] + complex(gd.along, gd.across) * d, d * np.exp(1j * gd.angle)


def guide_frame(mech: Mechanism, g, kin: Kinematics):
    """(through, unit) of an RRP group's guide over the angles of `kin`: a point of its line [m]
    and its unit direction — constants broadcast for a fixed guide, turning with its link for a
    guide on a moving link."""
    p, e = _guide_line(mech, g, kin.z, kin.angle)
    shape = kin.phi.shape
    return np.zeros(shape, dtype=complex) + p, np.zeros(shape, dtype=complex) + e


def slider_unit(mech: Mechanism, link: str, kin: Kinematics):
    """The unit direction a slider or block slides along over the angles of `kin`: its guide's
    (an RPP's block: the yoke's slot)."""
    ln = mech.link(link)
    g = mech.groups[ln.group - 1]
    if g.kind == "RRP" and not g.guide.moving:
        return np.zeros(kin.phi.shape, dtype=complex) + g.guide.unit
    return np.exp(1j * kin.angle[link])


def slider_pose(mech: Mechanism, kin: Kinematics, link: str, i: int):
    """How a slider or block of a guide looks at the angle number i, for the drawings: (centre [m],
    angle [rad], segments) — the segments [(p0, p1)] of a moving guide from its point on the link
    past the slider, and of an RPP yoke's slot through Y past the block."""
    ln = mech.link(link)
    g = mech.groups[ln.group - 1]
    centre = complex(kin.z[ln.pins[0]][i])
    if g.kind == "RRP" and not g.guide.moving:
        return centre, g.guide.angle, []
    angle = float(kin.angle[link][i])
    e = complex(np.exp(1j * angle))
    segs = []
    gd = dict(mech.guided()).get(link)
    if gd is not None and gd.moving:
        p, _ = _guide_line(mech, g, {n: x[i:i + 1] for n, x in kin.z.items()},
                           {n: x[i:i + 1] for n, x in kin.angle.items()}, gd)
        p = complex(np.atleast_1d(p)[0])
        t = ((centre - p) * e.conjugate()).real
        reach = 0.12 * mech.scale_m
        segs.append((p + min(0.0, t - reach) * e, p + max(0.0, t + reach) * e))
    if g.kind == "RPP" and link == g.links[1]:
        es = complex(np.exp(1j * kin.angle[g.links[0]][i]))
        t = float(kin.slide[g.links[0]][0][i])
        half = 1.15 * max(abs(t), mech.crank.length)  # the slot covers the block's travel (±r in a Scotch yoke)
        segs.append((centre - half * es, centre + half * es))
    return centre, angle, segs


def _guide_point(gd, at, z, v, a, omega, eps, base, shape):
    """Velocity, acceleration of the guide's link's point at `at`, and the link's ω, ε (zeros for a
    fixed guide)."""
    if not gd.moving:
        zero = np.zeros(shape)
        return zero + 0j, zero + 0j, zero, zero
    b = base[gd.link]
    vg, ag = rigid(at - z[b], v[b], a[b], omega[gd.link], eps[gd.link])
    return vg, ag, omega[gd.link], eps[gd.link]


def _prp(mech, g, z, v, a, angle, omega, eps, slide, base, shape):
    """PRP (kind 4): the joint B where the guides G1, G2 cross; block B′ slides on G1, block B on G2.

    B = P1 + s1·e1 = P2 + s2·e2; v_B = v_B1 + ṡ1·e1 = v_B2 + ṡ2·e2 (B1, B2 the guides' links'
    points at B); a_B = a_B1 + s̈1·e1 + 2ω1·ṡ1·ie1 = a_B2 + s̈2·e2 + 2ω2·ṡ2·ie2 (Coriolis where a
    guide turns). Each block turns with its guide's link."""
    (bj,) = g.joints
    l1, l2 = g.links
    g1, g2 = g.guides
    p1, e1 = _guide_line(mech, g, z, angle, g1)
    p2, e2 = _guide_line(mech, g, z, angle, g2)
    e1, e2 = np.zeros(shape) + e1, np.zeros(shape) + e2
    s1, s2 = solve2(e1, -e2, p2 - p1 + np.zeros(shape))
    b = p1 + s1 * e1
    v1, a1, w1, k1 = _guide_point(g1, b, z, v, a, omega, eps, base, shape)
    v2, a2, w2, k2 = _guide_point(g2, b, z, v, a, omega, eps, base, shape)
    d1, d2 = solve2(e1, -e2, v2 - v1)
    c1, c2 = 2j * w1 * d1 * e1, 2j * w2 * d2 * e2
    dd1, dd2 = solve2(e1, -e2, a2 + c2 - a1 - c1)
    z[bj], v[bj], a[bj] = b, v1 + d1 * e1, a1 + dd1 * e1 + c1
    angle[l1], angle[l2] = np.angle(e1), np.angle(e2)
    omega[l1], omega[l2], eps[l1], eps[l2] = w1, w2, k1, k2
    slide[l1], slide[l2] = (s1, d1, dd1), (s2, d2, dd2)
    base[l1] = base[l2] = bj


def _rpp(mech, g, z, v, a, angle, omega, eps, slide, base, shape):
    """RPP (kind 5): the block hinged at A slides in the yoke's slot (at `slot` from the guide's
    direction), the yoke slides along its guide; Y is where the slot's line crosses the guide's.

    A = P + s·e_g + t·e_s; the yoke moves as its guide's link does plus ṡ along it, so
    v_A = v_Ag + ṡ·e_g + ṫ·e_s and a_A = a_Ag + s̈·e_g + ẗ·e_s + 2ω_g·i(ṡ·e_g + ṫ·e_s) (Ag the
    guide's link's point at A; Coriolis where the guide turns); v_Y = v_Yg + ṡ·e_g."""
    ja, jy = g.joints
    l1, l2 = g.links
    p, eg = _guide_line(mech, g, z, angle)
    eg = np.zeros(shape) + eg
    es = eg * np.exp(1j * g.slot)
    s, t = solve2(eg, es, z[ja] - p)
    y = p + s * eg
    va_g, aa_g, w, k = _guide_point(g.guide, z[ja], z, v, a, omega, eps, base, shape)
    vy_g, ay_g, _, _ = _guide_point(g.guide, y, z, v, a, omega, eps, base, shape)
    ds, dt = solve2(eg, es, v[ja] - va_g)
    dds, ddt = solve2(eg, es, a[ja] - aa_g - 2j * w * (ds * eg + dt * es))
    z[jy], v[jy], a[jy] = y, vy_g + ds * eg, ay_g + dds * eg + 2j * w * ds * eg
    angle[l1], angle[l2] = np.angle(es), np.angle(eg)
    omega[l1] = omega[l2] = w
    eps[l1] = eps[l2] = k
    slide[l1], slide[l2] = (t, dt, ddt), (s, ds, dds)
    base[l1], base[l2] = ja, jy


def _points(mech: Mechanism, group: int, z, v, a, omega, eps, link_group, dirs):
    for pt in mech.points:
        if link_group[pt.link] != group:
            continue
        if pt.link in dirs:  # an offset slot: along u, across n = iu from the pivot
            r = complex(pt.along, pt.across) * dirs[pt.link]
        else:
            d = z[pt.toward] - z[pt.base]
            r = complex(pt.along, pt.across) * d / np.abs(d)
        z[pt.name] = z[pt.base] + r
        v[pt.name], a[pt.name] = rigid(r, v[pt.base], a[pt.base], omega[pt.link], eps[pt.link])


def solve(mech: Mechanism, phi, omega1: float | None = None, eps1: float = 0.0, upto: int | None = None) -> Kinematics:
    """Positions, velocities and accelerations at crank angle(s) φ [rad] (of the groups up to
    number `upto`, all by default). NaN where a group cannot be assembled (see :mod:`.assembly`).

    >>> from .mechanism_file import parse_mechanism
    >>> m = parse_mechanism({"frame": {"O": [0, 0]}, "crank": {"pivot": "O", "joint": "A",
    ...     "length": 0.06, "omega": 100.0}, "group": [{"kind": "RRP", "joints": ["A", "B"],
    ...     "length": 0.25, "guide": {"through": [0, 0], "angle_deg": 0}, "branch": "ahead"}]})
    >>> k = solve(m, [0.0])
    >>> round(float(k.z["B"][0].real), 12), round(float(k.a["B"][0].real), 4)   # x_B = r + l; a_B = −rω²(1 + r/l)
    (0.31, -744.0)
    """
    phi = np.atleast_1d(np.asarray(phi, dtype=float))
    w1 = mech.crank.omega if omega1 is None else float(omega1)
    e1 = float(eps1)
    zero = np.zeros(phi.shape, dtype=complex)
    z = {name: zero + p for name, p in mech.frame.items()}
    v = {name: zero.copy() for name in mech.frame}
    a = {name: zero.copy() for name in mech.frame}
    angle, omega, eps, slide, base, dirs = {}, {}, {}, {}, {}, {}
    link_group = {ln.name: ln.group for ln in mech.links}

    c = mech.crank
    name = mech.links[0].name
    z[c.joint] = crank_position(mech.frame[c.pivot], c.length, phi)
    r = z[c.joint] - z[c.pivot]
    v[c.joint], a[c.joint] = rigid(r, 0j, 0j, w1, e1)
    angle[name], omega[name], eps[name], base[name] = np.angle(r), np.full(phi.shape, w1), np.full(phi.shape, e1), c.pivot
    _points(mech, 0, z, v, a, omega, eps, link_group, dirs)

    for g in mech.groups:
        if upto is not None and g.index > upto:
            break
        l1, l2 = g.links
        if g.kind == "RRR":
            ja, jb, jc = g.joints
            z[jb] = rrr_position(z[ja], z[jc], g.lengths[0], g.lengths[1], g.branch)
            w2, w3, e2, e3, v[jb], a[jb] = rrr_motion(z[ja], z[jb], z[jc], v[ja], v[jc], a[ja], a[jc])
            angle[l1], angle[l2] = np.angle(z[jb] - z[ja]), np.angle(z[jc] - z[jb])
            base[l1], base[l2] = ja, jb
        elif g.kind == "RRP":
            ja, jb = g.joints
            if g.guide.moving:  # the guide turns with its link k: the slider turns with it
                through, unit = _guide_line(mech, g, z, angle)
                z[jb], s = rrp_position(z[ja], through, unit, g.lengths[0], g.branch)
                gl = g.guide.link
                w3, e3 = omega[gl], eps[gl]
                vg, ag = rigid(z[jb] - z[base[gl]], v[base[gl]], a[base[gl]], w3, e3)  # the guide's point under B
                w2, e2, ds, dds, v[jb], a[jb] = rrp_moving_motion(z[ja], z[jb], unit, v[ja], a[ja], vg, ag, w3)
                angle[l1], angle[l2] = np.angle(z[jb] - z[ja]), np.angle(unit)
            else:
                unit = g.guide.unit
                z[jb], s = rrp_position(z[ja], g.guide.through, unit, g.lengths[0], g.branch)
                w2, e2, ds, dds, v[jb], a[jb] = rrp_motion(z[ja], z[jb], unit, v[ja], a[ja])
                w3, e3 = np.zeros(phi.shape), np.zeros(phi.shape)
                angle[l1], angle[l2] = np.angle(z[jb] - z[ja]), np.full(phi.shape, math.remainder(g.guide.angle, 2 * math.pi))
            slide[l2] = (s, ds, dds)
            base[l1], base[l2] = ja, jb
        elif g.kind in ("PRP", "RPP"):
            (_prp if g.kind == "PRP" else _rpp)(mech, g, z, v, a, angle, omega, eps, slide, base, phi.shape)
            _points(mech, g.index, z, v, a, omega, eps, link_group, dirs)
            continue
        else:
            ja, jc = g.joints
            rho, theta = rpr_position(z[ja], z[jc], g.offset)
            w3, e3, dr, ddr = rpr_motion(z[ja], z[jc], v[ja], v[jc], a[ja], a[jc], g.offset)
            w2, e2 = w3, e3
            if g.offset == 0.0:
                angle[l1] = angle[l2] = np.angle(-np.exp(1j * theta))  # named AC: from A towards C
            else:  # an offset slot: the direction u of its slot
                dirs[l2] = np.exp(1j * theta)
                angle[l1] = angle[l2] = np.angle(dirs[l2])
            slide[l1] = (rho, dr, ddr)
            base[l1], base[l2] = ja, jc
        omega[l1], omega[l2], eps[l1], eps[l2] = w2, w3, e2, e3
        _points(mech, g.index, z, v, a, omega, eps, link_group, dirs)
    return Kinematics(phi, w1, e1, z, v, a, angle, omega, eps, slide, base)
