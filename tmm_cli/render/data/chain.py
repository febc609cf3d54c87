"""A dimensional chain's closing link as plain JSON data: `tmm chain --json` and the file it writes
(docs/accuracy.md lists the keys). Every value in the chain file's own unit; nothing is computed
here but the change of unit.
"""

from __future__ import annotations

import math

from ...accuracy.chain import ChainResult
from ...i18n.lang import note_text

MM = 1e3  # m -> mm


def _f(x, scale: float = 1.0) -> float | None:
    """A plain float rounded to 12 significant digits (no 0.17000000000000001), None if absent."""
    if x is None:
        return None
    x = float(x) * scale
    if not math.isfinite(x):
        return None
    return float(f"{x:.12g}")


def _limits(limits, unit: float) -> dict:
    out = {"es": _f(limits.es / unit), "ei": _f(limits.ei / unit), "tolerance": _f(limits.tolerance / unit),
           "max": _f(limits.max / unit), "min": _f(limits.min / unit), "middle": _f(limits.middle / unit)}
    if limits.t is not None:
        out["t"] = _f(limits.t)
        out["risk_percent"] = _f(limits.risk_percent)
    return out


def chain_document(res: ChainResult, lang: str = "en") -> dict:
    """Everything `tmm chain --json` prints and chain.json holds (values in the chain's unit)."""
    chain = res.chain
    unit = chain.unit_si
    links = []
    for link, share in zip(chain.links, res.shares):
        item = {"name": link.name, "sign": "+" if link.sign > 0 else "-", "nominal": _f(link.nominal / unit),
                "es": _f(link.es / unit), "ei": _f(link.ei / unit), "tolerance": _f(link.tolerance / unit),
                "distribution": link.distribution, "lambda2": _f(link.lambda2), "asymmetry": _f(link.asymmetry),
                "share_worst_case": _f(share.worst_case), "share_probabilistic": _f(share.probabilistic)}
        if link.clearance is not None:
            item["beta_from"] = {"clearance_mm": _f(link.clearance, MM), "length_mm": _f(link.length, MM)}
        links.append(item)
    return {
        "name": chain.name,
        "units": chain.units,
        "closing": {"nominal": _f(res.nominal / unit),
                    "worst_case": _limits(res.worst_case, unit),
                    "probabilistic": _limits(res.probabilistic, unit)},
        "probabilistic_exceeds_worst_case": res.probabilistic_exceeds_worst_case,
        "links": links,
        "largest_contributor": {"worst_case": res.largest_worst_case, "probabilistic": res.largest_probabilistic},
        "notes": [note_text(n, lang) for n in res.notes],
    }
