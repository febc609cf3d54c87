"""Section 1 of the note: the cam mechanism (sheet 3, book section 1), from a CamResult."""

from __future__ import annotations

import math

from ...cam.laws import law_impacts, law_max
from ..terminal.variants import law_words, scheme_words
from .ctx import Ctx

_PHASE = {"rise": ("rise", "удаление"), "far_dwell": ("far dwell", "дальнее стояние"),
          "return": ("return", "возвращение"), "near_dwell": ("near dwell", "ближнее стояние")}

_LAW_F = {
    1: ['f(t) = 2t^2 "  при " 0 <= t <= 1/2;', 'f(t) = 1 - 2(1 - t)^2 "  при " 1/2 < t <= 1'],
    2: ["f(t) = 3t^2 - 2t^3"],
    3: ["f(t) = (1 - cos π t)/2"],
    4: ["f(t) = t - sin(2π t)/(2π)"],
}


def cam_section(c: Ctx) -> None:
    r = c.r.cam
    v, m, z, p, d = r.variant, r.motion, r.sizing, r.profile, r.drawing
    t, n, q = c.t, c.n, c.q
    rocker = v.is_rocker
    mm = t("mm", "мм")
    doc = c.doc
    doc.h(1, t("Synthesis of the cam mechanism", "Синтез кулачкового механизма"))

    # 1.1 input ------------------------------------------------------------------------------
    doc.h(2, t("Input data", "Исходные данные"))
    doc.p(t(f"The input data are row {v.number} of Table 1.2 of the textbook [1]; they are listed in Table {{tab:cam_input}}. "
            "Fig. 1.8 of the textbook (the schemes) is read as stated in the table.",
            f"Исходные данные — строка {v.number} таблицы 1.2 пособия [1]; они приведены в таблице {{tab:cam_input}} "
            "с расшифровкой обозначений."))
    rows = [
        [t("Scheme of the mechanism", "Схема механизма"), str(v.scheme), scheme_words(v.scheme, c.lang)],
        [t("Acceleration law", "Закон изменения ускорения"), str(v.law),
         law_words(v.law, c.lang) + "; " + (t("soft impacts", "мягкие удары") if law_impacts(v.law) == "soft"
                                            else t("no impacts", "без ударов"))],
    ]
    if rocker:
        rows += [["$γ_max$, °", n(v.stroke), t("rocker swing", "угол качания коромысла")],
                 [f"$l_(B C)$, {mm}", n(v.l_bc_m * 1000), t("rocker length", "длина коромысла")]]
    else:
        rows += [[f"$S_max$, {mm}", n(v.stroke * 1000), t("follower stroke", "ход толкателя")]]
    rows += [
        ["$ν_max$, °", n(v.nu_max_deg), t("allowed pressure angle", "допустимый угол давления")],
        [f"$n_k$, {t('rpm', 'об/мин')}", n(v.n_cam_rpm),
         t("cam speed; ", "частота вращения кулачка; ")
         + (t("counter-clockwise (n > 0)", "против часовой стрелки (n > 0)") if v.ccw
            else t("clockwise (n < 0)", "по часовой стрелке (n < 0)"))],
        ['$φ_"у"$, °', n(v.phi_rise_deg), t("rise angle", "угол удаления")],
        ['$φ_"дс"$, °', n(v.phi_far_dwell_deg), t("far-dwell angle", "угол дальнего стояния")],
        ['$φ_"в"$, °', n(v.phi_return_deg), t("return angle", "угол возвращения")],
    ]
    doc.table("cam_input", t(f"Input data of variant {v.number}", f"Исходные данные варианта {v.number}"),
              [t("Quantity", "Величина"), t("Value", "Значение"), t("Meaning", "Содержание")], rows,
              align="left, center, left", widths=["auto", "auto", "1fr"])
    doc.p(t("The working angle of the cam and the near-dwell angle:", "Рабочий угол кулачка и угол ближнего стояния:"))
    doc.formula(f'φ_"р" = φ_"у" + φ_"дс" + φ_"в" = {q(v.phi_rise_deg)} + {q(v.phi_far_dwell_deg)} + '
                f'{q(v.phi_return_deg)} = {c.qd(v.phi_working_deg)}', "1.3")
    doc.formula(f'φ_"бс" = 360 degree - φ_"р" = "360°" - {c.qd(v.phi_working_deg)} = {c.qd(v.phi_near_dwell_deg)}', None)
    doc.p(t("The angular speed of the cam and the time of one turn:", "Угловая скорость кулачка и время одного оборота:"))
    doc.formula(f"ω_k = (π |n_k|)/30 = (π dot {q(abs(v.n_cam_rpm))})/30 = {q(m.omega, sig=5)} {c.u(t('rad/s', 'рад/с'))}", "1.5")
    doc.formula(f"T = 60/(|n_k|) = 60/{q(abs(v.n_cam_rpm))} = {q(m.period_s, sig=4)} {c.u(t('s', 'с'))}", None)

    # 1.2 motion law ---------------------------------------------------------------------------
    doc.h(2, t("Motion law of the follower", "Закон движения толкателя"))
    h_sym = "γ_max" if rocker else "S_max"
    h_val = q(math.radians(v.stroke), sig=4) + " " + c.u(t("rad", "рад")) if rocker else q(v.stroke, sig=4) + " " + c.u(t("m", "м"))
    doc.p(t(f"The follower moves by the law of {law_words(v.law, c.lang)} (Fig. 1.9 of [1]), the same on the rise and "
            "the return. As a share of the stroke, against the share $t$ of the phase angle, the displacement is",
            f"Толкатель движется по закону: {law_words(v.law, c.lang)} (рис. 1.9 [1]), одинаковому на удалении и "
            "возвращении. При относительном угле поворота $t$ на фазе перемещение толкателя в долях хода равно"))
    for line in _LAW_F[v.law]:
        doc.formula(line.replace('"  при "', '"  ' + t("for", "при") + ' "'), None)
    doc.p(t(f"The displacement on the rise is $s = {h_sym} dot f(φ/φ_\"у\")$ and on the return "
            f"$s = {h_sym} dot (1 - f((φ - φ_\"у\" - φ_\"дс\")/φ_\"в\"))$; the follower "
            + ("turns" if rocker else "moves") + " with the cam's constant speed, so $V = ω_k dot d s\\/d φ$, "
            "$a = ω_k^2 dot d^2 s\\/d φ^2$.",
            f"Перемещение на удалении $s = {h_sym} dot f(φ/φ_\"у\")$, на возвращении "
            f"$s = {h_sym} dot (1 - f((φ - φ_\"у\" - φ_\"дс\")/φ_\"в\"))$; кулачок вращается равномерно, поэтому "
            "$V = ω_k dot d s\\/d φ$, $a = ω_k^2 dot d^2 s\\/d φ^2$."))
    f1, f2, _ = law_max(v.law)
    mx = m.maxima
    vu = t("rad/s", "рад/с") if rocker else t("m/s", "м/с")
    au = t("rad/s²", "рад/с²") if rocker else t("m/s²", "м/с²")
    vs, as_ = ("ω", "ε") if rocker else ("V", "a")
    doc.p(t(f"With $f'_max = {q(f1, sig=4)}$ and $f''_max = {q(f2, sig=4)}$ of this law and $h = {h_sym} = {h_val}$, "
            "the largest velocity and acceleration on the rise are",
            f"Для этого закона $f'_max = {q(f1, sig=4)}$, $f''_max = {q(f2, sig=4)}$; при $h = {h_sym} = {h_val}$ "
            "наибольшие скорость и ускорение на удалении равны"))
    h_num = math.radians(v.stroke) if rocker else v.stroke
    phr = math.radians(v.phi_rise_deg)
    doc.formula(f'{vs}_("у" max) = (f\'_max dot h dot ω_k)/φ_"у" = ({q(f1, sig=4)} dot {q(h_num, sig=4)} dot '
                f'{q(m.omega, sig=5)})/{q(phr, sig=4)} = {q(mx.v_rise_max, sig=4)} {c.u(vu)}', None)
    a_rise = max(abs(mx.a_rise_max), abs(mx.a_rise_min))
    a_ret = max(abs(mx.a_return_max), abs(mx.a_return_min))
    doc.formula(f'{as_}_("у" max) = (f\'\'_max dot h dot ω_k^2)/φ_"у"^2 = ({q(f2, sig=4)} dot {q(h_num, sig=4)} dot '
                f'{q(m.omega, sig=5)}^2)/{q(phr, sig=4)}^2 = {q(a_rise, sig=4)} {c.u(au)}', None)
    doc.p(t("The accelerations on the return and on the rise are in the ratio (1.7):",
            "Отношение наибольших ускорений на возвращении и удалении — по (1.7):"))
    doc.formula(f'abs({as_}_("в" max)/{as_}_("у" max)) = {q(a_ret, sig=4)}/{q(a_rise, sig=4)} = '
                f'(φ_"у"/φ_"в")^2 = ({q(v.phi_rise_deg)}/{q(v.phi_return_deg)})^2 = {q(mx.accel_ratio_book, sig=4)}', "1.7")
    if rocker:
        lb = v.l_bc_m
        doc.p(t("The roller centre B moves along an arc of radius $l_(B C)$; its displacement, velocity and "
                "acceleration follow from the rocker's by (1.6):",
                "Центр ролика B движется по дуге радиусом $l_(B C)$; его перемещение, скорость и ускорение "
                "находятся по (1.6):"))
        doc.formula(f'S_(B max) = γ_max l_(B C) = {q(h_num, sig=4)} dot {q(lb, sig=4)} = {q(h_num * lb * 1000, sig=4)} {c.u(mm)};'
                    f' quad V_(B max) = ω_max l_(B C) = {q(mx.v_rise_max, sig=4)} dot {q(lb, sig=4)} = '
                    f'{q(mx.v_rise_max * lb, sig=4)} {c.u(t("m/s", "м/с"))}', "1.6")
    doc.p(t(f"The diagrams of the follower's motion are shown in Figure {{fig:cam_motion}}, the values at the positions "
            f"of the cam in Table {{tab:cam_motion}} (step {n(m.table_step_rise_deg)}° on the rise and "
            f"{n(m.table_step_return_deg)}° on the return, §1.2 of [1]).",
            f"Диаграммы движения толкателя показаны на рисунке {{fig:cam_motion}}, значения в положениях кулачка "
            f"приведены в таблице {{tab:cam_motion}} (шаг {n(m.table_step_rise_deg)}° на удалении и "
            f"{n(m.table_step_return_deg)}° на возвращении, п. 1.2 [1]). Отрезки $B_i D_i = V_(B i)\\/ω_k$ "
            "откладываются при определении основных размеров (1.20)."))
    c.fig("cam_motion", t("Diagrams of the follower's displacement, velocity and acceleration",
                          "Диаграммы перемещения, скорости и ускорения толкателя"))
    _motion_table(c)

    # 1.3 scales ------------------------------------------------------------------------------
    s = m.scales
    doc.h(2, t("Scales of the diagrams", "Масштабы диаграмм"))
    doc.p(t(f"The working angle is drawn as $b = {q(s.b_mm)}$ mm, the largest displacement as "
            f"$Y_(S max) = {q(s.y_s_max_mm)}$ mm; the integration bases are $H_V = {q(s.h_v_mm)}$ mm and "
            f"$H_a = {q(s.h_a_mm)}$ mm (the largest round bases keeping the ordinates within 60 mm).",
            f"Рабочий угол изображается отрезком $b = {q(s.b_mm)}$ мм, наибольшее перемещение — ординатой "
            f"$Y_(S max) = {q(s.y_s_max_mm)}$ мм; базы интегрирования $H_V = {q(s.h_v_mm)}$ мм и "
            f"$H_a = {q(s.h_a_mm)}$ мм (наибольшие круглые базы, при которых ординаты не превышают 60 мм)."))
    deg_mm = t('"°/mm"', '"°/мм"')
    doc.formula(f'k_φ = φ_"р"/b = {q(v.phi_working_deg)}/{q(s.b_mm)} = {q(s.k_phi_deg_mm, sig=4)} thin {deg_mm}', "1.9")
    doc.formula(f'k_t = φ_"р"/(6 |n_k| b) = {q(v.phi_working_deg)}/(6 dot {q(abs(v.n_cam_rpm))} dot {q(s.b_mm)}) = '
                f'{q(s.k_t_s_mm, sig=4)} {c.u(t("s/mm", "с/мм"))}', "1.10")
    if rocker:
        doc.formula(f'k_(γ "{t("deg", "град")}") = γ_max/Y_(γ max) = {q(v.stroke)}/{q(s.y_s_max_mm)} = '
                    f'{q(s.k_gamma_deg_mm, sig=4)} thin {deg_mm}', "1.14")
        doc.formula(f'k_(γ "{t("rad", "рад")}") = k_(γ "{t("deg", "град")}") π/180 = {q(s.k_gamma_deg_mm, sig=4)} dot π/180 = '
                    f'{q(s.k_s, sig=4)} {c.u(t("rad/mm", "рад/мм"))}', "1.15")
        doc.formula(f'k_ω = k_(γ "{t("rad", "рад")}")/(k_t H_V) = {q(s.k_s, sig=4)}/({q(s.k_t_s_mm, sig=4)} dot {q(s.h_v_mm)}) = '
                    f'{q(s.k_v, sig=4)} {c.u(t("rad/(s·mm)", "рад/(с·мм)"))}', "1.16")
        doc.formula(f'k_ε = k_ω/(k_t H_a) = {q(s.k_v, sig=4)}/({q(s.k_t_s_mm, sig=4)} dot {q(s.h_a_mm)}) = '
                    f'{q(s.k_a, sig=4)} {c.u(t("rad/(s²·mm)", "рад/(с²·мм)"))}', "1.17")
        doc.p(t("The scales of the roller centre's motion (1.18):", "Масштабы перемещения, скорости и ускорения центра ролика (1.18):"))
        doc.formula(f'k_S = k_(γ "{t("rad", "рад")}") l_(B C) = {q(s.k_s_b, sig=4)} {c.u(t("m/mm", "м/мм"))}; quad '
                    f'k_V = k_ω l_(B C) = {q(s.k_v_b, sig=4)} {c.u(t("m/(s·mm)", "м/(с·мм)"))}; quad '
                    f'k_a = k_ε l_(B C) = {q(s.k_a_b, sig=4)} {c.u(t("m/(s²·mm)", "м/(с²·мм)"))}', "1.18")
    else:
        doc.formula(f'k_S = S_max/Y_(S max) = {q(v.stroke, sig=4)}/{q(s.y_s_max_mm)} = {q(s.k_s, sig=4)} '
                    f'{c.u(t("m/mm", "м/мм"))}', "1.11")
        doc.formula(f'k_V = k_S/(k_t H_V) = {q(s.k_s, sig=4)}/({q(s.k_t_s_mm, sig=4)} dot {q(s.h_v_mm)}) = '
                    f'{q(s.k_v, sig=4)} {c.u(t("m/(s·mm)", "м/(с·мм)"))}', "1.12")
        doc.formula(f'k_a = k_V/(k_t H_a) = {q(s.k_v, sig=4)}/({q(s.k_t_s_mm, sig=4)} dot {q(s.h_a_mm)}) = '
                    f'{q(s.k_a, sig=4)} {c.u(t("m/(s²·mm)", "м/(с²·мм)"))}', "1.13")
    doc.p(t("The largest ordinate of the acceleration diagram on the return follows from that on the rise by (1.8):",
            "Наибольшая ордината диаграммы ускорений на возвращении связана с ординатой на удалении формулой (1.8):"))
    doc.formula(f'Y_(a."в".max) = Y_(a."у".max) (φ_"у"/φ_"в")^2 = {q(s.y_a_rise_max_mm, sig=4)} dot '
                f'({q(v.phi_rise_deg)}/{q(v.phi_return_deg)})^2 = {q(s.y_a_return_max_mm, sig=4)} {c.u(mm)}', "1.8")

    # 1.4 main dimensions -----------------------------------------------------------------------
    doc.h(2, t("Main dimensions of the mechanism", "Определение основных размеров механизма"))
    closure_words = t("force closure (a spring keeps the roller on the cam), so the condition (1.19) is imposed on "
                      "the rise only", "силовом замыкании (ролик прижимается к кулачку пружиной) условие (1.19) "
                      "накладывается только на участок удаления") if z.closure == "force" else \
        t("form closure (a groove), so the condition (1.19) holds on the rise and the return",
          "геометрическом замыкании (пазовый кулачок) условие (1.19) должно выполняться на удалении и возвращении")
    doc.p(t("The main dimensions follow from the pressure-angle condition", "Основные размеры находятся из условия ограничения угла давления"))
    doc.formula('ν_i <= ν_max < ν_"кр"', "1.19")
    doc.p(t(f"by the theorem on the position of the cam centre (§1.3 of [1]): at each position the segment "
            f"$B_i D_i = V_(B i)\\/ω_k$ (1.20) is laid off along the follower's velocity turned by 90° in the sense "
            f"of $ω_k$, and the cam centre must lie inside the angle $2ν_max$ at $D_i$. With {closure_words}. "
            "The program checks every position (every 0.2° of cam angle) and takes the point of the feasible zone "
            "nearest to $B_0$; the textbook takes the vertex where its two bounding lines meet. Both are given "
            f"in Table {{tab:cam_dims}}, the zone in Figure {{fig:cam_zone}}.",
            f"по теореме о положении центра вращения кулачка (п. 1.3 [1]): в каждом положении от точки $B_i$ "
            f"по вектору скорости, повёрнутому на 90° в сторону $ω_k$, откладывается отрезок "
            f"$B_i D_i = V_(B i)\\/ω_k$ (1.20), и центр кулачка должен лежать внутри угла $2ν_max$ с вершиной в $D_i$. "
            f"При {closure_words}. Программа проверяет все положения (через 0,2° угла поворота) и принимает точку "
            "зоны допустимого расположения центра, ближайшую к $B_0$; в пособии принимается точка пересечения "
            f"двух ограничивающих прямых. Оба решения приведены в таблице {{tab:cam_dims}}, зона — на рисунке {{fig:cam_zone}}."))
    doc.formula(f"r_0 = |O B_0| = {q(z.r0_m * 1000, decimals=2)} {c.u(mm)}", "1.22" if not rocker else "1.25")
    if rocker:
        doc.formula(f"l_(O C) = |O C| = {q(z.l_oc_m * 1000, decimals=2)} {c.u(mm)}", "1.25")
        sw = t("the same way as the cam", "в ту же сторону, что и кулачок") if z.swing == "same" else \
            t("opposite to the cam", "в сторону, противоположную вращению кулачка")
        doc.p(t(f"During the rise the rocker turns {sw}; the other swing would need "
                f"$r_0 = {q(z.r0_other_swing_m * 1000, decimals=2)}$ mm, so the smaller is taken.",
                f"При удалении коромысло поворачивается {sw}; при обратном направлении качания потребовалось бы "
                f"$r_0 = {q(z.r0_other_swing_m * 1000, decimals=2)}$ мм, поэтому принят меньший вариант."))
    else:
        doc.formula(f"e = {q(z.e_m * 1000, decimals=2)} {c.u(mm)}", "1.23")
        doc.where(t("$e > 0$: the follower's axis lies to the right of the cam centre (follower above the cam).",
                    "где $e > 0$ — ось толкателя правее центра кулачка (толкатель над кулачком)."))
    rows = [["$r_0$, " + mm, n(z.r0_m * 1000, decimals=2), n(z.book_r0_m * 1000, decimals=2)]]
    if rocker:
        rows.append(["$l_(O C)$, " + mm, n(z.l_oc_m * 1000, decimals=2), n(z.book_l_oc_m * 1000, decimals=2)])
    else:
        rows.append(["$e$, " + mm, n(z.e_m * 1000, decimals=2), n(z.book_e_m * 1000, decimals=2)])
    rows.append([t("$ν$ max on the rise, °", "$ν$ наиб. на удалении, °"), n(z.nu_rise_max_deg, decimals=2),
                 n(z.book_nu_rise_max_deg, decimals=2)])
    rows.append([t("$ν$ max on the return, °", "$ν$ наиб. на возвращении, °"), n(z.nu_return_max_deg, decimals=2),
                 n(z.book_nu_return_max_deg, decimals=2)])
    doc.table("cam_dims", t("Main dimensions: the exact zone and the textbook's vertex",
                            "Основные размеры: по точной зоне и по построению пособия"),
              [t("Quantity", "Величина"), t("Exact zone (taken)", "Точная зона (принято)"),
               t("Textbook's vertex", "Построение пособия")], rows)
    diff = (z.book_r0_m / z.r0_m - 1) * 100
    if n(z.book_r0_m * 1000, decimals=2) == n(z.r0_m * 1000, decimals=2):
        doc.p(t("The textbook's construction gives the same point here.", "Построение пособия здесь даёт ту же точку."))
    elif abs(diff) < 0.1:
        by = n(diff, decimals=2) if abs(diff) >= 0.01 else t("less than 0.01", "менее 0,01")
        doc.p(t(f"The two practically coincide (they differ by {by} %, within the step of the construction).",
                f"Оба решения практически совпадают (отличие {by} % — в пределах шага построения)."))
    else:
        doc.p(t(f"The textbook's construction gives $r_0$ larger by {n(diff, decimals=2)} %.",
                f"Построение пособия даёт $r_0$ больше на {n(diff, decimals=2)} %."))
    c.fig("cam_zone", t("Zone of the cam centre", "Зона допустимого расположения центра вращения кулачка"))

    # 1.5 profile -------------------------------------------------------------------------------
    doc.h(2, t("Profile of the cam", "Построение профиля кулачка"))
    doc.p(t("The profile is built by inversion (§1.4 of [1]): the cam is held still and the follower is turned "
            "about the cam centre against the cam's rotation; the roller centre then traces the pitch (theoretical) "
            "profile, and the working profile is the envelope of the roller circles.",
            "Профиль строится методом обращения движения (п. 1.4 [1]): кулачок считается неподвижным, а стойка "
            "с толкателем поворачивается вокруг центра кулачка в сторону, противоположную его вращению; центр "
            "ролика при этом описывает теоретический профиль, а действительный профиль — огибающая окружностей "
            "ролика."))
    ratio = d.k_s / d.k_sk
    doc.p(t(f"The profile is drawn at the scale M {d.scale} ($k_(S k) = {q(d.k_sk, sig=4)}$ m/mm, Table 1.1 of [1]); "
            f"the sizing scale is taken equal to the diagram scale, $k'_S = k_S$, so the lengths of the diagrams "
            "are converted by (1.26) and (1.27):",
            f"Профиль вычерчивается в масштабе М {d.scale} ($k_(S k) = {q(d.k_sk, sig=4)}$ м/мм, табл. 1.1 [1]); "
            "масштаб построения основных размеров принят равным масштабу диаграммы, $k'_S = k_S$, поэтому "
            "отрезки диаграмм пересчитываются по (1.26) и (1.27):"))
    st = d.size("stroke")
    r0s = d.size("r0")
    doc.formula(f'y_(S i k) = k_S/k_(S k) y_(S i) = {q(d.k_s, sig=4)}/{q(d.k_sk, sig=4)} dot {q(st.at_k_s_mm, sig=4)} = '
                f'{q(st.drawn_mm, sig=4)} {c.u(mm)}', "1.26")
    doc.formula(f"x_(i k) = (k'_S)/k_(S k) x_i = {q(ratio, sig=4)} dot {q(r0s.at_k_s_mm, sig=4)} = "
                f"{q(r0s.drawn_mm, sig=4)} {c.u(mm)}", "1.27")
    doc.where(t("(for the largest displacement and for $r_0$; the other sizes are in the table of the drawing).",
                "где в (1.26) подставлено наибольшее перемещение, в (1.27) — радиус $r_0$."))
    doc.p(t("The profile angles differ from the phase angles when the follower is offset or is a rocker; "
            "by (1.1), (1.2) and (1.4):",
            "Профильные углы отличаются от фазовых при смещённом толкателе и у коромысла; по (1.1), (1.2), (1.4):"))
    doc.formula(f'ψ_"у" + ψ_"дс" + ψ_"в" + ψ_"бс" = {q(p.psi_rise_deg, decimals=2)} + {q(abs(p.psi_far_deg), decimals=2)} + '
                f'{q(p.psi_return_deg, decimals=2)} + {q(p.psi_near_deg, decimals=2)} = "360°"', "1.1")
    doc.formula(f'ψ_"р" = ψ_"у" + ψ_"дс" + ψ_"в" = {c.qd(p.psi_working_deg, decimals=2)}', "1.2")
    doc.formula(f'ψ_"р" = φ_"р" = {c.qd(v.phi_working_deg)}', "1.4")
    doc.p(t("The roller radius by (1.28):", "Радиус ролика — по (1.28):"))
    doc.formula(f'r_"р" = {q(0.2)} r_0 = {q(0.2)} dot {q(z.r0_m * 1000, decimals=2)} = {q(p.roller_m * 1000, decimals=2)} {c.u(mm)}', "1.28")
    doc.p(t(f"Here $r_0$ is the base radius of the pitch profile; the smallest radius of the working profile is "
            f"$r_0 - r_\"р\" = {q(p.working_min_radius_m * 1000, decimals=2)}$ mm, the far-dwell radius of the pitch "
            f"profile is {n(p.r_far_m * 1000, decimals=2)} mm.",
            f"Здесь $r_0$ — радиус теоретического профиля; наименьший радиус действительного профиля "
            f"$r_0 - r_\"р\" = {q(p.working_min_radius_m * 1000, decimals=2)}$ мм, радиус дальнего стояния "
            f"теоретического профиля {n(p.r_far_m * 1000, decimals=2)} мм."))
    rho = p.roller_max_m
    if p.undercut:
        doc.p(t(f"Undercut check: the roller is not smaller than the smallest radius of curvature of the pitch profile, "
                f"$r_\"р\" = {q(p.roller_m * 1000, decimals=2)} >= ρ_min = {q(rho * 1000, decimals=2)}$ mm: the working "
                "profile would be undercut (see the warnings in the conclusion).",
                f"Проверка на подрез: радиус ролика не меньше наименьшего радиуса кривизны теоретического профиля, "
                f"$r_\"р\" = {q(p.roller_m * 1000, decimals=2)} >= ρ_min = {q(rho * 1000, decimals=2)}$ мм: "
                "действительный профиль получится подрезанным (см. предупреждения в заключении)."))
        if p.r0_for_rule_m is not None:
            fix = (f"l_(O C) = {q(p.fix_l_oc_m * 1000, decimals=2)}" if rocker else f"e = {q(p.fix_e_m * 1000, decimals=2)}")
            doc.p(t(f"The undercut disappears with a larger cam: $r_0 = {q(p.r0_for_rule_m * 1000, decimals=2)}$ mm, "
                    f"${fix}$ mm, or with a roller smaller than {n(rho * 1000, decimals=2)} mm.",
                    f"Подрез устраняется увеличением кулачка: $r_0 = {q(p.r0_for_rule_m * 1000, decimals=2)}$ мм, "
                    f"${fix}$ мм, — или роликом радиусом меньше {n(rho * 1000, decimals=2)} мм."))
    else:
        doc.p(t(f"Undercut check: $r_\"р\" = {q(p.roller_m * 1000, decimals=2)} < ρ_min = {q(rho * 1000, decimals=2)}$ mm "
                "(the smallest radius of curvature of the pitch profile on its convex part"
                + (" and of the groove's concave side" if z.closure == "form" else "") + "): no undercut.",
                f"Проверка на подрез: $r_\"р\" = {q(p.roller_m * 1000, decimals=2)} < ρ_min = {q(rho * 1000, decimals=2)}$ мм "
                "(наименьший радиус кривизны выпуклой части теоретического профиля"
                + (" и вогнутой стороны паза" if z.closure == "form" else "") + ") — подреза нет."))
    doc.p(t(f"The profile with the pitch curve, the base circle and the inverted positions of the follower is shown "
            f"in Figure {{fig:cam_profile}}.",
            f"Профиль кулачка с теоретическим профилем, окружностью радиуса $r_0$ и положениями толкателя в "
            f"обращённом движении показан на рисунке {{fig:cam_profile}}."))
    c.fig("cam_profile", t("Profile of the cam", "Профиль кулачка"))

    # 1.6 pressure angle --------------------------------------------------------------------------
    doc.h(2, t("Pressure angle over the cycle", "Угол давления за цикл"))
    if z.closure == "force":
        ret = t(f"on the return the roller is pushed by the spring, so the pressure angle there is not limited "
                f"(it reaches {n(z.nu_return_max_deg, decimals=1)}°).",
                f"на возвращении ролик прижимается пружиной, и угол давления там не ограничивается (достигает "
                f"{n(z.nu_return_max_deg, decimals=1)}°).")
    else:
        ret = t(f"on the return it reaches {n(z.nu_return_max_deg, decimals=2)}° ≤ {n(v.nu_max_deg)}°.",
                f"на возвращении — {n(z.nu_return_max_deg, decimals=2)}° ≤ {n(v.nu_max_deg)}°.")
    doc.p(t(f"The pressure angle at the chosen centre (Figure {{fig:cam_pressure_angle}}) reaches "
            f"{n(z.nu_rise_max_deg, decimals=2)}° ≤ $ν_max = {q(v.nu_max_deg)}°$ on the rise; " + ret,
            f"Угол давления при принятом положении центра (рисунок {{fig:cam_pressure_angle}}) на удалении достигает "
            f"{n(z.nu_rise_max_deg, decimals=2)}° ≤ $ν_max = {q(v.nu_max_deg)}°$; " + ret))
    c.fig("cam_pressure_angle", t("Pressure angle against the cam angle", "Угол давления в функции угла поворота кулачка"))


def _motion_table(c: Ctx) -> None:
    r = c.r.cam
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
                  f"$a$, {t('m/s²', 'м/с²')}", f"$B D$, {mm}", t("Phase", "Участок")]
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
                         n(row.v, decimals=3), n(row.a, decimals=1), n(bd, decimals=2),
                         t(*_PHASE[row.phase])])
    c.doc.table("cam_motion", t("Displacement, velocity and acceleration of the follower by positions",
                                "Перемещение, скорость и ускорение толкателя по положениям кулачка"),
                header, rows, align="center" + ", right" * (len(header) - 1 - (0 if rocker else 1))
                + ("" if rocker else ", left"))
