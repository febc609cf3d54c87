"""Planet-carrier bore centres from every measurement of the card, by least squares (seed 004).

Seed 004 (Леонтьев, Насонов, Бедный, 2012) proposes to find the centres of the planet bores in both
cheeks of the carrier from all the card's measurements at once — radial and chordal centre
distances and the skews — because the system is over-determined (5·z_c numbers or more, 4·z_c − 1
unknowns: the (y, z) of every centre less z_1 = 0) and inconsistent (every gauge errs). The
equations are those of :mod:`.measurements` (the seed's Figs. 2–4; the second skew group ``e`` is
a reconstruction, the preview stops there).

**Not the seed's linearisation.** The seed's system (2) writes each measured distance as two
components along the *nominal* directions (y_2 = R_2·sin α_2 with α_2 of the regular polygon), so
a bore turned by τ along the circle is written as if it were not turned: each equation is off by
about τ·sin θ_i, an error of the same order as the errors sought (tens of micrometres on a
250 mm carrier). Here the distances are the exact functions of the centres and the system is solved
by nonlinear least squares (``scipy.optimize.least_squares``, Levenberg–Marquardt with the
analytic Jacobian) starting from the nominal polygon — the reconstruction the issue asks for.

From the fit (standard least-squares statistics, e.g. ISO/IEC Guide 98-3 §H, Draper & Smith):

- residual of a measurement = measured − fitted; RMS over the measurements used;
- σ² = Σ r² / (m − n), the scatter of one measurement estimated from the residuals
  (m measurements, n = 4·z_c − 1 unknowns); the standard uncertainty of the coordinates is the
  square root of the diagonal of σ²·(JᵀJ)⁻¹, propagated to the radial and tangential errors;
- a misread gauge: the externally standardised residuals and the search of :mod:`.suspects`.
  The reported fit keeps every measurement the user did not exclude.

Errors of a bore (the issue's definitions): radial |P_i| − R, tangential R·(atan2(z_i, y_i) − θ_i),
both cheeks, R the drawing's radius.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import TmmError
from ..limits import CARRIER_RADIUS_MM
from ..notes import Note
from ..records import record
from .card import MM, Card
from .chord_only import chord_only_tangential, radial_bias
from .lsq import Problem, free_columns, measured_values, pack, solve, unpack
from .measurements import KINDS, measurement_names, nominal_angles, nominal_bores, predict
from .suspects import find_suspects

PLAUSIBLE = 0.05
"""A card whose distances differ from the drawing's by more than this share is refused (a wrong
--radius, a card in other units, rows of another carrier): real errors are ~10⁻⁴ of R."""

RESOLUTION_M = 1e-6
"""The gauges' resolution [m] (1 µm): the floor of the scatter in the suspect test, so that an
exactly consistent card does not make rounding noise look like a misread."""



@record
class BoreFit:
    """One bore's fitted centres and errors [m] (both cheeks); u_* are standard uncertainties.

    ``chord_only`` / ``chord_only_prime``: the plants' estimate of the tangential error relative to
    bore 1 (bore 1' on the right cheek); ``fit_relative_prime``: the fit's tangential error of the
    right cheek relative to bore 1' (on the left cheek bore 1 has none by the frame's choice).
    ``within``: the verdict against the tolerances, None without tolerances.
    """

    bore: int
    y: float
    z: float
    y_prime: float
    z_prime: float
    u_y: float | None
    u_z: float | None
    u_y_prime: float | None
    u_z_prime: float | None
    radial: float
    tangential: float
    radial_prime: float
    tangential_prime: float
    u_radial: float | None
    u_tangential: float | None
    u_radial_prime: float | None
    u_tangential_prime: float | None
    skew: float
    chord_only: float
    chord_only_prime: float
    fit_relative_prime: float
    radial_bias: float
    radial_bias_prime: float
    within: bool | None


@record
class Residual:
    """One measurement [m]: as measured, as the fitted carrier has it, their difference."""

    name: str
    measured: float
    fitted: float
    residual: float  # measured − fitted
    standardised: float | None  # externally standardised; None when it cannot be tested
    used: bool  # False: excluded by the user


@record
class CarrierFit:
    """The least-squares carrier (seed 004) and its diagnostics; lengths [m]."""

    z_c: int
    radius: float
    bores: tuple[BoreFit, ...]
    residuals: tuple[Residual, ...]
    rms: float  # of the residuals used
    sigma: float | None  # √(Σr²/(m − n)); None when m = n
    unknowns: int  # n = 4·z_c − 1
    used: int  # m
    redundancy: int  # m − n
    suspect: tuple[str, ...]
    excluded: tuple[str, ...]
    critical_t: float | None  # the suspect test's threshold
    tol_radial: float | None
    tol_tangential: float | None
    iterations: int
    notes: tuple[Note, ...] = ()

    @property
    def residual_by_name(self) -> dict[str, Residual]:
        return {r.name: r for r in self.residuals}


# ----------------------------------------------------------------------------- the entry point

def _check_radius(radius: float) -> float:
    lo, hi = CARRIER_RADIUS_MM
    if not (isinstance(radius, (int, float)) and math.isfinite(radius)) or not lo <= radius / MM <= hi:
        shown = f"{radius / MM:g} mm" if isinstance(radius, (int, float)) else repr(radius)
        raise TmmError(f"--radius is {shown}; give the nominal radius of the bore circle from the drawing, "
                       f"{lo:g} to {hi:g} mm")
    return float(radius)


def _check_plausible(card: Card, radius: float) -> None:
    z = card.z_c
    chord = 2.0 * radius * math.sin(math.pi / z)
    for kind, values, nominal in (("R", card.radial, radius), ("R_prime", card.radial_prime, radius),
                                  ("h", card.chord, chord), ("h_prime", card.chord_prime, chord)):
        for i, v in enumerate(values, 1):
            if abs(v - nominal) > PLAUSIBLE * nominal:
                raise TmmError(f"the card's {kind}{i} = {v / MM:g} mm is more than {PLAUSIBLE:.0%} off its nominal "
                               f"{nominal / MM:.3f} mm (radius {radius / MM:g} mm, {z} bores); check --radius, the "
                               f"card's units (millimetres) and the order of the rows")
    for kind, values in (("s", card.skew), ("e", card.pair_skew)):
        for i, v in enumerate(values, 1):
            if v is not None and abs(v) > PLAUSIBLE * radius:
                raise TmmError(f"the card's {kind}{i} = {v / MM:g} mm is more than {PLAUSIBLE:.0%} of the radius; "
                               f"a skew is a small displacement (micrometres to tenths of a millimetre): check the card")


def _check_tolerance(value, what: str) -> float | None:
    if value is None:
        return None
    if not (isinstance(value, (int, float)) and math.isfinite(value)) or value <= 0:
        shown = f"{value * 1e6:g} µm" if isinstance(value, (int, float)) else repr(value)
        raise TmmError(f"{what} is {shown}; give a positive tolerance in micrometres")
    return float(value)


def _angle_error(p: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """atan2(z, y) − θ wrapped into (−π, π] [rad]."""
    a = np.arctan2(p[:, 1], p[:, 0]) - theta
    return (a + math.pi) % (2.0 * math.pi) - math.pi


def fit_carrier(card: Card, radius: float, *, exclude: tuple[str, ...] | list[str] = (),
                tol_radial: float | None = None, tol_tangential: float | None = None,
                resolution: float = RESOLUTION_M) -> CarrierFit:
    """The bore centres of both cheeks that fit every measurement of ``card`` best (seed 004;
    the module's text). ``radius`` is the drawing's radius of the bore circle [m]; ``exclude``
    names measurements to leave out (``h3``); the tolerances on the radial and tangential errors
    [m] give each bore a verdict; ``resolution`` is the gauges' [m]. Results in metres.

    An exactly measured triangle carrier whose bore 2 sits 30 µm further out: the fit finds it,
    with no residual; the chord-only estimate turns bores 2 and 3 by tan 60°·30 µm ≈ 52 µm.

    >>> from tmm_cli.accuracy.card import Card
    >>> R = 0.125; left = nominal_bores(3, R); left[1] *= (R + 30e-6) / R
    >>> m = predict(left, left)
    >>> card = Card(*(tuple(m[k]) for k in KINDS[:5]), pair_skew=(None,) * 3)
    >>> fit = fit_carrier(card, R)
    >>> [round(b.radial * 1e6, 6) for b in fit.bores], round(fit.rms * 1e6, 6), fit.suspect
    ([0.0, 30.0, 0.0], 0.0, ())
    >>> [round(b.chord_only * 1e6, 1) for b in fit.bores]
    [0.0, 52.0, 103.9]
    """
    radius = _check_radius(radius)
    tol_r = _check_tolerance(tol_radial, "--tol-radial")
    tol_t = _check_tolerance(tol_tangential, "--tol-tangential")
    _check_plausible(card, radius)
    z = card.z_c
    n = 4 * z - 1
    names = measurement_names(z)
    values = measured_values(card)
    measured = np.concatenate([values[k] for k in KINDS])
    present = ~np.isnan(measured)
    known = {name for name, p in zip(names, present) if p}
    excluded = []
    for name in exclude:
        if name not in known:
            raise TmmError(f"--exclude {name}: the card has no measurement of that name; names are the column and "
                           f"the bore, e.g. h3, R_prime2, s1")
        if name not in excluded:
            excluded.append(name)
    used = present & ~np.isin(names, excluded)
    problem = Problem(card, radius, used)
    x0 = pack(*(nominal_bores(z, 1.0),) * 2)
    if int(used.sum()) < n or np.linalg.matrix_rank(problem.jac(x0)) < n:
        raise TmmError(f"without {', '.join(excluded)} the measurements no longer fix every bore centre "
                       f"({n} unknowns); exclude fewer")
    x, nfev = solve(problem, x0)
    left, right = unpack(x, z)
    if np.abs(np.concatenate((left, right)) - np.concatenate((nominal_bores(z, 1.0),) * 2)).max() > PLAUSIBLE:
        raise TmmError("the card's measurements do not fit one carrier near the drawing's polygon; check the card")
    jac = problem.jac(x)
    r_scaled = -problem.fun(x)  # measured − fitted
    m = int(used.sum())
    d = m - n
    ssr = float(r_scaled @ r_scaled)
    sigma_s = math.sqrt(ssr / d) if d > 0 else None
    # covariance of the unknowns (units of R²), then of all 4·z_c coordinates (z_1 is fixed: 0)
    cov = np.zeros((4 * z, 4 * z))
    if sigma_s is not None:
        cols = free_columns(z)
        cov[np.ix_(cols, cols)] = sigma_s**2 * np.linalg.pinv(jac.T @ jac)
    cov *= radius**2
    left_m, right_m = left * radius, right * radius
    predicted = predict(left_m, right_m)
    fitted = np.concatenate([predicted[k] for k in KINDS])

    floor = resolution / math.sqrt(12.0) / radius
    suspects, crit, t_first = find_suspects(card, radius, used, x, floor, names)

    theta = nominal_angles(z)
    rad = np.hypot(left_m[:, 0], left_m[:, 1]) - radius
    rad_p = np.hypot(right_m[:, 0], right_m[:, 1]) - radius
    tan = radius * _angle_error(left_m, theta)
    tan_p = radius * _angle_error(right_m, theta)
    skew = predicted["s"]
    chord_only = chord_only_tangential(card.chord, radius)
    chord_only_p = chord_only_tangential(card.chord_prime, radius)
    bias = radial_bias(tuple(rad))
    bias_p = radial_bias(tuple(rad_p))

    def u_of(i: int, cheek: int):
        """Standard uncertainties of y, z, radial, tangential of bore i on a cheek (0 left)."""
        if sigma_s is None:
            return None, None, None, None
        j = 2 * z * cheek + 2 * i
        c = cov[j:j + 2, j:j + 2]
        p = (left_m if cheek == 0 else right_m)[i]
        rho = math.hypot(*p)
        g_r = p / rho
        g_t = radius * np.array((-p[1], p[0])) / rho**2
        return (math.sqrt(max(c[0, 0], 0.0)), math.sqrt(max(c[1, 1], 0.0)),
                math.sqrt(max(g_r @ c @ g_r, 0.0)), math.sqrt(max(g_t @ c @ g_t, 0.0)))

    bores = []
    for i in range(z):
        uy, uz, ur, ut = u_of(i, 0)
        uyp, uzp, urp, utp = u_of(i, 1)
        within = None
        if tol_r is not None or tol_t is not None:
            within = bool((tol_r is None or max(abs(rad[i]), abs(rad_p[i])) <= tol_r)
                          and (tol_t is None or max(abs(tan[i]), abs(tan_p[i])) <= tol_t))
        bores.append(BoreFit(
            bore=i + 1, y=float(left_m[i, 0]), z=float(left_m[i, 1]), y_prime=float(right_m[i, 0]),
            z_prime=float(right_m[i, 1]), u_y=uy, u_z=uz,
            u_y_prime=uyp, u_z_prime=uzp,
            radial=float(rad[i]), tangential=float(tan[i]), radial_prime=float(rad_p[i]),
            tangential_prime=float(tan_p[i]), u_radial=ur, u_tangential=ut, u_radial_prime=urp,
            u_tangential_prime=utp, skew=float(skew[i]), chord_only=chord_only[i],
            chord_only_prime=chord_only_p[i], fit_relative_prime=float(tan_p[i] - tan_p[0]),
            radial_bias=bias[i], radial_bias_prime=bias_p[i], within=within))
    residuals = []
    for k, name in enumerate(names):
        if not present[k]:
            continue
        t = t_first[k]
        residuals.append(Residual(name=name, measured=float(measured[k]), fitted=float(fitted[k]),
                                  residual=float(measured[k] - fitted[k]),
                                  standardised=None if math.isnan(t) else float(t), used=bool(used[k])))
    notes = [Note.make("carrier_parallel_cheeks", "assumption")]
    if card.has_pair_skew:
        notes.append(Note.make("carrier_pair_skew", "assumption"))
    if suspects:
        t_top = next(r.standardised for r in residuals if r.name == suspects[0])
        notes.append(Note.make("carrier_suspect", "warning", names=", ".join(suspects), first=suspects[0],
                               t=float("nan") if t_top is None else abs(t_top), crit=crit))
    elif crit is None:
        notes.append(Note.make("carrier_untested", "assumption", redundant=d))
    return CarrierFit(
        z_c=z, radius=radius, bores=tuple(bores), residuals=tuple(residuals),
        rms=math.sqrt(ssr / m) * radius, sigma=None if sigma_s is None else sigma_s * radius,
        unknowns=n, used=m, redundancy=d, suspect=tuple(suspects), excluded=tuple(excluded),
        critical_t=crit, tol_radial=tol_r, tol_tangential=tol_t, iterations=nfev, notes=tuple(notes))
