"""summary.csv: one row per student of a batch — its columns, the warning flags in words, the rows of failures."""

from __future__ import annotations

from pathlib import Path

from ..i18n.lang import pick
from .roster import BatchJob

# key, English header, Russian header, numeric
SUMMARY_FIELDS = (
    ("student", "student", "студент", False),
    ("group", "group", "группа", False),
    ("variant", "variant", "вариант", True),
    ("scheme", "scheme", "схема", True),
    ("law", "law", "закон", True),
    ("status", "status", "статус", False),
    ("crank_rpm", "crank_rpm", "n_кр, об/мин", True),
    ("n_motor_rpm", "n_motor_rpm", "n_д, об/мин", True),
    ("power_kw", "power_kw", "N_д, кВт", True),
    ("i_spur", "i_spur", "i_пп (простая передача)", True),
    ("i_planetary", "i_planetary", "i_пл", True),
    ("planetary_scheme", "planetary_scheme", "схема редуктора", False),
    ("teeth", "teeth", "зубья z_k/z_c/z_n", False),
    ("planets", "planets", "сателлиты k", False),
    ("ratio_error_pct", "ratio_error_pct", "погрешность i_пл, %", True),
    ("z1", "z1", "z1", True),
    ("z2", "z2", "z2", True),
    ("eps_alpha", "eps_alpha", "ε_α", True),
    ("r0_mm", "r0_mm", "r0, мм", True),
    ("e_mm", "e_mm", "e, мм", True),
    ("l_oc_mm", "l_oc_mm", "l_OC, мм", True),
    ("roller_mm", "roller_mm", "r_р, мм", True),
    ("nu_rise_deg", "nu_rise_deg", "ν_у, °", True),
    ("nu_return_deg", "nu_return_deg", "ν_в, °", True),
    ("undercut", "undercut", "подрезание", True),
    ("pressure_angle", "pressure_angle", "угол давления", True),
    ("ratio_error", "ratio_error", "ошибка i", True),
    ("contact_ratio", "contact_ratio", "перекрытие", True),
    ("warnings", "warnings", "предупреждения", False),
    ("folder", "folder", "папка", False),
    ("error", "error", "ошибка", False),
)


SUMMARY_COLUMNS = tuple(f[0] for f in SUMMARY_FIELDS)


# a warning's name in the summary, from the codes of the notes (the four the course grades first)
FLAGS = {
    "undercut": ("undercut", "подрезание"),
    "pressure_angle": ("pressure angle", "угол давления"),
    "ratio_error": ("ratio error", "ошибка передаточного отношения"),
    "contact_ratio": ("contact ratio", "коэффициент перекрытия"),
    "few_planets": ("few planets", "мало сателлитов"),
    "power": ("motor power", "мощность двигателя"),
    "pivot": ("rocker pivot", "ось коромысла"),
    "roller": ("roller", "ролик"),
    "book": ("the book's example", "пример пособия"),
    "drawing": ("drawing size", "размер чертежа"),
}


STATUS = {"ok": ("ok", "готово"), "failed": ("failed", "ошибка"), "not run": ("not run (interrupted)", "не выполнен (прервано)")}


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


def flag_name(flag: str, lang: str) -> str:
    en, ru = FLAGS.get(flag, (flag.replace("_", " "), flag.replace("_", " ")))
    return pick(lang, en, ru)


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


def summary_csv(rows: list[dict], lang: str, csv_locale: str) -> bytes:
    """summary.csv: headers and status in `lang`; ';' and decimal commas under the ru CSV locale."""
    from ..render.data.csv import csv_encoding, csv_text

    header = [pick(lang, en, ru) for _, en, ru, _ in SUMMARY_FIELDS]
    numeric = {i for i, f in enumerate(SUMMARY_FIELDS) if f[3]}
    body = []
    for r in rows:
        cells = []
        for key, *_ in SUMMARY_FIELDS:
            v = r.get(key)
            if key == "status":
                v = pick(lang, *STATUS.get(v, (v, v)))
            elif key == "warnings":
                v = ", ".join(flag_name(f, lang) for f in (v or ()))
            cells.append(v)
        body.append(cells)
    return csv_text(header, body, numeric, csv_locale).encode(csv_encoding(csv_locale))


def write_summary_csv(path: Path, rows: list[dict], lang: str = "en", csv_locale: str = "en") -> None:
    """summary.csv, written atomically and recorded in the folder's manifest."""
    from ..output.folder import write_owned

    path = Path(path)
    write_owned(path.parent, path.name, summary_csv(rows, lang, csv_locale))
