"""The whole kinematic analysis of the slotted-link mechanism (sheet 1) as one frozen result.

Stroke H, time ratio K, the dead (extreme) positions of the ram, N equally spaced crank positions
starting from the beginning of the working stroke (the book's numbering 0 … N−1), a dense curve
for the diagrams and the CSV, one extra position `at` with its velocity and acceleration plans.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import TmmError
from ..limits import LINKAGE_EPS, LINKAGE_OMEGA, check_range
from ..notes import Note
from ..records import record
from .geometry import WHITWORTH, Geometry, positions
from .kinematics import motion, transfer
from .plans import Plans, plans

TWO_PI = 2.0 * math.pi
CURVE_POINTS = 721  # dense curve: every 0.5° of crank angle, both ends included
ROD_ANGLE_WARN_DEG = 45.0  # the rod pushes the ram at a poor angle beyond this
NEAR_PIVOT = 0.1  # warn when the block comes closer than this share of r1 to the link's pivot


@record
class State:
    """The mechanism at one crank angle: positions, velocities, accelerations (SI)."""

    phi: float  # φ21 in [0, 2π) [rad]
    link: float  # φ41 in (−π, π] [rad], measured like φ21
    rho: float  # O41A [m]
    x_c: float  # ram [m]
    psi: float  # rod angle to the guide, counter-clockwise [rad]
    a: tuple[float, float]  # crank pin A [m]
    b: tuple[float, float]  # B [m]
    omega_link: float  # [rad/s]
    eps_link: float  # [rad/s²]
    v_rel: float  # [m/s]
    a_rel: float  # [m/s²]
    a_cor: float  # 2·ω4·v_rel [m/s²]
    omega_rod: float  # [rad/s]
    eps_rod: float  # [rad/s²]
    v_c: float  # [m/s]
    a_c: float  # [m/s²]


@record
class Curve:
    """Dense curve over one crank turn from the start of the working stroke (arrays)."""

    phi_from_start: np.ndarray  # [rad], 0 … 2π
    phi: np.ndarray  # φ21 in [0, 2π) [rad]
    link: np.ndarray  # φ41 in (−π, π] [rad]
    rho: np.ndarray
    x_c: np.ndarray
    a: np.ndarray  # (M, 2)
    b: np.ndarray  # (M, 2)
    omega_link: np.ndarray
    eps_link: np.ndarray
    v_rel: np.ndarray
    a_cor: np.ndarray
    v_c: np.ndarray
    a_c: np.ndarray


@record
class LinkageResult:
    geometry: Geometry
    omega: float  # crank ω21 [rad/s]
    eps: float  # crank ε21 [rad/s²]
    regime: str  # 'whitworth' or 'crank_shaper'
    stroke: float  # H [m]
    x_min: float
    x_max: float
    time_ratio: float  # K = φ_working / φ_return
    working_rad: float  # crank angle of the working (slow) stroke
    return_rad: float
    dead: tuple[float, float]  # φ21 of the start of the working stroke, of the return stroke [rad]
    working_direction: int  # +1: the ram moves right (+x) on the working stroke, −1: left
    stationary: int  # how many times per turn the ram stops (2 for a sound mechanism)
    positions: tuple[State, ...]
    at: State
    dead_state: State  # the mechanism at the other dead position (start of the return stroke)
    curve: Curve
    plans: Plans
    residual: float  # largest loop-closure error [m]
    rod_angle_max: float  # max |ψ| over the turn [rad]
    notes: tuple[Note, ...]

    @property
    def rpm(self) -> float:
        return self.omega * 30.0 / math.pi

    @property
    def period(self) -> float:
        return TWO_PI / self.omega


def _norm(phi):
    return np.mod(phi, TWO_PI)


def _fold(link):
    """φ41 folded into (−π, π]."""
    x = np.mod(np.asarray(link) + math.pi, TWO_PI) - math.pi
    return np.where(x == -math.pi, math.pi, x)


def _states(g: Geometry, phi, omega: float, eps: float):
    p = positions(g, phi)
    t = transfer(g, p)
    m = motion(t, omega, eps)
    return p, t, m


def _state_at(g: Geometry, phi: float, omega: float, eps: float) -> tuple[State, float]:
    p, _, m = _states(g, phi, omega, eps)
    st = State(
        phi=float(_norm(phi)), link=float(_fold(p.link)), rho=float(p.rho), x_c=float(p.x_c), psi=float(p.psi),
        a=(float(p.a[0]), float(p.a[1])), b=(float(p.b[0]), float(p.b[1])),
        omega_link=float(m.omega_link), eps_link=float(m.eps_link), v_rel=float(m.v_rel), a_rel=float(m.a_rel),
        a_cor=float(m.a_cor), omega_rod=float(m.omega_rod), eps_rod=float(m.eps_rod), v_c=float(m.v_c), a_c=float(m.a_c),
    )
    return st, p.residual


def stationary_angles(g: Geometry, samples: int = 1440) -> np.ndarray:
    """Crank angles φ21 [rad] where the ram stops (dx_C/dφ21 = 0), to machine precision.

    Sign changes of the transfer function on a fine grid, then bisection of all brackets at once.

    >>> from .geometry import make_geometry
    >>> g = make_geometry(0.10, 0.04, 0.0, 0.08, 0.30, -0.04)
    >>> [round(math.degrees(x), 9) for x in stationary_angles(g)]   # link horizontal: 90° ± asin(h/r1) …
    [113.578178478, 246.421821522]
    """
    grid = np.linspace(0.0, TWO_PI, samples + 1)
    x1 = transfer(g, positions(g, grid)).x1
    lo_i = np.nonzero((x1[:-1] == 0.0) | (np.sign(x1[:-1]) * np.sign(x1[1:]) < 0))[0]
    lo, hi = grid[lo_i], grid[lo_i + 1]
    f_lo = x1[lo_i]
    for _ in range(64):
        mid = 0.5 * (lo + hi)
        f_mid = transfer(g, positions(g, mid)).x1
        left = np.sign(f_mid) * np.sign(f_lo) <= 0  # the root lies in [lo, mid]
        hi = np.where(left, mid, hi)
        lo = np.where(left, lo, mid)
        f_lo = np.where(left, f_lo, f_mid)
    roots = np.sort(_norm(0.5 * (lo + hi)))
    keep = [r for i, r in enumerate(roots) if i == 0 or r - roots[i - 1] > 1e-9]
    if len(keep) > 1 and keep[0] + TWO_PI - keep[-1] <= 1e-9:
        keep.pop()
    roots = np.array(keep)
    return roots


def analyse(g: Geometry, omega: float, eps: float = 0.0, n_positions: int = 12, at_deg: float = 45.0) -> LinkageResult:
    """Kinematic analysis of the mechanism for a crank at ω21 [rad/s] (and ε21 [rad/s²]).

    The working stroke is the slower of the two strokes (the larger crank angle between the dead
    positions); position 0 is its start. K = φ_working/φ_return.

    >>> from .geometry import make_geometry
    >>> r = analyse(make_geometry(0.10, 0.04, 0.0, 0.08, 0.30, -0.04), omega=10.0)
    >>> round(r.stroke, 12), round(r.time_ratio, 6), [round(math.degrees(x), 6) for x in r.dead]
    (0.16, 1.709953, [246.421822, 113.578178])
    """
    if not (math.isfinite(omega) and omega > 0):
        raise TmmError(f"the crank speed is {omega:g} rad/s; give a positive --rpm or --omega (φ21 grows with time)")
    check_range(omega, *LINKAGE_OMEGA, "the crank speed ω21 [rad/s]", " (--rpm from 0.1 to 10000)")
    if not math.isfinite(eps):
        raise TmmError(f"--eps-crank is {eps}; give a finite angular acceleration in rad/s²")
    check_range(eps, *LINKAGE_EPS, "--eps-crank [rad/s²]")
    if not isinstance(n_positions, int) or not 2 <= n_positions <= 360:
        raise TmmError(f"--positions is {n_positions}; give a whole number of crank positions from 2 to 360 (the book uses 12)")
    if not (math.isfinite(at_deg) and 0.0 <= at_deg <= 360.0):
        raise TmmError(f"--at is {at_deg:g}; give a crank angle φ21 from 0 to 360 degrees")

    roots = stationary_angles(g)
    if len(roots) < 2:  # pragma: no cover - a smooth periodic x_C always has a max and a min
        raise TmmError("the ram does not move; check the dimensions")
    x_roots = positions(g, roots).x_c
    phi_max, phi_min = float(roots[int(np.argmax(x_roots))]), float(roots[int(np.argmin(x_roots))])
    x_max, x_min = float(np.max(x_roots)), float(np.min(x_roots))
    left_arc = float(_norm(phi_min - phi_max))  # crank angle while the ram moves from x_max to x_min
    right_arc = TWO_PI - left_arc
    if left_arc > right_arc:
        start, other, direction, working, ret = phi_max, phi_min, -1, left_arc, right_arc
    else:
        start, other, direction, working, ret = phi_min, phi_max, +1, right_arc, left_arc

    states, residual = [], 0.0
    for k in range(n_positions):
        st, res = _state_at(g, start + TWO_PI * k / n_positions, omega, eps)
        states.append(st)
        residual = max(residual, res)
    at_phi = math.radians(at_deg)
    at_state, res = _state_at(g, at_phi, omega, eps)
    residual = max(residual, res)
    dead_state, res = _state_at(g, other, omega, eps)
    residual = max(residual, res)

    from_start = np.linspace(0.0, TWO_PI, CURVE_POINTS)
    p, _, m = _states(g, start + from_start, omega, eps)
    residual = max(residual, p.residual)
    curve = Curve(
        phi_from_start=from_start, phi=_norm(p.phi), link=_fold(p.link), rho=p.rho, x_c=p.x_c, a=p.a, b=p.b,
        omega_link=m.omega_link, eps_link=m.eps_link, v_rel=m.v_rel, a_cor=m.a_cor, v_c=m.v_c, a_c=m.a_c,
    )
    # the largest rod angle: at B's extreme heights, which the curve may step over
    reach = g.rod_reach()
    rod_max = math.asin(min(1.0, reach / g.r3))

    notes: list[Note] = []
    if g.regime == WHITWORTH:
        notes.append(Note.make("linkage_whitworth", "assumption", rho_min_mm=g.rho_min * 1000, rho_max_mm=g.rho_max * 1000,
                               r2_mm=g.r2 * 1000))
    else:
        notes.append(Note.make("linkage_crank_shaper", "assumption", swing_deg=2 * math.degrees(g.swing_half_rad),
                               rho_min_mm=g.rho_min * 1000, rho_max_mm=g.rho_max * 1000))
    if eps != 0.0:
        notes.append(Note.make("linkage_eps", "assumption", eps=eps, omega=omega))
    if math.degrees(rod_max) > ROD_ANGLE_WARN_DEG:
        notes.append(Note.make("linkage_rod_angle", "warning", angle_deg=math.degrees(rod_max), limit_deg=ROD_ANGLE_WARN_DEG))
    if g.rho_min < NEAR_PIVOT * g.r1:
        notes.append(Note.make("linkage_near_pivot", "warning", rho_min_mm=g.rho_min * 1000,
                               ratio=float(np.max(np.abs(m.omega_link))) / omega))
    if len(roots) > 2:
        notes.append(Note.make("linkage_reversals", "warning", count=len(roots)))

    result = LinkageResult(
        geometry=g, omega=float(omega), eps=float(eps), regime=g.regime, stroke=x_max - x_min, x_min=x_min, x_max=x_max,
        time_ratio=working / ret, working_rad=working, return_rad=ret, dead=(float(_norm(start)), float(_norm(other))),
        working_direction=direction, stationary=len(roots), positions=tuple(states), at=at_state, dead_state=dead_state, curve=curve,
        plans=plans(g, at_phi, omega, eps), residual=residual, rod_angle_max=rod_max, notes=tuple(notes),
    )
    if not finite_everywhere(result):  # validated after, too: a number that overflowed is an error, not a null
        raise TmmError("the motion of this mechanism cannot be computed in finite numbers (a position where a link "
                       "stands across its guide, or dimensions too far apart); check the dimensions")
    return result


def finite_everywhere(x) -> bool:
    """Whether every number in a result (records, tuples, dicts, arrays) is finite.

    >>> finite_everywhere((1.0, {"a": np.array([2.0, 3.0])})), finite_everywhere([1.0, float("nan")])
    (True, False)
    """
    import dataclasses

    if isinstance(x, float):
        return math.isfinite(x)
    if isinstance(x, np.ndarray):
        return x.dtype.kind not in "fc" or bool(np.all(np.isfinite(x)))
    if isinstance(x, (tuple, list)):
        return all(finite_everywhere(v) for v in x)
    if isinstance(x, dict):
        return all(finite_everywhere(v) for v in x.values())
    if dataclasses.is_dataclass(x) and not isinstance(x, type):
        return all(finite_everywhere(getattr(x, f.name)) for f in dataclasses.fields(x))
    return True
