"""The student's say over the cam (issue 8): overrides round-trip through the CLI's JSON, their
pressure angles recomputed here from the follower law alone, failed conditions reported, and
out-of-range values refused with one line and exit 2 (no files left behind)."""

import json
import math

import numpy as np
import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli

from reference_laws import law_f


def law_df(law, t):
    """df/dt of the four laws (METHOD.md "Inputs"), written out again here."""
    t = np.clip(t, 0.0, 1.0)
    if law == 1:
        return np.where(t < 0.5, 4 * t, 4 * (1 - t))
    if law == 2:
        return 6 * t - 6 * t**2
    if law == 3:
        return np.pi / 2 * np.sin(np.pi * t)
    return 1 - np.cos(2 * np.pi * t)


def translating_nu_deg(d, r0, e, phase):
    """Largest pressure angle [deg] of a translating roller follower on a phase, from the law alone.

    Ground frame: cam centre O at the origin, follower axis x = e, rise along +y, roller centre
    B = (e, s0 + s), s0 = √(r0² − e²). The cam point under B moves with ω × OB = κω(−(s0 + s), e)
    (κ = +1 ccw); B relative to the cam moves along (κ(s0 + s), s′ − κe)·ω, the pitch curve's
    tangent, so tan ν = |s′ − κe| / (s0 + s) with s′ = ds/dφ."""
    ph = d["phases_deg"]
    h = d["s_max_mm"]
    kappa = 1.0 if d["rotation"] == "ccw" else -1.0
    t = np.linspace(0.0, 1.0, 20001)
    length = math.radians(ph[phase])
    if phase == "rise":
        s, ds = h * law_f(d["law"], t), h * law_df(d["law"], t) / length
    else:
        s, ds = h * (1 - law_f(d["law"], t)), -h * law_df(d["law"], t) / length
    s0 = math.sqrt(r0 * r0 - e * e)
    return float(np.degrees(np.arctan(np.abs(ds - kappa * e) / (s0 + s))).max())


def run(args, tmp_path):
    res = CliRunner().invoke(cli, [*args, "--out", str(tmp_path), "--no-plots", "--lang", "en"], catch_exceptions=False)
    return res


def test_offset_override_round_trip(tmp_path):
    res = run(["cam", "--variant", "17", "--r0", "60", "--offset", "-10", "--json"], tmp_path)
    assert res.exit_code == 0, res.output
    d = json.loads(res.stdout)["cam"]
    assert d["r0_mm"] == pytest.approx(60.0, abs=1e-6)
    assert d["e_mm"] == pytest.approx(-10.0, abs=1e-6)
    assert d["design_source"] == "student"
    assert d["student_choice"]["r0_mm"] == 60.0 and d["student_choice"]["offset_mm"] == -10.0
    for phase in ("rise", "return"):
        mine = translating_nu_deg(d, 60.0, -10.0, phase)
        assert d["pressure_angle_max_deg"][phase] == pytest.approx(mine, abs=0.02), phase
    # variant 17 (ν_max = 25°, spring): this cam breaks the limit on the rise, and says so
    assert d["pressure_angle_max_deg"]["rise"] > d["nu_max_deg"]
    assert d["checks"]["pressure_angle_ok"] == {"rise": False, "return": True}
    assert any(w.startswith("FAILS the pressure-angle condition") and "rise" in w for w in d["warnings"])
    # the program's own design is shown beside it, and it does keep ν ≤ ν_max (own formula again)
    own = d["program_design"]
    assert translating_nu_deg(d, own["r0_mm"], own["e_mm"], "rise") <= d["nu_max_deg"] + 0.02


@pytest.mark.parametrize("number", [1, 2, 5, 17, 62, 65])
def test_program_design_pressure_angle_by_the_law(number, tmp_path):
    """The carried translating cams (schemes 1 and 2), rechecked by the formula above (constrained
    phases only)."""
    res = run(["cam", "--variant", str(number), "--json"], tmp_path)
    d = json.loads(res.stdout)["cam"]
    assert d["follower"] == "translating", number  # the formula is a translating follower's
    phases = ("rise",) if d["closure"] == "force" else ("rise", "return")
    for phase in ("rise", "return"):
        mine = translating_nu_deg(d, d["r0_mm"], d["e_mm"], phase)
        assert mine == pytest.approx(d["pressure_angle_max_deg"][phase], abs=0.02)
        if phase in phases:
            assert mine <= d["nu_max_deg"] + 0.02


def test_r0_alone_keeps_the_direction_and_a_larger_cam_is_fine(tmp_path):
    base = json.loads(run(["cam", "--variant", "17", "--json"], tmp_path).stdout)["cam"]
    d = json.loads(run(["cam", "--variant", "17", "--r0", "70", "--json"], tmp_path).stdout)["cam"]
    assert d["r0_mm"] == pytest.approx(70.0, abs=1e-6)
    assert d["e_mm"] == pytest.approx(base["e_mm"] * 70.0 / base["r0_mm"], abs=1e-3)
    assert translating_nu_deg(d, 70.0, d["e_mm"], "rise") <= d["nu_max_deg"] + 0.01  # on the same edge of the zone
    assert d["checks"]["all_ok"] is True and not any(w.startswith("FAILS") for w in d["warnings"])


def test_offset_alone_takes_the_smallest_r0_on_that_axis(tmp_path):
    d = json.loads(run(["cam", "--variant", "17", "--offset", "0", "--json"], tmp_path).stdout)["cam"]
    assert d["e_mm"] == pytest.approx(0.0, abs=1e-6)
    nu = translating_nu_deg(d, d["r0_mm"], 0.0, "rise")
    assert nu == pytest.approx(d["nu_max_deg"], abs=0.05)  # on the zone's edge: the smallest central cam
    assert translating_nu_deg(d, d["r0_mm"] * 0.98, 0.0, "rise") > d["nu_max_deg"]


@pytest.mark.parametrize("variant, n_rpm", [(1, 800), (17, -1000)])
@pytest.mark.parametrize("offset", [-8.0, 0.0, 8.0])
def test_offset_alone_either_way_round(variant, n_rpm, offset, tmp_path):
    """Variant 1 turns counter-clockwise (n_k = +800), 17 clockwise: the offset the student gives
    is the one the cam carries, and r0 is the smallest on that axis that keeps ν ≤ ν_max on the
    rise (the formula above: on the edge, and 2 % smaller breaks it)."""
    d = json.loads(run(["cam", "--variant", str(variant), "--offset", str(offset), "--json"], tmp_path).stdout)["cam"]
    assert d["n_cam_rpm"] == n_rpm
    assert d["e_mm"] == pytest.approx(offset, abs=1e-6)
    assert translating_nu_deg(d, d["r0_mm"], offset, "rise") == pytest.approx(d["nu_max_deg"], abs=0.05)
    assert translating_nu_deg(d, d["r0_mm"] * 0.98, offset, "rise") > d["nu_max_deg"]


def test_rocker_override_geometry_and_checks(tmp_path):
    res = run(["cam", "--variant", "3", "--r0", "55", "--l-oc", "100", "--swing", "opposite", "--roller", "6", "--json"], tmp_path)
    assert res.exit_code == 0, res.output
    d = json.loads(res.stdout)["cam"]
    g = d["follower_in_curve_frame"]
    assert d["r0_mm"] == pytest.approx(55.0, abs=1e-6) and d["l_oc_mm"] == pytest.approx(100.0, abs=1e-6)
    assert math.hypot(*g["pivot_mm"]) == pytest.approx(100.0, abs=1e-3)
    assert math.dist(g["pivot_mm"], g["b0_mm"]) == pytest.approx(d["l_bc_mm"], abs=1e-3)
    assert math.hypot(*g["b0_mm"]) == pytest.approx(55.0, abs=1e-3)
    assert d["swing"] == "opposite" and d["roller_mm"] == pytest.approx(6.0)
    assert d["roller_rule_applied"] == "student"
    assert d["checks"]["pivot_ok"] is True and d["checks"]["undercut_ok"] is True


def test_student_roller_that_undercuts_is_drawn_with_a_failed_check(tmp_path):
    res = run(["cam", "--variant", "19", "--roller", "20"], tmp_path)
    assert res.exit_code == 0
    assert "FAILS the undercut condition" in res.output
    assert (tmp_path / "variant-19" / "cam.json").is_file()


def test_project_takes_the_overrides(tmp_path):
    res = run(["project", "--variant", "17", "--r0", "60", "--offset", "-10", "--json"], tmp_path)
    assert res.exit_code == 0, res.output
    doc = json.loads(res.stdout)
    assert doc["cam"]["r0_mm"] == pytest.approx(60.0) and doc["cam"]["e_mm"] == pytest.approx(-10.0)


@pytest.mark.parametrize(
    "args, words",
    [
        (["--variant", "17", "--r0", "0"], "--r0 0 mm is out of range"),
        (["--variant", "17", "--r0", "-5"], "out of range"),
        (["--variant", "17", "--r0", "20", "--offset", "20"], "not smaller than --r0"),
        (["--variant", "17", "--r0", "20", "--offset", "-25"], "not smaller than --r0"),
        (["--variant", "17", "--roller", "0"], "--roller 0 mm is out of range"),
        (["--variant", "17", "--roller", "-1"], "out of range"),
        (["--variant", "17", "--r0", "30", "--roller", "30"], "not smaller than r0"),
        (["--variant", "17", "--roller", "500"], "not smaller than r0"),
        (["--variant", "17", "--l-oc", "90"], "--l-oc is for a rocker"),
        (["--variant", "17", "--swing", "same"], "--swing is for a rocker"),
        (["--variant", "3", "--offset", "5"], "--offset is for a translating follower"),
        (["--variant", "3", "--r0", "10", "--l-oc", "500"], "l_OC must lie between"),
        (["--variant", "3", "--l-oc", "-4"], "--l-oc -4 mm is out of range"),
        (["--variant", "3", "--l-oc", "5"], "no cam centre at l_OC"),
        (["--variant", "17", "--r0", "nan"], "not a finite number"),
        (["--variant", "17", "--r0", "inf"], "not a finite number"),
    ],
)
def test_out_of_range_overrides_are_refused(args, words, tmp_path):
    for cmd in ("cam", "project"):
        res = CliRunner().invoke(cli, [cmd, *args, "--out", str(tmp_path), "--no-plots", "--lang", "en"])
        assert res.exit_code == 2, (cmd, args, res.output)
        lines = [x for x in res.stderr.splitlines() if x.strip()]
        assert len(lines) == 1 and words in lines[0], (cmd, lines)
        assert "Traceback" not in res.output
        assert not any(tmp_path.iterdir()), "files left behind"
