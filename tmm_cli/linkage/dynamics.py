"""The dynamics of the machine reduced to the crank over its cycle (one turn; a four-stroke engine's
two, :mod:`.turns`): M_r(φ), J_r(φ), the works, the constant driving moment, the change of kinetic
energy.

The dynamic model of a machine (Artobolevsky, "Динамика машин: приведение сил и масс",
"Уравнение движения машины"; Frolov, "Динамика машин"; METHOD.md "Sheets 1 and 2"):

- the reduced moment of the resistance and the weights M_r(φ) = Σ(F·v + M·ω)/ω₁ (:mod:`.power`);
- their work since position 0, A_r(φ) = ∫₀^φ M_r dφ — here exactly, not by a quadrature: the
  load's as the area under its diagram times the stroke (:func:`.loads.load_work`), the weights'
  as the fall of their centres, −Σ m·g·(y_S(φ) − y_S(0));
- the driving moment constant over the cycle Φ (2π, or 4π) with A_d(Φ) = −A_r(Φ): M_d = −A_r(Φ)/Φ;
- the change of kinetic energy ΔT(φ) = A_d(φ) + A_r(φ) = M_d·φ + A_r(φ);
- the reduced moment of inertia J_r(φ) = Σ(m·v_S² + J_S·ω²)/ω₁² + J_rotor, split into the first
  group's constant part (the crank and the rotor) and the second group's J_II(φ) (every other
  link).

Here φ is the crank's travel from position 0 in its sense of rotation, and the moments and works
of this module are signed in that sense (positive drives the crank); the records say how to turn
them counter-clockwise positive. The grid is sheet 1's curve (every 0.5° of the turn).
"""

from __future__ import annotations

import math

import numpy as np

from ..records import record
from .chain import Kinematics
from .forces import G, applied, load_symbol
from .loads import Stroke, load_size, load_strokes, load_work, working_spans
from .masses import centre_motion
from .mechanism import Mechanism
from .power import reduced_inertia, total_power
from .sheet2_file import Sheet2Input


@record(eq=False)
class LoadDiagram:
    """A table load's own diagram over the cycle (the course's «диаграмма сил полезного
    сопротивления» against φ): its magnitude on the dynamics' grid — the table's value at the
    fraction of its own link's stroke on that link's working stroke, zero on the return
    (:func:`.loads.load_size`)."""

    symbol: str  # 'Fc' / 'Mc' (the only table load), 'Fc3', 'Mc5' (several: the link's number)
    kind: str  # 'force' [N] | 'moment' [N·m]
    values: np.ndarray  # the magnitude at the dynamics' travels, ≥ 0 [N or N·m]
    spans: tuple[tuple[float, float], ...]  # its working strokes' crank travel from position 0 [rad]


@record(eq=False)
class Dynamics:
    """The machine reduced to the crank over one turn from position 0."""

    travel: np.ndarray  # φ: the crank's travel from position 0 [rad], 0 … 2π (a two-turn cycle: 0 … 4π)
    omega_mean: float  # ω_m = |ω₁| [rad/s]
    sense: int  # +1 the crank turns counter-clockwise
    J_r: np.ndarray  # reduced moment of inertia of the mechanism and the rotor [kg·m²]
    J_first: float  # its constant part: the crank and the rotor [kg·m²]
    J_rotor: float  # the rotor's, as the file gives it [kg·m²]
    M_r: np.ndarray  # reduced moment of the resistance and the weights, in the sense of rotation [N·m]
    A_r: np.ndarray  # their work since position 0 [J]
    M_d: float  # the constant driving moment, in the sense of rotation [N·m]
    loads: tuple[LoadDiagram, ...] = ()  # each table load's own diagram (the file's order)

    @property
    def J_II(self) -> np.ndarray:
        """The second group's reduced moment of inertia (the links other than the crank) [kg·m²]."""
        return self.J_r - self.J_first

    @property
    def A_d(self) -> np.ndarray:
        """The driving moment's work since position 0 [J]."""
        return self.M_d * self.travel

    @property
    def dT(self) -> np.ndarray:
        """ΔT = A_d + A_r: the change of kinetic energy since position 0 [J]."""
        return self.A_d + self.A_r

    @property
    def drive_moment_ccw(self) -> float:
        """M_d counter-clockwise positive [N·m] (negative for a crank turning clockwise)."""
        return self.sense * self.M_d


def driving_moment(resistance_work: float, cycle: float = 2.0 * math.pi) -> float:
    """M_d = −A_r(Φ)/Φ [N·m]: the constant moment doing over the cycle Φ (one turn, 2π; a four-stroke
    engine's two, 4π) the work the resistance takes (the energy balance of a steady cycle, A_d + A_r = 0).

    >>> round(driving_moment(-628.3185307179587), 12)   # 628 J a turn: 100 N·m
    100.0
    >>> round(driving_moment(-628.3185307179587, 4 * math.pi), 12)   # 628 J in two turns: 50 N·m
    50.0
    """
    return -resistance_work / cycle


def weights_work(kin: Kinematics, masses):
    """−Σ m·g·(y_S − y_S(0)) [J]: the weights' work from the first angle of `kin` on.

    >>> from .mechanism_file import parse_mechanism
    >>> from .chain import solve
    >>> from .masses import Mass
    >>> mech = parse_mechanism({"frame": {"O": [0, 0]}, "crank": {"pivot": "O", "joint": "A",
    ...     "length": 0.1, "omega": 10.0}, "group": [{"kind": "RRP", "joints": ["A", "B"],
    ...     "length": 0.3, "guide": {"through": [0, 0], "angle_deg": 90}, "branch": "ahead"}]})
    >>> piston = Mass("B", 3, 1.0, 0.0, "B", None, "B")   # rises by 2r = 0.2 m from φ = −90° to 90°
    >>> round(float(weights_work(solve(mech, [-np.pi / 2, np.pi / 2]), [piston])[1]), 12)
    -1.962
    """
    total = np.zeros(kin.phi.shape)
    for ms in masses:
        z, _, _ = centre_motion(kin, ms)
        total = total - ms.m * G * (z.imag - z.imag[0])
    return total


def dynamics(mech: Mechanism, inp: Sheet2Input, stroke: Stroke | None, kin: Kinematics, travel,
             strokes=None) -> Dynamics:
    """The reduced quantities on the grid `kin` at the crank travels `travel` (0 … 2π from
    position 0, both ends included: sheet 1's curve; 0 … 4π for a two-turn cycle); `strokes` each table
    load's (found when not given, :func:`.loads.load_strokes`)."""
    travel = np.asarray(travel, dtype=float)
    w_m = abs(kin.omega1)
    sense = 1 if kin.omega1 > 0 else -1
    if strokes is None:
        start = stroke.start if stroke is not None else (mech.crank.start if mech.crank.start is not None else 0.0)
        strokes = load_strokes(mech, inp.tables, stroke, start)
    loading = applied(mech, inp, stroke, kin, strokes)
    m_r = total_power(kin, loading, ("load", "weight")) / w_m
    a_r = np.zeros(travel.shape)
    diagrams = []
    for ld, st in zip(inp.tables, strokes):
        if st is not None:
            a_r = a_r + load_work(ld, st, mech, kin, travel)
            diagrams.append(LoadDiagram(load_symbol(mech, ld, len(inp.tables)), ld.kind,
                                        load_size(ld, st, mech, kin), working_spans(st, float(travel[-1]))))
    for gl in inp.gas:
        from .gas import gas_work, piston

        a_r = a_r + gas_work(gl, piston(gl, mech), mech, kin)
    if inp.gravity:
        a_r = a_r + weights_work(kin, inp.masses)
    rotor = inp.dynamics.J_rotor if inp.dynamics is not None else 0.0
    j_r = reduced_inertia(kin, inp.masses, rotor)
    crank = [ms for ms in inp.masses if ms.number == 1]
    j_first = rotor + float(reduced_inertia(kin, crank)[0])
    cycle = 2.0 * math.pi * max(1, round(float(travel[-1]) / (2.0 * math.pi)))  # a turn, or a four-stroke's two
    return Dynamics(travel, w_m, sense, j_r, j_first, rotor, m_r, a_r, driving_moment(float(a_r[-1]), cycle),
                    tuple(diagrams))
