"""Where a figure's labels stand, read from matplotlib's renderer (no pixels compared): each
label's box as drawn (`get_window_extent`, its white box when it has one), so the tests can ask
that no two labels of a panel overlap, that each stays inside its panel, and that a boxed label
(a scale μ, α_w) hides no curve."""

from __future__ import annotations

import numpy as np
from matplotlib.text import Annotation, Text

PAD = 0.5  # px of tolerance at the figure's dpi (100): anti-aliasing, not a touch


def label_box(t: Text, renderer):
    """The label's box as drawn: its white box when it has one, else the text's own extent (an
    annotation's arrow not counted)."""
    if hasattr(t, "update_positions"):  # an annotation: its text's place from its point and offset
        t.update_positions(renderer)
    patch = t.get_bbox_patch()
    if patch is not None:
        t.update_bbox_position_size(renderer)
        return patch.get_window_extent(renderer)
    return Text.get_window_extent(t, renderer)


def labels(ax):
    """The texts shown on a panel (annotations included; an arrow without text is not a label, an
    annotation of a point outside the panel is not drawn)."""
    r = ax.figure.canvas.get_renderer()
    return [t for t in ax.texts if t.get_visible() and t.get_text().strip()
            and not (isinstance(t, Annotation) and not t._check_xy(r))]


def _overlap(a, b, pad=PAD) -> bool:
    return min(a.x1, b.x1) - max(a.x0, b.x0) > pad and min(a.y1, b.y1) - max(a.y0, b.y0) > pad


def overlapping_labels(fig) -> list[tuple[str, str]]:
    """Pairs of labels of one panel whose boxes overlap."""
    r = fig.canvas.get_renderer()
    out = []
    for ax in fig.axes:
        boxes = [(t.get_text(), label_box(t, r)) for t in labels(ax)]
        for i, (ta, a) in enumerate(boxes):
            for tb, b in boxes[i + 1:]:
                if _overlap(a, b):
                    out.append((ta, tb))
    return out


def labels_leaving_their_panel(fig, margin: float = 1.0) -> list[str]:
    """Labels whose box reaches the panel's border (within `margin` px) or runs past it."""
    r = fig.canvas.get_renderer()
    out = []
    for ax in fig.axes:
        if not ax.axison and not ax.patch.get_visible():
            continue
        frame = ax.get_window_extent(r)
        for t in labels(ax):
            b = label_box(t, r)
            if b.x0 < frame.x0 + margin or b.x1 > frame.x1 - margin or b.y0 < frame.y0 + margin \
                    or b.y1 > frame.y1 - margin:
                out.append(t.get_text())
    return out


def _curve_points(ax, step_px: float = 2.0) -> np.ndarray:
    """The drawn points of the panel's curves in pixels, every segment sampled at `step_px`
    (lines in data coordinates only: not the grid, a phase's border or a zero line across the panel)."""
    pts = []
    for line in ax.get_lines():
        if line.get_transform() != ax.transData or not line.get_visible() or line.get_alpha() == 0:
            continue
        xy = ax.transData.transform(np.asarray(line.get_xydata(), dtype=float))
        if line.get_linestyle() in ("None", "none", "", " "):
            pts.append(xy[np.isfinite(xy).all(axis=1)])
            continue
        for a, b in zip(xy[:-1], xy[1:]):
            if not (np.isfinite(a).all() and np.isfinite(b).all()):
                continue
            n = max(2, int(np.hypot(*(b - a)) / step_px) + 1)
            pts.append(a + np.linspace(0.0, 1.0, n)[:, None] * (b - a))
    return np.concatenate(pts) if pts else np.zeros((0, 2))


def boxed_labels_on_curves(fig) -> list[tuple[str, int]]:
    """Boxed labels (the scales μ, α_w) covering points of a curve of their panel: (text, how many)."""
    r = fig.canvas.get_renderer()
    out = []
    for ax in fig.axes:
        pts = _curve_points(ax)
        for t in labels(ax):
            if t.get_bbox_patch() is None:
                continue
            b = label_box(t, r)
            inside = (pts[:, 0] > b.x0 + PAD) & (pts[:, 0] < b.x1 - PAD) & (pts[:, 1] > b.y0 + PAD) & (pts[:, 1] < b.y1 - PAD)
            if inside.any():
                out.append((t.get_text(), int(inside.sum())))
    return out


def texts_leaving_the_figure(fig) -> list[str]:
    """The labels, the axes' names and the legends' texts whose box runs past the figure's edge —
    cut off on the page (the printed figure is exactly its size)."""
    r = fig.canvas.get_renderer()
    frame = fig.bbox
    texts = [(t, label_box(t, r)) for ax in fig.axes for t in labels(ax)]
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            if axis.get_visible() and axis.label.get_visible() and axis.label.get_text().strip():
                texts.append((axis.label, axis.label.get_window_extent(r)))
    for lg in fig.legends + [ax.get_legend() for ax in fig.axes if ax.get_legend()]:
        texts += [(t, t.get_window_extent(r)) for t in lg.get_texts()]
    return [t.get_text() for t, b in texts
            if b.x0 < frame.x0 - PAD or b.x1 > frame.x1 + PAD or b.y0 < frame.y0 - PAD or b.y1 > frame.y1 + PAD]
