"""Assembly (2.4) and neighbouring (2.5) checked by a geometric simulation, written apart from
the program: teeth as angular positions on pitch circles, planets placed at 2π·j/k."""

import math
import random

import pytest

from tmm_cli.gears.planetary.conditions import (
    assembly_book,
    assembly_ok,
    check_stage,
    max_planets,
    neighbour_limit,
    neighbour_ok,
    Stage,
)

TOL = 1e-7


def _wrap(a, period):
    """a reduced to (−period/2, period/2]."""
    return a - period * math.floor(a / period + 0.5)


def _near_multiple(a, period):
    return abs(_wrap(a, period)) < TOL


def geometric_fit(k, zk, zc, zc2, zn):
    """Place k identical planet blocks at θ_j = 2π·j/k between a standing sun and ring.

    Module 1, pitch radii r = z/2. The sun has tooth centres at 2π·i/z_k, the ring at 2π·i/z_n.
    Pitch circles roll without slip, so at a pitch point a tooth centre of one wheel at arc d
    (along the common tangent) faces a space centre of the other at the same arc d. Planet 0 is
    set in mesh with the sun; its row-2 gear c′ is then fixed on the block so that it meshes the
    ring (the block is made this way; all blocks alike). Planet j is set in mesh with the sun —
    z_c orientations, differing by whole teeth of c — and must then mesh the ring too."""
    rk, rc, rc2, rn = zk / 2, zc / 2, zc2 / 2, zn / 2
    assert abs(rk + rc + rc2 - rn) < 1e-12  # coaxial
    tau_k, tau_c, tau_c2, tau_n = (2 * math.pi / z for z in (zk, zc, zc2, zn))

    def planet_c_space(theta):
        # sun: arc (ccw) from the pitch point to the nearest sun tooth centre
        d = rk * _wrap(0.0 - theta, tau_k)
        # on the planet the ccw tangent at its pitch point (direction θ+π) is opposite: a space
        # centre of c sits clockwise by d/r_c from the pitch point
        return theta + math.pi - d / rc

    def c2_space_needed(theta):
        # ring: arc (ccw) from its pitch point at θ to the nearest ring tooth centre; the planet's
        # pitch point is outward (direction θ), same ccw tangent: a space of c′ at θ + d/r_c′
        d = rn * _wrap(0.0 - theta, tau_n)
        return theta + d / rc2

    # planet 0: a space of c at s0, a space of c′ at t0; the block's offset β = t0 − s0
    s0 = planet_c_space(0.0)
    beta = c2_space_needed(0.0) - s0
    for j in range(1, k):
        th = 2 * math.pi * j / k
        s = planet_c_space(th)
        need = c2_space_needed(th)
        ok = False
        for w in range(zc):  # the block turned by w whole teeth of c still meshes the sun
            c2_space = s + w * tau_c + beta
            if _near_multiple(c2_space - need, tau_c2):
                ok = True
                break
        if not ok:
            return False
    return True


def tips_clear(k, zk, zc, zc2):
    """Tip circles (radius z/2 + h_a*) of the larger planet on neighbouring positions keep a gap."""
    a = (zk + zc) / 2
    r_tip = max(zc, zc2) / 2 + 1
    return k == 1 or 2 * a * math.sin(math.pi / k) > 2 * r_tip


def test_simulation_reproduces_the_book_2_4():
    # §2.4: 40/25/90 takes k = 2, 5, 10, 13 … (z_k + z_n = 130)
    ks = [k for k in range(2, 14) if geometric_fit(k, 40, 25, 25, 90)]
    assert ks == [2, 5, 10, 13]
    assert [k for k in range(2, 14) if assembly_ok(k, 40, 25, None, 90)] == ks


def test_simulation_double_planet_turned_by_whole_teeth():
    # 20/64/42/126 gives 53/5; the book's form (k | N, z_k·i = 212/1) admits only 2 and 4 below 5,
    # the exact condition also 3 and 6 — the simulation agrees with the exact one
    n, d = assembly_book(20, 64, 42, 126)
    assert (n, d) == (212, 1)
    sim = [k for k in range(2, 9) if geometric_fit(k, 20, 64, 42, 126)]
    exact = [k for k in range(2, 9) if assembly_ok(k, 20, 64, 42, 126)]
    assert sim == exact
    assert 3 in sim and 212 % 3 != 0


def _random_sets(n, seed):
    rnd = random.Random(seed)
    out = []
    while len(out) < n:
        zk = rnd.randint(17, 70)
        zc = rnd.randint(17, 70)
        zc2 = rnd.randint(20, 70)
        if rnd.random() < 0.3:
            zc2 = zc  # single row
        # bias towards common factors so that the gcd term matters
        if rnd.random() < 0.5:
            f = rnd.choice((2, 3, 4, 6))
            zc, zc2 = max(17, zc - zc % f), max(20, zc2 - zc2 % f)
        zn = zk + zc + zc2
        if zn >= 85:
            out.append((zk, zc, zc2, zn))
    return out


@pytest.mark.parametrize("zk, zc, zc2, zn", _random_sets(120, 4))
def test_exact_assembly_condition_equals_the_simulation(zk, zc, zc2, zn):
    single = zc == zc2
    for k in range(2, 9):
        sim = geometric_fit(k, zk, zc, zc2, zn)
        assert assembly_ok(k, zk, zc, None if single else zc2, zn) == sim, k
        # the book's form is sufficient: whatever it admits, the simulation admits
        n, _ = assembly_book(zk, zc, None if single else zc2, zn)
        if n % k == 0:
            assert sim


@pytest.mark.parametrize("zk, zc, zc2, zn", _random_sets(60, 11))
def test_neighbouring_and_k_max_against_geometry(zk, zc, zc2, zn):
    single = zc == zc2
    z2 = None if single else zc2
    lim = neighbour_limit(zk, zc, z2)
    for k in range(2, 41):
        assert neighbour_ok(k, zk, zc, z2) == tips_clear(k, zk, zc, zc2)
    assert tips_clear(lim, zk, zc, zc2) and not tips_clear(lim + 1, zk, zc, zc2)
    best = max([k for k in range(2, 41) if tips_clear(k, zk, zc, zc2) and geometric_fit(k, zk, zc, zc2, zn)],
               default=1)
    assert max_planets(zk, zc, z2, zn) == best
    assert check_stage(Stage(zk, zc, z2, zn, 1)).k_max == best


def test_neighbouring_uses_the_larger_planet_of_either_row():
    # larger planet in row 1 (meshes the sun) and in row 2 (meshes the ring): the same centre
    # distance a = m(z_k + z_c)/2 = m(z_n − z_c′)/2 by coaxiality
    for zk, zc, zc2 in ((34, 56, 30), (20, 30, 60)):
        zn = zk + zc + zc2
        big = max(zc, zc2)
        assert zk + zc == zn - zc2
        q = (big + 2) / (zk + zc)
        for k in range(2, 8):
            assert neighbour_ok(k, zk, zc, zc2) == (math.sin(math.pi / k) > q)
