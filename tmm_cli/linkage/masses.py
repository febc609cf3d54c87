"""The masses of the links (the ``[[mass]]`` tables of a mechanism file) and the motion of their
centres of mass.

One table per moving link that has a mass: a bar, the crank or a slotted link named by two of its
joints (``link = ["A", "B"]``), a slider or a block by its joint (``joint = "B"``)::

    [[mass]]
    link = ["A", "B"]
    m = 2.4            # [kg]
    J = 0.012          # [kg·m²] about the centre of mass (a slider: 0, it does not turn)
    centre = "S2"      # a joint or [[point]] fixed on the link (default: the middle of its two
                       # joints; a slider's or block's: its joint)

The centre must be a point of the link itself: one of its pins (the crank's pivot is one, a
balanced crank has ``centre = "O"``) or a ``[[point]]`` of it. A slotted link has no default (the
block's joint is not fixed on it). Links without a table are massless. Errors name the key as
``mass[2].m``; they are worded by the mechanism file's reader (:mod:`.mechanism_file`).
"""

from __future__ import annotations

import numpy as np

from ..records import record
from .chain import Kinematics
from .mechanism import Link, Mechanism

MASS_KEYS = ("link", "joint", "m", "J", "centre")
MASS_MAX = 1.0e5  # [kg]
INERTIA_MAX = 1.0e5  # [kg·m²]


@record
class Mass:
    """The mass of one moving link and where its centre is."""

    link: str  # the link's name (Mechanism.link)
    number: int  # the link's number (1 the crank)
    m: float  # [kg]
    J: float  # [kg·m²] about the centre of mass
    centre: str | None  # a joint or point fixed on the link; None: the middle of `ends`
    ends: tuple[str, str] | None  # the two pins whose middle is the centre (when centre is None)
    label: str  # the centre's name on drawings: `centre`, or 'S<number>' for a middle


def centre_motion(kin: Kinematics, mass: Mass):
    """(z, v, a) of the centre of mass [m, m/s, m/s²], complex arrays over the kinematics' angles.

    A named centre is read from the kinematics; the middle of two pins is the point of the link
    at (z1 + z2)/2, moved by the rigid-body formulas (:meth:`.chain.Kinematics.body_point`).
    """
    if mass.centre is not None:
        return kin.z[mass.centre], kin.v[mass.centre], kin.a[mass.centre]
    z = 0.5 * (kin.z[mass.ends[0]] + kin.z[mass.ends[1]])
    v, a = kin.body_point(mass.link, z)
    return z, v, a


def kinetic_energy(kin: Kinematics, masses) -> np.ndarray:
    """T = Σ (m·v_S²/2 + J_S·ω²/2) [J] of the given masses over the kinematics' angles (König).

    >>> from .mechanism_file import parse_mechanism
    >>> from .chain import solve
    >>> mech = parse_mechanism({"frame": {"O": [0, 0]}, "crank": {"pivot": "O", "joint": "A",
    ...     "length": 0.1, "omega": 10.0}, "group": [{"kind": "RRP", "joints": ["A", "B"],
    ...     "length": 0.3, "guide": {"through": [0, 0], "angle_deg": 0}, "branch": "ahead"}]})
    >>> crank = Mass("OA", 1, 2.0, 0.01, None, ("O", "A"), "S1")   # v_S = ω·r/2 = 0.5 m/s
    >>> float(kinetic_energy(solve(mech, [0.3]), [crank])[0])      # 2·0.25/2 + 0.01·100/2
    0.75
    """
    total = np.zeros(kin.phi.shape)
    for ms in masses:
        _, v, _ = centre_motion(kin, ms)
        total = total + 0.5 * ms.m * np.abs(v) ** 2 + 0.5 * ms.J * kin.omega[ms.link] ** 2
    return total


def _find_link(r, mech: Mechanism, ends, key: str) -> Link:
    for ln in mech.links:
        if ln.axis is not None and ln.kind != "block" and set(ln.axis) == set(ends):
            return ln
    r.fail(f"'{key}': no moving link joins {ends[0]} and {ends[1]}; name a link by two of its joints, "
           "e.g. [\"A\", \"B\"]")


def _centre(r, mech: Mechanism, ln: Link, value, key: str, where: str):
    """The centre's name (checked to be a point of the link) or None for the middle."""
    on_link = set(ln.pins) | {p.name for p in mech.points if p.link == ln.name}
    if value is None:
        if ln.kind in ("slider", "block"):
            return ln.pins[0]  # its joint (a PRP's block B′: the pin B)
        if ln.kind == "slotted":
            r.fail(f"'{key}' is missing: the slotted link {ln.name} has no fixed middle (the block slides along it); "
                   f"give its centre of mass as a [[point]] of the link, e.g. centre = \"S{ln.number}\"")
        return None
    name = r.name(value, key, 'centre = "S2"')
    if ln.kind in ("slider", "block"):
        if name != ln.pins[0]:
            r.fail(f"'{key}' is {name!r}: the centre of mass of the {ln.kind} {ln.name} is its joint {ln.name}; "
                   "leave centre out")
        return name
    if name not in on_link:
        points = ", ".join(sorted(on_link))
        r.fail(f"'{key}' is {name!r}, not a point of the link {where}; give one of its joints or [[point]]s "
               f"({points}), or define the centre as a [[point]] of the link")
    return name


def parse_masses(r, mech: Mechanism, raw) -> tuple[Mass, ...]:
    """The ``[[mass]]`` tables → :class:`Mass` records in link order (`r`: the file's reader)."""
    if raw is None:
        return ()
    if not isinstance(raw, list):
        r.fail("'mass' must be tables [[mass]]")
    if len(raw) > len(mech.links):
        r.fail(f"'mass' has {len(raw)} entries; at most {len(mech.links)} are read")
    seen: dict[str, str] = {}
    out = []
    for i, t in enumerate(raw, start=1):
        key = f"mass[{i}]"
        t = r.table(t, key, MASS_KEYS)
        if ("link" in t) == ("joint" in t):
            r.fail(f"'{key}' needs either link = [\"A\", \"B\"] (a bar, the crank, a slotted link) or joint = \"B\" "
                   "(a slider or a block), not both")
        if "link" in t:
            ends = r.names(t["link"], f"{key}.link", 2, 'link = ["A", "B"]')
            ln = _find_link(r, mech, ends, f"{key}.link")
            where = f"{ends[0]}–{ends[1]}"
        else:
            joint = r.name(t["joint"], f"{key}.joint", 'joint = "B"')
            ln = next((x for x in mech.links if x.kind in ("slider", "block") and x.name == joint), None)
            if ln is None:
                r.fail(f"'{key}.joint': no slider or block sits on the joint {joint}; name a bar by two joints, "
                       "e.g. link = [\"A\", \"B\"]")
            where = joint
        if ln.name in seen:
            r.fail(f"'{key}': the link {where} already has its mass in {seen[ln.name]}; give each link one [[mass]]")
        seen[ln.name] = key
        m = r.number(r.required(t, "m", f"{key}.m", "m = 2.4"), f"{key}.m", "m = 2.4")
        if not 0.0 <= m <= MASS_MAX:
            r.fail(f"'{key}.m' is {m:g}; a mass must lie in [0, {MASS_MAX:g}] kg")
        inertia = r.number(t.get("J", 0.0), f"{key}.J", "J = 0.012")
        if not 0.0 <= inertia <= INERTIA_MAX:
            r.fail(f"'{key}.J' is {inertia:g}; a moment of inertia must lie in [0, {INERTIA_MAX:g}] kg·m²")
        if ln.kind == "slider" and inertia != 0.0 and not mech.slider_turns(ln.name):
            r.fail(f"'{key}.J' is {inertia:g}: the slider {ln.name} does not turn; leave J out")
        centre = _centre(r, mech, ln, t.get("centre"), f"{key}.centre", where)
        ends = tuple(ln.axis) if centre is None else None
        out.append(Mass(ln.name, ln.number, m, inertia, centre, ends, centre or f"S{ln.number}"))
    return tuple(sorted(out, key=lambda x: x.number))
