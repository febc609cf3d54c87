"""The spur pair from the motor to the cam: zero gears of §2.3 (sheet 4, lower field), and —
beyond the book — the same pair with profile shifts x1, x2 (``--shift``, ``--aw``; gears/shifted.py).

Fixed for every variant (§2.1.1, §2.3): m = 20 mm, α = 20°, h_a* = 1, c* = 0.25, x1 = x2 = 0.
Lengths are in millimetres (``_mm``) because the book's items are drawn at that scale; angles in
degrees carry ``_deg``.
"""

from __future__ import annotations

import math
from fractions import Fraction

from ..errors import TmmError
from ..records import record

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


@record
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
    # profile shift (beyond the book; zero pair by default). a_mm above is the reference distance
    # m(z1 + z2)/2; the gears run at a_w_mm (= a_mm for x1 + x2 = 0).
    x1: float = 0.0
    x2: float = 0.0
    shift_rule: str = "zero"  # "zero" | "given" | "auto" | "aw"
    a_w_mm: float = 0.0
    pair: object = None  # tmm_cli.gears.shifted.PairGeometry (d_w, s, s_w, s_a, y, Δy …)
    blocking: object = None  # tmm_cli.gears.blocking.PairChecks

    @property
    def shifted(self) -> bool:
        return self.shift_rule != "zero"

    @property
    def multiplier(self) -> bool:
        return self.i_d < 1.0


def spur_geometry(z1: int, z2: int, i_d: float | None = None, m_mm: float = M_MM,
                  alpha_deg: float = ALPHA_DEG, ha_star: float = HA_STAR, c_star: float = C_STAR,
                  x1: float = 0.0, x2: float = 0.0, shift_rule: str | None = None) -> SpurGeometry:
    """All items 3–11 of §2.3, plus ε_α computed from the geometry; with x1, x2 the shifted pair
    (α_w, a_w, Δy, d_a, d_f by gears/shifted.py, the checks of gears/blocking.py).

    ε_α = (√(r_a1² − r_b1²) + √(r_a2² − r_b2²) − a_w·sin α_w)/p_b (the active line P1P2 over the base
    pitch, Fig. 2.3); φ_α = ε_α·τ (§2.3, note). Item 11 checks a_w = d_a1/2 + d_f2/2 + C and
    d_a − d_f = 2h with h = (2h_a* + c* − Δy)m (Δy = 0 for a zero pair).

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

    Shifted to run at a_w = 380 mm (x1 = x2 = 0.2734):

    >>> h = spur_geometry(17, 20, x1=0.2734, x2=0.2734)
    >>> round(h.a_w_mm, 2), round(h.alpha_w_deg, 3), h.check_ok, round(h.eps_alpha, 3)
    (380.0, 23.799, True, 1.364)
    """
    from .blocking import check_pair
    from .shifted import pair_geometry, require_working

    pg = pair_geometry(z1, z2, m_mm, x1, x2, alpha_deg, ha_star, c_star)
    for j, z in enumerate((z1, z2)):
        if pg.sa_mm[j] <= 0:
            raise TmmError(f"the shift x{j + 1} = {pg.x[j]:g} makes gear {j + 1} (z = {z}) pointed: its tip thickness "
                           f"would be s_a = {pg.sa_mm[j]:.3f} mm ≤ 0; choose a smaller shift (s_a ≥ 0.25·m = "
                           f"{0.25 * m_mm:g} mm is the limit) or --shift auto")
    require_working(pg, "z1-z2")  # validated after: --shift 5,5 gave ε_α = −0,97 and d_a < d_f
    alpha = math.radians(alpha_deg)
    m = m_mm
    d1, d2 = pg.d_mm
    db1, db2 = pg.db_mm
    da1, da2 = pg.da_mm
    df1, df2 = pg.df_mm
    a = m * (z1 + z2) / 2
    a_w = pg.a_w_mm
    p = math.pi * m
    pb = p * math.cos(alpha)
    s = e = math.pi * m / 2
    tau1, tau2 = 360.0 / z1, 360.0 / z2
    h = (2 * ha_star + c_star - pg.dy) * m
    hd = (2 * ha_star - pg.dy) * m
    c = c_star * m
    chk_pitch = (pg.dw_mm[0] + pg.dw_mm[1]) / 2
    chk_12 = da1 / 2 + df2 / 2 + c
    chk_21 = da2 / 2 + df1 / 2 + c
    chk_h1, chk_h2 = da1 - df1, da2 - df2
    tol = 1e-9 * max(a_w, 1.0)
    ok = (abs(chk_pitch - a_w) < tol and abs(chk_12 - a_w) < tol and abs(chk_21 - a_w) < tol
          and abs(chk_h1 - 2 * h) < tol and abs(chk_h2 - 2 * h) < tol)
    rb1, rb2 = db1 / 2, db2 / 2
    g = pg.g_alpha_mm
    eps = pg.eps_alpha
    rule = shift_rule or ("zero" if x1 == 0 and x2 == 0 else "given")
    return SpurGeometry(
        z1=z1, z2=z2, m_mm=m, alpha_deg=alpha_deg, ha_star=ha_star, c_star=c_star,
        i_d=float(i_d) if i_d is not None else z2 / z1, i_actual=z2 / z1,
        d1_mm=d1, d2_mm=d2, db1_mm=db1, db2_mm=db2, da1_mm=da1, da2_mm=da2, df1_mm=df1, df2_mm=df2,
        a_mm=a, p_mm=p, pb_mm=pb, s_mm=s, e_mm=e, tau1_deg=tau1, tau2_deg=tau2, h_mm=h, hd_mm=hd, c_mm=c,
        fillet_mm=FILLET_RADIUS_FACTOR * m,
        check_a_pitch_mm=chk_pitch, check_a_12_mm=chk_12, check_a_21_mm=chk_21,
        check_2h_1_mm=chk_h1, check_2h_2_mm=chk_h2, check_ok=ok,
        alpha_w_deg=pg.alpha_w_deg, n1n2_mm=pg.n1n2_mm, pole_mm=pg.pole_mm, p1_mm=pg.p1_mm, p2_mm=pg.p2_mm,
        u1_mm=pg.p1_mm + pb, u2_mm=pg.p2_mm - pb, g_alpha_mm=g, eps_alpha=eps,
        phi_alpha1_deg=eps * tau1, phi_alpha2_deg=eps * tau2,
        phi_alpha1_geom_deg=math.degrees(g / rb1), phi_alpha2_geom_deg=math.degrees(g / rb2),
        single_zone_mm=max(0.0, 2 * pb - g), double_zone_mm=max(0.0, g - pb),
        z_min_undercut=z_min_undercut(alpha_deg, ha_star),
        x1=float(x1), x2=float(x2), shift_rule=rule, a_w_mm=a_w, pair=pg, blocking=check_pair(pg),
    )


def design_spur(n_motor_rpm: float, n_cam_rpm: float, shift=None, a_w_mm: float | None = None) -> SpurGeometry:
    """§2.3 from the speeds: tooth numbers (items 1–2), then the geometry (items 3–11); ``shift``
    ("auto" or (x1, x2)) and ``a_w_mm`` as in :func:`~tmm_cli.gears.shifted.resolve_shift`.

    >>> g = design_spur(720, 600)
    >>> (g.z1, g.z2, g.i_d, g.shift_rule)
    (17, 20, 1.2, 'zero')
    >>> round(design_spur(720, 600, a_w_mm=380.0).x1, 4)
    0.2734
    """
    from .shifted import resolve_shift

    z1, z2 = spur_teeth(n_motor_rpm, n_cam_rpm)
    x1, x2, rule = resolve_shift(z1, z2, M_MM, shift, a_w_mm, ALPHA_DEG, HA_STAR)
    return spur_geometry(z1, z2, i_d=n_motor_rpm / abs(n_cam_rpm), x1=x1, x2=x2, shift_rule=rule)
