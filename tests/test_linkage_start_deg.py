"""Sheet 2 whatever position 0 is (issue 34): with ``crank.start_deg`` the useful resistance still
acts on the working stroke measured from the extreme position where it starts.

Independent checks: the load at a crank angle is the same whichever angle position 0 is given
(the default position 0 is the working stroke's start); it acts only while the output moves the
working way (the sign of its velocity from the kinematics); the mean of the balancing moment over a
turn (a fine midpoint sum of the power balance) equals the driving moment from the exact area of
the load diagram; M_d and the flywheel do not depend on position 0."""

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from tmm_cli.linkage.chain import solve
from tmm_cli.linkage.forces import applied
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.positions import output_coordinate
from tmm_cli.linkage.power import balancing_moment_by_power
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2
from linkage_check import with_start

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"

# the issue's offset crank-slider turning clockwise (its position 0 by the load at 188°)
OFFSET_CW = {
    "frame": {"O": [0.0, 0.0]},
    "crank": {"pivot": "O", "joint": "A", "length": 0.05, "rpm": 100, "sense": "cw"},
    "group": [{"kind": "RRP", "joints": ["A", "B"], "length": 0.2,
               "guide": {"through": [0.0, 0.02], "angle_deg": 0.0}, "branch": "ahead"}],
    "mass": [{"link": ["A", "B"], "m": 2.0, "J": 0.01}, {"joint": "B", "m": 1.0}],
    "load": {"on": "B", "stroke": [0.0, 0.5, 1.0], "force": [0.0, 1000.0, 1000.0], "working": "away"},
    "dynamics": {"delta": 0.05},
}
# a press: the 5 kN load on the last fifth of the downward stroke, position 0 at either extreme
PRESS = {
    "frame": {"O": [0.0, 0.0]},
    "crank": {"pivot": "O", "joint": "A", "length": 0.08, "rpm": 60},
    "group": [{"kind": "RRP", "joints": ["A", "B"], "length": 0.35,
               "guide": {"through": [0.0, 0.0], "angle_deg": 90.0}, "branch": "behind"}],
    "mass": [{"link": ["A", "B"], "m": 6.0, "J": 0.06}, {"joint": "B", "m": 30.0}],
    "load": {"on": "B", "stroke": [0.0, 0.8, 0.8, 1.0], "force": [0.0, 0.0, 5000.0, 5000.0], "working": "towards"},
    "dynamics": {"delta": 0.1},
}


def _files():
    out = {"offset_cw": OFFSET_CW, "press": PRESS}
    for name in ("compressor", "four_bar", "shaper"):
        out[name] = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
    return out


FILES = _files()
STARTS = (None, 0.0, 45.0, 200.0, 310.0)


def _sheet2(data, start):
    m = parse_mechanism(with_start(data, start), "m.toml")
    s1 = analyse_mechanism(m)
    return m, analyse_sheet2(s1, parse_sheet2(m, "m.toml"))


_DEFAULT = {}


def _default(name):
    if name not in _DEFAULT:
        _DEFAULT[name] = _sheet2(FILES[name], None)
    return _DEFAULT[name]


def _load_at(m, s2, phi):
    k = solve(m, phi)
    ld = [f for f in applied(m, s2.input, s2.stroke, k).forces if f.kind == "load"]
    if ld:
        return k, ld[0].f
    return k, [c for c in applied(m, s2.input, s2.stroke, k).couples if c.kind == "load"][0].m


@pytest.mark.parametrize("start", STARTS[1:])
@pytest.mark.parametrize("name", sorted(FILES))
def test_the_load_at_a_crank_angle_does_not_depend_on_position_0(name, start):
    m0, s0 = _default(name)
    m, s = _sheet2(FILES[name], start)
    phi = np.linspace(0.0, 2 * math.pi, 721)[:-1] + 0.013  # off the table's jumps' exact angles
    k, f = _load_at(m, s, phi)
    _, f0 = _load_at(m0, s0, phi)
    scale = float(np.max(np.abs(f0)))
    assert scale > 1.0
    assert np.max(np.abs(f - f0)) <= 1e-9 * scale
    # the load acts only while the output moves the working way (from the kinematics alone)
    v = output_coordinate(m, k)[1] * s.sheet1.cycle.direction
    assert np.all((np.abs(f) == 0.0) | (v >= -1e-9 * np.max(np.abs(v))))


@pytest.mark.parametrize("start", STARTS)
@pytest.mark.parametrize("name", sorted(FILES))
def test_the_mean_balancing_moment_is_the_driving_moment(name, start):
    m, s = _sheet2(FILES[name], start)
    # the power balance at the sheet's positions (the force analysis agrees with it)
    scale = float(np.max(np.abs(s.balancing)))
    assert np.max(np.abs(s.balancing - s.power_balance)) <= 1e-9 * scale
    # mean M_b over a turn by a fine midpoint sum of the power balance; the inertia forces give
    # nothing over a turn, so it is the constant driving moment of the exact area
    n = 72000
    c = s.sheet1.cycle
    phi = c.start + m.crank.sense * (np.arange(n) + 0.5) * 2 * math.pi / n
    k = solve(m, phi)
    mb = balancing_moment_by_power(k, applied(m, s.input, s.stroke, k))
    assert float(np.mean(mb)) == pytest.approx(s.dynamics.drive_moment_ccw, rel=2e-4)
    # the cycle closes and nothing of the dynamics depends on where position 0 is
    d = s.dynamics
    assert d.dT[-1] == pytest.approx(0.0, abs=1e-9 * abs(d.A_r[-1]))
    _, s0 = _default(name)
    assert d.M_d == pytest.approx(s0.dynamics.M_d, rel=1e-12)
    assert float(np.ptp(d.dT)) == pytest.approx(float(np.ptp(s0.dynamics.dT)), rel=2e-3)
    if s.flywheel is not None:
        assert s.flywheel.J == pytest.approx(s0.flywheel.J, rel=5e-3)


def test_the_issues_offset_crank_slider():
    """start_deg = 200: the positions' loads are the diagram's at their share of the stroke."""
    m, s = _sheet2(OFFSET_CW, 200.0)
    c = s.sheet1.cycle
    q = output_coordinate(m, c.kin)[0]
    k_ext = solve(m, [c.extremes[0], c.extremes[1]])
    q_start, q_end = output_coordinate(m, k_ext)[0]
    share = (q - q_start) / (q_end - q_start)
    moving_working = output_coordinate(m, c.kin)[1] * (q_end - q_start) > 0
    want = np.where(moving_working, np.interp(share, [0.0, 0.5, 1.0], [0.0, 1000.0, 1000.0]), 0.0)
    got = np.abs([f for f in s.loading.forces if f.kind == "load"][0].f)
    # the position ends of the strokes (v = 0) may carry either value
    inner = np.abs(output_coordinate(m, c.kin)[1]) > 1e-6
    assert np.allclose(got[inner], want[inner], atol=1e-6)


# --- lengths and δ below a physical floor: one line, exit 2 (not a ZeroDivisionError) -----------


def _toml(data):
    import json

    lines = []

    def val(v):
        return json.dumps(v, ensure_ascii=False) if not isinstance(v, dict) else \
            "{ " + ", ".join(f"{k} = {val(x)}" for k, x in v.items()) + " }"

    for k, v in data.items():
        if not isinstance(v, (dict, list)) or (isinstance(v, list) and v and not isinstance(v[0], dict)):
            lines.append(f"{k} = {val(v)}")
    for k, v in data.items():
        if isinstance(v, dict):
            lines.append(f"[{k}]")
            lines += [f"{kk} = {val(x)}" for kk, x in v.items()]
        elif isinstance(v, list) and v and isinstance(v[0], dict):
            for item in v:
                lines.append(f"[[{k}]]")
                lines += [f"{kk} = {val(x)}" for kk, x in item.items()]
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("where,key,value,words", [
    ("crank", "length", 1e-300, ("'crank.length' is 1e-300 m", "0.0001 m")),
    ("crank", "length", 5e-5, ("'crank.length' is 5e-05 m",)),
    ("group", "length", 1e-300, ("'group[1].length' is 1e-300 m",)),
    ("dynamics", "delta", 1e-300, ("'dynamics.delta' is 1e-300", "below 0.0001")),
])
def test_lengths_and_delta_below_a_physical_floor(tmp_path, where, key, value, words):
    from cli_helpers import assert_one_line_error, run

    data = with_start(OFFSET_CW, None)
    data = {k: (dict(v) if isinstance(v, dict) else [dict(x) for x in v] if isinstance(v, list) else v)
            for k, v in data.items()}
    if where == "group":
        data["group"][0][key] = value
    else:
        data[where][key] = value
    path = tmp_path / "m.toml"
    path.write_text(_toml(data), encoding="utf-8")
    out = tmp_path / "out"
    res = run("linkage", path, "--out", out, "--no-plots", "--lang", "en")
    assert_one_line_error(res, *words)
    assert not out.exists()
    ru = run("linkage", path, "--out", out, "--no-plots", "--lang", "ru")
    assert ru.exit_code == 2 and "ошибка" in ru.stderr and "no link of" not in ru.stderr and "no machine" not in ru.stderr


def test_the_floor_itself_is_a_machine():
    data = with_start(OFFSET_CW, None)
    data["crank"]["length"] = 1e-4
    m = parse_mechanism(data, "m.toml")
    s = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m, "m.toml"))
    assert s.sheet1.cycle.stroke == pytest.approx(2e-4, rel=1e-2)
