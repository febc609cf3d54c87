"""A four-stroke engine's gas force over a cycle of two crank turns (issue 34): a ``[[load]]`` with
four rows of pressure (expansion, exhaust, intake, compression).

Independent of tmm's gas module: the piston's distance from its head and its stroke from the
kinematics on a dense grid, the dead centre nearest the head by scipy, the row from the turn since
that dead centre and the sign of the piston's velocity, the pressure by numpy's interpolation, the
cycle's work as the indicator diagram's loop area (trapezoids of the file's rows) × A × H. Then the
balance of powers at every position, mean(M_b) over 720° = M_d, J_r(φ + 360°) = J_r(φ), the
positions numbered on through the second turn, and hostile files."""

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from scipy.optimize import minimize_scalar

from tmm_cli.errors import TmmError
from tmm_cli.linkage.chain import solve
from tmm_cli.linkage.forces import applied
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.power import balancing_moment_by_power
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2
from linkage_check import assert_every_link_in_equilibrium

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
TWO_PI = 2 * math.pi


def data(name):
    return tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))


def sheet2(d):
    m = parse_mechanism(d, "m.toml")
    return m, analyse_sheet2(analyse_mechanism(m, source="m.toml"), parse_sheet2(m, "m.toml"), "m.toml")


def loop_work(ld, H):
    """A·H·∮p dx of the file's rows: + the strokes away from the head, − the strokes back [J]."""
    t, p = np.array(ld["travel"], float), np.array(ld["pressure"], float)
    area = sum((1 if j % 2 == 0 else -1) * float(np.sum(np.diff(t) * (row[1:] + row[:-1]) / 2)) for j, row in enumerate(p))
    return ld["area"] * H * 1e6 * area


def piston_geometry(m, ld, start):
    """(H, τ_near, τ_far): the piston's stroke [m] and the crank's travel from position 0 to its first
    dead centre nearest the head and farthest from it [rad, 0 … 2π), from the kinematics alone."""
    head = complex(*ld["head"])
    sense = m.crank.sense

    def q(t):
        return float(np.abs(solve(m, [start + sense * t]).z[ld["on"]][0] - head))

    grid = np.linspace(0.0, TWO_PI, 7201)[:-1]
    qs = np.abs(solve(m, start + sense * grid).z[ld["on"]] - head)
    i, j = int(np.argmin(qs)), int(np.argmax(qs))
    near = minimize_scalar(q, bounds=(grid[i] - 0.002, grid[i] + 0.002), method="bounded",
                           options={"xatol": 1e-12}).x
    far = minimize_scalar(lambda t: -q(t), bounds=(grid[j] - 0.002, grid[j] + 0.002), method="bounded",
                          options={"xatol": 1e-12}).x
    near, far = float(near) % TWO_PI, float(far) % TWO_PI
    if near > TWO_PI - 1e-6:  # at position 0 to the minimiser's precision: position 0's dead centre
        near -= TWO_PI
    return q(far) - q(near), near, far


def expected_forces(m, ld, start, travel):
    """The gas force [N, complex] at the crank travels from position 0 (nan within 1e-5 rad of a dead
    centre, where the row changes)."""
    head = complex(*ld["head"])
    H, near, far = piston_geometry(m, ld, start)
    k = solve(m, start + m.crank.sense * np.asarray(travel))
    r = k.z[ld["on"]] - head
    away = r / np.abs(r)
    qdot = (np.conj(away) * k.v[ld["on"]]).real
    qmin = float(np.abs(solve(m, [start + m.crank.sense * near]).z[ld["on"]][0] - head))
    x = np.clip((np.abs(r) - qmin) / H, 0.0, 1.0)
    rows = np.array(ld["pressure"], float)
    turn = np.floor((np.asarray(travel) - near) / TWO_PI) % (len(rows) // 2)
    row = (2 * turn + (qdot < 0)).astype(int)
    p = np.array([np.interp(xx, ld["travel"], rows[rr]) for xx, rr in zip(x, row)])
    f = p * 1e6 * ld["area"] * away
    # within 1e-5 rad of a dead centre the row is the one starting there: left out
    dead = [np.remainder(np.asarray(travel) - c + 1e-5, TWO_PI) < 2e-5 for c in (near, far)]
    return np.where(dead[0] | dead[1] | (np.abs(qdot) < 1e-6), np.nan, f), H


def check_cycle(d, m, s):
    """Every claim of the two-turn cycle, recomputed from the file."""
    c = s.sheet1.cycle
    n = len(c.positions)
    assert s.turns == 2 and len(s.positions) == 2 * n
    travel = np.array([p.travel for p in s.positions])
    assert np.all(np.diff(travel) > 0) and travel[0] == 0.0 and travel[-1] < 2 * TWO_PI
    assert np.allclose(travel[n:], travel[:n] + TWO_PI, rtol=0, atol=1e-12)
    assert [p.phi for p in s.positions[n:]] == [p.phi for p in s.positions[:n]]
    # the force analysis, the power balance and Zhukovsky's lever: one M_b at every position of both turns
    scale = max(float(np.max(np.abs(s.balancing))), 1.0)
    assert np.max(np.abs(s.balancing - s.power_balance)) <= 1e-8 * scale
    assert np.max(np.abs(s.balancing - s.lever.balancing)) <= 1e-8 * scale
    assert_every_link_in_equilibrium(s, d.get("name", "m"))
    # the gas forces at the 2N positions: the row of the turn since the first dead centre nearest the head
    work = 0.0
    for ld in d["load"]:
        if "head" not in ld:
            continue
        want, H = expected_forces(m, ld, c.start, travel)
        got = next(f for f in s.loading.forces if f.kind == "load" and f.point == ld["on"]).f
        ok = ~np.isnan(want)
        assert ok.sum() >= len(travel) - 8  # at most two dead centres a turn, each beside a position
        assert np.allclose(got[ok], want[ok], rtol=1e-9, atol=1e-6), (got[ok] - want[ok])
        work += loop_work(ld, H) * (2 if len(ld["pressure"]) == 2 else 1)
    d2 = s.dynamics
    assert d2.travel[-1] == pytest.approx(2 * TWO_PI, abs=1e-12)
    # over the cycle the weights' work returns to 0: A_r(720°) is the gas work
    assert d2.A_r[-1] == pytest.approx(work, rel=1e-9, abs=1e-9 * float(np.max(np.abs(d2.A_r))))
    assert d2.M_d == pytest.approx(-d2.A_r[-1] / (2 * TWO_PI), rel=1e-12)
    # mean(M_b) over the 720° equals M_d (inertia and weights do no work over a cycle)
    k = 36000
    t = (np.arange(k) + 0.5) * 2 * TWO_PI / k
    kk = solve(m, c.start + m.crank.sense * t)
    mb = balancing_moment_by_power(kk, applied(m, s.input, s.stroke, kk))
    assert float(np.mean(mb)) == pytest.approx(d2.drive_moment_ccw, rel=1e-4, abs=1e-6 * float(np.max(np.abs(mb))))
    # J_r repeats each turn, exactly (the kinematics are the same each turn)
    assert np.array_equal(s.reduced_inertia[:n], s.reduced_inertia[n:])
    half = (len(d2.travel) - 1) // 2
    assert np.array_equal(d2.J_r[1:half + 1], d2.J_r[half + 1:])
    assert d2.J_r[0] == pytest.approx(d2.J_r[half], rel=1e-12)
    # ΔT closes over the cycle and the flywheel sees it all
    assert d2.dT[-1] == pytest.approx(0.0, abs=1e-9 * float(np.max(np.abs(d2.A_r))))
    if s.flywheel is not None:
        assert s.flywheel.delta_actual == pytest.approx(s.flywheel.delta, rel=0.05)
    assert s.scales.phi == pytest.approx(2 * TWO_PI / s.scales.axis_mm)


def test_the_engine_example():
    d = data("engine_4stroke")
    m, s = sheet2(d)
    check_cycle(d, m, s)
    # a motor: the gas gives work, M_d is the moment taken off the crank (negative in the sense of rotation)
    assert s.dynamics.M_d < 0
    assert any(n.code == "dynamics_motor" for n in s.notes)
    assert [p.label for p in s.positions] == [str(j) for j in range(24)]
    # position 0 at the top dead centre: the expansion's first pressure, 5.1 MPa on the 90 mm bore
    f0 = next(f for f in s.loading.forces if f.kind == "load").f
    assert abs(f0[0]) == pytest.approx(5.1e6 * 0.0063617, rel=1e-9)
    assert abs(f0[12]) == pytest.approx(0.02e6 * 0.0063617, rel=1e-9)  # a turn later: the intake begins


@pytest.mark.parametrize("start", [0.0, 135.0, 200.0, 300.0])
def test_start_deg_puts_the_cycle_at_the_first_top_dead_centre_after_position_0(start):
    d = data("engine_4stroke")
    d["crank"]["start_deg"] = start
    d["gravity"] = False
    m, s = sheet2(d)
    check_cycle(d, m, s)


def test_a_one_turn_load_beside_a_two_turn_one():
    """The V compressor with its right cylinder made a four-stroke one: the cycle is 720°, the left
    cylinder's one-turn diagram works twice in it."""
    d = data("v_compressor")
    d["load"][0]["pressure"] = [[0.6, 0.25, 0.0, -0.01, -0.01, -0.01, -0.01, -0.01],
                                [0.0] * 8, [0.0] * 8,
                                [0.6, 0.6, 0.6, 0.6, 0.3, 0.12, 0.04, -0.01]]
    d["crank"]["start_deg"] = 100.0
    m, s = sheet2(d)
    check_cycle(d, m, s)


def test_two_rows_stay_one_turn():
    m, s = sheet2(data("v_compressor"))
    assert s.turns == 1 and s.positions == s.sheet1.cycle.positions and s.kin is s.sheet1.cycle.kin
    assert s.dynamics.travel[-1] == TWO_PI and s.scales.phi == TWO_PI / s.scales.axis_mm


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(r=st.floats(0.02, 0.08), lam=st.floats(0.15, 0.35), ang=st.floats(-180.0, 180.0), e=st.floats(-0.3, 0.3),
       clearance=st.floats(0.05, 0.5), start=st.one_of(st.none(), st.floats(0.0, 359.0)), cw=st.booleans(),
       n=st.integers(3, 8), seed=st.integers(0, 2 ** 31 - 1), gravity=st.booleans())
def test_random_four_stroke_files(r, lam, ang, e, clearance, start, cw, n, seed, gravity):
    """Random offset crank-sliders at any angle, turning either way, position 0 anywhere, random
    travel grids (entries apart enough that the mean of M_b on a 0.02° grid resolves the diagram's
    ramps) and four random rows of pressure."""
    rng = np.random.default_rng(seed)
    l = r / lam
    u = complex(math.cos(math.radians(ang)), math.sin(math.radians(ang)))
    off = e * r * 1j * u  # the guide's line passes e·r beside O
    far = math.sqrt((l + r) ** 2 - (e * r) ** 2)
    head = off + u * (far + clearance * 2 * r)
    inner = (np.arange(1, n - 1) + rng.uniform(-0.3, 0.3, n - 2)) / (n - 1)  # entries ≥ 0.4/(n − 1) apart
    travel = np.concatenate([[0.0], inner, [1.0]]).round(6).tolist()
    pressure = rng.uniform(-0.09, 8.0, (4, n)).round(4).tolist()
    d = {"frame": {"O": [0.0, 0.0]},
         "crank": {"pivot": "O", "joint": "A", "length": r, "rpm": 600, "sense": "cw" if cw else "ccw"},
         "group": [{"kind": "RRP", "joints": ["A", "B"], "length": l,
                    "guide": {"through": [off.real, off.imag], "angle_deg": ang}, "branch": "ahead"}],
         "point": [{"name": "S2", "link": ["A", "B"], "along": 0.3 * l}],
         "mass": [{"link": ["O", "A"], "m": 3.0, "J": 0.01, "centre": "O"},
                  {"link": ["A", "B"], "m": 1.0, "J": 0.005, "centre": "S2"}, {"joint": "B", "m": 0.8}],
         "gravity": gravity,
         "load": [{"on": "B", "head": [head.real, head.imag], "area": 0.005, "travel": travel,
                   "pressure": pressure}],
         "dynamics": {"delta": 0.02}}
    if start is not None:
        d["crank"]["start_deg"] = start
    try:
        m, s = sheet2(d)
    except TmmError:
        assume(False)
    check_cycle(d, m, s)


def _engine(change):
    d = data("engine_4stroke")
    d["load"][0].update(change)
    return d


@pytest.mark.parametrize("d,fragment", [
    (_engine({"pressure": [[0.0] * 14] * 3}), "'load[1].pressure' has 3 rows; give 2"),
    (_engine({"pressure": [[0.0] * 14] * 5}), "'load[1].pressure' has 5 rows; give 2"),
    (_engine({"pressure": [[0.0] * 14] * 3 + [[0.0] * 13]}), "'load[1].pressure' row 4 has 13 values"),
    (_engine({"head": [0.001, 0.2378571]}), "'load[1].head' is 0.001 m off the line of the piston B"),
])
def test_hostile_four_stroke_files(d, fragment):
    from tmm_cli.i18n.errors import translate_error

    with pytest.raises(TmmError) as err:
        sheet2(d)
    text = str(err.value)
    assert "\n" not in text and text.startswith("m.toml: ") and fragment in text, text
    ru = translate_error(text)
    assert ru != text and any("а" <= ch <= "я" for ch in ru), ru


# --- the JSON, the sheets and the note ----------------------------------------------------------


def test_the_json_lists_both_turns(tmp_path):
    """`tmm linkage --json`: 2·N positions in the order the crank turns, phi_deg the crank angle (+ 360°
    in the second turn: 0 … 720), travel_deg from position 0, each turn's kinematics the first's; the
    balancing moment of every position from its own applied forces' powers (recomputed here)."""
    import json

    from cli_helpers import run

    r = run("linkage", EXAMPLES / "engine_4stroke.toml", "--json", "--no-plots", "--out", tmp_path)
    assert r.exit_code == 0, r.output
    doc = json.loads(r.output)
    pos = doc["positions"]
    assert doc["cycle"] == {"turns": 2, "cycle_deg": 720, "positions_per_turn": 12} and len(pos) == 24
    assert [p["index"] for p in pos] == list(range(24)) and [p["label"] for p in pos] == [str(j) for j in range(24)]
    assert all(0.0 <= p["phi_deg"] < 720.0 for p in pos)
    assert [p["turn"] for p in pos] == [1] * 12 + [2] * 12
    # phi_deg as the crank has turned over the cycle: 30° on at each position (the crank turns ccw), passing
    # 720 → 0 once (as a turn's angle passes 360 → 0); the crank link's own angle is phi_deg mod 360; no 1e-13
    sense = {"ccw": 1, "cw": -1}[doc["crank"]["sense"]]
    steps = [(b["phi_deg"] - a["phi_deg"]) % 720.0 for a, b in zip(pos, pos[1:] + pos[:1])]
    assert steps == pytest.approx([(sense * 30.0) % 720.0] * 24, abs=1e-9)
    assert sum(b["phi_deg"] < a["phi_deg"] for a, b in zip(pos, pos[1:])) <= 1
    assert [p["phi_deg"] for p in pos[:10]] == pytest.approx([90.0 + 30.0 * j for j in range(10)], abs=1e-9)
    assert pos[9]["phi_deg"] == 360.0 and pos[21]["phi_deg"] == 0.0
    assert all(p["phi_deg"] == 0.0 or abs(p["phi_deg"]) > 1e-9 for p in pos)
    for p in pos:
        d_ = (p["phi_deg"] - p["links"]["OA"]["angle_deg"]) % 360.0
        assert min(d_, 360.0 - d_) < 1e-9
    for a, b in zip(pos[:12], pos[12:]):
        assert b["travel_deg"] == pytest.approx(a["travel_deg"] + 360.0, abs=1e-9)
        assert b["points"] == a["points"] and b["links"] == a["links"]
        assert b["reduced"]["inertia_kgm2"] == a["reduced"]["inertia_kgm2"]
    assert [p["travel_deg"] for p in pos] == pytest.approx([30.0 * j for j in range(24)], abs=1e-9)
    # the gas force of each position: expansion in the first half turn, intake a turn later
    d = data("engine_4stroke")
    ld = d["load"][0]
    area, t, rows = ld["area"], ld["travel"], np.array(ld["pressure"])
    for j in (1, 2, 4, 13, 14, 16, 19, 22):
        y = pos[j]["points"]["B"]["y"]
        vy = pos[j]["points"]["B"]["vy"]
        x = (0.225 - y) / 0.09  # s/H from the top dead centre (r + l = 0.225 m)
        row = 2 * (j // 12) + (1 if vy > 0 else 0)  # moving up: towards the head
        p = np.interp(x, t, rows[row])
        assert pos[j]["applied_forces"]["P3"]["force"][1] == pytest.approx(-p * 1e6 * area, rel=1e-9, abs=1e-6)
        # M_b from the powers of the applied forces at this position (no reaction works)
        power = 0.0
        for f in pos[j]["applied_forces"].values():
            pt = pos[j]["points"][f["at"]] if f["at"] in pos[j]["points"] else None
            if pt is None:
                continue
            power += f["force"][0] * pt["vx"] + f["force"][1] * pt["vy"]
        # the crank's weight acts at O (still) and the rod's inertia moment: add M·ω
        power += sum(m * pos[j]["links"]["AB"]["omega"] for k, m in pos[j]["applied_moments_Nm"].items() if k.endswith("2"))
        assert pos[j]["balancing_moment_Nm"] == pytest.approx(-power / doc["crank"]["omega_rad_s"], rel=1e-6, abs=1e-6)
    assert doc["forces"]["turn"] == 1 and doc["forces"]["gas"][0]["turns"] == 2
    assert doc["dynamics"]["drive_moment_Nm"] == pytest.approx(
        -loop_work(ld, 0.09) / (4 * math.pi), rel=1e-9)


def test_the_note_explains_the_two_turns():
    """The note's chapter 2: why two turns, the four rows of the diagram, the loop's work equal to
    A_r(720°), M_д = |A_с|/(4π); every substitution of chapters 1–2 reproduces."""
    from tmm_cli.project import analyse_linkage, run_project
    from tmm_cli.render.note import build_note
    from tmm_cli.render.note.markdown import markdown
    from tmm_cli.variants import get_variant

    s2 = analyse_linkage(data("engine_4stroke"), "engine_4stroke.toml")
    doc = build_note(run_project(get_variant("17"), linkage=s2, linkage_name="engine_4stroke.toml"), "ru", {})
    text = markdown(doc, "note")
    assert "повторяется лишь через два оборота кривошипа (720°)" in text
    assert "положения второго оборота нумеруются дальше, 12 … 23" in text
    for word in ("расширение (от крышки)", "выпуск (к крышке)", "впуск (от крышки)", "сжатие (к крышке)"):
        assert word in text
    assert "(первый оборот цикла)" in text and "/(4 π)" in text
    assert "Двигатель четырёхтактный: его рабочий цикл занимает два оборота кривошипа" in text  # chapter 1
    work = loop_work(data("engine_4stroke")["load"][0], 0.09)
    assert s2.dynamics.A_r[-1] == pytest.approx(work, rel=1e-6)


def test_the_dynamics_csv_runs_over_720(tmp_path):
    """linkage_dynamics.csv: the 0.5° grid over both turns; J_r repeats, ΔT closes, A_r ends at the loop's work."""
    import csv

    from cli_helpers import run

    r = run("linkage", EXAMPLES / "engine_4stroke.toml", "--no-plots", "--out", tmp_path)
    assert r.exit_code == 0, r.output
    rows = list(csv.DictReader((tmp_path / "linkage" / "linkage_dynamics.csv").open(encoding="utf-8")))
    assert len(rows) == 1441
    travel = np.array([float(x["travel_deg"]) for x in rows])
    assert travel[0] == 0.0 and travel[-1] == pytest.approx(720.0) and np.allclose(np.diff(travel), 0.5)
    jr = np.array([float(x["J_r_kgm2"]) for x in rows])
    assert np.array_equal(jr[1:721], jr[721:])
    assert all(0.0 <= float(x["phi_deg"]) < 360.0 for x in rows)
    assert float(rows[-1]["A_r_J"]) == pytest.approx(loop_work(data("engine_4stroke")["load"][0], 0.09), rel=1e-9)
    assert abs(float(rows[-1]["dT_J"])) < 1e-6


def test_sheet2_draws_the_cycle_over_720(tmp_path):
    """Sheet 2's diagrams: the positions of both turns numbered 0 … 23 under them, 360° and 720° marked,
    μ_φ for 720° on the same axis; everything inside the frame."""
    from test_sheets import FRAME, TITLE, check_layout, reopen

    from tmm_cli.render.sheets.dynamics_sheet import sheet2 as build

    _, s = sheet2(data("engine_4stroke"))
    doc = reopen(build(s, "ru", TITLE), tmp_path, "sheet2")
    assert {"lever", "dynamics_diagrams", "wittenbauer"} <= set(check_layout(doc))
    texts = [e.dxf.text for e in doc.modelspace().query("TEXT")]
    for e in doc.modelspace().query("TEXT"):
        assert FRAME[0] <= e.dxf.insert[0] <= FRAME[2] and FRAME[1] <= e.dxf.insert[1] <= FRAME[3], e.dxf.text
    assert {str(j) for j in range(24)} <= set(texts) and "360°" in texts and "720°" in texts
    mtexts = " ".join(e.text for e in doc.modelspace().query("MTEXT")) + " ".join(texts)
    assert "720°, цикл из 2 оборотов" in mtexts  # the caption (the DXF writes … as ...)
    assert math.degrees(s.scales.phi) * s.scales.axis_mm == pytest.approx(720.0)


@pytest.mark.parametrize("start", [None, 250.0])
def test_a_table_load_repeats_each_turn_of_the_cycle(start):
    """A stroke/force table beside the four-stroke gas load (a pump on the piston's rod): it acts on each
    turn's working stroke, so over the 720° cycle its work is twice −H·(area under its table); mean M_b = M_d."""
    d = data("engine_4stroke")
    d["load"].append({"on": "B", "stroke": [0.0, 0.5, 1.0], "force": [0.0, 800.0, 400.0], "working": "towards"})
    if start is not None:
        d["crank"]["start_deg"] = start
    m, s = sheet2(d)
    assert s.turns == 2 and s.input.load is not None
    table = -2 * 0.09 * float(np.sum(np.diff([0.0, 0.5, 1.0]) * (np.array([0.0, 800.0]) + np.array([800.0, 400.0])) / 2))
    gas = loop_work(d["load"][0], 0.09)
    assert s.dynamics.A_r[-1] == pytest.approx(gas + table, rel=1e-9)
    k = 36000
    t = (np.arange(k) + 0.5) * 2 * TWO_PI / k
    kk = solve(m, s.sheet1.cycle.start + m.crank.sense * t)
    mb = balancing_moment_by_power(kk, applied(m, s.input, s.stroke, kk))
    assert float(np.mean(mb)) == pytest.approx(s.dynamics.drive_moment_ccw, rel=1e-4)
    scale = float(np.max(np.abs(s.balancing)))
    assert np.max(np.abs(s.balancing - s.power_balance)) <= 1e-8 * scale
    assert np.max(np.abs(s.balancing - s.lever.balancing)) <= 1e-8 * scale


def test_the_note_figure_draws_the_whole_cycle():
    """The note's Figure 3 (M, ΔT, J over φ): the φ axis runs to 720° at a μ_φ that holds it, a dashed line
    ends turn 1, ΔT comes back to 0 at 720°; a one-turn example keeps 0 … 360° at 2,5 °/mm."""
    from tmm_cli.project import analyse_linkage
    from tmm_cli.render.figures import note_scales as S
    from tmm_cli.render.figures.note import note_figure_of, note_style

    for name, end in (("engine_4stroke", 720.0), ("four_bar", 360.0)):
        s2 = analyse_linkage(data(name), f"{name}.toml")
        sc = S.dynamics_scales(s2)
        assert sc.phi.mu * sc.phi.mm == pytest.approx(end) and sc.phi.mm <= S.DYNAMICS["x"][1]
        with note_style():
            fig = note_figure_of("linkage_dynamics", s2, "ru")
            ax_m, ax_t, ax_j = sorted(fig.axes, key=lambda a: -a.get_position().y0)[:3]
            for ax in (ax_m, ax_t, ax_j):
                assert ax.get_xlim()[1] == pytest.approx(end)
                dashed = [ln for ln in ax.get_lines() if ln.get_linestyle() == "--" and
                          np.allclose(ln.get_xdata(), 360.0)]
                assert len(dashed) == (end > 360.0)
            dT = next(ln for ln in ax_t.get_lines() if ln.get_label() == "Δ$T$")
            x, y = np.asarray(dT.get_xdata()), np.asarray(dT.get_ydata())
            assert x[-1] == pytest.approx(end) and x.max() == pytest.approx(end)
            assert abs(y[-1]) < 1e-6 * max(1.0, float(np.abs(y).max()))
            r = fig.canvas.get_renderer()
            for ax in (ax_m, ax_t, ax_j):  # each panel's μ box clear of its legend
                leg = ax.get_legend().get_window_extent(r)
                mus = [t.get_window_extent(r) for t in ax.texts if "μ" in t.get_text()]
                assert mus and not any(m.overlaps(leg) for m in mus), ax.get_ylabel()
            ticks = list(ax_j.get_xticks())
            assert ticks[-1] == pytest.approx(end) and len(ticks) == (25 if end > 360 else 13)
            import matplotlib.pyplot as plt
            plt.close(fig)


def _engine_note(name="engine_4stroke", lang="ru"):
    from tmm_cli.project import analyse_linkage, run_project
    from tmm_cli.render.note import build_note
    from tmm_cli.render.note.markdown import markdown
    from tmm_cli.variants import get_variant

    s2 = analyse_linkage(data(name), f"{name}.toml")
    return s2, markdown(build_note(run_project(get_variant("17"), linkage=s2, linkage_name=f"{name}.toml"), lang, {}),
                        "note")


def _num(x: str) -> float:
    return float(x.replace("−", "-").replace(",", ".").replace("\u00a0", "").replace(" ", ""))


def test_the_note_formulas_give_its_table_of_the_reduction():
    """The engine's chapter 2.4: the printed M_с = |A_д|/(4π) and ΔT = A_д − M_с Δφ, substituted at every position
    with the table's own A_д column, give the table's ΔT (to its rounding); −M_с is the figure's constant line."""
    import re

    s2, text = _engine_note()
    assert "Δ T = A<sub>д</sub> + A<sub>с</sub> = A<sub>д</sub> − M<sub>с</sub> Δ φ" in text
    m = re.search(r"M<sub>с</sub> = \|A<sub>д</sub>\|/\(4 π\) = ([\d,]+)/\(4 π\) = ([\d,]+) Н·м", text)
    assert m, "the formula of M_с"
    mc = _num(m.group(2))
    assert mc == pytest.approx(_num(m.group(1)) / (4 * math.pi), abs=1e-3)
    head = text.index("| № | Δ φ, ° | M<sub>пр</sub>, Н·м | J<sub>пр</sub>, кг·м² | A<sub>д</sub>, Дж | Δ T, Дж |")
    rows = []
    for line in text[head:].splitlines()[2:]:
        if not line.startswith("|"):
            break
        rows.append([_num(c) for c in line.strip("|").split("|")])
    assert len(rows) == 25  # 24 positions and the cycle's end
    for _, phi, _, _, a, dt in rows:
        assert a - mc * math.radians(phi) == pytest.approx(dt, abs=0.02), phi
    assert rows[-1][1] == 720.0 and rows[-1][5] == pytest.approx(0.0, abs=0.01)
    assert mc == pytest.approx(-s2.dynamics.M_d, abs=1e-3)


def test_an_engine_is_said_to_drive_its_consumer(tmp_path):
    """A machine-motor in the book's roles: the gas forces drive (A_д), the constant moment is the consumer's
    resisting moment M_с — in the note and in sheet 2's main results; sheet 4's motor choice says what it assumes.
    The V compressor (a machine-consumer) keeps the driving moment of its motor."""
    from test_sheets import TITLE, reopen

    from tmm_cli.render.sheets.dynamics_sheet import sheet2 as build

    text = _engine_note()[1].replace("\u00a0", " ")
    assert "момент сопротивления потребителя, приведённый к кривошипу" in text
    assert "M<sub>с</sub> = |A<sub>д</sub>|/(4 π)" in text and "M<sub>д</sub> = |A" not in text
    assert "A<sub>д</sub> = A<sub>P 3</sub> = 700,04 Дж" in text  # one term, not «= 700,04 = 700,04»
    assert "двигатель его притормаживает" not in text and "определяется мощность двигателя" not in text
    assert "момент сопротивления потребителя M<sub>с</sub> = 55,71 Н·м" in text  # the abstract
    assert "выбор электродвигателя ниже — лишь формальная проверка" in text  # the gear chapter
    assert "За цикл из двух оборотов Δ T<sub>I</sub> наибольшее" in text and "За оборот Δ T" not in text
    assert "С маховиком угловая скорость кривошипа за цикл из двух оборотов изменяется" in text
    _, comp = _engine_note("v_compressor")
    assert "M<sub>д</sub> = |A<sub>с</sub>|/(2 π)" in comp and "определяется мощность двигателя" in comp
    assert "потребител" not in comp
    for name, engine in (("engine_4stroke", True), ("v_compressor", False)):
        _, s = sheet2(data(name))
        doc = reopen(build(s, "ru", TITLE), tmp_path, f"sheet2-{name}")
        words = " ".join(e.dxf.text for e in doc.modelspace().query("TEXT")) + " ".join(
            e.text for e in doc.modelspace().query("MTEXT"))
        assert ("Момент сопротивления потребителя" in words) == engine, name
        assert ("Движущий момент" in words) != engine, name



def test_the_terminal_names_an_engines_constant_moment_the_consumers_resistance():
    """An engine's terminal table says what sheet 2 and the note say: the constant moment is the
    consumer's resistance M_с = A·H·∮p dx/(4π) > 0, printed positive (a compressor keeps «Движущий
    момент»)."""
    import re

    from cli_helpers import run

    for name, word, other in (("engine_4stroke", "Момент сопротивления потребителя M_с", "Движущий момент M_д"),
                              ("v_compressor", "Движущий момент M_д", "Момент сопротивления потребителя")):
        res = run("linkage", EXAMPLES / f"{name}.toml", "--lang", "ru", "--no-plots")
        assert res.exit_code == 0, res.output
        text = " ".join(res.output.split())
        assert word in text and other not in text, name
        # the reactions table's M_ур: the consumer's moment for an engine, the motor's for a compressor
        assert ("M_ур — момент потребителя на кривошипе" in text) == (name == "engine_4stroke"), name
        assert ("M_ур — момент двигателя на кривошипе" in text) == (name != "engine_4stroke"), name
        if name == "engine_4stroke":
            d = data(name)
            m = parse_mechanism(d, "m.toml")
            ld = next(ld for ld in d["load"] if "pressure" in ld)
            H, _, _ = piston_geometry(m, ld, 0.0)  # the stroke does not depend on where the turn starts
            printed = float(re.search(word + r"[^│]*│ ([\d,]+) Н·м", text).group(1).replace(",", "."))
            assert printed == pytest.approx(loop_work(ld, H) / (4 * math.pi), abs=2e-3)
