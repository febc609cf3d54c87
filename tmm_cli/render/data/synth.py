"""`tmm synth`'s result as JSON (issue 33): ``{"lengths": {...}, "checks": {...}, "mechanism_toml":
"<the file's text>"}``, and beside them ``type``, ``task``, ``construction`` and ``notes``.

Lengths in metres (``l_OA_m`` …), angles in degrees. Each check is ``{"task": …, "linkage": …,
"ok": …}``: the task's value and `tmm linkage`'s own for the mechanism written (H and K to 0.1 %,
ψ to 0.05°, γ_min at least the task's).
"""

from __future__ import annotations

import math

from ...i18n.lang import note_text
from ...linkage.synthesis import RockerSynthesis, SliderSynthesis, SlottedSynthesis

H_RTOL = 1e-3
K_RTOL = 1e-3
PSI_TOL_DEG = 0.05


def _f(x) -> float | None:
    if x is None:
        return None
    x = float(x)
    return float(f"{x:.12g}") if math.isfinite(x) else None


def _deg(x) -> float | None:
    return None if x is None else _f(math.degrees(x))


def lengths(syn) -> dict:
    """The mechanism's lengths [m] by the book's names."""
    if isinstance(syn, SliderSynthesis):
        return {"l_OA_m": _f(syn.crank), "l_AB_m": _f(syn.rod), "e_m": _f(syn.offset), "lambda": _f(syn.lam)}
    if isinstance(syn, RockerSynthesis):
        return {"l_AB_m": _f(syn.crank), "l_BC_m": _f(syn.coupler), "l_CD_m": _f(syn.rocker), "l_AD_m": _f(syn.frame)}
    return {"l_O1A_m": _f(syn.crank), "l_O1O2_m": _f(syn.frame), "l_O2B_m": _f(syn.link), "l_BC_m": _f(syn.rod),
            "guide_above_O2_m": _f(syn.guide)}


def checks(result) -> dict:
    """The task's H, K, ψ, γ beside `tmm linkage`'s."""
    syn, chk = result.synthesis, result.check
    out = {}
    if isinstance(syn, RockerSynthesis):
        psi_task = math.degrees(syn.swing)
        psi = math.degrees(chk.swing)
        out["swing_deg"] = {"task": _f(psi_task), "linkage": _f(psi), "ok": abs(psi - psi_task) <= PSI_TOL_DEG}
    else:
        out["stroke_m"] = {"task": _f(syn.stroke), "linkage": _f(chk.stroke),
                           "ok": abs(chk.stroke - syn.stroke) <= H_RTOL * syn.stroke}
    k_task = result.task.values.get("time_ratio")
    k_ok = abs(chk.time_ratio - syn.time_ratio) <= K_RTOL * syn.time_ratio
    out["time_ratio"] = {"task": _f(k_task), "linkage": _f(chk.time_ratio), "ok": k_ok}
    g_task = result.task.values.get("min_transmission_deg")
    g = math.degrees(chk.gamma_min)
    out["gamma_min_deg"] = {"task": _f(g_task), "linkage": _f(g), "ok": g_task is None or g >= g_task - 1e-6}
    return out


def construction(syn) -> dict:
    """The construction's angles and points (for a reader who draws it)."""
    base = {"theta_deg": _deg(syn.theta)}
    if isinstance(syn, SliderSynthesis):
        base.update({"mode": syn.mode, "OB1_m": _f(syn.far), "OB2_m": _f(syn.near), "x_B1_m": _f(syn.x_far),
                     "x_B2_m": _f(syn.x_near)})
    elif isinstance(syn, RockerSynthesis):
        pt = lambda z: [_f(z.real), _f(z.imag)]  # noqa: E731
        base.update({"mode": syn.mode, "A": pt(syn.A), "D": pt(syn.D), "C1": pt(syn.C1), "C2": pt(syn.C2),
                     "locus_centre": pt(syn.centre), "locus_radius_m": _f(syn.radius),
                     "gamma_best_deg": _deg(syn.gamma_best)})
    elif isinstance(syn, SlottedSynthesis):
        base.update({"swing_deg": _deg(syn.theta), "sagitta_m": _f(syn.sagitta), "rod_angle_max_deg": _deg(syn.rod_angle),
                     "slot_m": _f(syn.slot), "rod_ratio": _f(syn.rod_ratio)})
    return base


def synth_document(result, lang: str) -> dict:
    return {"type": result.task.type, "task": result.task.record, "lengths": lengths(result.synthesis),
            "checks": checks(result), "construction": construction(result.synthesis),
            "mirrored": result.mirrored, "notes": [note_text(n, lang) for n in result.notes],
            "mechanism_toml": result.text}
