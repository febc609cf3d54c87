"""Sheet 1 of any lever mechanism as one frozen result: structure, positions, plans, diagrams.

What `tmm linkage MECH.toml` renders (tables, figures, JSON, the sheet, the note); sheet 2
(forces and the flywheel) builds on the same :class:`~.mechanism.Mechanism` and
:class:`~.positions.Cycle`.
"""

from __future__ import annotations

import numpy as np

from ..errors import TmmError
from ..records import record
from .mechanism import Mechanism
from .positions import Cycle, cycle
from .scales import SCHEME_MM, DiagramScales, diagram_scales, drafting_scale
from .structure import Structure, structure
from .vector_plans import Plans, default_plan_positions, plans


@record(eq=False)
class Sheet1:
    mechanism: Mechanism
    structure: Structure
    cycle: Cycle
    plans: tuple[Plans, ...]  # the plans' positions: the asked (or the working stroke's) one first
    scales: DiagramScales  # of the diagrams s, v, a of the output link
    scheme_scale: float  # μ_l [m/mm] of the scheme in all positions


def analyse_mechanism(mech: Mechanism, plan: str | None = None, source: str = "mechanism") -> Sheet1:
    """Everything of sheet 1. `plan`: the label of the position of the (first) plans, e.g. '3'
    or "7'" (default: the file's `plan`, else the middle of the working stroke, or the position next to it
    where the plans are degenerate — a central crank-slider's v_BA = 0 at φ = 90°, as in the example).

    >>> from .mechanism_file import parse_mechanism
    >>> m = parse_mechanism({"frame": {"O": [0, 0]}, "crank": {"pivot": "O", "joint": "A",
    ...     "length": 0.06, "rpm": 1500}, "group": [{"kind": "RRP", "joints": ["A", "B"],
    ...     "length": 0.25, "guide": {"through": [0, 0], "angle_deg": 0}, "branch": "ahead"}]})
    >>> s = analyse_mechanism(m)
    >>> s.structure.formula, [p.position.label for p in s.plans], s.plans[0].velocity.scale
    ('I(0,1) → II(2,3)', ['4', '10'], 0.1)
    """
    c = cycle(mech, source)
    first, second = default_plan_positions(c)
    if plan is not None:
        i = c.index(plan)
        if i is None:
            labels = ", ".join(p.label for p in c.positions)
            raise TmmError(f"--plan {plan}: there is no such position; the positions are {labels}")
        first = i
    picks = [first] if first == second else [first, second]
    curve = c.curve
    scales = diagram_scales(float(np.max(np.abs(curve.s))), float(np.max(np.abs(curve.v))),
                            float(np.max(np.abs(curve.a))))
    zs = np.concatenate([curve.kin.z[n] for n in mech.joint_names])
    extent = max(float(np.ptp(zs.real)), float(np.ptp(zs.imag)))
    return Sheet1(mech, structure(mech), c, tuple(plans(c, i) for i in picks), scales, drafting_scale(extent, SCHEME_MM))
