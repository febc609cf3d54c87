"""Forces drawn as arrows not to scale (as the book draws a group's or the lever's forces): their
lengths, where each goes among the drawing's lines (:func:`place_arrows`), a drawing with its
arrows fitted into a field (:func:`fit_arrows`), and the arrows drawn and named.

Plain geometry in paper millimetres besides the drawing itself (`Sheet`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .lever_parts import dirs_from
from .paper import H_LABEL, Sheet

ARROW_MM = 28.0  # the longest force arrow on a group's or the lever's drawing (not to scale)
ARROW_MIN = 9.0  # the shortest (a force is never too small to be seen and named)


def arrow(sh: Sheet, a, b, layer="Основные"):
    """A force's arrow from a to b [sheet mm]: the shaft, a filled head at b."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    d = b - a
    n = float(np.hypot(*d))
    if n < 0.3:
        return
    head = min(3.5, 0.4 * n)
    sh.line(a, b - d / n * 0.6 * head, layer)
    sh.arrow(b, d, layer, head, 1.1)


def arrow_len(size: float, biggest: float) -> float:
    """An arrow's length on a drawing of forces not to scale: growing with the force, never shorter
    than ARROW_MIN (the square root keeps the small ones visible)."""
    return ARROW_MIN + (ARROW_MM - ARROW_MIN) * math.sqrt(max(size, 0.0) / biggest)


def force_label(sh: Sheet, tail, tip, text: str, within, priority=6, wide: bool = False) -> None:
    """A force's name beside its arrow's tip (a leader may start anywhere along the arrow); `wide`:
    see :meth:`Sheet.label`."""
    tail, tip = np.asarray(tail, float), np.asarray(tip, float)
    u = tip - tail
    u = u / (np.hypot(*u) or 1.0)
    sh.label(text, tuple(tip), H_LABEL, within=within, dirs=dirs_from(u, 6), dists=(0.8, 2.0, 3.5), priority=priority,
             anchors=[tuple(tail + (tip - tail) * t) for t in (0.7, 0.45)], wide=wide)


LABEL_PAD = (13.0, 9.0)  # [mm] beyond an arrow's tip: its name (sideways, up or down)


@dataclass(frozen=True)
class ArrowFit:
    """A drawing of points with force arrows of fixed paper lengths, fitted to a field."""

    fits: bool
    k: float  # paper mm per drawing unit
    origin: tuple[float, float]  # where the drawing's (0, 0) lands


def arrows_box(points, arrows, k: float, pad=(4.0, 4.0)):
    """Lower-left and upper-right corners [paper mm from the drawing's origin] of points [drawing
    units, complex] at the scale k with the arrows (point [units], vector [paper mm]) and the names
    beside their ends."""
    pts = np.asarray(list(points), complex) * k
    tips = np.array([complex(p) * k + complex(v) for p, v in arrows], complex) if arrows else np.zeros(0, complex)
    xs = np.concatenate([pts.real - pad[0], pts.real + pad[0], tips.real - LABEL_PAD[0], tips.real + LABEL_PAD[0]])
    ys = np.concatenate([pts.imag - pad[1], pts.imag + pad[1], tips.imag - LABEL_PAD[1], tips.imag + LABEL_PAD[1]])
    return np.array([xs.min(), ys.min()]), np.array([xs.max(), ys.max()])


def fit_arrows(points, arrows, room, k: float, pad=(4.0, 4.0)) -> ArrowFit:
    """Fit points [drawing units, complex] and arrows (point [units], vector [paper mm]) at the
    scale k into `room`, the names of the arrows beside their tips, the whole centred."""
    lo, hi = arrows_box(points, arrows, k, pad)
    w, h = room[2] - room[0], room[3] - room[1]
    fits = hi[0] - lo[0] <= w + 1e-9 and hi[1] - lo[1] <= h + 1e-9
    mid = (lo + hi) / 2
    return ArrowFit(fits, k, ((room[0] + room[2]) / 2 - mid[0], (room[1] + room[3]) / 2 - mid[1]))


def _seg_dist(q: np.ndarray, segs: np.ndarray) -> np.ndarray:
    """Distances [mm] from each point q (n, 2) to the nearest of the segments (m, 2, 2)."""
    if len(segs) == 0:
        return np.full(len(q), np.inf)
    a, b = segs[:, 0], segs[:, 1]
    d = b - a
    L2 = np.maximum((d ** 2).sum(axis=1), 1e-12)
    t = np.clip(((q[:, None, :] - a[None]) * d[None]).sum(axis=2) / L2[None], 0.0, 1.0)
    near = a[None] + t[..., None] * d[None]
    return np.sqrt(((q[:, None, :] - near) ** 2).sum(axis=2)).min(axis=1)


def place_arrows(items, segs) -> list[tuple[np.ndarray, np.ndarray]]:
    """Where each force's arrow goes: items are (point, unit vector, length) [paper mm], `segs` the
    drawing's lines ((m, 2, 2) [paper mm]). An arrow starts at its point (tail there) unless it would
    run along a line or an earlier arrow; then it ends at its point (tip there, the same line of
    action); only when both clash is it moved 2,5 or 5 mm aside, parallel. Returns (tail, tip)."""
    occupied = [np.asarray(segs, float).reshape(-1, 2, 2)]
    out = []
    for p, u, length in items:
        p, u = np.asarray(p, float), np.asarray(u, float)
        n = np.array([-u[1], u[0]])
        best = None
        for off in (0.0, 2.5, -2.5, 5.0, -5.0):
            base = p + n * off
            for tail, tip in ((base, base + u * length), (base - u * length, base)):
                q = tail + np.outer(np.linspace(0.15, 0.95, 9), tip - tail)
                near = _seg_dist(q, np.concatenate(occupied))
                if np.count_nonzero(near < 1.2) < 3:
                    best = (tail, tip)
                    break
            if best is not None:
                break
        if best is None:
            best = (p, p + u * length)
        out.append(best)
        occupied.append(np.array([[best[0], best[1]]]))
    return out


def draw_arrows(sh: Sheet, origin, arrows, within, priority=6, wide: bool = False) -> None:
    """Draw placed arrows (tail, tip, point [mm from `origin`], label, kind) and name each at its
    free end (the tip, or the tail when the tip is at the force's point); `wide`: see
    :meth:`Sheet.label`."""
    origin = np.asarray(origin, float)
    for tail, tip, point, label, kind in arrows:
        a, b = origin + tail, origin + tip
        arrow(sh, a, b, "Тонкие" if kind == "reaction" else "Основные")
        if np.hypot(*(tip - point)) < 1e-6:
            force_label(sh, b, a, label, within, priority, wide)
        else:
            force_label(sh, a, b, label, within, priority, wide)
