"""Sentences for the gear-drive notes (sheet 4), Russian and English, by note code."""

MESSAGES: dict[str, dict[str, str]] = {
    "crank_default": {
        "en": "No crank speed given: using n_cr = {rpm:g} rpm, the book's own example (§2.2, §2.4). "
              "Give your linkage's crank speed from sheet 1 with --crank-rpm.",
        "ru": "Частота вращения кривошипа не задана: принято n_кр = {rpm:g} об/мин, как в примере пособия "
              "(п. 2.2, 2.4). Задайте её по 1-му листу (--crank-rpm).",
    },
    "motor_choice": {
        "en": "Motor: the smallest standard speed with n_d ≥ 3·n_cr = {three_ncr} rpm is n_d = {n_d} rpm (§2.2).",
        "ru": "Двигатель: наименьшая стандартная частота с n_д ≥ 3·n_кр = {three_ncr} об/мин — n_д = {n_d} об/мин (п. 2.2).",
    },
    "book_printed_ok": {
        "en": "The book's printed answer of §{section} ({teeth}, k = {k}) is reproduced by its procedure.",
        "ru": "Ответ пособия в п. {section} ({teeth}, k = {k}) воспроизводится его методикой.",
    },
    "book_printed_wrong": {
        "en": "The book's printed answer of §{section}, {teeth}, is wrong: coaxiality gives {lhs} ≠ {rhs} and its "
              "ratio is {ratio}, not {fraction} = {target}. Carried through correctly, the book's procedure gives "
              "{procedure} (size {size}).",
        "ru": "Ответ пособия в п. {section} ({teeth}) ошибочен: условие соосности даёт {lhs} ≠ {rhs}, а передаточное "
              "отношение равно {ratio}, а не {fraction} = {target}. Методика пособия, доведённая правильно, даёт "
              "{procedure} (габарит {size}).",
    },
    "book_no_derivation": {
        "en": "The book's hand procedure finds no tooth set for scheme {scheme} from a simple fraction within the "
              "tolerance; only the search result is shown.",
        "ru": "Ручная методика пособия не дала чисел зубьев для схемы {scheme} ни для одной простой дроби в пределах "
              "допуска; показан только результат перебора.",
    },
    "book_vs_search_same": {
        "en": "The book's procedure gives {book} (size {book_size}); the exhaustive search finds no smaller reducer "
              "({found}, size {size}).",
        "ru": "Методика пособия даёт {book} (габарит {book_size}); полный перебор не нашёл меньшего редуктора "
              "({found}, габарит {size}).",
    },
    "book_vs_search_smaller": {
        "en": "The book's procedure gives {book} (size {book_size}); the exhaustive search finds a smaller one, "
              "{found} (size {size}), and the program carries that.",
        "ru": "Методика пособия даёт {book} (габарит {book_size}); полный перебор нашёл меньший редуктор "
              "{found} (габарит {size}), он и принят.",
    },
    "book_vs_search_book_smaller": {
        "en": "The book's procedure gives {book} (size {book_size}), smaller than the carried {found} (size {size}), "
              "but it takes fewer than 3 planets (or not the forced number); the search rule prefers ≥ 3 planets.",
        "ru": "Методика пособия даёт {book} (габарит {book_size}) меньше принятого {found} (габарит {size}), но с "
              "числом сателлитов меньше 3 (или не заданным); правило выбора предпочитает ≥ 3 сателлитов.",
    },
    "carried_smallest_3plus": {
        "en": "Carried: {teeth}, k = {k} — the smallest reducer (size = max(z_k + 2z_c, z_n) = {size}) with at least "
              "3 planets among {n} tooth sets within tolerance (every wheel ≤ {zmax} teeth).",
        "ru": "Принят {teeth}, k = {k} — наименьший редуктор (габарит max(z_k + 2z_c, z_n) = {size}) с не менее чем "
              "3 сателлитами среди наборов чисел зубьев в пределах допуска (всего их {n}; все колёса ≤ {zmax} зуб.).",
    },
    "carried_smallest_no3": {
        "en": "Carried: {teeth}, k = {k} — no tooth set within tolerance takes 3 planets, so the smallest "
              "(size {size}) is carried.",
        "ru": "Принят {teeth}, k = {k} — ни один набор в пределах допуска не допускает 3 сателлитов, поэтому принят "
              "наименьший (габарит {size}).",
    },
    "carried_forced_planets": {
        "en": "Carried: {teeth} — the smallest reducer (size {size}) that takes the requested k = {k} planets.",
        "ru": "Принят {teeth} — наименьший редуктор (габарит {size}), допускающий заданное число сателлитов k = {k}.",
    },
    "two_stage_order": {
        "en": "Two single-row stages in series (Fig. 2.4 scheme 3): stage 1 (motor side) takes the larger ratio, so "
              "the low-speed stage, which carries the larger torque, is the one with the smaller ratio; one module "
              "assumed for the size.",
        "ru": "Две последовательные однорядные ступени (рис. 2.4, схема 3): первая (со стороны двигателя) имеет "
              "большее передаточное отношение, тихоходная ступень с большим моментом — меньшее; габарит — при "
              "одинаковом модуле.",
    },
    "forced_ratio": {
        "en": "Ratio fixed by the user at {fraction} = {value}: only tooth sets giving it exactly are searched.",
        "ru": "Передаточное отношение задано пользователем: {fraction} = {value}; перебираются только наборы, "
              "дающие его точно.",
    },
    "few_planets": {
        "en": "The number of planets k = {k} is below 3: the carrier is unbalanced and loads the bearings; consider a "
              "wider tolerance or another fraction.",
        "ru": "Число сателлитов k = {k} меньше 3: водило не уравновешено, опоры нагружены; расширьте допуск или "
              "возьмите другую дробь.",
    },
    "assembly_forms_differ": {
        "en": "Stage {stage}: the exact assembly condition (k·{g} divides {t}) admits up to k = {exact}, the book's "
              "form (k divides N = {n}) only k = {book}; a double planet can be fitted turned by whole teeth.",
        "ru": "Ступень {stage}: точное условие сборки (k·{g} делит {t}) допускает до k = {exact}, форма пособия "
              "(k делит N = {n}) — лишь k = {book}; двойной сателлит можно установить с поворотом на целое число зубьев.",
    },
    "ratio_error": {
        "en": "The reducer gives i = {i} instead of {target} ({err} %, tolerance ±{tol} %): the crank turns at "
              "{rpm} rpm instead of {want}.",
        "ru": "Редуктор даёт i = {i} вместо {target} ({err} %, допуск ±{tol} %): кривошип вращается с "
              "{rpm} об/мин вместо {want}.",
    },
    "spur_multiplier": {
        "en": "n_d < |n_k|: the spur pair is a multiplier, so the driven gear on the cam shaft is the small one "
              "(z1 = {z1} on the motor, z2 = {z2} on the cam).",
        "ru": "n_д < |n_к|: простая передача — мультипликатор, малое колесо ведомое, на валу кулачка "
              "(z1 = {z1} на двигателе, z2 = {z2} на кулачке).",
    },
    "spur_ratio": {
        "en": "Spur pair z1/z2 = {z1}/{z2}: i = {i} instead of {target} ({err} %); the cam turns at {rpm} rpm instead "
              "of {want}.",
        "ru": "Простая передача z1/z2 = {z1}/{z2}: i = {i} вместо {target} ({err} %); кулачок вращается с "
              "{rpm} об/мин вместо {want}.",
    },
    "undercut": {
        "en": "z = {z} is below the undercut limit 2h_a*/sin²α = {zmin} of a zero gear: a slight undercut of the root "
              "(a shift x ≥ {x} would remove it); the book's rule z_min = 17 accepts it.",
        "ru": "z = {z} меньше предела подрезания 2h_a*/sin²α = {zmin} нулевого колеса: незначительный подрез ножки "
              "(устраняется смещением x ≥ {x}); по правилу пособия z_min = 17 допустимо.",
    },
    "eps_low": {
        "en": "Contact ratio ε_α = {eps} is below the recommended 1.2: the pair runs less smoothly.",
        "ru": "Коэффициент перекрытия ε_α = {eps} меньше рекомендуемого 1,2: плавность работы снижена.",
    },
    "efficiency": {
        "en": "Efficiencies for (2.6): η1 = {eta1} for scheme {scheme} (0.96 per single- or double-row stage, §2.6; "
              "two stages 0.96²), η2 = {eta2} for the linkage.",
        "ru": "КПД в (2.6): η1 = {eta1} для схемы {scheme} (0,96 на однорядную или двухрядную ступень, п. 2.6; "
              "две ступени — 0,96²), η2 = {eta2} для рычажного механизма.",
    },
    "power_above_series": {
        "en": "Required power {kw} kW is above the largest rated motor of the series ({top} kW).",
        "ru": "Потребная мощность {kw} кВт больше наибольшей в ряду ({top} кВт).",
    },
    # mesh stiffness of the spur pair (tmm gears/project --stiffness): beyond the course
    "stiffness_paper": {
        "en": "V. P. Tarasik, “Determining the stiffness parameters of the gear trains of mobile machines” "
              "(Belarusian-Russian University, Mogilev; in Russian)",
        "ru": "В. П. Тарасик, «Определение параметров жёсткости зубчатых передач трансмиссий мобильных машин» "
              "(Белорусско-Российский университет, г. Могилёв)",
    },
    "stiffness_scope": {
        "en": "Mesh stiffness is beyond the course (after V. P. Tarasik, “Determining the stiffness parameters of the "
              "gear trains of mobile machines”) and only informative: each tooth "
              "is a cantilever of trapezoidal section (bending, eqs. (1)–(14)), the contact deformation follows "
              "Nakhatakyan's formula (16), and the turn angles add: c = c_b·c_H/(c_b + c_H) (20); stiffness reduced "
              "to the motor shaft (gear 1, the driving gear).",
        "ru": "Жёсткость зацепления — сверх программы курса (по статье В. П. Тарасика «Определение параметров "
              "жёсткости зубчатых передач трансмиссий мобильных машин»), справочно: зуб — "
              "консольная балка трапецеидального сечения (изгиб, формулы (1)–(14)), контактная деформация — по "
              "формуле Нахатакяна (16), углы поворота складываются: c = c_и·c_H/(c_и + c_H) (20); жёсткость "
              "приведена к валу двигателя (колесо 1, ведущее).",
    },
    "stiffness_material": {
        "en": "Steel, E = {e}·10¹¹ Pa, ν = {nu}: the paper prints neither, these values reproduce its worked example.",
        "ru": "Сталь, E = {e}·10¹¹ Па, ν = {nu}: в статье они не указаны, эти значения воспроизводят её пример.",
    },
    "stiffness_width": {
        "en": "Face width b_w = ψ_m·m = {psi}·{m} = {bw} mm, with ψ_m = b_w/m = 5 of the paper's example "
              "(10 mm / 2 mm): the course does not size the face width.",
        "ru": "Ширина венца b_w = ψ_m·m = {psi}·{m} = {bw} мм, ψ_m = b_w/m = 5 как в примере статьи (10 мм / 2 мм): "
              "в курсовом проекте ширина венца не определяется.",
    },
    "stiffness_load_motor": {
        "en": "Load: the motor torque T_d = N/ω_d = {t} N·m (power (2.6) at n_d) on gear 1, F = {f} N, "
              "q = {q} N/mm — an upper bound, since the spur pair drives only the cam; only c_H depends on the load "
              "(logarithmically), c_b does not.",
        "ru": "Нагрузка: момент двигателя T_д = N/ω_д = {t} Н·м (мощность (2.6) при n_д) на колесе 1, F = {f} Н, "
              "q = {q} Н/мм — оценка сверху, простая передача приводит только кулачок; от нагрузки зависит только "
              "c_H (логарифмически), c_и не зависит.",
    },
    "stiffness_load_nominal": {
        "en": "Load: no moment given (--torque), so the paper's nominal line load q = F/b_w = {q} N/mm is used "
              "(F = {f} N, M1 = {t} N·m on gear 1); only c_H depends on the load (logarithmically), c_b does not.",
        "ru": "Нагрузка: момент не задан (--torque), принята погонная нагрузка примера статьи q = F/b_w = {q} Н/мм "
              "(F = {f} Н, M1 = {t} Н·м на колесе 1); от нагрузки зависит только c_H (логарифмически), c_и не "
              "зависит.",
    },
    "stiffness_multiplier": {
        "en": "The pair is a multiplier (z1 = {z1} > z2 = {z2}): the paper's pinion is its driving gear, so gear 1 "
              "takes the pinion's model (loaded at the pitch circle) although it is the larger one.",
        "ru": "Передача — мультипликатор (z1 = {z1} > z2 = {z2}): шестерня статьи — ведущее колесо, поэтому модель "
              "шестерни (нагрузка на делительной окружности) применена к колесу 1, хотя оно большее.",
    },
    # issue 8: the selection rule, the two-stage range, sanity remark
    "book_vs_search_accurate": {
        "en": "The book's procedure gives {book} (size {book_size}); the carried {found} (size {size}) is at most one "
              "tooth larger than the smallest set found and has the more accurate ratio (selection rule above).",
        "ru": "Методика пособия даёт {book} (габарит {book_size}); принятый {found} (габарит {size}) не более чем на "
              "один зуб больше наименьшего найденного и точнее по передаточному отношению (правило выбора выше).",
    },
    "select_accurate_same": {
        "en": "Selection rule (--select accurate): among the sets within tolerance, those at most {slack} tooth larger "
              "than the smallest are compared and the most accurate ratio is carried; here the smallest, {teeth} "
              "(size {size}, {err} %), is also the most accurate.",
        "ru": "Правило выбора (--select accurate): из наборов в пределах допуска сравниваются те, что не более чем на "
              "{slack} зуб больше наименьшего, и принимается самый точный по передаточному отношению; здесь "
              "наименьший {teeth} (габарит {size}, {err} %) и есть самый точный.",
    },
    "select_accurate_other": {
        "en": "Carried: {teeth}, k = {k} (size {size}, ratio error {err} %) — selection rule (--select accurate): among "
              "the {n} tooth sets within tolerance (every wheel ≤ {zmax} teeth), those at most {slack} tooth larger "
              "than the smallest are compared and the most accurate ratio is carried. The smallest is {s_teeth}, "
              "k = {s_k} (size {s_size}, {s_err} %); --select smallest carries that one.",
        "ru": "Принят {teeth}, k = {k} (габарит {size}, ошибка передаточного отношения {err} %) — правило выбора "
              "(--select accurate): из {n} наборов в пределах допуска (все колёса ≤ {zmax} зубьев) сравниваются те, "
              "что не более чем на {slack} зуб больше наименьшего, и принимается самый точный. Наименьший — "
              "{s_teeth}, k = {s_k} (габарит {s_size}, {s_err} %); его даёт --select smallest.",
    },
    "select_larger_both": {
        "en": "Why {teeth} ({err} %) is carried: the rule compares only the sets of size ≤ {limit} (at most {slack} "
              "tooth larger than the smallest), and none of them is more accurate. Larger sets are: {m_teeth} "
              "(size {m_size}, {m_err} %), and the smallest exact one, {e_teeth} (size {e_size}, 0.00 %) — "
              "--ratio {ratio} carries the exact set, a narrower --tolerance the more accurate one.",
        "ru": "Почему принят {teeth} ({err} %): правило сравнивает только наборы габарита ≤ {limit} (не более чем на "
              "{slack} зуб больше наименьшего), и среди них нет более точного. Бо́льшие наборы: {m_teeth} "
              "(габарит {m_size}, {m_err} %) и наименьший точный {e_teeth} (габарит {e_size}, 0,00 %) — "
              "--ratio {ratio} даёт точный набор, более узкий --tolerance — более точный.",
    },
    "select_larger_exact": {
        "en": "Why {teeth} ({err} %) is carried: the rule compares only the sets of size ≤ {limit} (at most {slack} "
              "tooth larger than the smallest), and none of them is more accurate. The smallest exact set is larger: "
              "{e_teeth} (size {e_size}, 0.00 %); --ratio {ratio} carries it.",
        "ru": "Почему принят {teeth} ({err} %): правило сравнивает только наборы габарита ≤ {limit} (не более чем на "
              "{slack} зуб больше наименьшего), и среди них нет более точного. Наименьший точный набор больше: "
              "{e_teeth} (габарит {e_size}, 0,00 %); его даёт --ratio {ratio}.",
    },
    "select_larger_more": {
        "en": "Why {teeth} ({err} %) is carried: the rule compares only the sets of size ≤ {limit} (at most {slack} "
              "tooth larger than the smallest), and none of them is more accurate. A more accurate set is larger: "
              "{m_teeth} (size {m_size}, {m_err} %); a narrower --tolerance carries it.",
        "ru": "Почему принят {teeth} ({err} %): правило сравнивает только наборы габарита ≤ {limit} (не более чем на "
              "{slack} зуб больше наименьшего), и среди них нет более точного. Более точный набор больше: "
              "{m_teeth} (габарит {m_size}, {m_err} %); его даёт более узкий --tolerance.",
    },
    "select_smallest": {
        "en": "Selection rule (--select smallest): the smallest reducer is carried, {teeth} (size {size}), whatever "
              "its ratio error within tolerance (the default --select accurate compares the sets up to {slack} tooth "
              "larger and takes the most accurate ratio).",
        "ru": "Правило выбора (--select smallest): принят наименьший редуктор {teeth} (габарит {size}) при любой "
              "ошибке в пределах допуска (по умолчанию, --select accurate, сравниваются наборы до {slack} зуба больше "
              "и принимается самый точный).",
    },
    "two_stage_range_ok": {
        "en": "Both stages lie within the single-row range {lo}…{hi} of Fig. 2.4: i1 = {i1}, i2 = {i2}.",
        "ru": "Обе ступени лежат в диапазоне однорядной схемы {lo}…{hi} (рис. 2.4): i1 = {i1}, i2 = {i2}.",
    },
    "two_stage_range_outside": {
        "en": "No pair of single-row stages within tolerance keeps both stages within Fig. 2.4's range {lo}…{hi}; "
              "the carried stages have i1 = {i1}, i2 = {i2}.",
        "ru": "Ни одна пара однорядных ступеней в пределах допуска не укладывается в диапазон {lo}…{hi} (рис. 2.4); "
              "у принятых ступеней i1 = {i1}, i2 = {i2}.",
    },
    "ratio_error_large": {
        "en": "Remark: the ratio error {err} % is over {limit} % (legal within the tolerance, but the crank turns at "
              "{rpm} rpm instead of {want}); a narrower --tolerance or --select accurate finds a closer set if one exists.",
        "ru": "Замечание: ошибка передаточного отношения {err} % больше {limit} % (в пределах допуска, но кривошип "
              "вращается с {rpm} об/мин вместо {want}); более узкий --tolerance или --select accurate найдут более "
              "точный набор, если он есть.",
    },
}
