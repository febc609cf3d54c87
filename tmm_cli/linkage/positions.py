"""The crank positions of sheet 1: position 0, the evenly spaced ones, both extreme positions of
the output link, the stroke, the time ratio K and the pressure angles over a turn.

The standard method (METHOD.md, "Sheets 1 and 2"): position 0 is the extreme position of the
output link where its working stroke begins; the working stroke is the slower one (the larger
crank angle), unless the file says which (``[load] working = "away" | "towards"`` from the crank
pivot); when both strokes take the same crank angle (K = 1) position 0 is the extreme farthest
from the crank pivot (an engine's or a compressor's top dead centre); ``crank.start_deg`` overrides
all of this. The positions follow every 360°/N in the sense of rotation and are labelled 0 … N−1;
an extreme position that falls between positions k and k + 1 is added as k′ (the book's prime).

The extreme positions are the crank angles where the output's velocity is zero: sign changes on a
grid, then Newton's method on the exact velocity (its derivative is the exact acceleration),
safeguarded by bisection — true extrema to machine precision, not grid points.
"""

from __future__ import annotations

import math

import numpy as np

from ..notes import Note
from ..records import record
from .assembly import GRID, Margin, check_assembly, golden_min
from .chain import Kinematics, guide_frame, solve
from .mechanism import Group, Mechanism

TWO_PI = 2.0 * math.pi
CURVE_STEPS = 720  # the dense curve: every 0.5° of crank turn, both ends included
PRESSURE_WARN_DEG = 45.0  # the usual limit of a lever mechanism's pressure angle
PRIME = "′"


@record
class Position:
    """One crank position of the sheet."""

    index: int  # its place in the list (0, 1, …), the order of crank travel from position 0
    label: str  # the book's label: '0', '1', …, or '7′' for an extreme position between 7 and 8
    phi: float  # crank angle [rad] from +x, counter-clockwise, in [0, 2π)
    travel: float  # crank angle turned since position 0 [rad], in [0, 2π)
    extreme: str | None  # 'start' | 'end' of the working stroke, or None


@record
class Pressure:
    """The largest pressure angle of a group over the turn (0: the force drives along the path)."""

    group: int
    worst: float  # [rad], in [0, π/2]
    phi: float  # the crank angle where it occurs [rad]


@record(eq=False)
class Curve:
    """The whole turn from position 0 on a fine grid, for the diagrams, the traced paths and CSV."""

    travel: np.ndarray  # crank angle turned since position 0 [rad], 0 … 2π
    kin: Kinematics  # at φ0 + sense·travel
    s: np.ndarray  # the output's displacement from the working stroke's start extreme [m or rad], 0 … H
    v: np.ndarray  # its velocity [m/s or rad/s]
    a: np.ndarray  # its acceleration [m/s² or rad/s²]
    pressure: dict[int, np.ndarray]  # group → pressure angle [rad]


@record(eq=False)
class Cycle:
    """Sheet 1's positions and the numbers of the cycle."""

    mechanism: Mechanism
    positions: tuple[Position, ...]
    kin: Kinematics  # at the positions, in the same order
    start: float  # crank angle of position 0 [rad]
    start_rule: str  # 'working' (slower stroke) | 'load' | 'far' (K = 1) | 'given' | 'turning' | 'gas' (a piston's dead centre nearest its head)
    extremes: tuple[float, float] | None  # crank angles where the working stroke starts and ends
    stroke: float | None  # slider: H [m]; rocker: its swing [rad]
    working: float | None  # crank angle of the working stroke [rad]
    returning: float | None  # … of the return stroke [rad]
    time_ratio: float | None  # K = working / returning
    direction: int  # +1: the working stroke increases the output's coordinate, −1: decreases it
    stops: int  # how many times per turn the output stops
    pressure: tuple[Pressure, ...]
    margins: tuple[Margin, ...]
    curve: Curve
    notes: tuple[Note, ...]

    @property
    def lead(self) -> float:
        """The crank's travel from position 0 to the extreme position where the working stroke starts
        [rad, 0 … 2π): 0 unless ``crank.start_deg`` puts position 0 elsewhere (0 without extremes)."""
        return next((p.travel for p in self.positions if p.extreme == "start"), 0.0)

    def stroke_spans(self, working: bool = True) -> tuple[tuple[float, float], ...]:
        """The crank travel from position 0 [rad] covered by the working (or the return) stroke, as
        intervals within [0, 2π] (two when the stroke wraps past position 0; none without extremes).

        >>> from types import SimpleNamespace as N
        >>> c = N(working=3.0, returning=2 * math.pi - 3.0, lead=5.0)
        >>> [tuple(round(x, 6) for x in s) for s in Cycle.stroke_spans(c)]
        [(5.0, 6.283185), (0.0, 1.716815)]
        """
        if self.working is None:
            return ()
        lo = self.lead if working else self.lead + self.working
        hi = lo + (self.working if working else self.returning)
        lo, hi = lo % TWO_PI, (lo % TWO_PI) + (hi - lo)
        spans = [(lo, min(hi, TWO_PI))]
        if hi > TWO_PI + 1e-12:
            spans.append((0.0, hi - TWO_PI))
        return tuple(spans)

    def working_start(self) -> Position | None:
        """The extreme position where the working stroke starts (None when the output turns fully)."""
        return next((p for p in self.positions if p.extreme == "start"), None)

    def working_end(self) -> Position | None:
        """The extreme position where the working stroke ends (None when the output turns fully)."""
        return next((p for p in self.positions if p.extreme == "end"), None)

    def index(self, label: str) -> int | None:
        """The list index of the position labelled `label` ("7'" and "7′" alike), or None."""
        label = str(label).strip().replace("'", PRIME)
        for p in self.positions:
            if p.label == label:
                return p.index
        return None


def output_coordinate(mech: Mechanism, k: Kinematics):
    """(q, q̇, q̈) of the output link: a slider's place along its guide [m], or a rocker's angle [rad]."""
    out = mech.output
    if out.kind == "slider":
        return k.slide[out.link]
    return k.angle[out.link], k.omega[out.link], k.epsilon[out.link]


def _wrap(x):
    return np.remainder(np.asarray(x) + math.pi, TWO_PI) - math.pi


def stationary(mech: Mechanism) -> np.ndarray:
    """Crank angles [rad] in [0, 2π) where the output stops and turns back (q̇ changes sign).

    Newton's step is φ ← φ − q̇·ω1/q̈ (dq̇/dφ = q̈/ω1 for a uniform crank), kept inside the bracket.
    """
    w1 = mech.crank.omega
    step = TWO_PI / GRID
    grid = np.arange(GRID) * step
    f = output_coordinate(mech, solve(mech, grid))[1]
    sg = np.sign(f)
    exact = grid[(sg == 0) & (np.roll(sg, 1) * np.roll(sg, -1) < 0)]
    i = np.nonzero(sg * np.roll(sg, -1) < 0)[0]
    lo, hi, f_lo = grid[i], grid[i] + step, f[i]
    x = 0.5 * (lo + hi)
    for _ in range(100):
        _, fx, fdd = output_coordinate(mech, solve(mech, x))
        left = np.sign(fx) != np.sign(f_lo)  # the root lies in [lo, x]
        hi, lo = np.where(left, x, hi), np.where(left, lo, x)
        f_lo = np.where(left, f_lo, fx)
        with np.errstate(divide="ignore", invalid="ignore"):
            newton = x - fx * w1 / fdd
        inside = (newton > lo) & (newton < hi)
        new = np.where(inside, newton, 0.5 * (lo + hi))
        done = np.all((np.abs(new - x) <= 4e-16 * TWO_PI) | (fx == 0))
        x = np.where(fx == 0, x, new)
        if done:
            break
    roots = np.sort(np.remainder(np.concatenate([x, exact]), TWO_PI))
    keep = [r for j, r in enumerate(roots) if j == 0 or r - roots[j - 1] > 1e-9]
    if len(keep) > 1 and keep[0] + TWO_PI - keep[-1] <= 1e-9:
        keep.pop()
    return np.array(keep)


def pressure_angle(mech: Mechanism, g: Group, k: Kinematics):
    """The group's pressure angle [rad]: between the force its first link transmits and the
    velocity of the point it drives. RRR: AB against the normal to BC at B, arcsin|cos∠(AB, BC)|
    (90° minus the transmission angle); RRP: AB against the guide; RPR: 0 (the block presses
    across the slot and the slot's point moves across it), with a slot offset d from the pivot
    arctan(|d|/t) (the slot's point under the block moves ⊥ CA, the pressure is ⊥ the slot).

    >>> from .mechanism_file import parse_mechanism
    >>> m = parse_mechanism({"frame": {"O": [0, 0]}, "crank": {"pivot": "O", "joint": "A",
    ...     "length": 0.06, "rpm": 100}, "group": [{"kind": "RRP", "joints": ["A", "B"],
    ...     "length": 0.12, "guide": {"through": [0, 0], "angle_deg": 0}, "branch": "ahead"}]})
    >>> round(float(np.degrees(pressure_angle(m, m.groups[0], solve(m, [np.pi / 2]))[0])), 9)   # asin(r/l)
    30.0
    """
    if g.kind == "RRR":
        ja, jb, jc = g.joints
        u1, u2 = k.z[jb] - k.z[ja], k.z[jc] - k.z[jb]
        c = (np.conj(u1) * u2).real / (np.abs(u1) * np.abs(u2))
        return np.arcsin(np.minimum(np.abs(c), 1.0))
    if g.kind == "RRP":
        ja, jb = g.joints
        u1 = k.z[jb] - k.z[ja]
        unit = g.guide.unit if not g.guide.moving else guide_frame(mech, g, k)[1]
        c = (np.conj(u1) * unit).real / np.abs(u1)
        return np.arccos(np.minimum(np.abs(c), 1.0))
    if g.kind == "PRP":  # block B′ pushes across G1, block B moves along G2
        e1 = np.exp(1j * k.angle[g.links[0]])
        e2 = np.exp(1j * k.angle[g.links[1]])
        return np.arccos(np.minimum(np.abs((np.conj(1j * e1) * e2).real), 1.0))
    if g.kind == "RPP":  # the block pushes across the slot, the yoke moves along its guide
        return np.full(k.phi.shape, math.acos(min(abs(math.sin(g.slot)), 1.0)))
    if g.kind == "RPR" and g.offset != 0.0:
        return np.arctan2(abs(g.offset), np.abs(k.slide[g.links[0]][0]))
    return np.zeros(k.phi.shape)


def _worst_pressure(mech: Mechanism, g: Group) -> Pressure:
    step = TWO_PI / GRID
    grid = np.arange(GRID) * step
    p = pressure_angle(mech, g, solve(mech, grid, upto=g.index))
    i = int(np.argmax(p))
    if p[i] == 0.0:
        return Pressure(g.index, 0.0, 0.0)
    x, fx = golden_min(lambda t: -pressure_angle(mech, g, solve(mech, t, upto=g.index)), np.array([grid[i] - step]),
                       np.array([grid[i] + step]))
    return Pressure(g.index, float(-fx[0]), float(np.remainder(x[0], TWO_PI)))


def _extremum(f, sign: float) -> float:
    """The smallest (sign +1) or largest (sign −1) value of f(φ) over a turn: grid, then golden
    section around the best grid point."""
    step = TWO_PI / GRID
    grid = np.arange(GRID) * step
    i = int(np.argmin(sign * f(grid)))
    _, fx = golden_min(lambda t: sign * f(t), np.array([grid[i] - step]), np.array([grid[i] + step]))
    return float(sign * fx[0])


def slot_range(mech: Mechanism, g: Group) -> tuple[float, float]:
    """The least and the greatest distance [m] of an RPR group's block from the slotted link's
    pivot over a turn (the slot must reach the greatest)."""
    def rho(t):
        k = solve(mech, t, upto=g.index)
        return k.slide[g.links[0]][0]

    return _extremum(rho, 1.0), _extremum(rho, -1.0)


def _distance_from_pivot(mech: Mechanism, phi: float) -> float:
    k = solve(mech, [phi])
    return float(abs(k.z[mech.output.joint][0] - mech.frame[mech.crank.pivot]))


def _start(mech: Mechanism, roots: np.ndarray):
    """Position 0 and the cycle's numbers from the output's stationary angles."""
    sense = mech.crank.sense
    if len(roots) < 2:
        start = mech.crank.start if mech.crank.start is not None else 0.0
        return start, ("given" if mech.crank.start is not None else "turning"), None, None, None, None, 1
    q = output_coordinate(mech, solve(mech, roots))[0]
    if mech.output.kind == "rocker":
        q = _wrap(q - q[0])
    i_max, i_min = int(np.argmax(q)), int(np.argmin(q))
    phi_max, phi_min = float(roots[i_max]), float(roots[i_min])
    rising = float(np.remainder(sense * (phi_max - phi_min), TWO_PI))  # crank travel while q grows
    falling = TWO_PI - rising
    if mech.gas_head is not None and mech.gas_head[0] == mech.output.link:  # a piston: its dead centre nearest the head
        head = mech.gas_head[1]
        k = solve(mech, [phi_min, phi_max])
        z = k.z[mech.output.joint]
        up, rule = abs(z[0] - head) < abs(z[1] - head), "gas"
    elif mech.working is not None:
        near_min = _distance_from_pivot(mech, phi_min) < _distance_from_pivot(mech, phi_max)
        up = near_min == (mech.working == "away")  # the working stroke goes from min to max
        rule = "load"
    elif abs(rising - falling) > 1e-9:
        up, rule = rising > falling, "working"
    else:
        up, rule = _distance_from_pivot(mech, phi_max) < _distance_from_pivot(mech, phi_min), "far"
    first, last = (phi_min, phi_max) if up else (phi_max, phi_min)
    working, returning = (rising, falling) if up else (falling, rising)
    start = first
    if mech.crank.start is not None:
        start, rule = mech.crank.start, "given"
    return start, rule, (first, last), float(q[i_max] - q[i_min]), working, returning, 1 if up else -1


def stroke_numbers(mech: Mechanism):
    """(extremes, stroke, working, direction) of the output link by the rule of position 0 (the
    extreme where the working stroke starts first in `extremes`; the stroke H [m] or swing [rad]; the
    working stroke's crank travel [rad]; +1 when it increases the output's coordinate), or None when
    the output turns fully. What a load on another link measures its own stroke by
    (:func:`.loads.link_stroke`, with that link made the output)."""
    _, _, extremes, stroke, working, _, direction = _start(mech, stationary(mech))
    return None if extremes is None else (extremes, stroke, working, direction)


def _positions(mech: Mechanism, start: float, extremes) -> tuple[Position, ...]:
    n, sense = mech.positions, mech.crank.sense
    spacing = TWO_PI / n
    items = [[spacing * j, str(j), None] for j in range(n)]
    for which, phi in zip(("start", "end"), extremes or ()):
        travel = float(np.remainder(sense * (phi - start), TWO_PI))
        if travel > TWO_PI - 1e-9:
            travel = 0.0
        j = int(round(travel / spacing))
        if abs(travel - j * spacing) <= 1e-9 and j < n:
            items[j][2] = which
            continue
        j = int(travel // spacing)
        primes = 1 + sum(1 for t, lab, _ in items if lab.startswith(f"{j}{PRIME}"))
        items.append([travel, f"{j}{PRIME * primes}", which])
    items.sort(key=lambda it: it[0])
    return tuple(Position(i, lab, float(np.remainder(start + sense * t, TWO_PI)), t, ex)
                 for i, (t, lab, ex) in enumerate(items))


def displacement(mech: Mechanism, extremes, direction: int, q) -> np.ndarray:
    """The output's displacement [m or rad] at its coordinates `q`, counted as the book counts it:
    from the extreme position where the working stroke starts (``extremes[0]``), positive along the
    working stroke, so 0 ≤ s ≤ H whatever position 0 is; from `q`'s first value without extremes."""
    q = np.asarray(q, dtype=float)
    q0 = float(output_coordinate(mech, solve(mech, [extremes[0]]))[0][0]) if extremes else float(q.flat[0])
    d = q - q0 if mech.output.kind == "slider" else _wrap(q - q0)
    return direction * d


def _curve(mech: Mechanism, start: float, direction: int, extremes=None) -> Curve:
    travel = np.linspace(0.0, TWO_PI, CURVE_STEPS + 1)
    k = solve(mech, start + mech.crank.sense * travel)
    q, qd, qdd = output_coordinate(mech, k)
    s = displacement(mech, extremes, direction, q)
    pressure = {g.index: pressure_angle(mech, g, k) for g in mech.groups}
    return Curve(travel, k, s, direction * qd, direction * qdd, pressure)


def _notes(mech: Mechanism, rule: str, stops: int, pressure, time_ratio) -> tuple[Note, ...]:
    notes = [Note.make(f"mechanism_position0_{rule}", "assumption")]
    if time_ratio is not None and time_ratio < 1.0 - 1e-9:
        notes.append(Note.make("mechanism_fast_working", "warning", time_ratio=time_ratio))
    if stops > 2:
        notes.append(Note.make("mechanism_stops", "warning", count=stops))
    for p in pressure:
        if math.degrees(p.worst) > PRESSURE_WARN_DEG:
            notes.append(Note.make("mechanism_pressure", "warning", group=p.group, angle_deg=math.degrees(p.worst),
                                   phi_deg=math.degrees(p.phi), limit_deg=PRESSURE_WARN_DEG))
    for g in mech.groups:
        if g.kind == "RPR":
            lo, hi = slot_range(mech, g)
            notes.append(Note.make("mechanism_slot", "assumption", link=g.links[1], pivot=g.joints[1],
                                   rho_min_mm=lo * 1000, rho_max_mm=hi * 1000))
    return tuple(notes)


def cycle(mech: Mechanism, source: str = "mechanism") -> Cycle:
    """Sheet 1's positions of the mechanism and the numbers of its cycle (TmmError if some group
    cannot be assembled somewhere in the turn).

    >>> from .mechanism_file import parse_mechanism
    >>> m = parse_mechanism({"frame": {"O": [0, 0]}, "crank": {"pivot": "O", "joint": "A",
    ...     "length": 0.06, "rpm": 100}, "group": [{"kind": "RRP", "joints": ["A", "B"],
    ...     "length": 0.25, "guide": {"through": [0, 0], "angle_deg": 0}, "branch": "ahead"}]})
    >>> c = cycle(m)   # central crank-slider: H = 2r, K = 1, position 0 at the far dead centre
    >>> round(c.stroke, 12), round(c.time_ratio, 12), c.start, c.start_rule, len(c.positions)
    (0.12, 1.0, 0.0, 'far', 12)
    """
    margins = check_assembly(mech, source)
    roots = stationary(mech)
    start, rule, extremes, stroke, working, returning, direction = _start(mech, roots)
    positions = _positions(mech, start, extremes)
    kin = solve(mech, [p.phi for p in positions])
    pressure = tuple(_worst_pressure(mech, g) for g in mech.groups)
    curve = _curve(mech, start, direction, extremes)
    k_ratio = working / returning if working is not None else None
    return Cycle(mech, positions, kin, float(start), rule, extremes, stroke, working, returning, k_ratio, direction,
                 len(roots), pressure, margins, curve, _notes(mech, rule, len(roots), pressure, k_ratio))
