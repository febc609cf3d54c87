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
    loc = np.array([[-pad, -d - pad], [w + pad, -d - pad], [w + pad, h + pad], [-pad, h + pad]])
    c, s = math.cos(math.radians(rot)), math.sin(math.radians(rot))
    return loc @ np.array([[c, s], [-s, c]]) + np.array([x, y])


def _aabb(corners: np.ndarray) -> tuple[float, float, float, float]:
    lo = corners.min(axis=0)
    hi = corners.max(axis=0)
    return float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1])


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
    """Segments and text boxes drawn so far, with a coarse grid for quick look-ups."""

    CELL = 12.0

    def __init__(self):
        self._p0: list[np.ndarray] = []
        self._p1: list[np.ndarray] = []
        self._grid: dict | None = None
        self._long: np.ndarray | None = None
        self._P0 = self._P1 = None
        self._recent0: list[np.ndarray] = []
        self._recent1: list[np.ndarray] = []
        self._recent = None
        self.boxes: list[np.ndarray] = []
        self._box_aabb: list[tuple[float, float, float, float]] = []

    # -- adding
    def add_polyline(self, pts) -> None:
        pts = np.asarray(pts, dtype=float)
        if len(pts) < 2:
            return
        p0, p1 = pts[:-1], pts[1:]
        if self._grid is None:
            self._p0.append(p0)
            self._p1.append(p1)
        else:  # after the index was built (leaders): kept aside
            self._recent0.append(p0)
            self._recent1.append(p1)
            self._recent = None

    def add_circle(self, c, r: float, a0: float = 0.0, a1: float = 360.0) -> None:
        span = (a1 - a0) % 360.0 or 360.0
        n = max(4, int(math.ceil(span / max(1.0, min(10.0, math.degrees(2.0 / max(r, 1e-6)))))))
        t = np.radians(a0 + np.linspace(0.0, span, n + 1))
        self.add_polyline(np.column_stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)]))

    def add_box(self, corners: np.ndarray) -> None:
        self.boxes.append(np.asarray(corners, dtype=float))
        self._box_aabb.append(_aabb(corners))
        self._aabb_arr = None

    # -- the grid
    def _build(self) -> None:
        P0 = np.concatenate(self._p0) if self._p0 else np.zeros((0, 2))
        P1 = np.concatenate(self._p1) if self._p1 else np.zeros((0, 2))
        self._P0, self._P1 = P0, P1
        c = self.CELL
        ix0 = np.floor(np.minimum(P0[:, 0], P1[:, 0]) / c).astype(int)
        ix1 = np.floor(np.maximum(P0[:, 0], P1[:, 0]) / c).astype(int)
        iy0 = np.floor(np.minimum(P0[:, 1], P1[:, 1]) / c).astype(int)
        iy1 = np.floor(np.maximum(P0[:, 1], P1[:, 1]) / c).astype(int)
        long = ((ix1 - ix0) > 2) | ((iy1 - iy0) > 2)
        self._long = np.nonzero(long)[0]
        grid: dict = {}
        short = np.nonzero(~long)[0]
        for dx in range(3):
            for dy in range(3):
                sel = short[(ix0[short] + dx <= ix1[short]) & (iy0[short] + dy <= iy1[short])]
                keys = (ix0[sel] + dx) * 100003 + (iy0[sel] + dy)
                order = np.argsort(keys, kind="stable")
                ks, idx = keys[order], sel[order]
                if not len(ks):
                    continue
                cuts = np.nonzero(np.diff(ks))[0] + 1
                for k, part in zip(ks[np.r_[0, cuts]], np.split(idx, cuts)):
                    grid.setdefault(int(k), []).append(part)
        self._grid = {k: np.concatenate(v) for k, v in grid.items()}

    def line_hits(self, corners: np.ndarray) -> int:
        """How many drawn segments cross the box."""
        if self._grid is None:
            self._build()
        x0, y0, x1, y1 = _aabb(corners)
        c = self.CELL
        parts = [self._long]
        for ix in range(int(math.floor(x0 / c)), int(math.floor(x1 / c)) + 1):
            for iy in range(int(math.floor(y0 / c)), int(math.floor(y1 / c)) + 1):
                g = self._grid.get(ix * 100003 + iy)
                if g is not None:
                    parts.append(g)
        idx = np.unique(np.concatenate(parts)) if len(parts) > 1 else parts[0]
        n = int(segments_hit_box(self._P0[idx], self._P1[idx], corners).sum()) if len(idx) else 0
        if self._recent0:
            if self._recent is None:
                self._recent = (np.concatenate(self._recent0), np.concatenate(self._recent1))
            n += int(segments_hit_box(self._recent[0], self._recent[1], corners).sum())
        return n

    def _near(self, x0, y0, x1, y1) -> np.ndarray:
        if getattr(self, "_aabb_arr", None) is None:
            self._aabb_arr = np.array(self._box_aabb, dtype=float).reshape(-1, 4)
        a = self._aabb_arr
        return np.nonzero((a[:, 0] < x1) & (x0 < a[:, 2]) & (a[:, 1] < y1) & (y0 < a[:, 3]))[0]

    def text_hits(self, corners: np.ndarray) -> int:
        x0, y0, x1, y1 = _aabb(corners)
        return sum(1 for i in self._near(x0, y0, x1, y1) if boxes_overlap(self.boxes[i], corners))

    def segment_hits_text(self, p0, p1) -> int:
        """How many text boxes the segment p0–p1 crosses (a leader must cross no text)."""
        p0 = np.asarray(p0, dtype=float)[None]
        p1 = np.asarray(p1, dtype=float)[None]
        lo = np.minimum(p0, p1)[0]
        hi = np.maximum(p0, p1)[0]
        return sum(1 for i in self._near(lo[0], lo[1], hi[0], hi[1]) if segments_hit_box(p0, p1, self.boxes[i])[0])


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
