"""Sentences for the notes of shifted gears and the AA̅ planetary synthesis (seed 000), ru and en."""

MESSAGES: dict[str, dict[str, str]] = {
    "shift_undercut": {
        "en": "Pair {pair}: gear z = {z} is undercut — x = {x} < x_min = h_a*(17 − z)/17 = {xmin}; shift it by at "
              "least x_min.",
        "ru": "Пара {pair}: колесо z = {z} подрезано — x = {x} < x_min = h_a*(17 − z)/17 = {xmin}; сместите его не "
              "меньше чем на x_min.",
    },
    "shift_tip_thin": {
        "en": "Pair {pair}: the tip of gear z = {z} is too thin — s_a = {sa} mm = {sam}·m < {limit} mm (limit "
              "0.25·m); reduce its shift.",
        "ru": "Пара {pair}: зуб колеса z = {z} заострён — s_a = {sa} мм = {sam}·m < {limit} мм (предел 0,25·m); "
              "уменьшите его смещение.",
    },
    "shift_eps_low": {
        "en": "Pair {pair}: contact ratio ε_α = {eps} < 1.2 (recommended; hard limit 1.05).",
        "ru": "Пара {pair}: коэффициент перекрытия ε_α = {eps} < 1,2 (рекомендуемый; предельный 1,05).",
    },
    "shift_eps_hard": {
        "en": "Pair {pair}: contact ratio ε_α = {eps} < 1.05 — below the hard limit; the pair will not run smoothly. "
              "Reduce the shifts or the working angle.",
        "ru": "Пара {pair}: коэффициент перекрытия ε_α = {eps} < 1,05 — ниже предельного; плавной работы не будет. "
              "Уменьшите смещения или угол зацепления.",
    },
    "shift_interference": {
        "en": "Pair {pair}: fillet interference on gear z = {z} — the mate's tip reaches it at roll length {rho} mm, "
              "below the involute's lower limit point at {limit} mm (rack-cut gear); change the shifts.",
        "ru": "Пара {pair}: интерференция на колесе z = {z} — вершина сопряжённого зуба заходит на переходную кривую: "
              "контакт начинается на длине {rho} мм, ниже граничной точки эвольвенты {limit} мм (нарезание рейкой); "
              "измените смещения.",
    },
    "aa_planet_tip": {
        "en": "The planet is one gear meshing both wheels: its tip diameter is the smaller of the two the meshes "
              "allow, d_a = min({da12}, {da34}) = {da} mm, so the radial clearance holds in both.",
        "ru": "Сателлит — одно колесо в двух зацеплениях: диаметр его вершин — меньший из допускаемых обоими "
              "зацеплениями, d_a = min({da12}; {da34}) = {da} мм, чтобы радиальный зазор был в обоих.",
    },
    "aa_neighbours": {
        "en": "Neighbouring fails: the planets' tip circles d_a = {da} mm do not fit {k} planets, "
              "2a_w·sin(π/k) = {limit} mm; use fewer planets.",
        "ru": "Условие соседства не выполнено: окружности вершин сателлитов d_a = {da} мм не помещаются при k = {k}, "
              "2a_w·sin(π/k) = {limit} мм; уменьшите число сателлитов.",
    },
    "spur_shifted_given": {
        "en": "Spur pair with the given profile shifts x1 = {x1}, x2 = {x2} (beyond the book): a_w = {aw} mm, "
              "α_w = {alpha_w}°.",
        "ru": "Простая передача с заданными смещениями x1 = {x1}, x2 = {x2} (сверх пособия): a_w = {aw} мм, "
              "α_w = {alpha_w}°.",
    },
    "spur_shifted_auto": {
        "en": "Spur pair shifted by the rule --shift auto (no undercut, then x1 = −x2 when z1 + z2 ≥ 34, else each gear "
              "at its limit h_a*(17 − z)/17): x1 = {x1}, x2 = {x2}, a_w = {aw} mm, α_w = {alpha_w}°.",
        "ru": "Смещения по правилу --shift auto (без подрезания; при z1 + z2 ≥ 34 равносмещённая передача x1 = −x2, "
              "иначе каждое колесо на пределе h_a*(17 − z)/17): x1 = {x1}, x2 = {x2}, a_w = {aw} мм, α_w = {alpha_w}°.",
    },
    "spur_shifted_aw": {
        "en": "Spur pair at the required centre distance a_w = {aw} mm: α_w = {alpha_w}°, x_Σ split as --shift auto "
              "plus half the difference to each gear: x1 = {x1}, x2 = {x2}.",
        "ru": "Простая передача на заданном межосевом расстоянии a_w = {aw} мм: α_w = {alpha_w}°, x_Σ распределена "
              "как при --shift auto плюс половина разности каждому колесу: x1 = {x1}, x2 = {x2}.",
    },
    "spur_shift_suggest": {
        "en": "Gear z = {z} < 17 is undercut as a zero gear: shift it by x ≥ h_a*(17 − z)/17 = {x}; "
              "--shift auto gives x1 = {x1}, x2 = {x2}.",
        "ru": "Колесо z = {z} < 17 без смещения подрезается: сместите его на x ≥ h_a*(17 − z)/17 = {x}; "
              "--shift auto даёт x1 = {x1}, x2 = {x2}.",
    },
    "aa_bar_hint": {
        "en": "Beyond the book: the planetary mechanism AA̅ with shifted gears (S. N. Kavetsky, Vestnik NTU KhPI, 2010), driven at its carrier H "
              "with the output on wheel 1, gives i_H1 = 1/i = {ratio} ({err} %) with Z = {teeth}, k = 3: "
              "tmm planetary --ratio {i} --c {c} --x1 {x1} --x2 {x2} (α_w34 = {aw34}°; every blocking-contour line holds).",
        "ru": "Сверх пособия: планетарный механизм AA̅ со смещёнными колёсами (С. Н. Кавецкий, Вестник НТУ «ХПИ», 2010) с входом на водило H и "
              "выходом на колесо 1 даёт i_H1 = 1/i = {ratio} ({err} %) при Z = {teeth}, k = 3: "
              "tmm planetary --ratio {i} --c {c} --x1 {x1} --x2 {x2} (α_w34 = {aw34}°; блокирующий контур соблюдён).",
    },
}
