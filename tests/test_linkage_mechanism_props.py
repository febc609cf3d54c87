"""Properties over random assemblable crank-rocker four-bars (Grashof, the crank shortest): the
extreme positions where the crank and the coupler fall in line, the rocker's swing, K, the worst
pressure angle from the extreme transmission angles, and velocities against central differences."""

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from tmm_cli.linkage.chain import solve
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.positions import cycle
from tmm_cli.linkage.sheet1 import analyse_mechanism


def four_bar(a, b, c, d, gamma, branch, rpm, sense):
    """Crank OA = a about O = 0, coupler AB = b, rocker CB = c about C at d·e^{iγ}."""
    return parse_mechanism({
        "frame": {"O": [0.0, 0.0], "C": [d * math.cos(gamma), d * math.sin(gamma)]},
        "crank": {"pivot": "O", "joint": "A", "length": a, "rpm": rpm, "sense": sense},
        "group": [{"kind": "RRR", "joints": ["A", "B", "C"], "lengths": [b, c], "branch": branch}],
    })


def _b_at(o, cpt, radius_ob, c, branch):
    """B with |OB| = radius_ob and |CB| = c, left (+1) or right (−1) of the line O→C."""
    d = abs(cpt - o)
    p = (d * d + radius_ob ** 2 - c * c) / (2 * d)
    h = math.sqrt(radius_ob ** 2 - p * p)
    return o + (p + 1j * branch * h) * (cpt - o) / d


lengths = st.floats(0.05, 0.6)


@settings(max_examples=60, deadline=None)
@given(a=st.floats(0.02, 0.1), b=lengths, c=lengths, d=lengths, gamma=st.floats(-math.pi, math.pi),
       branch=st.sampled_from(["left", "right"]), rpm=st.floats(10, 3000), sense=st.sampled_from(["ccw", "cw"]))
def test_random_crank_rocker(a, b, c, d, gamma, branch, rpm, sense):
    assume(a < min(b, c, d) - 0.01)
    assume(a + max(b, c, d) < (a + b + c + d - a - max(b, c, d)) - 0.03)  # Grashof with room
    assume(d + a < b + c - 0.02 and d - a > abs(b - c) + 0.02)  # never in line: no dead point
    m = four_bar(a, b, c, d, gamma, branch, rpm, sense)
    cyc = cycle(m)
    sgn = 1 if branch == "left" else -1
    o, cpt = 0j, complex(d * math.cos(gamma), d * math.sin(gamma))
    # with A on the line OB, B is on the same side of A→C as of O→C (cross products of one sign)
    b_ext, b_fold = _b_at(o, cpt, a + b, c, sgn), _b_at(o, cpt, b - a, c, sgn)
    phi_ext = math.atan2(b_ext.imag, b_ext.real)
    assert abs(solve(m, [phi_ext]).z["B"][0] - b_ext) < 1e-9
    phi_fold = math.atan2(b_fold.imag, b_fold.real) + math.pi
    assert abs(solve(m, [phi_fold]).z["B"][0] - b_fold) < 1e-9
    got = sorted(x % (2 * math.pi) for x in cyc.extremes)
    want = sorted(x % (2 * math.pi) for x in (phi_ext, phi_fold))
    assert got == pytest.approx(want, abs=1e-9)
    swing = abs(math.remainder(np.angle(b_ext - cpt) - np.angle(b_fold - cpt), 2 * math.pi))
    assert cyc.stroke == pytest.approx(swing, abs=1e-9)
    theta = abs(math.remainder(phi_ext - phi_fold + math.pi, 2 * math.pi))  # the angle between OB_ext and OB_fold
    assert max(cyc.time_ratio, 1 / cyc.time_ratio) == pytest.approx((math.pi + theta) / (math.pi - theta), rel=1e-9)
    assert cyc.time_ratio >= 1 - 1e-12  # no `working`: the slower stroke is the working one
    # transmission angle μ at B: cos μ = (b² + c² − |AC|²)/(2bc), |AC| from d − a to d + a
    mus = [math.acos((b * b + c * c - x * x) / (2 * b * c)) for x in (d - a, d + a)]
    worst = max(abs(math.pi / 2 - mu) for mu in mus)
    assert cyc.pressure[0].worst == pytest.approx(worst, abs=1e-9)
    # velocities against central differences at a random-ish angle
    phi = 0.3 + gamma
    h = 1e-5
    w = m.crank.omega
    kk = solve(m, [phi - h, phi, phi + h])
    v_fd = (kk.z["B"][2] - kk.z["B"][0]) / (2 * h / w)
    assert abs(kk.v["B"][1] - v_fd) < 1e-6 * max(1.0, abs(w) * a)


@settings(max_examples=15, deadline=None)
@given(a=st.floats(0.02, 0.08), b=st.floats(0.2, 0.4), gamma=st.floats(-math.pi, math.pi))
def test_random_plans_close(a, b, gamma):
    m = four_bar(a, b, 0.25, 0.3, gamma, "left", 100.0, "ccw")
    assume(0.3 + a < b + 0.25 - 0.02 and 0.3 - a > abs(b - 0.25) + 0.02 and a + b < 0.55 - 0.02)
    s = analyse_mechanism(m)
    for pl in s.plans:
        for plan in (pl.velocity, pl.acceleration):
            for v in plan.vectors:
                assert abs(plan.points[v.end] - plan.points[v.start] - v.value) < 1e-12 * max(
                    abs(z) for z in plan.points.values())
