"""The rocker pivot C must clear the cam body; checked from the exported numbers alone."""

import pytest

from tmm_cli.cam.design import design_cam
from tmm_cli.render.cam_json import cam_to_json
from tmm_cli.variants import load_table

ROCKERS = [n for n, v in load_table().items() if v.is_rocker]


@pytest.mark.parametrize("number", ROCKERS)
def test_pivot_warning_iff_the_cam_sweeps_over_the_pivot(number):
    v = load_table()[number]
    cam = design_cam(v)
    d = cam_to_json(cam, "en")
    sign = 1 if d["closure"] == "form" else -1  # groove: outer wall; spring: working profile D1
    body = d["far_dwell_radius_mm"] + sign * d["roller_mm"]
    warned = any(n.code.startswith("cam_pivot_inside") for n in cam.notes)
    assert warned == (d["l_oc_mm"] <= body)


def test_known_offenders():
    warned = {n for n in ROCKERS if any(x.code.startswith("cam_pivot_inside") for x in design_cam(load_table()[n]).notes)}
    assert {3, 7, 11, 4, 12} <= warned
