"""Sheet 4 «Синтез и анализ зубчатых механизмов» (§2.1–§2.5, the book's sample sheet).

Fields: the reducer's kinematic scheme at a stated K_S, the pictures of linear and angular
velocities (2.3), the assembly order (2.4), the spur mesh at a standard scale (§2.3, Fig. 2.2) and
a table. Every number and every point comes from the :class:`~tmm_cli.gears.design.GearsResult`
(the velocity pictures from ``checks.velocity``, the mesh from ``spur``); the involute teeth are
drawn with the figure module's tooth outline.
"""

from __future__ import annotations

import math

import numpy as np

from ...i18n.lang import pick
from ...i18n.numbers import num
from ..figures.gears import _mesh_geometry, _shift_kw, tooth_outline
from .cam_sheet import table
from .paper import GOST_SCALES, Sheet, fit_scale, thin_out

BOX_SCHEME = (22.0, 300.0, 252.0, 587.0)
BOX_LINEAR = (254.0, 300.0, 420.0, 587.0)
BOX_ANGULAR = (22.0, 175.0, 220.0, 298.0)
BOX_ASSEMBLY = (222.0, 7.0, 420.0, 298.0)
BOX_TABLE = (22.0, 7.0, 220.0, 173.0)
BOX_MESH = (422.0, 62.0, 834.0, 587.0)

H_LABEL = 3.5
H_SMALL = 2.5
ENLARGE = tuple((lab, f) for lab, f in GOST_SCALES if 0.5 <= f <= 10.0)


def _n(x, lang, d=2):
    return num(x, lang, decimals=d)


def _g6(x, lang):
    """A number as %g would print it (6 significant digits), with a decimal comma under ru."""
    return num(x, lang, sig=6)


def aw_of(g) -> float:
    return centre_distance(g)


# ----------------------------------------------------------------------------------------------
# scheme and velocity pictures (module units: r = z/2 with m = 1 mm)


def _scheme_layout(d):
    rmax = max(max(s.z_ring / 2, (s.z_sun + 2 * s.z_planet) / 2) for s in d.stages)
    gap = 0.22 * rmax
    x = 0.0
    out = []
    for s in d.stages:
        xk = x + gap
        x_c2 = xk + (gap * 0.8 if s.z_planet2 is not None else 0.0)
        xh = x_c2 + gap
        out.append((xk, x_c2, xh))
        x = xh
    return rmax, gap, out, x


def _scheme_field(sh: Sheet, r, lang: str):
    d = r.planetary
    rmax, gap, xs, x_end = _scheme_layout(d)
    width = x_end + 0.9 * gap + 0.5 * rmax
    height = 2 * 1.16 * rmax  # the ring hatch ends at 1.14·r_max
    x0b, y0b, x1b, y1b = BOX_SCHEME
    name, f = fit_scale((width, height), (x1b - x0b - 16.0, y1b - y0b - 36.0), ENLARGE)
    k_s = 0.001 / f  # m/mm for a module of 1 mm
    cy = (y0b + 12.0 + y1b - 30.0) / 2
    origin = (x0b + 12.0 + 0.45 * rmax * f, cy)
    fld = sh.add_field("scheme", BOX_SCHEME, pick(lang, "Planetary reducer scheme", "Схема планетарного механизма"),
                       origin=origin, scale=f, scale_label=name,
                       scale_text=f"K_{{S}} = {num(k_s, lang, sig=3)} {pick(lang, 'm/mm', 'м/мм')} ({pick(lang, 'M', 'М')} {pick(lang, name.replace(',', '.'), name)}, m = 1 {pick(lang, 'mm', 'мм')})")
    P = fld.p
    # the axis
    fld.line((-0.4 * rmax, 0), (x_end + 0.9 * gap, 0), "Осевые")
    prev = -0.35 * rmax
    for j, (s, (xk, x_c2, xh)) in enumerate(zip(d.stages, xs)):
        suf = str(j + 1) if len(d.stages) > 1 else ""
        rk, rc, rc2, rn = s.z_sun / 2, s.z_planet / 2, s.zc2 / 2, s.z_ring / 2
        rC = rk + rc
        tick = 0.04 * rmax
        # input shaft
        sh.line(P(prev, 0), P(xk, 0), "Основные")
        sh.line(P(prev, 0.6), P(xk, 0.6), "Основные")
        # sun: a bar across its pitch diameter with ticks
        _bar(sh, fld, xk, -rk, rk, tick)
        for sg in (1, -1):
            _bar(sh, fld, xk, sg * rk, sg * (rk + 2 * rc), tick)
            if s.z_planet2 is not None:
                _bar(sh, fld, x_c2, sg * (rC - rc2), sg * (rC + rc2), tick)
                sh.line(P(xk, sg * rC), P(x_c2, sg * rC), "Основные")
            # planet axle, carrier arm
            sh.line(P(xk - 0.3 * gap, sg * rC), P(xh, sg * rC), "Основные")
            sh.line(P(xh, 0), P(xh, sg * rC), "Основные")
            sh.dot(P(xk if s.z_planet2 is None else (xk + x_c2) / 2, sg * rC), 0.6)
            # fixed ring: bar from r_n outwards, ground hatching
            xr = x_c2
            sh.line(P(xr, sg * rn), P(xr, sg * (rn + 0.1 * rmax)), "Основные")
            sh.line(P(xr - tick, sg * rn), P(xr + tick, sg * rn), "Основные")
            yb = sg * (rn + 0.1 * rmax)
            sh.line(P(xr - 0.08 * rmax, yb), P(xr + 0.08 * rmax, yb), "Основные")
            for hx in np.linspace(xr - 0.08 * rmax, xr + 0.05 * rmax, 5):
                sh.line(P(hx, yb), P(hx + 0.03 * rmax, yb + sg * 0.04 * rmax), "Тонкие")
        # labels
        for (lx, ly, t) in ((xk, 0.5 * rk, f"k{suf}"), (xk, rk + rc, f"c{suf}"), (xh, 0.5 * rC, f"H{suf}"),
                            (x_c2, rn + 0.05 * rmax, f"n{suf}")):
            q = P(lx, ly)
            if t.startswith("c"):  # above the planet's axle, which runs left of the bar
                sh.text(q[0] - 1.5, q[1] + 1.2, t, H_LABEL, align="right")
            else:
                sh.text(q[0] - 1.5, q[1], t, H_LABEL, align="right", valign="middle")
        if s.z_planet2 is not None:
            q = P(x_c2, rC + 0.5 * rc2)
            sh.text(q[0] + 1.5, q[1], f"c′{suf}", H_LABEL, valign="middle")
        prev = xh
    sh.line(P(prev, 0), P(prev + 0.8 * gap, 0), "Основные")
    sh.line(P(prev, 0.6), P(prev + 0.8 * gap, 0.6), "Основные")
    q = P(-0.4 * rmax, 0)
    sh.text(q[0], q[1] + 0.6 * fld.scale + 1.5, pick(lang, "from motor", "от двигателя"), H_SMALL)
    q = P(prev + 0.8 * gap, 0)
    # beyond the shaft's end (above it the text would cross the carrier's arm)
    sh.text(q[0] + 1.0, q[1] + 0.6 * fld.scale + 1.5, pick(lang, "to crank", "к кривошипу"), H_SMALL,
            width=max(8.0, x1b - q[0] - 3.0), max_lines=2)
    teeth = "; ".join(", ".join(f"{n} = {v}" for n, v in zip(
        ("z_{k}", "z_{c}", "z_{c′}", "z_{n}") if s.z_planet2 is not None else ("z_{k}", "z_{c}", "z_{n}"), s.teeth))
        + f", k = {s.planets}" for s in d.stages)
    sh.text(x0b + 3.0, y0b + 3.0, pick(lang, f"Scheme {d.scheme}: ", f"Схема {d.scheme}: ") + teeth, H_SMALL,
            width=x1b - x0b - 6.0, max_lines=2)
    return fld, rmax


def _bar(sh, fld, x, y0, y1, tick):
    P = fld.p
    sh.line(P(x, y0), P(x, y1), "Основные")
    for y in (y0, y1):
        sh.line(P(x - tick, y), P(x + tick, y), "Основные")


def _linear_field(sh: Sheet, r, lang: str, scheme):
    """Linear velocities on the scheme's radius scale (projection lines from the scheme)."""
    v = r.checks.velocity
    fld_s, rmax = scheme
    x0b, y0b, x1b, y1b = BOX_LINEAR
    vmax = max(max(s.v_a for s in v.stages), max(abs(s.v_a / (s.r_a - s.r_b)) * (max(s.r_b, s.r_a + 2 * s.r_planet) - s.r_b) for s in v.stages))
    vmin = min(0.0, min(s.v_a / (s.r_a - s.r_b) * (max(s.r_b, s.r_a + 2 * s.r_planet) - s.r_b) for s in v.stages))
    kv = (x1b - x0b - 28.0) / (1.1 * vmax - vmin)  # velocities: the picture's own scale; radii: the scheme's
    xo = x0b + 12.0 - kv * vmin
    yo = fld_s.origin[1]
    fy = fld_s.scale
    fld = sh.add_field("linear", BOX_LINEAR, pick(lang, "Linear velocities", "Картина линейных скоростей"),
                       origin=(xo, yo), scale=fy, scale_label="",
                       scale_text=None)

    def P(vx, ry):
        return (xo + kv * vx, yo + fy * ry)

    sh.line((xo, yo - 2.0), (xo, yo + fy * 1.12 * rmax), "Тонкие")
    sh.text(xo - 1.5, yo + fy * 1.12 * rmax, "r", H_LABEL, align="right", valign="top")
    sh.text(xo - 1.5, yo - 1.0, "O", H_LABEL, align="right", valign="top")
    named = []
    for j, s in enumerate(v.stages):
        suf = str(j + 1) if len(v.stages) > 1 else ""
        sh.line(P(0, 0), P(s.v_a, s.r_a), "Основные")
        slope = s.v_a / (s.r_a - s.r_b)
        r_hi = max(s.r_b, s.r_a + 2 * s.r_planet)
        sh.line(P(slope * (s.r_a - s.r_b), s.r_a), P(slope * (r_hi - s.r_b), r_hi), "Основные")
        sh.line(P(0, 0), P(s.v_c, s.r_c), "Основные")
        for vx, ry in ((s.v_a, s.r_a), (s.v_c, s.r_c)):
            sh.line(P(0, ry), P(vx, ry), "Тонкие")
            sh.arrow(P(vx, ry), (1, 0), "Тонкие", 2.5, 0.8)
        # projection lines from the scheme
        for ry in (s.r_a, s.r_c, s.r_b):
            sh.line((fld_s.box[2] - 2.0, yo + fy * ry), (xo, yo + fy * ry), "Тонкие", "DASHED")
        named += [(s.v_a, s.r_a, f"a{suf}"), (s.v_c, s.r_c, f"c{suf}"), (0.0, s.r_b, f"b{suf}")]
        q = P(0.55 * s.v_a, 0.55 * s.r_a)
        if j == 0:
            sh.text(q[0] + 1.5, q[1] - 1.0, f"k{suf}", H_LABEL, valign="top")
        q = P(0.75 * s.v_c, 0.75 * s.r_c)
        sh.text(q[0] - 1.0, q[1] + 1.0, f"H{suf}", H_LABEL, align="right")
    seen = []
    for vx, ry, t in named:
        q = np.array(P(vx, ry))
        sh.dot(q, 0.5)
        if all(np.hypot(*(q - s)) > 2.5 for s in seen):
            sh.text(q[0] + 1.5, q[1] + 1.0, t, H_SMALL)
            seen.append(q)
    s0, sl = v.stages[0], v.stages[-1]
    rr = 0.35 * fy * min(s0.r_a, sl.r_c)
    sh.arc(P(0, 0), rr, 90 - s0.phi_k_deg, 90, "Тонкие")
    sh.arc(P(0, 0), rr * 1.3, 90 - sl.phi_h_deg, 90, "Тонкие")
    ratios = " · ".join(_n(s.ratio, lang, 4) for s in v.stages)
    lines = [f"i = tg φ_{{k}} / tg φ_{{H}} = {ratios}",
             "φ_{k} = " + "; ".join(f"{_n(s.phi_k_deg, lang, 2)}°" for s in v.stages)
             + ";  φ_{H} = " + "; ".join(f"{_n(s.phi_h_deg, lang, 2)}°" for s in v.stages)]
    y = y0b + 3.0 + 4.6
    for t in lines:
        sh.text(x0b + 2.0, y, t, H_SMALL, width=x1b - x0b - 4.0)
        y -= 4.6
    return fld


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
    span = max(xs) - min(xs)
    f = min((x1b - x0b - 30.0) / span, (y1b - y0b - 40.0) / h)
    fld = sh.add_field("angular", BOX_ANGULAR, pick(lang, "Angular velocities", "Картина угловых скоростей"))
    xo = x0b + 15.0 - min(xs) * f
    yl = y1b - 16.0
    pole = (xo, yl - h * f)
    sh.line((xo + min(xs) * f - 5, yl), (xo + max(xs) * f + 5, yl), "Основные")
    sh.line(pole, (xo, yl), "Тонкие")
    sh.dot(pole, 0.6)
    sh.text(pole[0] + 1.5, pole[1] - 1.0, "P", H_LABEL, valign="top")
    sh.text(xo - 1.0, yl + 1.2, "o", H_LABEL, align="right")
    last = None
    for xv, name in sorted(pts):
        q = (xo + xv * f, yl)
        sh.line(pole, q, "Основные")
        sh.dot(q, 0.5)
        up = last is None or q[0] - last > 5.0
        sh.text(q[0], yl + (1.5 if up else -2.0), name, H_LABEL, align="center", valign="base" if up else "top")
        last = q[0]
    sh.text(x0b + 2.0, y0b + 3.0, f"i = ok/oh = {_n(v.ok, lang, 1)}/{_n(v.oh, lang, 2)} = {_n(v.ratio, lang, 4)}",
            H_SMALL, width=x1b - x0b - 4.0)
    return fld


def _assembly_field(sh: Sheet, r, lang: str):
    d = r.planetary
    n = len(d.stages)
    fld = sh.add_field("assembly", BOX_ASSEMBLY, pick(lang, "Assembly order", "Порядок сборки планетарного механизма"))
    x0b, y0b, x1b, y1b = fld.inner
    cw = (x1b - x0b) / n
    for j, (st, ch) in enumerate(zip(d.stages, r.checks.stages)):
        rk, rc, rc2, rn = st.z_sun / 2, st.z_planet / 2, st.zc2 / 2, st.z_ring / 2
        rC = rk + rc
        big = max(rn, rC + max(rc, rc2))
        f = min((cw - 10.0) / (2 * big + 4), (y1b - y0b - 50.0) / (2 * big + 4))
        c = np.array([x0b + cw * (j + 0.5), y0b + 20.0 + (y1b - y0b - 30.0) / 2])
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
                sh.circle(pc, rc2 * f, "Тонкие", "DASHED")
            sh.dot(pc, 0.6)
            q = pc + (rc * f * 0.45) * np.array([math.cos(th - math.pi / 2), math.sin(th - math.pi / 2)])
            sh.text(q[0], q[1], str(i + 1), H_LABEL, align="center", valign="middle")
        _cross_small(sh, c)
        if k >= 2:
            ra = 0.55 * rk * f
            sh.dim_arc(c, ra, 90.0, 90.0 + 360.0 / k, f"2β = {num(360.0 / k, lang, sig=4)}°", H_SMALL)
        suf = pick(lang, f"Stage {j + 1}: ", f"Ступень {j + 1}: ") if n > 1 else ""
        lines = [suf + f"K = {k};  c = {ch.assembly_c};  2β = 360°/{k} = {num(360.0 / k, lang, sig=4)}°",
                 f"φ_{{H1}} = c·2β = {num(ch.carrier_turn_deg, lang, sig=5)}°"
                 + (f" = {int(ch.carrier_turn_deg // 360)}·360° + {num(ch.carrier_turn_deg % 360, lang, sig=4)}°"
                    if ch.carrier_turn_deg >= 360 else "")]
        y = c[1] - big * f - 7.0
        for t in lines:
            sh.text(c[0], y, t, H_SMALL, align="center", width=cw - 4.0)
            y -= 4.6
    order = pick(lang, "Fit planet 1; turn the carrier by φ_H1 = c·2β; fit the next planet at the same place; repeat.",
                 "Установить сателлит 1; повернуть водило на φ_{H1} = c·2β; установить следующий сателлит на то же место; повторить.")
    sh.text((x0b + x1b) / 2, y1b - 1.0, order, H_SMALL, align="center", valign="top", width=x1b - x0b - 4.0, max_lines=3)
    return fld


def _cross_small(sh, c, s=3.0):
    sh.line((c[0] - s, c[1]), (c[0] + s, c[1]), "Тонкие")
    sh.line((c[0], c[1] - s), (c[0], c[1] + s), "Тонкие")


# ----------------------------------------------------------------------------------------------
# the spur mesh


MESH_ROOM = (BOX_MESH[1] + 30.0, BOX_MESH[3] - 28.0)  # y band of the drawing (captions below, heading above)


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


def mesh_scale(g) -> tuple[str, float]:
    """The mesh field's ГОСТ 2.302 scale, at most 1:1: the largest at which the smaller wheel's
    centre and the mesh zone with its dimensions fit; the larger wheel's centre may lie beyond
    the field (its circles are then drawn as arcs and a_w as a dimension broken at the edge)."""
    lo, hi = MESH_ROOM
    room = hi - lo - 12.0
    choices = [(lab, f) for lab, f in GOST_SCALES if 0.1 <= f <= 1.0]
    r_small = min(g.d1_mm, g.d2_mm) / 2
    ok = [c for c in choices if centre_distance(g) * c[1] <= room or r_small * c[1] + 14.0 + 150.0 <= room]
    return max(ok, key=lambda c: c[1], default=choices[0])


def mesh_origin(g, f: float) -> tuple[float, float]:
    """Sheet position of O1 (the field's origin): both centres centred in the band when they fit,
    else the smaller wheel's centre 10 mm inside the band's edge."""
    lo, hi = MESH_ROOM
    x = (BOX_MESH[0] + BOX_MESH[2]) / 2
    aw = centre_distance(g)
    if aw * f <= hi - lo - 12.0:
        return x, (lo + hi) / 2 - f * aw / 2
    if g.d2_mm <= g.d1_mm:  # O2 (top) shown, O1 below the field
        return x, hi - 10.0 - f * aw
    return x, lo + 10.0


def _circle_labels(sh, c, f, theta0, clip, items):
    """Names of concentric circles written along them, upright, each just outside its circle,
    spread along the arc from ``theta0`` [deg] so that neighbours never overlap; a name whose
    place falls outside the field is left out (its circle is named in the captions)."""
    th = math.radians(theta0)
    for d, txt in items:
        if d is None:
            continue
        r = d / 2 * f
        w = sh.text_width(txt, H_SMALL)
        up = np.array([math.cos(th), math.sin(th)])
        rot = math.degrees(th) - 90.0
        out = True
        if math.sin(th) < 0:  # lower half: read left to right, the letters inside the circle
            rot += 180.0
            out = False
        q = c + (r + (0.8 if out else -0.8 - H_SMALL)) * up
        if clip[0] + 3 < q[0] < clip[2] - 3 and clip[1] + 3 < q[1] < clip[3] - 3:
            sh.text(q[0], q[1], txt, H_SMALL, align="center", rot=rot)
        th += (w + 3.0) / max(r, 1.0)


def dim_tooth(g, f, c1, clip, sx) -> int:
    """The tooth of gear 1 that carries the p, s, e dimensions: ≥ 40° from the pole, its
    dimension arcs inside the field and clear of gear 2's tip circle; the side away from N2 first."""
    t1 = 2 * math.pi / g.z1
    r_in, r_out = g.da1_mm / 2 * f + 4.0, g.da1_mm / 2 * f + 22.0
    c2 = c1 + np.array([0.0, centre_distance(g) * f])
    ra2 = g.da2_mm / 2 * f + 3.0
    for clear in (True, False):
        for deg_min in (50.0, 40.0, 60.0, 70.0, 30.0):
            for side in (-sx, sx):
                j = int(math.ceil(math.radians(deg_min) / t1)) * int(side)
                ok = True
                for da in np.linspace(-0.5 * t1, 1.5 * t1, 9):
                    a = math.pi / 2 + j * t1 + da
                    e = np.array([math.cos(a), math.sin(a)])
                    for q in (c1 + r_in * e, c1 + r_out * e):
                        ok &= clip[0] + 3 < q[0] < clip[2] - 3 and clip[1] + 3 < q[1] < clip[3] - 3
                    q = c1 + (r_in + 11.0) * e  # the labels s and e
                    ok &= (not clear) or float(np.hypot(*(q - c2))) > ra2
                if ok:
                    return j
    return int(math.ceil(math.radians(50.0) / t1)) * int(-sx)


def _mesh_field(sh: Sheet, r, lang: str):
    g = r.spur
    name, f = mesh_scale(g)
    x0b, y0b, x1b, y1b = BOX_MESH
    o1, o2, p, u, n1, at = _mesh_geometry(g, r.directions.motor)
    sx = 1.0 if u[0] > 0 else -1.0
    # O1 low in the field, the pole in the middle band
    origin = mesh_origin(g, f)
    fld = sh.add_field("mesh", BOX_MESH, pick(lang, "Spur gear mesh synthesis", "Геометрический синтез зубчатого зацепления"),
                       origin=origin, scale=f, scale_label=name, scale_text=f"{pick(lang, 'M', 'М')} {pick(lang, name.replace(',', '.'), name)}")
    clip = (x0b + 1.0, y0b + 24.0, x1b - 1.0, fld.inner[3])
    fld.box = clip
    m = g.m_mm
    aw = centre_distance(g)
    ts = tooth_sizes(g)
    rot1, rot2 = math.pi / 2, -math.pi / 2 + math.pi / g.z2
    # circles d (dash-dot), d_b, d_a, d_f (thin), d_w of a shifted pair (dash-dot), centres, the line of centres
    for j, (centre, d, db, da, df) in enumerate(((o1, g.d1_mm, g.db1_mm, g.da1_mm, g.df1_mm),
                                                  (o2, g.d2_mm, g.db2_mm, g.da2_mm, g.df2_mm))):
        fld.circle(centre, d / 2, "Осевые")
        fld.circle(centre, db / 2, "Тонкие")
        fld.circle(centre, da / 2, "Тонкие")
        fld.circle(centre, df / 2, "Тонкие")
        if g.shifted and abs(g.pair.dw_mm[j] - d) * f > 0.3:
            fld.circle(centre, g.pair.dw_mm[j] / 2, "Осевые")
    fld.line((0, -0.05 * aw), (0, aw * 1.05), "Осевые")
    for c, nm in ((o1, "O_1"), (o2, "O_2")):
        q = fld.p(*c)
        if clip[1] < q[1] < clip[3]:
            _cross_small(sh, q, 4.0)
            sh.dot(q, 0.7)
            sh.text(q[0] + 2.0, q[1] + 1.5, nm, H_LABEL)
    # teeth: 4 on either side of the line of centres
    tooth1 = thin_out(tooth_outline(g.z1, m, **_shift_kw(g, 1)), 0.6 / f)  # a vertex every 0.6 mm of paper
    tooth2 = thin_out(tooth_outline(g.z2, m, **_shift_kw(g, 2)), 0.6 / f)
    active = []
    drawn = []  # the teeth on the sheet [mm]: the point labels keep clear of them
    for z, tooth, centre, rot, rmin_s, ra in ((g.z1, tooth1, o1, rot1, g.p1_mm, g.da1_mm / 2),
                                              (g.z2, tooth2, o2, rot2, g.p2_mm, g.da2_mm / 2)):
        tau = 2 * math.pi / z
        r_start = float(np.hypot(*(at(rmin_s) - centre)))
        extra = [dim_tooth(g, f, np.array(fld.p(*o1)), clip, sx)] if z == g.z1 else [int(round(3 * sx))]
        for j in sorted(set(range(-4, 5)) | set(extra)):
            a = rot + j * tau
            ca, sa = math.cos(a), math.sin(a)
            pts = tooth @ np.array([[ca, sa], [-sa, ca]]) + centre
            fld.poly(pts, "Основные")
            drawn.append(np.asarray(fld.origin) + f * pts)
            # the working flank's active part: radii r(P1 or P2) … r_a, on the side that works
            rad = np.hypot(*(pts - centre).T)
            ang = np.arctan2(pts[:, 1] - centre[1], pts[:, 0] - centre[0]) - a
            ang = (ang + math.pi) % (2 * math.pi) - math.pi
            sel = (rad >= r_start) & (rad <= ra - 0.02 * m) & (sx * ang < 0) & (np.abs(ang) < tau / 2)
            if sel.sum() >= 2 and abs(j) <= 2:
                seg = pts[sel]
                order = np.argsort(np.hypot(*(seg - centre).T))
                seg = seg[order]
                # the second line: the same flank turned 0.8 mm (paper) into the tooth
                dth = -np.sign(ang[sel][order]) * 0.8 / f / np.hypot(*(seg - centre).T)
                rel = seg - centre
                c2, s2 = np.cos(dth), np.sin(dth)
                inner = np.column_stack([c2 * rel[:, 0] - s2 * rel[:, 1], s2 * rel[:, 0] + c2 * rel[:, 1]]) + centre
                fld.poly(inner, "Основные")
                active.append(seg)
    # line of action N1N2 (extended), points, zones
    ext = 0.15 * g.n1n2_mm
    fld.line(at(-ext), at(g.n1n2_mm + ext), "Тонкие")
    fld.line(o1, n1, "Тонкие")
    n2 = at(g.n1n2_mm)
    fld.line(o2, n2, "Тонкие")
    pts_on = {"N_1": 0.0, "P_1": g.p1_mm, "U_2": g.u2_mm, "P": g.pole_mm, "U_1": g.u1_mm, "P_2": g.p2_mm, "N_2": g.n1n2_mm}
    nrm = np.array([-u[1], u[0]])  # left of the line
    # each name where it is farthest from the teeth, the zone numbers and the names already placed
    # (alternating sides of the line of action by default)
    busy = np.vstack(drawn + [np.array([fld.p(*((at(s0) + at(s1)) / 2 - nrm * 3.5 / f))
                                         for s0, s1 in ((g.p1_mm, g.u2_mm), (g.u2_mm, g.u1_mm), (g.u1_mm, g.p2_mm))])])
    uu = np.asarray(u)
    for k_, (nm, s) in enumerate(pts_on.items()):
        q = np.array(fld.p(*at(s)))
        sh.dot(q, 0.6)
        side = 1.0 if k_ % 2 == 0 else -1.0
        best, best_score = None, -1.0
        for sd in (side, -side):
            for dist in (4.0, 6.0):
                for t in (0.0, 2.5, -2.5):
                    c = q + nrm * sd * dist + uu * t
                    score = float(np.min(np.hypot(*(busy - c).T)))
                    if score > best_score + 0.3:
                        best, best_score = c, score
        sh.text(best[0], best[1], nm, H_LABEL, align="center", valign="middle")
        busy = np.vstack([busy, best[None, :], q[None, :]])
    # zones: a band beside the line (double-pair hatched ticks, single-pair plain)
    band = -nrm * 7.0 / f
    for s0, s1, lab in ((g.p1_mm, g.u2_mm, "2"), (g.u2_mm, g.u1_mm, "1"), (g.u1_mm, g.p2_mm, "2")):
        a0, a1 = at(s0) + band, at(s1) + band
        fld.line(a0, a1, "Тонкие")
        for s in (s0, s1):
            fld.line(at(s) + band * 0.6, at(s) + band * 1.4, "Тонкие")
        q = np.array(fld.p(*((a0 + a1) / 2 + band * 0.5)))
        sh.text(q[0], q[1], lab, H_SMALL, align="center", valign="middle")
    # α_w at P between the tangent to the pitch circles and the line of action
    pq = np.array(fld.p(*p))
    # on the P1 side, below the tangent (the P2 side carries the zone labels)
    rr = 0.65 * (g.pole_mm - g.p1_mm) * f
    sh.line(pq + np.array([sx * 5.0, 0]), pq - np.array([sx * (rr + 6.0), 0]), "Тонкие")
    a0, a1 = (180.0, 180.0 + g.alpha_w_deg) if sx > 0 else (360.0 - g.alpha_w_deg, 360.0)
    sh.dim_arc(pq, rr, a0, a1, "", H_SMALL)
    # its value on a leader into gear 1's body, below the teeth (the mesh zone is full of lines)
    am = math.radians((a0 + a1) / 2)
    q_arc = pq + rr * np.array([math.cos(am), math.sin(am)])
    y_lab = pq[1] - (g.d1_mm / 2 - g.df1_mm / 2 + m) * f - 6.0
    q_lab = np.array([pq[0] - sx * (rr + 18.0), y_lab])
    sh.line(q_arc, q_lab, "Размеры")
    txt = f"α_{{w}} = {num(g.alpha_w_deg, lang, sig=4)}°"
    w_lab = sh.text_width(txt, H_LABEL)
    sh.line(q_lab, q_lab - np.array([sx * w_lab, 0.0]), "Размеры")
    sh.text(q_lab[0] - sx * w_lab / 2, q_lab[1] + 0.8, txt, H_LABEL, align="center")
    # the circles named along their arcs: gear 1 on the side away from its dimensioned teeth
    _circle_labels(sh, np.array(fld.p(*o1)), f, 90.0 + sx * 58.0, clip, [
        (g.da1_mm, "d_{a1}"), (g.pair.dw_mm[0] if g.shifted else None, "d_{w1}"), (g.d1_mm, "d_{1}"),
        (g.db1_mm, "d_{b1}"), (g.df1_mm, "d_{f1}")])
    _circle_labels(sh, np.array(fld.p(*o2)), f, 270.0 - sx * 62.0, clip, [
        (g.da2_mm, "d_{a2}"), (g.pair.dw_mm[1] if g.shifted else None, "d_{w2}"), (g.d2_mm, "d_{2}"),
        (g.db2_mm, "d_{b2}"), (g.df2_mm, "d_{f2}")])
    # arcs φ_α1, φ_α2 (the gears' turns while a pair of teeth is in mesh), about the centres
    for centre, phi, rad, nm, base in ((o1, g.phi_alpha1_deg, 0.55 * g.df1_mm / 2, "φ_{α1}", 90.0),
                                       (o2, g.phi_alpha2_deg, 0.55 * g.df2_mm / 2, "φ_{α2}", 270.0)):
        q = np.array(fld.p(*centre))
        ext = 0.0
        if not clip[1] < q[1] < clip[3]:  # the centre is beyond the field: the arc 30 mm inside it
            edge = clip[1] if base == 90 else clip[3]
            rad = (abs(edge - q[1]) + 30.0) / f
            ext = (rad * f) - 25.0
            if rad > 0.9 * (g.df1_mm if base == 90 else g.df2_mm) / 2:
                continue  # no room below the root circle
        if clip[1] + 10 < q[1] + (rad * f if base == 90 else -rad * f) < clip[3] - 10:
            sh.dim_arc(q, rad * f, base - phi / 2, base + phi / 2, f"{nm} = {num(phi, lang, sig=4)}°", H_SMALL,
                       ext_from=ext)
    # dimensions on gear 1: p, s, e on the pitch circle of a tooth left of the pole; h, h_a, h_f
    r1 = g.d1_mm / 2
    t1 = 2 * math.pi / g.z1
    half_s = ts["s"][0] / 2 / r1
    c1 = np.array(fld.p(*o1))
    rdim = g.da1_mm / 2 * f + 5.0
    jd = dim_tooth(g, f, c1, clip, sx)
    a_t = rot1 + jd * t1
    deg = math.degrees
    sh.dim_arc(c1, rdim, deg(a_t - half_s), deg(a_t + half_s), "s", H_SMALL, ext_from=r1 * f)
    # the space e on the side of the tooth farther from gear 2 (its label clear of gear 2's teeth)
    e_ang = ts["e"][0] / r1
    c2s = np.array(fld.p(*o2))

    def far(a):
        return float(np.hypot(*(c1 + (rdim + 8.0) * np.array([math.cos(a), math.sin(a)]) - c2s)))

    e0 = a_t + half_s if far(a_t + half_s + e_ang / 2) >= far(a_t - half_s - e_ang / 2) else a_t - half_s - e_ang
    sh.dim_arc(c1, rdim + 7.0, deg(e0), deg(e0 + e_ang), "e", H_SMALL, ext_from=r1 * f)
    p0 = min(e0, a_t - half_s)
    sh.dim_arc(c1, rdim + 14.0, deg(p0), deg(p0 + g.p_mm / r1), "p", H_SMALL, ext_from=r1 * f)
    # radial dimensions h_f, h_a, h (gear 2, a tooth away from the pole) and c
    r2 = g.d2_mm / 2
    t2 = 2 * math.pi / g.z2
    a2 = rot2 + 3 * t2 * sx
    e2 = np.array([math.cos(a2), math.sin(a2)])
    nn = np.array([-e2[1], e2[0]]) * sx
    c2c = np.array(fld.p(*o2))
    for (ra_, rb_, txt, off) in ((g.df2_mm / 2, r2, "h_{f}", 8.0), (r2, g.da2_mm / 2, "h_{a}", 8.0),
                                  (g.df2_mm / 2, g.da2_mm / 2, "h", 16.0)):
        sh.dim_linear(c2c + e2 * ra_ * f, c2c + e2 * rb_ * f, nn * off, txt, H_SMALL)
    # x·m of a shifted gear: from its pitch circle to the tool rack's pitch line (a thin arc at r + x·m)
    for j, (cc, rr_, ang, sg) in enumerate(((c1, r1, a_t - 1.5 * t1 * (1 if jd * sx < 0 else -1), 1.0),
                                             (c2c, r2, a2 - 1.5 * t2 * sx, -1.0))):
        xm = ts["xm"][j]
        if abs(xm) * f < 0.2:
            continue
        ev = np.array([math.cos(ang), math.sin(ang)])
        a_deg = math.degrees(ang)
        sh.arc(cc, (rr_ + xm) * f, a_deg - 4.0, a_deg + 4.0, "Тонкие", "DASHED")
        sh.dim_linear(cc + ev * rr_ * f, cc + ev * (rr_ + xm) * f, np.array([-ev[1], ev[0]]) * 6.0 * sg,
                      f"x_{{{j + 1}}}m", H_SMALL)
    # c: clearance between gear 1's tip and gear 2's root on the line of centres
    q1 = np.array(fld.p(0.0, g.da1_mm / 2))
    q2 = np.array(fld.p(0.0, aw - g.df2_mm / 2))
    sh.line(q2, q2 + np.array([-sx * 22.0, 8.0]), "Размеры")
    sh.text(q2[0] - sx * 22.0, q2[1] + 9.0, f"c = {num(g.c_mm, lang, sig=3)}", H_SMALL, align="center")
    sh.dot(q1, 0.4)
    # a_w: along the line of centres, shifted to the side
    xa = (x1b - 14.0) if sx < 0 else (x0b + 14.0)
    pa, pb = np.array(fld.p(*o1)), np.array(fld.p(*o2))
    if clip[1] < pa[1] and pb[1] < clip[3]:
        sh.dim_linear(pa, pb, (xa - pa[0], 0.0), f"a_{{w}} = {num(aw, lang, sig=6)}", H_LABEL)
    else:  # one centre beyond the field: the dimension line broken at the field's edge
        seen, other = (pa, pb) if clip[1] < pa[1] < clip[3] else (pb, pa)
        end_y = clip[1] + 2.0 if other[1] < seen[1] else clip[3] - 2.0
        sh.line(seen + (np.sign(xa - seen[0]) * 2.0, 0.0), (xa + np.sign(xa - seen[0]) * 2.0, seen[1]), "Размеры")
        sh.line((xa, seen[1]), (xa, end_y), "Размеры")
        sh.arrow((xa, seen[1]), (0.0, np.sign(seen[1] - end_y)), "Размеры", 3.0, 0.9)
        ym = seen[1] + np.sign(end_y - seen[1]) * min(60.0, abs(end_y - seen[1]) / 2)
        sh.text(xa - 1.0, ym, f"a_{{w}} = {num(aw, lang, sig=6)}", H_LABEL, align="center", rot=90.0)
    # captions
    mm = pick(lang, "mm", "мм")

    def g3(v):
        return num(v, lang, sig=6)

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
        + pick(lang, "zones: 2 — two pairs, 1 — one pair; active profiles — double line",
               "зоны: 2 — двухпарное, 1 — однопарное зацепление; активные профили — двойная линия"),
    ]
    sh.caption(x0b, x1b, y0b + 3.0, lines, H_SMALL, 4.8)
    return fld


def _results(sh: Sheet, r, lang: str):
    d, g = r.planetary, r.spur
    teeth = " + ".join("/".join(map(str, s.teeth)) for s in d.stages)
    rows = [
        (pick(lang, "Motor speed n_{d}", "Частота двигателя n_{д}"), f"{r.motor_rpm} " + pick(lang, "rpm", "об/мин")),
        (pick(lang, "Reducer scheme; teeth", "Схема редуктора; числа зубьев"), f"{d.scheme}; {teeth}"),
        (pick(lang, "Planets k", "Число сателлитов k"), str(d.planets)),
        (pick(lang, "i_{pl}: required / obtained", "i_{пл}: требуемое / получено"),
         f"{_n(r.i_planetary, lang, 3)} / {_n(d.ratio, lang, 3)} ({num(d.ratio_error_pct, lang, decimals=2)} %)"),
        (pick(lang, "Spur pair z_{1}/z_{2}, m", "Передача z_{1}/z_{2}, m"), f"{g.z1}/{g.z2}, {_g6(g.m_mm, lang)} " + pick(lang, "mm", "мм")),
        (pick(lang, "i_{12}: required / obtained", "i_{12}: требуемое / получено"), f"{_n(r.i_spur, lang, 3)} / {_n(g.i_actual, lang, 3)}"),
    ]
    if g.shifted:
        pr = g.pair
        rule = {"given": pick(lang, "given", "заданы"), "auto": pick(lang, "auto", "авто"),
                "aw": pick(lang, "from a_{w}", "по a_{w}")}.get(g.shift_rule, g.shift_rule)
        rows += [
            (pick(lang, "Shifts x_{1}; x_{2}", "Смещения x_{1}; x_{2}"),
             f"{num(g.x1, lang, sig=4)}; {num(g.x2, lang, sig=4)} ({rule})"),
            (pick(lang, "a_{w}; α_{w}", "a_{w}; α_{w}"), f"{_g6(aw_of(g), lang)}; {num(g.alpha_w_deg, lang, sig=5)}°"),
            ("d_{w1}; d_{w2}", f"{_n(pr.dw_mm[0], lang)}; {_n(pr.dw_mm[1], lang)}"),
        ]
    rows += [
        ("d_{1}; d_{2}", f"{_g6(g.d1_mm, lang)}; {_g6(g.d2_mm, lang)}"),
        ("d_{a1}; d_{a2}", f"{_n(g.da1_mm, lang)}; {_n(g.da2_mm, lang)}" if g.shifted else f"{_g6(g.da1_mm, lang)}; {_g6(g.da2_mm, lang)}"),
        ("d_{f1}; d_{f2}", f"{_n(g.df1_mm, lang)}; {_n(g.df2_mm, lang)}" if g.shifted else f"{_g6(g.df1_mm, lang)}; {_g6(g.df2_mm, lang)}"),
        ("d_{b1}; d_{b2}", f"{_n(g.db1_mm, lang)}; {_n(g.db2_mm, lang)}"),
        (pick(lang, "a_{w}; contact ratio ε_{α}", "a_{w}; коэффициент перекрытия ε_{α}") if not g.shifted
         else pick(lang, "a; contact ratio ε_{α}", "a; коэффициент перекрытия ε_{α}"),
         f"{_g6(g.a_mm, lang)}; {_n(g.eps_alpha, lang, 3)}"),
    ]
    table(sh, BOX_TABLE, pick(lang, "Gear data", "Параметры зубчатых механизмов"), rows, col1=0.55, h=H_SMALL)


def sheet4(result, variant: int, lang: str, title) -> Sheet:
    """Build sheet 4 for a GearsResult (no file written)."""
    sh = Sheet(lang)
    sh.frame()
    scheme = _scheme_field(sh, result, lang)
    _linear_field(sh, result, lang, scheme)
    _angular_field(sh, result, lang)
    _assembly_field(sh, result, lang)
    mesh = _mesh_field(sh, result, lang)
    _results(sh, result, lang)
    sh.title_block(title, name=pick(lang, "Gear mechanisms: synthesis and analysis", "Синтез и анализ зубчатых механизмов"),
                   designation=title.designation_for(4, variant), scale=mesh.scale_label)
    return sh
