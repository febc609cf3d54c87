"""The blocking-contour lines (gears/blocking.py): verdicts on known pairs, the limits stated,
and properties over many pairs."""

import math

from hypothesis import given, settings
from hypothesis import strategies as st

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


def test_thin_tip_and_the_limit_in_mm():
    g = pair_geometry(12, 30, 5, 0.9, 0.0)
    c = check_pair(g)
    assert 0 < g.sa_mm[0] < 0.25 * 5 and c.pointed == (True, False)
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


@settings(max_examples=120, deadline=None)
@given(st.integers(8, 80), st.integers(8, 80), st.floats(-0.8, 1.0), st.floats(-0.8, 1.0))
def test_undercut_verdict_is_the_rounded_rule(z1, z2, x1, x2):
    try:
        g = pair_geometry(z1, z2, 3, x1, x2)
    except Exception:
        return
    c = check_pair(g)
    assert c.undercut == (x1 < (17 - z1) / 17 - 1e-9, x2 < (17 - z2) / 17 - 1e-9)
    assert c.pointed == (g.sa_mm[0] < 0.75 - 1e-9, g.sa_mm[1] < 0.75 - 1e-9)
