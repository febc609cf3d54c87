"""The plants' chord-only estimate of the bores' tangential errors (seed 004, first term of eq. (1)).

Seed 004, eq. (1): the complex error of planet i contains the accumulated error of the chordal
distances between the first and the i-th bore, Σ_{k=1}^{i−1} ΔX_{k,k+1}, scaled by 1/cos(π/z_c);
the plants find the bores from these chords alone (the seed's ref. [1]) and throw the other
measurements away. Written with the card's chords (h_k = |P_k P_{k−1}|, nominal 2R·sin(π/z_c)):

    τ̂_i = Σ_{k=2..i} (h_k − 2R·sin(π/z_c)) / cos(π/z_c),    τ̂_1 = 0,

the tangential position of bore i relative to bore 1, as arc length on the radius R.

What it misses (derivation, the project's; checked by the tests): put bore k at radius R + Δr_k
and at arc τ_k from its nominal angle. To first order in the errors,
h_k = 2R·sin φ + sin φ·(Δr_k + Δr_{k−1}) + cos φ·(τ_k − τ_{k−1}), φ = π/z_c, because
∂h/∂r_k = ∂h/∂r_{k−1} = sin φ and ∂h/∂(angle between the bores) = R·cos φ at the nominal polygon.
Summing,

    τ̂_i = (τ_i − τ_1) + tan(π/z_c)·Σ_{k=1}^{i−1} (Δr_k + Δr_{k+1}):

exact to first order when there are no radial errors (the remainder, −tan(π/z_c)·Σ(τ_k − τ_{k−1})²/(4R),
is below 0.03 µm for ±40 µm on a 250 mm carrier), and biased by tan(π/z_c) times the sum of the
radial errors along the way otherwise — bores pushed outwards look turned forwards, by tens of
micrometres for radial errors of ±30 µm.
"""

from __future__ import annotations

import math


def chord_only_tangential(chords: tuple[float, ...] | list[float], radius: float) -> tuple[float, ...]:
    """τ̂_i [same unit as the chords]: bore i's tangential error relative to bore 1 from the chords
    h_1…h_{z_c} alone (seed 004, eq. (1), first term); bore 1 first (0). ``chords[0]`` (the closing
    chord h_1 = |P_1 P_{z_c}|) is not used.

    A square (R = 100) whose bore 2 lies 0.03 further out: the chords 1–2 and 2–3 are
    √(100² + 100.03²) long, and the estimate turns bores 2 and 3 forwards by 0.03 and 0.06 although
    no bore is turned (tan 45° = 1; see :func:`radial_bias`).

    >>> h = math.hypot(100, 100.03); h0 = 100 * math.sqrt(2)
    >>> [round(t, 4) for t in chord_only_tangential([h0, h, h, h0], 100.0)]
    [0.0, 0.03, 0.06, 0.06]
    """
    z_c = len(chords)
    phi = math.pi / z_c
    nominal = 2.0 * radius * math.sin(phi)
    out = [0.0]
    for k in range(1, z_c):
        out.append(float(out[-1] + (chords[k] - nominal) / math.cos(phi)))
    return tuple(out)


def radial_bias(radial_errors: tuple[float, ...] | list[float]) -> tuple[float, ...]:
    """How far radial errors Δr push the chord-only estimate, to first order [unit of Δr]:
    tan(π/z_c)·Σ_{k=1}^{i−1} (Δr_k + Δr_{k+1}), bore 1 first (0). Derivation: the module's text.

    >>> [round(b, 6) for b in radial_bias([0.0, 0.03, 0.0, 0.0])]
    [0.0, 0.03, 0.06, 0.06]
    """
    z_c = len(radial_errors)
    t = math.tan(math.pi / z_c)
    out = [0.0]
    for k in range(1, z_c):
        out.append(float(out[-1] + t * (radial_errors[k - 1] + radial_errors[k])))
    return tuple(out)
