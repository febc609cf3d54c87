"""The links' roles, as the course names them (Artobolevsky; METHOD.md "Sheets 1 and 2"):
кривошип — turns fully about the frame; коромысло — swings about the frame; шатун — joins two moving
joints; ползун — slides on a fixed guide; кулиса — the slotted link (a moving guide); кулисный
камень — the block sliding in it. Derived from the structure (which joints a link has on the frame)
and, for a bar pivoted on the frame, from its motion over the turn (full turn or swing).
"""

from __future__ import annotations

import math

import numpy as np

ROLES = ("crank", "rocker", "coupler", "slider", "slotted", "block")


def link_roles(s1) -> dict[str, str]:
    """Link name → role (one of ROLES) for sheet 1's mechanism `s1` (a :class:`~.sheet1.Sheet1`).

    >>> from .mechanism_file import parse_mechanism
    >>> from .sheet1 import analyse_mechanism
    >>> m = parse_mechanism({"frame": {"O": [0, 0], "C": [0.3, 0]}, "crank": {"pivot": "O",
    ...     "joint": "A", "length": 0.08, "rpm": 60}, "group": [{"kind": "RRR",
    ...     "joints": ["A", "B", "C"], "lengths": [0.28, 0.2], "branch": "left"}]})
    >>> link_roles(analyse_mechanism(m))
    {'OA': 'crank', 'AB': 'coupler', 'BC': 'rocker'}
    """
    m = s1.mechanism
    kin = s1.cycle.curve.kin
    out = {}
    guides = {}  # the links that carry a moving guide: each is a кулиса
    for slider, gd in m.guided():  # an RRP's slider, a PRP's blocks, an RPP's yoke on a moving guide
        if gd.moving:
            guides[slider] = gd.link
    for g in m.groups:
        if g.kind == "RPP":  # the block in the yoke's slot: a кулисный камень (its guide is the yoke)
            guides[g.links[0]] = g.links[1]
    yokes = {g.links[1] for g in m.groups if g.kind == "RPP"}
    for ln in m.links:
        if ln.name in yokes:
            out[ln.name] = "slotted"  # the Scotch yoke: its slot guides the block (a кулиса that slides)
            continue
        if ln.kind == "slider" and ln.name in guides:
            out[ln.name] = "block"  # a block sliding along a moving link: a кулисный камень
            continue
        if ln.kind in ("crank", "slider", "slotted", "block"):
            out[ln.name] = ln.kind
            continue
        ends = ln.axis or ()
        if not any(j in m.frame for j in ends):
            out[ln.name] = "coupler"  # both of its joints move
            continue
        if ln.name in guides.values():
            out[ln.name] = "slotted"  # its guide carries a block: a кулиса
            continue
        angle = np.unwrap(np.asarray(kin.angle[ln.name], dtype=float))
        turns = abs(float(angle[-1] - angle[0])) >= 2.0 * math.pi * 0.99 or float(np.ptp(angle)) >= 2.0 * math.pi * 0.99
        out[ln.name] = "crank" if turns else "rocker"
    return out
