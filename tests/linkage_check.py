"""Checks of sheets 1–2 shared by the linkage tests, written once from the textbook's statics, not
from the code under test."""

from __future__ import annotations

import numpy as np

from tmm_cli.linkage.motion import cross


def assert_every_link_in_equilibrium(s, name: str) -> None:
    """Rebuild each link's free body from the loads and the reactions the analysis found (the
    balancing moment on the crank): ΣF = 0 and ΣM = 0 about the link's first pin, every position."""
    m = s.sheet1.mechanism
    k = s.kin  # the cycle's positions: sheet 1's, or a four-stroke engine's two turns of them
    n = len(k.phi)
    big = max(float(np.max(np.abs(s.balancing))), 1.0) * 1e-9
    for ln in m.links:
        force = np.zeros(n, complex)
        moment = np.zeros(n)
        ref = k.z[ln.pins[0]]
        forces, couples = s.loading.on(ln.number)
        for f in forces:
            force += f.f
            moment += cross(f.z - ref, f.f)
        for c in couples:
            moment += c.m
        for r in s.forces.reactions:
            i, j = r.pair.links
            sign = 1.0 if j == ln.number else -1.0 if i == ln.number else 0.0
            if sign:
                force += sign * r.force
                moment += sign * cross(r.at - ref, r.force)
                if r.couple is not None:
                    moment += sign * r.couple
        if ln.number == 1:
            moment += s.balancing
        assert np.max(np.abs(force)) < big * 1e3, (name, ln.name)
        assert np.max(np.abs(moment)) < big * 1e2, (name, ln.name)


def with_start(data: dict, start: float | None) -> dict:
    """A mechanism file's tables with `crank.start_deg` set to `start` (or removed for None)."""
    d = dict(data)
    d["crank"] = dict(data["crank"])
    d["crank"].pop("start_deg", None)
    if start is not None:
        d["crank"]["start_deg"] = start
    return d
