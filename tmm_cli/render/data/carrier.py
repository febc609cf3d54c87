"""The planet carrier's fit as plain JSON data: `carrier.json` and `tmm carrier --json`
(docs/accuracy.md lists the keys). Coordinates in millimetres, errors, residuals and uncertainties
in micrometres: the card's and the plant's units. Nothing is computed here.
"""

from __future__ import annotations

import math

from ...accuracy.carrier import CarrierFit
from ...i18n.lang import note_text

MM = 1e3  # m -> mm
UM = 1e6  # m -> µm

CARRIER_FRAME = ("X the carrier's axis; Y through the centre of bore 1 on the left cheek (z_1 = 0); Z completes a "
                 "right-handed frame; bores 1..z_c counter-clockwise seen from the end of X, nominal angle "
                 "theta_i = 2*pi*(i-1)/z_c from +Y towards +Z (Leontiev, Nasonov, Bedny 2012, Figs. 1-4); "
                 "radial = |P_i| - R, tangential = R*(atan2(z_i, y_i) - theta_i); residual = measured - fitted")


def _f(x, scale: float = 1.0, decimals: int | None = None) -> float | None:
    """A plain float, None if absent: rounded to ``decimals`` (µm to 10⁻⁶, mm to 10⁻⁹: a picometre,
    so no −1.99999999999 for −2), else to 12 significant digits."""
    if x is None:
        return None
    x = float(x) * scale
    if not math.isfinite(x):
        return None
    if decimals is not None:
        return round(x, decimals) + 0.0  # + 0.0: no −0.0
    return float(f"{x:.12g}")


def _um(x) -> float | None:
    return _f(x, UM, 6)


def _mm(x) -> float | None:
    return _f(x, MM, 9)


def carrier_document(fit: CarrierFit, card_name: str | None = None, lang: str = "en") -> dict:
    """Everything `tmm carrier --json` prints and carrier.json holds."""
    bores = []
    for b in fit.bores:
        bores.append({
            "bore": b.bore,
            "y": _mm(b.y), "z": _mm(b.z), "y_prime": _mm(b.y_prime), "z_prime": _mm(b.z_prime),
            "radial_um": _um(b.radial), "tangential_um": _um(b.tangential),
            "radial_prime_um": _um(b.radial_prime), "tangential_prime_um": _um(b.tangential_prime),
            "skew_um": _um(b.skew),
            "u_y_um": _um(b.u_y), "u_z_um": _um(b.u_z), "u_y_prime_um": _um(b.u_y_prime),
            "u_z_prime_um": _um(b.u_z_prime),
            "u_radial_um": _um(b.u_radial), "u_tangential_um": _um(b.u_tangential),
            "u_radial_prime_um": _um(b.u_radial_prime), "u_tangential_prime_um": _um(b.u_tangential_prime),
            "within": b.within,
        })
    doc = {
        "card": card_name,
        "z_c": fit.z_c,
        "radius_mm": _mm(fit.radius),
        "frame": CARRIER_FRAME,
        "bores": bores,
        "residuals_um": {r.name: _um(r.residual) for r in fit.residuals},
        "standardised_residuals": {r.name: _f(r.standardised) for r in fit.residuals},
        "rms_um": _um(fit.rms),
        "sigma_um": _um(fit.sigma),
        "measurements": fit.used,
        "unknowns": fit.unknowns,
        "redundancy": fit.redundancy,
        "suspect": list(fit.suspect),
        "suspect_threshold": _f(fit.critical_t),
        "excluded": list(fit.excluded),
        "chord_only_tangential_um": [_um(b.chord_only) for b in fit.bores],
        "chord_only_tangential_prime_um": [_um(b.chord_only_prime) for b in fit.bores],
        "chord_only_minus_fit_um": [_um(b.chord_only - b.tangential) for b in fit.bores],
        "chord_only_minus_fit_prime_um": [_um(b.chord_only_prime - b.fit_relative_prime) for b in fit.bores],
        "radial_bias_um": [_um(b.radial_bias) for b in fit.bores],
        "radial_bias_prime_um": [_um(b.radial_bias_prime) for b in fit.bores],
        "tolerances_um": {"radial": _um(fit.tol_radial), "tangential": _um(fit.tol_tangential)},
        "notes": [note_text(n, lang) for n in fit.notes],
    }
    return doc
