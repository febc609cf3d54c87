"""A normcontroller's check of a sheet, read back from its DXF document (not from the code that drew
it): every entity inside the frame and inside one field (or the title block); no text over text and
no line through text (boxes of the glyphs' extent); text heights; dashed polylines flagged for
linetype generation; text readable from the bottom or the right. Usable for any sheet (3, 4 and
the lever sheets 1, 2 when they come).

Text boxes: about a TEXT's or MTEXT's alignment point (the left end, centre or right end of its
baseline: TEXT halign 0/1/2, MTEXT attachment 7/8/9); the width is measured with the sheet's font
(ezdxf's font measurement of osifont), optionally `room` times wider (a CAD program's fallback
font, issue 31), the box reaches 0.2·h below the baseline (0.4·h with a lowered index) and h above it.
"""

from __future__ import annotations

import math
import re

import numpy as np

FRAME = (20.0, 5.0, 836.0, 589.0)
TITLE_BLOCK = (836.0 - 185.0, 5.0, 836.0, 60.0)
_RUN = re.compile(r"\\S\^ ([^;]*);|\\S([^;^]*)\^ ;")
_FONTS: dict = {}


def _width(text: str, h: float, wf: float = 1.0) -> float:
    from ezdxf.fonts import fonts

    key = (round(h, 4), round(wf, 4))
    if key not in _FONTS:
        _FONTS[key] = fonts.make_font("osifont.ttf", h, wf)
    return _FONTS[key].text_width(text)


def mtext_runs(content: str):
    wf = 1.0
    if content.startswith("\\W"):
        head, _, content = content.partition(";")
        wf = float(head[2:])
    out, pos = [], 0
    for m in _RUN.finditer(content):
        if m.start() > pos:
            out.append((content[pos:m.start()], 0))
        out.append((m.group(1), -1) if m.group(1) is not None else (m.group(2), 1))
        pos = m.end()
    if pos < len(content):
        out.append((content[pos:], 0))
    return [(t, lv) for t, lv in out if t], wf


def all_texts(doc) -> list[str]:
    """Every text of the sheet as a reader sees it: TEXT as written, MTEXT with its stacked indices
    written inline (r\\S^ 0; -> r0), a number's minus (set as «–»: the sheet font has no U+2212)
    read as '-'."""
    out = [e.dxf.text for e in doc.modelspace().query("TEXT")]
    out += ["".join(t for t, _ in mtext_runs(e.text)[0]) for e in doc.modelspace().query("MTEXT")]
    return [re.sub(r"–(?=\d)", "-", t) for t in out]


def text_boxes(doc, room: float = 1.0):
    """(entity, corners (4, 2), height, rotation, plain text) of every TEXT and MTEXT; `room`: the
    widths that many times osifont's (1.3: a CAD program's wider fallback font, about the text's
    alignment point)."""
    out = []
    for e in doc.modelspace().query("TEXT MTEXT"):
        if e.dxftype() == "TEXT":
            h, wf = e.dxf.height, e.dxf.get("width", 1.0)
            w = _width(e.dxf.text, h, wf)
            low, txt = 0.2 * h, e.dxf.text
        else:
            h = e.dxf.char_height
            runs, wf = mtext_runs(e.text)
            w = sum(_width(t, h if lv == 0 else 0.7 * h, wf) for t, lv in runs)
            low = (0.4 if any(lv < 0 for _, lv in runs) else 0.2) * h
            txt = "".join(t for t, _ in runs)
        rot = e.dxf.get("rotation", 0.0)
        c, s = math.cos(math.radians(rot)), math.sin(math.radians(rot))
        ins = e.dxf.insert
        if e.dxftype() == "TEXT":
            k = {1: 0.5, 2: 1.0}.get(e.dxf.get("halign", 0), 0.0)
            if k:
                ins = e.dxf.align_point
        else:
            k = {8: 0.5, 9: 1.0}.get(e.dxf.get("attachment_point", 7), 0.0)
        w = w * room
        x0 = -k * w
        loc = np.array([[x0, -low], [x0 + w, -low], [x0 + w, h], [x0, h]])
        corners = loc @ np.array([[c, s], [-s, c]]) + np.array([ins[0], ins[1]])
        out.append((e, corners, h, rot, txt))
    return out


def _arc_pts(cx, cy, r, a0, a1):
    span = (a1 - a0) % 360.0 or 360.0
    n = max(8, int(span / 2.0))
    t = np.radians(a0 + np.linspace(0.0, span, n + 1))
    return np.column_stack([cx + r * np.cos(t), cy + r * np.sin(t)])


def entity_points(e):
    """Points of an entity's outline (lines, polylines, arcs, circles, solids) [sheet mm]."""
    t = e.dxftype()
    if t == "LINE":
        return np.array([[e.dxf.start[0], e.dxf.start[1]], [e.dxf.end[0], e.dxf.end[1]]])
    if t == "LWPOLYLINE":
        pts = np.array([p[:2] for p in e.get_points()])
        widths = [max(p[2], p[3]) for p in e.get_points()]
        if max(widths) > 0:  # a dot: its disc
            r = max(widths) / 2 + np.hypot(*(pts.max(0) - pts.min(0))) / 2
            c = pts.mean(axis=0)
            return _arc_pts(c[0], c[1], r, 0, 360)
        return np.vstack([pts, pts[:1]]) if e.closed else pts
    if t == "ARC":
        return _arc_pts(e.dxf.center[0], e.dxf.center[1], e.dxf.radius, e.dxf.start_angle, e.dxf.end_angle)
    if t == "CIRCLE":
        return _arc_pts(e.dxf.center[0], e.dxf.center[1], e.dxf.radius, 0, 360)
    if t == "HATCH":  # its boundary (the pattern's lines lie inside it)
        pts = np.array([v[:2] for path in e.paths for v in path.vertices])
        return np.vstack([pts, pts[:1]])
    if t == "SOLID":
        pts = np.array([[e.dxf.vtx0[0], e.dxf.vtx0[1]], [e.dxf.vtx1[0], e.dxf.vtx1[1]], [e.dxf.vtx2[0], e.dxf.vtx2[1]]])
        return np.vstack([pts, pts[:1]])
    return None


def _seg_box_hits(p0, p1, corners):
    o = corners[0]
    ex, ey = corners[1] - o, corners[3] - o
    lx, ly = np.hypot(*ex), np.hypot(*ey)
    if lx < 1e-9 or ly < 1e-9:
        return np.zeros(len(p0), bool)
    ux, uy = ex / lx, ey / ly
    ax, ay = (p0 - o) @ ux, (p0 - o) @ uy
    bx, by = (p1 - o) @ ux, (p1 - o) @ uy
    hit = ~((np.maximum(ax, bx) <= 0) | (np.minimum(ax, bx) >= lx) | (np.maximum(ay, by) <= 0) | (np.minimum(ay, by) >= ly))
    dx, dy = bx - ax, by - ay
    cs = np.array([dx * (cy - ay) - dy * (cx - ax) for cx, cy in ((0, 0), (lx, 0), (lx, ly), (0, ly))])
    return hit & (cs.min(axis=0) <= 0) & (cs.max(axis=0) >= 0)


def _boxes_overlap(a, b) -> bool:
    for poly in (a, b):
        for i in range(4):
            e = poly[(i + 1) % 4] - poly[i]
            n = np.array([-e[1], e[0]])
            pa, pb = a @ n, b @ n
            if pa.max() <= pb.min() + 1e-6 or pb.max() <= pa.min() + 1e-6:
                return False
    return True


def field_boxes(doc) -> dict:
    out = {}
    for e in doc.modelspace():
        if e.has_xdata("TMM_FIELD"):
            tags = [t.value for t in e.get_xdata("TMM_FIELD")]
            out[tags[0]] = tuple(tags[1:5])
    return out


def _within(lo, hi, box, tol=1e-6) -> bool:
    return box[0] - tol <= lo[0] and box[1] - tol <= lo[1] and hi[0] <= box[2] + tol and hi[1] <= box[3] + tol


def problems(doc, *, min_label=3.5, min_title_block=2.5, room: float = 1.0) -> list[str]:
    """Everything a normcontroller would mark, as sentences (empty: the sheet passes); `room`: the
    texts measured that many times wider (a CAD program's fallback font)."""
    out = []
    msp = doc.modelspace()
    fields = field_boxes(doc)
    boxes = list(fields.items()) + [("title block", TITLE_BLOCK)]
    segs0, segs1 = [], []
    for e in msp:
        pts = entity_points(e)
        if pts is None:
            continue
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        is_frame = e.dxftype() == "LWPOLYLINE" and e.closed and len(e) == 4 and (
            np.allclose([lo[0], lo[1], hi[0], hi[1]], FRAME) or np.allclose([lo[0], lo[1], hi[0], hi[1]], (0, 0, 841, 594)))
        if not is_frame:
            segs0.append(pts[:-1])
            segs1.append(pts[1:])
            if not _within(lo, hi, FRAME):
                out.append(f"{e.dxftype()} on {e.dxf.layer} leaves the frame: {lo.round(1)}–{hi.round(1)}")
            elif not any(_within(lo, hi, b, 0.05) for _, b in boxes):
                out.append(f"{e.dxftype()} on {e.dxf.layer} is in no single field: {lo.round(1)}–{hi.round(1)}")
        if e.dxftype() == "LWPOLYLINE":
            lt = e.dxf.get("linetype", "BYLAYER")
            if lt.upper() == "BYLAYER":
                lt = doc.layers.get(e.dxf.layer).dxf.linetype
            if lt.upper() != "CONTINUOUS" and not (e.dxf.flags & 128):
                out.append(f"dashed polyline ({lt}) without the linetype generation flag")
    P0 = np.concatenate(segs0)
    P1 = np.concatenate(segs1)
    texts = text_boxes(doc, room)
    for e, c, h, rot, txt in texts:
        lo, hi = c.min(axis=0), c.max(axis=0)
        in_tb = _within(lo, hi, TITLE_BLOCK, 0.05)
        if not _within(lo, hi, FRAME):
            out.append(f"text {txt!r} leaves the frame")
        elif not any(_within(lo, hi, b, 0.05) for _, b in boxes):
            out.append(f"text {txt!r} is in no single field")
        if h < (min_title_block if in_tb else min_label) - 1e-9:
            out.append(f"text {txt!r} is {h:g} mm high")
        r = ((rot + 180.0) % 360.0) - 180.0
        if not (-90.0 < r <= 90.0 + 1e-6):
            out.append(f"text {txt!r} at {rot:g}° reads upside down")
        sel = (np.maximum(P0[:, 0], P1[:, 0]) > lo[0]) & (np.minimum(P0[:, 0], P1[:, 0]) < hi[0]) & \
              (np.maximum(P0[:, 1], P1[:, 1]) > lo[1]) & (np.minimum(P0[:, 1], P1[:, 1]) < hi[1])
        if sel.any() and _seg_box_hits(P0[sel], P1[sel], c).any():
            out.append(f"text {txt!r} is crossed by a line")
    for i in range(len(texts)):
        ci = texts[i][1]
        li, hi_ = ci.min(axis=0), ci.max(axis=0)
        for j in range(i + 1, len(texts)):
            cj = texts[j][1]
            lj, hj = cj.min(axis=0), cj.max(axis=0)
            if li[0] < hj[0] and lj[0] < hi_[0] and li[1] < hj[1] and lj[1] < hi_[1] and _boxes_overlap(ci, cj):
                out.append(f"texts {texts[i][4]!r} and {texts[j][4]!r} overlap")
    return out
