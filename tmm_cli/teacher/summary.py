"""summary.csv's rows: one per student of a batch, read from the project's JSON document, and the rows of failures."""

from __future__ import annotations

from pathlib import Path

from ..render.data.summary import SUMMARY_FIELDS
from .roster import BatchJob

SUMMARY_COLUMNS = tuple(f[0] for f in SUMMARY_FIELDS)


def flag_of(code: str) -> str:
    """The summary name of a warning's code.

    >>> [flag_of(c) for c in ("undercut", "cam_undercut_convex", "cam_pressure_over", "eps_low", "x_y")]
    ['undercut', 'undercut', 'pressure_angle', 'contact_ratio', 'x_y']
    """
    if code == "undercut" or code.startswith("cam_undercut"):
        return "undercut"
    if code == "cam_pressure_over":
        return "pressure_angle"
    if code == "ratio_error":
        return "ratio_error"
    if code == "eps_low":
        return "contact_ratio"
    if code == "few_planets":
        return "few_planets"
    if code == "power_above_series":
        return "power"
    if code.startswith("cam_pivot"):
        return "pivot"
    if code.startswith("cam_roller"):
        return "roller"
    if code.startswith("book_"):
        return "book"
    if code.startswith("cam_drawing"):
        return "drawing"
    return code


def failure_row(job: BatchJob, reason: str, status: str = "failed") -> dict:
    row = {c: "" for c in SUMMARY_COLUMNS}
    row.update(student=job.label, group=job.group, variant=job.variant, status=status, error=reason, warnings=(),
               line=job.line)
    return row


def summary_row(job: BatchJob, doc: dict, folder: str, codes=()) -> dict:
    """One summary row from a project JSON document (the content of results.json) and the codes
    of its warnings (`result.notes`)."""
    g, c = doc["gears"], doc["cam"]
    pl = g["planetary"]
    stages = pl["stages"]
    teeth = " + ".join(
        "/".join(str(s[k]) for k in ("z_sun", "z_planet", "z_planet2", "z_ring") if s.get(k) is not None)
        for s in stages
    )
    planets = "+".join(str(s["planets"]) for s in stages)
    pa = c["pressure_angle_max_deg"]
    flags = tuple(dict.fromkeys(flag_of(code) for code in codes))
    row = {
        "student": job.label,
        "group": job.group,
        "variant": doc["variant"],
        "scheme": doc["input"]["scheme"],
        "law": doc["input"]["law"],
        "status": "ok",
        "crank_rpm": g["crank_rpm"],
        "n_motor_rpm": g["motor"]["n_rpm"],
        "power_kw": g["motor"].get("power_kw"),
        "i_spur": g["i_spur"],
        "i_planetary": g["i_planetary"],
        "planetary_scheme": pl["scheme"],
        "teeth": teeth,
        "planets": planets,
        "ratio_error_pct": pl["ratio_error_pct"],
        "z1": g["spur"]["z1"],
        "z2": g["spur"]["z2"],
        "eps_alpha": g["spur"]["eps_alpha"],
        "r0_mm": c["r0_mm"],
        "e_mm": c.get("e_mm"),
        "l_oc_mm": c.get("l_oc_mm"),
        "roller_mm": c.get("roller_mm"),
        "nu_rise_deg": pa.get("rise"),
        "nu_return_deg": pa.get("return"),
        **{k: int(k in flags) for k in ("undercut", "pressure_angle", "ratio_error", "contact_ratio")},
        "warnings": flags,
        "folder": folder,
        "error": "",
        "line": job.line,
    }
    return row


def write_summary_csv(path: Path, rows: list[dict], lang: str = "en", csv_locale: str = "en") -> None:
    """summary.csv, written atomically and recorded in the folder's manifest."""
    from ..output.folder import write_owned
    from ..render.data.summary import summary_csv

    path = Path(path)
    write_owned(path.parent, path.name, summary_csv(rows, lang, csv_locale))
