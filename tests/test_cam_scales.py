"""The drawing scales (1.9)–(1.18) mean what the book's graphical integration needs.

On the sheet the abscissa is x = φ/k_φ [mm] and the time is t = x·k_t; graphical integration with
a base H draws Y_S = (1/H)·∫Y_V dx and Y_V = (1/H_a)·∫Y_a dx. So with ordinates Y = value/scale
taken from the diagrams in SI, the integrals must reproduce the next diagram — whatever the
scheme, for every variant. Rocker: k_γрад = k_γград·π/180 (1.15), and (1.18) gives the roller
centre's scales from l_BC.
"""

import math

import numpy as np
import pytest

from tmm_cli.cam.motion import follower_motion


def _cumtrapz(y, x):
    return np.concatenate([[0.0], np.cumsum(0.5 * (y[1:] + y[:-1]) * np.diff(x))])


def test_scales_are_those_of_graphical_integration(table):
    for n, v in table.items():
        m = follower_motion(v)
        s = m.scales
        deg = np.degrees(m.phi)
        x = deg / s.k_phi_deg_mm  # (1.9) [mm]
        # (1.10): time along the abscissa
        assert np.allclose(x * s.k_t_s_mm, m.time, rtol=1e-9, atol=1e-12), n
        assert x[np.searchsorted(deg, v.phi_working_deg)] == pytest.approx(s.b_mm, rel=1e-3)
        y_s, y_v, y_a = m.s / s.k_s, m.v / s.k_v, m.a / s.k_a
        assert y_s.max() == pytest.approx(s.y_s_max_mm, rel=1e-9), n  # (1.11) / (1.14)
        # integrate on a fine grid (the acceleration jumps: keep the trapezoid error small)
        fx = np.linspace(0.0, s.b_mm, 48001)
        fs, f1, f2, _ = m.program.at(np.radians(fx * s.k_phi_deg_mm))
        fy_s, fy_v, fy_a = fs / s.k_s, m.omega * f1 / s.k_v, m.omega**2 * f2 / s.k_a
        assert np.abs(_cumtrapz(fy_v, fx) / s.h_v_mm - fy_s).max() < 1e-4 * s.y_s_max_mm, n  # (1.12) / (1.16)
        assert np.abs(_cumtrapz(fy_a, fx) / s.h_a_mm - fy_v).max() < 1e-3 * s.y_v_max_mm, n  # (1.13) / (1.17)
        assert np.abs(y_v).max() == pytest.approx(s.y_v_max_mm, rel=1e-3)
        assert np.abs(y_v).max() <= 60.0 + 1e-6 and np.abs(y_a).max() <= 60.0 + 1e-6
        if v.is_rocker:
            assert s.k_gamma_deg_mm == pytest.approx(v.stroke / s.y_s_max_mm)  # (1.14)
            assert s.k_s == pytest.approx(s.k_gamma_deg_mm * math.pi / 180)  # (1.15)
            # (1.18): the same ordinates read as the roller centre's S_B, V_B, a_B (1.6)
            l = v.l_bc_m
            assert np.allclose(y_s * s.k_s_b, m.s * l) and np.allclose(y_v * s.k_v_b, m.v * l)
            assert np.allclose(y_a * s.k_a_b, m.a * l)
        else:
            assert s.k_s == pytest.approx(v.stroke / s.y_s_max_mm)  # (1.11), m/mm
            assert s.k_s_b is None


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_printed_scale_units(table, lang):
    """The scales table names each unit in the output language; (1.10) uses |n_k| (clockwise cams)."""
    import io

    from rich.console import Console

    from tmm_cli.cam.design import design_cam
    from tmm_cli.render.terminal.cam import _scales_table

    for n in (1, 3):  # translating, rocker (clockwise)
        buf = io.StringIO()
        Console(file=buf, width=200, color_system=None).print(_scales_table(design_cam(table[n]), lang))
        text = buf.getvalue()
        assert "|n_k|" in text
        if lang == "en":
            assert not any(w in text for w in ("град", "рад", "мм")), text
            assert ("m/s² per mm" in text) and ("s/mm" in text)
            if n == 3:
                assert "k_γ deg" in text and "k_γ rad" in text and "rad/s per mm" in text
        else:
            assert "м/(с²·мм)" in text
            if n == 3:
                assert "k_γ град" in text and "k_γ рад" in text


def test_json_scale_units(table):
    from tmm_cli.cam.design import design_cam
    from tmm_cli.render.data.cam import cam_to_json

    for n, units in ((1, ("m/mm", "m/s per mm", "m/s^2 per mm")), (3, ("rad/mm", "rad/s per mm", "rad/s^2 per mm"))):
        sc = cam_to_json(design_cam(table[n]), "en")["scales"]
        assert (sc["k_s_unit"], sc["k_v_unit"], sc["k_a_unit"]) == units
