"""Renderers of sheet 3: JSON, CSV, rich tables, figures."""

import csv
import io
import json
import math

import pytest

from tmm_cli.cam.design import design_cam

REQUIRED = {
    "scheme", "law", "closure", "follower", "r0_mm", "e_mm", "l_oc_mm", "roller_mm",
    "pressure_angle_max_deg", "psi_deg", "rho_min_mm", "pitch_curve_mm", "warnings",
}


@pytest.fixture(scope="module")
def some(table):
    return {n: design_cam(table[n]) for n in (1, 2, 3, 4, 17, 19, 20, 43)}


def test_json_all_variants_serialisable(table):
    from tmm_cli.render.data.cam import cam_to_json

    for n, v in table.items():
        r = design_cam(v)
        d = cam_to_json(r, "en" if n % 2 else "ru")
        text = json.dumps(d, allow_nan=False)  # plain floats only, no NaN/inf, no numpy types
        back = json.loads(text)
        assert REQUIRED <= set(back)
        assert back["closure"] in ("force", "form") and back["follower"] in ("translating", "rocker")
        assert (back["e_mm"] is None) == v.is_rocker and (back["l_oc_mm"] is None) != v.is_rocker
        assert set(back["pressure_angle_max_deg"]) == {"rise", "return"}
        assert {"rise", "far_dwell", "return"} <= set(back["psi_deg"])
        pts = back["pitch_curve_mm"]
        assert len(pts) >= 361
        # the first point lies on the base circle, the curve is closed
        assert math.hypot(*pts[0]) == pytest.approx(back["r0_mm"], rel=1e-4)
        assert pts[0] == pts[-1]
        assert all(isinstance(w, str) for w in back["warnings"])


def test_json_warnings_name_the_undercut(some):
    from tmm_cli.render.data.cam import cam_to_json

    from tmm_cli.cam.design import CamChoice, design_cam

    # issue 8: the carried roller never undercuts; the book's 0.2·r0 given as the student's --roller does
    assert cam_to_json(some[19], "en")["undercut"] is False
    book = round(some[19].profile.roller_book_m * 1000, 2)
    r = design_cam(some[19].variant, choice=CamChoice(roller_mm=book))
    d = cam_to_json(r, "en")
    assert d["undercut"] is True and d["checks"]["undercut_ok"] is False
    assert any("undercut" in w for w in d["warnings"])
    d = cam_to_json(r, "ru")
    assert any("подрез" in w for w in d["warnings"])


def test_profile_csv(some):
    from tmm_cli.render.data.cam import profile_csv

    for n, r in some.items():
        text = profile_csv(r)
        rows = list(csv.reader(io.StringIO(text)))
        head = rows[0]
        assert head[:3] == ["phi_deg", "pitch_x_mm", "pitch_y_mm"]
        assert all(h.endswith(("_mm", "_deg")) for h in head)
        assert ("outer_x_mm" in head) == (r.closure == "form")
        assert len(rows) - 1 >= 360 * 4
        x, y = float(rows[1][1]), float(rows[1][2])
        assert math.hypot(x, y) == pytest.approx(r.sizing.r0_m * 1000, rel=1e-5)


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_print_cam(some, lang):
    from rich.console import Console

    from tmm_cli.render.terminal.cam import print_cam

    for n in (1, 3, 4):
        buf = io.StringIO()
        print_cam(Console(file=buf, width=160), some[n], lang)
        out = buf.getvalue()
        assert "ν_max" in out and "r_0" in out and "ψ_у" in out
        if lang == "ru":
            assert "Проверки" in out and "мм" in out
        else:
            assert "Checks" in out and "mm" in out
        assert ("l_OC" in out) == some[n].variant.is_rocker


def test_figures_each_scheme(some):
    from matplotlib.figure import Figure

    from tmm_cli.render.figures.cam import cam_figures

    for n in (1, 2, 3, 4):
        figs = cam_figures(some[n], "ru" if n % 2 else "en")
        assert set(figs) == {"cam_motion", "cam_zone", "cam_profile", "cam_pressure_angle", "cam_profile_scaled"}
        for name, fig in figs.items():
            assert isinstance(fig, Figure)
            assert str(n) in fig.get_suptitle()
            buf = io.BytesIO()
            fig.savefig(buf, format="png", dpi=40)
            assert buf.getvalue()[:4] == b"\x89PNG"
        prof = figs["cam_profile"].axes[0]
        assert prof.get_aspect() == 1.0


def test_module_import_does_not_pull_matplotlib():
    import subprocess
    import sys

    code = "import sys, tmm_cli.render.figures.cam, tmm_cli.cam.design; print('matplotlib' in sys.modules, 'scipy' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.strip()
    assert out == "False False"
