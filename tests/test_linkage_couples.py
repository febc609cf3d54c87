"""The couples a slide transmits (issue 36): fixtures where none of them is zero.

In the examples every slide couple is exactly 0 — the slider's load and mass act at its pin, the
blocks have no J — so a wrong sign of a couple passed every test. The fixtures in
tests/data/kinetostatics/ put a slider's load and centre of mass off its pin (the guide's couple
M₀ₙ then holds their moment) and give a block a moment of inertia (the slot's couple M₂₃ is then
its inertia moment). Each couple is checked three ways a reader can redo: the free bodies rebuilt
from the reactions, the power balance (it sees the block's couple: the block turns), and by hand.
"""

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from tmm_cli.linkage.chain import solve
from tmm_cli.linkage.forces import AppliedForce, Loading, applied
from tmm_cli.linkage.kinetostatics import kinetostatics
from tmm_cli.linkage.loads import stroke_of
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.motion import cross
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2

FIXTURES = Path(__file__).resolve().parent / "data" / "kinetostatics"
NAMES = ("shaper_tool", "crosshead")
_CACHE = {}


def case(name):
    """(mechanism, kinematics, loading with the slider's forces moved off its pin, force analysis,
    the offsets [m] as complex numbers)."""
    if name not in _CACHE:
        path = FIXTURES / f"{name}.toml"
        raw = tomllib.loads(path.read_text(encoding="utf-8"))
        offsets = {k: complex(*v) for k, v in raw.pop("offsets").items()}
        m = parse_mechanism(raw, path.name)
        s1 = analyse_mechanism(m)
        kin = s1.cycle.kin
        base = applied(m, parse_sheet2(m, name), stroke_of(s1.cycle), kin)
        slider = next(ln for ln in m.links if ln.kind == "slider")
        forces = []
        for f in base.forces:
            if f.number == slider.number:
                shift = offsets["load"] if f.kind == "load" else offsets["centre"]
                f = AppliedForce(f.link, f.number, f.kind, f.symbol, f.point, f.z + shift, f.f)
            forces.append(f)
        loading = Loading(tuple(forces), base.couples)
        _CACHE[name] = (m, kin, loading, kinetostatics(m, loading, kin), offsets)
    return _CACHE[name]


@pytest.mark.parametrize("name", NAMES)
def test_every_slide_transmits_a_couple(name):
    """The fixtures do what they are for: no slide couple is zero (else its sign goes untested).
    The block's is small (J₂·ε₃ ≈ 0.08 N·m against M_b ≈ 190 N·m) but a million times the
    tolerance of the balances below (1e-9 of M_b)."""
    m, kin, loading, ks, _ = case(name)
    couples = [r for r in ks.reactions if r.couple is not None]
    assert len(couples) == sum(p.kind == "P" for p in m.pairs) >= 1
    scale = float(np.max(np.abs(ks.balancing)))
    for r in couples:
        assert np.max(np.abs(r.couple)) > 1e-6 * scale, r.label


@pytest.mark.parametrize("name", NAMES)
def test_power_balance_with_every_couple(name):
    """M_b from the power of the applied forces and couples, Σ(F·v + M·ω) + M_b·ω₁ = 0; the
    block's inertia moment does work (the block turns with the slotted link)."""
    m, k, loading, ks, _ = case(name)
    power = np.zeros(len(k.phi))
    for f in loading.forces:
        v, _ = k.body_point(f.link, f.z)
        power += f.f.real * v.real + f.f.imag * v.imag
    for c in loading.couples:
        power += c.m * k.omega[c.link]
    scale = float(np.max(np.abs(ks.balancing)))
    assert np.max(np.abs(ks.balancing + power / k.omega1)) <= 1e-9 * scale


@pytest.mark.parametrize("name", NAMES)
def test_every_link_is_in_equilibrium_with_its_reactions_and_couples(name):
    """Each link's free body rebuilt from the applied loads and the reactions found (a reaction
    R_ij acts on j, its opposite on i; so does a slide's couple): ΣF = 0 and ΣM = 0 about a pin."""
    m, k, loading, ks, _ = case(name)
    n = len(k.phi)
    big = max(float(np.max(np.abs(ks.balancing))), 1.0) * 1e-9
    for ln in m.links:
        force, moment = np.zeros(n, complex), np.zeros(n)
        ref = k.z[ln.pins[0]]
        forces, couples = loading.on(ln.number)
        for f in forces:
            force += f.f
            moment += cross(f.z - ref, f.f)
        for c in couples:
            moment += c.m
        for r in ks.reactions:
            i, j = r.pair.links
            sign = 1.0 if j == ln.number else -1.0 if i == ln.number else 0.0
            force += sign * r.force
            moment += sign * cross(r.at - ref, r.force)
            if r.couple is not None:
                moment += sign * r.couple
        if ln.number == 1:
            moment += ks.balancing
        assert np.max(np.abs(force)) < big * 1e3, (name, ln.name)
        assert np.max(np.abs(moment)) < big * 1e2, (name, ln.name)


@pytest.mark.parametrize("name", NAMES)
def test_guide_couple_is_minus_the_moment_of_the_offsets(name):
    """The slider translates: its rod's force passes through its pin, so the guide's couple alone
    holds the moment about the pin of the load at the load's offset d_l and of the weight and
    inertia at the centre's offset d_s: M₀ₙ = −(d_l × F_c + d_s × (G + Φ))."""
    m, k, loading, ks, off = case(name)
    slider = next(ln for ln in m.links if ln.kind == "slider")
    guide = next(r for r in ks.reactions if r.pair.kind == "P" and r.pair.links == (0, slider.number))
    held = np.zeros(len(k.phi))
    for f in loading.forces:
        if f.number == slider.number:
            held += cross(off["load"] if f.kind == "load" else off["centre"], f.f)
    assert np.max(np.abs(held)) > 1.0
    assert np.allclose(guide.couple, -held, rtol=1e-12, atol=1e-9)


def test_block_couple_is_its_inertia_moment_from_the_positions():
    """The block's forces act at its centre A, so the slot holds only its inertia moment:
    M₂₃ = −J₂·ε₃, ε₃ = ω₁²·d²θ₃/dφ² (a uniform crank) by central differences of the slotted
    link's angle from the positions alone."""
    m, k, loading, ks, _ = case("shaper_tool")
    block = next(ln for ln in m.links if ln.kind == "block")
    slotted = next(ln for ln in m.links if ln.kind == "slotted")
    j2 = 0.004  # tests/data/kinetostatics/shaper_tool.toml
    h = 1e-4
    theta = [np.unwrap(solve(m, k.phi + s * h).angle[slotted.name]) for s in (-1, 0, 1)]
    eps3 = k.omega1 ** 2 * (theta[0] - 2 * theta[1] + theta[2]) / h ** 2
    slot = next(r for r in ks.reactions if r.pair.kind == "P" and r.pair.links == (block.number, slotted.number))
    assert np.max(np.abs(slot.couple)) > 0.01
    assert np.allclose(slot.couple, -j2 * eps3, rtol=1e-5, atol=1e-7)


def test_crank_slider_with_the_load_above_the_guide_by_hand():
    """Massless links, a constant P against the working stroke acting h above the slider's pin:
    the guide's couple is P·h (the slider about its pin: (0, h) × (P, 0) = −P·h, held by the
    guide), and nothing else changes — the rod still carries P/cos β and M_b = P·r·sin(φ − β)/cos β;
    on the return stroke (no load) the couple is 0."""
    r, l, p, h = 0.05, 0.2, 1000.0, 0.03
    m = parse_mechanism({
        "frame": {"O": [0.0, 0.0]},
        "crank": {"pivot": "O", "joint": "A", "length": r, "rpm": 200},
        "group": [{"kind": "RRP", "joints": ["A", "B"], "length": l, "guide": {"through": [0.0, 0.0], "angle_deg": 0.0},
                   "branch": "ahead"}],
        "load": {"on": "B", "stroke": [0.0, 1.0], "force": [p, p], "working": "towards"},
    })
    s = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m))
    loading = Loading(tuple(AppliedForce(f.link, f.number, f.kind, f.symbol, f.point, f.z + 1j * h, f.f)
                            for f in s.loading.forces), s.loading.couples)
    ks = kinetostatics(m, loading, s.sheet1.cycle.kin)
    c = s.sheet1.cycle
    working = returning = 0
    for pos in c.positions:
        i, phi = pos.index, pos.phi
        guide = ks.reaction("R03").couple[i]
        if 1e-9 < pos.travel < c.working - 1e-9:
            working += 1
            beta = math.asin(-r * math.sin(phi) / l)
            assert guide == pytest.approx(p * h, rel=1e-12)
            assert abs(ks.reaction("R23").force[i]) == pytest.approx(p / math.cos(beta), rel=1e-12)
            assert ks.balancing[i] == pytest.approx(p * r * math.sin(phi - beta) / math.cos(beta), rel=1e-12)
        elif pos.travel > c.working + 1e-9:
            returning += 1
            assert guide == pytest.approx(0.0, abs=1e-9)
    assert working == 5 and returning >= 4
