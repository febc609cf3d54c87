"""summary.csv in the reader's language: the columns' headers, the statuses and the warning flags in words."""

from __future__ import annotations

from ...i18n import N_, tr


# key, header (English msgid), numeric
SUMMARY_FIELDS = (
    ("student", N_("student"), False),
    ("group", N_("group"), False),
    ("variant", N_("variant"), True),
    ("scheme", N_("scheme"), True),
    ("law", N_("law"), True),
    ("status", N_("status"), False),
    ("crank_rpm", N_("crank_rpm"), True),
    ("n_motor_rpm", N_("n_motor_rpm"), True),
    ("power_kw", N_("power_kw"), True),
    ("i_spur", N_("i_spur"), True),
    ("i_planetary", N_("i_planetary"), True),
    ("planetary_scheme", N_("planetary_scheme"), False),
    ("teeth", N_("teeth"), False),
    ("planets", N_("planets"), False),
    ("ratio_error_pct", N_("ratio_error_pct"), True),
    ("z1", N_("z1"), True),
    ("z2", N_("z2"), True),
    ("eps_alpha", N_("eps_alpha"), True),
    ("r0_mm", N_("r0_mm"), True),
    ("e_mm", N_("e_mm"), True),
    ("l_oc_mm", N_("l_oc_mm"), True),
    ("roller_mm", N_("roller_mm"), True),
    ("nu_rise_deg", N_("nu_rise_deg"), True),
    ("nu_return_deg", N_("nu_return_deg"), True),
    ("undercut", N_("undercut"), True),
    ("pressure_angle", N_("pressure_angle"), True),
    ("ratio_error", N_("ratio_error"), True),
    ("contact_ratio", N_("contact_ratio"), True),
    ("warnings", N_("warnings"), False),
    ("folder", N_("folder"), False),
    ("error", N_("error"), False),
)


# a warning's name in the summary, from the codes of the notes (the four the course grades first)
FLAGS = {
    "undercut": N_("undercut"),
    "pressure_angle": N_("pressure angle"),
    "ratio_error": N_("ratio error"),
    "contact_ratio": N_("contact ratio"),
    "few_planets": N_("few planets"),
    "power": N_("motor power"),
    "pivot": N_("rocker pivot"),
    "roller": N_("roller"),
    "book": N_("the book's example"),
    "drawing": N_("drawing size"),
    "ratio_over_3": N_("ratio error over 3 % (within tolerance)"),
    "book_vertex": N_("the book's vertex exceeds the allowed pressure angle"),
    "small_cam": N_("cam much smaller than the rocker"),
    "long_stroke": N_("unusually long stroke"),
    "stage_range": N_("stage ratios outside 3…8"),
    "assembly": N_("assembly forms differ"),
    "shift": N_("a shift is suggested"),
    "linkage": N_("linkage"),
}


STATUS = {"ok": N_("ok"), "failed": N_("failed"), "not run": N_("not run (interrupted)")}


def flag_name(flag: str, lang: str) -> str:
    """A warning's name in words (an unknown code still reads as words, never as a code)."""
    if flag in FLAGS:
        return tr(lang, FLAGS[flag])
    return tr(lang, "warning: {name}").format(name=flag.replace("_", " "))


def summary_csv(rows: list[dict], lang: str, csv_locale: str) -> bytes:
    """summary.csv: headers and status in `lang`; ';' and decimal commas under the ru CSV locale."""
    from .csv import csv_encoding, csv_text

    header = [tr(lang, head) for _, head, _ in SUMMARY_FIELDS]
    numeric = {i for i, f in enumerate(SUMMARY_FIELDS) if f[2]}
    body = []
    for r in rows:
        cells = []
        for key, *_ in SUMMARY_FIELDS:
            v = r.get(key)
            if key == "status":
                v = tr(lang, STATUS.get(v, v))
            elif key == "warnings":
                v = ", ".join(flag_name(f, lang) for f in (v or ()))
            cells.append(v)
        body.append(cells)
    return csv_text(header, body, numeric, csv_locale).encode(csv_encoding(csv_locale))
