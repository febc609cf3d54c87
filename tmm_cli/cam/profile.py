"""Cam profile by inversion, §1.4, (1.26)–(1.28).

The cam is held still and the frame turns with −ω_k about O: the roller centre traces the pitch
(theoretical) curve P(φ) = R(−φ)·(B(φ) − O), written in the cam's own frame at the start of the
rise (cam centre at the origin, follower rising along +y at B0). A clockwise cam is the mirror
image x → −x, as in :mod:`tmm_cli.cam.sizing`.

With Q1 = B' − J(B − O) and Q2 = B'' − 2J·B' − (B − O) (J: rotation by +90°, primes: d/dφ) the
pitch curve has P' = R(−φ)Q1, P'' = R(−φ)Q2, so its curvature is exact in the motion law:
κ = (Q1 × Q2)/|Q1|³. The pitch curve runs round O against the cam's rotation, so convex parts
have ρ = −1/κ > 0 in the canonical frame; the profile is reported with ρ > 0 convex, ρ < 0
concave. The pressure angle over the whole turn is the angle between the normal to the pitch
curve and the follower's velocity: cos ν = |Q1 × u|/|Q1|.

The working profile is the envelope of the roller circles: the inner one for force closure,
both (the groove) for form closure. A roller of radius r works on a convex stretch only while
r < ρ_min there (else the envelope self-intersects: undercut); for a groove the outer envelope
also needs r < |ρ| on the concave stretches.

Roller rule (METHOD.md sheet 3 item 3; one rule, stated in the output). The book takes
r_р = 0.2·r0 (1.28) and says it is acceptable "in most cases" (§1.4); for a few variants (3, 7, 11,
19) it is not smaller than the pitch curve's ρ_min and the profile undercuts. The program keeps the
pressure-angle r0 (the main result of §1.3) and limits the roller instead:
r_р = min(0.2·r0, 0.8·ρ_lim), ρ_lim = the smallest convex radius of curvature of the pitch curve
(groove: the smallest concave one too). 0.8·ρ_min is the usual upper bound of the roller in Russian
course texts (e.g. Artobolevsky, *Theory of Mechanisms and Machines*, the roller condition
r_р ≤ 0.8·ρ_min; the same share below which the program stops calling a roller "tight"): the
working profile keeps a radius of curvature ρ − r_р ≥ 0.2·ρ_min instead of a near-cusp, which a
larger cam at the same 0.2·r0 roller would have right at its limit. The book's 0.2·r0 is reported
beside it, and where it would undercut, :mod:`tmm_cli.cam.book_roller` gives the other way out —
the smallest cam of the zone that keeps it, with a certificate that no smaller one does.
"""

from __future__ import annotations

import math

import numpy as np

from ..records import record
from .motion import DENSE_STEP_DEG, CamProgram
from .sizing import Sizing, follower_state, rot90

ROLLER_RULE = 0.2  # r_p = 0.2·r0, (1.28)
ROLLER_LIMIT = 0.8  # the carried roller is at most this share of ρ_lim (no undercut, no near-cusp)
FINE_STEP_DEG = 0.05  # grid for the curvature minimum


def _rotate(v: np.ndarray, angle: np.ndarray) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * v[:, 0] - s * v[:, 1], s * v[:, 0] + c * v[:, 1]], axis=-1)


@record(eq=False)
class _Pitch:
    p: np.ndarray
    q1: np.ndarray
    q2: np.ndarray
    u: np.ndarray
    b_rel: np.ndarray
    pivot_cam: np.ndarray | None


def _pitch(program, centre, phi, rocker, l_bc_m, sigma) -> _Pitch:
    st = follower_state(program, phi, rocker=rocker, l_bc_m=l_bc_m, sigma=sigma)
    o = np.asarray(centre, dtype=float)
    b_rel = st.b - o
    q1 = st.b1 - rot90(b_rel)
    q2 = st.b2 - 2.0 * rot90(st.b1) - b_rel
    p = _rotate(b_rel, -st.phi)
    piv = None
    if st.pivot is not None:
        c_rel = np.broadcast_to(np.asarray(st.pivot) - o, b_rel.shape)
        piv = _rotate(np.array(c_rel), -st.phi)
    return _Pitch(p, q1, q2, st.u, b_rel, piv)


def signed_radius(q1: np.ndarray, q2: np.ndarray) -> np.ndarray:
    """Radius of curvature of the pitch curve [m]: > 0 convex, < 0 concave, ±inf straight.

    >>> q1 = np.array([[0.05, 0.0]]); q2 = np.array([[0.0, -0.05]])  # circle r = 0.05 m
    >>> float(signed_radius(q1, q2)[0])
    0.05
    """
    cross = q1[:, 0] * q2[:, 1] - q1[:, 1] * q2[:, 0]
    n3 = np.hypot(q1[:, 0], q1[:, 1]) ** 3
    with np.errstate(divide="ignore"):
        return np.where(cross != 0.0, n3 / -cross, np.inf)


def pressure_angle_deg(q1: np.ndarray, u: np.ndarray) -> np.ndarray:
    """ν between the pitch-curve normal and the follower's velocity direction u [deg], (1.19).

    >>> round(float(pressure_angle_deg(np.array([[1.0, 1.0]]), np.array([[0.0, 1.0]]))[0]), 9)
    45.0
    """
    cross = np.abs(q1[:, 0] * u[:, 1] - q1[:, 1] * u[:, 0])
    return np.degrees(np.arccos(np.clip(cross / np.hypot(q1[:, 0], q1[:, 1]), 0.0, 1.0)))


@record(eq=False)
class Profile:
    """Pitch curve and working profile(s) in the cam frame [m], angles [deg] where named."""

    closure: str
    phi: np.ndarray  # cam angle from the start of rise [rad], 0 … 2π (closed: last = first point)
    pitch: np.ndarray  # (N, 2) pitch curve T, r0 is its base radius
    inner: np.ndarray  # (N, 2) working profile D1 (inner envelope)
    outer: np.ndarray | None  # (N, 2) D2, outer envelope (groove), form closure only
    axis_dir: np.ndarray  # (N, 2) follower rise direction in the cam frame (inverted motion)
    pivot_path: np.ndarray | None  # (N, 2) rocker pivot C in the cam frame
    radius: np.ndarray  # |P| [m]
    rho: np.ndarray  # signed radius of curvature of the pitch curve [m]
    nu_deg: np.ndarray  # pressure angle over the turn [deg]
    roller_m: float  # carried roller radius: min(0.2·r0, 0.8·ρ_lim), or the student's
    rho_min_convex_m: float
    phi_rho_min_convex_deg: float
    rho_min_concave_m: float | None  # None: the pitch curve has no concave stretch
    phi_rho_min_concave_deg: float | None
    roller_max_m: float  # the roller must be smaller than this (cusp limit)
    undercut: bool
    # kept for readers of the old fields: always None now (the roller rule carries no larger cam)
    r0_for_rule_m: float | None
    fix_centre: tuple[float, float] | None
    fix_e_m: float | None
    fix_l_oc_m: float | None
    psi_rise_deg: float
    psi_far_deg: float
    psi_return_deg: float
    psi_near_deg: float
    r0_m: float
    r_far_m: float  # far-dwell radius of the pitch curve
    working_min_radius_m: float  # r0 − r_p: smallest radius of the working profile D1
    nu_rise_max_deg: float
    nu_return_max_deg: float
    roller_book_m: float = 0.0  # the book's 0.2·r0 (1.28), shown beside the carried roller
    roller_rule: str = "book"  # "book" (0.2·r0 works), "limited" (0.8·ρ_lim), "student" (--roller)

    @property
    def psi_working_deg(self) -> float:
        """ψ_р = ψ_у + ψ_дс + ψ_в, (1.2); equals φ_р by (1.4)."""
        return self.psi_rise_deg + self.psi_far_deg + self.psi_return_deg


def _rho_extremes(program, centre, rocker, l_bc_m, sigma, step_deg: float = FINE_STEP_DEG):
    n = int(round(360.0 / step_deg))
    phi = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    eps = 1e-9
    marks = [0.0, program.phi_rise, program.return_start, program.phi_working]
    marks += [program.phi_rise / 2, program.return_start + program.phi_return / 2]
    extra = np.array([m + d for m in marks for d in (-eps, eps)])
    phi = np.concatenate([phi, np.mod(extra, 2.0 * math.pi)])
    pc = _pitch(program, centre, phi, rocker, l_bc_m, sigma)
    rho = signed_radius(pc.q1, pc.q2)
    conv = rho > 0
    k = int(np.argmin(np.where(conv, rho, np.inf)))
    rc, pc_deg = float(rho[k]), math.degrees(float(phi[k]))
    concave = rho < 0
    if concave.any():
        j = int(np.argmin(np.where(concave, -rho, np.inf)))
        rv, pv_deg = float(-rho[j]), math.degrees(float(phi[j]))
    else:
        rv, pv_deg = None, None
    return rc, pc_deg, rv, pv_deg


def _polar(program, centre, phi, rocker, l_bc_m, sigma) -> np.ndarray:
    pc = _pitch(program, centre, np.asarray(phi, dtype=float), rocker, l_bc_m, sigma)
    return np.arctan2(pc.p[:, 1], pc.p[:, 0])


def _limit(closure: str, rc: float, rv: float | None) -> float:
    return min(rc, rv) if (closure == "form" and rv is not None) else rc


def carried_roller(r0_m: float, rho_limit_m: float) -> tuple[float, str]:
    """The roller radius the program carries [m] and its rule: the book's 0.2·r0 (1.28) unless it
    exceeds 0.8·ρ_lim (then the roller is limited to 0.8·ρ_lim; see the module docstring).

    >>> r, rule = carried_roller(0.050, 0.040)  # 0.2·50 = 10 mm < 0.8·40 = 32 mm
    >>> round(r * 1000, 2), rule
    (10.0, 'book')
    >>> r, rule = carried_roller(0.04316, 0.00735)  # variant 3: 8.63 mm would undercut ρ_min 7.35 mm
    >>> round(r * 1000, 2), rule
    (5.88, 'limited')
    """
    book = ROLLER_RULE * r0_m
    cap = ROLLER_LIMIT * rho_limit_m
    return (book, "book") if book <= cap else (cap, "limited")


def cam_profile(program: CamProgram, sizing: Sizing, *, rocker: bool, l_bc_m: float | None, roller_m: float | None = None) -> Profile:
    """Pitch curve, roller envelopes, ψ angles (1.1)–(1.4), curvature and undercut check, §1.4.

    `roller_m`: the student's roller [m]; None carries :func:`carried_roller`.

    >>> from tmm_cli.cam.sizing import size_cam
    >>> p = CamProgram(law=4, stroke=0.03, phi_rise=math.radians(90), phi_far=0.5, phi_return=math.radians(90))
    >>> z = size_cam(p, rocker=False, l_bc_m=None, nu_max_deg=30, closure="form", ccw=False)
    >>> pr = cam_profile(p, z, rocker=False, l_bc_m=None)
    >>> round(pr.psi_working_deg - math.degrees(p.phi_working), 9)  # (1.4)
    0.0
    >>> round(float(pr.radius.min() / z.r0_m), 9)
    1.0
    """
    sg = sizing.sigma
    o = sizing.centre_canonical
    n = int(round(360.0 / DENSE_STEP_DEG))
    phi = np.linspace(0.0, 2.0 * math.pi, n + 1)
    pc = _pitch(program, o, phi, rocker, l_bc_m, sg)
    p = pc.p.copy()
    p[-1] = p[0]
    t_cam = _rotate(pc.q1, -phi)
    t_hat = t_cam / np.hypot(t_cam[:, 0], t_cam[:, 1])[:, None]
    n_out = rot90(t_hat)  # the curve runs clockwise round O in the canonical frame
    n_out[-1] = n_out[0]
    rc, rc_phi, rv, rv_phi = _rho_extremes(program, o, rocker, l_bc_m, sg)
    limit = _limit(sizing.closure, rc, rv)
    if roller_m is None:
        r_p, rule = carried_roller(sizing.r0_m, limit)
    else:
        r_p, rule = float(roller_m), "student"
    inner = p - r_p * n_out
    outer = p + r_p * n_out if sizing.closure == "form" else None
    axis = _rotate(pc.u, -phi)
    axis[-1] = axis[0]
    rho = signed_radius(pc.q1, pc.q2)
    nu = pressure_angle_deg(pc.q1, pc.u)
    nu[-1] = nu[0]

    undercut = r_p >= limit
    mirror = np.array([1.0, 1.0]) if sizing.ccw else np.array([-1.0, 1.0])

    # profile angles: polar angle of the pitch curve swept (against the rotation) over each phase
    segs = [(0.0, program.phi_rise), (program.phi_rise, program.return_start), (program.return_start, program.phi_working)]
    grid = np.concatenate([np.linspace(a, b, 1201) for a, b in segs])
    th = np.unwrap(_polar(program, o, grid, rocker, l_bc_m, sg))
    ends = th[[0, 1200, 1201 + 1200, 2402 + 1200]]
    psi_deg = [math.degrees(float(x)) for x in -np.diff(ends)]
    psi_near = 360.0 - sum(psi_deg)

    # pressure angle maxima on a fine phase-local grid
    def nu_max_on(a0, length):
        ph = np.linspace(a0, a0 + length, max(3, int(math.degrees(length) / 0.05) + 1))
        q = _pitch(program, o, ph, rocker, l_bc_m, sg)
        return float(pressure_angle_deg(q.q1, q.u).max())

    radius = np.hypot(p[:, 0], p[:, 1])
    far_pt = _pitch(program, o, np.array([program.phi_rise]), rocker, l_bc_m, sg).p[0]
    piv = None
    if pc.pivot_cam is not None:
        piv = pc.pivot_cam * mirror
        piv[-1] = piv[0]
    return Profile(
        closure=sizing.closure,
        phi=phi,
        pitch=p * mirror,
        inner=inner * mirror,
        outer=None if outer is None else outer * mirror,
        axis_dir=axis * mirror,
        pivot_path=piv,
        radius=radius,
        rho=rho,
        nu_deg=nu,
        roller_m=r_p,
        rho_min_convex_m=rc,
        phi_rho_min_convex_deg=rc_phi,
        rho_min_concave_m=rv,
        phi_rho_min_concave_deg=rv_phi,
        roller_max_m=limit,
        undercut=bool(undercut),
        r0_for_rule_m=None,  # the larger-cam alternative is no longer carried (roller rule above)
        fix_centre=None,
        fix_e_m=None,
        fix_l_oc_m=None,
        psi_rise_deg=psi_deg[0],
        psi_far_deg=psi_deg[1],
        psi_return_deg=psi_deg[2],
        psi_near_deg=psi_near,
        r0_m=sizing.r0_m,
        r_far_m=float(np.hypot(*far_pt)),
        working_min_radius_m=sizing.r0_m - r_p,
        nu_rise_max_deg=nu_max_on(0.0, program.phi_rise),
        nu_return_max_deg=nu_max_on(program.return_start, program.phi_return),
        roller_book_m=ROLLER_RULE * sizing.r0_m,
        roller_rule=rule,
    )
