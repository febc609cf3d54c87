"""The useful resistance (the ``[load]`` table of a mechanism file): its value along the working
stroke and its exact work.

On a slider (``on = "B"``): a force [N] along the guide; on a rocker or a slotted link
(``on = ["C", "B"]``): a moment [N·m]. Its magnitude is a table against the fraction of the stroke
(or swing) covered since the working stroke began, linear in between; it opposes the working
motion and is zero on the return stroke (the standard load diagram of a machine's working member:
Artobolevsky, Frolov — "силы полезного сопротивления", the indicator diagram of a compressor, the
cutting force of a shaper)::

    [load]
    on = "B"
    stroke = [0.0, 0.25, 0.5, 0.75, 1.0]   # from 0 to 1, never decreasing (a repeated value is a jump)
    force = [0, 500, 1500, 1500, 0]        # [N], ≥ 0, as many values as `stroke`
    working = "away"                       # read by sheet 1: which stroke is the working one

The load acts on the output link (the one whose extreme positions give position 0 and the stroke);
a file whose load is elsewhere sets ``output`` to it. A file may give several ``[[load]]`` tables, each
on its own link (two presses on one crank): each then measures its stroke from its own link's extreme
position where its working stroke starts (its own ``working``, or the slower stroke, or — both strokes
equal — the extreme farthest from the crank pivot, the rule of sheet 1's position 0), :func:`link_stroke`.
"""

from __future__ import annotations

import math

import numpy as np

from ..records import record
from .chain import Kinematics, slider_unit, solve
from .mechanism import Mechanism
from .positions import Cycle, output_coordinate

LOAD_KEYS = ("on", "stroke", "force", "moment", "working", "direction_deg")
TABLE_MAX = 1000  # entries of the load table
FORCE_MAX = 1.0e9  # [N] or [N·m]
WORKING_TOLERANCE = 1e-9  # [rad] of crank travel: the end of the working stroke still belongs to it


@record
class Load:
    """The useful resistance on the output link."""

    link: str  # the output link's name
    kind: str  # 'force' (a slider, [N]) | 'moment' (a turning link, [N·m])
    stroke: tuple[float, ...]  # fractions of the stroke, 0 … 1, non-decreasing
    values: tuple[float, ...]  # magnitudes at those fractions, ≥ 0
    direction: float | None = None  # a force's own direction from +x [rad] (None: against the working motion)
    working: str | None = None  # 'away' | 'towards' (the file's `working`), else None
    joint: str | None = None  # the point whose distance from the crank pivot tells 'away' from 'towards'
    key: str = "load"  # its name in the file ('load', or 'load[2]' of several [[load]])


@record
class Stroke:
    """What the load needs of sheet 1's cycle: where the working stroke starts and how long it is."""

    start: float  # crank angle of position 0 [rad]
    sense: int  # +1 the crank turns counter-clockwise
    working: float  # crank travel of the working stroke [rad]
    length: float  # the stroke H [m] or the swing ψ [rad]
    direction: int  # +1: the working stroke increases the output coordinate
    q0: float  # the output coordinate where the working stroke starts [m or rad]
    kind: str  # 'slider' | 'rocker'
    origin: float  # crank angle where the working stroke starts [rad] (position 0 unless start_deg moves it)
    unit: complex | None = None  # a slider output's fixed guide direction (None: a rocker or a moving guide)
    link: str | None = None  # the link whose stroke this is (None: the mechanism's output)

    @property
    def lead(self) -> float:
        """The crank's travel from position 0 to the working stroke's start [rad], in [0, 2π)."""
        t = float(np.remainder(self.sense * (self.origin - self.start), 2.0 * math.pi))
        return 0.0 if t > 2.0 * math.pi - WORKING_TOLERANCE else t


def stroke_of(c: Cycle) -> Stroke | None:
    """The :class:`Stroke` of a cycle (None when the output turns fully: it has no stroke)."""
    if c.stroke is None:
        return None
    mech = c.mechanism
    origin = c.extremes[0]
    q0 = float(output_coordinate(mech, solve(mech, [origin]))[0][0])
    gd = dict(mech.guided()).get(mech.output.link) if mech.output.kind == "slider" else None
    unit = gd.unit if gd is not None and not gd.moving else None
    return Stroke(c.start, mech.crank.sense, c.working, c.stroke, c.direction, q0, mech.output.kind, origin, unit)


def link_stroke(mech: Mechanism, load: Load, start: float) -> Stroke | None:
    """The :class:`Stroke` of a table load's own link (None when that link turns fully: no stroke).

    Sheet 1's rule of position 0 applied to that link as if it were the output: its extreme positions
    are where its velocity is zero (:func:`.positions.stationary`, exact), the working stroke starts at
    the one the load's ``working`` names (away from / towards the crank pivot), else the slower stroke's
    start, else (both strokes equal) the extreme farthest from the crank pivot. `start` is the crank
    angle of position 0 [rad] (sheet 1's, whatever link gave it)."""
    from dataclasses import replace

    from .mechanism import Output
    from .positions import stroke_numbers

    ln = mech.link(load.link)
    kind = "slider" if load.kind == "force" else "rocker"
    own = replace(mech, output=Output(kind, ln.name, load.joint or ln.name, ln.group), working=load.working,
                  gas_head=None)
    numbers = stroke_numbers(own)
    if numbers is None:
        return None
    extremes, length, working, direction = numbers
    origin = extremes[0]
    q0 = float(output_coordinate(own, solve(own, [origin]))[0][0])
    gd = dict(mech.guided()).get(ln.name) if kind == "slider" else None
    unit = gd.unit if gd is not None and not gd.moving else None
    return Stroke(start, mech.crank.sense, working, length, direction, q0, kind, origin, unit, ln.name)


def load_strokes(mech: Mechanism, loads, stroke: Stroke | None, start: float) -> tuple[Stroke | None, ...]:
    """Each table load's :class:`Stroke`: the output's (`stroke`, sheet 1's) for a load on the output
    link, its own link's (:func:`link_stroke`) for a load elsewhere; `start` is position 0's crank
    angle [rad]."""
    return tuple(stroke if ld.link == mech.output.link else link_stroke(mech, ld, start) for ld in loads)


def table_value(load: Load, fraction):
    """The load's magnitude at the fraction(s) of the stroke (linear between the table's entries).

    >>> table_value(Load("B", "force", (0.0, 0.5, 1.0), (0.0, 100.0, 100.0)), [0.25, 0.75])
    array([ 50., 100.])
    """
    return np.interp(np.asarray(fraction, dtype=float), load.stroke, load.values)


def table_integral(load: Load, fraction):
    """∫₀^f F(x) dx of the piecewise-linear table, exactly [N or N·m]: the load's work per unit of
    stroke (the area under the load diagram up to the fraction f).

    >>> ld = Load("B", "force", (0.0, 0.5, 0.5, 1.0), (0.0, 100.0, 200.0, 200.0))   # a jump at ½
    >>> [float(x) for x in table_integral(ld, [0.5, 1.0, 0.75])]   # 25; 25 + 100; 25 + 50
    [25.0, 125.0, 75.0]
    """
    x = np.asarray(load.stroke, dtype=float)
    y = np.asarray(load.values, dtype=float)
    cum = np.concatenate([[0.0], np.cumsum(np.diff(x) * (y[:-1] + y[1:]) / 2.0)])
    f = np.clip(np.asarray(fraction, dtype=float), 0.0, 1.0)
    j = np.clip(np.searchsorted(x, f, side="right") - 1, 0, len(x) - 2)
    return cum[j] + (f - x[j]) * (y[j] + table_value(load, f)) / 2.0


def phase(stroke: Stroke, phi):
    """The crank's travel since the working stroke last began [rad, 0 … 2π) at the crank angles
    `phi` — measured from the extreme position where the working stroke starts, whatever position 0
    is (``crank.start_deg`` may put it anywhere in the turn)."""
    t = np.remainder(stroke.sense * (np.asarray(phi, dtype=float) - stroke.origin), 2.0 * math.pi)
    return np.where(t > 2.0 * math.pi - WORKING_TOLERANCE, 0.0, t)


def progress(stroke: Stroke, mech: Mechanism, kin: Kinematics):
    """(phase, fraction, working) at the kinematics' angles: the crank's travel since the working
    stroke began [rad, 0 … 2π) (:func:`phase`), the fraction of the stroke covered since then
    (0 … 1), and whether the crank is on the working stroke (its end included)."""
    travel = phase(stroke, kin.phi)
    if stroke.link is None or stroke.link == mech.output.link:
        q = output_coordinate(mech, kin)[0]
    else:  # a load's own link: a slider's place along its guide, a turning link's angle
        q = kin.slide[stroke.link][0] if stroke.kind == "slider" else kin.angle[stroke.link]
    dq = q - stroke.q0
    if stroke.kind == "rocker":
        dq = np.remainder(dq + math.pi, 2.0 * math.pi) - math.pi
    fraction = np.clip(stroke.direction * dq / stroke.length, 0.0, 1.0)
    return travel, fraction, travel <= stroke.working + WORKING_TOLERANCE


def load_size(load: Load, stroke: Stroke, mech: Mechanism, kin: Kinematics):
    """The load's magnitude at the kinematics' angles [N or N·m]: the table's value at the fraction
    of the stroke covered on the working stroke, zero on the return stroke — the ordinates of its
    diagram against the crank's turn (the course's «диаграмма сил полезного сопротивления»)."""
    _, fraction, working = progress(stroke, mech, kin)
    return np.where(working, table_value(load, fraction), 0.0)


def working_spans(stroke: Stroke, end: float) -> tuple[tuple[float, float], ...]:
    """The crank's travel from position 0 [rad] on the working strokes, as intervals within
    [0, `end`] (`end`: the cycle's travel, 2π, or 4π for a two-turn cycle); a stroke that began
    before position 0 gives the first interval from 0.

    >>> st = Stroke(0.0, 1, 3.0, 0.1, 1, 0.0, "slider", 5.0)   # 3 rad of working stroke from 5 rad on
    >>> [tuple(round(x, 6) for x in s) for s in working_spans(st, 2 * math.pi)]
    [(0.0, 1.716815), (5.0, 6.283185)]
    """
    out = []
    k = -1
    while stroke.lead + 2.0 * math.pi * k < end - WORKING_TOLERANCE:
        lo = stroke.lead + 2.0 * math.pi * k
        hi = lo + stroke.working
        if hi > WORKING_TOLERANCE:
            out.append((max(lo, 0.0), min(hi, end)))
        k += 1
    return tuple(out)


def load_value(load: Load, stroke: Stroke, mech: Mechanism, kin: Kinematics):
    """The load at the kinematics' angles: a force as a complex vector [N] (along the guide,
    against the working motion) or a moment [N·m] (counter-clockwise positive, against the working
    swing); zero on the return stroke."""
    size = load_size(load, stroke, mech, kin)
    if load.kind == "moment":
        return -stroke.direction * size
    if load.direction is not None:  # its own fixed direction (a cutting force with a vertical part)
        return size * complex(math.cos(load.direction), math.sin(load.direction))
    g = mech.groups[mech.link(load.link).group - 1]
    if g.kind == "RRP" and not g.guide.moving:
        return -stroke.direction * size * g.guide.unit
    return -stroke.direction * size * slider_unit(mech, load.link, kin)


def _along(load: Load, stroke: Stroke) -> float:
    """The force's component along the working motion per unit of its size: −1 for a load against
    it; cos of the angle to the guide (signed) for a force of its own direction — only that part works."""
    if load.direction is None or stroke.unit is None:
        return -1.0
    w = stroke.direction * stroke.unit
    return math.cos(load.direction) * w.real + math.sin(load.direction) * w.imag


def _cumulative_work(load: Load, stroke: Stroke, fraction, theta):
    """The load's work [J] since the working stroke began at crank travel `theta` from that start
    (unwrapped: every whole turn adds one turn's work −H·∫₀¹F)."""
    turns = np.floor((theta + WORKING_TOLERANCE) / (2.0 * math.pi))
    within = theta - turns * 2.0 * math.pi
    whole = float(table_integral(load, 1.0))
    done = np.where(within <= stroke.working + WORKING_TOLERANCE, table_integral(load, fraction), whole)
    return _along(load, stroke) * stroke.length * (done + turns * whole)


def load_work(load: Load, stroke: Stroke, mech: Mechanism, kin: Kinematics, travel=None):
    """The load's work since position 0 [J], exactly: the area under the load diagram times the
    stroke, −H·∫₀^f F(x) dx on the working stroke (f the fraction covered), −H·∫₀¹ F(x) dx over
    a whole working stroke (H the stroke, or the swing in rad), counted from the working stroke's
    start and shifted to position 0. `travel` (the crank's travel since position 0 [rad], up to 2π)
    tells a whole turn's end from its start; without it the angles are taken within the first turn.

    The power F·v = −F·H·df/dt (the force opposes the motion that increases f), so the work is
    the area under the load diagram times the stroke, with a minus sign."""
    _, fraction, _ = progress(stroke, mech, kin)
    if travel is None:
        travel = np.remainder(stroke.sense * (kin.phi - stroke.start), 2.0 * math.pi)
        travel = np.where(travel > 2.0 * math.pi - WORKING_TOLERANCE, 0.0, travel)
    theta = np.asarray(travel, dtype=float) - stroke.lead
    _, f0, _ = progress(stroke, mech, solve(mech, [stroke.start]))
    at_zero = _cumulative_work(load, stroke, f0, np.array([-stroke.lead]))
    return _cumulative_work(load, stroke, fraction, theta) - at_zero[0]


def _numbers(r, value, key: str, example: str) -> tuple[float, ...]:
    if not isinstance(value, list) or not 2 <= len(value) <= TABLE_MAX:
        r.fail(f"'{key}' must be a list of 2 to {TABLE_MAX} numbers, e.g. {example}")
    return tuple(r.number(v, key, example) for v in value)


def parse_load(r, mech: Mechanism, raw, key: str = "load", anywhere: bool = False) -> Load | None:
    """The ``[load]`` table → :class:`Load` (`r`: the file's reader; None without a table). `key` names
    it in messages (``load``, or ``load[2]`` of several); `anywhere`: the load may sit on a link other
    than the output (one of several table loads, each measuring its own link's stroke)."""
    if raw is None:
        return None
    t = r.table(raw, key, LOAD_KEYS)
    if set(t) <= {"working"}:  # only which stroke is the working one (sheet 1's key): no load
        return None
    on = r.required(t, "on", f"{key}.on", 'on = "B"')
    if isinstance(on, str):
        name = r.name(on, f"{key}.on", 'on = "B"')
        ln = next((x for x in mech.links if x.kind == "slider" and x.name == name), None)
        if ln is None:
            r.fail(f"'{key}.on' is {name!r}: no slider sits on that joint; give a slider's joint (on = \"B\") or a "
                   "turning link by two joints (on = [\"C\", \"B\"])")
        kind, joint = "force", ln.name
    else:
        ends = r.names(on, f"{key}.on", 2, 'on = ["C", "B"]')
        ln = next((x for x in mech.links if x.axis is not None and x.kind not in ("block", "crank")
                   and set(x.axis) == set(ends)), None)
        if ln is None:
            r.fail(f"'{key}.on': no moving link joins {ends[0]} and {ends[1]} (the crank takes no load); give a "
                   "turning link by two joints, e.g. on = [\"C\", \"B\"], or a slider's joint")
        kind, joint = "moment", ends[1] if ends[1] not in mech.frame else ends[0]  # the end that moves
    if ln.name != mech.output.link and not anywhere:
        r.fail(f"'{key}.on' is the link {ln.name} but the output link is {mech.output.link}: the load follows the "
               f"output's working stroke; put output = {_output_key(ln)} at the top of the file")
    values_key, other = ("force", "moment") if kind == "force" else ("moment", "force")
    if other in t:
        what = "a slider takes a force" if kind == "force" else "a turning link takes a moment"
        r.fail(f"'{key}.{other}': {what}; give {key}.{values_key} = [...]")
    stroke = _numbers(r, r.required(t, "stroke", f"{key}.stroke", "stroke = [0.0, 0.5, 1.0]"), f"{key}.stroke",
                      "stroke = [0.0, 0.5, 1.0]")
    ex = f"{values_key} = [0.0, 500.0, 500.0]"
    values = _numbers(r, r.required(t, values_key, f"{key}.{values_key}", ex), f"{key}.{values_key}", ex)
    if len(values) != len(stroke):
        r.fail(f"'{key}.{values_key}' has {len(values)} values but '{key}.stroke' has {len(stroke)}; give one value "
               "per entry of the stroke")
    if stroke[0] != 0.0 or stroke[-1] != 1.0 or any(b < a for a, b in zip(stroke, stroke[1:])):
        r.fail(f"'{key}.stroke' must run from 0 to 1 without decreasing (fractions of the stroke; repeat a fraction "
               "for a jump), e.g. stroke = [0.0, 0.5, 0.5, 1.0]")
    direction = None
    if "direction_deg" in t:
        gd = dict(mech.guided()).get(ln.name)
        if kind != "force" or gd is None or gd.moving:
            r.fail(f"'{key}.direction_deg' gives a force its own direction: it acts on a slider on a fixed guide; leave "
                   "it out here (the load then opposes the working motion)")
        direction = math.radians(r.number(t["direction_deg"], f"{key}.direction_deg", "direction_deg = 170") % 360.0)
        if abs(math.cos(direction - gd.angle)) < 1e-6:
            r.fail(f"'{key}.direction_deg' is across the slider's guide: such a force does no work and is no useful "
                   "resistance; give a direction with a part along the guide")
    unit = "N" if kind == "force" else "N·m"
    for v in values:
        if not 0.0 <= v <= FORCE_MAX:
            r.fail(f"'{key}.{values_key}' has {v:g}; give magnitudes in [0, {FORCE_MAX:g}] {unit} (the load always "
                   "opposes the working motion)")
    working = None
    if "working" in t:
        working = r.choice(t["working"], f"{key}.working", ("away", "towards"), 'working = "away"')
    return Load(ln.name, kind, stroke, values, direction, working, joint, key)


def _output_key(ln) -> str:
    if ln.axis is None:
        return f'"{ln.name}"'
    return f'["{ln.axis[0]}", "{ln.axis[1]}"]'
