"""summary.csv in the reader's language: the columns' headers, the statuses and the warning flags in words."""

from __future__ import annotations

from ...i18n.lang import pick

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
    "ratio_over_3": ("ratio error over 3 % (within tolerance)", "погрешность i больше 3 % (в допуске)"),
    "book_vertex": ("the book's vertex exceeds the allowed pressure angle", "вершина по пособию превышает допустимый угол давления"),
    "small_cam": ("cam much smaller than the rocker", "кулачок много меньше коромысла"),
    "long_stroke": ("unusually long stroke", "необычно большой ход"),
    "stage_range": ("stage ratios outside 3…8", "ступени вне диапазона 3…8"),
    "assembly": ("assembly forms differ", "формы условия сборки расходятся"),
    "shift": ("a shift is suggested", "рекомендовано смещение"),
    "linkage": ("linkage", "рычажный механизм"),
}


STATUS = {"ok": ("ok", "готово"), "failed": ("failed", "ошибка"), "not run": ("not run (interrupted)", "не выполнен (прервано)")}


def flag_name(flag: str, lang: str) -> str:
    """A warning's name in words (an unknown code still reads as words, never as a code)."""
    en, ru = FLAGS.get(flag, (flag.replace("_", " "), "предупреждение: " + flag.replace("_", " ")))
    return pick(lang, en, ru)


def summary_csv(rows: list[dict], lang: str, csv_locale: str) -> bytes:
    """summary.csv: headers and status in `lang`; ';' and decimal commas under the ru CSV locale."""
    from .csv import csv_encoding, csv_text

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
