"""The spur pair from the motor to the cam: zero gears of §2.3 (sheet 4, lower field).

Fixed for every variant (§2.1.1, §2.3): m = 20 mm, α = 20°, h_a* = 1, c* = 0.25, x1 = x2 = 0.
Lengths are in millimetres (``_mm``) because the book's items are drawn at that scale; angles in
degrees carry ``_deg``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

M_MM = 20.0
ALPHA_DEG = 20.0
HA_STAR = 1.0
C_STAR = 0.25
Z_SMALL = 17
FILLET_RADIUS_FACTOR = 0.38  # r_f = 0.38·m (§2.1.1 step 2)


def z_min_undercut(alpha_deg: float = ALPHA_DEG, ha_star: float = HA_STAR) -> float:
    """Undercut limit of a rack-cut zero gear z_min = 2h_a*/sin² α (17.1 for α = 20°, h_a* = 1).

    >>> round(z_min_undercut(), 2)
    17.1
    """
    return 2.0 * ha_star / math.sin(math.radians(alpha_deg)) ** 2


def exact_number(x: float | int | Fraction) -> Fraction:
    """The decimal number the user meant: 600.0 → 600, 0.1 → 1/10 (not the binary float)."""
    if isinstance(x, (int, Fraction)):
        return Fraction(x)
    return Fraction(repr(float(x)))


def round_half_up(q: Fraction) -> int:
    """Nearest integer of a positive exact fraction, an exact .5 going up (§2.3 item 2).

    >>> round_half_up(Fraction(85, 2)), round_half_up(Fraction(408, 20))
    (43, 20)
    """
    return math.floor(q + Fraction(1, 2))


def spur_teeth(n_motor_rpm: float, n_cam_rpm: float) -> tuple[int, int]:
    """(z1 on the motor, z2 on the cam) per §2.3 items 1–2.

    i_d = n_d/|n_k|; a reducer (i_d ≥ 1) has the 17-tooth driving pinion, z2 = round(17·i_d);
    a multiplier (i_d < 1) has the 17-tooth driven gear, z1 = round(17/i_d).

    >>> spur_teeth(720, 600)          # §2.3: i_d = 1.2, z2 = 20.4 → 20
    (17, 20)
    >>> spur_teeth(720, -1800)        # variant 24: 17·1800/720 = 42.5 → 43
    (43, 17)
    """
    i = exact_number(n_motor_rpm) / abs(exact_number(n_cam_rpm))
    if i >= 1:
        return Z_SMALL, round_half_up(Z_SMALL * i)
    return round_half_up(Z_SMALL / i), Z_SMALL


@dataclass(frozen=True)
class SpurGeometry:
    """Items 3–11 of §2.3, the contact ratio and the zones on the line of action.

    Positions along the line of action are measured from N1 (tangent point on gear 1's base
    circle) towards N2, in mm: P1 (start of engagement, tip circle of gear 2), U1 = P1 + p_b,
    U2 = P2 − p_b, P2 (end, tip circle of gear 1); P1U2 and U1P2 are the double-pair zones and
    U2U1 the single-pair zone (Fig. 2.3).
    """

    z1: int
    z2: int
    m_mm: float
    alpha_deg: float
    ha_star: float
    c_star: float
    i_d: float  # required n_d/|n_k|
    i_actual: float  # z2/z1
    d1_mm: float
    d2_mm: float
    db1_mm: float
    db2_mm: float
    da1_mm: float
    da2_mm: float
    df1_mm: float
    df2_mm: float
    a_mm: float
    p_mm: float
    pb_mm: float
    s_mm: float
    e_mm: float
    tau1_deg: float
    tau2_deg: float
    h_mm: float
    hd_mm: float  # depth of engagement (глубина захода) 2h_a*·m
    c_mm: float
    fillet_mm: float
    # item 11, the check
    check_a_pitch_mm: float  # (d1 + d2)/2
    check_a_12_mm: float  # da1/2 + df2/2 + C
    check_a_21_mm: float  # da2/2 + df1/2 + C
    check_2h_1_mm: float  # da1 − df1
    check_2h_2_mm: float  # da2 − df2
    check_ok: bool
    # line of action
    alpha_w_deg: float
    n1n2_mm: float
    pole_mm: float  # N1P
    p1_mm: float
    p2_mm: float
    u1_mm: float
    u2_mm: float
    g_alpha_mm: float  # P1P2
    eps_alpha: float
    phi_alpha1_deg: float
    phi_alpha2_deg: float
    phi_alpha1_geom_deg: float  # g_α / r_b1: the turn of gear 1 while a tooth runs P1 → P2
    phi_alpha2_geom_deg: float
    single_zone_mm: float  # U2U1
    double_zone_mm: float  # P1U2 (= U1P2)
    z_min_undercut: float

    @property
    def multiplier(self) -> bool:
        return self.i_d < 1.0


def spur_geometry(z1: int, z2: int, i_d: float | None = None, m_mm: float = M_MM,
                  alpha_deg: float = ALPHA_DEG, ha_star: float = HA_STAR, c_star: float = C_STAR) -> SpurGeometry:
    """All items 3–11 of §2.3 for a zero pair, plus ε_α computed from the geometry.

    ε_α = (√(r_a1² − r_b1²) + √(r_a2² − r_b2²) − a·sin α_w)/p_b (the active line P1P2 over the base
    pitch, Fig. 2.3); φ_α = ε_α·τ (§2.3, note).

    The book's example z1 = 17, z2 = 20, m = 20 mm:

    >>> g = spur_geometry(17, 20)
    >>> g.d1_mm, g.d2_mm, g.da1_mm, g.df1_mm, g.a_mm
    (340.0, 400.0, 380.0, 290.0, 370.0)
    >>> round(g.db1_mm, 2), round(g.p_mm, 2), round(g.pb_mm, 2), round(g.s_mm, 2)
    (319.5, 62.83, 59.04, 31.42)
    >>> g.h_mm, g.hd_mm, g.c_mm, round(g.tau1_deg, 3), g.tau2_deg, g.check_ok
    (45.0, 40.0, 5.0, 21.176, 18.0, True)
    >>> round(g.eps_alpha, 3)
    1.536
    """
    alpha = math.radians(alpha_deg)
    m = m_mm
    d1, d2 = m * z1, m * z2
    db1, db2 = d1 * math.cos(alpha), d2 * math.cos(alpha)
    da1, da2 = d1 + 2 * ha_star * m, d2 + 2 * ha_star * m
    df1, df2 = d1 - 2 * (ha_star + c_star) * m, d2 - 2 * (ha_star + c_star) * m
    a = m * (z1 + z2) / 2
    p = math.pi * m
    pb = p * math.cos(alpha)
    s = e = math.pi * m / 2
    tau1, tau2 = 360.0 / z1, 360.0 / z2
    h = (2 * ha_star + c_star) * m
    hd = 2 * ha_star * m
    c = c_star * m
    chk_pitch = (d1 + d2) / 2
    chk_12 = da1 / 2 + df2 / 2 + c
    chk_21 = da2 / 2 + df1 / 2 + c
    chk_h1, chk_h2 = da1 - df1, da2 - df2
    tol = 1e-9 * max(a, 1.0)
    ok = (abs(chk_pitch - a) < tol and abs(chk_12 - a) < tol and abs(chk_21 - a) < tol
          and abs(chk_h1 - 2 * h) < tol and abs(chk_h2 - 2 * h) < tol)
    # line of action (zero gears: α_w = α, a_w = a)
    alpha_w = alpha
    rb1, rb2, ra1, ra2 = db1 / 2, db2 / 2, da1 / 2, da2 / 2
    n1n2 = a * math.sin(alpha_w)
    pole = rb1 * math.tan(alpha_w)
    p2 = math.sqrt(ra1 * ra1 - rb1 * rb1)  # from N1: tip circle of gear 1 ends the contact
    p1 = n1n2 - math.sqrt(ra2 * ra2 - rb2 * rb2)  # tip circle of gear 2 starts it
    g = p2 - p1
    eps = g / pb
    return SpurGeometry(
        z1=z1, z2=z2, m_mm=m, alpha_deg=alpha_deg, ha_star=ha_star, c_star=c_star,
        i_d=float(i_d) if i_d is not None else z2 / z1, i_actual=z2 / z1,
        d1_mm=d1, d2_mm=d2, db1_mm=db1, db2_mm=db2, da1_mm=da1, da2_mm=da2, df1_mm=df1, df2_mm=df2,
        a_mm=a, p_mm=p, pb_mm=pb, s_mm=s, e_mm=e, tau1_deg=tau1, tau2_deg=tau2, h_mm=h, hd_mm=hd, c_mm=c,
        fillet_mm=FILLET_RADIUS_FACTOR * m,
        check_a_pitch_mm=chk_pitch, check_a_12_mm=chk_12, check_a_21_mm=chk_21,
        check_2h_1_mm=chk_h1, check_2h_2_mm=chk_h2, check_ok=ok,
        alpha_w_deg=math.degrees(alpha_w), n1n2_mm=n1n2, pole_mm=pole, p1_mm=p1, p2_mm=p2,
        u1_mm=p1 + pb, u2_mm=p2 - pb, g_alpha_mm=g, eps_alpha=eps,
        phi_alpha1_deg=eps * tau1, phi_alpha2_deg=eps * tau2,
        phi_alpha1_geom_deg=math.degrees(g / rb1), phi_alpha2_geom_deg=math.degrees(g / rb2),
        single_zone_mm=max(0.0, 2 * pb - g), double_zone_mm=max(0.0, g - pb),
        z_min_undercut=z_min_undercut(alpha_deg, ha_star),
    )


def design_spur(n_motor_rpm: float, n_cam_rpm: float) -> SpurGeometry:
    """§2.3 from the speeds: tooth numbers (items 1–2), then the geometry (items 3–11).

    >>> g = design_spur(720, 600)
    >>> (g.z1, g.z2, g.i_d)
    (17, 20, 1.2)
    """
    z1, z2 = spur_teeth(n_motor_rpm, n_cam_rpm)
    return spur_geometry(z1, z2, i_d=n_motor_rpm / abs(n_cam_rpm))
