"""The layout and the scales μ of the note's own figures, from the result alone (no matplotlib).

The note's figures are drawn for the page (16,5 cm wide, text ≥ 10 pt at print size) with fixed
axes boxes in millimetres, so each plan and diagram has an exact, round scale: the drawing
(:mod:`.note`) and the note's text (the captions, the segments it quotes) read the same numbers
from here.

A scale is "so much per millimetre of the printed figure": μ_l [m/mm], μ_S [mm/mm], μ_φ [°/mm], …
The planetary reducer is drawn with the module sheet 4 chooses for it (the synthesis gives tooth
numbers only): its μ_l and μ_V are stated with that module.
"""

from __future__ import annotations

import math

from ...records import record

TEXT_WIDTH_MM = 165.0
SERIES = (1.0, 2.0, 2.5, 4.0, 5.0)  # round scale values (ГОСТ 2.302 steps), × 10^k


def nice(x: float, series=SERIES) -> float:
    """The smallest value of `series` (1, 2, 2,5, 4, 5) × 10^k not below x.

    >>> nice(0.43), nice(3.0), nice(2.0), nice(0.0012)
    (0.5, 4.0, 2.0, 0.002)
    """
    if not x > 0:
        return 1.0
    e = math.floor(math.log10(x))
    for k in (e, e + 1):
        for s in series:
            v = s * 10.0 ** k
            if v >= x * (1 - 1e-9):
                return float(f"{v:.6g}")
    return 10.0 ** (e + 1)


@record
class Box:
    """An axes box on the figure [mm from the figure's left and bottom edge]."""

    left: float
    bottom: float
    width: float
    height: float


@record
class Axis:
    """One axis at its scale: the data range [lo, lo + mm·mu] shown on `mm` millimetres."""

    lo: float
    mu: float  # data units per mm
    mm: float

    @property
    def hi(self) -> float:
        return self.lo + self.mu * self.mm


def fit_axis(lo: float, hi: float, mm: float, pad: float = 0.06, keep_zero: bool = True) -> Axis:
    """The round scale that shows [lo, hi] (with a margin) on `mm` millimetres, centred."""
    if keep_zero:
        lo, hi = min(lo, 0.0), max(hi, 0.0)
    span = (hi - lo) or 1.0
    mu = nice(span * (1 + 2 * pad) / mm)
    mid = (lo + hi) / 2
    return Axis(mid - mu * mm / 2, mu, mm)


def fit_plan(xlo: float, xhi: float, ylo: float, yhi: float, w_mm: float, h_mm: float, pad: float = 0.05) -> tuple[Axis, Axis]:
    """One round scale for both axes of a plan (equal aspect), the content centred."""
    sx = (xhi - xlo) * (1 + 2 * pad) / w_mm
    sy = (yhi - ylo) * (1 + 2 * pad) / h_mm
    mu = nice(max(sx, sy, 1e-12))
    cx, cy = (xlo + xhi) / 2, (ylo + yhi) / 2
    return Axis(cx - mu * w_mm / 2, mu, w_mm), Axis(cy - mu * h_mm / 2, mu, h_mm)


# --------------------------------------------------------------------------------------------------
# the figures

MOTION = {"size": (TEXT_WIDTH_MM, 190.0), "x": (17.0, 144.0), "panel": 48.0, "gap": 7.0, "bottom": 13.0}
PRESSURE = {"size": (TEXT_WIDTH_MM, 74.0), "box": Box(17.0, 13.0, 144.0, 56.0)}
PLAN = {"size": (TEXT_WIDTH_MM, 150.0), "box": Box(18.0, 33.0, 143.0, 113.0)}
MESH = {"size": (TEXT_WIDTH_MM, 140.0), "box": Box(18.0, 33.0, 143.0, 103.0)}
PLANETARY = {"size": (TEXT_WIDTH_MM, 178.0), "scheme": Box(4.0, 52.0, 78.0, 122.0), "velocity": Box(86.0, 52.0, 76.0, 122.0),
             "angular": Box(86.0, 4.0, 76.0, 42.0)}
ASSEMBLY_MM = 100.0  # one stage's plan, square (two stages: 76 mm each)
# the lever mechanism's velocity and acceleration plans of the first plan position: side by side, or
# one above the other when that draws them larger (flat plans)
LINKAGE_SIDE = {"size": (TEXT_WIDTH_MM, 96.0), "velocity": Box(2.0, 2.0, 78.0, 86.0),
                "acceleration": Box(85.0, 2.0, 78.0, 86.0)}
LINKAGE_STACKED = {"size": (TEXT_WIDTH_MM, 166.0), "velocity": Box(2.0, 84.0, 161.0, 80.0),
                   "acceleration": Box(2.0, 2.0, 161.0, 80.0), "stacked": True}
PLAN_SERIES = (1.0, 1.5, 2.0, 2.5, 4.0, 5.0, 7.5)  # ГОСТ 2.302's ratios 1:1 … 1:75 per decade
LINKAGE_TITLE_MM = 9.0  # the room for the scale's line at the top of a plan


def _plan_nice(x: float) -> float:
    """The smallest of :data:`PLAN_SERIES` × 10^k not below x.

    >>> _plan_nice(0.0116), _plan_nice(0.03), _plan_nice(0.0)
    (0.015, 0.04, 1.0)
    """
    return nice(x, PLAN_SERIES)


PLAN_PAD = 0.08  # the margin around a plan, a share of its extent on each side
PLAN_MIN_MM = 40.0  # the least width of a plan's box (its scale's line)


def _extent_mm(plan, mu: float) -> tuple[float, float]:
    """Width and height [mm] of a plan's points drawn at μ, with the margins."""
    pts = list(plan.points.values())
    xs, ys = [z.real for z in pts], [z.imag for z in pts]
    return (max(xs) - min(xs)) * (1 + 2 * PLAN_PAD) / mu, (max(ys) - min(ys)) * (1 + 2 * PLAN_PAD) / mu


def linkage_plan_axes(plan, box: Box) -> tuple[Axis, Axis]:
    """The scale (the same on both axes) that shows a plan's points [m/s or m/s²] in `box`, the
    room of the scale's line at the top kept free, the plan centred below it: the plan's own μ
    (sheet 1's, the one the note's segment lengths use) when it fits the box, else the smallest
    round μ that does."""
    pts = list(plan.points.values())
    xs, ys = [z.real for z in pts], [z.imag for z in pts]
    h = box.height - LINKAGE_TITLE_MM
    w_mm, h_mm = _extent_mm(plan, plan.scale)
    if w_mm <= box.width + 1e-6 and h_mm <= h + 1e-6:
        mu = plan.scale
    else:
        mu = _plan_nice(max((max(xs) - min(xs)) * (1 + 2 * PLAN_PAD) / box.width,
                            (max(ys) - min(ys)) * (1 + 2 * PLAN_PAD) / h, 1e-12))
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    return Axis(cx - mu * box.width / 2, mu, box.width), Axis(cy - mu * h / 2, mu, box.height)


LINKAGE_MAX_MM = 230.0  # the tallest figure of the plans (a page's text height less the caption)


def linkage_layout(s1) -> dict:
    """The figure of the plans of the first plan position, each plan at sheet 1's scale μ_v, μ_a
    (the note's text gives its segments at those): side by side when both fit the text's width,
    else one above the other (``"stacked"``), each box as tall as its plan; when even that is taller
    than a page, :data:`LINKAGE_SIDE` or :data:`LINKAGE_STACKED` at scales of their own."""
    pl = s1.plans[0]
    (wv, hv), (wa, ha) = (_extent_mm(p, p.scale) for p in (pl.velocity, pl.acceleration))
    wv, wa = max(wv, PLAN_MIN_MM), max(wa, PLAN_MIN_MM)
    hv, ha = max(hv, 10.0) + LINKAGE_TITLE_MM, max(ha, 10.0) + LINKAGE_TITLE_MM
    full = TEXT_WIDTH_MM - 4.0
    if wv + wa + 5.0 <= full:
        h = max(hv, ha)
        if h + 4.0 <= LINKAGE_MAX_MM:
            half = (full - 5.0) / 2
            if wv <= half and wa <= half:
                wv = wa = half
            return {"size": (TEXT_WIDTH_MM, h + 4.0), "velocity": Box(2.0, 2.0, wv, h),
                    "acceleration": Box(2.0 + wv + 5.0, 2.0, wa, h), "own": True}
    if max(wv, wa) <= full and hv + ha + 6.0 <= LINKAGE_MAX_MM:
        return {"size": (TEXT_WIDTH_MM, hv + ha + 6.0), "velocity": Box(2.0, ha + 4.0, full, hv),
                "acceleration": Box(2.0, 2.0, full, ha), "stacked": True, "own": True}

    def smallest(layout):
        return min(1.0 / linkage_plan_axes(plan, layout[kind])[0].mu * max(abs(z) for z in plan.points.values())
                   for kind, plan in (("velocity", pl.velocity), ("acceleration", pl.acceleration)))

    return LINKAGE_STACKED if smallest(LINKAGE_STACKED) > 1.4 * smallest(LINKAGE_SIDE) else LINKAGE_SIDE


# sheet 2's diagrams over the crank's turn (M_пр and M_д, ΔT and ΔT_I, J_пр): 360° at 2,5 °/mm on 144 mm
SYNTHESIS = {"size": (TEXT_WIDTH_MM, 130.0)}  # the construction of the synthesis (tmm synth)
DYNAMICS = {"size": (TEXT_WIDTH_MM, 162.0), "x": (17.0, 144.0), "panel": 40.0, "gap": 7.0, "bottom": 16.0,
            "mu_phi": 2.5}


@record
class DynamicsScales:
    """The note's diagrams of sheet 2 over the cycle φ (0 … 360° a turn; a four-stroke engine's two turns 0 … 720°)."""

    phi: Axis  # °
    M: Axis  # N·m
    T: Axis  # J
    J: Axis  # kg·m²


def dynamics_scales(s2) -> DynamicsScales:
    """μ of the note's M_пр/M_д, ΔT/ΔT_I and J_пр diagrams (a Sheet2), each on its panel."""
    d, fw = s2.dynamics, s2.flywheel
    ph = DYNAMICS["panel"]
    m_lo, m_hi = min(float(d.M_r.min()), d.M_d), max(float(d.M_r.max()), d.M_d)
    t_lo, t_hi = float(d.dT.min()), float(d.dT.max())
    if fw is not None:
        dt1 = fw.mertsalov.dT_I - fw.mertsalov.dT_I[0]
        t_lo, t_hi = min(t_lo, float(dt1.min())), max(t_hi, float(dt1.max()))
    mu_phi = DYNAMICS["mu_phi"] * s2.turns  # the cycle on the same 144 mm: 5 °/mm for two turns
    return DynamicsScales(Axis(0.0, mu_phi, 360.0 * s2.turns / mu_phi), fit_axis(m_lo, m_hi, ph), fit_axis(t_lo, t_hi, ph),
                          fit_axis(float(d.J_r.min()), float(d.J_r.max()), ph, keep_zero=False))


@record
class MotionScales:
    phi: Axis  # °
    s: Axis  # mm (or ° for a rocker)
    v: Axis  # m/s (rad/s)
    a: Axis  # m/s² (rad/s²)


def motion_scales(cam) -> MotionScales:
    """S, V, a against φ: 2,5 °/mm along the 144 mm axis, round scales on 48 mm panels."""
    import numpy as np

    m, v = cam.motion, cam.variant
    s = np.degrees(m.s) if v.is_rocker else m.s * 1000.0
    h = MOTION["panel"]
    return MotionScales(Axis(0.0, 360.0 / MOTION["x"][1], MOTION["x"][1]),
                        fit_axis(float(s.min()), float(s.max()), h),
                        fit_axis(float(m.v.min()), float(m.v.max()), h),
                        fit_axis(float(m.a.min()), float(m.a.max()), h))


def pressure_scales(cam) -> tuple[Axis, Axis]:
    import numpy as np

    b = PRESSURE["box"]
    nu = cam.profile.nu_deg
    top = max(float(np.nanmax(nu)), cam.variant.nu_max_deg) * 1.05
    return Axis(0.0, 360.0 / b.width, b.width), Axis(0.0, nice(top / b.height), b.height)


def _zone_points(cam):
    import numpy as np

    z = cam.sizing
    zn = z.zone
    k = 1000.0
    pts = [zn.b * k, zn.d * k, np.array(z.centre)[None] * k, np.array(z.book_centre)[None] * k, np.zeros((1, 2))]
    if z.pivot is not None:
        pts.append(np.array(z.pivot)[None] * k)
    return np.concatenate(pts)


def zone_scales(cam) -> tuple[Axis, Axis]:
    """The zone plan in mm of the mechanism; μ_l in mm/mm."""
    import numpy as np

    p = _zone_points(cam)
    lo, hi = p.min(axis=0), p.max(axis=0)
    o = np.array(cam.sizing.centre) * 1000.0
    lo = np.minimum(lo, o - np.array([0.0, 0.45 * float(max(hi - lo))]))  # the zone below the centre
    b = PLAN["box"]
    return fit_plan(float(lo[0]), float(hi[0]), float(lo[1]), float(hi[1]), b.width, b.height)


def profile_scales(cam) -> tuple[Axis, Axis]:
    """The profile plan (cam frame, mm), with the rollers and the rocker's pivot circle."""
    import numpy as np

    p = cam.profile
    k = 1000.0
    pts = [p.pitch * k, p.inner * k]
    if p.outer is not None:
        pts.append(p.outer * k)
    if p.pivot_path is not None:
        pts.append(p.pivot_path * k)
    allp = np.concatenate(pts)
    r = float(np.max(np.hypot(allp[:, 0], allp[:, 1]))) + p.roller_m * k
    b = PLAN["box"]
    return fit_plan(-1.08 * r, 1.08 * r, -1.08 * r, 1.08 * r, b.width, b.height, pad=0.0)


def mesh_scales(gears) -> tuple[Axis, Axis]:
    """The zoomed mesh around the pole P (mm of the gears)."""
    g = gears.spur
    half = min(max(1.25 * g.g_alpha_mm, 0.6 * g.n1n2_mm * math.cos(math.radians(g.alpha_w_deg))), 2.2 * g.g_alpha_mm)
    al = math.radians(g.alpha_w_deg)
    r1 = g.d1_mm / 2 * math.cos(math.radians(g.alpha_deg)) / math.cos(al)
    b = MESH["box"]
    return fit_plan(-half, half, r1 - 0.85 * half, r1 + 0.85 * half, b.width, b.height, pad=0.0)


@record
class PlanetaryScales:
    y: Axis  # radius, in modules (shared by the scheme and the linear velocities)
    x_scheme: Axis
    x_velocity: Axis  # drawn velocity lengths, in the same units per mm as y
    x_angular: Axis
    y_angular: Axis
    module_mm: float  # the module the reducer is drawn with: sheet 4's (gears_sheet.reducer_fit)
    mu_l: float  # mm of the reducer per mm of the figure at that module (a ГОСТ 2.302 scale)
    mu_v: float  # (m/s)/mm at that module
    mu_omega: float  # (rad/s)/mm
    ok_mm: float  # the segments of the angular plan as drawn [mm]
    oh_mm: float


def planetary_scales(gears) -> PlanetaryScales:
    d = gears.planetary
    vp = gears.checks.velocity
    rmax = max(max(s.z_ring / 2, (s.z_sun + 2 * s.z_planet) / 2) for s in d.stages)
    sb, vb, ab = PLANETARY["scheme"], PLANETARY["velocity"], PLANETARY["angular"]
    # one scale (modules per mm) for the radius, the scheme's length and the drawn velocities
    stages = len(d.stages)
    gap = 0.09 * rmax
    length = stages * 3 * gap + 0.22 * rmax + 0.35 * rmax
    vmax = max(max(s.v_a for s in vp.stages), 1e-9)
    vmin = min(min(s.v_a / (s.r_a - s.r_b) * (max(s.r_b, s.r_a + 2 * s.r_planet) - s.r_b) for s in vp.stages), 0.0)
    vspan = vmax * 1.35 - min(vmin * 1.2, -0.1 * vmax)
    xs = [p for p in (vp.pole * math.tan(math.radians(vp.stages[0].phi_k_deg)),) ] + \
         [vp.pole * math.tan(math.radians(s.phi_h_deg)) for s in vp.stages] + \
         [vp.pole * (-s.v_a / (s.r_b - s.r_a)) for s in vp.stages]
    aspan = max(xs + [0.0]) - min(xs + [0.0])
    # the module of sheet 4's drawing, and the round scale μ_l (mm/mm) that shows the reducer at it
    m = drawing_module(gears)
    mu_l = nice(max(2.6 * rmax / sb.height, length / sb.width, vspan / vb.width) * m)
    mu = mu_l / m  # modules per mm
    mu_a = nice(max(aspan * 1.15 / ab.width, vp.pole * 1.3 / ab.height))  # the angular plan's own scale
    y = Axis(-mu * sb.height / 2, mu, sb.height)
    x_scheme = Axis(-0.22 * rmax - 0.1 * rmax - (mu * sb.width - length) / 2, mu, sb.width)
    vlo = min(vmin * 1.2, -0.1 * vmax)
    x_vel = Axis(vlo - (mu * vb.width - vspan) / 2, mu, vb.width)
    xlo = min(xs + [0.0])
    x_ang = Axis(xlo - (mu_a * ab.width - aspan) / 2, mu_a, ab.width)
    y_ang = Axis(-vp.pole - (mu_a * ab.height - vp.pole) / 2, mu_a, ab.height)
    omega_d = math.pi * gears.motor_rpm / 30.0
    s0 = vp.stages[0]
    # V_A = ω_д·r_k: r_k = r_a modules = r_a·m mm; drawn v_a/μ mm long
    mu_v = omega_d * s0.r_a * m * 1e-3 / (s0.v_a / mu)
    mu_omega = omega_d / (vp.ok / mu_a)
    return PlanetaryScales(y, x_scheme, x_vel, x_ang, y_ang, m, mu_l, mu_v, mu_omega, vp.ok / mu_a, vp.oh / mu_a)


def drawing_module(gears) -> float:
    """The planetary reducer's module of the drawing [mm]: sheet 4's choice (the largest standard
    module at which the scheme fits its field at a ГОСТ scale), which the note's figures state too."""
    from ..sheets.gears_sheet import reducer_fit

    return reducer_fit(gears)[1]


def assembly_side(gears) -> float:
    """The side of one stage's square plan [mm]."""
    return ASSEMBLY_MM if len(gears.planetary.stages) == 1 else 76.0


def assembly_mu_l(gears) -> float:
    """mm of the reducer per mm of the assembly plan at the drawing's module (a ГОСТ 2.302 scale)."""
    lim = 0.0
    for st in gears.planetary.stages:
        big = max(st.z_planet, st.zc2) / 2
        lim = max(lim, st.z_ring / 2, st.z_sun / 2 + st.z_planet / 2 + big) + 4
    return nice(2 * lim * drawing_module(gears) / assembly_side(gears))


def assembly_scale(gears) -> float:
    """Modules per mm of the assembly plan."""
    return assembly_mu_l(gears) / drawing_module(gears)


INDICATOR = {"x": (17.0, 124.0), "panel": 50.0, "gap": 16.0, "bottom": 14.0, "top": 4.0}


def indicator_size(count: int) -> tuple[float, float]:
    """The note's indicator diagrams, one panel a piston one over the other [mm]."""
    i = INDICATOR
    return TEXT_WIDTH_MM, i["bottom"] + count * i["panel"] + (count - 1) * i["gap"] + i["top"]


def figure_size_cm(name: str, gears=None, linkage=None) -> tuple[float, float]:
    """Width and height of a note figure as printed [cm] (`linkage`: the result's sheets 1-2, for
    its figures)."""
    if name == "linkage_plans":
        w, h = linkage_layout(linkage.sheet1)["size"]
        return w / 10, h / 10
    sizes = {"cam_motion": MOTION["size"], "cam_pressure_angle": PRESSURE["size"], "cam_zone": PLAN["size"],
             "cam_profile": PLAN["size"], "gears_mesh": MESH["size"], "gears_planetary": PLANETARY["size"],
             "linkage_dynamics": DYNAMICS["size"], "linkage_synthesis": SYNTHESIS["size"]}
    if name == "linkage_indicator":
        w, h = indicator_size(len(linkage.indicators))
        return w / 10, h / 10
    if name == "gears_assembly":
        n = len(gears.planetary.stages)
        side = assembly_side(gears)
        return (min(TEXT_WIDTH_MM, n * (side + 8) + 4) / 10, (side + 14) / 10)
    w, h = sizes[name]
    return w / 10, h / 10
