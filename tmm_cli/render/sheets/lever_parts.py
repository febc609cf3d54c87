"""Pieces sheets 1 and 2 (the lever mechanism) share: the mechanism's links at a position, fixed
pivots and guides (ГОСТ 2.770), a diagram over the crank's turn, captions wrapped to a width, the
scale line under a heading, and the marks of joint and position labels.

Everything is drawn from the core's records (positions, arrays, scales); this module only scales,
places and writes.
"""

from __future__ import annotations

import math

import numpy as np

from .layout import DESCENT, SUB_DESCENT
from .paper import H_LABEL, H_MIN_LABEL, ROOM, Sheet, _dirs_towards, rich_parts

MM = 1000.0  # real millimetres per metre
GAP = 2.0  # between fields
LINE = 5.6  # caption line pitch (3,5 mm text)
H_NOTE = 3.5  # captions
HEAD_PAD = 8.0  # a heading keeps this far from its field's sides: neighbouring headings stay apart
SCALE_H = 10.0  # the scale line under a heading (5 mm text) with its gaps


def sub(name: str) -> str:
    """A joint or plan label with its digits as a subscript: 'O41' → 'O_{41}', 'a3' → 'a_{3}'.

    >>> sub("O41"), sub("s2"), sub("A")
    ('O_{41}', 's_{2}', 'A')
    """
    head = name.rstrip("0123456789")
    tail = name[len(head):]
    return f"{head}_{{{tail}}}" if head and tail else name


def field(sh: Sheet, name: str, box, heading: str):
    """A field whose heading keeps HEAD_PAD from its sides."""
    return sh.add_field(name, box, heading, heading_pad=HEAD_PAD)


def head(sh: Sheet, heading: str, width: float) -> float:
    """The height the heading of a field `width` wide takes (see :func:`field`)."""
    return sh.heading_height(heading, width, heading_pad=HEAD_PAD)


def scale_line(sh: Sheet, f, text: str, h: float = H_LABEL) -> None:
    """The field's scale on its own line under the heading (ГОСТ 2.316: «М 1:2; μ_l = …»); the
    field's inner box shrinks below it."""
    x0, y0, x1, y1 = f.inner
    sh.text((x0 + x1) / 2, y1 - 1.0, text, h, align="center", valign="top", width=x1 - x0 - 2.0, min_h=H_MIN_LABEL)
    f.inner = (x0, y0, x1, y1 - 1.0 - h * (1.0 + SUB_DESCENT) - 1.5)


def wrap_items(sh: Sheet, items: list[str], width: float, h: float = H_NOTE, sep: str = ";  ") -> list[str]:
    """Items joined by `sep` into lines no wider than `width` [mm] (an item is never split), with
    room for a CAD program's wider font (paper.ROOM)."""
    lines, cur = [], ""
    for it in items:
        cand = f"{cur}{sep}{it}" if cur else it
        if cur and sh.text_width(cand, h) * ROOM > width:
            lines.append(cur)
            cur = it
        else:
            cur = cand
    if cur:
        lines.append(cur)
    return lines


def caption(sh: Sheet, box, lines: list[str], h: float = H_NOTE) -> float:
    """`lines` at the bottom of `box`, the last one lowest; returns the top of the block [mm]."""
    if not lines:
        return box[1]
    return sh.caption(box[0], box[2], box[1] + 2.5, lines, h, LINE) + 1.5


def caption_height(n: int) -> float:
    return 0.0 if n == 0 else 2.5 + (n - 1) * LINE + H_NOTE + 2.5


def text_box_height(h: float, text: str) -> float:
    """The height a one-line text takes with its descent."""
    return h * (1.0 + (SUB_DESCENT if any(lv for _, lv in rich_parts(text)) else DESCENT))


# ----------------------------------------------------------------------------------------------
# the mechanism (ГОСТ 2.770)


def ground(sh: Sheet, q, layer="Основные") -> None:
    """A fixed pivot: a small circle on a triangle standing on a hatched base."""
    x, y = float(q[0]), float(q[1])
    sh.circle((x, y), 1.3, layer)
    sh.line((x - 0.6, y - 1.2), (x - 2.5, y - 5.0), layer)
    sh.line((x + 0.6, y - 1.2), (x + 2.5, y - 5.0), layer)
    sh.line((x - 4.5, y - 5.0), (x + 4.5, y - 5.0), layer)
    for k in range(5):
        xx = x - 4.5 + 2.2 * k
        sh.line((xx + 1.5, y - 5.0), (xx, y - 6.8), "Тонкие")


def link_segments(mech, kin, i: int, names=None, unit: float = 1.0, reach: dict | None = None,
                  guide_stub: float = 0.0):
    """What the links of `names` (all when None) look like at position number i of `kin` [real mm]:
    ('line', p0, p1) for bars (from the farthest pins and points on their axis), ('poly', pts) the
    outline and ('hatch', [(p0, p1), …]) the hatching of a bar with a joint off its axis (a rigid plate), ('box', centre, angle, w, h) for blocks and sliders (size
    in paper mm: `unit` real mm per paper mm); a slotted link runs from its pivot past the block to
    `reach[name]` [real mm] plus 4 paper mm. With `guide_stub` [paper mm] > 0 (a group's own view), the
    guide of a slider or block that lies on a link outside `names` is only ('guide', p0, p1) — a stub
    `guide_stub` either side of the block, drawn thin dash-dot: the neighbouring link is not the group's."""
    z = {n: complex(x[i]) * MM for n, x in kin.z.items()}
    on_link: dict[str, list[str]] = {}
    for p in mech.points:
        on_link.setdefault(p.link, []).append(p.name)
    hang = {j for g in mech.groups for j in g.known}  # the points later groups hang on: the link's joints
    out = []
    for ln in mech.links:
        if names is not None and ln.name not in names:
            continue
        if ln.kind in ("crank", "bar"):
            a, b = ln.axis
            d = (z[b] - z[a]) / abs(z[b] - z[a])
            ends, off = [z[a], z[b]], []
            for p in on_link.get(ln.name, []):
                across = abs(((z[p] - z[a]) * d.conjugate()).imag)
                if across <= 1e-6 * max(1.0, abs(z[b] - z[a])):
                    ends.append(z[p])  # on the axis: the bar runs on to it
                elif p in hang:
                    off.append(z[p])  # a joint off the axis: the link is a rigid plate
            t = [((e - z[a]) * d.conjugate()).real for e in ends]
            out.append(("line", z[a] + min(t) * d, z[a] + max(t) * d, ln))
            if off:  # a link of three or more joints: one body, a hatched plate (the book's way)
                hull = convex_hull([z[a] + min(t) * d, z[a] + max(t) * d] + off)
                out.append(("poly", hull + hull[:1], ln))
                if unit > 0:
                    out.append(("hatch", hatch_lines(hull, 2.0 * unit), ln))
        elif ln.kind == "slotted":
            a, cpin = ln.axis
            riders = [g.joints[1] for g in mech.groups if g.guide is not None and g.guide.link == ln.name]
            far = max([abs(z[p] - z[cpin]) for p in on_link.get(ln.name, []) + riders] + [abs(z[a] - z[cpin])])
            r = max(far, (reach or {}).get(ln.name, 0.0))
            d = (z[a] - z[cpin]) / abs(z[a] - z[cpin])
            if mech.groups[ln.group - 1].offset != 0.0:  # an offset slot: the arm from the pivot to it, then the slot
                from ...linkage.chain import slot_axis

                foot, d = (complex(x[i]) for x in slot_axis(mech, kin, ln.name))
                foot = foot * MM
                out.append(("poly", [z[cpin], foot], ln))
                out.append(("line", foot, foot + (r + 4.0 * unit) * d, ln))
            else:
                out.append(("line", z[cpin], z[cpin] + (r + 4.0 * unit) * d, ln))
        elif ln.kind == "block":
            out.append(("box", z[ln.name], float(kin.angle[ln.name][i]), 7.0, 4.0, ln))
        elif ln.kind == "slider":
            from ...linkage.chain import slider_pose

            centre, angle, segs = slider_pose(mech, kin, ln.name, i)
            gd = dict(mech.guided()).get(ln.name)
            foreign = (guide_stub > 0 and names is not None and gd is not None and gd.moving
                       and gd.link not in names)
            for j, (p0, p1) in enumerate(segs):
                if foreign and j == 0:  # the moving guide's segment comes first (slider_pose)
                    e = (p1 - p0) / abs(p1 - p0)
                    half = guide_stub * unit
                    out.append(("guide", centre * MM - half * e, centre * MM + half * e, ln))
                else:
                    out.append(("line", p0 * MM, p1 * MM, ln))
            out.append(("box", centre * MM, angle, 10.0, 5.0, ln))
    return out


def convex_hull(pts: list[complex]) -> list[complex]:
    """The convex hull of points, counter-clockwise (Andrew's monotone chain).

    >>> convex_hull([0j, 2 + 0j, 1 + 1j, 1 + 0.2j])
    [0j, (2+0j), (1+1j)]
    """
    p = sorted(set(pts), key=lambda q: (q.real, q.imag))
    if len(p) < 3:
        return p

    def cross(o, a, b):
        return (a - o).real * (b - o).imag - (a - o).imag * (b - o).real

    lower, upper = [], []
    for q in p:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], q) <= 0:
            lower.pop()
        lower.append(q)
    for q in reversed(p):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], q) <= 0:
            upper.pop()
        upper.append(q)
    return lower[:-1] + upper[:-1]


def hatch_lines(hull: list[complex], step: float) -> list[tuple[complex, complex]]:
    """Thin 45° hatching of a convex polygon, lines `step` apart (ГОСТ 2.306's section lines)."""
    if len(hull) < 3 or step <= 0:
        return []
    u = complex(math.cos(math.pi / 4), math.sin(math.pi / 4))  # along the lines
    n = u * 1j  # across them
    proj = [(q * n.conjugate()).real for q in hull]
    out = []
    c = min(proj) + step / 2
    while c < max(proj):
        hits = []
        for k in range(len(hull)):
            p0, p1 = hull[k], hull[(k + 1) % len(hull)]
            s0, s1 = proj[k], proj[(k + 1) % len(hull)]
            if (s0 - c) * (s1 - c) < 0:
                hits.append(p0 + (p1 - p0) * (c - s0) / (s1 - s0))
        if len(hits) >= 2:
            hits.sort(key=lambda q: (q * u.conjugate()).real)
            out.append((hits[0], hits[-1]))
        c += step
    return out


def draw_links(f, segs, layer: str, linetype, unit: float, size: float = 1.0) -> None:
    """Draw :func:`link_segments` in a field (real mm)."""
    for sg in segs:
        if sg[0] == "hatch":
            if layer != "Основные":
                continue  # the other positions' plates in outline only (the scheme stays readable)
            for p0, p1 in sg[1]:
                f.poly([[p0.real, p0.imag], [p1.real, p1.imag]], "Тонкие", None)
        elif sg[0] == "line":
            p0, p1 = sg[1], sg[2]
            f.poly([[p0.real, p0.imag], [p1.real, p1.imag]], layer, linetype)
        elif sg[0] == "guide":  # a neighbouring link's guide under a block: thin dash-dot (ГОСТ 2.303)
            p0, p1 = sg[1], sg[2]
            f.poly([[p0.real, p0.imag], [p1.real, p1.imag]], "Осевые", None)
        elif sg[0] == "poly":
            f.poly([[q.real, q.imag] for q in sg[1]], layer, linetype)
        else:
            c, angle, w, h = sg[1], sg[2], sg[3], sg[4]
            e = complex(math.cos(angle), math.sin(angle))
            corners = [c + unit * size * (sx * w / 2 + 1j * sy * h / 2) * e for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
            f.poly([[q.real, q.imag] for q in corners], layer, linetype, closed=True)


def pins(mech) -> list[str]:
    """The moving joints drawn as hinges (small circles): every joint of a group and the crank's."""
    hang = {j for g in mech.groups for j in g.known}
    out = []
    for n in mech.joint_names:
        if n in mech.frame:
            continue
        if n == mech.crank.joint or any(n in g.new for g in mech.groups) or n in hang:
            out.append(n)
    return out


def rotation_arrow(sh: Sheet, centre, r: float, sense: int, a_mid: float = 225.0, layer="Тонкие"):
    """An arc of radius r [mm] about `centre` with an arrow in the sense of rotation (+1 ccw); returns
    the point at the middle of the arc (for its label)."""
    a0, a1 = a_mid - 25.0, a_mid + 25.0
    sh.arc(centre, r, a0, a1, layer)
    end = a1 if sense > 0 else a0
    e = math.radians(end)
    tip = np.asarray(centre, float) + r * np.array([math.cos(e), math.sin(e)])
    tangent = np.array([-math.sin(e), math.cos(e)]) * (1 if sense > 0 else -1)
    sh.arrow(tip + tangent * 0.5, tangent, layer, 3.0, 1.0)
    m = math.radians(a_mid)
    return np.asarray(centre, float) + r * np.array([math.cos(m), math.sin(m)]), np.array([math.cos(m), math.sin(m)])


def dirs_from(v, n: int = 8) -> tuple[str, ...]:
    """Compass directions, nearest to the vector v first."""
    return _dirs_towards(v)[:n]


# ----------------------------------------------------------------------------------------------
# a diagram over the crank's turn


def diagram_extent(curves) -> tuple[float, float]:
    """(up, down) [paper mm] of a diagram's ordinates (each ≥ 0)."""
    up = max(max(float(np.max(c)) for c in curves), 0.0)
    down = max(max(float(-np.min(c)) for c in curves), 0.0)
    return up, down


LABEL_APART = 4.0  # [mm] two curves' names anchored closer than this: the later one moves along its curve
DIAGRAM_TOP = 13.0  # above the highest ordinate: the arrow and the axis' name
DIAGRAM_BOTTOM = 3.0  # below the lowest
NUMBERS_H = 2.5 + 2 * (H_MIN_LABEL + 2.2) + H_MIN_LABEL  # three rows of position numbers


def diagram_height(curves) -> float:
    up, down = diagram_extent(curves)
    return DIAGRAM_TOP + up + down + DIAGRAM_BOTTOM


def diagram(sh: Sheet, within, x0: float, y_top: float, length: float, xs, curves, name: str, marks, dashed=(),
            label_curves: bool = True) -> float:
    """One diagram below `y_top`: the abscissa from x0 over `length` with an arrow and φ, the
    ordinate axis with an arrow and `name`, the curves (each (ordinates [mm over xs], layer,
    linetype, label or None)), a tick and an ordinate to the first curve at each of `marks` (x [mm]),
    a dashed line at each of `dashed` (x [mm]); returns the axis' y."""
    ys = [np.asarray(c[0], float) for c in curves]
    up, down = diagram_extent(ys)
    y0 = y_top - DIAGRAM_TOP - up
    sh.line((x0, y0), (x0 + length + 5.0, y0), "Основные")
    sh.arrow((x0 + length + 9.0, y0), (1, 0), "Основные", 4.0, 1.2)
    sh.line((x0, y0 - down - 1.0), (x0, y0 + up + 4.0), "Основные")
    sh.arrow((x0, y0 + up + 8.0), (0, 1), "Основные", 4.0, 1.2)
    sh.label("φ", (x0 + length + 9.0, y0), H_LABEL, within=within, dirs=("se", "ne", "s", "n"), dists=(0.8, 2.0),
             priority=8)
    sh.label(name, (x0, y0 + up + 8.0), H_LABEL, within=within, dirs=("w", "nw", "sw", "e", "ne"), dists=(1.2, 2.5),
             priority=8)
    xs = np.asarray(xs, float)
    for (vals, layer, lt, _), yy in zip(curves, ys):
        keep = np.zeros(len(xs), bool)
        keep[::2] = True
        keep[-1] = True
        sh.poly(np.column_stack([xs[keep], y0 + yy[keep]]), layer, lt)
    for x in marks:
        sh.line((x, y0 - 1.2), (x, y0 + 1.2), "Тонкие")
        h = float(np.interp(x, xs, ys[0]))
        if abs(h) > 1.5:
            sh.line((x, y0), (x, y0 + h), "Тонкие")
    for x in dashed:
        sh.line((x, y0 - down), (x, y0 + up), "Штриховые")
    if label_curves:
        anchors = []
        for (vals, layer, lt, lab), yy in zip(curves, ys):
            if not lab:
                continue
            j = int(np.argmax(np.abs(yy)))
            if float(np.ptp(yy)) < 1.0:  # a straight line: the label near its right end
                j = int(0.88 * (len(yy) - 1))
            if any(math.hypot(xs[j] - ax, yy[j] - ay) < LABEL_APART for ax, ay in anchors):
                # its extreme is an earlier curve's (ΔT_I at ΔT's): named where it parts most from the first
                # curve, away from the earlier names, so that the two names do not meet at one point
                free = np.all([np.abs(xs - ax) >= 3.0 * LABEL_APART for ax, _ in anchors], axis=0)
                if np.any(free):
                    j = int(np.argmax(np.where(free, np.abs(yy - ys[0]) + 1e-3 * np.abs(yy), -1.0)))
            anchors.append((float(xs[j]), float(yy[j])))
            out = (0.0, 1.0) if yy[j] >= 0 else (0.0, -1.0)
            sh.label(lab, (float(xs[j]), y0 + float(yy[j])), H_LABEL, within=within, dirs=dirs_from(out),
                     dists=(1.0, 2.5, 4.5), priority=6)
    return y0


def fixed(x: float, top: float, lang: str, sig: int = 4) -> str:
    """`x` with as many decimals as give `top` (the largest value of its list) `sig` significant
    digits, so that a list reads in one precision and a value that is zero to rounding reads 0.

    >>> fixed(1.757e-14, 9.111, "ru"), fixed(0.6283, 9.111, "ru"), fixed(1383.2, 1383.2, "en")
    ('0', '0,628', '1383')
    """
    from ...i18n.numbers import num

    top = abs(top)
    dec = 0 if top <= 0 else max(0, sig - 1 - math.floor(math.log10(top)))
    text = num(abs(x), lang, decimals=dec)
    return "0" if float(text.replace(",", ".")) == 0.0 else text


MAX_SHOWN = 24  # positions drawn and numbered on a scheme or under a diagram


def shown(positions) -> list:
    """The positions a sheet draws and numbers: all of them up to MAX_SHOWN, else every k-th of the
    crank's regular positions and the extreme ones (the diagrams still tick every position)."""
    regular = [p for p in positions if p.label.isdigit()]
    if len(positions) <= MAX_SHOWN:
        return list(positions)
    k = math.ceil(len(regular) / MAX_SHOWN)
    return [p for p in positions if p.extreme or (p.label.isdigit() and int(p.label) % k == 0)]


def position_numbers(sh: Sheet, within, xs_labels, y: float, h: float = H_MIN_LABEL, rows: int = 3) -> None:
    """Position numbers centred under their ticks at x, in the first of `rows` rows under `y` where
    they are free (two positions a degree apart get two rows)."""
    for x, text in xs_labels:
        w = sh.text_width(text, h)
        pos = [(x - w / 2, y - 1.2 - h - k * (h + 2.2), 0.0) for k in range(rows)]
        sh.label(text, (x, y), h, within=within, positions=pos, dirs=(), dists=(), leader=False, priority=4)
