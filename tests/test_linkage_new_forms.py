"""The new forms of the mechanism file (issue 34): an RPR whose slot passes at an offset from the
pivot, …

Independent checks, not restatements: the positions against the constraints rebuilt from the
exported points (the slot's distance from the pivot, the rigid links); the velocities and
accelerations against central differences of the positions at 0.1° of crank turn; every plan's
vectors join their points and add up; the force analysis against the power balance and
Zhukovsky's lever; every link in equilibrium with its reactions; the example end to end; hostile
files."""

import math
import tomllib
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from tmm_cli.errors import TmmError
from tmm_cli.linkage.chain import solve
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.motion import cross
from tmm_cli.linkage.positions import cycle
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2
from tmm_cli.linkage.vector_plans import plans
from linkage_check import assert_every_link_in_equilibrium

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
NEW = ("shaper_offset", "rocking_block", "tangent", "scotch_yoke", "v_compressor", "engine_4stroke")


def data(name):
    return tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))


def load(name):
    return parse_mechanism(data(name), f"{name}.toml")


_S2 = {}


def sheet2(name):
    if name not in _S2:
        m = load(name)
        _S2[name] = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m, name))
    return _S2[name]


# --- kinematics ---------------------------------------------------------------------------------


@pytest.mark.parametrize("name", NEW)
def test_velocities_and_accelerations_are_derivatives_of_the_positions(name):
    """Central differences of the closed-form positions at h = 0.1° of crank turn."""
    _check_derivatives(load(name))


VARIANTS = [  # a guide off the slotted link's axis, turned from it; an offset slot carrying it; on the crank
    {"group": {1: {"guide": {"link": ["O2", "A"], "along": 0.1, "across": 0.02, "angle_deg": 8.0}}}},
    {"group": {0: {"offset": -0.02}, 1: {"guide": {"link": ["O2", "A"], "across": -0.02}}}},
    {"group": {1: {"guide": {"link": ["O1", "A"], "along": 0.05, "angle_deg": 60.0}, "length": 0.35}},
     "frame": {"D": [0.0, 0.25]}, "output": "B", "load": {"on": "B", "stroke": [0.0, 1.0], "force": [100.0, 100.0]}},
]


def _variant(change):
    d = data("rocking_block")
    for i, g in change.get("group", {}).items():
        d["group"][i].update(g)
    d["frame"].update(change.get("frame", {}))
    for key in ("output", "load"):
        if key in change:
            d[key] = change[key]
    return d


@pytest.mark.parametrize("k", range(len(VARIANTS)))
def test_moving_guides_and_offsets_three_ways(k):
    m = parse_mechanism(_variant(VARIANTS[k]), "m.toml")
    cycle(m, "m.toml")  # it can be assembled over the turn
    _check_derivatives(m)
    s = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m, "m.toml"))
    scale = float(np.max(np.abs(s.balancing)))
    assert np.max(np.abs(s.balancing - s.power_balance)) <= 1e-9 * scale
    assert np.max(np.abs(s.balancing - s.lever.balancing)) <= 1e-9 * scale
    assert s.dynamics.dT[-1] == pytest.approx(0.0, abs=1e-9 * abs(s.dynamics.A_r[-1]))


def _check_derivatives(m):
    w1 = m.crank.omega
    phi = np.linspace(0.0, 2 * math.pi, 73)[:-1] + 0.01
    h = math.radians(0.1)
    km, k0, kp = (solve(m, phi + d) for d in (-h, 0.0, h))
    dt = h / w1
    for n in k0.z:
        if n in m.frame:
            continue
        scale_v = float(np.max(np.abs(k0.v[n]))) + 1e-9
        scale_a = float(np.max(np.abs(k0.a[n]))) + 1e-9
        v_fd = (kp.z[n] - km.z[n]) / (2 * dt)
        a_fd = (kp.z[n] - 2 * k0.z[n] + km.z[n]) / dt ** 2
        assert np.max(np.abs(v_fd - k0.v[n])) <= 1e-5 * scale_v + 1e-12, n
        assert np.max(np.abs(a_fd - k0.a[n])) <= 1e-4 * scale_a + 1e-9, n
    for ln in k0.angle:
        d1 = np.remainder(kp.angle[ln] - km.angle[ln] + math.pi, 2 * math.pi) - math.pi
        d2 = (np.remainder(kp.angle[ln] - k0.angle[ln] + math.pi, 2 * math.pi) - math.pi
              - (np.remainder(k0.angle[ln] - km.angle[ln] + math.pi, 2 * math.pi) - math.pi))
        sw = float(np.max(np.abs(k0.omega[ln]))) + abs(w1)
        se = float(np.max(np.abs(k0.epsilon[ln]))) + w1 * w1
        assert np.max(np.abs(d1 / (2 * dt) - k0.omega[ln])) <= 1e-5 * sw, ln
        assert np.max(np.abs(d2 / dt ** 2 - k0.epsilon[ln])) <= 1e-4 * se, ln
    for ln, (s, ds, dds) in k0.slide.items():
        sp, sm = kp.slide[ln][0], km.slide[ln][0]
        assert np.max(np.abs((sp - sm) / (2 * dt) - ds)) <= 1e-5 * (np.max(np.abs(ds)) + 1e-9), ln
        assert np.max(np.abs((sp - 2 * s + sm) / dt ** 2 - dds)) <= 1e-4 * (np.max(np.abs(dds)) + 1e-9), ln


def test_the_offset_slot_keeps_its_distance_from_the_pivot():
    """From the exported points only: B lies on the slot's line (across = d), so the line through
    the block's joint A and B passes |d| from the pivot O2 at every crank angle; the slotted
    link's points stay rigid; d = 0 gives today's RPR exactly."""
    m = load("shaper_offset")
    d = m.groups[0].offset
    assert d == 0.03
    k = solve(m, np.linspace(0, 2 * math.pi, 361))
    a, b, c, s3 = k.z["A"], k.z["B"], k.z["O2"], k.z["S3"]
    dist = cross(b - a, c - a) / np.abs(b - a)
    assert np.allclose(np.abs(dist), d, rtol=0, atol=1e-12)
    assert np.allclose(np.abs(b - c), math.hypot(0.5, 0.03), atol=1e-12)
    assert np.allclose(np.abs(s3 - c), 0.25, atol=1e-12)
    assert np.allclose(np.abs(b - s3), math.hypot(0.25, 0.03), atol=1e-12)
    # the block's slide t: its distance along the slot from the foot of the perpendicular from O2
    t = k.slide["A"][0]
    assert np.allclose(t, np.sqrt(np.abs(a - c) ** 2 - d * d), atol=1e-12)
    # the slotted link's angle is the slot's direction u: A − O2 = (t + i·d)·u
    u = np.exp(1j * k.angle["AO2"])
    assert np.allclose(a - c, (t + 1j * d) * u, atol=1e-12)
    # offset = 0 is the RPR through the pivot, number for number
    plain = data("shaper")
    zero = data("shaper")
    zero["group"][0]["offset"] = 0.0
    k0, k1 = solve(parse_mechanism(plain), k.phi), solve(parse_mechanism(zero), k.phi)
    for n in k0.z:
        assert np.array_equal(k0.z[n], k1.z[n]) and np.array_equal(k0.a[n], k1.a[n])


def test_the_pressure_angle_of_an_offset_slot():
    m = load("shaper_offset")
    c = cycle(m)
    p = c.curve.pressure[1]
    t = c.curve.kin.slide["A"][0]
    assert np.allclose(p, np.arctan(0.03 / t), atol=1e-12)


@pytest.mark.parametrize("name", NEW)
def test_every_plan_adds_up(name):
    s1 = analyse_mechanism(load(name))
    for i in range(len(s1.cycle.positions)):
        pl = plans(s1.cycle, i)
        for plan in (pl.velocity, pl.acceleration):
            for vec in plan.vectors:
                if vec.start in plan.points and vec.end in plan.points:
                    assert abs(plan.points[vec.end] - plan.points[vec.start] - vec.value) <= 1e-9 * (
                        max(abs(x) for x in plan.points.values())), (i, vec.symbol)
    # the Coriolis vector of the offset slot: 2·ω3 × v_A3A2, v_A3A2 = −ṫ·u (the slot under the block)
    pl = plans(s1.cycle, 2)
    m = s1.mechanism
    k = s1.cycle.kin.at(2)
    if m.groups[0].kind == "RPR":
        cor = next(v for v in pl.acceleration.vectors if v.symbol.startswith("a^k"))
        g = m.groups[0]
        t = k.slide[g.links[0]][0][0]
        u = (k.z[g.joints[0]][0] - k.z[g.joints[1]][0]) / (t + 1j * g.offset)  # the slot towards the block
        w3 = k.omega[g.links[1]][0]
        vrel = k.slide[g.links[0]][1][0]
        assert cor.value == pytest.approx(-2j * w3 * vrel * u, abs=1e-12)


# --- sheet 2 ------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", NEW)
def test_force_analysis_power_balance_and_zhukovsky_agree(name):
    s = sheet2(name)
    mb = s.balancing
    scale = float(np.max(np.abs(mb)))
    assert scale > 1.0
    k = s.kin  # the cycle's positions (a four-stroke engine: both turns)
    power = np.zeros(len(mb))
    for f in s.loading.forces:
        v, _ = k.body_point(f.link, f.z)
        power += f.f.real * v.real + f.f.imag * v.imag
    for c in s.loading.couples:
        power += c.m * k.omega[c.link]
    assert np.max(np.abs(mb + power / k.omega1)) <= 1e-9 * scale
    assert np.max(np.abs(mb - s.lever.balancing)) <= 1e-9 * scale


@pytest.mark.parametrize("name", NEW)
def test_every_link_is_in_equilibrium_with_its_reactions(name):
    s = sheet2(name)
    m, k = s.sheet1.mechanism, s.sheet1.cycle.kin
    assert_every_link_in_equilibrium(s, name)
    # the block presses across the offset slot: R23 ⊥ u
    for g in m.groups:
        if g.kind == "RPR":
            r23 = s.forces.reaction(f"R{g.numbers[0]}{g.numbers[1]}").force
            u = np.exp(1j * k.angle[g.links[1]])
            assert np.max(np.abs((np.conj(u) * r23).real)) <= 1e-9 * np.max(np.abs(r23))


@pytest.mark.parametrize("name", NEW)
def test_the_cycle_closes(name):
    s = sheet2(name)
    d = s.dynamics
    assert d.dT[-1] == pytest.approx(0.0, abs=1e-9 * abs(d.A_r[-1]))
    assert s.flywheel is None or s.flywheel.J > 0


# --- files --------------------------------------------------------------------------------------


@pytest.mark.parametrize("change,fragment", [
    ({"offset": 0.3}, "group 1 (RPR A-O2) cannot be assembled"),
    ({"offset": "a"}, "'group[1].offset' must be a number"),
    ({"offset": 1000.0}, "'group[1].offset' is 1000; a coordinate must lie in"),
])
def test_hostile_offsets(change, fragment):
    d = data("shaper_offset")
    d["group"][0].update(change)
    with pytest.raises(TmmError) as err:
        cycle(parse_mechanism(d, "m.toml"), "m.toml")
    text = str(err.value)
    assert "\n" not in text and text.startswith("m.toml: ") and fragment in text, text


# --- end to end: tmm project --mechanism, the note's chapters 1 and 2 ---------------------------


@pytest.mark.parametrize("name", NEW)
def test_project_end_to_end(name, tmp_path):
    import json

    from cli_helpers import run

    r = run("project", "-v", 17, "--mechanism", EXAMPLES / f"{name}.toml", "--no-plots", "--report", "md",
            "--out", tmp_path, "--lang", "ru")
    assert r.exit_code == 0, r.output
    folder = tmp_path / "variant-17"
    for n in (1, 2, 3, 4):
        assert (folder / f"sheet{n}.dxf").stat().st_size > 10000 and (folder / f"sheet{n}.pdf").is_file()
    doc = json.loads((folder / "linkage.json").read_text(encoding="utf-8"))
    assert max(abs(p["zhukovsky_difference_pct"]) for p in doc["positions"]) < 1e-6
    assert doc["dynamics"]["motor_moment_Nm"] > 0


@pytest.mark.parametrize("name", NEW)
def test_the_notes_chapters_reproduce_every_substitution(name):
    from tmm_cli.project import analyse_linkage, run_project
    from tmm_cli.render.note import build_note
    from tmm_cli.render.note.mathsyntax import check_line
    from tmm_cli.render.note.model import Formula, Heading
    from tmm_cli.variants import get_variant

    s2 = analyse_linkage(data(name), f"{name}.toml")
    doc = build_note(run_project(get_variant("17"), linkage=s2, linkage_name=f"{name}.toml"), "ru", {})
    assert doc.off == []
    inside, checked = False, 0
    for b in doc.blocks:
        if isinstance(b, Heading) and b.level == 1:
            inside = b.label in ("linkage", "dynamics")
        if inside and isinstance(b, Formula):
            for c in check_line(b.math):
                checked += 1
                assert c.ok, f"{c.text} {c.relation} {c.target} in: {b.math}"
    assert checked > 20


def _moving(change=None, top=None, drop=None):
    d = data("rocking_block")
    if change:
        d["group"][1]["guide"] = change
    if top:
        d.update(top)
    for k in drop or ():
        d.pop(k)
    return d


@pytest.mark.parametrize("d,fragment", [
    (_moving({"link": ["D", "B"], "along": 0.0}), "'group[2].guide.link': no link joining D and B is placed before"),
    (_moving({"link": ["A", "O2"]}), "'group[2].guide.link': measure a guide on the slotted link AO2 from its pivot"),
    (_moving({"through": [0, 0], "angle_deg": 0, "along": 0.1}), "'group[2].guide.along' places a guide on a moving"),
    (_moving({"link": ["O2", "A"], "through": [0, 0]}), "unknown key 'group[2].guide.through'"),
    (_moving(drop=("output", "load")), "'output' is missing: the slider B of the last group slides on a moving guide"),
    (_moving({"link": ["O2", "A"], "across": 0.5}), "group 2 (RRP D-B) cannot be assembled"),
])
def test_hostile_moving_guides(d, fragment):
    from tmm_cli.i18n.errors import translate_error

    with pytest.raises(TmmError) as err:
        cycle(parse_mechanism(d, "m.toml"), "m.toml")
    text = str(err.value)
    assert "\n" not in text and text.startswith("m.toml: ") and fragment in text, text
    ru = translate_error(text)
    assert ru != text and "ошибка" not in ru and any("а" <= ch <= "я" for ch in ru), ru


def test_a_slider_on_a_moving_guide_turns_with_it():
    """The slider's ω, ε are its guide's link's; its J counts in the reduced inertia; B stays on the
    slotted link's line (the guide along it) — from the exported points."""
    s = sheet2("rocking_block")
    k = s.sheet1.cycle.curve.kin
    assert np.array_equal(k.omega["B"], k.omega["AO2"]) and np.array_equal(k.epsilon["B"], k.epsilon["AO2"])
    a, b, o2 = k.z["A"], k.z["B"], k.z["O2"]
    assert np.max(np.abs(cross(a - o2, b - o2)) / np.abs(a - o2)) < 1e-12
    assert np.allclose(np.abs(b - k.z["D"]), 0.30, atol=1e-12)
    # the slider's J·ω² is in J_r: drop it and J_r falls by exactly J·(ω/ω1)²
    from tmm_cli.linkage.power import reduced_inertia

    masses = s.input.masses
    jb = next(ms for ms in masses if ms.link == "B")
    assert jb.J == 0.002
    full = reduced_inertia(k, masses)
    without = reduced_inertia(k, [replace(ms, J=0.0) if ms.link == "B" else ms for ms in masses])
    assert np.allclose(full - without, 0.002 * (k.omega["B"] / k.omega1) ** 2, rtol=1e-12, atol=1e-15)
    assert np.max(full - without) > 1e-6


def _kind(name, group, change=None, top=None, drop=()):
    d = data(name)
    g = d["group"][group]
    for k in drop:
        g.pop(k, None)
    g.update(change or {})
    d.update(top or {})
    return d


@pytest.mark.parametrize("d,fragment", [
    (_kind("tangent", 1, {"guides": [{"through": [0, 0], "angle_deg": 90}, {"through": [0, 0.22], "angle_deg": 0}]}),
     "group 2 (PRP B) has both guides fixed; it would not move"),
    (_kind("tangent", 1, {"guides": [{"link": ["O2", "A"]}]}), "'group[2].guides' must be a list of the two blocks"),
    (_kind("tangent", 1, {"guides": [{"link": ["O2", "A"]}, {"through": [0, 0.22], "angle_deg": 90}]}),
     "group 2 (PRP-B) cannot be assembled".replace("PRP-B", "PRP B")),
    (_kind("tangent", 1, {"joints": ["B", "C"]}), "'group[2].joints' must be a list of 1 joint names"),
    (_kind("scotch_yoke", 0, {"slot_deg": 180.0}), "'group[1].slot_deg' is 180: the yoke's slot would run along"),
    (_kind("scotch_yoke", 0, {"guide": {"link": ["O", "A"], "angle_deg": 90}}),
     "'output' is missing: the block Y of the last group slides on a moving guide"),
    (_kind("scotch_yoke", 0, {"kind": "RPQ"}), "'group[1].kind' is 'RPQ'; the kinds are RRR, RRP, RPR, PRP and RPP"),
])
def test_hostile_prp_and_rpp(d, fragment):
    from tmm_cli.i18n.errors import translate_error

    with pytest.raises(TmmError) as err:
        cycle(parse_mechanism(d, "m.toml"), "m.toml")
    text = str(err.value)
    assert "\n" not in text and text.startswith("m.toml: ") and fragment in text, text
    ru = translate_error(text)
    assert ru != text and any("а" <= ch <= "я" for ch in ru), ru


def test_the_tangent_and_the_sine_laws():
    """By hand: the tangent mechanism's ram at x_B = 0.52·tg ψ (ψ the slotted link's angle from the
    vertical, B on y = 0.22); the Scotch yoke's x_Y = r·cos φ, v = −rω·sin φ, a = −rω²·cos φ; kinds 4 and 5."""
    from tmm_cli.linkage.structure import structure

    m = load("tangent")
    k = solve(m, np.linspace(0, 2 * math.pi, 97))
    a, o2 = k.z["A"], k.z["O2"]
    tan_psi = (a - o2).real / (a - o2).imag
    assert np.allclose(k.z["B"].real, 0.52 * tan_psi, atol=1e-12) and np.allclose(k.z["B"].imag, 0.22, atol=1e-12)
    assert structure(m).groups[2].kind == 4
    y = load("scotch_yoke")
    phi = np.linspace(0, 2 * math.pi, 97)
    k = solve(y, phi)
    w = y.crank.omega
    assert np.allclose(k.z["Y"], 0.05 * np.cos(phi), atol=1e-12)
    assert np.allclose(k.v["Y"], -0.05 * w * np.sin(phi), atol=1e-12)
    assert np.allclose(k.a["Y"], -0.05 * w * w * np.cos(phi), atol=1e-9)
    assert np.allclose(k.slide["A"][0], 0.05 * np.sin(phi), atol=1e-12)  # the block up the slot
    assert structure(y).groups[1].kind == 5


# --- gas forces from indicator diagrams ([[load]] with head) -----------------------------------


def _gas_sheet2(d):
    m = parse_mechanism(d, "m.toml")
    return m, analyse_sheet2(analyse_mechanism(m, source="m.toml"), parse_sheet2(m, "m.toml"), "m.toml")


@pytest.mark.parametrize("start", [None, 100.0])
def test_gas_forces_from_the_indicator_diagrams(start):
    """Independently of tmm's gas module: the piston's distance from its head from the kinematics, its
    stroke H from a dense grid, the row from the sign of its velocity, the pressure by numpy's
    interpolation; the cycle's work = −Σ A·H·(area under the back row − under the away row); the mean
    M_b over the turn equals M_d; position 0 at piston B's dead centre nearest its head."""
    from scipy.integrate import trapezoid

    d = data("v_compressor")
    if start is not None:
        d["crank"]["start_deg"] = start
    m, s = _gas_sheet2(d)
    phi = np.linspace(0.0, 2 * math.pi, 36001)[:-1]
    k = solve(m, phi)
    work = 0.0
    for ld in d["load"]:
        head = complex(*ld["head"])
        q = np.abs(k.z[ld["on"]] - head)
        H = q.max() - q.min()
        assert H == pytest.approx(0.1, rel=1e-6)
        t, p = np.array(ld["travel"]), np.array(ld["pressure"])
        work += ld["area"] * H * 1e6 * (trapezoid(p[0], t) - trapezoid(p[1], t))
        # the force at the sheet's positions: p·A along the cylinder, away from the head
        kp = s.sheet1.cycle.kin
        qp = np.abs(kp.z[ld["on"]] - head)
        away = (kp.z[ld["on"]] - head) / qp
        qdot = (np.conj(away) * kp.v[ld["on"]]).real
        x = (qp - q.min()) / H
        moving = np.abs(qdot) > 1e-6
        want = np.where(qdot > 0, np.interp(x, t, p[0]), np.interp(x, t, p[1])) * 1e6 * ld["area"]
        f = next(f for f in s.loading.forces if f.kind == "load" and f.point == ld["on"]).f
        assert np.allclose(f[moving], (want * away)[moving], rtol=1e-9, atol=1e-6)
    assert s.dynamics.A_r[-1] == pytest.approx(work, rel=1e-9)
    assert s.dynamics.M_d == pytest.approx(-work / (2 * math.pi), rel=1e-9)
    n = 72000
    c = s.sheet1.cycle
    ph = c.start + m.crank.sense * (np.arange(n) + 0.5) * 2 * math.pi / n
    kk = solve(m, ph)
    from tmm_cli.linkage.forces import applied
    from tmm_cli.linkage.power import balancing_moment_by_power

    mb = balancing_moment_by_power(kk, applied(m, s.input, s.stroke, kk))
    assert float(np.mean(mb)) == pytest.approx(s.dynamics.drive_moment_ccw, rel=1e-4)
    if start is None:
        assert c.start_rule == "gas" and math.degrees(c.start) == pytest.approx(45.0, abs=1e-6)
        b = k.z["B"]
        assert abs(complex(solve(m, [c.start]).z["B"][0]) - complex(*d["load"][0]["head"])) == pytest.approx(
            np.min(np.abs(b - complex(*d["load"][0]["head"]))), abs=1e-9)


def _gas(change, i=0):
    d = data("v_compressor")
    d["load"][i].update(change)
    return d


@pytest.mark.parametrize("d,fragment", [
    (_gas({"pressure": [[0.0] * 8] * 3}), "'load[1].pressure' has 3 rows; give 2"),
    (_gas({"pressure": [[0.0] * 8] * 5}), "'load[1].pressure' has 5 rows; give 2 (one turn"),
    (_gas({"pressure": [[0.0] * 8, [0.0] * 7]}), "'load[1].pressure' row 2 has 7 values but 'load[1].travel' has 8"),
    (_gas({"head": [0.3, 0.2]}), "'load[1].head' is"),
    (_gas({"head": [0.15, 0.15]}), "'load[1].head' is reached by the piston B"),
    (_gas({"on": "A"}), "'load[1].on' is 'A': a gas force acts on a piston"),
    (_gas({"travel": [0.0, 0.5, 0.4, 1.0, 1.0, 1.0, 1.0, 1.0]}), "'load[1].travel' must run from 0 to 1"),
    (_gas({"area": 0.0}), "'load[1].area' is 0; the piston's area must lie in"),
    (_gas({"on": "B", "head": [0.2333452, 0.2333452]}, 1), "'load': two gas loads on one piston"),
])
def test_hostile_gas_loads(d, fragment):
    from tmm_cli.i18n.errors import translate_error

    with pytest.raises(TmmError) as err:
        _gas_sheet2(d)
    text = str(err.value)
    assert "\n" not in text and text.startswith("m.toml: ") and fragment in text, text
    ru = translate_error(text)
    assert ru != text and any("а" <= ch <= "я" for ch in ru), ru


# --- a load of its own direction (direction_deg) -----------------------------------------------


def test_a_cutting_force_of_its_own_direction():
    """shaper_offset's cutting force points at 160°: on the working stroke it is the table's size
    along e^{i·160°} (zero on the return), only its part along the guide works (cos 160° of the area
    times the stroke), and the mean M_b over the turn is M_d."""
    from tmm_cli.linkage.forces import applied
    from tmm_cli.linkage.power import balancing_moment_by_power

    s = sheet2("shaper_offset")
    m = s.sheet1.mechanism
    c = s.sheet1.cycle
    f = next(f for f in s.loading.forces if f.kind == "load").f
    e = complex(math.cos(math.radians(160.0)), math.sin(math.radians(160.0)))
    on = np.abs(f) > 0
    assert on.any() and np.allclose(f[on] / np.abs(f[on]), e, atol=1e-12)
    vx = c.kin.v["C"].real  # the ram's working motion is +x here
    assert np.all(vx[on] >= -1e-9)
    area = (0.95 - 0.05) * 1500.0  # the table: 1500 N from 5 % to 95 % of the stroke
    assert s.dynamics.A_r[-1] == pytest.approx(c.stroke * area * math.cos(math.radians(160.0)), rel=1e-9)
    n = 72000
    ph = c.start + m.crank.sense * (np.arange(n) + 0.5) * 2 * math.pi / n
    k = solve(m, ph)
    mb = balancing_moment_by_power(k, applied(m, s.input, s.stroke, k))
    assert float(np.mean(mb)) == pytest.approx(s.dynamics.drive_moment_ccw, rel=2e-4)


@pytest.mark.parametrize("name,change,fragment", [
    ("rocking_block", {"direction_deg": 90.0}, "'load.direction_deg' gives a force its own direction"),
    ("shaper_offset", {"direction_deg": 90.0}, "'load.direction_deg' is across the slider's guide"),
])
def test_hostile_directions(name, change, fragment):
    from tmm_cli.i18n.errors import translate_error

    d = data(name)
    d["load"].update(change)
    with pytest.raises(TmmError) as err:
        parse_sheet2(parse_mechanism(d, "m.toml"), "m.toml")
    text = str(err.value)
    assert "\n" not in text and fragment in text, text
    assert any("а" <= ch <= "я" for ch in translate_error(text))


# --- random files of the new forms (hypothesis) ------------------------------------------------

from hypothesis import HealthCheck, assume, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


def _random_file(kind, r, h, d, ang, slot, along, across):
    base = {"frame": {"O1": [0.0, 0.0], "O2": [0.0, -h]},
            "crank": {"pivot": "O1", "joint": "A", "length": r, "rpm": 60},
            "mass": [{"link": ["O1", "A"], "m": 2.0, "J": 0.01, "centre": "O1"}],
            "load": {"on": "B", "stroke": [0.0, 1.0], "force": [100.0, 300.0]}}
    if kind == "RPP":
        base["group"] = [{"kind": "RPP", "joints": ["A", "B"], "guide": {"through": [0.0, d], "angle_deg": ang},
                          "slot_deg": slot}]
        base["mass"] += [{"joint": "A", "m": 0.5}, {"joint": "B", "m": 3.0}]
        return base
    base["group"] = [{"kind": "RPR", "joints": ["A", "O2"], "offset": d}]
    base["point"] = [{"name": "S3", "link": ["O2", "A"], "along": 0.2, "across": across}]
    base["mass"] += [{"link": ["O2", "A"], "m": 5.0, "J": 0.1, "centre": "S3"}]
    if kind == "PRP":
        base["group"].append({"kind": "PRP", "joints": ["B"], "guides": [
            {"link": ["O2", "A"], "along": along, "across": across, "angle_deg": ang},
            {"through": [0.0, 0.5 * h], "angle_deg": slot - 90.0}]})  # G2 within 30° of horizontal
        base["mass"] += [{"joint": "B′", "m": 0.5, "J": 0.002}, {"joint": "B", "m": 4.0}]
    else:  # a slider on the slotted link's guide, hinged to a lever about a fixed D
        base["frame"]["D"] = [0.05, 0.6 * h]
        base["group"].append({"kind": "RRP", "joints": ["D", "B"], "length": 1.2 * h,
                              "guide": {"link": ["O2", "A"], "along": along, "across": across, "angle_deg": ang},
                              "branch": "ahead"})
        base["output"] = "B"
        base["mass"] += [{"link": ["D", "B"], "m": 2.0, "J": 0.02}, {"joint": "B", "m": 1.0, "J": 0.001}]
    return base


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(kind=st.sampled_from(["RPP", "PRP", "RRP"]), r=st.floats(0.04, 0.10), h=st.floats(0.3, 0.5),
       d=st.floats(-0.03, 0.03), ang=st.floats(-15.0, 15.0), slot=st.floats(70.0, 110.0),
       along=st.floats(0.0, 0.2), across=st.floats(-0.02, 0.02))
def test_random_files_of_the_new_forms(kind, r, h, d, ang, slot, along, across):
    """Random RPP yokes, PRP groups on an offset slotted link and sliders on a moving guide: the
    velocities and accelerations are the positions' derivatives, and the force analysis, the power
    balance and Zhukovsky's lever give one M_b. (The ranges keep the guides of a PRP at least 35°
    apart: nearly parallel guides send B far away so fast that differences at 0.1° lose 1e-5.)"""
    data_ = _random_file(kind, r, h, d, ang, slot, along, across)
    try:
        m = parse_mechanism(data_, "m.toml")
        s1 = analyse_mechanism(m)
        s = analyse_sheet2(s1, parse_sheet2(m, "m.toml"))
    except TmmError:
        assume(False)
    assume(float(np.max(np.abs(s.balancing))) > 1e-3)
    _check_derivatives(m)
    scale = float(np.max(np.abs(s.balancing)))
    assert np.max(np.abs(s.balancing - s.power_balance)) <= 1e-8 * scale
    assert np.max(np.abs(s.balancing - s.lever.balancing)) <= 1e-8 * scale
