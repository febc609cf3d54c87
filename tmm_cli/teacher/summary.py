"""summary.csv's rows: one per student of a batch, read from the project's JSON document, and the rows of failures."""

from __future__ import annotations

from pathlib import Path

from ..render.data.summary import SUMMARY_FIELDS
from .roster import BatchJob

SUMMARY_COLUMNS = tuple(f[0] for f in SUMMARY_FIELDS)


# a warning's code -> its name in the summary (the four the course grades first have their own columns)
_FLAG_PREFIXES = (
    ("cam_fail_undercut", "undercut"), ("cam_undercut", "undercut"), ("undercut", "undercut"),
    ("cam_fail_nu", "pressure_angle"), ("cam_pressure_over", "pressure_angle"),
    ("ratio_error_large", "ratio_over_3"), ("ratio_error", "ratio_error"), ("eps_low", "contact_ratio"),
    ("few_planets", "few_planets"), ("power_above_series", "power"), ("cam_pivot", "pivot"),
    ("cam_book_vertex_over", "book_vertex"), ("cam_small_vs_rocker", "small_cam"), ("cam_stroke_long", "long_stroke"),
    ("cam_roller", "roller"), ("book_", "book"), ("cam_drawing", "drawing"),
    ("two_stage_range", "stage_range"), ("assembly_forms_differ", "assembly"), ("spur_shift", "shift"),
    ("linkage_", "linkage"),
)


def flag_of(code: str) -> str:
    """The summary name of a warning's code (render/data/summary.py says it in words).

    >>> [flag_of(c) for c in ("undercut", "cam_fail_undercut_convex", "cam_fail_nu_rise", "eps_low", "ratio_error_large", "x_y")]
    ['undercut', 'undercut', 'pressure_angle', 'contact_ratio', 'ratio_over_3', 'x_y']
    """
    for prefix, flag in _FLAG_PREFIXES:
        if code == prefix or code.startswith(prefix):
            return flag
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
    flags = [flag_of(code) for code in codes if flag_of(code) != "ratio_error"]
    # the ratio error is a fault only outside the tolerance in force (the note is said at any size)
    if abs(float(pl["ratio_error_pct"])) > float(g.get("tolerance_pct") or 5.0) * (1 + 1e-9) + 1e-9:
        flags.insert(0, "ratio_error")
    flags = tuple(dict.fromkeys(flags))
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


def write_summary_csv(path: Path, rows: list[dict], lang: str = "en", csv_locale: str = "en", writer: str | None = None,
                      force: bool = False, kept: list | None = None) -> Path:
    """summary.csv, written atomically and recorded in the folder's manifest; returns the path
    written (``summary.new.csv`` beside a summary.csv the teacher changed, see output/folder.py)."""
    from ..output.folder import write_owned
    from ..render.data.summary import summary_csv

    path = Path(path)
    return write_owned(path.parent, path.name, summary_csv(rows, lang, csv_locale), writer=writer, force=force, kept=kept)
