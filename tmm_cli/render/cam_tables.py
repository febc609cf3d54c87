"""Rich tables of sheet 3 (the cam): input, motion table, scales, dimensions, ψ angles, checks."""

from __future__ import annotations

import math

from ..cam.design import CamResult
from ..cam.laws import law_impacts
from .i18n import pick
from .table_model import Table
from .variants_tables import law_words, rotation_words, scheme_words

OK = "[green]✔[/green]"
BAD = "[red]✘[/red]"
WARN = "[yellow]![/yellow]"


def _table(title: str, *cols: tuple[str, str]):
    t = Table(title=title, header_style="bold")
    for name, justify in cols:
        t.add_column(name, justify=justify)
    return t


def _g(x: float, nd: int = 4) -> str:
    return f"{x:.{nd}g}"


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
        t.add_row("γ_max", f"{v.stroke:g}°", pick(lang, "rocker swing", "угол качания коромысла"))
        t.add_row("l_BC", f"{v.l_bc_m * 1000:g} " + pick(lang, "mm", "мм"), pick(lang, "rocker length", "длина коромысла"))
    else:
        t.add_row("S_max", f"{v.stroke * 1000:g} " + pick(lang, "mm", "мм"), pick(lang, "follower stroke", "ход толкателя"))
    t.add_row("ν_max", f"{v.nu_max_deg:g}°", pick(lang, "allowed pressure angle (1.19)", "допустимый угол давления (1.19)"))
    t.add_row("n_k", f"{v.n_cam_rpm:g} " + pick(lang, "rpm", "об/мин"), rotation_words(v, lang))
    t.add_row("ω_k", f"{m.omega:.3f} " + pick(lang, "rad/s", "рад/с"), "ω_k = π·|n_k|/30 (1.5)")
    t.add_row("φ_у", f"{v.phi_rise_deg:g}°", pick(lang, "rise", "удаление"))
    t.add_row("φ_дс", f"{v.phi_far_dwell_deg:g}°", pick(lang, "far dwell", "дальнее стояние"))
    t.add_row("φ_в", f"{v.phi_return_deg:g}°", pick(lang, "return", "возвращение"))
    t.add_row("φ_бс", f"{v.phi_near_dwell_deg:g}°", pick(lang, "near dwell = 360° − φ_р", "ближнее стояние = 360° − φ_р"))
    t.add_row("φ_р", f"{v.phi_working_deg:g}°", "φ_у + φ_дс + φ_в (1.3)")
    t.add_row("T", f"{m.period_s * 1000:.3f} " + pick(lang, "ms", "мс"), pick(lang, "one cam turn", "время одного оборота"))
    return t


_PHASE = {
    "rise": ("rise", "удаление"),
    "far_dwell": ("far dwell", "дальнее стояние"),
    "return": ("return", "возвращение"),
    "near_dwell": ("near dwell", "ближнее стояние"),
}


def _motion_table(r: CamResult, lang: str):
    m, v = r.motion, r.variant
    steps = f"{m.table_step_rise_deg:g}° / {m.table_step_return_deg:g}°"
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
                str(row.index), f"{row.phi_deg:g}", f"{row.t_s * 1000:.3f}",
                f"{math.degrees(row.s):.3f}", f"{row.v:.3f}", f"{row.a:.1f}",
                f"{row.s_b_m * 1000:.3f}", f"{row.v_b_m_s:.4f}", f"{row.a_b_m_s2:.2f}", ph,
            )
        else:
            t.add_row(str(row.index), f"{row.phi_deg:g}", f"{row.t_s * 1000:.3f}", f"{row.s * 1000:.3f}", f"{row.v:.4f}", f"{row.a:.2f}", ph)
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
    t.add_row(f"{vs}_max, {vu}", f"{mx.v_rise_max:.4f} (φ = {mx.phi_v_rise_max_deg:.1f}°)", f"{mx.v_return_min:.4f} (φ = {mx.phi_v_return_min_deg:.1f}°)")
    t.add_row(f"{as_}_max, {au}", f"{mx.a_rise_max:.2f}", f"{mx.a_return_max:.2f}")
    t.add_row(f"{as_}_min, {au}", f"{mx.a_rise_min:.2f}", f"{mx.a_return_min:.2f}")
    if rocker:
        l = v.l_bc_m
        t.add_row(pick(lang, "V_B max, m/s (1.6)", "V_B max, м/с (1.6)"), f"{mx.v_rise_max * l:.4f}", f"{mx.v_return_min * l:.4f}")
        t.add_row(pick(lang, "a_B max, m/s² (1.6)", "a_B max, м/с² (1.6)"), f"{max(abs(mx.a_rise_max), abs(mx.a_rise_min)) * l:.2f}", f"{max(abs(mx.a_return_max), abs(mx.a_return_min)) * l:.2f}")
    t.add_row(
        "|a_в.max / a_у.max| (1.7)",
        f"{mx.accel_ratio:.6f}",
        f"(φ_у/φ_в)² = {mx.accel_ratio_book:.6f}",
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
    t.add_row(pick(lang, "layout", "разметка"), f"b = {s.b_mm:g} {mm}, Y_Smax = {s.y_s_max_mm:g} {mm}", f"H_V = {s.h_v_mm:g} {mm}, H_a = {s.h_a_mm:g} {mm}")
    t.add_row("k_φ", _g(s.k_phi_deg_mm, 5), pick(lang, "deg/mm = φ_р/b (1.9)", "град/мм = φ_р/b (1.9)"))
    t.add_row("k_t", _g(s.k_t_s_mm, 5), pick(lang, "s/mm = φ_р/(6·|n_k|·b) (1.10)", "с/мм = φ_р/(6·|n_k|·b) (1.10)"))
    if v.is_rocker:
        t.add_row(pick(lang, "k_γ deg", "k_γ град"), _g(s.k_gamma_deg_mm, 5), pick(lang, "deg/mm = γ_max/Y_γmax (1.14)", "град/мм = γ_max/Y_γmax (1.14)"))
        t.add_row(pick(lang, "k_γ rad", "k_γ рад"), _g(s.k_s, 5), pick(lang, "rad/mm = k_γ deg·π/180 (1.15)", "рад/мм = k_γ град·π/180 (1.15)"))
        t.add_row("k_ω", _g(s.k_v, 5), pick(lang, "rad/s per mm = k_γ rad/(k_t·H_V) (1.16)", "рад/(с·мм) = k_γ рад/(k_t·H_V) (1.16)"))
        t.add_row("k_ε", _g(s.k_a, 5), pick(lang, "rad/s² per mm = k_ω/(k_t·H_a) (1.17)", "рад/(с²·мм) = k_ω/(k_t·H_a) (1.17)"))
        t.add_row("k_S", _g(s.k_s_b, 5), pick(lang, "m/mm = k_γ rad·l_BC (1.18)", "м/мм = k_γ рад·l_BC (1.18)"))
        t.add_row("k_V", _g(s.k_v_b, 5), pick(lang, "m/s per mm = k_ω·l_BC (1.18)", "м/(с·мм) = k_ω·l_BC (1.18)"))
        t.add_row("k_a", _g(s.k_a_b, 5), pick(lang, "m/s² per mm = k_ε·l_BC (1.18)", "м/(с²·мм) = k_ε·l_BC (1.18)"))
    else:
        t.add_row("k_S", _g(s.k_s, 5), pick(lang, "m/mm = S_max/Y_Smax (1.11)", "м/мм = S_max/Y_Smax (1.11)"))
        t.add_row("k_V", _g(s.k_v, 5), pick(lang, "m/s per mm = k_S/(k_t·H_V) (1.12)", "м/(с·мм) = k_S/(k_t·H_V) (1.12)"))
        t.add_row("k_a", _g(s.k_a, 5), pick(lang, "m/s² per mm = k_V/(k_t·H_a) (1.13)", "м/(с²·мм) = k_V/(k_t·H_a) (1.13)"))
    t.add_row("Y_V max", f"{s.y_v_max_mm:.1f}", mm)
    t.add_row("Y_a.у.max", f"{s.y_a_rise_max_mm:.1f}", mm)
    t.add_row("Y_a.в.max", f"{s.y_a_return_max_mm:.1f}", f"{mm} = Y_a.у.max·(φ_у/φ_в)² (1.8)")
    return t


def _dims_table(r: CamResult, lang: str):
    z, p, v = r.sizing, r.profile, r.variant
    mm = pick(lang, "mm", "мм")
    t = _table(
        pick(lang, "Main dimensions (1.19)–(1.25), roller (1.28)", "Основные размеры (1.19)–(1.25), ролик (1.28)"),
        (pick(lang, "Quantity", "Величина"), "left"),
        (pick(lang, "Chosen (exact zone)", "Принято (точная зона)"), "right"),
        (pick(lang, "Book's vertex", "Вершина по пособию"), "right"),
        (pick(lang, "Note", "Примечание"), "left"),
    )
    t.add_row("r_0", f"{z.r0_m * 1000:.2f} {mm}", f"{z.book_r0_m * 1000:.2f} {mm}", pick(lang, "pitch-curve base radius |O B0|", "радиус теоретического профиля |O B0|"))
    if v.is_rocker:
        t.add_row("l_OC", f"{z.l_oc_m * 1000:.2f} {mm}", f"{z.book_l_oc_m * 1000:.2f} {mm}", pick(lang, "cam centre to rocker pivot", "межцентровое расстояние"))
        t.add_row("l_BC", f"{v.l_bc_m * 1000:.2f} {mm}", "", pick(lang, "given", "задано"))
        sw = pick(lang, "same way as the cam", "в ту же сторону, что и кулачок") if z.swing == "same" else pick(lang, "opposite to the cam", "против вращения кулачка")
        t.add_row(pick(lang, "swing on rise", "качание при удалении"), sw, "", pick(lang, f"other swing: r_0 = {z.r0_other_swing_m * 1000:.2f} mm", f"другое направление: r_0 = {z.r0_other_swing_m * 1000:.2f} мм"))
    else:
        t.add_row("e", f"{z.e_m * 1000:+.2f} {mm}", f"{z.book_e_m * 1000:+.2f} {mm}", pick(lang, "e > 0: follower axis right of O (follower above the cam)", "e > 0: ось толкателя правее O (толкатель над кулачком)"))
    t.add_row(
        pick(lang, "ν max on rise", "ν max на удалении"),
        f"{z.nu_rise_max_deg:.2f}°",
        f"{z.book_nu_rise_max_deg:.2f}°",
        f"ν_max = {v.nu_max_deg:g}°",
    )
    t.add_row(
        pick(lang, "ν max on return", "ν max на возвращении"),
        f"{z.nu_return_max_deg:.2f}°",
        f"{z.book_nu_return_max_deg:.2f}°",
        pick(lang, "not limited (spring)", "не ограничивается (пружина)") if z.closure == "force" else f"ν_max = {v.nu_max_deg:g}°",
    )
    t.add_row("r_р", f"{p.roller_m * 1000:.2f} {mm}", "", "0.2·r_0 (1.28)")
    t.add_row("r_0 − r_р", f"{p.working_min_radius_m * 1000:.2f} {mm}", "", pick(lang, "smallest radius of the working profile", "наименьший радиус действительного профиля"))
    t.add_row(pick(lang, "far-dwell radius", "радиус дальнего стояния"), f"{p.r_far_m * 1000:.2f} {mm}", "", pick(lang, "pitch curve", "теоретический профиль"))
    return t


def _psi_table(r: CamResult, lang: str):
    p, v = r.profile, r.variant
    t = _table(
        pick(lang, "Profile angles (1.1)–(1.4)", "Профильные углы (1.1)–(1.4)"),
        (pick(lang, "Angle", "Угол"), "left"),
        ("ψ, °", "right"),
        ("φ, °", "right"),
    )
    t.add_row("ψ_у", f"{p.psi_rise_deg:.2f}", f"{v.phi_rise_deg:g}")
    t.add_row("ψ_дс", f"{abs(p.psi_far_deg):.2f}", f"{v.phi_far_dwell_deg:g}")
    t.add_row("ψ_в", f"{p.psi_return_deg:.2f}", f"{v.phi_return_deg:g}")
    t.add_row("ψ_бс", f"{p.psi_near_deg:.2f}", f"{v.phi_near_dwell_deg:g}")
    t.add_row("ψ_р = φ_р (1.4)", f"{p.psi_working_deg:.2f}", f"{v.phi_working_deg:g}")
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
        f"{m_sign} {d.scale}", "", "", f"k_Sk = {d.k_sk:g}",
        pick(lang, f"m/mm; largest for a {d.field_mm:g}×{d.field_mm:g} mm field",
             f"м/мм; наибольший для поля {d.field_mm:g}×{d.field_mm:g} мм"),
    )
    t.add_row(
        "k_S = k_S′", "", _g(d.k_s, 5), f"k_S/k_Sk = {d.k_s / d.k_sk:.4g}",
        pick(lang, "m/mm, " + ("k_S_B (1.18)" if v.is_rocker else "(1.11)") + "; k_S′ = k_S (§1.3.1)",
             "м/мм, " + ("k_S_B (1.18)" if v.is_rocker else "(1.11)") + "; k_S′ = k_S (п. 1.3.1)"),
    )
    t.add_row("", "", "y_Si, x_i", "y_Sik, x_ik", "y_Sik = (k_S/k_Sk)·y_Si (1.26); x_ik = (k_S′/k_Sk)·x_i (1.27)")
    t.add_row(
        pick(lang, "cam with roller", "габарит с роликом"),
        f"{d.width_m * 1000:.1f} × {d.height_m * 1000:.1f}", "", f"{w:.1f} × {h:.1f}",
        (OK if d.fits else BAD) + " " + pick(lang, f"≤ {d.field_mm:g} {mm}", f"≤ {d.field_mm:g} {mm}"),
    )
    for s in d.sizes:
        sym, en, ru = _SIZE_NAMES[s.name]
        if s.name == "stroke" and v.is_rocker:
            sym, en, ru = "S_B max", "arc γ_max·l_BC (1.6)", "дуга γ_max·l_BC (1.6)"
        sign = "+" if s.name == "e" else ""
        t.add_row(sym, f"{s.length_m * 1000:{sign}.2f}", f"{s.at_k_s_mm:{sign}.2f}", f"{s.drawn_mm:{sign}.2f}", f"({s.formula}) " + pick(lang, en, ru))
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
    t.add_row(OK if z.nu_rise_max_deg <= lim else BAD, pick(lang, "ν ≤ ν_max on rise (1.19)", "ν ≤ ν_max на удалении (1.19)"), f"{z.nu_rise_max_deg:.2f}° ≤ {v.nu_max_deg:g}°")
    if z.closure == "form":
        t.add_row(OK if z.nu_return_max_deg <= lim else BAD, pick(lang, "ν ≤ ν_max on return (1.19)", "ν ≤ ν_max на возвращении (1.19)"), f"{z.nu_return_max_deg:.2f}° ≤ {v.nu_max_deg:g}°")
    else:
        t.add_row(OK, pick(lang, "return by the spring (no jamming)", "возвращение пружиной (заклинивания нет)"), f"ν ≤ {z.nu_return_max_deg:.1f}°")
    book_nu = z.book_nu_rise_max_deg if z.closure == "force" else max(z.book_nu_rise_max_deg, z.book_nu_return_max_deg)
    t.add_row(
        OK if book_nu <= v.nu_max_deg + 0.05 else WARN,
        pick(lang, "book's vertex keeps ν ≤ ν_max", "вершина по пособию: ν ≤ ν_max"),
        f"{book_nu:.2f}°",
    )
    rho = p.roller_max_m
    mark = BAD if p.undercut else (WARN if p.roller_m > 0.8 * rho else OK)
    what = pick(lang, "r_р < ρ_min (no undercut)", "r_р < ρ_min (нет подреза)")
    val = f"{p.roller_m * 1000:.2f} {mm} {'<' if not p.undercut else '≥'} {rho * 1000:.2f} {mm}"
    t.add_row(mark, what, val)
    if p.undercut and p.r0_for_rule_m is not None:
        fix = f"l_OC = {p.fix_l_oc_m * 1000:.2f} {mm}" if v.is_rocker else f"e = {p.fix_e_m * 1000:+.2f} {mm}"
        t.add_row("→", pick(lang, "fix: larger cam", "исправление: больший кулачок"), f"r_0 = {p.r0_for_rule_m * 1000:.2f} {mm}, {fix}")
    conv = f"ρ_min {pick(lang, 'convex', 'выпукл.')} = {p.rho_min_convex_m * 1000:.2f} {mm}"
    if p.rho_min_concave_m is not None:
        conv += f"; {pick(lang, 'concave', 'вогнут.')} = {p.rho_min_concave_m * 1000:.2f} {mm}"
    t.add_row("", pick(lang, "pitch curve radius of curvature", "радиус кривизны теоретического профиля"), conv)
    ok = abs(p.psi_working_deg - v.phi_working_deg) < 1e-6
    t.add_row(OK if ok else BAD, "ψ_р = φ_р (1.4)", f"{p.psi_working_deg:.4f}° = {v.phi_working_deg:g}°")
    mx = m.maxima
    ok = abs(mx.accel_ratio - mx.accel_ratio_book) < 1e-9
    t.add_row(OK if ok else BAD, "|a_в.max/a_у.max| = (φ_у/φ_в)² (1.7)", f"{mx.accel_ratio:.6f} = {mx.accel_ratio_book:.6f}")
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
