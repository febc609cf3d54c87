"""Sheet 2 «Силовой расчёт рычажного механизма и расчёт маховика» of a mechanism file (issue 25;
norm-control: issue 21).

Fields: the groups of one position (the last first, the crank last) at a ГОСТ 2.302 scale with the
forces and moments on them (arrows not to scale, as the book draws them; the outer reactions as
their normal and tangential parts where the group analysis finds them so), under each its force
polygon at the core's μ_F; Zhukovsky's lever (the velocity plan of that position turned through
90°, at its μ_v) with the forces at their points; the diagrams M_r and M_d, A_r and A_d, ΔT (with
Mertsalov's ΔT_I) and J_r at the core's scales; the energy–mass diagram (Wittenbauer) with its
tangents and the segment kl; the main results.

The fields are laid out from the measured size of each drawing (:func:`layout`): the diagrams, the
energy–mass diagram and the table in the right column; the groups over their polygons, and the
lever under them, on the left. Everything is read from :class:`~tmm_cli.linkage.sheet2.Sheet2`
(the drawing scales and places its numbers; the scales of the groups' drawings and of the
energy–mass diagram are drawing scales chosen to fit their fields and printed in them).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from ...i18n import tr
from ...i18n.numbers import num, small_pct
from ...linkage.scales import drafting_scale
from ...linkage.sheet2 import Sheet2
from ...linkage.zhukovsky import DECIMALS
from .arrows import (
    LABEL_PAD,
    arrow,
    arrow_len,
    arrows_box,
    draw_arrows,
    fit_arrows,
    place_arrows,
)
from . import indicator_view
from .cam_sheet import table
from .layout import GOST_SCALES, fit_view
from .lever_parts import (
    GAP,
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
    ground,
    head,
    link_segments,
    position_numbers,
    rotation_arrow,
    scale_line,
    shown,
    sub,
    wrap_items,
)
from .paper import FRAME, H_LABEL, H_MIN_LABEL, ROOM, TB_BOX, Sheet
from ..terminal.mechanism import pattern

POLY_PAD = (10.0, 8.0, 10.0, 8.0)  # [mm] around a force polygon: its names
SHORT_MM = 9.0  # a polygon's vector shorter than this is named in the caption, not on the drawing
ROW_H = 9.0
H_NOTE = 3.5


def symbol(sym: str, lang: str) -> str:
    """A force's symbol in the sheet's markup: 'Φ2' → 'Φ_{2}', 'Rτ12' → 'R^{τ}_{12}', 'Fc' → 'F_{пс}'."""
    tick = ""
    if sym[-1] in "′″":
        tick, sym = ("'" if sym[-1] == "′" else "''"), sym[:-1]
    if sym[:2] in ("Fc", "Mc") and sym[2:].isdigit() or sym in ("Fc", "Mc"):  # Fc, or Fc3 of several loads
        base = tr(lang, "F_{c}") if sym[:2] == "Fc" else tr(lang, "M_{c}")
        return (base[:-1] + sym[2:] + "}" if sym[2:] and base.endswith("}") else base) + tick
    if sym.startswith("MΦ"):
        return f"M_{{Φ{sym[2:]}}}" + tick
    if sym.startswith(("Rτ", "Rn")):
        return f"R^{{{sym[1]}}}_{{{sym[2:]}}}" + tick
    return f"{sym[0]}_{{{sym[1:]}}}" + tick if len(sym) > 1 else sym + tick


def _link_lines(m, kin, i: int, names, k: float, reach: dict | None = None) -> np.ndarray:
    """The lines of the links of `names` at position i [paper mm from the real origin, scale k]."""
    segs = []
    for sg in link_segments(m, kin, i, names=names, unit=1.0 / k, reach=reach, guide_stub=GUIDE_STUB):
        if sg[0] in ("line", "guide"):
            segs.append([sg[1], sg[2]])
        elif sg[0] == "poly":
            segs += [[a, b] for a, b in zip(sg[1][:-1], sg[1][1:])]
        elif sg[0] == "hatch":
            continue  # inside the outline: nothing an arrow must avoid beyond it
        else:
            c, angle, w, h = sg[1], sg[2], sg[3], sg[4]
            e = complex(math.cos(angle), math.sin(angle))
            cs = [c + (sx * w / 2 + 1j * sy * h / 2) * e / k for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
            segs += [[cs[j], cs[(j + 1) % 4]] for j in range(4)]
    z = np.array(segs, complex).reshape(-1, 2) * k
    return np.stack([z.real, z.imag], axis=-1)


# ----------------------------------------------------------------------------------------------
# the groups and their polygons


def _group_links(s: Sheet2, group: int):
    return [ln for ln in s.sheet1.mechanism.links if ln.group == group]


GUIDE_STUB = 10.0  # [paper mm] either side of a block: the neighbouring link's guide in a group's view


def _group_reach(s: Sheet2, group: int, i: int) -> dict[str, float]:
    """How far a group's view draws each of its slotted links from the pivot [real mm]: to every
    point where a force acts on the link (a block riding on it — the tangent mechanism's R43 at B —,
    a load, its centre of mass), so that no arrow stands off the link."""
    kin = s.sheet1.cycle.kin
    out = {}
    for ln in _group_links(s, group):
        if ln.kind != "slotted":
            continue
        pivot = complex(kin.z[ln.axis[1]][i])
        at = [complex(f.z[i]) for f in s.loading.forces if f.number == ln.number]
        at += [complex(r.at[i]) for r in s.forces.reactions if ln.number in r.pair.links]
        out[ln.name] = max([abs(z - pivot) for z in at], default=0.0) * MM
    return out


def _group_segments(s: Sheet2, group: int, i: int, unit: float):
    """:func:`link_segments` of a group's own view: its links wholly, a neighbour's guide as a stub."""
    m, kin = s.sheet1.mechanism, s.sheet1.cycle.kin
    return link_segments(m, kin, i, names={ln.name for ln in _group_links(s, group)}, unit=unit,
                         reach=_group_reach(s, group, i), guide_stub=GUIDE_STUB)


def _group_names(s: Sheet2, group: int) -> list[str]:
    m = s.sheet1.mechanism
    names = []
    for ln in _group_links(s, group):
        for n in list(ln.axis or ()) + list(ln.pins) + [p.name for p in m.points if p.link == ln.name]:
            if n not in names:
                names.append(n)
    return names


def _forces_on(s: Sheet2, group: int, i: int, lang: str):
    """(point [real mm], force [N], label, kind) of every force on the group's links: the applied
    ones, then the outer reactions (as their normal and tangential parts where the core splits them)."""
    numbers = {ln.number for ln in _group_links(s, group)}
    out = []
    for f in s.loading.forces:
        if f.number in numbers and abs(complex(f.f[i])) > 0:
            out.append((complex(f.z[i]) * MM, complex(f.f[i]), symbol(f.symbol, lang), "applied"))
    for r in s.forces.reactions:
        a, b = r.pair.links
        at = complex(r.at[i]) * MM
        if a in numbers and b not in numbers:
            out.append((at, -complex(r.force[i]), f"R_{{{b}{a}}}" if max(a, b) < 10 else f"R_{{{b},{a}}}", "reaction"))
        elif b in numbers and a not in numbers:
            if r.normal is not None and r.tangential is not None:
                out.append((at, complex(r.tangential[i]), symbol("Rτ" + r.label[1:], lang), "reaction"))
                out.append((at, complex(r.normal[i]), symbol("Rn" + r.label[1:], lang), "reaction"))
            else:
                out.append((at, complex(r.force[i]), f"R_{{{r.label[1:]}}}", "reaction"))
    return out


def _couples_on(s: Sheet2, group: int, i: int, lang: str):
    """(centre [real mm], moment [N·m], label) of the moments on the group's links (and M_b on the crank)."""
    m, k = s.sheet1.mechanism, s.sheet1.cycle.kin
    numbers = {ln.number: ln for ln in _group_links(s, group)}
    out = []
    for c in s.loading.couples:
        if c.number not in numbers or float(c.m[i]) == 0.0:
            continue
        centre = next((complex(f.z[i]) * MM for f in s.loading.forces if f.number == c.number and f.kind == "inertia"),
                      None)
        if centre is None:
            ln = numbers[c.number]
            ends = [complex(k.z[n][i]) * MM for n in (ln.axis or (ln.name,))]
            centre = sum(ends) / len(ends)
        out.append((centre, float(c.m[i]), symbol(c.symbol, lang)))
    if group == 0:
        out.append((complex(m.frame[m.crank.pivot]) * MM, float(s.balancing[i]), tr(lang, "M_{b}")))
    return out


SLIDE_ARC = 225.0  # [°] the middle of a slide couple's arc (a link's own M_Φ takes 45°: the two never meet)


def _slide_couples(s: Sheet2, group: int, i: int):
    """(centre [real mm], moment [N·m], label) of the couples the slides pass onto the group's links
    (a guide holding its block against turning, as the note names them: M_03 of a yoke on its
    guide, M_34 of a block in a moving slot), each at its block's joint; a couple zero to the
    problem's precision (below 10⁻⁹ of the cycle's largest force on the crank's arm or largest
    moment, as the note's zero) is not drawn."""
    numbers = {ln.number for ln in _group_links(s, group)}
    fmax = max((float(np.max(np.abs(f.f))) for f in s.loading.forces), default=0.0)
    mmax = max((float(np.max(np.abs(c.m))) for c in s.loading.couples), default=0.0)
    floor = 1e-9 * max(fmax * s.sheet1.mechanism.crank.length, mmax)
    out = []
    for r in s.forces.reactions:
        a, b = r.pair.links
        if r.couple is None or abs(float(r.couple[i])) <= floor or (a in numbers) == (b in numbers):
            continue  # no couple, or an inner pair's (not a load on the group)
        at = complex(r.at[i]) * MM
        pair = f"{a}{b}" if max(a, b) < 10 else f"{a},{b}"
        if b in numbers:
            out.append((at, float(r.couple[i]), f"M_{{{pair}}}"))
        else:  # the group's link holds a later group's block: the couple back on it (as R_ba)
            back = f"{b}{a}" if max(a, b) < 10 else f"{b},{a}"
            out.append((at, -float(r.couple[i]), f"M_{{{back}}}"))
    return out


def _group_arrows(s: Sheet2, group: int, i: int, k: float, lang: str = "en"):
    """The group's force arrows at k paper mm per real mm: (tail, tip, point) [paper mm from the real
    origin], label, kind — placed by :func:`place_arrows` among the group's links."""
    m, kin = s.sheet1.mechanism, s.sheet1.cycle.kin
    items = _forces_on(s, group, i, lang)
    biggest = max((abs(v) for _, v, _, _ in items), default=1.0) or 1.0
    items = [x for x in items if abs(x[1]) > 1e-9 * biggest]
    pts = [np.array([z.real, z.imag]) * k for z, *_ in items]
    us = [np.array([v.real, v.imag]) / abs(v) for _, v, _, _ in items]
    lens = [arrow_len(abs(v), biggest) for _, v, _, _ in items]
    segs = _link_lines(m, kin, i, {ln.name for ln in _group_links(s, group)}, k, _group_reach(s, group, i))
    placed = place_arrows(list(zip(pts, us, lens)), segs)
    return [(tail, tip, p, label, kind) for (tail, tip), p, (_, _, label, kind) in zip(placed, pts, items)]


def _group_drawing(s: Sheet2, group: int, i: int, k: float):
    """The group's points [real mm] and its arrows' far ends as (point [real mm], vector [paper mm])
    at k paper mm per real mm (the forces' arrows as placed, and for the moments a ring of the arc's
    size)."""
    kin = s.sheet1.cycle.kin
    pts = [complex(kin.z[n][i]) * MM for n in _group_names(s, group)]
    for sg in _group_segments(s, group, i, 1.0 / k):
        if sg[0] in ("line", "guide"):
            pts += [sg[1], sg[2]]
    arrows = []
    for tail, tip, _, _, _ in _group_arrows(s, group, i, k):
        for end in (tail, tip):
            arrows.append((0j, complex(end[0], end[1])))
    for z, _, _ in _couples_on(s, group, i, "en") + _slide_couples(s, group, i):
        arrows += [(z, 9.0 * complex(math.cos(a), math.sin(a))) for a in (0.0, math.pi / 2, math.pi, -math.pi / 2)]
    return pts, arrows


def _draw_group(sh: Sheet, f, s: Sheet2, group: int, i: int, lang: str, within) -> None:
    m, k = s.sheet1.mechanism, s.sheet1.cycle.kin
    unit = 1.0 / f.scale
    draw_links(f, _group_segments(s, group, i, unit), "Основные", None, unit, 1.0)
    names = _group_names(s, group)
    pts = {n: np.array(f.p(k.z[n][i].real * MM, k.z[n][i].imag * MM)) for n in names}
    for n, q in pts.items():
        if n in m.frame and group == 0:
            ground(sh, q)
        else:
            sh.circle(q, 1.1, "Основные")
    centre = np.mean(list(pts.values()), axis=0)
    # a crowded drawing: every name with room for a CAD program's wider font (as the lever's)
    draw_arrows(sh, f.origin, _group_arrows(s, group, i, f.scale, lang), within, wide=True)
    couples = [(z, mom, label, 45.0) for z, mom, label in _couples_on(s, group, i, lang)]
    couples += [(z, mom, label, SLIDE_ARC) for z, mom, label in _slide_couples(s, group, i)]
    for z, mom, label, a_mid in couples:
        c = np.array(f.p(z.real, z.imag))
        mid, out = rotation_arrow(sh, c, 6.5, 1 if mom > 0 else -1, a_mid, "Основные")
        sh.label(label, tuple(mid), H_LABEL, within=within, dirs=dirs_from(out, 5), dists=(1.0, 2.5, 4.0), priority=6,
                 wide=True)
    named = {n for n in pts}
    for n, q in pts.items():
        d = q - centre
        d = d / (np.hypot(*d) or 1.0)
        sh.label(sub(n), tuple(q), H_LABEL, within=within, dirs=dirs_from(-d if group else d), dists=(1.2, 2.5, 4.0),
                 priority=8, wide=True)
    for f_ in s.loading.forces:
        if f_.point in named or f_.number not in {ln.number for ln in _group_links(s, group)}:
            continue
        named.add(f_.point)
        q = np.array(f.p(complex(f_.z[i]).real * MM, complex(f_.z[i]).imag * MM))
        sh.dot(q, 0.6)
        sh.label(sub(f_.point), tuple(q), H_LABEL, within=within, dirs=("sw", "se", "nw", "ne", "w", "e"),
                 dists=(1.2, 2.5, 4.0), priority=7, wide=True)


def _polygon_tips(pg) -> np.ndarray:
    return np.cumsum([0j] + [v.value / pg.scale for v in pg.vectors])


def _polygon_extent(pg):
    t = _polygon_tips(pg)
    return np.array([t.real.min(), t.imag.min()]), np.array([t.real.max(), t.imag.max()])


def _polygon_items(pg, lang: str) -> list[str]:
    """The polygon's found reactions and its vectors too short to be named on it, with their values."""
    unit = tr(lang, "N")
    found, short = [], []
    for v in pg.vectors:
        length = abs(v.value) / pg.scale
        item = f"{symbol(v.symbol, lang)} = {num(abs(v.value), lang, decimals=1)}"
        if v.kind != "unknown" and length < SHORT_MM:
            short.append(item)  # a side of the polygon too short to carry its name at μ_F
        elif v.kind == "unknown":
            found.append(item)
    if found:
        found[0] = tr(lang, "found:") + " " + found[0]
        found[-1] += f" {unit}"
    if short:  # every force of the equation is a side of the polygon: the short ones are named here
        short[0] = tr(lang, "short sides (< {mm} mm), unnamed above:").format(
            mm=num(SHORT_MM, lang)) + " " + short[0]
        short[-1] += f" {unit}"
    return found + short


def _polygon_size(sh: Sheet, pg, lang: str, width: float | None = None) -> tuple[float, float]:
    lo, hi = _polygon_extent(pg)
    w = max(hi[0] - lo[0] + POLY_PAD[0] + POLY_PAD[2], 110.0)
    n = len(wrap_items(sh, _polygon_items(pg, lang), (width or w) - 4.0))
    return w, hi[1] - lo[1] + POLY_PAD[1] + POLY_PAD[3] + head(sh, _polygon_heading(pg, lang), w) + SCALE_H \
        + caption_height(n)


def _polygon_heading(pg, lang: str) -> str:
    if pg.group == 0:
        return tr(lang, "Force polygon of the crank")
    return tr(lang, "Force polygon of group {group}").format(group=pg.group)


def _polygon_field(sh: Sheet, s: Sheet2, pg, box, lang: str) -> None:
    f = field(sh, f"polygon_{pg.group}", box, _polygon_heading(pg, lang))
    lines = wrap_items(sh, _polygon_items(pg, lang), box[2] - box[0] - 4.0)
    x0, _, x1, y1 = f.inner
    room = (x0, box[1] + caption_height(len(lines)), x1, y1 - SCALE_H)
    lo, hi = _polygon_extent(pg)
    fit = fit_view(lo, hi, room, margin=POLY_PAD, choices=[("", 1.0)])
    mu, k = pg.scale, 1.0
    note = ""
    if not fit.fits:  # the next round μ_F at which it fits (said under it)
        for mu2 in sorted(float(f"{c * 10.0 ** e:.6g}") for c in (1.0, 2.0, 2.5, 4.0, 5.0) for e in range(-6, 9)):
            if mu2 <= mu * (1 + 1e-9):
                continue
            fit = fit_view(lo, hi, room, margin=POLY_PAD, choices=[("", mu / mu2)])
            if fit.fits:
                note = tr(lang, "drawn at μ = {mu2}: the polygon's μ = {mu} does not fit").format(
                    mu2=num(mu2, lang, sig=3), mu=num(mu, lang, sig=3))
                mu, k = mu2, pg.scale / mu2
                break
    sh.set_field_transform(f, fit.origin, k / pg.scale, "")
    scale_line(sh, f, f"μ_{{F}} = {num(mu, lang, sig=3)} " + tr(lang, "N/mm"))
    origin = np.array(fit.origin)
    tips = [origin + k * np.array([t.real, t.imag]) for t in _polygon_tips(pg)]
    sh.dot(tips[0], 0.7)
    for v, a, b in zip(pg.vectors, tips[:-1], tips[1:]):
        arrow(sh, a, b, "Тонкие" if v.kind == "unknown" else "Основные")
        d = b - a
        n = float(np.hypot(*d))
        if n >= SHORT_MM:
            side = np.array([-d[1], d[0]]) / n
            sh.label(symbol(v.symbol, lang), tuple((a + b) / 2), H_LABEL, within=room, dirs=dirs_from(side, 4) +
                     dirs_from(-side, 4), dists=(0.8, 2.0, 3.5), priority=6, wide=True)
    if note:
        lines = wrap_items(sh, _polygon_items(pg, lang) + [note], box[2] - box[0] - 4.0)
    caption(sh, box, lines)


# ----------------------------------------------------------------------------------------------
# Zhukovsky's lever


def _lever_points(s: Sheet2) -> dict[str, complex]:
    """The velocity plan turned through 90° counter-clockwise [drawing mm from the pole]."""
    plan = s.sheet1.plans[0].velocity
    out = {n: 1j * z / plan.scale for n, z in plan.points.items()}
    out.update(_pair_points(s))
    return out


def _pair_points(s: Sheet2) -> dict[str, complex]:
    """The images of the points the lever's forces stand at that the velocity plan has not — the
    point B′ of a slider's pair (its couple as two forces at B and B′) as b′ [drawing mm from the
    pole]; each is drawn with its ray from p."""
    i = s.force_position
    plan = s.sheet1.plans[0].velocity
    out = {}
    for f in s.lever.forces:
        name = f.point.lower()
        if name not in plan.points and f.point not in plan.points:
            out[name] = complex(f.lever[i]) / plan.scale
    return out


def _lever_forces(s: Sheet2, lang: str):
    i = s.force_position
    plan = s.sheet1.plans[0].velocity
    lv = s.lever
    items = [(complex(x.lever[i]) / plan.scale, complex(x.force[i]), symbol(x.symbol, lang), False) for x in lv.forces]
    a_pt = 1j * complex(s.sheet1.cycle.kin.v[s.sheet1.mechanism.crank.joint][i]) / plan.scale
    items.append((a_pt, complex(lv.balancing_force[i]), tr(lang, "F_{b}"), True))
    return items


def _lever_extent(s: Sheet2):
    z = np.array(list(_lever_points(s).values()) + [p for p, *_ in _lever_forces(s, "en")])
    return np.array([z.real.min(), z.imag.min()]), np.array([z.real.max(), z.imag.max()])


def _lever_placed(s: Sheet2, k: float, lang: str = "en"):
    """The lever's force arrows at k drawing mm per plan mm: (tail, tip, point) [mm from the pole],
    label, kind ('balancing' for F_ур) — placed among the plan's lines by :func:`place_arrows`."""
    plan = s.sheet1.plans[0].velocity
    pts = _lever_points(s)
    items = _lever_forces(s, lang)
    biggest = max((abs(v) for _, v, _, _ in items), default=1.0) or 1.0
    items = [x for x in items if abs(x[1]) > 1e-9 * biggest]
    segs = np.array([[[pts[v.start].real, pts[v.start].imag], [pts[v.end].real, pts[v.end].imag]]
                     for v in plan.vectors], float).reshape(-1, 2, 2) * k
    ps = [np.array([z.real, z.imag]) * k for z, *_ in items]
    placed = place_arrows([(p, np.array([v.real, v.imag]) / abs(v), arrow_len(abs(v), biggest))
                           for p, (_, v, _, _) in zip(ps, items)], segs)
    return [(tail, tip, p, lab, "balancing" if bal else "applied")
            for (tail, tip), p, (_, _, lab, bal) in zip(placed, ps, items)]


def lever_items(s: Sheet2, lang: str, drawn_mu: float | None = None) -> list[str]:
    """The lever's table (:meth:`Sheet2.lever_table`, the note's too) as the caption's items: each
    force's ±F·h [N·mm], ΣF·h, F_ур = |ΣF·h|/(pa), M_ур = F_ур·l_OA, the force analysis's M_ур and
    the difference; the arms' scale when the drawing stands at another μ."""
    t = s.lever_table()
    d = DECIMALS
    nm, nmm, n_ = tr(lang, "N·m"), tr(lang, "N·mm"), tr(lang, "N")
    head = tr(lang, "moments about the pole p, ±F·h, N·mm (F, N; h, mm):")
    if drawn_mu is not None and abs(drawn_mu - t.scale) > 1e-9 * t.scale:
        head = tr(lang, "the arms h at μ_{{v}} = {mu} (m/s)/mm;").format(mu=num(t.scale, lang, sig=3)) + " " + head
    out = [head]
    for x in t.terms:
        sign = "-" if x.sign < 0 else ""
        out.append(f"{symbol(x.symbol, lang)}: {sign}{num(x.force, lang, decimals=d['force'])}·"
                   f"{num(x.arm, lang, decimals=d['arm'])} = {num(x.moment, lang, decimals=d['moment'])}")
    out.append(f"ΣF·h = {num(t.total, lang, decimals=d['moment'])} {nmm}")
    fb, mb, mz = tr(lang, "F_{b}"), tr(lang, "M_{b}"), tr(lang, "M_{b}^{Zh}")
    (tot, pa), res = _substituted([(abs(t.total), d["moment"]), (t.pa, d["pa"])], lambda a, b: a / b,
                                  t.balancing_force, d["balancing_force"], lang)
    out.append(f"{fb} = |ΣF·h|/(pa) = {tot}/{pa} = {res} {n_}")
    (f_b, _), res = _substituted([(t.balancing_force, d["balancing_force"]), (t.crank, None)], lambda a, b: a * b,
                                 t.balancing, d["balancing"], lang)
    out.append(f"{mz} = {fb}·l_{{1}} = {f_b}·{num(t.crank, lang, sig=9)} = {res} {nm}")
    out.append(tr(lang, "force analysis: ") + f"{mb} = {num(t.kinetostatic, lang, decimals=d['balancing'])} {nm}")
    out.append(f"Δ = (|{mb}| − {mz})/|{mb}|·100 {small_pct(t.difference_pct, lang, minus='-')} %")
    return out


def _lever_scale_text(lang: str, mu: float, turned: bool = True) -> str:
    text = f"μ_{{v}} = {num(mu, lang, sig=3)} " + tr(lang, "(m/s)/mm")
    return text + tr(lang, "; the plan turned 90° counter-clockwise") if turned else text


def _turned_in_caption(sh: Sheet, lang: str, width: float) -> bool:
    """Whether the scale line with «the plan turned 90°» would shrink below its 5 mm in a field
    `width` wide: the remark then opens the caption instead."""
    return sh.text_width(_lever_scale_text(lang, 0.0025), H_LABEL) * ROOM > width


def _lever_caption(sh: Sheet, s: Sheet2, lang: str, width: float, drawn_mu: float | None = None) -> list[str]:
    """The caption's items: the lever's table (:func:`lever_items`), opened by «the plan turned 90°»
    where the scale line has no room for it."""
    head = [tr(lang, "the plan turned 90° counter-clockwise")] if _turned_in_caption(sh, lang, width) else []
    return head + lever_items(s, lang, drawn_mu)


def _substituted(leaves, op, result: float, decimals: int, lang: str):
    """The leaves of a substitution as printed (each (value, decimals), None: as given, to 9
    significant digits) with as many more decimals as it takes for `op` of the printed leaves to
    give the printed result to half a unit of its last digit (as the note's substitutions are
    printed), and the result's text."""
    shown = float(f"{result:.{decimals}f}")
    texts = []
    for extra in range(5):
        texts = [num(x, lang, sig=9) if dec is None else num(x, lang, decimals=dec + extra) for x, dec in leaves]
        vals = [float(x) if dec is None else round(x, dec + extra) for x, dec in leaves]
        if abs(op(*vals) - shown) <= 0.5 * 10.0 ** -decimals * (1 + 1e-9):
            break
    return texts, num(result, lang, decimals=decimals)


def _lever_arrows(s: Sheet2, k: float = 1.0):
    """The far ends of the lever's arrows as (0, end) [mm from the pole at k] for the fitting."""
    return [(0j, complex(*end) / 1.0) for tail, tip, *_ in _lever_placed(s, k) for end in (tail, tip)]


def _lever_scale(s: Sheet2, room):
    """The lever's μ and its fit in `room`: the largest drawing of :func:`_lever_ks` that fits, else
    the first round μ beyond μ_v that does (the lever may be drawn at any scale: only the arms'
    ratios count)."""
    mu_v = s.sheet1.plans[0].velocity.scale
    pts = list(_lever_points(s).values()) + [p for p, *_ in _lever_forces(s, "en")]
    beyond = [(mu, mu_v / mu) for mu in _series_mu() if mu > mu_v * (1 + 1e-9)]
    last = None
    for mu, k in _lever_ks(s) + beyond:
        last = mu, fit_arrows(pts, _lever_arrows(s, k), room, k)
        if last[1].fits:
            return last
    return last


def _lever_heading(s: Sheet2, lang: str) -> str:
    label = s.sheet1.cycle.positions[s.force_position].label
    return tr(lang, "Zhukovsky's lever, position {label}").format(label=label)


def _lever_field(sh: Sheet, s: Sheet2, lang: str, box) -> None:
    plan = s.sheet1.plans[0].velocity
    f = field(sh, "lever", box, _lever_heading(s, lang))
    width = box[2] - box[0] - 4.0
    lines = wrap_items(sh, _lever_caption(sh, s, lang, width), width)
    x0, _, x1, y1 = f.inner
    room = (x0, box[1] + caption_height(len(lines)), x1, y1 - SCALE_H)
    mu, fit = _lever_scale(s, room)
    if abs(mu - s.lever_scale()) > 1e-9 * mu:  # drawn at another μ than the table's: the caption says so
        lines = wrap_items(sh, _lever_caption(sh, s, lang, width, mu), width)
    k = fit.k
    sh.set_field_transform(f, fit.origin, k / plan.scale, "")
    scale_line(sh, f, _lever_scale_text(lang, mu, not _turned_in_caption(sh, lang, width)))
    origin = np.array(fit.origin)
    pts = _lever_points(s)

    def at(z):
        return origin + k * np.array([z.real, z.imag])

    for v in plan.vectors:
        a, b = at(pts[v.start]), at(pts[v.end])
        if np.hypot(*(b - a)) > 0.3:
            sh.line(a, b, "Основные" if v.start == plan.pole else "Тонкие")
    for z in _pair_points(s).values():  # b′ of a slider's pair: its ray p b′, as the plan's other rays
        if abs(z) * k > 0.3:
            sh.line(at(0j), at(z), "Основные")
    sh.dot(at(0j), 0.8)
    draw_arrows(sh, origin, _lever_placed(s, k, lang), room, wide=True)  # a crowded drawing: room for a wider font
    named = set()
    centre = np.mean([at(z) for z in pts.values()], axis=0)
    for n in sorted(pts, key=lambda q: (q != plan.pole, q)):
        if n in named:
            continue
        q = at(pts[n])
        group = [g for g in sorted(pts) if g not in named and np.hypot(*(at(pts[g]) - q)) < 1.5]
        if n not in group:
            group.insert(0, n)
        named.update(group)
        group.sort(key=lambda g: (g != plan.pole, g))
        text = ", ".join(sub(g) for g in group)
        d = q - centre
        sh.label(text, tuple(q), H_LABEL, within=room, dirs=dirs_from(d if np.hypot(*d) > 1e-9 else (0, 1)),
                 dists=(1.2, 2.5, 4.0), priority=8, wide=True)
    caption(sh, box, lines)


# ----------------------------------------------------------------------------------------------
# the diagrams and the energy–mass diagram


DIAGRAM_LEFT = 22.0
DIAGRAM_RIGHT = 16.0


def _series(s: Sheet2, lang: str):
    """(name, μ, unit, [(ordinates [mm], layer, linetype, label)]) of the diagrams: the piston forces P and
    each table load's own (F_пс3, M_пс5: the core's Dynamics.loads), then M, A, ΔT, J."""
    d, fw, sc = s.dynamics, s.flywheel, s.scales
    jm = tr(lang, "J/mm")
    out = [("M", sc.M, tr(lang, "N·m/mm"), [(d.M_r / sc.M, "Основные", None, tr(lang, "M_{r}")),
                                                (np.full(d.travel.shape, d.M_d) / sc.M, "Основные", None,
                                                 tr(lang, "M_{d}"))]),
           ("A", sc.A, jm, [(d.A_r / sc.A, "Основные", None, tr(lang, "A_{r}")),
                            (d.A_d / sc.A, "Основные", None, tr(lang, "A_{d}"))]),
           ("ΔT", sc.T, jm, [(d.dT / sc.T, "Основные", None, "ΔT")] + (
               [((fw.mertsalov.dT_I - fw.mertsalov.dT_I[0]) / sc.T, "Штриховые", None, "ΔT_{I}")] if fw is not None
               else [])),
           ("J", sc.J, tr(lang, "kg·m²/mm"), [(d.J_r / sc.J, "Основные", None, tr(lang, "J_{r}")),
                                                (np.full(d.travel.shape, d.J_first) / sc.J, "Штриховые", None, None)])]
    out[0:0] = [(symbol(ld.symbol, lang), mu, tr(lang, "N/mm") if ld.kind == "force" else tr(lang, "N·m/mm"),
                 [(ld.values / mu, "Основные", None, None)])
                for ld, mu in zip(d.loads, sc.loads)]  # each table load's own diagram, zero on its return stroke
    forces, mu = s.piston_force_diagram()  # P = p·A over the cycle (+ away from the head), from the core
    if forces:
        mech = s.sheet1.mechanism
        out.insert(0, ("P", mu, tr(lang, "N/mm"), [
            (f / mu, "Основные" if j == 0 else "Штриховые", None, f"P_{{{mech.link(name).number}}}")
            for j, (name, f) in enumerate(forces.items())]))
    return out


def _flat(name: str) -> str:
    """A diagram's name as one subscript of its μ: 'F_{пс3}' → 'Fпс3' (markup does not nest)."""
    return re.sub(r"[_^]\{([^}]*)\}", r"\1", name)


def _diagram_items(s: Sheet2, lang: str) -> list[str]:
    items = [f"μ_{{{_flat(name)}}} = {num(mu, lang, sig=3)} {unit}" for name, mu, unit, _ in _series(s, lang)]
    items.append(f"μ_{{φ}} = {num(math.degrees(s.scales.phi), lang, sig=3)} °/" + tr(lang, "mm"))
    if s.turns > 1:  # a four-stroke engine: the axis covers its cycle of two turns
        items.append(tr(lang, "φ: 0 … {deg}°, the cycle of {turns} turns; dashed: the end of a turn").format(
            deg=360 * s.turns, turns=s.turns))
    items.append(tr(lang, "positions from position 0; moments and works in the crank's sense of rotation"))
    items.append(tr(lang, "dashed: the crank and the rotor, ") + f"{num(s.dynamics.J_first, lang, sig=4)} " +
                 tr(lang, "kg·m²"))
    return items


def _diagrams_size(sh: Sheet, s: Sheet2, lang: str) -> tuple[float, float]:
    w = DIAGRAM_LEFT + s.scales.axis_mm + 9.0 + DIAGRAM_RIGHT
    n = len(wrap_items(sh, _diagram_items(s, lang), w - 4.0))
    h = head(sh, _diagrams_heading(lang), w) + sum(diagram_height([c[0] for c in curves]) + 4.0
                                                   for *_, curves in _series(s, lang)) + NUMBERS_H \
        + caption_height(n)
    return w, h


def _diagrams_heading(lang: str) -> str:
    return tr(lang, "Diagrams of the reduced moments, works and energy")


def _diagrams_field(sh: Sheet, s: Sheet2, lang: str, box) -> None:
    d, sc = s.dynamics, s.scales
    f = field(sh, "dynamics_diagrams", box, _diagrams_heading(lang))
    x0b, y0b, x1b, y1b = f.inner
    length = sc.axis_mm
    x0 = x0b + DIAGRAM_LEFT - 1.0 + max(0.0, (x1b - x0b) - (DIAGRAM_LEFT + length + 9.0 + DIAGRAM_RIGHT)) / 2
    xs = x0 + d.travel / sc.phi
    marks = [x0 + p.travel / sc.phi for p in s.positions]  # the cycle's: a four-stroke engine's two turns
    turns = [x0 + 2.0 * math.pi * k / sc.phi for k in range(1, s.turns)]
    lines = wrap_items(sh, _diagram_items(s, lang), box[2] - box[0] - 4.0)
    within = (x0b, y0b + caption_height(len(lines)), x1b, y1b)
    y = y1b
    y_axis = y
    loads = {symbol(ld.symbol, lang): ld for ld in d.loads}
    for name, mu, unit, curves in _series(s, lang):
        y_axis = diagram(sh, within, x0, y, length, xs, curves, name, marks, dashed=turns)
        if name in loads:  # a table load's own diagram: its working strokes dimensioned above it
            _working_spans(sh, within, x0, y_axis, y_axis + max(float(np.max(curves[0][0])), 0.0) + 3.0, sc.phi,
                           loads[name], lang)
        down = max(max(float(-np.min(cv[0])) for cv in curves), 0.0)
        y = y_axis - down - 3.0 - 4.0
    position_numbers(sh, within, [(x0 + p.travel / sc.phi, p.label) for p in shown(s.positions)], y + 4.0)
    if s.turns > 1:  # the axis of a two-turn cycle: its turns' ends in degrees under the numbers
        position_numbers(sh, within, [(x0 + 2.0 * math.pi * k / sc.phi, f"{360 * k}°") for k in range(1, s.turns + 1)],
                         y + 4.0 - H_MIN_LABEL - 2.2)
    caption(sh, box, lines)


def _working_spans(sh: Sheet, within, x0: float, y_axis: float, y: float, mu_phi: float, ld, lang: str) -> None:
    """The working strokes of a table load's diagram (:attr:`LoadDiagram.spans`) as dimension lines at
    height `y` over extension lines from the φ axis, the longest named «working stroke» (a moment on
    a rocker: «working swing»), so that where the load acts reads even where its table starts or ends
    at zero."""
    spans = [(x0 + lo / mu_phi, x0 + hi / mu_phi) for lo, hi in ld.spans if (hi - lo) / mu_phi > 1.0]
    for a, b in spans:
        for x in (a, b):
            if x > x0 + 0.3:
                sh.line((x, y_axis), (x, y + 1.5), "Тонкие")
        sh.line((a, y), (b, y), "Тонкие")
        if b - a > 7.0:
            sh.arrow((a, y), (-1, 0), "Тонкие", 2.5, 0.8)
            sh.arrow((b, y), (1, 0), "Тонкие", 2.5, 0.8)
    if spans:
        a, b = max(spans, key=lambda ab: ab[1] - ab[0])
        text = tr(lang, "working stroke") if ld.kind == "force" else tr(lang, "working swing")
        sh.label(text, ((a + b) / 2, y), H_MIN_LABEL, within=within, dirs=("n", "ne", "nw"), dists=(0.8, 1.5),
                 leader=False, priority=5, optional=True)


def _witt_items(s: Sheet2, lang: str) -> list[str]:
    wi = s.flywheel.wittenbauer
    kgm = tr(lang, "kg·m²")
    return [f"tg ψ_{{max}} = {num(wi.slope_max, lang, sig=5)}", f"tg ψ_{{min}} = {num(wi.slope_min, lang, sig=5)}",
            tr(lang, "J_{fl} = kl·μ_{T}/(tg ψ_{max} − tg ψ_{min}) = ") + f"{num(max(wi.J_fl, 0.0), lang, sig=4)} {kgm}"]


def _wittenbauer_field(sh: Sheet, s: Sheet2, lang: str, box) -> None:
    d, fw = s.dynamics, s.flywheel
    wi = fw.wittenbauer
    f = field(sh, "wittenbauer", box, tr(lang, "Energy–mass diagram (Wittenbauer)"))
    lines = wrap_items(sh, _witt_items(s, lang), box[2] - box[0] - 4.0)
    x0, _, x1, y1 = f.inner
    room = (x0, box[1] + caption_height(len(lines)), x1, y1 - SCALE_H)
    jmax = float(d.J_r.max()) * 1.1
    lo_t, hi_t = min(float(d.dT.min()), wi.c_min, wi.c_min + wi.slope_min * jmax), \
        max(float(d.dT.max()), wi.c_max, wi.c_max + wi.slope_max * jmax)
    pad = (16.0, 8.0, 16.0, 12.0)
    w, h = room[2] - room[0] - pad[0] - pad[2], room[3] - room[1] - pad[1] - pad[3]
    mu_j = drafting_scale(jmax, w)
    mu_t = drafting_scale(hi_t - lo_t, h)
    kg, j = tr(lang, "kg·m²/mm"), tr(lang, "J/mm")
    scale_line(sh, f, f"μ_{{J}} = {num(mu_j, lang, sig=3)} {kg}; μ_{{T}} = {num(mu_t, lang, sig=3)} {j}")
    ox = room[0] + pad[0] + max(0.0, w - jmax / mu_j) / 2
    oy = room[1] + pad[1] + max(0.0, h - (hi_t - lo_t) / mu_t) / 2 - lo_t / mu_t
    sh.set_field_transform(f, (ox, oy), 1.0, "")

    def p(jj, tt):
        return (ox + jj / mu_j, oy + tt / mu_t)

    # axes: ΔT up from the lowest point, J_r right along ΔT = 0
    top = oy + hi_t / mu_t
    sh.line((ox, oy + lo_t / mu_t - 1.0), (ox, top + 4.0), "Основные")
    sh.arrow((ox, top + 8.0), (0, 1), "Основные", 4.0, 1.2)
    sh.label("ΔT", (ox, top + 8.0), H_LABEL, within=room, dirs=("w", "nw", "e", "ne"), dists=(1.2, 2.5), priority=8)
    right = ox + jmax / mu_j + 3.0
    sh.line((ox, oy), (right, oy), "Основные")
    sh.arrow((right + 4.0, oy), (1, 0), "Основные", 4.0, 1.2)
    sh.label(tr(lang, "J_{r}"), (right + 4.0, oy), H_LABEL, within=room, dirs=("se", "ne", "s", "n"), dists=(0.8, 2.0),
             priority=8)
    sh.poly(np.array([p(a, b) for a, b in zip(d.J_r[::2], d.dT[::2])]), "Основные")
    for slope, cc, name, j_ in ((wi.slope_max, wi.c_max, "ψ_{max}", wi.i_max), (wi.slope_min, wi.c_min, "ψ_{min}",
                                                                                wi.i_min)):
        end = p(jmax, cc + slope * jmax)
        sh.line(p(0.0, cc), end, "Тонкие")
        sh.dot(p(float(d.J_r[j_]), float(d.dT[j_])), 0.7)
        sh.label(name, end, H_LABEL, within=room, dirs=("ne", "e", "se", "n", "s", "nw"), dists=(1.0, 2.5, 4.0),
                 priority=7)
    k_, l_ = p(0.0, wi.c_max), p(0.0, wi.c_min)
    sh.poly(np.array([k_, l_]), "Основные", lineweight=100)
    sh.label("k", k_, H_LABEL, within=room, dirs=("w", "nw", "sw", "e"), dists=(1.5, 3.0), priority=9)
    sh.label("l", l_, H_LABEL, within=room, dirs=("w", "sw", "nw", "e"), dists=(1.5, 3.0), priority=9)
    caption(sh, box, lines)


# ----------------------------------------------------------------------------------------------
# the layout


@dataclass(frozen=True)
class Layout2:
    groups: tuple  # a box per polygon's group, in the order of s.polygons
    polygons: tuple
    lever: tuple
    diagrams: tuple
    wittenbauer: tuple | None
    table: tuple
    group_scale: tuple  # (label, paper mm per real mm) of the groups' drawings
    indicators: tuple = ()  # a box per indicator diagram (indicator_view.place)


def _series_mu() -> list[float]:
    return sorted(float(f"{c * 10.0 ** e:.6g}") for c in (1.0, 2.0, 2.5, 4.0, 5.0) for e in range(-9, 10))


def _lever_ks(s: Sheet2) -> list[tuple[float, float]]:
    """(μ, drawing mm per plan mm) the lever may take: the core's μ of its table
    (:meth:`Sheet2.lever_scale`, the note's) first, then the smaller drawings up to μ_v."""
    mu_v = s.sheet1.plans[0].velocity.scale
    mu0 = s.lever_scale()
    return [(mu, mu_v / mu) for mu in _series_mu() if mu0 * (1 - 1e-9) <= mu <= mu_v * (1 + 1e-9)]


def _lever_need(sh: Sheet, s: Sheet2, lang: str, k: float, width: float | None = None) -> tuple[float, float]:
    """(width, height) [mm] of the lever's field at k drawing mm per plan mm: the turned plan, the
    arrows, their names, the heading, the scale and the caption."""
    ends = [z * k for z in list(_lever_points(s).values()) + [p for p, *_ in _lever_forces(s, "en")]]
    ends += [v for _, v in _lever_arrows(s, k)]
    w = max(z.real for z in ends) - min(z.real for z in ends) + 2 * LABEL_PAD[0] + 4.0
    w = max(w, 150.0)
    cap = caption_height(len(wrap_items(sh, _lever_caption(sh, s, lang, (width or w) - 4.0), (width or w) - 4.0)))
    h = max(z.imag for z in ends) - min(z.imag for z in ends) + 2 * LABEL_PAD[1] + 4.0 + SCALE_H + cap \
        + head(sh, _lever_heading(s, lang), width or w)
    return w, h


def _group_heading(s: Sheet2, g: int, lang: str) -> str:
    if g == 0:
        return tr(lang, "The crank")
    return tr(lang, "Group {g} ({kind})").format(g=g, kind=pattern(s.sheet1.mechanism.groups[g - 1].kind, lang))


GROUP_PAD = (8.0, 8.0)  # [mm] around a group's points (pins, blocks, names)


def _group_scale(sh: Sheet, s: Sheet2, lang: str, poly_needs, width: float, h_max: float):
    """The largest ГОСТ 2.302 scale (at most 5:1) at which the groups with their arrows, each over
    its polygon (`poly_needs`: their widths), fit side by side in `width` and in `h_max` high;
    (label, factor, the height the groups need, the columns' widths)."""
    i = s.force_position
    n = len(s.polygons)
    for lab, fac in sorted(GOST_SCALES, key=lambda c: -c[1]):
        if fac > 5.0:
            continue
        ws, hs = [], []
        for pg, pw in zip(s.polygons, poly_needs):
            lo, hi = arrows_box(*_group_drawing(s, pg.group, i, fac), fac, pad=GROUP_PAD)
            w = max(hi[0] - lo[0] + 4.0, pw)
            ws.append(w)
            hs.append(hi[1] - lo[1] + head(sh, _group_heading(s, pg.group, lang), w) + SCALE_H + 4.0)
        if sum(ws) + GAP * (n - 1) <= width and max(hs) <= h_max:
            return lab, fac, min(h_max, max(hs) + 8.0), _columns(ws, width)
    lab, fac = min(GOST_SCALES, key=lambda c: c[1])
    return lab, fac, h_max, _columns(list(poly_needs), width)


def _columns(needs, width: float) -> list[float]:
    """Column widths: each its need and an equal share of what is spare (shrunk alike if short)."""
    n = len(needs)
    spare = width - sum(needs) - GAP * (n - 1)
    if spare >= 0:
        return [w + spare / n for w in needs]
    return [w * (width - GAP * (n - 1)) / sum(needs) for w in needs]


def _left(sh: Sheet, s: Sheet2, lang: str, x0: float, x1: float, column: bool):
    """The groups over their polygons and the lever in the left part x0…x1: the lever under them
    across the width, or (`column`) in a column of the full height at the right; returns
    (groups, polygons, lever box, group scale, lever's k) or None when the lever's column leaves
    the groups no room."""
    y0, y1 = FRAME[1] + GAP, FRAME[3] - GAP
    sizes = [_polygon_size(sh, pg, lang) for pg in s.polygons]
    needs = [max(w, 100.0) for w, _ in sizes]
    h_poly = max(h for _, h in sizes)
    ks = _lever_ks(s)
    if column:
        for mu, k in ks:
            lw, lh = _lever_need(sh, s, lang, k)
            if lh <= y1 - y0 and x1 - x0 - lw - GAP >= sum(needs) + GAP * (len(needs) - 1):
                break
        else:
            return None
        lever = (x1 - lw, y0, x1, y1)
        h_groups = (y1 - y0) - GAP - h_poly
        lab, fac, _, widths = _group_scale(sh, s, lang, needs, lever[0] - GAP - x0, h_groups)
    else:
        _, h_lever_min = _lever_need(sh, s, lang, ks[-1][1], x1 - x0)
        _, h_lever = _lever_need(sh, s, lang, ks[0][1], x1 - x0)  # at the table's μ, if the groups keep 120 mm
        if (y1 - y0) - 2 * GAP - h_poly - h_lever >= 120.0:
            h_lever_min = h_lever
        rest = (y1 - y0) - 2 * GAP - h_poly
        if rest - h_lever_min < 120.0:  # the polygons give way (drawn at a larger μ_F, said under them)
            h_poly = max(90.0, (y1 - y0) - 2 * GAP - 120.0 - h_lever_min)
            rest = (y1 - y0) - 2 * GAP - h_poly
        lab, fac, h_groups, widths = _group_scale(sh, s, lang, needs, x1 - x0, max(rest - h_lever_min, 120.0))
        lever = (x0, y0, x1, y1 - h_groups - h_poly - 2 * GAP)
        k = next((k for _, k in ks if _lever_need(sh, s, lang, k, x1 - x0)[1] <= lever[3] - lever[1]
                  and _lever_need(sh, s, lang, k, x1 - x0)[0] <= x1 - x0), ks[-1][1])
    groups, polygons = [], []
    x = x0
    for w in widths:
        groups.append((x, y1 - h_groups, x + w, y1))
        polygons.append((x, y1 - h_groups - GAP - h_poly, x + w, y1 - h_groups - GAP))
        x += w + GAP
    return groups, polygons, lever, (lab, fac), k


def layout(sh: Sheet, s: Sheet2, lang: str, rows: int) -> Layout2:
    """The field boxes of sheet 2 from the measured drawings: the right column holds the diagrams
    (their size at the core's scales), the energy–mass diagram (what is left) and the table over
    the title block; the left part a column per group — the group's drawing over its polygon (the
    polygons at the core's μ_F set the row's height) — and the lever under them or, when that
    gives the drawings larger scales (a tall lever), in a column of its own at their right."""
    X0, _, X1, Y1 = FRAME
    dw, dh = _diagrams_size(sh, s, lang)
    wr = max(dw, 215.0)
    xr0, xr1 = X1 - GAP - wr, X1 - GAP
    th = 12.0 + ROW_H * rows + 3.0
    table_box = (xr0, TB_BOX[3] + GAP, xr1, TB_BOX[3] + GAP + th)
    room_right = (Y1 - GAP) - (table_box[3] + GAP)
    if s.flywheel is not None:
        dh = min(dh, room_right - 110.0 - GAP)
        diagrams = (xr0, Y1 - GAP - dh, xr1, Y1 - GAP)
        witt = (xr0, table_box[3] + GAP, xr1, diagrams[1] - GAP)
    else:
        diagrams = (xr0, table_box[3] + GAP, xr1, Y1 - GAP)
        witt = None
    xl0, xl1 = X0 + GAP, xr0 - GAP
    options = [o for o in (_left(sh, s, lang, xl0, xl1, False), _left(sh, s, lang, xl0, xl1, True)) if o is not None]
    best = max(options, key=lambda o: 2.0 * math.log(o[3][1]) + math.log(o[4]) - 1e-6 * options.index(o))
    groups, polygons, lever, scale, _ = best
    lever, witt, inds = indicator_view.place(sh, s, lang, lever, witt,
                                             lambda w: _lever_need(sh, s, lang, _lever_ks(s)[-1][1], w))
    return Layout2(tuple(groups), tuple(polygons), lever, diagrams, witt, table_box, scale, inds)


def _group_fields(sh: Sheet, s: Sheet2, lang: str, lay: Layout2) -> None:
    i = s.force_position
    lab, fac = lay.group_scale
    mu = num(1.0 / (fac * MM), lang, sig=3)
    for pg, box in zip(s.polygons, lay.groups):
        g = pg.group
        f = field(sh, f"group_{g}", box, _group_heading(s, g, lang))
        x0, y0, x1, y1 = f.inner
        room = (x0, y0, x1, y1 - SCALE_H)
        pts, arrows = _group_drawing(s, g, i, fac)
        fit = fit_arrows(pts, arrows, room, fac, pad=GROUP_PAD)
        sh.set_field_transform(f, fit.origin, fac, lab)
        scale_line(sh, f, tr(lang, "M") + " " + (lab if lang == "ru" else lab.replace(",", ".")) +
                   f"; μ_{{l}} = {mu} " + tr(lang, "m/mm"))
        f.clip = room
        _draw_group(sh, f, s, g, i, lang, room)


def _results(sh: Sheet, s: Sheet2, lang: str, box) -> None:
    table(sh, box, tr(lang, "Main results"), _rows(s, lang), col1=0.5, h=H_NOTE)


def _rows(s: Sheet2, lang: str) -> list[tuple[str, str]]:
    d, fw = s.dynamics, s.flywheel
    nm, kg = tr(lang, "N·m"), tr(lang, "kg·m²")
    i = s.force_position
    engine = s.is_engine  # the gas drives: the constant moment is the consumer's resistance
    rows = [(tr(lang, "Consumer's resisting moment M_{c}"), f"{num(-d.M_d, lang, decimals=2)} {nm}") if engine else
            (tr(lang, "Driving moment M_{d}"), f"{num(d.M_d, lang, decimals=2)} {nm}"),
            (tr(lang, "M_{{b}}, position {label}; Zhukovsky").format(label=s.sheet1.cycle.positions[i].label),
             f"{num(float(s.balancing[i]), lang, decimals=2)}; {num(float(s.lever.balancing[i]), lang, decimals=2)} {nm}")]
    if fw is not None:
        rows += [(tr(lang, "δ; ω_{max}, ω_{min}, rad/s"),
                  f"{num(fw.delta, lang, sig=3)}; {num(fw.omega_max, lang, sig=4)}, {num(fw.omega_min, lang, sig=4)}"),
                 (tr(lang, "Flywheel J_{fl} (Mertsalov)"), f"{num(fw.J, lang, sig=4)} {kg}"),
                 (tr(lang, "J_{fl} (Wittenbauer)"),
                  f"{num(max(fw.wittenbauer.J_fl, 0.0), lang, sig=4)} {kg}")]
        if fw.size is not None:
            dims = f"D = {num(fw.size.D * MM, lang, decimals=0)}, b = {num(fw.size.b * MM, lang, decimals=0)}"
            if fw.size.h is not None:
                dims += f", h = {num(fw.size.h * MM, lang, decimals=0)}"
            rows.append((tr(lang, "Flywheel, mm; mass"),
                         f"{dims}; {num(fw.size.m, lang, decimals=1)} " + tr(lang, "kg")))
    return rows


def sheet2(s: Sheet2, lang: str, title, variant: int = 0) -> Sheet:
    """Build sheet 2 of a mechanism (no file written); `variant` (the project's, with sheets 3–4)
    goes into the designation ТММ.02.<variant>.00.00 like theirs (0 for `tmm linkage` alone)."""
    sh = Sheet(lang)
    sh.frame()
    rows = _rows(s, lang)
    lay = layout(sh, s, lang, len(rows))
    _group_fields(sh, s, lang, lay)
    for pg, box in zip(s.polygons, lay.polygons):
        _polygon_field(sh, s, pg, box, lang)
    _lever_field(sh, s, lang, lay.lever)
    _diagrams_field(sh, s, lang, lay.diagrams)
    if lay.wittenbauer is not None:
        _wittenbauer_field(sh, s, lang, lay.wittenbauer)
    indicator_view.fields(sh, s, lang, lay.indicators)
    _results(sh, s, lang, lay.table)
    sh.title_block(title, name=tr(lang, "Force analysis of the lever mechanism and the flywheel"),
                   designation=title.designation_for(2, variant), scale=lay.group_scale[0])
    sh.finish()
    return sh
