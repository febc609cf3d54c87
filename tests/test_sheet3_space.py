"""Sheet 3 uses its A1 field (issue 32, «Layout»: an empty 250 × 190 mm field beside views drawn at
smaller scales than would fit), read back from the DXF of every variant:

- the views (what each field draws, measured from its entities) stand apart, inside the frame and
  clear of the title block;
- no empty square of EMPTY_MAX mm or more is left between them. Before this layout the largest
  empty square was 195–307 mm (mean ≈ 250; the issue's empty field, 250 × 190 mm, on v52); now it
  is at most 205 mm, and above 180 mm only where the zone took a larger scale that leaves the rest
  no better place (v27, v65: the zone doubled). What stays empty is set by the scales that are not
  the sheet's to choose — the motion laws at the book's (1.9)–(1.13) (b = 240 mm), the profile at
  the core's Table 1.1 scale (the note states the same) — and by the steps between ГОСТ 2.302
  scales (1:1 to 2:1 doubles a view);
- the minimum-radius construction is at the largest ГОСТ 2.302 scale that fits: at the next larger
  scale its field — the extent at scale 1 the field exports in its XDATA times that scale, plus the
  room its margins, heading and captions take (exported beside it; the captions under the drawing
  or beside it) — has no free place anywhere on the sheet beside the other views' fields, 2 mm
  apart and from the frame (a search over the whole sheet, not the layout's own candidates).
"""

from __future__ import annotations

import functools

import numpy as np
import pytest
from ezdxf import bbox

from sheet_check import text_boxes
from tmm_cli.cam.design import design_cam
from tmm_cli.inputs.titleblock import TitleFields
from tmm_cli.render.sheets import sheet3
from tmm_cli.variants import load_table

V = load_table()
TITLE = TitleFields(student="Иванов И. И.", group="П-243", teacher="Петров П. П.", org="ЮУрГУ, кафедра ТММ")
FRAME = (20.0, 5.0, 836.0, 589.0)  # ГОСТ 2.301 A1, the frame 20 mm from the left edge, 5 mm elsewhere
TITLE_BLOCK = (836.0 - 185.0, 5.0, 836.0, 5.0 + 55.0)  # ГОСТ 2.104 form 1, 185 × 55 mm
EMPTY_MAX = 210.0
GAP = 2.0  # [mm] between two fields
# ГОСТ 2.302: reductions, natural size, enlargements (paper mm per real mm)
GOST = (1 / 100, 1 / 75, 1 / 50, 1 / 40, 1 / 25, 1 / 20, 1 / 15, 1 / 10, 1 / 5, 1 / 4, 1 / 2.5, 1 / 2, 1.0,
        2.0, 2.5, 4.0, 5.0, 10.0, 20.0, 40.0, 50.0, 100.0)


@functools.lru_cache(maxsize=2)
def _read(number):
    """Each field's XDATA and the box of what is drawn in it (the entities whose box's centre lies in
    the field; the frame and the title block aside)."""
    doc = sheet3(design_cam(V[number]), "ru", TITLE).doc
    msp = doc.modelspace()
    fields = {}
    for e in msp:
        if e.has_xdata("TMM_FIELD"):
            tags = [t.value for t in e.get_xdata("TMM_FIELD")]
            fields[tags[0]] = tags
    ink = {name: None for name in fields}
    texts = {e.dxf.handle: (c.min(axis=0), c.max(axis=0)) for e, c, *_ in text_boxes(doc)}
    for e, b in zip(msp, bbox.multi_flat(msp, fast=True)):
        if e.dxf.handle in texts:  # a text: its box as the normcontroller's check measures it
            lo, hi = texts[e.dxf.handle]
        elif not b.has_data or e.dxf.layer == "Рамка" or b.extmax.x - b.extmin.x > FRAME[2] - FRAME[0]:
            continue  # the frame, the sheet's edge
        else:
            lo, hi = (b.extmin.x, b.extmin.y), (b.extmax.x, b.extmax.y)
        c = ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2)
        for name, tags in fields.items():
            x0, y0, x1, y1 = tags[1:5]
            if x0 <= c[0] <= x1 and y0 <= c[1] <= y1:
                box = (float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1]))
                old = ink[name]
                ink[name] = box if old is None else (min(old[0], box[0]), min(old[1], box[1]),
                                                     max(old[2], box[2]), max(old[3], box[3]))
                break
    return fields, ink


def _grown(box, g=GAP):
    return (box[0] - g, box[1] - g, box[2] + g, box[3] + g)


def _overlap(a, b, tol=1e-6) -> bool:
    return a[0] < b[2] - tol and b[0] < a[2] - tol and a[1] < b[3] - tol and b[1] < a[3] - tol


def _fits_somewhere(w, h, frame, boxes) -> bool:
    """Whether a w × h rectangle fits in `frame` overlapping none of `boxes`: a free place, when there
    is one, can be slid left and down until it rests on the frame or on a box's right and top side."""
    xs = [frame[0]] + [b[2] for b in boxes]
    ys = [frame[1]] + [b[3] for b in boxes]
    for x in xs:
        for y in ys:
            r = (x, y, x + w, y + h)
            if r[2] <= frame[2] and r[3] <= frame[3] and not any(_overlap(r, b) for b in boxes):
                return True
    return False


def _largest_empty_square(frame, boxes) -> float:
    """The side of the largest square in `frame` clear of `boxes` (every strip between box sides)."""
    xs = sorted({frame[0], frame[2], *(b[0] for b in boxes), *(b[2] for b in boxes)})
    best = 0.0
    for i, xa in enumerate(xs):
        for xb in xs[i + 1:]:
            if not frame[0] <= xa < xb <= frame[2]:
                continue
            y, run = frame[1], 0.0
            for c0, c1 in sorted((b[1], b[3]) for b in boxes if b[0] < xb and b[2] > xa):
                run = max(run, c0 - y)
                y = max(y, c1)
            best = max(best, min(xb - xa, max(run, frame[3] - y)))
    return best


@pytest.mark.parametrize("number", sorted(V))
def test_views_apart_in_the_frame_and_the_field_used(number):
    fields, ink = _read(number)
    assert set(fields) == {"motion", "pressure", "zone", "profile", "table"}
    for name, tags in fields.items():
        box = tuple(tags[1:5])
        assert FRAME[0] <= box[0] < box[2] <= FRAME[2] and FRAME[1] <= box[1] < box[3] <= FRAME[3], name
        assert not _overlap(box, TITLE_BLOCK), f"{name} runs into the title block"
        v = ink[name]
        assert v is not None, f"{name} draws nothing"
        assert FRAME[0] <= v[0] and FRAME[1] <= v[1] and v[2] <= FRAME[2] and v[3] <= FRAME[3], \
            f"{name}'s drawing leaves the frame: {np.round(v, 1)}"
        assert not _overlap(v, TITLE_BLOCK), f"{name}'s drawing runs into the title block"
    names = sorted(fields)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            assert not _overlap(tuple(fields[a][1:5]), tuple(fields[b][1:5])), f"fields {a} and {b} overlap"
            assert not _overlap(ink[a], ink[b]), f"views {a} and {b} overlap"
    empty = _largest_empty_square(FRAME, list(ink.values()) + [TITLE_BLOCK])
    assert empty < EMPTY_MAX, f"an empty square of {empty:.0f} mm"


@pytest.mark.parametrize("number", sorted(V))
def test_zone_at_the_largest_gost_scale_that_fits(number):
    fields, ink = _read(number)
    tags = fields["zone"]
    scale = tags[7]
    k = tags.index("extent")
    lo, hi = np.array(tags[k + 1:k + 3]), np.array(tags[k + 3:k + 5])
    assert any(abs(scale - g) < 1e-9 for g in GOST)
    # the drawing at its scale is what the field shows (its hatched zone and lines span the window)
    w, h = (hi - lo) * scale
    v = ink["zone"]
    assert v[2] - v[0] >= 0.9 * w and v[3] - v[1] >= 0.9 * h
    bigger = [g for g in GOST if g > scale * (1 + 1e-9)]
    if not bigger:
        return
    # the other views' fields (they stand GAP apart), the title block
    others = [_grown(tags_[1:5]) for name, tags_ in fields.items() if name != "zone"] + [_grown(TITLE_BLOCK)]
    for room, least in ((tags[k + 5:k + 7], tags[k + 9]), (tags[k + 7:k + 9], 0.0)):  # captions under, beside
        w2, h2 = (hi - lo) * bigger[0] + np.array(room)
        w2 = max(w2, least)
        assert not _fits_somewhere(w2, h2, _grown(FRAME, -GAP), others), \
            f"the zone at {bigger[0]:g}:1 ({w2:.0f} × {h2:.0f} mm) would fit beside the other views"
