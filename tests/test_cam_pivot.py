"""The rocker pivot C must clear the cam body; checked from the exported numbers alone."""

import pytest

from tmm_cli.cam.design import design_cam
from tmm_cli.render.data.cam import cam_to_json
from tmm_cli.variants import load_table

ROCKERS = [n for n, v in load_table().items() if v.is_rocker]


@pytest.mark.parametrize("number", ROCKERS)
def test_pivot_warning_iff_the_cam_sweeps_over_the_pivot(number):
    v = load_table()[number]
    cam = design_cam(v)
    d = cam_to_json(cam, "en")
    sign = 1 if d["closure"] == "form" else -1  # groove: outer wall; spring: working profile D1
    body = d["far_dwell_radius_mm"] + sign * d["roller_mm"]
    warned = any(n.code.startswith(("cam_pivot_inside", "cam_fail_pivot")) for n in cam.notes)
    assert warned == (d["l_oc_mm"] <= body)
    assert not warned, f"variant {number}: the carried rocker's pivot lies inside the cam's sweep"  # issue 8
    assert d["checks"]["pivot_ok"] is True


def test_known_offenders_move():
    """Issue 8: the smallest cams of 3, 4, 7, 11, 12 sweep over their pivot; the program carries
    the other swing direction (its smallest cam clears the pivot) and says so."""
    for n in (3, 4, 7, 11, 12):
        cam = design_cam(load_table()[n])
        assert cam.pivot_move == "swing", n
        codes = [x.code for x in cam.notes]
        assert "cam_pivot_moved_swing" in codes, n
        assert cam.sizing.r0_other_swing_m < cam.sizing.r0_m  # the smaller cam was rejected
        # the decision, as data for the note (issue 20): the rejected cam, and why
        c = cam.pivot_conflict
        assert c is not None and c.swing != cam.sizing.swing, n
        assert c.r0_m == pytest.approx(cam.sizing.r0_other_swing_m, rel=1e-12)
        assert c.l_oc_m <= c.body_m  # its body reaches the pivot
        assert cam.checks.l_oc_m > cam.checks.body_m  # the carried one clears it


def test_no_conflict_when_the_smaller_cam_is_carried():
    """Every rocker but the five offenders above carries the smaller cam of the two swings, and
    records no conflict."""
    moved = []
    for n in ROCKERS:
        cam = design_cam(load_table()[n])
        if cam.pivot_move is None:
            assert cam.pivot_conflict is None
            assert cam.sizing.r0_m <= cam.sizing.r0_other_swing_m * (1 + 1e-12), n
        else:
            moved.append(n)
    assert len(ROCKERS) == 34 and moved == [3, 4, 7, 11, 12]


def test_student_swing_over_the_pivot_is_reported():
    """A student who forces the swing of the smallest cam of variant 3 gets the failed condition."""
    from tmm_cli.cam.design import CamChoice

    cam = design_cam(load_table()[3], choice=CamChoice(swing="same"))
    d = cam_to_json(cam, "en")
    assert d["swing"] == "same" and d["checks"]["pivot_ok"] is False
    assert any(n.code == "cam_fail_pivot_force" for n in cam.notes)


def test_zone_scan_fallback_finds_the_nearest_allowed_centre():
    """The fallback that moves a centre off the pivot (used when neither swing clears it; no Table
    1.2 variant needs it): with the condition |O| ≥ 1.25·r0 the scan returns a zone point on that
    circle, inside the pressure-angle zone."""
    import numpy as np

    from tmm_cli.cam.sizing import _inside, nearest_centre_where

    v = load_table()[3]
    cam = design_cam(v)
    z = cam.sizing
    target = 1.25 * z.r0_m
    o = nearest_centre_where(z, lambda pts: np.hypot(*np.atleast_2d(pts).T) >= target)
    assert o is not None
    assert np.hypot(*o) == pytest.approx(target, rel=1e-6)
    assert _inside(z.polygon_canonical, o[None])[0]
    # nothing closer than r0 can be found: the zone's nearest point is the carried centre
    o2 = nearest_centre_where(z, lambda pts: np.ones(len(np.atleast_2d(pts)), bool))
    assert np.hypot(*o2) == pytest.approx(z.r0_m, rel=2e-3)
