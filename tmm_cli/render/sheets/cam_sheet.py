"""Sheet 3 «Синтез кулачкового механизма» (§1.2–§1.4, the book's sample sheet).

Four fields with the book's headings plus a table of results, drawn from a
:class:`~tmm_cli.cam.design.CamResult`: the motion laws at the scales (1.9)–(1.13), the centre
zone (Fig. 1.3/1.4) with the wedges of every position, the profile by inversion (Fig. 1.6/1.7) at
the core's drawing scale (``CamResult.drawing``: the one scale the note states too), and ν(φ).
Nothing is computed a second time: every curve is an array of the result placed on the sheet
(scaling, shifting, picking the table positions out of the dense arrays); every number printed is
a field of the result.

The fields are laid out from the measured extent of their drawings (:func:`layout`): the motion
laws and ν(φ) in the left column, the profile (at the core's scale) and the table at one of a few
places on the right, the zone at the largest ГОСТ 2.302 scale that has a free place beside them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...i18n import tr
from ...i18n.numbers import num
from .layout import GOST_SCALES, fit_view, largest_empty_square, nice_scale
from .paper import FRAME, H_LABEL, H_MIN_LABEL, TB_BOX, Sheet, gost_label

H_NOTE = 3.5  # captions under a field
LINE = 5.6  # caption line pitch
LEFT_W = 320.0  # the left column (motion laws, ν(φ)): b = 240 mm plus the axes
GAP = 2.0  # between fields
PROFILE_RING = 14.0  # [paper mm] from the cam's outline to the first ψ arc; 7 mm between the arcs
PROFILE_PAD = 12.0  # beyond the last ψ arc (its label)


def _n(x, lang, d=2):
    return num(x, lang, decimals=d)


def _g(x, lang, sig=4):
    return num(x, lang, sig=sig)


def _m(lang, lab: str) -> str:
    """A scale label as printed: 'М 1:2,5' (ru), 'M 1:2.5' (en)."""
    return tr(lang, "M") + " " + (lab if lang == "ru" else lab.replace(",", "."))  # the scale's decimal sign


# ----------------------------------------------------------------------------------------------
# layout


@dataclass(frozen=True)
class Layout3:
    motion: tuple
    pressure: tuple
    zone: tuple
    profile: tuple
    table: tuple
    zone_caption_beside: bool = False  # the zone's captions at its right, not under it


def _motion_height(r) -> float:
    up_v, dn_v, up_a, dn_a = _va_extents(r)
    sc = r.motion.scales
    return 16.0 + 14.0 + sc.y_s_max_mm + 14.0 + up_v + dn_v + 16.0 + up_a + dn_a + 16.0 + LINE * 4 + 4.0


def _table_height(r) -> float:
    return 12.0 + 9.0 * (_results_rows(r)) + 3.0


ZONE_CAP_W = 175.0  # the zone's captions beside its drawing
ZONE_MIN_W = 165.0  # the zone's captions (narrowed to fit)
ZONE_CAP_WIDE = 236.0  # … and where they need not be narrowed
PROFILE_MIN_W = 200.0  # its heading
TABLE_MIN_W = 215.0
ZONE_HEAD = 16.0 + 8.0  # heading and its scale
ZONE_CAPS = 2.5 + LINE * 5 + 2.0  # five caption lines: the data, the hatching, the book's lines, O_b, the numbers left out
ZONE_MARGIN = (12.0, 10.0, 12.0, 8.0)


def _zone_need(ext, s: float, side: bool = False) -> tuple[float, float]:
    """[mm] The zone field's width and height at scale `s` (`ext`: the window's width and height
    [real mm], :func:`_zone_window`): the window with its margins, heading and captions — under
    the drawing (at least ZONE_MIN_W wide), or `side` by side with it."""
    ml, mb, mr, mt = ZONE_MARGIN
    w, h = ext[0] * s + ml + mr + 2.5, ext[1] * s + mb + mt + ZONE_HEAD + 2.5  # 0.5 mm to spare
    if side:
        return w + ZONE_CAP_W, max(h + 2.0, ZONE_HEAD + ZONE_CAPS)
    return max(w, ZONE_MIN_W), h + ZONE_CAPS


def _zone_scale(ext, cell, side: bool = False) -> float:
    """The largest ГОСТ 2.302 scale at which the zone field fits the cell (x0, y0, x1, y1); 0: none."""
    w, h = cell[2] - cell[0], cell[3] - cell[1]
    best = 0.0
    for _, s in GOST_SCALES:
        nw, nh = _zone_need(ext, s, side)
        if nw <= w + 1e-9 and nh <= h + 1e-9:
            best = s
    return best


def _profile_need(r) -> tuple[float, float]:
    """[mm] The profile field's width and height at the core's scale (heading, scale, two caption lines)."""
    lo, hi = _profile_extent(r, _profile_factor(r))
    return max(hi[0] - lo[0] + 8.0, PROFILE_MIN_W), hi[1] - lo[1] + 16.0 + 8.0 + LINE * 2 + 6.0


def _free_places(w: float, h: float, frame, boxes) -> np.ndarray:
    """Lower-left corners (n × 2) at which a w × h box stands in `frame` clear of `boxes`: a free
    place, when there is one, can be slid left and down until it rests on the frame or on a box's
    right or top side, so those are the corners tried."""
    b = np.asarray(boxes, float).reshape(-1, 4)
    xs = np.concatenate([[frame[0]], b[:, 2]])
    ys = np.concatenate([[frame[1]], b[:, 3]])
    X, Y = np.tile(xs, len(ys)), np.repeat(ys, len(xs))
    ok = (X + w <= frame[2] + 1e-9) & (Y + h <= frame[3] + 1e-9)
    hit = ((X[:, None] < b[None, :, 2] - 1e-9) & (b[None, :, 0] < X[:, None] + w - 1e-9)
           & (Y[:, None] < b[None, :, 3] - 1e-9) & (b[None, :, 1] < Y[:, None] + h - 1e-9)).any(axis=1)
    return np.column_stack([X, Y])[ok & ~hit]


def _spread(corner, w: float, h: float, frame, boxes):
    """The w × h box at a free corner moved to the middle of the free room to its right and above."""
    x, y = corner
    right, top = frame[2], frame[3]
    for b in boxes:
        if b[1] < y + h and y < b[3] and b[0] >= x + w - 1e-9:
            right = min(right, b[0])
        if b[0] < x + w and x < b[2] and b[1] >= y + h - 1e-9:
            top = min(top, b[1])
    x += max(0.0, right - GAP - x - w) / 2
    y += max(0.0, top - GAP - y - h) / 2
    return (x, y, x + w, y + h)


def _grown(box, g: float = GAP):
    return (box[0] - g, box[1] - g, box[2] + g, box[3] + g)


def _fixed_places(r, right):
    """Where the profile (its size fixed by the core's scale) and the table may stand in the frame
    right of the left column: pairs (profile box, table box) that do not overlap."""
    xa, Y0, X1, Y1 = right
    wr, hr = _profile_need(r)
    wr = min(wr, X1 - xa)  # the profile's rings wider than that are cut at the field's edge
    ht = _table_height(r)
    tb = TB_BOX[3] + GAP  # the lowest y over the title block
    profs = {(X1 - wr, Y1 - hr), (X1 - wr, max(tb, (tb + Y1 - hr) / 2)), (xa, Y1 - hr), (xa, Y0)}
    if Y1 - hr >= tb:
        profs.add((X1 - wr, tb))
    wt = max(min(wr, TB_BOX[2] - TB_BOX[0]), TABLE_MIN_W)
    tabs = [(X1 - wt, y, X1, y + ht) for y in (tb, (tb + Y1 - ht) / 2, Y1 - ht)]  # over the title block
    tabs.append((xa, Y0, TB_BOX[0] - GAP, Y0 + ht))  # beside it
    out = []
    for px, py in sorted(profs):
        prof = (px, py, px + wr, py + hr)
        if py < Y0 - 1e-9 or py + hr > Y1 + 1e-9:
            continue
        for tab in tabs:
            if tab[2] - tab[0] < TABLE_MIN_W - 1e-9 or _overlap(_grown(prof), tab):
                continue
            if _overlap(_grown(prof), TB_BOX) or _overlap(_grown(tab), TB_BOX):
                continue
            out.append((prof, tab))
    return out


def _overlap(a, b) -> bool:
    return a[0] < b[2] - 1e-9 and b[0] < a[2] - 1e-9 and a[1] < b[3] - 1e-9 and b[1] < a[3] - 1e-9


def _left_ink(r, motion, pressure):
    """Where the left column's drawings reach (their fields are wider and the ν plot lower than
    their boxes): what the search for the least empty square counts as used."""
    sc = r.motion.scales
    x0 = motion[0] + 1.0
    xo = x0 + max(26.0, min(max(sc.h_v_mm, sc.h_a_mm) + 10.0, motion[2] - x0 - sc.b_mm - 26.0))
    m = (motion[0], motion[1], min(motion[2], xo + sc.b_mm + 24.0), motion[3])
    v, p = r.variant, r.profile
    keep = np.degrees(p.phi) <= v.phi_working_deg + 1e-9
    top = max(float(p.nu_deg[keep].max()), v.nu_max_deg)
    yo = pressure[1] + 1.0 + 2.5 + LINE * 2 + 12.0
    hh = 14.0
    k_nu = nice_scale(top / (pressure[3] - hh - yo - 16.0))
    pr = (pressure[0], pressure[1], pressure[0] + 23.0 + sc.b_mm + 40.0,
          min(pressure[3], yo + top / k_nu + 14.0 + hh))
    return m, pr


def layout(r) -> Layout3:
    """The field boxes of sheet 3, each sized to its drawing: the motion laws and ν(φ) in the left
    column (the book's scales (1.9)–(1.13)); on the right the profile at the core's scale and the
    table, at one of a few places each (:func:`_fixed_places`), and the zone at the largest ГОСТ
    2.302 scale at which its field (captions under the drawing or beside it) has a free place
    anywhere beside them; of those, the places that leave the smallest empty square on the sheet."""
    X0, Y0, X1, Y1 = FRAME
    xl = X0 + LEFT_W
    hm = min(_motion_height(r), Y1 - Y0 - 170.0)
    motion = (X0 + GAP, Y1 - hm, xl, Y1 - GAP)
    pressure = (X0 + GAP, Y0 + GAP, xl, Y1 - hm - GAP)
    right = (xl + GAP, Y0 + GAP, X1 - GAP, Y1 - GAP)
    lo, hi = _zone_window(r)
    ext = (float(hi[0] - lo[0]), float(hi[1] - lo[1]))
    scales = [g for _, g in GOST_SCALES]
    cands = []  # (scale, caption beside, profile, table)
    best_i = -1  # the largest scale found so far: a place need only be tried at it and above
    for prof, tab in _fixed_places(r, right):
        taken = [_grown(b) for b in (motion, pressure, TB_BOX, prof, tab)]
        for side in (False, True):
            if best_i >= 0 and not len(_free_places(*_zone_need(ext, scales[best_i], side), right, taken)):
                continue  # not even the scale found: this place cannot do better
            lo_i, hi_i = best_i, len(scales) - 1  # the largest scale with a free place: a bisection
            while lo_i < hi_i:
                mid = (lo_i + hi_i + 1) // 2
                if len(_free_places(*_zone_need(ext, scales[mid], side), right, taken)):
                    lo_i = mid
                else:
                    hi_i = mid - 1
            if lo_i >= 0:
                best_i = lo_i
                cands.append((scales[lo_i], side, prof, tab, taken))
    if not cands:  # a zone too large even at 1:100: the room left of the profile, the drawing cut there
        prof, tab = _fixed_places(r, right)[0]
        return Layout3(motion, pressure, (right[0], Y0 + GAP, prof[0] - GAP, Y1 - GAP), prof, tab)
    s_best = max(c[0] for c in cands)
    fixed = [*_left_ink(r, motion, pressure), TB_BOX]
    best = None
    for s, side, prof, tab, taken in cands:
        if s < s_best:
            continue
        w, h = _zone_need(ext, s, side)
        seen = set()
        for corner in _free_places(w, h, right, taken):
            zone = tuple(float(c) for c in _spread(corner, w, h, right, taken))
            if tuple(round(c, 1) for c in zone) in seen:
                continue
            seen.add(tuple(round(c, 1) for c in zone))
            empty = largest_empty_square(FRAME, [*fixed, prof, tab, zone], give_up=-best[0][0] if best else math.inf)
            key = (-round(empty, 6), not side)
            if best is None or key > best[0]:
                best = (key, zone, prof, tab, side, taken)
    _, zone, prof, tab, side, taken = best
    if not side:  # as wide as the captions like where there is room (not narrowed), still centred
        for grow in np.linspace(max(0.0, ZONE_CAP_WIDE - (zone[2] - zone[0])) / 2, 0.0, 5):
            wider = (zone[0] - grow, zone[1], zone[2] + grow, zone[3])
            if wider[0] >= right[0] and wider[2] <= right[2] and not any(_overlap(wider, b) for b in taken):
                zone = wider
                break
    return Layout3(motion, pressure, zone, prof, tab, side)


# ----------------------------------------------------------------------------------------------
# field 1: motion laws


def _va_extents(r):
    v, m = r.variant, r.motion
    sc = m.scales
    keep = np.degrees(m.phi) <= v.phi_working_deg + 1e-9
    v_arr = m.v[keep] / sc.k_v
    a_arr = m.a[keep] / sc.k_a
    return (max(float(v_arr.max()), 0.0), max(-float(v_arr.min()), 0.0),
            max(float(a_arr.max()), 0.0), max(-float(a_arr.min()), 0.0))


def _axis(sh: Sheet, box, x0, y0, length, up, down, xlabel, ylabel):
    """Abscissa from x0 with an arrow, ordinate from y0 − down to y0 + up with an arrow."""
    sh.line((x0, y0), (x0 + length + 6, y0), "Основные")
    sh.arrow((x0 + length + 10, y0), (1, 0), "Основные", 4.0, 1.3)
    sh.line((x0, y0 - down), (x0, y0 + up + 6), "Основные")
    sh.arrow((x0, y0 + up + 10), (0, 1), "Основные", 4.0, 1.3)
    sh.label(xlabel, (x0 + length + 10, y0), H_LABEL, within=box, dirs=("se", "ne", "s"), dists=(1.0, 2.5), priority=8)
    sh.label(ylabel, (x0, y0 + up + 10), H_LABEL, within=box, dirs=("w", "nw", "e", "ne"), dists=(1.5, 3.0), priority=8)


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


def _numbers_below(sh, box, rows, xs, y, h=H_MIN_LABEL):
    """Position numbers under an axis at the table abscissae (every other one when they crowd)."""
    w = max(sh.text_width(str(row.index), h) for row in rows) + 1.5
    step = min(np.diff(xs)) if len(xs) > 1 else 99.0
    every = 1 if step >= w else (2 if 2 * step >= w else 3)
    for k, (row, x) in enumerate(zip(rows, xs)):
        if k % every and k != len(rows) - 1:
            continue
        sh.label(str(row.index), (x, y), h, within=box, dirs=("s", "sw", "se"), dists=(1.2, 2.5), leader=False,
                 priority=6)


def _motion_field(sh: Sheet, r, lang: str, box) -> None:
    v, m = r.variant, r.motion
    sc = m.scales
    f = sh.add_field("motion", box, tr(lang, "Follower motion laws"))
    x0b, y0b, x1b, y1b = f.inner
    hv, ha = sc.h_v_mm, sc.h_a_mm
    pole_room = max(hv, ha) + 10.0
    xo = x0b + max(26.0, min(pole_room, x1b - x0b - sc.b_mm - 26.0))
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
    up_v, dn_v, up_a, dn_a = _va_extents(r)
    ys0 = y1b - 14.0 - sc.y_s_max_mm
    yv0 = ys0 - 14.0 - up_v - 10.0
    ya0 = yv0 - dn_v - 16.0 - up_a - 10.0
    b = sc.b_mm
    names = (("S", "V", "a") if not rocker else ("γ", "ω", "ε"))
    for (y0, arr, pts, up, dn, nm, jb) in ((ys0, s_arr, rs, sc.y_s_max_mm, 0.0, names[0], False),
                                            (yv0, v_arr, rv, up_v, dn_v, names[1], False),
                                            (ya0, a_arr, ra, up_a, dn_a, names[2], True)):
        _axis(sh, f.inner, xo, y0, b, up, dn, "φ, t", nm)
        _curve(sh, xs, y0 + arr, jump_break=jb)
        for x, yy in zip(xr, pts):
            if abs(yy) > 0.3:
                sh.line((x, y0), (x, y0 + yy), "Тонкие")
    _numbers_below(sh, f.inner, rows, xr, ys0)
    # poles of graphical differentiation: P_V, P_a at H_V, H_a left of the origin
    for y0, H, nm in ((yv0, hv, "V"), (ya0, ha, "a")):
        if H > xo - x0b - 3.0:  # the pole would leave the field: H is printed below instead
            continue
        px = xo - H
        sh.dot((px, y0), 0.8)
        sh.label(f"P_{{{nm if not rocker else ('ω' if nm == 'V' else 'ε')}}}", (px, y0), H_LABEL, within=f.inner,
                 dirs=("n", "s", "nw", "sw", "ne"), priority=7)
    # scales
    mm = tr(lang, "mm")
    if rocker:
        s_unit, v_unit, a_unit = (tr(lang, "rad/mm"), tr(lang, "rad/(s·mm)"),
                                  tr(lang, "rad/(s²·mm)"))
        kn = ("k_{γ}", "k_{ω}", "k_{ε}")
    else:
        s_unit, v_unit, a_unit = (tr(lang, "m/mm"), tr(lang, "m/(s·mm)"),
                                  tr(lang, "m/(s²·mm)"))
        kn = ("k_{S}", "k_{V}", "k_{a}")
    lines = [
        f"k_{{φ}} = {_g(sc.k_phi_deg_mm, lang)} °/{mm};  k_{{t}} = {_g(sc.k_t_s_mm, lang)} "
        + tr(lang, "s/mm") + f";  b = {num(sc.b_mm, lang, sig=6)} {mm}",
        f"{kn[0]} = {_g(sc.k_s, lang)} {s_unit};  {kn[1]} = {_g(sc.k_v, lang)} {v_unit}",
        f"{kn[2]} = {_g(sc.k_a, lang)} {a_unit};  H_{{V}} = {num(hv, lang, sig=6)} {mm};  H_{{a}} = {num(ha, lang, sig=6)} {mm}",
        tr(lang, "law {law}").format(law=v.law) + ";  " + tr(lang, "n_{c}")
        + f" = {num(abs(v.n_cam_rpm), lang, sig=6)} " + tr(lang, "rpm"),
    ]
    if rocker:
        lines[-1] += (f";  k_{{SB}} = k_{{γ}}·l_{{BC}} = {_g(sc.k_s_b, lang)} " + tr(lang, "m/mm")
                      + f";  k_{{γ°}} = {_g(sc.k_gamma_deg_mm, lang)} °/{mm}")
    sh.caption(box[0], box[2], box[1] + 2.5, lines, H_NOTE, LINE)


# ----------------------------------------------------------------------------------------------
# field 2: the centre zone


def _table_index(phis: np.ndarray, phi_deg: float) -> int:
    return int(np.argmin(np.abs(np.degrees(phis) - phi_deg)))


def _profile_index(p, phi_deg: float) -> int:
    n = len(p.phi) - 1
    return int(round(math.radians(phi_deg) / (2 * math.pi) * n)) % n


def _zone_window(r):
    """Lower-left and upper-right corners [real mm, zone frame] of the construction: the roller
    centres B_i, the points D_i, B0, the chosen centre O (and some of the zone below it), the
    pivot C, the book's vertex when it is near."""
    z = r.sizing
    zn = z.zone
    k = 1000.0
    B, D = zn.b * k, zn.d * k
    O = np.array(z.centre) * k
    BV = np.array(z.book_centre) * k
    pts = [B, D, O[None], np.zeros((1, 2))]
    if z.pivot is not None:
        pts.append(np.array(z.pivot)[None] * k)
    allp = np.concatenate(pts)
    lo, hi = allp.min(axis=0), allp.max(axis=0)
    size = float((hi - lo).max())
    if np.hypot(*(BV - O)) < 0.6 * size:
        lo, hi = np.minimum(lo, BV), np.maximum(hi, BV)
    lo = np.minimum(lo, O - np.array([0.0, 0.22 * size]))  # the zone below O
    pad = 0.05 * size
    return lo - pad, hi + pad


def _zone_field(sh: Sheet, r, lang: str, box, beside: bool = False):
    v, z, p = r.variant, r.sizing, r.profile
    zn = z.zone
    k = 1000.0
    mm = tr(lang, "mm")
    B, D = zn.b * k, zn.d * k
    O = np.array(z.centre) * k
    BV = np.array(z.book_centre) * k
    piv = None if z.pivot is None else np.array(z.pivot) * k
    lo, hi = _zone_window(r)
    f = sh.add_field("zone", box, tr(lang, "Minimum cam radius"))
    x0b, y0b, x1b, y1b = box
    if beside:  # the captions in a column at the right, the drawing beside them
        room = (x0b + 1.0, y0b + 2.0, x1b - ZONE_CAP_W, y1b - ZONE_HEAD)
    else:
        room = (x0b + 1.0, y0b + ZONE_CAPS, x1b - 1.0, y1b - ZONE_HEAD)
    fit = fit_view(lo, hi, room, margin=ZONE_MARGIN)
    fac = fit.scale
    sh.set_field_transform(f, fit.origin, fac, fit.label)
    _export_extent(sh, f, lo, hi)
    _field_scale_text(sh, f, lang, fit.label)
    w0, w1 = f.p(*lo), f.p(*hi)
    window = (max(room[0], w0[0]), max(room[1], w0[1]), min(room[2], w1[0]), min(room[3], w1[1]))
    f.clip = window
    within = room
    # the feasible zone the wedges cut: outline (thin) and a 45° hatch
    poly = zn.polygon * k
    f.poly(poly, "Тонкие", closed=True)
    _hatch(f, poly, spacing=3.0 / fac, through=O)  # a hatch line through O: the centre stands on the hatching
    rise = zn.phase == 0
    ret = zn.phase == 2
    # B path and D-curves
    if z.rocker:
        f.poly(B[rise], "Тонкие")
    else:
        f.line((0.0, min(0.0, lo[1])), (0.0, B[:, 1].max() * 1.05), "Осевые")
    f.poly(D[rise], "Основные")
    f.poly(D[ret], "Основные" if z.closure == "form" else "Штриховые")
    # every table position: B_i D_i, the point D_i, the wedge at D_i (half-angle ν about −u: the
    # rays at the allowed pressure angle), its number
    nu = math.radians(z.nu_design_deg)
    span = float((hi - lo).max()) * 3.0
    nums = []
    for row in r.motion.table:
        if row.phase not in ("rise", "return"):
            continue
        mask = rise if row.phase == "rise" else ret
        idx = np.nonzero(mask)[0]
        i = idx[_table_index(zn.phi[idx], row.phi_deg)]
        f.line(B[i], D[i], "Тонкие")
        sh.dot(f.p(*D[i]), 0.5)
        if zn.constrained[i]:  # the rays run to the zone's corner O and a little beyond
            w = -zn.u[i]
            reach = 1.12 * float(np.hypot(*(O - D[i])))
            for sgn in (1.0, -1.0):
                c, s = math.cos(sgn * nu), math.sin(sgn * nu)
                d = np.array([c * w[0] - s * w[1], s * w[0] + c * w[1]])
                f.line(D[i], D[i] + reach * d, "Тонкие")
        nums.append((row.index, D[i], B[i], row.phase))
    for idx_, d, b, _ in nums:
        out = d - b
        nrm = float(np.hypot(*out))
        dirv = out / nrm if nrm > 1e-9 else np.array([1.0, 0.0])
        from .paper import _dirs_towards

        # its own candidates, outward along its ray B_i D_i and around D_i, then on a leader that
        # crosses no other leader; a number that finds no free place is left out, and said so
        txt_ = str(idx_)
        w_ = sh.text_width(txt_, H_MIN_LABEL)
        ds = np.array(f.p(*d))
        pos = [(float(c[0] - w_ / 2), float(c[1] - H_MIN_LABEL / 2), 0.0)
               for c in (ds + t * dirv for t in (2.5, 3.5, 4.5))]
        f.label(txt_, d, H_MIN_LABEL, within=within, dirs=_dirs_towards(dirv)[:5], dists=(1.0, 2.5), priority=2,
                positions=pos, optional=True)
    # the book's bounding lines A and B/C
    for L in zn.lines:
        p0 = np.array(L.point) * k
        dd = np.array(L.direction)
        f.line(p0 - span * dd, p0 + span * dd, "Тонкие")
        # name near where it is inside the window, towards its upper end
        for t in np.linspace(span, -span, 400):
            q = np.array(f.p(*(p0 + t * dd)))
            if window[0] + 6 < q[0] < window[2] - 6 and window[1] + 6 < q[1] < window[3] - 6:
                sh.label(L.name, q, H_LABEL, within=within, priority=3)
                break
    # B0, O, the book's vertex, r0, e or the pivot
    sh.dot(f.p(0, 0), 0.8)
    f.label("B_0", (0, 0), H_LABEL, within=within, dirs=("se", "e", "sw", "ne", "w"), priority=9)
    _cross(sh, f.p(*O), 4.0)
    f.label("O", O, H_LABEL, within=within, dirs=("se", "sw", "ne", "nw", "e", "w"), priority=9)
    ro = np.array(f.p(*O))
    rb0 = np.array(f.p(0, 0))
    dvec = ro - rb0
    nrm = np.array([-dvec[1], dvec[0]]) / (np.hypot(*dvec) or 1.0)
    if nrm[0] < 0:
        nrm = -nrm
    sh.line(rb0, ro, "Основные")
    sh.dim_linear(rb0, ro, nrm * 10.0, f"r_{{0}} = {_n(z.r0_m * k, lang, 2)}", H_LABEL, within=within, priority=8)
    if np.hypot(*(BV - O)) * fac > 2.0 and window[0] < f.p(*BV)[0] < window[2] and window[1] < f.p(*BV)[1] < window[3]:
        sh.circle(f.p(*BV), 1.2, "Тонкие")
        f.label("O_{" + tr(lang, "b") + "}", BV, H_MIN_LABEL, within=within, priority=4)
    if piv is not None:
        _pivot(sh, f.p(*piv))
        f.label("C", piv, H_LABEL, within=within, dirs=("ne", "nw", "e", "w", "n"), priority=9)
        f.line(piv, (0.0, 0.0), "Основные")
        sh.dim_linear(ro, f.p(*piv), _unit_normal(f.p(*piv), ro, away=np.array(f.p(0, 0))) * 10.0,
                      f"l_{{OC}} = {_n(z.l_oc_m * k, lang, 2)}", H_LABEL, within=within, priority=8)
    elif abs(z.e_m) * k * fac > 0.5:
        # e: from the follower's axis (x = 0) to O, horizontal, below O
        a = np.array(f.p(0.0, O[1]))
        sh.dim_linear(a, ro, (0.0, -12.0), f"e = {_n(z.e_m * k, lang, 2)}", H_LABEL, within=within, priority=8)
    # ν at the extreme positions of the rise and of the return: the ray D_i O at the pressure
    # angle the profile carries there (the core's ν), against the follower direction −u
    for phase in ("rise", "return"):
        cand = [row for row in r.motion.table if row.phase == phase]
        if not cand:
            continue
        row = max(cand, key=lambda rw: p.nu_deg[_profile_index(p, rw.phi_deg)])
        nu_i = float(p.nu_deg[_profile_index(p, row.phi_deg)])
        mask = rise if phase == "rise" else ret
        idx = np.nonzero(mask)[0]
        i = idx[_table_index(zn.phi[idx], row.phi_deg)]
        d, u = D[i], zn.u[i]
        lo_len = 0.3 * float(np.hypot(*(O - d)))
        f.line(d, O, "Штриховые")
        f.line(d, d - lo_len * u, "Основные")
        a1 = math.degrees(math.atan2(-u[1], -u[0]))
        a2 = math.degrees(math.atan2(*(O - d)[::-1]))
        lo_a, hi_a = sorted((a1, a2))
        if hi_a - lo_a > 180:
            lo_a, hi_a = hi_a, lo_a + 360
        rr = max(8.0, 0.6 * lo_len * fac)
        sh.dim_arc(f.p(*d), rr, lo_a, hi_a, f"ν_{{{row.index}}} = {_n(nu_i, lang, 1)}°", H_MIN_LABEL, within=within,
                   priority=7)
    # caption under the drawing
    txt = [
        f"ν_{{max}} = {num(v.nu_max_deg, lang, sig=6)}°;  r_{{0}} = {_n(z.r0_m * k, lang, 2)} {mm};  "
        + (f"l_{{OC}} = {_n(z.l_oc_m * k, lang, 2)} {mm};  l_{{BC}} = {num(v.l_bc_m * k, lang, sig=6)} {mm}"
           if z.rocker else f"e = {_n(z.e_m * k, lang, 2)} {mm}"),
        tr(lang, "Hatched: the centres with ν ≤ ν_{max} at every position (the wedges at D_{i})"),
        tr(lang, "O_b — the book's vertex: r_0 = {v} mm").format(v=_n(z.book_r0_m * k, lang, 2)),
    ]
    if zn.lines:  # the letters on the drawing said (a norm-controller marks a letter never defined)
        txt.insert(2, tr(lang, "{names} — the textbook's lines at ν_{{max}} (§1.3), meeting at O_b").format(
            names=", ".join(L.name for L in zn.lines)))
    if not fit.fits:
        txt[-1] += tr(lang, " (the construction is cut at the field's edge)")
    numbers = {str(i) for i, *_ in nums}

    def caption():
        """The caption, written once the labels are placed: it names the position numbers left out."""
        left = sorted((t for t in sh.omitted if t in numbers), key=int)
        lines = list(txt)
        if left:
            lines.append(tr(lang, "Positions {list} are not marked").format(list=", ".join(left)))
        sh.caption(box[2] - ZONE_CAP_W if beside else box[0], box[2], box[1] + 2.5, lines, H_NOTE, LINE)

    return f, caption


def _export_extent(sh: Sheet, f, lo, hi) -> None:
    """What the zone needs at any scale, appended to the field's XDATA after a tag "extent": the
    window at scale 1 (its own units: lower-left and upper-right corners), then the paper room
    [mm] (width, height) its margins, heading and captions add — captions under the drawing, then
    beside it —, then the least width with the captions under it. A reader can tell what a larger
    scale would need: extent × scale + room."""
    from .paper import XDATA_APP

    rooms = [np.array(_zone_need((0.0, 0.0), 0.0, side)) for side in (False, True)]
    rooms[0][0] = ZONE_MARGIN[0] + ZONE_MARGIN[2] + 2.0  # under: as wide as the drawing and its margins …
    for e in sh.msp:
        if e.has_xdata(XDATA_APP):
            tags = [(t.code, t.value) for t in e.get_xdata(XDATA_APP)]
            if tags[0][1] == f.name:  # … but at least ZONE_MIN_W (its captions)
                e.set_xdata(XDATA_APP, tags + [(1000, "extent")]
                            + [(1040, float(v)) for v in (*lo, *hi, *rooms[0], *rooms[1], ZONE_MIN_W)])
                return


def _unit_normal(a, b, away):
    """The unit normal of the segment a–b pointing away from the point `away`."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    d = b - a
    n = np.array([-d[1], d[0]]) / (np.hypot(*d) or 1.0)
    if (np.asarray(away, float) - (a + b) / 2) @ n > 0:
        n = -n
    return n


def _field_scale_text(sh, f, lang, lab):
    """The field's scale under its heading (ГОСТ 2.316: «М 1:2»)."""
    x0, y0, x1, y1 = f.inner
    sh.text((x0 + x1) / 2, y1 - 1.0, _m(lang, lab), H_LABEL, align="center", valign="top")
    f.inner = (x0, y0, x1, y1 - 1.0 - H_LABEL - 1.5 - 2.0)


def _hatch(f, poly, spacing, through=None):
    """The zone hatched at 45° in thin lines `spacing` (drawing units) apart, cut to the field's
    window: one HATCH entity of the standard pattern ANSI31 (a CAD user can edit or re-scale it;
    LINEs before) at the pattern scale that gives the drawn spacing, its boundary the cut polygon.
    The lines it draws go into the sheet's index of lines, so labels keep clear of them.

    With `through` (the chosen centre O, a corner of the zone) the lines run at 45° or 135°, whichever
    enters the zone from O (else along the corner's bisector: ГОСТ 2.306 turns the hatching when 45°
    does not suit), and one of them starts at O: the pattern's own definition, its base point O (the
    hatching used to begin up to 2,4 mm from O, which looked outside the zone)."""
    x0, y0, x1, y1 = f.cut
    lo = (np.array([x0, y0]) - f.origin) / f.scale
    hi = (np.array([x1, y1]) - f.origin) / f.scale
    for a, c in (((-1.0, 0.0), -lo[0]), ((1.0, 0.0), hi[0]), ((0.0, -1.0), -lo[1]), ((0.0, 1.0), hi[1])):
        poly = _clip_half(poly, np.array(a), c)
        if len(poly) < 3:
            return
    sh = f.sheet
    pts = [(float(x), float(y)) for x, y in f.to_sheet(poly)]
    step = spacing * f.scale  # [sheet mm]
    hatch = sh.msp.add_hatch(color=256, dxfattribs={"layer": "Тонкие"})
    hatch.paths.add_polyline_path(pts, is_closed=True)
    d = np.array([1.0, 1.0]) / math.sqrt(2)
    q = np.asarray(pts)
    start = None
    if through is not None:
        p = np.asarray(f.to_sheet(np.asarray([through], float))[0], float)
        d = _hatch_direction(q, p, d)
        start = float(p @ np.array([-d[1], d[0]]))
        angle = math.degrees(math.atan2(d[1], d[0]))
        off = step * np.array([-d[1], d[0]])
        hatch.set_pattern_fill("TMM_ZONE", scale=1.0, definition=[
            [angle, (float(p[0]), float(p[1])), (float(off[0]), float(off[1])), []]])
    else:
        hatch.set_pattern_fill("ANSI31", scale=step / ANSI31_SPACING)
    # the pattern's lines, for the index of what is drawn (labels avoid them)
    for a_, b_ in hatch_chords(q, d, step, start):
        sh.obstacles.add_polyline(np.array([a_, b_]))


def _hatch_direction(q: np.ndarray, p: np.ndarray, d: np.ndarray) -> np.ndarray:
    """45°, 135° or the bisector of the corner of polygon `q` nearest `p`: the first whose line
    through p enters the polygon."""
    centroid = q.mean(axis=0)
    j = int(np.argmin(np.hypot(*(q - p).T)))
    e1, e2 = q[j - 1] - q[j], q[(j + 1) % len(q)] - q[j]
    bis = e1 / max(float(np.hypot(*e1)), 1e-300) + e2 / max(float(np.hypot(*e2)), 1e-300)
    bis = bis / max(float(np.hypot(*bis)), 1e-300)
    h = 1e-3 * float(np.ptp(q, axis=0).max())
    for cand in (d, np.array([-1.0, 1.0]) / math.sqrt(2), bis):
        if any(_inside(q, p + sgn * h * cand + 1e-9 * (centroid - p)) for sgn in (1.0, -1.0)):
            return cand
    return d


def hatch_chords(q: np.ndarray, d: np.ndarray, step: float, start: float | None = None):
    """The chords of polygon `q` cut by the lines along `d`, `step` apart: from half a step in, or
    through the offset `start` (a line through a corner counts)."""
    n = np.array([-d[1], d[0]])
    proj = q @ n
    if start is None:
        offsets = np.arange(proj.min() + step / 2, proj.max(), step)
    else:
        k0 = math.floor((proj.min() - start) / step)
        offsets = start + step * np.arange(k0, math.ceil((proj.max() - start) / step) + 1)
        offsets = offsets[(offsets >= proj.min() - 1e-12) & (offsets <= proj.max() + 1e-12)]
    tol = 1e-6 * float(np.ptp(q, axis=0).max())
    out = []
    for c in offsets:
        hits = []
        for a, b in zip(q, np.roll(q, -1, axis=0)):
            pa, pb = a @ n - c, b @ n - c
            if abs(pa) <= tol:
                hits.append(a)
            elif pa * pb < 0 and abs(pb) > tol:
                hits.append(a + pa / (pa - pb) * (b - a))
        if len(hits) >= 2:
            hits = sorted(hits, key=lambda h: h @ d)
            if float(np.hypot(*(hits[-1] - hits[0]))) > tol:
                out.append((hits[0], hits[-1]))
    return out


def _inside(poly: np.ndarray, q: np.ndarray) -> bool:
    """Whether q is inside the convex polygon (either orientation)."""
    e = np.roll(poly, -1, axis=0) - poly
    w = q - poly
    cr = e[:, 0] * w[:, 1] - e[:, 1] * w[:, 0]
    return bool(np.all(cr >= -1e-12) or np.all(cr <= 1e-12))


ANSI31_SPACING = 3.175  # mm between the lines of ANSI31 at pattern scale 1 (1/8")


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
    """A fixed pivot: a small circle with a hatched ground under it (ГОСТ 2.770)."""
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


def _profile_factor(r) -> float:
    """Paper mm per real mm of the profile: the core's drawing scale (CamResult.drawing)."""
    return 0.001 / r.drawing.k_sk


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


def _outline_radius(r, fac) -> float:
    p = r.profile
    return (float(np.hypot(*p.pitch.T).max()) + p.roller_m) * 1000.0 * fac


def _psi_arcs(r, fac) -> list[tuple[int, float, float, float]]:
    """(j, lo, hi, radius [paper mm]) of the ψ arcs: each just outside the cam (and the rocker's
    pivot circle) over its own angles, so that a small side of the cam keeps its arc close."""
    p = r.profile
    P = p.pitch
    ang = np.degrees(np.arctan2(P[:, 1], P[:, 0]))
    rad = (np.hypot(*P.T) + p.roller_m) * 1000.0 * fac
    out = []
    for j, lo, hi in _psi_spans(r):
        sel = ((ang - (lo - 8.0)) % 360.0) <= (hi - lo + 16.0)
        big = float(rad[sel].max()) if sel.any() else float(rad.max())
        if p.pivot_path is not None:
            big = max(big, r.sizing.l_oc_m * 1000.0 * fac + 6.0)
        out.append((j, lo, hi, big + PROFILE_RING))
    return out


def _local_radius(r, fac, ray, half_deg=6.0) -> float:
    """[paper mm] The cam's outline radius (pitch curve + roller) around the direction `ray`."""
    ang, rad = _polar(r.profile)
    a0 = math.degrees(math.atan2(ray[1], ray[0]))
    sel = np.abs(((ang - a0) + 180.0) % 360.0 - 180.0) <= half_deg
    return float(rad[sel].max() if sel.any() else rad.max()) * 1000.0 * fac


_POLAR: dict = {}


def _polar(p):
    """The pitch curve's polar angles [deg] and outline radii (+ roller) [m], computed once a profile."""
    key = id(p)
    got = _POLAR.get(key)
    if got is None or got[0] is not p:
        P = p.pitch
        got = (p, np.degrees(np.arctan2(P[:, 1], P[:, 0])), np.hypot(P[:, 0], P[:, 1]) + p.roller_m)
        _POLAR.clear()  # one profile at a time (a sheet); no growth over a batch
        _POLAR[key] = got
    return got[1], got[2]


def _scale_rays(r) -> list[np.ndarray]:
    """Unit vectors from O to the tangent points C_i of the follower's axis at the table positions
    (translating follower; the roller centre when the offset is nil): the angle scale."""
    p = r.profile
    if p.pivot_path is not None:
        return []
    out = []
    for row in r.motion.table:
        i = _profile_index(p, row.phi_deg)
        b, u = p.pitch[i], p.axis_dir[i]
        foot = b - (b @ u) * u
        at = foot if np.hypot(*foot) > 1e-3 * np.hypot(*b) else b
        out.append(at / (np.hypot(*at) or 1.0))
    return out


def _profile_extent(r, fac: float) -> tuple[np.ndarray, np.ndarray]:
    """Lower-left and upper-right corners [paper mm, O at 0] of everything the field draws: the
    construction box of the core, the ψ arcs with their labels, the angle scale."""
    p = r.profile
    x0, x1, y0, y1 = (c * 1000.0 * fac for c in r.drawing.construction_bbox_m)
    pts = [np.array([[x0 - 8.0, y0 - 8.0], [x1 + 8.0, y1 + 8.0]])]
    big = _outline_radius(r, fac)
    for j, lo, hi, rr in _psi_arcs(r, fac):
        t = np.radians(np.linspace(lo, hi, 30))
        pts.append(np.column_stack([(rr + PROFILE_PAD) * np.cos(t), (rr + PROFILE_PAD) * np.sin(t)]))
    for ray in _scale_rays(r):  # the angle scale's ticks and their numbers
        q = ray * (_local_radius(r, fac, ray) + 6.0)
        pts.append(np.array([q - 8.0, q + 8.0]))
    if p.pivot_path is not None:
        pp = p.pivot_path * 1000.0 * fac
        pts.append(np.vstack([pp - 10.0, pp + 10.0]))
    a = np.vstack(pts)
    return a.min(axis=0), a.max(axis=0)


def profile_layout(r, box=None) -> tuple[str, float, tuple[float, float]]:
    """The profile field's scale and the sheet position of O: the core's drawing scale
    (``r.drawing``), the construction centred in the field."""
    box = box or layout(r).profile
    fac = _profile_factor(r)
    lo, hi = _profile_extent(r, fac)
    x0, y0, x1, y1 = box
    cap = 2.5 + LINE * 2 + 2.0
    top = y1 - 16.0
    mid = (lo + hi) / 2
    return gost_label(fac), fac, ((x0 + x1) / 2 - mid[0], (y0 + cap + top) / 2 - mid[1])


def profile_scale(r) -> tuple[str, float]:
    """The profile field's ГОСТ 2.302 scale (label, paper mm per real mm): the core's."""
    lab, f, _ = profile_layout(r)
    return lab, f


def _profile_field(sh: Sheet, r, lang: str, box):
    v, z, p, d = r.variant, r.sizing, r.profile, r.drawing
    k = 1000.0
    name, fac, (cx, cy) = profile_layout(r, box)
    f = sh.add_field("profile", box, tr(lang, "Cam profile synthesis"),
                     origin=(cx, cy), scale=fac, scale_label=name)
    _field_scale_text(sh, f, lang, name)
    x0b, y0b, x1b, y1b = f.inner
    f.clip = (x0b, y0b + 2.5 + LINE * 2, x1b, y1b)
    n_before = len(list(sh.msp))
    within = f.clip
    P = p.pitch * k
    n = len(p.phi) - 1
    r0 = z.r0_m * k
    rp = p.roller_m * k
    big = float(np.hypot(*P.T).max()) + rp
    # axes of the cam and the circles
    f.line((-1.08 * big, 0), (1.08 * big, 0), "Осевые")
    f.line((0, -1.08 * big), (0, 1.08 * big), "Осевые")
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
    o_s = np.array(f.p(0, 0))
    big_p = big * fac
    # the inverted follower at every table position: the roller, the follower's axis (tangent to
    # the offset circle at C_i) or the rocker C_i B_i; the angle scale: a ray from O through C_i
    # (the division of the working angle against the rotation) with the position's number i′
    rays = _scale_rays(r)
    for j_row, row in enumerate(r.motion.table):
        i = _profile_index(p, row.phi_deg)
        b = P[i]
        f.circle(b, rp, "Тонкие")
        if p.pivot_path is not None:  # the pivot positions C_i divide the pivot circle: the scale
            c = p.pivot_path[i] * k
            f.line(c, b, "Тонкие")
            sh.dot(f.p(*c), 0.6)
            ray = c / (np.hypot(*c) or 1.0)
            end = np.array(f.p(*c))
        else:
            u = p.axis_dir[i]
            foot = b - (b @ u) * u  # the tangent point C_i on the offset circle
            f.line(foot, b + u * (rp + 4.0 / fac), "Тонкие")
            ray = rays[j_row]
            rl = _local_radius(r, fac, ray)
            end = o_s + ray * (rl + 6.0)
            # the division point C_i of the angle scale, and its ray out to the number i′ (the book's
            # inversion: the follower's axis at position i is the tangent at C_i, drawn above)
            c_i = o_s + ray * float(np.hypot(*foot)) * fac
            if np.hypot(*foot) * fac > 0.5:
                sh.dot(c_i, 0.4)
            sh.line(c_i, end, "Тонкие")
        sh.label(f"{row.index}′", end, H_MIN_LABEL, within=within, dirs=_dirs(ray), dists=(0.8, 2.0, 3.5), priority=4)
    # centre O, the pivot C_0 (rocker) with the rocker in the start position
    _cross(sh, o_s, 5.0)
    sh.label("O", o_s, H_LABEL, within=within, dirs=("se", "sw", "ne", "nw"), dists=(1.5, 3.0, 5.0), priority=9)
    if p.pivot_path is not None:
        c0 = p.pivot_path[0] * k
        _pivot(sh, f.p(*c0))
        f.label("C_0", c0, H_LABEL, within=within, dirs=("ne", "nw", "e", "w", "n"), priority=9)
        f.line(c0, P[0], "Основные")
    # profile angles ψ as arcs outside the cam, between rays from O (the core's values)
    names = (tr(lang, "ψ_{r}"), tr(lang, "ψ_{fd}"), tr(lang, "ψ_{ret}"))  # the book's symbols in Russian
    vals = (p.psi_rise_deg, p.psi_far_deg, p.psi_return_deg)
    for j, lo_a, hi_a, rr in _psi_arcs(r, fac):
        for a in (lo_a, hi_a):
            e = np.array([math.cos(math.radians(a)), math.sin(math.radians(a))])
            sh.line(o_s + e * (rr - 8.0), o_s + e * (rr + 2.5), "Тонкие")
        sh.dim_arc(o_s, rr, lo_a, hi_a, f"{names[j]} = {_n(vals[j], lang, 1)}°", H_MIN_LABEL, within=within, priority=6)
    # rotation of the cam
    e_abs = 0.0 if p.pivot_path is not None else abs(z.e_m) * k
    rr = (0.45 * r0 if e_abs < 0.3 * r0 else 0.5 * (e_abs + r0)) * fac
    a0, a1 = 200.0, 250.0
    sh.arc(o_s, rr, a0, a1, "Основные")
    e = math.radians(a1 if v.ccw else a0)
    tip = o_s + (rr * math.cos(e), rr * math.sin(e))
    tang = np.array([-math.sin(e), math.cos(e)]) * (1 if v.ccw else -1)
    sh.arrow(tip, tang, "Основные", 3.5, 1.2)
    qm = o_s + (rr * math.cos(math.radians(225)), rr * math.sin(math.radians(225)))
    sh.label(tr(lang, "ω_{c}"), qm, H_LABEL, within=within, dirs=("sw", "w", "s", "nw", "se"),
             priority=7)
    # captions: k_Sk and the roller; the scale is the core's (the note states the same)
    txt = [f"k_{{Sk}} = {_g(d.k_sk, lang)} " + tr(lang, "m/mm") + ";  " + tr(lang, "r_{r}") + f" = {_roller_text(p, lang)}"]
    if not d.fits:
        scale = d.scale if lang == "ru" else d.scale.replace(",", ".")
        txt.append(tr(lang, "({scale}: beyond Table 1.1, the cam is too large for 1:10)").format(scale=scale))
    # under the profile it describes (not at the foot of the field): the drawing's lowest point
    ext = _extents_lxb(list(sh.msp)[n_before:])
    y_cap = box[1] + 2.5
    xa, xb = box[0], box[2]
    if ext is not None:
        y_cap = max(y_cap, ext[1] - 3.0 - H_NOTE - LINE * (len(txt) - 1))
        xa, xb = max(box[0], ext[0] - 2.0), min(box[2], max(ext[2], ext[0] + 200.0) + 2.0)
    sh.caption(xa, xb, y_cap, txt, H_NOTE, LINE)
    return f


def _extents_lxb(entities):
    """(x_min, y_min, x_max) of ezdxf's exact bounding box of `entities` (``bbox.extents(…,
    fast=False)``; None when empty), asking ezdxf only about the entities that can reach an extreme:
    each entity's box is bounded from outside (its points grown by its width and 0.05 mm for the
    flattening of a curve) and from inside (points the exact box surely holds: ends and vertices);
    an entity whose outer bound cannot reach past the best inner bound of all cannot hold the
    extreme. The same numbers as the whole call, at a fraction of its time (it flattens every
    curve and traces every wide polyline)."""
    from ezdxf import bbox as _bbox

    tol = 0.05
    rows = []  # (entity, outer (x0, y0, x1, y1) or None: always asked, inner (x0, y0, x1, y1))
    for e in entities:
        kind = e.dxftype()
        outer = inner = None
        ext = e.dxf.get("extrusion", (0.0, 0.0, 1.0))
        if abs(ext[0]) < 1e-12 and abs(ext[1]) < 1e-12 and ext[2] > 0:
            if kind == "LINE":
                a, b = e.dxf.start, e.dxf.end
                inner = (min(a.x, b.x), min(a.y, b.y), max(a.x, b.x), max(a.y, b.y))
                outer = (inner[0] - tol, inner[1] - tol, inner[2] + tol, inner[3] + tol)
            elif kind == "LWPOLYLINE" and len(e) > 0:
                pts = np.asarray(e.get_points("xyseb"), float)
                grow = max(float(np.abs(pts[:, 2:4]).max()), abs(e.dxf.get("const_width", 0.0))) / 2 + tol
                if np.any(pts[:, 4] != 0.0):  # an arc segment bulges by at most half its chord
                    grow += float(np.hypot(*np.diff(np.vstack([pts[:, :2], pts[:1, :2]]), axis=0).T).max()) / 2
                lo, hi = pts[:, :2].min(axis=0), pts[:, :2].max(axis=0)
                inner = (float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1]))
                outer = (inner[0] - grow, inner[1] - grow, inner[2] + grow, inner[3] + grow)
            elif kind in ("CIRCLE", "ARC"):
                c, rad = e.dxf.center, e.dxf.radius
                outer = (c.x - rad - tol, c.y - rad - tol, c.x + rad + tol, c.y + rad + tol)
                if kind == "ARC":
                    a, b = e.start_point, e.end_point
                    inner = (min(a.x, b.x), min(a.y, b.y), max(a.x, b.x), max(a.y, b.y))
            elif kind == "SOLID":
                v = [e.dxf.get(f"vtx{i}") for i in range(4)]
                v = [q for q in v if q is not None]
                inner = (min(q.x for q in v), min(q.y for q in v), max(q.x for q in v), max(q.y for q in v))
                outer = (inner[0] - tol, inner[1] - tol, inner[2] + tol, inner[3] + tol)
        rows.append((e, outer, inner))
    if not rows:
        return None
    inners = [i for _, _, i in rows if i is not None]
    if inners:
        bx0 = min(i[0] for i in inners)  # the exact box reaches at least this far
        by0 = min(i[1] for i in inners)
        bx1 = max(i[2] for i in inners)
    else:
        bx0 = by0 = math.inf
        bx1 = -math.inf
    ask = [e for e, o, _ in rows if o is None or o[0] <= bx0 or o[1] <= by0 or o[2] >= bx1]
    got = _bbox.extents(ask, fast=False)
    if not got.has_data:
        return None
    return (got.extmin.x, got.extmin.y, got.extmax.x)


def _dirs(v) -> tuple[str, ...]:
    from .paper import _dirs_towards

    return _dirs_towards(v)[:5]


# ----------------------------------------------------------------------------------------------
# field 4: pressure angle


def _pressure_field(sh: Sheet, r, lang: str, box):
    v, m, p, z = r.variant, r.motion, r.profile, r.sizing
    sc = m.scales
    heading = tr(lang, "Pressure angle against cam position")
    hh = sh.heading_height(heading, box[2] - box[0])
    x0b, y0b = box[0] + 1.0, box[1] + 1.0
    xo = x0b + 22.0
    yo = y0b + 2.5 + LINE * 2 + 12.0
    phw = v.phi_working_deg
    keep = np.degrees(p.phi) <= phw + 1e-9
    nu = p.nu_deg[keep]
    top = max(float(nu.max()), v.nu_max_deg)
    room = box[3] - hh - yo - 16.0
    k_nu = nice_scale(top / room)  # °/mm, a round drawing scale
    # the field ends just above its plot (the ordinate's arrow at yo + top/k_nu + 10): the heading
    # stands over the diagram it names, not over the room a round k_ν leaves unused
    box = (box[0], box[1], box[2], min(box[3], yo + top / k_nu + 10.0 + 4.0 + hh))
    f = sh.add_field("pressure", box, heading)
    xs = xo + np.degrees(p.phi[keep]) / sc.k_phi_deg_mm
    _axis(sh, f.inner, xo, yo, sc.b_mm, top / k_nu, 0.0, "φ", "ν")
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
    sh.label(f"ν_{{max}} = {num(v.nu_max_deg, lang, sig=6)}°", (xo + sc.b_mm, ym), H_MIN_LABEL, within=f.inner,
             dirs=("nw", "sw", "n", "s", "w"), priority=7)
    rows = [row for row in m.table]
    xr = [xo + row.phi_deg / sc.k_phi_deg_mm for row in rows]
    for x in xr:
        sh.line((x, yo), (x, yo - 1.5), "Тонкие")
    _numbers_below(sh, f.inner, rows, xr, yo - 1.5)
    # ticks on the ν axis every 10°
    for t in range(10, int(top) + 1, 10):
        y = yo + t / k_nu
        sh.line((xo - 1.5, y), (xo, y), "Тонкие")
        sh.label(f"{t}", (xo - 1.5, y), H_MIN_LABEL, within=f.inner, dirs=("w",), dists=(1.0, 2.0), leader=False,
                 priority=6)
    lab = [tr(lang, "k_ν = {k_nu} °/mm;  k_φ = {k_phi_deg_mm} °/mm").format(k_nu=_g(k_nu, lang), k_phi_deg_mm=_g(sc.k_phi_deg_mm, lang)),
           tr(lang, "max ν: rise {nu_rise_max_deg}°, return {nu_return_max_deg}°").format(nu_rise_max_deg=_n(z.nu_rise_max_deg, lang, 1), nu_return_max_deg=_n(z.nu_return_max_deg, lang, 1))]
    if z.closure == "force":
        lab[1] += tr(lang, " (spring: return not limited)")
    sh.caption(box[0], box[2], box[1] + 2.5, lab, H_NOTE, LINE)
    return f


# ----------------------------------------------------------------------------------------------
# the results table


def table(sh: Sheet, box, title: str, rows: list[tuple[str, str]], col1: float = 0.58, h=H_NOTE):
    """A two-column table (quantity, value) with a heading, in thin lines, a thick outline."""
    x0, y0, x1, y1 = box
    sh.add_field("table", box, title)
    top = y1 - 12.0
    row_h = min(9.0, (top - y0) / max(len(rows), 1))
    bottom = top - row_h * len(rows)
    xm = x0 + col1 * (x1 - x0)
    sh.rect(x0, bottom, x1, top, "Основные")
    sh.line((xm, bottom), (xm, top), "Основные")
    for j, (a, b) in enumerate(rows):
        y = top - (j + 1) * row_h
        if j < len(rows) - 1:
            sh.line((x0, y), (x1, y), "Тонкие")
        hh = min(h, row_h - 3.0)
        sh.text(x0 + 2.0, y + row_h / 2 - 0.3, a, hh, valign="middle", width=xm - x0 - 4.0, height_max=row_h - 2.0,
                max_lines=2, min_h=min(hh, 3.5) if hh >= 3.5 else hh)
        sh.text((xm + x1) / 2, y + row_h / 2 - 0.3, b, hh, align="center", valign="middle", width=x1 - xm - 4.0,
                height_max=row_h - 2.0, max_lines=2, min_h=min(hh, 3.5) if hh >= 3.5 else hh)
    return bottom


def _roller_text(p, lang: str) -> str:
    """The carried roller and the rule that gave it (the core's ``roller_rule``); the book's
    0.2·r_0 beside it when the roller differs from it."""
    mm = tr(lang, "mm")
    val = f"{_n(p.roller_m * 1000.0, lang)} {mm}"
    sign = "," if lang == "ru" else "."  # the decimal sign
    book = f"0{sign}2·r_{{0}}"
    if p.roller_rule == "book":
        return f"{val} ({book})"
    rule = {"limited": f"0{sign}8·ρ_{{min}}", "student": tr(lang, "given")}.get(p.roller_rule, p.roller_rule)
    return f"{val} ({rule}; {book} = {_n(p.roller_book_m * 1000.0, lang)})"


def _results_rows(r) -> int:
    return 9 if r.sizing.rocker else 8


def _results(sh: Sheet, r, lang: str, box, prof_scale: str) -> None:
    v, z, p, sc = r.variant, r.sizing, r.profile, r.motion.scales
    k = 1000.0
    mm = tr(lang, "mm")
    rows = [
        # r_0 is the base radius of the pitch (theoretical) profile, as the book names it (§1.3)
        (tr(lang, "Base radius of the pitch profile r_0"), f"{_n(z.r0_m * k, lang)} {mm}"),
    ]
    if z.rocker:
        rows += [(tr(lang, "Centre distance l_{OC}"), f"{_n(z.l_oc_m * k, lang)} {mm}"),
                 (tr(lang, "Rocker length l_{BC}"), f"{_n(v.l_bc_m * k, lang)} {mm}")]
    else:
        rows.append((tr(lang, "Offset e"), f"{_n(z.e_m * k, lang)} {mm}"))
    rows += [
        (tr(lang, "Roller radius r_{r}"), _roller_text(p, lang)),
        (tr(lang, "Pressure angle ν_{max} (given / reached)"),
         f"{num(v.nu_max_deg, lang, sig=6)}° / {_n(max(z.nu_rise_max_deg, z.nu_return_max_deg if z.closure == 'form' else 0), lang, 1)}°"),
        (tr(lang, "Profile angles ψ"),
         f"{_n(p.psi_rise_deg, lang, 1)}°; {_n(p.psi_far_deg, lang, 1)}°; {_n(p.psi_return_deg, lang, 1)}°"),
        (tr(lang, "Scales k_{S}, k_{V}, k_{a}") if not z.rocker
         else tr(lang, "Scales k_{γ}, k_{ω}, k_{ε}"),
         "; ".join(_g(x, lang) + " " + u for x, u in zip(
             (sc.k_s, sc.k_v, sc.k_a), (tr(lang, "rad/mm"), tr(lang, "(rad/s)/mm"), tr(lang, "(rad/s²)/mm")) if z.rocker
             else (tr(lang, "m/mm"), tr(lang, "(m/s)/mm"), tr(lang, "(m/s²)/mm"))))),
        (tr(lang, "Profile scale (k_{Sk})"), _m(lang, prof_scale)),
        (tr(lang, "Closure, follower"),
         (tr(lang, "force closure") if z.closure == "force" else tr(lang, "form closure")) + ", "
         + (tr(lang, "rocker") if z.rocker else tr(lang, "translating"))),
    ]
    table(sh, box, tr(lang, "Main results"), rows)


def sheet3(result, lang: str, title) -> Sheet:
    """Build sheet 3 for a CamResult (no file written)."""
    sh = Sheet(lang)
    sh.frame()
    lay = layout(result)
    _motion_field(sh, result, lang, lay.motion)
    _pressure_field(sh, result, lang, lay.pressure)
    prof = _profile_field(sh, result, lang, lay.profile)
    _, zone_caption = _zone_field(sh, result, lang, lay.zone, lay.zone_caption_beside)
    _results(sh, result, lang, lay.table, prof.scale_label)
    v = result.variant
    sh.title_block(title, name=tr(lang, "Cam mechanism synthesis"),
                   designation=title.designation_for(3, v.number), scale=prof.scale_label)
    sh.place_labels()
    zone_caption()  # below the labels' room: it names the numbers they left out
    sh.finish()
    return sh
