"""Acceptance audit of issue 13 (`tmm linkage`, the Whitworth / crank-shaper mechanism).

Each test is named after the bullet of the issue it proves. The CLI is driven as a user would;
the numbers are checked against a position analysis written again here from the issue's
conventions (A = (r1·sin φ21, r1·cos φ21), O41 = (−c, −h), φ41 from +y towards +x, C on y = b
left of B), differentiated numerically — nothing of tmm_cli.linkage is used.
"""

import csv
import json
import math
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli
from cli_helpers import assert_one_line_error

WHITWORTH = dict(r1=0.10, h=0.04, c=0.0, r2=0.08, r3=0.30, b=-0.04)
SHAPER = dict(r1=0.10, h=0.30, c=0.02, r2=0.45, r3=0.30, b=0.25)
KEYS = ("phi_deg", "link_angle_deg", "rho_m", "x_c_m", "omega_link_rad_s", "eps_link_rad_s2", "v_rel_m_s",
        "a_cor_m_s2", "v_c_m_s", "a_c_m_s2")


def args_of(d, rpm=60):
    out = []
    for k, v in d.items():
        out += [f"--{k}", str(v)]
    return out + ["--rpm", str(rpm)]


def run(*args):
    return CliRunner().invoke(cli, ["linkage", *[str(a) for a in args]])


def run_json(d, *extra, rpm=60):
    res = run(*args_of(d, rpm), "--json", "--no-plots", *extra)
    assert res.exit_code == 0, res.output
    return json.loads(res.stdout)


# --- the independent position analysis -------------------------------------------------------

def pose(d, phi):
    """(link angle φ41 unwrapped later, ρ, x_C) at crank angle φ [rad] from the issue's conventions."""
    ax, ay = d["r1"] * math.sin(phi), d["r1"] * math.cos(phi)
    dx, dy = ax + d["c"], ay + d["h"]
    psi = math.atan2(dx, dy)  # from +y towards +x
    rho = math.hypot(dx, dy)
    bx, by = -d["c"] + d["r2"] * math.sin(psi), -d["h"] + d["r2"] * math.cos(psi)
    xc = bx - math.sqrt(d["r3"] ** 2 - (d["b"] - by) ** 2)  # C left of B
    return psi, rho, xc


def derivs(d, phi, omega, step=1e-4):
    """First and second time derivatives of (φ41, ρ, x_C) by central differences (uniform crank)."""
    vals = [np.array(pose(d, phi + k * step)) for k in (-2, -1, 0, 1, 2)]
    for v in vals:  # keep φ41 on one branch around phi
        v[0] = vals[2][0] + (v[0] - vals[2][0] + math.pi) % (2 * math.pi) - math.pi
    m2, m1, p0, p1, p2 = vals
    first = (-p2 + 8 * p1 - 8 * m1 + m2) / (12 * step) * omega
    second = (-p2 + 16 * p1 - 30 * p0 + 16 * m1 - m2) / (12 * step * step) * omega**2
    return p0, first, second




# --- Acceptance numbers ------------------------------------------------------------------------

def test_acceptance_numbers_time_ratio_and_stroke_whitworth():
    doc = run_json(WHITWORTH)
    k = (math.pi + 2 * math.asin(0.04 / 0.10)) / (math.pi - 2 * math.asin(0.04 / 0.10))
    assert round(k, 6) == 1.709953
    assert doc["time_ratio"] == pytest.approx(k, rel=1e-9)
    assert doc["stroke_m"] == pytest.approx(0.16, abs=1e-12)
    assert doc["regime"] == "whitworth"


def test_acceptance_numbers_recomputed_from_the_exported_curve(tmp_path):
    """H and K again from the CSV of the dense curve (not from the JSON summary)."""
    res = run(*args_of(WHITWORTH), "--no-plots", "--out", tmp_path)
    assert res.exit_code == 0, res.output
    rows = list(csv.DictReader((tmp_path / "linkage" / "linkage_curve.csv").open(encoding="utf-8")))
    x = np.array([float(r["x_c_m"]) for r in rows])
    v = np.array([float(r["v_c_m_s"]) for r in rows])
    phi0 = np.array([float(r["phi_from_start_deg"]) for r in rows])
    assert x.max() - x.min() == pytest.approx(0.16, abs=1e-4)
    # the working stroke: from the start until v_C changes sign
    turn = phi0[np.nonzero((v[1:] * v[:-1] < 0) & (phi0[1:] > 5))[0][0] + 1]
    k = turn / (360 - turn)
    assert k == pytest.approx(1.709953, abs=0.02)  # the curve's 0.5° step


@pytest.mark.parametrize("d", [WHITWORTH, SHAPER], ids=["whitworth", "crank_shaper"])
@pytest.mark.parametrize("at", [0, 17.5, 45, 100, 170, 200, 250, 300, 359])
def test_acceptance_velocities_accelerations_agree_with_central_differences(d, at):
    doc = run_json(d, "--at", at, rpm=60)
    omega = 2 * math.pi
    (psi, rho, xc), first, second = derivs(d, math.radians(at), omega)
    a = doc["at"]
    assert a["phi_deg"] == pytest.approx(at)
    # link angle: same branch as atan2 (the article's arctg is wrong where h + r1·cos φ < 0)
    assert (math.radians(a["link_angle_deg"]) - psi + math.pi) % (2 * math.pi) - math.pi == pytest.approx(0, abs=1e-9)
    assert a["rho_m"] == pytest.approx(rho, rel=1e-9)
    assert a["x_c_m"] == pytest.approx(xc, rel=1e-9, abs=1e-12)
    scale_v = max(abs(first[2]), d["r1"] * omega)
    scale_a = max(abs(second[2]), d["r1"] * omega**2)
    assert a["omega_link_rad_s"] == pytest.approx(first[0], rel=1e-6, abs=1e-6 * omega)
    assert a["v_rel_m_s"] == pytest.approx(first[1], abs=1e-6 * scale_v)
    assert a["v_c_m_s"] == pytest.approx(first[2], abs=1e-6 * scale_v)
    assert a["eps_link_rad_s2"] == pytest.approx(second[0], abs=1e-6 * omega**2 * 10)
    assert a["a_c_m_s2"] == pytest.approx(second[2], abs=1e-6 * scale_a)
    assert a["a_cor_m_s2"] == pytest.approx(2 * a["omega_link_rad_s"] * a["v_rel_m_s"], rel=1e-9, abs=1e-12)


@pytest.mark.parametrize("d", [WHITWORTH, SHAPER], ids=["whitworth", "crank_shaper"])
def test_acceptance_loop_closure_residuals_below_1e_12(d):
    """The program's own residual is below 1e-12 m; the exported positions (12 significant digits in
    the JSON) close the loops O21-A-O41 and O41-B-C to that rounding (5e-12 m)."""
    doc = run_json(d, "--positions", 36)
    assert doc["closure_residual_m"] < 1e-12
    tol = 5e-12
    for p in doc["positions"]:
        phi, psi = math.radians(p["phi_deg"]), math.radians(p["link_angle_deg"])
        ax, ay = d["r1"] * math.sin(phi), d["r1"] * math.cos(phi)
        # A lies on the link at ρ from O41
        assert abs(-d["c"] + p["rho_m"] * math.sin(psi) - ax) < tol
        assert abs(-d["h"] + p["rho_m"] * math.cos(psi) - ay) < tol
        bx, by = -d["c"] + d["r2"] * math.sin(psi), -d["h"] + d["r2"] * math.cos(psi)
        assert abs(math.hypot(p["x_c_m"] - bx, d["b"] - by) - d["r3"]) < tol
        assert p["x_c_m"] < bx  # C left of B, as the article draws


# --- What the user runs ----------------------------------------------------------------------

@pytest.mark.parametrize("d", [WHITWORTH, SHAPER], ids=["whitworth", "crank_shaper"])
def test_positions_equally_spaced_starting_from_the_extreme_position_of_the_ram(d):
    doc = run_json(d)
    pos = doc["positions"]
    assert len(pos) == 12
    phis = [p["phi_deg"] for p in pos]
    steps = [(b - a) % 360 for a, b in zip(phis, phis[1:] + phis[:1])]
    assert steps == pytest.approx([30.0] * 12)
    # position 0: an extreme position of the ram (v_C = 0, x_C at its minimum or maximum)
    assert abs(pos[0]["v_c_m_s"]) < 1e-9
    _, _, x0 = pose(d, math.radians(phis[0]))
    xs = [pose(d, math.radians(t / 10))[2] for t in range(3600)]
    assert min(abs(x0 - min(xs)), abs(x0 - max(xs))) < 1e-6
    # it starts the working (slower) stroke: the ram moves during the larger crank arc first
    dead = doc["dead_positions_deg"]
    assert phis[0] == pytest.approx(dead[0])
    assert doc["working_stroke_deg"] >= doc["return_stroke_deg"]
    assert doc["time_ratio"] == pytest.approx(doc["working_stroke_deg"] / doc["return_stroke_deg"])


def test_positions_count_option_and_dead_positions():
    doc = run_json(SHAPER, "--positions", 8)
    assert len(doc["positions"]) == 8
    for deg in doc["dead_positions_deg"]:  # the ram stops at the dead positions
        _, first, _ = derivs(SHAPER, math.radians(deg), 2 * math.pi)
        assert abs(first[2]) < 1e-6
    # crank-shaper: the link is perpendicular to the crank at the dead positions, K closed form
    s = math.asin(SHAPER["r1"] / math.hypot(SHAPER["h"], SHAPER["c"]))
    assert doc["time_ratio"] == pytest.approx((math.pi + 2 * s) / (math.pi - 2 * s), rel=1e-9)


def test_both_regimes_link_oscillates_or_turns_fully():
    shaper = run_json(SHAPER, "--positions", 72)
    whit = run_json(WHITWORTH, "--positions", 72)
    assert shaper["regime"] == "crank_shaper" and whit["regime"] == "whitworth"
    swing = [p["link_angle_deg"] for p in shaper["positions"]]
    assert max(swing) - min(swing) < 180  # oscillates
    turned = sum(((b - a + 180) % 360) - 180 for a, b in zip(
        [p["link_angle_deg"] for p in whit["positions"]], [p["link_angle_deg"] for p in whit["positions"][1:]]
        + [whit["positions"][0]["link_angle_deg"]]))
    assert abs(turned) == pytest.approx(360.0)  # a full turn per crank turn


def test_crank_angular_acceleration_optional():
    """--eps-crank: a_C = x″·ω² + x′·ε (chain rule), checked against the difference quotients."""
    eps = 3.0
    doc = run_json(WHITWORTH, "--at", 60, "--eps-crank", eps)
    omega = 2 * math.pi
    _, first, second = derivs(WHITWORTH, math.radians(60), omega)
    x1, x2 = first[2] / omega, second[2] / omega**2
    assert doc["at"]["a_c_m_s2"] == pytest.approx(x2 * omega**2 + x1 * eps, rel=1e-6)


def test_figures_json_and_csv_of_the_dense_curve(tmp_path):
    res = run(*args_of(WHITWORTH), "--out", tmp_path, "--lang", "en")
    assert res.exit_code == 0, res.output
    names = {p.name for p in (tmp_path / "linkage").iterdir()}
    for f in ("linkage.json", "linkage_curve.csv", "linkage_mechanism.png", "linkage_diagrams.png",
              "linkage_velocity_plan.png", "linkage_acceleration_plan.png"):
        assert f in names, names
    doc = json.loads((tmp_path / "linkage" / "linkage.json").read_text(encoding="utf-8"))
    assert set(KEYS) <= set(doc["at"]) and all(set(KEYS) <= set(p) for p in doc["positions"])


def test_velocity_and_acceleration_plan_labels_and_polygons_close():
    """Poles p and π, the textbook's point names, and each vector equation closes."""
    doc = run_json(WHITWORTH, "--at", 45)
    vel, acc = doc["plans"]["velocity"], doc["plans"]["acceleration"]
    assert {"p", "a2", "a4", "b", "c"} <= set(vel["points"])
    assert {"π", "a2", "k", "a4", "n4", "b", "n5", "c"} <= set(acc["points"])
    P, A = vel["points"], acc["points"]
    v = lambda s, e: np.subtract(P[e], P[s])  # noqa: E731
    # v_A4 = v_A2 + v_A4A2; v_C = v_B + v_CB; v_C along the guide (x), equal to the ram's velocity
    assert np.allclose(v("p", "a4"), v("p", "a2") + v("a2", "a4"), atol=1e-12)
    assert np.allclose(v("p", "c"), v("p", "b") + v("b", "c"), atol=1e-12)
    assert P["c"][1] == pytest.approx(0, abs=1e-12) and P["c"][0] == pytest.approx(doc["at"]["v_c_m_s"], rel=1e-9)
    # crank point A2: |v| = ω·r1 perpendicular to O21A
    assert np.hypot(*P["a2"]) == pytest.approx(2 * math.pi * 0.10, rel=1e-9)
    # a_A4 = a_A2 + a^k + a^r; Coriolis magnitude 2·ω4·v_rel; a_C along the guide
    a = lambda s, e: np.subtract(A[e], A[s])  # noqa: E731
    assert np.allclose(a("π", "a4"), a("π", "a2") + a("a2", "k") + a("k", "a4"), atol=1e-12)
    assert np.hypot(*a("a2", "k")) == pytest.approx(abs(doc["at"]["a_cor_m_s2"]), rel=1e-9)
    assert A["c"][1] == pytest.approx(0, abs=1e-12) and A["c"][0] == pytest.approx(doc["at"]["a_c_m_s2"], rel=1e-9)


def test_department_table_in_toml_gives_the_same_numbers_as_options(tmp_path):
    f = tmp_path / "dept.toml"
    f.write_text("rpm = 60\nc = 0.0\n[variants.7]\nr1 = 0.10\nh = 0.04\nr2 = 0.08\nr3 = 0.30\nb = -0.04\n",
                 encoding="utf-8")
    res = run("--input", f, "--variant", 7, "--json", "--no-plots")
    assert res.exit_code == 0, res.output
    assert json.loads(res.stdout)["positions"] == run_json(WHITWORTH)["positions"]


# --- Must hold: bad input --------------------------------------------------------------------

BAD = [
    (dict(WHITWORTH, r1=0), (), ["--r1", "positive"]),
    (dict(WHITWORTH, r3=-0.3), (), ["--r3", "positive"]),
    (dict(WHITWORTH, r3=0.05), (), ["rod cannot reach"]),
    (dict(SHAPER, r2=0.2), (), ["block leaves"]),
    (WHITWORTH, ("--bogus", "1"), ["--bogus"]),
    (WHITWORTH, ("--at", "400"), ["--at", "360"]),
    (WHITWORTH, ("--at", "-1"), ["--at"]),
    (WHITWORTH, ("--at", "nan"), ["--at"]),
    (dict(WHITWORTH, r1=1e308), (), ["--r1", "limit"]),
    (WHITWORTH, ("--positions", "1"), ["--positions"]),
]


@pytest.mark.parametrize("d, extra, words", BAD)
def test_bad_input_one_line_exit_2_nothing_written(tmp_path, d, extra, words):
    out = tmp_path / "new" / "deep"
    res = run(*args_of(d), *extra, "--out", out)
    assert_one_line_error(res, *words)
    assert not (tmp_path / "new").exists()


def test_bench_times_linkage_json_no_plots():
    text = (Path(__file__).resolve().parents[1] / "bench" / "bench.py").read_text(encoding="utf-8")
    assert "linkage" in text and "--no-plots" in text and "--json" in text
