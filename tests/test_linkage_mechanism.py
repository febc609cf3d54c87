"""Any lever mechanism of a crank and class II groups (issue 24): the crank-slider against its
textbook closed forms, positions against an independent Newton solution of the loop constraints,
velocities and accelerations against central differences of those positions, the plans' polygons,
the extreme positions, the structure, and the Whitworth mechanism of seed 003 against `tmm linkage`'s
own (article) model."""

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from tmm_cli.linkage.analysis import analyse
from tmm_cli.linkage.chain import solve
from tmm_cli.linkage.geometry import make_geometry
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.positions import cycle, output_coordinate
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.structure import structure
from tmm_cli.linkage.vector_plans import plans

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
NAMES = ("compressor", "four_bar", "shaper", "whitworth")


def load(name):
    path = EXAMPLES / f"{name}.toml"
    return parse_mechanism(tomllib.loads(path.read_text(encoding="utf-8")), path.name)


def slider_crank(r, l, e, rpm=300.0, sense="ccw"):
    """Crank O at the origin, the slider B on the line y = e along +x, B ahead (right)."""
    return parse_mechanism({
        "frame": {"O": [0.0, 0.0]},
        "crank": {"pivot": "O", "joint": "A", "length": r, "rpm": rpm, "sense": sense},
        "group": [{"kind": "RRP", "joints": ["A", "B"], "length": l,
                   "guide": {"through": [0.0, e], "angle_deg": 0.0}, "branch": "ahead"}],
        "point": [{"name": "S2", "link": ["A", "B"], "along": 0.3 * l}],
    })


# --- the crank-slider against the textbook's closed forms ----------------------------------------


@pytest.mark.parametrize("r, l, e", [(0.06, 0.24, 0.0), (0.05, 0.18, 0.02), (0.08, 0.25, -0.03)])
def test_crank_slider_textbook_closed_forms(r, l, e):
    m = slider_crank(r, l, e)
    w = m.crank.omega
    phi = np.linspace(0.0, 2 * np.pi, 73)
    k = solve(m, phi)
    lam = r / l
    sin_b = (r * np.sin(phi) - e) / l  # β: the rod's angle to the guide
    cos_b = np.sqrt(1.0 - sin_b ** 2)
    x_b = r * np.cos(phi) + np.sqrt(l * l - (r * np.sin(phi) - e) ** 2)
    v_b = -w * r * np.sin(phi + np.arcsin(sin_b)) / cos_b
    a_b = -w * w * r * (np.cos(phi + np.arcsin(sin_b)) / cos_b + lam * np.cos(phi) ** 2 / cos_b ** 3)
    w2 = -w * lam * np.cos(phi) / cos_b  # the rod AB's angle is −β
    e2 = w * w * lam * (np.sin(phi) / cos_b - lam * np.cos(phi) ** 2 * sin_b / cos_b ** 3)
    assert np.allclose(k.z["B"].real, x_b, atol=1e-14) and np.allclose(k.z["B"].imag, e, atol=1e-15)
    assert np.allclose(k.v["B"].real, v_b, atol=1e-12 * w * r) and np.allclose(k.v["B"].imag, 0.0, atol=1e-12)
    assert np.allclose(k.a["B"].real, a_b, atol=1e-11 * w * w * r) and np.allclose(k.a["B"].imag, 0.0, atol=1e-9)
    assert np.allclose(k.omega["AB"], w2, atol=1e-12 * w) and np.allclose(k.epsilon["AB"], e2, atol=1e-10 * w * w)
    if e == 0.0:  # the central mechanism's ε2 = ω²λ·sin φ·(1 − λ²)/(1 − λ²·sin²φ)^{3/2}
        book = w * w * lam * np.sin(phi) * (1 - lam ** 2) / (1 - lam ** 2 * np.sin(phi) ** 2) ** 1.5
        assert np.allclose(k.epsilon["AB"], book, atol=1e-10 * w * w)


@pytest.mark.parametrize("r, l, e", [(0.06, 0.24, 0.0), (0.05, 0.18, 0.02), (0.08, 0.25, -0.03)])
def test_crank_slider_stroke_and_time_ratio(r, l, e):
    """H = √((l + r)² − e²) − √((l − r)² − e²); the dead positions are the crank in line with the
    rod; K = (180° + θ)/(180° − θ) with θ = asin(e/(l − r)) − asin(e/(l + r))."""
    c = cycle(slider_crank(r, l, e))
    stroke = math.sqrt((l + r) ** 2 - e * e) - math.sqrt((l - r) ** 2 - e * e)
    theta = math.asin(e / (l - r)) - math.asin(e / (l + r))
    k = (math.pi + abs(theta)) / (math.pi - abs(theta))
    assert c.stroke == pytest.approx(stroke, abs=1e-13)
    assert c.time_ratio == pytest.approx(k, rel=1e-12)
    ext = sorted(math.degrees(x) for x in c.extremes)
    far, near = math.asin(e / (l + r)), math.pi + math.asin(e / (l - r))
    assert ext == pytest.approx(sorted(math.degrees(x) % 360 for x in (far, near)), abs=1e-9)


# --- positions: an independent solution of the constraints; closure ------------------------------


def _newton_chain(m, phis, start):
    """Positions by Newton's method on the constraints alone (|AB| = l, B on the guide, A on the
    slotted link's line), continued step by step from the positions at `start` (the branch)."""
    z = {n: complex(v) for n, v in start.items()}
    out = []
    for phi in phis:
        z[m.crank.joint] = m.frame[m.crank.pivot] + m.crank.length * complex(math.cos(phi), math.sin(phi))
        for name, zz in m.frame.items():
            z[name] = zz
        _place_points(m, 0, z)
        for g in m.groups:
            if g.kind == "RRR":
                a, b, c = (z[j] for j in g.joints)
                l1, l2 = g.lengths
                for _ in range(50):
                    f = np.array([abs(b - a) ** 2 - l1 ** 2, abs(b - c) ** 2 - l2 ** 2])
                    jac = np.array([[2 * (b - a).real, 2 * (b - a).imag], [2 * (b - c).real, 2 * (b - c).imag]])
                    dx = np.linalg.solve(jac, -f)
                    b += complex(dx[0], dx[1])
                    if abs(dx[0]) + abs(dx[1]) < 1e-16:
                        break
                z[g.joints[1]] = b
            elif g.kind == "RRP":
                a, b = z[g.joints[0]], z[g.joints[1]]
                e, p = g.guide.unit, g.guide.through
                s = ((b - p) * e.conjugate()).real
                for _ in range(50):
                    q = p + s * e
                    ds = -(abs(q - a) ** 2 - g.lengths[0] ** 2) / (2 * ((q - a) * e.conjugate()).real)
                    s += ds
                    if abs(ds) < 1e-17:
                        break
                z[g.joints[1]] = p + s * e
            _place_points(m, g.index, z)
        out.append(dict(z))
    return out


def _place_points(m, group, z):
    for pt in m.points:
        ln = m.link(pt.link)
        if ln.group == group:
            d = z[pt.toward] - z[pt.base]
            z[pt.name] = z[pt.base] + complex(pt.along, pt.across) * d / abs(d)


@pytest.mark.parametrize("name", NAMES)
def test_positions_match_an_independent_newton_solution(name):
    m = load(name)
    phis = np.linspace(0.0, 2 * np.pi, 1441)
    k = solve(m, phis)
    first = {n: x[0] for n, x in k.z.items()}
    newton = _newton_chain(m, phis, first)
    for n in k.z:
        got = k.z[n]
        want = np.array([d[n] for d in newton])
        assert np.max(np.abs(got - want)) < 1e-12, n


@pytest.mark.parametrize("name", NAMES)
def test_every_constraint_holds_over_the_turn(name):
    m = load(name)
    k = solve(m, np.linspace(0.0, 2 * np.pi, 721))
    for g in m.groups:
        if g.kind == "RRR":
            a, b, c = (k.z[j] for j in g.joints)
            assert np.max(np.abs(np.abs(b - a) - g.lengths[0])) < 1e-14
            assert np.max(np.abs(np.abs(b - c) - g.lengths[1])) < 1e-14
        elif g.kind == "RRP":
            a, b = (k.z[j] for j in g.joints)
            assert np.max(np.abs(np.abs(b - a) - g.lengths[0])) < 1e-14
            assert np.max(np.abs(((b - g.guide.through) * np.conj(g.guide.unit)).imag)) < 1e-14
        else:
            a, c = (k.z[j] for j in g.joints)
            u = np.exp(1j * k.angle[g.links[1]])  # the slotted link AC's direction, A → C
            assert np.max(np.abs((np.conj(u) * (c - a)).imag)) < 1e-14


# --- velocities and accelerations against central differences ------------------------------------


def _central(m, phis, h):
    """d/dt and d²/dt² of every point and link angle by central differences of positions solved
    by Newton's method (independently of the code's velocities), for the mechanism's ω1."""
    w = m.crank.omega
    dt = h / w
    start = {n: x[0] for n, x in solve(m, [phis[0] - h]).z.items()}
    steps = []
    for phi in phis:
        steps += [phi - h, phi, phi + h]
    zs = _newton_chain(m, steps, start)
    out = {}
    for n in zs[0]:
        z = np.array([d[n] for d in zs]).reshape(-1, 3)
        out[n] = ((z[:, 2] - z[:, 0]) / (2 * dt), (z[:, 2] - 2 * z[:, 1] + z[:, 0]) / dt ** 2)
    return out


@pytest.mark.parametrize("name", NAMES)
def test_velocities_and_accelerations_against_central_differences(name):
    m = load(name)
    phis = np.linspace(0.0, 2 * np.pi, 37)[:-1] + 0.01
    k = solve(m, phis)
    fd = _central(m, phis, 1e-4)
    for n, (v, a) in fd.items():
        vmax = max(np.max(np.abs(k.v[n])), 1e-9)
        amax = max(np.max(np.abs(k.a[n])), 1e-9)
        assert np.max(np.abs(k.v[n] - v)) < 1e-6 * max(vmax, 1.0), n
        assert np.max(np.abs(k.a[n] - a)) < 1e-4 * max(amax, 1.0), n


@pytest.mark.parametrize("name", NAMES)
def test_link_angles_differentiate_to_omega_and_epsilon(name):
    m = load(name)
    w = m.crank.omega
    h = 1e-4
    phis = np.linspace(0.0, 2 * np.pi, 25)[:-1] + 0.02
    k0, km, kp = solve(m, phis), solve(m, phis - h), solve(m, phis + h)
    dt = h / w
    for ln in m.links:
        wrap = lambda x: np.remainder(x + np.pi, 2 * np.pi) - np.pi  # noqa: E731
        d1 = wrap(kp.angle[ln.name] - km.angle[ln.name]) / (2 * dt)
        d2 = (wrap(kp.angle[ln.name] - k0.angle[ln.name]) - wrap(k0.angle[ln.name] - km.angle[ln.name])) / dt ** 2
        scale = max(w * w, np.max(np.abs(k0.epsilon[ln.name])))  # roundoff: 1e-16/dt² = 1e-8·ω²
        assert np.max(np.abs(d1 - k0.omega[ln.name])) < 1e-6 * max(1.0, abs(w)), ln.name
        assert np.max(np.abs(d2 - k0.epsilon[ln.name])) < 1e-6 * scale, ln.name


# --- the plans -----------------------------------------------------------------------------------


@pytest.mark.parametrize("name", NAMES)
def test_every_plan_closes_and_draws_its_lines(name):
    m = load(name)
    c = cycle(m)
    for i in range(len(c.positions)):
        pl = plans(c, i)
        for plan in (pl.velocity, pl.acceleration):
            pts = dict(plan.points)
            size = max(abs(z) for z in pts.values())
            for vec in plan.vectors:  # every vector is the difference of its end points
                assert abs(pts[vec.end] - pts[vec.start] - vec.value) < 1e-12 * size, (plan.kind, vec)
                if vec.line and vec.line != "guide":
                    j1, j2 = _split(m, vec.line)
                    d = c.kin.z[j2][i] - c.kin.z[j1][i]
                    dot, cross = (np.conj(d) * vec.value).real, (np.conj(d) * vec.value).imag
                    off = dot if vec.relation == "⊥" else cross
                    assert abs(off) < 1e-12 * size * abs(d) + 1e-15, (plan.kind, vec)
                    if vec.relation == "∥" and vec.symbol.startswith("a^n"):  # towards the centre
                        assert dot >= -1e-12 * size * abs(d), vec
            by_symbol = {v.symbol: v.value for v in plan.vectors}
            absolute = {f"{plan.kind[0]}_{n}": pts.get(n.lower(), 0j) for n in m.joint_names}
            absolute.update({f"{plan.kind[0]}_{g.joints[0]}{g.numbers[0]}": pts[g.joints[0].lower()]
                             for g in m.groups if g.kind == "RPR"})  # v_A2 = v_A: the block on the pin
            for eq in plan.equations:  # every side of every equation adds up to its left side
                if eq.group == 0 and plan.kind == "velocity":
                    continue  # v_A = ω1 × OA
                for side in eq.sides:
                    total = sum(by_symbol[s] if s in by_symbol else absolute[s] for s in side)
                    assert abs(total - by_symbol[eq.lhs]) < 1e-12 * size, (eq, side)


def _split(m, line):
    names = sorted(set(m.joint_names), key=len, reverse=True)
    for a in names:
        if line.startswith(a) and line[len(a):] in names:
            return a, line[len(a):]
    raise AssertionError(line)


def test_plan_scales_are_round_and_fit():
    s = analyse_mechanism(load("shaper"))
    for pl in s.plans:
        for plan in (pl.velocity, pl.acceleration):
            mantissa = plan.scale / 10 ** math.floor(math.log10(plan.scale))
            assert round(mantissa, 9) in (1.0, 2.0, 2.5, 4.0, 5.0)
            longest = max(abs(plan.mm(p)) for p in plan.points)
            assert 40.0 < longest <= 100.0 + 1e-9


def test_whitworth_plan_at_position_matches_the_article_model():
    """The Coriolis acceleration of the block and v_B of the new plans equal the old model's."""
    m = load("whitworth")
    c = cycle(m)
    g = make_geometry(0.10, 0.04, 0.0, 0.08, 0.30, -0.04)
    for i, p in enumerate(c.positions):
        pl = plans(c, i)
        old = analyse(g, omega=2 * math.pi, at_deg=(90.0 - math.degrees(p.phi)) % 360.0)
        cor = next(v for v in pl.acceleration.vectors if v.symbol.startswith("a^k"))
        assert cor.magnitude == pytest.approx(abs(old.at.a_cor), abs=1e-12)
        assert abs(pl.velocity.points["c"] - old.at.v_c) < 1e-12


# --- extreme positions, position 0, labels --------------------------------------------------------


@pytest.mark.parametrize("name", NAMES)
def test_extreme_positions_are_true_extrema(name):
    m = load(name)
    c = cycle(m)
    assert c.extremes is not None and c.stops == 2
    q0 = output_coordinate(m, solve(m, list(c.extremes)))
    for phi, q, v in zip(c.extremes, q0[0], q0[1]):
        assert abs(v) < 1e-12 * max(1.0, np.max(np.abs(c.curve.v)))
        for d in (1e-3, 1e-2, 0.1):
            qq = output_coordinate(m, solve(m, [phi - d, phi + d]))[0]
            side = np.sign(np.remainder(qq - q + np.pi, 2 * np.pi) - np.pi) if m.output.kind == "rocker" else np.sign(qq - q)
            assert side[0] == side[1] != 0, (phi, d)
    s = c.curve.s
    assert np.min(s) >= -1e-12 and np.max(s) <= c.stroke + 1e-12  # position 0 starts the stroke
    ext = [p for p in c.positions if p.extreme]
    assert [p.extreme for p in ext] == ["start", "end"]
    assert ext[0].label == "0" and ext[0].travel == 0.0
    assert ext[1].travel == pytest.approx(c.working, abs=1e-12)


@pytest.mark.parametrize("name", NAMES)
def test_structure_by_chebyshev(name):
    m = load(name)
    s = structure(m)
    assert s.dof == 1 and s.p4 == 0 and s.n == 1 + 2 * len(m.groups) and s.p5 == 1 + 3 * len(m.groups)
    assert s.formula.startswith("I(0,1)") and s.mechanism_class == 2
    assert [g.kind for g in s.groups[1:]] == [{"RRR": 1, "RRP": 2, "RPR": 3}[g.kind] for g in m.groups]


# --- the Whitworth mechanism of seed 003: the same numbers as `tmm linkage` gives today -----------


def test_whitworth_file_gives_the_numbers_of_tmm_linkage():
    m = load("whitworth")
    c = cycle(m)
    old = analyse(make_geometry(0.10, 0.04, 0.0, 0.08, 0.30, -0.04), omega=2 * math.pi)
    assert c.stroke == pytest.approx(old.stroke, abs=1e-15)
    assert c.time_ratio == pytest.approx(old.time_ratio, rel=1e-13)
    assert c.working == pytest.approx(old.working_rad, abs=1e-12)
    # the article's φ21 is measured from +y clockwise: φ = 90° − φ21
    assert [math.degrees(x) % 360 for x in c.extremes] == pytest.approx(
        [(90 - math.degrees(x)) % 360 for x in old.dead], abs=1e-9)
    evens = [p for p in c.positions if p.label.isdigit()]
    assert len(evens) == len(old.positions) == 12
    for p, s in zip(evens, old.positions):
        i = p.index
        assert math.degrees(p.phi) == pytest.approx((90 - math.degrees(s.phi)) % 360, abs=1e-9)
        assert c.kin.z["C"][i].real == pytest.approx(s.x_c, abs=1e-14)
        assert c.kin.v["C"][i].real == pytest.approx(s.v_c, abs=1e-13)
        assert c.kin.a["C"][i].real == pytest.approx(s.a_c, abs=1e-12)
        assert c.kin.slide["A"][0][i] == pytest.approx(s.rho, abs=1e-15)
        assert c.kin.slide["A"][1][i] == pytest.approx(s.v_rel, abs=1e-13)
        assert c.kin.omega["AO41"][i] == pytest.approx(-s.omega_link, abs=1e-12)  # the article's is clockwise
        assert c.kin.epsilon["AO41"][i] == pytest.approx(-s.eps_link, abs=1e-11)
        assert c.kin.omega["BC"][i] == pytest.approx(s.omega_rod, abs=1e-12)


def test_analyse_is_fast():
    import time

    m = load("shaper")
    analyse_mechanism(m)
    t0 = time.perf_counter()
    for _ in range(5):
        analyse_mechanism(m)
    assert (time.perf_counter() - t0) / 5 < 0.25  # the issue: well under a second


# --- a fully turning output, a given position 0, an accelerating crank ---------------------------


def test_double_crank_has_no_extreme_positions():
    """Drag-link (frame the shortest): the output turns fully; no stroke, no K, positions from 0°."""
    m = parse_mechanism({"frame": {"O": [0.0, 0.0], "C": [0.05, 0.0]},
                         "crank": {"pivot": "O", "joint": "A", "length": 0.15, "rpm": 60},
                         "group": [{"kind": "RRR", "joints": ["A", "B", "C"], "lengths": [0.18, 0.16], "branch": "left"}]})
    c = cycle(m)
    assert c.extremes is None and c.stroke is None and c.time_ratio is None and c.start_rule == "turning"
    assert [p.label for p in c.positions] == [str(i) for i in range(12)] and c.start == 0.0


def test_start_deg_overrides_position_0_and_labels_both_extremes():
    m = slider_crank(0.05, 0.18, 0.02, rpm=300.0)
    data_start = 10.0
    m2 = parse_mechanism({
        "frame": {"O": [0.0, 0.0]},
        "crank": {"pivot": "O", "joint": "A", "length": 0.05, "rpm": 300, "start_deg": data_start},
        "group": [{"kind": "RRP", "joints": ["A", "B"], "length": 0.18,
                   "guide": {"through": [0.0, 0.02], "angle_deg": 0.0}, "branch": "ahead"}]})
    c, c2 = cycle(m), cycle(m2)
    assert math.degrees(c2.start) == pytest.approx(data_start) and c2.start_rule == "given"
    assert sorted(p.extreme for p in c2.positions if p.extreme) == ["end", "start"]
    assert [p.phi for p in c2.positions if p.extreme == "start"] == pytest.approx([c.start], abs=1e-12)
    assert all("′" in p.label for p in c2.positions if p.extreme)
    assert c2.time_ratio == pytest.approx(c.time_ratio) and c2.stroke == pytest.approx(c.stroke)


def test_plans_of_an_accelerating_crank_close():
    from tmm_cli.linkage.vector_plans import plans_at

    m = load("shaper")
    c = cycle(m)
    k = solve(m, [c.positions[3].phi], eps1=5.0)
    pl = plans_at(m, k, c.positions[3])
    pts = pl.acceleration.points
    assert "n1" in pts
    for v in pl.acceleration.vectors:
        assert abs(pts[v.end] - pts[v.start] - v.value) < 1e-12 * max(abs(z) for z in pts.values())
    h = 1e-4
    w = m.crank.omega
    # with ε1 the crank's ω grows: a_B = d v_B/dt along φ(t) = φ + ωt + εt²/2
    dt = h / abs(w)
    phis = [c.positions[3].phi + w * t + 2.5 * t * t for t in (-dt, dt)]
    ks = [solve(m, [p], omega1=w + 5.0 * t) for p, t in zip(phis, (-dt, dt))]
    a_fd = (ks[1].v["C"][0] - ks[0].v["C"][0]) / (2 * dt)
    assert abs(a_fd - k.a["C"][0]) < 1e-5 * max(1.0, abs(k.a["C"][0]))


@pytest.mark.parametrize("name, d, r", [("shaper", 0.30, 0.10), ("whitworth", 0.04, 0.10)])
def test_the_slot_length_the_note_states_by_hand(name, d, r):
    """The block rides on the crank pin A, so its distance from the slotted link's pivot ranges from
    |d − r| to d + r (the crank pointing towards and away from the pivot, d apart): the note's ρ_min
    and ρ_max, which say how long the slot must be."""
    path = Path(__file__).resolve().parents[1] / "docs" / "examples" / f"{name}.toml"
    m = parse_mechanism(tomllib.loads(path.read_text(encoding="utf-8")), path.name)
    slot = next(n for n in cycle(m).notes if n.code == "mechanism_slot").kwargs
    assert slot["rho_min_mm"] == pytest.approx(abs(d - r) * 1000, abs=1e-6)
    assert slot["rho_max_mm"] == pytest.approx((d + r) * 1000, abs=1e-6)
