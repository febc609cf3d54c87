"""Geometry of an external spur pair cut by a rack with profile shifts x1, x2 (seed 000 and the
standard textbook formulas of shifted gearing).

Sources: seed 000 (Kavetsky 2010: inv α_w = inv α + 2x_Σ tg α/(z1 + z2), a_w = a·cos α/cos α_w);
the rest are the classical formulas of rack-cut shifted gears as every Russian TMM textbook gives
them (e.g. Артоболевский И. И., «Теория механизмов и машин», 1988, гл. 22; ГОСТ 16532-70, табл. 1):
the centre-distance change y = (a_w − a)/m, the tip reduction Δy = x_Σ − y, d_w = d·cos α/cos α_w,
d_a = d + 2(h_a* + x − Δy)m, d_f = d − 2(h_a* + c* − x)m, the tooth thickness on the pitch circle
s = m(π/2 + 2x tg α) and on any circle r_y: s_y = 2r_y(s/d + inv α − inv α_y), cos α_y = r_b/r_y.

Lengths are millimetres (``_mm``), angles carry ``_deg``; inside, radians. Per-gear values are
pairs ``(gear 1, gear 2)``. The core never prints; bad input raises :class:`~tmm_cli.errors.TmmError`.
"""

from __future__ import annotations

import math

from ..errors import TmmError
from ..limits import SHIFT_X
from ..records import record
from .involute import inv, inv_inverse

ALPHA_DEG = 20.0
HA_STAR = 1.0
C_STAR = 0.25
Z_UNDERCUT = 17
"""Tooth number below which a zero rack-cut gear (α = 20°, h_a* = 1) is undercut, in the rounded form
the blocking contours use (the exact limit 2h_a*/sin²α is 17.1)."""


def x_min_undercut(z: int, ha_star: float = HA_STAR, z_limit: float = Z_UNDERCUT) -> float:
    """Smallest shift without undercut x_min = h_a*(17 − z)/17 (Артоболевский, гл. 22; the
    undercut line of the blocking contour). Negative for z > 17: such a gear may be shifted in.

    >>> round(x_min_undercut(12), 4), x_min_undercut(17), round(x_min_undercut(27), 4)
    (0.2941, 0.0, -0.5882)
    """
    return ha_star * (z_limit - z) / z_limit


def pitch_thickness_mm(m_mm: float, x: float, alpha_deg: float = ALPHA_DEG) -> float:
    """Tooth thickness on the pitch circle s = m(π/2 + 2x tg α) [mm] (rack-cut gear).

    >>> round(pitch_thickness_mm(20, 0.0), 4), round(pitch_thickness_mm(5, 0.4), 4)
    (31.4159, 9.3099)
    """
    return m_mm * (math.pi / 2 + 2 * x * math.tan(math.radians(alpha_deg)))


def thickness_at_radius_mm(r_mm: float, rb_mm: float, s_mm: float, d_mm: float, alpha_deg: float = ALPHA_DEG) -> float:
    """Tooth thickness on the circle of radius r_y: s_y = 2r_y(s/d + inv α − inv α_y) [mm],
    cos α_y = r_b/r_y (the involute's polar equation). Negative: the tooth is pointed below r_y.

    The zero gear z = 17, m = 20 on its tip circle (r_a = 190 mm):

    >>> round(thickness_at_radius_mm(190.0, 170 * math.cos(math.radians(20)), 10 * math.pi, 340.0), 3)
    13.482
    """
    alpha = math.radians(alpha_deg)
    ay = math.acos(min(1.0, rb_mm / r_mm))
    return 2 * r_mm * (s_mm / d_mm + inv(alpha) - inv(ay))


def lower_limit_roll_mm(z: int, m_mm: float, x: float, alpha_deg: float = ALPHA_DEG, ha_star: float = HA_STAR) -> float:
    """Roll length ρ_l [mm] (distance from the base-circle tangent point N) of the lower limit point
    of the involute of a rack-cut gear: ρ_l = r·sin α − (h_a* − x)m/sin α.

    The rack's straight flank ends (h_a* − x)·m inside the pitch circle; along the generating line
    of action (through the pitch point, at α) that is (h_a* − x)m/sin α short of it. Below this
    point the flank is the fillet (transition curve), not involute; ρ_l < 0 means undercut
    (the condition ρ_l ≥ 0 is x ≥ h_a* − z·sin²α/2, the exact undercut limit).

    The book's zero pinion z = 17 (below the exact limit 17.1) is very slightly undercut; 18 is not:

    >>> round(lower_limit_roll_mm(17, 20, 0.0), 3), round(lower_limit_roll_mm(18, 20, 0.0), 3)
    (-0.333, 3.088)
    """
    alpha = math.radians(alpha_deg)
    return m_mm * z / 2 * math.sin(alpha) - (ha_star - x) * m_mm / math.sin(alpha)


@record
class PairGeometry:
    """A shifted external pair. Line-of-action positions are measured from N1 towards N2 [mm]:
    P1 (contact starts, tip circle of gear 2), P (pole), P2 (contact ends, tip circle of gear 1).
    ``rho_l_mm`` are the roll lengths of the involute's lower limit points from N1 (gear 1) and
    from N2 (gear 2); ``rho_contact_mm`` the roll lengths where each flank first/last works:
    N1P1 on gear 1, N2P2 on gear 2."""

    z: tuple[int, int]
    m_mm: float
    alpha_deg: float
    ha_star: float
    c_star: float
    x: tuple[float, float]
    x_sum: float
    alpha_w_deg: float
    a_mm: float  # reference a = m(z1 + z2)/2
    a_w_mm: float
    y: float  # centre-distance change (a_w − a)/m
    dy: float  # tip reduction Δy = x_Σ − y
    d_mm: tuple[float, float]
    db_mm: tuple[float, float]
    dw_mm: tuple[float, float]
    da_mm: tuple[float, float]
    df_mm: tuple[float, float]
    da_nominal_mm: tuple[float, float]  # d + 2(h_a* + x − Δy)m before any override (linked planet)
    s_mm: tuple[float, float]  # on the pitch circle
    sw_mm: tuple[float, float]  # on the working circle
    sa_mm: tuple[float, float]  # on the tip circle
    p_mm: float
    pb_mm: float
    pw_mm: float  # circular pitch on the working circles π·d_w/z
    n1n2_mm: float
    pole_mm: float
    p1_mm: float
    p2_mm: float
    g_alpha_mm: float
    eps_alpha: float
    rho_l_mm: tuple[float, float]
    rho_contact_mm: tuple[float, float]
    x_min: tuple[float, float]

    @property
    def z1(self) -> int:
        return self.z[0]

    @property
    def z2(self) -> int:
        return self.z[1]

    @property
    def e_mm(self) -> tuple[float, float]:
        """Space width on the pitch circle e = p − s [mm] (the drawing sheet's dimension e)."""
        return tuple(self.p_mm - si for si in self.s_mm)

    @property
    def ha_mm(self) -> tuple[float, float]:
        """Addendum h_a = (d_a − d)/2 = (h_a* + x − Δy)·m [mm] of each gear."""
        return tuple((da - d) / 2 for da, d in zip(self.da_mm, self.d_mm))

    @property
    def hf_mm(self) -> tuple[float, float]:
        """Dedendum h_f = (d − d_f)/2 = (h_a* + c* − x)·m [mm] of each gear."""
        return tuple((d - df) / 2 for d, df in zip(self.d_mm, self.df_mm))

    @property
    def shift_mm(self) -> tuple[float, float]:
        """The tool's displacement x·m [mm] of each gear (+ away from the centre)."""
        return tuple(xi * self.m_mm for xi in self.x)


def working_angle_deg(z1: int, z2: int, x_sum: float, alpha_deg: float = ALPHA_DEG) -> float:
    """α_w [deg] from inv α_w = inv α + 2x_Σ tg α/(z1 + z2) (seed 000, step 1), by Newton.

    >>> round(working_angle_deg(30, 48, 0.0), 9), round(working_angle_deg(48, 27, 1.7003942), 3)
    (20.0, 25.371)
    """
    alpha = math.radians(alpha_deg)
    value = inv(alpha) + 2 * x_sum * math.tan(alpha) / (z1 + z2)
    if value <= 0:
        raise TmmError(f"the shift sum x1 + x2 = {x_sum:g} is too negative for z1 + z2 = {z1 + z2}: inv α_w would be "
                       f"{value:.4g} ≤ 0; use a larger shift sum (x1 + x2 > {-inv(alpha) * (z1 + z2) / (2 * math.tan(alpha)):.3f})")
    return math.degrees(inv_inverse(value))


def shift_sum_for_distance(z1: int, z2: int, m_mm: float, a_w_mm: float, alpha_deg: float = ALPHA_DEG) -> tuple[float, float]:
    """(α_w [deg], x_Σ) for a required centre distance a_w (seed 000, step 3):
    cos α_w = a·cos α/a_w, x_Σ = (inv α_w − inv α)(z1 + z2)/(2 tg α).

    >>> aw, xs = shift_sum_for_distance(48, 27, 5, 195.0)
    >>> round(aw, 3), round(xs, 3), round(xs, 5)
    (25.371, 1.7, 1.70039)
    """
    alpha = math.radians(alpha_deg)
    a = m_mm * (z1 + z2) / 2
    if not (math.isfinite(a_w_mm) and a_w_mm > 0):
        raise TmmError(f"centre distance a_w must be a positive number of mm, got {a_w_mm!r}; e.g. --aw {a + m_mm:g}")
    cos_aw = a * math.cos(alpha) / a_w_mm
    if cos_aw >= 1.0:
        raise TmmError(f"centre distance a_w = {a_w_mm:g} mm cannot be reached: no shift sum brings z1 = {z1}, z2 = {z2}, "
                       f"m = {m_mm:g} mm closer than a·cos α = {a * math.cos(alpha):.2f} mm (and practically not much "
                       f"below a = {a:g} mm); give --aw of about {a:g} mm or more")
    aw = math.acos(cos_aw)
    return math.degrees(aw), (inv(aw) - inv(alpha)) * (z1 + z2) / (2 * math.tan(alpha))


def pair_geometry(z1: int, z2: int, m_mm: float, x1: float, x2: float, alpha_deg: float = ALPHA_DEG,
                  ha_star: float = HA_STAR, c_star: float = C_STAR,
                  da_mm: tuple[float, float] | None = None) -> PairGeometry:
    """The shifted pair: α_w, a_w, y, Δy, d_w, d_a, d_f, s, s_w, s_a and ε_α from the real tip circles
    (``da_mm`` overrides the tip diameters, e.g. for a planet that meshes two wheels).

    ε_α = (√(r_a1² − r_b1²) + √(r_a2² − r_b2²) − a_w·sin α_w)/p_b.

    Seed 000's first pair, z = 30/48, m = 5, x = −0.4/0.4:

    >>> g = pair_geometry(30, 48, 5, -0.4, 0.4)
    >>> round(g.alpha_w_deg, 6), round(g.a_w_mm, 6), round(g.dy, 6), g.da_mm
    (20.0, 195.0, 0.0, (156.0, 254.0))

    Its second pair at the same centre distance, x3 = 0.4, x4 = x_Σ34 − x3 = 1.70039 − 0.4 (1.3 in the seed):

    >>> h = pair_geometry(48, 27, 5, 0.4, 1.3003942)
    >>> round(h.alpha_w_deg, 3), round(h.a_w_mm, 3), round(h.y, 3), round(h.dy, 3)
    (25.371, 195.0, 1.5, 0.2)

    The book's zero pair 17/20, m = 20: ε_α = 1.536 as in spur.py.

    >>> round(pair_geometry(17, 20, 20, 0, 0).eps_alpha, 3)
    1.536
    """
    for name, v in (("x1", x1), ("x2", x2)):
        if not math.isfinite(v):
            raise TmmError(f"shift {name} must be a number, got {v!r}; e.g. --shift 0.3,-0.3")
    if z1 < 1 or z2 < 1:
        raise TmmError(f"tooth numbers must be positive, got {z1}, {z2}")
    alpha = math.radians(alpha_deg)
    m = m_mm
    x_sum = x1 + x2
    alpha_w_deg = alpha_deg if x_sum == 0 else working_angle_deg(z1, z2, x_sum, alpha_deg)
    alpha_w = math.radians(alpha_w_deg)
    a = m * (z1 + z2) / 2
    a_w = a * math.cos(alpha) / math.cos(alpha_w)
    y = (a_w - a) / m
    dy = x_sum - y
    zz = (z1, z2)
    xx = (x1, x2)
    d = tuple(m * z for z in zz)
    db = tuple(di * math.cos(alpha) for di in d)
    dw = tuple(di * math.cos(alpha) / math.cos(alpha_w) for di in d)
    da_nom = tuple(di + 2 * (ha_star + xi - dy) * m for di, xi in zip(d, xx))
    da = tuple(da_mm) if da_mm is not None else da_nom
    df = tuple(di - 2 * (ha_star + c_star - xi) * m for di, xi in zip(d, xx))
    rb1, rb2 = db[0] / 2, db[1] / 2
    ra1, ra2 = da[0] / 2, da[1] / 2
    if ra1 <= rb1 or ra2 <= rb2:  # before any involute function is asked outside its domain (--shift 10,-10)
        if x_sum > 0 and dy > 0 and min(xx) >= 0:  # the tip reduction, not a negative shift, cut the tips away
            raise TmmError(f"the shift sum x1 + x2 = {x_sum:.4g} is so large that the tip reduction Δy = {dy:.4g} puts a "
                           f"tip circle inside its base circle; take a smaller shift sum (a_w closer to a = {a:.4g} mm)")
        raise TmmError("a tip circle lies inside its base circle: the shifts are far too negative for these teeth")
    s = tuple(pitch_thickness_mm(m, xi, alpha_deg) for xi in xx)
    sw = tuple(thickness_at_radius_mm(dwi / 2, dbi / 2, si, di, alpha_deg) for dwi, dbi, si, di in zip(dw, db, s, d))
    sa = tuple(thickness_at_radius_mm(dai / 2, dbi / 2, si, di, alpha_deg) for dai, dbi, si, di in zip(da, db, s, d))
    p = math.pi * m
    pb = p * math.cos(alpha)
    pw = math.pi * dw[0] / z1
    n1n2 = a_w * math.sin(alpha_w)
    pole = rb1 * math.tan(alpha_w)
    p2 = math.sqrt(ra1 * ra1 - rb1 * rb1)
    p1 = n1n2 - math.sqrt(ra2 * ra2 - rb2 * rb2)
    g = p2 - p1
    rho_l = tuple(lower_limit_roll_mm(z, m, xi, alpha_deg, ha_star) for z, xi in zip(zz, xx))
    return PairGeometry(
        z=zz, m_mm=m, alpha_deg=alpha_deg, ha_star=ha_star, c_star=c_star, x=xx, x_sum=x_sum,
        alpha_w_deg=alpha_w_deg, a_mm=a, a_w_mm=a_w, y=y, dy=dy, d_mm=d, db_mm=db, dw_mm=dw, da_mm=da, df_mm=df,
        da_nominal_mm=da_nom, s_mm=s, sw_mm=sw, sa_mm=sa, p_mm=p, pb_mm=pb, pw_mm=pw, n1n2_mm=n1n2, pole_mm=pole,
        p1_mm=p1, p2_mm=p2, g_alpha_mm=g, eps_alpha=g / pb, rho_l_mm=rho_l, rho_contact_mm=(p1, n1n2 - p2),
        x_min=(x_min_undercut(z1, ha_star), x_min_undercut(z2, ha_star)),
    )


def require_working(g: PairGeometry, pair: str, contact: bool = True) -> None:
    """TmmError (with the reason) for a designed pair that cannot be made or cannot run: a tip
    circle inside its root circle (d_a ≤ d_f: the tip reduction Δy took the whole tooth), or (with
    `contact`) a contact ratio ε_α < 1 (a pair of teeth leaves the mesh before the next engages).

    >>> require_working(pair_geometry(17, 20, 20, 0.3, 0.3), "z1-z2")
    >>> require_working(pair_geometry(24, 17, 20, 5, 5), "z1-z2")
    Traceback (most recent call last):
    tmm_cli.errors.TmmError: pair z1-z2: gear 1 (z = 24) would have its tip circle d_a = 565.299 mm inside its root circle d_f = 630.000 mm (the tip reduction Δy = 3.868 of x1 + x2 = 10 takes the whole tooth); take smaller shifts (or --shift auto)
    """
    for j in range(2):
        if g.da_mm[j] <= g.df_mm[j]:
            raise TmmError(f"pair {pair}: gear {j + 1} (z = {g.z[j]}) would have its tip circle d_a = {g.da_mm[j]:.3f} mm "
                           f"inside its root circle d_f = {g.df_mm[j]:.3f} mm (the tip reduction Δy = {g.dy:.3f} of "
                           f"x1 + x2 = {g.x_sum:.4g} takes the whole tooth); take smaller shifts (or --shift auto)")
    if contact and not g.eps_alpha >= 1.0:
        raise TmmError(f"pair {pair}: the contact ratio ε_α = {g.eps_alpha:.3f} < 1: a pair of teeth leaves the mesh "
                       f"before the next one engages, so the gears cannot run; take smaller shifts (or --shift auto)")


def auto_shift(z1: int, z2: int, ha_star: float = HA_STAR) -> tuple[float, float]:
    """``--shift auto``: no undercut on either gear, then a balanced split (the classical rule of
    Russian TMM textbooks, e.g. Артоболевский И. И., «Теория механизмов и машин», 1988, гл. 22;
    Кореняко А. С. и др., «Курсовое проектирование по ТММ», 1970):

    * each gear needs x_i ≥ x_min,i = h_a*(17 − z_i)/17;
    * z1 + z2 ≥ 34: a height-corrected pair (x_Σ = 0, the centre distance stays a = m(z1 + z2)/2):
      the smaller gear takes x = max(x_min, 0), the larger one the opposite shift −x (it does not
      undercut, because z1 + z2 ≥ 34); two gears of 17 or more teeth stay a zero pair;
    * z1 + z2 < 34: a positive pair, each gear at its own limit, x_i = x_min,i (the smallest
      x_Σ without undercut).

    >>> auto_shift(17, 20), auto_shift(12, 40), auto_shift(12, 14)
    ((0.0, 0.0), (0.2941, -0.2941), (0.2941, 0.1765))
    """
    l1, l2 = x_min_undercut(z1, ha_star), x_min_undercut(z2, ha_star)
    if z1 + z2 >= 2 * Z_UNDERCUT:
        if z1 <= z2:
            x1 = round(max(l1, 0.0), 4)
            return x1 + 0.0, -x1 + 0.0
        x2 = round(max(l2, 0.0), 4)
        return -x2 + 0.0, x2 + 0.0
    return round(l1, 4), round(l2, 4)


def split_shift_sum(z1: int, z2: int, x_sum: float, ha_star: float = HA_STAR) -> tuple[float, float]:
    """Split a shift sum required by a centre distance (``--aw``): start from :func:`auto_shift`
    and share the difference x_Σ − x_Σ,auto equally between the two gears.

    >>> x1, x2 = split_shift_sum(17, 20, 0.5)
    >>> round(x1, 4), round(x2, 4)
    (0.25, 0.25)
    """
    b1, b2 = auto_shift(z1, z2, ha_star)
    extra = (x_sum - (b1 + b2)) / 2
    return b1 + extra, b2 + extra


def parse_shift(text: str) -> tuple[float, float] | str:
    """``--shift``: "auto" or two numbers "x1,x2" (also "x1;x2" or "x1 x2"; decimals with a dot).

    >>> parse_shift("auto"), parse_shift("0.3,-0.3"), parse_shift(" -0.2 ; 0.5 ")
    ('auto', (0.3, -0.3), (-0.2, 0.5))
    """
    t = (text or "").strip().lower()
    if t in ("auto", "авто"):
        return "auto"
    parts = [p for p in t.replace(";", ",").replace(" ", ",").split(",") if p]
    try:
        if len(parts) != 2:
            raise ValueError
        x1, x2 = (float(p) for p in parts)
    except ValueError:
        raise TmmError(f"cannot read --shift {text!r}: write two shift coefficients with decimal dots, "
                       "e.g. --shift 0.3,-0.3, or --shift auto") from None
    if not (math.isfinite(x1) and math.isfinite(x2)):
        raise TmmError(f"--shift {text!r} must be two finite numbers, e.g. --shift 0.3,-0.3")
    lo, hi = SHIFT_X
    for name, x in (("x1", x1), ("x2", x2)):
        if not lo <= x <= hi:
            raise TmmError(f"--shift {text!r}: {name} = {x:g} is outside {lo:g} … {hi:g}; profile shift coefficients "
                           f"lie within about ±1.5 (e.g. --shift 0.3,-0.3, or --shift auto)")
    return x1, x2


def resolve_shift(z1: int, z2: int, m_mm: float, shift: tuple[float, float] | str | None = None,
                  a_w_mm: float | None = None, alpha_deg: float = ALPHA_DEG,
                  ha_star: float = HA_STAR) -> tuple[float, float, str]:
    """(x1, x2, rule) from the user's ``--shift`` and ``--aw``; rule is "zero" (the book's default),
    "given", "auto" (:func:`auto_shift`) or "aw" (x_Σ from a_w, split by :func:`split_shift_sum`).

    >>> resolve_shift(17, 20, 20), resolve_shift(17, 20, 20, "auto")
    ((0.0, 0.0, 'zero'), (0.0, 0.0, 'auto'))
    >>> x1, x2, rule = resolve_shift(17, 20, 20, None, 380.0)
    >>> round(x1, 4), round(x2, 4), rule
    (0.2734, 0.2734, 'aw')
    """
    if a_w_mm is not None:
        _, xs = shift_sum_for_distance(z1, z2, m_mm, a_w_mm, alpha_deg)
        if shift is None or shift == "auto":
            x1, x2 = split_shift_sum(z1, z2, xs, ha_star)
            return x1, x2, "aw"
        x1, x2 = shift
        g = pair_geometry(z1, z2, m_mm, x1, x2, alpha_deg, ha_star)
        if abs(g.a_w_mm - a_w_mm) > 1e-3:
            raise TmmError(f"--shift {x1:g},{x2:g} gives a_w = {g.a_w_mm:.3f} mm, not the required --aw {a_w_mm:g}: "
                           f"give one of them (for a_w = {a_w_mm:g} mm the shift sum must be x1 + x2 = {xs:.4f})")
        return x1, x2, "given"
    if shift is None:
        return 0.0, 0.0, "zero"
    if shift == "auto":
        x1, x2 = auto_shift(z1, z2, ha_star)
        return x1, x2, "auto"
    x1, x2 = shift
    return float(x1), float(x2), "given"
