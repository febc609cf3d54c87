"""Sheet 4 against the book's worked examples (§2.3, §2.4, §2.5) and seed 000's involute example."""

import math

import pytest

from tmm_cli.gears.design import design_gears
from tmm_cli.gears.involute import inv, inv_inverse, shift_sum_for_distance, working_angle, centre_distance_mm
from tmm_cli.gears.spur import design_spur, spur_geometry, spur_teeth


# ---------------------------------------------------------------- §2.3 spur pair


def test_spur_book_example_teeth_and_geometry():
    g = design_spur(720, 600)  # §2.3: n_d = 720, n_k = 600
    assert (g.z1, g.z2) == (17, 20)
    assert g.i_d == pytest.approx(1.2)
    m = 20.0
    assert (g.d1_mm, g.d2_mm) == (340.0, 400.0)
    assert g.db1_mm == pytest.approx(340 * math.cos(math.radians(20)))
    assert (g.da1_mm, g.da2_mm, g.df1_mm, g.df2_mm) == (380.0, 440.0, 290.0, 350.0)
    assert g.a_mm == 370.0
    assert g.p_mm == pytest.approx(math.pi * m) and g.pb_mm == pytest.approx(59.0426, abs=1e-4)
    assert g.s_mm == g.e_mm == pytest.approx(31.4159, abs=1e-4)
    assert g.tau1_deg == pytest.approx(21.1765, abs=1e-4) and g.tau2_deg == 18.0
    assert (g.h_mm, g.hd_mm, g.c_mm) == (45.0, 40.0, 5.0)
    # item 11, the check: a = da1/2 + df2/2 + C = da2/2 + df1/2 + C; 2h = da − df
    assert g.check_ok
    assert 380 / 2 + 350 / 2 + 5 == g.a_mm == 440 / 2 + 290 / 2 + 5


def test_contact_ratio_by_the_angle_formula():
    # independent form: ε = [z1(tg α_a1 − tg α_w) + z2(tg α_a2 − tg α_w)]/(2π)
    for z1, z2 in ((17, 20), (17, 43), (59, 17), (24, 17)):
        g = spur_geometry(z1, z2)
        al = math.radians(20)
        aa1 = math.acos(z1 * math.cos(al) / (z1 + 2))
        aa2 = math.acos(z2 * math.cos(al) / (z2 + 2))
        eps = (z1 * (math.tan(aa1) - math.tan(al)) + z2 * (math.tan(aa2) - math.tan(al))) / (2 * math.pi)
        assert g.eps_alpha == pytest.approx(eps, rel=1e-12)
        # overlap angles: ε·τ equals the turn while the contact runs P1 → P2
        assert g.phi_alpha1_deg == pytest.approx(g.phi_alpha1_geom_deg, rel=1e-12)
        assert g.phi_alpha2_deg == pytest.approx(g.phi_alpha2_geom_deg, rel=1e-12)
        # zones: P1 < U2 < U1 < P2 when 1 < ε < 2, double zones equal
        assert g.p1_mm < g.u2_mm < g.u1_mm < g.p2_mm
        assert g.u2_mm - g.p1_mm == pytest.approx(g.p2_mm - g.u1_mm)


def _overlap_angles_deg(z1, z2, x1=0.0, x2=0.0, m=20.0):
    """φ_α1, φ_α2 [°] by the book's definition (§2.3, the note to Fig. 2.3): the turn of a gear
    from its tooth's entry into contact to its exit. Along the line of action each base circle
    rolls off the active part, so gear j turns by the difference of its roll angles tg α at the two
    ends: with t_j = tg α_aj − tg α_w, φ_α1 = t1 + (z2/z1)·t2 and φ_α2 = t2 + (z1/z2)·t1 [rad].
    The geometry written out here (standard formulas; nothing of tmm_cli.gears): inv α_w =
    2·x_Σ·tg α/(z1 + z2) + inv α, a_w = a·cos α/cos α_w, Δy = x_Σ − (a_w − a)/m,
    r_a = m·(z/2 + 1 + x − Δy), r_b = m·z·cos α/2."""
    al = math.radians(20)

    def inv(x):
        return math.tan(x) - x

    target = 2 * (x1 + x2) * math.tan(al) / (z1 + z2) + inv(al)
    aw = al
    for _ in range(60):  # Newton: d(inv)/dα = tg²α
        aw -= (inv(aw) - target) / math.tan(aw) ** 2
    a = m * (z1 + z2) / 2
    a_w = a * math.cos(al) / math.cos(aw)
    dy = x1 + x2 - (a_w - a) / m
    t = []
    for z, x in ((z1, x1), (z2, x2)):
        ra, rb = m * (z / 2 + 1 + x - dy), m * z * math.cos(al) / 2
        t.append(math.sqrt(ra * ra - rb * rb) / rb - math.tan(aw))
    return math.degrees(t[0] + z2 / z1 * t[1]), math.degrees(t[1] + z1 / z2 * t[0])


@pytest.mark.parametrize("z1, z2, x1, x2", [(17, 20, 0, 0), (17, 43, 0, 0), (59, 17, 0, 0), (24, 17, 0, 0),
                                            (17, 20, 0.2734, 0.2734), (13, 31, 0.5, -0.2), (12, 12, 0.4, 0.4)])
def test_overlap_angles_by_the_roll_of_the_base_circles(z1, z2, x1, x2):
    """The book's example (z1 = 17, z2 = 20): φ_α1 = 1.536·21.18° ≈ 32.5°, φ_α2 = 1.536·18° ≈ 27.6°;
    every pair, shifted ones too, against the roll angles; the two gears turn in the ratio of
    their teeth, φ_α1/φ_α2 = z2/z1, and each angle over its pitch angle is the one ε_α."""
    g = spur_geometry(z1, z2, x1=x1, x2=x2)
    phi1, phi2 = _overlap_angles_deg(z1, z2, x1, x2)
    assert g.phi_alpha1_deg == pytest.approx(phi1, rel=1e-9)
    assert g.phi_alpha2_deg == pytest.approx(phi2, rel=1e-9)
    assert g.phi_alpha1_deg * z1 == pytest.approx(g.phi_alpha2_deg * z2, rel=1e-12)
    assert g.phi_alpha1_deg / (360 / z1) == pytest.approx(g.phi_alpha2_deg / (360 / z2), rel=1e-12)
    if (z1, z2, x1) == (17, 20, 0):
        assert (round(g.phi_alpha1_deg, 1), round(g.phi_alpha2_deg, 1)) == (32.5, 27.6)


def test_single_and_double_pair_zones_on_the_line_of_action():
    """Fig. 2.3: on the active line P1P2 (length g_α = ε_α·p_b) the two end zones of length
    g_α − p_b carry two pairs, the middle U2U1 of length 2·p_b − g_α one pair. The book's example
    17/20: p_b = 59.04 mm, g_α = 1.5358·p_b = 90.68 mm: 27.41 mm single, 31.64 mm double."""
    for z1, z2, x1, x2 in ((17, 20, 0, 0), (17, 43, 0, 0), (13, 31, 0.5, -0.2), (24, 17, 0.3, 0.3)):
        g = spur_geometry(z1, z2, x1=x1, x2=x2)
        assert g.single_zone_mm == pytest.approx(g.u1_mm - g.u2_mm, rel=1e-12)
        assert g.double_zone_mm == pytest.approx(g.u2_mm - g.p1_mm, rel=1e-12)
        assert g.single_zone_mm + 2 * g.double_zone_mm == pytest.approx(g.p2_mm - g.p1_mm, rel=1e-12)
    g = spur_geometry(17, 20)
    assert (round(g.single_zone_mm, 2), round(g.double_zone_mm, 2)) == (27.41, 31.64)


def test_a_pointed_shift_names_the_limit_in_mm():
    """m = 20 mm: the limit the message offers is 0.25·m = 5 mm."""
    from tmm_cli.errors import TmmError

    with pytest.raises(TmmError, match=r"s_a ≥ 0\.25·m = 5 mm is the limit") as info:
        spur_geometry(17, 20, x1=2.5, x2=0.0)
    assert str(info.value).startswith("the shift x1 = 2.5 makes gear 1 (z = 17) pointed")


def test_no_single_row_scheme_below_a_ratio_of_2():
    """§2.4: z_n/z_k = i − 1 and z_c = (z_n − z_k)/2, so i ≤ 2 leaves the planet no teeth."""
    from fractions import Fraction

    from tmm_cli.gears.planetary.book import book_scheme1

    assert book_scheme1(Fraction(3, 2)) is None and book_scheme1(Fraction(2)) is None
    assert book_scheme1(Fraction(13, 4)).chosen.teeth == (40, 25, 90)


@pytest.mark.parametrize("value", [1e-12, 1e-6, 0.0149, 0.5, 3.0, 50.0, 1e3, 1e5])
def test_inverse_involute_round_trip_up_to_the_asymptote(value):
    """inv α = tg α − α grows without bound as α → 90°: its inverse must stay below 90° and give
    the value back for every value, also where Newton's first step would jump past the asymptote."""
    a = inv_inverse(value)
    assert 0 < a < math.pi / 2
    assert inv(a) == pytest.approx(value, rel=1e-9)  # near 90° a step of α's last bit moves inv α by 1e-11


@pytest.mark.parametrize("n_cr, rule", [(40, "exact"), (37, "simple"), (33, "simple")])
def test_two_stage_book_derivation_within_the_tolerance(n_cr, rule):
    """§2.4 applied twice (i > 16: scheme 1+1): the book's procedure finds two stages whose product
    is i_pl within ±5 % (720/40 = 18 exactly; 720/37 = 19.46 through simple fractions near √i)."""
    r = design_gears(1000, n_cr)
    i = r.motor_rpm / n_cr
    d = r.derivation
    assert r.planetary.scheme == "1+1" and d is not None and d.scheme == "1+1" and len(d.stages) == 2
    assert d.fraction_rule == rule
    assert abs(float(d.ratio_fraction) / i - 1) <= 0.05 + 1e-12


@pytest.mark.parametrize("scheme, fraction", [("1", (13, 4)), ("1", (36, 7)), ("2", (53, 5)), ("2", (72, 5))])
def test_book_stage_planets_by_the_reference_conditions(scheme, fraction):
    """The planets the book's chosen set carries (k_max_exact) are the most that pass the
    neighbouring and assembly conditions, checked by tests/reference_gears.py with the set's own
    sun, planet(s) and ring."""
    from fractions import Fraction

    from tmm_cli.gears.planetary.book import book_scheme1, book_scheme2

    from reference_gears import max_planets

    b = (book_scheme1 if scheme == "1" else book_scheme2)(Fraction(*fraction))
    t = b.chosen.teeth
    zk, zc, zc2, zn = (t[0], t[1], t[1], t[2]) if scheme == "1" else t  # the reference's single planet: zc2 = zc
    assert b.k_max_exact == max_planets(zk, zc, zc2, zn) >= 2
    assert (b.stage.z_sun, b.stage.z_ring) == (zk, zn)


def test_spur_rounding_exact_half_goes_up():
    # variants 24 and 44 have n_k = −1800: 17·1800/720 = 42.5 → 43 (a float could round it either way)
    assert spur_teeth(720, -1800) == (43, 17)
    assert spur_teeth(720, 600) == (17, 20)
    assert spur_teeth(720, 720) == (17, 17)
    # a multiplier: the small gear is the driven one, on the cam
    z1, z2 = spur_teeth(720, 2500)
    assert z2 == 17 and z1 == round(17 * 2500 / 720)


# ---------------------------------------------------------------- §2.4 single row


def test_book_2_4_single_row_example():
    r = design_gears(600, 220, ratio=(13, 4))
    assert r.motor_rpm == 720 and r.scheme == "1"
    st = r.planetary.stages[0]
    assert (st.z_sun, st.z_planet, st.z_ring, st.planets) == (40, 25, 90, 5)
    assert st.z_planet2 is None
    d = r.derivation.stages[0]
    assert (d.chosen.d, d.chosen.a) == (9, 4)  # z_n/z_k = 13/4 − 1 = 9/4 (the book prints 1 − 13/4)
    assert d.chosen.y_min == 10
    # the book's list "k1 = 2, k2 = 5, k3 = 10, k4 = 13 …": the divisors of z_k·i = 40·13/4 = 130,
    # the planet counts the assembly condition (2.4) allows
    assert d.assembly_n == 130 and d.assembly_ks[:4] == (2, 5, 10, 13)
    assert d.neighbour_limit == 7 and d.k_max == 5
    codes = {n.code for n in r.notes}
    assert "book_printed_ok" in codes and "book_printed_wrong" not in codes
    assert r.checks.ok
    assert r.checks.velocity.ratio == pytest.approx(3.25, rel=1e-12)
    assert r.checks.ratio_formula_21_total == pytest.approx(3.25, rel=1e-12)


def test_default_crank_speed_is_the_books():
    r = design_gears(600)
    assert r.crank_rpm == 220 and r.crank_rpm_assumed
    assert any(n.code == "crank_default" for n in r.notes)


# ---------------------------------------------------------------- §2.5 double row


def test_book_2_5_double_row_carried_honestly():
    r = design_gears(600, 67, ratio=(53, 5))
    assert r.motor_rpm == 720 and r.scheme == "2"
    bad = [n for n in r.notes if n.code == "book_printed_wrong"]
    assert len(bad) == 1
    kw = bad[0].kwargs
    assert kw["teeth"] == "34/56/50/120" and (kw["lhs"], kw["rhs"]) == (90, 70)
    assert float(kw["ratio"]) == pytest.approx(1 + 56 * 120 / (34 * 50), abs=1e-3)
    assert not r.printed.coaxial_ok and not r.printed.ratio_ok
    d = r.derivation.stages[0]
    assert d.x1_range == (10, 23) and d.x2_range == (11, 25)  # the book's (corrected) ranges
    row10 = next(rw for rw in d.rows if rw.table == "2.3" and rw.x == 10)
    assert row10.teeth == (38, 76, 30, 144) and (row10.gamma1, row10.gamma2) == (190, 144)  # Table 2.3's printed row
    # the book's x2 = 12 set with z_k ≥ 17 kept: y_min = 3 (y = 2 gives the book's z_k = 14)
    row12 = next(rw for rw in d.rows if rw.table == "2.4x2" and rw.x == 12)
    assert row12.teeth == (21, 84, 75, 180)
    # every row realises 53/5 exactly and is coaxial
    for rw in d.rows:
        zk, zc, zc2, zn = rw.teeth
        assert zk + zc == zn - zc2
        assert (zk * zc2 + zc * zn) * 5 == 53 * zk * zc2
        assert zk >= 17 and zc >= 17 and zc2 >= 20 and zn >= 85
    # the carried design gives 53/5 exactly and is no larger than the procedure's best row
    pl = r.planetary
    assert pl.ratio == pytest.approx(53 / 5, rel=1e-12)
    assert pl.size <= d.chosen.size
    assert r.checks.ok


def test_assembly_exact_condition_admits_more_than_the_books_form():
    # 20/64/42/126 realises 53/5; z_k·i = 212 = 2²·53 (book: k = 2) but a double planet turned
    # by whole teeth fits 3 (k·gcd(64, 42) = 6 divides 20·42 + 64·126 = 8904)
    r = design_gears(600, 67, ratio=(53, 5))
    c = r.checks.stages[0]
    if c.stage.teeth == (20, 64, 42, 126):
        assert c.k_max == 3 and c.k_max_book == 2
        assert any(n.code == "assembly_forms_differ" for n in r.notes)


# ---------------------------------------------------------------- seed 000: involute helpers


def test_seed000_shifted_planetary_example():
    aw12 = working_angle(30, 48, -0.4 + 0.4)
    assert math.degrees(aw12) == pytest.approx(20.0, abs=1e-12)
    assert centre_distance_mm(5, 30, 48, aw12) == pytest.approx(195.0, abs=1e-9)
    aw34, xs = shift_sum_for_distance(5, 48, 27, 195.0)
    assert math.degrees(aw34) == pytest.approx(25.371, abs=5e-4)
    assert xs == pytest.approx(1.7, abs=5e-3)
    assert xs - 0.4 == pytest.approx(1.3, abs=5e-3)


@pytest.mark.parametrize("deg", [0.5, 5, 20, 25.371, 45, 70, 85])
def test_inv_inverse_round_trip(deg):
    a = math.radians(deg)
    assert inv_inverse(inv(a)) == pytest.approx(a, rel=1e-12)
