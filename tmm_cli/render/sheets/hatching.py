"""The frame's hatching on sheet 1's scheme placed where no drawn line runs (issue 34): a fixed guide's
surface hatched on the side and over the piece of its length that the links of every drawn position
(and the traced paths) leave free, a fixed pivot's base turned towards a free direction — as a
draftsman would hatch a short free piece rather than across the links.

Both are drawn after the links, the paths and the pins, and ask the sheet's bitmap of what is drawn
(:class:`~.layout.Obstacles`, 0,5 mm cells and their neighbours: a line within about half a millimetre
or a little more counts as a crossing).
"""

from __future__ import annotations

import math

import numpy as np

from .paper import Sheet

STEP = 2.5  # [mm] between a guide's hatch strokes
STROKE = (1.8, 1.4)  # a stroke: 1,8 mm out from the surface, 1,4 mm back along it (the shape sheet 1 always drew)
BEYOND = 30.0  # [mm] a guide may be hatched this far past the ends of its axis
MIN_RUN = 4  # strokes: a hatched piece at least 10 mm long


def blocked(sh: Sheet, a, b, within=None) -> bool:
    """Does the segment a–b [sheet mm] pass through a cell a line is drawn in (or leave `within`)?"""
    a, b = np.asarray(a, float), np.asarray(b, float)
    if within is not None:
        x0, y0, x1, y1 = within
        if min(a[0], b[0]) < x0 or max(a[0], b[0]) > x1 or min(a[1], b[1]) < y0 or max(a[1], b[1]) > y1:
            return True
    ob = sh.obstacles
    n = max(2, int(math.ceil(float(np.hypot(*(b - a))) / ob.STEP)) + 1)
    pts = a + np.outer(np.linspace(0.0, 1.0, n), b - a)
    iy, ix = ob._cells(pts)
    # the neighbouring cells too: two lines crossing at a cell's corner may mark no common cell
    iy = np.clip((iy[:, None] + _DY).ravel(), 0, ob.ny - 1)
    ix = np.clip((ix[:, None] + _DX).ravel(), 0, ob.nx - 1)
    return bool(ob.lines[iy, ix].any())


_DY, _DX = (a.ravel() for a in np.meshgrid((-1, 0, 1), (-1, 0, 1), indexing="ij"))


def guide(sh: Sheet, a, b, normals, within) -> None:
    """A fixed guide's surface parallel to its axis a–b [sheet mm] with its hatch strokes: on the first
    of `normals` (unit vectors from the axis to the surface, the preferred side first; the surface
    4,3 mm off the axis) where the whole length is free; else the longest free run of strokes on
    either side, up to BEYOND past the axis' ends (the axis is then drawn on to it)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    L = float(np.hypot(*(b - a)))
    if L < 1e-6:
        return
    u = (b - a) / L
    ts = np.arange(-BEYOND + 1.0, L + BEYOND, STEP)
    best = None
    for k, n in enumerate(normals):
        n = np.asarray(n, float)
        off = n * 4.3
        free = []
        for t in ts:
            p = a + off + u * t
            q = p + n * STROKE[0] - u * STROKE[1]
            axis = a + u * t  # the axis is drawn on beside a piece past its ends: in the field too
            free.append(not blocked(sh, p, q, within) and not blocked(sh, p - u * STEP / 2, p + u * STEP / 2, within)
                        and _inside(axis - u * STEP, within) and _inside(axis + u * STEP, within))
        free = np.array(free)
        inside = (ts >= 1.0) & (ts < L)
        if free[inside].all():  # the whole travel: as before
            _draw(sh, a + off, u, n, ts[inside], L)
            return
        for i0, i1 in _runs(free):
            length = i1 - i0
            middle = abs((ts[i0] + ts[i1 - 1]) / 2 - L / 2)
            key = (length >= MIN_RUN, length, -k, -middle)
            if best is None or key > best[0]:
                best = (key, a + off, n, ts[i0:i1])
    if best is None or not best[0][0]:
        # nowhere free for 10 mm: the preferred side, the strokes that are free
        n = np.asarray(normals[0], float)
        p0 = a + n * 4.3
        keep = [t for t in np.arange(1.0, L, STEP) if not blocked(sh, p0 + u * t, p0 + u * t + n * STROKE[0] - u * STROKE[1])]
        _draw(sh, p0, u, n, np.array(keep), L, surface=(0.0, L))
        return
    _, p0, n, run = best
    lo, hi = float(run[0]) - STROKE[1] - 0.5, float(run[-1]) + 1.0
    if lo < 0.0:  # the axis drawn on under the hatched piece
        sh.line(a + u * lo, a, "Осевые")
    if hi > L:
        sh.line(b, a + u * hi, "Осевые")
    _draw(sh, p0, u, n, run, L, surface=(lo, hi))


def _inside(p, within) -> bool:
    return within is None or (within[0] <= p[0] <= within[2] and within[1] <= p[1] <= within[3])


def _draw(sh: Sheet, p0, u, n, ts, L: float, surface=None) -> None:
    lo, hi = surface if surface is not None else (0.0, L)
    sh.line(p0 + u * lo, p0 + u * hi, "Основные")
    for t in ts:
        p = p0 + u * t
        sh.line(p, p + n * STROKE[0] - u * STROKE[1], "Тонкие")


def _runs(free: np.ndarray) -> list[tuple[int, int]]:
    """(start, end) index pairs of the runs of True."""
    out, start = [], None
    for i, f in enumerate(list(free) + [False]):
        if f and start is None:
            start = i
        elif not f and start is not None:
            out.append((start, i))
            start = None
    return out


def _ground_parts(q, angle: float, stroke_at: float | None = None):
    """The segments of a fixed pivot's symbol at q whose base faces `angle` [rad] (−π/2: below):
    (legs and base, strokes) [sheet mm]; `stroke_at`: one stroke only, its far end there along the base."""
    c, s = math.cos(angle + math.pi / 2), math.sin(angle + math.pi / 2)
    x, y = float(q[0]), float(q[1])

    def r(px, py):
        return (x + c * px - s * py, y + s * px + c * py)

    body = [(r(-0.6, -1.2), r(-2.5, -5.0)), (r(0.6, -1.2), r(2.5, -5.0)), (r(-4.5, -5.0), r(4.5, -5.0))]
    xs = [-4.5 + 2.2 * k for k in range(5)] if stroke_at is None else [stroke_at]
    strokes = [(r(x0 + 1.5, -5.0), r(x0, -6.8)) for x0 in xs]
    return body, strokes


def ground(sh: Sheet, q, within=None, layer="Основные") -> None:
    """A fixed pivot (a small circle on a triangle standing on a hatched base) turned to the first
    direction, from straight below in 15° steps either way, where neither its legs beyond the circle,
    its base nor its strokes touch a drawn line; where none is free (a crank's pivot amid the crank's
    positions) it faces where most of its strokes are free, and the strokes a line crosses are left out."""
    angles = [-math.pi / 2 + math.radians(15.0 * k * sgn) for k in range(12) for sgn in ((1,) if k == 0 else (-1, 1))]

    def clear(a, b):
        a, b = np.asarray(a), np.asarray(b)
        d = b - a
        n = float(np.hypot(*d))
        return not blocked(sh, a + d * min(1.0, 1.6 / n), b, within) if n > 1.6 else True

    for ang in angles:
        body, strokes = _ground_parts(q, ang)
        if all(not blocked(sh, a, b, within) for a, b in body[2:] + strokes) and all(clear(a, b) for a, b in body[:2]):
            break
    else:  # the direction that keeps the most strokes, each slid along the base to a free place
        best = None
        for ang in angles:
            body, _ = _ground_parts(q, ang)
            c, s_ = math.cos(ang + math.pi / 2), math.sin(ang + math.pi / 2)
            keep, last = [], -1e9
            for x0 in np.arange(-4.5, 3.01, 0.5):
                a = (q[0] + c * (x0 + 1.5) + s_ * 5.0, q[1] + s_ * (x0 + 1.5) - c * 5.0)
                b = (q[0] + c * x0 + s_ * 6.8, q[1] + s_ * x0 - c * 6.8)
                if x0 - last >= 2.0 and not blocked(sh, a, b, within):
                    keep.append((a, b))
                    last = x0
            if best is None or len(keep) > len(best[1]):
                best = (body, keep)
            if len(keep) >= 4:  # as many as the base holds
                break
        body, strokes = best
    sh.circle((float(q[0]), float(q[1])), 1.3, layer)
    for a, b in body:
        sh.line(a, b, layer)
    for a, b in strokes:
        sh.line(a, b, "Тонкие")
