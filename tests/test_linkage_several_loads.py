"""Several table loads, each on its own link (issue 34: "Several table loads: each measures its stroke
from its own link's working-stroke start").

Independent checks, from the exported JSON (linkage.json's positions: the points' velocities, the
links' ω, the applied forces and moments, M_b) and from the file's own tables, not from the code under
test: the power balance at every position; each load recomputed from its table — its own link's
extremes found on a fine grid of the kinematics, its working stroke by the file's `working` (the
distance of the link's point from the crank pivot), its share of the stroke from the link's place —,
zero on that link's idle stroke; the mean of M_b over a turn equals M_d (the mean of the loads' power
from those recomputed loads); M_b of both loads is the sum of the runs with each load alone; hostile
files refused in one line, exit 2. The example docs/examples/press_feeder.toml and random files
(hypothesis): a crank with a slider (a force table) and a crank-rocker's rocker (a moment table)."""

import json
import math
import tomllib
from copy import deepcopy
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from tmm_cli.cli import cli
from tmm_cli.errors import TmmError
from tmm_cli.linkage.chain import solve
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2
from tmm_cli.render.data.dynamics import add_sheet2
from tmm_cli.render.data.mechanism import mechanism_document

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
EXAMPLE = tomllib.loads((EXAMPLES / "press_feeder.toml").read_text(encoding="utf-8"))
TWO_PI = 2.0 * math.pi


def _run(data: dict, name: str = "m.toml"):
    m = parse_mechanism(deepcopy(data), name)
    s2 = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m, name), name)
    doc = json.loads(json.dumps(add_sheet2(mechanism_document(s2.sheet1, "en"), s2)))  # as linkage.json holds it
    return m, s2, doc


# --- the loads recomputed from the file's tables -----------------------------------------------------


def _coordinate(m, data, ld, k):
    """The load's link's coordinate: a slider's place along its guide [m], a link's angle [rad] (unwrapped
    about its first value: a rocker swings less than a half turn), and the point whose distance from the
    crank pivot tells 'away' from 'towards'."""
    on = ld["on"]
    if isinstance(on, str):
        g = next(g for g in data["group"] if g["kind"] == "RRP" and g["joints"][1] == on)
        u = complex(math.cos(math.radians(g["guide"]["angle_deg"])), math.sin(math.radians(g["guide"]["angle_deg"])))
        return (np.conj(u) * k.z[on]).real, k.z[on], u
    a, b = on
    d = k.z[b] - k.z[a]
    return np.angle(d / d[0]), k.z[b if b not in data["frame"] else a], None  # the end that moves


class Own:
    """One table load as the file defines it, on its own link's working stroke."""

    def __init__(self, m, data, ld):
        self.m, self.data, self.ld = m, data, ld
        n = 72000
        grid = np.arange(n) * TWO_PI / n
        q, z, _ = _coordinate(m, data, ld, solve(m, grid))
        ends = []
        for i in (int(np.argmin(q)), int(np.argmax(q))):  # each refined by the parabola through three points
            y0, y1, y2 = q[i - 1], q[i], q[(i + 1) % n]
            ends.append(grid[i] + 0.5 * (y0 - y2) / (y0 - 2 * y1 + y2) * TWO_PI / n)
        k = solve(m, ends)
        qe, ze, _ = _coordinate(m, data, ld, k)
        pivot = complex(*data["frame"][data["crank"]["pivot"]])
        far = abs(ze[1] - pivot) > abs(ze[0] - pivot)  # the max end is the farther one
        away = ld.get("working") == "away"
        i0 = 0 if far == away else 1  # the working stroke runs from ends[i0] to the other end
        self.sense = 1 if m.crank.omega > 0 else -1
        self.start, self.end = ends[i0], ends[1 - i0]
        self.work = (self.sense * (self.end - self.start)) % TWO_PI
        self.q0, self.H = qe[i0], abs(qe[1] - qe[0])
        self.direction = 1.0 if qe[1 - i0] > qe[i0] else -1.0

    def value(self, phi):
        """(the force [complex N] or moment [N·m] the table gives, the link's velocity or ω) at the angles."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        k = solve(self.m, phi)
        q, z, u = _coordinate(self.m, self.data, self.ld, k)
        on = self.ld["on"]
        if u is None:  # a link's angle, measured from its direction at the start extreme
            a, b = on
            k0 = solve(self.m, [self.start])
            dq = np.angle((k.z[b] - k.z[a]) / complex(k0.z[b][0] - k0.z[a][0]))
        else:
            dq = q - self.q0
        travel = (self.sense * (phi - self.start)) % TWO_PI
        travel = np.where(travel > TWO_PI - 1e-9, 0.0, travel)
        working = travel <= self.work + 1e-9
        share = np.clip(self.direction * dq / self.H, 0.0, 1.0)
        key = "force" if isinstance(on, str) else "moment"
        size = np.where(working, np.interp(share, self.ld["stroke"], self.ld[key]), 0.0)
        if u is not None and "direction_deg" in self.ld:  # its own direction, its size from the table
            return size * np.exp(1j * math.radians(self.ld["direction_deg"])), k.v[on]
        if u is not None:
            return -self.direction * size * u, k.v[on]
        link = self.m.link_between(*on).name
        return -self.direction * size, k.omega[link]


def _own_loads(m, data):
    return [Own(m, data, ld) for ld in data["load"]]


def _symbol(m, data, ld):
    n = m.link(ld["on"]).number if isinstance(ld["on"], str) else m.link_between(*ld["on"]).number
    return ("Fc" if isinstance(ld["on"], str) else "Mc") + str(n)


# --- the checks ---------------------------------------------------------------------------------------


def _check_power_balance(m, doc):
    """Σ F·v + Σ M·ω + M_b·ω₁ = 0 at every position, from the JSON alone."""
    w1 = doc["crank"]["omega_rad_s"]  # signed: counter-clockwise positive
    scale = max(abs(p["balancing_moment_Nm"]) for p in doc["positions"]) * abs(w1)
    for p in doc["positions"]:
        power = p["balancing_moment_Nm"] * w1
        for sym, f in p["applied_forces"].items():
            if f["at"] in p["points"]:
                v = complex(p["points"][f["at"]]["vx"], p["points"][f["at"]]["vy"])
            else:  # a centre of mass in the middle of its link (no named point): the mean of its ends' velocities
                ends = m.links[int("".join(ch for ch in sym if ch.isdigit())) - 1].axis
                v = sum(complex(p["points"][j]["vx"], p["points"][j]["vy"]) for j in ends) / 2
            power += f["force"][0] * v.real + f["force"][1] * v.imag
        for sym, mom in p["applied_moments_Nm"].items():
            number = int("".join(ch for ch in sym if ch.isdigit()))
            power += mom * p["links"][m.links[number - 1].name]["omega"]
        assert abs(power) <= 1e-9 * scale, (p["label"], power)


def _check_loads_from_tables(m, data, doc):
    """Every load at every position equals its table on its own link's working stroke, 0 on the idle one;
    each is zero somewhere (an idle stroke) and acts somewhere."""
    for own in _own_loads(m, data):
        sym = _symbol(m, data, own.ld)
        phi = np.radians([p["phi_deg"] for p in doc["positions"]])
        expected, _ = own.value(phi)
        scale = max(own.ld.get("force", own.ld.get("moment")))
        for p, e in zip(doc["positions"], expected):
            if isinstance(own.ld["on"], str):
                got = complex(*p["applied_forces"][sym]["force"]) if sym in p["applied_forces"] else 0j
            else:
                got = p["applied_moments_Nm"].get(sym, 0.0)
            assert abs(got - e) <= 1e-6 * scale, (sym, p["label"], got, e)
        entry = next(x for x in doc["forces"]["loads"] if x["symbol"] == sym)
        gap = (entry["working_start_deg"] - math.degrees(own.start) + 180.0) % 360.0 - 180.0  # 0° is 360°
        assert abs(gap) <= 1e-6
        assert entry["working_stroke_deg"] == pytest.approx(math.degrees(own.work), abs=1e-6)
        # over a fine grid: zero wherever the link is on its idle stroke (it moves back there)
        grid = np.linspace(0.0, TWO_PI, 1441)[:-1] + 0.0007
        f, v = own.value(grid)
        power = (np.conj(f) * v).real if isinstance(own.ld["on"], str) else f * v
        assert np.all(power <= 1e-9 * scale)  # a useful resistance never drives
        travel = (own.sense * (grid - own.start)) % TWO_PI
        assert np.all(np.abs(f[travel > own.work + 1e-6]) == 0.0)


def _check_mean(m, data, s2, doc):
    """mean(M_b) over a turn = M_d: the weights and the inertia forces give nothing over a turn, so the
    mean of −(the loads' power)/ω₁ on a fine midpoint grid is the constant driving moment."""
    n = 36000
    phi = (np.arange(n) + 0.5) * TWO_PI / n
    w1 = m.crank.omega
    power = np.zeros(n)
    for own in _own_loads(m, data):
        f, v = own.value(phi)
        power += (np.conj(f) * v).real if isinstance(own.ld["on"], str) else f * v
    assert float(np.mean(-power / w1)) == pytest.approx(doc["dynamics"]["drive_moment_Nm"], rel=1e-4)
    assert doc["dynamics"]["drive_moment_Nm"] == pytest.approx(s2.dynamics.drive_moment_ccw, rel=1e-10)


def _alone(data, which, start_deg):
    """The file with only load `which` (None: no load), position 0 at `start_deg`, the output on that load."""
    d = deepcopy(data)
    d["crank"]["start_deg"] = start_deg
    loads = d.pop("load")
    if which is not None:
        d["load"] = [loads[which]]
        d["output"] = loads[which]["on"]
    return d


def _check_superposition(data, doc):
    """M_b with both loads = the sum of the runs with each alone (less the run with none: the masses'
    part counted once), at the crank angles all runs share (position 0 fixed by start_deg); M_d too."""
    start = doc["positions"][0]["phi_deg"]
    both = _run({**deepcopy(data), "crank": {**data["crank"], "start_deg": start}})[2]
    runs = [_run(_alone(data, w, start))[2] for w in (0, 1, None)]

    def by_phi(d):
        return {round(p["phi_deg"], 6): p["balancing_moment_Nm"] for p in d["positions"]}

    b, one, two, none = (by_phi(d) for d in (both, *runs))
    shared = set(b) & set(one) & set(two) & set(none)
    assert len(shared) >= data.get("positions", 12)
    scale = max(abs(x) for x in b.values())
    for phi in shared:
        assert b[phi] == pytest.approx(one[phi] + two[phi] - none[phi], abs=1e-9 * scale), phi
    md = [d["dynamics"]["drive_moment_Nm"] for d in (both, *runs)]
    assert md[0] == pytest.approx(md[1] + md[2] - md[3], rel=1e-9)


# --- the example --------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def example():
    return _run(EXAMPLE, "press_feeder.toml")


def test_the_example_carries_both_loads_each_on_its_own_stroke(example):
    m, s2, doc = example
    assert [x["symbol"] for x in doc["forces"]["loads"]] == ["Fc3", "Mc5"]
    assert doc["forces"]["load"]["link"] == "B"  # the output's
    ram, rocker = doc["forces"]["loads"]
    # the two working strokes start at different crank angles: each its own link's extreme
    assert abs(ram["working_start_deg"] - rocker["working_start_deg"]) > 10.0
    i = s2.force_position  # both act in the position of the force analysis (drawn on sheet 2)
    p = doc["positions"][i]
    assert abs(complex(*p["applied_forces"]["Fc3"]["force"])) > 100.0 and abs(p["applied_moments_Nm"]["Mc5"]) > 10.0
    assert {f.symbol for f in s2.lever.forces} >= {"Fc3", "Mc5′", "Mc5″"}
    polygon = [v.symbol for pg in s2.polygons for v in pg.vectors]
    assert "Fc3" in polygon


def test_the_example_power_balance_and_loads_from_the_tables(example):
    m, s2, doc = example
    _check_power_balance(m, doc)
    _check_loads_from_tables(m, EXAMPLE, doc)


def test_the_example_mean_balancing_moment_is_the_driving_moment(example):
    m, s2, doc = example
    _check_mean(m, EXAMPLE, s2, doc)


def test_the_example_is_the_sum_of_its_loads_alone(example):
    _check_superposition(EXAMPLE, example[2])


def test_a_force_of_its_own_direction_beside_a_moment():
    """direction_deg on one of several loads: its own direction, its size from its table, on its own
    working stroke only; the balance, the table and mean(M_b) = M_d hold as for a load along the guide."""
    d = deepcopy(EXAMPLE)
    d["load"][0]["direction_deg"] = 160.0  # the forming force pushes back and up (the ram works towards +x)
    m, s2, doc = _run(d)
    assert doc["forces"]["loads"][0]["direction_deg"] == pytest.approx(160.0)
    _check_power_balance(m, doc)
    _check_loads_from_tables(m, d, doc)
    _check_mean(m, d, s2, doc)


def test_a_single_table_load_keeps_its_numbers():
    """One [[load]] table on the output is today's [load]: the same applied force, M_b and M_d."""
    d = deepcopy(EXAMPLE)
    one = d.pop("load")[0]
    a = _run({**d, "load": one})[2]
    b = _run({**d, "load": [one]})[2]
    assert [p["balancing_moment_Nm"] for p in a["positions"]] == [p["balancing_moment_Nm"] for p in b["positions"]]
    assert a["dynamics"] == b["dynamics"] and "loads" not in b["forces"]
    assert "Fc" in a["positions"][3]["applied_forces"]


# --- random files -------------------------------------------------------------------------------------


@st.composite
def two_loads(draw):
    r = 0.05
    d = draw(st.floats(0.18, 0.30))
    alpha = draw(st.floats(90.0, 200.0))  # where the rocker's pivot lies
    l_c = draw(st.floats(0.15, 0.32))
    c = draw(st.floats(0.08, 0.20))
    assume(l_c + c > d + r + 0.03 and abs(l_c - c) < d - r - 0.03)  # a crank-rocker, away from dead points
    e = draw(st.floats(-0.03, 0.03))
    guide = draw(st.floats(-30.0, 30.0))
    fractions = sorted(draw(st.lists(st.floats(0.05, 0.95), min_size=1, max_size=3)))
    forces = draw(st.lists(st.floats(0.0, 3000.0), min_size=len(fractions) + 2, max_size=len(fractions) + 2))
    moments = draw(st.lists(st.floats(0.0, 80.0), min_size=3, max_size=3))
    assume(max(forces) > 10.0 and max(moments) > 1.0)
    pivot = [d * math.cos(math.radians(alpha)), d * math.sin(math.radians(alpha))]
    crank = {"pivot": "O", "joint": "A", "length": r, "rpm": draw(st.sampled_from([60, 100, 150])),
             "sense": draw(st.sampled_from(["ccw", "cw"]))}
    start = draw(st.one_of(st.none(), st.floats(0.0, 359.9)))  # position 0 anywhere: the loads do not care
    if start is not None:
        crank["start_deg"] = start
    return {
        "gravity": draw(st.booleans()),
        "output": "B",
        "frame": {"O": [0.0, 0.0], "D": pivot},
        "crank": crank,
        "group": [{"kind": "RRP", "joints": ["A", "B"], "length": draw(st.floats(0.2, 0.35)),
                   "guide": {"through": [0.0, e], "angle_deg": guide}, "branch": "ahead"},
                  {"kind": "RRR", "joints": ["A", "C", "D"], "lengths": [l_c, c],
                   "branch": draw(st.sampled_from(["left", "right"]))}],
        "mass": [{"link": ["A", "B"], "m": 2.0, "J": 0.01}, {"joint": "B", "m": draw(st.floats(0.5, 20.0))},
                 {"link": ["A", "C"], "m": 1.0, "J": 0.005}, {"link": ["C", "D"], "m": 1.0, "J": 0.002}],
        "load": [{"on": "B", "stroke": [0.0, *fractions, 1.0], "force": forces,
                  "working": draw(st.sampled_from(["away", "towards"]))},
                 {"on": draw(st.sampled_from([["D", "C"], ["C", "D"]])), "stroke": [0.0, 0.5, 1.0], "moment": moments,
                  "working": draw(st.sampled_from(["away", "towards"]))}],
        "dynamics": {"delta": 0.05},
    }


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(data=two_loads())
def test_random_files_with_two_table_loads(data):
    try:
        m, s2, doc = _run(data)
    except TmmError as exc:  # a random geometry a file may not have (a dead point within the turn)
        assume("cannot be assembled" not in str(exc) and "dead" not in str(exc))
        raise
    _check_power_balance(m, doc)
    _check_loads_from_tables(m, data, doc)
    _check_mean(m, data, s2, doc)
    _check_superposition(data, doc)


# --- hostile files ------------------------------------------------------------------------------------


def _whitworth_two():
    d = tomllib.loads((EXAMPLES / "whitworth.toml").read_text(encoding="utf-8"))
    d["load"] = [{"on": "C", "stroke": [0.0, 1.0], "force": [100.0, 100.0]},
                 {"on": ["O41", "A"], "stroke": [0.0, 1.0], "moment": [5.0, 5.0]}]
    return d


def _hostile(change):
    d = deepcopy(EXAMPLE)
    change(d)
    return d


HOSTILE = [
    (_hostile(lambda d: d["load"].append(dict(d["load"][0]))), "'load[3].on' is the link B, which load[1] loads already"),
    (_hostile(lambda d: d["load"][1].update(on="B")), "'load[2].moment': a slider takes a force; give load[2].force"),
    (_hostile(lambda d: d.update(output=["A", "C"])), "'output' is AC, which none of the table loads is on"),
    (_hostile(lambda d: d["load"][1].update(on=["O", "A"])), "'load[2].on': no moving link joins O and A (the crank takes no load)"),
    (_hostile(lambda d: d["load"][1].update(working="up")), "'load[2].working' is 'up'; choose one of away, towards"),
    (_hostile(lambda d: d["load"][0].update(working="up")), "'load[1].working' is 'up'; choose one of away, towards"),
    (_hostile(lambda d: d["load"][1].update(moment=[0.0, 1.0])), "'load[2].moment' has 2 values but 'load[2].stroke' has 3"),
    (_hostile(lambda d: d["load"][1].update(direction_deg=10.0)), "'load[2].direction_deg' gives a force its own direction"),
    (_hostile(lambda d: d["load"].__setitem__(1, {"working": "away"})), "'load[2]' gives no load (only 'working')"),
    (_whitworth_two(), "'load[2].on' is the link AO41, which turns fully: it has no stroke"),
]


def _toml(data: dict) -> str:
    def value(v):
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, str):
            return json.dumps(v, ensure_ascii=False)
        if isinstance(v, dict):
            return "{ " + ", ".join(f"{k} = {value(x)}" for k, x in v.items()) + " }"
        if isinstance(v, list):
            return "[" + ", ".join(value(x) for x in v) + "]"
        return repr(v)

    lines = [f"{k} = {value(v)}" for k, v in data.items() if not isinstance(v, (dict, list)) or k == "output"]
    for k, v in data.items():
        if isinstance(v, dict):
            lines += [f"[{k}]"] + [f"{kk} = {value(x)}" for kk, x in v.items()]
        elif isinstance(v, list) and k != "output":
            for item in v:
                lines += [f"[[{k}]]"] + [f"{kk} = {value(x)}" for kk, x in item.items()]
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("data,words", HOSTILE, ids=[w[:40] for _, w in HOSTILE])
def test_hostile_files_are_refused_in_one_line(tmp_path, data, words):
    path = tmp_path / "m.toml"
    path.write_text(_toml(data), encoding="utf-8")
    out = tmp_path / "out"
    res = CliRunner().invoke(cli, ["linkage", str(path), "--no-plots", "--out", str(out), "--lang", "en"])
    assert res.exit_code == 2, res.output
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and words in lines[0], res.stderr
    assert not out.exists() or not [p for p in out.rglob("*") if p.is_file()]
    ru = CliRunner().invoke(cli, ["linkage", str(path), "--no-plots", "--out", str(out), "--lang", "ru"])
    assert ru.exit_code == 2 and len(ru.stderr.strip().splitlines()) == 1
    assert "tmm: ошибка: " in ru.stderr and "which" not in ru.stderr, ru.stderr
