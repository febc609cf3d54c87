"""Sheet 2 (issue 25): the force analysis, Zhukovsky's lever, the dynamics and the flywheel.

Independent checks, not restatements: the balancing moment of the group-by-group force analysis
against the power balance computed from the kinematics alone; every link's equilibrium rebuilt from
the reactions; the crank-slider's and the four-bar's statics by hand; the work of a cycle against the
area of the load diagram; the reduced inertia against the inertia forces' power; the speed with the
flywheel keeping δ; random four-bars (hypothesis)."""

import dataclasses
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tmm_cli.errors import TmmError
from tmm_cli.linkage.chain import solve
from tmm_cli.linkage.forces import applied
from tmm_cli.linkage.loads import stroke_of
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.motion import cross
from linkage_check import assert_every_link_in_equilibrium
from tmm_cli.linkage.power import balancing_moment_by_power, reduced_inertia, total_power
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2
from tmm_cli.linkage.zhukovsky import lever

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
WITH_MASSES = ("compressor", "four_bar", "shaper")


def load(name):
    path = EXAMPLES / f"{name}.toml"
    return parse_mechanism(tomllib.loads(path.read_text(encoding="utf-8")), path.name)


_CACHE = {}


def sheet2(name):
    if name not in _CACHE:
        m = load(name)
        _CACHE[name] = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m, name))
    return _CACHE[name]


# --- the balancing moment three ways -----------------------------------------------------------


@pytest.mark.parametrize("name", WITH_MASSES)
def test_force_analysis_equals_power_balance_every_position(name):
    s = sheet2(name)
    mb = s.balancing
    scale = float(np.max(np.abs(mb)))
    assert scale > 1.0
    # the power balance from the kinematics alone, written out here: Σ(F·v + M·ω) + M_b·ω₁ = 0
    k = s.sheet1.cycle.kin
    power = np.zeros(len(mb))
    for f in s.loading.forces:
        v, _ = k.body_point(f.link, f.z)
        power += f.f.real * v.real + f.f.imag * v.imag
    for c in s.loading.couples:
        power += c.m * k.omega[c.link]
    assert np.max(np.abs(mb - (-power / k.omega1))) <= 1e-9 * scale
    assert np.max(np.abs(mb - s.power_balance)) <= 1e-9 * scale


@pytest.mark.parametrize("name", WITH_MASSES)
def test_zhukovsky_lever_gives_the_same_moment(name):
    s = sheet2(name)
    scale = float(np.max(np.abs(s.balancing)))
    assert np.max(np.abs(s.lever.balancing - s.balancing)) <= 1e-9 * scale
    assert np.max(np.abs(s.difference_pct())) < 1e-6
    # the lever is in equilibrium: the balancing force's moment about the pole cancels the rest
    k = s.sheet1.cycle.kin
    va = k.v[s.sheet1.mechanism.crank.joint]
    assert np.allclose(cross(1j * va, s.lever.balancing_force) + s.lever.moment_sum, 0.0, atol=1e-9 * scale * 100)


@pytest.mark.parametrize("name", WITH_MASSES)
def test_every_link_is_in_equilibrium_with_its_reactions(name):
    """Rebuild each link's free body from the reactions the analysis found: ΣF = 0 and ΣM = 0."""
    assert_every_link_in_equilibrium(sheet2(name), name)


def test_reaction_components_are_along_and_across_their_links():
    s = sheet2("four_bar")
    k = s.sheet1.cycle.kin
    r12, r03 = s.forces.reaction("R12"), s.forces.reaction("R03")
    ab, cb = k.z["B"] - k.z["A"], k.z["B"] - k.z["C"]
    for r, d in ((r12, ab), (r03, cb)):
        assert np.allclose(cross(d, r.normal), 0.0, atol=1e-9)
        assert np.allclose((np.conj(d) * r.tangential).real, 0.0, atol=1e-9)
        assert np.allclose(r.normal + r.tangential, r.force)


# --- statics by hand ----------------------------------------------------------------------------


def _crank_slider(r, l, force, working="towards"):
    return parse_mechanism({
        "frame": {"O": [0.0, 0.0]},
        "crank": {"pivot": "O", "joint": "A", "length": r, "rpm": 200},
        "group": [{"kind": "RRP", "joints": ["A", "B"], "length": l, "guide": {"through": [0.0, 0.0], "angle_deg": 0.0},
                   "branch": "ahead"}],
        "load": {"on": "B", "stroke": [0.0, 1.0], "force": [force, force], "working": working},
    })


def test_crank_slider_statics_by_hand():
    """Massless links, a constant force P on the slider's working stroke (towards the crank):
    the rod carries S = P/cos β and the crank needs M_b = P·r·sin(φ + β)/cos β against it."""
    r, l, p = 0.05, 0.2, 1000.0
    m = _crank_slider(r, l, p)
    s = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m))
    c = s.sheet1.cycle
    checked = 0
    for pos in c.positions:
        if pos.travel > c.working - 1e-9 or pos.travel < 1e-9:
            continue
        checked += 1
        phi = pos.phi
        beta = math.asin(-r * math.sin(phi) / l)  # the rod's angle to the guide, A above → B's rod points down
        mb = p * r * math.sin(phi - beta) / math.cos(beta)
        assert s.balancing[pos.index] == pytest.approx(mb, rel=1e-12, abs=1e-9)
        rod = s.forces.reaction("R23").force[pos.index]  # the rod on the slider
        assert abs(rod) == pytest.approx(p / math.cos(beta), rel=1e-12)
    assert checked == 5


def test_four_bar_rocker_moment_by_hand():
    """Massless links, a moment M on the rocker: the coupler is a two-force member along AB; the
    rocker's moment about C gives its force, the crank's moment about O the balancing moment."""
    m_free = parse_mechanism({**_strip(EXAMPLES / "four_bar.toml"), "mass": []})
    s = analyse_sheet2(analyse_mechanism(m_free), parse_sheet2(m_free))
    k = s.sheet1.cycle.kin
    mc = s.loading.couples[0].m
    u = (k.z["B"] - k.z["A"]) / np.abs(k.z["B"] - k.z["A"])
    size = -mc / cross(k.z["B"] - k.z["C"], -u)  # the coupler's pull −S·u on the rocker at B balances M
    on_crank = size * u  # the coupler on the crank at A
    mb = -cross(k.z["A"] - k.z["O"], on_crank)
    assert np.allclose(s.balancing, mb, rtol=1e-10, atol=1e-9)
    assert np.max(np.abs(mb)) > 1.0


def _strip(path):
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    data.pop("mass", None)
    return data


# --- the dynamics -------------------------------------------------------------------------------


def _table_area(stroke, values):
    return sum((b - a) * (fa + fb) / 2 for a, b, fa, fb in zip(stroke, stroke[1:], values, values[1:]))


@pytest.mark.parametrize("name", WITH_MASSES)
def test_cycle_work_balance(name):
    s = sheet2(name)
    d = s.dynamics
    ld = s.input.load
    c = s.sheet1.cycle
    area = _table_area(ld.stroke, ld.values)
    assert d.A_r[-1] == pytest.approx(-c.stroke * area, rel=1e-12)  # the weights give nothing back over a turn
    assert d.A_d[-1] + d.A_r[-1] == pytest.approx(0.0, abs=1e-9 * abs(d.A_r[-1]))
    assert d.dT[-1] == pytest.approx(0.0, abs=1e-9 * abs(d.A_r[-1]))
    # the reduced moment integrates to the same work (a quadrature over the 0.5° grid: jumps cost)
    from scipy.integrate import trapezoid  # numpy's is np.trapezoid from 2.0 only (the floor is 1.24)

    assert trapezoid(d.M_r, d.travel) == pytest.approx(d.A_r[-1], rel=1e-3)
    assert len(d.travel) >= 361 and d.travel[0] == 0.0 and d.travel[-1] == pytest.approx(2 * math.pi)


@pytest.mark.parametrize("name", WITH_MASSES)
def test_reduced_inertia_against_the_inertia_forces_power(name):
    """At a uniform crank the inertia forces' power is −dT/dt, so their reduced moment equals
    −(ω₁²/2)·dJ_r/dφ (central differences of J_r, computed independently)."""
    s = sheet2(name)
    m = s.sheet1.mechanism
    inp = s.input
    phi = np.linspace(0.1, 2 * math.pi, 40)
    h = 1e-5
    jr = [reduced_inertia(solve(m, phi + d), inp.masses) for d in (-h, h)]
    djr = (jr[1] - jr[0]) / (2 * h)
    k = solve(m, phi)
    p_inertia = total_power(k, applied(m, inp, stroke_of(s.sheet1.cycle), k), ("inertia",))
    w1 = m.crank.omega
    assert np.allclose(p_inertia / w1, -(w1 ** 2) / 2 * djr, rtol=1e-5, atol=1e-6 * np.max(np.abs(p_inertia / w1)))


@pytest.mark.parametrize("name", WITH_MASSES)
def test_flywheel_keeps_the_speed_within_delta(name):
    from tmm_cli.linkage.flywheel import speed

    s = sheet2(name)
    d, fw = s.dynamics, s.flywheel
    # Wittenbauer's flywheel holds ω between ω_max and ω_min exactly (to the grid)
    w = speed(d.dT, d.J_r, fw.wittenbauer.J_fl, d.omega_mean)
    assert (w.max() - w.min()) / d.omega_mean == pytest.approx(fw.delta, rel=1e-3)
    assert w.max() == pytest.approx(fw.omega_max, rel=1e-5) and w.min() == pytest.approx(fw.omega_min, rel=1e-5)
    # Mertsalov's neglects T_II's change with the speed: close to δ, not exact
    assert fw.delta_actual == pytest.approx(fw.delta, rel=0.05)
    assert fw.mertsalov.J_fl == pytest.approx(fw.wittenbauer.J_fl, rel=0.05)
    assert fw.size.J == fw.J == fw.mertsalov.J_fl > 0


def _speed_from_energy(dT, J_r, J, omega_m):
    """ω(φ) of the machine with a flywheel J, from its energy alone: T₀ + ΔT(φ) = (J + J_r(φ))·ω²/2,
    T₀ such that (ω_max + ω_min)/2 = ω_m (scipy's root finder; not :func:`flywheel.speed`)."""
    from scipy.optimize import brentq

    total = J + np.asarray(J_r)

    def omega(t0):
        return np.sqrt(2 * (t0 + np.asarray(dT)) / total)

    def off(t0):
        w = omega(t0)
        return (w.max() + w.min()) / 2 - omega_m

    lo = float(np.max(-np.asarray(dT)))
    t0 = brentq(off, lo, lo + float(np.max(total)) * omega_m ** 2 * 4 + 1.0, xtol=1e-14, rtol=1e-15)
    return omega(t0)


@pytest.mark.parametrize("name", WITH_MASSES)
def test_mertsalov_is_exact_as_delta_goes_to_zero(name):
    """Mertsalov takes T_II = J_II·ω²/2 at ω_m; the speed really swings by ±δ/2, so his flywheel is
    right to first order in δ: at δ = 0.002 the machine's speed with it, from its energy, swings by
    δ within 0.5 % (at the file's δ it is 0.5–2 % off, which is why the test above allows 5 %),
    and Wittenbauer's exact construction gives the same J within 0.5 %. (T_II = J_II·ω² would be
    1–40 % off here, whatever δ.)"""
    from tmm_cli.linkage.flywheel import flywheel

    s = sheet2(name)
    d = s.dynamics
    delta = 0.002
    fw = flywheel(d, dataclasses.replace(s.input.dynamics, delta=delta))
    assert fw.mertsalov.J_fl > 0
    w = _speed_from_energy(d.dT, d.J_r, fw.mertsalov.J_fl, d.omega_mean)
    assert (w.max() - w.min()) / d.omega_mean == pytest.approx(delta, rel=5e-3)
    assert fw.mertsalov.J_fl == pytest.approx(fw.wittenbauer.J_fl, rel=5e-3)


def test_mertsalov_by_hand_for_a_machine_that_does_no_work():
    """No work is done (ΔT = 0) but the second group's inertia swings, J_II = J₀ + a·cos φ: the
    first group's energy is ΔT_I = −a·cos φ·ω_m²/2, its swing a·ω_m², so J_I = a/δ. Check: the
    energy (J_I + J_II)·ω²/2 is constant, so ω ∝ (J_I + J_II)^(−1/2) swings by ≈ a/J_I = δ."""
    from tmm_cli.linkage.flywheel import mertsalov

    a, j0, w_m, delta = 0.3, 0.5, 12.0, 0.01
    phi = np.linspace(0, 2 * np.pi, 721)
    j_ii = j0 + a * np.cos(phi)
    me = mertsalov(np.zeros_like(phi), j_ii, w_m, delta, 1.0)
    assert me.J_I == pytest.approx(a / delta, rel=1e-12)
    assert me.J_fl == pytest.approx(a / delta - 1.0, rel=1e-12)
    w = _speed_from_energy(np.zeros_like(phi), me.J_I + j_ii, 0.0, w_m)
    assert (w.max() - w.min()) / w_m == pytest.approx(delta, rel=0.02)  # O(δ) + O(J₀/J_I)


def test_no_flywheel_needed_when_the_machine_is_heavy_enough():
    data = tomllib.loads((EXAMPLES / "four_bar.toml").read_text(encoding="utf-8"))
    data["dynamics"]["J_rotor"] = 100.0
    m = parse_mechanism(data, "x.toml")
    s = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m))
    assert s.flywheel.J == 0.0 and s.flywheel.size is None and s.flywheel.mertsalov.J_fl < 0
    assert s.flywheel.delta_actual < s.flywheel.delta
    assert "dynamics_no_flywheel" in [n.code for n in s.notes]


def test_motor_input_for_sheet_4():
    s = sheet2("shaper")
    moment, rpm = s.motor_input()
    assert moment == pytest.approx(abs(s.dynamics.M_d)) and moment > 0
    assert rpm == pytest.approx(60.0)
    assert s.dynamics.drive_moment_ccw < 0  # the shaper's crank turns clockwise


def test_polygons_close():
    for name in WITH_MASSES:
        s = sheet2(name)
        for pg in s.polygons:
            biggest = max(abs(v.value) for v in pg.vectors)
            assert abs(pg.closure) <= 1e-9 * biggest, (name, pg.group)
            assert max(abs(v.value) for v in pg.vectors) / pg.scale <= 100.0 + 1e-9


# --- random four-bars ---------------------------------------------------------------------------


@settings(max_examples=40, deadline=None)
@given(st.floats(0.04, 0.09), st.floats(0.25, 0.35), st.floats(0.15, 0.25), st.floats(0.5, 5.0), st.floats(0.5, 5.0),
       st.floats(0.0, 0.05), st.floats(-0.05, 0.05), st.floats(0.0, 50.0), st.sampled_from(["ccw", "cw"]))
def test_random_four_bars_three_ways(a, b, c, m2, m3, j3, across, moment, sense):
    d = 0.30
    if not (a + d <= b + c and a + min(b, c, d) <= max(b, c, d) and abs(b - c) + 0.02 < d - a and b + c - 0.02 > d + a):
        return
    data = {
        "frame": {"O": [0.0, 0.0], "C": [d, 0.0]},
        "crank": {"pivot": "O", "joint": "A", "length": a, "rpm": 150, "sense": sense},
        "group": [{"kind": "RRR", "joints": ["A", "B", "C"], "lengths": [b, c], "branch": "left"}],
        "point": [{"name": "S2", "link": ["A", "B"], "along": 0.4 * b, "across": across}],
        "gravity": True,
        "mass": [{"link": ["A", "B"], "m": m2, "J": 0.01, "centre": "S2"}, {"link": ["B", "C"], "m": m3, "J": j3}],
        "load": {"on": ["C", "B"], "stroke": [0.0, 0.5, 1.0], "moment": [0.0, moment, moment]},
    }
    m = parse_mechanism(data)
    try:
        s1 = analyse_mechanism(m)
    except TmmError:  # a dead point inside the turn: not a four-bar to analyse
        return
    s = analyse_sheet2(s1, parse_sheet2(m))
    scale = max(float(np.max(np.abs(s.balancing))), 1e-6)
    assert np.max(np.abs(s.balancing - s.power_balance)) <= 1e-9 * scale
    assert np.max(np.abs(s.lever.balancing - s.balancing)) <= 1e-9 * scale
    k = s1.cycle.kin
    assert np.allclose(lever(m, s.loading, k).balancing, balancing_moment_by_power(k, s.loading), atol=1e-9 * scale)


@pytest.mark.parametrize("name, couples", [("compressor", ["MΦ2"]), ("four_bar", ["MΦ2", "MΦ3", "Mc"]),
                                           ("shaper", ["MΦ3", "MΦ4"])])
def test_a_uniform_crank_has_no_inertia_moment(name, couples):
    """The crank turns at its mean speed (ε₁ = 0), so its inertia moment −J₁·ε₁ is zero and the
    loading (the tables, the plans of forces) leaves it out; every other link with J swings."""
    s = sheet2(name)
    assert [c.symbol for c in s.loading.couples] == couples
    assert all(np.max(np.abs(c.m)) > 0 for c in s.loading.couples)


@pytest.mark.parametrize("name", WITH_MASSES)
def test_the_energy_diagram_fits_its_height(name):
    """Sheet 2 draws ΔT(φ) and Mertsalov's ΔT_I(φ) (from its value at position 0) at one scale μ_T:
    both curves stay within the diagram's height at that scale, and μ_T is not needlessly small
    (the largest of them fills more than a tenth of it)."""
    s = sheet2(name)
    sc, fw = s.scales, s.flywheel
    curves = (s.dynamics.dT, fw.mertsalov.dT_I - fw.mertsalov.dT_I[0])
    tallest = max(float(np.max(np.abs(c))) for c in curves) / sc.T
    assert 0.1 * sc.height_mm < tallest <= sc.height_mm + 1e-9
