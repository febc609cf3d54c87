"""The four laws of Fig. 1.9 and the follower diagrams (§1.2): identities and numerical derivatives."""

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from tmm_cli.cam.laws import law_max, law_values
from tmm_cli.cam.motion import CamProgram, follower_motion, table_step
from tmm_cli.errors import TmmError

LAWS = (1, 2, 3, 4)


@pytest.mark.parametrize("law", LAWS)
def test_law_ends_and_continuity(law):
    f, f1, _, _ = law_values(law, np.array([0.0, 1.0]))
    assert f.tolist() == pytest.approx([0.0, 1.0], abs=1e-15)
    # velocity is continuous with the dwells: no hard impact in any law
    assert f1.tolist() == pytest.approx([0.0, 0.0], abs=1e-12)


@pytest.mark.parametrize("law", LAWS)
def test_law_maxima_found_numerically(law):
    t = np.linspace(0.0, 1.0, 200001)
    _, f1, f2, _ = law_values(law, t)
    m1, m2, _ = law_max(law)
    assert f1.max() == pytest.approx(m1, rel=1e-8)
    assert np.abs(f2).max() == pytest.approx(m2, rel=1e-8)


@pytest.mark.parametrize("law", LAWS)
def test_law_derivatives_are_numerical_derivatives(law):
    t = np.linspace(0.01, 0.99, 981)
    h = 1e-6
    f, f1, f2, _ = law_values(law, t)
    fp, _, _, _ = law_values(law, t + h)
    fm, _, _, _ = law_values(law, t - h)
    assert np.allclose((fp - fm) / (2 * h), f1, atol=1e-7)
    _, f1p, _, _ = law_values(law, t + h)
    _, f1m, _, _ = law_values(law, t - h)
    smooth = np.abs(t - 0.5) > 2 * h  # law 1 jumps at mid-phase
    assert np.allclose(((f1p - f1m) / (2 * h))[smooth], f2[smooth], atol=1e-5)


@settings(max_examples=40, deadline=None)
@given(
    law=st.sampled_from(LAWS),
    rise=st.floats(20, 160),
    far=st.floats(0, 60),
    ret=st.floats(20, 160),
    h=st.floats(0.005, 0.3),
)
def test_book_1_7_ratio(law, rise, far, ret, h):
    """(1.7): |a_return,max / a_rise,max| = (φ_у/φ_в)² for every law."""
    assume(rise + far + ret <= 359.0)  # a cam program: the phases fit in one turn (else the return wraps)
    p = CamProgram(law=law, stroke=h, phi_rise=math.radians(rise), phi_far=math.radians(far), phi_return=math.radians(ret))
    t = np.linspace(0.0, 1.0, 2001)[1:-1]  # junction points belong to the phase before them
    _, _, a_r, _ = p.at(t * p.phi_rise)
    _, _, a_b, _ = p.at(p.return_start + t * p.phi_return)
    ratio = np.abs(a_b).max() / np.abs(a_r).max()
    assert ratio == pytest.approx((rise / ret) ** 2, rel=1e-9)


@settings(max_examples=25, deadline=None)
@given(law=st.sampled_from(LAWS), rise=st.floats(20, 160), ret=st.floats(20, 160), n=st.floats(100, 3000))
def test_velocity_is_derivative_of_displacement_in_time(law, rise, ret, n):
    from tmm_cli.variants import Variant

    v = Variant(99, 1, None, 30.0, n, 0.04, law, rise, 360.0 - rise - ret - 1.0, ret)
    m = follower_motion(v)
    # central differences of the stored S(t) against the stored V(t) (0.25° grid: kinks of
    # V at the phase ends limit the agreement to a few per cent of V_max there)
    dt = m.time[2:] - m.time[:-2]
    v_num = (m.s[2:] - m.s[:-2]) / dt
    scale = np.abs(m.v).max()
    assert np.abs(v_num - m.v[1:-1]).max() < 0.03 * scale
    # and to 1e-6 with a fine step taken directly on the displacement program
    phi = np.linspace(0.001, 2 * math.pi - 0.001, 5000)
    d = 1e-7
    s_p, _, _, _ = m.program.at(phi + d)
    s_m, _, _, _ = m.program.at(phi - d)
    _, ds, _, _ = m.program.at(phi)
    assert np.abs((s_p - s_m) / (2 * d) - ds).max() < 1e-6 * np.abs(ds).max()
    # the cycle closes: displacement back to zero after a turn
    assert m.s[0] == pytest.approx(0.0, abs=1e-15) and m.s[-1] == pytest.approx(0.0, abs=1e-15)


def test_rocker_roller_centre_values_follow_1_6():
    from tmm_cli.variants import Variant

    v = Variant(3, 3, 0.06, 45.0, -1050.0, 33.0, 3, 40.0, 30.0, 80.0)
    m = follower_motion(v)
    for row in m.table:
        assert row.s_b_m == pytest.approx(row.s * 0.06)
        assert row.v_b_m_s == pytest.approx(row.v * 0.06)
    assert max(math.degrees(r.s) for r in m.table) == pytest.approx(33.0)
    # short rise (40°) gets the halved step, the 80° return keeps 10°
    assert (m.table_step_rise_deg, m.table_step_return_deg) == (5.0, 10.0)


def test_table_hits_phase_ends_and_book_scales():
    from tmm_cli.variants import Variant

    v = Variant(1, 1, None, 25.0, 800.0, 0.05, 1, 100.0, 20.0, 100.0)
    m = follower_motion(v)
    phis = [r.phi_deg for r in m.table]
    assert phis[0] == 0 and phis[-1] == 220 and 100 in phis and 120 in phis
    assert len(phis) == 22
    # last row is the end of the return: S = 0, a one-sided (not the dwell's zero)
    assert m.table[-1].s == pytest.approx(0.0, abs=1e-12) and abs(m.table[-1].a) > 1.0
    s = m.scales
    assert s.k_phi_deg_mm == pytest.approx(220 / 240)  # (1.9)
    assert s.k_t_s_mm == pytest.approx(220 / (6 * 800 * 240))  # (1.10)
    assert s.k_s == pytest.approx(0.05 / 80)  # (1.11)
    assert s.k_v == pytest.approx(s.k_s / (s.k_t_s_mm * s.h_v_mm))  # (1.12)
    assert s.y_a_return_max_mm == pytest.approx(s.y_a_rise_max_mm * (100 / 100) ** 2)  # (1.8)
    assert s.y_v_max_mm <= 60.0 + 1e-9


def test_table_step_rule():
    assert table_step(100, 10) == 10
    assert table_step(50, 10) == 5


@pytest.mark.parametrize("bad", [0, -5, 31, float("nan")])
def test_bad_step_is_a_tmm_error(bad):
    from tmm_cli.cam.design import design_cam
    from tmm_cli.variants import Variant

    v = Variant(1, 1, None, 25.0, 800.0, 0.05, 1, 100.0, 20.0, 100.0)
    with pytest.raises(TmmError, match="step"):
        design_cam(v, step_deg=bad)


def test_reported_maxima_keep_1_7_for_all_68_variants():
    """The maxima the project reports (and the note prints with (1.7)) are each phase's own: with no
    far dwell (variant 59: law 2, φ_дс = 0) the point where the rise ends belongs to the rise, and
    its −a_max is not the return's largest acceleration (it was: the note printed 1 = 0,25)."""
    from tmm_cli.cam.motion import follower_motion
    from tmm_cli.variants import load_table

    for number, v in load_table().items():
        mx = follower_motion(v, 10.0).maxima
        assert mx.accel_ratio == pytest.approx(mx.accel_ratio_book, rel=1e-6), number


@pytest.mark.parametrize("rise, far, ret", [(100, 20, 100), (40, 30, 80), (160, 0, 120), (60, 200, 60)])
def test_phase_index_follows_the_phase_angles(rise, far, ret):
    """Every half degree of the turn is in the phase Table 1.2's angles put it in: rise on
    [0, φ_у], far dwell up to φ_у + φ_дс, return up to φ_р, near dwell after (the ends to 10⁻⁶)."""
    p = CamProgram(law=1, stroke=0.05, phi_rise=math.radians(rise), phi_far=math.radians(far),
                   phi_return=math.radians(ret))
    deg = np.arange(0.0, 360.0, 0.5)
    ends = np.array([rise, rise + far, rise + far + ret])
    inner = np.min(np.abs(deg[:, None] - ends[None, :]), axis=1) > 1e-6
    want = np.searchsorted(ends, deg, side="left")  # 0 up to φ_у, 1 up to φ_у + φ_дс, …
    got = p.phase_index(np.radians(deg))
    assert np.array_equal(got[inner], want[inner])
    assert {0, 2, 3} <= set(got.tolist()) and (1 in got) == (far > 0)
    # an end belongs to the rise or the return (the table's rows there are named after them)
    ends_rad = np.radians([0.0, rise, rise + far, rise + far + ret])
    assert p.phase_index(ends_rad).tolist() == [0, 0, 2 if far > 0 else 0, 2]  # no far dwell: the rise ends there


def test_the_ends_of_the_rise_and_return_take_the_laws_end_values():
    """At φ_у exactly (the motion table's last rise row) the program gives the law's end: law 2,
    f = 3t² − 2t³, has f″(1) = −6, so d²s/dφ² = −6h/φ_у² there (the far dwell would give 0); at
    the end of the return +6h/φ_в²."""
    h, rise, far, ret = 0.05, math.radians(100), math.radians(20), math.radians(100)
    p = CamProgram(law=2, stroke=h, phi_rise=rise, phi_far=far, phi_return=ret)
    s, d1, d2, _ = p.at(np.array([rise, rise + far + ret]))
    assert s.tolist() == pytest.approx([h, 0.0], abs=1e-15)
    assert d1.tolist() == pytest.approx([0.0, 0.0], abs=1e-12)
    assert d2.tolist() == pytest.approx([-6 * h / rise ** 2, 6 * h / ret ** 2], rel=1e-12)
