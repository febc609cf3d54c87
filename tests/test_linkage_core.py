"""The slotted-link (Whitworth) mechanism, seed 003: acceptance numbers, finite differences,
loop closure, both regimes, the article's closed forms (1)–(5) as a cross-check, the plans,
properties over random geometries, and bad geometry."""

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from tmm_cli.errors import TmmError
from tmm_cli.linkage.analysis import analyse
from tmm_cli.linkage.geometry import make_geometry, positions
from tmm_cli.linkage.kinematics import motion, transfer
from tmm_cli.linkage.plans import plans

ACCEPT = dict(r1=0.10, h=0.04, c=0.0, r2=0.08, r3=0.30, b=-0.04)  # the true Whitworth
SHAPER = dict(r1=0.10, h=0.30, c=0.0, r2=0.50, r3=0.20, b=0.22)  # a crank-shaper, c = 0
SHAPER_OFFSET = dict(r1=0.08, h=0.25, c=0.05, r2=0.45, r3=0.25, b=0.15)
WHIT_OFFSET = dict(r1=0.10, h=0.05, c=0.03, r2=0.12, r3=0.35, b=0.02)
GEOMETRIES = [ACCEPT, SHAPER, SHAPER_OFFSET, WHIT_OFFSET]


def cross(p, q):
    return p[0] * q[1] - p[1] * q[0]


def geom(d):
    return make_geometry(d["r1"], d["h"], d["c"], d["r2"], d["r3"], d["b"])


# --- acceptance numbers ------------------------------------------------------------------------


def test_acceptance_whitworth_time_ratio_and_stroke():
    r = analyse(geom(ACCEPT), omega=2 * math.pi)
    alpha = math.asin(0.04 / 0.10)
    assert r.regime == "whitworth"
    assert r.time_ratio == pytest.approx((math.pi + 2 * alpha) / (math.pi - 2 * alpha), rel=1e-12)
    assert round(r.time_ratio, 6) == 1.709953
    assert r.stroke == pytest.approx(0.16, abs=1e-12)
    # dead positions: the link horizontal, A at y = −h: φ21 = 90° + α (x_C max), 270° − α (x_C min)
    assert sorted(math.degrees(x) for x in r.dead) == pytest.approx(
        [90 + math.degrees(alpha), 270 - math.degrees(alpha)], abs=1e-9)
    assert math.degrees(r.working_rad) == pytest.approx(180 + 2 * math.degrees(alpha), abs=1e-9)
    assert r.positions[0].v_c == pytest.approx(0.0, abs=1e-12)
    assert r.positions[0].x_c == pytest.approx(r.x_min if r.working_direction > 0 else r.x_max, abs=1e-15)


@pytest.mark.parametrize("r2, r3", [(0.05, 0.2), (0.08, 0.30), (0.15, 0.6)])
def test_whitworth_guide_through_pivot(r2, r3):
    """Guide through O41 (b = −h, c = 0): B turns on a circle about the guide, H = 2·r2, K as above."""
    r1, h = 0.12, 0.05
    r = analyse(make_geometry(r1, h, 0.0, r2, r3, -h), omega=3.0)
    a = math.asin(h / r1)
    assert r.stroke == pytest.approx(2 * r2, abs=1e-12)
    assert r.time_ratio == pytest.approx((math.pi + 2 * a) / (math.pi - 2 * a), rel=1e-12)


@pytest.mark.parametrize("r1, h", [(0.10, 0.30), (0.05, 0.40), (0.2, 0.25)])
def test_crank_shaper_closed_forms(r1, h):
    """Crank-shaper, c = 0: dead positions with the crank ⊥ the link, K = (π + 2β)/(π − 2β), β = asin(r1/h);
    B's two extremes lie at the same height, so H = 2·r2·sin β."""
    r2 = h + r1 + 0.1
    b = -h + r2 + 0.01
    r = analyse(make_geometry(r1, h, 0.0, r2, 1.0, b), omega=4.0)  # a long rod: the ram turns with the link
    beta = math.asin(r1 / h)
    assert r.regime == "crank_shaper"
    assert r.time_ratio == pytest.approx((math.pi + 2 * beta) / (math.pi - 2 * beta), rel=1e-12)
    assert r.stroke == pytest.approx(2 * r2 * r1 / h, rel=1e-12)
    assert r.stationary == 2
    for s in r.positions:  # the link never leaves its swing
        assert abs(s.link) <= beta + 1e-12


# --- finite differences ------------------------------------------------------------------------


def _fd_check(g, omega, eps, n=1441, dt_rad=1e-3):
    """Central differences in time (five-point stencil) of the positions against the analytic ω, ε,
    v, a: agreement to 1e-6 of the largest value over the cycle."""
    phi0 = np.linspace(0.0, 2 * math.pi, n)
    dt = dt_rad / omega
    # φ(t0 + k·dt) for k = −2 … 2, the crank accelerating at ε
    pos = {k: positions(g, phi0 + omega * k * dt + 0.5 * eps * (k * dt) ** 2) for k in (-2, -1, 0, 1, 2)}
    m = motion(transfer(g, pos[0]), omega, eps)
    pairs = [
        ("link", m.omega_link, m.eps_link),
        ("rho", m.v_rel, m.a_rel),
        ("x_c", m.v_c, m.a_c),
        ("psi", m.omega_rod, m.eps_rod),
    ]
    for name, vel, acc in pairs:
        f = {k: getattr(p, name) for k, p in pos.items()}
        if name == "link":  # bring every shifted angle onto the branch of the unshifted one
            f = {k: x + np.round((f[0] - x) / (2 * math.pi)) * 2 * math.pi for k, x in f.items()}
        v_fd = (-f[2] + 8 * f[1] - 8 * f[-1] + f[-2]) / (12 * dt)
        a_fd = (-f[2] + 16 * f[1] - 30 * f[0] + 16 * f[-1] - f[-2]) / (12 * dt * dt)
        assert np.max(np.abs(v_fd - vel)) <= 1e-6 * np.max(np.abs(vel)), name
        assert np.max(np.abs(a_fd - acc)) <= 1e-6 * np.max(np.abs(acc)), name


@pytest.mark.parametrize("d", GEOMETRIES)
@pytest.mark.parametrize("omega, eps", [(2 * math.pi, 0.0), (15.0, 0.0), (6.0, 25.0), (3.0, -8.0)])
def test_velocities_accelerations_agree_with_finite_differences(d, omega, eps):
    _fd_check(geom(d), omega, eps)


def test_coriolis_is_twice_omega_times_sliding_velocity():
    g = geom(ACCEPT)
    m = motion(transfer(g, positions(g, np.linspace(0, 6, 50))), 7.0)
    assert np.allclose(m.a_cor, 2 * m.omega_link * m.v_rel, rtol=0, atol=1e-15)


# --- loop closure, recomputed here -------------------------------------------------------------


@pytest.mark.parametrize("d", GEOMETRIES)
def test_loop_closure_below_1e_12(d):
    g = geom(d)
    r = analyse(g, omega=5.0, n_positions=24)
    o41 = np.array([-g.c, -g.h])
    for s in (*r.positions, r.at, r.dead_state):
        a = np.array([g.r1 * math.sin(s.phi), g.r1 * math.cos(s.phi)])
        u = np.array([math.sin(s.link), math.cos(s.link)])
        b = o41 + g.r2 * u
        c = np.array([s.x_c, g.b])
        assert np.linalg.norm(o41 + s.rho * u - a) < 1e-12  # loop 1: O21A = O21O41 + O41A
        assert np.allclose(s.a, a, atol=1e-15) and np.allclose(s.b, b, atol=1e-15)
        assert abs(np.linalg.norm(b - c) - g.r3) < 1e-12  # loop 2: |BC| = r3 with C on y = b
        assert c[0] < b[0]  # C left of B, as the article draws it
    assert r.residual < 1e-12


# --- the article's closed forms (seed 003, eqs. (1)–(5)) as an independent cross-check ---------


def article(d, phi, omega):
    """Eqs. (3), (4), (5) of Goban, Monková, Šmeringaiová, typed in literally (arctg, uniform crank).

    In (5) the factor printed as "I" is 1 (differentiating (4) gives r2·r3²·sin²(arctg K)/(√(r3² − L²))³)."""
    r1, h, c, r2, r3, b = (d[k] for k in ("r1", "h", "c", "r2", "r3", "b"))
    s, co = math.sin(phi), math.cos(phi)
    K = (c + r1 * s) / (h + r1 * co)
    at = math.atan(K)
    L = b - r2 * math.cos(at) + h
    M = (r1 + h * co + c * s) / (h + r1 * co) ** 2
    root = math.sqrt(r3 ** 2 - L ** 2)
    x_c = r2 * math.sin(at) - c - root  # (3)
    v_c = omega * r1 * r2 * (M / (1 + K ** 2)) * (math.cos(at) + math.sin(at) * L / root)  # (4)
    first = ((c * co - h * s) * (h + r1 * co) + 2 * r1 * s * (r1 + h * co + c * s)) / (h + r1 * co) ** 3 \
        - 2 * K * M ** 2 * r1 / (1 + K ** 2)
    second = -math.sin(at) + math.cos(at) * L / root + r2 * r3 ** 2 * math.sin(at) ** 2 * 1 / root ** 3
    a_c = r1 * r2 * omega ** 2 / (1 + K ** 2) * (first * (math.cos(at) + math.sin(at) * L / root)
                                                 + r1 * M ** 2 / (1 + K ** 2) * second)  # (5)
    return x_c, v_c, a_c


@pytest.mark.parametrize("d", GEOMETRIES)
def test_article_closed_forms_agree_where_valid(d):
    g = geom(d)
    omega = 5.0  # the article's ω21
    checked = 0
    for deg in np.arange(0.0, 360.0, 7.5):
        phi = math.radians(deg)
        if d["h"] + d["r1"] * math.cos(phi) <= 1e-3:
            continue  # arctg puts the link on the wrong side there
        p = positions(g, phi)
        m = motion(transfer(g, p), omega)
        x_c, v_c, a_c = article(d, phi, omega)
        assert float(p.x_c) == pytest.approx(x_c, abs=1e-12)
        assert float(m.v_c) == pytest.approx(v_c, abs=1e-11)
        assert float(m.a_c) == pytest.approx(a_c, abs=1e-9)
        checked += 1
    assert checked >= 20


def test_article_arctg_is_wrong_where_h_plus_r1_cos_negative():
    """For the Whitworth mechanism at φ21 = 160° the arctg form points the link up; it points down."""
    phi = math.radians(160.0)
    x_art, _, _ = article(ACCEPT, phi, 5.0)
    p = positions(geom(ACCEPT), phi)
    a = np.array(p.a)
    u = np.array([math.sin(float(p.link)), math.cos(float(p.link))])
    assert np.dot(a - np.array([0.0, -0.04]), u) > 0  # the link points from O41 towards the block
    assert 90.0 < math.degrees(float(p.link)) < 180.0
    assert abs(float(p.x_c) - x_art) > 0.05  # the arctg form puts B on the other side of O41


# --- the plans ----------------------------------------------------------------------------------


@pytest.mark.parametrize("d", GEOMETRIES)
@pytest.mark.parametrize("deg, eps", [(45.0, 0.0), (170.0, 0.0), (300.0, 12.0)])
def test_plans_close_and_directions(d, deg, eps):
    g = geom(d)
    phi, omega = math.radians(deg), 6.0
    pl = plans(g, phi, omega, eps)
    p = positions(g, phi)
    m = motion(transfer(g, p), omega, eps)
    v, a = pl.velocity, pl.acceleration
    u = np.array([math.sin(float(p.link)), math.cos(float(p.link))])
    rod = np.array(p.b) - np.array([float(p.x_c), g.b])
    # velocity plan: pa2 ⊥ O21A, a2a4 ∥ link, pa4 ⊥ link, pc ∥ guide, bc ⊥ BC; lengths
    assert abs(np.dot(v.vector("p", "a2"), p.a)) < 1e-12
    assert abs(cross(v.vector("a2", "a4"), u)) < 1e-12
    assert abs(np.dot(v.vector("p", "a4"), u)) < 1e-12
    assert abs(np.dot(v.vector("b", "c"), rod)) < 1e-12
    assert v.points["c"][1] == 0.0 and v.points["c"][0] == pytest.approx(float(m.v_c), abs=1e-15)
    assert v.length("p", "a2") == pytest.approx(omega * g.r1, rel=1e-12)
    assert v.length("a2", "a4") == pytest.approx(abs(float(m.v_rel)), abs=1e-12)
    # acceleration plan: both routes to a4 meet; Coriolis length; directions of the components
    n4_route = np.add(a.points["n4"], a.vector("n4", "a4"))
    assert np.allclose(n4_route, a.points["a4"], atol=1e-12)
    assert abs(np.dot(a.vector("n4", "a4"), u)) < 1e-9  # tangential ⊥ link
    assert abs(cross(a.vector("k", "a4"), u)) < 1e-12  # relative ∥ link
    assert abs(np.dot(a.vector("a2", "k"), u)) < 1e-12  # Coriolis ⊥ link
    assert a.length("a2", "k") == pytest.approx(abs(float(m.a_cor)), abs=1e-12)
    tangential = g.r1 * abs(eps)
    assert a.length("n1", "a2") == pytest.approx(tangential, abs=1e-12)
    # n4a4 is ε4·ρ: the link's angular acceleration read off the plan
    assert a.length("n4", "a4") == pytest.approx(abs(float(m.eps_link)) * float(p.rho), rel=1e-9, abs=1e-12)
    assert abs(np.dot(a.vector("n5", "c"), rod)) < 1e-9
    assert a.points["c"][1] == 0.0 and a.points["c"][0] == pytest.approx(float(m.a_c), abs=1e-15)
    # the plan's c closes: b + bn5 + n5c
    assert np.allclose(np.add(a.points["b"], a.vector("b", "c")), a.points["c"], atol=1e-12)
    assert abs(np.add(a.points["n5"], a.vector("n5", "c"))[1]) < 1e-9


# --- properties over random feasible geometries --------------------------------------------------


@st.composite
def feasible(draw):
    r1 = draw(st.floats(0.02, 0.3))
    whit = draw(st.booleans())
    if whit:
        d0 = r1 * draw(st.floats(0.1, 0.85))
    else:
        d0 = r1 * draw(st.floats(1.2, 5.0))
    ang = draw(st.floats(-0.6, 0.6))  # direction of O41 from O21, below it
    h, c = d0 * math.cos(ang), d0 * math.sin(ang)
    r2 = draw(st.floats(0.3, 2.0)) * r1 if whit else (d0 + r1) * draw(st.floats(1.0, 1.6))
    b = -h + draw(st.floats(-1.2, 1.2)) * r2
    r3 = draw(st.floats(1.1, 3.0)) * (abs(b + h) + r2)  # reaches the guide, rod angle below ~65°
    omega = draw(st.floats(0.5, 100.0))
    return dict(r1=r1, h=h, c=c, r2=r2, r3=r3, b=b), omega


@settings(max_examples=40, deadline=None)
@given(feasible())
def test_property_random_geometries(case):
    d, omega = case
    g = geom(d)
    assume(g.rod_reach() < 0.9 * g.r3)
    _fd_check(g, omega, 0.0, n=181)
    r = analyse(g, omega, n_positions=12)
    assert r.residual < 1e-12
    assert r.time_ratio >= 1.0
    assert r.working_rad + r.return_rad == pytest.approx(2 * math.pi, abs=1e-12)
    assert r.stroke > 0 and r.stroke == pytest.approx(r.x_max - r.x_min)
    assert np.all(r.curve.x_c <= r.x_max + 1e-12) and np.all(r.curve.x_c >= r.x_min - 1e-12)
    scale = float(np.max(np.abs(r.curve.v_c)))
    assert abs(r.positions[0].v_c) <= 1e-9 * scale and abs(r.dead_state.v_c) <= 1e-9 * scale
    assert r.regime == ("whitworth" if math.hypot(d["c"], d["h"]) < d["r1"] else "crank_shaper")


# --- bad geometry -------------------------------------------------------------------------------


@pytest.mark.parametrize("over, words", [
    (dict(r1=0.0), ["--r1", "positive"]),
    (dict(r1=-0.1), ["--r1", "positive"]),
    (dict(h=0.0), ["--h", "positive"]),
    (dict(r2=-1.0), ["--r2", "positive"]),
    (dict(r3=0.0), ["--r3", "positive"]),
    (dict(h=0.10), ["passes through", "O41"]),
    (dict(h=0.06, c=0.08), ["passes through"]),
    (dict(h=0.30, r2=0.35), ["block leaves", "--r2", "0.4"]),
    (dict(r3=0.05), ["rod cannot reach", "--r3"]),
    (dict(b=0.5), ["rod cannot reach"]),
    (dict(r1=float("nan")), ["--r1"]),
])
def test_bad_geometry(over, words):
    d = dict(ACCEPT, **over)
    with pytest.raises(TmmError) as e:
        geom(d)
    msg = str(e.value)
    assert "\n" not in msg
    for w in words:
        assert w in msg, (w, msg)


def test_rod_exactly_across_the_guide_is_refused():
    # |b − y_B| reaches r3 exactly: the ram's speed would be infinite
    d = dict(ACCEPT, b=0.0, r3=0.12)  # y_B ∈ [−0.12, 0.04]
    with pytest.raises(TmmError):
        geom(d)


@pytest.mark.parametrize("kw, word", [(dict(omega=0.0), "crank speed"), (dict(omega=-3.0), "crank speed"),
                                      (dict(omega=1.0, n_positions=1), "--positions"),
                                      (dict(omega=1.0, at_deg=float("inf")), "--at"),
                                      (dict(omega=1.0, eps=float("nan")), "--eps-crank")])
def test_bad_motion_input(kw, word):
    with pytest.raises(TmmError) as e:
        analyse(geom(ACCEPT), **kw)
    assert word in str(e.value)


def test_notes_both_regimes_and_warnings():
    codes = {n.code for n in analyse(geom(ACCEPT), 1.0).notes}
    assert codes == {"linkage_whitworth"}
    codes = {n.code for n in analyse(geom(SHAPER), 1.0, eps=2.0).notes}
    assert codes == {"linkage_crank_shaper", "linkage_eps"}
    steep = make_geometry(0.10, 0.04, 0.0, 0.08, 0.13, 0.0)  # rod nearly across the guide
    assert "linkage_rod_angle" in {n.code for n in analyse(steep, 1.0).notes}
    near = make_geometry(0.10, 0.095, 0.0, 0.08, 0.30, -0.04)  # O41 just inside the crank circle
    assert "linkage_near_pivot" in {n.code for n in analyse(near, 1.0).notes}
