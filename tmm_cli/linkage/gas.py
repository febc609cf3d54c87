"""Gas forces on pistons from their indicator diagrams (a ``[[load]]`` with ``head``): the piston
compressor, the two-stroke engine, the pump — a cycle of one crank turn — and the four-stroke
engine, a cycle of two turns.

The standard load of sheet 2 for engines and compressors (Artobolevsky, «Динамика машин»: the
indicator diagram; Frolov, «Силовой анализ механизмов»)::

    [[load]]
    on = "B"                  # the piston: a slider (RRP) or a yoke (RPP)
    head = [0.0, 0.45]        # a point of the cylinder head on the piston's line
    area = 0.0050             # the piston's area [m²]
    travel = [0.0, 0.1, 0.5, 1.0]                      # s/H from the dead centre nearest the head
    pressure = [[0.8, 0.2, 0.0, 0.0], [0.0, 0.1, 0.3, 0.8]]   # gauge pressure [MPa], one row a stroke

The force is p·A along the piston's guide, away from the head, on both strokes: row 1 while the
piston moves away from the head (from the dead centre nearest it), row 2 while it comes back. It
drives where the piston moves away and resists where it comes back. The pressure is linear in the
travel between the table's entries. Its work is exact: A·H·∫p dx over each stroke (+ away, − back),
the area of the indicator diagram times A·H over a cycle.

Four rows are a four-stroke engine's cycle of two crank turns (Artobolevsky, «Динамика машин»: the
indicator diagram of a four-stroke engine; Frolov, «Теория механизмов и машин», the engine's cycle
of 720°): expansion (away from the head), exhaust (back), intake (away), compression (back), in the
cycle's order from the dead centre nearest the head. Which pair of rows acts depends on the turn:
the load then carries ``origin``, the crank angle [rad] where its first row begins — its first dead
centre nearest the head at or after position 0 (:func:`bind_cycle`) — and the crank angles of the
kinematics are taken as turned, unwrapped (φ0 + sense·travel, travel 0 … 4π), not folded into a turn.
"""

from __future__ import annotations

import math

import numpy as np

from ..records import record
from .assembly import golden_min
from .chain import Kinematics, solve
from .mechanism import Mechanism

GAS_KEYS = ("on", "head", "area", "travel", "pressure")
PRESSURE_MAX = 1000.0  # [MPa]
AREA_MAX = 10.0  # [m²]
HEAD_TOLERANCE = 1e-6  # [m]: the head lies on the piston's line
GRID = 3600


@record
class GasLoad:
    """The gas force on a piston from its indicator diagram."""

    link: str  # the piston: a slider's or a yoke's link
    head: complex  # a point of the cylinder head on the piston's line [m]
    area: float  # [m²]
    travel: tuple[float, ...]  # s/H from the dead centre nearest the head, 0 … 1
    pressure: tuple[tuple[float, ...], ...]  # [MPa] gauge, one row a stroke (away, back; 4 rows: two turns)
    kind: str = "gas"
    origin: float | None = None  # a two-turn cycle: the crank angle where row 1 begins [rad] (None: the near dead centre)

    @property
    def turns(self) -> int:
        """The turns of the crank its cycle takes: 1 (2 rows) or 2 (4 rows, a four-stroke engine)."""
        return len(self.pressure) // 2


@record
class Piston:
    """A piston's dead centres: the crank angles and its distance from the head at them."""

    near: float  # crank angle of the dead centre nearest the head [rad]
    far: float  # … farthest from it [rad]
    q_near: float  # the distance from the head along the guide there [m]
    q_far: float
    away: complex  # the unit vector along the guide away from the head (a fixed guide)

    @property
    def stroke(self) -> float:
        """H [m]."""
        return self.q_far - self.q_near


def _away(gl: GasLoad, mech: Mechanism) -> complex:
    """The unit vector along the (fixed) cylinder away from the head: the side the piston is on at
    crank angle 0 (a head between the piston's dead centres shows as a negative distance)."""
    e = dict(mech.guided())[gl.link].unit
    pin = mech.link(gl.link).pins[0]
    z0 = complex(solve(mech, [0.0]).z[pin][0])
    return e if (e.conjugate() * (z0 - gl.head)).real >= 0.0 else -e


def _distance(gl: GasLoad, mech: Mechanism, kin: Kinematics):
    """(q, q̇): the piston's distance from the head along its cylinder [m] and its rate [m/s]."""
    away = _away(gl, mech)
    pin = mech.link(gl.link).pins[0]
    r = kin.z[pin] - gl.head
    return (away.conjugate() * r).real, (away.conjugate() * kin.v[pin]).real


_PISTONS: dict = {}


def piston(gl: GasLoad, mech: Mechanism) -> Piston:
    """The piston's dead centres over a turn (grid, then golden section to machine precision)."""
    key = (id(mech), gl)
    hit = _PISTONS.get(key)
    if hit is not None and hit[0] is mech:
        return hit[1]
    out = _piston(gl, mech)
    if len(_PISTONS) > 64:
        _PISTONS.clear()
    _PISTONS[key] = (mech, out)
    return out


def _piston(gl: GasLoad, mech: Mechanism) -> Piston:
    grid = np.arange(GRID) * (2.0 * math.pi / GRID)
    q, _ = _distance(gl, mech, solve(mech, grid))
    step = 2.0 * math.pi / GRID

    def best(sign):
        i = int(np.argmin(sign * q))
        x, fx = golden_min(lambda t: sign * _distance(gl, mech, solve(mech, t))[0], np.array([grid[i] - step]),
                           np.array([grid[i] + step]))
        return float(np.remainder(x[0], 2.0 * math.pi)), float(sign * fx[0])

    near, q_near = best(1.0)
    far, q_far = best(-1.0)
    return Piston(near, far, q_near, q_far, _away(gl, mech))


def _row_integral(travel, row, x):
    """∫₀^x p(t) dt of the piecewise-linear row [MPa] (x clipped to 0 … 1)."""
    t = np.asarray(travel, dtype=float)
    p = np.asarray(row, dtype=float)
    cum = np.concatenate([[0.0], np.cumsum(np.diff(t) * (p[:-1] + p[1:]) / 2.0)])
    x = np.clip(np.asarray(x, dtype=float), 0.0, 1.0)
    j = np.clip(np.searchsorted(t, x, side="right") - 1, 0, len(t) - 2)
    return cum[j] + (x - t[j]) * (p[j] + np.interp(x, t, p)) / 2.0


TURN_TOLERANCE = 1e-6  # [rad] of crank travel: the dead centres found to ~1e-8 still start their turn


def turn_of(gl: GasLoad, pst: Piston, mech: Mechanism, phi, back):
    """Which turn of a two-turn cycle (0 or 1) the crank angles `phi` (as turned, unwrapped) lie in,
    counted from the load's `origin`; `back` (0/1 per angle) says the piston comes back to the head —
    a back stroke ends a turn, so an angle a rounding past a near dead centre stays in its turn."""
    origin = pst.near if gl.origin is None else gl.origin
    theta = mech.crank.sense * (np.asarray(phi, dtype=float) - origin)
    nudge = TURN_TOLERANCE * (1.0 - 2.0 * np.asarray(back, dtype=float))
    return np.remainder(np.floor((theta + nudge) / (2.0 * math.pi)), 2.0).astype(int)


def state(gl: GasLoad, pst: Piston, mech: Mechanism, kin: Kinematics):
    """(x, row, q): the travel s/H from the dead centre nearest the head, the row of the diagram
    acting (0 moving away from the head, 1 coming back; at a dead centre, the stroke that starts
    there; a two-turn cycle: + 2 in its second turn, rows 0 … 3) and the distance from the head [m]."""
    q, qd = _distance(gl, mech, kin)
    x = np.clip((q - pst.q_near) / pst.stroke, 0.0, 1.0)
    tol = 1e-9 * pst.stroke * abs(mech.crank.omega)
    row = np.where(qd > tol, 0, np.where(qd < -tol, 1, np.where(x < 0.5, 0, 1)))
    if gl.turns == 2:
        row = row + 2 * turn_of(gl, pst, mech, kin.phi, row)
    return x, row, q


def gas_pressure(gl: GasLoad, pst: Piston, mech: Mechanism, kin: Kinematics):
    """The gauge pressure [Pa] on the piston at the kinematics' angles."""
    x, row, _ = state(gl, pst, mech, kin)
    p = np.choose(row, [np.interp(x, gl.travel, r) for r in gl.pressure])
    return p * 1.0e6


def gas_force(gl: GasLoad, pst: Piston, mech: Mechanism, kin: Kinematics):
    """The gas force p·A [N] as a complex vector along the guide, away from the head."""
    return gas_pressure(gl, pst, mech, kin) * gl.area * pst.away


def gas_work(gl: GasLoad, pst: Piston, mech: Mechanism, kin: Kinematics):
    """The gas force's work [J] from the first angle of `kin` on, exactly along the piston's path:
    +A·H·∫p₁ dx while it moves away from the head, −A·H·∫p₂ dx while it comes back, each stroke's
    piece split at the dead centre between two angles (the angles must follow the crank's turn
    closely enough that the piston passes at most one dead centre between them). A two-turn cycle's
    rows follow one another the same way: expansion, exhaust, intake, compression."""
    x, row, _ = state(gl, pst, mech, kin)
    scale = gl.area * pst.stroke * 1.0e6

    def integral(r, v):
        return _row_integral(gl.travel, gl.pressure[r], v)

    out = np.zeros(len(x))
    for i in range(1, len(x)):
        r0, r1, x0, x1 = int(row[i - 1]), int(row[i]), float(x[i - 1]), float(x[i])
        if r0 == r1:  # away: F along the motion, x grows; back: against it, x falls — both p·A·H·dx
            w = integral(r0, x1) - integral(r0, x0)
        else:
            end = 1.0 if r0 % 2 == 0 else 0.0  # the dead centre passed: the far one after a stroke away
            w = (integral(r0, end) - integral(r0, x0)) + (integral(r1, x1) - integral(r1, end))
        out[i] = out[i - 1] + scale * float(w)
    return out


def parse_gas(r, mech: Mechanism, t: dict, key: str) -> GasLoad:
    """A ``[[load]]`` with ``head`` → :class:`GasLoad` (`r`: the file's reader, `key`: 'load[1]')."""
    t = r.table(t, key, GAS_KEYS)
    ex_on = 'on = "B"'
    name = r.name(r.required(t, "on", f"{key}.on", ex_on), f"{key}.on", ex_on)
    ln = next((x for x in mech.links if x.kind == "slider" and x.name == name), None)
    guided = dict(mech.guided())
    if ln is None or name not in guided:
        r.fail(f"'{key}.on' is {name!r}: a gas force acts on a piston, a slider of an RRP group or the yoke of an RPP "
               "group; give its joint, e.g. on = \"B\"")
    head = r.xy(r.required(t, "head", f"{key}.head", "head = [0.0, 0.45]"), f"{key}.head", "head = [0.0, 0.45]")
    area = r.number(r.required(t, "area", f"{key}.area", "area = 0.005"), f"{key}.area", "area = 0.005")
    if not 0.0 < area <= AREA_MAX:
        r.fail(f"'{key}.area' is {area:g}; the piston's area must lie in (0, {AREA_MAX:g}] m²")
    ex_t = "travel = [0.0, 0.5, 1.0]"
    raw = r.required(t, "travel", f"{key}.travel", ex_t)
    if not isinstance(raw, list) or not 2 <= len(raw) <= 1000:
        r.fail(f"'{key}.travel' must be a list of 2 to 1000 numbers, e.g. {ex_t}")
    travel = tuple(r.number(v, f"{key}.travel", ex_t) for v in raw)
    if travel[0] != 0.0 or travel[-1] != 1.0 or any(b < a for a, b in zip(travel, travel[1:])):
        r.fail(f"'{key}.travel' must run from 0 to 1 without decreasing (s/H from the dead centre nearest the head), "
               f"e.g. {ex_t}")
    ex_p = "pressure = [[0.8, 0.1, 0.0], [0.0, 0.2, 0.8]]"
    rows = r.required(t, "pressure", f"{key}.pressure", ex_p)
    if not isinstance(rows, list) or not all(isinstance(x, list) for x in rows):
        r.fail(f"'{key}.pressure' must be a list of rows of gauge pressures [MPa], one row a stroke, e.g. {ex_p}")
    if len(rows) not in (2, 4):
        r.fail(f"'{key}.pressure' has {len(rows)} rows; give 2 (one turn: the stroke away from the head, then back) or "
               "4 (two turns, a four-stroke engine: expansion, exhaust, intake, compression)")
    pressure = []
    for j, row in enumerate(rows, start=1):
        if len(row) != len(travel):
            r.fail(f"'{key}.pressure' row {j} has {len(row)} values but '{key}.travel' has {len(travel)}; give one "
                   "pressure per travel")
        vals = tuple(r.number(v, f"{key}.pressure", ex_p) for v in row)
        for v in vals:
            if not -0.1013 <= v <= PRESSURE_MAX:
                r.fail(f"'{key}.pressure' has {v:g}; a gauge pressure must lie in [-0.1013, {PRESSURE_MAX:g}] MPa")
        pressure.append(vals)
    gl = GasLoad(ln.name, head, area, travel, tuple(pressure))
    gd = guided[name]
    if gd.moving:
        r.fail(f"'{key}.on': the piston {name} slides on a moving guide; a cylinder is fixed: give a piston on a fixed "
               "guide")
    pin = ln.pins[0]
    k = solve(mech, [0.0])
    off = abs(((complex(k.z[pin][0]) - head) * gd.unit.conjugate()).imag)
    if off > HEAD_TOLERANCE:
        r.fail(f"'{key}.head' is {off:.6g} m off the line of the piston {name}; put the cylinder head on it (within "
               f"{HEAD_TOLERANCE:g} m)")
    return gl


def piston_forces(mech: Mechanism, gas, kin: Kinematics) -> dict[str, np.ndarray]:
    """The gas force p·A [N] of every piston at the kinematics' angles, + away from its head (the
    piston force diagram of sheet 2)."""
    out = {}
    for gl in gas:
        pst = piston(gl, mech)
        out[gl.link] = gas_pressure(gl, pst, mech, kin) * gl.area
    return out


def cycle_turns(gas) -> int:
    """The turns of the crank the machine's cycle takes: the longest of its gas loads' (a four-stroke
    engine's 2; every other load repeats each turn).

    >>> cycle_turns([]), cycle_turns([GasLoad("B", 0j, 0.01, (0.0, 1.0), ((1.0, 0.0),) * 4)])
    (1, 2)
    """
    return max((gl.turns for gl in gas), default=1)


def bind_cycle(gas, mech: Mechanism, start: float) -> tuple:
    """The gas loads with the crank angle where each two-turn load's first row begins: its first dead
    centre nearest the head at or after position 0 (crank angle `start` [rad]), as turned from there
    (start + sense·τ, 0 ≤ τ < 2π; a dead centre within TURN_TOLERANCE of position 0 is position 0's)."""
    out = []
    for gl in gas:
        if gl.turns == 2:
            sense = mech.crank.sense
            tau = float(np.remainder(sense * (piston(gl, mech).near - start), 2.0 * math.pi))
            if tau < TURN_TOLERANCE or tau > 2.0 * math.pi - TURN_TOLERANCE:
                tau = 0.0
            gl = GasLoad(gl.link, gl.head, gl.area, gl.travel, gl.pressure, gl.kind, start + sense * tau)
        out.append(gl)
    return tuple(out)
