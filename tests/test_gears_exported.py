"""Issue 8, "must hold": the carried reducer meets the five conditions of §2.1.3 for every crank
speed 30 … 960 rpm and the 68 variants, checked from the exported JSON (render/data/gears.py) with
the independent checker of tests/reference_gears.py — nothing of tmm_cli.gears is used beyond
producing the JSON. The cam does not depend on the crank speed (Table 1.2 gives n_k); its checks
from the exported curve are in test_cam_exported.py (all 68 variants)."""

import math
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tmm_cli.gears.design import design_gears
from tmm_cli.render.data.gears import gears_to_json

from reference_gears import max_planets, stage_ok, willis

MOTORS = (720, 920, 1420, 2880)
TOL = 5.0


def expected(n_cr):
    """Motor (§2.2: the smallest standard speed ≥ 3·n_cr), i_pl and the scheme of Fig. 2.4."""
    n_d = next(n for n in MOTORS if n >= 3 * n_cr)
    i = n_d / n_cr
    return n_d, i, ("1" if i <= 8 else "2" if i <= 16 else "1+1")


def check_exported(g, n_cr):
    n_d, i_req, scheme = expected(n_cr)
    assert g["motor"]["n_rpm"] == n_d
    p = g["planetary"]
    assert p["scheme"] == scheme
    ratio = 1
    for s in p["stages"]:
        double = s["z_planet2"] is not None
        assert double == (scheme == "2")
        zc2 = s["z_planet2"] if double else s["z_planet"]
        zk, zc, zn, k = s["z_sun"], s["z_planet"], s["z_ring"], s["planets"]
        # coaxiality, Table 2.2, neighbouring and assembly with k planets
        assert stage_ok(zk, zc, zc2, zn, k, double), (n_cr, s)
        assert k == max_planets(zk, zc, zc2, zn), (n_cr, s)  # the largest count the set admits
        ratio *= willis(zk, zc, zc2, zn)
        if scheme == "1+1":  # Fig. 2.4: a single-row stage 3…8
            assert 3.0 <= float(willis(zk, zc, zc2, zn)) <= 8.0, (n_cr, s)
    err = float(ratio) / i_req - 1
    assert abs(err) <= TOL / 100 + 1e-12, (n_cr, err)  # condition 1: the ratio
    assert float(ratio) == pytest.approx(p["ratio"], rel=1e-6)
    assert p["planets"] >= 3, n_cr
    if scheme == "1+1":
        assert p["stage_range_ok"] is True
    # the stated selection rule holds among the alternatives the JSON lists
    near = [a for a in p["alternatives"] if a["size"] <= p["smallest"]["size"] + 1 and a["planets"] >= 3]
    assert p["size"] <= p["smallest"]["size"] + 1
    assert abs(p["ratio_error_pct"]) <= min(abs(a["ratio_error_pct"]) for a in near) + 1e-9
    assert g["checks"]["ok"] is True
    check_overlap_angles(g["spur"])


def check_overlap_angles(sp):
    """φ_α1, φ_α2 (the turn of each gear while one tooth pair is in contact, §2.3) from the JSON's
    own diameters and α_w: each base circle rolls off the active line, so with t_j = tg α_aj − tg α_w
    (cos α_aj = d_bj/d_aj), φ_α1 = t1 + (z2/z1)·t2 and φ_α2 = t2 + (z1/z2)·t1 [rad]."""
    z1, z2 = sp["z1"], sp["z2"]
    tw = math.tan(math.radians(sp["alpha_w_deg"]))
    t1, t2 = (math.sqrt(da * da - db * db) / db - tw for da, db in zip(sp["da_mm"], sp["db_mm"]))
    assert sp["phi_alpha_deg"][0] == pytest.approx(math.degrees(t1 + z2 / z1 * t2), abs=2e-4)
    assert sp["phi_alpha_deg"][1] == pytest.approx(math.degrees(t2 + z1 / z2 * t1), abs=2e-4)


@pytest.mark.parametrize("n_cr", range(30, 961, 10))
def test_reducer_from_json_every_10_rpm(n_cr):
    check_exported(gears_to_json(design_gears(1000, n_cr), "en"), n_cr)


@settings(max_examples=25, deadline=None)
@given(st.floats(min_value=30.0, max_value=960.0, allow_nan=False))
def test_reducer_from_json_any_speed(n_cr):
    check_exported(gears_to_json(design_gears(-750, n_cr), "en"), n_cr)


def test_reducer_from_json_for_the_68_variants_at_220(table):
    seen = set()
    for n, v in table.items():
        g = gears_to_json(design_gears(v.n_cam_rpm), "en")
        check_exported(g, 220.0)
        assert g["crank_rpm_assumed"] is True
        seen.add(tuple(s["z_ring"] for s in g["planetary"]["stages"]))
    assert len(seen) == 1  # the reducer depends on n_cr only


def test_variant_3_at_140_rpm_exact_ratio_and_smallest_restores_the_old_choice():
    g = gears_to_json(design_gears(-1000, 140), "en")
    s = g["planetary"]["stages"][0]
    assert (s["z_sun"], s["z_planet"], s["z_ring"]) == (21, 33, 87) and s["planets"] >= 4
    assert g["planetary"]["ratio_error_pct"] == 0.0 and s["ratio_fraction"] == "36/7"
    assert g["book"]["fraction_rule"] == "exact"
    old = gears_to_json(design_gears(-1000, 140, select="smallest"), "en")["planetary"]["stages"][0]
    assert (old["z_sun"], old["z_planet"], old["z_ring"]) == (22, 32, 86)


def test_book_procedure_starts_from_the_exact_fraction():
    r = design_gears(-1000, 60)  # i = 12: §2.5 from 12/1, not 35/3
    assert r.derivation.fraction_rule == "exact"
    assert r.derivation.ratio_fraction == 12
    r = design_gears(-1000, 220)  # 720/220 = 36/11: no denominator ≤ 10; its last convergent, 13/4 (§2.4)
    assert r.derivation.fraction_rule == "convergent"
    assert r.derivation.ratio_fraction == Fraction(13, 4)
    assert r.derivation.stages[0].chosen.teeth == (40, 25, 90)  # the book's own answer of §2.4


def test_two_stages_at_40_rpm_inside_3_to_8():
    r = design_gears(-1000, 40)
    assert all(3.0 <= s.ratio <= 8.0 for s in r.planetary.stages)
    assert any(n.code == "two_stage_range_ok" for n in r.notes)


def test_check_accepts_the_old_smallest_and_the_new_accurate_reducer():
    """`tmm check` (check.py, not changed) must accept any valid reducer a student found."""
    from tmm_cli.teacher.check import check_one
    from tmm_cli.variants import load_table

    v = load_table()[3]
    for teeth in ((22, 32, 86), (21, 33, 87)):
        ans = dict(zip(("z_sun", "z_planet", "z_ring"), teeth), planets=4)
        rows = {r.key: r.status for r in check_one(v, ans, crank_rpm=140).rows}
        assert all(rows[k].startswith("pass") for k in ("z_sun", "z_planet", "z_ring", "planets")), (teeth, rows)


def test_ratio_error_remark_over_3_pct():
    r = design_gears(-1000, 140, select="smallest")  # 22/32/86: −4.55 %
    assert any(n.code == "ratio_error_large" for n in r.notes)
    r = design_gears(-1000, 140)
    assert not any(n.code == "ratio_error_large" for n in r.notes)


def test_the_cam_does_not_depend_on_the_crank_speed(table):
    """So the cam checks of test_cam_exported.py (all 68 variants) hold for every n_cr."""
    from tmm_cli.project import run_project
    from tmm_cli.render.data.cam import cam_to_json

    v = table[3]
    docs = [cam_to_json(run_project(v, crank_rpm=n).cam, "en") for n in (30, 333, 960)]
    for d in docs[1:]:
        assert d["pitch_curve_mm"] == docs[0]["pitch_curve_mm"] and d["roller_mm"] == docs[0]["roller_mm"]
    assert docs[0]["checks"]["all_ok"] is True
