"""Shifted spur pairs (gears/shifted.py) checked independently of the code under test:

* α_w by bisection (not Newton) and a_w by the forward formula against the reverse one (x_Σ from a_w);
* zero backlash on the working circles, s_w1 + s_w2 = p_w, with s_y = 2r_y(s/d + inv α − inv α_y)
  written out here;
* ε_α against a geometric computation: the two tooth profiles are drawn as point sets, turned
  together by the ratio, and the turn of gear 1 during which one tooth pair really touches (the
  touching point lying on both drawn flanks) is measured and divided by the angular pitch;
* the fillet-interference line against the lower limit point found in Cartesian coordinates.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tmm_cli.errors import TmmError
from tmm_cli.gears.blocking import check_pair
from tmm_cli.gears.shifted import (
    auto_shift,
    pair_geometry,
    parse_shift,
    resolve_shift,
    shift_sum_for_distance,
    split_shift_sum,
    x_min_undercut,
)

ALPHA = math.radians(20.0)


def _inv(a):
    return math.tan(a) - a


def _alpha_w_bisection(z1, z2, x_sum):
    target = _inv(ALPHA) + 2 * x_sum * math.tan(ALPHA) / (z1 + z2)
    lo, hi = 1e-9, math.pi / 2 - 1e-9
    for _ in range(200):
        mid = (lo + hi) / 2
        if _inv(mid) < target:
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


GRID = [(z1, z2, x1, x2) for z1, z2 in ((12, 30), (17, 20), (17, 43), (24, 17), (30, 48), (48, 27), (20, 80))
        for x1, x2 in ((0.0, 0.0), (0.3, -0.3), (0.5, 0.2), (-0.2, 0.6), (0.4, 0.4))]


def _valid(z1, z2, x1, x2, m=5.0):
    try:
        g = pair_geometry(z1, z2, m, x1, x2)
    except TmmError:
        return None
    return g if min(g.sa_mm) > 0 else None


@pytest.mark.parametrize("z1,z2,x1,x2", GRID)
def test_alpha_w_and_a_w_forward_and_reverse(z1, z2, x1, x2):
    g = _valid(z1, z2, x1, x2)
    if g is None:
        pytest.skip("pointed")
    aw_b = _alpha_w_bisection(z1, z2, x1 + x2)
    assert math.isclose(math.radians(g.alpha_w_deg), aw_b, abs_tol=1e-12)
    m = 5.0
    a_w = m * (z1 + z2) / 2 * math.cos(ALPHA) / math.cos(aw_b)
    assert math.isclose(g.a_w_mm, a_w, rel_tol=1e-12)
    # the reverse formula: from a_w back to the shift sum and the angle
    alpha_w_deg, xs = shift_sum_for_distance(z1, z2, m, a_w)
    assert math.isclose(xs, x1 + x2, abs_tol=1e-9)
    assert math.isclose(alpha_w_deg, g.alpha_w_deg, abs_tol=1e-9)
    # item 11 of §2.3 extended to shifted gears: a_w = r_a1 + r_f2 + c*m, and y, Δy by definition
    assert math.isclose(g.da_mm[0] / 2 + g.df_mm[1] / 2 + 0.25 * m, a_w, rel_tol=1e-12)
    assert math.isclose(g.da_mm[1] / 2 + g.df_mm[0] / 2 + 0.25 * m, a_w, rel_tol=1e-12)
    assert math.isclose(g.y, (a_w - m * (z1 + z2) / 2) / m, abs_tol=1e-12)
    assert g.dy >= -1e-12  # the tip reduction is never negative for an external pair
    # working circles roll on each other
    assert math.isclose(g.dw_mm[0] / 2 + g.dw_mm[1] / 2, a_w, rel_tol=1e-12)
    assert math.isclose(g.dw_mm[1] / g.dw_mm[0], z2 / z1, rel_tol=1e-12)


@pytest.mark.parametrize("z1,z2,x1,x2", GRID)
def test_zero_backlash_on_the_working_circles(z1, z2, x1, x2):
    g = _valid(z1, z2, x1, x2)
    if g is None:
        pytest.skip("pointed")
    m = 5.0
    aw = math.radians(g.alpha_w_deg)
    sw = []
    for z, x in ((z1, x1), (z2, x2)):
        d = m * z
        s = m * (math.pi / 2 + 2 * x * math.tan(ALPHA))
        rw = d / 2 * math.cos(ALPHA) / math.cos(aw)
        sw.append(2 * rw * (s / d + _inv(ALPHA) - _inv(aw)))
    p_w = math.pi * m * math.cos(ALPHA) / math.cos(aw)
    assert math.isclose(sw[0] + sw[1], p_w, rel_tol=1e-10)
    assert math.isclose(g.sw_mm[0], sw[0], rel_tol=1e-10) and math.isclose(g.sw_mm[1], sw[1], rel_tol=1e-10)
    assert math.isclose(g.pw_mm, p_w, rel_tol=1e-12)


# ----------------------------------------------------------------------------------------------
# ε_α from drawn profiles


def _flank(z, m, x, r_lo, r_hi, n):
    """Polar samples (ρ, half-angle ψ(ρ)) of one flank of a rack-cut gear, drawn from its involute."""
    r = m * z / 2
    rb = r * math.cos(ALPHA)
    s = m * (math.pi / 2 + 2 * x * math.tan(ALPHA))
    rho = np.linspace(max(r_lo, rb), r_hi, n)
    a = np.arccos(np.clip(rb / rho, -1, 1))
    return rho, s / (2 * r) + _inv(ALPHA) - (np.tan(a) - a)


def _touch(phi1, g, m, n=20000):
    """Turn gear 1 by φ1 (ccw) and gear 2 by −φ1·z1/z2; return the radii (on gear 1, on gear 2) of the
    point where the left flank of gear 1's tooth 0 touches the facing flank of gear 2 (both flanks
    drawn past their tips so the touching point always exists), and the touching gap [mm]."""
    z1, z2 = g.z
    aw = g.a_w_mm
    ra1, ra2 = g.da_mm[0] / 2, g.da_mm[1] / 2
    rho2, psi2 = _flank(z2, m, g.x[1], 0, ra2 + m, n)
    tau2 = 2 * math.pi / z2
    th2 = -math.pi / 2 - tau2 / 2 + psi2 - phi1 * z1 / z2  # gear 2's tooth left of the space on the centre line
    wx, wy = rho2 * np.cos(th2), aw + rho2 * np.sin(th2)
    rho1 = np.hypot(wx, wy)
    th_w = np.arctan2(wy, wx)
    rb1 = m * z1 / 2 * math.cos(ALPHA)
    ok = (rho1 >= rb1) & (rho1 <= ra1 + m)
    a1 = np.arccos(np.clip(rb1 / np.where(ok, rho1, rb1), -1, 1))
    s1 = m * (math.pi / 2 + 2 * g.x[0] * math.tan(ALPHA))
    psi1 = s1 / (m * z1) + _inv(ALPHA) - (np.tan(a1) - a1)
    gap = (th_w - (math.pi / 2 + phi1 + psi1) + math.pi) % (2 * math.pi) - math.pi
    gap = np.where(ok, gap * rho1, np.inf)
    k = int(np.argmin(np.abs(gap)))
    return rho1[k], rho2[k], gap[k]


def _in_contact(phi1, g, m):
    r1, r2, gap = _touch(phi1, g, m)
    return abs(gap) < 1e-3 * m and r1 <= g.da_mm[0] / 2 and r2 <= g.da_mm[1] / 2


def _eps_geometric(g, m):
    tau1 = 2 * math.pi / g.z[0]
    phis = np.linspace(-2.5 * tau1, 2.5 * tau1, 126)
    flags = [_in_contact(p, g, m) for p in phis]
    idx = [i for i, f in enumerate(flags) if f]
    assert idx and idx[0] > 0 and idx[-1] < len(phis) - 1
    assert idx == list(range(idx[0], idx[-1] + 1))  # one contiguous stretch

    def edge(inside, outside):
        for _ in range(45):
            mid = (inside + outside) / 2
            if _in_contact(mid, g, m):
                inside = mid
            else:
                outside = mid
        return (inside + outside) / 2

    start = edge(phis[idx[0]], phis[idx[0] - 1])
    end = edge(phis[idx[-1]], phis[idx[-1] + 1])
    return (end - start) / tau1


@pytest.mark.parametrize("z1,z2,x1,x2", [(17, 20, 0.0, 0.0), (30, 48, -0.4, 0.4), (48, 27, 0.4, 1.3003942),
                                         (12, 30, 0.3, 0.2), (24, 17, 0.5, 0.3), (20, 80, 0.5, -0.5)])
def test_eps_alpha_from_drawn_profiles(z1, z2, x1, x2):
    m = 5.0
    g = pair_geometry(z1, z2, m, x1, x2)
    eps = _eps_geometric(g, m)
    assert math.isclose(eps, g.eps_alpha, abs_tol=2e-4), (eps, g.eps_alpha)


# ----------------------------------------------------------------------------------------------
# the involute's lower limit point (fillet interference), in Cartesian coordinates


@pytest.mark.parametrize("z1,z2,x1,x2", GRID)
def test_interference_line_in_cartesian_form(z1, z2, x1, x2):
    g = _valid(z1, z2, x1, x2)
    if g is None:
        pytest.skip("pointed")
    m = 5.0
    for j, (z, x) in enumerate(((z1, x1), (z2, x2))):
        r = m * z / 2
        h = (1.0 - x) * m  # the rack's straight flank ends this far inside the pitch circle
        # the generating pole is (0, r); the end of the straight flank on the generating line is at depth h
        p = np.array([-h / math.tan(ALPHA), r - h])
        r_limit = float(np.hypot(*p))
        rb = r * math.cos(ALPHA)
        rho_l = g.rho_l_mm[j]
        if rho_l >= 0:
            assert math.isclose(math.hypot(rb, rho_l), r_limit, rel_tol=1e-12)
        # the radius on this gear where the mate's tip circle cuts the line of action
        other = 1 - j
        ra_o, rb_o = g.da_mm[other] / 2, g.db_mm[other] / 2
        roll = g.n1n2_mm - math.sqrt(ra_o ** 2 - rb_o ** 2)
        r_contact = math.hypot(g.db_mm[j] / 2, roll)
        verdict = check_pair(g).interference[j]
        if abs(r_contact - r_limit) > 1e-6 and roll > 0 and rho_l > 0:
            assert verdict == (r_contact < r_limit)


# ----------------------------------------------------------------------------------------------
# the auto rule and the split


@settings(max_examples=150, deadline=None)
@given(st.integers(6, 150), st.integers(6, 150))
def test_auto_shift_removes_undercut_and_is_balanced(z1, z2):
    x1, x2 = auto_shift(z1, z2)
    assert x1 >= x_min_undercut(z1) - 1e-4 and x2 >= x_min_undercut(z2) - 1e-4
    if z1 + z2 >= 34:
        assert x1 + x2 == 0.0  # height-corrected: the centre distance stays a
        assert min(x1, x2) <= 0.0 <= max(x1, x2)
    else:
        assert x1 + x2 > 0
    if z1 >= 17 and z2 >= 17:
        assert (x1, x2) == (0.0, 0.0)  # the book's zero pair needs no shift


@settings(max_examples=60, deadline=None)
@given(st.integers(12, 60), st.integers(12, 60), st.floats(0.0, 0.25))
def test_split_reaches_the_required_distance(z1, z2, extra_mm_per_m):
    m = 4.0
    a = m * (z1 + z2) / 2
    a_w = a * (1 + extra_mm_per_m / 10)
    x1, x2, rule = resolve_shift(z1, z2, m, None, a_w)
    assert rule == "aw"
    g = pair_geometry(z1, z2, m, x1, x2)
    assert math.isclose(g.a_w_mm, a_w, rel_tol=1e-9)
    b1, b2 = auto_shift(z1, z2)
    assert math.isclose(x1 - b1, x2 - b2, abs_tol=1e-12)  # the difference is shared equally
    assert split_shift_sum(z1, z2, x1 + x2) == pytest.approx((x1, x2))


def test_parse_shift():
    assert parse_shift("auto") == "auto"
    assert parse_shift("0.5,-0.5") == (0.5, -0.5)
    for bad in ("", "0.5", "a,b", "1,2,3", "0,5,-0,5", "nan,0"):
        with pytest.raises(TmmError):
            parse_shift(bad)


def test_unreachable_distance_and_conflict():
    with pytest.raises(TmmError, match="cannot be reached"):
        resolve_shift(17, 20, 20, None, 340.0)  # below a·cos α = 347.7
    with pytest.raises(TmmError, match="give one of them"):
        resolve_shift(17, 20, 20, (0.1, 0.1), 380.0)
    assert resolve_shift(17, 20, 20, (0.2734, 0.2734), 380.0)[2] == "given"


def test_too_negative_shift_sum():
    with pytest.raises(TmmError, match="too negative"):
        pair_geometry(17, 20, 20, -3.0, -3.0)
