"""The least-squares problem of a carrier card (seed 004): unknowns, residuals, Jacobian, solve.

The unknowns are the centres of both cheeks less z_1 (the frame puts bore 1 of the left cheek on +Y):
x = (y_1, y_2, z_2, …, y_{z_c}, z_{z_c}, y'_1, z'_1, …, y'_{z_c}, z'_{z_c}), 4·z_c − 1 numbers.
Everything is scaled by the nominal radius R (lengths in units of R), so the solver sees numbers
near 1 whatever the carrier's size. The measurement equations and their derivatives are those of
:mod:`.measurements`; the solver is ``scipy.optimize.least_squares`` (Levenberg–Marquardt with the
analytic Jacobian), imported only here, only when a card is fitted.
"""

from __future__ import annotations

import numpy as np

from .card import Card
from .measurements import KINDS, jacobian, predict


def measured_values(card: Card) -> dict[str, np.ndarray]:
    """The card's numbers by kind [m]; an unmeasured e is NaN."""
    e = np.array([np.nan if v is None else v for v in card.pair_skew])
    return {"R": np.array(card.radial), "R_prime": np.array(card.radial_prime), "h": np.array(card.chord),
            "h_prime": np.array(card.chord_prime), "s": np.array(card.skew), "e": e}


def unpack(x: np.ndarray, z: int) -> tuple[np.ndarray, np.ndarray]:
    """Parameters (y_1, y_2, z_2, …, y_{z_c}, z_{z_c}, y'_1, z'_1, …) → centres (left, right).

    >>> unpack(np.arange(7.0), 2)[0].tolist(), unpack(np.arange(7.0), 2)[1].tolist()
    ([[0.0, 0.0], [1.0, 2.0]], [[3.0, 4.0], [5.0, 6.0]])
    """
    left = np.empty((z, 2))
    left[0] = (x[0], 0.0)
    left[1:] = x[1:2 * z - 1].reshape(z - 1, 2)
    return left, x[2 * z - 1:].reshape(z, 2)


def pack(left: np.ndarray, right: np.ndarray) -> np.ndarray:
    """Centres (left, right) → parameters; z_1 is dropped (the inverse of :func:`unpack`)."""
    return np.concatenate(([left[0, 0]], left[1:].ravel(), right.ravel()))


def free_columns(z: int) -> np.ndarray:
    """The columns of :func:`~.measurements.jacobian` that are unknowns: all but z_1's."""
    return np.delete(np.arange(4 * z), 1)


class Problem:
    """The residual function (fitted − measured, units of R) of one card and one set of used
    measurements (a boolean mask over :func:`~.measurements.measurement_names`)."""

    def __init__(self, card: Card, radius: float, used: np.ndarray):
        self.z = card.z_c
        measured = measured_values(card)
        self.measured = np.concatenate([measured[k] for k in KINDS]) / radius
        self.used = used
        self.cols = free_columns(self.z)

    def fun(self, x):
        left, right = unpack(x, self.z)
        pred = predict(left, right)
        return (np.concatenate([pred[k] for k in KINDS]) - self.measured)[self.used]

    def jac(self, x):
        left, right = unpack(x, self.z)
        return jacobian(left, right)[np.ix_(self.used, self.cols)]


def solve(problem: Problem, x0: np.ndarray) -> tuple[np.ndarray, int]:
    """The least-squares parameters from ``x0`` and the number of evaluations it took."""
    from scipy.optimize import least_squares  # heavy: only when a card is fitted

    sol = least_squares(problem.fun, x0, jac=problem.jac, method="lm", xtol=1e-15, ftol=1e-15, gtol=1e-15,
                        max_nfev=200)
    return sol.x, int(sol.nfev)
