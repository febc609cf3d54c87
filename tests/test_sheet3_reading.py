"""Sheet 3 as a reader sees it (issue 32), measured on the DXF of every variant:

- the position numbers of the minimum-radius construction: no two overlap, no leader crosses
  another, and a number left out is named in the caption;
- the ν-diagram's heading stands just above its plot (≤ 15 mm), not over empty room;
- the profile's «k_Sk = …» stands under the profile it describes, near the drawing.
"""

from __future__ import annotations

import functools
import re

import numpy as np
import pytest

from sheet_check import _boxes_overlap, field_boxes, text_boxes
from tmm_cli.cam.design import design_cam
from tmm_cli.inputs.titleblock import TitleFields
from tmm_cli.render.sheets import sheet3
from tmm_cli.variants import load_table

V = load_table()
TITLE = TitleFields(student="Иванов И. И.", group="П-243", teacher="Петров П. П.", org="ЮУрГУ, кафедра ТММ")


@functools.lru_cache(maxsize=4)
def _sheet(number):
    cam = design_cam(V[number])
    return cam, sheet3(cam, "ru", TITLE)


def _inside(pt, box, tol=0.0):
    return box[0] - tol <= pt[0] <= box[2] + tol and box[1] - tol <= pt[1] <= box[3] + tol


def _cross(a, b, c, d) -> bool:
    def side(p, q, r):
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])

    return side(c, d, a) * side(c, d, b) < -1e-9 and side(a, b, c) * side(a, b, d) < -1e-9


def _lines(doc, box):
    out = []
    for e in doc.modelspace().query("LINE"):
        a, b = np.array([e.dxf.start.x, e.dxf.start.y]), np.array([e.dxf.end.x, e.dxf.end.y])
        if _inside(a, box, 0.5) and _inside(b, box, 0.5):
            out.append((a, b))
    return out


@pytest.mark.parametrize("number", sorted(V))
def test_zone_numbers_readable(number):
    cam, sh = _sheet(number)
    doc = sh.doc
    box = field_boxes(doc)["zone"]
    expected = {str(row.index) for row in cam.motion.table if row.phase in ("rise", "return")}
    nums = [(c, t, e.dxf.handle) for e, c, h, rot, t in text_boxes(doc)
            if t in expected and all(_inside(p, box) for p in c)]
    drawn = [t for _, t, _ in nums]
    assert len(drawn) == len(set(drawn)), f"a number drawn twice: {sorted(drawn)}"
    # no two numbers' boxes overlap, and no number overlaps any other text
    allb = [(e.dxf.handle, c) for e, c, *_ in text_boxes(doc)]
    for c, t, hd in nums:
        hits = [o for k, o in allb if k != hd and _boxes_overlap(c, o)]
        assert not hits, f"number {t} overlaps a text"
    # the leaders: a non-horizontal line ending on a shelf (the horizontal line under a number)
    lines = _lines(doc, box)
    shelves = []
    for c, t, _ in nums:
        lo, hi = c.min(axis=0), c.max(axis=0)
        for a, b in lines:
            if abs(a[1] - b[1]) < 1e-6 and 0.0 <= lo[1] - a[1] <= 2.0 and min(a[0], b[0]) <= (lo[0] + hi[0]) / 2 <= max(a[0], b[0]):
                shelves.append((a, b))
    leaders = []
    for a, b in lines:
        if abs(a[1] - b[1]) < 1e-6:
            continue
        for s0, s1 in shelves:
            if abs(b[1] - s0[1]) < 1e-6 and min(s0[0], s1[0]) - 1e-6 <= b[0] <= max(s0[0], s1[0]) + 1e-6:
                leaders.append((a, b))
                break
    for i in range(len(leaders)):
        for j in range(i + 1, len(leaders)):
            assert not _cross(*leaders[i], *leaders[j]), f"leaders cross: {leaders[i]} × {leaders[j]}"
    # a number left out is said in the caption
    left = expected - set(drawn)
    caption = " ".join(t for e, c, h, rot, t in text_boxes(doc) if "не обозначены" in t or "not marked" in t)
    if left:
        named = set(re.findall(r"\d+", caption.split("озиции")[-1]))
        assert left <= named, f"left out {sorted(left, key=int)}, caption: {caption!r}"
    else:
        assert not caption


def _heading_bottom(doc, box):
    """The lowest point of the field's heading (its text of the title height, 7 mm; labels are 5 mm)."""
    return min(c[:, 1].min() for e, c, h, rot, t in text_boxes(doc) if h >= 6.9 and _inside(c.mean(0), box))


@pytest.mark.parametrize("number", sorted(V))
def test_pressure_heading_over_its_plot(number):
    _, sh = _sheet(number)
    doc = sh.doc
    box = field_boxes(doc)["pressure"]
    head = _heading_bottom(doc, box)
    # the plot's top: the highest point of a line or polyline in the field (the ordinate's arrow)
    tops = []
    for e in doc.modelspace().query("LINE LWPOLYLINE SOLID"):
        from sheet_check import entity_points

        pts = entity_points(e)
        if pts is not None and all(_inside(p, box) for p in pts):
            tops.append(pts[:, 1].max())
    top = max(tops)
    assert top < head, (top, head)
    assert head - top <= 15.0, f"heading {head - top:.1f} mm above the plot"


@pytest.mark.parametrize("number", sorted(V))
def test_profile_scale_text_under_the_profile(number):
    _, sh = _sheet(number)
    doc = sh.doc
    box = field_boxes(doc)["profile"]
    ksk = [c for e, c, h, rot, t in text_boxes(doc) if t.startswith("k") and "Sk" in t and _inside(c.mean(0), box)]
    assert len(ksk) == 1
    c = ksk[0]
    from sheet_check import entity_points

    pts = [entity_points(e) for e in doc.modelspace().query("LINE LWPOLYLINE ARC CIRCLE")]
    pts = np.vstack([p for p in pts if p is not None and all(_inside(q, box) for q in p)])
    below = pts[:, 1].min()  # the drawing's lowest point
    assert c[:, 1].max() <= below + 1e-6, "k_Sk overlaps the drawing"
    assert below - c[:, 1].max() <= 10.0, f"k_Sk {below - c[:, 1].max():.1f} mm under the drawing"
    # and under it, not off to one side
    assert pts[:, 0].min() - 5.0 <= c[:, 0].min() <= pts[:, 0].max()
