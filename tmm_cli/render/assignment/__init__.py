"""The assignment sheet (задание на курсовой проект) of `tmm assign`, typeset with typst: one A4 page
per student with the variant's data of Table 1.2 for sheets 3 and 4 in the book's notation, the
crank speed and moment from the roster where given, the list of sheets and of the note's chapters,
the dates and the signature lines; one PDF per student and one merged PDF to print them all.

The page's layout is ``assignment-style.typ`` (package data); its words are here, in Russian or
English. The data (who gets what) comes from teacher/assign.py, read by its fields.
"""

from __future__ import annotations

from pathlib import Path

from ...i18n.lang import pick
from ...i18n.numbers import num
from ..note.doc import typst_escape, typst_string

STYLE_FILE = "assignment-style.typ"


def default_style() -> str:
    return Path(__file__).with_name(STYLE_FILE).read_text(encoding="utf-8")


def _t(text) -> str:
    """Plain text inside typst markup."""
    return typst_escape(str(text), start=False)


def _n(x, lang: str, sig: int = 6) -> str:
    return num(float(x), lang, sig=sig, sci=False, minus="−")


def _date(d, lang: str) -> str:
    if d is None:
        return "#blank(3cm)"
    return _t(d.strftime("%d.%m.%Y") if lang == "ru" else d.isoformat())


# the book's symbols as typst math (Cyrillic subscripts upright, as the book prints them)
SYM = {
    "scheme": "№ сх.", "law": "№ зак.",
    "l_bc": '$l_"BC"$', "nu_max": '$nu_max$', "n_k": '$n_"к"$', "s_max": '$S_max$', "gamma_max": '$gamma_max$',
    "phi_rise": '$φ_"у"$', "phi_far": '$φ_"дс"$', "phi_return": '$φ_"в"$', "phi_near": '$φ_"бс"$',
    "n_cr": '$n_"кр"$', "torque": '$M_"пр"$', "n_d": '$n_"д"$',
}
SYM_EN = {**SYM, "scheme": "Scheme", "law": "Law", "n_k": "$n_k$", "phi_rise": '$φ_"rise"$', "phi_far": '$φ_"far"$',
          "phi_return": '$φ_"ret"$', "phi_near": '$φ_"near"$', "n_cr": '$n_"cr"$', "torque": "$M$", "n_d": "$n_d$"}


def _rows3(a, lang: str) -> list[tuple[str, str, str]]:
    """Sheet 3's data: (symbol, meaning, value) as typst markup, the variant's row of Table 1.2."""
    from ..terminal.variants import law_words, rotation_words, scheme_words

    v = a.variant
    sym = SYM if lang == "ru" else SYM_EN
    deg = "°"
    rows = [(sym["scheme"], _t(pick(lang, "cam mechanism (Fig. 1.8): ", "схема кулачкового механизма (рис. 1.8): ")
                               + scheme_words(v.scheme, lang)), str(v.scheme))]
    if v.is_rocker:
        rows.append((sym["l_bc"], _t(pick(lang, "rocker length", "длина коромысла")), f"{_n(v.l_bc_m, lang)} " + pick(lang, "m", "м")))
    rows.append((sym["nu_max"], _t(pick(lang, "largest allowed pressure angle", "максимально допустимый угол давления")),
                 f"{_n(v.nu_max_deg, lang)}{deg}"))
    rows.append((sym["n_k"], _t(pick(lang, "cam speed, ", "частота вращения кулачка, ") + rotation_words(v, lang).split(" (")[0]),
                 f"{_n(v.n_cam_rpm, lang)} " + pick(lang, "rpm", "об/мин")))
    if v.is_rocker:
        rows.append((sym["gamma_max"], _t(pick(lang, "rocker swing", "максимальный угол поворота коромысла")),
                     f"{_n(v.stroke, lang)}{deg}"))
    else:
        rows.append((sym["s_max"], _t(pick(lang, "follower stroke", "максимальное перемещение толкателя")),
                     f"{_n(v.stroke, lang)} " + pick(lang, "m", "м")))
    rows.append((sym["law"], _t(pick(lang, "follower acceleration law (Fig. 1.9): ", "закон ускорений толкателя (рис. 1.9): ")
                                + law_words(v.law, lang)), str(v.law)))
    for key, en, ru, value in (("phi_rise", "phase angle of rise", "фазовый угол удаления", v.phi_rise_deg),
                               ("phi_far", "phase angle of far dwell", "фазовый угол дальнего стояния", v.phi_far_dwell_deg),
                               ("phi_return", "phase angle of return", "фазовый угол возвращения", v.phi_return_deg),
                               ("phi_near", "near dwell: 360° less the three phases",
                                "ближнее стояние: 360° без трёх фаз", v.phi_near_dwell_deg)):
        rows.append((sym[key], _t(pick(lang, en, ru)), f"{_n(value, lang)}{deg}"))
    return rows


def _rows4(a, lang: str) -> list[tuple[str, str, str]]:
    """Sheet 4's data: the crank speed and the moment of sheets 1–2 (from the roster, or to take from
    them), the cam speed, the standard motor speeds and the spur pair's constants (§2.2, §2.3)."""
    from ...gears.drive import DEFAULT_CRANK_RPM, MOTOR_RPM

    sym = SYM if lang == "ru" else SYM_EN
    rpm = pick(lang, "rpm", "об/мин")
    crank = (f"{_n(a.crank_rpm, lang)} {rpm}" if a.crank_rpm is not None else
             pick(lang, f"from sheet 1 (if none: {DEFAULT_CRANK_RPM:g} rpm, §2.2)",
                  f"по листу 1 (если нет — {DEFAULT_CRANK_RPM:g} об/мин, п. 2.2)"))
    torque = (f"{_n(a.torque_nm, lang)} " + pick(lang, "N·m", "Н·м") if a.torque_nm is not None else
              pick(lang, "from sheet 2", "по листу 2"))
    speeds = ", ".join(str(n) for n in MOTOR_RPM)
    rule = pick(lang, 'motor: the smallest standard speed with $n_d >= 3 n_"cr"$ (§2.2)',
                'двигатель: наименьшая стандартная частота с $n_"д" >= 3 n_"кр"$ (п. 2.2)')
    return [
        (sym["n_cr"], _t(pick(lang, "crank speed of the linkage (sheet 1)", "частота вращения кривошипа (лист 1)")), _t(crank)),
        (sym["torque"], _t(pick(lang, "mean reduced moment (sheet 2), for the motor power (§2.6)",
                                "средний приведённый момент (лист 2), для мощности двигателя (п. 2.6)")), _t(torque)),
        (sym["n_k"], _t(pick(lang, "cam speed (sheet 3)", "частота вращения кулачка (лист 3)")),
         f"{_n(abs(a.variant.n_cam_rpm), lang)} {rpm}"),
        (sym["n_d"], rule, f"{speeds} {rpm}"),
        ("$m, alpha$", _t(pick(lang, "spur pair of zero gears (§2.3): module, pressure angle",
                               "простая передача из нулевых колёс (п. 2.3): модуль, угол профиля")),
         pick(lang, "20 mm, 20°", "20 мм, 20°")),
    ]


def sheets_list(lang: str) -> list[str]:
    """The drawing sheets and what each holds (A1)."""
    return [
        pick(lang, "Sheet 3, «Synthesis of the cam mechanism»: the follower's motion diagrams; the zone of the cam "
                   "centre and the main dimensions (base radius, offset or centre distance); the cam profile (pitch and working) at a standard "
                   "scale with the profile angles; the pressure angle over the cycle.",
             "Лист 3 «Синтез кулачкового механизма»: диаграммы движения толкателя; зона положения центра кулачка и "
             "основные размеры (минимальный радиус, эксцентриситет или межцентровое расстояние); профиль кулачка (теоретический и действительный) в стандартном "
             "масштабе с профильными углами; угол давления за цикл."),
        pick(lang, "Sheet 4, «Synthesis and analysis of the gear mechanisms»: the spur mesh with the line of action and "
                   "the zones of one- and two-pair contact; the planetary reducer's scheme with the linear and angular "
                   "velocity pictures; the assembly of the planets.",
             "Лист 4 «Синтез и анализ зубчатых механизмов»: картина эвольвентного зацепления простой передачи с линией "
             "зацепления и зонами одно- и двухпарного зацепления; схема планетарного редуктора с планами линейных и "
             "угловых скоростей; схема сборки сателлитов."),
    ]


def note_chapters(lang: str) -> list[str]:
    """The explanatory note's chapters, as the note (render/note) has them."""
    return [
        pick(lang, "1. Synthesis of the cam mechanism: input data; motion law of the follower; scales of the diagrams; "
                   "main dimensions; profile of the cam; pressure angle over the cycle.",
             "1. Синтез кулачкового механизма: исходные данные; закон движения толкателя; масштабы диаграмм; "
             "определение основных размеров; построение профиля кулачка; угол давления за цикл."),
        pick(lang, "2. Synthesis of the gear mechanisms: motor speed and gear ratios; scheme of the planetary reducer; "
                   "tooth numbers (the book's procedure and the smallest set); conditions of synthesis; checking the "
                   "ratio; the spur pair; power of the motor.",
             "2. Синтез зубчатых механизмов: выбор двигателя и передаточных отношений; выбор схемы планетарного "
             "редуктора; подбор чисел зубьев; проверка условий синтеза; проверка передаточного отношения; расчёт "
             "простой зубчатой передачи; потребная мощность двигателя."),
        pick(lang, "Conclusion. References.", "Заключение. Список литературы."),
    ]


def _table(rows) -> str:
    cells = []
    for sym, meaning, value in rows:
        cells += [f"[{sym}]", f"[{meaning}]", f"[{value}]"]
    return "#data-table(\n  " + ",\n  ".join(cells) + ",\n)"


def page_source(a, lang: str, *, teacher: str = "", org: str = "", issued=None, due=None) -> str:
    """One student's page: a call of the style's `assignment`."""
    from ..note import TEXTBOOK

    org_lines = [s.strip() for s in (org or "").split(",") if s.strip()]
    org_arg = "(" + "".join(typst_string(s) + ", " for s in org_lines) + ")"
    who = pick(lang, f"Student: *{_t(a.student)}*", f"Студент: *{_t(a.student)}*")
    if a.group:
        who += pick(lang, f" #h(1.5em) Group: *{_t(a.group)}*", f" #h(1.5em) Группа: *{_t(a.group)}*")
    who += pick(lang, f" #h(1.5em) Variant: *{a.variant.number}*", f" #h(1.5em) Вариант: *{a.variant.number}*")
    body = [
        "*" + pick(lang, "1. Subject.", "1. Тема.") + "* " + _t(pick(
            lang, "Synthesis of the cam mechanism (sheet 3) and synthesis and analysis of the gear mechanisms of the "
                  "drive (sheet 4) by the book [1].",
            "Синтез кулачкового механизма (лист 3), синтез и анализ зубчатых механизмов привода (лист 4) по пособию [1].")),
        "*" + pick(lang, f"2. Input data for sheet 3", "2. Исходные данные к листу 3") + "* " + _t(pick(
            lang, f"(Table 1.2, variant {a.variant.number}):", f"(табл. 1.2, вариант {a.variant.number}):")),
        _table(_rows3(a, lang)),
        "*" + pick(lang, "3. Input data for sheet 4:", "3. Исходные данные к листу 4:") + "*",
        _table(_rows4(a, lang)),
        "*" + pick(lang, "4. Drawings", "4. Графическая часть") + "* " + _t(pick(lang, "(two A1 sheets):", "(два листа формата А1):")),
        "\n".join(f"- {_t(s)}" for s in sheets_list(lang)),
        "*" + pick(lang, "5. Explanatory note", "5. Расчётно-пояснительная записка") + "* " + _t(pick(
            lang, "(A4, with every quantity as formula, substitution and result):",
            "(формат А4; каждая величина — формула, подстановка, результат):")),
        "\n".join(f"#pad(left: 1em)[{_t(s)}]" for s in note_chapters(lang)),
        "*" + pick(lang, "6. Literature:", "6. Литература:") + "* " + _t("1. " + (TEXTBOOK["ru"] if lang == "ru" else TEXTBOOK["en"])),
        "#v(0.5em)",
        pick(lang, "Issued: ", "Дата выдачи задания: ") + _date(issued, lang) + " #h(2em) "
        + pick(lang, "Due: ", "Срок сдачи проекта: ") + _date(due, lang),
        "#v(0.8em)",
        f"#sign([{pick(lang, 'Teacher', 'Руководитель')}], [{_t(teacher)}])",
        "#v(0.5em)",
        f"#sign([{pick(lang, 'Accepted by the student', 'Задание принял к исполнению')}], [{_t(a.student)}], "
        f"date-label: [{pick(lang, 'date', 'дата')} #blank(2.5cm)])",
    ]
    return (f"#assignment(org: {org_arg}, title: [{pick(lang, 'ASSIGNMENT', 'ЗАДАНИЕ')}],\n"
            f"  subtitle: [{_t(pick(lang, 'for the course project in the Theory of Mechanisms and Machines', 'на курсовой проект по теории механизмов и машин'))}],\n"
            f"  who: [{who}])[\n" + "\n\n".join(body) + "\n]\n")


def document_source(items, lang: str, **common) -> str:
    """A typst document of the pages of `items` (one page each)."""
    head = (f"// Assignments written by `tmm assign`.\n#import \"{STYLE_FILE}\": *\n"
            f"#set text(lang: \"{'ru' if lang == 'ru' else 'en'}\")\n"
            f"#set document(title: {typst_string(pick(lang, 'Course project assignments', 'Задания на курсовой проект'))})\n")
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
