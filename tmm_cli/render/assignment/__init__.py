"""The assignment sheet (задание на курсовой проект) of `tmm assign`, typeset with typst: one A4 page
per student with the variant's data of Table 1.2 for sheets 3 and 4 in the book's notation, the
crank speed and moment from the roster where given, the list of sheets and of the note's chapters,
the dates and the signature lines; one PDF per student and one merged PDF to print them all.

The page's layout is ``assignment-style.typ`` (package data); its words are here, in Russian or
English. The data (who gets what) comes from teacher/assign.py, read by its fields.
"""

from __future__ import annotations

from pathlib import Path

from ...i18n import N_, tr, trc
from ...i18n.numbers import num
from ..note.doc import typst_escape, typst_string
from ..note.typst import literal_text

STYLE_FILE = "assignment-style.typ"


def default_style() -> str:
    return Path(__file__).with_name(STYLE_FILE).read_text(encoding="utf-8")


def _t(text) -> str:
    """Plain text inside typst markup."""
    return typst_escape(str(text), start=False)


def _who(text) -> str:
    """A person's text (a name, a group, the teacher) inside typst markup: the characters given."""
    return literal_text(str(text))


def _n(x, lang: str, sig: int = 6) -> str:
    return num(float(x), lang, sig=sig, sci=False, minus="−")


def _date(d, lang: str) -> str:
    if d is None:
        return "#blank(3cm)"
    return _t(d.strftime("%d.%m.%Y") if lang == "ru" else d.isoformat())


# the book's symbols as typst math (Cyrillic subscripts upright, as the book prints them; the
# English text writes them with Latin letters)
SYM = {
    "l_bc": '$l_"BC"$', "nu_max": '$nu_max$', "s_max": '$S_max$', "gamma_max": '$gamma_max$',
    "n_k": ('$n_k$', '$n_"к"$'), "phi_rise": ('$φ_"rise"$', '$φ_"у"$'), "phi_far": ('$φ_"far"$', '$φ_"дс"$'),
    "phi_return": ('$φ_"ret"$', '$φ_"в"$'), "phi_near": ('$φ_"near"$', '$φ_"бс"$'), "n_cr": ('$n_"cr"$', '$n_"кр"$'),
    "torque": ("$M$", '$M_"пр"$'), "n_d": ("$n_d$", '$n_"д"$'),
}


def _symbols(lang: str) -> dict:
    """SYM in `lang`'s letters, and the table's column words for the scheme and law numbers."""
    out = {k: (v[1] if lang == "ru" else v[0]) if isinstance(v, tuple) else v for k, v in SYM.items()}
    out["scheme"] = _t(trc(lang, "column, short", "Scheme"))
    out["law"] = _t(trc(lang, "column, short", "Law"))
    return out


def _rows3(a, lang: str) -> list[tuple[str, str, str]]:
    """Sheet 3's data: (symbol, meaning, value) as typst markup, the variant's row of Table 1.2."""
    from ..terminal.variants import law_words, rotation_words, scheme_words

    v = a.variant
    sym = _symbols(lang)
    deg = "°"
    rows = [(sym["scheme"], _t(tr(lang, 'cam mechanism (Fig. 1.8): ')
                               + scheme_words(v.scheme, lang)), str(v.scheme))]
    if v.is_rocker:
        rows.append((sym["l_bc"], _t(tr(lang, 'rocker length')), f"{_n(v.l_bc_m, lang)} " + tr(lang, 'm')))
    rows.append((sym["nu_max"], _t(tr(lang, 'largest allowed pressure angle')),
                 f"{_n(v.nu_max_deg, lang)}{deg}"))
    rows.append((sym["n_k"], _t(tr(lang, 'cam speed, ') + rotation_words(v, lang).split(" (")[0]),
                 f"{_n(v.n_cam_rpm, lang)} " + tr(lang, 'rpm')))
    if v.is_rocker:
        rows.append((sym["gamma_max"], _t(tr(lang, 'rocker swing')),
                     f"{_n(v.stroke, lang)}{deg}"))
    else:
        rows.append((sym["s_max"], _t(tr(lang, 'follower stroke')),
                     f"{_n(v.stroke, lang)} " + tr(lang, 'm')))
    rows.append((sym["law"], _t(tr(lang, 'follower acceleration law (Fig. 1.9): ')
                                + law_words(v.law, lang)), str(v.law)))
    for key, meaning, value in (("phi_rise", N_("phase angle of rise"), v.phi_rise_deg),
                                ("phi_far", N_("phase angle of far dwell"), v.phi_far_dwell_deg),
                                ("phi_return", N_("phase angle of return"), v.phi_return_deg),
                                ("phi_near", N_("near dwell: 360° less the three phases"), v.phi_near_dwell_deg)):
        rows.append((sym[key], _t(tr(lang, meaning)), f"{_n(value, lang)}{deg}"))
    return rows


def _rows4(a, lang: str) -> list[tuple[str, str, str]]:
    """Sheet 4's data: the crank speed and the moment of sheets 1–2 (from the roster, or to take from
    them), the cam speed, the standard motor speeds and the spur pair's constants (§2.2, §2.3)."""
    from ...gears.drive import DEFAULT_CRANK_RPM, MOTOR_RPM

    sym = _symbols(lang)
    rpm = tr(lang, 'rpm')
    crank = (f"{_n(a.crank_rpm, lang)} {rpm}" if a.crank_rpm is not None else
             tr(lang, 'from sheet 1 (if none: {rpm:g} rpm, §2.2)').format(rpm=DEFAULT_CRANK_RPM))
    torque = (f"{_n(a.torque_nm, lang)} " + tr(lang, 'N·m') if a.torque_nm is not None else
              tr(lang, 'from sheet 2'))
    speeds = ", ".join(str(n) for n in MOTOR_RPM)
    rule = tr(lang, 'motor: the smallest standard speed with $n_d >= 3 n_"cr"$ (§2.2)')
    return [
        (sym["n_cr"], _t(tr(lang, 'crank speed of the linkage (sheet 1)')), _t(crank)),
        (sym["torque"], _t(tr(lang, 'mean reduced moment (sheet 2), for the motor power (§2.6)')), _t(torque)),
        (sym["n_k"], _t(tr(lang, 'cam speed (sheet 3)')),
         f"{_n(abs(a.variant.n_cam_rpm), lang)} {rpm}"),
        (sym["n_d"], rule, f"{speeds} {rpm}"),
        ("$m, alpha$", _t(tr(lang, 'spur pair of zero gears (§2.3): module, pressure angle')),
         tr(lang, '20 mm, 20°')),
    ]


def sheets_list(lang: str) -> list[str]:
    """The drawing sheets and what each holds (A1)."""
    return [
        tr(lang, "Sheet 3, «Synthesis of the cam mechanism»: the follower's motion diagrams; the zone of the cam centre and the main dimensions (base radius, offset or centre distance); the cam profile (pitch and working) at a standard scale with the profile angles; the pressure angle over the cycle."),
        tr(lang, "Sheet 4, «Synthesis and analysis of the gear mechanisms»: the spur mesh with the line of action and the zones of one- and two-pair contact; the planetary reducer's scheme with the linear and angular velocity pictures; the assembly of the planets."),
    ]


def note_chapters(lang: str) -> list[str]:
    """The explanatory note's chapters, as the note (render/note) has them."""
    return [
        tr(lang, '1. Synthesis of the cam mechanism: input data; motion law of the follower; scales of the diagrams; main dimensions; profile of the cam; pressure angle over the cycle.'),
        tr(lang, "2. Synthesis of the gear mechanisms: motor speed and gear ratios; scheme of the planetary reducer; tooth numbers (the book's procedure and the smallest set); conditions of synthesis; checking the ratio; the spur pair; power of the motor."),
        tr(lang, 'Conclusion. References.'),
    ]


def _table(rows) -> str:
    cells = []
    for sym, meaning, value in rows:
        cells += [f"[{sym}]", f"[{meaning}]", f"[{value}]"]
    return "#data-table(\n  " + ",\n  ".join(cells) + ",\n)"


def page_source(a, lang: str, *, teacher: str = "", org: str = "", issued=None, due=None) -> str:
    """One student's page: a call of the style's `assignment`."""
    from ..note import textbook

    org_lines = [s.strip() for s in (org or "").split(",") if s.strip()]
    org_arg = "(" + "".join(typst_string(s) + ", " for s in org_lines) + ")"
    who = tr(lang, 'Student: *{student}*').format(student=_who(a.student))
    if a.group:
        who += tr(lang, ' #h(1.5em) Group: *{group}*').format(group=_who(a.group))
    who += tr(lang, ' #h(1.5em) Variant: *{number}*').format(number=a.variant.number)
    body = [
        "*" + tr(lang, '1. Subject.') + "* " + _t(tr(lang, 'Synthesis of the cam mechanism (sheet 3) and synthesis and analysis of the gear mechanisms of the drive (sheet 4) by the book [1].')),
        "*" + tr(lang, "2. Input data for sheet 3") + "* " + _t(tr(lang, '(Table 1.2, variant {number}):').format(number=a.variant.number)),
        _table(_rows3(a, lang)),
        "*" + tr(lang, '3. Input data for sheet 4:') + "*",
        _table(_rows4(a, lang)),
        "*" + tr(lang, '4. Drawings') + "* " + _t(tr(lang, '(two A1 sheets):')),
        "\n".join(f"- {_t(s)}" for s in sheets_list(lang)),
        "*" + tr(lang, '5. Explanatory note') + "* " + _t(tr(lang, '(A4, with every quantity as formula, substitution and result):')),
        "\n".join(f"#pad(left: 1em)[{_t(s)}]" for s in note_chapters(lang)),
        "*" + tr(lang, '6. Literature:') + "* " + _t("1. " + textbook(lang)),
        "#v(0.5em)",
        tr(lang, 'Issued: ') + _date(issued, lang) + " #h(2em) "
        + tr(lang, 'Due: ') + _date(due, lang),
        "#v(0.8em)",
        "#sign([" + tr(lang, "Teacher") + f"], [{_who(teacher)}])",
        "#v(0.5em)",
        "#sign([" + tr(lang, "Accepted by the student") + f"], [{_who(a.student)}], date-label: ["
        + tr(lang, "date") + " #blank(2.5cm)])",
    ]
    title = tr(lang, "ASSIGNMENT")
    subtitle = _t(tr(lang, "for the course project in the Theory of Mechanisms and Machines"))
    return (f"#assignment(org: {org_arg}, title: [{title}],\n  subtitle: [{subtitle}],\n"
            f"  who: [{who}])[\n" + "\n\n".join(body) + "\n]\n")


def document_source(items, lang: str, **common) -> str:
    """A typst document of the pages of `items` (one page each)."""
    title = typst_string(tr(lang, "Course project assignments"))
    head = (f"// Assignments written by `tmm assign`.\n#import \"{STYLE_FILE}\": *\n"
            f"#set text(lang: \"{'ru' if lang == 'ru' else 'en'}\")\n"
            f"#set document(title: {title})\n")
    pages = [page_source(a, lang, **common) for a in items]
    return head + "\n#pagebreak()\n".join(pages)


def write_assignments(folder: Path, items, lang: str, names, merged: str, **common) -> list[str]:
    """One PDF per item (`names`: its file name) and the merged PDF `merged`, into `folder` (a staging
    folder); the typst sources are removed. Returns the names written."""
    from ..note import compile_note

    folder = Path(folder)
    (folder / STYLE_FILE).write_text(default_style(), encoding="utf-8")
    written = []
    try:
        for a, name in zip(items, names):
            src = name.removesuffix(".pdf") + ".typ"
            (folder / src).write_text(document_source([a], lang, **common), encoding="utf-8")
            try:
                compile_note(folder, src, name)
            finally:
                (folder / src).unlink(missing_ok=True)
            written.append(name)
        if items:
            src = merged.removesuffix(".pdf") + ".typ"
            (folder / src).write_text(document_source(items, lang, **common), encoding="utf-8")
            try:
                compile_note(folder, src, merged)
            finally:
                (folder / src).unlink(missing_ok=True)
            written.append(merged)
    finally:
        (folder / STYLE_FILE).unlink(missing_ok=True)
    return written
