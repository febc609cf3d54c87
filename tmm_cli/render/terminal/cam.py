"""Rich tables of sheet 3 (the cam): input, motion table, scales, dimensions, ψ angles, checks."""

from __future__ import annotations

import math

from ...cam.design import CamResult
from ...cam.laws import law_impacts
from ...i18n.lang import pick
from ...i18n.numbers import num
from .table import Table
from .variants import law_words, rotation_words, scheme_words

OK = "[green]✓[/green]"  # the same marks as the gear tables
BAD = "[red]✗[/red]"
WARN = "[yellow]![/yellow]"


def _table(title: str, *cols: tuple[str, str]):
    t = Table(title=title, header_style="bold")
    for name, justify in cols:
        t.add_column(name, justify=justify)
    return t


def _g(lang: str, x: float, nd: int = 4) -> str:
    """`nd` significant digits; 9,42·10⁻⁵ for the small scales (never 9.4246e-05)."""
    return num(x, lang, sig=nd)


def _n(lang: str, x, spec: str) -> str:
    """`x` as the format `spec` would print it (g, .2f, +.2f, .4g), in the reader's notation."""
    if spec == "g":
        return num(x, lang, sig=6, sci=False)
    if spec.endswith("g"):
        return num(x, lang, sig=int(spec[1:-1]), sci=False)
    text = num(x, lang, decimals=int(spec.lstrip("+")[1:-1]))
    if spec.startswith("+") and not text.startswith("-") and not set(text) <= set("0,."):
        text = "+" + text
    return text


def _nu(lang: str, x: float, limit: float) -> str:
    """A pressure angle beside its limit: 2 decimals, 3 when 2 would hide that it passes the limit."""
    nd = 3 if round(x, 2) == round(limit, 2) and abs(x - limit) >= 5e-4 else 2
    return num(x, lang, decimals=nd)


def _input_table(r: CamResult, lang: str):
    v, m = r.variant, r.motion
    t = _table(
        pick(lang, f"Variant {v.number}: input data (Table 1.2)", f"Вариант {v.number}: исходные данные (табл. 1.2)"),
        (pick(lang, "Quantity", "Величина"), "left"),
        (pick(lang, "Value", "Значение"), "right"),
        (pick(lang, "Note", "Примечание"), "left"),
    )
    t.add_row(pick(lang, "Scheme", "Схема"), str(v.scheme), scheme_words(v.scheme, lang))
    impacts = law_impacts(v.law)
    t.add_row(
        pick(lang, "Acceleration law", "Закон ускорений"),
        str(v.law),
        law_words(v.law, lang)
        + "; "
        + (pick(lang, "soft impacts (a jumps)", "мягкие удары (скачки a)") if impacts == "soft" else pick(lang, "no impacts", "без ударов")),
    )
    if v.is_rocker:
        t.add_row("γ_max", f"{_n(lang, v.stroke, 'g')}°", pick(lang, "rocker swing", "угол качания коромысла"))
        t.add_row("l_BC", f"{_n(lang, v.l_bc_m * 1000, 'g')} " + pick(lang, "mm", "мм"), pick(lang, "rocker length", "длина коромысла"))
    else:
        t.add_row("S_max", f"{_n(lang, v.stroke * 1000, 'g')} " + pick(lang, "mm", "мм"), pick(lang, "follower stroke", "ход толкателя"))
    t.add_row("ν_max", f"{_n(lang, v.nu_max_deg, 'g')}°", pick(lang, "allowed pressure angle (1.19)", "допустимый угол давления (1.19)"))
    t.add_row("n_k", f"{_n(lang, v.n_cam_rpm, 'g')} " + pick(lang, "rpm", "об/мин"), rotation_words(v, lang))
    t.add_row("ω_k", f"{_n(lang, m.omega, '.3f')} " + pick(lang, "rad/s", "рад/с"), "ω_k = π·|n_k|/30 (1.5)")
    t.add_row("φ_у", f"{_n(lang, v.phi_rise_deg, 'g')}°", pick(lang, "rise", "удаление"))
    t.add_row("φ_дс", f"{_n(lang, v.phi_far_dwell_deg, 'g')}°", pick(lang, "far dwell", "дальнее стояние"))
    t.add_row("φ_в", f"{_n(lang, v.phi_return_deg, 'g')}°", pick(lang, "return", "возвращение"))
    t.add_row("φ_бс", f"{_n(lang, v.phi_near_dwell_deg, 'g')}°", pick(lang, "near dwell = 360° − φ_р", "ближнее стояние = 360° − φ_р"))
    t.add_row("φ_р", f"{_n(lang, v.phi_working_deg, 'g')}°", "φ_у + φ_дс + φ_в (1.3)")
    t.add_row("T", f"{_n(lang, m.period_s * 1000, '.3f')} " + pick(lang, "ms", "мс"), pick(lang, "one cam turn", "время одного оборота"))
    return t


_PHASE = {
    "rise": ("rise", "удаление"),
    "far_dwell": ("far dwell", "дальнее стояние"),
    "return": ("return", "возвращение"),
    "near_dwell": ("near dwell", "ближнее стояние"),
}


def _motion_table(r: CamResult, lang: str):
    m, v = r.motion, r.variant
    steps = f"{_n(lang, m.table_step_rise_deg, 'g')}° / {_n(lang, m.table_step_return_deg, 'g')}°"
    title = pick(lang, f"Follower motion (step rise/return {steps})", f"Диаграммы движения толкателя (шаг удаление/возвращение {steps})")
    if v.is_rocker:
        cols = [
            ("№", "right"), ("φ, °", "right"), (pick(lang, "t, ms", "t, мс"), "right"),
            ("γ, °", "right"), (pick(lang, "ω, rad/s", "ω, рад/с"), "right"), (pick(lang, "ε, rad/s²", "ε, рад/с²"), "right"),
            (pick(lang, "S_B, mm", "S_B, мм"), "right"), (pick(lang, "V_B, m/s", "V_B, м/с"), "right"), (pick(lang, "a_B, m/s²", "a_B, м/с²"), "right"),
            (pick(lang, "phase", "участок"), "left"),
        ]
    else:
        cols = [
            ("№", "right"), ("φ, °", "right"), (pick(lang, "t, ms", "t, мс"), "right"),
            (pick(lang, "S, mm", "S, мм"), "right"), (pick(lang, "V, m/s", "V, м/с"), "right"), (pick(lang, "a, m/s²", "a, м/с²"), "right"),
            (pick(lang, "phase", "участок"), "left"),
        ]
    t = _table(title, *cols)
    for row in m.table:
        ph = pick(lang, *_PHASE[row.phase])
        if v.is_rocker:
            t.add_row(
                str(row.index), f"{_n(lang, row.phi_deg, 'g')}", f"{_n(lang, row.t_s * 1000, '.3f')}",
                f"{_n(lang, math.degrees(row.s), '.3f')}", f"{_n(lang, row.v, '.3f')}", f"{_n(lang, row.a, '.1f')}",
                f"{_n(lang, row.s_b_m * 1000, '.3f')}", f"{_n(lang, row.v_b_m_s, '.4f')}", f"{_n(lang, row.a_b_m_s2, '.2f')}", ph,
            )
        else:
            t.add_row(str(row.index), f"{_n(lang, row.phi_deg, 'g')}", f"{_n(lang, row.t_s * 1000, '.3f')}", f"{_n(lang, row.s * 1000, '.3f')}", f"{_n(lang, row.v, '.4f')}", f"{_n(lang, row.a, '.2f')}", ph)
    return t


def _maxima_table(r: CamResult, lang: str):
    m, v = r.motion, r.variant
    mx = m.maxima
    rocker = v.is_rocker
    vu, au = (pick(lang, "rad/s", "рад/с"), pick(lang, "rad/s²", "рад/с²")) if rocker else (pick(lang, "m/s", "м/с"), pick(lang, "m/s²", "м/с²"))
    vs, as_ = ("ω", "ε") if rocker else ("V", "a")
    t = _table(
        pick(lang, "Extremes on rise and return", "Экстремумы на удалении и возвращении"),
        (pick(lang, "Quantity", "Величина"), "left"),
        (pick(lang, "Rise", "Удаление"), "right"),
        (pick(lang, "Return", "Возвращение"), "right"),
    )
    t.add_row(f"{vs}_max, {vu}", f"{_n(lang, mx.v_rise_max, '.4f')} (φ = {_n(lang, mx.phi_v_rise_max_deg, '.1f')}°)", f"{_n(lang, mx.v_return_min, '.4f')} (φ = {_n(lang, mx.phi_v_return_min_deg, '.1f')}°)")
    t.add_row(f"{as_}_max, {au}", f"{_n(lang, mx.a_rise_max, '.2f')}", f"{_n(lang, mx.a_return_max, '.2f')}")
    t.add_row(f"{as_}_min, {au}", f"{_n(lang, mx.a_rise_min, '.2f')}", f"{_n(lang, mx.a_return_min, '.2f')}")
    if rocker:
        l = v.l_bc_m
        t.add_row(pick(lang, "V_B max, m/s (1.6)", "V_B max, м/с (1.6)"), f"{_n(lang, mx.v_rise_max * l, '.4f')}", f"{_n(lang, mx.v_return_min * l, '.4f')}")
        t.add_row(pick(lang, "a_B max, m/s² (1.6)", "a_B max, м/с² (1.6)"), f"{_n(lang, max(abs(mx.a_rise_max), abs(mx.a_rise_min)) * l, '.2f')}", f"{_n(lang, max(abs(mx.a_return_max), abs(mx.a_return_min)) * l, '.2f')}")
    t.add_row(
        "|a_в.max / a_у.max| (1.7)",
        f"{_n(lang, mx.accel_ratio, '.6f')}",
        f"(φ_у/φ_в)² = {_n(lang, mx.accel_ratio_book, '.6f')}",
    )
    return t


def _scales_table(r: CamResult, lang: str):
    s, v = r.motion.scales, r.variant
    mm = pick(lang, "mm", "мм")
    t = _table(
        pick(lang, "Drawing scales (1.9)–(1.18)", "Масштабы диаграмм (1.9)–(1.18)"),
        (pick(lang, "Scale", "Масштаб"), "left"),
        (pick(lang, "Value", "Значение"), "right"),
        (pick(lang, "Unit / formula", "Единицы / формула"), "left"),
    )
    t.add_row(pick(lang, "layout", "разметка"), f"b = {_n(lang, s.b_mm, 'g')} {mm}, Y_Smax = {_n(lang, s.y_s_max_mm, 'g')} {mm}", f"H_V = {_n(lang, s.h_v_mm, 'g')} {mm}, H_a = {_n(lang, s.h_a_mm, 'g')} {mm}")
    t.add_row("k_φ", _g(lang, s.k_phi_deg_mm, 5), pick(lang, "deg/mm = φ_р/b (1.9)", "град/мм = φ_р/b (1.9)"))
    t.add_row("k_t", _g(lang, s.k_t_s_mm, 5), pick(lang, "s/mm = φ_р/(6·|n_k|·b) (1.10)", "с/мм = φ_р/(6·|n_k|·b) (1.10)"))
    if v.is_rocker:
        t.add_row(pick(lang, "k_γ deg", "k_γ град"), _g(lang, s.k_gamma_deg_mm, 5), pick(lang, "deg/mm = γ_max/Y_γmax (1.14)", "град/мм = γ_max/Y_γmax (1.14)"))
        t.add_row(pick(lang, "k_γ rad", "k_γ рад"), _g(lang, s.k_s, 5), pick(lang, "rad/mm = k_γ deg·π/180 (1.15)", "рад/мм = k_γ град·π/180 (1.15)"))
        t.add_row("k_ω", _g(lang, s.k_v, 5), pick(lang, "rad/s per mm = k_γ rad/(k_t·H_V) (1.16)", "рад/(с·мм) = k_γ рад/(k_t·H_V) (1.16)"))
        t.add_row("k_ε", _g(lang, s.k_a, 5), pick(lang, "rad/s² per mm = k_ω/(k_t·H_a) (1.17)", "рад/(с²·мм) = k_ω/(k_t·H_a) (1.17)"))
        t.add_row("k_S", _g(lang, s.k_s_b, 5), pick(lang, "m/mm = k_γ rad·l_BC (1.18)", "м/мм = k_γ рад·l_BC (1.18)"))
        t.add_row("k_V", _g(lang, s.k_v_b, 5), pick(lang, "m/s per mm = k_ω·l_BC (1.18)", "м/(с·мм) = k_ω·l_BC (1.18)"))
        t.add_row("k_a", _g(lang, s.k_a_b, 5), pick(lang, "m/s² per mm = k_ε·l_BC (1.18)", "м/(с²·мм) = k_ε·l_BC (1.18)"))
    else:
        t.add_row("k_S", _g(lang, s.k_s, 5), pick(lang, "m/mm = S_max/Y_Smax (1.11)", "м/мм = S_max/Y_Smax (1.11)"))
        t.add_row("k_V", _g(lang, s.k_v, 5), pick(lang, "m/s per mm = k_S/(k_t·H_V) (1.12)", "м/(с·мм) = k_S/(k_t·H_V) (1.12)"))
        t.add_row("k_a", _g(lang, s.k_a, 5), pick(lang, "m/s² per mm = k_V/(k_t·H_a) (1.13)", "м/(с²·мм) = k_V/(k_t·H_a) (1.13)"))
    t.add_row("Y_V max", f"{_n(lang, s.y_v_max_mm, '.1f')}", mm)
    t.add_row("Y_a.у.max", f"{_n(lang, s.y_a_rise_max_mm, '.1f')}", mm)
    t.add_row("Y_a.в.max", f"{_n(lang, s.y_a_return_max_mm, '.1f')}", f"{mm} = Y_a.у.max·(φ_у/φ_в)² (1.8)")
    return t


def _dims_table(r: CamResult, lang: str):
    z, p, v = r.sizing, r.profile, r.variant
    mm = pick(lang, "mm", "мм")
    t = _table(
        pick(lang, "Main dimensions (1.19)–(1.25), roller (1.28)", "Основные размеры (1.19)–(1.25), ролик (1.28)"),
        (pick(lang, "Quantity", "Величина"), "left"),
        (pick(lang, "Chosen (exact zone)", "Принято (точная зона)") if r.source == "program" else pick(lang, "Your choice", "Ваш выбор"), "right"),
        (pick(lang, "Book's vertex", "Вершина по пособию"), "right"),
        (pick(lang, "Note", "Примечание"), "left"),
    )
    t.add_row("r_0", f"{_n(lang, z.r0_m * 1000, '.2f')} {mm}", f"{_n(lang, z.book_r0_m * 1000, '.2f')} {mm}", pick(lang, "pitch-curve base radius |O B0|", "радиус теоретического профиля |O B0|"))
    if v.is_rocker:
        t.add_row("l_OC", f"{_n(lang, z.l_oc_m * 1000, '.2f')} {mm}", f"{_n(lang, z.book_l_oc_m * 1000, '.2f')} {mm}", pick(lang, "cam centre to rocker pivot", "межцентровое расстояние"))
        t.add_row("l_BC", f"{_n(lang, v.l_bc_m * 1000, '.2f')} {mm}", "", pick(lang, "given", "задано"))
        sw = pick(lang, "same way as the cam", "в ту же сторону, что и кулачок") if z.swing == "same" else pick(lang, "opposite to the cam", "против вращения кулачка")
        other = "" if z.r0_other_swing_m is None else pick(lang, f"other swing: r_0 = {_n(lang, z.r0_other_swing_m * 1000, '.2f')} mm", f"другое направление: r_0 = {_n(lang, z.r0_other_swing_m * 1000, '.2f')} мм")
        t.add_row(pick(lang, "swing on rise", "качание при удалении"), sw, "", other)
    else:
        t.add_row("e", f"{_n(lang, z.e_m * 1000, '+.2f')} {mm}", f"{_n(lang, z.book_e_m * 1000, '+.2f')} {mm}", pick(lang, "e > 0: follower axis right of O (follower above the cam)", "e > 0: ось толкателя правее O (толкатель над кулачком)"))
    t.add_row(
        pick(lang, "ν max on rise", "ν max на удалении"),
        f"{_n(lang, z.nu_rise_max_deg, '.2f')}°",
        f"{_n(lang, z.book_nu_rise_max_deg, '.2f')}°",
        f"ν_max = {_n(lang, v.nu_max_deg, 'g')}°",
    )
    t.add_row(
        pick(lang, "ν max on return", "ν max на возвращении"),
        f"{_n(lang, z.nu_return_max_deg, '.2f')}°",
        f"{_n(lang, z.book_nu_return_max_deg, '.2f')}°",
        pick(lang, "not limited (spring)", "не ограничивается (пружина)") if z.closure == "force" else f"ν_max = {_n(lang, v.nu_max_deg, 'g')}°",
    )
    rule = {"book": "0.2·r_0 (1.28)", "limited": pick(lang, "0.8·ρ_min (0.2·r_0 too large)", "0,8·ρ_min (0,2·r_0 велик)"),
            "student": pick(lang, "your --roller", "ваш --roller")}.get(p.roller_rule, "")
    if lang == "ru":
        rule = rule.replace("0.2·r_0 (1.28)", "0,2·r_0 (1.28)")
    t.add_row("r_р", f"{_n(lang, p.roller_m * 1000, '.2f')} {mm}", f"{_n(lang, p.roller_book_m * 1000, '.2f')} {mm}", rule)
    t.add_row("r_0 − r_р", f"{_n(lang, p.working_min_radius_m * 1000, '.2f')} {mm}", "", pick(lang, "smallest radius of the working profile", "наименьший радиус действительного профиля"))
    t.add_row(pick(lang, "far-dwell radius", "радиус дальнего стояния"), f"{_n(lang, p.r_far_m * 1000, '.2f')} {mm}", "", pick(lang, "pitch curve", "теоретический профиль"))
    return t


def _psi_table(r: CamResult, lang: str):
    p, v = r.profile, r.variant
    t = _table(
        pick(lang, "Profile angles (1.1)–(1.4)", "Профильные углы (1.1)–(1.4)"),
        (pick(lang, "Angle", "Угол"), "left"),
        ("ψ, °", "right"),
        ("φ, °", "right"),
    )
    t.add_row("ψ_у", f"{_n(lang, p.psi_rise_deg, '.2f')}", f"{_n(lang, v.phi_rise_deg, 'g')}")
    t.add_row("ψ_дс", f"{_n(lang, abs(p.psi_far_deg), '.2f')}", f"{_n(lang, v.phi_far_dwell_deg, 'g')}")
    t.add_row("ψ_в", f"{_n(lang, p.psi_return_deg, '.2f')}", f"{_n(lang, v.phi_return_deg, 'g')}")
    t.add_row("ψ_бс", f"{_n(lang, p.psi_near_deg, '.2f')}", f"{_n(lang, v.phi_near_dwell_deg, 'g')}")
    t.add_row("ψ_р = φ_р (1.4)", f"{_n(lang, p.psi_working_deg, '.2f')}", f"{_n(lang, v.phi_working_deg, 'g')}")
    return t


_SIZE_NAMES = {
    "r0": ("r_0", "base radius of T", "радиус теор. профиля"),
    "e": ("e", "offset", "эксцентриситет"),
    "l_oc": ("l_OC", "centre distance", "межцентровое расстояние"),
    "l_bc": ("l_BC", "rocker length", "длина коромысла"),
    "roller": ("r_р", "roller radius (1.28)", "радиус ролика (1.28)"),
    "working_min_radius": ("r_0 − r_р", "smallest radius of D1", "наименьший радиус D1"),
    "far_dwell_radius": ("R_дс", "far-dwell radius of T", "радиус дальнего стояния T"),
    "stroke": ("S_max", "stroke", "ход толкателя"),
}


def _drawing_table(r: CamResult, lang: str):
    d, v = r.drawing, r.variant
    mm = pick(lang, "mm", "мм")
    t = _table(
        pick(lang, "Profile drawing scale (Table 1.1), (1.26)–(1.27)", "Масштаб построения профиля (табл. 1.1), (1.26)–(1.27)"),
        (pick(lang, "Quantity", "Величина"), "left"),
        (pick(lang, f"Real, {mm}", f"Натур., {mm}"), "right"),
        (pick(lang, f"At k_S, {mm}", f"При k_S, {mm}"), "right"),
        (pick(lang, f"At k_Sk, {mm}", f"При k_Sk, {mm}"), "right"),
        (pick(lang, "Note", "Примечание"), "left"),
    )
    w, h = d.extent_mm
    m_sign = pick(lang, "M", "М")
    t.add_row(
        f"{m_sign} {d.scale}", "", "", f"k_Sk = {_n(lang, d.k_sk, 'g')}",
        pick(lang, f"m/mm; largest for a {_n(lang, d.field_mm, 'g')}×{_n(lang, d.field_mm, 'g')} mm field",
             f"м/мм; наибольший для поля {_n(lang, d.field_mm, 'g')}×{_n(lang, d.field_mm, 'g')} мм"),
    )
    t.add_row(
        "k_S = k_S′", "", _g(lang, d.k_s, 5), f"k_S/k_Sk = {_n(lang, d.k_s / d.k_sk, '.4g')}",
        pick(lang, "m/mm, " + ("k_S_B (1.18)" if v.is_rocker else "(1.11)") + "; k_S′ = k_S (§1.3.1)",
             "м/мм, " + ("k_S_B (1.18)" if v.is_rocker else "(1.11)") + "; k_S′ = k_S (п. 1.3.1)"),
    )
    t.add_row("", "", "y_Si, x_i", "y_Sik, x_ik", "y_Sik = (k_S/k_Sk)·y_Si (1.26); x_ik = (k_S′/k_Sk)·x_i (1.27)")
    t.add_row(
        pick(lang, "cam with roller", "габарит с роликом"),
        f"{_n(lang, d.width_m * 1000, '.1f')} × {_n(lang, d.height_m * 1000, '.1f')}", "", f"{_n(lang, w, '.1f')} × {_n(lang, h, '.1f')}",
        (OK if d.fits else BAD) + " " + pick(lang, f"≤ {_n(lang, d.field_mm, 'g')} {mm}", f"≤ {_n(lang, d.field_mm, 'g')} {mm}"),
    )
    for s in d.sizes:
        sym, en, ru = _SIZE_NAMES[s.name]
        if s.name == "stroke" and v.is_rocker:
            sym, en, ru = "S_B max", "arc γ_max·l_BC (1.6)", "дуга γ_max·l_BC (1.6)"
        sign = "+" if s.name == "e" else ""
        t.add_row(sym, f"{_n(lang, s.length_m * 1000, sign + '.2f')}", f"{_n(lang, s.at_k_s_mm, sign + '.2f')}", f"{_n(lang, s.drawn_mm, sign + '.2f')}", f"({s.formula}) " + pick(lang, en, ru))
    return t


def _checks_table(r: CamResult, lang: str):
    z, p, v, m = r.sizing, r.profile, r.variant, r.motion
    mm = pick(lang, "mm", "мм")
    t = _table(
        pick(lang, "Checks", "Проверки"),
        ("", "center"),
        (pick(lang, "Condition", "Условие"), "left"),
        (pick(lang, "Value", "Значение"), "left"),
    )
    lim = v.nu_max_deg + 0.01
    t.add_row(OK if z.nu_rise_max_deg <= lim else BAD, pick(lang, "ν ≤ ν_max on rise (1.19)", "ν ≤ ν_max на удалении (1.19)"), f"{_nu(lang, z.nu_rise_max_deg, v.nu_max_deg)}° ≤ {_n(lang, v.nu_max_deg, 'g')}°")
    if z.closure == "form":
        t.add_row(OK if z.nu_return_max_deg <= lim else BAD, pick(lang, "ν ≤ ν_max on return (1.19)", "ν ≤ ν_max на возвращении (1.19)"), f"{_nu(lang, z.nu_return_max_deg, v.nu_max_deg)}° ≤ {_n(lang, v.nu_max_deg, 'g')}°")
    else:
        t.add_row(OK, pick(lang, "return by the spring (no jamming)", "возвращение пружиной (заклинивания нет)"), f"ν ≤ {_n(lang, z.nu_return_max_deg, '.1f')}°")
    book_nu = z.book_nu_rise_max_deg if z.closure == "force" else max(z.book_nu_rise_max_deg, z.book_nu_return_max_deg)
    t.add_row(
        OK if book_nu <= v.nu_max_deg + 0.05 else WARN,
        pick(lang, "book's vertex keeps ν ≤ ν_max", "вершина по пособию: ν ≤ ν_max"),
        f"{_n(lang, book_nu, '.2f')}°",
    )
    rho = p.roller_max_m
    mark = BAD if p.undercut else (WARN if p.roller_m > 0.8 * rho else OK)
    what = pick(lang, "r_р < ρ_min (no undercut)", "r_р < ρ_min (нет подреза)")
    val = f"{_n(lang, p.roller_m * 1000, '.2f')} {mm} {'<' if not p.undercut else '≥'} {_n(lang, rho * 1000, '.2f')} {mm}"
    t.add_row(mark, what, val)
    if p.undercut and p.r0_for_rule_m is not None:
        fix = f"l_OC = {_n(lang, p.fix_l_oc_m * 1000, '.2f')} {mm}" if v.is_rocker else f"e = {_n(lang, p.fix_e_m * 1000, '+.2f')} {mm}"
        t.add_row("→", pick(lang, "fix: larger cam", "исправление: больший кулачок"), f"r_0 = {_n(lang, p.r0_for_rule_m * 1000, '.2f')} {mm}, {fix}")
    ch = r.checks
    if ch is not None and ch.pivot_ok is not None:
        t.add_row(OK if ch.pivot_ok else BAD, pick(lang, "pivot C outside the cam's sweep", "опора C вне кулачка"),
                  f"l_OC = {_n(lang, ch.l_oc_m * 1000, '.2f')} {mm} {'>' if ch.pivot_ok else '≤'} {_n(lang, ch.body_m * 1000, '.2f')} {mm}")
    conv = f"ρ_min {pick(lang, 'convex', 'выпукл.')} = {_n(lang, p.rho_min_convex_m * 1000, '.2f')} {mm}"
    if p.rho_min_concave_m is not None:
        conv += f"; {pick(lang, 'concave', 'вогнут.')} = {_n(lang, p.rho_min_concave_m * 1000, '.2f')} {mm}"
    t.add_row("", pick(lang, "pitch curve radius of curvature", "радиус кривизны теоретического профиля"), conv)
    ok = abs(p.psi_working_deg - v.phi_working_deg) < 1e-6
    t.add_row(OK if ok else BAD, "ψ_р = φ_р (1.4)", f"{_n(lang, p.psi_working_deg, '.4f')}° = {_n(lang, v.phi_working_deg, 'g')}°")
    mx = m.maxima
    ok = abs(mx.accel_ratio - mx.accel_ratio_book) < 1e-9
    t.add_row(OK if ok else BAD, "|a_в.max/a_у.max| = (φ_у/φ_в)² (1.7)", f"{_n(lang, mx.accel_ratio, '.6f')} = {_n(lang, mx.accel_ratio_book, '.6f')}")
    return t


def print_cam(console, result: CamResult, lang: str, *, include_input: bool = True) -> None:
    """Print sheet 3's tables to a rich Console (the shell prints the notes, once, at the end)."""
    makers = (_motion_table, _maxima_table, _scales_table, _dims_table, _psi_table, _drawing_table, _checks_table)
    if include_input:
        makers = (_input_table,) + makers
    for make in makers:
        console.print(make(result, lang))


def print_cam_input(console, result: CamResult, lang: str) -> None:
    """The input-data table alone (the project report opens with it)."""
    console.print(_input_table(result, lang))
