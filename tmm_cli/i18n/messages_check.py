"""Sentences of `tmm check`'s feedback to a student (teacher/diagnose.py, reducer.py, alternatives.py):
the likely cause of a wrong value, the condition a tooth set breaks, a remark on a value that
passes against another design. ru and en; the book's sections are named where the row's place is."""

MESSAGES: dict[str, dict[str, str]] = {
    # keys and cells
    "key_suggest": {"en": "unknown key; did you mean {key}?", "ru": "неизвестный ключ; возможно, имелся в виду {key}?"},
    "key_unknown": {"en": "unknown key; `tmm check --keys` lists the keys",
                    "ru": "неизвестный ключ; список ключей: `tmm check --keys`"},
    "key_duplicate": {"en": "{written} is the same value as {first}, given earlier; keep one",
                      "ru": "{written} — та же величина, что и {first}, указанная выше; оставьте одну"},
    "cell_unreadable": {"en": "'{raw}' is not a number; write digits with a dot or a comma, e.g. 41,5",
                        "ru": "«{raw}» — не число; запишите цифрами с точкой или запятой, например 41,5"},
    "cell_not_number": {"en": "not a number (a finite number of sensible size); write digits with a dot or a comma, e.g. 41,5",
                        "ru": "не число (нужно конечное число разумной величины); запишите цифрами с точкой или запятой, "
                              "например 41,5"},
    "missing_required": {"en": "required for this sheet and not given", "ru": "обязателен для листа, но не указан"},
    # the spur pair's shifts
    "shift_impossible": {
        "en": "the shifts x1 = {x1:g}, x2 = {x2:g} make no working pair ({reason}); the rest is checked for the "
              "unshifted pair",
        "ru": "смещения x1 = {x1:g}, x2 = {x2:g} не дают работоспособной передачи ({reason}); остальное проверено для "
              "передачи без смещения"},
    "depends_on_shift": {"en": "depends on x1, x2, which make no pair: not checked",
                         "ru": "зависит от x1, x2, которые не дают передачи: не проверено"},
    # the planetary set
    "alt_valid": {
        "en": "your set {teeth} with k = {k} differs from the program's but meets every condition of §2.1.3 "
              "(ratio error {err:+.2f} % within ±{tol:g} %): a valid alternative",
        "ru": "ваш набор {teeth} при k = {k} отличается от принятого программой, но удовлетворяет всем условиям п. 2.1.3 "
              "(погрешность {err:+.2f} % в пределах ±{tol:g} %): верная альтернатива"},
    "alt_fewer_planets": {
        "en": "k = {k} fits; up to {k_max} planets fit this set (§2.4 step 5 takes the largest)",
        "ru": "k = {k} допустимо; этот набор допускает до {k_max} сателлитов (п. 2.4, этап 5 берёт наибольшее)"},
    "alt_fewer_planets_stage": {
        "en": "stage {stage}: k = {k} fits; up to {k_max} planets fit this set (§2.4 step 5 takes the largest)",
        "ru": "ступень {stage}: k = {k} допустимо; этот набор допускает до {k_max} сателлитов (п. 2.4, этап 5 берёт "
              "наибольшее)"},
    "set_invalid": {"en": "your set {teeth} with k = {k} breaks a condition of §2.1.3:",
                    "ru": "ваш набор {teeth} при k = {k} нарушает условие п. 2.1.3:"},
    "set_not_positive": {"en": "every tooth number and k must be a positive whole number",
                         "ru": "числа зубьев и число сателлитов должны быть целыми положительными"},
    "set_ratio": {
        "en": "the ratio i = {ratio:.4f} is {err:+.2f} % off the required {target:.4f}, outside ±{tol:g} % "
              "(condition 1, (2.1))",
        "ru": "передаточное отношение i = {ratio:.4f} отличается от требуемого {target:.4f} на {err:+.2f} %, больше "
              "±{tol:g} % (условие 1, (2.1))"},
    "set_coaxial": {"en": "not coaxial: {formula} gives {lhs} ≠ {rhs} (condition 2)",
                    "ru": "не выполнено условие соосности {formula}: {lhs} ≠ {rhs} (условие 2)"},
    "set_coaxial_stage": {"en": "stage {stage} not coaxial: {formula} gives {lhs} ≠ {rhs} (condition 2)",
                          "ru": "ступень {stage}: не выполнено условие соосности {formula}: {lhs} ≠ {rhs} (условие 2)"},
    "set_assembly": {"en": "k = {k} planets cannot be assembled (2.4); this set admits k = {ks}",
                     "ru": "k = {k} сателлитов не собрать (условие сборки (2.4)); набор допускает k = {ks}"},
    "set_assembly_stage": {"en": "stage {stage}: k = {k} planets cannot be assembled (2.4); the set admits k = {ks}",
                           "ru": "ступень {stage}: k = {k} сателлитов не собрать (2.4); набор допускает k = {ks}"},
    "set_neighbour": {
        "en": "k = {k} planets touch: sin(π/k) = {sin:.3f} is not above (z_c + 2h_a*)/(z_k + z_c) = {q:.3f} (2.5); "
              "at most {limit}",
        "ru": "k = {k} сателлитов задевают друг друга: sin(π/k) = {sin:.3f} не больше (z_c + 2h_a*)/(z_k + z_c) = {q:.3f} "
              "(условие соседства (2.5)); не более {limit}"},
    "set_neighbour_stage": {
        "en": "stage {stage}: k = {k} planets touch: sin(π/k) = {sin:.3f} ≤ {q:.3f} (2.5); at most {limit}",
        "ru": "ступень {stage}: k = {k} сателлитов задевают друг друга: sin(π/k) = {sin:.3f} ≤ {q:.3f} (2.5); не более {limit}"},
    "set_interference": {"en": "{symbol} = {value} is below {limit} (Table 2.2: the teeth interfere)",
                         "ru": "{symbol} = {value} меньше {limit} (табл. 2.2: интерференция зубьев)"},
    "set_interference_stage": {"en": "stage {stage}: {symbol} = {value} is below {limit} (Table 2.2)",
                               "ru": "ступень {stage}: {symbol} = {value} меньше {limit} (табл. 2.2)"},
    "follows_your_set": {"en": "right for your set {teeth}, which itself breaks a condition",
                         "ru": "верно для вашего набора {teeth}, но сам набор нарушает условие"},
    # remarks on values that pass against another design
    "remark_book_vertex": {"en": "the book's two-line vertex; the exact zone gives {program:.2f} mm",
                           "ru": "вершина по двум прямым, как в пособии; точная зона даёт {program:.2f} мм"},
    "remark_other_swing": {"en": "the smallest cam of the other swing (its pivot lies inside the cam); the program "
                                 "carries {program:.2f} mm",
                           "ru": "наименьший кулачок при другом направлении качания (ось коромысла внутри кулачка); "
                                 "программа принимает {program:.2f} мм"},
    "remark_roller_undercuts": {"en": "the book's 0.2·r0, but it undercuts this cam; the program carries {program:.2f} mm",
                                "ru": "0,2·r_0 по пособию, но такой ролик подрезает профиль; программа принимает "
                                      "{program:.2f} мм"},
    # likely causes of a wrong value
    "cause_r0_small_force": {
        "en": "the zone's bounding lines are probably swapped: line A must touch the curve of the points D_i at "
              "ν_max to the velocity, line C pass through B0 — or the segments B_iD_i were laid off against the rule "
              "(V_B turned 90° in the sense of ω_k)",
        "ru": "вероятно, перепутаны прямые, ограничивающие зону: прямая A касается кривой точек D_i под углом ν_max к "
              "скорости, прямая C проходит через B0 — или отрезки B_iD_i отложены против правила (V_B, повёрнутый на "
              "90° в сторону ω_k)"},
    "cause_r0_small_form": {
        "en": "the zone's bounding lines A and B are probably swapped or drawn at ν_max from the wrong side, or the "
              "segments B_iD_i were laid off against the rule (V_B turned 90° in the sense of ω_k)",
        "ru": "вероятно, прямые A и B, ограничивающие зону, перепутаны или проведены под углом ν_max не с той "
              "стороны, или отрезки B_iD_i отложены против правила (V_B, повёрнутый на 90° в сторону ω_k)"},
    "cause_r0_large": {
        "en": "the cam centre was probably taken inside the zone, not where its bounding lines meet (the smallest cam)",
        "ru": "вероятно, центр кулачка взят внутри зоны, а не в точке пересечения ограничивающих её прямых "
              "(наименьший кулачок)"},
    "follows_your_r0": {"en": "it follows from the centre you chose: correct {key} first",
                        "ru": "величина следует из выбранного вами центра: сначала исправьте {key}"},
    "cause_e_sign": {"en": "the size is right but the sign is not: e > 0 when the follower's axis lies right of the "
                           "cam centre",
                     "ru": "величина верна, знак — нет: e > 0, когда ось толкателя правее центра кулачка"},
    "cause_e_value": {"en": "e is the distance from the chosen centre to the follower's axis (1.23), read at the "
                            "same centre as r_0",
                      "ru": "e — расстояние от выбранного центра до оси толкателя (1.23), при том же центре, что и r_0"},
    "cause_l_oc": {"en": "l_OC is the distance from the chosen centre to the rocker's pivot C (1.25)",
                   "ru": "l_OC — расстояние от выбранного центра до центра качания коромысла C (1.25)"},
    "cause_roller_rule": {"en": "r_p = 0.2·r_0 (1.28), and below the pitch curve's smallest radius of curvature",
                          "ru": "r_р = 0,2·r_0 (1.28) и меньше наименьшего радиуса кривизны центрового профиля"},
    "cause_nu_is_limit": {"en": "{nu_max:g}° is the allowed ν_max; asked is the largest angle at the centre you chose",
                          "ru": "{nu_max:g}° — допустимый ν_max; нужен наибольший угол давления при выбранном центре"},
    "cause_nu": {"en": "the pressure angle is read at the chosen centre: the line through the centre and D_i against "
                       "the follower's velocity, the largest over the phase",
                 "ru": "угол давления определяется при выбранном центре: между прямой через центр и D_i и скоростью "
                       "толкателя, наибольший за фазу"},
    "cause_psi_is_phi": {"en": "{phi:g}° is the phase angle φ; the profile angle ψ differs from it when e ≠ 0",
                         "ru": "{phi:g}° — фазовый угол φ; профильный угол ψ отличается от него при e ≠ 0"},
    "cause_psi": {"en": "the profile angle is measured on the profile at the cam centre between the points B′ of "
                        "the phase's ends",
                  "ru": "профильный угол измеряется на профиле из центра кулачка между точками B′ концов фазы"},
    "cause_motor_below": {"en": "n_d must be at least 3·n_cr = {n3:g} rpm (n_cr = {crank:g} rpm)",
                          "ru": "n_д должно быть не меньше 3·n_кр = {n3:g} об/мин (n_кр = {crank:g} об/мин)"},
    "cause_motor_not_smallest": {"en": "take the smallest standard speed with n_d ≥ 3·n_cr = {n3:g} rpm",
                                 "ru": "берётся наименьшая стандартная частота с n_д ≥ 3·n_кр = {n3:g} об/мин"},
    "cause_motor_standard": {"en": "n_d is one of the standard 720, 920, 1420, 2880 rpm",
                             "ru": "n_д — одна из стандартных частот 720, 920, 1420, 2880 об/мин"},
    "cause_ratio_inverted_spur": {"en": "inverted: i_d = n_d/n_k, not n_k/n_d",
                                  "ru": "отношение перевёрнуто: i_д = n_д/n_к, а не n_к/n_д"},
    "cause_ratio_inverted_planetary": {"en": "inverted: i_pl = n_d/n_cr, not n_cr/n_d",
                                       "ru": "отношение перевёрнуто: i_пл = n_д/n_кр, а не n_кр/n_д"},
    "follows_your_motor": {"en": "it follows from your n_d = {n:g}, which is wrong: correct n_d first",
                           "ru": "следует из вашего n_д = {n:g}, которое неверно: сначала исправьте n_д"},
    "cause_crank_220": {"en": "computed with the book's 220 rpm; your crank speed is n_cr = {crank:g} rpm",
                        "ru": "рассчитано по 220 об/мин из пособия; ваша частота кривошипа n_кр = {crank:g} об/мин"},
    "cause_i_spur": {"en": "i_d = n_d/|n_k|", "ru": "i_д = n_д/|n_к|"},
    "cause_i_planetary": {"en": "i_pl = n_d/n_cr", "ru": "i_пл = n_д/n_кр"},
    "cause_i_kh": {"en": "the ratio of the set: i = 1 + z_n/z_k (scheme 1), 1 + z_c·z_n/(z_k·z_c′) (scheme 2)",
                   "ru": "передаточное отношение набора: i = 1 + z_n/z_k (схема 1), 1 + z_c·z_n/(z_k·z_c′) (схема 2)"},
    "cause_ratio_error": {"en": "the error is (i − i_pl)/i_pl·100 %", "ru": "погрешность равна (i − i_пл)/i_пл·100 %"},
    "cause_spur_swapped": {"en": "z1 and z2 are swapped: z1 is the gear on the motor",
                           "ru": "z1 и z2 перепутаны: z1 — колесо на валу двигателя"},
    "cause_spur_swapped_multiplier": {
        "en": "z1 and z2 are swapped: i_d < 1, so the pair is a multiplier and the small gear (17 teeth) is the "
              "driven one, on the cam",
        "ru": "z1 и z2 перепутаны: i_д < 1, передача — мультипликатор, и малое колесо (17 зубьев) ведомое, на валу "
              "кулачка"},
    "cause_spur_rule": {"en": "the smaller gear has 17 teeth, the other the nearest whole number to 17·i_d (or 17/i_d)",
                        "ru": "у меньшего колеса 17 зубьев, у другого — ближайшее целое к 17·i_д (или 17/i_д)"},
    "follows_your_teeth": {"en": "right for your {key}, which are wrong: correct them first",
                           "ru": "верно для ваших {key}, но они неверны: сначала исправьте их"},
    "cause_a": {"en": "a = m·(z1 + z2)/2 with m = 20 mm", "ru": "a = m·(z1 + z2)/2 при m = 20 мм"},
    "cause_eps": {"en": "ε_α = φ_α1/τ1 from the mesh drawn to size (the angle of the active line of action)",
                  "ru": "ε_α = φ_α1/τ1 по вычерченному в масштабе зацеплению (угол перекрытия)"},
    "cause_set_incomplete": {
        "en": "give z_k, z_c, z_n (z_c′) and k together: another set that meets every condition then passes too",
        "ru": "укажите z_k, z_c, z_n (z_c′) и k вместе: тогда засчитывается и другой набор, удовлетворяющий всем условиям"},
    "cause_input": {"en": "variant {variant} of Table 1.2 has {value:g}: check that you took your own row",
                    "ru": "в варианте {variant} табл. 1.2 — {value:g}: проверьте, что взята ваша строка"},
    "cause_shifted": {"en": "for shifted gears a_w and α_w follow from x1 + x2 (inv α_w)",
                      "ru": "для колёс со смещением a_w и α_w следуют из x1 + x2 (inv α_w)"},
}
