"""The chapter on the cam mechanism (sheet 3, book section 1), from a CamResult.

Every sentence that gives a reason is made from the decision the core took (the swing of a
rocker, the centre of the cam, the roller, the drawing scale) and is recorded as a claim
(:meth:`~.model.Document.claim`) that the tests check against the numbers.
"""

from __future__ import annotations

import math

from ...cam.laws import law_impacts, law_max
from ..terminal.variants import law_words
from .ctx import Ctx, V

_PHASE = {"rise": ("rise", "удаление"), "far_dwell": ("far dwell", "дальнее стояние"),
          "return": ("return", "возвращение"), "near_dwell": ("near dwell", "ближнее стояние")}

_LAW_F = {
    1: ['f(t) = 2t^2 "  при " 0 <= t <= 1/2', 'f(t) = 1 - 2(1 - t)^2 "  при " 1/2 < t <= 1'],
    2: ["f(t) = 3t^2 - 2t^3"],
    3: ["f(t) = (1 - cos π t)/2"],
    4: ["f(t) = t - (sin 2π t)/(2π)"],
}

_SCHEME = {
    1: ("a translating roller follower kept on the cam by a spring (force closure)",
        "поступательный роликовый толкатель с силовым замыканием (пружиной)"),
    2: ("a translating roller follower in a groove of the cam (form closure)",
        "поступательный роликовый толкатель с геометрическим замыканием (пазовый кулачок)"),
    3: ("an oscillating roller follower (rocker) kept on the cam by a spring (force closure)",
        "качающийся роликовый толкатель (коромысло) с силовым замыканием (пружиной)"),
    4: ("an oscillating roller follower (rocker) in a groove of the cam (form closure)",
        "качающийся роликовый толкатель (коромысло) с геометрическим замыканием (пазовый кулачок)"),
}


def cam_chapter(c: Ctx) -> None:
    r = c.r.cam
    c.doc.add(_heading(c, 1, c.t("Synthesis of the cam mechanism", "Синтез кулачкового механизма"), "cam"))
    _input(c, r)
    _motion(c, r)
    _scales(c, r)
    _sizing(c, r)
    _profile(c, r)
    _pressure(c, r)


def _heading(c: Ctx, level: int, text: str, label: str | None = None):
    from .model import Heading

    return Heading(level, text, "chapter", label)


# --------------------------------------------------------------------------------------------------
def _input(c: Ctx, r) -> None:
    v = r.variant
    t, n = c.t, c.n
    mm = t("mm", "мм")
    c.doc.add(_heading(c, 2, t("Input data", "Исходные данные")))
    c.p(t(f"The cam mechanism is designed for variant {v.number} of Table 1.2 {{cite:book}}: "
          f"{_SCHEME[v.scheme][0]}. The input data are given in Table {{tab:cam_input}}.",
          f"Кулачковый механизм проектируется по варианту {v.number} таблицы 1.2 {{cite:book}}: "
          f"{_SCHEME[v.scheme][1]}. Исходные данные приведены в таблице {{tab:cam_input}}."))
    rows = [
        [t("Scheme of the mechanism", "Схема механизма"), "—", str(v.scheme)],
        [t("Acceleration law", "Закон изменения ускорения"), "—",
         f"{v.law} ({law_words(v.law, c.lang)})"],
    ]
    if v.is_rocker:
        rows += [[t("Swing of the rocker", "Угол качания коромысла"), "$γ_max$, °", n(v.stroke)],
                 [t("Length of the rocker", "Длина коромысла"), f"$l_(B C)$, {mm}", n(v.l_bc_m * 1000)]]
    else:
        rows += [[t("Stroke of the follower", "Ход толкателя"), f"$S_max$, {mm}", n(v.stroke * 1000)]]
    rows += [
        [t("Allowed pressure angle", "Допустимый угол давления"), "$ν_max$, °", n(v.nu_max_deg)],
        [t("Cam speed (sign: sense of rotation)", "Частота вращения кулачка (знак — направление)"),
         f"$n_k$, {t('rpm', 'об/мин')}", n(v.n_cam_rpm)],
        [t("Rise angle", "Угол удаления"), '$φ_"у"$, °', n(v.phi_rise_deg)],
        [t("Far-dwell angle", "Угол дальнего стояния"), '$φ_"дс"$, °', n(v.phi_far_dwell_deg)],
        [t("Return angle", "Угол возвращения"), '$φ_"в"$, °', n(v.phi_return_deg)],
    ]
    c.table("cam_input", t(f"Input data of the cam mechanism, variant {v.number}",
                           f"Исходные данные кулачкового механизма, вариант {v.number}"),
            [t("Quantity", "Величина"), t("Symbol, unit", "Обозначение, единица"), t("Value", "Значение")], rows,
            align=["left", "center", "center"], widths=[2.4, 1.3, 1.5])
    sense = t("counter-clockwise", "против часовой стрелки") if v.ccw else t("clockwise", "по часовой стрелке")
    c.p(t(f"The cam turns {sense} (the sign of $n_k$). Its working angle {{cite:book:formula (1.3)}} and the "
          "near-dwell angle are",
          f"Кулачок вращается {sense} (знак $n_k$). Рабочий угол кулачка {{cite:book:формула (1.3)}} и угол "
          "ближнего стояния:"))
    c.formula(c.calc('φ_"р" = φ_"у" + φ_"дс" + φ_"в"', "{0} + {1} + {2}",
                     [V(v.phi_rise_deg, exact=True), V(v.phi_far_dwell_deg, exact=True), V(v.phi_return_deg, exact=True)],
                     V(v.phi_working_deg, exact=True, deg=True)),
              where=['φ_"р"', 'φ_"у"', 'φ_"дс"', 'φ_"в"'])
    c.formula(c.calc('φ_"бс" = 360 degree - φ_"р"', "{0} - {1}", [V(360, exact=True, deg=True),
                                                                  V(v.phi_working_deg, exact=True, deg=True)],
                     V(v.phi_near_dwell_deg, exact=True, deg=True)), where=['φ_"бс"'])
    m = r.motion
    c.p(t("The angular speed of the cam {cite:book:formula (1.5)} and the time of one turn:",
          "Угловая скорость кулачка {cite:book:формула (1.5)} и время одного оборота:"))
    c.formula(c.calc("ω_k = (π |n_k|)/30", "(π dot {0})/30", [V(abs(v.n_cam_rpm), exact=True)],
                     V(m.omega, decimals=2), t("rad/s", "рад/с")), label="omega_k", where=["ω_k", "n_k"])
    c.formula(c.calc("T = 60/(|n_k|)", "60/{0}", [V(abs(v.n_cam_rpm), exact=True)],
                     V(m.period_s, sig=4), t("s", "с")), where=["T"])


# --------------------------------------------------------------------------------------------------
def _motion(c: Ctx, r) -> None:
    v, m = r.variant, r.motion
    t, n = c.t, c.n
    rocker = v.is_rocker
    c.doc.add(_heading(c, 2, t("Motion law of the follower", "Закон движения толкателя")))
    impacts = (t("the acceleration jumps at the ends of the phases, which gives soft impacts",
                 "ускорение изменяется скачком в начале и в конце фаз, что вызывает мягкие удары")
               if law_impacts(v.law) == "soft" else
               t("velocity and acceleration change without jumps, so there are no impacts",
                 "скорость и ускорение изменяются без скачков, ударов нет"))
    c.p(t(f"The follower moves by the {law_words(v.law, c.lang)} law (Figure 1.9 {{cite:book}}), the same on the "
          f"rise and on the return; {impacts}. With the share $t$ of the phase angle turned, the displacement as "
          "a share of the stroke is",
          f"Толкатель движется по закону: {law_words(v.law, c.lang)} (рисунок 1.9 {{cite:book}}), одинаковому на "
          f"удалении и возвращении; {impacts}. Перемещение в долях хода при доле $t$ пройденного угла фазы равно"))
    for j, line in enumerate(_LAW_F[v.law]):
        c.formula(line.replace('"  при "', '"  ' + t("for", "при") + ' "'),
                  where=["t", "f(t)"] if j == len(_LAW_F[v.law]) - 1 else ())
    h_sym = "γ_max" if rocker else "S_max"
    c.p(t(f"The follower's displacement on the rise is $s = {h_sym} f(φ/φ_\"у\")$, on the return "
          f"$s = {h_sym} (1 - f((φ - φ_\"у\" - φ_\"дс\")/φ_\"в\"))$. The cam turns at a constant speed, so "
          "$V = ω_k d s/d φ$ and $a = ω_k^2 d^2 s/d φ^2$; the largest values on the rise are",
          f"Перемещение толкателя на удалении $s = {h_sym} f(φ/φ_\"у\")$, на возвращении "
          f"$s = {h_sym} (1 - f((φ - φ_\"у\" - φ_\"дс\")/φ_\"в\"))$. Кулачок вращается равномерно, поэтому "
          "$V = ω_k d s/d φ$, $a = ω_k^2 d^2 s/d φ^2$, и наибольшие значения на удалении равны"))
    f1, f2, _ = law_max(v.law)
    mx = m.maxima
    h_num = math.radians(v.stroke) if rocker else v.stroke
    phr = math.radians(v.phi_rise_deg)
    vs, as_ = ("ω", "ε") if rocker else ("V", "a")
    vu = t("rad/s", "рад/с") if rocker else t("m/s", "м/с")
    au = t("rad/s²", "рад/с²") if rocker else t("m/s²", "м/с²")
    a_rise = max(abs(mx.a_rise_max), abs(mx.a_rise_min))
    a_ret = max(abs(mx.a_return_max), abs(mx.a_return_min))
    c.formula(c.calc(f'{vs}_("у" max) = (f\'_max h ω_k)/φ_"у"', "({0} dot {1} dot {2})/{3}",
                     [V(f1, sig=4, exact=f1 == round(f1)), V(h_num, sig=4), V(m.omega, decimals=2), V(phr, sig=4)],
                     V(mx.v_rise_max, sig=4), vu),
              where=[f'{vs}_("у" max)', "f'_max", ("h", t("the stroke, m", "ход толкателя, м") if not rocker else
                                                    t("the swing of the rocker, rad", "угол качания коромысла, рад"))])
    c.formula(c.calc(f'{as_}_("у" max) = (f\'\'_max h ω_k^2)/φ_"у"^2', "({0} dot {1} dot {2}^2)/{3}^2",
                     [V(f2, sig=4, exact=f2 == round(f2)), V(h_num, sig=4), V(m.omega, decimals=2), V(phr, sig=4)],
                     V(a_rise, sig=4), au),
              where=[f'{as_}_("у" max)', "f''_max"])
    c.p(t("The largest accelerations of the return and of the rise are in the ratio {cite:book:formula (1.7)}",
          "Наибольшие ускорения на возвращении и удалении относятся как {cite:book:формула (1.7)}"))
    c.formula(c.calc(f'abs({as_}_("в" max)/{as_}_("у" max))',
                     '{0}/{1} = (φ_"у"/φ_"в")^2 = ({2}/{3})^2',
                     [V(a_ret, sig=4), V(a_rise, sig=4), V(v.phi_rise_deg, exact=True), V(v.phi_return_deg, exact=True)],
                     V(mx.accel_ratio_book, sig=4)), where=[f'{as_}_("в" max)'])
    if rocker:
        lb = v.l_bc_m
        c.p(t("The roller centre B moves along an arc of radius $l_(B C)$; its largest displacement and velocity "
              "{cite:book:formula (1.6)} are",
              "Центр ролика B движется по дуге радиуса $l_(B C)$; его наибольшие перемещение и скорость "
              "{cite:book:формула (1.6)}:"))
        c.formula(c.calc("S_(B max) = γ_max l_(B C)", "{0} dot {1}", [V(h_num, sig=4), V(lb, exact=True)],
                         V(h_num * lb, sig=4), t("m", "м")),
                  c.calc("V_(B max) = ω_max l_(B C)", "{0} dot {1}", [V(mx.v_rise_max, sig=4), V(lb, exact=True)],
                         V(mx.v_rise_max * lb, sig=4), t("m/s", "м/с")),
                  where=["S_(B max)", "V_(B max)", "l_(B C)"])
    step = (n(m.table_step_rise_deg) + "°" if m.table_step_rise_deg == m.table_step_return_deg else
            t(f"{n(m.table_step_rise_deg)}° on the rise and {n(m.table_step_return_deg)}° on the return",
              f"{n(m.table_step_rise_deg)}° на удалении и {n(m.table_step_return_deg)}° на возвращении"))
    halved = ""
    if m.table_step_rise_deg < r.step_deg or m.table_step_return_deg < r.step_deg:
        halved = t(f" (the step of {n(r.step_deg)}° is halved on a phase shorter than eight steps, §1.2 {{cite:book}})",
                   f" (на фазе короче восьми шагов шаг {n(r.step_deg)}° уменьшен вдвое, п. 1.2 {{cite:book}})")
    c.p(t(f"The values at the positions of the cam, every {step}{halved}, are given in Table {{tab:cam_motion}}; "
          f"the column $B D$ holds the segments $B_i D_i = V_(B i)/ω_k$ of the sizing construction "
          f"{{cite:book:formula (1.20)}}.", f"Значения в положениях кулачка через {step}{halved} приведены в таблице "
          f"{{tab:cam_motion}}; в графе $B D$ — отрезки $B_i D_i = V_(B i)/ω_k$ для определения основных размеров "
          f"{{cite:book:формула (1.20)}}.")
        + c.if_fig("cam_motion", t(" The diagrams are shown in Figure {fig:cam_motion}.",
                                   " Диаграммы перемещения, скорости и ускорения толкателя показаны на рисунке "
                                   "{fig:cam_motion}.")))
    _motion_table(c, r)
    c.fig("cam_motion", t("Diagrams of the displacement, velocity and acceleration of the follower",
                          "Диаграммы перемещения, скорости и ускорения толкателя"))


def _motion_table(c: Ctx, r) -> None:
    v, m = r.variant, r.motion
    t, n = c.t, c.n
    rocker = v.is_rocker
    mm = t("mm", "мм")
    if rocker:
        header = ["№", "$φ$, °", f"$t$, {t('ms', 'мс')}", "$γ$, °", f"$ω$, {t('rad/s', 'рад/с')}",
                  f"$ε$, {t('rad/s²', 'рад/с²')}", f"$S_B$, {mm}", f"$V_B$, {t('m/s', 'м/с')}",
                  f"$a_B$, {t('m/s²', 'м/с²')}", f"$B D$, {mm}"]
    else:
        header = ["№", "$φ$, °", f"$t$, {t('ms', 'мс')}", f"$S$, {mm}", f"$V$, {t('m/s', 'м/с')}",
                  f"$a$, {t('m/s²', 'м/с²')}", f"$B D$, {mm}", t("Phase", "Фаза")]
    rows = []
    for row in m.table:
        bd = abs(row.v_b_m_s if rocker else row.v) / m.omega * 1000
        if rocker:
            rows.append([str(row.index), n(row.phi_deg), n(row.t_s * 1000, decimals=2),
                         n(math.degrees(row.s), decimals=3), n(row.v, decimals=3), n(row.a, decimals=1),
                         n(row.s_b_m * 1000, decimals=2), n(row.v_b_m_s, decimals=3), n(row.a_b_m_s2, decimals=1),
                         n(bd, decimals=2)])
        else:
            rows.append([str(row.index), n(row.phi_deg), n(row.t_s * 1000, decimals=2), n(row.s * 1000, decimals=3),
                         n(row.v, decimals=3), n(row.a, decimals=1), n(bd, decimals=2), t(*_PHASE[row.phase])])
    align = ["center"] + ["right"] * (len(header) - 1 - (0 if rocker else 1)) + ([] if rocker else ["left"])
    widths = [0.55, 0.7, 0.9, 0.9, 1.0, 1.0, 1.0, 1.0, 1.0, 0.9] if rocker else [0.5, 0.65, 0.85, 1.0, 0.9, 1.0, 0.9, 1.55]
    c.table("cam_motion", t("Displacement, velocity and acceleration of the follower in the positions of the cam",
                            "Перемещение, скорость и ускорение толкателя в положениях кулачка"), header, rows, align=align,
            widths=widths)


# --------------------------------------------------------------------------------------------------
def _scales(c: Ctx, r) -> None:
    v, m = r.variant, r.motion
    s = m.scales
    t = c.t
    q = c.q
    rocker = v.is_rocker
    c.doc.add(_heading(c, 2, t("Scales of the diagrams", "Масштабы диаграмм")))
    c.p(t(f"On the sheet the working angle is drawn as a segment $b = {q(s.b_mm)}$ mm and the largest displacement as "
          f"an ordinate $Y_(S max) = {q(s.y_s_max_mm)}$ mm; the integration bases are $H_V = {q(s.h_v_mm)}$ mm and "
          f"$H_a = {q(s.h_a_mm)}$ mm, the largest round bases that keep the ordinates of the velocity and "
          "acceleration diagrams within 60 mm. The scales {cite:book:formulas (1.9)–(1.18)}:",
          f"На листе рабочий угол изображается отрезком $b = {q(s.b_mm)}$ мм, наибольшее перемещение — ординатой "
          f"$Y_(S max) = {q(s.y_s_max_mm)}$ мм; базы интегрирования $H_V = {q(s.h_v_mm)}$ мм и "
          f"$H_a = {q(s.h_a_mm)}$ мм — наибольшие круглые значения, при которых ординаты диаграмм скоростей и "
          "ускорений не превышают 60 мм. Масштабы {cite:book:формулы (1.9)–(1.18)}:"))
    deg_mm = t("°/mm", "°/мм")
    c.formula(c.calc('k_φ = φ_"р"/b', "{0}/{1}", [V(v.phi_working_deg, exact=True), V(s.b_mm, exact=True)],
                     V(s.k_phi_deg_mm, sig=4), deg_mm), where=["k_φ", "b"])
    c.formula(c.calc('k_t = φ_"р"/(6 |n_k| b)', "{0}/(6 dot {1} dot {2})",
                     [V(v.phi_working_deg, exact=True), V(abs(v.n_cam_rpm), exact=True), V(s.b_mm, exact=True)],
                     V(s.k_t_s_mm, sig=4), t("s/mm", "с/мм")), where=["k_t"])
    if rocker:
        c.formula(c.calc('k_(γ "°") = γ_max/Y_(γ max)', "{0}/{1}", [V(v.stroke, exact=True), V(s.y_s_max_mm, exact=True)],
                         V(s.k_gamma_deg_mm, sig=4), deg_mm), where=['k_(γ "°")', ("Y_(γ max)", c.glossary_text("Y_(γ max)"))])
        c.formula(c.calc('k_γ = k_(γ "°") π/180', "{0} dot π/180", [V(s.k_gamma_deg_mm, sig=4)],
                         V(s.k_s, sig=4), t("rad/mm", "рад/мм")), where=["k_γ"])
        c.formula(c.calc("k_ω = k_γ/(k_t H_V)", "{0}/({1} dot {2})", [V(s.k_s, sig=4), V(s.k_t_s_mm, sig=4), V(s.h_v_mm, exact=True)],
                         V(s.k_v, sig=4), t("rad/(s·mm)", "рад/(с·мм)")), where=["k_ω", "H_V"])
        c.formula(c.calc("k_ε = k_ω/(k_t H_a)", "{0}/({1} dot {2})", [V(s.k_v, sig=4), V(s.k_t_s_mm, sig=4), V(s.h_a_mm, exact=True)],
                         V(s.k_a, sig=4), t("rad/(s²·mm)", "рад/(с²·мм)")), where=["k_ε", "H_a"])
        c.p(t("The scales of the roller centre's displacement, velocity and acceleration {cite:book:formula (1.18)}:",
              "Масштабы перемещения, скорости и ускорения центра ролика {cite:book:формула (1.18)}:"))
        lb = v.l_bc_m
        c.formula(c.calc("k_S = k_γ l_(B C)", "{0} dot {1}", [V(s.k_s, sig=4), V(lb, exact=True)], V(s.k_s_b, sig=4),
                         t("m/mm", "м/мм")),
                  c.calc("k_V = k_ω l_(B C)", "{0} dot {1}", [V(s.k_v, sig=4), V(lb, exact=True)], V(s.k_v_b, sig=4),
                         t("m/(s·mm)", "м/(с·мм)")), where=["k_S", "k_V"])
        c.formula(c.calc("k_a = k_ε l_(B C)", "{0} dot {1}", [V(s.k_a, sig=4), V(lb, exact=True)], V(s.k_a_b, sig=4),
                         t("m/(s²·mm)", "м/(с²·мм)")), where=["k_a"])
    else:
        c.formula(c.calc("k_S = S_max/Y_(S max)", "{0}/{1}", [V(v.stroke, exact=True), V(s.y_s_max_mm, exact=True)],
                         V(s.k_s, sig=4), t("m/mm", "м/мм")), where=["k_S", "S_max", "Y_(S max)"])
        c.formula(c.calc("k_V = k_S/(k_t H_V)", "{0}/({1} dot {2})", [V(s.k_s, sig=4), V(s.k_t_s_mm, sig=4), V(s.h_v_mm, exact=True)],
                         V(s.k_v, sig=4), t("m/(s·mm)", "м/(с·мм)")), where=["k_V", "H_V"])
        c.formula(c.calc("k_a = k_V/(k_t H_a)", "{0}/({1} dot {2})", [V(s.k_v, sig=4), V(s.k_t_s_mm, sig=4), V(s.h_a_mm, exact=True)],
                         V(s.k_a, sig=4), t("m/(s²·mm)", "м/(с²·мм)")), where=["k_a", "H_a"])
    c.p(t("The largest ordinate of the acceleration diagram on the return follows from that on the rise "
          "{cite:book:formula (1.8)}:",
          "Наибольшая ордината диаграммы ускорений на возвращении связана с ординатой на удалении "
          "{cite:book:формула (1.8)}:"))
    c.formula(c.calc('Y_(a "в" max) = Y_(a "у" max) (φ_"у"/φ_"в")^2', "{0} dot ({1}/{2})^2",
                     [V(s.y_a_rise_max_mm, sig=4), V(v.phi_rise_deg, exact=True), V(v.phi_return_deg, exact=True)],
                     V(s.y_a_return_max_mm, sig=4), t("mm", "мм")), where=['Y_(a "в" max)', 'Y_(a "у" max)'])


# --------------------------------------------------------------------------------------------------
def _sizing(c: Ctx, r) -> None:
    v, z = r.variant, r.sizing
    t, n = c.t, c.n
    mm = t("mm", "мм")
    rocker = v.is_rocker
    c.doc.add(_heading(c, 2, t("Main dimensions of the mechanism", "Определение основных размеров механизма")))
    c.p(t("The main dimensions follow from the condition that limits the pressure angle {cite:book:formula (1.19)}",
          "Основные размеры механизма определяются из условия ограничения угла давления {cite:book:формула (1.19)}"))
    c.formula('ν_i <= ν_max < ν_"кр"', where=["ν_i", "ν_max", 'ν_"кр"'])
    closure = (t("The mechanism has force closure: on the return the spring presses the roller to the cam and the "
                 "cam does not drive the follower, so the condition is imposed on the rise only.",
                 "Механизм с силовым замыканием: на возвращении ролик прижимается к кулачку пружиной, кулачок "
                 "толкатель не ведёт, поэтому условие накладывается только на участок удаления.")
               if z.closure == "force" else
               t("The mechanism has form closure (a groove): the cam drives the follower both ways, so the condition "
                 "holds on the rise and on the return.",
                 "Механизм с геометрическим замыканием (паз): кулачок ведёт толкатель в обе стороны, поэтому "
                 "условие выполняется и на удалении, и на возвращении."))
    c.p(t("By the theorem on the position of the cam centre (§1.3 {cite:book}), in every position of the follower the "
          "segment $B_i D_i = V_(B i)/ω_k$ {cite:book:formula (1.20)} is laid off from the roller centre along its "
          "velocity turned by 90° in the sense of $ω_k$; the cam centre must lie inside the angle $2 ν_max$ with the "
          f"vertex $D_i$ whose bisector is opposite to the rise. {closure} The zone common to all positions (every "
          "0,2° of the cam angle) is the zone of admissible centres; the base radius is the distance from the centre "
          "to the initial position $B_0$ of the roller centre.",
          "По теореме о положении центра вращения кулачка (п. 1.3 {cite:book}) в каждом положении толкателя от "
          "центра ролика по вектору его скорости, повёрнутому на 90° в сторону $ω_k$, откладывается отрезок "
          "$B_i D_i = V_(B i)/ω_k$ {cite:book:формула (1.20)}; центр кулачка должен лежать внутри угла $2 ν_max$ с "
          f"вершиной в точке $D_i$, биссектриса которого направлена против удаления. {closure} Область, общая для "
          "всех положений (через 0,2° угла поворота кулачка), — зона допустимого расположения центра; радиус "
          "основной окружности равен расстоянию от центра до начального положения $B_0$ центра ролика."))
    if rocker:
        _swing(c, r)
    own = r.own
    geometry_given = r.choice is not None and any(x is not None for x in (r.choice.r0_mm, r.choice.offset_mm, r.choice.l_oc_mm))
    student = r.source == "student" and geometry_given and own is not None
    r0 = z.r0_m * 1000
    book_r0 = z.book_r0_m * 1000
    if student:
        ch = r.choice
        given = []
        if ch.r0_mm is not None:
            given.append("$r_0$")
        if ch.offset_mm is not None:
            given.append("$e$")
        if ch.l_oc_mm is not None:
            given.append("$l_(O C)$")
        own_geo = (t(f", $l_(O C) = {c.q(own.l_oc_m * 1000, decimals=2)}$ mm", f", $l_(O C) = {c.q(own.l_oc_m * 1000, decimals=2)}$ мм")
                   if rocker else t(f", $e = {c.q(own.e_m * 1000, decimals=2)}$ mm", f", $e = {c.q(own.e_m * 1000, decimals=2)}$ мм"))
        c.p(t(f"The designer sets {' and '.join(given)}; the other dimensions follow from them. The point of the zone "
              f"nearest to $B_0$ would give $r_0 = {c.q(own.r0_m * 1000, decimals=2)}$ mm{own_geo}.",
              f"Конструктором заданы {' и '.join(given)}; остальные размеры получены из них. Ближайшая к $B_0$ "
              f"точка зоны дала бы $r_0 = {c.q(own.r0_m * 1000, decimals=2)}$ мм{own_geo}."))
        c.doc.claim(kind="cam_student", r0_mm=r0, own_r0_mm=own.r0_m * 1000)
    elif r.pivot_move == "centre":
        r0_min = (z.r0_min_m or z.r0_m) * 1000
        c.p(t(f"The point of the zone nearest to $B_0$ gives $r_0 = {c.q(r0_min, decimals=2)}$ mm, but there the cam "
              f"body reaches the rocker's pivot C; the centre is moved along the zone to the nearest point at which the "
              f"cam clears the pivot, $r_0 = {c.q(r0, decimals=2)}$ mm.",
              f"Ближайшая к $B_0$ точка зоны даёт $r_0 = {c.q(r0_min, decimals=2)}$ мм, но при ней тело кулачка "
              f"задевает ось коромысла C; центр перенесён по зоне в ближайшую точку, при которой кулачок не задевает "
              f"ось, $r_0 = {c.q(r0, decimals=2)}$ мм."))
        c.doc.claim(kind="cam_centre_moved", r0_mm=r0, r0_min_mm=r0_min)
    else:
        c.p(t(f"The cam centre is taken at the point of the zone nearest to $B_0$, which gives the smallest cam"
              + (" for this swing" if rocker else "") + f": $r_0 = {c.q(r0, decimals=2)}$ mm.",
              f"Центр кулачка принимаем в ближайшей к $B_0$ точке зоны, что даёт наименьший кулачок"
              + (" при этом направлении качания" if rocker else "") + f": $r_0 = {c.q(r0, decimals=2)}$ мм."))
        c.doc.claim(kind="cam_centre_nearest", r0_mm=r0)
    # the book's vertex beside the taken centre
    if not student:
        base = (z.r0_min_m or z.r0_m) * 1000
        diff = (book_r0 / base - 1) * 100
        if n(book_r0, decimals=2) == n(base, decimals=2):
            cmp = t("The construction of the textbook (the vertex where its two bounding lines meet) gives the same "
                    "point.", "Построение пособия (точка пересечения двух ограничивающих прямых) даёт ту же точку.")
        elif abs(diff) < 0.1:
            cmp = t(f"The construction of the textbook (the vertex where its two bounding lines meet) gives "
                    f"$r_0 = {c.q(book_r0, decimals=2)}$ mm: the two differ by less than 0,1 %, within the step of "
                    "the construction.",
                    f"Построение пособия (точка пересечения двух ограничивающих прямых) даёт $r_0 = "
                    f"{c.q(book_r0, decimals=2)}$ мм; решения отличаются менее чем на 0,1 % — в пределах точности "
                    "построения.")
        else:
            more = diff > 0
            cmp = t(f"The construction of the textbook (the vertex where its two bounding lines meet) gives "
                    f"$r_0 = {c.q(book_r0, decimals=2)}$ mm, {c.pct(abs(diff))} {'larger' if more else 'smaller'}",
                    f"Построение пособия (точка пересечения двух ограничивающих прямых) даёт $r_0 = "
                    f"{c.q(book_r0, decimals=2)}$ мм — на {c.pct(abs(diff))} {'больше' if more else 'меньше'}")
            book_nu = z.book_nu_rise_max_deg if z.closure == "force" else max(z.book_nu_rise_max_deg, z.book_nu_return_max_deg)
            if book_nu > v.nu_max_deg + 0.05:
                cmp += t(f", and there the pressure angle reaches {n(book_nu, decimals=2)}° > $ν_max$: the bounding "
                         "lines of the textbook turn with the follower and do not bound the zone exactly.",
                         f", причём угол давления там достигает {n(book_nu, decimals=2)}° > $ν_max$: ограничивающие "
                         "прямые пособия поворачиваются вместе с толкателем и не ограничивают зону точно.")
            else:
                cmp += "."
        c.p(cmp)
        c.doc.claim(kind="cam_book_vertex", r0_mm=base, book_r0_mm=book_r0, diff_pct=diff)
    c.p(t("The main dimensions are", "Основные размеры механизма:"))
    if rocker:
        c.formula(f"r_0 = {c.q(r0, decimals=2)} {c.u(mm)}", f"l_(O C) = {c.q(z.l_oc_m * 1000, decimals=2)} {c.u(mm)}",
                  where=["r_0", "l_(O C)"])
    else:
        c.formula(f"r_0 = {c.q(r0, decimals=2)} {c.u(mm)}", f"e = {c.q(z.e_m * 1000, decimals=2)} {c.u(mm)}",
                  where=["r_0", ("e", t("the offset of the follower axis from the cam centre (e > 0: to the right "
                                         "of the centre, the follower above the cam), mm",
                                         "эксцентриситет: смещение оси толкателя от центра кулачка (e > 0 — вправо "
                                         "от центра при толкателе над кулачком), мм"))])
    ch = r.checks
    rows = [["$r_0$, " + mm, n(r0, decimals=2), n(book_r0, decimals=2)]]
    if rocker:
        rows.append(["$l_(O C)$, " + mm, n(z.l_oc_m * 1000, decimals=2), n(z.book_l_oc_m * 1000, decimals=2)])
    else:
        rows.append(["$e$, " + mm, n(z.e_m * 1000, decimals=2), n(z.book_e_m * 1000, decimals=2)])
    rows.append([t("largest $ν$ on the rise, °", "наибольший $ν$ на удалении, °"), n(ch.nu_rise_deg, decimals=2),
                 n(z.book_nu_rise_max_deg, decimals=2)])
    rows.append([t("largest $ν$ on the return, °", "наибольший $ν$ на возвращении, °"), n(ch.nu_return_deg, decimals=2),
                 n(z.book_nu_return_max_deg, decimals=2)])
    taken = t("Taken", "Принято")
    c.p(t("They are compared with the construction of the textbook in Table {tab:cam_dims}",
          "Сравнение с построением пособия дано в таблице {tab:cam_dims}")
        + c.if_fig("cam_zone", t("; the zone is shown in Figure {fig:cam_zone}", ", зона допустимого расположения "
                                 "центра показана на рисунке {fig:cam_zone}")) + ".")
    c.table("cam_dims", t("Main dimensions of the cam mechanism", "Основные размеры кулачкового механизма"),
            [t("Quantity", "Величина"), taken, t("Construction of the textbook", "Построение пособия")], rows,
            align=["left", "center", "center"], widths=[2, 1, 1.3])
    c.fig("cam_zone", t("Zone of admissible positions of the cam centre", "Зона допустимого расположения центра кулачка"))


def _swing(c: Ctx, r) -> None:
    """Which way the rocker turns on the rise, and why (the decision of cam/design.py)."""
    z = r.sizing
    t = c.t
    sense = {"same": t("the same way as the cam", "в ту же сторону, что и кулачок"),
             "opposite": t("against the cam", "в сторону, противоположную вращению кулачка")}
    r0 = z.r0_m * 1000
    if r.source == "student" and r.choice.swing is not None:
        c.p(t(f"On the rise the rocker turns {sense[z.swing]}, as the designer chose.",
              f"При удалении коромысло поворачивается {sense[z.swing]} — по выбору конструктора."))
        return
    pc = r.pivot_conflict
    if pc is not None and r.pivot_move == "swing":
        c.p(t(f"The rocker may turn on the rise either way. Turning {sense[pc.swing]} it needs the smaller cam, "
              f"$r_0 = {c.q(pc.r0_m * 1000, decimals=2)}$ mm, but then the cam body (radius "
              f"{c.qty(pc.body_m * 1000, 'mm', decimals=2)}) reaches the rocker's pivot C "
              f"($l_(O C) = {c.q(pc.l_oc_m * 1000, decimals=2)}$ mm). Therefore the rocker is made to turn "
              f"{sense[z.swing]}: $r_0 = {c.q(r0, decimals=2)}$ mm, and the cam clears the pivot.",
              f"Коромысло может поворачиваться при удалении в любую сторону. При повороте {sense[pc.swing]} "
              f"кулачок получается меньше, $r_0 = {c.q(pc.r0_m * 1000, decimals=2)}$ мм, но тогда тело кулачка "
              f"(радиус {c.qty(pc.body_m * 1000, 'мм', decimals=2)}) задевает ось коромысла C "
              f"($l_(O C) = {c.q(pc.l_oc_m * 1000, decimals=2)}$ мм). Поэтому принимаем поворот коромысла "
              f"{sense[z.swing]}: $r_0 = {c.q(r0, decimals=2)}$ мм, и кулачок не задевает ось."))
        c.doc.claim(kind="cam_swing_pivot", carried_r0_mm=r0, rejected_r0_mm=pc.r0_m * 1000,
                    rejected_l_oc_mm=pc.l_oc_m * 1000, rejected_body_mm=pc.body_m * 1000)
        return
    other = z.r0_other_swing_m
    if other is None:
        return
    o = other * 1000
    if c.n(o, decimals=2) == c.n(r0, decimals=2):
        c.p(t(f"On the rise the rocker turns {sense[z.swing]}; the other sense needs the same cam "
              f"($r_0 = {c.q(o, decimals=2)}$ mm): the mechanism is symmetric.",
              f"При удалении коромысло поворачивается {sense[z.swing]}; при обратном направлении кулачок тот же "
              f"($r_0 = {c.q(o, decimals=2)}$ мм): механизм симметричен."))
    else:
        c.p(t(f"On the rise the rocker turns {sense[z.swing]}: the other sense would need a larger cam, "
              f"$r_0 = {c.q(o, decimals=2)}$ mm ({c.pct((o / r0 - 1) * 100)} more).",
              f"При удалении коромысло поворачивается {sense[z.swing]}: при обратном направлении потребовался бы "
              f"больший кулачок, $r_0 = {c.q(o, decimals=2)}$ мм (на {c.pct((o / r0 - 1) * 100)} больше)."))
    c.doc.claim(kind="cam_swing_smaller", carried_r0_mm=r0, other_r0_mm=o)


# --------------------------------------------------------------------------------------------------
def _profile(c: Ctx, r) -> None:
    v, z, p, d = r.variant, r.sizing, r.profile, r.drawing
    t, n = c.t, c.n
    mm = t("mm", "мм")
    c.doc.add(_heading(c, 2, t("Profile of the cam", "Построение профиля кулачка")))
    c.p(t("The profile is built by inversion (§1.4 {cite:book}): the cam is held still and the frame with the follower "
          "is turned about the cam centre against the cam's rotation; the roller centre then traces the pitch "
          "(theoretical) profile, and the working profile is the envelope of the roller's circles.",
          "Профиль кулачка строится методом обращения движения (п. 1.4 {cite:book}): кулачок считается "
          "неподвижным, а стойка с толкателем поворачивается вокруг центра кулачка в сторону, противоположную его "
          "вращению; центр ролика при этом описывает теоретический профиль, а действительный профиль — огибающая "
          "окружностей ролика."))
    w, h = d.extent_mm
    c.p(t(f"The profile is drawn at the scale {d.scale} ($k_(S k) = {c.q(d.k_sk, sig=4)}$ m/mm, Table 1.1 "
          f"{{cite:book}}): the largest scale of the standard series at which the cam with its roller "
          f"({c.qty(w, 'mm', decimals=1)} × {c.qty(h, 'mm', decimals=1)}) fits the field of "
          f"{c.qty(d.field_mm, 'mm', decimals=0)} × {c.qty(d.field_mm, 'mm', decimals=0)} of the sheet. The scale of the "
          "sizing construction is taken equal to that of the displacement diagram, $k'_S = k_S$; the lengths are "
          "converted {cite:book:formulas (1.26), (1.27)}:",
          f"Профиль вычерчивается в масштабе {d.scale} ($k_(S k) = {c.q(d.k_sk, sig=4)}$ м/мм, таблица 1.1 "
          f"{{cite:book}}) — наибольшем стандартном масштабе, при котором кулачок с роликом "
          f"({c.qty(w, 'мм', decimals=1)} × {c.qty(h, 'мм', decimals=1)}) помещается в поле листа "
          f"{c.qty(d.field_mm, 'мм', decimals=0)} × {c.qty(d.field_mm, 'мм', decimals=0)}. Масштаб построения "
          "основных размеров принят равным масштабу диаграммы перемещений, $k'_S = k_S$; отрезки пересчитываются "
          "по формулам {cite:book:формулы (1.26), (1.27)}:"))
    c.doc.claim(kind="cam_drawing_scale", scale=d.scale, fits=d.fits, width_mm=w, height_mm=h, field_mm=d.field_mm)
    st = d.size("stroke")
    r0s = d.size("r0")
    c.formula(c.calc("y_(S i k) = k_S/k_(S k) y_(S i)", "{0}/{1} dot {2}",
                     [V(d.k_s, sig=4), V(d.k_sk, sig=4), V(st.at_k_s_mm, sig=4)], V(st.drawn_mm, sig=4), mm),
              where=["y_(S i k)", "y_(S i)", "k_(S k)"])
    c.formula(c.calc("x_(i k) = (k'_S)/k_(S k) x_i", "{0} dot {1}",
                     [V(d.k_s_prime / d.k_sk, sig=4), V(r0s.at_k_s_mm, sig=4)], V(r0s.drawn_mm, sig=4), mm),
              where=["x_(i k)", "k'_S", "x_i"])
    c.p(t("(in the first, the largest displacement; in the second, the base radius $r_0$).",
          "(в первой — наибольшее перемещение, во второй — радиус $r_0$)."), indent=False)
    c.p(t("The profile angles differ from the phase angles when the follower axis is offset and for a rocker; they "
          "are measured on the profile and checked {cite:book:formulas (1.1), (1.2), (1.4)}:",
          "Профильные углы отличаются от фазовых при смещённой оси толкателя и у коромысла; они измеряются по "
          "профилю и проверяются по формулам {cite:book:формулы (1.1), (1.2), (1.4)}:"))
    c.formula(c.calc('ψ_"у" + ψ_"дс" + ψ_"в" + ψ_"бс"', "{0} + {1} + {2} + {3}",
                     [V(p.psi_rise_deg, decimals=2, deg=True), V(abs(p.psi_far_deg), decimals=2, deg=True),
                      V(p.psi_return_deg, decimals=2, deg=True), V(p.psi_near_deg, decimals=2, deg=True)],
                     V(360, exact=True, deg=True)))
    c.formula(c.calc('ψ_"р" = ψ_"у" + ψ_"дс" + ψ_"в"', "{0} + {1} + {2}",
                     [V(p.psi_rise_deg, decimals=2, deg=True), V(abs(p.psi_far_deg), decimals=2, deg=True),
                      V(p.psi_return_deg, decimals=2, deg=True)], V(p.psi_working_deg, decimals=2, deg=True))
              + f' = φ_"р" = {c.qd(v.phi_working_deg)}', where=['ψ_"р"'])
    _roller(c, r)
    if c.has("cam_profile"):
        c.p(t("The profile with the pitch curve, the base circle and the positions of the follower in the inverted "
              "motion is shown in Figure {fig:cam_profile}.",
              "Профиль кулачка с теоретическим профилем, окружностью радиуса $r_0$ и положениями толкателя в "
              "обращённом движении показан на рисунке {fig:cam_profile}."))
    c.fig("cam_profile", t("Profile of the cam", "Профиль кулачка"))


def _roller(c: Ctx, r) -> None:
    z, p = r.sizing, r.profile
    t = c.t
    mm = t("mm", "мм")
    rho = p.roller_max_m * 1000
    book = p.roller_book_m * 1000
    roller = p.roller_m * 1000
    r0 = z.r0_m * 1000
    concave = z.closure == "form" and p.rho_min_concave_m is not None and p.rho_min_concave_m * 1000 <= rho + 1e-9
    where_rho = (t("of the concave side of the groove", "вогнутой стороны паза") if concave else
                 t("of the convex part of the pitch profile", "выпуклой части теоретического профиля"))
    c.p(t("The roller radius by the textbook's rule {cite:book:formula (1.28)}:",
          "Радиус ролика по рекомендации пособия {cite:book:формула (1.28)}:"))
    c.formula(c.calc('r_"р" = "0,2" r_0', '{0} dot {1}', [V(0.2, exact=True), V(r0, decimals=2)], V(book, decimals=2), mm),
              where=['r_"р"'])
    rule = p.roller_rule
    if rule == "book":
        c.p(t(f"The roller must be smaller than the smallest radius of curvature {where_rho}, "
              f"$ρ_min = {c.q(rho, decimals=2)}$ mm, or the working profile is undercut; "
              f"$r_\"р\" = {c.q(roller, decimals=2)} < ρ_min$, so the roller of the textbook is taken and the profile "
              "is not undercut.",
              f"Радиус ролика должен быть меньше наименьшего радиуса кривизны {where_rho} "
              f"$ρ_min = {c.q(rho, decimals=2)}$ мм, иначе действительный профиль получится подрезанным; "
              f"$r_\"р\" = {c.q(roller, decimals=2)} < ρ_min$, поэтому принимаем ролик по рекомендации пособия, "
              "подреза нет."))
    elif rule == "limited":
        c.p(t(f"The roller must be smaller than the smallest radius of curvature {where_rho}, "
              f"$ρ_min = {c.q(rho, decimals=2)}$ mm, or the working profile is undercut. The textbook's roller "
              f"{'reaches' if book >= rho else 'comes within 20 % of'} it, so the roller is reduced to 0,8 $ρ_min$:",
              f"Радиус ролика должен быть меньше наименьшего радиуса кривизны {where_rho} "
              f"$ρ_min = {c.q(rho, decimals=2)}$ мм, иначе действительный профиль получится подрезанным. Ролик по "
              f"рекомендации пособия {'не меньше' if book >= rho else 'ближе чем на 20 % к'} этого значения, "
              "поэтому радиус ролика уменьшаем до 0,8 $ρ_min$:"))
        c.formula(c.calc('r_"р" = "0,8" ρ_min', "{0} dot {1}", [V(0.8, exact=True), V(rho, decimals=2)],
                         V(roller, decimals=2), mm), where=["ρ_min"])
        fix = r.book_roller_fix
        if fix is not None:
            geo = (f"l_(O C) = {c.q(fix.l_oc_m * 1000, decimals=2)}" if r.variant.is_rocker
                   else f"e = {c.q(fix.e_m * 1000, decimals=2)}")
            c.p(t(f"The textbook's roller could be kept with a larger cam, $r_0 = {c.q(fix.r0_m * 1000, decimals=2)}$ mm, "
                  f"${geo}$ mm; the smaller roller keeps the smallest cam.",
                  f"Ролик по рекомендации пособия можно сохранить, увеличив кулачок до $r_0 = "
                  f"{c.q(fix.r0_m * 1000, decimals=2)}$ мм, ${geo}$ мм; меньший ролик сохраняет наименьший кулачок."))
    else:
        ok = roller < rho
        c.p(t(f"The designer takes the roller $r_\"р\" = {c.q(roller, decimals=2)}$ mm. The smallest radius of "
              f"curvature {where_rho} is $ρ_min = {c.q(rho, decimals=2)}$ mm: "
              + ("the roller is smaller, the profile is not undercut." if ok else
                 "the roller is not smaller, the working profile is undercut."),
              f"Конструктор принимает ролик $r_\"р\" = {c.q(roller, decimals=2)}$ мм. Наименьший радиус кривизны "
              f"{where_rho} $ρ_min = {c.q(rho, decimals=2)}$ мм: "
              + ("ролик меньше, подреза нет." if ok else "ролик не меньше, действительный профиль подрезан.")))
    c.doc.claim(kind="cam_roller", rule=rule, roller_mm=roller, book_mm=book, rho_mm=rho)
    c.p(t(f"Here $r_0$ is the base radius of the pitch profile; the smallest radius of the working profile is "
          f"$r_0 - r_\"р\" = {c.q(p.working_min_radius_m * 1000, decimals=2)}$ mm; the far-dwell radius of the pitch "
          f"profile is {c.qty(p.r_far_m * 1000, mm, decimals=2)}.",
          f"Здесь $r_0$ — радиус основной окружности теоретического профиля; наименьший радиус действительного "
          f"профиля $r_0 - r_\"р\" = {c.q(p.working_min_radius_m * 1000, decimals=2)}$ мм, радиус дальнего стояния "
          f"теоретического профиля {c.qty(p.r_far_m * 1000, mm, decimals=2)}."))


# --------------------------------------------------------------------------------------------------
def _pressure(c: Ctx, r) -> None:
    v, z, ch = r.variant, r.sizing, r.checks
    t, n = c.t, c.n
    c.doc.add(_heading(c, 2, t("Pressure angle over the cycle", "Проверка угла давления")))
    rise_ok = ch.nu_rise_ok
    sign = "≤" if rise_ok else ">"
    rise = t(f"on the rise the pressure angle reaches {n(ch.nu_rise_deg, decimals=2)}° {sign} $ν_max$ = "
             f"{n(v.nu_max_deg)}°", f"на удалении угол давления достигает {n(ch.nu_rise_deg, decimals=2)}° {sign} "
             f"$ν_max$ = {n(v.nu_max_deg)}°")
    if z.closure == "force":
        ret = t(f"on the return the spring drives the follower and the pressure angle is not limited (it reaches "
                f"{n(ch.nu_return_deg, decimals=1)}°)", f"на возвращении толкатель движется под действием пружины, "
                f"угол давления не ограничивается (достигает {n(ch.nu_return_deg, decimals=1)}°)")
    else:
        sign2 = "≤" if ch.nu_return_ok else ">"
        ret = t(f"on the return it reaches {n(ch.nu_return_deg, decimals=2)}° {sign2} $ν_max$",
                f"на возвращении — {n(ch.nu_return_deg, decimals=2)}° {sign2} $ν_max$")
    verdict = (t("The condition (1.19) holds.", "Условие ограничения угла давления выполняется.")
               if rise_ok and ch.nu_return_ok else
               t("The condition is not met.", "Условие ограничения угла давления не выполняется."))
    fig = c.if_fig("cam_pressure_angle", t(" (Figure {fig:cam_pressure_angle})", " (рисунок {fig:cam_pressure_angle})"))
    c.p(t(f"With the centre taken, {rise}; {ret}{fig}. {verdict}",
          f"При принятом положении центра кулачка {rise}; {ret}{fig}. {verdict}"))
    c.doc.claim(kind="cam_pressure", nu_rise=ch.nu_rise_deg, nu_return=ch.nu_return_deg, nu_max=v.nu_max_deg,
                limited_return=z.closure == "form", ok=rise_ok and ch.nu_return_ok)
    c.fig("cam_pressure_angle", t("Pressure angle against the cam angle", "Угол давления в функции угла поворота кулачка"))
