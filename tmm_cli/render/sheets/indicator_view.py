"""Sheet 2's indicator diagrams (issue 34): for each piston with a gas load, the gauge pressure p
against its travel s at μ_p, μ_s — one main line a stroke (a row of the file's table), an arrow on it
the way the piston moves and its number, the strokes named under the field —, the piston force
F = p·A read on a second ordinate at μ_F = μ_p·A, and sheet 1's positions projected onto it.

Everything is read from :class:`~tmm_cli.linkage.indicator.Indicator` (``Sheet2.indicators``): the
field draws and places, it computes nothing. :func:`place` finds the fields room on the sheet
(beside or under Zhukovsky's lever, else over the energy–mass diagram).
"""

from __future__ import annotations

import math

import numpy as np

from ...i18n import tr
from ...i18n.numbers import num
from ...linkage.scales import drafting_scale
from .lever_parts import (
    GAP,
    MM,
    NUMBERS_H,
    SCALE_H,
    caption,
    caption_height,
    field,
    head,
    position_numbers,
    scale_line,
    wrap_items,
)
from .paper import H_LABEL, H_MIN_LABEL

LEFT = 20.0  # [mm] left of the p axis: its tick values
RIGHT = 32.0  # right of the curves to the F axis' values' end
TOP = 13.0  # above the highest ordinate: the arrow and the axis' name
BOTTOM = 3.0
TICK_MM = 8.0  # the ordinates' ticks at least this far apart
WIDTH_MIN = 150.0


def heading(ind, lang: str) -> str:
    return tr(lang, "Indicator diagram, piston {n}").format(n=ind.number)


def _stroke_word(stroke: str, lang: str) -> str:
    return {"away": tr(lang, "away from the head"), "back": tr(lang, "towards the head"),
            "expansion": tr(lang, "expansion"), "exhaust": tr(lang, "exhaust"), "intake": tr(lang, "intake"),
            "compression": tr(lang, "compression")}[stroke]


def _items(ind, lang: str) -> list[str]:
    items = [f"{j + 1} — " + _stroke_word(st, lang) for j, st in enumerate(ind.strokes)]
    items.append(f"μ_{{F}} = μ_{{p}}·A = {num(ind.mu_F, lang, sig=4)} " + tr(lang, "N/mm"))
    items.append(f"A = {num(ind.area, lang, sig=4)} " + tr(lang, "m²"))
    items.append(f"H = {num(ind.stroke * MM, lang, sig=4)} " + tr(lang, "mm"))
    return items


def _extent(ind) -> tuple[float, float, float]:
    """(length of s, up, down) [mm] of the drawing."""
    pts = np.vstack([ind.row_mm(j) for j in range(len(ind.pressure))])
    return ind.stroke / ind.mu_s, max(float(pts[:, 1].max()), 0.0), max(float(-pts[:, 1].min()), 0.0)


def size(sh, ind, lang: str, width: float | None = None) -> tuple[float, float]:
    """(width, height) [mm] the field of one indicator diagram needs."""
    length, up, down = _extent(ind)
    w = max(LEFT + length + RIGHT + 8.0, WIDTH_MIN)
    n = len(wrap_items(sh, _items(ind, lang), (width or w) - 4.0))
    return w, head(sh, heading(ind, lang), width or w) + SCALE_H + TOP + up + down + BOTTOM + NUMBERS_H \
        + (_rows(ind) - 4) * (H_MIN_LABEL + 2.2) + caption_height(n) + 2.0


def _rows(ind) -> int:
    """Rows of position numbers under the s axis: 4, and 7 for the 2·N positions of a two-turn cycle
    (each s/H then carries up to four positions' numbers)."""
    return 7 if len(ind.marks) > 16 else 4


def _ticks(lo: float, hi: float, mu: float) -> tuple[float, list[float]]:
    """A round step (at least TICK_MM apart at μ) and the ticks lo … hi it gives (0 among them)."""
    step = drafting_scale(mu * TICK_MM, 1.0)
    k0, k1 = math.ceil(lo / step - 1e-9), math.floor(hi / step + 1e-9)
    return step, [k * step for k in range(k0, k1 + 1)]


def draw(sh, ind, lang: str, box) -> None:
    """One piston's indicator diagram in `box` (the field ``indicator_<number>``; its XDATA origin is
    the diagram's origin s = 0, p = 0, its scale 1 drawing mm per mm)."""
    f = field(sh, f"indicator_{ind.number}", box, heading(ind, lang))
    unit_p, unit_s = tr(lang, "MPa/mm"), tr(lang, "m/mm")
    scale_line(sh, f, f"μ_{{s}} = {num(ind.mu_s, lang, sig=3)} {unit_s}; μ_{{p}} = {num(ind.mu_p, lang, sig=3)} {unit_p}")
    lines = wrap_items(sh, _items(ind, lang), box[2] - box[0] - 4.0)
    x0b, _, x1b, y1b = f.inner
    within = (x0b, box[1] + caption_height(len(lines)), x1b, y1b)
    length, up, down = _extent(ind)
    spare = max(0.0, (x1b - x0b) - (LEFT + length + RIGHT))
    ox = x0b + LEFT + spare / 2
    oy = y1b - TOP - up
    sh.set_field_transform(f, (ox, oy), 1.0, "")
    # the axes: s along the stroke, p up; the F axis at the right with round forces
    sh.line((ox, oy), (ox + length + 5.0, oy), "Основные")
    sh.arrow((ox + length + 9.0, oy), (1, 0), "Основные", 4.0, 1.2)
    sh.label("s", (ox + length + 9.0, oy), H_LABEL, within=within, dirs=("ne", "n", "se", "s"), dists=(0.8, 2.0),
             priority=8)
    sh.line((ox, oy - down - 1.0), (ox, oy + up + 4.0), "Основные")
    sh.arrow((ox, oy + up + 8.0), (0, 1), "Основные", 4.0, 1.2)
    sh.label(tr(lang, "p, MPa"), (ox, oy + up + 8.0), H_LABEL, within=within, dirs=("w", "nw", "e", "ne"), dists=(1.2, 2.5),
             priority=8)
    _, pt = _ticks(-down * ind.mu_p, up * ind.mu_p, ind.mu_p)
    for p in pt:
        y = oy + p / ind.mu_p
        sh.line((ox - 1.2, y), (ox, y), "Тонкие")
        sh.text(ox - 2.0, y - H_MIN_LABEL / 2, num(p, lang, sig=3), H_MIN_LABEL, align="right")
    xf = ox + length + 16.0
    sh.line((xf, oy - down - 1.0), (xf, oy + up + 4.0), "Тонкие")
    sh.arrow((xf, oy + up + 8.0), (0, 1), "Тонкие", 4.0, 1.2)
    sh.label(tr(lang, "F, N"), (xf, oy + up + 8.0), H_LABEL, within=within, dirs=("e", "ne", "w", "nw"),
             dists=(1.2, 2.5), priority=8)
    _, ft = _ticks(-down * ind.mu_F, up * ind.mu_F, ind.mu_F)
    for fv in ft:
        y = oy + fv / ind.mu_F
        sh.line((xf, y), (xf + 1.2, y), "Тонкие")
        sh.text(xf + 2.0, y - H_MIN_LABEL / 2, num(fv, lang, sig=4), H_MIN_LABEL, align="left")
    # the strokes, each with its arrow the way the piston moves and its number
    for j in range(len(ind.pressure)):
        pts = ind.row_mm(j) + np.array([ox, oy])
        sh.poly(pts, "Основные")
        tip, d = _arrow_at(pts, oy)
        sh.arrow(tuple(tip), tuple(d), "Основные", 4.0, 1.2)
        nrm = np.array([-d[1], d[0]]) / (np.hypot(*d) or 1.0)
        side = ("n", "ne", "nw", "e", "w") if nrm[1] >= 0 else ("s", "se", "sw", "e", "w")
        sh.label(str(j + 1), tuple(tip), H_LABEL, within=within, dirs=side + ("n", "s"), dists=(1.2, 2.5, 4.0),
                 priority=7)
    # sheet 1's positions: an ordinate from the s axis to the stroke acting, the numbers under the axis
    xs = []
    for label, row, x in ind.marks:
        xm = ox + x * ind.stroke / ind.mu_s
        y = oy + ind.pressure_at(row, x) / ind.mu_p
        sh.line((xm, oy - 1.2), (xm, oy + 1.2), "Тонкие")
        if abs(y - oy) > 1.5:
            sh.line((xm, oy), (xm, y), "Тонкие")
        xs.append((xm, label))
    position_numbers(sh, within, xs, oy - down, rows=_rows(ind))
    caption(sh, box, lines)


def _arrow_at(pts: np.ndarray, y_axis: float):
    """Where a stroke's arrow goes: the point of the middle 70 % of the polyline (by length) farthest
    from the s axis (an arrow on the axis would not be seen), nearest the middle among equals; its
    tip and the direction of travel there."""
    seg = np.hypot(*np.diff(pts, axis=0).T)
    cum = np.concatenate([[0.0], np.cumsum(seg)])
    total = float(cum[-1]) or 1.0
    best = None
    for frac in np.linspace(0.15, 0.85, 57):
        at = frac * total
        k = min(int(np.searchsorted(cum, at, side="right")) - 1, len(seg) - 1)
        while seg[k] <= 0.0 and k > 0:
            k -= 1
        t = (at - cum[k]) / (seg[k] or 1.0)
        q = pts[k] + (pts[k + 1] - pts[k]) * t
        key = (round(abs(float(q[1]) - y_axis), 1), -abs(frac - 0.5))
        if best is None or key > best[0]:
            best = (key, q, pts[k + 1] - pts[k])
    return best[1], best[2]


def fields(sh, s, lang: str, boxes) -> None:
    for ind, box in zip(s.indicators, boxes):
        draw(sh, ind, lang, box)


def place(sh, s, lang: str, lever, witt, lever_min):
    """Room for the indicator diagrams: (lever box, energy–mass box, the indicators' boxes). Tried in
    turn: beside the lever in its row (side by side or one over the other), under it, over the
    energy–mass diagram (keeping it 110 mm); else beside the lever, which then takes a smaller μ.
    `lever_min(width)` is the lever's least (width, height) in a field `width` wide."""
    inds = s.indicators
    if not inds:
        return lever, witt, ()
    need = [size(sh, ind, lang) for ind in inds]
    w1, h1 = max(w for w, _ in need), max(h for _, h in need)
    n = len(inds)
    shapes = [(n * w1 + (n - 1) * GAP, h1, "row"), (w1, n * h1 + (n - 1) * GAP, "column")]
    x0, y0, x1, y1 = lever
    for W, H, how in shapes:  # beside the lever, at the bottom of its row
        rest = x1 - x0 - W - GAP
        if H <= y1 - y0 and rest > 0:
            lw, lh = lever_min(rest)
            if lw <= rest and lh <= y1 - y0:
                return (x0, y0, x1 - W - GAP, y1), witt, _boxes(x1 - W, y0, W, H, n, how, w1, h1)
    for W, H, how in shapes:  # under the lever
        rest = y1 - y0 - H - GAP
        if W <= x1 - x0 and rest > 0:
            lw, lh = lever_min(x1 - x0)
            if lw <= x1 - x0 and lh <= rest:
                return (x0, y0 + H + GAP, x1, y1), witt, _boxes(x0 + (x1 - x0 - W) / 2, y0, W, H, n, how, w1, h1)
    if witt is not None:
        a0, b0, a1, b1 = witt
        for W, H, how in shapes:
            if W <= a1 - a0 and b1 - b0 - H - GAP >= 110.0:
                return lever, (a0, b0, a1, b1 - H - GAP), _boxes(a0 + (a1 - a0 - W) / 2, b1 - H, W, H, n, how, w1, h1)
    W, H, how = shapes[0] if x1 - x0 - shapes[0][0] > 150.0 else shapes[1]
    return (x0, y0, x1 - W - GAP, y1), witt, _boxes(x1 - W, y0, W, min(H, y1 - y0), n, how, w1, h1)


def _boxes(x: float, y: float, W: float, H: float, n: int, how: str, w1: float, h1: float):
    if how == "row":
        return tuple((x + k * (w1 + GAP), y, x + k * (w1 + GAP) + w1, y + H) for k in range(n))
    h = (H - (n - 1) * GAP) / n
    return tuple((x, y + H - (k + 1) * h - k * GAP, x + W, y + H - k * h - k * GAP) for k in range(n))
