"""An independent checker of a planetary stage (the five conditions of §2.1.3), written without
tmm_cli: assembly by placing a second planet tooth by tooth, neighbouring by the tip circles,
ratio by Willis. Shared by test_gears_search.py and test_gears_exported.py."""

import math
from fractions import Fraction



def planet_fits(k, zk, zc, zc2, zn):
    """Can a second planet be placed 360°/k after the first, sun and ring standing still?

    Tooth phases (in pitches): the sun at the contact direction u (turns) is at z_k·u, the planet c
    there at z_c·(u + ½ − v) (v its orientation); in an external mesh their sum is fixed. The ring
    at u is at z_n·u, the planet c′ at z_c′·(u − v); in an internal mesh their difference is fixed.
    c and c′ are one rigid block. Searching the planet's orientation over the z_c solutions of the
    first condition, the second must hold too. (For k planets equally spaced, planet j is j times
    the first step.)"""
    u = Fraction(1, k)
    for m in range(zc):
        dv = ((zk + zc) * u + m) / zc  # z_c·dv ≡ (z_k + z_c)·u (mod 1)
        if (zc2 * dv - (zc2 - zn) * u).denominator == 1:
            return True
    return False


def neighbours_fit(k, zk, zc, zc2):
    """Tip circles of the larger planet on adjacent carrier positions do not touch (m = 1)."""
    a = (zk + zc) / 2
    d_tip = max(zc, zc2) + 2
    c0 = (a, 0.0)
    c1 = (a * math.cos(2 * math.pi / k), a * math.sin(2 * math.pi / k))
    return k == 1 or math.dist(c0, c1) > d_tip + 1e-9


def stage_ok(zk, zc, zc2, zn, k, double):
    coaxial = zk + zc == zn - zc2
    table22 = zk >= 17 and zn >= 85 and zn - zc2 >= 8 and (zc >= 17 and zc2 >= 20 if double else zc >= 20)
    return coaxial and table22 and neighbours_fit(k, zk, zc, zc2) and planet_fits(k, zk, zc, zc2, zn)


def willis(zk, zc, zc2, zn):
    """Willis: (ω_k − ω_H)/(ω_n − ω_H) = −z_c·z_n/(z_k·z_c′) with ω_n = 0."""
    return 1 + Fraction(zc * zn, zk * zc2)


def max_planets(zk, zc, zc2, zn):
    best = 1
    for k in range(2, 41):
        if neighbours_fit(k, zk, zc, zc2) and planet_fits(k, zk, zc, zc2, zn):
            best = k
    return best


