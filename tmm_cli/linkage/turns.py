"""A machine's cycle of several crank turns: a four-stroke engine's two (720°).

The kinematics of a lever mechanism repeat every turn; only the loads of a longer cycle (a
four-stroke engine's gas force: expansion and exhaust in one turn, intake and compression in the
next; Artobolevsky, «Динамика машин»; Frolov, «Теория механизмов и машин», the engine's cycle) do
not. Sheet 2 then takes the positions, the diagrams, ΔT and the flywheel over the whole cycle: the
positions of a turn repeated in the order the crank turns (``positions`` counts per turn, so a
two-turn cycle lists 2·N of them, numbered on: 0 … 2N−1, the extreme positions k′ of the second
turn (k+N)′), and the kinematics of each turn copied from the first — the same numbers bit for bit,
so J_r(φ + 360°) = J_r(φ) exactly — with the crank angle as turned, φ0 + sense·travel (travel
0 … 2π·turns), which tells the turns apart.
"""

from __future__ import annotations

import math

import numpy as np

from .chain import Kinematics
from .positions import Position

TWO_PI = 2.0 * math.pi


def _label(label: str, shift: int) -> str:
    """A position's label numbered on by `shift` ('7′' → '19′' for shift 12).

    >>> _label("7′", 12), _label("0", 12), _label("3", 0)
    ('19′', '12', '3')
    """
    digits = len(label) - len(label.lstrip("0123456789"))
    return str(int(label[:digits]) + shift) + label[digits:] if shift and digits else label


def repeat_positions(positions, turns: int, per_turn: int) -> tuple[Position, ...]:
    """The positions of a turn repeated `turns` times, in the order the crank turns: the travel
    grows by 2π a turn, the labels by `per_turn` (the regular positions per turn).

    >>> p = (Position(0, "0", 1.0, 0.0, "start"), Position(1, "0′", 2.0, 1.0, "end"), Position(2, "1", 3.0, 3.0, None))
    >>> [(q.index, q.label, round(q.travel, 4), q.extreme) for q in repeat_positions(p, 2, 2)][3:]
    [(3, '2', 6.2832, 'start'), (4, '2′', 7.2832, 'end'), (5, '3', 9.2832, None)]
    """
    out = []
    for t in range(turns):
        for p in positions:
            out.append(Position(len(out), _label(p.label, t * per_turn), p.phi, p.travel + t * TWO_PI, p.extreme))
    return tuple(out)


def take(kin: Kinematics, index, phi) -> Kinematics:
    """The kinematics at the angle numbers `index` of `kin`, labelled with the crank angles `phi`
    (the same angle a turn later: the same numbers)."""
    ix = np.asarray(index, dtype=int)
    return Kinematics(
        np.asarray(phi, dtype=float), kin.omega1, kin.eps1, {n: x[ix] for n, x in kin.z.items()},
        {n: x[ix] for n, x in kin.v.items()}, {n: x[ix] for n, x in kin.a.items()},
        {n: x[ix] for n, x in kin.angle.items()}, {n: x[ix] for n, x in kin.omega.items()},
        {n: x[ix] for n, x in kin.epsilon.items()}, {n: tuple(q[ix] for q in x) for n, x in kin.slide.items()},
        kin.base)


def repeat_positions_kin(kin: Kinematics, positions, turns: int, start: float, sense: int) -> Kinematics:
    """The kinematics of a turn's positions (`kin`, in their order) over `turns` turns, the crank
    angles as turned from position 0 (φ0 + sense·travel)."""
    n = len(positions)
    travel = np.concatenate([[p.travel + t * TWO_PI for p in positions] for t in range(turns)])
    return take(kin, np.tile(np.arange(n), turns), start + sense * travel)


def repeat_curve(kin: Kinematics, travel, turns: int, start: float, sense: int) -> tuple[Kinematics, np.ndarray]:
    """(kinematics, travel) of a turn's dense curve (both ends included) over `turns` turns: each
    turn after the first adds the curve's points after its start (its end is the next turn's start).

    >>> t = np.linspace(0.0, TWO_PI, 5)
    >>> [round(float(x / math.pi), 2) for x in np.concatenate([t] + [t[1:] + TWO_PI])]
    [0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0]
    """
    travel = np.asarray(travel, dtype=float)
    m = len(travel)
    index = np.concatenate([np.arange(m)] + [np.arange(1, m)] * (turns - 1))
    full = np.concatenate([travel] + [travel[1:] + t * TWO_PI for t in range(1, turns)])
    return take(kin, index, start + sense * full), full
