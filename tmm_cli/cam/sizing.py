"""Main dimensions from the pressure-angle condition, §1.3, (1.19)–(1.25).

The graphical "theorem on the position of the cam centre" in analytic form (METHOD.md, Sheet 3
item 2). For each constrained cam position φ the roller centre B, its rise direction u and the
point D with BD = V_B/ω_k laid along V_B turned 90° in the sense of ω_k (1.20) are known; the cam
centre O keeps the pressure angle ν ≤ ν_max (1.19) exactly when it lies in the wedge at D of
half-angle ν_max about −u. Each wedge is two half-planes, so the feasible centres form a convex
region, and the smallest base radius r0 = |O B0| (1.22), (1.25) is the distance from B0 to it.

Frames. All geometry is first built in a *canonical* frame: B0 (the roller centre at the start of
the rise) at the origin, the follower's rise direction at B0 along +y, the cam turning
counter-clockwise. A clockwise cam (n_k < 0) is the mirror image x → −x of that mechanism, so the
results are mirrored before they leave this module ("zone frame" = canonical frame mirrored when
the cam turns clockwise). For a rocker the pivot C is at (−σ·l_BC, 0) in the canonical frame:
σ = +1 means the rocker turns the same way as the cam during the rise, σ = −1 the opposite way.

Method. The wedges are sampled every 0.2° of cam angle over the constrained phases (force
closure: the rise; form closure: rise and return); the convex polygon they cut from a large square
is found by exact half-plane clipping and B0 is projected onto it (exact for the sampled
constraints). The pressure angle is then recomputed on a 0.05° grid; if it exceeds ν_max by more
than 0.005° between samples, the solve is repeated with ν_max reduced by the excess. The book's own
choice — the vertex where its two bounding lines meet — is computed beside it.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import TmmError
from ..records import record
from .motion import CamProgram

SAMPLE_DEG = 0.2  # spacing of the sampled wedges
CHECK_DEG = 0.05  # spacing of the pressure-angle check
TOL_DEG = 0.005  # allowed excess over ν_max between samples before re-solving


def rot90(v: np.ndarray) -> np.ndarray:
    """Rotate vectors (…, 2) by +90° (counter-clockwise)."""
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


@record(eq=False)
class FollowerState:
    """Roller centre B, dB/dφ, d²B/dφ² and unit rise direction u in the canonical frame [m]."""

    phi: np.ndarray
    s: np.ndarray
    b: np.ndarray
    b1: np.ndarray
    b2: np.ndarray
    u: np.ndarray
    pivot: tuple[float, float] | None


def follower_state(program: CamProgram, phi, *, rocker: bool, l_bc_m: float | None, sigma: int = 1) -> FollowerState:
    """Roller-centre kinematics against cam angle in the canonical frame (B0 at the origin).

    Translating follower: B = (0, S), u = (0, 1). Rocker of length l_BC pivoting at
    C = (−σ·l_BC, 0): B = C + l_BC·(cos θ, sin θ) with θ = θ0 + σγ, so S_B = γ·l_BC (1.6).

    >>> p = CamProgram(law=4, stroke=math.radians(30), phi_rise=1.0, phi_far=0.5, phi_return=1.0)
    >>> st = follower_state(p, [0.0, 1.0], rocker=True, l_bc_m=0.1)
    >>> [round(float(x), 9) for x in st.b[1]]  # l·(cos 30° − 1), l·sin 30°
    [-0.01339746, 0.05]
    """
    phi = np.atleast_1d(np.asarray(phi, dtype=float))
    s, s1, s2, _ = program.at(phi)
    if not rocker:
        zero = np.zeros_like(s)
        b = np.stack([zero, s], axis=-1)
        b1 = np.stack([zero, s1], axis=-1)
        b2 = np.stack([zero, s2], axis=-1)
        u = np.stack([zero, np.ones_like(s)], axis=-1)
        return FollowerState(phi, s, b, b1, b2, u, None)
    if not l_bc_m or l_bc_m <= 0:
        raise TmmError("a rocker needs a positive length l_BC; fill in l_bc_m")
    l = float(l_bc_m)
    theta = (0.0 if sigma > 0 else math.pi) + sigma * s
    e = np.stack([np.cos(theta), np.sin(theta)], axis=-1)
    ep = rot90(e)
    u = sigma * ep
    c = np.array([-sigma * l, 0.0])
    b = c + l * e
    b1 = (l * s1)[:, None] * u
    b2 = (l * s2)[:, None] * u - (l * s1**2)[:, None] * e
    return FollowerState(phi, s, b, b1, b2, u, (float(c[0]), float(c[1])))


def d_points(st: FollowerState) -> np.ndarray:
    """Points D: B plus V_B/ω_k turned +90° (the canonical cam turns counter-clockwise), (1.20)."""
    return st.b + rot90(st.b1)


def cone_angle_deg(centre, st: FollowerState) -> np.ndarray:
    """Pressure angle by the theorem on the cam centre: angle between O − D and −u [deg].

    >>> p = CamProgram(law=1, stroke=0.05, phi_rise=1.0, phi_far=0.5, phi_return=1.0)
    >>> st = follower_state(p, [0.5], rocker=False, l_bc_m=None)
    >>> round(float(cone_angle_deg((0.0, -0.1), st)[0]), 6)  # tan ν = S'/(r0 + S) = 0.1/0.125
    38.659808
    """
    o = np.asarray(centre, dtype=float)
    w = o - d_points(st)
    p = rot90(st.u)
    along = -(w * st.u).sum(axis=-1)
    across = np.abs((w * p).sum(axis=-1))
    return np.degrees(np.arctan2(across, along))


def _half_planes(st: FollowerState, nu: float) -> tuple[np.ndarray, np.ndarray]:
    """Both edges of every wedge as rows of A·O ≤ c."""
    d = d_points(st)
    p = rot90(st.u)
    rows, rhs = [], []
    for sgn in (1.0, -1.0):
        a = sgn * math.cos(nu) * p + math.sin(nu) * st.u
        rows.append(a)
        rhs.append((a * d).sum(axis=-1))
    return np.concatenate(rows), np.concatenate(rhs)


def _clip(poly: np.ndarray, a: np.ndarray, c: float) -> np.ndarray:
    """Convex polygon ∩ {x: a·x ≤ c} (one Sutherland–Hodgman step)."""
    vals = poly @ a - c
    inside = vals <= 0.0
    if inside.all():
        return poly
    if not inside.any():
        return poly[:0]
    nxt = np.roll(np.arange(len(poly)), -1)
    cross = inside != inside[nxt]
    with np.errstate(divide="ignore", invalid="ignore"):
        frac = np.where(cross, vals / (vals - vals[nxt]), 0.0)
    inter = poly + (poly[nxt] - poly) * frac[:, None]
    stacked = np.stack([poly, inter], axis=1).reshape(-1, 2)
    keep = np.stack([inside, cross], axis=1).reshape(-1)
    return stacked[keep]


def feasible_polygon(a: np.ndarray, c: np.ndarray, half_size: float) -> np.ndarray:
    """The convex polygon {x: A·x ≤ c} inside the square |x|, |y| ≤ half_size (vertices in order)."""
    m = half_size
    poly = np.array([[-m, -m], [m, -m], [m, m], [-m, m]])
    # clip first by a coarse subset, then only by the constraints still violated
    order = np.arange(0, len(a), max(1, len(a) // 64))
    for k in order:
        poly = _clip(poly, a[k], c[k])
        if len(poly) == 0:
            return poly
    for _ in range(50):
        viol = (poly @ a.T - c).max(axis=0)
        bad = np.nonzero(viol > 1e-12 * m)[0]
        if len(bad) == 0:
            break
        for k in bad[np.argsort(-viol[bad])]:
            poly = _clip(poly, a[k], c[k])
            if len(poly) == 0:
                return poly
    return poly


def nearest_point(poly: np.ndarray, point=(0.0, 0.0)) -> np.ndarray:
    """The point of a convex polygon (its boundary) nearest to `point`."""
    q = np.asarray(point, dtype=float)
    p0 = poly
    p1 = np.roll(poly, -1, axis=0)
    d = p1 - p0
    L2 = (d * d).sum(axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(L2 > 0, ((q - p0) * d).sum(axis=1) / L2, 0.0)
    t = np.clip(t, 0.0, 1.0)
    cand = p0 + d * t[:, None]
    dist = np.hypot(*(cand - q).T)
    return cand[int(np.argmin(dist))]


def _constrained_phis(program: CamProgram, closure: str, step_deg: float) -> tuple[np.ndarray, np.ndarray]:
    """Cam angles of the constrained positions and their phase (0 rise, 2 return)."""
    n_r = max(2, int(math.ceil(math.degrees(program.phi_rise) / step_deg)) + 1)
    phis = [np.linspace(0.0, program.phi_rise, n_r)]
    phase = [np.zeros(n_r, dtype=int)]
    if closure == "form":
        n_b = max(2, int(math.ceil(math.degrees(program.phi_return) / step_deg)) + 1)
        phis.append(np.linspace(program.return_start, program.phi_working, n_b))
        phase.append(np.full(n_b, 2, dtype=int))
    return np.concatenate(phis), np.concatenate(phase)


@record(eq=False)
class _Solve:
    sigma: int
    centre: np.ndarray
    r0: float
    nu_used: float
    polygon: np.ndarray
    nu_rise: float
    nu_return: float


def _scale(program: CamProgram, rocker: bool, l_bc_m: float | None) -> float:
    return (program.stroke * l_bc_m + l_bc_m) if rocker else program.stroke


def _achieved(centre, program, rocker, l_bc_m, sigma) -> tuple[float, float]:
    """Max pressure angle [deg] on the rise and on the return (0.05° grid, cone measure)."""
    out = []
    for a0, length in ((0.0, program.phi_rise), (program.return_start, program.phi_return)):
        n = max(3, int(math.ceil(math.degrees(length) / CHECK_DEG)) + 1)
        st = follower_state(program, np.linspace(a0, a0 + length, n), rocker=rocker, l_bc_m=l_bc_m, sigma=sigma)
        moving = np.abs(st.b1).sum(axis=1) > 0
        nu = cone_angle_deg(centre, st)[moving]
        out.append(float(nu.max()) if len(nu) else 0.0)
    return out[0], out[1]


def _solve(program, rocker, l_bc_m, nu_max_deg, closure, sigma) -> _Solve:
    phis, _ = _constrained_phis(program, closure, SAMPLE_DEG)
    st = follower_state(program, phis, rocker=rocker, l_bc_m=l_bc_m, sigma=sigma)
    size = 200.0 * _scale(program, rocker, l_bc_m)
    nu_used = math.radians(nu_max_deg)
    for _ in range(4):
        a, c = _half_planes(st, nu_used)
        poly = feasible_polygon(a, c, size)
        if len(poly) < 3:
            raise TmmError(
                f"no cam centre keeps the pressure angle within {nu_max_deg:g}°; allow a larger nu_max or a longer phase"
            )
        o = nearest_point(poly)
        r0 = float(np.hypot(*o))
        if r0 <= 1e-12 * size:
            raise TmmError("the pressure-angle zone contains B0 itself; check the stroke and the phase angles")
        if max(abs(o[0]), abs(o[1])) > 0.9 * size:
            raise TmmError(
                f"the smallest cam for nu_max = {nu_max_deg:g}° is larger than 100 strokes; allow a larger nu_max"
            )
        nu_r, nu_b = _achieved(o, program, rocker, l_bc_m, sigma)
        worst = nu_r if closure == "force" else max(nu_r, nu_b)
        excess = worst - nu_max_deg
        if excess <= TOL_DEG:
            break
        nu_used -= math.radians(excess + 0.002)
    return _Solve(sigma, o, r0, math.degrees(nu_used), poly, nu_r, nu_b)


@record
class BookLine:
    """A bounding line of the book's construction: a point on it and its unit direction (zone frame)."""

    name: str  # "A"; "B" (form closure, or a force-closed rocker) or "C" (a force-closed translating follower)
    point: tuple[float, float]
    direction: tuple[float, float]


@record(eq=False)
class Zone:
    """Geometry of the centre-zone construction (Fig. 1.3, 1.4), zone frame [m]."""

    phi: np.ndarray  # cam angles of the positions [rad]
    phase: np.ndarray  # 0 rise, 2 return
    constrained: np.ndarray  # bool: wedge used
    b: np.ndarray  # roller centres B_i (N, 2)
    d: np.ndarray  # points D_i (N, 2)
    u: np.ndarray  # rise directions at B_i (N, 2)
    polygon: np.ndarray  # feasible region (clipped to a large square)
    lines: tuple[BookLine, ...]


@record(eq=False)
class Sizing:
    """Main dimensions (1.22)–(1.25): the true smallest r0 and, beside it, the book's vertex.

    Coordinates are in the zone frame (B0 at the origin, rise direction at B0 along +y, true
    rotation sense). e_m is the signed x of the follower axis measured from the cam centre
    (e > 0: axis to the right of O, looking with the follower above the cam).
    """

    closure: str
    rocker: bool
    ccw: bool
    nu_max_deg: float
    r0_m: float
    e_m: float | None
    l_oc_m: float | None
    centre: tuple[float, float]
    pivot: tuple[float, float] | None
    sigma: int  # +1: rocker turns with the cam on the rise; −1: against (1 for translating)
    swing: str | None  # "same" | "opposite" (rockers)
    r0_other_swing_m: float | None
    nu_rise_max_deg: float  # achieved at the chosen centre
    nu_return_max_deg: float
    nu_design_deg: float  # ν used for the wedges (ν_max less any safety margin)
    book_centre: tuple[float, float]
    book_r0_m: float
    book_e_m: float | None
    book_l_oc_m: float | None
    book_nu_rise_max_deg: float
    book_nu_return_max_deg: float
    zone: Zone
    origin: str = "minimum"  # "minimum" (smallest r0), "pivot" (moved to clear the pivot), "student"
    r0_min_m: float | None = None  # the smallest r0 of this swing direction (when origin != "minimum")

    @property
    def centre_canonical(self) -> tuple[float, float]:
        x, y = self.centre
        return (x, y) if self.ccw else (-x, y)

    @property
    def polygon_canonical(self) -> np.ndarray:
        """The feasible zone (clipped to the solver's square) in the canonical frame [m]."""
        return self.zone.polygon * (np.array([1.0, 1.0]) if self.ccw else np.array([-1.0, 1.0]))


def _book_line(st: FollowerState, idx: np.ndarray, nu: float, name: str, through_b0: bool = False) -> tuple[np.ndarray, float, BookLine]:
    """The book's bounding line for a phase: its direction taken at the largest BD, drawn tangent
    to that phase's D-curve (1.3.2 items 3–4); line C through B0 with the direction at B0."""
    d = d_points(st)
    bd = np.hypot(*st.b1[idx].T)
    k = int(idx[int(np.argmax(bd))])
    p = rot90(st.u[k])
    side = float(np.dot(d[k] - st.b[k], p))
    sgn = -math.copysign(1.0, side) if side != 0 else -1.0
    if through_b0:
        k0 = int(idx[0])
        p0 = rot90(st.u[k0])
        a = -sgn * math.cos(nu) * p0 + math.sin(nu) * st.u[k0]
        c = float(np.dot(a, st.b[k0]))
    else:
        a = sgn * math.cos(nu) * p + math.sin(nu) * st.u[k]
        c = float((d[idx] @ a).min())
    point = a * c  # |a| = 1
    direction = rot90(a)
    return a, c, BookLine(name, (float(point[0]), float(point[1])), (float(direction[0]), float(direction[1])))


def size_cam(
    program: CamProgram,
    *,
    rocker: bool,
    l_bc_m: float | None,
    nu_max_deg: float,
    closure: str,
    ccw: bool,
    sigma: int | None = None,
) -> Sizing:
    """Smallest base radius r0 (and e or l_OC) with ν ≤ ν_max, (1.19)–(1.25), §1.3.

    Rockers: both swing directions are solved and the smaller r0 kept unless `sigma` is given.

    >>> p = CamProgram(law=2, stroke=0.05, phi_rise=math.radians(100), phi_far=0.3, phi_return=1.7)
    >>> z = size_cam(p, rocker=False, l_bc_m=None, nu_max_deg=30, closure="force", ccw=True)
    >>> z.nu_rise_max_deg <= 30.01, z.e_m > 0
    (True, True)
    """
    if closure not in ("force", "form"):
        raise TmmError(f"closure '{closure}' is unknown; use 'force' or 'form'")
    if not 0.0 < nu_max_deg < 90.0:
        raise TmmError(f"nu_max {nu_max_deg:g}° is out of range; give an angle between 0 and 90 degrees")
    sigmas = [1] if not rocker else ([sigma] if sigma else [1, -1])
    sols = [_solve(program, rocker, l_bc_m, nu_max_deg, closure, sg) for sg in sigmas]
    best = min(sols, key=lambda z: z.r0)
    other = [z for z in sols if z is not best]
    sg = best.sigma

    # the construction's positions (rise and return, for the drawing) and the book's vertex
    n_r = max(2, int(math.ceil(math.degrees(program.phi_rise) / 0.5)) + 1)
    n_b = max(2, int(math.ceil(math.degrees(program.phi_return) / 0.5)) + 1)
    phis = np.concatenate([np.linspace(0.0, program.phi_rise, n_r), np.linspace(program.return_start, program.phi_working, n_b)])
    phase = np.concatenate([np.zeros(n_r, dtype=int), np.full(n_b, 2, dtype=int)])
    st = follower_state(program, phis, rocker=rocker, l_bc_m=l_bc_m, sigma=sg)
    nu = math.radians(nu_max_deg)
    rise_idx = np.nonzero(phase == 0)[0]
    ret_idx = np.nonzero(phase == 2)[0]
    a1, c1, line_a = _book_line(st, rise_idx, nu, "A")
    if closure == "form":
        a2, c2, line_2 = _book_line(st, ret_idx, nu, "B")
    else:
        # the book's line C through B0 (§1.3); a rocker's pivot is C in the same view, so there the line
        # takes the book's other name of the second line, B (its form-closure construction)
        a2, c2, line_2 = _book_line(st, rise_idx, nu, "B" if rocker else "C", through_b0=True)
    try:
        vtx = np.linalg.solve(np.array([a1, a2]), np.array([c1, c2]))
    except np.linalg.LinAlgError:  # parallel lines: no vertex, fall back to the true centre
        vtx = best.centre.copy()
    bk_r, bk_b = _achieved(vtx, program, rocker, l_bc_m, sg)

    mirror = np.array([1.0, 1.0]) if ccw else np.array([-1.0, 1.0])

    def m(pt) -> tuple[float, float]:
        q = np.asarray(pt, dtype=float) * mirror
        return (float(q[0]), float(q[1]))

    centre = m(best.centre)
    book = m(vtx)
    pivot = m((-sg * l_bc_m, 0.0)) if rocker else None
    lines = tuple(BookLine(L.name, m(L.point), m(L.direction)) for L in (line_a, line_2))
    constrained = phase == 0 if closure == "force" else np.ones_like(phase, dtype=bool)
    zone = Zone(
        phi=phis,
        phase=phase,
        constrained=constrained,
        b=st.b * mirror,
        d=d_points(st) * mirror,
        u=st.u * mirror,
        polygon=best.polygon * mirror,
        lines=lines,
    )

    def dist(a, b) -> float:
        return float(math.hypot(a[0] - b[0], a[1] - b[1]))

    return Sizing(
        closure=closure,
        rocker=rocker,
        ccw=ccw,
        nu_max_deg=nu_max_deg,
        r0_m=best.r0,
        e_m=None if rocker else -centre[0],
        l_oc_m=dist(centre, pivot) if rocker else None,
        centre=centre,
        pivot=pivot,
        sigma=sg,
        swing=("same" if sg > 0 else "opposite") if rocker else None,
        r0_other_swing_m=other[0].r0 if other else None,
        nu_rise_max_deg=best.nu_rise,
        nu_return_max_deg=best.nu_return,
        nu_design_deg=best.nu_used,
        book_centre=book,
        book_r0_m=float(math.hypot(*book)),
        book_e_m=None if rocker else -book[0],
        book_l_oc_m=dist(book, pivot) if rocker else None,
        book_nu_rise_max_deg=bk_r,
        book_nu_return_max_deg=bk_b,
        zone=zone,
    )


# ----------------------------------------------------------------------------------------------
# another centre: the student's, or one that clears the rocker pivot


def achieved_deg(centre_canonical, program: CamProgram, *, rocker: bool, l_bc_m: float | None, sigma: int) -> tuple[float, float]:
    """Largest pressure angle [deg] on the rise and on the return for a cam centre given in the
    canonical frame (0.05° grid, the cone measure of the theorem on the cam centre, (1.19)).

    >>> p = CamProgram(law=2, stroke=0.05, phi_rise=1.0, phi_far=0.3, phi_return=1.0)
    >>> nu_r, nu_b = achieved_deg((0.0, -0.1), p, rocker=False, l_bc_m=None, sigma=1)
    >>> round(nu_r, 2) == round(nu_b, 2)  # a central follower: the same law both ways
    True
    """
    return _achieved(np.asarray(centre_canonical, dtype=float), program, rocker, l_bc_m, sigma)


def far_point_canonical(program: CamProgram, *, rocker: bool, l_bc_m: float | None, sigma: int) -> np.ndarray:
    """The roller centre at the far dwell (largest pitch-curve radius) in the canonical frame [m]."""
    return follower_state(program, [program.phi_rise], rocker=rocker, l_bc_m=l_bc_m, sigma=sigma).b[0]


def place_centre(z: Sizing, program: CamProgram, centre_canonical, *, l_bc_m: float | None, origin: str) -> Sizing:
    """The same construction with the cam centre moved to `centre_canonical` [m]: r0, e or l_OC
    and the achieved pressure angles recomputed; the zone and the book's vertex are kept."""
    from dataclasses import replace

    o = np.asarray(centre_canonical, dtype=float)
    nu_r, nu_b = _achieved(o, program, z.rocker, l_bc_m, z.sigma)
    cz = (float(o[0]) if z.ccw else -float(o[0]), float(o[1]))
    return replace(
        z,
        centre=cz,
        r0_m=float(math.hypot(*o)),
        e_m=None if z.rocker else -cz[0],
        l_oc_m=math.dist(cz, z.pivot) if z.rocker else None,
        nu_rise_max_deg=nu_r,
        nu_return_max_deg=nu_b,
        origin=origin,
        r0_min_m=z.r0_m if z.origin == "minimum" else z.r0_min_m,
    )


def _inside(poly: np.ndarray, pts: np.ndarray) -> np.ndarray:
    """Points inside (or on) a convex polygon, either orientation."""
    e = np.roll(poly, -1, axis=0) - poly
    cr = e[:, 0][None] * (pts[:, 1][:, None] - poly[:, 1][None]) - e[:, 1][None] * (pts[:, 0][:, None] - poly[:, 0][None])
    tol = 1e-12 * float(np.abs(poly).max())
    return (cr >= -tol).all(axis=1) | (cr <= tol).all(axis=1)


def _ray_interval(poly: np.ndarray, d: np.ndarray) -> tuple[float, float] | None:
    """The stretch [t0, t1] of the ray t·d (t ≥ 0) inside a convex polygon, exactly."""
    nxt = np.roll(poly, -1, axis=0)
    lo, hi = 0.0, math.inf
    area = float(np.sum(poly[:, 0] * nxt[:, 1] - nxt[:, 0] * poly[:, 1]))
    sgn = 1.0 if area > 0 else -1.0
    for a, b in zip(poly, nxt):
        edge = b - a
        # inside: sgn·(edge × (t·d − a)) ≥ 0  →  t·(edge × d) ≥ edge × a
        k = sgn * (edge[0] * d[1] - edge[1] * d[0])
        c = sgn * (edge[0] * a[1] - edge[1] * a[0])
        if abs(k) < 1e-300:
            if c > 0:
                return None
            continue
        if k > 0:
            lo = max(lo, c / k)
        else:
            hi = min(hi, c / k)
    return (lo, hi) if hi >= lo else None


def centre_on_offset_line(z: Sizing, e_m: float) -> np.ndarray | None:
    """Translating follower: the centre with offset e [m] nearest to B0 inside the zone (canonical
    frame), or None when the line x = −e (zone frame) misses the zone."""
    x = -e_m if z.ccw else e_m
    poly = z.polygon_canonical
    nxt = np.roll(poly, -1, axis=0)
    ys = []
    for a, b in zip(poly, nxt):
        if (a[0] - x) * (b[0] - x) <= 0 and a[0] != b[0]:
            t = (x - a[0]) / (b[0] - a[0])
            ys.append(a[1] + t * (b[1] - a[1]))
        elif a[0] == x:
            ys.append(a[1])
    if not ys:
        return None
    y0, y1 = min(ys), max(ys)
    y = min(max(0.0, y0), y1)  # the point of [y0, y1] nearest to B0's y = 0
    return np.array([x, y])


def centre_on_pivot_circle(z: Sizing, l_oc_m: float, samples: int = 7200) -> np.ndarray | None:
    """Rocker: the centre at distance l_OC [m] from the pivot nearest to B0 inside the zone
    (canonical frame), or None when that circle misses the zone (sampled every 0.05°)."""
    c = np.array(z.pivot, dtype=float) * (np.array([1.0, 1.0]) if z.ccw else np.array([-1.0, 1.0]))
    t = np.linspace(0.0, 2.0 * math.pi, samples, endpoint=False)
    pts = c + l_oc_m * np.stack([np.cos(t), np.sin(t)], axis=-1)
    ok = _inside(z.polygon_canonical, pts)
    if not ok.any():
        return None
    r = np.hypot(pts[:, 0], pts[:, 1])
    return pts[int(np.argmin(np.where(ok, r, np.inf)))]


def centre_from_r0_l_oc(z: Sizing, r0_m: float, l_oc_m: float) -> np.ndarray:
    """Rocker: the centre with |O B0| = r0 and |O C| = l_OC (canonical frame), on the same side
    of the line B0C as the program's centre. Raises TmmError when the two circles do not meet."""
    l = float(math.dist((0.0, 0.0), z.pivot))  # = l_BC
    if not abs(l - r0_m) < l_oc_m < l + r0_m:
        raise TmmError(
            f"no cam centre has r0 = {r0_m * 1000:g} mm and l_OC = {l_oc_m * 1000:g} mm with l_BC = {l * 1000:g} mm: "
            f"l_OC must lie between |l_BC − r0| = {abs(l - r0_m) * 1000:g} mm and l_BC + r0 = {(l + r0_m) * 1000:g} mm"
        )
    cx = -z.sigma * l  # C = (cx, 0) in the canonical frame
    x = (r0_m**2 - l_oc_m**2 + cx**2) / (2.0 * cx)
    y = math.sqrt(max(r0_m**2 - x**2, 0.0))
    side = -1.0 if z.centre_canonical[1] <= 0 else 1.0
    return np.array([x, side * y])


def nearest_centre_where(z: Sizing, ok, *, n_dir: int = 1441, n_t: int = 400) -> np.ndarray | None:
    """The zone's centre nearest to B0 among those where `ok(points) -> bool array` holds
    (canonical frame), or None. A polar scan: rays from B0 every (span/1440) of the zone's angular
    span, each cut exactly by the zone and sampled at n_t points, then the first good sample
    bisected. Used only to move a centre off the rocker's pivot (no minimality is claimed)."""
    poly = z.polygon_canonical
    ang = np.arctan2(poly[:, 1], poly[:, 0])
    base = math.atan2(*np.asarray(z.centre_canonical)[::-1])
    rel = np.angle(np.exp(1j * (ang - base)))
    best = None
    for th in base + np.linspace(rel.min(), rel.max(), n_dir):
        d = np.array([math.cos(th), math.sin(th)])
        iv = _ray_interval(poly, d)
        if iv is None:
            continue
        t0, t1 = iv
        if best is not None:
            t1 = min(t1, best[0])
        if t1 <= t0:
            continue
        ts = np.linspace(t0, t1, n_t)
        good = ok(ts[:, None] * d)
        if not good.any():
            continue
        j = int(np.argmax(good))
        hi = ts[j]
        if j > 0:
            lo = ts[j - 1]
            for _ in range(30):
                mid = 0.5 * (lo + hi)
                lo, hi = (lo, mid) if ok((mid * d)[None])[0] else (mid, hi)
        if best is None or hi < best[0]:
            best = (hi, hi * d)
    return None if best is None else best[1]
