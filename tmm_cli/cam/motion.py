"""Follower diagrams and the book's drawing scales (§1.2, (1.5)–(1.18)).

Everything here is SI: angles in rad, lengths in m, time in s. The displacement program runs over
one full cam turn from the start of the rise: rise φ_у, far dwell φ_дс, return φ_в, near dwell φ_бс.
For a translating follower the "follower coordinate" s is the displacement S [m]; for a rocker it
is the swing angle γ [rad], and the roller-centre values follow from (1.6): S_B = γ·l_BC,
V_B = ω·l_BC, a_B = ε·l_BC.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import TmmError
from ..records import record
from ..variants import Variant
from .laws import law_values

DENSE_STEP_DEG = 0.25  # grid of the stored diagrams and of the pitch curve (4 points per degree)

# Default drawing layout for the scales (1.9)–(1.18); stated in the output.
LAYOUT_B_MM = 240.0  # length of the abscissa that shows the working angle φ_р
LAYOUT_Y_S_MAX_MM = 80.0  # ordinate of the largest displacement (S_max or γ_max)
LAYOUT_Y_MAX_MM = 60.0  # H_V, H_a are the largest round values keeping |Y_V|, |Y_a| within this
ROUND_BASES_MM = (10.0, 15.0, 20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 80.0, 100.0)

PHASES = ("rise", "far_dwell", "return", "near_dwell")
_EPS = 1e-12  # [rad] phase ends are sums of rounded radians


@record
class CamProgram:
    """Follower displacement over one cam turn [m or rad] against cam angle φ [rad].

    rise: s = h·f(φ/φ_у); far dwell: s = h; return: s = h·(1 − f((φ − φ_у − φ_дс)/φ_в));
    near dwell: s = 0 (METHOD.md, "Inputs").
    """

    law: int
    stroke: float  # h: S_max [m] or γ_max [rad]
    phi_rise: float  # [rad]
    phi_far: float  # [rad]
    phi_return: float  # [rad]

    @property
    def phi_working(self) -> float:
        """φ_р = φ_у + φ_дс + φ_в, (1.3) [rad]."""
        return self.phi_rise + self.phi_far + self.phi_return

    @property
    def phi_near(self) -> float:
        """φ_бс = 2π − φ_р [rad]."""
        return 2.0 * math.pi - self.phi_working

    @property
    def return_start(self) -> float:
        return self.phi_rise + self.phi_far

    def phase_index(self, phi) -> np.ndarray:
        """0 rise, 1 far dwell, 2 return, 3 near dwell, for φ taken modulo 2π."""
        p = np.mod(np.asarray(phi, dtype=float), 2.0 * math.pi)
        idx = np.full(p.shape, 3, dtype=int)
        idx[p <= self.phi_working + _EPS] = 2
        idx[p < self.return_start - _EPS] = 1
        idx[p <= self.phi_rise + _EPS] = 0
        return idx

    def at(self, phi) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """s, ds/dφ, d²s/dφ², d³s/dφ³ at cam angle φ [rad] (units of s per rad^k).

        >>> p = CamProgram(law=2, stroke=0.05, phi_rise=math.radians(100), phi_far=0.3, phi_return=1.0)
        >>> [round(float(x), 9) for x in p.at(math.radians(50))[:2]]  # h·f(½), h·1.5/φ_у
        [0.025, 0.042971835]
        """
        p = np.mod(np.asarray(phi, dtype=float), 2.0 * math.pi)
        h = self.stroke
        s = np.zeros_like(p)
        d1 = np.zeros_like(p)
        d2 = np.zeros_like(p)
        d3 = np.zeros_like(p)
        rise = p <= self.phi_rise + _EPS
        if rise.any():
            f, f1, f2, f3 = law_values(self.law, p[rise] / self.phi_rise)
            k = self.phi_rise
            s[rise], d1[rise], d2[rise], d3[rise] = h * f, h * f1 / k, h * f2 / k**2, h * f3 / k**3
        ret = (p >= self.return_start - _EPS) & (p <= self.phi_working + _EPS) & ~rise
        far = ~rise & ~ret & (p < self.return_start)
        s[far] = h
        if ret.any():
            f, f1, f2, f3 = law_values(self.law, (p[ret] - self.return_start) / self.phi_return)
            k = self.phi_return
            s[ret], d1[ret], d2[ret], d3[ret] = h * (1.0 - f), -h * f1 / k, -h * f2 / k**2, -h * f3 / k**3
        return s, d1, d2, d3


def program_of(variant: Variant) -> CamProgram:
    """The displacement program of a Table 1.2 row (stroke in m, or rad for rockers)."""
    h = math.radians(variant.stroke) if variant.is_rocker else variant.stroke
    return CamProgram(
        law=variant.law,
        stroke=h,
        phi_rise=math.radians(variant.phi_rise_deg),
        phi_far=math.radians(variant.phi_far_dwell_deg),
        phi_return=math.radians(variant.phi_return_deg),
    )


def omega_cam(n_rpm: float) -> float:
    """Cam angular speed ω_k = π·n_k/30, (1.5) [rad/s] (magnitude).

    >>> round(omega_cam(800), 6)
    83.775804
    """
    return math.pi * abs(n_rpm) / 30.0


@record
class MotionRow:
    """One position of the book's table (positions 0, 1, … of Fig. 1.3/1.4)."""

    index: int
    phi_deg: float
    t_s: float
    phase: str
    s: float  # S [m] or γ [rad]
    v: float  # V [m/s] or ω [rad/s]
    a: float  # a [m/s²] or ε [rad/s²]
    s_b_m: float | None  # rocker: S_B = γ·l_BC (1.6)
    v_b_m_s: float | None
    a_b_m_s2: float | None


@record
class MotionMaxima:
    """Extremes on rise and return (follower units: m or rad; per s, s²)."""

    v_rise_max: float
    phi_v_rise_max_deg: float
    v_return_min: float
    phi_v_return_min_deg: float
    a_rise_max: float
    a_rise_min: float
    a_return_max: float
    a_return_min: float
    accel_ratio: float  # |a_return,max| / |a_rise,max|
    accel_ratio_book: float  # (φ_у/φ_в)², (1.7)


@record
class DrawingScales:
    """Scales (1.9)–(1.18) for the stated layout; lengths in mm on the sheet.

    For a rocker the generic k_s, k_v, k_a are k_γ [rad/mm], k_ω, k_ε (1.15)–(1.17), and the
    roller-centre scales (1.18) are k_s_b, k_v_b, k_a_b.
    """

    b_mm: float
    y_s_max_mm: float
    h_v_mm: float
    h_a_mm: float
    k_phi_deg_mm: float  # (1.9)
    k_t_s_mm: float  # (1.10)
    k_s: float  # (1.11) m/mm, or (1.15) rad/mm
    k_v: float  # (1.12) or (1.16)
    k_a: float  # (1.13) or (1.17)
    k_gamma_deg_mm: float | None  # (1.14)
    k_s_b: float | None  # (1.18) m/mm
    k_v_b: float | None
    k_a_b: float | None
    y_v_max_mm: float  # largest |ordinate| of the velocity diagram
    y_a_rise_max_mm: float  # Y_a.у.max
    y_a_return_max_mm: float  # Y_a.в.max = Y_a.у.max·(φ_у/φ_в)², (1.8)


@record(eq=False)
class Motion:
    """Follower diagrams over one cam turn on the dense grid, plus the book's table and scales."""

    program: CamProgram
    rocker: bool
    l_bc_m: float | None
    omega: float  # |ω_k| [rad/s]
    phi: np.ndarray  # cam angle from the start of rise [rad], 0 … 2π
    time: np.ndarray  # [s]
    s: np.ndarray  # S [m] or γ [rad]
    v: np.ndarray  # V [m/s] or ω [rad/s]
    a: np.ndarray  # a [m/s²] or ε [rad/s²]
    jerk: np.ndarray  # [m/s³] or [rad/s³]
    maxima: MotionMaxima
    table: tuple[MotionRow, ...]
    table_step_rise_deg: float
    table_step_return_deg: float
    scales: DrawingScales

    @property
    def period_s(self) -> float:
        return 2.0 * math.pi / self.omega


def table_step(phase_deg: float, step_deg: float) -> float:
    """The book's step (§1.2 item 2): `step_deg` (10°), halved on a short phase (fewer than 6 steps).

    >>> table_step(100, 10), table_step(40, 10)
    (10, 5.0)
    """
    return step_deg if phase_deg / step_deg >= 6.0 - 1e-9 else step_deg / 2.0


def _phase_points(start: float, length: float, step: float) -> list[float]:
    n = int(math.floor(length / step + 1e-9))
    pts = [start + k * step for k in range(n + 1)]
    if length - n * step > 1e-9:
        pts.append(start + length)
    return pts


def _pick_base(y_per_mm_base: float) -> float:
    """Largest round base H [mm] keeping the ordinate (linear in H) within LAYOUT_Y_MAX_MM."""
    best = ROUND_BASES_MM[0]
    for h in ROUND_BASES_MM:
        if y_per_mm_base * h <= LAYOUT_Y_MAX_MM + 1e-9:
            best = h
    return best


def drawing_scales(variant: Variant, v_abs_max: float, a_rise_abs_max: float, a_return_abs_max: float) -> DrawingScales:
    """Scales (1.9)–(1.18) for b = 240 mm, Y_Smax = 80 mm and round H_V, H_a (stated layout).

    `v_abs_max`, `a_*_abs_max` are the follower's extremes in SI (m/s or rad/s, …).
    """
    b = LAYOUT_B_MM
    k_phi = variant.phi_working_deg / b  # (1.9)
    k_t = variant.phi_working_deg / (6.0 * abs(variant.n_cam_rpm) * b)  # (1.10)
    if variant.is_rocker:
        k_g_deg = variant.stroke / LAYOUT_Y_S_MAX_MM  # (1.14)
        k_s = k_g_deg * math.pi / 180.0  # (1.15)
    else:
        k_g_deg = None
        k_s = variant.stroke / LAYOUT_Y_S_MAX_MM  # (1.11)
    # Y_V = V/k_V = V·k_t·H_V/k_s  -> ordinate per mm of base
    h_v = _pick_base(v_abs_max * k_t / k_s)
    k_v = k_s / (k_t * h_v)  # (1.12) / (1.16)
    a_abs = max(a_rise_abs_max, a_return_abs_max)
    h_a = _pick_base(a_abs * k_t / k_v)
    k_a = k_v / (k_t * h_a)  # (1.13) / (1.17)
    l = variant.l_bc_m
    y_a_rise = a_rise_abs_max / k_a
    return DrawingScales(
        b_mm=b,
        y_s_max_mm=LAYOUT_Y_S_MAX_MM,
        h_v_mm=h_v,
        h_a_mm=h_a,
        k_phi_deg_mm=k_phi,
        k_t_s_mm=k_t,
        k_s=k_s,
        k_v=k_v,
        k_a=k_a,
        k_gamma_deg_mm=k_g_deg,
        k_s_b=k_s * l if l else None,  # (1.18)
        k_v_b=k_v * l if l else None,
        k_a_b=k_a * l if l else None,
        y_v_max_mm=v_abs_max / k_v,
        y_a_rise_max_mm=y_a_rise,
        y_a_return_max_mm=y_a_rise * (variant.phi_rise_deg / variant.phi_return_deg) ** 2,  # (1.8)
    )


def follower_motion(variant: Variant, step_deg: float = 10.0) -> Motion:
    """Diagrams S(φ), V(φ), a(φ) (or γ, ω, ε) in SI over a whole turn, §1.2 and (1.5)–(1.6).

    V = ω_k·ds/dφ, a = ω_k²·d²s/dφ², jerk = ω_k³·d³s/dφ³ (the cam turns at constant speed).

    >>> from tmm_cli.variants import Variant
    >>> v = Variant(1, 1, None, 25.0, 800.0, 0.05, 1, 100.0, 20.0, 100.0)
    >>> m = follower_motion(v)
    >>> round(m.maxima.v_rise_max, 4)  # 2·h·ω/φ_у = 2·0.05·83.776/1.7453
    4.8
    >>> round(m.maxima.accel_ratio, 9) == round(m.maxima.accel_ratio_book, 9) == 1.0
    True
    """
    if not (step_deg > 0 and step_deg <= 30):
        raise TmmError(f"table step {step_deg:g}° is out of range; give a step above 0 and at most 30 degrees (the book uses 10)")
    prog = program_of(variant)
    w = omega_cam(variant.n_cam_rpm)
    n = int(round(360.0 / DENSE_STEP_DEG))
    phi = np.linspace(0.0, 2.0 * math.pi, n + 1)
    s, d1, d2, d3 = prog.at(phi)
    s[-1], d1[-1], d2[-1], d3[-1] = s[0], d1[0], d2[0], d3[0]
    v, a, j = w * d1, w**2 * d2, w**3 * d3

    # extremes from a finer, phase-local grid (exact law maxima sit inside the phases)
    # (each grid kept a hair inside its phase: with no far dwell the return starts where the rise
    # ends, and the shared point belongs to the rise — law 2's −a_max there is not the return's)
    eps = 1e-9
    tr = np.linspace(eps, prog.phi_rise - eps, 2001)
    tb = np.linspace(prog.return_start + eps, prog.phi_working - eps, 2001)
    _, r1, r2, _ = prog.at(tr)
    _, b1, b2, _ = prog.at(tb)
    # law 1's acceleration jumps at mid-phase; take both one-sided values
    ir, ib = int(np.argmax(r1)), int(np.argmin(b1))
    maxima = MotionMaxima(
        v_rise_max=float(w * r1[ir]),
        phi_v_rise_max_deg=math.degrees(float(tr[ir])),
        v_return_min=float(w * b1[ib]),
        phi_v_return_min_deg=math.degrees(float(tb[ib])),
        a_rise_max=float(w**2 * r2.max()),
        a_rise_min=float(w**2 * r2.min()),
        a_return_max=float(w**2 * b2.max()),
        a_return_min=float(w**2 * b2.min()),
        accel_ratio=float(np.abs(b2).max() / np.abs(r2).max()),
        accel_ratio_book=(variant.phi_rise_deg / variant.phi_return_deg) ** 2,
    )

    st_r = table_step(variant.phi_rise_deg, step_deg)
    st_b = table_step(variant.phi_return_deg, step_deg)
    pts = _phase_points(0.0, variant.phi_rise_deg, st_r)
    if variant.phi_far_dwell_deg > 0:
        pts.append(variant.phi_rise_deg + variant.phi_far_dwell_deg)
    ret = _phase_points(variant.phi_rise_deg + variant.phi_far_dwell_deg, variant.phi_return_deg, st_b)
    pts += ret[1:]
    pdeg = np.array(pts)
    ts, t1, t2, _ = prog.at(np.radians(pdeg))
    # a junction point is listed with the moving phase it bounds (one-sided values of a)
    names = np.array(PHASES)[prog.phase_index(np.radians(pdeg))]
    ts, t1, t2 = (np.where(np.abs(x) < 1e-12, 0.0, x) for x in (ts, t1, t2))
    l = variant.l_bc_m
    rows = []
    for i, (pd, si, vi, ai, ph) in enumerate(zip(pdeg, ts, w * t1, w**2 * t2, names)):
        rows.append(
            MotionRow(
                index=i,
                phi_deg=float(pd),
                t_s=math.radians(float(pd)) / w,
                phase=str(ph),
                s=float(si),
                v=float(vi),
                a=float(ai),
                s_b_m=float(si * l) if l else None,
                v_b_m_s=float(vi * l) if l else None,
                a_b_m_s2=float(ai * l) if l else None,
            )
        )
    scales = drawing_scales(
        variant,
        max(abs(maxima.v_rise_max), abs(maxima.v_return_min)),
        max(abs(maxima.a_rise_max), abs(maxima.a_rise_min)),
        max(abs(maxima.a_return_max), abs(maxima.a_return_min)),
    )
    return Motion(
        program=prog,
        rocker=variant.is_rocker,
        l_bc_m=l,
        omega=w,
        phi=phi,
        time=phi / w,
        s=s,
        v=v,
        a=a,
        jerk=j,
        maxima=maxima,
        table=tuple(rows),
        table_step_rise_deg=st_r,
        table_step_return_deg=st_b,
        scales=scales,
    )
