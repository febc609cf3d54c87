"""The JSON documents of `tmm cam`, `tmm gears` and `tmm project` (results.json): the head and the sheets' parts."""

from __future__ import annotations

from ... import __version__
from ...i18n.lang import note_text
from ...variants import Variant


def _head(v: Variant) -> dict:
    return {"tool": f"tmm {__version__}", "variant": v.number, "input": v.as_input_dict()}


def cam_document(v: Variant, cam, lang: str) -> dict:
    """The JSON of `tmm cam`: variant, input row, cam."""
    from .cam import cam_to_json

    return {**_head(v), "cam": cam_to_json(cam, lang)}


def gears_document(v: Variant, gears, lang: str) -> dict:
    """The JSON of `tmm gears`: variant, input row, gears."""
    from .gears import gears_to_json

    return {**_head(v), "gears": gears_to_json(gears, lang)}


def run_options(result) -> dict:
    """The options of the run that gave `result` (so that the note for Word can be written again
    from results.json: `tmm note --to docx`). None where the book's default was used.

    >>> from tmm_cli.project import run_project
    >>> from tmm_cli.variants import get_variant
    >>> run_options(run_project(get_variant(17), crank_rpm=95))["crank_rpm"]
    95.0
    """
    g, cam = result.gears, result.cam
    sp = g.spur
    shift = None
    if sp.shift_rule == "given":
        shift = [sp.x1, sp.x2]
    elif sp.shift_rule == "auto":
        shift = "auto"
    ch = cam.choice
    return {
        "crank_rpm": None if g.crank_rpm_assumed else g.crank_rpm,
        "torque_nm": g.torque_nm,
        "ratio": None if g.forced_ratio is None else f"{g.forced_ratio[0]}/{g.forced_ratio[1]}",
        "tolerance_pct": g.tolerance_pct,
        "planets": g.forced_planets,
        "shift": shift,
        "a_w_mm": sp.a_w_mm if sp.shift_rule == "aw" else None,
        "select": g.search.select,
        "step_deg": cam.step_deg,
        "cam_choice": None if ch is None else {k: getattr(ch, k) for k in ("r0_mm", "offset_mm", "l_oc_mm", "swing", "roller_mm")},
    }


def project_document(result, lang: str) -> dict:
    """The JSON of `tmm project` (= results.json): the union of the cam and gears documents, and
    the options of the run."""
    from .cam import cam_to_json
    from .gears import gears_to_json

    notes = result.notes
    doc = {
        **_head(result.variant),
        "options": run_options(result),
        "gears": gears_to_json(result.gears, lang),
        "cam": cam_to_json(result.cam, lang),
        "assumptions": [note_text(n, lang) for n in notes if n.level == "assumption"],
        "warnings": [note_text(n, lang) for n in notes if n.level == "warning"],
    }
    if result.linkage is not None:  # tmm project --mechanism: what sheet 4 took from sheets 1–2
        doc["mechanism"] = mechanism_summary(result.linkage)
    return doc


def mechanism_summary(s2) -> dict:
    """The mechanism's numbers a project's results.json carries (the whole of sheets 1–2 is in
    linkage.json beside it)."""
    from .dynamics import dynamics_json

    c = s2.sheet1.cycle
    m = s2.sheet1.mechanism
    return {"name": m.name, "crank_rpm": m.crank.rpm, "formula": s2.sheet1.structure.formula,
            "stroke_m": c.stroke if m.output.kind == "slider" else None,
            "time_ratio": c.time_ratio, "dynamics": dynamics_json(s2)}
