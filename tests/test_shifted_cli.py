"""`tmm gears` / `tmm project` with --shift and --aw: the JSON keys, the default zero pair, the
shifted mesh figure, and hostile inputs (one line, exit 2, nothing written)."""

import json
import math

import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli
from tmm_cli.gears.design import design_gears


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])


def spur_of(res):
    assert res.exit_code == 0, res.output
    d = json.loads(res.stdout)
    return d["spur"] if "spur" in d else d["gears"]["spur"]


def test_default_stays_the_books_zero_pair(tmp_path):
    s = spur_of(run("gears", "-v", 17, "--json", "--no-plots", "--out", tmp_path))
    assert (s["x1"], s["x2"], s["shift_rule"]) == (0.0, 0.0, "zero")
    assert s["a_w_mm"] == s["a_mm"] and s["alpha_w_deg"] == 20.0
    assert s["da_mm"] == [s["d_mm"][0] + 40, s["d_mm"][1] + 40]


def test_shift_keys_beside_the_spur_keys(tmp_path):
    s = spur_of(run("gears", "-v", 17, "--shift", "0.4,0.2", "--json", "--no-plots", "--out", tmp_path))
    assert (s["x1"], s["x2"], s["shift_rule"]) == (0.4, 0.2, "given")
    z1, z2, m = s["z1"], s["z2"], s["m_mm"]
    alpha = math.radians(20)
    aw = math.radians(s["alpha_w_deg"])
    # recompute from the exported numbers: inv α_w and a_w
    assert math.isclose(math.tan(aw) - aw, math.tan(alpha) - alpha + 2 * 0.6 * math.tan(alpha) / (z1 + z2), rel_tol=1e-6)
    assert math.isclose(s["a_w_mm"], m * (z1 + z2) / 2 * math.cos(alpha) / math.cos(aw), rel_tol=1e-6)
    sh = s["shifted"]
    assert sh["x"] == [0.4, 0.2] and len(sh["checks"]) == 7
    assert s["da_mm"] == sh["da_mm"] and s["eps_alpha"] == sh["eps_alpha"]


def test_required_centre_distance(tmp_path):
    s = spur_of(run("gears", "-v", 17, "--aw", 420, "--json", "--no-plots", "--out", tmp_path))
    assert s["shift_rule"] == "aw" and math.isclose(s["a_w_mm"], 420.0, abs_tol=1e-6)
    assert math.isclose(s["x1"], s["x2"], abs_tol=1e-9)  # auto is (0, 0) for 24/17: the sum is split equally


def test_auto_for_the_course_pair_is_zero(tmp_path):
    s = spur_of(run("gears", "-v", 17, "--shift", "auto", "--json", "--no-plots", "--out", tmp_path))
    assert (s["x1"], s["x2"], s["shift_rule"]) == (0.0, 0.0, "auto")


def test_project_carries_the_shift(tmp_path):
    res = run("project", "-v", 3, "--shift", "0.3,-0.1", "--json", "--no-plots", "--out", tmp_path)
    s = spur_of(res)
    assert (s["x1"], s["x2"]) == (0.3, -0.1)
    doc = json.loads((tmp_path / "variant-03" / "results.json").read_text(encoding="utf-8"))
    assert doc["gears"]["spur"]["a_w_mm"] == s["a_w_mm"]


def test_suggestion_below_17_teeth():
    # the pipeline always has a 17-tooth gear; the core suggests a shift for a smaller one
    from tmm_cli.gears.design import _spur_shift_notes
    from tmm_cli.gears.spur import spur_geometry

    notes = _spur_shift_notes(spur_geometry(14, 30))
    assert [n.code for n in notes] == ["spur_shift_suggest"]
    assert notes[0].kwargs["x"] == f"{3 / 17:.4f}"


def test_shifted_mesh_figure_draws():
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from tmm_cli.render.figures.gears import gears_figures

    r = design_gears(-1000, 220, shift=(0.5, 0.3))
    fig = gears_figures(r, "ru", names=["gears_mesh"])["gears_mesh"]
    FigureCanvasAgg(fig)
    fig.canvas.draw()
    titles = " ".join(ax.get_title() for ax in fig.axes)
    assert "x1 = 0,5" in titles and "a_w" in titles  # ru: decimal commas (num(), issue 9)
    o2 = [ln for ln in fig.axes[0].lines if len(ln.get_xdata()) == 1]
    assert any(math.isclose(float(ln.get_ydata()[0]), r.spur.a_w_mm) for ln in o2)  # O2 at a_w


@pytest.mark.parametrize("args,words", [
    (["--shift", "x"], ["--shift", "auto"]),
    (["--shift", "0.3"], ["--shift"]),
    (["--shift", "3,-0.5"], ["pointed"]),
    (["--aw", "200"], ["cannot be reached"]),
    (["--aw", "-5"], ["positive"]),
    (["--shift", "0.1,0.1", "--aw", "420"], ["give one of them"]),
])
def test_bad_shift_input(tmp_path, args, words):
    res = run("gears", "-v", 17, *args, "--out", tmp_path)
    assert res.exit_code == 2, res.output
    err = res.stderr.strip()
    assert len(err.splitlines()) == 1 and err.startswith("tmm: error:") and "Traceback" not in err
    for w in words:
        assert w in err, (w, err)
    assert not (tmp_path / "variant-17").exists()
