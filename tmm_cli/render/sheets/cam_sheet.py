"""Sheet 3 «Синтез кулачкового механизма» (§1.2–§1.4, the book's sample sheet).

Four fields with the book's headings plus a table of results, drawn from a
:class:`~tmm_cli.cam.design.CamResult`: the motion laws at the scales (1.9)–(1.13), the centre
zone (Fig. 1.3/1.4), the profile by inversion (Fig. 1.6/1.7) at a standard scale, and ν(φ).
Nothing is computed a second time: every curve is an array of the result placed on the sheet
(scaling, shifting, picking the table positions out of the dense arrays).
"""

from __future__ import annotations

import math

import numpy as np

from ...i18n.lang import pick
from ...i18n.numbers import num
from .paper import Sheet, fit_scale, gost_scale

# field boxes (x0, y0, x1, y1) on the A1 sheet [mm]; the frame is 20…836 × 5…589
BOX_MOTION = (22.0, 228.0, 300.0, 587.0)
BOX_ZONE = (302.0, 7.0, 518.0, 587.0)
BOX_PROFILE = (520.0, 222.0, 834.0, 587.0)
BOX_PRESSURE = (22.0, 7.0, 300.0, 226.0)
BOX_TABLE = (520.0, 64.0, 834.0, 220.0)

H_LABEL = 3.5
H_SMALL = 2.5


def _n(x, lang, d=2):
    return num(x, lang, decimals=d)


def _g(x, lang, sig=4):
    return num(x, lang, sig=sig)


# ----------------------------------------------------------------------------------------------
# field 1: motion laws


def _axis(sh: Sheet, x0, y0, length, up, down, xlabel, ylabel):
    """Abscissa from x0 with an arrow, ordinate from y0 − down to y0 + up with an arrow."""
    sh.line((x0, y0), (x0 + length + 4, y0), "Основные")
    sh.arrow((x0 + length + 6, y0), (1, 0), "Основные", 3.5, 1.2)
    sh.line((x0, y0 - down), (x0, y0 + up + 6), "Основные")
    sh.arrow((x0, y0 + up + 8), (0, 1), "Основные", 3.5, 1.2)
    sh.text(x0 + length + 3, y0 - 1.5, xlabel, H_LABEL, valign="top")
    sh.text(x0 - 1.5, y0 + up + 8, ylabel, H_LABEL, align="right", valign="top")


def _curve(sh: Sheet, x, y, jump_break: bool = False):
    # every second point of the 0.25° grid: 0.5° is at most 0.6 mm of abscissa (b = 240 mm)
    x = np.asarray(x, float)
    y = np.asarray(y, float)
    keep = np.zeros(len(x), dtype=bool)
    keep[::2] = True
    keep[-1] = True
    if jump_break:  # keep both sides of a jump of the acceleration
        big = np.nonzero(np.abs(np.diff(y)) > 0.2 * (np.abs(y).max() + 1e-12))[0]
        keep[big] = keep[big + 1] = True
    x, y = x[keep], y[keep]
    if jump_break:
        big = np.abs(np.diff(y)) > 0.2 * (np.abs(y).max() + 1e-12)
        cuts = np.nonzero(big)[0] + 1
        start = 0
        for c in list(cuts) + [len(x)]:
            if c - start >= 2:
                sh.poly(np.column_stack([x[start:c], y[start:c]]), "Основные")
            if c < len(x):  # the jump itself, a thin vertical line
                sh.line((x[c - 1], y[c - 1]), (x[c], y[c]), "Тонкие")
            start = c
        return
    sh.poly(np.column_stack([x, y]), "Основные")


def _motion_field(sh: Sheet, r, lang: str) -> None:
    v, m = r.variant, r.motion
    sc = m.scales
    f = sh.add_field("motion", BOX_MOTION, pick(lang, "Follower motion laws", "Законы движения толкателя"))
    x0b, y0b, x1b, y1b = f.inner
    xo = x0b + 26.0  # ordinate axes (the poles P_V, P_a at H left of them when H fits)
    phw = v.phi_working_deg
    keep = np.degrees(m.phi) <= phw + 1e-9
    xs = xo + np.degrees(m.phi[keep]) / sc.k_phi_deg_mm
    rows = [row for row in m.table if row.phi_deg <= phw + 1e-9]
    xr = [xo + row.phi_deg / sc.k_phi_deg_mm for row in rows]
    rocker = v.is_rocker
    s_arr = m.s[keep] / sc.k_s
    v_arr = m.v[keep] / sc.k_v
    a_arr = m.a[keep] / sc.k_a
    rv = [row.v / sc.k_v for row in rows]
    ra = [row.a / sc.k_a for row in rows]
    rs = [row.s / sc.k_s for row in rows]
    up_v, dn_v = max(float(v_arr.max()), 0.0), max(-float(v_arr.min()), 0.0)
    up_a, dn_a = max(float(a_arr.max()), 0.0), max(-float(a_arr.min()), 0.0)
    # vertical layout: S on top, then V, then a; gaps for labels
    gap = 13.0
    total = sc.y_s_max_mm + up_v + dn_v + up_a + dn_a + 3 * gap + 8.0
    room = y1b - y0b - 26.0
    squeeze = min(1.0, room / total)  # never at this layout (80 + 2·60 + 2·60 + gaps fit)
    ys0 = y1b - gap - sc.y_s_max_mm * squeeze
    yv0 = ys0 - gap - (up_v + 0.0) * squeeze - 6.0
    ya0 = yv0 - dn_v * squeeze - gap - up_a * squeeze - 6.0
    b = sc.b_mm
    names = (("S", "V", "a") if not rocker else ("γ", "ω", "ε"))
    for (y0, arr, pts, up, dn, nm, jb) in ((ys0, s_arr, rs, sc.y_s_max_mm, 0.0, names[0], False),
                                            (yv0, v_arr, rv, up_v, dn_v, names[1], False),
                                            (ya0, a_arr, ra, up_a, dn_a, names[2], True)):
        _axis(sh, xo, y0, b, up * squeeze, dn * squeeze, "φ, t", nm)
        _curve(sh, xs, y0 + arr * squeeze, jump_break=jb)
        for x, yy in zip(xr, pts):
            if abs(yy) > 0.3:
                sh.line((x, y0), (x, y0 + yy * squeeze), "Тонкие")
    # position numbers under the S axis and the t axis under the last one
    for row, x in zip(rows, xr):
        sh.text(x, ys0 - 1.2, str(row.index), H_SMALL, align="center", valign="top")
    # poles of graphical differentiation: P_V, P_a at H_V, H_a left of the origin
    for y0, H, nm in ((yv0, sc.h_v_mm, "V"), (ya0, sc.h_a_mm, "a")):
        if H > xo - x0b - 3.0:  # the pole would leave the field: H is printed below instead
            continue
        px = xo - H
        sh.dot((px, y0), 0.8)
        sh.text(px, y0 + 1.5, f"P_{{{nm if not rocker else ('ω' if nm == 'V' else 'ε')}}}", H_SMALL, align="center")
    # scales
    mm = pick(lang, "mm", "мм")
    if rocker:
        s_unit, v_unit, a_unit = (pick(lang, "rad/mm", "рад/мм"), pick(lang, "rad/(s·mm)", "рад/(с·мм)"),
                                  pick(lang, "rad/(s²·mm)", "рад/(с²·мм)"))
        kn = ("k_{γ}", "k_{ω}", "k_{ε}")
    else:
        s_unit, v_unit, a_unit = (pick(lang, "m/mm", "м/мм"), pick(lang, "m/(s·mm)", "м/(с·мм)"),
                                  pick(lang, "m/(s²·mm)", "м/(с²·мм)"))
        kn = ("k_{S}", "k_{V}", "k_{a}")
    lines = [
        f"k_{{φ}} = {_g(sc.k_phi_deg_mm, lang)} °/{mm};  k_{{t}} = {_g(sc.k_t_s_mm, lang)} "
        + pick(lang, "s/mm", "с/мм") + f";  b = {num(sc.b_mm, lang, sig=6)} {mm}",
        f"{kn[0]} = {_g(sc.k_s, lang)} {s_unit};  {kn[1]} = {_g(sc.k_v, lang)} {v_unit};  {kn[2]} = {_g(sc.k_a, lang)} {a_unit}",
        f"H_{{V}} = {num(sc.h_v_mm, lang, sig=6)} {mm};  H_{{a}} = {num(sc.h_a_mm, lang, sig=6)} {mm};  "
        + pick(lang, f"law {v.law}", f"закон {v.law}") + f";  {pick(lang, 'n_{c}', 'n_{к}')} = {num(abs(v.n_cam_rpm), lang, sig=6)} "
        + pick(lang, "rpm", "об/мин"),
    ]
    if rocker:
        lines.append(f"k_{{SB}} = k_{{γ}}·l_{{BC}} = {_g(sc.k_s_b, lang)} {pick(lang, 'm/mm', 'м/мм')}"
                     f";  k_{{γ,°}} = {_g(sc.k_gamma_deg_mm, lang)} °/{mm}")
    y = y0b + 2.0 + 4.6 * (len(lines) - 1)
    for t in lines:
        sh.text(x0b + 2.0, y, t, H_SMALL, width=x1b - x0b - 4.0)
        y -= 4.6


# ----------------------------------------------------------------------------------------------
# field 2: the centre zone


def _table_index(phis: np.ndarray, phi_deg: float) -> int:
    return int(np.argmin(np.abs(np.degrees(phis) - phi_deg)))


def _zone_field(sh: Sheet, r, lang: str):
    v, z = r.variant, r.sizing
    zn = z.zone
    k = 1000.0  # m -> real mm
    B, D = zn.b * k, zn.d * k
    O = np.array(z.centre) * k
    BV = np.array(z.book_centre) * k
    piv = None if z.pivot is None else np.array(z.pivot) * k
    pts = [B, D, O[None], BV[None], np.zeros((1, 2))] + ([piv[None]] if piv is not None else [])
    allp = np.concatenate(pts)
    lo, hi = allp.min(axis=0), allp.max(axis=0)
    lo = np.minimum(lo, O - np.array([0.0, 0.25 * (hi - lo).max()]))  # the zone below O
    x0b, y0b, x1b, y1b = BOX_ZONE
    room = (x1b - x0b - 12.0, y1b - y0b - 40.0 - 30.0)
    name, fac = fit_scale(tuple((hi - lo) * 1.04), room)
    mid = (lo + hi) / 2
    cx = (x0b + x1b) / 2
    cy = (y0b + 30.0 + y1b - 40.0) / 2
    origin = (cx - fac * mid[0], cy - fac * mid[1])
    f = sh.add_field("zone", BOX_ZONE, pick(lang, "Minimum cam radius", "Определение минимального радиуса кулачка"),
                     origin=origin, scale=fac, scale_label=name, scale_text=f"{pick(lang, 'M', 'М')} {pick(lang, name.replace(',', '.'), name)}")
    clip = (x0b + 1, y0b + 28.0, x1b - 1, f.inner[3])
    # the construction's own window: the zone and the lines end a little beyond it
    pad = 0.06 * float((hi - lo).max())
    w0, w1 = f.p(*(lo - pad)), f.p(*(hi + pad))
    clip = (max(clip[0], w0[0]), max(clip[1], w0[1]), min(clip[2], w1[0]), min(clip[3], w1[1]))
    f.box = clip
    # feasible zone: outline (thin) and a light hatch of parallel lines
    poly = zn.polygon * k
    f.poly(poly, "Тонкие", closed=True)
    _hatch(f, poly, spacing=4.0 / fac)
    rise = zn.phase == 0
    ret = zn.phase == 2
    # B path and D-curves
    if z.rocker:
        f.poly(B[rise], "Тонкие")
    else:
        f.line((0.0, 0.0), (0.0, B[:, 1].max() * 1.05), "Осевые")
    f.poly(D[rise], "Основные")
    f.poly(D[ret], "Основные" if z.closure == "form" else "Тонкие", linetype=None if z.closure == "form" else "DASHED")
    # B_i D_i at the table positions, numbered
    nums = []
    for row in r.motion.table:
        if row.phase not in ("rise", "return"):
            continue
        mask = rise if row.phase == "rise" else ret
        idx = np.nonzero(mask)[0]
        i = idx[_table_index(zn.phi[idx], row.phi_deg)]
        f.line(B[i], D[i], "Тонкие")
        sh.dot(f.p(*D[i]), 0.45)
        nums.append((row.index, D[i], B[i]))
    seen = []
    for idx_, d, b in nums:
        q = np.array(f.p(*d))
        dirv = d - b
        nrm = np.hypot(*dirv)
        off = dirv / nrm * 2.5 if nrm > 1e-9 else np.array([2.5, 0.0])
        pos = q + off
        if all(np.hypot(*(pos - s)) > 3.0 for s in seen):
            sh.text(pos[0], pos[1], str(idx_), H_SMALL, align="center", valign="middle")
            seen.append(pos)
    # the book's bounding lines A and B/C
    span = float((hi - lo).max()) * 3
    for L in zn.lines:
        p0 = np.array(L.point) * k
        d = np.array(L.direction)
        f.line(p0 - span * d, p0 + span * d, "Тонкие")
        # label near where it is inside the clip box, towards the top
        for t in np.linspace(span, -span, 300):
            q = np.array(f.p(*(p0 + t * d)))
            if clip[0] + 8 < q[0] < clip[2] - 8 and clip[1] + 8 < q[1] < clip[3] - 8:
                sh.text(q[0] + 1.5, q[1], L.name, H_LABEL)
                break
    # B0, O, the book's vertex, r0, e or the pivot
    sh.dot(f.p(0, 0), 0.7)
    sh.text(*np.add(f.p(0, 0), (1.5, -4.0)), "B_0", H_LABEL)
    f.line((0, 0), O, "Основные")
    _cross(sh, f.p(*O), 4.0)
    sh.text(*np.add(f.p(*O), (2.0, -5.0)), "O", H_LABEL)
    mid_r = np.array(f.p(*(O / 2)))
    sh.text(mid_r[0] + 1.5, mid_r[1], f"r_0 = {_n(z.r0_m * k, lang, 1)}", H_SMALL)
    bvq = np.array(f.p(*BV))
    if np.hypot(*(BV - O)) * fac > 2.0:
        sh.circle(bvq, 1.2, "Тонкие")
        sh.text(bvq[0] + 2.0, bvq[1] + 1.0, "O_{" + pick(lang, "b", "кн") + "}", H_SMALL)
    if piv is not None:
        _pivot(sh, f.p(*piv))
        sh.text(*np.add(f.p(*piv), (2.0, 2.0)), "C", H_LABEL)
        f.line(piv, (0.0, 0.0), "Основные")
        f.line(O, piv, "Тонкие", "DASHED")
        m2 = np.array(f.p(*((O + piv) / 2)))
        sh.text(m2[0] + 1.5, m2[1] - 3.0, f"l_{{OC}} = {_n(z.l_oc_m * k, lang, 1)}", H_SMALL)
    else:
        f.line(O, (0.0, O[1]), "Тонкие")
        m2 = np.array(f.p(O[0] / 2, O[1]))
        sh.text(m2[0], m2[1] - 3.5, f"e = {_n(z.e_m * k, lang, 1)}", H_SMALL, align="center")
    # ν_i constructed at one position: the rise position with the largest B_iD_i
    cand = [(np.hypot(*(d - b)), i, d, b) for i, d, b in nums if any(row.index == i and row.phase == "rise" for row in r.motion.table)]
    if cand:
        _, i, d, b = max(cand, key=lambda t: t[0])
        u = zn.u[_nearest(B, b)]
        lo_len = 0.35 * np.hypot(*(O - d))
        f.line(d, d - lo_len * u, "Тонкие")  # −u: the follower direction through D_i
        f.line(d, O, "Тонкие", "DASHED")
        a1 = math.degrees(math.atan2(-u[1], -u[0]))
        a2 = math.degrees(math.atan2(*(O - d)[::-1]))
        rr = 0.25 * lo_len * fac
        lo_a, hi_a = sorted((a1, a2))
        if hi_a - lo_a > 180:
            lo_a, hi_a = hi_a, lo_a + 360
        sh.arc(f.p(*d), rr, lo_a, hi_a, "Тонкие")
        nu_i = abs(((a2 - a1 + 180) % 360) - 180)
        q = np.array(f.p(*(d - lo_len * u)))  # at the free end of the −u line
        sh.text(q[0] + 1.0, q[1] - 1.0, f"ν_{{{i}}} = {_n(nu_i, lang, 1)}°", H_SMALL, valign="top")
    # caption under the drawing
    txt = [
        f"ν_{{max}} = {num(v.nu_max_deg, lang, sig=6)}°;  r_0 = {_n(z.r0_m * k, lang, 2)} {pick(lang, 'mm', 'мм')}",
        (f"l_{{OC}} = {_n(z.l_oc_m * k, lang, 2)} {pick(lang, 'mm', 'мм')};  l_{{BC}} = {num(v.l_bc_m * k, lang, sig=6)} {pick(lang, 'mm', 'мм')}"
         if z.rocker else f"e = {_n(z.e_m * k, lang, 2)} {pick(lang, 'mm', 'мм')}"),
        pick(lang, f"O_b — book's vertex: r_0 = {_n(z.book_r0_m * k, lang, 2)} mm",
             f"O_{{кн}} — вершина по пособию: r_0 = {_n(z.book_r0_m * k, lang, 2)} мм"),
    ]
    y = y0b + 3.0 + 5.0 * (len(txt) - 1)
    for t in txt:
        sh.text(x0b + 3.0, y, t, H_SMALL, width=x1b - x0b - 6.0)
        y -= 5.0
    return f


def _nearest(arr, p) -> int:
    return int(np.argmin(np.hypot(*(arr - p).T)))


def _hatch(f, poly, spacing):
    """45° thin hatch lines across a convex polygon (drawing units), clipped by the field."""
    # only the part inside the field's window (drawing units): a few dozen lines, not thousands
    x0, y0, x1, y1 = f.box
    lo = (np.array([x0, y0]) - f.origin) / f.scale
    hi = (np.array([x1, y1]) - f.origin) / f.scale
    for a, c in (((-1.0, 0.0), -lo[0]), ((1.0, 0.0), hi[0]), ((0.0, -1.0), -lo[1]), ((0.0, 1.0), hi[1])):
        poly = _clip_half(poly, np.array(a), c)
        if len(poly) < 3:
            return
    d = np.array([1.0, 1.0]) / math.sqrt(2)
    n = np.array([-d[1], d[0]])
    proj = poly @ n
    for c in np.arange(proj.min() + spacing / 2, proj.max(), spacing):
        # intersect the line {x: x·n = c} with the polygon's edges
        hits = []
        for a, b in zip(poly, np.roll(poly, -1, axis=0)):
            pa, pb = a @ n - c, b @ n - c
            if pa * pb < 0:
                t = pa / (pa - pb)
                hits.append(a + t * (b - a))
        if len(hits) >= 2:
            hits = sorted(hits, key=lambda h: h @ d)
            f.line(hits[0], hits[-1], "Тонкие")


def _clip_half(poly: np.ndarray, a: np.ndarray, c: float) -> np.ndarray:
    """Convex polygon ∩ {x: a·x ≤ c} (a drawing transform: the zone cut to the window)."""
    out = []
    n = len(poly)
    for i in range(n):
        p, q = poly[i], poly[(i + 1) % n]
        fp, fq = p @ a - c, q @ a - c
        if fp <= 0:
            out.append(p)
        if fp * fq < 0:
            out.append(p + (q - p) * (fp / (fp - fq)))
    return np.array(out).reshape(-1, 2)


def _cross(sh: Sheet, c, size):
    sh.line((c[0] - size, c[1]), (c[0] + size, c[1]), "Тонкие")
    sh.line((c[0], c[1] - size), (c[0], c[1] + size), "Тонкие")
    sh.dot(c, 0.8)


def _pivot(sh: Sheet, c, r=1.5):
    """A fixed pivot: a small circle with a hatched ground under it."""
    sh.circle(c, r, "Основные")
    x, y = c
    sh.line((x, y - r), (x - 2.5, y - 5.0), "Основные")
    sh.line((x, y - r), (x + 2.5, y - 5.0), "Основные")
    sh.line((x - 4.5, y - 5.0), (x + 4.5, y - 5.0), "Основные")
    for k in range(5):
        xx = x - 4.5 + 2.2 * k
        sh.line((xx, y - 5.0), (xx - 1.5, y - 6.8), "Тонкие")


# ----------------------------------------------------------------------------------------------
# field 3: the profile by inversion


PROFILE_SCALES = tuple((lab, gost_scale(lab)) for lab in ("1:10", "1:5", "1:4", "1:2,5", "1:2", "1:1", "2:1",
                                                              "2,5:1", "4:1", "5:1", "10:1"))


def _psi_spans(r) -> list[tuple[int, float, float]]:
    """(j, lo, hi) [deg, ccw] of the profile angles ψ_у, ψ_дс, ψ_в as arcs about O: from the ray
    to the pitch-curve point at the start of each phase, swept against the rotation by the core's ψ."""
    p, v = r.profile, r.variant
    P = p.pitch
    n = len(p.phi) - 1
    prog = r.motion.program
    marks = [0.0, prog.phi_rise, prog.return_start]
    ang = [math.degrees(math.atan2(P[i, 1], P[i, 0])) for i in (int(round(a / (2 * math.pi) * n)) % n for a in marks)]
    sgn = 1.0 if v.ccw else -1.0  # ψ is swept against the rotation: clockwise for a ccw cam
    out = []
    for j, val in enumerate((p.psi_rise_deg, p.psi_far_deg, p.psi_return_deg)):
        if val < 0.05:
            continue
        sweep = -sgn * val
        out.append((j, *((ang[j] + sweep, ang[j]) if sweep < 0 else (ang[j], ang[j] + sweep))))
    return out


PSI_GAP = 6.0  # [paper mm] from the cam's outline to the first ψ arc; 5 mm between the arcs


def _profile_extent(r, fac: float) -> tuple[np.ndarray, np.ndarray]:
    """Lower-left and upper-right corners [paper mm, O at 0] of everything the field draws."""
    p = r.profile
    k = 1000.0
    x0, x1, y0, y1 = (c * k * fac for c in r.drawing.bbox_m)
    pts = [np.array([[x0, y0], [x1, y1]])]
    big = (float(np.hypot(*p.pitch.T).max()) + p.roller_m) * k * fac
    for j, lo, hi in _psi_spans(r):
        rr = big + PSI_GAP + 5.0 * j
        t = np.radians(np.linspace(lo, hi, 30))
        pts.append(np.column_stack([(rr + 5.0) * np.cos(t), (rr + 5.0) * np.sin(t)]))
        am = math.radians((lo + hi) / 2)
        c = (rr + 4.0) * np.array([math.cos(am), math.sin(am)])
        pts.append(np.array([c - (13.0, 3.0), c + (13.0, 3.0)]))  # its label
    if p.pivot_path is not None:
        pp = p.pivot_path * k * fac
        pts.append(np.vstack([pp - 7.0, pp + 7.0]))
    a = np.vstack(pts)
    return a.min(axis=0), a.max(axis=0)


PROFILE_ROOM = (BOX_PROFILE[0] + 4.0, BOX_PROFILE[1] + 14.0, BOX_PROFILE[2] - 4.0, BOX_PROFILE[3] - 20.0)


def profile_layout(r) -> tuple[str, float, tuple[float, float]]:
    """The profile field's scale and the sheet position of O: the core's Table 1.1 scale, or a
    smaller ГОСТ 2.302 one when the cam with its rollers, ψ arcs and (rocker) the pivot circle would
    not fit the field; the drawing is centred in the field."""
    f0 = 0.001 / r.drawing.k_sk
    X0, Y0, X1, Y1 = PROFILE_ROOM
    choices = sorted(((lab, f) for lab, f in PROFILE_SCALES if f <= f0 + 1e-12), key=lambda c: -c[1])
    for lab, f in choices:
        lo, hi = _profile_extent(r, f)
        if hi[0] - lo[0] <= X1 - X0 and hi[1] - lo[1] <= Y1 - Y0:
            break
    mid = (lo + hi) / 2
    return lab, f, ((X0 + X1) / 2 - mid[0], (Y0 + Y1) / 2 - mid[1])


def profile_scale(r) -> tuple[str, float]:
    """The profile field's ГОСТ 2.302 scale (label, paper mm per real mm)."""
    lab, f, _ = profile_layout(r)
    return lab, f


def _profile_field(sh: Sheet, r, lang: str):
    v, z, p, d = r.variant, r.sizing, r.profile, r.drawing
    k = 1000.0
    name, fac, (cx, cy) = profile_layout(r)
    x0b, y0b, x1b, y1b = BOX_PROFILE
    f = sh.add_field("profile", BOX_PROFILE, pick(lang, "Cam profile synthesis", "Синтез профиля кулачка"),
                     origin=(cx, cy), scale=fac, scale_label=name, scale_text=f"{pick(lang, 'M', 'М')} {pick(lang, name.replace(',', '.'), name)}")
    f.box = (x0b + 1, y0b + 1, x1b - 1, f.inner[3])
    P = p.pitch * k
    n = len(p.phi) - 1
    r0 = z.r0_m * k
    rp = p.roller_m * k
    # axes of the cam and the circles
    big = float(np.hypot(*P.T).max()) + rp
    f.line((-1.1 * big, 0), (1.1 * big, 0), "Осевые")
    f.line((0, -1.1 * big), (0, 1.1 * big), "Осевые")
    f.circle((0, 0), r0, "Тонкие")
    if p.pivot_path is not None:
        f.circle((0, 0), z.l_oc_m * k, "Осевые")
    elif abs(z.e_m) * k * fac > 0.5:
        f.circle((0, 0), abs(z.e_m) * k, "Тонкие")
    # pitch curve T (thin dash-dot, every second point) and the working profile(s) (every point)
    f.poly(np.vstack([P[::2], P[-1:]]), "Осевые")
    f.poly(p.inner * k, "Основные")
    if p.outer is not None:
        f.poly(p.outer * k, "Основные")
    # inverted follower positions at the table positions, rollers, numbers B_i'
    rows = r.motion.table
    labels = []
    for row in rows:
        i = int(round(math.radians(row.phi_deg) / (2 * math.pi) * n)) % n
        b = P[i]
        f.circle(b, rp, "Тонкие")
        if p.pivot_path is not None:
            c = p.pivot_path[i] * k
            f.line(c, b, "Тонкие")
            sh.dot(f.p(*c), 0.45)
        else:
            u = p.axis_dir[i]
            foot = b - (b @ u) * u  # the tangent point C_i on the offset circle
            f.line(foot, b + u * 0.25 * r0, "Тонкие")
        out = b / (np.hypot(*b) or 1.0)
        labels.append((row.index, np.array(f.p(*b)) + out * (rp * fac + 2.5)))
    seen = []
    for idx, q in labels:  # a number is left out where it would touch one already written
        w = sh.text_width(f"{idx}'", H_SMALL)
        if all(abs(q[0] - s[0]) > (w + ws) / 2 + 0.6 or abs(q[1] - s[1]) > H_SMALL + 0.4 for s, ws in seen):
            sh.text(q[0], q[1], f"{idx}'", H_SMALL, align="center", valign="middle")
            seen.append((q, w))
    # centre O, B_0', the pivot C (rocker) with the rocker in the start position
    _cross(sh, f.p(0, 0), 5.0)
    sh.text(*np.add(f.p(0, 0), (1.5, -5.0)), "O", H_LABEL)
    if p.pivot_path is not None:
        c0 = p.pivot_path[0] * k
        _pivot(sh, f.p(*c0))
        sh.text(*np.add(f.p(*c0), (2.5, 2.0)), "C_0", H_LABEL)
        f.line(c0, P[0], "Основные")
    # profile angles ψ as arcs outside the cam, between rays from O (the core's values)
    names = ("ψ_{у}", "ψ_{дс}", "ψ_{в}") if lang == "ru" else ("ψ_{r}", "ψ_{fd}", "ψ_{ret}")
    vals = (p.psi_rise_deg, p.psi_far_deg, p.psi_return_deg)
    o_s = np.array(f.p(0, 0))
    big_p = big * fac
    rays = set()
    for j, lo_a, hi_a in _psi_spans(r):
        rr = big_p + PSI_GAP + 5.0 * j
        for a in (lo_a, hi_a):
            key = round(a % 360.0, 3)
            e = np.array([math.cos(math.radians(a)), math.sin(math.radians(a))])
            if key not in rays:
                rays.add(key)
            sh.line(o_s, o_s + e * (rr + 2.5), "Тонкие")
        sh.arc(o_s, rr, lo_a, hi_a, "Размеры")
        for end, dirn in ((lo_a, 1), (hi_a, -1)):
            e = math.radians(end)
            tip = o_s + (rr * math.cos(e), rr * math.sin(e))
            tang = np.array([-math.sin(e), math.cos(e)]) * -dirn
            sh.arrow(tip, tang, "Размеры", 3.0, 0.9)
        am = math.radians((lo_a + hi_a) / 2)
        q = o_s + ((rr + 4.0) * math.cos(am), (rr + 4.0) * math.sin(am))
        sh.text(q[0], q[1], f"{names[j]} = {_n(vals[j], lang, 1)}°", H_SMALL, align="center", valign="middle")
    # rotation of the cam
    e_abs = 0.0 if p.pivot_path is not None else abs(z.e_m) * k
    rr = (0.45 * r0 if e_abs < 0.3 * r0 else 0.5 * (e_abs + r0)) * fac
    a0, a1 = 200.0, 250.0
    sh.arc(f.p(0, 0), rr, a0, a1, "Основные")
    e = math.radians(a1 if v.ccw else a0)
    tip = np.add(f.p(0, 0), (rr * math.cos(e), rr * math.sin(e)))
    tang = np.array([-math.sin(e), math.cos(e)]) * (1 if v.ccw else -1)
    sh.arrow(tip, tang, "Основные", 3.5, 1.2)
    qm = np.add(f.p(0, 0), ((rr + 4) * math.cos(math.radians(225)), (rr + 4) * math.sin(math.radians(225))))
    sh.text(qm[0], qm[1], "ω_{к}" if lang == "ru" else "ω_{c}", H_LABEL, align="right", valign="top")
    # captions
    txt = [f"k_{{Sk}} = {_g(0.001 / fac, lang)} {pick(lang, 'm/mm', 'м/мм')};  {pick(lang, 'r_{r}', 'r_{р}')} = {_roller_text(p, lang)}"]
    if abs(fac - 0.001 / d.k_sk) > 1e-12:
        why = pick(lang, "the pivot circle", "окружность центров качания") if p.pivot_path is not None else \
            pick(lang, "the profile with its constructions", "профиль с построениями")
        txt.append(pick(lang, f"(Table 1.1 gives {d.scale.replace(',', '.')}; a smaller ГОСТ 2.302 scale here to fit {why})",
                        f"(по табл. 1.1 — {d.scale}; здесь меньший масштаб ГОСТ 2.302, чтобы уместить {why})"))
    sh.caption(x0b, x1b, y0b + 2.0, txt, H_SMALL, 4.6)
    return f


# ----------------------------------------------------------------------------------------------
# field 4: pressure angle


def _pressure_field(sh: Sheet, r, lang: str):
    v, m, p, z = r.variant, r.motion, r.profile, r.sizing
    sc = m.scales
    f = sh.add_field("pressure", BOX_PRESSURE, pick(lang, "Pressure angle against cam position",
                                                    "Зависимость угла давления от положения кулачка"))
    x0b, y0b, x1b, y1b = f.inner
    xo = x0b + 22.0
    yo = y0b + 18.0
    phw = v.phi_working_deg
    keep = np.degrees(p.phi) <= phw + 1e-9
    nu = p.nu_deg[keep]
    top = max(float(nu.max()), v.nu_max_deg)
    room = y1b - yo - 14.0
    k_nu = next((c for c in (0.25, 0.4, 0.5, 1.0, 2.0, 2.5) if top / c <= room), 5.0)  # °/mm
    xs = xo + np.degrees(p.phi[keep]) / sc.k_phi_deg_mm
    _axis(sh, xo, yo, sc.b_mm, top / k_nu, 0.0, "φ", "ν")
    ph = m.program.phase_index(p.phi[keep])
    moving = (ph == 0) | (ph == 2)
    # the constrained phases in a main line, the rest thin
    for mask, layer in ((moving, "Основные"), (~moving, "Тонкие")):
        yy = np.where(mask, yo + nu / k_nu, np.nan)
        start = None
        for j in range(len(yy) + 1):
            ok = j < len(yy) and not np.isnan(yy[j])
            if ok and start is None:
                start = j
            if not ok and start is not None:
                if j - start >= 2:
                    sh.poly(np.column_stack([xs[start:j], yy[start:j]]), layer)
                start = None
    ym = yo + v.nu_max_deg / k_nu
    sh.line((xo, ym), (xo + sc.b_mm, ym), "Осевые")
    sh.text(xo + sc.b_mm, ym + 1.2, f"ν_{{max}} = {num(v.nu_max_deg, lang, sig=6)}°", H_SMALL, align="right")
    for row in m.table:
        x = xo + row.phi_deg / sc.k_phi_deg_mm
        sh.line((x, yo), (x, yo - 1.5), "Тонкие")
        sh.text(x, yo - 2.5, str(row.index), H_SMALL, align="center", valign="top")
    # ticks on the ν axis every 10°
    for t in range(10, int(top) + 1, 10):
        y = yo + t / k_nu
        sh.line((xo - 1.5, y), (xo, y), "Тонкие")
        sh.text(xo - 2.5, y, f"{t}", H_SMALL, align="right", valign="middle")
    lab = pick(lang, f"k_ν = {_g(k_nu, lang)} °/mm;  k_φ = {_g(sc.k_phi_deg_mm, lang)} °/mm;  max ν: rise {_n(z.nu_rise_max_deg, lang, 1)}°, return {_n(z.nu_return_max_deg, lang, 1)}°",
               f"k_{{ν}} = {_g(k_nu, lang)} °/мм;  k_{{φ}} = {_g(sc.k_phi_deg_mm, lang)} °/мм;  ν на удалении ≤ {_n(z.nu_rise_max_deg, lang, 1)}°, на возвращении ≤ {_n(z.nu_return_max_deg, lang, 1)}°")
    if z.closure == "force":
        lab += pick(lang, " (spring: return not limited)", " (силовое замыкание: не ограничивается)")
    sh.text(x0b + 2.0, y0b + 2.0, lab, H_SMALL, width=x1b - x0b - 4.0, max_lines=2)
    return f


# ----------------------------------------------------------------------------------------------
# the results table


def table(sh: Sheet, box, title: str, rows: list[tuple[str, str]], col1: float = 0.62, h=H_LABEL):
    """A two-column table (quantity, value) with a heading, in thin lines, a thick outline."""
    x0, y0, x1, y1 = box
    sh.text((x0 + x1) / 2, y1 - 1.5, title.upper(), 5.0, align="center", valign="top", width=x1 - x0 - 4)
    top = y1 - 9.0
    row_h = min(8.0, (top - y0) / max(len(rows), 1))
    bottom = top - row_h * len(rows)
    xm = x0 + col1 * (x1 - x0)
    sh.rect(x0, bottom, x1, top, "Основные")
    sh.line((xm, bottom), (xm, top), "Основные")
    for j, (a, b) in enumerate(rows):
        y = top - (j + 1) * row_h
        if j < len(rows) - 1:
            sh.line((x0, y), (x1, y), "Тонкие")
        hh = min(h, row_h - 2.5)
        sh.text(x0 + 2.0, y + row_h / 2, a, hh, valign="middle", width=xm - x0 - 4.0, height_max=row_h - 1.5, max_lines=2)
        sh.text((xm + x1) / 2, y + row_h / 2, b, hh, align="center", valign="middle", width=x1 - xm - 4.0)
    return bottom


def _roller_text(p, lang: str) -> str:
    """The carried roller and the rule that gave it (the core's ``roller_rule``); the book's
    0.2·r_0 beside it when the roller differs from it."""
    mm = pick(lang, "mm", "мм")
    val = f"{_n(p.roller_m * 1000.0, lang)} {mm}"
    book = f"0{pick(lang, '.', ',')}2·r_{{0}}"
    if p.roller_rule == "book":
        return f"{val} ({book})"
    rule = {"limited": f"0{pick(lang, '.', ',')}8·ρ_{{min}}", "student": pick(lang, "given", "задан")}.get(p.roller_rule, p.roller_rule)
    return f"{val} ({rule}; {book} = {_n(p.roller_book_m * 1000.0, lang)})"


def _results(sh: Sheet, r, lang: str, prof_scale: str) -> None:
    v, z, p, sc = r.variant, r.sizing, r.profile, r.motion.scales
    k = 1000.0
    mm = pick(lang, "mm", "мм")
    ru = lang == "ru"
    rows = [
        (pick(lang, "Minimum cam radius r_0", "Минимальный радиус кулачка r_0"), f"{_n(z.r0_m * k, lang)} {mm}"),
    ]
    if z.rocker:
        rows += [(pick(lang, "Centre distance l_{OC}", "Межосевое расстояние l_{OC}"), f"{_n(z.l_oc_m * k, lang)} {mm}"),
                 (pick(lang, "Rocker length l_{BC}", "Длина коромысла l_{BC}"), f"{_n(v.l_bc_m * k, lang)} {mm}")]
    else:
        rows.append((pick(lang, "Offset e", "Эксцентриситет e"), f"{_n(z.e_m * k, lang)} {mm}"))
    rows += [
        (pick(lang, "Roller radius r_{r}", "Радиус ролика r_{р}"), _roller_text(p, lang)),
        (pick(lang, "Pressure angle ν_{max} (given / reached)", "Угол давления ν_{max} (задан / получен)"),
         f"{num(v.nu_max_deg, lang, sig=6)}° / {_n(max(z.nu_rise_max_deg, z.nu_return_max_deg if z.closure == 'form' else 0), lang, 1)}°"),
        (("Профильные углы ψ_{у}, ψ_{дс}, ψ_{в}" if ru else "Profile angles ψ"),
         f"{_n(p.psi_rise_deg, lang, 1)}°; {_n(p.psi_far_deg, lang, 1)}°; {_n(p.psi_return_deg, lang, 1)}°"),
        (pick(lang, "Scales k_{S}, k_{V}, k_{a}", "Масштабы k_{S}, k_{V}, k_{a}") if not z.rocker
         else pick(lang, "Scales k_{γ}, k_{ω}, k_{ε}", "Масштабы k_{γ}, k_{ω}, k_{ε}"),
         f"{_g(sc.k_s, lang, 3)}; {_g(sc.k_v, lang, 3)}; {_g(sc.k_a, lang, 3)}"),
        (pick(lang, "Profile scale (k_{Sk})", "Масштаб профиля (k_{Sk})"), f"{pick(lang, 'M', 'М')} {pick(lang, prof_scale.replace(',', '.'), prof_scale)}"),
        (pick(lang, "Closure, follower", "Замыкание, толкатель"),
         pick(lang, f"{z.closure}, {'rocker' if z.rocker else 'translating'}",
              f"{'силовое' if z.closure == 'force' else 'геометрическое'}, {'коромысло' if z.rocker else 'поступательный'}")),
    ]
    table(sh, BOX_TABLE, pick(lang, "Main results", "Основные результаты"), rows)


def sheet3(result, lang: str, title) -> Sheet:
    """Build sheet 3 for a CamResult (no file written)."""
    sh = Sheet(lang)
    sh.frame()
    _motion_field(sh, result, lang)
    _zone_field(sh, result, lang)
    prof = _profile_field(sh, result, lang)
    _pressure_field(sh, result, lang)
    _results(sh, result, lang, prof.scale_label)
    v = result.variant
    sh.title_block(title, name=pick(lang, "Cam mechanism synthesis", "Синтез кулачкового механизма"),
                   designation=title.designation_for(3, v.number), scale=prof.scale_label)
    return sh
