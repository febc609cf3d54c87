"""The planet carrier's fit as plain JSON data: `carrier.json` and `tmm carrier --json`
(docs/accuracy.md lists the keys). Coordinates in millimetres, errors, residuals and uncertainties
in micrometres: the card's and the plant's units. Nothing is computed here.
"""

from __future__ import annotations

import math

from ...accuracy.carrier import CarrierFit

MM = 1e3  # m -> mm
UM = 1e6  # m -> µm

CARRIER_FRAME = ("X the carrier's axis; Y through the centre of bore 1 on the left cheek (z_1 = 0); Z completes a "
                 "right-handed frame; bores 1..z_c counter-clockwise seen from the end of X, nominal angle "
                 "theta_i = 2*pi*(i-1)/z_c from +Y towards +Z (Leontiev, Nasonov, Bedny 2012, Figs. 1-4); "
                 "radial = |P_i| - R, tangential = R*(atan2(z_i, y_i) - theta_i); residual = measured - fitted")


def _f(x, scale: float = 1.0) -> float | None:
    """A plain float rounded to 12 significant digits (no 0.17000000000000001), None if absent."""
    if x is None:
        return None
    x = float(x) * scale
    if not math.isfinite(x):
        return None
    return float(f"{x:.12g}")


def carrier_document(fit: CarrierFit, card_name: str | None = None) -> dict:
    """Everything `tmm carrier --json` prints and carrier.json holds."""
    bores = []
    for b in fit.bores:
        bores.append({
            "bore": b.bore,
            "y": _f(b.y, MM), "z": _f(b.z, MM), "y_prime": _f(b.y_prime, MM), "z_prime": _f(b.z_prime, MM),
            "radial_um": _f(b.radial, UM), "tangential_um": _f(b.tangential, UM),
            "radial_prime_um": _f(b.radial_prime, UM), "tangential_prime_um": _f(b.tangential_prime, UM),
            "skew_um": _f(b.skew, UM),
            "u_y_um": _f(b.u_y, UM), "u_z_um": _f(b.u_z, UM), "u_y_prime_um": _f(b.u_y_prime, UM),
            "u_z_prime_um": _f(b.u_z_prime, UM),
            "u_radial_um": _f(b.u_radial, UM), "u_tangential_um": _f(b.u_tangential, UM),
            "u_radial_prime_um": _f(b.u_radial_prime, UM), "u_tangential_prime_um": _f(b.u_tangential_prime, UM),
            "within": b.within,
        })
    doc = {
        "card": card_name,
        "z_c": fit.z_c,
        "radius_mm": _f(fit.radius, MM),
        "frame": CARRIER_FRAME,
        "bores": bores,
        "residuals_um": {r.name: _f(r.residual, UM) for r in fit.residuals},
        "standardised_residuals": {r.name: _f(r.standardised) for r in fit.residuals},
        "rms_um": _f(fit.rms, UM),
        "sigma_um": _f(fit.sigma, UM),
        "measurements": fit.used,
        "unknowns": fit.unknowns,
        "redundancy": fit.redundancy,
        "suspect": list(fit.suspect),
        "suspect_threshold": _f(fit.critical_t),
        "excluded": list(fit.excluded),
        "chord_only_tangential_um": [_f(b.chord_only, UM) for b in fit.bores],
        "chord_only_tangential_prime_um": [_f(b.chord_only_prime, UM) for b in fit.bores],
        "chord_only_minus_fit_um": [_f(b.chord_only - b.tangential, UM) for b in fit.bores],
        "chord_only_minus_fit_prime_um": [_f(b.chord_only_prime - b.fit_relative_prime, UM) for b in fit.bores],
        "radial_bias_um": [_f(b.radial_bias, UM) for b in fit.bores],
        "radial_bias_prime_um": [_f(b.radial_bias_prime, UM) for b in fit.bores],
        "tolerances_um": {"radial": _f(fit.tol_radial, UM), "tangential": _f(fit.tol_tangential, UM)},
    }
    return doc
