"""The words of a check: a key's symbol and unit, a verdict, a place in the book, and the sentence a
student reads for each checked value ("r_0 = 43 mm is 12 % too small (…): the zone's bounding lines
are probably swapped — §1.3.1, steps 3–5, (1.22)").

A row is a :class:`tmm_cli.teacher.rows.CheckRow` (read by its fields: render/ does not import teacher/).
"""

from __future__ import annotations

from ...i18n.lang import note_text, pick
from ...i18n.numbers import num

# key -> (English symbol, Russian symbol): the book's letters
SYMBOLS = {
    "n_motor_rpm": ("n_d", "n_д"), "i_spur": ("i_d", "i_д"), "i_planetary": ("i_pl", "i_пл"), "i_kh": ("i_kH", "i_kH"),
    "ratio_error_pct": ("δi", "δi"), "z_sun": ("z_k", "z_k"), "z_planet": ("z_c", "z_c"), "z_planet2": ("z_c′", "z_c′"),
    "z_ring": ("z_n", "z_n"), "planets": ("k", "k"), "z_sun_2": ("z_k (2)", "z_k (2)"), "z_planet_2": ("z_c (2)", "z_c (2)"),
    "z_ring_2": ("z_n (2)", "z_n (2)"), "planets_2": ("k (2)", "k (2)"), "z1": ("z1", "z1"), "z2": ("z2", "z2"),
    "a_mm": ("a", "a"), "eps_alpha": ("ε_α", "ε_α"), "x1": ("x1", "x1"), "x2": ("x2", "x2"), "a_w_mm": ("a_w", "a_w"),
    "alpha_w_deg": ("α_w", "α_w"), "r0_mm": ("r_0", "r_0"), "e_mm": ("e", "e"), "l_oc_mm": ("l_OC", "l_OC"),
    "roller_mm": ("r_p", "r_р"), "nu_rise_deg": ("ν_rise", "ν_у"), "nu_return_deg": ("ν_return", "ν_в"),
    "psi_rise_deg": ("ψ_rise", "ψ_у"), "psi_far_dwell_deg": ("ψ_far", "ψ_дс"), "psi_return_deg": ("ψ_return", "ψ_в"),
    "phi_rise_deg": ("φ_rise", "φ_у"), "phi_far_dwell_deg": ("φ_far", "φ_дс"), "phi_return_deg": ("φ_return", "φ_в"),
    "nu_max_deg": ("ν_max", "ν_max"), "n_cam_rpm": ("n_k", "n_к"),
}
UNITS = {"mm": ("mm", "мм"), "deg": ("°", "°"), "rpm": ("rpm", "об/мин"), "%": ("%", "%")}
_UNIT_OF = {k: u for k, u in (("n_motor_rpm", "rpm"), ("n_cam_rpm", "rpm"), ("a_mm", "mm"), ("a_w_mm", "mm"),
                              ("alpha_w_deg", "deg"), ("r0_mm", "mm"), ("e_mm", "mm"), ("l_oc_mm", "mm"),
                              ("roller_mm", "mm"), ("ratio_error_pct", "%"))}
for _k in SYMBOLS:
    if _k.endswith("_deg"):
        _UNIT_OF[_k] = "deg"

# a row's verdict: (English, Russian), short (tables, CSV) and long (the terminal's table)
STATUS = {
    "pass": ("pass", "верно"),
    "pass (book)": ("pass (the book's vertex)", "верно (вершина по пособию)"),
    "pass (valid alternative)": ("valid alternative", "верная альтернатива"),
    "pass (book roller)": ("pass (the book's roller 0.2·r0)", "верно (ролик 0,2·r0 по пособию)"),
    "pass (book roller, undercuts)": ("pass (the book's roller; it undercuts)", "верно (ролик по пособию; подрезает)"),
    "pass (other swing)": ("pass (the other swing)", "верно (другое направление качания)"),
    "fail": ("wrong", "неверно"),
    "unknown key": ("unknown key", "неизвестный ключ"),
    "not computed": ("not computed for this variant", "не вычисляется для варианта"),
    "missing": ("missing (required)", "нет ответа (обязательный)"),
    "unreadable": ("not a number", "не число"),
    "duplicate": ("given twice", "указан дважды"),
    "not checked": ("not checked", "не проверено"),
}
BASIS = {
    "program": ("the program's design", "расчёт программы"),
    "book_vertex": ("the book's vertex", "вершина по пособию"),
    "book_roller": ("the book's roller 0.2·r0", "ролик 0,2·r0 по пособию"),
    "other_swing": ("the other swing", "другое направление качания"),
    "student_set": ("your own tooth set", "ваш набор зубьев"),
    "variant": ("Table 1.2", "табл. 1.2"),
}


def passed(row) -> bool:
    return str(row.status).startswith("pass")


def status_word(status: str, lang: str) -> str:
    en, ru = STATUS.get(status, (status, status))
    return pick(lang, en, ru)


def basis_word(basis: str, lang: str) -> str:
    en, ru = BASIS.get(basis, (basis, basis))
    return pick(lang, en, ru)


def symbol(key: str, lang: str) -> str:
    en, ru = SYMBOLS.get(key, (key, key))
    return pick(lang, en, ru)


def unit(key: str, lang: str) -> str:
    u = _UNIT_OF.get(key)
    if not u:
        return ""
    en, ru = UNITS[u]
    return pick(lang, en, ru)


def value_text(value, key: str, lang: str, with_unit: bool = True) -> str:
    """A value as the student reads it: 48,86 мм, 38, 25,0°; '—' for none."""
    if value is None or value == "":
        return "—"
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return str(value)
    text = str(value) if isinstance(value, int) else num(float(value), lang, sig=5, sci=False, minus="−")
    if isinstance(value, int) and value < 0:
        text = "−" + str(-value)
    u = unit(key, lang) if with_unit else ""
    if not u:
        return text
    return f"{text}{u}" if u == "°" else f"{text} {u}"


def signed(x: float, lang: str, decimals: int = 2) -> str:
    """+1,25 / −0,40 (a typographic minus)."""
    text = num(abs(x), lang, decimals=decimals)
    return ("−" if x < 0 else "+") + text


def place_text(place, lang: str) -> str:
    """§1.3.1, steps 3–5, (1.22), Table 2.2 / п. 1.3.1, этапы 3–5, формула (1.22), табл. 2.2."""
    if place is None:
        return ""
    parts = []
    if getattr(place, "section", ""):
        parts.append(pick(lang, "§", "п. ") + place.section)
    if getattr(place, "steps", ""):
        many = any(ch in place.steps for ch in "–-,")
        parts.append(pick(lang, "steps " if many else "step ", "этапы " if many else "этап ") + place.steps)
    if getattr(place, "eq", ""):
        eqs = [e.strip() for e in place.eq.split(",")]
        parts.append(pick(lang, "", "формулы " if len(eqs) > 1 else "формула ") + ", ".join(f"({e})" for e in eqs))
    if getattr(place, "table", ""):
        parts.append(pick(lang, "Table ", "табл. ") + place.table)
    if getattr(place, "doc", ""):
        parts.append(place.doc)
    return ", ".join(parts)


def _unit_suffix(key: str, lang: str) -> str:
    u = unit(key, lang)
    return "" if not u else (u if u == "°" else f" {u}")


def tolerance_text(row, lang: str) -> str:
    """±3 % (±1,47 мм) / exact."""
    if row.tolerance_pct is None:
        return pick(lang, "exact", "точно") if row.status in ("pass", "fail", "pass (valid alternative)") else ""
    share = pick(lang, " of r_0", " от r_0") if row.key == "e_mm" else ""
    text = f"±{num(row.tolerance_pct, lang, sig=3, sci=False)} %{share}"
    if row.tolerance is not None and unit(row.key, lang):
        text += f" (±{num(row.tolerance, lang, sig=3, sci=False)}{_unit_suffix(row.key, lang)})"
    return text


def deviation_text(row, lang: str) -> str:
    """−5,86 мм (−12,0 %); '0' for an exact match, '' when there is none."""
    if row.deviation is None or row.status not in ("pass", "fail") and not passed(row):
        return ""
    d = row.deviation
    if d == 0:
        return "0"
    if isinstance(row.given, int) and isinstance(row.expected, int):
        abs_text = signed(d, lang, decimals=0)
    else:
        abs_text = ("−" if d < 0 else "+") + num(abs(d), lang, sig=4, sci=False)
    abs_text += _unit_suffix(row.key, lang)
    if row.deviation_pct is None:
        return abs_text
    return f"{abs_text} ({signed(row.deviation_pct, lang, 1)} %)"


SET_KEYS = ("z_sun", "z_planet", "z_planet2", "z_ring", "planets", "z_sun_2", "z_planet_2", "z_ring_2", "planets_2")


def _how_far(row, lang: str) -> str:
    """"12,0 % too small" / "на 12,0 % меньше"; for whole numbers "expected 38" (for a tooth set
    "the program's set has 38": another set may be right too)."""
    if row.deviation_pct is None or row.tolerance_pct is None:
        if row.key in SET_KEYS:
            return pick(lang, "the program's set has ", "в наборе программы ") + value_text(row.expected, row.key, lang)
        return pick(lang, "expected ", "ожидалось ") + value_text(row.expected, row.key, lang)
    pct = num(abs(row.deviation_pct), lang, decimals=1)
    if row.deviation < 0:
        return pick(lang, f"{pct} % too small", f"на {pct} % меньше верного")
    return pick(lang, f"{pct} % too large", f"на {pct} % больше верного")


def findings_lines(findings, lang: str) -> list[str]:
    """The remarks on a whole answer as lines; a broken tooth set and the conditions it breaks make
    one line."""
    lines: list[str] = []
    for n in findings:
        text = note_text(n, lang)
        if n.code.startswith("set_") and n.code != "set_invalid" and lines and lines[-1].endswith((":", ";")):
            lines[-1] = f"{lines[-1]} {text};"
            continue
        lines.append(text)
    return [ln[:-1] + "." if ln.endswith(";") else ln for ln in lines]


def _end(text: str) -> str:
    return text if text.endswith((".", "?", "!")) else text + "."


def row_sentence(row, lang: str) -> str:
    """The feedback on one checked value, one sentence."""
    sym = symbol(row.key, lang) if row.status != "unknown key" else (row.written or row.key)
    given = value_text(row.given, row.key, lang)
    cause = note_text(row.cause, lang) if row.cause is not None else ""
    where = place_text(row.place, lang)
    tail = (f": {cause}" if cause else "") + (f" — {where}" if where else "")
    st = row.status
    if st == "missing":
        return pick(lang, f"{sym}: not given; it is required for this sheet (the value is {value_text(row.expected, row.key, lang)})",
                    f"{sym}: не указано, а для листа это обязательно (верное значение {value_text(row.expected, row.key, lang)})") \
            + (f" — {where}" if where else "") + "."
    if st == "unknown key":
        return _end(f"{sym}: {cause}") if cause else f"{sym}: " + pick(lang, "unknown key.", "неизвестный ключ.")
    if st in ("unreadable", "duplicate", "not checked", "not computed"):
        text = cause or status_word(st, lang)
        return _end(f"{sym}: {text}" + (f" — {where}" if where and st != "not computed" else ""))
    if passed(row):
        ref = f"{value_text(row.expected, row.key, lang)}"
        dev = f", {signed(row.deviation_pct, lang, 1)} %" if row.deviation_pct is not None and row.tolerance_pct else ""
        head = f"{sym} = {given}: " + status_word(st, lang)
        if st == "pass":
            return head + f" ({ref}{dev})."
        return head + (f" — {cause}" if cause else "") + "."
    # a wrong value
    if row.expected is None:  # nothing to compare with (shifts that make no pair): the cause says it all
        return _end(f"{sym} = {given}" + (f": {cause}" if cause else " " + pick(lang, "is wrong", "неверно"))
                    + (f" — {where}" if where else ""))
    how = _how_far(row, lang)
    ref = value_text(row.expected, row.key, lang)
    tol = tolerance_text(row, lang)
    detail = pick(lang, f"right is {ref}", f"верно {ref}")
    if row.tolerance_pct is not None:
        detail += pick(lang, f", tolerance {tol}", f", допуск {tol}")
    if row.basis not in ("program", "variant"):
        detail += ", " + pick(lang, "compared with ", "сравнение: ") + basis_word(row.basis, lang)
    if row.tolerance_pct is None:
        return f"{sym} = {given} " + pick(lang, "is wrong", "неверно") + f" ({how}){tail}."
    return f"{sym} = {given} " + pick(lang, "is ", "") + f"{how} ({detail}){tail}."
