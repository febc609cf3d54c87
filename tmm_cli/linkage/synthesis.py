"""Synthesis of the course's lever mechanisms from the task of sheet 1: the stroke H, the time ratio
K (коэффициент изменения средней скорости), the rocker's swing ψ (issue 33, `tmm synth`).

The standard method (METHOD.md, "Sheets 1 and 2": synthesis by the time ratio; Artobolevsky,
*Теория механизмов и машин*, the chapter on the synthesis of four-bar mechanisms by the time
ratio; Frolov (ed.), *Теория механизмов и машин*, the same chapter). The seeds hold no sheet-1
chapter, so no printed worked example of the book can be reproduced here; every doctest below is a
worked example of the formula it documents, and the tests analyse every synthesised mechanism with
`tmm linkage`'s own core (tests/test_synthesis.py).

- The angle between the crank's positions at the output's two extreme positions,
  θ = 180°·(K − 1)/(K + 1): the working stroke takes 180° + θ of crank turn, the return 180° − θ.
- Crank-slider (кривошипно-ползунный): central, l_OA = H/2, l_AB = l_OA/λ; offset by e, from the
  triangle O B₁ B₂ of the two extreme positions (O B₁ = l_AB + l_OA, O B₂ = l_AB − l_OA, the angle
  at O is θ, B₁B₂ = H, the height from O is e).
- Crank-rocker (кривошипно-коромысловый): the rocker's ends C₁, C₂ at its extremes; the crank's
  pivot A on the circle through C₁, C₂ on which C₁C₂ subtends θ; l_AB = (AC₂ − AC₁)/2,
  l_BC = (AC₂ + AC₁)/2.
- Slotted-link mechanism of a shaper (кулисный механизм строгального станка): the link swings by
  ψ = θ, l_OA = l_O1O2·sin(θ/2), H = 2·l_O2B·sin(ψ/2), the ram's guide through the middle of the
  sagitta of the arc of B.

Pure functions of plain numbers (SI: metres, radians) returning frozen records; a task without a
solution raises :class:`TmmError` naming the datum to change.
"""

from __future__ import annotations

import cmath
import math

import numpy as np

from ..errors import TmmError
from ..records import record

TYPES = ("crank-slider", "crank-rocker", "slotted-link")
GAMMA_TOL = 1e-9  # [rad]: a γ_min equal to the task's γ up to rounding meets it


def theta_of(k: float) -> float:
    """θ = π·(K − 1)/(K + 1) [rad]: the angle of the crank between the output's extreme positions
    (METHOD.md, "Synthesis by the time ratio"; K = (180° + θ)/(180° − θ)).

    >>> round(math.degrees(theta_of(1.4)), 12), round(math.degrees(theta_of(1.0)), 12)
    (30.0, 0.0)
    """
    return math.pi * (k - 1.0) / (k + 1.0)


def k_of(theta: float) -> float:
    """K = (π + θ)/(π − θ), the inverse of :func:`theta_of`.

    >>> round(k_of(math.radians(30.0)), 12)
    1.4
    """
    return (math.pi + theta) / (math.pi - theta)


# ---------------------------------------------------------------------------------------------------
# crank-slider

@record
class SliderSynthesis:
    """A crank-slider found from its stroke: the crank O→A, the rod A→B, the slider B on a guide
    at the distance `offset` from O."""

    mode: str  # 'lambda' (central) | 'time_ratio' (K and e) | 'lambda_offset' (λ and e)
    stroke: float  # H [m]
    offset: float  # e [m], ≥ 0
    theta: float  # θ [rad]
    time_ratio: float  # K
    crank: float  # l_OA [m]
    rod: float  # l_AB [m]
    lam: float  # λ = l_OA/l_AB
    x_far: float  # the far extreme position B₁ along the guide from the foot of the perpendicular from O [m]
    x_near: float  # the near one, B₂ [m]

    @property
    def far(self) -> float:
        """O B₁ = l_AB + l_OA [m]."""
        return self.rod + self.crank

    @property
    def near(self) -> float:
        """O B₂ = l_AB − l_OA [m]."""
        return self.rod - self.crank


def _slider(mode, stroke, offset, crank, rod) -> SliderSynthesis:
    x_far = math.sqrt((rod + crank) ** 2 - offset ** 2)
    x_near = math.sqrt((rod - crank) ** 2 - offset ** 2)
    theta = math.atan2(offset, x_near) - math.atan2(offset, x_far)
    return SliderSynthesis(mode, stroke, offset, theta, k_of(theta), crank, rod, crank / rod, x_far, x_near)


def crank_slider_central(stroke: float, lam: float) -> SliderSynthesis:
    """The central crank-slider (e = 0, K = 1): l_OA = H/2, l_AB = l_OA/λ [m] (METHOD.md, "Central
    crank-slider").

    >>> s = crank_slider_central(0.12, 0.25)      # the compressor of docs/examples/compressor.toml
    >>> round(s.crank, 12), round(s.rod, 12), s.time_ratio
    (0.06, 0.24, 1.0)
    """
    if not 0.0 < lam < 1.0:
        raise TmmError(f"'lambda' is {lam:g}; λ = l_OA/l_AB must lie in (0, 1) (usually 0.2 … 0.35)")
    crank = stroke / 2.0
    return _slider("lambda", stroke, 0.0, crank, crank / lam)


def offset_limit(stroke: float, theta: float) -> float:
    """The largest offset e [m] an offset crank-slider of stroke H and angle θ < 90° can have:
    e < H·cot θ (at that offset the near extreme position B₂ is the foot of the perpendicular from
    O, and the rod l_AB − l_OA = e just reaches the guide).

    >>> round(offset_limit(0.1, math.radians(45.0)), 12)
    0.1
    """
    return stroke / math.tan(theta)


def crank_slider_offset(stroke: float, k: float, offset: float) -> SliderSynthesis:
    """The offset crank-slider from H, K and e: θ = 180°(K − 1)/(K + 1); in the triangle O B₁ B₂
    (sides l_AB + l_OA, l_AB − l_OA, H; the angle θ at O, the height e on B₁B₂) the law of cosines
    and the area ½·H·e = ½·(l_AB + l_OA)(l_AB − l_OA)·sin θ give

        l_OA = ½·√(H² − 2·H·e·tg(θ/2)),   l_AB = ½·√(H² + 2·H·e·ctg(θ/2))   [m].

    >>> s = crank_slider_offset(0.10, 1.2, 0.02)   # H = 100 mm, K = 1,2, e = 20 mm: θ = 16,3636°
    >>> round(math.degrees(s.theta), 4), round(s.crank * 1000, 3), round(s.rod * 1000, 3)
    (16.3636, 48.541, 97.238)
    """
    if k <= 1.0:
        raise TmmError(f"'time_ratio' is {k:g}; an offset crank-slider needs K > 1 (give time_ratio > 1, or lambda for "
                       "a central one)")
    theta = theta_of(k)
    if theta >= math.pi / 2.0 - 1e-9:
        raise TmmError(f"'time_ratio' is {k:g}; a crank-slider reaches only K < 3 (θ < 90°): lower time_ratio or take "
                       "a slotted-link mechanism")
    if offset <= 0.0:
        raise TmmError(f"'offset' is {offset:g}; with time_ratio K > 1 the guide must be offset: give offset > 0 m")
    limit = offset_limit(stroke, theta)
    if offset >= limit * (1.0 - 1e-9):
        raise TmmError(f"'offset' is {offset:g} m; with stroke {stroke:g} m and K = {k:g} the rod cannot reach the guide: "
                       f"give offset below {limit:.4g} m (or a smaller time_ratio)")
    t = math.tan(theta / 2.0)
    crank = 0.5 * math.sqrt(stroke ** 2 - 2.0 * stroke * offset * t)
    rod = 0.5 * math.sqrt(stroke ** 2 + 2.0 * stroke * offset / t)
    return _slider("time_ratio", stroke, offset, crank, rod)


def _slider_stroke(crank: float, lam: float, offset: float) -> float:
    rod = crank / lam
    return math.sqrt((rod + crank) ** 2 - offset ** 2) - math.sqrt(max((rod - crank) ** 2 - offset ** 2, 0.0))


def crank_slider_lambda_offset(stroke: float, lam: float, offset: float) -> SliderSynthesis:
    """The offset crank-slider from H, λ and e: l_OA solves H = √((l_AB + l_OA)² − e²) −
    √((l_AB − l_OA)² − e²) with l_AB = l_OA/λ (the positions of B at the two extreme positions);
    the root on the branch where H grows with l_OA (away from the dead point l_AB − l_OA = e);
    K then follows from θ = ∠B₂OB₁.

    >>> s = crank_slider_lambda_offset(0.12, 0.25, 0.02)
    >>> round(s.crank * 1000, 3), round(s.rod * 1000, 3), round(s.time_ratio, 4)
    (59.776, 239.102, 1.0289)
    """
    if not 0.0 < lam < 1.0:
        raise TmmError(f"'lambda' is {lam:g}; λ = l_OA/l_AB must lie in (0, 1) (usually 0.2 … 0.35)")
    if offset == 0.0:
        return crank_slider_central(stroke, lam)
    lo = offset * lam / (1.0 - lam)  # l_AB − l_OA = e: the rod just reaches the guide
    # H(r) falls from r = lo to a minimum, then grows like 2r: the minimum by golden section
    a, b = lo, max(lo * 4.0, stroke)
    g = (math.sqrt(5.0) - 1.0) / 2.0
    for _ in range(200):
        c, d = b - g * (b - a), a + g * (b - a)
        if _slider_stroke(c, lam, offset) < _slider_stroke(d, lam, offset):
            b = d
        else:
            a = c
    r_min = 0.5 * (a + b)
    h_min = _slider_stroke(r_min, lam, offset)
    if stroke <= h_min * (1.0 + 1e-9):
        raise TmmError(f"'offset' is {offset:g} m; with lambda {lam:g} no crank gives the stroke {stroke:g} m (the "
                       f"smallest stroke with this offset is {h_min:.4g} m): give a smaller offset or a larger stroke")
    hi = stroke / 2.0  # H > 2·l_OA whenever e > 0
    lo_r = r_min
    for _ in range(200):
        mid = 0.5 * (lo_r + hi)
        if _slider_stroke(mid, lam, offset) < stroke:
            lo_r = mid
        else:
            hi = mid
    crank = 0.5 * (lo_r + hi)
    return _slider("lambda_offset", stroke, offset, crank, crank / lam)


# ---------------------------------------------------------------------------------------------------
# crank-rocker

@record
class RockerSynthesis:
    """A crank-rocker four-bar A-B-C-D (the book's letters: crank AB, coupler BC, rocker CD, frame
    AD) found on the locus of θ. Points are complex x + iy [m] in the mechanism's frame: A at the
    origin, D on +x."""

    mode: str  # 'frame' (l_AD given) | 'transmission' (the pivot where γ_min is largest)
    rocker: float  # l_CD [m]
    swing: float  # ψ [rad]
    theta: float  # θ [rad]
    time_ratio: float  # K
    frame: float  # l_AD [m]
    crank: float  # l_AB [m]
    coupler: float  # l_BC [m]
    gamma_min: float  # the smallest transmission angle over the turn [rad]
    gamma_best: float  # the largest γ_min any pivot on the locus gives [rad]
    gamma_task: float | None  # the task's min_transmission_deg [rad]
    A: complex
    D: complex
    C1: complex  # the rocker's end at the folded extreme (crank and coupler overlapping): AC₁ = l_BC − l_AB
    C2: complex  # at the extended extreme: AC₂ = l_BC + l_AB
    centre: complex  # the locus circle's centre
    radius: float  # its radius C₁C₂/(2·sin θ)
    branch: int  # +1: C left of the directed line B → D (the mechanism file's RRR branch), −1 right


def transmission_min(a, b, c, d):
    """The smallest transmission angle γ_min [rad] of a crank-rocker over a turn: the angle μ at C
    between the coupler BC and the rocker CD, cos μ = (b² + c² − BD²)/(2bc), is extreme at
    BD = d − a and d + a (the crank along the frame); γ = μ or 180° − μ, whichever is acute
    (Artobolevsky; Frolov: the transmission angle of the four-bar).

    >>> round(math.degrees(transmission_min(0.08, 0.28, 0.20, 0.30)), 4)   # docs/examples/four_bar.toml
    51.3178
    """
    a, b, c, d = (np.asarray(x, dtype=float) for x in (a, b, c, d))
    mu1 = np.arccos(np.clip((b * b + c * c - (d - a) ** 2) / (2 * b * c), -1.0, 1.0))
    mu2 = np.arccos(np.clip((b * b + c * c - (d + a) ** 2) / (2 * b * c), -1.0, 1.0))
    out = np.minimum(np.minimum(mu1, np.pi - mu1), np.minimum(mu2, np.pi - mu2))
    return float(out) if out.ndim == 0 else out


def _cross(u, v):
    return (np.conj(u) * v).imag


def _unit(z):
    return z / np.abs(z)


def _candidates(c1: complex, c2: complex, d: complex, theta: float, rocker: float, pivots: np.ndarray):
    """For crank pivots A on the locus: the lengths, the transmission angle and whether A gives a
    crank-rocker whose extreme positions are C₁C₂ as the construction says (masked arrays)."""
    a1, a2 = np.abs(pivots - c1), np.abs(pivots - c2)
    with np.errstate(invalid="ignore", divide="ignore"):  # a pivot on C₁ itself: no angle, not valid
        angle = np.abs(np.angle((c2 - pivots) / (c1 - pivots)))
    far_is_2 = a2 >= a1
    far = np.where(far_is_2, a2, a1)
    near = np.where(far_is_2, a1, a2)
    c_far, c_near = np.where(far_is_2, c2, c1), np.where(far_is_2, c1, c2)
    crank, coupler = (far - near) / 2.0, (far + near) / 2.0
    frame = np.abs(d - pivots)
    lengths = np.stack([crank, coupler, np.full(crank.shape, rocker), frame])
    longest = lengths.max(axis=0)
    grashof = (crank < lengths[1:].min(axis=0)) & (crank + longest < lengths.sum(axis=0) - crank - longest - 1e-12)
    with np.errstate(invalid="ignore", divide="ignore"):
        b_ext = pivots + crank * _unit(c_far - pivots)
        b_fold = pivots - crank * _unit(c_near - pivots)
        s_ext = np.sign(_cross(d - b_ext, c_far - b_ext))
        s_fold = np.sign(_cross(d - b_fold, c_near - b_fold))
    ok = (np.abs(angle - theta) < 1e-7) & grashof & (s_ext == s_fold) & (s_ext != 0) & (near > 1e-12)
    gamma = np.where(ok, transmission_min(crank, coupler, rocker, frame), -1.0)
    return ok, gamma, crank, coupler, frame, s_ext


def _circle_points(centre: complex, radius: float, t: np.ndarray) -> np.ndarray:
    return centre + radius * np.exp(1j * t)


def crank_rocker(rocker: float, swing: float, k: float, frame: float | None = None,
                 gamma_task: float | None = None) -> RockerSynthesis:
    """The crank-rocker from the rocker l_CD, its swing ψ [rad], K and either the frame l_AD [m]
    or the smallest transmission angle γ [rad] (METHOD.md, "Crank-rocker"): C₁, C₂ = D + l_CD·e^{iβ}
    at the rocker's extremes, ψ apart; the chord C₁C₂ = 2·l_CD·sin(ψ/2); the locus of the crank's
    pivot A, the circles of radius R = C₁C₂/(2·sin θ) through C₁ and C₂ (either side of the
    chord), on whose major arcs C₁C₂ subtends θ; then l_AB = (AC₂ − AC₁)/2, l_BC = (AC₂ + AC₁)/2.
    With `frame` A is where the circle |AD| = l_AD meets the locus (the point with the larger
    γ_min); without it, A is the point of the locus where γ_min is largest (the tool's choice; the
    book leaves the point to the designer), and γ_min must reach the task's γ.

    >>> s = crank_rocker(0.20, math.radians(40.0), 1.2, frame=0.30)
    >>> round(s.crank * 1000, 2), round(s.coupler * 1000, 2), round(math.degrees(s.gamma_min), 2)
    (63.99, 181.49, 34.88)
    >>> s = crank_rocker(0.20, math.radians(40.0), 1.2, gamma_task=math.radians(40.0))
    >>> round(s.frame * 1000, 2), round(s.crank * 1000, 2), round(math.degrees(s.gamma_min), 2)
    (211.11, 64.65, 45.77)
    """
    if k <= 1.0:
        raise TmmError(f"'time_ratio' is {k:g}; a crank-rocker synthesised by K needs K > 1 (give time_ratio > 1)")
    if not 0.0 < swing < math.pi:
        raise TmmError(f"'swing_deg' is {math.degrees(swing):g}; the rocker's swing ψ must lie in (0, 180)°")
    theta = theta_of(k)
    d = 0j
    c1 = rocker * cmath.exp(1j * (math.pi / 2.0 + swing / 2.0))
    c2 = rocker * cmath.exp(1j * (math.pi / 2.0 - swing / 2.0))
    chord = abs(c2 - c1)
    radius = chord / (2.0 * math.sin(theta))
    mid = (c1 + c2) / 2.0
    centres = (mid + 1j * radius * math.cos(theta), mid - 1j * radius * math.cos(theta))
    # the best γ_min over the whole locus (both circles): a grid, then two finer grids around the best
    best = (-1.0, None, None)
    for centre in centres:
        t = np.linspace(0.0, 2.0 * math.pi, 7200, endpoint=False)
        ok, gamma, *_ = _candidates(c1, c2, d, theta, rocker, _circle_points(centre, radius, t))
        if not ok.any():
            continue
        i = int(np.argmax(gamma))
        step = t[1] - t[0]
        for _ in range(3):
            t = np.linspace(t[i] - step, t[i] + step, 801)
            step = t[1] - t[0]
            ok2, gamma2, *_ = _candidates(c1, c2, d, theta, rocker, _circle_points(centre, radius, t))
            i = int(np.argmax(gamma2))
            gamma = gamma2
        if gamma[i] > best[0]:
            best = (float(gamma[i]), centre, float(t[i]))
    if best[1] is None:
        raise TmmError(f"'swing_deg' is {math.degrees(swing):g}; no crank-rocker has ψ = {math.degrees(swing):g}° and "
                       f"K = {k:g}: change swing_deg or time_ratio")
    gamma_best = best[0]
    if frame is None:
        if gamma_task is not None and gamma_best < gamma_task - GAMMA_TOL:
            raise TmmError(f"'min_transmission_deg' is {math.degrees(gamma_task):g}; the best a crank-rocker with "
                           f"ψ = {math.degrees(swing):g}° and K = {k:g} reaches is {math.degrees(gamma_best):.2f}°: lower "
                           "min_transmission_deg, swing_deg or time_ratio")
        centre, pivot = best[1], _circle_points(best[1], radius, np.array([best[2]]))[0]
        mode = "transmission"
    else:
        found = []
        for centre in centres:  # the circle |A − D| = l_AD meets the locus circle
            dist = abs(centre - d)
            if dist < 1e-15:
                continue
            x = (dist ** 2 + frame ** 2 - radius ** 2) / (2.0 * dist)
            h2 = frame ** 2 - x ** 2
            if h2 < 0.0:
                continue
            u = (centre - d) / dist
            for sgn in (1.0, -1.0):
                found.append((centre, d + u * (x + sgn * 1j * math.sqrt(h2))))
        pts = np.array([p for _, p in found], dtype=complex)
        ok, gamma, *_ = _candidates(c1, c2, d, theta, rocker, pts) if len(pts) else (np.zeros(0, bool), None)
        if not ok.any():
            lo, hi = _frame_range(c1, c2, d, theta, rocker, centres, radius)
            raise TmmError(f"'frame' is {frame:g} m; with the rocker {rocker:g} m, ψ = {math.degrees(swing):g}° and "
                           f"K = {k:g} the crank's pivot on the locus of θ lies {lo:.4g} … {hi:.4g} m from D: change frame")
        i = int(np.argmax(gamma))
        centre, pivot = found[i][0], found[i][1]
        mode = "frame"
        if gamma_task is not None and gamma[i] < gamma_task - GAMMA_TOL:
            raise TmmError(f"'min_transmission_deg' is {math.degrees(gamma_task):g}; with frame {frame:g} m the smallest "
                           f"transmission angle is {math.degrees(gamma[i]):.2f}° (the best on the locus is "
                           f"{math.degrees(gamma_best):.2f}°): change frame or lower min_transmission_deg")
    ok, gamma, crank, coupler, frame_len, side = (np.asarray(x).item() for x in
                                                  _candidates(c1, c2, d, theta, rocker, np.array([pivot])))
    # into the mechanism's frame: A at the origin, D on +x
    turn = np.conj(_unit(d - pivot))

    def put(z: complex) -> complex:
        return complex((z - pivot) * turn)

    a1, a2 = abs(pivot - c1), abs(pivot - c2)
    fold, ext = (c1, c2) if a2 >= a1 else (c2, c1)
    return RockerSynthesis(mode, rocker, swing, theta, k, float(frame_len), float(crank), float(coupler), float(gamma),
                           gamma_best, gamma_task, 0j, put(d), put(fold), put(ext), put(centre), radius, int(side))


def rocker_construction_frame(syn: RockerSynthesis) -> dict[str, complex]:
    """The construction's points [m] — C₁, C₂, the pivot A and the locus centre O — with the origin
    at D and the y axis along the bisector of the rocker's swing (the frame the derivation writes
    its coordinates in: C₁,₂ = (∓l_CD·sin(ψ/2), l_CD·cos(ψ/2)), O on the y axis).

    >>> p = rocker_construction_frame(crank_rocker(0.20, math.radians(40.0), 1.2, frame=0.30))
    >>> round(abs(p["C1"].real) * 1000, 3), round(p["C1"].imag * 1000, 3), round(abs(p["O"].real), 12)
    (68.404, 187.939, 0.0)
    """
    mid = (syn.C1 + syn.C2) / 2.0
    rot = 1j * abs(mid - syn.D) / (mid - syn.D)

    def put(z: complex) -> complex:
        return complex((z - syn.D) * rot)

    return {"C1": put(syn.C1), "C2": put(syn.C2), "A": put(syn.A), "O": put(syn.centre)}


def _frame_range(c1, c2, d, theta, rocker, centres, radius) -> tuple[float, float]:
    """The least and the greatest l_AD over the valid arcs of the locus (for the error message)."""
    t = np.linspace(0.0, 2.0 * math.pi, 7200, endpoint=False)
    frames = []
    for centre in centres:
        ok, _, _, _, frame, _ = _candidates(c1, c2, d, theta, rocker, _circle_points(centre, radius, t))
        frames.extend(frame[ok].tolist())
    return (min(frames), max(frames)) if frames else (float("nan"), float("nan"))


# ---------------------------------------------------------------------------------------------------
# slotted-link mechanism of a shaper

ROD_RATIO = 0.3  # l_BC/l_O2B when the task gives none (the usual 0.25 … 0.35 of shaper schemes)


@record
class SlottedSynthesis:
    """The slotted-link mechanism of a shaper: the crank O1A, the block on A in the slotted link
    O2B swinging about O2 (directly below O1), the rod BC and the ram C on a horizontal guide."""

    stroke: float  # H [m]
    time_ratio: float  # K
    theta: float  # θ = ψ [rad]
    frame: float  # l_O1O2 [m]
    crank: float  # l_O1A [m]
    link: float  # l_O2B [m]
    rod: float  # l_BC [m]
    rod_ratio: float  # l_BC / l_O2B
    sagitta: float  # f = l_O2B·(1 − cos(ψ/2)) [m]
    guide: float  # the guide's height above O2: l_O2B − f/2 [m]
    rod_angle: float  # the rod's largest angle to the guide, asin(f/(2·l_BC)) [rad]
    slot: float  # the block's farthest place from O2, l_O1O2 + l_O1A [m]


def slotted_link(stroke: float, k: float, frame: float, rod_ratio: float = ROD_RATIO) -> SlottedSynthesis:
    """The shaper's slotted-link mechanism from H, K and l_O1O2 (METHOD.md, "Slotted-link (shaper)
    mechanism"): the link's extreme positions are tangent to the crank circle, so it swings by
    ψ = θ and l_O1A = l_O1O2·sin(θ/2); B moves on an arc of radius l_O2B and the ram's stroke is
    its chord, H = 2·l_O2B·sin(ψ/2); the guide passes through the middle of the arc's sagitta
    f = l_O2B·(1 − cos(ψ/2)), at l_O2B − f/2 above O2, so the rod leans at most asin(f/(2·l_BC));
    l_BC = rod_ratio·l_O2B.

    >>> s = slotted_link(0.40, 1.5, 0.30)      # H = 400 mm, K = 1,5: θ = 36°
    >>> round(math.degrees(s.theta), 6), round(s.crank * 1000, 3), round(s.link * 1000, 3), round(s.guide * 1000, 3)
    (36.0, 92.705, 647.214, 631.375)
    """
    if k <= 1.0:
        raise TmmError(f"'time_ratio' is {k:g}; a slotted-link mechanism needs K > 1 (give time_ratio > 1)")
    if not 0.0 < rod_ratio <= 10.0:
        raise TmmError(f"'rod_ratio' is {rod_ratio:g}; l_BC/l_O2B must lie in (0, 10] (usually 0.25 … 0.35)")
    theta = theta_of(k)
    crank = frame * math.sin(theta / 2.0)
    if crank >= frame:
        raise TmmError(f"'frame' is {frame:g} m; the crank {crank:g} m would be longer than the frame: the slotted link "
                       "would turn fully; give a longer frame or a smaller time_ratio")
    link = stroke / (2.0 * math.sin(theta / 2.0))
    sagitta = link * (1.0 - math.cos(theta / 2.0))
    rod = rod_ratio * link
    if rod <= sagitta / 2.0:
        raise TmmError(f"'rod_ratio' is {rod_ratio:g}; the rod {rod:.4g} m cannot reach the guide from B (it must be "
                       f"longer than {sagitta / 2.0:.4g} m): give a larger rod_ratio")
    return SlottedSynthesis(stroke, k, theta, frame, crank, link, rod, rod_ratio, sagitta, link - sagitta / 2.0,
                            math.asin(sagitta / (2.0 * rod)), frame + crank)
