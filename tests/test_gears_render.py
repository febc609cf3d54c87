"""Sheet 4 rendering: JSON, rich tables and figures for the three schemes."""

import io
import json

import pytest
from rich.console import Console

from tmm_cli.gears.design import design_gears
from tmm_cli.render.data.gears import gears_to_json
from tmm_cli.render.terminal.gears import print_gears

CASES = {
    "1": dict(n_cam_rpm=600, crank_rpm=220, ratio=(13, 4), torque_nm=100),
    "2": dict(n_cam_rpm=-1800, crank_rpm=67, ratio=(53, 5)),
    "1+1": dict(n_cam_rpm=800, crank_rpm=40),
}


@pytest.fixture(scope="module")
def results():
    return {k: design_gears(**v) for k, v in CASES.items()}


@pytest.mark.parametrize("scheme", list(CASES))
def test_json_contract(results, scheme):
    r = results[scheme]
    doc = gears_to_json(r, "en")
    doc = json.loads(json.dumps(doc))  # plain types only
    assert doc["crank_rpm"] == CASES[scheme]["crank_rpm"]
    assert doc["motor"]["n_rpm"] == 720
    assert (doc["motor"]["power_kw"] is None) == (CASES[scheme].get("torque_nm") is None)
    assert doc["planetary"]["scheme"] == scheme
    stages = doc["planetary"]["stages"]
    assert len(stages) == (2 if scheme == "1+1" else 1)
    for st in stages:
        assert set(st) >= {"z_sun", "z_planet", "z_planet2", "z_ring", "planets", "ratio"}
        assert (st["z_planet2"] is None) == (scheme != "2")
    assert doc["planetary"]["ratio"] == pytest.approx(r.planetary.ratio)
    assert isinstance(doc["planetary"]["ratio_error_pct"], float)
    for key in ("z1", "z2", "m_mm", "a_mm", "eps_alpha"):
        assert key in doc["spur"]
    assert doc["i_spur"] > 0 and doc["i_planetary"] > 0
    assert all(isinstance(w, str) for w in doc["warnings"])


def test_json_power(results):
    doc = gears_to_json(results["1"], "ru")
    # N = M·ω/(η1·η2)·1e-3 = 100·(π·220/30)/(0.96·0.8)/1000
    assert doc["motor"]["power_kw"] == pytest.approx(100 * 3.14159265 * 220 / 30 / 0.768 / 1000, rel=1e-5)
    assert doc["motor"]["rated_kw"] == 3.0


def test_json_book_2_5_warning_in_russian(results):
    doc = gears_to_json(results["2"], "ru")
    assert any("34/56/50/120" in w and "ошибочен" in w for w in doc["warnings"])


@pytest.mark.parametrize("scheme", list(CASES))
@pytest.mark.parametrize("lang", ["ru", "en"])
def test_tables_render(results, scheme, lang):
    c = Console(width=120, file=io.StringIO(), record=True, color_system=None)
    print_gears(c, results[scheme], lang)
    text = c.export_text()
    assert "z_k" in text and "ε_α" in text and "(2.1)" in text
    if lang == "ru":
        assert "i_пл" in text and "Соосность" in text
    else:
        assert "Coaxiality" in text
    if scheme == "2":
        assert "Таблица 2.3" in text or "Table 2.3" in text


@pytest.mark.parametrize("scheme", list(CASES))
def test_figures(results, scheme):
    from matplotlib.figure import Figure

    from tmm_cli.render.figures.gears import gears_figures

    figs = gears_figures(results[scheme], "ru" if scheme == "2" else "en")
    assert set(figs) == {"gears_planetary", "gears_assembly", "gears_mesh"}
    for f in figs.values():
        assert isinstance(f, Figure)
        buf = io.BytesIO()
        f.savefig(buf, format="png", dpi=40)
        assert buf.getvalue()[:4] == b"\x89PNG"


def test_tooth_outline_is_a_closed_involute_gear():
    import math

    import numpy as np

    from tmm_cli.render.figures.gears import gear_outline

    z, m = 17, 20.0
    p = gear_outline(z, m)
    r = np.hypot(p[:, 0], p[:, 1])
    assert r.max() == pytest.approx(m * z / 2 + m, rel=1e-9)  # tip circle
    assert r.min() == pytest.approx(m * z / 2 - 1.25 * m, rel=1e-6)  # root circle
    assert np.allclose(p[0], p[-1])
    # tooth thickness on the pitch circle is πm/2: the outline crosses the pitch circle 2z times,
    # alternately tooth and space of equal angular width
    rp = m * z / 2
    ang = np.unwrap(np.arctan2(p[:, 1], p[:, 0]))
    s = np.sign(r - rp)
    idx = np.nonzero(np.diff(s) != 0)[0]
    cross = []
    for i in idx:
        t = (rp - r[i]) / (r[i + 1] - r[i])
        cross.append(ang[i] + t * (ang[i + 1] - ang[i]))
    widths = np.diff(cross)
    assert len(cross) == 2 * z
    assert np.allclose(np.abs(widths), math.pi / z, rtol=1e-3)
