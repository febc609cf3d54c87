"""Layout machinery shared by every sheet: views scaled to ГОСТ 2.302 scales that fit their field,
an index of everything drawn, and a greedy label placer that keeps text clear of lines and of
other text.

How a sheet uses it (sheets 1 and 2 of the lever mechanisms can do the same):

1. Split the frame into fields (`paper.Sheet.add_field`); measure each view's extent in its own
   units and take :func:`fit_view` — the largest standard scale at which the view with its margins
   fits the field, the drawing centred in it (`FitResult.origin`).
2. Draw the geometry (`Sheet.line/poly/circle/arc` …): every segment goes into the sheet's
   :class:`Obstacles`.
3. Ask for labels with `Sheet.label(text, anchor, …)` (and dimensions with `Sheet.dim_linear` /
   `Sheet.dim_arc`): they are queued, and `Sheet.place_labels()` puts each one, in priority order,
   at the first candidate position (around its anchor, near first) whose box touches no line and no
   text and stays inside its field; when every near position is taken it tries farther rings with a
   leader (a thin line from the anchor to a shelf under the text, ГОСТ 2.316).
4. Text is always readable from the bottom or the right of the sheet (:func:`readable`).

Everything here is plain geometry in sheet millimetres (numpy only; no ezdxf).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

# ГОСТ 2.302 (label, paper mm per real mm), small to large
GOST_SCALES: tuple[tuple[str, float], ...] = (
    ("1:100", 0.01), ("1:75", 1 / 75), ("1:50", 0.02), ("1:40", 0.025), ("1:25", 0.04), ("1:20", 0.05),
    ("1:15", 1 / 15), ("1:10", 0.1), ("1:5", 0.2), ("1:4", 0.25), ("1:2,5", 0.4), ("1:2", 0.5), ("1:1", 1.0),
    ("2:1", 2.0), ("2,5:1", 2.5), ("4:1", 4.0), ("5:1", 5.0), ("10:1", 10.0), ("20:1", 20.0), ("40:1", 40.0),
    ("50:1", 50.0), ("100:1", 100.0),
)

CLEAR = 0.8  # [mm] a label keeps this far from lines and from other text
DESCENT = 0.25  # below the baseline, in heights (descenders of р, у, ф)
SUB_DESCENT = 0.45  # with a subscript (set 0.3 h lower at 0.7 h)


# ----------------------------------------------------------------------------------------------
# scales


@dataclass(frozen=True)
class FitResult:
    """A view fitted to a field: the scale and where its own origin lands on the sheet."""

    label: str  # ГОСТ 2.302 label, "1:2"
    scale: float  # paper mm per drawing unit
    origin: tuple[float, float]  # sheet position of the view's (0, 0)
    fits: bool  # False: even the smallest allowed scale overflows (the caller says so)
    reduced: bool  # True: a smaller scale than `prefer` was taken to make it fit


def fit_view(lo, hi, room, *, margin=(0.0, 0.0, 0.0, 0.0), choices=None, prefer: float | None = None,
             largest: float | None = None) -> FitResult:
    """The largest ГОСТ 2.302 scale at which the view spanning `lo`…`hi` (its own units) plus paper
    margins (left, bottom, right, top) [mm] fits `room` (x0, y0, x1, y1) [sheet mm], the view
    centred in what is left.

    `prefer`: a scale chosen elsewhere (the core's); it is kept when it fits, else the next smaller
    standard one is taken (``reduced``). `largest` caps the scale (a drawing need not be larger).

    >>> r = fit_view((0, 0), (300, 100), (0, 0, 250, 250))
    >>> r.label, r.origin
    ('1:2', (50.0, 100.0))
    >>> fit_view((0, 0), (100, 100), (0, 0, 250, 250), prefer=2.0).label
    '2:1'
    >>> r = fit_view((0, 0), (200, 100), (0, 0, 250, 250), prefer=2.0)
    >>> r.label, r.reduced
    ('1:1', True)
    """
    lo = np.asarray(lo, dtype=float)
    hi = np.asarray(hi, dtype=float)
    ext = np.maximum(hi - lo, 1e-9)
    ml, mb, mr, mt = margin
    x0, y0, x1, y1 = room
    w, h = x1 - x0 - ml - mr, y1 - y0 - mb - mt
    opts = sorted(GOST_SCALES if choices is None else choices, key=lambda c: c[1])
    if largest is not None:
        opts = [c for c in opts if c[1] <= largest * (1 + 1e-12)] or opts[:1]
    if prefer is not None:
        opts = [c for c in opts if c[1] <= prefer * (1 + 1e-12)] or opts[:1]
    best = None
    for lab, f in opts:
        if ext[0] * f <= w + 1e-9 and ext[1] * f <= h + 1e-9:
            best = (lab, f)
    fits = best is not None
    lab, f = best or opts[0]
    mid = (lo + hi) / 2
    cx = x0 + ml + w / 2
    cy = y0 + mb + h / 2
    reduced = prefer is not None and f < prefer * (1 - 1e-12)
    return FitResult(lab, f, (float(cx - f * mid[0]), float(cy - f * mid[1])), fits, reduced)


def nice_scale(value: float, up: bool = True) -> float:
    """A round scale value (1, 2, 2,5, 4, 5 × 10^k) at or above `value` (below with up=False): the
    book asks for round diagram scales.

    >>> nice_scale(0.0137), nice_scale(3.1), nice_scale(3.1, up=False)
    (0.02, 4.0, 2.5)
    """
    if value <= 0:
        return 1.0
    k = math.floor(math.log10(value))
    steps = (1.0, 2.0, 2.5, 4.0, 5.0, 10.0)
    cands = [s * 10.0 ** k for s in steps] + [s * 10.0 ** (k - 1) for s in steps[3:]]
    if up:
        return float(min(c for c in cands if c >= value * (1 - 1e-12)))
    return float(max(c for c in cands if c <= value * (1 + 1e-12)))


def largest_empty_square(frame, boxes, give_up: float = math.inf) -> float:
    """[mm] The side of the largest square inside `frame` (x0, y0, x1, y1) that overlaps none of
    `boxes`: how much of a sheet is left unused in one place (a layout keeps it small). Stops as
    soon as a square of `give_up` is found (a search for the smallest need not look further).

    >>> largest_empty_square((0, 0, 100, 50), [(0, 0, 30, 50)])
    50.0
    >>> largest_empty_square((0, 0, 100, 100), [(40, 40, 60, 60)])
    40.0
    """
    x0, y0, x1, y1 = frame
    bs = [(max(b[0], x0), max(b[1], y0), min(b[2], x1), min(b[3], y1)) for b in boxes]
    bs = sorted((b for b in bs if b[2] > b[0] and b[3] > b[1]), key=lambda b: b[1])
    xs = sorted({x0, x1, *(b[0] for b in bs), *(b[2] for b in bs)})
    best = 0.0
    for i, xa in enumerate(xs):  # every strip between two box edges: its longest free run of y
        for xb in reversed(xs[i + 1:]):  # widest first: a narrower strip cannot do better than its width
            if xb - xa <= best:
                break
            y = y0
            run = 0.0
            for b in bs:
                if b[0] < xb and b[2] > xa:
                    if b[1] - y > run:
                        run = b[1] - y
                    if b[3] > y:
                        y = b[3]
            if y1 - y > run:
                run = y1 - y
            if min(xb - xa, run) > best:
                best = min(xb - xa, run)
                if best >= give_up:
                    return float(best)
    return float(best)


# ----------------------------------------------------------------------------------------------
# text boxes and readability


def readable(rot: float) -> float:
    """A text angle [deg] turned by 180° if needed so that it reads from the bottom or from the
    right of the sheet (ГОСТ 2.304/2.316): the result lies in (−90°, 90°].

    >>> readable(180.0), readable(-90.0), readable(90.0), readable(-30.0)
    (0.0, 90.0, 90.0, -30.0)
    """
    r = ((rot + 180.0) % 360.0) - 180.0
    if r <= -90.0 + 1e-9 or r > 90.0 + 1e-9:
        r = ((r + 360.0) % 360.0) - 180.0
    return float(round(r, 9)) + 0.0


def text_corners(x: float, y: float, w: float, h: float, rot: float = 0.0, *, sub: bool = False,
                 pad: float = 0.0) -> np.ndarray:
    """The four corners [sheet mm] of a text's box: insertion (x, y) at the left end of the
    baseline, width `w`, cap height `h`, turned by `rot` [deg]; below the baseline by DESCENT·h
    (SUB_DESCENT·h with a subscript); grown by `pad` on every side."""
    d = (SUB_DESCENT if sub else DESCENT) * h
    x0, y0, x1, y1 = -pad, -d - pad, w + pad, h + pad
    if rot == 0.0:  # the common case, without the rotation's matrix product
        return np.array([[x + x0, y + y0], [x + x1, y + y0], [x + x1, y + y1], [x + x0, y + y1]])
    loc = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
    c, s = math.cos(math.radians(rot)), math.sin(math.radians(rot))
    return loc @ np.array([[c, s], [-s, c]]) + np.array([x, y])


def _aabb(corners) -> tuple[float, float, float, float]:
    """(x0, y0, x1, y1) of a few points (plain Python: numpy's min/max cost more on four points)."""
    xs, ys = zip(*corners.tolist()) if isinstance(corners, np.ndarray) else zip(*corners)
    return float(min(xs)), float(min(ys)), float(max(xs)), float(max(ys))


def boxes_overlap(a: np.ndarray, b: np.ndarray) -> bool:
    """Two convex quadrilaterals overlap (separating axis test; touching counts as apart)."""
    for poly in (a, b):
        for i in range(4):
            e = poly[(i + 1) % 4] - poly[i]
            n = np.array([-e[1], e[0]])
            pa, pb = a @ n, b @ n
            if pa.max() <= pb.min() + 1e-9 or pb.max() <= pa.min() + 1e-9:
                return False
    return True


def segments_hit_box(p0: np.ndarray, p1: np.ndarray, corners: np.ndarray) -> np.ndarray:
    """Which segments p0[i]–p1[i] cross or lie in the box (a rectangle given by its 4 corners)."""
    o = corners[0]
    ex = corners[1] - o
    ey = corners[3] - o
    lx, ly = float(np.hypot(*ex)), float(np.hypot(*ey))
    ux, uy = ex / lx, ey / ly
    a = p0 - o
    b = p1 - o
    ax, ay = a @ ux, a @ uy
    bx, by = b @ ux, b @ uy
    hit = ~((np.maximum(ax, bx) <= 0) | (np.minimum(ax, bx) >= lx) | (np.maximum(ay, by) <= 0) | (np.minimum(ay, by) >= ly))
    if not hit.any():
        return hit
    # the rectangle's corners on both sides of the segment's line
    dx, dy = bx - ax, by - ay
    cs = []
    for cx, cy in ((0.0, 0.0), (lx, 0.0), (lx, ly), (0.0, ly)):
        cs.append(dx * (cy - ay) - dy * (cx - ax))
    cs = np.array(cs)
    return hit & (cs.min(axis=0) <= 0) & (cs.max(axis=0) >= 0)


# ----------------------------------------------------------------------------------------------
# the index of what is drawn


class Obstacles:
    """What is drawn so far, as two bitmaps of the sheet (0.5 mm cells): cells a line passes
    through, cells a text covers. A candidate label is free when its box (grown by CLEAR) touches
    no marked cell — a conservative test, a few microseconds a candidate."""

    RES = 0.5  # [mm] a cell
    STEP = 0.2  # [mm] lines are sampled this densely

    def __init__(self, width: float = 841.0, height: float = 594.0):
        self.nx, self.ny = int(math.ceil(width / self.RES)) + 1, int(math.ceil(height / self.RES)) + 1
        self.lines = np.zeros((self.ny, self.nx), dtype=bool)
        self.texts = np.zeros((self.ny, self.nx), dtype=bool)
        self.taken = np.zeros((self.ny, self.nx), dtype=bool)  # lines | texts: one lookup a candidate

    def _cells(self, pts: np.ndarray):
        ix = np.clip((pts[:, 0] / self.RES).astype(int), 0, self.nx - 1)
        iy = np.clip((pts[:, 1] / self.RES).astype(int), 0, self.ny - 1)
        return iy, ix

    # -- adding
    def add_polyline(self, pts) -> None:
        pts = np.asarray(pts, dtype=float)
        if len(pts) < 2:
            if len(pts):
                cells = self._cells(pts)
                self.lines[cells] = True
                self.taken[cells] = True
            return
        d = np.diff(pts, axis=0)
        n = np.maximum(1, np.ceil(np.hypot(d[:, 0], d[:, 1]) / self.STEP).astype(int))
        seg = np.repeat(np.arange(len(d)), n)
        start = np.repeat(np.cumsum(n) - n, n)
        t = (np.arange(int(n.sum())) - start) / n[seg]
        q = pts[:-1][seg] + d[seg] * t[:, None]
        cells = self._cells(np.vstack([q, pts[-1:]]))
        self.lines[cells] = True
        self.taken[cells] = True

    def add_circle(self, c, r: float, a0: float = 0.0, a1: float = 360.0) -> None:
        span = (a1 - a0) % 360.0 or 360.0
        n = max(8, int(math.ceil(math.radians(span) * r / 1.0)))
        t = np.radians(a0 + np.linspace(0.0, span, n + 1))
        self.add_polyline(np.column_stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)]))

    def add_box(self, corners: np.ndarray) -> None:
        cells = self._box_cells(np.asarray(corners, dtype=float))
        self.texts[cells] = True
        self.taken[cells] = True

    def _box_cells(self, corners: np.ndarray):
        x0, y0, x1, y1 = _aabb(corners)
        e1, e3 = corners[1] - corners[0], corners[3] - corners[0]
        if abs(e1[1]) < 1e-9 and abs(e3[0]) < 1e-9:  # upright: the cells of the rectangle
            ix0, ix1 = int(max(0, x0 // self.RES)), int(min(self.nx - 1, x1 // self.RES))
            iy0, iy1 = int(max(0, y0 // self.RES)), int(min(self.ny - 1, y1 // self.RES))
            return np.s_[iy0:iy1 + 1, ix0:ix1 + 1]
        la, lb = float(np.hypot(*e1)), float(np.hypot(*e3))
        u = np.arange(0.0, la + 1e-9, self.RES / 2)
        v = np.arange(0.0, lb + 1e-9, self.RES / 2)
        uu, vv = np.meshgrid(np.append(u, la), np.append(v, lb))
        pts = corners[0] + np.outer(uu.ravel() / la, e1) + np.outer(vv.ravel() / lb, e3)
        return self._cells(pts)

    # -- looking up
    def free(self, corners: np.ndarray) -> bool:
        """No line cell and no text cell under the box (one lookup of its cells)."""
        return not self.taken[self._box_cells(np.asarray(corners, dtype=float))].any()

    def free_rect(self, x0: float, y0: float, x1: float, y1: float) -> bool:
        """:meth:`free` of an upright box given by its sides (the cells :meth:`_box_cells` takes for
        it, without building its corners: the placer asks this thousands of times a sheet)."""
        ix0, ix1 = int(max(0, x0 // self.RES)), int(min(self.nx - 1, x1 // self.RES))
        iy0, iy1 = int(max(0, y0 // self.RES)), int(min(self.ny - 1, y1 // self.RES))
        return not self.taken[iy0:iy1 + 1, ix0:ix1 + 1].any()

    def line_hits(self, corners: np.ndarray) -> int:
        """How many line cells the box covers (0: free of lines)."""
        return int(np.count_nonzero(self.lines[self._box_cells(np.asarray(corners, dtype=float))]))

    def text_hits(self, corners: np.ndarray) -> int:
        return int(np.count_nonzero(self.texts[self._box_cells(np.asarray(corners, dtype=float))]))

    def segment_hits_text(self, p0, p1) -> int:
        """How many text cells the segment p0–p1 passes (a leader must cross no text)."""
        p0, p1 = np.asarray(p0, dtype=float), np.asarray(p1, dtype=float)
        n = max(2, int(math.ceil(np.hypot(*(p1 - p0)) / self.STEP)) + 1)
        q = p0 + np.outer(np.linspace(0.0, 1.0, n), p1 - p0)
        return int(np.count_nonzero(self.texts[self._cells(q)]))


# ----------------------------------------------------------------------------------------------
# labels


@dataclass
class Label:
    """A text to be placed near `anchor` (sheet mm) by the placer."""

    text: str
    anchor: tuple[float, float]
    h: float
    within: tuple[float, float, float, float]  # the label's box must stay inside
    rot: float = 0.0
    dirs: tuple[str, ...] = ("ne", "e", "n", "se", "nw", "s", "w", "sw")
    dists: tuple[float, ...] = (1.2, 2.5, 4.5)
    leader: bool = True
    priority: int = 0
    positions: tuple = ()  # explicit candidates: (x, y, rot, align) tried before the ring
    dot: bool = False  # a leader ends on a dot (a point inside an outline) instead of an arrow-less end
    order: int = 0
    anchors: tuple = ()  # further points a leader may start from (along a dimension line)
    optional: bool = False  # no free place: left out (the sheet lists it in `omitted`), not forced
    wide: bool = False  # every place with room for a wider font (a leader too) before any without it


# a direction -> (unit vector towards the text, the text box's alignment point: fx, fy in 0..1)
_DIRS = {
    "e": ((1.0, 0.0), (0.0, 0.5)), "w": ((-1.0, 0.0), (1.0, 0.5)),
    "n": ((0.0, 1.0), (0.5, 0.0)), "s": ((0.0, -1.0), (0.5, 1.0)),
    "ne": ((0.707, 0.707), (0.0, 0.0)), "nw": ((-0.707, 0.707), (1.0, 0.0)),
    "se": ((0.707, -0.707), (0.0, 1.0)), "sw": ((-0.707, -0.707), (1.0, 1.0)),
}


def ring_positions(anchor, w: float, h: float, dirs, dists, sub: bool) -> list[tuple[float, float]]:
    """Insertion points (left end of the baseline, unrotated text) of a w × h text put in each
    direction at each distance from `anchor`: the box's near corner/edge at that distance."""
    d_lo = (SUB_DESCENT if sub else DESCENT) * h
    tot = h + d_lo
    out = []
    for dist in dists:
        for name in dirs:
            (ux, uy), (fx, fy) = _DIRS[name]
            px, py = anchor[0] + ux * dist, anchor[1] + uy * dist
            # box lower-left so that the point (fx, fy) of the box is at p
            bx = px - fx * w
            by = py - fy * tot
            out.append((bx, by + d_lo))
    return out


def inside(corners: np.ndarray, box) -> bool:
    x0, y0, x1, y1 = _aabb(corners)
    return box[0] <= x0 and box[1] <= y0 and x1 <= box[2] and y1 <= box[3]
