"""Issue 34 (review): sheets 1–2 and the note count the working stroke from the extreme position where
it starts, whatever position 0 is (``crank.start_deg``).

For every example file with a load, with position 0 at several angles (0°, 90°, 200°, either
extreme), checked independently of the code under test, from the kinematics of the mechanism:

- the extreme labelled "start" is the one after which the output moves the working way (away from
  or towards the crank pivot as the file's `load.working` says; else the slower stroke), and the
  crank's travel from it to the one labelled "end" is the working stroke's angle;
- the first plan (and the force analysis, and the lever) is in the position nearest the middle of the
  working stroke counted from that extreme, and the output moves the working way there; the second
  plan is on the return stroke;
- the displacement s (the curve, the note's table) is measured from the start extreme: 0 ≤ s ≤ H,
  s = 0 there and H at the end;
- the note's claims (the plans "in the middle of the working stroke", the extremes) agree.
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tmm_cli.linkage.chain import solve
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2
from tmm_cli.render.data.mechanism import mechanism_document
from tmm_cli.linkage.vector_plans import middle_of_working
from tmm_cli.render.note.linkage_part import position_rows
from linkage_check import with_start

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
TWO_PI = 2 * math.pi


def _examples():
    out = {}
    for f in sorted(EXAMPLES.glob("*.toml")):
        data = tomllib.loads(f.read_text(encoding="utf-8"))
        if ("load" in data or "dynamics" in data) and "crank" in data:
            out[f.stem] = data
    return out


FILES = _examples()


def _mech(name, start):
    return parse_mechanism(with_start(FILES[name], start), f"{name}.toml")


def _starts(name):
    """0°, 90°, 200° and both extremes of the file's default cycle."""
    c = analyse_mechanism(_mech(name, None)).cycle
    ext = [math.degrees(p.phi) for p in c.positions if p.extreme]
    return [0.0, 90.0, 200.0] + ext


CASES = [(n, round(s, 6)) for n in FILES for s in _starts(n)]


def _out_point(m, phi):
    """The output joint's place (complex) and velocity at the crank angles (its own joint's path)."""
    k = solve(m, np.atleast_1d(np.asarray(phi, dtype=float)))
    return k.z[m.output.joint], k.v[m.output.joint]


def _working_way(m, c, phi):
    """+1 where the output moves the working way at crank angle phi (independent: the working stroke
    carries the output from the start extreme's place to the end extreme's place)."""
    first = next(p for p in c.positions if p.extreme == "start")
    last = next(p for p in c.positions if p.extreme == "end")
    (z0,), _ = _out_point(m, first.phi)
    (z1,), _ = _out_point(m, last.phi)
    (_,), (v,) = _out_point(m, phi)
    return np.sign(((z1 - z0).conjugate() * v).real)  # a rocker's point on an arc < 180° as well


def _degenerate(m, c, p, limit_mm=2.0):
    """Whether the plans of position p collapse: all their tips (the pole included) lie within a strip
    `limit_mm` wide at the plan's scale, or a moving joint's tip lies within `limit_mm` of the pole."""
    from tmm_cli.linkage.vector_plans import plans

    pl = plans(c, p.index)
    moving = {n.lower() for n in (*m.joint_names, *(pt.name for pt in m.points)) if n not in m.frame}
    for plan in (pl.velocity, pl.acceleration):
        tips = np.array([complex(z) for z in plan.points.values()]) / plan.scale
        xy = np.c_[tips.real, tips.imag]
        xy = xy - xy.mean(axis=0)
        near = [abs(complex(z)) / plan.scale for n, z in plan.points.items() if n in moving]
        if np.abs(xy @ np.linalg.svd(xy)[2][1]).max() < limit_mm or min(near) < limit_mm:
            return True
    return False


@pytest.mark.parametrize("name,start", CASES)
def test_the_extremes_the_plans_and_s_count_from_the_working_stroke_start(name, start):
    m = _mech(name, start)
    s1 = analyse_mechanism(m)
    c = s1.cycle
    if c.working is None:
        pytest.skip("the output turns fully: no working stroke")
    first = next(p for p in c.positions if p.extreme == "start")
    last = next(p for p in c.positions if p.extreme == "end")
    sense = m.crank.sense
    # the crank's travel start → end is the working stroke's angle
    assert (sense * (last.phi - first.phi)) % TWO_PI == pytest.approx(c.working, abs=1e-9)
    # just after the start extreme the output moves towards the end extreme's place, and back after the end
    eps = 1e-3
    assert _working_way(m, c, first.phi + sense * eps) == 1.0
    assert _working_way(m, c, last.phi + sense * eps) == -1.0
    # linkage.json names them in that order (start, end)
    assert mechanism_document(s1, "en")["extreme_positions"] == [first.label, last.label]
    # which stroke is the working one: by load.working (the distance from the crank pivot), else the slower
    working = FILES[name].get("load", {}).get("working") if isinstance(FILES[name].get("load"), dict) else None
    if working is not None and m.output.kind == "slider":
        pivot = m.frame[m.crank.pivot]
        (z0,), _ = _out_point(m, first.phi)
        (z1,), _ = _out_point(m, last.phi)
        if abs(abs(z1 - pivot) - abs(z0 - pivot)) > 1e-9:  # (a Scotch yoke's both ends are as far)
            assert (abs(z1 - pivot) > abs(z0 - pivot)) == (working == "away")
    elif working is None and m.gas_head is None:
        assert c.working >= c.returning - 1e-9
    # the plans: the first in the middle of the working stroke (round the turn from its start)
    lead = (sense * (first.phi - c.start)) % TWO_PI
    evens = [p for p in c.positions if p.label.isdigit()]

    def gap(p, t):
        d = (p.travel - t) % TWO_PI
        return min(d, TWO_PI - d)
    p1, p2 = s1.plans[0].position, s1.plans[1].position
    if m.plan is None:  # the nearest to the middle whose plans are not degenerate (nearer ones are)
        for p_, target, way in ((p1, lead + c.working / 2, 1.0), (p2, lead + c.working + c.returning / 2, -1.0)):
            assert _working_way(m, c, p_.phi) == way
            nearer = [p for p in evens if gap(p, target) < gap(p_, target) - 1e-9]
            assert all(_degenerate(m, c, p) for p in nearer), (p_.label, [p.label for p in nearer])
            assert not _degenerate(m, c, p_) or not [p for p in evens if _working_way(m, c, p.phi) == way
                                                      and not _degenerate(m, c, p)]
    # s from the start extreme: 0 ≤ s ≤ H, 0 at the start, H at the end
    tol = 1e-9 * max(1.0, c.stroke)
    assert c.curve.s.min() >= -tol and c.curve.s.max() <= c.stroke + tol
    if m.output.kind == "slider":
        (z0,), _ = _out_point(m, first.phi)
        z, _ = _out_point(m, [p.phi for p in c.positions])
        rows = position_rows(s1)
        for p, row, zz in zip(c.positions, rows, z):
            assert row[2] == pytest.approx(abs(zz - z0), abs=1e-9)  # a slider on a line: |Δz| is s
        assert rows[first.index][2] == pytest.approx(0.0, abs=1e-12)
        assert rows[last.index][2] == pytest.approx(c.stroke, abs=1e-9)


@pytest.mark.parametrize("name,start", [(n, s) for n, s in CASES if s in (90.0, 200.0)])
def test_the_force_analysis_is_on_the_working_stroke_where_the_load_acts(name, start):
    data = FILES[name]
    load = data.get("load")
    if not isinstance(load, dict) or "force" not in load or "dynamics" not in data:
        pytest.skip("no table force")
    m = _mech(name, start)
    s1 = analyse_mechanism(m)
    if m.plan is not None:
        pytest.skip("the file names the plans' position")
    s2 = analyse_sheet2(s1, parse_sheet2(m, f"{name}.toml"))
    c = s1.cycle
    i = s2.force_position
    assert i == s1.plans[0].position.index
    # the fraction of the stroke covered since the working stroke began, from the output's place
    first = next(p for p in c.positions if p.extreme == "start")
    (z0,), _ = _out_point(m, first.phi)
    (zi,), _ = _out_point(m, c.positions[i].phi)
    fraction = abs(zi - z0) / c.stroke
    expected = float(np.interp(fraction, load["stroke"], load["force"]))
    f = [x for x in s2.forces.loading.forces if x.kind == "load"]
    assert f and abs(complex(f[0].f[i])) == pytest.approx(expected, rel=1e-9, abs=1e-6)


def _note_claims(name, start):
    from dataclasses import replace

    from tmm_cli.project import run_project
    from tmm_cli.render.note import build_note
    from tmm_cli.variants import get_variant

    m = _mech(name, start)
    s2 = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m, f"{name}.toml"))
    r = replace(run_project(get_variant("17")), linkage=s2)
    return m, s2, build_note(r, "ru", {})


@pytest.mark.parametrize("name,start", [("shaper", 90.0), ("shaper", 200.0), ("four_bar", 90.0),
                                        ("compressor", 200.0)])
def test_the_notes_claims_agree_whatever_position_0_is(name, start):
    from test_note_linkage import check_claim

    m, s2, doc = _note_claims(name, start)
    s1, c = s2.sheet1, s2.sheet1.cycle
    kinds = {cl["kind"] for cl in doc.claims}
    assert "linkage_plan_position" in kinds
    for cl in doc.claims:
        check_claim(cl, s1)
        if cl["kind"] == "linkage_plan_position" and m.plan is None:  # «в середине рабочего хода» — and it is
            assert cl["middle"] or _degenerate(m, c, c.positions[middle_of_working(c)])  # (checked by check_claim)
        if cl["kind"] == "linkage_load_at_position":  # «совершает рабочий ход … доля …»: from the output's place
            i = c.index(cl["label"])
            assert cl["working"] == (_working_way(m, c, c.positions[i].phi) == 1.0)
            first = next(p for p in c.positions if p.extreme == "start")
            (z0,), _ = _out_point(m, first.phi)
            (zi,), _ = _out_point(m, c.positions[i].phi)
            if m.output.kind == "slider" and cl["working"]:
                assert cl["share"] == pytest.approx(abs(zi - z0) / c.stroke, abs=1e-9)
            if m.plan is None:
                assert cl["working"]  # the force analysis is made on the working stroke
    if s2.input.load is not None:
        assert "linkage_load_at_position" in kinds
    first = next(p for p in c.positions if p.extreme == "start")
    if first.index != 0:
        assert "linkage_working_extremes" in kinds


@settings(max_examples=12, deadline=None)
@given(name=st.sampled_from(["shaper", "four_bar", "shaper_offset"]), start=st.floats(0.0, 359.999))
def test_any_position_0_keeps_the_plans_on_their_strokes_and_s_non_negative(name, start):
    m = _mech(name, start)
    s1 = analyse_mechanism(m)
    c = s1.cycle
    if m.plan is None:
        assert _working_way(m, c, s1.plans[0].position.phi) == 1.0
        assert _working_way(m, c, s1.plans[1].position.phi) == -1.0
    assert c.curve.s.min() >= -1e-9 and c.curve.s.max() <= c.stroke + 1e-9
