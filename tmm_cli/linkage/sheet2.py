"""Sheet 2 of a lever mechanism as one frozen result: the force analysis of every position, Zhukovsky's
lever, the dynamics reduced to the crank and the flywheel.

Built on sheet 1 (:class:`~.sheet1.Sheet1`: the same positions and the same exact kinematics) and
the sheet-2 tables of the mechanism file (:mod:`.sheet2_file`). What `tmm linkage MECH.toml`
renders beside sheet 1, and what ``tmm project --mechanism`` hands to sheet 4: the constant
driving moment and the crank's speed (:meth:`Sheet2.motor_input`).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import TmmError
from ..notes import Note
from ..records import record
from .dynamics import Dynamics, dynamics
from .flywheel import Flywheel, flywheel
from .forces import Loading, applied
from .indicator import Indicator, indicators
from .kinetostatics import Kinetostatics, kinetostatics
from .loads import Stroke, load_strokes, stroke_of
from .polygons import ForcePolygon, force_polygons
from .power import balancing_moment_by_power, reduced_inertia, reduced_moment
from .scales import DIAGRAM_AXIS_MM, DIAGRAM_HEIGHT_MM, drafting_scale
from .sheet1 import Sheet1
from .sheet2_file import Sheet2Input
from .zhukovsky import Lever, LeverTable, lever, lever_scale, lever_table


@record
class DynamicsScales:
    """The drafter's scales of sheet 2's diagrams (each the smallest round μ with the largest
    ordinate within `height_mm`; the crank's turn on `axis_mm`)."""

    phi: float  # μ_φ [rad/mm]
    M: float  # μ_M [N·m/mm]
    A: float  # μ_A [J/mm] (the works A_r, A_d)
    T: float  # μ_T [J/mm] (ΔT, ΔT_I)
    J: float  # μ_J [kg·m²/mm] (J_r against the turn)
    axis_mm: float
    height_mm: float
    loads: tuple[float, ...] = ()  # μ of each table load's own diagram [N/mm or N·m/mm] (Dynamics.loads' order)


def dynamics_scales(dyn: Dynamics, fw: Flywheel | None, axis_mm: float = DIAGRAM_AXIS_MM,
                    height_mm: float = DIAGRAM_HEIGHT_MM) -> DynamicsScales:
    """μ of the diagrams M_r and M_d, A_r and A_d, ΔT (and ΔT_I), J_r over the cycle (a turn; a
    four-stroke engine's two on the same axis length), and of each table load's own diagram."""
    m = max(float(np.max(np.abs(dyn.M_r))), abs(dyn.M_d))
    a = max(float(np.max(np.abs(dyn.A_r))), float(np.max(np.abs(dyn.A_d))))
    t = float(np.max(np.abs(dyn.dT)))
    if fw is not None:
        t = max(t, float(np.max(np.abs(fw.mertsalov.dT_I - fw.mertsalov.dT_I[0]))))
    return DynamicsScales(float(dyn.travel[-1]) / axis_mm, drafting_scale(m, height_mm), drafting_scale(a, height_mm),
                          drafting_scale(t, height_mm), drafting_scale(float(np.max(dyn.J_r)), height_mm), axis_mm,
                          height_mm, tuple(drafting_scale(float(np.max(ld.values)), height_mm) for ld in dyn.loads))


@record(eq=False)
class Sheet2:
    sheet1: Sheet1
    input: Sheet2Input
    stroke: Stroke | None
    forces: Kinetostatics  # at the cycle's positions (:attr:`positions`: sheet 1's, or two turns of them)
    power_balance: np.ndarray  # M_b from the power balance at the positions [N·m]
    lever: Lever  # Zhukovsky's lever at the positions
    force_position: int  # the position of the force polygons and of the lever's drawing (list index)
    polygons: tuple[ForcePolygon, ...]  # of that position, the last group first, the crank last
    reduced_moment: np.ndarray  # M_r at the positions, counter-clockwise positive [N·m]
    reduced_inertia: np.ndarray  # J_r at the positions (with the rotor) [kg·m²]
    dynamics: Dynamics  # on the fine grid (every 0.5°)
    flywheel: Flywheel | None  # None without a [dynamics] table
    scales: DynamicsScales  # of the diagrams
    notes: tuple[Note, ...]
    turns: int = 1  # the crank turns of the machine's cycle (a four-stroke engine: 2)
    cycle_positions: tuple = ()  # its positions, a turn's repeated each turn (:mod:`.turns`); () = sheet 1's
    cycle_kin: object = None  # the kinematics at them, the crank angle as turned (None: sheet 1's)

    @property
    def positions(self):
        """The positions of the cycle, in the order the crank turns: sheet 1's for a cycle of one
        turn, 2·N of them (numbered on) for two. Every per-position array of this record follows it."""
        return self.cycle_positions or self.sheet1.cycle.positions

    @property
    def kin(self):
        """The kinematics at :attr:`positions` (a two-turn cycle: each turn's the first's, the crank
        angle φ0 + sense·travel as turned)."""
        return self.cycle_kin if self.cycle_kin is not None else self.sheet1.cycle.kin

    def curve_kin(self):
        """The kinematics on the dynamics' grid (:attr:`Dynamics.travel`): sheet 1's curve, or its
        turns repeated over a two-turn cycle."""
        c = self.sheet1.cycle
        if self.turns == 1:
            return c.curve.kin
        from .turns import repeat_curve

        return repeat_curve(c.curve.kin, c.curve.travel, self.turns, c.start, self.sheet1.mechanism.crank.sense)[0]

    def piston_force_diagram(self) -> tuple[dict[str, np.ndarray], float]:
        """Sheet 2's diagram of the piston forces: P = p·A [N] of each gas load's piston on the
        dynamics' grid over the cycle (+ away from its head; :func:`.gas.piston_forces`) and its
        drafting scale μ_P [N/mm] for DIAGRAM_HEIGHT_MM; ({}, 0.0) without a gas load."""
        if not self.input.gas:
            return {}, 0.0
        from .gas import piston_forces

        forces = piston_forces(self.sheet1.mechanism, self.input.gas, self.curve_kin())
        return forces, drafting_scale(max(float(np.max(np.abs(f))) for f in forces.values()), DIAGRAM_HEIGHT_MM)
    indicators: tuple[Indicator, ...] = ()  # the gas loads' indicator diagrams as drawn (:mod:`.indicator`)
    strokes: tuple = ()  # each table load's Stroke (input.tables' order): its own link's working stroke

    @property
    def loading(self) -> Loading:
        return self.forces.loading

    @property
    def balancing(self) -> np.ndarray:
        """M_b by the force analysis at the positions [N·m], counter-clockwise positive."""
        return self.forces.balancing

    def difference_pct(self) -> np.ndarray:
        """(M_b − M_b,Zhukovsky)/|M_b|·100 per position [%] (0 where M_b is 0 to rounding)."""
        mb, mz = self.balancing, self.lever.balancing
        scale = max(float(np.max(np.abs(mb))), 1e-300)
        size = np.maximum(np.abs(mb), 1e-9 * scale)
        return np.where(np.abs(mb) <= 1e-12 * scale, 0.0, 100.0 * (mb - mz) / size)

    def lever_points(self) -> dict[str, complex]:
        """The lever's points of the force position [mm from the pole at sheet 1's μ_v]: the velocity
        plan turned through 90° counter-clockwise, the images of the forces' points (a slider's
        pair's B′ as 'b′') and of the crank's point a."""
        i = self.force_position
        plan = self.sheet1.plans[0].velocity
        out = {n: 1j * z / plan.scale for n, z in plan.points.items()}
        for f in self.lever.forces:
            name = f.point.lower()
            if name not in plan.points and f.point not in plan.points:
                out[name] = complex(f.lever[i]) / plan.scale
        for f in self.lever.forces:
            out.setdefault("@" + f.symbol, complex(f.lever[i]) / plan.scale)
        out.setdefault("a", 1j * complex(self.sheet1.cycle.kin.v[self.sheet1.mechanism.crank.joint][i]) / plan.scale)
        return out

    @property
    def is_engine(self) -> bool:
        """A machine-motor: gas loads whose work over the cycle is given out (M_d < 0), so the gas
        forces drive and the constant moment is the consumer's resistance M_с = −M_d (the book's
        machine-motor, §2 of the dynamics; issue 34's review)."""
        return bool(self.input.gas) and self.dynamics.M_d < 0.0

    def lever_scale(self) -> float:
        """μ [(m/s)/mm] of Zhukovsky's lever as drawn on sheet 2 and read in the note."""
        return lever_scale(self.sheet1.plans[0].velocity.scale, self.lever_points().values())

    def lever_table(self) -> LeverTable:
        """Zhukovsky's lever of the force position at :meth:`lever_scale`: the one table of its
        forces' arms and moments, F_ур and M_ур that sheet 2 and the note print."""
        i = self.force_position
        return lever_table(self.sheet1.mechanism, self.sheet1.cycle.kin, self.lever, i, self.lever_scale(),
                           float(self.balancing[i]))

    def motor_input(self) -> tuple[float, float]:
        """(M [N·m], n [rpm]) for sheet 4: the driving moment's size and the crank's mean speed (the
        file's rpm back from ω to 12 digits: 60 rpm stays 60, not 59.99999999999999)."""
        return abs(self.dynamics.M_d), float(f"{self.sheet1.mechanism.crank.rpm:.12g}")


def _notes(s1: Sheet1, inp: Sheet2Input, fw: Flywheel | None, dyn: Dynamics) -> tuple[Note, ...]:
    notes = [Note.make("dynamics_uniform", "assumption", rpm=s1.mechanism.crank.rpm)]
    notes.append(Note.make("dynamics_gravity" if inp.gravity else "dynamics_no_gravity", "assumption"))
    if not inp.masses:
        notes.append(Note.make("dynamics_massless", "assumption"))
    if not inp.has_load:
        notes.append(Note.make("dynamics_no_load", "assumption"))
    if fw is None:
        notes.append(Note.make("dynamics_no_table", "assumption"))
    else:
        if fw.mertsalov.J_fl <= 0.0:
            notes.append(Note.make("dynamics_no_flywheel", "assumption", delta=fw.delta,
                                   delta_actual=fw.delta_actual))
        if fw.wittenbauer.J_fl > 0.0 and fw.mertsalov.J_fl > 0.0:
            diff = 100.0 * (fw.mertsalov.J_fl - fw.wittenbauer.J_fl) / fw.wittenbauer.J_fl
            notes.append(Note.make("dynamics_methods", "assumption", diff_pct=diff, j_w=fw.wittenbauer.J_fl))
    if dyn.M_d < 0.0 and inp.gas:  # an engine: the gas drives, the machine's resistance takes M_d
        notes.append(Note.make("dynamics_motor", "assumption", moment=-dyn.M_d))
    elif dyn.M_d < 0.0:
        notes.append(Note.make("dynamics_driving_negative", "warning", moment=dyn.M_d))
    return tuple(notes)


def analyse_sheet2(s1: Sheet1, inp: Sheet2Input, source: str = "mechanism") -> Sheet2:
    """Everything of sheet 2 for sheet 1's mechanism and positions.

    >>> from .mechanism_file import parse_mechanism
    >>> from .sheet1 import analyse_mechanism
    >>> from .sheet2_file import parse_sheet2
    >>> m = parse_mechanism({"frame": {"O": [0, 0]}, "crank": {"pivot": "O", "joint": "A",
    ...     "length": 0.05, "rpm": 300}, "group": [{"kind": "RRP", "joints": ["A", "B"],
    ...     "length": 0.2, "guide": {"through": [0, 0], "angle_deg": 0}, "branch": "ahead"}],
    ...     "load": {"on": "B", "stroke": [0, 1], "force": [1000, 1000], "working": "towards"}})
    >>> s = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m))
    >>> round(s.dynamics.M_d * 2 * math.pi, 9)   # the work of 1000 N over the 0.1 m stroke
    100.0
    """
    mech = s1.mechanism
    c = s1.cycle
    stroke = stroke_of(c)
    if inp.load is not None and stroke is None:
        raise TmmError(f"{source}: the load needs an output link that moves back and forth (it has no working "
                       f"stroke: {mech.output.link} turns fully); drop [load] or choose another output")
    strokes = load_strokes(mech, inp.tables, stroke, c.start)
    for ld, st in zip(inp.tables, strokes):
        if st is None:
            raise TmmError(f"{source}: '{ld.key}.on' is the link {ld.link}, which turns fully: it has no stroke to "
                           "measure the load's diagram along; put the load on a link that moves back and forth")
    for i, gl in enumerate(inp.gas, start=1):
        from .gas import piston

        if piston(gl, mech).q_near <= 0.0:
            raise TmmError(f"{source}: 'load[{i}].head' is reached by the piston {gl.link} (it comes "
                           f"{-piston(gl, mech).q_near:.6g} m past it); put the cylinder head beyond the piston's "
                           "dead centre")
    kin, curve_kin, curve_travel, turns, repeated = c.kin, c.curve.kin, c.curve.travel, 1, ()
    if inp.gas:
        from .gas import bind_cycle, cycle_turns

        turns = cycle_turns(inp.gas)
        if turns > 1:  # a four-stroke engine: the positions and the diagrams over its two turns
            from dataclasses import replace

            from .turns import repeat_curve, repeat_positions, repeat_positions_kin

            inp = replace(inp, gas=bind_cycle(inp.gas, mech, c.start))
            repeated = repeat_positions(c.positions, turns, mech.positions)
            kin = repeat_positions_kin(c.kin, c.positions, turns, c.start, mech.crank.sense)
            curve_kin, curve_travel = repeat_curve(c.curve.kin, c.curve.travel, turns, c.start, mech.crank.sense)
    loading = applied(mech, inp, stroke, kin, strokes)
    ks = kinetostatics(mech, loading, kin)
    i = s1.plans[0].position.index
    rotor = inp.dynamics.J_rotor if inp.dynamics is not None else 0.0
    dyn = dynamics(mech, inp, stroke, curve_kin, curve_travel, strokes)
    fw = flywheel(dyn, inp.dynamics) if inp.dynamics is not None else None
    return Sheet2(s1, inp, stroke, ks, balancing_moment_by_power(kin, loading), lever(mech, loading, kin), i,
                  force_polygons(mech, ks, i), reduced_moment(kin, loading), reduced_inertia(kin, inp.masses, rotor),
                  dyn, fw, dynamics_scales(dyn, fw), _notes(s1, inp, fw, dyn), turns, repeated,
                  kin if turns > 1 else None, indicators=indicators(mech, inp.gas, repeated or c.positions, kin),
                  strokes=strokes)
