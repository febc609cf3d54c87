"""Rich tables for Table 1.2: the whole list and one row explained."""

from __future__ import annotations

from ...i18n.lang import pick
from ...i18n.numbers import num
from ...variants import Variant

SCHEME_WORDS = {
    1: ("translating roller follower, force closure (spring)", "поступательный роликовый толкатель, силовое замыкание (пружина)"),
    2: ("translating roller follower, form closure (grooved cam)", "поступательный роликовый толкатель, геометрическое замыкание (пазовый кулачок)"),
    3: ("oscillating roller follower (rocker), force closure (spring)", "качающийся роликовый толкатель (коромысло), силовое замыкание (пружина)"),
    4: ("oscillating roller follower (rocker), form closure (grooved cam)", "качающийся роликовый толкатель (коромысло), геометрическое замыкание (пазовый кулачок)"),
}
LAW_WORDS = {
    1: ("constant acceleration (parabolic)", "закон постоянного ускорения (параболический)"),
    2: ("linearly decreasing acceleration", "закон линейно убывающего ускорения"),
    3: ("cosine acceleration (harmonic)", "косинусоидальный закон ускорения"),
    4: ("sine acceleration (cycloidal)", "синусоидальный закон ускорения"),
}


def scheme_words(scheme: int, lang: str) -> str:
    return pick(lang, *SCHEME_WORDS[scheme])


def law_words(law: int, lang: str) -> str:
    return pick(lang, *LAW_WORDS[law])


def rotation_words(v: Variant, lang: str) -> str:
    if v.ccw:
        return pick(lang, "counter-clockwise (n_k > 0)", "против часовой стрелки (n_k > 0)")
    return pick(lang, "clockwise (n_k < 0)", "по часовой стрелке (n_k < 0)")


def stroke_text(v: Variant, lang: str = "en") -> str:
    return f"{_g(v.stroke, lang)}°" if v.is_rocker else f"{_g(v.stroke, lang)} " + pick(lang, "m", "м")


def _g(x, lang: str) -> str:
    """A table value as the book prints it (up to 6 significant digits), decimal comma under ru."""
    return num(x, lang, sig=6, sci=False)


def print_variant_table(console, table: dict[int, Variant], lang: str) -> None:
    from rich.table import Table

    t = Table(title=pick(lang, "Table 1.2 — variants of sheet 3", "Таблица 1.2 — задания на 3-й лист"), header_style="bold")
    for head in (
        pick(lang, "No.", "№ вар."),
        pick(lang, "Scheme", "№ сх."),
        pick(lang, "l_BC, m", "l_BC, м"),
        "ν_max, °",
        pick(lang, "n_k, rpm", "n_k, об/мин"),
        pick(lang, "S_max, m / γ_max, °", "S_max, м / γ_max, °"),
        pick(lang, "Law", "№ зак."),
        "φ_у, °",
        "φ_дс, °",
        "φ_в, °",
        "φ_бс, °",
    ):
        t.add_column(head, justify="right")
    for n in sorted(table):
        v = table[n]
        t.add_row(
            str(n), str(v.scheme), "—" if v.l_bc_m is None else _g(v.l_bc_m, lang), _g(v.nu_max_deg, lang),
            _g(v.n_cam_rpm, lang), stroke_text(v, lang), str(v.law), _g(v.phi_rise_deg, lang),
            _g(v.phi_far_dwell_deg, lang), _g(v.phi_return_deg, lang), _g(v.phi_near_dwell_deg, lang),
        )
    console.print(t)
    console.print(pick(
        lang,
        "Schemes: 1, 2 translating follower; 3, 4 rocker; 1, 3 spring (force closure); 2, 4 grooved cam (form closure).",
        "Схемы: 1, 2 — поступательный толкатель; 3, 4 — коромысло; 1, 3 — силовое замыкание; 2, 4 — геометрическое (паз).",
    ))


def print_variant_detail(console, v: Variant, lang: str) -> None:
    from rich.table import Table

    t = Table(title=pick(lang, f"Variant {v.number}", f"Вариант {v.number}"), header_style="bold", show_lines=False)
    t.add_column(pick(lang, "Field", "Параметр"))
    t.add_column(pick(lang, "Value", "Значение"), justify="right")
    t.add_column(pick(lang, "Meaning", "Смысл"))
    t.add_row(pick(lang, "Scheme", "№ схемы"), str(v.scheme), scheme_words(v.scheme, lang))
    if v.is_rocker:
        t.add_row("l_BC", f"{_g(v.l_bc_m, lang)} " + pick(lang, "m", "м"), pick(lang, "rocker length", "длина коромысла"))
        t.add_row("γ_max", f"{_g(v.stroke, lang)}°", pick(lang, "rocker swing", "максимальный угол поворота коромысла"))
    else:
        t.add_row("S_max", f"{_g(v.stroke, lang)} " + pick(lang, "m", "м"), pick(lang, "follower stroke", "максимальное перемещение толкателя"))
    t.add_row("ν_max", f"{_g(v.nu_max_deg, lang)}°", pick(lang, "maximum allowed pressure angle", "максимально допустимый угол давления"))
    t.add_row("n_k", f"{_g(v.n_cam_rpm, lang)} " + pick(lang, "rpm", "об/мин"), rotation_words(v, lang))
    t.add_row("ω_k", f"{num(v.omega_cam, lang, decimals=3)} " + pick(lang, "rad/s", "рад/с"), "ω_k = π·|n_k|/30 (1.5)")
    t.add_row(pick(lang, "Law", "№ закона"), str(v.law), law_words(v.law, lang))
    t.add_row("φ_у", f"{_g(v.phi_rise_deg, lang)}°", pick(lang, "rise", "фазовый угол удаления"))
    t.add_row("φ_дс", f"{_g(v.phi_far_dwell_deg, lang)}°", pick(lang, "far dwell", "фазовый угол дальнего стояния"))
    t.add_row("φ_в", f"{_g(v.phi_return_deg, lang)}°", pick(lang, "return", "фазовый угол возвращения"))
    t.add_row("φ_бс", f"{_g(v.phi_near_dwell_deg, lang)}°", pick(lang, "near dwell = 360° − (φ_у + φ_дс + φ_в)", "ближнее стояние = 360° − (φ_у + φ_дс + φ_в)"))
    t.add_row("φ_р", f"{_g(v.phi_working_deg, lang)}°", pick(lang, "working angle (1.3)", "рабочий угол (1.3)"))
    console.print(t)
