"""Sheet 4 «Синтез и анализ зубчатых механизмов» (§2.1–§2.5, the book's sample sheet).

Fields: the reducer's kinematic scheme by ГОСТ 2.770 (shafts as thick lines, bearings, the carrier,
the fixed link hatched) at a stated K_S with the picture of linear velocities beside it on the same
radius scale, the picture of angular velocities, the assembly order (2.4), the spur mesh at a
standard scale (§2.3, Fig. 2.2: partial wheels cut by wavy lines, the involute construction of one
flank, the active line with its limits and zones, the working parts of the profiles as one heavy
line) and a table. Every number and every point comes from the
:class:`~tmm_cli.gears.design.GearsResult` (the velocity pictures from ``checks.velocity``, the
mesh from ``spur``, the involute construction from ``gears.involute.flank_construction``); the
sheet only chooses drawing scales and places things.
"""

from __future__ import annotations

import math

import numpy as np

from ...gears.involute import flank_construction
from ...i18n import tr
from ...i18n.numbers import num
from ..figures.gears import _mesh_geometry, _shift_kw, tooth_outline
from .cam_sheet import LINE, _dirs, _m, table
from .layout import GOST_SCALES, fit_view, nice_scale
from .paper import FRAME, H_LABEL, H_MIN_LABEL, TB_BOX, Sheet, thin_out

X0, Y0, X1, Y1 = FRAME
LEFT = 420.0  # the left part: scheme with linear velocities, angular velocities, assembly, table
BOX_SCHEME = (X0 + 2.0, 318.0, LEFT, Y1 - 2.0)
BOX_ANGULAR = (X0 + 2.0, 190.0, 214.0, 316.0)
BOX_TABLE = (X0 + 2.0, Y0 + 2.0, 214.0, 188.0)
BOX_ASSEMBLY = (216.0, Y0 + 2.0, LEFT, 316.0)
BOX_MESH = (LEFT + 2.0, TB_BOX[3] + 2.0, X1 - 2.0, Y1 - 2.0)

H_NOTE = 3.5
ENLARGE = tuple((lab, f) for lab, f in GOST_SCALES if 0.5 <= f <= 10.0)
TEETH_EACH_SIDE = 4


def _n(x, lang, d=2):
    return num(x, lang, decimals=d)


def _g6(x, lang):
    """A number as %g would print it (6 significant digits), with a decimal comma under ru."""
    return num(x, lang, sig=6)


def aw_of(g) -> float:
    return centre_distance(g)


def centre_distance(g) -> float:
    """The distance the wheels run at [mm]: a_w of a shifted pair (= a for the book's zero pair)."""
    return g.a_w_mm or g.a_mm


def tooth_sizes(g) -> dict:
    """s, e on the pitch circle, h_a, h_f of each gear and x·m [mm], read from the result: the
    shifted pair's geometry (``g.pair``) when there is one, the book's zero pair otherwise."""
    pr = g.pair
    if pr is None:
        ha, hf = g.ha_star * g.m_mm, (g.ha_star + g.c_star) * g.m_mm
        return {"s": (g.s_mm, g.s_mm), "e": (g.e_mm, g.e_mm), "ha": (ha, ha), "hf": (hf, hf), "xm": (0.0, 0.0)}
    return {"s": pr.s_mm, "e": pr.e_mm, "ha": pr.ha_mm, "hf": pr.hf_mm, "xm": pr.shift_mm}


def _cross_small(sh, c, s=3.0):
    sh.line((c[0] - s, c[1]), (c[0] + s, c[1]), "Тонкие")
    sh.line((c[0], c[1] - s), (c[0], c[1] + s), "Тонкие")


def _ground(sh, a, b, side, layer="Тонкие", step=2.0, depth=2.0):
    """A fixed link's hatch along the segment a–b [sheet mm], strokes on `side` (a unit normal)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    L = float(np.hypot(*(b - a)))
    u = (b - a) / (L or 1.0)
    n = np.asarray(side, float)
    for t in np.arange(0.5 * step, L, step):
        q = a + u * t
        sh.line(q, q + n * depth - u * depth * 0.8, layer)


# ----------------------------------------------------------------------------------------------
# scheme (ГОСТ 2.770) and the picture of linear velocities (drawn in module units r = z/2; the module
# the drawing takes: planetary_module)


# ГОСТ 9563-60, series 1 (the preferred modules) [mm]
MODULES = (1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 16.0, 20.0, 25.0)


def planetary_module(paper_per_module: float) -> float:
    """The module the reducer is drawn with: the largest standard one at which its scheme, drawn
    `paper_per_module` paper mm per module, stands at 1:1 or larger; 1 mm when even that needs a
    reduction.

    >>> planetary_module(2.0), planetary_module(2.5), planetary_module(0.5), planetary_module(7.0)
    (2.0, 2.5, 1.0, 6.0)
    """
    return max([m for m in MODULES if m <= paper_per_module * (1 + 1e-9)] or [1.0])


SCHEME_HEADING_MM = 13.0  # the scheme field's one-line heading with its gaps (paper.Sheet.heading_height: 12,75)


def reducer_fit(r):
    """The scheme's ГОСТ scale on sheet 4 (paper mm per module) and the module the reducer is drawn
    with (:func:`planetary_module`) — from the result alone, so the note's figures state the same
    module: (fit, m [mm], scale [paper mm per real mm], its label)."""
    rmax, gap, _, x_end = _scheme_layout(r.planetary)
    x0b, y0b, x1b, y1b = BOX_SCHEME
    split = x0b + 0.6 * (x1b - x0b)  # the scheme takes the left 60 % of the field, the linear velocities the rest
    lo = np.array([-0.55 * rmax, -1.22 * rmax])
    hi = np.array([x_end + 1.0 * gap + 0.3 * rmax, 1.22 * rmax])
    room = (x0b + 2.0, y0b + 2.5 + LINE * 2 + 2.0, split, y1b - SCHEME_HEADING_MM - 2.0)
    fit = fit_view(lo, hi, room, margin=(14.0, 4.0, 6.0, 4.0), choices=ENLARGE)
    m_pl = planetary_module(fit.scale)
    scale = fit.scale / m_pl  # paper mm per real mm
    label = next((lab for lab, x in GOST_SCALES if abs(x - scale) < 1e-9 * scale), fit.label)
    return fit, m_pl, scale, label


def _scheme_layout(d):
    rmax = max(max(s.z_ring / 2, (s.z_sun + 2 * s.z_planet) / 2) for s in d.stages)
    gap = 0.26 * rmax
    x = 0.0
    out = []
    for s in d.stages:
        xk = x + gap
        x_c2 = xk + (gap * 0.8 if s.z_planet2 is not None else 0.0)
        xh = x_c2 + gap
        out.append((xk, x_c2, xh))
        x = xh
    return rmax, gap, out, x


def _bearing(sh, q, along, size=2.2, fixed=True):
    """A radial bearing on a shaft (ГОСТ 2.770): a short thick line on either side of the shaft,
    the housing hatched when it is the fixed link."""
    q = np.asarray(q, float)
    u = np.asarray(along, float)
    n = np.array([-u[1], u[0]])
    for sg in (1.0, -1.0):
        c = q + n * sg * size
        sh.line(c - u * 2.5, c + u * 2.5, "Основные")
        if fixed:
            _ground(sh, c - u * 3.0, c + u * 3.0, n * sg, step=1.8, depth=1.6)


def _scheme_field(sh: Sheet, r, lang: str):
    d = r.planetary
    v = r.checks.velocity
    rmax, gap, xs, x_end = _scheme_layout(d)
    x0b, y0b, x1b, y1b = BOX_SCHEME
    # the scheme takes the left 60 % of the field, the linear velocities the rest (same radii)
    split = x0b + 0.6 * (x1b - x0b)
    fld = sh.add_field("scheme", BOX_SCHEME, tr(lang, "Planetary reducer scheme and linear velocities"))
    room = (x0b + 2.0, y0b + 2.5 + LINE * 2 + 2.0, split, fld.inner[3] - 2.0)
    # the reducer's module: the synthesis gives tooth numbers only; the drawing takes the largest standard
    # module (ГОСТ 9563, series 1) at which the scheme fits its field at 1:1 (f paper mm per module);
    # reducer_fit (the note's figures take the module from it) under the heading's usual height
    fit, m_pl, scale, label = reducer_fit(r)
    f = fit.scale
    sh.set_field_transform(fld, fit.origin, f, fit.label)
    P = fld.p
    k_s = 0.001 / scale  # m/mm of the reducer at its module
    inner = (x0b + 1.0, room[1], x1b - 1.0, fld.inner[3])
    # the axis of the reducer
    sh.line(P(-0.5 * rmax, 0), P(x_end + 0.95 * gap, 0), "Осевые")
    prev = -0.45 * rmax
    sh.line(P(prev, 0), P(xs[0][0], 0), "Основные")  # input shaft
    _bearing(sh, P(prev + 0.12 * rmax, 0), (1, 0))
    for j, (s, (xk, x_c2, xh)) in enumerate(zip(d.stages, xs)):
        suf = str(j + 1) if len(d.stages) > 1 else ""
        rk, rc, rc2, rn = s.z_sun / 2, s.z_planet / 2, s.zc2 / 2, s.z_ring / 2
        rC = rk + rc
        tick = 0.05 * rmax
        if j > 0:  # this stage's sun on the previous carrier's shaft
            sh.line(P(prev, 0), P(xk, 0), "Основные")
        _bar(sh, fld, xk, -rk, rk, tick)
        for sg in (1, -1):
            _bar(sh, fld, xk, sg * (rC - rc), sg * (rC + rc), tick)
            if s.z_planet2 is not None:
                _bar(sh, fld, x_c2, sg * (rC - rc2), sg * (rC + rc2), tick)
            # planet axle (thick), its bearing, the carrier's arm to the output shaft
            sh.line(P(xk - 0.25 * gap, sg * rC), P(xh, sg * rC), "Основные")
            _bearing(sh, P(xk - 0.12 * gap, sg * rC), (1, 0), size=1.6, fixed=False)
            sh.line(P(xh, 0), P(xh, sg * rC), "Основные")
            # the fixed ring: a bar from r_n outwards, the housing hatched
            xr = x_c2
            sh.line(P(xr, sg * rn), P(xr, sg * (rn + 0.1 * rmax)), "Основные")
            sh.line(P(xr - tick, sg * rn), P(xr + tick, sg * rn), "Основные")
            yb = sg * (rn + 0.1 * rmax)
            a, b = np.array(P(xr - 0.1 * rmax, yb)), np.array(P(xr + 0.1 * rmax, yb))
            sh.line(a, b, "Основные")
            _ground(sh, a, b, (0.0, float(sg)))
        for (lx, ly, t) in ((xk, 0.5 * rk, f"k{suf}"), (xk, rC + 0.5 * rc, f"c{suf}"), (xh, 0.5 * rC, f"H{suf}"),
                            (x_c2, rn + 0.05 * rmax, f"n{suf}")):
            sh.label(t, P(lx, ly), H_LABEL, within=inner, dirs=("w", "e", "nw", "sw", "ne", "se"), dists=(1.5, 3.0),
                     priority=8)
        if s.z_planet2 is not None:
            sh.label(f"c′{suf}", P(x_c2, rC + 0.5 * rc2), H_LABEL, within=inner, dirs=("e", "w", "ne", "se"),
                     dists=(1.5, 3.0), priority=8)
        prev = xh
    sh.line(P(prev, 0), P(prev + 0.85 * gap, 0), "Основные")  # output shaft
    _bearing(sh, P(prev + 0.45 * gap, 0), (1, 0))
    sh.label(tr(lang, "from motor"), P(-0.45 * rmax, 0), H_MIN_LABEL, within=inner,
             dirs=("n", "nw", "ne", "s"), dists=(3.0, 5.0), priority=6)
    sh.label(tr(lang, "to crank"), P(prev + 0.85 * gap, 0), H_MIN_LABEL, within=inner,
             dirs=("n", "ne", "nw", "s", "se"), dists=(3.0, 5.0), priority=6)
    # the linear velocities on the scheme's radius scale: V_A drawn v_a·kv mm (velocities in the
    # core's drawn units, module units × kv)
    vmax = max(max(s.v_a for s in v.stages),
               max(abs(s.v_a / (s.r_a - s.r_b)) * (max(s.r_b, s.r_a + 2 * s.r_planet) - s.r_b) for s in v.stages))
    vmin = min(0.0, min(s.v_a / (s.r_a - s.r_b) * (max(s.r_b, s.r_a + 2 * s.r_planet) - s.r_b) for s in v.stages))
    room_w = x1b - split - 26.0
    omega = math.pi * r.motor_rpm / 30.0  # the sun k turns with the motor [rad/s]
    v_real = omega * v.stages[0].r_a * m_pl * 0.001  # V_A of stage 1 [m/s] at the module m_pl
    k_v = nice_scale(v_real / v.stages[0].v_a * (1.1 * vmax - vmin) / room_w)  # (m/s)/mm, round
    kv = v_real / v.stages[0].v_a / k_v  # paper mm per drawn unit of the core
    xo = split + 14.0 - kv * vmin
    yo = fit.origin[1]

    def V(vx, ry):
        return (xo + kv * vx, yo + f * ry)

    sh.line((xo, yo - 2.0), (xo, yo + f * 1.12 * rmax), "Тонкие")
    sh.label("r", (xo, yo + f * 1.12 * rmax), H_LABEL, within=inner, dirs=("w", "nw", "e"), priority=7)
    sh.label("O", (xo, yo), H_LABEL, within=inner, dirs=("sw", "w", "s", "se"), priority=7)
    named = []
    for j, s in enumerate(v.stages):
        suf = str(j + 1) if len(v.stages) > 1 else ""
        sh.line(V(0, 0), V(s.v_a, s.r_a), "Основные")
        slope = s.v_a / (s.r_a - s.r_b)
        r_hi = max(s.r_b, s.r_a + 2 * s.r_planet)
        sh.line(V(slope * (s.r_a - s.r_b), s.r_a), V(slope * (r_hi - s.r_b), r_hi), "Основные")
        sh.line(V(0, 0), V(s.v_c, s.r_c), "Основные")
        for vx, ry in ((s.v_a, s.r_a), (s.v_c, s.r_c)):
            sh.line(V(0, ry), V(vx, ry), "Тонкие")
            sh.arrow(V(vx, ry), (1, 0), "Тонкие", 2.5, 0.8)
        for ry in (s.r_a, s.r_c, s.r_b):  # projection lines from the scheme
            sh.line((split - 2.0, yo + f * ry), (xo, yo + f * ry), "Штриховые")
        named += [(s.v_a, s.r_a, f"a{suf}"), (s.v_c, s.r_c, f"c{suf}"), (0.0, s.r_b, f"b{suf}")]
        sh.label(f"k{suf}", V(0.55 * s.v_a, 0.55 * s.r_a), H_LABEL, within=inner, dirs=("se", "e", "s", "nw"), priority=6)
        sh.label(f"H{suf}", V(0.7 * s.v_c, 0.7 * s.r_c), H_LABEL, within=inner, dirs=("nw", "w", "n", "se"), priority=6)
    for vx, ry, t in named:
        q = V(vx, ry)
        sh.dot(q, 0.5)
        sh.label(t, q, H_MIN_LABEL, within=inner, dirs=("ne", "e", "se", "n", "nw"), priority=5)
    s0, sl = v.stages[0], v.stages[-1]

    def drawn(phi_deg: float) -> float:
        """The angle of a ray as drawn here [°]: velocities at k_V, radii at the scheme's scale (the
        core's φ is at equal scales); tg φ scales by kv/f alike for k and H, so i = tg φ_k / tg φ_H holds."""
        return math.degrees(math.atan(kv / f * math.tan(math.radians(phi_deg))))

    rr = 0.35 * f * min(s0.r_a, sl.r_c)
    sh.dim_arc(V(0, 0), rr, 90 - drawn(s0.phi_k_deg), 90, "φ_{k}", H_MIN_LABEL, within=inner)
    sh.dim_arc(V(0, 0), rr * 1.45, 90 - drawn(sl.phi_h_deg), 90, "φ_{H}", H_MIN_LABEL, within=inner)
    ratios = " · ".join(_n(s.ratio, lang, 4) for s in v.stages)
    mm = tr(lang, "mm")
    teeth = "; ".join(", ".join(f"{n} = {val}" for n, val in zip(
        ("z_{k}", "z_{c}", "z_{c′}", "z_{n}") if s.z_planet2 is not None else ("z_{k}", "z_{c}", "z_{n}"), s.teeth))
        + f", k = {s.planets}" for s in d.stages)
    lines = [
        f"k_{{l}} = {num(k_s, lang, sig=3)} " + tr(lang, "m/mm") + f" ({_m(lang, label)}, m = {num(m_pl, lang, sig=3)} {mm}"
        + tr(lang, ": the largest standard module at which the reducer fits at 1:1") * (abs(scale - 1.0) < 1e-9) + ");  "
        + f"k_{{V}} = {num(k_v, lang, sig=3)} " + tr(lang, "(m/s)/mm") + ";  "
        + tr(lang, "scheme {scheme}: ").format(scheme=d.scheme) + teeth,
        f"i = tg φ_{{k}} / tg φ_{{H}} = {ratios};  φ_{{k}} = "
        + "; ".join(f"{_n(drawn(s.phi_k_deg), lang, 2)}°" for s in v.stages)
        + ";  φ_{H} = " + "; ".join(f"{_n(drawn(s.phi_h_deg), lang, 2)}°" for s in v.stages),
    ]
    sh.caption(x0b, x1b, y0b + 2.5, lines, H_NOTE, LINE)
    return fld, rmax, m_pl


def _bar(sh, fld, x, y0, y1, tick):
    P = fld.p
    sh.line(P(x, y0), P(x, y1), "Основные")
    for y in (y0, y1):
        sh.line(P(x - tick, y), P(x + tick, y), "Основные")


def _angular_field(sh: Sheet, r, lang: str):
    v = r.checks.velocity
    x0b, y0b, x1b, y1b = BOX_ANGULAR
    h = v.pole
    pts = []
    for j, s in enumerate(v.stages):
        suf = str(j + 1) if len(v.stages) > 1 else ""
        tk = math.tan(math.radians(s.phi_k_deg))
        th = math.tan(math.radians(s.phi_h_deg))
        tc = -s.v_a / (s.r_b - s.r_a)
        if j == 0:
            pts.append((h * tk, f"k{suf}"))
        pts.append((h * tc, f"c{suf}"))
        pts.append((h * th, f"h{suf}"))
    xs = [p[0] for p in pts] + [0.0]
    fld = sh.add_field("angular", BOX_ANGULAR, tr(lang, "Angular velocities"))
    ix0, iy0, ix1, iy1 = fld.inner
    span = max(xs) - min(xs)
    room_w = ix1 - ix0 - 24.0
    room_h = iy1 - (iy0 + 2.5 + LINE * 2) - 22.0
    f = min(room_w / span, room_h / h)
    # the scale: ω of the sun k (the motor's) drawn as the segment ok
    omega = math.pi * r.motor_rpm / 30.0
    k_w = nice_scale(omega / (v.ok * f))
    f = omega / (v.ok * k_w)  # a round scale: the picture a little smaller than the room
    xo = (ix0 + ix1) / 2 - (max(xs) + min(xs)) / 2 * f
    yl = iy1 - 10.0
    pole = (xo, yl - h * f)
    inner = (ix0, iy0 + 2.5 + LINE * 2, ix1, iy1)
    sh.line((xo + min(xs) * f - 6, yl), (xo + max(xs) * f + 6, yl), "Основные")
    sh.line(pole, (xo, yl), "Тонкие")
    sh.dot(pole, 0.7)
    sh.label("P", pole, H_LABEL, within=inner, dirs=("s", "se", "sw", "e", "w"), priority=8)
    sh.label("o", (xo, yl), H_LABEL, within=inner, dirs=("n", "nw", "ne"), priority=8)
    for xv, name in sorted(pts):
        q = (xo + xv * f, yl)
        sh.line(pole, q, "Основные")
        sh.dot(q, 0.5)
        sh.label(name, q, H_LABEL, within=inner, dirs=("n", "ne", "nw"), dists=(1.2, 2.5, 4.0), priority=7)
    # the segments as drawn here [mm] (the core's ok, oh are at its own pole distance)
    lines = [f"i = ok/oh = {_n(v.ok * f, lang, 2)}/{_n(v.oh * f, lang, 2)} ≈ {_n(v.ratio, lang, 3)}",
             f"k_{{ω}} = {num(k_w, lang, sig=3)} " + tr(lang, "(rad/s)/mm") + ";  "
             + tr(lang, "pole distance") + f" {_n(h * f, lang, 1)} " + tr(lang, "mm")]
    sh.caption(x0b, x1b, y0b + 2.5, lines, H_NOTE, LINE)
    return fld


def _assembly_field(sh: Sheet, r, lang: str, m_pl: float = 1.0):
    d = r.planetary
    n = len(d.stages)
    fld = sh.add_field("assembly", BOX_ASSEMBLY, tr(lang, "Assembly order"))
    x0b, y0b, x1b, y1b = fld.inner
    order = tr(lang, "Fit planet 1; turn the carrier by φ_{H1} = c·2β; fit the next planet at the same place; repeat.")
    ents = sh.text((x0b + x1b) / 2, y1b - 1.0, order, H_NOTE, align="center", valign="top", width=x1b - x0b - 4.0,
                   max_lines=3)
    top = min(e.dxf.insert[1] for e in ents) - 4.0
    cw = (x1b - x0b) / n
    caps = []
    for j, (st, ch) in enumerate(zip(d.stages, r.checks.stages)):
        suf = tr(lang, "Stage {v}: ").format(v=j + 1) if n > 1 else ""
        caps.append(suf + f"k = {st.planets};  c = {ch.assembly_c};  2β = 360°/k = {num(360.0 / st.planets, lang, sig=4)}°")
        caps.append(f"φ_{{H1}} = c·2β = {num(ch.carrier_turn_deg, lang, sig=5)}°"
                    + (f" = {int(ch.carrier_turn_deg // 360)}·360° + {num(ch.carrier_turn_deg % 360, lang, sig=4)}°"
                       if ch.carrier_turn_deg >= 360 else ""))
    # one ГОСТ 2.302 scale for the view, at the module the scheme is drawn with (stated in the caption)
    top_guess = top
    cap_guess = BOX_ASSEMBLY[1] + 2.5 + LINE * (len(caps) + 1) + H_NOTE
    f_max = min(min((cw - 10.0) / (2 * max(st.z_ring / 2, st.z_sun / 2 + st.z_planet / 2 + max(st.z_planet, st.zc2) / 2)
                                     + 4), (top_guess - cap_guess - 8.0) /
                    (2 * max(st.z_ring / 2, st.z_sun / 2 + st.z_planet / 2 + max(st.z_planet, st.zc2) / 2) + 4))
                for st in d.stages)
    fits = [(lab, x) for lab, x in GOST_SCALES if x * m_pl <= f_max * (1 + 1e-9)]
    lab_a, x_a = fits[-1] if fits else GOST_SCALES[0]
    mm = tr(lang, "mm")
    caps.append(f"{_m(lang, lab_a)}, m = {num(m_pl, lang, sig=3)} {mm}")
    cap_top = sh.caption(BOX_ASSEMBLY[0], BOX_ASSEMBLY[2], BOX_ASSEMBLY[1] + 2.5, caps, H_NOTE, LINE)
    inner = (x0b, cap_top + 2.0, x1b, top)
    for j, (st, ch) in enumerate(zip(d.stages, r.checks.stages)):
        rk, rc, rc2, rn = st.z_sun / 2, st.z_planet / 2, st.zc2 / 2, st.z_ring / 2
        rC = rk + rc
        f = x_a * m_pl  # paper mm per module unit
        c = np.array([x0b + cw * (j + 0.5), (cap_top + top) / 2])
        sh.circle(c, rk * f, "Основные")
        sh.circle(c, rn * f, "Основные")
        sh.circle(c, rC * f, "Осевые")
        k = st.planets
        for i in range(k):
            th = math.pi / 2 + 2 * math.pi * i / k
            pc = c + rC * f * np.array([math.cos(th), math.sin(th)])
            sh.line(c, pc, "Основные")
            sh.circle(pc, rc * f, "Основные")
            if st.z_planet2 is not None:
                sh.circle(pc, rc2 * f, "Штриховые")
            sh.dot(pc, 0.6)
            q = pc + (rc * f * 0.5) * np.array([math.cos(th - math.pi / 2), math.sin(th - math.pi / 2)])
            sh.label(str(i + 1), q, H_LABEL, within=inner, dirs=("e", "w", "n", "s"), dists=(0.5, 1.5, 3.0), priority=6)
        _cross_small(sh, c)
        if k >= 2:
            ra = 0.6 * rk * f
            sh.dim_arc(c, ra, 90.0, 90.0 + 360.0 / k, "2β", H_MIN_LABEL, within=inner)
    return fld


# ----------------------------------------------------------------------------------------------
# the spur mesh


def _sector(g, idx: int, nt: int = TEETH_EACH_SIDE) -> tuple[float, float, float, float]:
    """(centre direction [deg], half-angle [deg], inner radius, outer radius [mm]) of the part of
    wheel `idx` drawn: `nt` teeth on either side of the line of centres, cut off by wavy lines from
    under the root (or base) circle to over the tip circle."""
    z = (g.z1, g.z2)[idx]
    m = g.m_mm
    tau = 360.0 / z
    half = min((nt + 0.75) * tau, 100.0)
    rf = (g.df1_mm, g.df2_mm)[idx] / 2
    rb = (g.db1_mm, g.db2_mm)[idx] / 2
    ra = (g.da1_mm, g.da2_mm)[idx] / 2
    return (90.0 if idx == 0 else 270.0), half, max(0.0, min(rf, rb) - 1.2 * m), ra + 0.4 * m


def _sector_pts(centre, sec) -> np.ndarray:
    mid, half, r_in, r_out = sec
    t = np.radians(np.linspace(mid - half, mid + half, 48))
    pts = [np.column_stack([centre[0] + r_out * np.cos(t), centre[1] + r_out * np.sin(t)]),
           np.column_stack([centre[0] + r_in * np.cos(t), centre[1] + r_in * np.sin(t)])]
    return np.vstack(pts)


def mesh_layout(r, box=BOX_MESH):
    """The mesh field's scale, O1's place, whether both centres are drawn and how many teeth on
    either side of the pole: the largest ГОСТ 2.302 scale (at most 4:1) at which both partial
    wheels (4 teeth, or 3 when that gives a larger scale), the line of action and — when they fit
    at that scale too — both centres fit the field with the room the dimensions need."""
    g = r.spur
    o1, o2, p, u, n1, at = _mesh_geometry(g, r.directions.motor)
    aw = centre_distance(g)
    x0, y0, x1, y1 = box
    room = (x0 + 2.0, y0 + 2.5 + LINE * 3 + 2.0, x1 - 2.0, y1 - 16.0)
    margin = (24.0, 14.0, 24.0, 10.0)
    choices = tuple(c for c in GOST_SCALES if 0.02 <= c[1] <= 4.0)
    best = None
    for nt in (TEETH_EACH_SIDE, TEETH_EACH_SIDE - 1):
        pts = [_sector_pts(o1, _sector(g, 0, nt)), _sector_pts(o2, _sector(g, 1, nt)),
               np.array([at(-0.1 * g.n1n2_mm), at(1.1 * g.n1n2_mm)])]
        core = np.vstack(pts)
        full = np.vstack([core, o1[None], o2[None]])
        f_full = fit_view(full.min(0), full.max(0), room, margin=margin, choices=choices)
        f_core = fit_view(core.min(0), core.max(0), room, margin=margin, choices=choices)
        cand = (f_full, True, aw, nt) if f_full.scale >= f_core.scale else (f_core, False, aw, nt)
        if best is None or cand[0].scale > best[0].scale * (1 + 1e-9):
            best = cand
    return best


def _mesh_field(sh: Sheet, r, lang: str):
    g = r.spur
    fit, centres, aw, nt = mesh_layout(r)
    f = fit.scale
    x0b, y0b, x1b, y1b = BOX_MESH
    o1, o2, p, u, n1, at = _mesh_geometry(g, r.directions.motor)
    sx = 1.0 if u[0] > 0 else -1.0
    fld = sh.add_field("mesh", BOX_MESH, tr(lang, "Spur gear mesh synthesis"),
                       origin=fit.origin, scale=f, scale_label=fit.label)
    from .cam_sheet import _field_scale_text

    _field_scale_text(sh, fld, lang, fit.label)
    clip = (x0b + 1.0, y0b + 2.5 + LINE * 3 + 2.0, x1b - 1.0, fld.inner[3])
    fld.clip = clip
    within = clip
    m = g.m_mm
    ts = tooth_sizes(g)
    rot1, rot2 = math.pi / 2, -math.pi / 2 + math.pi / g.z2
    secs = (_sector(g, 0, nt), _sector(g, 1, nt))
    centres_xy = (o1, o2)

    def arc(j, radius, layer, extra=0.0):
        mid, half, _, _ = secs[j]
        c = fld.p(*centres_xy[j])
        for a0, a1 in _clip_arc(c, radius * f, mid - half - extra, mid + half + extra, clip):
            sh.arc(c, radius * f, a0, a1, layer)

    # circles d (dash-dot), d_b, d_a, d_f (thin), d_w of a shifted pair (dash-dot), over each sector
    for j, (d, db, da, df) in enumerate(((g.d1_mm, g.db1_mm, g.da1_mm, g.df1_mm), (g.d2_mm, g.db2_mm, g.da2_mm, g.df2_mm))):
        arc(j, d / 2, "Осевые")
        arc(j, db / 2, "Тонкие")
        arc(j, da / 2, "Тонкие")
        arc(j, df / 2, "Тонкие")
        if g.shifted and abs(g.pair.dw_mm[j] - d) * f > 0.3:
            arc(j, g.pair.dw_mm[j] / 2, "Осевые")
    # the wavy break lines at the sector ends
    for j in (0, 1):
        mid, half, r_in, r_out = secs[j]
        c = np.array(fld.p(*centres_xy[j]))
        for a in (mid - half, mid + half):
            e = np.array([math.cos(math.radians(a)), math.sin(math.radians(a))])
            piece = _clip_seg(c + e * r_in * f, c + e * r_out * f, clip)
            if piece is not None:
                sh.wavy(*piece, amp=1.2, wave=8.0)
    # the line of centres, the centres
    fld.line((0, -0.02 * aw), (0, aw * 1.02), "Осевые")
    for c, nm in ((o1, "O_{1}"), (o2, "O_{2}")):
        q = fld.p(*c)
        if clip[1] < q[1] < clip[3]:
            _cross_small(sh, q, 4.0)
            sh.dot(q, 0.7)
            sh.label(nm, q, H_LABEL, within=within, dirs=("ne", "nw", "se", "sw", "e", "w"), priority=9)
    # teeth: TEETH_EACH_SIDE on either side of the line of centres
    tooth1 = thin_out(tooth_outline(g.z1, m, **_shift_kw(g, 1)), 0.6 / f)  # a vertex every 0.6 mm of paper
    tooth2 = thin_out(tooth_outline(g.z2, m, **_shift_kw(g, 2)), 0.6 / f)
    for j_gear, (z, tooth, centre, rot, rmin_s, ra) in enumerate(((g.z1, tooth1, o1, rot1, g.p1_mm, g.da1_mm / 2),
                                                                  (g.z2, tooth2, o2, rot2, g.p2_mm, g.da2_mm / 2))):
        tau = 2 * math.pi / z
        r_start = float(np.hypot(*(at(rmin_s) - centre)))
        for j in range(-nt, nt + 1):
            a = rot + j * tau
            ca, sa = math.cos(a), math.sin(a)
            pts = tooth @ np.array([[ca, sa], [-sa, ca]]) + centre
            fld.poly(pts, "Основные")
            # the working flank's active part (radii r(P1 or P2) … r_a, on the side that works):
            # one heavy line over the outline
            rad = np.hypot(*(pts - centre).T)
            ang = np.arctan2(pts[:, 1] - centre[1], pts[:, 0] - centre[0]) - a
            ang = (ang + math.pi) % (2 * math.pi) - math.pi
            sel = (rad >= r_start) & (rad <= ra + 1e-9) & (sx * ang < 0) & (np.abs(ang) < tau / 2)
            if sel.sum() >= 2 and abs(j) <= 2:
                seg = pts[sel]
                seg = seg[np.argsort(np.hypot(*(seg - centre).T))]
                for piece in fld.poly(seg, "Рабочие"):
                    piece.dxf.lineweight = 100
    # the involute construction of one flank of gear 1 (a tooth on the side away from the
    # p, s, e dimensions): base points, the lines rolled off, the points of the involute
    jc = (nt - 1) * int(sx)
    t, T, Pt = flank_construction(g.z1, m, g.da1_mm / 2, x=g.x1 if g.shifted else 0.0, alpha_deg=g.alpha_deg, steps=4)
    a = rot1 + jc * 2 * math.pi / g.z1
    R = np.array([[math.cos(a), math.sin(a)], [-math.sin(a), math.cos(a)]])
    T, Pt = T @ R + o1, Pt @ R + o1
    for k in range(len(t)):
        sh.dot(fld.p(*T[k]), 0.5)
        sh.dot(fld.p(*Pt[k]), 0.5)
        if k:
            fld.line(T[k], Pt[k], "Тонкие")
            fld.label(f"{k}", Pt[k], H_MIN_LABEL, within=within, dirs=_dirs(Pt[k] - T[k]), priority=3)
    # line of action N1N2 (extended), O1N1, O2N2, points, zones
    ext = 0.12 * g.n1n2_mm
    fld.line(at(-ext), at(g.n1n2_mm + ext), "Тонкие")
    fld.line(o1, n1, "Тонкие")
    n2 = at(g.n1n2_mm)
    fld.line(o2, n2, "Тонкие")
    pts_on = {"N_{1}": 0.0, "P_{1}": g.p1_mm, "U_{2}": g.u2_mm, "P": g.pole_mm, "U_{1}": g.u1_mm, "P_{2}": g.p2_mm,
              "N_{2}": g.n1n2_mm}
    nrm = np.array([-u[1], u[0]])
    for k_, (nm, s) in enumerate(pts_on.items()):
        q = np.array(fld.p(*at(s)))
        sh.dot(q, 0.6)
        side = nrm if k_ % 2 == 0 else -nrm
        sh.label(nm, q, H_LABEL, within=within, dirs=_dirs(side), priority=8)
    # zones: a band beside the line (2 — two pairs, 1 — one pair)
    band = -nrm * 9.0 / f
    for s0, s1, lab in ((g.p1_mm, g.u2_mm, "2"), (g.u2_mm, g.u1_mm, "1"), (g.u1_mm, g.p2_mm, "2")):
        a0, a1 = at(s0) + band, at(s1) + band
        fld.line(a0, a1, "Тонкие")
        for s in (s0, s1):
            fld.line(at(s) + band * 0.75, at(s) + band * 1.25, "Тонкие")
        q = np.array(fld.p(*((a0 + a1) / 2)))
        sh.label(lab, q, H_MIN_LABEL, within=within, dirs=_dirs(-nrm), dists=(1.0, 2.0), priority=7)
    # α_w at P between the common tangent and the line of action
    pq = np.array(fld.p(*p))
    rr = max(12.0, 0.45 * (g.pole_mm - g.p1_mm) * f)
    sh.line(pq + np.array([sx * 6.0, 0]), pq - np.array([sx * (rr + 6.0), 0]), "Тонкие")
    a0, a1 = (180.0, 180.0 + g.alpha_w_deg) if sx > 0 else (360.0 - g.alpha_w_deg, 360.0)
    sh.dim_arc(pq, rr, a0, a1, f"α_{{w}} = {num(g.alpha_w_deg, lang, sig=4)}°", H_LABEL, within=within, priority=6)
    # the circles named: a leader from a point on each circle near the sector's end
    for j_gear, items in ((0, [(g.da1_mm, "d_{a1}"), (g.pair.dw_mm[0] if g.shifted else None, "d_{w1}"), (g.d1_mm, "d_{1}"),
                               (g.db1_mm, "d_{b1}"), (g.df1_mm, "d_{f1}")]),
                          (1, [(g.da2_mm, "d_{a2}"), (g.pair.dw_mm[1] if g.shifted else None, "d_{w2}"), (g.d2_mm, "d_{2}"),
                               (g.db2_mm, "d_{b2}"), (g.df2_mm, "d_{f2}")])):
        mid, half, _, _ = secs[j_gear]
        c = np.array(fld.p(*centres_xy[j_gear]))
        side = -sx if j_gear == 0 else sx  # the end away from the dimensions
        for k_, (dd, nm) in enumerate(items):
            if dd is None:
                continue
            ang = math.radians(mid + side * (half - 0.35 * (360.0 / (g.z1, g.z2)[j_gear]) - 1.5 * k_))
            q = c + dd / 2 * f * np.array([math.cos(ang), math.sin(ang)])
            if clip[0] < q[0] < clip[2] and clip[1] < q[1] < clip[3]:
                out = np.array([math.cos(ang), math.sin(ang)])
                sh.label(nm, q, H_MIN_LABEL, within=within, dirs=_dirs(out + np.array([side, 0]) * 0.3),
                         dists=(1.0, 2.5), priority=4)
    # φ_α1, φ_α2: the turns of the gears while a pair is in mesh, about the centres
    for centre, phi, nm, base in ((o1, g.phi_alpha1_deg, "φ_{α1}", 90.0), (o2, g.phi_alpha2_deg, "φ_{α2}", 270.0)):
        q = np.array(fld.p(*centre))
        rad = 0.55 * ((g.df1_mm if base == 90 else g.df2_mm) / 2) * f
        top = q[1] + (rad if base == 90 else -rad)
        if clip[1] + 8 < q[1] < clip[3] - 8 and clip[1] + 8 < top < clip[3] - 8 and rad > 12.0:
            sh.dim_arc(q, rad, base - phi / 2, base + phi / 2, f"{nm} = {num(phi, lang, sig=4)}°", H_MIN_LABEL,
                       within=within, ext_from=0.0)
    # dimensions on gear 1: p, s, e on the pitch circle of the tooth 3 places from the pole
    r1 = g.d1_mm / 2
    t1 = 2 * math.pi / g.z1
    half_s = ts["s"][0] / 2 / r1
    c1 = np.array(fld.p(*o1))
    rdim = g.da1_mm / 2 * f + 6.0
    jd = -(nt - 1) * int(sx)
    a_t = rot1 + jd * t1
    deg = math.degrees
    sh.dim_arc(c1, rdim, deg(a_t - half_s), deg(a_t + half_s), "s", H_LABEL, ext_from=r1 * f, within=within)
    e_ang = ts["e"][0] / r1
    e0 = a_t + half_s if jd > 0 else a_t - half_s - e_ang
    sh.dim_arc(c1, rdim + 8.0, deg(e0), deg(e0 + e_ang), "e", H_LABEL, ext_from=r1 * f, within=within)
    p0 = min(e0, a_t - half_s)
    sh.dim_arc(c1, rdim + 16.0, deg(p0), deg(p0 + g.p_mm / r1), "p", H_LABEL, ext_from=r1 * f, within=within)
    # radial dimensions h_f, h_a, h on gear 2 (a tooth three places from the pole) and c
    r2 = g.d2_mm / 2
    t2 = 2 * math.pi / g.z2
    a2 = rot2 + (nt - 1) * t2 * sx
    e2 = np.array([math.cos(a2), math.sin(a2)])
    nn = np.array([-e2[1], e2[0]]) * sx
    c2c = np.array(fld.p(*o2))
    for (ra_, rb_, txt, off) in ((g.df2_mm / 2, r2, "h_{f}", 9.0), (r2, g.da2_mm / 2, "h_{a}", 9.0),
                                  (g.df2_mm / 2, g.da2_mm / 2, "h", 18.0)):
        sh.dim_linear(c2c + e2 * ra_ * f, c2c + e2 * rb_ * f, nn * off, txt, H_LABEL, within=within)
    # x·m of a shifted gear: from its pitch circle to the tool rack's pitch line (a dashed arc at r + x·m)
    for j, (cc, rr_, ang, sg) in enumerate(((c1, r1, a_t - 1.5 * t1 * (1 if jd * sx < 0 else -1), 1.0),
                                             (c2c, r2, a2 - 1.5 * t2 * sx, -1.0))):
        xm = ts["xm"][j]
        if abs(xm) * f < 0.2:
            continue
        ev = np.array([math.cos(ang), math.sin(ang)])
        a_deg = math.degrees(ang)
        sh.arc(cc, (rr_ + xm) * f, a_deg - 4.0, a_deg + 4.0, "Штриховые")
        sh.dim_linear(cc + ev * rr_ * f, cc + ev * (rr_ + xm) * f, np.array([-ev[1], ev[0]]) * 7.0 * sg,
                      f"x_{{{j + 1}}}m", H_LABEL, within=within)
    # c: clearance between gear 1's tip and gear 2's root on the line of centres (a leader)
    q1 = np.array(fld.p(0.0, (g.da1_mm / 2 + aw - g.df2_mm / 2) / 2))
    sh.label(f"c = {num(g.c_mm, lang, sig=3)}", q1, H_MIN_LABEL, within=within, dirs=(), dists=(), priority=5)
    # a_w: along the line of centres, beside the wheels
    pa, pb = np.array(fld.p(*o1)), np.array(fld.p(*o2))
    xa = clip[2] - 16.0 if sx < 0 else clip[0] + 16.0
    if centres:
        sh.dim_linear(pa, pb, (xa - pa[0], 0.0), f"a_{{w}} = {num(aw, lang, sig=6)}", H_LABEL, within=within, priority=9)
    else:  # a centre beyond the field: the dimension line broken at the field's edge
        inside_ = [q for q in (pa, pb) if clip[1] < q[1] < clip[3]]
        seen = inside_[0] if inside_ else pa
        other = pb if seen is pa else pa
        end_y = clip[1] + 3.0 if other[1] < seen[1] else clip[3] - 3.0
        if clip[1] < seen[1] < clip[3]:
            sh.line(seen + (np.sign(xa - seen[0]) * 2.0, 0.0), (xa + np.sign(xa - seen[0]) * 2.0, seen[1]), "Размеры")
            sh.line((xa, seen[1]), (xa, end_y), "Размеры")
            sh.arrow((xa, seen[1]), (0.0, np.sign(seen[1] - end_y)), "Размеры", 3.0, 0.9)
            sh.label(f"a_{{w}} = {num(aw, lang, sig=6)}", (xa, (seen[1] + end_y) / 2), H_LABEL, within=within,
                     rot=90.0, dists=(1.5, 3.0), priority=9)
    # captions
    mm = tr(lang, "mm")

    def g3(val):
        return num(val, lang, sig=6)

    if g.shifted:
        pr = g.pair
        lines = [
            f"z_{{1}} = {g.z1}, z_{{2}} = {g.z2}, m = {g3(g.m_mm)} {mm}, α = {g3(g.alpha_deg)}°; "
            f"x_{{1}} = {num(g.x1, lang, sig=4)}, x_{{2}} = {num(g.x2, lang, sig=4)}; "
            f"x_{{1}}m = {_n(ts['xm'][0], lang)}, x_{{2}}m = {_n(ts['xm'][1], lang)}; "
            f"a_{{w}} = {g3(aw)} (a = {g3(g.a_mm)}), α_{{w}} = {num(g.alpha_w_deg, lang, sig=5)}°, "
            f"y = {_n(pr.y, lang, 4)}, Δy = {_n(pr.dy, lang, 4)}",
            f"d_{{w1}} = {_n(pr.dw_mm[0], lang)}, d_{{w2}} = {_n(pr.dw_mm[1], lang)}; p = {_n(g.p_mm, lang)}; "
            f"s_{{1}} = {_n(ts['s'][0], lang)}, e_{{1}} = {_n(ts['e'][0], lang)}; "
            f"h_{{a1}} = {_n(ts['ha'][0], lang)}, h_{{a2}} = {_n(ts['ha'][1], lang)}, "
            f"h_{{f1}} = {_n(ts['hf'][0], lang)}, h_{{f2}} = {_n(ts['hf'][1], lang)}, h = {_n(g.h_mm, lang)}, "
            f"c = {g3(g.c_mm)}; s_{{a1}} = {_n(pr.sa_mm[0], lang)}, s_{{a2}} = {_n(pr.sa_mm[1], lang)} {mm}",
        ]
    else:
        lines = [
            f"z_{{1}} = {g.z1}, z_{{2}} = {g.z2}, m = {g3(g.m_mm)} {mm}, α = {g3(g.alpha_deg)}°, x_{{1}} = x_{{2}} = 0;  "
            f"p = {_n(g.p_mm, lang)}, s = e = {_n(g.s_mm, lang)}, h = {g3(g.h_mm)}, h_{{a}} = {g3(ts['ha'][0])}, "
            f"h_{{f}} = {g3(ts['hf'][0])}, c = {g3(g.c_mm)} {mm}",
        ]
    lines += [
        f"ε_{{α}} = P_{{1}}P_{{2}}/p_{{b}} = {_n(g.g_alpha_mm, lang, 1)}/{_n(g.pb_mm, lang)} = {_n(g.eps_alpha, lang, 3)};  "
        + tr(lang, "zones: 2 — two pairs, 1 — one pair; working profiles — heavy line; 1…4 — the involute constructed"),
    ]
    if not centres:
        lines[-1] += tr(lang, "; the centre beyond the field: a_w broken")
    sh.caption(x0b, x1b, y0b + 2.5, lines, H_NOTE, LINE)
    return fld


def _clip_arc(c, r, a0, a1, box):
    """The parts [deg] of the arc a0…a1 (ccw) about c of radius r inside box."""
    t = np.linspace(a0, a1, max(8, int((a1 - a0) * 2)))
    x = c[0] + r * np.cos(np.radians(t))
    y = c[1] + r * np.sin(np.radians(t))
    ok = (x >= box[0]) & (x <= box[2]) & (y >= box[1]) & (y <= box[3])
    out, start = [], None
    for i, flag in enumerate(ok):
        if flag and start is None:
            start = t[i]
        if (not flag or i == len(ok) - 1) and start is not None:
            end = t[i] if flag else t[i - 1]
            if end - start > 0.2:
                out.append((start % 360.0, end % 360.0 if end % 360.0 > start % 360.0 else end % 360.0 + 360.0))
            start = None
    return out


def _clip_seg(a, b, box):
    from .paper import clip_polyline

    pieces = clip_polyline(np.array([a, b]), box)
    return (pieces[0][0], pieces[0][-1]) if pieces else None


def _results(sh: Sheet, r, lang: str):
    d, g = r.planetary, r.spur
    teeth = " + ".join("/".join(map(str, s.teeth)) for s in d.stages)
    mm = tr(lang, "mm")
    rows = [
        (tr(lang, "Motor speed n_{d}"), f"{r.motor_rpm} " + tr(lang, "rpm")),
        (tr(lang, "Reducer scheme; teeth"), f"{d.scheme}; {teeth}"),
        (tr(lang, "Planets k"), str(d.planets)),
        (tr(lang, "i_{pl}: required / obtained"),
         f"{_n(r.i_planetary, lang, 3)} / {_n(d.ratio, lang, 3)} ({num(d.ratio_error_pct, lang, decimals=2)} %)"),
        (tr(lang, "Spur pair z_{1}/z_{2}; module of the drawing m"), f"{g.z1}/{g.z2}; {_g6(g.m_mm, lang)} " + tr(lang, "mm")),
        (tr(lang, "i_{12}: required / obtained"), f"{_n(r.i_spur, lang, 3)} / {_n(g.i_actual, lang, 3)}"),
    ]
    if g.shifted:
        pr = g.pair
        rule = {"given": tr(lang, "given"), "auto": tr(lang, "auto"),
                "aw": tr(lang, "from a_{w}")}.get(g.shift_rule, g.shift_rule)
        rows += [
            (tr(lang, "Shifts x_{1}; x_{2}"),
             f"{num(g.x1, lang, sig=4)}; {num(g.x2, lang, sig=4)} ({rule})"),
            (tr(lang, "a_{w}; α_{w}"), f"{_g6(aw_of(g), lang)}; {num(g.alpha_w_deg, lang, sig=5)}°"),
            ("d_{w1}; d_{w2}", f"{_n(pr.dw_mm[0], lang)}; {_n(pr.dw_mm[1], lang)} {mm}"),
        ]
    rows += [  # every value with its unit (a table on a sheet has no column of units)
        ("d_{1}; d_{2}", f"{_g6(g.d1_mm, lang)}; {_g6(g.d2_mm, lang)} {mm}"),
        ("d_{a1}; d_{a2}", (f"{_n(g.da1_mm, lang)}; {_n(g.da2_mm, lang)}" if g.shifted else
                            f"{_g6(g.da1_mm, lang)}; {_g6(g.da2_mm, lang)}") + f" {mm}"),
        ("d_{f1}; d_{f2}", (f"{_n(g.df1_mm, lang)}; {_n(g.df2_mm, lang)}" if g.shifted else
                            f"{_g6(g.df1_mm, lang)}; {_g6(g.df2_mm, lang)}") + f" {mm}"),
        ("d_{b1}; d_{b2}", f"{_n(g.db1_mm, lang)}; {_n(g.db2_mm, lang)} {mm}"),
        (tr(lang, "a_{w}; contact ratio ε_{α}") if not g.shifted
         else tr(lang, "a; contact ratio ε_{α}"),
         f"{_g6(g.a_mm, lang)} {mm}; {_n(g.eps_alpha, lang, 3)}"),
    ]
    table(sh, BOX_TABLE, tr(lang, "Gear data"), rows, col1=0.55)


def sheet4(result, variant: int, lang: str, title) -> Sheet:
    """Build sheet 4 for a GearsResult (no file written)."""
    sh = Sheet(lang)
    sh.frame()
    _, _, m_pl = _scheme_field(sh, result, lang)
    _angular_field(sh, result, lang)
    _assembly_field(sh, result, lang, m_pl)
    mesh = _mesh_field(sh, result, lang)
    _results(sh, result, lang)
    sh.title_block(title, name=tr(lang, "Gear mechanisms: synthesis and analysis"),
                   designation=title.designation_for(4, variant), scale=mesh.scale_label)
    sh.finish()
    return sh
