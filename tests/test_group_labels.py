"""Sheet 2's group views and force polygons as a reader sees them (issue 32, «S3/Φ3» on the
shaper's, tangent's and rocking block's group 1, «Φ3/P3» on the V-compressor's polygon at a CAD
program's wider font): measured on the DXF of every docs/examples mechanism with sheet 2 and of
the teacher's six-link, the names in each group's view and each polygon overlap no other name and
are crossed by no line — as osifont sets them and with the room of a wider fallback font (1.3×)."""

from __future__ import annotations

import pytest

from sheet_check import field_boxes
from test_lever_labels import MECHANISMS, clashes, field_texts, sheet2_dxf


@pytest.mark.parametrize("name,text", MECHANISMS, ids=[n for n, _ in MECHANISMS])
def test_the_group_views_and_polygons_names_are_free(name, text, tmp_path):
    s, doc = sheet2_dxf(name, text, tmp_path)
    boxes = field_boxes(doc)
    keys = [k for k in boxes if k.startswith(("group_", "polygon_"))]
    assert len(keys) == 2 * len(s.polygons)  # a view and a polygon per group and the crank
    for key in keys:
        for room in (1.0, 1.3):
            texts, segs = field_texts(doc, boxes[key], room)
            assert len(segs[0]) > 3, key  # drawn
            assert len(texts) >= 2, key  # its points or vectors are named (the scale line besides)
            assert not clashes(texts, segs), f"{name} {key} (room {room}): {clashes(texts, segs)}"
