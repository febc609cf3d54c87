"""Sheet 1 «Кинематический анализ рычажного механизма» of a mechanism file (issue 24; norm-control:
issue 21).

Fields: the scheme of the mechanism in all positions with the traced paths of its points, at the
ГОСТ 2.302 scale of the core's μ_l; the kinematic diagrams s, v, a of the output link at their
scales; the velocity and the acceleration plans of two positions at μ_v, μ_a with their poles, the
points named and the vectors' values; a table of the main results.

The fields are laid out from the measured size of each drawing at the core's scales (:func:`layout`):
the scheme over the diagrams in the left column, the plans in rows (a position a row) on the right,
the table left of (or above) the title block. Everything is read from
:class:`~tmm_cli.linkage.sheet1.Sheet1`: the drawing scales, shifts and places the core's arrays and
prints the core's numbers; it computes nothing a second time.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...i18n import tr
from ...i18n.numbers import num
from ...linkage.scales import SERIES
from ...linkage.sheet1 import Sheet1
from ...linkage.vector_plans import Plan, book_symbol
from . import hatching
from .cam_sheet import table
from .layout import fit_view
from .lever_parts import (
    GAP,
    H_NOTE,
    MM,
    NUMBERS_H,
    SCALE_H,
    caption,
    caption_height,
    diagram,
    diagram_height,
    dirs_from,
    draw_links,
    field,
    fixed,
    head,
    link_segments,
    pins,
    position_numbers,
    rotation_arrow,
    scale_line,
    shown,
    sub,
    wrap_items,
)
from .paper import FRAME, H_LABEL, H_MIN_LABEL, TB_BOX, TB_H, Sheet, thin_out
from .synthesis_overlay import draw_construction, sheet_name

SCHEME_PAD = (16.0, 16.0, 16.0, 12.0)  # [mm] around the scheme: pivots, sliders, labels
PLAN_PAD = (12.0, 10.0, 12.0, 8.0)  # around a plan: its labels
DIAGRAM_LEFT = 22.0  # [mm] from the field's edge to the diagrams' ordinate axis
DIAGRAM_RIGHT = 16.0  # beyond the abscissa's arrow
TABLE_W = 250.0  # the table beside the title block
ROW_H = 9.0


# ----------------------------------------------------------------------------------------------
# measuring the drawings


def _scheme_extent(s: Sheet1):
    """Lower-left and upper-right corners [real mm] of everything the scheme draws at real size: the
    paths of every joint and point over the turn, the slotted links to their reach."""
    m, c = s.mechanism, s.cycle
    zs = [c.curve.kin.z[n] * MM for n in m.joint_names]
    for p in c.positions:
        for sg in link_segments(m, c.kin, p.index, unit=0.0, reach=_reach(s)):
            if sg[0] == "line":
                zs.append(np.array([sg[1], sg[2]]))
    z = np.concatenate(zs)
    return np.array([z.real.min(), z.imag.min()]), np.array([z.real.max(), z.imag.max()])


def _away_side(m, kin, pin: str, e: complex) -> float:
    """+1 when the guide's surface goes on the right of its direction e (the side −i·e), −1 on the
    left: the side away from the links hinged at the slider's pin (the rod B–C of a shaper comes from
    below its ram: the ram's guide is hatched above), judged over every position of the cycle."""
    zs = kin.z[pin]
    side = 0.0
    for ln in m.links:
        if ln.axis is None or pin not in ln.axis:
            continue
        other = ln.axis[1] if ln.axis[0] == pin else ln.axis[0]
        side += float(np.sum(((kin.z[other] - zs) * np.conj(e)).imag))
    return 1.0 if side >= 0.0 else -1.0


def _reach(s: Sheet1) -> dict[str, float]:
    """How far each slotted link is drawn from its pivot [real mm]: the block's farthest place."""
    m = s.mechanism
    out = {}
    for ln in m.links:
        if ln.kind == "slotted":
            block = m.links[ln.number - 2].name
            k = s.cycle.curve.kin
            riders = [g.joints[1] for g in m.groups if g.guide is not None and g.guide.link == ln.name]
            out[ln.name] = max([float(np.max(k.slide[block][0]))] +
                               [float(np.max(np.abs(k.z[j] - k.z[ln.axis[1]]))) for j in riders]) * MM
    return out


def _scheme_factor(s: Sheet1) -> float:
    """Paper mm per real mm of the core's μ_l (μ_l [m/mm] → 1/(μ_l·1000))."""
    return 1.0 / (s.scheme_scale * MM)


def _plan_points(plan: Plan) -> dict[str, complex]:
    return {n: plan.mm(n) for n in plan.points}


def _plan_extent(plan: Plan):
    z = np.array(list(_plan_points(plan).values()))
    return np.array([z.real.min(), z.imag.min()]), np.array([z.real.max(), z.imag.max()])


def _diagram_series(s: Sheet1):
    """(name, unit, μ, ordinates [paper mm]) of the diagrams s, v, a (ψ, ω, ε for a rocker)."""
    m, sc, cv = s.mechanism, s.scales, s.cycle.curve
    if m.output.kind == "slider":
        names = ("S", "V", "a")
        units = ("m/mm", "(m/s)/mm", "(m/s²)/mm")
    else:
        names = ("ψ", "ω", "ε")
        units = ("rad/mm", "(rad/s)/mm", "(rad/s²)/mm")
    return [(n, u, mu, np.asarray(v) / mu) for n, u, (v, mu) in zip(names, units, ((cv.s, sc.s), (cv.v, sc.v),
                                                                                      (cv.a, sc.a)))]


def _diagrams_size(sh: Sheet, s: Sheet1, lang: str) -> tuple[float, float]:
    w = DIAGRAM_LEFT + s.scales.axis_mm + 9.0 + DIAGRAM_RIGHT
    n_cap = len(wrap_items(sh, _diagram_items(s, lang), w - 4.0))
    h = head(sh, _diagrams_heading(s, lang), w) + sum(diagram_height([y]) + 4.0 for *_, y in _diagram_series(s)) \
        + NUMBERS_H + caption_height(n_cap)
    return w, h


def _diagram_items(s: Sheet1, lang: str) -> list[str]:
    units = {"m/mm": tr(lang, "m/mm"), "(m/s)/mm": tr(lang, "(m/s)/mm"), "(m/s²)/mm": tr(lang, "(m/s²)/mm"),
             "rad/mm": tr(lang, "rad/mm"), "(rad/s)/mm": tr(lang, "(rad/s)/mm"),
             "(rad/s²)/mm": tr(lang, "(rad/s²)/mm")}
    items = [f"μ_{{{name}}} = {num(mu, lang, sig=3)} {units[unit]}" for name, unit, mu, _ in _diagram_series(s)]
    mu_phi = num(math.degrees(s.scales.phi), lang, sig=3)
    items.append(f"μ_{{φ}} = {mu_phi} °/" + tr(lang, "mm"))
    items.append(tr(lang, "positions from position 0"))
    return items


# ----------------------------------------------------------------------------------------------
# the layout


@dataclass(frozen=True)
class Layout1:
    scheme: tuple
    diagrams: tuple
    plans: tuple  # ((velocity box, acceleration box), …) a position a row
    table: tuple


def layout(sh: Sheet, s: Sheet1, lang: str) -> Layout1:
    """The field boxes of sheet 1, each sized to its drawing at the core's scales: the scheme over the
    diagrams in the left column (the scheme takes what the column has spare), the plans in a row
    per position on the right (the rows share what is spare), the table beside the title block (or
    above it when the right part is narrow)."""
    X0, Y0, X1, Y1 = FRAME
    f = _scheme_factor(s)
    lo, hi = _scheme_extent(s)
    pl, pb, pr, pt = SCHEME_PAD
    sw = (hi[0] - lo[0]) * f + pl + pr + 2.0
    shh = (hi[1] - lo[1]) * f + pb + pt + head(sh, _scheme_heading(lang), sw) + SCALE_H \
        + caption_height(_scheme_caption_lines(sh, s, lang, sw))
    dw, dh = _diagrams_size(sh, s, lang)
    wl = max(sw, dw, 240.0)
    # the plans: each row's needs
    rows = []
    for pl_ in s.plans[:2]:
        need = []
        for plan in (pl_.velocity, pl_.acceleration):
            plo, phi = _plan_extent(plan)
            w = max(phi[0] - plo[0] + PLAN_PAD[0] + PLAN_PAD[2], 150.0)
            cap = len(wrap_items(sh, _plan_items(s, plan, pl_.position.index, lang), w - 4.0))
            h = phi[1] - plo[1] + PLAN_PAD[1] + PLAN_PAD[3] + head(sh, _plan_heading(plan, pl_.position.label, lang), w) \
                + SCALE_H + caption_height(cap)
            need.append((w, h))
        rows.append(need)
    wv = max(r[0][0] for r in rows)
    wa = max(r[1][0] for r in rows)
    wr_avail = X1 - X0 - 3 * GAP - wl
    if wv + wa + GAP > wr_avail:  # the left column gives way (its drawings then shrink to fit)
        wl = max(X1 - X0 - 3 * GAP - (wv + wa + GAP), 200.0)
        wr_avail = X1 - X0 - 3 * GAP - wl
    xl0, xl1 = X0 + GAP, X0 + GAP + wl
    xr0, xr1 = xl1 + GAP, X1 - GAP
    # left column: the diagrams at the bottom at their size, the scheme above with the rest
    dh = min(dh, Y1 - Y0 - 3 * GAP - min(shh, 200.0))
    diagrams = (xl0, Y0 + GAP, xl1, Y0 + GAP + dh)
    scheme = (xl0, diagrams[3] + GAP, xl1, Y1 - GAP)
    # right part: the table beside the title block when it fits there, else above it
    th = 12.0 + ROW_H * _results_rows(s) + 3.0
    beside = TB_BOX[0] - GAP - xr0 >= 200.0
    if beside:
        table_box = (xr0, Y0 + GAP, min(TB_BOX[0] - GAP, xr0 + TABLE_W + 60.0), Y0 + GAP + max(th, TB_H - GAP))
        bottom = max(table_box[3], TB_BOX[3])
    else:
        table_box = (xr0, TB_BOX[3] + GAP, xr1, TB_BOX[3] + GAP + th)
        bottom = table_box[3]
    # the plan rows share the height, columns the width, in proportion to their needs
    top_r, bot_r = Y1 - GAP, bottom + GAP
    need_h = [max(r[0][1], r[1][1]) for r in rows]
    spare_h = (top_r - bot_r) - sum(need_h) - GAP * (len(rows) - 1)
    hs = [h + spare_h * h / sum(need_h) for h in need_h] if spare_h < 0 else [h + spare_h / len(rows) for h in need_h]
    spare_w = (xr1 - xr0) - GAP - wv - wa
    wv2 = wv + spare_w * (wv / (wv + wa))
    boxes = []
    y = top_r
    for h in hs:
        boxes.append(((xr0, y - h, xr0 + wv2, y), (xr0 + wv2 + GAP, y - h, xr1, y)))
        y -= h + GAP
    return Layout1(scheme, diagrams, tuple(boxes), table_box)


# ----------------------------------------------------------------------------------------------
# field 1: the scheme in all positions


def _scheme_caption_lines(sh: Sheet, s: Sheet1, lang: str, width: float) -> int:
    return len(wrap_items(sh, _scheme_items(s, lang), width - 4.0))


def _scheme_items(s: Sheet1, lang: str, reduced: str = "") -> list[str]:
    c = s.cycle
    first, last = c.working_start(), c.working_end()
    items = [tr(lang, "position 0 — main lines")]
    if first is not None and first.index != 0:  # crank.start_deg: position 0 is not an extreme
        items.append(tr(lang, "the extreme positions {start} (start of the working stroke) and {end} (its end) — "
                              "dashed").format(start=first.label, end=last.label))
    elif last is not None:
        items.append(tr(lang, "the other extreme position {label} — dashed").format(label=last.label))
    items.append(tr(lang, "dashed curves: the paths of the points"))
    if reduced:
        items.append(reduced)
    return items


def _scheme_heading(lang: str) -> str:
    return tr(lang, "Scheme of the mechanism in its positions")


def _diagrams_heading(s: Sheet1, lang: str) -> str:
    return tr(lang, "Kinematic diagrams of the output link {link}").format(link=s.mechanism.output.link)


def _plan_heading(plan: Plan, label: str, lang: str) -> str:
    if plan.kind == "velocity":
        return tr(lang, "Velocity plan, position {label}").format(label=label)
    return tr(lang, "Acceleration plan, position {label}").format(label=label)


def _scheme_field(sh: Sheet, s: Sheet1, lang: str, box):
    m, c = s.mechanism, s.cycle
    lo, hi = _scheme_extent(s)
    core = _scheme_factor(s)
    f = field(sh, "scheme", box, _scheme_heading(lang))
    # the scale line and the caption take their room first; the drawing is fitted to what is left
    x0, _, x1, y1 = f.inner
    room_top = y1 - SCALE_H
    n_cap = _scheme_caption_lines(sh, s, lang, box[2] - box[0])
    room = (x0, box[1] + caption_height(n_cap), x1, room_top)
    fit = fit_view(lo, hi, room, margin=SCHEME_PAD, prefer=core)
    factor = fit.scale
    sh.set_field_transform(f, fit.origin, factor, fit.label)
    mu = num(1.0 / (factor * MM), lang, sig=3)
    scale_line(sh, f, tr(lang, "M") + " " + _gost(fit.label, lang) + f"; μ_{{l}} = {mu} " + tr(lang, "m/mm"))
    f.clip = room
    within = room
    unit = 1.0 / factor  # one paper millimetre in real millimetres
    reach = _reach(s)
    # the guides: their axes over the sliders' travel (their surfaces hatched after the links, below)
    surfaces = []
    for slider, gd in m.guided():
        if gd.moving:  # a moving guide is drawn with its link
            continue
        zs = c.curve.kin.z[m.link(slider).pins[0]] * MM
        e = gd.unit
        t = ((zs - zs[0]) * e.conjugate()).real
        a = zs[0] + (t.min() - 8.0 * unit) * e
        b = zs[0] + (t.max() + 8.0 * unit) * e
        f.poly([[a.real, a.imag], [b.real, b.imag]], "Осевые")
        n = 1j * e * _away_side(m, c.curve.kin, m.link(slider).pins[0], e)
        surfaces.append((f.p(a.real, a.imag), f.p(b.real, b.imag), [(-n.real, -n.imag), (n.real, n.imag)]))
    # the paths: of the joints thin, of the points that are not joints (centres of mass) dashed
    joints = set(pins(m)) | {m.crank.joint}
    for n in m.joint_names:
        if n in m.frame:
            continue
        z = c.curve.kin.z[n] * MM
        f.poly(thin_out(np.column_stack([z.real, z.imag]), 0.5 * unit), "Тонкие" if n in joints else "Штриховые")
    ends = [p.index for p in c.positions if p.extreme]
    drawn = shown(c.positions)
    for p in drawn:
        if p.index == 0:
            continue
        draw_links(f, link_segments(m, c.kin, p.index, unit=unit, reach=reach),
                   "Штриховые" if p.index in ends else "Тонкие", None, unit, 0.8)
    draw_links(f, link_segments(m, c.kin, 0, unit=unit, reach=reach), "Основные", None, unit, 1.0)
    draw_construction(sh, f, s, lang, within)  # the synthesis' θ, locus, sagitta (tmm synth, issue 33)
    for n in pins(m):
        q = f.p(*(_xy(c.kin.z[n][0])))
        sh.circle(q, 1.2, "Основные")
    # the sense of rotation ω1 about the crank's pivot
    o = np.array(f.p(*(_xy(m.frame[m.crank.pivot]))))
    r = max(0.4 * m.crank.length * MM * factor, 7.0)
    mid, out = rotation_arrow(sh, o, r, m.crank.sense, 225.0)
    sh.label("ω_{1}", mid, H_LABEL, within=within, dirs=dirs_from(out, 5), dists=(1.0, 2.5, 4.5), priority=7)
    # fixed pivots and the guides' surfaces, hatched where the links of every position leave room
    for name, z in m.frame.items():
        if any(name in ln.pins or (ln.axis and name in ln.axis) for ln in m.links):
            hatching.ground(sh, f.p(z.real * MM, z.imag * MM), within)
    for pa, pb, normals in surfaces:
        hatching.guide(sh, pa, pb, normals, within)
    # the position numbers at the crank pin (outward from the pivot), the joints named in position 0
    for p in drawn:
        a = np.array(f.p(*(_xy(c.kin.z[m.crank.joint][p.index]))))
        d = a - o
        d = d / (np.hypot(*d) or 1.0)
        sh.label(p.label, tuple(a), H_MIN_LABEL, within=within, dirs=dirs_from(d, 5), dists=(1.0, 2.2, 3.8),
                 priority=5)
    pts = {n: np.array(f.p(*(_xy(c.kin.z[n][0])))) for n in m.joint_names}
    centre = np.mean(list(pts.values()), axis=0)
    for n, q in pts.items():
        d = q - centre
        d = d / (np.hypot(*d) or 1.0)
        sh.label(sub(n), tuple(q), H_LABEL, within=within, dirs=dirs_from(d), dists=(1.4, 2.8, 4.5), priority=9)
    reduced = ""
    if fit.reduced or not fit.fits:
        reduced = tr(lang, "drawn at {scale}: the scheme does not fit at μ_l = {mu} m/mm").format(
            scale=_gost(fit.label, lang), mu=num(s.scheme_scale, lang, sig=3))
    caption(sh, box, wrap_items(sh, _scheme_items(s, lang, reduced), box[2] - box[0] - 4.0))
    return f


def _xy(z) -> tuple[float, float]:
    z = complex(z) * MM
    return z.real, z.imag


def _gost(label: str, lang: str) -> str:
    return label if lang == "ru" else label.replace(",", ".")


# ----------------------------------------------------------------------------------------------
# field 2: the kinematic diagrams of the output link


def _diagrams_field(sh: Sheet, s: Sheet1, lang: str, box):
    c, sc = s.cycle, s.scales
    cv = c.curve
    f = field(sh, "diagrams", box, _diagrams_heading(s, lang))
    x0b, y0b, x1b, y1b = f.inner
    length = sc.axis_mm
    x0 = x0b + DIAGRAM_LEFT - 1.0 + max(0.0, (x1b - x0b) - (DIAGRAM_LEFT + length + 9.0 + DIAGRAM_RIGHT)) / 2
    xs = x0 + np.asarray(cv.travel) / sc.phi
    marks = [x0 + p.travel / sc.phi for p in c.positions]
    ends = [x0 + p.travel / sc.phi for p in c.positions if p.extreme and p.index != 0]
    series = _diagram_series(s)
    lines = wrap_items(sh, _diagram_items(s, lang), box[2] - box[0] - 4.0)
    cap_h = caption_height(len(lines))
    within = (x0b, y0b + cap_h, x1b, y1b)
    y = y1b
    y_axis = y
    for name, unit, mu, ys in series:
        y_axis = diagram(sh, within, x0, y, length, xs, [(ys, "Основные", None, None)], name, marks, ends)
        down = max(float(-ys.min()), 0.0)
        y = y_axis - down - 3.0 - 4.0
    # the position numbers under the last diagram
    position_numbers(sh, within, [(x0 + p.travel / sc.phi, p.label) for p in shown(c.positions)], y + 4.0)
    caption(sh, box, lines)
    return f


# ----------------------------------------------------------------------------------------------
# fields 3–6: the plans


def _vec_symbol(sym: str) -> str:
    """A plan vector's symbol in the sheet's markup: 'v_BA' → 'v_{BA}', 'a^τ_BA' → 'a^{τ}_{BA}'."""
    head, _, tail = sym.partition("_")
    sup = ""
    if "^" in head:
        head, sup = head.split("^", 1)
        sup = f"^{{{sup}}}"
    return f"{head}{sup}_{{{tail}}}" if tail else head + sup


def _plan_items(s: Sheet1, plan: Plan, i: int, lang: str) -> list[str]:
    """The vectors' values of a plan (the core's magnitudes), then the links' ω (ε) at its position."""
    velocity = plan.kind == "velocity"
    seen, vals = set(), []
    top = max((v.magnitude for v in plan.vectors), default=0.0)
    for v in plan.vectors:
        if v.symbol in seen:
            continue
        seen.add(v.symbol)
        vals.append(f"{_vec_symbol(book_symbol(s.mechanism, v.symbol))} = {fixed(v.magnitude, top, lang)}")
    unit = tr(lang, "m/s") if velocity else tr(lang, "m/s²")
    if vals:
        vals[-1] += f" {unit}"
    k = s.cycle.kin
    rot = [ln for ln in s.mechanism.links if ln.kind in ("bar", "slotted")]
    ang = []
    arr = k.omega if velocity else k.epsilon
    top = max([abs(float(arr[ln.name][i])) for ln in rot] + [abs(k.omega1) if velocity else 0.0])
    for ln in rot:
        ang.append(f"{'ω' if velocity else 'ε'}_{{{ln.number}}} = {fixed(float(arr[ln.name][i]), top, lang)}")
    if ang:
        ang[-1] += " " + (tr(lang, "rad/s") if velocity else tr(lang, "rad/s²"))
    return vals + ang


def _plan_field(sh: Sheet, s: Sheet1, plan: Plan, box, label: str, index: int, lang: str):
    velocity = plan.kind == "velocity"
    pts = _plan_points(plan)
    lo, hi = _plan_extent(plan)
    f = field(sh, plan.kind + "_plan_" + label.replace("′", "'"), box, _plan_heading(plan, label, lang))
    lines = wrap_items(sh, _plan_items(s, plan, index, lang), box[2] - box[0] - 4.0)
    x0, _, x1, y1 = f.inner
    room = (x0, box[1] + caption_height(len(lines)), x1, y1 - SCALE_H)
    mu = plan.scale
    fit = fit_view(lo, hi, room, margin=PLAN_PAD, choices=[("", 1.0)])
    note = ""
    if not fit.fits:  # the next round μ at which it fits (said under the plan)
        for mu2 in sorted(float(f"{m * 10.0 ** e:.6g}") for m in SERIES for e in range(-9, 10)):
            if mu2 <= mu * (1 + 1e-9):
                continue
            fit = fit_view(lo, hi, room, margin=PLAN_PAD, choices=[("", mu / mu2)])
            if fit.fits:
                note = tr(lang, "drawn at μ = {mu2}: the plan's μ = {mu} does not fit").format(
                    mu2=num(mu2, lang, sig=3), mu=num(mu, lang, sig=3))
                mu = mu2
                break
    k = fit.scale
    sh.set_field_transform(f, fit.origin, k / plan.scale, "")
    unit_text = tr(lang, "(m/s)/mm") if velocity else tr(lang, "(m/s²)/mm")
    scale_line(sh, f, f"μ_{{{'v' if velocity else 'a'}}} = {num(mu, lang, sig=3)} {unit_text}")
    within = room
    origin = np.array(fit.origin)

    def at(name):
        z = pts[name] * k
        return origin + np.array([z.real, z.imag])

    drawn = set()
    for v in plan.vectors:
        a, b = at(v.start), at(v.end)
        d = b - a
        n = float(np.hypot(*d))
        if n < 0.5 or (v.start, v.end) in drawn:
            continue
        drawn.add((v.start, v.end))
        absolute = v.start == plan.pole
        layer = "Основные" if absolute else "Тонкие"
        sh.line(a, b - d / n * min(2.0, 0.3 * n), layer)
        sh.arrow(b, d, layer, min(3.5, 0.45 * n), 1.1 if absolute else 0.9)
    sh.dot(at(plan.pole), 0.8)
    # the points named, coincident ones together ("b, s_4"); the pole with the fixed joints
    named = set()
    centre = np.mean([at(n) for n in pts], axis=0)
    for n in sorted(pts, key=lambda q: (q != plan.pole, q)):
        if n in named:
            continue
        q = at(n)
        group = [g for g in sorted(pts) if g not in named and np.hypot(*(at(g) - q)) < 1.5]
        if n not in group:
            group.insert(0, n)
        named.update(group)
        group.sort(key=lambda g: (g != plan.pole, g))
        text = ", ".join(sub(g) for g in group)
        if plan.pole in group and plan.at_pole:
            text += ", " + ", ".join(sub(g) for g in plan.at_pole)
        others = [at(g) for g in pts if g not in group]
        push = sum(((q - r) / max(np.hypot(*(q - r)), 1e-6) ** 2 for r in others), np.zeros(2))
        if np.hypot(*push) < 1e-9:
            push = q - centre if np.hypot(*(q - centre)) > 1e-9 else np.array([0.0, 1.0])
        sh.label(text, tuple(q), H_LABEL, within=within, dirs=dirs_from(push), dists=(1.2, 2.5, 4.5),
                 priority=8 if n == plan.pole else 7)
    if note:
        lines = wrap_items(sh, _plan_items(s, plan, index, lang) + [note], box[2] - box[0] - 4.0)
    caption(sh, box, lines)
    return f


# ----------------------------------------------------------------------------------------------
# the results table and the sheet


def _results_rows(s: Sheet1) -> int:
    return 5 if s.cycle.stroke is not None else 3


def _results(sh: Sheet, s: Sheet1, lang: str, box) -> None:
    m, c, st = s.mechanism, s.cycle, s.structure
    rows = [(tr(lang, "Structural formula; W"), f"{st.formula}; W = {st.dof}"),
            (tr(lang, "Crank speed n_{1}"),
             f"{num(m.crank.rpm, lang, sig=5)} " + tr(lang, "rpm"))]
    if c.stroke is not None:
        if m.output.kind == "slider":
            rows.append((tr(lang, "Stroke H"), f"{num(c.stroke * MM, lang, decimals=2)} " + tr(lang, "mm")))
        else:
            rows.append((tr(lang, "Swing ψ"), f"{num(math.degrees(c.stroke), lang, decimals=2)}°"))
        rows.append((tr(lang, "Time ratio K"), num(c.time_ratio, lang, decimals=4)))
    worst = max(c.pressure, key=lambda p: p.worst)
    rows.append((tr(lang, "Largest pressure angle"),
                 f"{num(math.degrees(worst.worst), lang, decimals=1)}°"))
    table(sh, box, tr(lang, "Main results"), rows, col1=0.55, h=H_NOTE)


def sheet1(s: Sheet1, lang: str, title, variant: int = 0) -> Sheet:
    """Build sheet 1 of a mechanism (no file written); `variant` (the project's, with sheets 3–4)
    goes into the designation ТММ.01.<variant>.00.00 like theirs (0 for `tmm linkage` alone)."""
    sh = Sheet(lang)
    sh.frame()
    lay = layout(sh, s, lang)
    scheme = _scheme_field(sh, s, lang, lay.scheme)
    _diagrams_field(sh, s, lang, lay.diagrams)
    for boxes, pl in zip(lay.plans, s.plans[:2]):
        _plan_field(sh, s, pl.velocity, boxes[0], pl.position.label, pl.position.index, lang)
        _plan_field(sh, s, pl.acceleration, boxes[1], pl.position.label, pl.position.index, lang)
    _results(sh, s, lang, lay.table)
    sh.title_block(title, name=sheet_name(s, lang),
                   designation=title.designation_for(1, variant), scale=scheme.scale_label)
    sh.finish()
    return sh
