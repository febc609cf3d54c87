"""The words of a check: a key's symbol and unit, a verdict, a place in the book, and the sentence a
student reads for each checked value ("r_0 = 43 mm is 12 % too small (…): the zone's bounding lines
are probably swapped — §1.3.1, steps 3–5, (1.22)").

A row is a :class:`tmm_cli.teacher.rows.CheckRow` (read by its fields: render/ does not import teacher/).
"""

from __future__ import annotations

from ...i18n import N_, tr, trc
from ...i18n.lang import note_text
from ...i18n.numbers import num

# key -> the book's symbol (its Russian letters from the catalogue)
SYMBOLS = {
    'n_motor_rpm': N_('n_d'),
    'i_spur': N_('i_d'),
    'i_planetary': N_('i_pl'),
    'i_kh': 'i_kH',
    'ratio_error_pct': 'δi',
    'z_sun': 'z_k',
    'z_planet': 'z_c',
    'z_planet2': 'z_c′',
    'z_ring': 'z_n',
    'planets': 'k',
    'z_sun_2': 'z_k (2)',
    'z_planet_2': 'z_c (2)',
    'z_ring_2': 'z_n (2)',
    'planets_2': 'k (2)',
    'z1': 'z1',
    'z2': 'z2',
    'a_mm': 'a',
    'eps_alpha': 'ε_α',
    'x1': 'x1',
    'x2': 'x2',
    'a_w_mm': 'a_w',
    'alpha_w_deg': 'α_w',
    'r0_mm': 'r_0',
    'e_mm': 'e',
    'l_oc_mm': 'l_OC',
    'roller_mm': N_('r_p'),
    'nu_rise_deg': N_('ν_rise'),
    'nu_return_deg': N_('ν_return'),
    'psi_rise_deg': N_('ψ_rise'),
    'psi_far_dwell_deg': N_('ψ_far'),
    'psi_return_deg': N_('ψ_return'),
    'phi_rise_deg': N_('φ_rise'),
    'phi_far_dwell_deg': N_('φ_far'),
    'phi_return_deg': N_('φ_return'),
    'nu_max_deg': 'ν_max',
    'n_cam_rpm': N_('n_k'),
}

# unit -> its word
UNITS = {
    'mm': N_('mm'),
    'deg': '°',
    'rpm': N_('rpm'),
    '%': '%',
}

_UNIT_OF = {k: u for k, u in (("n_motor_rpm", "rpm"), ("n_cam_rpm", "rpm"), ("a_mm", "mm"), ("a_w_mm", "mm"),
                              ("alpha_w_deg", "deg"), ("r0_mm", "mm"), ("e_mm", "mm"), ("l_oc_mm", "mm"),
                              ("roller_mm", "mm"), ("ratio_error_pct", "%"))}
for _k in SYMBOLS:
    if _k.endswith("_deg"):
        _UNIT_OF[_k] = "deg"

# a row's verdict
STATUS = {
    'pass': N_('pass'),
    'pass (book)': N_("pass (the book's vertex)"),
    'pass (valid alternative)': N_('valid alternative'),
    'pass (book roller)': N_("pass (the book's roller 0.2·r0)"),
    'pass (book roller, undercuts)': N_("pass (the book's roller; it undercuts)"),
    'pass (other swing)': N_('pass (the other swing)'),
    'fail': N_('wrong'),
    'unknown key': N_('unknown key'),
    'not computed': N_('not computed for this variant'),
    'missing': N_('missing (required)'),
    'unreadable': N_('not a number'),
    'duplicate': N_('given twice'),
    'not checked': N_('not checked'),
}

# what a value was compared with
BASIS = {
    'program': N_("the program's design"),
    'book_vertex': N_("the book's vertex"),
    'book_roller': N_("the book's roller 0.2·r0"),
    'other_swing': N_('the other swing'),
    'student_set': N_('your own tooth set'),
    'variant': N_('Table 1.2'),
}


def passed(row) -> bool:
    return str(row.status).startswith("pass")


def status_word(status: str, lang: str) -> str:
    return tr(lang, STATUS[status]) if status in STATUS else status


def basis_word(basis: str, lang: str) -> str:
    return tr(lang, BASIS[basis]) if basis in BASIS else basis


def symbol(key: str, lang: str) -> str:
    return tr(lang, SYMBOLS[key]) if key in SYMBOLS else key


def unit(key: str, lang: str) -> str:
    u = _UNIT_OF.get(key)
    return tr(lang, UNITS[u]) if u else ""


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
        parts.append(tr(lang, '§') + place.section)
    if getattr(place, "steps", ""):
        many = any(ch in place.steps for ch in "–-,")
        parts.append((tr(lang, "steps {steps}") if many else tr(lang, "step {steps}")).format(steps=place.steps))
    if getattr(place, "eq", ""):
        eqs = [e.strip() for e in place.eq.split(",")]
        shown = ", ".join(f"({e})" for e in eqs)
        parts.append((trc(lang, "equations", "{eqs}") if len(eqs) > 1 else trc(lang, "equation", "{eqs}")).format(eqs=shown))
    if getattr(place, "table", ""):
        parts.append(tr(lang, 'Table ') + place.table)
    if getattr(place, "doc", ""):
        parts.append(place.doc)
    return ", ".join(parts)


def _unit_suffix(key: str, lang: str) -> str:
    u = unit(key, lang)
    return "" if not u else (u if u == "°" else f" {u}")


def tolerance_text(row, lang: str) -> str:
    """±3 % (±1,47 мм) / exact."""
    if row.tolerance_pct is None:
        return tr(lang, 'exact') if row.status in ("pass", "fail", "pass (valid alternative)") else ""
    share = tr(lang, ' of r_0') if row.key == "e_mm" else ""
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
            return tr(lang, "the program's set has ") + value_text(row.expected, row.key, lang)
        return tr(lang, 'expected ') + value_text(row.expected, row.key, lang)
    pct = num(abs(row.deviation_pct), lang, decimals=1)
    if row.deviation < 0:
        return tr(lang, '{pct} % too small').format(pct=pct)
    return tr(lang, '{pct} % too large').format(pct=pct)


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
        text = tr(lang, "{sym}: not given; it is required for this sheet (the value is {value})")
        return text.format(sym=sym, value=value_text(row.expected, row.key, lang)) + (f" — {where}" if where else "") + "."
    if st == "unknown key":
        return _end(f"{sym}: {cause}") if cause else f"{sym}: " + tr(lang, 'unknown key.')
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
        return _end(f"{sym} = {given}" + (f": {cause}" if cause else " " + tr(lang, 'is wrong'))
                    + (f" — {where}" if where else ""))
    how = _how_far(row, lang)
    ref = value_text(row.expected, row.key, lang)
    tol = tolerance_text(row, lang)
    detail = tr(lang, 'right is {ref}').format(ref=ref)
    if row.tolerance_pct is not None:
        detail += tr(lang, ', tolerance {tol}').format(tol=tol)
    if row.basis not in ("program", "variant"):
        detail += ", " + tr(lang, 'compared with ') + basis_word(row.basis, lang)
    if row.tolerance_pct is None:
        return f"{sym} = {given} " + tr(lang, 'is wrong') + f" ({how}){tail}."
    return tr(lang, "{sym} = {given} is {how} ({detail})").format(sym=sym, given=given, how=how, detail=detail) + f"{tail}."
