"""Mesh stiffness of a spur pair (seed 002, Tarasik): worked example, the beam solution checked
against numerical integration, the combination law, scaling and units, and the course wiring."""

import io
import json
import math

import pytest
from rich.console import Console
from scipy.integrate import quad

from tmm_cli.gears import stiffness as st
from tmm_cli.gears.design import design_gears
from tmm_cli.gears.drive import omega_rad_s
from tmm_cli.render.data.gears import gears_to_json
from tmm_cli.render.terminal.gears import print_gears

# The paper's example (Table 1 and the text): z = 20/25, m = 2 mm, b_w = 10 mm, M1 = 20 N·m.
EX = dict(z1=20, z2=25, m_m=2e-3, b_w_m=10e-3, torque1_nm=20.0)


def sig(x: float, digits: int = 4) -> float:
    """x rounded to the paper's printed significant digits (it prints 2.471·10⁵, 0.367·10⁻⁶ …)."""
    return float(f"{x:.{digits - 1}e}")


@pytest.fixture(scope="module")
def ex():
    return st.mesh_stiffness(**EX)


def test_worked_example_tooth_geometry(ex):
    # Table 1, rows 6, 9 [mm]: exact to the printed three decimals
    assert [round(v * 1e3, 3) for v in ex.s_a_m] == [1.390, 1.440]
    assert [round(v * 1e3, 3) for v in ex.s_d_m] == [3.142, 3.142]
    assert [round(v * 1e3, 3) for v in ex.s_b_m] == [3.512, 3.652]
    assert [round(v * 1e3, 3) for v in ex.rho_m] == [6.840, 8.551]
    # row 7: J_d [m⁴] — the section of the trapezoid ABCD at the pitch circle
    assert [round(v * 1e10, 3) for v in ex.j_d_m4] == [0.167, 0.164]


def test_worked_example_deformations_and_stiffness(ex):
    assert ex.force_n == pytest.approx(1000.0)  # F = M1/r_d1 = 20/0.02
    # row 8: deflections at the pitch circles; text: y_H = 2.789·10⁻⁶ m
    assert [sig(v, 3) for v in ex.y_bend_m] == [0.367e-6, 1.25e-6]
    assert round(ex.y_bend_m[1] * 1e6, 3) == 1.252
    assert sig(ex.y_contact_m) == 2.789e-6
    # the text: c_и = 2.471·10⁵, c_H = 1.434·10⁵, c = 9.074·10⁴ N·m/rad — all four digits, no tolerance
    assert sig(ex.c_bend) == 2.471e5
    assert sig(ex.c_contact) == 1.434e5
    assert sig(ex.c) == 9.074e4
    # Table 2, "предлагаемая методика": c_уд, c_и,уд, c_H,уд [N/(mm·μm)]
    assert (round(ex.c_spec, 3), round(ex.c_spec_bend, 3), round(ex.c_spec_contact, 3)) == (22.685, 61.769, 35.852)


def test_worked_example_pins_the_unprinted_material_constants():
    """The paper prints neither E nor ν: E = 2.1·10¹¹ Pa, ν = 0.3 reproduce it, nearby values do not."""
    assert sig(st.mesh_stiffness(**EX, e_pa=2.0e11).c_bend) != 2.471e5
    assert sig(st.mesh_stiffness(**EX, e_pa=2.06e11).c_bend) != 2.471e5
    assert sig(st.mesh_stiffness(**EX, nu=0.25).c_contact) != 1.434e5
    # ν does not enter bending at all
    assert st.mesh_stiffness(**EX, nu=0.25).c_bend == pytest.approx(st.mesh_stiffness(**EX).c_bend, rel=1e-12)


def test_thickness_formula_special_circles():
    m, z = 3e-3, 31
    rd = m * z / 2
    rb = rd * math.cos(math.radians(20))
    assert st.tooth_thickness(z, m, rd) == pytest.approx(math.pi * m / 2, rel=1e-12)  # s = πm/2 for x = 0
    assert st.tooth_thickness(z, m, rb) == pytest.approx(2 * rb * (math.pi / (2 * z) + st.inv(math.radians(20))))
    # thickness falls from base to tip; a positive shift thickens the tooth at the pitch circle by 2x·m·tg α
    assert st.tooth_thickness(z, m, rb) > st.tooth_thickness(z, m, rd) > st.tooth_thickness(z, m, rd + m) > 0
    assert st.tooth_thickness(z, m, rd, x=0.5) - st.tooth_thickness(z, m, rd) == pytest.approx(
        2 * 0.5 * m * math.tan(math.radians(20)), rel=1e-12)
    with pytest.raises(ValueError):
        st.tooth_thickness(z, m, 0.9 * rb)


@pytest.mark.parametrize("a, b, l, x", [(0.6, 3.1e-3, 2.5e-3, 0.0), (0.4, 1.4e-3, 4.5e-3, 2e-3),
                                        (0.05, 1e-3, 3e-3, 1e-3)])
def test_beam_closed_form_matches_numerical_integration(a, b, l, x):
    """(9)–(11) against y(x) = ∫_x^l (s − x)·y''(s) ds with y'' = A·s/(a·s + b)³ (4)–(7), which has
    y(l) = y'(l) = 0 built in; (8) against θ(x) = −∫_x^l y''(s) ds."""
    A = st.beam_load_factor(1000.0, 0.01)
    ypp = lambda s: A * s / (a * s + b) ** 3  # noqa: E731
    y_num = quad(lambda s: (s - x) * ypp(s), x, l, epsabs=0, epsrel=1e-12)[0]
    th_num = -quad(ypp, x, l, epsabs=0, epsrel=1e-12)[0]
    assert st.beam_deflection(A, a, b, l, x) == pytest.approx(y_num, rel=1e-8)
    assert st.beam_slope(A, a, b, l, x) == pytest.approx(th_num, rel=1e-8)
    assert st.beam_deflection(A, a, b, l, l) == pytest.approx(0.0, abs=1e-12 * y_num)
    if x == 0.0:
        assert st.beam_tip_deflection(A, a, b, l) == pytest.approx(y_num, rel=1e-8)  # (12)
        assert st.beam_tip_slope(A, a, b, l) == pytest.approx(th_num, rel=1e-8)  # (15)


def test_beam_uniform_limit():
    """As the taper vanishes the tip deflection tends to the prismatic cantilever's F·l³/(3EJ);
    to first order y = F·l³/(3EJ)·(1 − 9al/(4b)) (expand (as + b)⁻³ under ∫ A·s²/(as + b)³ ds)."""
    F, bw, E, b, l, a = 1000.0, 0.01, 2.1e11, 3e-3, 3e-3, 1e-3
    A = st.beam_load_factor(F, bw, E)
    prismatic = F * l ** 3 / (3 * E * bw * b ** 3 / 12)
    y = st.beam_tip_deflection(A, a, b, l)
    assert y == pytest.approx(prismatic * (1 - 9 * a * l / (4 * b)), rel=2e-5)
    assert y < prismatic  # the tapering section is stiffer


def test_combination_law(ex):
    """(20) is the series law of springs because the turn angles add: c = M1/(φ_и + φ_H)."""
    assert ex.c == pytest.approx(ex.torque1_nm / (ex.phi_bend_rad + ex.phi_contact_rad), rel=1e-12)
    assert 1 / ex.c == pytest.approx(1 / ex.c_bend + 1 / ex.c_contact, rel=1e-12)
    assert ex.c < min(ex.c_bend, ex.c_contact)
    # the turn from the summed deflections differs only by the arctg's curvature (~1e-8 here)
    total = math.atan((sum(ex.y_bend_m) + ex.y_contact_m) / ex.r_d_m[0])
    assert ex.c == pytest.approx(ex.torque1_nm / total, rel=1e-7)
    assert st.series_stiffness(3.0, 6.0) == pytest.approx(2.0)
    assert 1 / ex.k == pytest.approx(1 / ex.k_bend + 1 / ex.k_contact, rel=1e-12)


def test_bending_linear_in_face_width_and_load_free():
    base = st.mesh_stiffness(**EX)
    wide = st.mesh_stiffness(**{**EX, "b_w_m": 2 * EX["b_w_m"]})
    # J ∝ b_w, so y ∝ 1/b_w and c_и ∝ b_w (up to arctg(y/r) ≈ y/r: relative 1e-9 here)
    assert wide.c_bend == pytest.approx(2 * base.c_bend, rel=1e-8)
    assert wide.c_spec_bend == pytest.approx(base.c_spec_bend, rel=1e-12)
    # the paper (Fig. 6): c_и does not depend on the load, c_H and c grow with it, and c_H,уд too (Fig. 8)
    loads = [5.0, 20.0, 60.0]
    runs = [st.mesh_stiffness(**{**EX, "torque1_nm": t}) for t in loads]
    for r in runs:
        assert r.c_bend == pytest.approx(base.c_bend, rel=1e-6)
    assert runs[0].c_contact < runs[1].c_contact < runs[2].c_contact
    assert runs[0].c < runs[1].c < runs[2].c
    assert runs[0].c_spec_contact < runs[1].c_spec_contact < runs[2].c_spec_contact
    # and wider gears (same torque, lower q) are stiffer in contact too
    assert wide.c_contact > base.c_contact


def test_units_and_scaling():
    base = st.mesh_stiffness(**EX)
    # same force F = M1/r_d1 on a module twice as large: the beam deflections are scale-free
    # (y = F/(b_w·E)·f(z)), so c_и = M1/φ ≈ F·r²/y grows as m²
    big = st.mesh_stiffness(**{**EX, "m_m": 2 * EX["m_m"], "torque1_nm": 2 * EX["torque1_nm"]})
    assert big.force_n == pytest.approx(base.force_n)
    assert big.y_bend_m[0] == pytest.approx(base.y_bend_m[0], rel=1e-9)
    assert big.y_bend_m[1] == pytest.approx(base.y_bend_m[1], rel=1e-9)
    assert big.c_bend == pytest.approx(4 * base.c_bend, rel=1e-6)
    # N·m/rad ↔ N/m: c ≈ k·r_d1²; N/(mm·μm) = 10⁻⁹ N/m²: c_spec = k/b_w·10⁻⁹
    for r in (base, big):
        assert r.c == pytest.approx(r.k * r.r_d_m[0] ** 2, rel=1e-6)
        assert r.c_spec == pytest.approx(r.k / r.b_w_m * 1e-9, rel=1e-12)
        assert r.line_load_n_per_m == pytest.approx(r.force_n / r.b_w_m)
    # E in Pa: a softer material (E/2) halves bending stiffness exactly
    soft = st.mesh_stiffness(**EX, e_pa=st.E_STEEL_PA / 2)
    assert soft.c_bend == pytest.approx(base.c_bend / 2, rel=1e-8)


def test_bad_inputs():
    for kw in ({"torque1_nm": 0.0}, {"b_w_m": -1e-3}, {"b_w_m": 0.0}, {"m_m": 0.0}, {"nu": 0.5}):
        with pytest.raises(ValueError):
            st.mesh_stiffness(**{**EX, **kw})
    with pytest.raises(ValueError):
        st.contact_deformation(0.0, 1e-3, 1e-3, 1e-2, 1e-2)


# ---------------------------------------------------------------- the course's spur pair

def test_course_pair_with_torque_uses_motor_torque():
    r = design_gears(600, 220, ratio=(13, 4), torque_nm=100)
    s = r.spur_stiffness
    assert s is not None and s.load == "motor"
    assert s.motor_torque_nm == pytest.approx(r.power.power_kw * 1e3 / omega_rad_s(r.motor_rpm))
    assert s.mesh.torque1_nm == pytest.approx(s.motor_torque_nm)
    assert s.mesh.z == (r.spur.z1, r.spur.z2) and s.mesh.m_m == pytest.approx(0.02)
    assert s.mesh.b_w_m == pytest.approx(st.PSI_M * 0.02)
    assert {n.code for n in s.notes} >= {"stiffness_scope", "stiffness_material", "stiffness_width",
                                         "stiffness_load_motor"}
    # the note states the width it assumed in mm: b_w = ψ_m·m
    width = next(n for n in s.notes if n.code == "stiffness_width").kwargs
    assert float(width["bw"]) == pytest.approx(float(width["psi"]) * 20.0, rel=1e-12) and width["m"] == "20"
    # its notes stay in the block, not among the course's assumptions
    assert not any(n.code.startswith("stiffness") for n in r.notes)


def test_course_pair_nominal_and_optional():
    r = design_gears(-1800, 67, ratio=(53, 5))
    s = r.spur_stiffness
    assert s.load == "nominal" and s.motor_torque_nm is None
    assert s.mesh.line_load_n_per_m == pytest.approx(st.NOMINAL_LINE_LOAD_N_PER_M)
    assert r.spur.z1 > r.spur.z2 and "stiffness_multiplier" in {n.code for n in s.notes}
    assert design_gears(-1800, 67, ratio=(53, 5), stiffness=False).spur_stiffness is None
    # a zero moment gives no power to load the pair with: fall back to the nominal load
    assert design_gears(600, 220, torque_nm=0).spur_stiffness.load == "nominal"


def test_course_pair_json_and_tables():
    r = design_gears(600, 220, ratio=(13, 4), torque_nm=100)
    doc = json.loads(json.dumps(gears_to_json(r, "en")))
    sj = doc["spur"]["stiffness"]
    assert sj["informative"] and sj["beyond_course"] and sj["load"] == "motor"
    assert sj["c_nm_per_rad"] == pytest.approx(r.spur_stiffness.mesh.c, rel=1e-6)
    assert len(sj["s_a_mm"]) == 2 and sj["b_w_mm"] == pytest.approx(100.0)
    assert any("beyond the course" in n for n in sj["notes"])
    assert gears_to_json(design_gears(600, 220, stiffness=False), "ru")["spur"]["stiffness"] is None
    for lang, title in (("en", "Mesh stiffness (beyond the course, informative): V. P. Tarasik's method"),
                        ("ru", "Жёсткость зацепления (сверх программы курса, справочно): методика В. П. Тарасика")):
        c = Console(width=160, file=io.StringIO(), record=True, color_system=None)
        print_gears(c, r, lang)
        text = c.export_text()
        assert title in text and "(20)" in text and "ψ_m" in text
