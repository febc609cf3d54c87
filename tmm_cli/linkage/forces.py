"""The forces applied to the links at given crank angles (d'Alembert): inertia forces and moments,
weights, the useful resistance.

The kinetostatic method (Artobolevsky, "Кинетостатика механизмов"; Frolov, "Силовой анализ
механизмов"; METHOD.md "Sheets 1 and 2"): each moving link carries, beside the real forces, its
inertia force Φ = −m·a_S at the centre of mass S and the inertia moment M_Φ = −J_S·ε, and is then
in equilibrium. Weights G = m·g act at S towards −y (when ``gravity = true``). The load (the useful
resistance, :mod:`.loads`) acts at the slider's joint along its guide, or as a moment on a rocker.
The crank turns uniformly at its mean speed (ε₁ = 0), as the book's kinetostatics assumes.

Forces and couples are arrays over the kinematics' angles: a force a complex vector [N] at a point
z [m], a couple a real moment [N·m], counter-clockwise positive. Symbols are the book's, language
neutral: Φ2, G2, MΦ2 (inertia force, weight, inertia moment of link 2), Fc, Mc (the resistance).
"""

from __future__ import annotations

import numpy as np

from ..records import record
from .chain import Kinematics
from .loads import Stroke, load_strokes, load_value
from .masses import centre_motion
from .mechanism import Mechanism
from .sheet2_file import Sheet2Input

G = 9.81  # [m/s²]


@record(eq=False)
class AppliedForce:
    """A force applied to a link (not a reaction)."""

    link: str  # the link it acts on
    number: int  # its number
    kind: str  # 'inertia' | 'weight' | 'load'
    symbol: str  # 'Φ2', 'G2', 'Fc'
    point: str  # the name of the point it acts at (a centre of mass, a slider's joint)
    z: np.ndarray  # where it acts (complex) [m]
    f: np.ndarray  # the force (complex) [N]


@record(eq=False)
class AppliedCouple:
    """A moment applied to a link."""

    link: str
    number: int
    kind: str  # 'inertia' | 'load'
    symbol: str  # 'MΦ2', 'Mc'
    m: np.ndarray  # [N·m], counter-clockwise positive


@record(eq=False)
class Loading:
    """Every applied force and couple at the kinematics' angles."""

    forces: tuple[AppliedForce, ...]
    couples: tuple[AppliedCouple, ...]

    def on(self, number: int):
        """(forces, couples) on the link of that number."""
        return (tuple(f for f in self.forces if f.number == number),
                tuple(c for c in self.couples if c.number == number))


def inertia_force(m: float, a_s):
    """Φ = −m·a_S [N] (d'Alembert), a_S the centre of mass's acceleration [m/s²] (complex).

    >>> complex(inertia_force(2.0, 3.0 - 4.0j))
    (-6+8j)
    """
    return -m * np.asarray(a_s)


def inertia_moment(J: float, eps):
    """M_Φ = −J_S·ε [N·m], ε the link's angular acceleration [rad/s²], ccw positive.

    >>> float(inertia_moment(0.5, 10.0))
    -5.0
    """
    return -J * np.asarray(eps, dtype=float)


def weight(m: float):
    """G = m·g towards −y [N] (complex), g = 9.81 m/s².

    >>> weight(2.0).imag
    -19.62
    """
    return -1j * m * G


def applied(mech: Mechanism, inp: Sheet2Input, stroke: Stroke | None, kin: Kinematics, strokes=None) -> Loading:
    """The applied forces and couples of every link at the kinematics' angles. A force or moment
    that is zero at every angle (the inertia of a crank turning uniformly about its centre of mass)
    is left out. `stroke` is the output's (sheet 1's); `strokes` each table load's
    (:func:`.loads.load_strokes`, found here when not given). One table load is Fc (Mc); of several,
    each is named by its link's number, Fc3, Mc5."""
    forces, couples = [], []
    for ms in inp.masses:
        n = ms.number
        z, _, a = centre_motion(kin, ms)
        if ms.m > 0.0:
            phi_f = inertia_force(ms.m, a)
            if np.any(phi_f != 0.0):
                forces.append(AppliedForce(ms.link, n, "inertia", f"Φ{n}", ms.label, z, phi_f))
            if inp.gravity:
                forces.append(AppliedForce(ms.link, n, "weight", f"G{n}", ms.label, z, np.full(z.shape, weight(ms.m))))
        if ms.J > 0.0:
            mom = inertia_moment(ms.J, kin.epsilon[ms.link])
            if np.any(mom != 0.0):
                couples.append(AppliedCouple(ms.link, n, "inertia", f"MΦ{n}", mom))
    for gl in inp.gas:
        from .gas import gas_force, piston

        ln = mech.link(gl.link)
        pin = ln.pins[0]
        forces.append(AppliedForce(ln.name, ln.number, "load", f"P{ln.number}", pin, kin.z[pin],
                                   gas_force(gl, piston(gl, mech), mech, kin)))
    tables = inp.tables
    if strokes is None:
        strokes = load_strokes(mech, tables, stroke, stroke.start if stroke is not None else _start(mech))
    for ld, st in zip(tables, strokes):
        if st is None:
            continue
        ln = mech.link(ld.link)
        value = load_value(ld, st, mech, kin)
        if ld.kind == "force":
            forces.append(AppliedForce(ln.name, ln.number, "load", load_symbol(mech, ld, len(tables)), ln.name,
                                       kin.z[ln.name], value))
        else:
            couples.append(AppliedCouple(ln.name, ln.number, "load", load_symbol(mech, ld, len(tables)), value))
    return Loading(tuple(forces), tuple(couples))


def load_symbol(mech: Mechanism, load, count: int) -> str:
    """A table load's symbol: Fc (a force) or Mc (a moment) when it is the only one (`count`), else
    followed by its link's number, Fc3, Mc5."""
    return ("Fc" if load.kind == "force" else "Mc") + (str(mech.link(load.link).number) if count > 1 else "")


def _start(mech: Mechanism) -> float:
    """Position 0's crank angle when the output has no stroke: ``start_deg`` or 0 (sheet 1's rule)."""
    return mech.crank.start if mech.crank.start is not None else 0.0
