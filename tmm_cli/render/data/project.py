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


def project_document(result, lang: str) -> dict:
    """The JSON of `tmm project` (= results.json): the union of the cam and gears documents."""
    from .cam import cam_to_json
    from .gears import gears_to_json

    notes = result.notes
    doc = {
        **_head(result.variant),
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
