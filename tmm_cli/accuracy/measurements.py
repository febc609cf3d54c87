"""What each measurement of a carrier card is, as a function of the bore centres (seed 004).

Frame (seed 004, Figs. 1–4; the issue fixes the orientation): X is the carrier's central axis,
Y passes through the centre of bore 1 on the left cheek, Z completes a right-handed frame, so
seen from the end of X the angle from +Y towards +Z is counter-clockwise. Bores are numbered
1…z_c counter-clockwise; the nominal angle of bore i is θ_i = 2π(i−1)/z_c. The cheeks are parallel
(the seed's assumption), so X drops out and each centre is a point (y, z): P_i on the left cheek,
P'_i on the right one. Arrays here hold the centres as rows, index 0 = bore 1, in any one length
unit (the fit uses metres divided by the nominal radius).

The six measurement kinds, each one value per bore i (i−1 is cyclic: bore 0 is bore z_c):

- ``R``       R_i  = |P_i|                        radial centre distance, Fig. 3
- ``R_prime`` R'_i = |P'_i|                       Fig. 3
- ``h``       h_i  = |P_i P_{i−1}|                chordal centre distance, Fig. 4 (h_1 = |P_1 P_{z_c}|)
- ``h_prime`` h'_i = |P'_i P'_{i−1}|              Fig. 4
- ``s``       s_i  = (P_i × P'_i)/|P_i|           skew of axis i about X, counter-clockwise positive
                                                  (Fig. 3, the displacement of P'_i from the plane X P_i)
- ``e``       e_i  = ((P'_i − P_i) − (P'_{i−1} − P_{i−1}))·n_i   skew of neighbouring axes:
              n_i is the outward unit normal of the left chord P_{i−1}P_i. **Reconstruction**: the
              preview stops where the seed begins this second skew group (after eq. (3)); this is
              the project's reading — the relative displacement of the two axes across the plane
              that holds their nominal positions.

A measurement's name is its kind and bore number: ``h3``, ``R_prime2``.
"""

from __future__ import annotations

import math

import numpy as np

KINDS = ("R", "R_prime", "h", "h_prime", "s", "e")


def measurement_names(z_c: int, kinds=KINDS) -> list[str]:
    """Names of the measurements of ``kinds``, kind by kind, bore 1 first.

    >>> measurement_names(3, ("R", "h_prime"))
    ['R1', 'R2', 'R3', 'h_prime1', 'h_prime2', 'h_prime3']
    """
    return [f"{kind}{i}" for kind in kinds for i in range(1, z_c + 1)]


def nominal_angles(z_c: int) -> np.ndarray:
    """Nominal angles θ_i = 2π(i−1)/z_c [rad] of bores 1…z_c from +Y towards +Z (the issue's frame)."""
    return 2.0 * math.pi * np.arange(z_c) / z_c


def nominal_bores(z_c: int, radius: float) -> np.ndarray:
    """Nominal centres (R cos θ_i, R sin θ_i) as rows (y, z): the regular polygon of the drawing.

    >>> np.round(nominal_bores(4, 2.0), 12).tolist()
    [[2.0, 0.0], [0.0, 2.0], [-2.0, 0.0], [-0.0, -2.0]]
    """
    theta = nominal_angles(z_c)
    return radius * np.column_stack((np.cos(theta), np.sin(theta)))


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]


def predict(left: np.ndarray, right: np.ndarray) -> dict[str, np.ndarray]:
    """Every measurement kind's values for the centres ``left`` (P_i) and ``right`` (P'_i).

    A square carrier of R = 100 whose right cheek is turned counter-clockwise by a = 10⁻⁴ rad: every
    axis leans the same way, s_i = R·sin a; neighbouring axes then cross (lines of a hyperboloid),
    e_i = −h_i·sin a.

    >>> left = nominal_bores(4, 100.0)
    >>> a = 1e-4; turn = np.array([[math.cos(a), math.sin(a)], [-math.sin(a), math.cos(a)]])
    >>> m = predict(left, left @ turn)
    >>> [round(float(m[k][2]), 9) for k in ("h", "s", "e")]
    [141.421356237, 0.01, -0.014142136]
    """
    rho = np.hypot(left[:, 0], left[:, 1])
    d = left - np.roll(left, 1, axis=0)  # P_i − P_{i−1}
    d_p = right - np.roll(right, 1, axis=0)
    h = np.hypot(d[:, 0], d[:, 1])
    normal = np.column_stack((d[:, 1], -d[:, 0])) / h[:, None]  # outward for counter-clockwise bores
    shift = right - left  # D_i = P'_i − P_i
    g = shift - np.roll(shift, 1, axis=0)
    return {
        "R": rho,
        "R_prime": np.hypot(right[:, 0], right[:, 1]),
        "h": h,
        "h_prime": np.hypot(d_p[:, 0], d_p[:, 1]),
        "s": _cross(left, right) / rho,
        "e": np.einsum("ij,ij->i", g, normal),
    }


def jacobian(left: np.ndarray, right: np.ndarray) -> np.ndarray:
    """∂(measurements)/∂(coordinates): rows kind by kind as :data:`KINDS`, bore 1 first (6·z_c);
    columns y_1, z_1, …, y_{z_c}, z_{z_c} of the left cheek, then the same of the right (4·z_c).

    Derivatives (u = unit vector along P_i − P_{i−1}, n_i the outward normal, ρ_i = |P_i|,
    g_i = D_i − D_{i−1}):  ∂R_i/∂P_i = P_i/ρ_i;  ∂h_i/∂P_i = −∂h_i/∂P_{i−1} = u;
    ∂s_i/∂P_i = (z'_i, −y'_i)/ρ_i − s_i·P_i/ρ_i², ∂s_i/∂P'_i = (−z_i, y_i)/ρ_i;
    ∂e_i/∂P'_i = −∂e_i/∂P'_{i−1} = n_i, ∂e_i/∂P_i = −∂e_i/∂P_{i−1} = −(1 + (g_i·u)/h_i)·n_i
    (n_i turns with the chord: ∂(g·n)/∂(P_i − P_{i−1}) = −(g·u)·n/h).
    """
    z = len(left)
    rho = np.hypot(left[:, 0], left[:, 1])
    rho_p = np.hypot(right[:, 0], right[:, 1])
    d = left - np.roll(left, 1, axis=0)
    d_p = right - np.roll(right, 1, axis=0)
    h = np.hypot(d[:, 0], d[:, 1])
    h_p = np.hypot(d_p[:, 0], d_p[:, 1])
    u = d / h[:, None]
    u_p = d_p / h_p[:, None]
    normal = np.column_stack((u[:, 1], -u[:, 0]))
    shift = right - left
    g = shift - np.roll(shift, 1, axis=0)
    skew = _cross(left, right) / rho

    jac = np.zeros((6 * z, 4 * z))
    idx = np.arange(z)
    prev = np.roll(idx, 1)
    L = lambda i: 2 * i  # noqa: E731  column of y_i on the left cheek (z_i is the next one)
    Rt = lambda i: 2 * z + 2 * i  # noqa: E731  ... on the right cheek

    def put(row0, cols, values):
        for k in range(2):
            np.add.at(jac, (row0 + idx, cols + k), values[:, k])

    put(0, L(idx), left / rho[:, None])  # R
    put(z, Rt(idx), right / rho_p[:, None])  # R_prime
    put(2 * z, L(idx), u)  # h
    put(2 * z, L(prev), -u)
    put(3 * z, Rt(idx), u_p)  # h_prime
    put(3 * z, Rt(prev), -u_p)
    ds_dp = np.column_stack((right[:, 1], -right[:, 0])) / rho[:, None] - (skew / rho**2)[:, None] * left
    put(4 * z, L(idx), ds_dp)  # s
    put(4 * z, Rt(idx), np.column_stack((-left[:, 1], left[:, 0])) / rho[:, None])
    turn = 1.0 + np.einsum("ij,ij->i", g, u) / h
    put(5 * z, Rt(idx), normal)  # e
    put(5 * z, Rt(prev), -normal)
    put(5 * z, L(idx), -turn[:, None] * normal)
    put(5 * z, L(prev), turn[:, None] * normal)
    return jac
