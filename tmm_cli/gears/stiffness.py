"""Mesh stiffness of a spur pair — beyond the course (seed 002).

Source: В. П. Тарасик, «Определение параметров жёсткости зубчатых передач трансмиссий мобильных
машин» (seed ``002_c35a69b11dd1c1f9``), equations (1)–(20). The tooth is a cantilever of
variable (trapezoidal) section loaded by the tangential force F = M1/r_d1; bending of both teeth,
measured at the pitch circles, gives the bending stiffness c_и; the contact deformation of
Nakhatakyan's formula (16) gives the contact stiffness c_H; the two turn angles add, so the mesh
stiffness is c = c_и·c_H/(c_и + c_H) (20). All stiffnesses c are reduced to the driving gear's
shaft [N·m/rad]; the paper's specific normal stiffness F/(y·b_w) [N/(mm·μm)] and the plain
linear stiffness F/y [N/m] are given too.

Roles (paper, §«Методика»): gear 1 is the paper's *pinion* (шестерня), the driving gear carrying
M1: its tooth is loaded at the pitch circle (beam from s_CB = s_d, x = 0, l = 1.25m); gear 2, the
*wheel* (колесо), is loaded at its tip (beam from s_CB = s_a, deflection read at x = m,
l = 2.25m). Zero gears (x1 = x2 = 0), α = 20°, h_a* = 1, c* = 0.25 — as in the paper's example.

The paper prints neither E nor ν (it only says ν = 0.25…0.35). Its worked example (z = 20/25,
m = 2 mm, b_w = 10 mm, M1 = 20 N·m) is reproduced to every printed digit with steel
E = 2.1·10¹¹ Pa, ν = 0.3 (E = 2.0·10¹¹ would give c_и = 2.353·10⁵, ν = 0.25 c_H = 1.393·10⁵), and
with the exact inv 20° = 0.014904 (the paper's rounded 0.0149 gives c_и = 2.470·10⁵).

SI units inside: lengths [m], forces [N], moments [N·m], moduli [Pa], angles [rad].
"""

from __future__ import annotations

import math

from ..records import record
from .involute import inv

E_STEEL_PA = 2.1e11
"""Young's modulus of steel E [Pa]; not printed in the paper, implied by its worked example."""

NU_STEEL = 0.3
"""Poisson's ratio of steel ν [-]; the paper gives the range 0.25…0.35, its example implies 0.3."""

ALPHA_DEG = 20.0
"""Pressure angle α_w [deg] (the paper: «согласно ГОСТ 16530—83 α_w = 20°»)."""

NAKHATAKYAN_K = 2.124
"""The constant under the logarithm of Nakhatakyan's contact formula (16) [-]."""


# ---------------------------------------------------------------- tooth geometry, (1)–(3), (17)

def profile_angle(r_base_m: float, r_x_m: float) -> float:
    """Profile angle α_x [rad] of the involute at radius r_x: α_x = arccos(r_b/r_x), eq. (2).

    >>> round(math.degrees(profile_angle(math.cos(math.radians(20.0)), 1.0)), 9)
    20.0
    """
    if r_x_m < r_base_m * (1 - 1e-12):
        raise ValueError("the involute exists only outside the base circle (r_x ≥ r_b)")
    return math.acos(min(1.0, r_base_m / r_x_m))


def tooth_thickness(z: int, m_m: float, r_x_m: float, x: float = 0.0, alpha_deg: float = ALPHA_DEG) -> float:
    """Arc tooth thickness s_x [m] on the circle of radius r_x [m], eq. (1) with (2), (3).

    s_x = 2r_x·(π/(2z) + 2x·tg α/z + inv α − inv α_x), inv α = tg α − α (3).

    The paper's (1) prints the shift term as 2x·tg α_w without the 1/z of its source
    (Mashkov [9]); it is immaterial for the paper's zero gears and the textbook form is used here.
    Paper, Table 1 (z = 20, m = 2 mm): s_a = 1.390, s_d = 3.142, s_b = 3.512 mm.

    >>> m = 2e-3; rd = m * 20 / 2; rb = rd * math.cos(math.radians(20.0))
    >>> [round(tooth_thickness(20, m, r) * 1e3, 3) for r in (rd + m, rd, rb)]
    [1.39, 3.142, 3.512]
    """
    alpha = math.radians(alpha_deg)
    r_b = m_m * z / 2.0 * math.cos(alpha)
    a_x = profile_angle(r_b, r_x_m)
    return 2.0 * r_x_m * (math.pi / (2.0 * z) + 2.0 * x * math.tan(alpha) / z + inv(alpha) - inv(a_x))


def involute_curvature_radius(r_base_m: float, r_x_m: float) -> float:
    """Radius of curvature of the involute ρ_x = r_b·tg α_x [m] at radius r_x, eq. (17).

    Paper, Table 1: ρ = 6.840 mm (z = 20) at the pitch circle, m = 2 mm.

    >>> rb = 0.02 * math.cos(math.radians(20.0))
    >>> round(involute_curvature_radius(rb, 0.02) * 1e3, 3)
    6.84
    """
    return r_base_m * math.tan(profile_angle(r_base_m, r_x_m))


def flank_angle(s_a_m: float, s_b_m: float, r_a_m: float, r_b_m: float) -> float:
    """Half-angle γ [rad] of the trapezoid ABCD through the tip and base thicknesses (Fig. 2):
    γ = arctg((s_b − s_a)/(2(r_a − r_b))) (unnumbered, before (6)).

    >>> round(math.degrees(flank_angle(1.0, 3.0, 2.0, 1.0)), 6)
    45.0
    """
    return math.atan((s_b_m - s_a_m) / (2.0 * (r_a_m - r_b_m)))


def section_inertia(b_w_m: float, s_cb_m: float, gamma_rad: float, x_m: float) -> float:
    """Second moment of area J(x) = b_w/12·(s_CB + 2x·tg γ)³ [m⁴] of the beam section at
    distance x [m] from its free end, eqs. (5)–(6).

    Paper, Table 1, row 7 (pinion z = 20, m = 2, b_w = 10 mm): J_d = 0.167·10⁻¹⁰ m⁴ — the section
    of the trapezoid ABCD (s_CB = s_a) at the pitch circle, x = r_a − r_d = m.

    >>> m = 2e-3; rd = 0.02; ra = rd + m; rb = rd * math.cos(math.radians(20.0))
    >>> sa, sb = tooth_thickness(20, m, ra), tooth_thickness(20, m, rb)
    >>> round(section_inertia(0.01, sa, flank_angle(sa, sb, ra, rb), m) * 1e10, 3)
    0.167
    """
    return b_w_m / 12.0 * (s_cb_m + 2.0 * x_m * math.tan(gamma_rad)) ** 3


# ---------------------------------------------------------------- the variable-section beam, (7)–(15)

def beam_load_factor(force_n: float, b_w_m: float, e_pa: float = E_STEEL_PA) -> float:
    """A = 12F/(b_w·E) [m] of eq. (7) (with a = 2 tg γ, b = s_CB: y'' = Ax/(ax + b)³).

    >>> beam_load_factor(1000.0, 0.01, 2.1e11)  # doctest: +ELLIPSIS
    5.714...e-06
    """
    return 12.0 * force_n / (b_w_m * e_pa)


def integration_constant_c(a: float, b_m: float, l_m: float) -> float:
    """C of eq. (10) [1/m]: the built-in end x = l does not turn, θ(l) = 0.

    C = 1/a²·[1/(al + b) − b/(2(al + b)²)].

    >>> integration_constant_c(1.0, 1.0, 1.0)
    0.375
    """
    u = a * l_m + b_m
    return (1.0 / u - b_m / (2.0 * u * u)) / (a * a)


def integration_constant_d(a: float, b_m: float, l_m: float) -> float:
    """D of eq. (11) [-]: the built-in end x = l does not deflect, y(l) = 0.

    D = 1/a²·[ln(al + b)/a + b/(2a(al + b))] − C·l. (The logarithm of a length, as printed: the
    ln-units cancel against the same term of (9); only differences of logarithms survive.)

    >>> round(integration_constant_d(1.0, 1.0, 1.0), 6)
    0.568147
    """
    u = a * l_m + b_m
    return (math.log(u) / a + b_m / (2.0 * a * u)) / (a * a) - integration_constant_c(a, b_m, l_m) * l_m


def beam_slope(a_load_m: float, a: float, b_m: float, l_m: float, x_m: float) -> float:
    """Slope θ = dy/dx [rad] of the beam at x, eq. (8) with C of (10).

    θ = A·[1/a²·(b/(2(ax + b)²) − 1/(ax + b)) + C]; θ(l) = 0.

    >>> beam_slope(1.0, 1.0, 1.0, 1.0, 1.0)
    0.0
    """
    u = a * x_m + b_m
    return a_load_m * ((b_m / (2.0 * u * u) - 1.0 / u) / (a * a) + integration_constant_c(a, b_m, l_m))


def beam_deflection(a_load_m: float, a: float, b_m: float, l_m: float, x_m: float) -> float:
    """Deflection y [m] of the variable-section cantilever at distance x from the free end, eq. (9)
    with C, D of (10), (11).

    y = A·{−1/a²·[ln(ax + b)/a + b/(2a(ax + b))] + C·x + D}.

    Paper, Table 1, row 8: y1 = 0.367·10⁻⁶ m (pinion z = 20, x = 0, b = s_d, l = 1.25m) for
    F = 1000 N, b_w = 10 mm.

    >>> m = 2e-3; rd = 0.02; ra = rd + m; rb = rd * math.cos(math.radians(20.0))
    >>> sa, sd, sb = (tooth_thickness(20, m, r) for r in (ra, rd, rb))
    >>> a = 2 * math.tan(flank_angle(sa, sb, ra, rb))
    >>> round(beam_deflection(beam_load_factor(1000.0, 0.01), a, sd, 1.25 * m, 0.0) * 1e6, 3)
    0.367
    """
    u = a * x_m + b_m
    c = integration_constant_c(a, b_m, l_m)
    d = integration_constant_d(a, b_m, l_m)
    return a_load_m * (-(math.log(u) / a + b_m / (2.0 * a * u)) / (a * a) + c * x_m + d)


def beam_tip_deflection(a_load_m: float, a: float, b_m: float, l_m: float) -> float:
    """Deflection of the free end y(0) [m], eq. (12):

    y = A·{1/a³·[ln(al/b + 1) − al/(2(al + b))] − C·l}  (eq. (9) at x = 0, written without
    logarithms of lengths).

    >>> round(beam_tip_deflection(1.0, 1.0, 1.0, 1.0) - beam_deflection(1.0, 1.0, 1.0, 1.0, 0.0), 12)
    0.0
    """
    al = a * l_m
    return a_load_m * ((math.log(al / b_m + 1.0) - al / (2.0 * (al + b_m))) / a ** 3
                       - integration_constant_c(a, b_m, l_m) * l_m)


def beam_tip_slope(a_load_m: float, a: float, b_m: float, l_m: float) -> float:
    """Slope of the free end θ(0) = −A·l²/(2b(al + b)²) [rad], eq. (15).

    >>> round(beam_tip_slope(1.0, 1.0, 1.0, 1.0) - beam_slope(1.0, 1.0, 1.0, 1.0, 0.0), 12)
    0.0
    """
    return -a_load_m * l_m * l_m / (2.0 * b_m * (a * l_m + b_m) ** 2)


# ---------------------------------------------------------------- contact, (16)

def contact_deformation(line_load_n_per_m: float, s_x1_m: float, s_x2_m: float, rho_x1_m: float, rho_x2_m: float,
                        e_pa: float = E_STEEL_PA, nu: float = NU_STEEL) -> float:
    """Contact deformation of the two teeth y_H [m] by Nakhatakyan's formula, eq. (16):

    y_H = 4(1 − ν²)q/(πE) · ln[2.124·√(E·s_x1·s_x2·(ρ_x1 + ρ_x2)/(q·ρ_x1·ρ_x2))],

    q = F/b_w [N/m] the line load, s_x the tooth thicknesses and ρ_x the involute radii of
    curvature at the contact radii (the paper takes the pitch circles). The argument of ln is
    dimensionless, unlike N. M. Belyaev's older formula which the paper quotes and rejects.
    Paper: y_H = 2.789·10⁻⁶ m for q = 1000 N/10 mm, s = 3.142 mm, ρ = 6.840/8.551 mm.

    >>> s = math.pi * 1e-3; rb1 = 0.02 * math.cos(math.radians(20.0)); rb2 = 0.025 * math.cos(math.radians(20.0))
    >>> y = contact_deformation(1e5, s, s, involute_curvature_radius(rb1, 0.02), involute_curvature_radius(rb2, 0.025))
    >>> round(y * 1e6, 3)
    2.789
    """
    if line_load_n_per_m <= 0:
        raise ValueError("the line load q must be positive")
    arg = e_pa * s_x1_m * s_x2_m * (rho_x1_m + rho_x2_m) / (line_load_n_per_m * rho_x1_m * rho_x2_m)
    return 4.0 * (1.0 - nu * nu) * line_load_n_per_m / (math.pi * e_pa) * math.log(NAKHATAKYAN_K * math.sqrt(arg))


# ---------------------------------------------------------------- stiffness, (13)–(14), (18)–(20)

def turn_angle(deflection_m: float, r_d1_m: float) -> float:
    """Turn of the pinion relative to the wheel φ = arctg(y/r_d1) [rad], eqs. (13) and (18).

    >>> round(turn_angle(1e-6, 0.02), 9)
    5e-05
    """
    return math.atan(deflection_m / r_d1_m)


def angular_stiffness(torque1_nm: float, phi_rad: float) -> float:
    """Stiffness reduced to the pinion shaft c = M1/φ [N·m/rad], eqs. (14) and (19).

    >>> angular_stiffness(20.0, 1e-4)
    200000.0
    """
    return torque1_nm / phi_rad


def series_stiffness(c_bend: float, c_contact: float) -> float:
    """Mesh stiffness c = c_и·c_H/(c_и + c_H), eq. (20): the turn angles φ_и and φ_H add.

    Paper: c_и = 2.471·10⁵, c_H = 1.434·10⁵ → c = 9.074·10⁴ N·m/rad.

    >>> round(series_stiffness(2.471e5, 1.434e5) / 1e4, 3)
    9.074
    """
    return c_bend * c_contact / (c_bend + c_contact)


def specific_stiffness(force_n: float, deflection_m: float, b_w_m: float) -> float:
    """Specific normal stiffness F/(y·b_w)·10⁻⁹ [N/(mm·μm)] (unnumbered, before Table 2;
    the unit of ISO 6336 / GOST 21354—87 c').

    >>> round(specific_stiffness(1000.0, 2.789e-6, 0.01), 2)
    35.86
    """
    return force_n / (deflection_m * b_w_m) * 1e-9


# ---------------------------------------------------------------- the whole method

@record
class MeshStiffness:
    """The paper's method for one spur pair. Pairs are (gear 1 = driving pinion, gear 2 = wheel).

    Inputs: ``z``, ``m_m`` [m], ``b_w_m`` [m], ``torque1_nm`` M1 [N·m] on gear 1, ``e_pa`` [Pa], ``nu``.
    Geometry [m]: radii ``r_d_m``, ``r_b_m``, ``r_a_m``; thicknesses ``s_a_m`` (tip), ``s_d_m``
    (pitch), ``s_b_m`` (base), (1)–(3); ``gamma_rad`` the trapezoid half-angle; ``j_d_m4`` [m⁴]
    the section of the trapezoid ABCD at the pitch circle, as in the paper's Table 1 row 7 (the
    pinion's beam itself starts at s_CB = s_d, so its pitch section is b_w·s_d³/12 — the paper's
    table shows the trapezoid's); ``rho_m`` ρ at the pitch circles (17).
    Load: ``force_n`` F = M1/r_d1 [N], ``line_load_n_per_m`` q = F/b_w [N/m].
    Deformations [m]: ``y_bend_m`` (y1, y2) at the pitch circles, (9)–(11); ``y_contact_m`` y_H (16).
    Turn angles [rad]: ``phi_bend_rad`` (13), ``phi_contact_rad`` (18).
    Stiffness reduced to gear 1's shaft [N·m/rad]: ``c_bend`` (14), ``c_contact`` (19), ``c`` (20).
    Linear stiffness along the pitch circle F/y [N/m]: ``k_bend``, ``k_contact``, ``k``; and per
    unit face width, the paper's specific normal stiffness [N/(mm·μm)]: ``c_spec_bend``,
    ``c_spec_contact``, ``c_spec`` (Table 2).
    """

    z: tuple[int, int]
    m_m: float
    b_w_m: float
    torque1_nm: float
    e_pa: float
    nu: float
    r_d_m: tuple[float, float]
    r_b_m: tuple[float, float]
    r_a_m: tuple[float, float]
    s_a_m: tuple[float, float]
    s_d_m: tuple[float, float]
    s_b_m: tuple[float, float]
    gamma_rad: tuple[float, float]
    j_d_m4: tuple[float, float]
    rho_m: tuple[float, float]
    force_n: float
    line_load_n_per_m: float
    y_bend_m: tuple[float, float]
    y_contact_m: float
    phi_bend_rad: float
    phi_contact_rad: float
    c_bend: float
    c_contact: float
    c: float
    k_bend: float
    k_contact: float
    k: float
    c_spec_bend: float
    c_spec_contact: float
    c_spec: float


def mesh_stiffness(z1: int, z2: int, m_m: float, b_w_m: float, torque1_nm: float, e_pa: float = E_STEEL_PA,
                   nu: float = NU_STEEL, alpha_deg: float = ALPHA_DEG) -> MeshStiffness:
    """Bending, contact and combined mesh stiffness of a zero spur pair (seed 002, eqs. (1)–(20)).

    Gear 1 is the driving pinion carrying M1 = ``torque1_nm`` [N·m]; m, b_w in metres. Bending:
    F = M1/r_d1 at the pinion's pitch circle (beam x = 0, b = s_d, l = 1.25m) and at the wheel's
    tip (deflection at x = m, b = s_a, l = 2.25m); contact at the pitch circles.

    The paper's worked example (Table 1; E = 2.1·10¹¹ Pa, ν = 0.3 implied):

    >>> s = mesh_stiffness(20, 25, 2e-3, 10e-3, 20.0)
    >>> [round(v * 1e3, 3) for v in s.s_a_m + s.s_d_m + s.s_b_m + s.rho_m]
    [1.39, 1.44, 3.142, 3.142, 3.512, 3.652, 6.84, 8.551]
    >>> [round(v * 1e10, 3) for v in s.j_d_m4], [round(v * 1e6, 3) for v in s.y_bend_m], round(s.y_contact_m * 1e6, 3)
    ([0.167, 0.164], [0.367, 1.252], 2.789)
    >>> f"{s.c_bend:.3e}  {s.c_contact:.3e}  {s.c:.3e}"
    '2.471e+05  1.434e+05  9.074e+04'
    >>> round(s.c_spec_bend, 3), round(s.c_spec_contact, 3), round(s.c_spec, 3)
    (61.769, 35.852, 22.685)
    """
    if z1 < 1 or z2 < 1 or int(z1) != z1 or int(z2) != z2:
        raise ValueError("tooth numbers must be positive whole numbers")
    if not (m_m > 0 and b_w_m > 0 and torque1_nm > 0 and e_pa > 0 and 0 <= nu < 0.5):
        raise ValueError("m, b_w, M1 and E must be positive and 0 ≤ ν < 0.5")
    alpha = math.radians(alpha_deg)
    zs = (int(z1), int(z2))
    r_d = tuple(m_m * z / 2.0 for z in zs)
    r_b = tuple(r * math.cos(alpha) for r in r_d)
    r_a = tuple(r + m_m for r in r_d)  # h_a* = 1
    s_a = tuple(tooth_thickness(z, m_m, ra, alpha_deg=alpha_deg) for z, ra in zip(zs, r_a))
    s_d = tuple(tooth_thickness(z, m_m, rd, alpha_deg=alpha_deg) for z, rd in zip(zs, r_d))
    s_b = tuple(tooth_thickness(z, m_m, rb, alpha_deg=alpha_deg) for z, rb in zip(zs, r_b))
    gamma = tuple(flank_angle(sa, sb, ra, rb) for sa, sb, ra, rb in zip(s_a, s_b, r_a, r_b))
    j_d = tuple(section_inertia(b_w_m, sa, g, ra - rd) for sa, g, ra, rd in zip(s_a, gamma, r_a, r_d))
    rho = tuple(involute_curvature_radius(rb, rd) for rb, rd in zip(r_b, r_d))

    force = torque1_nm / r_d[0]
    q = force / b_w_m
    a_load = beam_load_factor(force, b_w_m, e_pa)
    # pinion: loaded at the pitch circle, beam from s_d down to the root (l = 1.25m), read at x = 0
    y1 = beam_deflection(a_load, 2.0 * math.tan(gamma[0]), s_d[0], 1.25 * m_m, 0.0)
    # wheel: loaded at the tip, beam from s_a to the root (l = 2.25m), read at the pitch circle x = m
    y2 = beam_deflection(a_load, 2.0 * math.tan(gamma[1]), s_a[1], 2.25 * m_m, m_m)
    y_h = contact_deformation(q, s_d[0], s_d[1], rho[0], rho[1], e_pa, nu)

    phi_b = turn_angle(y1 + y2, r_d[0])
    phi_h = turn_angle(y_h, r_d[0])
    c_b = angular_stiffness(torque1_nm, phi_b)
    c_h = angular_stiffness(torque1_nm, phi_h)
    sb_spec = specific_stiffness(force, y1 + y2, b_w_m)
    sh_spec = specific_stiffness(force, y_h, b_w_m)
    k_b, k_h = force / (y1 + y2), force / y_h
    return MeshStiffness(
        z=zs, m_m=m_m, b_w_m=b_w_m, torque1_nm=torque1_nm, e_pa=e_pa, nu=nu,
        r_d_m=r_d, r_b_m=r_b, r_a_m=r_a, s_a_m=s_a, s_d_m=s_d, s_b_m=s_b, gamma_rad=gamma, j_d_m4=j_d, rho_m=rho,
        force_n=force, line_load_n_per_m=q, y_bend_m=(y1, y2), y_contact_m=y_h,
        phi_bend_rad=phi_b, phi_contact_rad=phi_h,
        c_bend=c_b, c_contact=c_h, c=series_stiffness(c_b, c_h),
        k_bend=k_b, k_contact=k_h, k=series_stiffness(k_b, k_h),
        c_spec_bend=sb_spec, c_spec_contact=sh_spec, c_spec=series_stiffness(sb_spec, sh_spec),
    )


# ---------------------------------------------------------------- the course's spur pair (informative)

PSI_M = 5.0
"""Face-width factor ψ_m = b_w/m [-] for the course's spur pair: the paper's example (10 mm / 2 mm);
the course does not size the face width."""

NOMINAL_LINE_LOAD_N_PER_M = 1.0e5
"""Nominal line load q = F/b_w [N/m] when no moment is given: the paper's example (1000 N / 10 mm)."""


@record
class SpurPairStiffness:
    """The paper's method applied to the course's spur pair — informative, beyond the course.

    ``mesh`` the result; ``psi_m`` the face-width factor used (b_w = ψ_m·m); ``load`` "motor"
    (the motor torque from (2.6) on gear 1) or "nominal" (the paper's line load);
    ``motor_torque_nm`` the motor torque [N·m] when known; ``notes`` the assumptions.
    """

    mesh: MeshStiffness
    psi_m: float
    load: str
    motor_torque_nm: float | None
    notes: tuple


def spur_pair_stiffness(z1: int, z2: int, m_mm: float, motor_torque_nm: float | None = None,
                        psi_m: float = PSI_M) -> SpurPairStiffness:
    """Mesh stiffness of the course's spur pair (gear 1 on the motor drives) by seed 002.

    b_w = ψ_m·m; the load is the motor torque on gear 1 when it is known and positive (an upper
    bound: the whole motor torque through the pair that drives only the cam), else the paper's
    nominal line load q = 100 N/mm. E, ν of steel as implied by the paper's example.

    >>> s = spur_pair_stiffness(17, 20, 20.0)
    >>> round(s.mesh.b_w_m, 6), s.load, round(s.mesh.force_n)
    (0.1, 'nominal', 10000)
    """
    from ..notes import Note

    m_m = m_mm * 1e-3
    b_w = psi_m * m_m
    r_d1 = m_m * z1 / 2.0
    notes = [Note.make("stiffness_scope", "assumption"),
             Note.make("stiffness_material", "assumption", e=f"{E_STEEL_PA / 1e11:g}", nu=f"{NU_STEEL:g}"),
             Note.make("stiffness_width", "assumption", psi=f"{psi_m:g}", m=f"{m_mm:g}", bw=f"{b_w * 1e3:g}")]
    if motor_torque_nm is not None and motor_torque_nm > 0:
        load, torque = "motor", float(motor_torque_nm)
        notes.append(Note.make("stiffness_load_motor", "assumption", t=f"{torque:.2f}",
                               f=f"{torque / r_d1:.0f}", q=f"{torque / r_d1 / b_w * 1e-3:.2f}"))
    else:
        load = "nominal"
        torque = NOMINAL_LINE_LOAD_N_PER_M * b_w * r_d1
        notes.append(Note.make("stiffness_load_nominal", "assumption", q=f"{NOMINAL_LINE_LOAD_N_PER_M * 1e-3:g}",
                               f=f"{NOMINAL_LINE_LOAD_N_PER_M * b_w:.0f}", t=f"{torque:.0f}"))
    if z1 > z2:
        notes.append(Note.make("stiffness_multiplier", "assumption", z1=z1, z2=z2))
    mesh = mesh_stiffness(z1, z2, m_m, b_w, torque)
    return SpurPairStiffness(mesh=mesh, psi_m=psi_m, load=load,
                             motor_torque_nm=float(motor_torque_nm) if load == "motor" else None, notes=tuple(notes))
