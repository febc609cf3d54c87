"""Sheet 4 figures: the reducer's kinematic scheme with its velocity pictures, the assembly
picture, and the spur mesh with true involute teeth.

matplotlib is imported inside the functions (``tmm --help`` stays instant) and only through
``matplotlib.figure.Figure`` (no pyplot, no global state: batch runs draw in worker processes).
"""

from __future__ import annotations

import math

import numpy as np

from ...i18n import ntr, tr, trc
from ...i18n.numbers import num
from .kit import (
    bottom_legend,
    decimal_commas,
    fmt,
    hide_axis,
    legend_height,
    mt,
    new_figure,
    offset_places,
    settle,
    suptitle,
    title_height,
)

C_SUN = "#1f77b4"
C_PLANET = "#d62728"
C_CARRIER = "#2ca02c"
C_RING = "#444444"
C_STAGE2 = ("#9467bd", "#ff7f0e", "#17becf")


# ----------------------------------------------------------------------------------------------
# involute tooth outlines


def _flank_half_angle(r: np.ndarray, rb: float, psi: float) -> np.ndarray:
    """Half angle of a zero-gear tooth at radius r: ψ + inv α − inv α_r (radial below r_b)."""
    alpha = math.acos(rb / (rb / math.cos(math.radians(20.0))))  # = 20°, kept explicit
    inv_a = math.tan(alpha) - alpha
    rr = np.maximum(r, rb)
    ar = np.arccos(rb / rr)
    return psi + inv_a - (np.tan(ar) - ar)


def tooth_outline(z: int, m: float, ha: float = 1.0, c: float = 0.25, fillet: float = 0.38,
                  alpha_deg: float = 20.0, n: int = 40, x: float = 0.0, ra: float | None = None) -> np.ndarray:
    """One tooth of a gear, centred on the +x axis, from the middle of the space
    below it to the middle of the space above it: root arc, fillet of radius 0.38·m (§2.1.1),
    flank (involute above the base circle, radial below it), tip arc, and back. Returns (N, 2).
    A shifted gear (beyond the book) takes its shift ``x`` and its real tip radius ``ra``."""
    r = m * z / 2
    rb = r * math.cos(math.radians(alpha_deg))
    ra = r + ha * m if ra is None else ra
    rf = r - (ha + c - x) * m
    rho = fillet * m
    psi = (math.pi / 2 + 2 * x * math.tan(math.radians(alpha_deg))) / z
    alpha = math.radians(alpha_deg)
    inv_a = math.tan(alpha) - alpha

    def half(rad):
        rad = np.asarray(rad, dtype=float)
        rr = np.maximum(rad, rb)
        ar = np.arccos(np.clip(rb / rr, -1, 1))
        return psi + inv_a - (np.tan(ar) - ar)

    # dense flank from r_f to r_a (upper flank: angle +half(r))
    rs = np.linspace(rf, ra, 400)
    fx, fy = rs * np.cos(half(rs)), rs * np.sin(half(rs))
    space_mid = math.pi / z
    rc = rf + rho

    def gap(phi):
        cx, cy = rc * math.cos(phi), rc * math.sin(phi)
        d = np.hypot(fx - cx, fy - cy)
        j = int(np.argmin(d))
        return d[j] - rho, j

    lo, hi = float(half(rf)), space_mid
    if gap(hi)[0] < 0:  # space too narrow for two full fillets: they meet in the middle
        phi_c = hi
    else:
        for _ in range(50):
            mid = (lo + hi) / 2
            if gap(mid)[0] < 0:
                lo = mid
            else:
                hi = mid
        phi_c = hi
    _, j_t = gap(phi_c)
    cx, cy = rc * math.cos(phi_c), rc * math.sin(phi_c)
    a_start = math.atan2(fy[j_t] - cy, fx[j_t] - cx)
    a_end = math.atan2(-math.sin(phi_c), -math.cos(phi_c))  # towards the root circle
    da = (a_end - a_start + math.pi) % (2 * math.pi) - math.pi
    arc_a = a_start + np.linspace(0, 1, 12) * da
    fil = np.column_stack([cx + rho * np.cos(arc_a), cy + rho * np.sin(arc_a)])
    # upper half: tip arc (0 → half(ra)), flank down to the tangent point, fillet, root arc
    tip_t = np.linspace(0, float(half(ra)), 8)
    tip = np.column_stack([ra * np.cos(tip_t), ra * np.sin(tip_t)])
    flank = np.column_stack([fx[j_t:][::-1], fy[j_t:][::-1]])
    root_phi = math.atan2(fil[-1, 1], fil[-1, 0])
    root_t = np.linspace(root_phi, space_mid, 6)
    root = np.column_stack([rf * np.cos(root_t), rf * np.sin(root_t)])
    upper = np.vstack([tip, flank, fil, root])
    lower = upper[::-1] * np.array([1, -1])
    return np.vstack([lower, upper])


def gear_outline(z: int, m: float, centre=(0.0, 0.0), rot: float = 0.0, **kw) -> np.ndarray:
    """Closed outline of a whole zero gear with one tooth centred at angle ``rot`` [rad]."""
    t = tooth_outline(z, m, **kw)
    pts = []
    for j in range(z):
        a = rot + 2 * math.pi * j / z
        ca, sa = math.cos(a), math.sin(a)
        pts.append(t @ np.array([[ca, sa], [-sa, ca]]))
    p = np.vstack(pts + [pts[0][:1]])
    return p + np.asarray(centre)


def _drawn_outline(outline, z: int, centre, rot: float, m: float, window=None):
    """(line, area): what of a whole gear's outline (z teeth of equal length, as gear_outline
    gives it) a picture needs, for speed only: the same pixels from fewer vertices.

    Whole gear (`window` None): a vertex every m/40 along the outline (a fraction of a pixel at
    the sizes drawn). Zoomed (`window` = ((x0, x1), (y0, y1)) not holding the centre): only the
    teeth seen through the window and one more on each side, the area closed through the centre
    (its radial edges lie outside the window). The full outline has 720 vertices a tooth.
    """
    if window is None:
        seg = np.hypot(*np.diff(outline, axis=0).T)
        s = np.concatenate([[0.0], np.cumsum(seg)])
        _, keep = np.unique(np.floor(s / (m / 40)), return_index=True)
        keep = np.union1d(keep, [len(outline) - 1])
        thin = outline[keep]
        return thin, thin
    (x0, x1), (y0, y1) = window
    cx, cy = float(centre[0]), float(centre[1])
    pad = 0.1 * max(x1 - x0, y1 - y0)
    if x0 - pad <= cx <= x1 + pad and y0 - pad <= cy <= y1 + pad:
        return outline, outline
    towards = math.atan2((y0 + y1) / 2 - cy, (x0 + x1) / 2 - cx)
    corners = [math.atan2(y - cy, x - cx) - towards for x in (x0, x1) for y in (y0, y1)]
    corners = [(a + math.pi) % (2 * math.pi) - math.pi for a in corners]
    tau = 2 * math.pi / z
    lo, hi = min(corners) - 1.5 * tau, max(corners) + 1.5 * tau
    n = (len(outline) - 1) // z  # vertices of one tooth
    teeth = []
    for j in range(z):
        d = (rot + j * tau - towards + math.pi) % (2 * math.pi) - math.pi
        if lo <= d <= hi:
            teeth.append((d, j))
    if len(teeth) >= z - 1:
        return outline, outline
    line = np.vstack([outline[j * n:(j + 1) * n] for _, j in sorted(teeth)])
    area = np.vstack([[[cx, cy]], line, [[cx, cy]]])
    return line, area


# ----------------------------------------------------------------------------------------------
# the mesh


def _shift_kw(g, idx: int) -> dict:
    """tooth_outline's shift and real tip radius for gear ``idx`` of a shifted pair ({} for the zero pair)."""
    if not getattr(g, "shifted", False):
        return {}
    return {"x": (g.x1, g.x2)[idx - 1], "ra": (g.da1_mm, g.da2_mm)[idx - 1] / 2}


def _shift_title(g, lang: str) -> str:
    """", x1 = …, x2 = …, a_w = …" for a shifted pair (beyond the book), "" for the zero pair."""
    if not getattr(g, "shifted", False):
        return ""
    return (f"\nx1 = {num(g.x1, lang, sig=4)}, x2 = {num(g.x2, lang, sig=4)}, a_w = {num(g.a_w_mm, lang, sig=5)}, "
            f"α_w = {num(g.alpha_w_deg, lang, sig=4)}°")


def _mesh_geometry(g, motor_sense: str = "cw"):
    """Centres, pole, the unit vector u of the line of action from N1 to N2, N1, and s ↦ point.

    Gear 1 (on the motor, centre O1 below) drives. The line of action is the one along which
    its working flanks push: the pitch-point velocity of gear 1 has a positive component along u,
    so contact runs P1 → P2 (from gear 2's tip circle to gear 1's). Gear 1 turning clockwise
    (top moving right) gives the line rising to the right; counter-clockwise, its mirror image.
    """
    a = g.a_w_mm or g.a_mm  # the working centre distance (= a for the book's zero pair)
    al = math.radians(g.alpha_w_deg)
    r1 = g.d1_mm / 2 * math.cos(math.radians(g.alpha_deg)) / math.cos(al)  # working radius (= r1 when zero)
    o1, o2 = np.array([0.0, 0.0]), np.array([0.0, a])
    p = np.array([0.0, r1])
    sx = 1.0 if motor_sense == "cw" else -1.0
    u = np.array([sx * math.cos(al), math.sin(al)])
    n1 = p - g.pole_mm * u

    def at(s):
        return n1 + s * u
    return o1, o2, p, u, n1, at


def _rotation_arrow(ax, centre, radius, sense, mid_deg, color, label):
    """A curved arrow of 70° about ``centre`` showing the sense of rotation ('cw'/'ccw')."""
    sgn = 1.0 if sense == "ccw" else -1.0
    t = np.radians(mid_deg + sgn * np.linspace(-35.0, 35.0, 40))
    x, y = centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t)
    ax.plot(x[:-1], y[:-1], color=color, lw=1.6)
    ax.annotate("", (x[-1], y[-1]), xytext=(x[-3], y[-3]),
                arrowprops=dict(arrowstyle="-|>,head_length=0.7,head_width=0.35", color=color, lw=1.6,
                                shrinkA=0, shrinkB=0))
    m = math.radians(mid_deg)
    ax.annotate(label, (centre[0] + radius * math.cos(m), centre[1] + radius * math.sin(m)),
                xytext=(10 * math.cos(m), 10 * math.sin(m)), textcoords="offset points", color=color, fontsize=10,
                fontweight="bold", ha="left" if math.cos(m) > 0.2 else ("right" if math.cos(m) < -0.2 else "center"),
                va="bottom" if math.sin(m) > 0.2 else ("top" if math.sin(m) < -0.2 else "center"))


def _sense_text(sense, lang):
    return (trc(lang, "figure, short", "counter-clockwise") if sense == "ccw" else trc(lang, "figure, short", "clockwise"))


def pair_names(text: str) -> str:
    """The mesh's segments in a (translated) text with the book's subscripts: «P1U2, U1P2» →
    «$P_1U_2$, $U_1P_2$» (mathtext: a plain «P1U2» read as one word).

    >>> pair_names("zones P1U2, U1P2; U2U1")
    'zones $P_1U_2$, $U_1P_2$; $U_2U_1$'
    """
    import re

    return re.sub(r"\b([NPU])([12])([NPU])([12])\b", r"$\1_\2\3_\4$", text)


def point_name(name: str) -> str:
    """A point's name as the book writes it, its digit a subscript: N1 → $N_1$, P → $P$.

    >>> point_name("N1"), point_name("P"), point_name("O2")
    ('$N_1$', '$P$', '$O_2$')
    """
    return f"${name[0]}_{{{name[1:]}}}$" if len(name) > 2 else f"${name[0]}_{name[1]}$" if len(name) == 2 else f"${name}$"


def _draw_mesh(ax, g, lang, zoom: bool, motor_sense: str = "cw"):
    from matplotlib.patches import Arc, Polygon

    o1, o2, p, u, n1, at = _mesh_geometry(g, motor_sense)
    sx = 1.0 if u[0] > 0 else -1.0  # the mirror of the picture for a motor turning counter-clockwise
    m = g.m_mm
    # gear 1 tooth on the line of centres at P; gear 2 a space there
    rot1, rot2 = math.pi / 2, -math.pi / 2 + math.pi / g.z2
    g1 = gear_outline(g.z1, m, o1, rot=rot1, **_shift_kw(g, 1))
    g2 = gear_outline(g.z2, m, o2, rot=rot2, **_shift_kw(g, 2))
    half = min(max(1.25 * g.g_alpha_mm, 0.6 * g.n1n2_mm * math.cos(math.radians(g.alpha_w_deg))),
               2.2 * g.g_alpha_mm)  # the zoomed window: P ± half across, ± 0.85 half up and down
    window = ((p[0] - half, p[0] + half), (p[1] - 0.85 * half, p[1] + 0.85 * half)) if zoom else None
    # add_artist, not fill(): fill() updates the data limits vertex by vertex through Bezier
    # extrema (0.4 s per gear); the outlines plotted beside them set the limits anyway
    for gg, centre, z, rot, col, alpha in ((g1, o1, g.z1, rot1, C_SUN, 0.18), (g2, o2, g.z2, rot2, C_PLANET, 0.15)):
        line, area = _drawn_outline(gg, z, centre, rot, m, window)
        ax.add_artist(Polygon(area, closed=True, color=col, alpha=alpha, lw=0))
        ax.plot(line[:, 0], line[:, 1], color=col, lw=1.0)
    styles = (("d", "-", 0.9), ("d_b", "--", 0.8), ("d_a", ":", 0.8), ("d_f", "-.", 0.8))
    t = np.linspace(0, 2 * math.pi, 721)
    for (centre, col, d, db, da, df, idx) in ((o1, C_SUN, g.d1_mm, g.db1_mm, g.da1_mm, g.df1_mm, 1),
                                              (o2, C_PLANET, g.d2_mm, g.db2_mm, g.da2_mm, g.df2_mm, 2)):
        for (name, ls, lw), dia in zip(styles, (d, db, da, df)):
            ax.plot(centre[0] + dia / 2 * np.cos(t), centre[1] + dia / 2 * np.sin(t), ls=ls, lw=lw, color=col, alpha=0.8)
        if getattr(g, "shifted", False):  # the working circle d_w of a shifted pair (beyond the book)
            dw = g.pair.dw_mm[idx - 1]
            ax.plot(centre[0] + dw / 2 * np.cos(t), centre[1] + dw / 2 * np.sin(t), ls=(0, (1, 2)), lw=1.0, color="k",
                    alpha=0.6)
        ax.plot(*centre, "o", color=col, ms=4)
        ax.annotate(point_name(f"O{idx}"), centre, xytext=(6, 4), textcoords="offset points", color=col, fontsize=10)
    ax.plot([o1[0], o2[0]], [o1[1], o2[1]], color="0.4", lw=0.7, ls=(0, (8, 3, 2, 3)))
    # line of action and its points
    s_pts = {"N1": 0.0, "P1": g.p1_mm, "U2": g.u2_mm, "P": g.pole_mm, "U1": g.u1_mm, "P2": g.p2_mm, "N2": g.n1n2_mm}
    ext = 0.12 * g.n1n2_mm
    a0, a1 = at(-ext), at(g.n1n2_mm + ext)
    ax.plot([a0[0], a1[0]], [a0[1], a1[1]], color="k", lw=0.8)
    # zones: double P1U2, single U2U1, double U1P2
    for s0, s1, col, lw in ((g.p1_mm, g.u2_mm, "#ff7f0e", 5), (g.u2_mm, g.u1_mm, "#2ca02c", 5),
                            (g.u1_mm, g.p2_mm, "#ff7f0e", 5)):
        q0, q1 = at(s0), at(s1)
        ax.plot([q0[0], q1[0]], [q0[1], q1[1]], color=col, lw=lw, alpha=0.75, solid_capstyle="butt")
    # foot perpendiculars O1N1, O2N2
    n2 = at(g.n1n2_mm)
    ax.plot([o1[0], n1[0]], [o1[1], n1[1]], color=C_SUN, lw=0.7)
    ax.plot([o2[0], n2[0]], [o2[1], n2[1]], color=C_PLANET, lw=0.7)
    fs = 10 if zoom else 8
    pts = np.array([at(s) for s in s_pts.values()])
    ax.plot(pts[:, 0], pts[:, 1], "o", color="k", ms=3.5 if zoom else 2.5, zorder=5)  # one line of seven markers
    # the names as the book writes them (N₁, P₂, U₁ …), each on the side of the line of action where it
    # hides no other name and least of the drawing (kit.settle places them once the figure is drawn):
    # first across the line, the two ends' names beyond their ends
    nrm = np.array([-u[1], u[0]])
    across = [tuple(nrm), tuple(-nrm), tuple((nrm + u) / np.hypot(*(nrm + u))), tuple((nrm - u) / np.hypot(*(nrm - u))),
              tuple((-nrm + u) / np.hypot(*(-nrm + u))), tuple((-nrm - u) / np.hypot(*(-nrm - u)))]
    for name, s in s_pts.items():
        q = at(s)
        if zoom or name in ("N1", "N2", "P"):
            dirs = across + ([tuple(-u)] if name == "N1" else [tuple(u)] if name == "N2" else [])
            if name in ("N1", "N2"):
                dirs = dirs[-1:] + dirs[:-1]
            places = offset_places(dirs, 5.0) + offset_places(dirs, 10.0)
            t = ax.annotate(point_name(name), q, xytext=places[0]["xyann"], textcoords="offset points", fontsize=fs,
                            ha=places[0]["ha"], va=places[0]["va"], zorder=6)
            t._tmm_places = places
    # α_w: between the tangent to the pitch circles at P (horizontal) and the line of action
    if zoom:
        rr = 0.6 * g.g_alpha_mm
        th0, th1 = (0.0, g.alpha_w_deg) if sx > 0 else (180.0 - g.alpha_w_deg, 180.0)
        ax.add_patch(Arc(tuple(p), 2 * rr, 2 * rr, theta1=th0, theta2=th1, color="k", lw=0.9))
        ax.plot([p[0], p[0] + sx * 1.3 * rr], [p[1], p[1]], color="k", lw=0.7, ls="--")
        mid = math.radians(g.alpha_w_deg / 2)
        # beside its arc, below the tangent, or past the arc's end: where it covers no name and least
        # of the drawing (kit.settle); the arc's end on the line of action is where N₂ and P₂ stand
        side = "left" if sx > 0 else "right"
        places = [{"xyann": (sx * d, dy), "ha": side, "va": va} for d, dy, va in
                  ((10, -3, "center"), (4, -6, "top"), (18, -6, "top"), (10, 6, "bottom"), (30, -3, "center"))]
        t = ax.annotate(mt(f"α_w = {num(g.alpha_w_deg, lang, sig=4)}°"), (p[0] + sx * rr * math.cos(mid), p[1] + rr * math.sin(mid)),
                        xytext=places[0]["xyann"], textcoords="offset points", fontsize=fs, ha=side, va="center",
                        bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.8), zorder=6)
        t._tmm_places = places
        # the active profile parts (double line in the book): radii of P1 from O1 and P2 from O2
        r_p1_on_1 = float(np.hypot(*(at(g.p1_mm) - o1)))
        r_p2_on_2 = float(np.hypot(*(at(g.p2_mm) - o2)))
        # only the working flanks: those meeting along this line of action — the clockwise side of
        # each tooth of either gear when gear 1 turns clockwise, the other side otherwise
        for gg, centre, rmin, rmax, col, axis0, z in (
                (g1, o1, r_p1_on_1, g.da1_mm / 2, C_SUN, rot1, g.z1),
                (g2, o2, r_p2_on_2, g.da2_mm / 2, C_PLANET, rot2, g.z2)):
            rad = np.hypot(gg[:, 0] - centre[0], gg[:, 1] - centre[1])
            near = np.hypot(gg[:, 0] - p[0], gg[:, 1] - p[1]) < 1.15 * g.p_mm
            tau = 2 * math.pi / z
            delta = np.arctan2(gg[:, 1] - centre[1], gg[:, 0] - centre[0]) - axis0
            delta = delta - tau * np.floor(delta / tau + 0.5)
            sel = (rad >= rmin - 1e-6) & (rad <= rmax - 0.02 * m) & near & (sx * delta < 0)
            pts = np.where(sel[:, None], gg, np.nan)
            ax.plot(pts[:, 0], pts[:, 1], color=col, lw=2.6)
        ax.set_xlim(*window[0])
        ax.set_ylim(*window[1])
    ax.set_aspect("equal")


def _mesh_figure(result, lang):
    from matplotlib.lines import Line2D

    g = result.spur
    f = fmt(lang)
    W, H = 15.0, 8.2
    fig = new_figure(W, H)
    bottom = legend_height(8, 4, 9) + 0.45
    gs = fig.add_gridspec(1, 2, width_ratios=[1, 1.25], left=0.55 / W, right=1 - 0.1 / W, bottom=bottom / H,
                          top=1 - title_height(2, 10.5) / H, wspace=0.1)
    ax0 = fig.add_subplot(gs[0])
    ax1 = fig.add_subplot(gs[1])
    dirs = result.directions
    _draw_mesh(ax0, g, lang, zoom=False, motor_sense=dirs.motor)
    _draw_mesh(ax1, g, lang, zoom=True, motor_sense=dirs.motor)
    # senses of rotation: motor (gear 1) and cam (gear 2), opposite in an external mesh
    _rotation_arrow(ax0, (0.0, 0.0), 0.45 * g.d1_mm / 2, dirs.motor, 235.0, C_SUN, "ω1")
    _rotation_arrow(ax0, (0.0, g.a_w_mm or g.a_mm), 0.45 * g.d2_mm / 2, dirs.cam, 55.0, C_PLANET, "ω2")
    ax0.set_title(tr(lang, "Spur pair z1 = {z1}, z2 = {z2}, m = {m_mm} mm, a = {a_mm} mm{g}\nω1: motor ({motor}), ω2: cam ({cam})").format(z1=g.z1, z2=g.z2, m_mm=f(g.m_mm), a_mm=f(g.a_mm), g=_shift_title(g, lang), motor=_sense_text(dirs.motor, lang), cam=_sense_text(dirs.cam, lang)),
                  fontsize=10.5, y=1.0)
    zone = (f"ε_α = P1P2/p_b = {f(g.g_alpha_mm, decimals=1)}/{f(g.pb_mm, decimals=2)} = {f(g.eps_alpha, decimals=3)};  "
            f"φ_α1 = {f(g.phi_alpha1_deg, decimals=2)}°, φ_α2 = {f(g.phi_alpha2_deg, decimals=2)}°")
    ax1.set_title(pair_names(mt(tr(lang, "Mesh zone: ") + zone)), fontsize=11, y=1.0)
    for ax in (ax0, ax1):
        ax.set_xlabel(tr(lang, "mm"))
        ax.grid(alpha=0.15)
    handles = [
        Line2D([], [], color="0.3", ls="-", label=mt(tr(lang, "pitch circle d"))),
        Line2D([], [], color="0.3", ls="--", label=mt(tr(lang, "base circle d_b"))),
        Line2D([], [], color="0.3", ls=":", label=mt(tr(lang, "tip circle d_a"))),
        Line2D([], [], color="0.3", ls="-.", label=mt(tr(lang, "root circle d_f"))),
        Line2D([], [], color="k", lw=0.8, label=pair_names(tr(lang, "line of action N1N2"))),
        Line2D([], [], color="#ff7f0e", lw=5, alpha=0.75, label=pair_names(tr(lang, "double-pair zones P1U2, U1P2"))),
        Line2D([], [], color="#2ca02c", lw=5, alpha=0.75, label=pair_names(trc(lang, "figure, short", "single-pair zone U2U1"))),
        Line2D([], [], color=C_SUN, lw=2.6, label=tr(lang, "active profiles")),
    ]
    bottom_legend(fig, handles, [h.get_label() for h in handles], ncol=4, fontsize=9)
    settle(fig)
    return fig


# ----------------------------------------------------------------------------------------------
# the planetary reducer: kinematic scheme + velocity pictures


def _gear_bar(ax, x, y0, y1, col, lw=2.2, tick=0.9, internal=False):
    """A gear in a kinematic scheme: a bar across its pitch diameter with short end ticks."""
    ax.plot([x, x], [y0, y1], color=col, lw=lw, solid_capstyle="butt")
    for y in (y0, y1):
        ax.plot([x - tick, x + tick], [y, y], color=col, lw=lw)


def _scheme(ax, result, lang):
    d = result.planetary
    x = 0.0
    span = []
    labels = []
    stage_cols = [(C_SUN, C_PLANET, C_CARRIER), C_STAGE2]
    rmax = max(max(s.z_ring / 2, (s.z_sun + 2 * s.z_planet) / 2) for s in d.stages)
    gap = 0.09 * rmax
    shaft_in0 = -0.22 * rmax
    prev_out = shaft_in0
    for j, s in enumerate(d.stages):
        ck, cc, ch_col = stage_cols[j]
        rk, rc, rc2, rn = s.z_sun / 2, s.z_planet / 2, s.zc2 / 2, s.z_ring / 2
        rC = rk + rc
        xk = x + gap
        x_c2 = xk + (gap if s.z_planet2 is not None else 0.0)
        xH = x_c2 + gap
        suffix = str(j + 1) if len(d.stages) > 1 else ""
        for sg in (1, -1):
            # sun
            _gear_bar(ax, xk, -rk if sg > 0 else -rk, rk, ck) if sg > 0 else None
            # planet c (meshes with the sun) and c′ (with the ring)
            _gear_bar(ax, xk, sg * rk, sg * (rk + 2 * rc), cc)
            if s.z_planet2 is not None:
                _gear_bar(ax, x_c2, sg * (rC - rc2), sg * (rC + rc2), cc)
            # planet axle and carrier arm
            ax.plot([xk - 0.4 * gap, xH], [sg * rC, sg * rC], color=ch_col, lw=1.6)
            ax.plot([xH, xH], [0, sg * rC], color=ch_col, lw=1.6)
            # ring, fixed: bar from r_n outwards with ground hatching
            x_ring = x_c2
            ax.plot([x_ring, x_ring], [sg * rn, sg * (rn + 0.08 * rmax)], color=C_RING, lw=2.2)
            ax.plot([x_ring - 0.9, x_ring + 0.9], [sg * rn, sg * rn], color=C_RING, lw=2.2)
            yb = sg * (rn + 0.08 * rmax)
            ax.plot([x_ring - 0.05 * rmax, x_ring + 0.05 * rmax], [yb, yb], color=C_RING, lw=1.2)
            for hx in np.linspace(x_ring - 0.05 * rmax, x_ring + 0.04 * rmax, 5):
                ax.plot([hx, hx + 0.02 * rmax], [yb, yb + sg * 0.03 * rmax], color=C_RING, lw=0.8)
        # input shaft to the sun (from the motor or from the previous carrier)
        ax.plot([prev_out, xk], [0, 0], color=ck, lw=3.0)
        prev_out = xH
        labels += [(xk, rk * 0.55, f"k{suffix}", ck), (xk, rk + 0.6 * rc, f"c{suffix}", cc),
                   (xH, rC * 0.5, f"H{suffix}", ch_col), (x_ring - 0.05 * rmax, rn + 0.06 * rmax, f"n{suffix}", C_RING)]
        if s.z_planet2 is not None:
            labels.append((x_c2, rC + rc2 * 0.45, f"c′{suffix}", cc))
        span.append((xk, x_c2, xH))
        x = xH
    ax.plot([prev_out, prev_out + 0.25 * rmax], [0, 0], color=C_CARRIER if len(d.stages) == 1 else C_STAGE2[2], lw=3.0)
    for (lx, ly, text, col) in labels:
        ax.annotate(text, (lx, ly), xytext=(-6, 0), textcoords="offset points", color=col, fontsize=11,
                    fontweight="bold", va="center", ha="right")
    ax.plot([shaft_in0 - 0.05 * rmax, prev_out + 0.3 * rmax], [0, 0], color="0.5", lw=0.7, ls=(0, (10, 3, 2, 3)))
    ax.annotate(tr(lang, "from the motor"), (shaft_in0, 0), xytext=(0, 8), textcoords="offset points",
                fontsize=9)
    # over the output shaft, from the carrier's arm or ending at the shaft's end, else under it:
    # inside the panel (kit.settle; it touched the border)
    end = prev_out + 0.25 * rmax
    places = [{"xy": (prev_out, 0), "xyann": (4, 6), "ha": "left", "va": "bottom"},
              {"xy": (end, 0), "xyann": (0, 6), "ha": "right", "va": "bottom"},
              {"xy": (prev_out, 0), "xyann": (4, -6), "ha": "left", "va": "top"},
              {"xy": (end, 0), "xyann": (0, -6), "ha": "right", "va": "top"}]
    t = ax.annotate(tr(lang, "to the crank"), places[0]["xy"], xytext=places[0]["xyann"], textcoords="offset points",
                    fontsize=9, ha="left", va="bottom")
    t._tmm_places = places
    ax.set_xlim(shaft_in0 - 0.1 * rmax, prev_out + 0.35 * rmax)
    ax.set_ylim(-1.3 * rmax, 1.3 * rmax)
    ax.set_ylabel(tr(lang, "radius r = z/2, modules"))
    hide_axis(ax.xaxis)
    teeth = "  +  ".join(
        ", ".join(f"{n} = {v}" for n, v in zip(("z_k", "z_c", "z_c′", "z_n") if s.z_planet2 is not None else ("z_k", "z_c", "z_n"), s.teeth))
        + f", k = {s.planets}" for s in d.stages)
    ax.set_title(mt(tr(lang, "Scheme {scheme}: {teeth}").format(scheme=d.scheme, teeth=teeth)), fontsize=10, y=1.0)


def _velocity(ax, result, lang, ylim):
    v = result.checks.velocity
    d = result.planetary
    cols = [(C_SUN, C_PLANET, C_CARRIER), C_STAGE2]
    vmax = max(max(s.v_a for s in v.stages), 1e-9)
    named = []  # (v, r, name): points of the picture; coinciding points share one label
    for j, (s, st) in enumerate(zip(v.stages, d.stages)):
        ck, cc, chc = cols[j]
        suf = str(j + 1) if len(v.stages) > 1 else ""
        ax.plot([0, s.v_a], [0, s.r_a], color=ck, lw=1.8)
        # planet block: from its lowest to its highest radius
        r_lo = s.r_a
        r_hi = max(s.r_b, s.r_a + 2 * s.r_planet)
        slope = s.v_a / (s.r_a - s.r_b)
        ax.plot([slope * (r_lo - s.r_b), slope * (r_hi - s.r_b)], [r_lo, r_hi], color=cc, lw=1.8)
        ax.plot([0, s.v_c], [0, s.r_c], color=chc, lw=1.8)
        # the vectors V_A and V_C, drawn from the vertical (radius) axis as in the book
        for vx, ry in ((s.v_a, s.r_a), (s.v_c, s.r_c)):
            ax.annotate("", (vx, ry), xytext=(0, ry), arrowprops=dict(arrowstyle="-|>", color="0.35", lw=0.8,
                                                                      shrinkA=0, shrinkB=0))
        named += [(s.v_a, s.r_a, f"A{suf}"), (s.v_c, s.r_c, f"C{suf}"), (0.0, s.r_b, f"B{suf}")]
        last = j == len(v.stages) - 1
        if j == 0:  # a later stage's sun turns with the carrier before it: one line, one label
            ax.annotate(f"k{suf}", (0.7 * s.v_a, 0.7 * s.r_a), xytext=(4, -12), textcoords="offset points",
                        color=ck, fontsize=10, fontweight="bold")
        if last:
            ax.annotate(f"H{suf}", (0.8 * s.v_c, 0.8 * s.r_c), xytext=(-6, 2), textcoords="offset points", color=chc,
                        fontsize=10, fontweight="bold", ha="right")
        else:  # right of the line, below the next sun's point A and below this stage's arrow V_A
            r_lab = min(0.45 * s.r_c, s.r_a)
            ax.annotate(f"H{suf} = k{j + 2}", (s.v_c * r_lab / s.r_c, r_lab), xytext=(6, -3),
                        textcoords="offset points", color=chc, fontsize=10, fontweight="bold", ha="left", va="top")
        # the planet's label between A and C (C is the midpoint of AB in a single row: keep off it)
        r_lab = s.r_a + 0.5 * (s.r_c - s.r_a)
        ax.annotate(f"c{suf}", (slope * (r_lab - s.r_b), r_lab), xytext=(6, 0),
                    textcoords="offset points", color=cc, fontsize=10, fontweight="bold", va="center")
        # over the middle of its arrow (beside A it sat on the planet's line rising from A)
        ax.annotate(mt(f"V_A{suf}"), (0.5 * s.v_a, s.r_a), xytext=(0, 2), textcoords="offset points", fontsize=8,
                    ha="center", va="bottom")
    groups: list[list] = []
    tol = 1e-6 * max(1.0, vmax)
    for vx, ry, name in named:
        for gr in groups:
            if abs(gr[0] - vx) < tol and abs(gr[1] - ry) < tol:
                gr[2].append(name)
                break
        else:
            groups.append([vx, ry, [name]])
    for vx, ry, names in groups:
        ax.plot(vx, ry, "o", color="k", ms=3.5)
        left = names == ["B2"]  # the two rings can differ by one tooth: B2 left of the axis, B1 right
        ax.annotate(" = ".join(names), (vx, ry), xytext=(-5, 3) if left else (5, 3), textcoords="offset points",
                    fontsize=9, ha="right" if left else "left")
    s0, sl = v.stages[0], v.stages[-1]
    from matplotlib.patches import Arc

    r_arc = 0.4 * min(math.hypot(s0.v_a, s0.r_a), math.hypot(sl.v_c, sl.r_c))
    ax.add_patch(Arc((0, 0), 2 * r_arc, 2 * r_arc, theta1=90 - s0.phi_k_deg, theta2=90, color=C_SUN, lw=1))
    ax.add_patch(Arc((0, 0), 2.7 * r_arc, 2.7 * r_arc, theta1=90 - sl.phi_h_deg, theta2=90,
                     color=C_CARRIER if len(v.stages) == 1 else C_STAGE2[2], lw=1))
    # the angle labels left of the radius axis, at the top of their arcs (the picture is on the right)
    ax.annotate(mt("φ_k"), (0, r_arc), xytext=(-4, 0), textcoords="offset points", fontsize=9, color=C_SUN,
                ha="right", va="center")
    ax.annotate(mt("φ_H"), (0, 1.35 * r_arc), xytext=(-4, 0), textcoords="offset points", fontsize=9,
                color=C_CARRIER if len(v.stages) == 1 else C_STAGE2[2], ha="right", va="center")
    ax.plot([0, 0], [0, ylim[1]], color="k", lw=0.8)
    ax.axhline(0, color="0.5", lw=0.7, ls=(0, (10, 3, 2, 3)))
    vmin = min(min(s.v_a / (s.r_a - s.r_b) * (max(s.r_b, s.r_a + 2 * s.r_planet) - s.r_b) for s in v.stages), 0)
    ax.plot([min(vmin * 1.2, -0.1 * vmax), vmax * 1.35], [0, 0], alpha=0)  # x data extent
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(tr(lang, "linear velocity (drawing units)"))
    ax.set_xticks([])
    ratios = " · ".join(num(s.ratio, lang, sig=4) for s in v.stages)
    ax.set_title(mt(tr(lang, "Linear velocities: i = tg φ_k/tg φ_H = {ratios}; below: angular velocities").format(ratios=ratios)),
                 fontsize=10, y=1.0)
    ax.tick_params(axis="y", labelleft=False)


def _angular(ax, result, lang, y0: float):
    """The angular-velocity picture: rays from the pole P parallel to each link's velocity line
    cut the horizontal line (at y0) in k, c, h; i = ok/oh (2.3)."""
    v = result.checks.velocity
    h = v.pole
    cols = [(C_SUN, C_PLANET, C_CARRIER), C_STAGE2]
    pts = []
    for j, s in enumerate(v.stages):
        ck, cc, chc = cols[j]
        suf = str(j + 1) if len(v.stages) > 1 else ""
        tk = math.tan(math.radians(s.phi_k_deg))
        th = math.tan(math.radians(s.phi_h_deg))
        tc = -s.v_a / (s.r_b - s.r_a)
        if j == 0:
            pts.append((h * tk, f"k{suf}", ck))
        pts.append((h * tc, f"c{suf}", cc))
        last = j == len(v.stages) - 1
        pts.append((h * th, f"h{suf}" if last else f"h{suf} = k{j + 2}", chc))
    xs = [p[0] for p in pts]
    # labels above the line; one that would run into its left neighbour goes below it
    span = max(xs + [0]) - min(xs + [0])
    prev_x, prev_up, prev_name = None, False, ""
    for xv, name, col in sorted(pts, key=lambda p: p[0]):
        ax.plot([0, xv], [y0 - h, y0], color=col, lw=1.4)
        ax.plot(xv, y0, "o", color=col, ms=4)
        room = 0.0225 * span * (len(prev_name) + len(name))  # two centred labels of these lengths touch
        up = not (prev_x is not None and prev_up and xv - prev_x < room)
        ax.annotate(name, (xv, y0), xytext=(0, 6) if up else (0, -8), textcoords="offset points", ha="center",
                    va="bottom" if up else "top", color=col, fontsize=10, fontweight="bold")
        prev_x, prev_up, prev_name = xv, up, name
    ax.plot([min(xs + [0]) - 0.05 * h, max(xs) + 0.05 * h], [y0, y0], color="k", lw=0.9)
    ax.plot(0, y0 - h, "ko", ms=4)
    ax.annotate("P", (0, y0 - h), xytext=(6, -4), textcoords="offset points", fontsize=10)
    ax.annotate("o", (0, y0), xytext=(-10, 6), textcoords="offset points", fontsize=10)
    f = fmt(lang)
    ratio = f"i = ok/oh = {f(v.ok, decimals=1)}/{f(v.oh, decimals=2)} = {f(v.ratio, sig=4)}"
    # centred under the picture (from the pole rightwards the Russian caption reached the figure's edge)
    ax.annotate(tr(lang, "angular velocities: {ratio}").format(ratio=ratio),
                (0.5, y0 - h), xycoords=("axes fraction", "data"), xytext=(0, -18), textcoords="offset points",
                fontsize=9.5, ha="center")


def _checks_text(fig, box, result, lang):
    """The ratio checks as lines of text in `box` (a figure-fraction Bbox): figure texts placed as
    an axes' texts would be, without an Axes (with its axis, ticks and spines) to carry them."""
    from matplotlib.transforms import BboxTransformTo, TransformedBbox

    place = BboxTransformTo(TransformedBbox(box, fig.transSubfigure))  # what an Axes at `box` calls transAxes
    ch = result.checks
    v = ch.velocity
    d = result.planetary
    f = fmt(lang)
    lines = [tr(lang, "Ratio check"), ""]
    per = " · ".join(f(x, sig=4) for x in ch.ratio_formula_21)
    lines.append("(2.1): i = 1 + z_c·z_n/(z_k·z_c′)"
                 + (f" = {per}" if len(ch.ratio_formula_21) > 1 else "") + f" = {f(ch.ratio_formula_21_total, decimals=4)}")
    for j, s in enumerate(v.stages, 1):
        pre = tr(lang, "stage {j}: ").format(j=j) if len(v.stages) > 1 else ""
        lines.append(f"(2.3): {pre}tg φ_k/tg φ_H = tg {f(s.phi_k_deg, decimals=2)}°/tg {f(s.phi_h_deg, decimals=2)}° = "
                     f"{f(s.ratio, decimals=4)}")
    lines.append(f"(2.3): ok/oh = {f(v.ok, decimals=2)}/{f(v.oh, decimals=3)} = {f(v.ratio, decimals=4)}")
    err = percent(d.ratio_error_pct, lang)
    lines.append(tr(lang, "required i_пл = {i_planetary}, error {err} (±{tolerance_pct} %)").format(i_planetary=f(result.i_planetary, decimals=4), err=err, tolerance_pct=f(result.tolerance_pct)))
    lines.append(ntr(lang, "size max(z_k + 2z_c, z_n) = {size} module; planets k = {planets}",
                     "size max(z_k + 2z_c, z_n) = {size} modules; planets k = {planets}", d.size).format(size=d.size, planets=d.planets))
    # one text per line: mathtext sets a line, not a paragraph
    for i, line in enumerate(lines):
        if line:
            fig.text(0.02, 0.95 - i * 0.13, mt(line), va="top", ha="left", fontsize=10, transform=place,
                     weight="bold" if i == 0 else "normal")


def _planetary_figure(result, lang):
    W, H = 15.0, 10.5
    fig = new_figure(W, H)
    gs = fig.add_gridspec(2, 2, width_ratios=[1.1, 1], height_ratios=[4.2, 1], left=0.75 / W, right=1 - 0.15 / W,
                          bottom=0.02, top=1 - (title_height(1) + title_height(1, 10)) / H, wspace=0.04, hspace=0.1)
    ax_s = fig.add_subplot(gs[0, 0])
    ax_v = fig.add_subplot(gs[0, 1], sharey=ax_s)
    _scheme(ax_s, result, lang)
    ylim = ax_s.get_ylim()
    _velocity(ax_v, result, lang, ylim)
    _angular(ax_v, result, lang, y0=-0.15 * result.checks.velocity.pole)
    ax_s.set_ylim(*ylim)
    # projection lines: the picture's radii are the scheme's radii
    for st in result.checks.velocity.stages:
        for ry in (st.r_a, st.r_c, st.r_b):
            ax_s.axhline(ry, color="0.75", lw=0.6, ls=":", zorder=0)
    _checks_text(fig, gs[1, :].get_position(fig), result, lang)
    f = fmt(lang)
    err = percent(result.planetary.ratio_error_pct, lang)
    suptitle(fig, mt(tr(lang, "Planetary reducer: i_пл = n_д/n_кр = {motor_rpm}/{crank_rpm} = {i_planetary}, realised {ratio} ({err})").format(motor_rpm=result.motor_rpm, crank_rpm=f(result.crank_rpm), i_planetary=f(result.i_planetary, sig=4), ratio=f(result.planetary.ratio, sig=4), err=err)))
    return fig


# ----------------------------------------------------------------------------------------------
# assembly picture


def _assembly_stage(ax, stage, checks, lang, title):
    from matplotlib.patches import Arc, Circle

    rk, rc, rc2, rn = stage.z_sun / 2, stage.z_planet / 2, stage.zc2 / 2, stage.z_ring / 2
    rC = rk + rc
    k = stage.planets
    ax.add_patch(Circle((0, 0), rk, fill=True, color=C_SUN, alpha=0.18))
    ax.add_patch(Circle((0, 0), rk, fill=False, color=C_SUN, lw=1.5))
    ax.add_patch(Circle((0, 0), rn, fill=False, color=C_RING, lw=1.8))
    ax.add_patch(Circle((0, 0), rn + 1.25, fill=False, color=C_RING, lw=0.8, ls=":"))
    ax.add_patch(Circle((0, 0), rC, fill=False, color=C_CARRIER, lw=0.7, ls="--"))
    big = max(rc, rc2)
    for j in range(k):
        th = math.pi / 2 + 2 * math.pi * j / k
        cx, cy = rC * math.cos(th), rC * math.sin(th)
        ax.plot([0, cx], [0, cy], color=C_CARRIER, lw=2.0)
        ax.add_patch(Circle((cx, cy), rc, fill=True, color=C_PLANET, alpha=0.16))
        ax.add_patch(Circle((cx, cy), rc, fill=False, color=C_PLANET, lw=1.3))
        if stage.z_planet2 is not None:
            ax.add_patch(Circle((cx, cy), rc2, fill=False, color="#8c564b", lw=1.3, ls="--"))
        ax.add_patch(Circle((cx, cy), big + 1.0, fill=False, color="0.4", lw=0.6, ls=":"))
        ax.plot(cx, cy, "o", color="k", ms=3)
        # the planet's number beside its centre, on the side away from the carrier arm
        ax.annotate(str(j + 1), (cx, cy), xytext=(12 * math.cos(th - math.pi / 2), 12 * math.sin(th - math.pi / 2)),
                    textcoords="offset points", ha="center", va="center", fontsize=13, fontweight="bold", color="k")
    if k >= 2:
        # the angle 2β between the first two arms, its label outside the arc (a small sun must not
        # hide the arc under the label)
        r_arc = max(0.55 * rk, 0.4 * rC)
        ax.add_patch(Arc((0, 0), 2 * r_arc, 2 * r_arc, theta1=90, theta2=90 + 360 / k, color="k", lw=1.2))
        mid = math.radians(90 + 180 / k)
        ax.annotate(f"2β = {num(360 / k, lang, sig=4)}°", (r_arc * math.cos(mid), r_arc * math.sin(mid)),
                    xytext=(14 * math.cos(mid), 14 * math.sin(mid)), textcoords="offset points",
                    ha="right" if math.cos(mid) < -0.2 else ("left" if math.cos(mid) > 0.2 else "center"),
                    va="bottom" if math.sin(mid) > 0.2 else ("top" if math.sin(mid) < -0.2 else "center"),
                    fontsize=10, bbox=dict(boxstyle="round,pad=0.2", fc="white", ec="none", alpha=0.85))
    ax.plot(0, 0, "k+", ms=8)
    lim = max(rn, rC + big) + 4
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_aspect("equal")
    hide_axis(ax.xaxis, ax.yaxis)
    c = checks
    if stage.z_planet2 is None:
        asm = f"(z_k + z_n)/k = {stage.z_sun + stage.z_ring}/{k} = {num((stage.z_sun + stage.z_ring) / k, lang, sig=4)}"
    else:
        asm = f"(z_k·z_c′ + z_c·z_n)/(k·{c.assembly_g}) = {c.assembly_t}/{k * c.assembly_g} = {num(c.assembly_t / (k * c.assembly_g), lang, sig=4)}"
    nb = f"sin(π/{k}) = {num(c.neighbour_sin, lang, decimals=3)} > {num(c.neighbour_q, lang, decimals=3)}"
    ax.set_title(f"{title}\n{mt(asm)}\n{nb}", fontsize=9.5, y=1.0)


def _assembly_figure(result, lang):
    d = result.planetary
    n = len(d.stages)
    fig = new_figure(7.2 * n + 1.5, 8.4)
    axes = [fig.add_subplot(1, n, j + 1) for j in range(n)]
    for j, (ax, st, ch) in enumerate(zip(axes, d.stages, result.checks.stages)):
        lab = "/".join(map(str, st.teeth))
        title = (tr(lang, "Stage {v}: ").format(v=j + 1) if n > 1 else "") + \
            ntr(lang, "{teeth}, k = {planets} planet", "{teeth}, k = {planets} planets", st.planets).format(teeth=lab, planets=st.planets)
        _assembly_stage(ax, st, ch, lang, title)
    order = tr(lang, "Assembly order: fit planet 1; turn the carrier by 2β = 360°/k (the sun turns by a whole number of teeth, condition (2.4)); fit the next planet in the same place; repeat.")
    import textwrap

    width = int(11 * (7.2 * n + 1.5))  # characters per line that fit the figure at 10.5 pt
    wrapped = textwrap.wrap(order, width)
    suptitle(fig, tr(lang, "Planets placed at 2β = 360°/k") + "\n"
             + "\n".join(wrapped), fontsize=10.5)
    W, H = fig.get_size_inches()
    double = any(st.z_planet2 is not None for st in d.stages)
    top = title_height(1 + len(wrapped), 10.5) + title_height(3, 9.5) + 0.05
    bottom = legend_height(3, 3, 9) if double else 0.1
    fig.subplots_adjust(left=0.15 / W, right=1 - 0.15 / W, bottom=bottom / H, top=1 - top / H, wspace=0.08)
    if double:
        from matplotlib.lines import Line2D

        handles = [Line2D([], [], color=C_PLANET, label=tr(lang, "planet c (row 1, meshes the sun)")),
                            Line2D([], [], color="#8c564b", ls="--", label=tr(lang, "planet c′ (row 2, meshes the ring)")),
                            Line2D([], [], color="0.4", ls=":", label=tr(lang, "tip circle of the larger planet"))]
        bottom_legend(fig, handles, [h.get_label() for h in handles], ncol=3, fontsize=9)
    return fig


def percent(x: float, lang: str) -> str:
    """A signed percentage, "−2,85 %"; one too small to show reads "0,00 %", never "-0.00 %"."""
    text = num(x, lang, decimals=2, minus="−")
    return (text if text.startswith("−") or set(text) <= set("0,.") else "+" + text) + " %"


def gears_figures(result, lang: str, names=None) -> dict:
    """Sheet-4 figures: "gears_planetary", "gears_assembly", "gears_mesh" (matplotlib Figures).

    `names` limits the drawing to some of them (all three by default).
    """
    makers = {"gears_planetary": _planetary_figure, "gears_assembly": _assembly_figure, "gears_mesh": _mesh_figure}
    figs = {name: make(result, lang) for name, make in makers.items() if names is None or name in names}
    for fig in figs.values():
        decimal_commas(fig, lang)
    return figs
