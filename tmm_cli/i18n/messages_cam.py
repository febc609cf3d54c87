"""Sentences for the cam notes (sheet 3), ru and en; `note_text` formats them with the note's params."""

_SCHEME = {
    1: ("translating roller follower with force closure (spring)", "поступательный роликовый толкатель, силовое замыкание (пружина)"),
    2: ("translating roller follower with form closure (grooved cam)", "поступательный роликовый толкатель, геометрическое замыкание (пазовый кулачок)"),
    3: ("rocker (oscillating roller follower) with force closure (spring)", "качающийся роликовый толкатель (коромысло), силовое замыкание (пружина)"),
    4: ("rocker (oscillating roller follower) with form closure (grooved cam)", "качающийся роликовый толкатель (коромысло), геометрическое замыкание (пазовый кулачок)"),
}

MESSAGES: dict[str, dict[str, str]] = {}

for _n, (_en, _ru) in _SCHEME.items():
    MESSAGES[f"cam_scheme_{_n}"] = {
        "en": f"Scheme {_n} is read as a {_en} (Fig. 1.8 is missing from the book's text; project reading).",
        "ru": f"Схема {_n} принята как {_ru} (рис. 1.8 в тексте пособия утрачен; принятое в проекте прочтение).",
    }

MESSAGES.update(
    {
        "cam_swing_same": {
            "en": "The rocker turns the same way as the cam during the rise: r0 = {r0_mm:.2f} mm (the opposite swing would need {other_mm:.2f} mm).",
            "ru": "Коромысло при удалении поворачивается в ту же сторону, что и кулачок: r_0 = {r0_mm:.2f} мм (при обратном направлении качания потребовалось бы {other_mm:.2f} мм).",
        },
        "cam_swing_opposite": {
            "en": "The rocker turns opposite to the cam during the rise: r0 = {r0_mm:.2f} mm (the same-way swing would need {other_mm:.2f} mm).",
            "ru": "Коромысло при удалении поворачивается в сторону, противоположную вращению кулачка: r_0 = {r0_mm:.2f} мм (при качании в ту же сторону потребовалось бы {other_mm:.2f} мм).",
        },
        "cam_true_minimum": {
            "en": "The cam centre is the exact smallest-r0 point of the feasible zone (every position checked): r0 = {r0_mm:.2f} mm; the book's vertex of the two bounding lines gives r0 = {book_r0_mm:.2f} mm ({diff_pct:+.2f} %).",
            "ru": "Центр кулачка выбран в точке зоны возможного положения с наименьшим r_0 (проверены все положения): r_0 = {r0_mm:.2f} мм; точка пересечения двух ограничивающих прямых по пособию даёт r_0 = {book_r0_mm:.2f} мм ({diff_pct:+.2f} %).",
        },
        "cam_book_vertex_over": {
            "en": "The book's vertex (r0 = {book_r0_mm:.2f} mm) would give a pressure angle of {nu_deg:.2f}° > ν_max = {nu_max_deg:g}°, because the wedges turn with the follower; the exact zone gives r0 = {r0_mm:.2f} mm instead.",
            "ru": "Точка пересечения прямых по пособию (r_0 = {book_r0_mm:.2f} мм) дала бы угол давления {nu_deg:.2f}° > ν_max = {nu_max_deg:g}°, так как направления ограничивающих прямых меняются с положением толкателя; по точной зоне r_0 = {r0_mm:.2f} мм.",
        },
        "cam_pressure_over": {
            "en": "The pressure angle reaches {nu_deg:.3f}° > ν_max = {nu_max_deg:g}° on a constrained phase; enlarge r0.",
            "ru": "Угол давления на проверяемом участке достигает {nu_deg:.3f}° > ν_max = {nu_max_deg:g}°; увеличьте r_0.",
        },
        "cam_force_return": {
            "en": "Force closure: the return is driven by the spring, so its pressure angle is not limited (it reaches {nu_return_deg:.1f}°).",
            "ru": "Силовое замыкание: возвращение обеспечивает пружина, угол давления на участке возвращения не ограничивается (достигает {nu_return_deg:.1f}°).",
        },
        "cam_roller_rule": {
            "en": "Roller radius r_roller = {ratio:g}·r0 = {roller_mm:.2f} mm (1.28); r0 is the pitch-curve base radius, the working profile's smallest radius is r0 − r_roller = {working_min_mm:.2f} mm.",
            "ru": "Радиус ролика r_р = {ratio:g}·r_0 = {roller_mm:.2f} мм (1.28); r_0 — радиус теоретического профиля, наименьший радиус действительного профиля r_0 − r_р = {working_min_mm:.2f} мм.",
        },
        "cam_undercut_convex": {
            "en": "Undercut: the roller ({roller_mm:.2f} mm) is not smaller than the pitch curve's smallest convex radius of curvature {rho_mm:.2f} mm (at φ = {phi_deg:g}°); use a roller below {rho_mm:.2f} mm or a larger r0.",
            "ru": "Подрез профиля: радиус ролика ({roller_mm:.2f} мм) не меньше наименьшего радиуса кривизны выпуклой части теоретического профиля {rho_mm:.2f} мм (при φ = {phi_deg:g}°); возьмите ролик меньше {rho_mm:.2f} мм или увеличьте r_0.",
        },
        "cam_undercut_concave": {
            "en": "Undercut of the groove's outer side: the roller ({roller_mm:.2f} mm) is not smaller than the smallest concave radius of curvature {rho_mm:.2f} mm (at φ = {phi_deg:g}°); use a roller below {rho_mm:.2f} mm or a larger r0.",
            "ru": "Подрез наружной стороны паза: радиус ролика ({roller_mm:.2f} мм) не меньше наименьшего радиуса кривизны вогнутой части {rho_mm:.2f} мм (при φ = {phi_deg:g}°); возьмите ролик меньше {rho_mm:.2f} мм или увеличьте r_0.",
        },
        "cam_undercut_convex_fix_offset": {
            "en": "Undercut: the roller ({roller_mm:.2f} mm) is not smaller than the pitch curve's smallest convex radius of curvature {rho_mm:.2f} mm (at φ = {phi_deg:g}°). Use a roller below {rho_mm:.2f} mm, or r0 = {r0_fix_mm:.2f} mm with e = {fix_mm:.2f} mm (keeps ν ≤ ν_max and the 0.2·r0 roller).",
            "ru": "Подрез профиля: радиус ролика ({roller_mm:.2f} мм) не меньше наименьшего радиуса кривизны выпуклой части теоретического профиля {rho_mm:.2f} мм (при φ = {phi_deg:g}°). Возьмите ролик меньше {rho_mm:.2f} мм или r_0 = {r0_fix_mm:.2f} мм при e = {fix_mm:.2f} мм (ν ≤ ν_max сохраняется, ролик 0,2·r_0 работает).",
        },
        "cam_undercut_convex_fix_rocker": {
            "en": "Undercut: the roller ({roller_mm:.2f} mm) is not smaller than the pitch curve's smallest convex radius of curvature {rho_mm:.2f} mm (at φ = {phi_deg:g}°). Use a roller below {rho_mm:.2f} mm, or r0 = {r0_fix_mm:.2f} mm with l_OC = {fix_mm:.2f} mm (keeps ν ≤ ν_max and the 0.2·r0 roller).",
            "ru": "Подрез профиля: радиус ролика ({roller_mm:.2f} мм) не меньше наименьшего радиуса кривизны выпуклой части теоретического профиля {rho_mm:.2f} мм (при φ = {phi_deg:g}°). Возьмите ролик меньше {rho_mm:.2f} мм или r_0 = {r0_fix_mm:.2f} мм при l_OC = {fix_mm:.2f} мм (ν ≤ ν_max сохраняется, ролик 0,2·r_0 работает).",
        },
        "cam_undercut_concave_fix_offset": {
            "en": "Undercut of the groove's outer side: the roller ({roller_mm:.2f} mm) is not smaller than the smallest concave radius of curvature {rho_mm:.2f} mm (at φ = {phi_deg:g}°). Use a roller below {rho_mm:.2f} mm, or r0 = {r0_fix_mm:.2f} mm with e = {fix_mm:.2f} mm.",
            "ru": "Подрез наружной стороны паза: радиус ролика ({roller_mm:.2f} мм) не меньше наименьшего радиуса кривизны вогнутой части {rho_mm:.2f} мм (при φ = {phi_deg:g}°). Возьмите ролик меньше {rho_mm:.2f} мм или r_0 = {r0_fix_mm:.2f} мм при e = {fix_mm:.2f} мм.",
        },
        "cam_undercut_concave_fix_rocker": {
            "en": "Undercut of the groove's outer side: the roller ({roller_mm:.2f} mm) is not smaller than the smallest concave radius of curvature {rho_mm:.2f} mm (at φ = {phi_deg:g}°). Use a roller below {rho_mm:.2f} mm, or r0 = {r0_fix_mm:.2f} mm with l_OC = {fix_mm:.2f} mm.",
            "ru": "Подрез наружной стороны паза: радиус ролика ({roller_mm:.2f} мм) не меньше наименьшего радиуса кривизны вогнутой части {rho_mm:.2f} мм (при φ = {phi_deg:g}°). Возьмите ролик меньше {rho_mm:.2f} мм или r_0 = {r0_fix_mm:.2f} мм при l_OC = {fix_mm:.2f} мм.",
        },
        "cam_pivot_inside_force": {
            "en": "The rocker pivot C (l_OC = {l_oc_mm:.2f} mm) lies inside the circle the cam body sweeps (largest radius of the working profile {body_mm:.2f} mm): mount the rocker beside the cam plane (a cranked rocker) or choose a larger l_OC.",
            "ru": "Центр качания коромысла C (l_OC = {l_oc_mm:.2f} мм) лежит внутри окружности, которую заметает кулачок (наибольший радиус действительного профиля {body_mm:.2f} мм): коромысло нужно вынести из плоскости кулачка (изогнутое коромысло) или взять большее l_OC.",
        },
        "cam_pivot_inside_form": {
            "en": "The rocker pivot C (l_OC = {l_oc_mm:.2f} mm) lies inside the circle swept by the groove's outer wall (radius {body_mm:.2f} mm, before any wall thickness): the pivot cannot sit in the cam plane; mount the rocker beside it or choose a larger l_OC.",
            "ru": "Центр качания коромысла C (l_OC = {l_oc_mm:.2f} мм) лежит внутри окружности, которую заметает наружная стенка паза (радиус {body_mm:.2f} мм без учёта толщины стенки): опору нельзя разместить в плоскости кулачка; вынесите коромысло из плоскости или возьмите большее l_OC.",
        },
        "cam_roller_tight": {
            "en": "The roller ({roller_mm:.2f} mm) is above 80 % of the limiting radius of curvature {rho_mm:.2f} mm: no undercut, but a sharp working profile (high contact stress).",
            "ru": "Радиус ролика ({roller_mm:.2f} мм) больше 80 % предельного радиуса кривизны {rho_mm:.2f} мм: подреза нет, но действительный профиль острый (высокие контактные напряжения).",
        },
        "cam_layout": {
            "en": "Drawing scales (1.9)–(1.18) assume b = {b_mm:g} mm for φ_р, Y_Smax = {y_mm:g} mm, H_V = {h_v_mm:g} mm, H_a = {h_a_mm:g} mm (largest round bases keeping ordinates within 60 mm).",
            "ru": "Масштабы (1.9)–(1.18) рассчитаны для b = {b_mm:g} мм на φ_р, Y_Smax = {y_mm:g} мм, H_V = {h_v_mm:g} мм, H_a = {h_a_mm:g} мм (наибольшие круглые базы, при которых ординаты не превышают 60 мм).",
        },
        "cam_drawing_scale": {
            "en": "The profile is drawn at M {scale} (k_Sk = {k_sk:g} m/mm, Table 1.1): the largest standard scale at which the cam with its roller ({width_mm:.1f} × {height_mm:.1f} mm on the sheet) fits a {field_mm:g} × {field_mm:g} mm field; the sizing scale k_S′ is taken equal to the diagram scale k_S (§1.3.1), so (1.26) and (1.27) use k_S/k_Sk.",
            "ru": "Профиль строится в масштабе М {scale} (k_Sk = {k_sk:g} м/мм, табл. 1.1) — наибольшем стандартном масштабе, при котором кулачок с роликом ({width_mm:.1f} × {height_mm:.1f} мм на листе) умещается в поле {field_mm:g} × {field_mm:g} мм; масштаб k_S′ построения основных размеров принят равным масштабу диаграммы k_S (п. 1.3.1), поэтому в (1.26) и (1.27) множитель k_S/k_Sk.",
        },
        "cam_drawing_too_big": {
            "en": "Even at M {scale} (k_Sk = {k_sk:g} m/mm, the smallest scale of Table 1.1) the cam with its roller takes {width_mm:.1f} × {height_mm:.1f} mm, more than the {field_mm:g} × {field_mm:g} mm field.",
            "ru": "Даже в масштабе М {scale} (k_Sk = {k_sk:g} м/мм, наименьший в табл. 1.1) кулачок с роликом занимает {width_mm:.1f} × {height_mm:.1f} мм — больше поля {field_mm:g} × {field_mm:g} мм.",
        },
        "cam_step_halved_rise": {
            "en": "The rise is short, so its table step is {step_deg:g}° (§1.2 item 2).",
            "ru": "Участок удаления короткий, шаг таблицы на нём {step_deg:g}° (§1.2, п. 2).",
        },
        "cam_step_halved_return": {
            "en": "The return is short, so its table step is {step_deg:g}° (§1.2 item 2).",
            "ru": "Участок возвращения короткий, шаг таблицы на нём {step_deg:g}° (§1.2, п. 2).",
        },
    }
)

# issue 8: the roller rule, the pivot move, the student's choice and its failed checks, sanity remarks
MESSAGES.update(
    {
        "cam_swing_same_given": {
            "en": "The rocker turns the same way as the cam during the rise (your --swing same); the smallest cam for it has r0 = {r0_mm:.2f} mm.",
            "ru": "Коромысло при удалении поворачивается в ту же сторону, что и кулачок (ваш --swing same); наименьший кулачок для этого r_0 = {r0_mm:.2f} мм.",
        },
        "cam_swing_opposite_given": {
            "en": "The rocker turns opposite to the cam during the rise (your --swing opposite); the smallest cam for it has r0 = {r0_mm:.2f} mm.",
            "ru": "Коромысло при удалении поворачивается навстречу вращению кулачка (ваш --swing opposite); наименьший кулачок для этого r_0 = {r0_mm:.2f} мм.",
        },
        "cam_pivot_moved_swing": {
            "en": "With the smallest cam (the other swing direction, r0 = {r0_before_mm:.2f} mm) the rocker pivot C (l_OC = {l_oc_before_mm:.2f} mm) would lie inside the circle the cam sweeps ({body_before_mm:.2f} mm); the program carries the other swing direction instead: r0 = {r0_mm:.2f} mm, l_OC = {l_oc_mm:.2f} mm > {body_mm:.2f} mm, ν ≤ ν_max kept.",
            "ru": "У наименьшего кулачка (при другом направлении качания, r_0 = {r0_before_mm:.2f} мм) центр качания коромысла C (l_OC = {l_oc_before_mm:.2f} мм) оказался бы внутри окружности, которую заметает кулачок ({body_before_mm:.2f} мм); поэтому принято обратное направление качания: r_0 = {r0_mm:.2f} мм, l_OC = {l_oc_mm:.2f} мм > {body_mm:.2f} мм, условие ν ≤ ν_max сохранено.",
        },
        "cam_pivot_moved_centre": {
            "en": "With the smallest cam (r0 = {r0_before_mm:.2f} mm) the rocker pivot C (l_OC = {l_oc_before_mm:.2f} mm) would lie inside the circle the cam sweeps ({body_before_mm:.2f} mm), and so would it with the other swing; the program carries the zone's centre nearest to B0 that clears it: r0 = {r0_mm:.2f} mm, l_OC = {l_oc_mm:.2f} mm > {body_mm:.2f} mm, ν ≤ ν_max kept.",
            "ru": "У наименьшего кулачка (r_0 = {r0_before_mm:.2f} мм) центр качания коромысла C (l_OC = {l_oc_before_mm:.2f} мм) оказался бы внутри окружности, которую заметает кулачок ({body_before_mm:.2f} мм), и при обратном качании тоже; принят ближайший к B_0 центр зоны, при котором C вне кулачка: r_0 = {r0_mm:.2f} мм, l_OC = {l_oc_mm:.2f} мм > {body_mm:.2f} мм, условие ν ≤ ν_max сохранено.",
        },
        "cam_student_offset": {
            "en": "Your choice is carried ({options}): r0 = {r0_mm:.2f} mm, e = {geo_mm:.2f} mm. The program's own design: r0 = {own_r0_mm:.2f} mm, e = {own_geo_mm:.2f} mm (the smallest r0 with ν ≤ ν_max; the book's vertex: {book_r0_mm:.2f} mm).",
            "ru": "Принят ваш выбор ({options}): r_0 = {r0_mm:.2f} мм, e = {geo_mm:.2f} мм. Собственный расчёт программы: r_0 = {own_r0_mm:.2f} мм, e = {own_geo_mm:.2f} мм (наименьший r_0 при ν ≤ ν_max; по точке пересечения прямых пособия — {book_r0_mm:.2f} мм).",
        },
        "cam_student_rocker": {
            "en": "Your choice is carried ({options}): r0 = {r0_mm:.2f} mm, l_OC = {geo_mm:.2f} mm. The program's own design: r0 = {own_r0_mm:.2f} mm, l_OC = {own_geo_mm:.2f} mm (the smallest r0 with ν ≤ ν_max; the book's vertex: {book_r0_mm:.2f} mm).",
            "ru": "Принят ваш выбор ({options}): r_0 = {r0_mm:.2f} мм, l_OC = {geo_mm:.2f} мм. Собственный расчёт программы: r_0 = {own_r0_mm:.2f} мм, l_OC = {own_geo_mm:.2f} мм (наименьший r_0 при ν ≤ ν_max; по точке пересечения прямых пособия — {book_r0_mm:.2f} мм).",
        },
        "cam_fail_nu_rise": {
            "en": "FAILS the pressure-angle condition (1.19) on the rise: ν reaches {nu_deg:.2f}° > ν_max = {nu_max_deg:g}°. The cam is drawn anyway; move the centre into the zone (the smallest r0 is {r0_min_mm:.2f} mm).",
            "ru": "НЕ ВЫПОЛНЕНО условие по углу давления (1.19) на участке удаления: ν достигает {nu_deg:.2f}° > ν_max = {nu_max_deg:g}°. Кулачок построен, но центр нужно перенести в зону допустимого положения (наименьший r_0 = {r0_min_mm:.2f} мм).",
        },
        "cam_fail_nu_return": {
            "en": "FAILS the pressure-angle condition (1.19) on the return (a groove drives the return too): ν reaches {nu_deg:.2f}° > ν_max = {nu_max_deg:g}°. The cam is drawn anyway; move the centre into the zone (the smallest r0 is {r0_min_mm:.2f} mm).",
            "ru": "НЕ ВЫПОЛНЕНО условие по углу давления (1.19) на участке возвращения (паз ведёт толкатель и при возвращении): ν достигает {nu_deg:.2f}° > ν_max = {nu_max_deg:g}°. Кулачок построен, но центр нужно перенести в зону допустимого положения (наименьший r_0 = {r0_min_mm:.2f} мм).",
        },
        "cam_roller_limited_undercut": {
            "en": "Roller radius r_roller = {share:g}·ρ_min = {roller_mm:.2f} mm: the book's 0.2·r0 = {book_mm:.2f} mm (1.28) is not smaller than the pitch curve's smallest radius of curvature ρ_min = {rho_mm:.2f} mm (at φ = {phi_deg:g}°) and would undercut the profile. Rule: r0 is kept, the roller is limited to {share:g}·ρ_min (r_roller ≤ 0.8·ρ_min, the usual roller condition); the working profile's smallest radius is r0 − r_roller = {working_min_mm:.2f} mm.",
            "ru": "Радиус ролика r_р = {share:g}·ρ_min = {roller_mm:.2f} мм: по пособию 0,2·r_0 = {book_mm:.2f} мм (1.28) не меньше наименьшего радиуса кривизны теоретического профиля ρ_min = {rho_mm:.2f} мм (при φ = {phi_deg:g}°), профиль был бы подрезан. Правило: r_0 сохраняется, радиус ролика ограничивается величиной {share:g}·ρ_min (обычное условие r_р ≤ 0,8·ρ_min); наименьший радиус действительного профиля r_0 − r_р = {working_min_mm:.2f} мм.",
        },
        "cam_roller_limited_tight": {
            "en": "Roller radius r_roller = {share:g}·ρ_min = {roller_mm:.2f} mm: the book's 0.2·r0 = {book_mm:.2f} mm (1.28) does not undercut, but exceeds {share:g} of the smallest radius of curvature ρ_min = {rho_mm:.2f} mm (at φ = {phi_deg:g}°), a nearly sharp working profile. Rule: r0 is kept, the roller is limited to {share:g}·ρ_min (the usual roller condition r_roller ≤ 0.8·ρ_min); r0 − r_roller = {working_min_mm:.2f} mm.",
            "ru": "Радиус ролика r_р = {share:g}·ρ_min = {roller_mm:.2f} мм: по пособию 0,2·r_0 = {book_mm:.2f} мм (1.28) подреза не даёт, но превышает {share:g} наименьшего радиуса кривизны ρ_min = {rho_mm:.2f} мм (при φ = {phi_deg:g}°) — действительный профиль почти острый. Правило: r_0 сохраняется, радиус ролика ограничивается величиной {share:g}·ρ_min (обычное условие r_р ≤ 0,8·ρ_min); r_0 − r_р = {working_min_mm:.2f} мм.",
        },
        "cam_roller_student": {
            "en": "Roller radius r_roller = {roller_mm:.2f} mm (your --roller; the book's 0.2·r0 = {book_mm:.2f} mm, the program's rule would take {own_mm:.2f} mm, the limit 0.8·ρ_min = {limit_mm:.2f} mm); r0 − r_roller = {working_min_mm:.2f} mm.",
            "ru": "Радиус ролика r_р = {roller_mm:.2f} мм (ваш --roller; по пособию 0,2·r_0 = {book_mm:.2f} мм, по правилу программы {own_mm:.2f} мм, предел 0,8·ρ_min = {limit_mm:.2f} мм); r_0 − r_р = {working_min_mm:.2f} мм.",
        },
        "cam_fail_undercut_convex": {
            "en": "FAILS the undercut condition: the roller ({roller_mm:.2f} mm) is not smaller than the pitch curve's smallest convex radius of curvature {rho_mm:.2f} mm (at φ = {phi_deg:g}°); the working profile has a cusp. Take a roller of at most {limit_mm:.2f} mm (0.8·ρ_min) or a larger r0.",
            "ru": "НЕ ВЫПОЛНЕНО условие отсутствия подреза: радиус ролика ({roller_mm:.2f} мм) не меньше наименьшего радиуса кривизны выпуклой части теоретического профиля {rho_mm:.2f} мм (при φ = {phi_deg:g}°), на действительном профиле острие. Возьмите ролик не больше {limit_mm:.2f} мм (0,8·ρ_min) или увеличьте r_0.",
        },
        "cam_fail_undercut_concave": {
            "en": "FAILS the undercut condition on the groove's outer side: the roller ({roller_mm:.2f} mm) is not smaller than the smallest concave radius of curvature {rho_mm:.2f} mm (at φ = {phi_deg:g}°). Take a roller of at most {limit_mm:.2f} mm (0.8·ρ_min) or a larger r0.",
            "ru": "НЕ ВЫПОЛНЕНО условие отсутствия подреза наружной стороны паза: радиус ролика ({roller_mm:.2f} мм) не меньше наименьшего радиуса кривизны вогнутой части {rho_mm:.2f} мм (при φ = {phi_deg:g}°). Возьмите ролик не больше {limit_mm:.2f} мм (0,8·ρ_min) или увеличьте r_0.",
        },
        "cam_fail_pivot_force": {
            "en": "FAILS the pivot condition: the rocker pivot C (l_OC = {l_oc_mm:.2f} mm) lies inside the circle the cam body sweeps (largest radius of the working profile {body_mm:.2f} mm); choose a larger l_OC or the other --swing.",
            "ru": "НЕ ВЫПОЛНЕНО условие размещения опоры: центр качания коромысла C (l_OC = {l_oc_mm:.2f} мм) лежит внутри окружности, которую заметает кулачок (наибольший радиус действительного профиля {body_mm:.2f} мм); увеличьте l_OC или выберите другое --swing.",
        },
        "cam_fail_pivot_form": {
            "en": "FAILS the pivot condition: the rocker pivot C (l_OC = {l_oc_mm:.2f} mm) lies inside the circle swept by the groove's outer wall (radius {body_mm:.2f} mm, before any wall thickness); choose a larger l_OC or the other --swing.",
            "ru": "НЕ ВЫПОЛНЕНО условие размещения опоры: центр качания коромысла C (l_OC = {l_oc_mm:.2f} мм) лежит внутри окружности, которую заметает наружная стенка паза (радиус {body_mm:.2f} мм без толщины стенки); увеличьте l_OC или выберите другое --swing.",
        },
        "cam_small_vs_rocker": {
            "en": "Remark: the cam is much smaller than its follower: r0 = {r0_mm:.2f} mm against l_BC = {l_bc_mm:.0f} mm ({ratio:g} times, under a quarter). It meets ν ≤ ν_max, but such a cam is hard to make and the rocker's bearing takes large forces; a larger r0 (--r0) is a sensible choice for the drawing.",
            "ru": "Замечание: кулачок много меньше толкателя: r_0 = {r0_mm:.2f} мм при l_BC = {l_bc_mm:.0f} мм (в {ratio:g} раза, меньше четверти). Условие ν ≤ ν_max выполнено, но такой кулачок трудно изготовить, а опора коромысла сильно нагружена; для чертежа разумно взять больший r_0 (--r0).",
        },
        "cam_roller_small": {
            "en": "Remark: the roller radius {roller_mm:.2f} mm is under {min_mm:g} mm, smaller than any practical roller bearing; a larger r0 (--r0) allows a larger roller.",
            "ru": "Замечание: радиус ролика {roller_mm:.2f} мм меньше {min_mm:g} мм — меньше любого реального роликового подшипника; больший r_0 (--r0) позволит взять больший ролик.",
        },
        "cam_stroke_long": {
            "en": "Remark: the stroke S_max = {s_mm:.0f} mm is unusually long (Table 1.2's strokes are 20…130 mm, here r0 = {r0_mm:.0f} mm); the program computes with it as given — check the value in your copy of the table (a misprint such as 0.025 m is possible).",
            "ru": "Замечание: ход толкателя S_max = {s_mm:.0f} мм необычно велик (в табл. 1.2 ходы 20…130 мм, здесь r_0 = {r0_mm:.0f} мм); программа считает с заданным значением — сверьте его со своим экземпляром таблицы (возможна опечатка, например 0,025 м).",
        },
            "cam_book_roller_fix_offset": {
            "en": "To keep the book's roller 0.2·r0 ({book_mm:.2f} mm would undercut here) the cam must grow to r0 = {r0_mm:.2f} mm with e = {geo_mm:.2f} mm: the smallest such cam in the pressure-angle zone, every smaller centre (by more than {tol_pct:g} %) proven to undercut{proven}; --r0 {r0_mm:.2f} --offset {geo_mm:.2f} --roller {roller_mm:.2f} carries it.",
            "ru": "Чтобы сохранить ролик 0,2·r_0 по пособию (здесь {book_mm:.2f} мм дал бы подрез), кулачок нужно увеличить до r_0 = {r0_mm:.2f} мм при e = {geo_mm:.2f} мм: это наименьший такой кулачок в зоне допустимого положения центра, для всех меньших (более чем на {tol_pct:g} %) подрез доказан{proven}; его даёт --r0 {r0_mm:.2f} --offset {geo_mm:.2f} --roller {roller_mm:.2f}.",
        },
        "cam_book_roller_fix_rocker": {
            "en": "To keep the book's roller 0.2·r0 ({book_mm:.2f} mm would undercut here) the cam must grow to r0 = {r0_mm:.2f} mm with l_OC = {geo_mm:.2f} mm: the smallest such cam in the pressure-angle zone, every smaller centre (by more than {tol_pct:g} %) proven to undercut{proven}; --r0 {r0_mm:.2f} --l-oc {geo_mm:.2f} --swing {swing} --roller {roller_mm:.2f} carries it.",
            "ru": "Чтобы сохранить ролик 0,2·r_0 по пособию (здесь {book_mm:.2f} мм дал бы подрез), кулачок нужно увеличить до r_0 = {r0_mm:.2f} мм при l_OC = {geo_mm:.2f} мм: это наименьший такой кулачок в зоне допустимого положения центра, для всех меньших (более чем на {tol_pct:g} %) подрез доказан{proven}; его даёт --r0 {r0_mm:.2f} --l-oc {geo_mm:.2f} --swing {swing} --roller {roller_mm:.2f}.",
        },
    }
)
