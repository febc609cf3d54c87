"""Sheet 2 after the second review (/work/review/findings2.md), read back from the DXF:

- C11: in the ΔT diagram the names «ΔT» and «ΔT_I» (Mertsalov's dashed curve) stand apart — at
  least a label's height (5 mm) between their boxes — for every example with a flywheel (the dashed
  curve's extreme is the solid one's: its name used to be set beside ΔT's, touching it on the
  four-stroke engine and 3 mm from it on the V compressor).
"""

from __future__ import annotations

import numpy as np
import pytest

from sheet_check import field_boxes, text_boxes
from test_sheets import TITLE
from test_sheets12_layout import NAMES, analysed
from tmm_cli.render.sheets.dynamics_sheet import sheet2


def _gap(a, b) -> float:
    (ax0, ay0), (ax1, ay1) = a.min(0), a.max(0)
    (bx0, by0), (bx1, by1) = b.min(0), b.max(0)
    return float(np.hypot(max(bx0 - ax1, ax0 - bx1, 0.0), max(by0 - ay1, ay0 - by1, 0.0)))


@pytest.mark.parametrize("name", [n for n in NAMES if analysed(n)[1] is not None and analysed(n)[1].flywheel])
def test_the_energy_curves_names_stand_apart(name):
    doc = sheet2(analysed(name)[1], "ru", TITLE).doc
    x0, y0, x1, y1 = field_boxes(doc)["dynamics_diagrams"]
    inside = [(c, t) for _, c, _, _, t in text_boxes(doc)
              if x0 <= c[:, 0].min() and c[:, 0].max() <= x1 and y0 <= c[:, 1].min() and c[:, 1].max() <= y1]
    dt = [c for c, t in inside if t == "ΔT"]  # the axis' name and the solid curve's
    dti = [c for c, t in inside if t == "ΔTI"]
    assert len(dt) == 2 and len(dti) == 1, [t for _, t in inside]
    assert min(_gap(dti[0], c) for c in dt) >= 5.0
