"""What every figure of tmm shares: a fixed layout, cheap PNG encoding, book symbols with real
subscripts (matplotlib mathtext) and tick labels with the reader's decimal sign.

Why fixed layouts: the figures' contents never change their arrangement (a title of known lines,
axes, a legend of known rows), so the margins are set once from the figure size instead of
asking the constrained-layout engine, which draws every figure twice (half of the saving time).

matplotlib is imported inside the functions only, so importing this module stays cheap.
"""

from __future__ import annotations

import math
import os
import re
import sys

from ...i18n.numbers import num
from .agg import copying_ticks, png_rgb, share_svg_text  # noqa: F401  (the figures' kit; the hooks live in agg.py)

PT = 1 / 72  # inch per point

# x_sub where x is one Latin or Greek letter and sub letters, digits or a prime: "i_пл", "z_c′",
# "φ_у", "ν_max", "l_OC", "φ_α1". Not inside a word ("phi_deg" stays as it is).
_SYMBOL = re.compile(r"(?<![A-Za-zА-Яа-яЁёα-ωΑ-Ω_\\$])([A-Za-zα-ωΑ-Ω])_([0-9A-Za-zА-Яа-яЁёα-ω′]+)")


def literal_text(text: str) -> str:
    r"""A person's text (a mechanism's name) for a matplotlib text: every "$" escaped, so no part of
    it is mathtext (an unknown macro or a lone "^" would stop the drawing) — shown as typed.

    >>> literal_text("A $x^$ B")
    'A \\$x^\\$ B'
    """
    return str(text).replace("$", r"\$")


def mt(text: str) -> str:
    """Book symbols of `text` as mathtext: a letter, then its subscript set upright and small.

    The subscript is ``x_\\text{k}`` (mathtext has ``\\text`` since matplotlib 3.8, below the
    package's floor): the same pixels as ``x_\\mathregular{k}`` (compared), parsed in half the
    time — mathtext's grammar takes a braced group character by character, ``\\text`` reads it as
    one literal, and a legend entry or a title is parsed anew for every variant, its numbers being new.

    >>> mt("i_пл = n_д/n_кр")
    '$i_\\\\text{пл}$ = $n_\\\\text{д}$/$n_\\\\text{кр}$'
    >>> mt("r_0 = 48,9; z_12")
    '$r_0$ = 48,9; $z_{12}$'
    >>> mt("2z_c")
    '2$z_\\\\text{c}$'
    >>> mt("rise, max 31°")
    'rise, max 31°'
    """
    def sub(m) -> str:
        x, s = m.group(1), m.group(2)
        if s.isdigit():  # digits are upright in mathtext anyway: no font switch to parse
            return f"${x}_{s}$" if len(s) == 1 else f"${x}_{{{s}}}$"
        return f"${x}_\\text{{{s}}}$"

    return _SYMBOL.sub(sub, text)


def new_figure(width_in: float, height_in: float):
    """An empty figure of the given size with no layout engine (the caller places the axes)."""
    from .agg import classes

    figure, canvas = classes()
    fig = figure(figsize=(width_in, height_in), layout="none")
    canvas(fig)
    return fig


def title_height(lines: int, fontsize: float = 12.0, pad_pt: float = 8.0) -> float:
    """Height [inch] of a title of `lines` lines at `fontsize` points, with its padding."""
    return (lines * fontsize * 1.25 + pad_pt) * PT


def legend_height(entries: int, ncol: int, fontsize: float = 8.0) -> float:
    """Height [inch] of a frameless legend of `entries` in `ncol` columns at `fontsize`."""
    rows = max(1, math.ceil(entries / ncol))
    return (rows * fontsize * 1.75 + 6.0) * PT


def bottom_legend(fig, handles, labels, ncol: int, fontsize: float = 8.0) -> None:
    """The legend in one frameless block centred at the bottom edge of the figure."""
    fig.legend(handles, labels, loc="lower center", bbox_to_anchor=(0.5, 0.003), ncol=ncol, fontsize=fontsize,
               frameon=False)


def suptitle(fig, text: str, fontsize: float = 12.0) -> None:
    """The figure title at the top edge (fixed place: no layout engine moves it)."""
    fig.suptitle(text, y=1.0 - 4 * PT / fig.get_figheight(), va="top", fontsize=fontsize)


def decimal_commas(fig, lang: str) -> None:
    """Tick labels with a decimal comma under ru (every axis of `fig`, secondary axes too)."""
    if lang != "ru":
        return
    from matplotlib.ticker import ScalarFormatter

    class CommaFormatter(ScalarFormatter):
        def __call__(self, x, pos=None):
            return super().__call__(x, pos).replace(".", ",")

        def get_offset(self):
            return super().get_offset().replace(".", ",")

    def axes_of(ax):
        yield ax
        for child in getattr(ax, "child_axes", ()):
            yield from axes_of(child)

    for top in fig.axes:
        for ax in axes_of(top):
            for axis in (ax.xaxis, ax.yaxis):
                if type(axis.get_major_formatter()) is ScalarFormatter:
                    axis.set_major_formatter(CommaFormatter())


def fmt(lang: str):
    """``f(x, **kw) = num(x, lang, **kw)``: numbers in figure texts as the reader writes them."""
    return lambda x, **kw: num(x, lang, **kw)


def _warm_up() -> None:
    """Build what both processes need once, before the fork: mathtext's grammar (~0.2 s, kept on
    the parser class) and the DejaVu fonts (regular, bold, oblique)."""
    import io

    fig = new_figure(1, 1)
    fig.text(0.1, 0.5, mt("x_пл"), fontsize=10)
    fig.text(0.1, 0.2, "x", fontsize=10, weight="bold")
    fig.savefig(io.BytesIO(), format="png", dpi=10)


_FORKED = False  # set in a child forked here: it never forks again (two cores are busy already)


def can_fork() -> bool:
    """Whether work may be spread over a forked child process (Linux, more than one core, and not
    inside such a child already)."""
    return sys.platform.startswith("linux") and (os.cpu_count() or 1) > 1 and hasattr(os, "fork") and not _FORKED


class SharedWork:
    """Tasks shared by this process and a forked child, each run once, whoever is free first.

    `shared` tasks (largest first) go into a queue both processes take from; `child_first` tasks
    the child runs before it takes from the queue (the sheets, which no report waits for). This
    process takes its part with :meth:`run_here`; :meth:`wait_shared` returns once every shared
    task is done, :meth:`wait` once everything is. A task the child took but did not finish (it
    failed, or was killed) is run here instead, so the files come out the same and an error
    surfaces here as usual. :meth:`abort` kills the child at once (SIGKILL) and reaps it: the child
    writes only into the caller's staging folder, which the caller removes. Used as a context
    manager, an exception in the body aborts; a normal exit waits for everything.

    The queue is a pipe holding one byte per task (a read of one byte is atomic); the child
    reports each finished task through a second pipe and leaves with ``os._exit``, so it runs
    none of this process's ``finally`` blocks or exit handlers. Without fork (other systems, one
    core, ``fork=False``) everything runs here, in order.
    """

    def __init__(self, shared=(), child_first=(), fork: bool = True):
        self.tasks = list(shared) + list(child_first)
        self.n_shared = len(shared)
        if len(self.tasks) > 255:
            raise ValueError("at most 255 tasks")
        self.done: set[int] = set()
        self.pid = self._r = self._q = None
        self._buf = b""
        if not (fork and self.tasks and can_fork()):
            return
        q_r, q_w = os.pipe()
        os.write(q_w, bytes(range(self.n_shared)))
        os.close(q_w)
        r, w = os.pipe()
        sys.stdout.flush()
        sys.stderr.flush()
        pid = os.fork()
        if pid == 0:  # the child
            global _FORKED
            _FORKED = True
            code = 1
            try:
                os.close(r)
                for i in range(self.n_shared, len(self.tasks)):
                    self.tasks[i]()
                    os.write(w, bytes([i]))
                while True:
                    got = os.read(q_r, 1)
                    if not got:
                        break
                    self.tasks[got[0]]()
                    os.write(w, got)
                code = 0
            finally:
                os._exit(code)
        os.close(w)
        self.pid, self._r, self._q = pid, r, q_r

    def run_here(self) -> None:
        """Take shared tasks from the queue and run them here until it is empty."""
        if self._q is None:
            for i in range(self.n_shared):
                if i not in self.done:
                    self.tasks[i]()
                    self.done.add(i)
            return
        while True:
            got = os.read(self._q, 1)
            if not got:
                break
            self.tasks[got[0]]()
            self.done.add(got[0])

    def _read_until(self, needed) -> None:
        """Read the child's reports until `needed` are done or the child is gone."""
        while self._r is not None and not needed <= self.done:
            data = os.read(self._r, 64)
            if not data:  # the child has left (finished or failed)
                self._reap()
                return
            self.done.update(data)

    def _reap(self) -> None:
        for fd in (self._r, self._q):
            if fd is not None:
                os.close(fd)
        self._r = self._q = None
        if self.pid is not None:
            os.waitpid(self.pid, 0)
            self.pid = None

    def _finish(self, needed) -> None:
        self.run_here()
        self._read_until(needed)
        for i in sorted(needed - self.done):  # the child left without them: run them here
            self.tasks[i]()
            self.done.add(i)

    def run_until(self, needed) -> None:
        """Take shared tasks here until every task of `needed` is done (by either process): what
        waits for some tasks only (the note's figures) can start while the rest are drawn."""
        needed = set(needed)
        if self._q is None:
            for i in sorted(needed - self.done):
                self.tasks[i]()
                self.done.add(i)
            return
        import select

        while not needed <= self.done:
            while self._r is not None and select.select([self._r], [], [], 0)[0]:
                data = os.read(self._r, 64)
                if not data:
                    self._reap()
                    break
                self.done.update(data)
            if needed <= self.done or self._q is None:
                break
            got = os.read(self._q, 1)
            if not got:  # the queue is empty: the rest is the child's, wait for it
                self._read_until(needed)
                break
            self.tasks[got[0]]()
            self.done.add(got[0])
        for i in sorted(needed - self.done):  # the child left without them: run them here
            self.tasks[i]()
            self.done.add(i)

    def wait_shared(self) -> None:
        """Every shared task done (this process takes what is left in the queue first)."""
        self._finish(set(range(self.n_shared)))

    def wait(self) -> None:
        """Everything done and the child reaped."""
        self._finish(set(range(len(self.tasks))))
        if self._r is not None:
            self._read_until(set(range(len(self.tasks) + 1)))  # to the end of the pipe: the child left

    def abort(self) -> None:
        if self.pid is not None:
            try:
                os.kill(self.pid, 9)
            except ProcessLookupError:
                pass
        self._reap()

    def __enter__(self):
        return self

    def __exit__(self, exc_type, exc, tb):
        if exc_type is None:
            try:
                self.wait()
            except BaseException:  # a signal while waiting for the child: it must not outlive this
                self.abort()
                raise
        else:
            self.abort()
        return False


def bare_xaxis(ax, ticks, grid_alpha: float | None = None) -> None:
    """The x axis of `ax` drawn as its grid lines and bottom tick marks at `ticks` only, for the
    upper panels of stacked axes whose x tick labels show on the bottom panel alone.

    Two Line2Ds (the grid lines joined by NaN gaps, the tick marks as one marker line) instead of a
    Tick per position, each of five artists created and laid out at every save: the same pixels
    (the same colours, widths, transforms and drawing order as matplotlib's own) at a fraction of
    the cost. The Axis itself is hidden, so nothing of it is created or drawn.
    """
    import matplotlib as mpl
    import numpy as np
    from matplotlib.lines import TICKDOWN, TICKUP, Line2D

    rc = mpl.rcParams

    def rc_or(key, fallback):
        value = rc.get(key)
        return rc[fallback] if value is None else value

    xs = np.asarray(ticks, dtype=float)
    zorder = ax.xaxis.get_zorder()  # the Axis draws its ticks at its own zorder
    ax.xaxis.set_visible(False)
    gx = np.repeat(xs, 3)
    gx[2::3] = np.nan
    gy = np.tile([0.0, 1.0, np.nan], len(xs))
    alpha = rc_or("grid.major.alpha", "grid.alpha") if grid_alpha is None else grid_alpha
    grid = Line2D(gx, gy, color=rc_or("grid.major.color", "grid.color"), alpha=alpha,
                  linestyle=rc_or("grid.major.linestyle", "grid.linestyle"),
                  linewidth=rc_or("grid.major.linewidth", "grid.linewidth"), marker="", zorder=zorder,
                  transform=ax.get_xaxis_transform("grid"))
    ax.add_artist(grid)  # clipped to the axes patch, like a grid line; the data limits stay
    color = rc["xtick.color"]
    marker = {"out": TICKDOWN, "in": TICKUP, "inout": "|"}[rc["xtick.direction"]]
    marks = Line2D(xs, np.zeros_like(xs), color=color, linestyle="none", marker=marker, markeredgecolor=color,
                   markersize=rc["xtick.major.size"], markeredgewidth=rc["xtick.major.width"], zorder=zorder,
                   transform=ax.get_xaxis_transform("tick1"), clip_on=False)
    ax.add_artist(marks)
    marks.set_clip_path(None)
    marks.set_clip_on(False)


def hide_axis(*axes_axis) -> None:
    """Axes' x or y Axis objects with no ticks and no label, hidden: nothing of them is made or
    drawn (``set_xticks([])`` still makes a major and a minor Tick, five artists each, and lays
    them out at every save). The spines stay."""
    from matplotlib.ticker import NullLocator

    for axis in axes_axis:
        axis.set_major_locator(NullLocator())
        axis.set_visible(False)


# --------------------------------------------------------------------------------------------------
# labels placed from their boxes as drawn (issue 32: a scale's box hid a diagram's peak, a point's
# name sat on another's): matplotlib's renderer measures each candidate place


def text_box(t, renderer):
    """A label's box as drawn [px]: its background box when it has one, else the text's extent (an
    annotation's arrow not counted)."""
    from matplotlib.text import Text

    if hasattr(t, "update_positions"):  # an annotation: its text's place from its point and offset
        t.update_positions(renderer)
    patch = t.get_bbox_patch()
    if patch is not None:
        t.update_bbox_position_size(renderer)
        return patch.get_window_extent(renderer)
    return Text.get_window_extent(t, renderer)


def shown_labels(ax, renderer=None):
    """The labels a panel shows: texts and annotations with text (an annotation whose point lies
    outside the panel is not drawn)."""
    from matplotlib.text import Annotation

    out = []
    for t in ax.texts:
        if not (t.get_visible() and t.get_text().strip()):
            continue
        if isinstance(t, Annotation) and renderer is not None and not t._check_xy(renderer):
            continue
        out.append(t)
    return out


def curve_pixels(ax, step_px: float = 2.0):
    """The points of a panel's curves in pixels, each segment sampled every `step_px` (the lines in
    data coordinates: not the grid, a phase border or a zero line across the whole panel). Only the
    segments within a panel's size of the panel are sampled: a label is never placed farther out, and
    the mesh's gears drawn far beyond their clipped panel gave 5 million points for 800 near it."""
    import numpy as np

    frame = ax.get_window_extent(ax.figure.canvas.get_renderer())
    m = max(frame.width, frame.height)
    lo, hi = np.array([frame.x0 - m, frame.y0 - m]), np.array([frame.x1 + m, frame.y1 + m])
    segs = []
    for line in ax.get_lines():
        if line.get_transform() != ax.transData or not line.get_visible() or line.get_alpha() == 0:
            continue
        xy = ax.transData.transform(np.asarray(line.get_xydata(), dtype=float))
        if line.get_linestyle() in ("None", "none", "", " "):
            ok = np.isfinite(xy).all(axis=1)
            segs.append((xy[ok], xy[ok]))
            continue
        a, b = xy[:-1], xy[1:]
        ok = np.isfinite(a).all(axis=1) & np.isfinite(b).all(axis=1)
        ok &= (np.maximum(a, b) >= lo).all(axis=1) & (np.minimum(a, b) <= hi).all(axis=1)  # near the panel
        segs.append((a[ok], b[ok]))
    if not segs:
        return np.zeros((0, 2))
    a = np.concatenate([s[0] for s in segs])
    b = np.concatenate([s[1] for s in segs])
    n = np.maximum(2, (np.hypot(*(b - a).T) / step_px).astype(int) + 1)
    seg = np.repeat(np.arange(len(a)), n)
    first = np.repeat(np.cumsum(n) - n, n)
    f = (np.arange(len(seg)) - first) / np.repeat(n - 1, n)
    return a[seg] + f[:, None] * (b[seg] - a[seg])


def _covered(box, pts, pad: float = 1.0) -> int:
    if not len(pts):
        return 0
    return int(((pts[:, 0] > box.x0 - pad) & (pts[:, 0] < box.x1 + pad) & (pts[:, 1] > box.y0 - pad)
                & (pts[:, 1] < box.y1 + pad)).sum())


def _overlap_area(a, b, pad: float = 1.0) -> float:
    w = min(a.x1, b.x1) - max(a.x0, b.x0) + pad
    h = min(a.y1, b.y1) - max(a.y0, b.y0) + pad
    return w * h if w > 0 and h > 0 else 0.0


def _outside(box, frame, margin: float = 1.5) -> float:
    return max(0.0, frame.x0 + margin - box.x0) + max(0.0, box.x1 - frame.x1 + margin) \
        + max(0.0, frame.y0 + margin - box.y0) + max(0.0, box.y1 - frame.y1 + margin)


def _set(t, props: dict) -> None:
    for k, v in props.items():
        if k in ("xy", "xyann"):  # an annotation's point and its text's offset
            setattr(t, k, v)
        else:
            t.update({k: v})


def place_free(ax, t, places, avoid_curves: bool = True, others=None, pts=None, boxes=None) -> int:
    """Put the label `t` at the first of `places` where it stays inside its panel, overlaps no other
    label of the panel (or of `others`) and, with `avoid_curves`, covers no point of a curve; else at
    the place that does least of these, in this order (leaving the panel is worst, a curve under a
    label least bad). A place: a dict of Text properties (position, alignment,
    offset …) set on `t`. `pts` (the panel's :func:`curve_pixels`) and `boxes` ({label: its box}) may
    be given when several labels are placed in turn. Returns the index of the place taken."""
    fig = ax.figure
    r = fig.canvas.get_renderer()
    frame = ax.get_window_extent(r)
    if avoid_curves and pts is None:
        pts = curve_pixels(ax)
    import numpy as np

    rest = [o for o in (shown_labels(ax, r) if others is None else others) if o is not t]
    if boxes is None:
        boxes = {}
    boxes = [boxes[o] if o in boxes else text_box(o, r) for o in rest]

    # a point's name nearer another named point than its own reads as that one's
    named = getattr(t, "xycoords", None) == "data"
    if named:
        t_xy = np.asarray(t._get_xy(r, t.xy, "data"), dtype=float)
        near = [np.asarray(o._get_xy(r, o.xy, "data"), dtype=float) for o in rest
                if getattr(o, "xycoords", None) == "data"]
    best, cost_best = 0, None
    for i, props in enumerate(places):
        _set(t, props)
        b = text_box(t, r)
        strange = 0
        if named and near:
            c = np.array([(b.x0 + b.x1) / 2, (b.y0 + b.y1) / 2])
            strange = int(min(np.hypot(*(c - q)) for q in near) < np.hypot(*(c - t_xy)))
        cost = (_outside(b, frame), sum(_overlap_area(b, o) for o in boxes), strange,
                _covered(b, pts) if avoid_curves else 0)
        if not any(cost):
            return i
        if cost_best is None or cost < cost_best:
            best, cost_best = i, cost
    _set(t, places[best])
    return best


def corner_places(first: str = "upper left", inset_pt: float = 4.0):
    """The four corners of a panel as places for a boxed label (:func:`place_free`), `first` first:
    the label `inset_pt` inside the frame (its box, padded 0,25 em, stays inside)."""
    corners = {"upper left": ((0, 1), (inset_pt, -inset_pt), "left", "top"),
               "upper right": ((1, 1), (-inset_pt, -inset_pt), "right", "top"),
               "lower right": ((1, 0), (-inset_pt, inset_pt), "right", "bottom"),
               "lower left": ((0, 0), (inset_pt, inset_pt), "left", "bottom")}
    order = [first] + [c for c in corners if c != first]
    out = [{"xy": corners[c][0], "xyann": corners[c][1], "ha": corners[c][2], "va": corners[c][3]} for c in order]
    # then a line lower at the top (under the phases' names) and a line higher at the bottom
    for c in order:
        (x, y), (dx, dy), ha, va = corners[c]
        out.append({"xy": (x, y), "xyann": (dx, dy + (-14.0 if y else 14.0)), "ha": ha, "va": va})
    return out


def settle(fig) -> None:
    """Each label given places (``t._tmm_places``: a list of :func:`place_free` places, the first
    preferred) put where it hides nothing, after every curve and label of the figure is there and at
    its final size; the labels of a panel in the order they were written."""
    r = fig.canvas.get_renderer()
    for ax in fig.axes:
        todo = [t for t in ax.texts if getattr(t, "_tmm_places", None)]
        if not todo:
            continue
        pts = curve_pixels(ax)
        shown = shown_labels(ax, r)
        boxes = {o: text_box(o, r) for o in shown}
        for t in todo:
            place_free(ax, t, t._tmm_places, others=shown, pts=pts, boxes=boxes)
            boxes[t] = text_box(t, r)


def offset_places(directions, dist_pt: float = 6.0):
    """Places around an annotation's point at `dist_pt` in each direction (unit vectors (dx, dy),
    y up), aligned away from the point."""
    out = []
    for dx, dy in directions:
        ha = "left" if dx > 0.3 else "right" if dx < -0.3 else "center"
        va = "bottom" if dy > 0.3 else "top" if dy < -0.3 else "center"
        out.append({"xyann": (dist_pt * dx, dist_pt * dy), "ha": ha, "va": va})
    return out
