"""The blocking-contour lines (gears/blocking.py): verdicts on known pairs, the books' values
(seed 001: z_min = 17 and ε_α ≥ 1.2; seed 002: the tip thicknesses of its pair 20/25), and every
line's verdict over many pairs against the pair's geometry written out here (`pair`), not against
blocking.py's own rules."""

import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from tmm_cli.errors import TmmError

from tmm_cli.gears.blocking import EPS_HARD, EPS_MIN, SA_MIN_FACTOR, check_neighbours, check_pair
from tmm_cli.gears.shifted import pair_geometry


def test_limits_are_the_stated_ones():
    assert (SA_MIN_FACTOR, EPS_MIN, EPS_HARD) == (0.25, 1.2, 1.05)


def test_small_zero_pinion_is_undercut_and_interferes():
    c = check_pair(pair_geometry(10, 40, 5, 0.0, 0.0))
    assert c.undercut == (True, False) and c.interference == (True, False) and not c.ok
    # the undercut limit shift cures both
    x = (17 - 10) / 17
    c = check_pair(pair_geometry(10, 40, 5, x, -x))
    assert c.undercut == (False, False) and c.interference == (False, False)


ALPHA = math.radians(20)


def inv(a):
    return math.tan(a) - a


def pair(z1, z2, m, x1, x2):
    """The pair's geometry by the standard formulas (rack h_a* = 1, c* = 0.25, α = 20°), for the
    checks: per gear the tip thickness s_a [mm], the exact undercut limit x ≥ 1 − z·sin²α/2 (the
    rack's tip line through the limit point N), the roll length of the involute's lower limit
    point ρ_l = r·sin α − (1 − x)·m/sin α and of the lowest contact point (where the mate's tip
    circle cuts the line of action) [mm]; and ε_α."""
    target = 2 * (x1 + x2) * math.tan(ALPHA) / (z1 + z2) + inv(ALPHA)
    aw = ALPHA
    for _ in range(60):  # Newton: d(inv α)/dα = tg²α
        aw -= (inv(aw) - target) / math.tan(aw) ** 2
    a = m * (z1 + z2) / 2
    a_w = a * math.cos(ALPHA) / math.cos(aw)
    dy = x1 + x2 - (a_w - a) / m
    out = []
    for z, x in ((z1, x1), (z2, x2)):
        r = m * z / 2
        rb, ra = r * math.cos(ALPHA), m * (z / 2 + 1 + x - dy)
        s = m * (math.pi / 2 + 2 * x * math.tan(ALPHA))
        aa = math.acos(rb / ra)
        out.append({"sa": 2 * ra * (s / (2 * r) + inv(ALPHA) - inv(aa)), "x_exact": 1 - z * math.sin(ALPHA) ** 2 / 2,
                    "rho_l": r * math.sin(ALPHA) - (1 - x) * m / math.sin(ALPHA), "roll_tip": math.sqrt(ra * ra - rb * rb)})
    line = a_w * math.sin(aw)
    out[0]["low"], out[1]["low"] = line - out[1]["roll_tip"], line - out[0]["roll_tip"]
    eps = (out[0]["roll_tip"] + out[1]["roll_tip"] - line) / (math.pi * m * math.cos(ALPHA))
    return out, eps


def test_tip_thickness_of_seed_002s_pair():
    """Seed 002, Table 1: z = 20/25, m = 2 mm, x = 0: s_a = 1,390 and 1,440 mm."""
    g = pair_geometry(20, 25, 2, 0.0, 0.0)
    assert g.sa_mm == pytest.approx((1.390, 1.440), abs=1e-3)
    assert [p["sa"] for p in pair(20, 25, 2, 0.0, 0.0)[0]] == pytest.approx((1.390, 1.440), abs=1e-3)
    assert check_pair(g).pointed == (False, False)


def test_undercut_begins_below_the_books_z_min_17():
    """Seed 001, §2: a zero gear of fewer than z_min = 17 teeth is undercut (16 is, 17 is not), and
    the shift x_min = (17 − z)/17 cures it (x = 0.4 for 10 teeth is still short of 7/17 = 0.41)."""
    assert check_pair(pair_geometry(17, 40, 5, 0.0, 0.0)).undercut == (False, False)
    assert check_pair(pair_geometry(16, 40, 5, 0.0, 0.0)).undercut == (True, False)
    assert check_pair(pair_geometry(40, 16, 5, 0.0, 0.0)).undercut == (False, True)
    assert check_pair(pair_geometry(10, 40, 5, 0.40, 0.0)).undercut == (True, False)
    assert check_pair(pair_geometry(10, 40, 5, 0.42, 0.0)).undercut == (False, False)


def test_contact_ratio_line_is_the_books_1_2():
    """Seed 001, §2.3: ε_α ≥ 1.2 is recommended; 1.05 is the program's hard limit."""
    near = [(z, x) for z in (12, 14, 17) for x in (0.5, 0.7, 0.9, 1.1)]
    seen = set()
    for z, x in near:
        try:
            g = pair_geometry(z, z, 5, x, x)
        except TmmError:
            continue
        _, eps = pair(z, z, 5, x, x)
        c = check_pair(g)
        assert c.eps_alpha == pytest.approx(eps, rel=1e-9)
        assert c.eps_ok == (eps >= 1.2) and c.eps_hard_ok == (eps >= 1.05)
        seen.add(c.eps_ok)
    assert seen == {True, False}


def test_thin_tip_and_the_limit_in_mm():
    g = pair_geometry(12, 30, 5, 0.9, 0.0)
    c = check_pair(g)
    sa = pair(12, 30, 5, 0.9, 0.0)[0][0]["sa"]
    assert g.sa_mm[0] == pytest.approx(sa, rel=1e-9)
    assert 0 < sa < 0.25 * 5 and c.pointed == (True, False)
    line = next(k for k in c.checks if k.code == "tip_thickness" and k.gear == 1)
    assert line.limit == 1.25 and not line.ok


def test_contact_ratio_hard_limit():
    c = check_pair(pair_geometry(17, 20, 20, 2.0, 2.0))
    line = next(k for k in c.checks if k.code == "eps_alpha")
    assert c.eps_alpha < 1.05 and line.hard and not c.eps_hard_ok
    c = check_pair(pair_geometry(17, 20, 20, 0.0, 0.0))
    assert c.eps_ok and c.ok


def test_neighbours_with_real_tip_circles():
    ok = check_neighbours(195.0, 3, 252.0)
    assert ok.ok and math.isclose(ok.limit, 2 * 195 * math.sin(math.pi / 3))
    assert not check_neighbours(195.0, 5, 252.0).ok  # 2·195·sin 36° = 229.2
    assert check_neighbours(195.0, 1, 1e6).ok  # one planet has no neighbours


@settings(max_examples=120, deadline=None)
@given(st.integers(18, 150), st.integers(18, 150))
def test_zero_pairs_of_18_teeth_or_more_pass_every_line(z1, z2):
    c = check_pair(pair_geometry(z1, z2, 4, 0.0, 0.0))
    assert c.ok, [k for k in c.checks if not k.ok]


@settings(max_examples=150, deadline=None)
@given(st.integers(8, 80), st.integers(8, 80), st.floats(-0.8, 1.0), st.floats(-0.8, 1.0))
def test_every_line_against_the_geometry(z1, z2, x1, x2):
    """Each verdict from the pair's geometry written out above: undercut where x is below the
    exact limit 1 − z·sin²α/2 (the book rounds z_min = 17.1 to 17: between the two limits, a band
    of 0.0003·z, the verdict is the book's); a thin tip where s_a < 0.25·m; interference where the
    lowest contact point lies below the involute's limit point (or behind N); ε_α. Only the
    program's own refusal (TmmError: no such pair can be cut) is passed over; any other error fails."""
    m = 3
    try:
        g = pair_geometry(z1, z2, m, x1, x2)
    except TmmError:
        assume(False)
    c = check_pair(g)
    gears, eps = pair(z1, z2, m, x1, x2)
    assert c.eps_alpha == pytest.approx(eps, rel=1e-9, abs=1e-12)
    for j, (p, z, x) in enumerate(zip(gears, (z1, z2), (x1, x2))):
        book = (17 - z) / 17
        if not min(p["x_exact"], book) - 1e-9 <= x <= max(p["x_exact"], book) + 1e-9:
            assert c.undercut[j] == (x < p["x_exact"]), (j, x, p["x_exact"])
        else:
            assert c.undercut[j] == (x < book - 1e-9)
        assert g.sa_mm[j] == pytest.approx(p["sa"], rel=1e-9, abs=1e-9)
        if abs(p["sa"] - 0.25 * m) > 1e-6:
            assert c.pointed[j] == (p["sa"] < 0.25 * m), (j, p["sa"])
        limit = max(p["rho_l"], 0.0)
        if abs(p["low"] - limit) > 1e-6:
            assert c.interference[j] == (p["low"] < limit), (j, p["low"], limit)
