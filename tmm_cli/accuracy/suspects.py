"""A misread gauge on a carrier card: externally standardised residuals and the search for suspects.

Standard least-squares diagnostics (Draper & Smith, *Applied Regression Analysis*, ch. 8; Cook &
Weisberg 1982): with the residual projector M = I − J(JᵀJ)⁻¹Jᵀ (J the Jacobian at the fit, m rows,
n unknowns) the residual of measurement i has the variance σ²·M_ii; without it the scatter is
σ_(i)² = (Σr² − r_i²/M_ii)/(m − n − 1); the externally standardised residual
t_i = r_i/(σ_(i)·√M_ii) follows Student's law with m − n − 1 degrees of freedom. σ_(i) is never taken
below the gauge's resolution/√12, so the rounding noise of an exactly consistent card is never a
misread.

A measurement is *suspect* when its |t| exceeds the two-sided quantile at 1 % over all m
measurements (Bonferroni); it is set aside and the rest are tested again until none stands out or
too little redundancy is left. Measurements whose residuals the card cannot tell apart from the
suspect's (correlation of their columns of M above 0.999) are named with it. The project's choice
(the seed's preview stops before any such test).
"""

from __future__ import annotations

import math

import numpy as np

from .card import Card
from .lsq import Problem, solve

SUSPECT_ALPHA = 0.01
"""Family-wise false-alarm probability of the suspect test over all measurements of a card."""

INDISTINGUISHABLE = 0.999
"""Residual correlation above which two measurements cannot be told apart."""


def residual_projector(jac: np.ndarray) -> np.ndarray:
    """M = I − J(JᵀJ)⁻¹Jᵀ, through an orthonormal basis of J's columns.

    >>> np.round(residual_projector(np.ones((2, 1))), 12).tolist()
    [[0.5, -0.5], [-0.5, 0.5]]
    """
    q, _ = np.linalg.qr(jac)
    return np.eye(len(jac)) - q @ q.T


def standardised(jac: np.ndarray, r: np.ndarray, floor: float) -> tuple[np.ndarray, np.ndarray]:
    """Externally standardised residuals t_i of the residuals ``r`` (NaN where a measurement has no
    redundancy, or for all when m − n < 2) and the projector M; ``floor`` is the least σ_(i)."""
    m, n = jac.shape
    d = m - n
    proj = residual_projector(jac)
    mii = np.clip(np.diag(proj), 0.0, 1.0)
    t = np.full(m, np.nan)
    if d < 2:
        return t, proj
    ssr = float(r @ r)
    ok = mii > 1e-9
    s2 = (ssr - r[ok] ** 2 / mii[ok]) / (d - 1)
    sigma = np.maximum(np.sqrt(np.maximum(s2, 0.0)), floor)
    t[ok] = r[ok] / (sigma * np.sqrt(mii[ok]))
    return t, proj


def indistinguishable(proj: np.ndarray, k: int) -> list[int]:
    """The measurements whose residuals cannot be told apart from measurement ``k``'s: the
    correlation of their columns of M, |M_kj|/√(M_kk·M_jj), above INDISTINGUISHABLE.

    Two readings of one distance (J = [1, 1]ᵀ): each residual is minus the other's, so a misread
    of either looks the same:

    >>> indistinguishable(residual_projector(np.ones((2, 1))), 0)
    [1]
    >>> indistinguishable(residual_projector(np.array([[1.0], [1.0], [1.0]])), 0)   # correlation −1/2
    []
    """
    mii = np.diag(proj)
    return [j for j in range(len(mii)) if j != k and mii[j] > 1e-9
            and abs(proj[k, j]) / math.sqrt(mii[k] * mii[j]) > INDISTINGUISHABLE]


def critical_t(dof: int, m: int) -> float:
    """The Bonferroni threshold: Student's two-sided quantile at SUSPECT_ALPHA/m with ``dof``.

    >>> round(critical_t(10, 30), 2)
    5.33
    """
    from scipy.stats import t as student

    return float(student.ppf(1.0 - SUSPECT_ALPHA / (2.0 * m), dof))


def find_suspects(card: Card, radius: float, used: np.ndarray, x: np.ndarray, floor: float,
                  names: list[str]) -> tuple[list[str], float | None, np.ndarray]:
    """(suspect names in the order found, the first round's threshold, the first round's t for every
    measurement — NaN for unused or untestable ones) for the fit ``x`` of ``card`` with ``used``."""
    n = 4 * card.z_c - 1
    used = used.copy()
    suspects: list[str] = []
    first_t = np.full(len(names), np.nan)
    first_crit = None
    for round_no in range(len(names)):
        problem = Problem(card, radius, used)
        if round_no:
            x, _ = solve(problem, x)
        jac = problem.jac(x)
        if np.linalg.matrix_rank(jac) < n:
            break
        r = -problem.fun(x)  # measured − fitted
        t, proj = standardised(jac, r, floor)
        m = int(used.sum())
        if m - n < 2:
            break
        crit = critical_t(m - n - 1, m)
        index = np.flatnonzero(used)
        if round_no == 0:
            first_t[index] = t
            first_crit = crit
        if np.all(np.isnan(t)):
            break
        k = int(np.nanargmax(np.abs(t)))
        if abs(t[k]) <= crit:
            break
        group = [k] + indistinguishable(proj, k)
        suspects.extend(names[index[j]] for j in group if names[index[j]] not in suspects)
        used[index[k]] = False
        if m - 1 - n < 3:  # too little redundancy left to test the rest
            break
    return suspects, first_crit, first_t
