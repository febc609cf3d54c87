"""Section 2 of the note: the gear drive (sheet 4, book section 2), from a GearsResult."""

from __future__ import annotations

import math
import re
from fractions import Fraction

from .ctx import Ctx


def _fr(f: Fraction) -> str:
    """A fraction inside typst math."""
    return f"{f.numerator}/{f.denominator}" if f.denominator != 1 else f"{f.numerator}"


def _teeth(design) -> str:
    return " + ".join("/".join(map(str, s.teeth)) for s in design.stages)


def gears_section(c: Ctx) -> None:
    g = c.r.gears
    doc, t, n, q = c.doc, c.t, c.n, c.q
    kr, dd, pl = t("cr", "кр"), t("d", "д"), t("pl", "пл")
    rpm = t("rpm", "об/мин")
    doc.h(1, t("Synthesis of the gear mechanisms", "Синтез зубчатых механизмов"))

    # 2.1 motor and ratios ----------------------------------------------------------------------
    doc.h(2, t("Motor speed and gear ratios", "Выбор двигателя и передаточных отношений"))
    if g.crank_rpm_assumed:
        doc.p(t(f"The crank speed of the linkage is not part of Table 1.2; it is taken as $n_\"{kr}\" = {q(g.crank_rpm)}$ "
                "rpm, the textbook's own example (§2.2, §2.4 of [1]), and should be replaced by the speed of sheet 1.",
                f"Частота вращения кривошипа рычажного механизма в таблице 1.2 не задана; она принята "
                f"$n_\"{kr}\" = {q(g.crank_rpm)}$ об/мин, как в примере пособия (п. 2.2, 2.4 [1]); её следует "
                "заменить частотой по 1-му листу проекта."))
    else:
        doc.p(t(f"The crank of the linkage turns at $n_\"{kr}\" = {q(g.crank_rpm)}$ rpm (sheet 1).",
                f"Кривошип рычажного механизма вращается с частотой $n_\"{kr}\" = {q(g.crank_rpm)}$ об/мин (1-й лист)."))
    cands = ", ".join(str(x) for x in g.motor_candidates)
    doc.p(t(f"The motor speed is the smallest standard speed ({cands} rpm) that is at least three times the crank "
            "speed (§2.2 of [1]):",
            f"Частота вращения двигателя — наименьшая из стандартных ({cands} об/мин), не меньшая утроенной "
            "частоты вращения кривошипа (п. 2.2 [1]):"))
    doc.formula(f'n_"{dd}" >= 3 n_"{kr}" = 3 dot {q(g.crank_rpm)} = {q(3 * g.crank_rpm)} {c.u(rpm)}; quad '
                f'n_"{dd}" = {g.motor_rpm} {c.u(rpm)}', None)
    doc.p(t("The required ratios of the spur pair (motor to cam) and of the planetary reducer (motor to crank):",
            "Требуемые передаточные отношения простой передачи (двигатель — кулачок) и планетарного редуктора "
            "(двигатель — кривошип):"))
    doc.formula(f'i_"{dd}" = n_"{dd}"/(|n_k|) = {g.motor_rpm}/{q(abs(g.cam_rpm))} = {q(g.i_spur, sig=4)}; quad '
                f'i_"{pl}" = n_"{dd}"/n_"{kr}" = {g.motor_rpm}/{q(g.crank_rpm)} = {q(g.i_planetary, sig=4)}', None)
    rot = {"cw": t("clockwise", "по часовой стрелке"), "ccw": t("counter-clockwise", "против часовой стрелки")}
    d = g.directions
    doc.p(t(f"The cam turns {rot[d.cam]}; the spur pair is an external mesh, so the motor turns {rot[d.motor]}; "
            f"the planetary reducer keeps the sense, and the crank turns {rot[d.crank]}.",
            f"Кулачок вращается {rot[d.cam]}; простая передача — внешнее зацепление, поэтому двигатель вращается "
            f"{rot[d.motor]}; планетарный редуктор направления не меняет, кривошип вращается {rot[d.crank]}."))

    # 2.2 scheme ------------------------------------------------------------------------------------
    doc.h(2, t("Scheme of the planetary reducer", "Выбор схемы планетарного редуктора"))
    rows = []
    for s in g.schemes:
        chosen = s.key == g.scheme
        rows.append([str(s.number), f"{n(s.i_min)} … {n(s.i_max)}", f"{n(s.eta_max)} … {n(s.eta_min)}",
                     "$" + _formula_math(s.formula) + "$", t("chosen", "принята") if chosen else ""])
    doc.table("schemes", t("Schemes of planetary reducers (Fig. 2.4 of [1])", "Схемы планетарных редукторов (рис. 2.4 [1])"),
              ["№", t("Ratio range", "Диапазон $i$"), t("Efficiency", "КПД"), t("Ratio", "Передаточное отношение"), ""],
              rows, align="center, center, center, left, left", widths=["auto", "auto", "auto", "1fr", "auto"])
    i = n(g.i_planetary, sig=4)
    why = {
        "le8": t(f"Since $i_\"{pl}\" = {i} <= 8$, the single-row scheme 1 is taken: it has the highest efficiency and "
                 "the simplest design.",
                 f"Так как $i_\"{pl}\" = {i} <= 8$, принят однорядный редуктор по схеме 1: он имеет наибольший КПД и "
                 "наиболее прост."),
        "8to16": t(f"Since $8 < i_\"{pl}\" = {i} <= 16$, the double-row scheme 2 is taken: a single row cannot give "
                   "this ratio with reasonable sizes, schemes 4 and 5 have a low efficiency.",
                   f"Так как $8 < i_\"{pl}\" = {i} <= 16$, принят двухрядный редуктор по схеме 2: однорядный не даёт "
                   "такого передаточного отношения при приемлемых габаритах, а схемы 4 и 5 имеют низкий КПД."),
        "gt16": t(f"Since $i_\"{pl}\" = {i} > 16$, two single-row stages in series are taken (scheme 3 of Fig. 2.4), "
                  f"each with a ratio near $sqrt(i_\"{pl}\") = {q(math.sqrt(g.i_planetary), sig=3)}$ (§2.2 of [1]); "
                  "schemes 4 and 5 would give the ratio with a low efficiency.",
                  f"Так как $i_\"{pl}\" = {i} > 16$, приняты две последовательные однорядные ступени (схема 3 "
                  f"рис. 2.4) с передаточными отношениями около $sqrt(i_\"{pl}\") = {q(math.sqrt(g.i_planetary), sig=3)}$ "
                  "(п. 2.2 [1]); схемы 4 и 5 дали бы нужное отношение лишь при низком КПД."),
    }[g.scheme_reason]
    doc.p(why + " " + t(f"The schemes are compared in Table {{tab:schemes}}.",
                        f"Схемы сопоставлены в таблице {{tab:schemes}}."))

    # 2.3 the book's procedure --------------------------------------------------------------------
    doc.h(2, t("Tooth numbers by the textbook's procedure", "Подбор чисел зубьев по методике пособия"))
    der = g.derivation
    if der is None:
        doc.p(t("The textbook's hand procedure gives no tooth set from a simple fraction within the tolerance; the tooth "
                "numbers are found by the search below.",
                "Ручная методика пособия не даёт чисел зубьев ни для одной простой дроби в пределах допуска; числа "
                "зубьев найдены перебором (см. ниже)."))
    else:
        sec = {"1": "§2.4", "2": "§2.5", "1+1": "§2.2, §2.4"}[der.scheme]
        if der.fraction_rule == "forced":
            doc.p(t(f"The ratio is fixed as a simple fraction; the procedure of {sec} of [1] follows.",
                    f"Передаточное отношение задано простой дробью; далее — методика {sec.replace('§', 'п. ')} [1]."))
        else:
            tried = ", ".join(f"{f.replace('·', ' · ')} ({s})" for f, s in sorted(der.tried, key=lambda x: x[1])[:8])
            doc.p(t(f"The required ratio is replaced by a simple fraction within ±{n(g.tolerance_pct)} % "
                    f"(denominator up to 10); of the fractions tried (reducer size in brackets: {tried}) the one "
                    f"giving the smallest reducer is taken, and the procedure of {sec} of [1] follows.",
                    f"Требуемое передаточное отношение заменяется простой дробью с точностью ±{n(g.tolerance_pct)} % "
                    f"(знаменатель не более 10); из рассмотренных дробей (в скобках — габарит редуктора: {tried}) "
                    f"принята дающая наименьший редуктор; далее — методика {sec.replace('§', 'п. ')} [1]."))
        for j, st in enumerate(der.stages, 1):
            if len(der.stages) > 1:
                doc.p(t(f"Stage {j}:", f"Ступень {j}:"))
            if st.scheme == "1":
                _book_scheme1(c, st)
            else:
                _book_scheme2(c, st)
            _book_planets(c, st)
        if g.printed is not None:
            p = g.printed
            ok = p.coaxial_ok and p.ratio_ok
            teeth = "/".join(map(str, p.stage.teeth))
            if ok:
                doc.p(t(f"The answer printed in §{p.section} of [1] ({teeth}) is reproduced.",
                        f"Ответ, приведённый в п. {p.section} [1] ({teeth}), воспроизводится."))
            else:
                doc.p(t(f"The answer printed in §{p.section} of [1], {teeth}, does not satisfy coaxiality "
                        f"({p.coaxial_lhs} ≠ {p.coaxial_rhs}) and gives $i = {q(p.ratio, sig=3)}$ instead of "
                        f"{_fr(p.fraction)}; the procedure carried through correctly gives the numbers above.",
                        f"Ответ, приведённый в п. {p.section} [1] ({teeth}), не удовлетворяет условию соосности "
                        f"({p.coaxial_lhs} ≠ {p.coaxial_rhs}) и даёт $i = {q(p.ratio, sig=3)}$ вместо "
                        f"{_fr(p.fraction)}; методика, доведённая правильно, даёт числа, полученные выше."))

    # 2.4 the search ------------------------------------------------------------------------------
    s = g.search
    doc.h(2, t("Smallest reducer by exhaustive search", "Наименьший редуктор по результатам перебора"))
    doc.p(t(f"Beside the hand procedure, every tooth set of the scheme with at most {s.z_max} teeth per wheel was "
            f"checked: {s.n_sets} sets are within ±{n(g.tolerance_pct)} % of the ratio and satisfy coaxiality and "
            "Table 2.2. The size of a reducer is $max(Γ_1, Γ_2) = max(z_k + 2 z_c, z_n)$ teeth (§2.5 of [1]). The "
            f"smallest sets are listed in Table {{tab:search}}.",
            f"Кроме ручной методики, перебраны все наборы чисел зубьев схемы с числом зубьев каждого колеса не более "
            f"{s.z_max}: {s.n_sets} наборов дают передаточное отношение с точностью ±{n(g.tolerance_pct)} % и "
            "удовлетворяют условиям соосности и табл. 2.2. Габарит редуктора оценивается числом "
            "$max(Γ_1, Γ_2) = max(z_k + 2 z_c, z_n)$ (п. 2.5 [1]). Наименьшие наборы приведены в таблице "
            "{tab:search}."))
    double = g.scheme == "2"
    if g.scheme == "1+1":
        header = [t("Stage 1: $z_k$/$z_c$/$z_n$", "Ступень 1: $z_k$/$z_c$/$z_n$"),
                  t("Stage 2: $z_k$/$z_c$/$z_n$", "Ступень 2: $z_k$/$z_c$/$z_n$")]
    else:
        header = ["$z_k$", "$z_c$", "$z'_c$", "$z_n$"] if double else ["$z_k$", "$z_c$", "$z_n$"]
    header += ["$i$", t("Error, %", "Отклонение, %"), t("Size", "Габарит"), "$k$", ""]
    rows = []
    for a in s.alternatives:
        if g.scheme == "1+1":
            cells = ["/".join(map(str, st.teeth)) for st in a.stages]
        else:
            cells = [str(x) for x in a.stages[0].teeth]
        rows.append(cells + [n(a.ratio, decimals=4), n(a.ratio_error_pct, decimals=2), str(a.size), str(a.planets),
                             t("taken", "принят") if a == g.planetary else ""])
    doc.table("search", t("Smallest tooth sets found by the search", "Наименьшие наборы чисел зубьев по перебору"),
              header, rows, align=", ".join(["center"] * len(header)))
    rule = {"smallest_3plus": t("the smallest reducer taking at least three planets",
                                "наименьший редуктор, допускающий не менее трёх сателлитов"),
            "smallest_no3": t("the smallest reducer (no set within the tolerance takes three planets)",
                              "наименьший редуктор (ни один набор в пределах допуска не допускает трёх сателлитов)"),
            "forced_planets": t(f"the smallest reducer taking {s.forced_planets} planets",
                                f"наименьший редуктор, допускающий {c.planets(s.forced_planets or 0)}")}[s.rule]
    design = g.planetary
    book_size = der.size if der is not None else None
    cmp = ""
    if book_size is not None:
        if book_size == design.size:
            cmp = t(" The textbook's procedure gives a reducer of the same size.",
                    " Методика пособия даёт редуктор того же габарита.")
        elif design.size < book_size:
            cmp = t(f" It is smaller than the one of the textbook's procedure (size {book_size}).",
                    f" Он меньше полученного по методике пособия (габарит {book_size}).")
        else:
            cmp = t(f" The textbook's procedure gives a smaller size ({book_size}) but fewer planets.",
                    f" Методика пособия даёт меньший габарит ({book_size}), но с меньшим числом сателлитов.")
    doc.p(t(f"Taken: {_teeth(design)} with $k = {design.planets}$ planets, size {design.size} — {rule}.",
            f"Принят набор {_teeth(design)} с числом сателлитов $k = {design.planets}$, габарит {design.size} — "
            f"{rule}.") + cmp)

    # 2.5 the five conditions ----------------------------------------------------------------------
    _conditions(c)
    # 2.6 ratio checks -----------------------------------------------------------------------------
    _ratio_checks(c)
    # 2.7 spur pair --------------------------------------------------------------------------------
    _spur(c)
    # 2.8 power ------------------------------------------------------------------------------------
    _power(c)


def _formula_math(text: str) -> str:
    """The ASCII-ish formulas of drive.SCHEMES ("i = 1 + z_n/z_k") as typst math."""
    out = text.replace("·", " dot ").replace("′", "'")
    out = out.replace("z_c'", "z'_c").replace("z_k'", "z'_k")
    return re.sub(r"z_([a-z])(\d)", r"z_(\1 \2)", out)


def _book_scheme1(c: Ctx, st) -> None:
    doc, t = c.doc, c.t
    row = st.chosen
    a_, d_ = row.a, row.d
    half = Fraction(d_ - a_, 2)
    doc.p(t("1) From the ratio, $z_n$ and $z_k$ through the factors D and A:",
            "1) Из условия обеспечения передаточного отношения числа зубьев $z_n$ и $z_k$ выражаются через "
            "множители D и A:"))
    doc.formula(f"i^n_(k H) = 1 + z_n/z_k = {_fr(st.fraction)}; quad z_n/z_k = {_fr(st.fraction)} - 1 = "
                f"{_fr(st.reduced)} = D/A; quad D = {d_}, A = {a_}", None)
    doc.p(t("2) From coaxiality, the planet:", "2) Из условия соосности — число зубьев сателлита:"))
    doc.formula(f"z_k + z_c = z_n - z_c; quad z_c = (z_n - z_k)/2 = (D - A)/2 y = ({d_} - {a_})/2 y = {_fr(half)} y", None)
    doc.p(t("3)–4) With the multiplier y and Table 2.2 (no interference):",
            "3)–4) Через коэффициент пропорциональности y и условия отсутствия интерференции (табл. 2.2):"))
    b = row.base
    doc.formula(f"z_k = {_fr(b[0])} y >= 17; quad z_c = {_fr(b[1])} y >= 20; quad z_n = {_fr(b[2])} y >= 85 "
                f"quad => quad y_min = {_fr(row.y_min)}", None)
    z = row.teeth
    doc.formula(f"z_k = {z[0]}; quad z_c = {z[1]}; quad z_n = {z[2]}", None)


def _book_scheme2(c: Ctx, st) -> None:
    doc, t = c.doc, c.t
    red = st.reduced
    doc.p(t("1) The ratio through the factors A, B, D, E:", "1) Передаточное отношение через множители A, B, D, E:"))
    doc.formula(f"(z_c z_n)/(z_k z'_c) = i - 1 = {_fr(st.fraction)} - 1 = {_fr(red)} = (B D)/(A E)", None)
    doc.p(t("2) The factors are split by the ranges 1 < B/A ≤ 5, 2 < D/E ≤ 5 (§2.5 of [1]):",
            "2) Множители разделяются с учётом ограничений 1 < B/A ≤ 5, 2 < D/E ≤ 5 (п. 2.5 [1]):"))
    if st.x1_range:
        doc.formula(f"B/A = x_1/{red.denominator}, quad D/E = {red.numerator}/x_1 quad => quad "
                    f"{st.x1_range[0]} <= x_1 <= {st.x1_range[1]}", None)
    if st.x2_range:
        doc.formula(f"B/A = {red.numerator}/x_2, quad D/E = x_2/{red.denominator} quad => quad "
                    f"{st.x2_range[0]} <= x_2 <= {st.x2_range[1]}", None)
    doc.p(t("3) From coaxiality $z_k + z_c = z_n - z'_c$ the tooth numbers through the multiplier y:",
            "3) Из условия соосности $z_k + z_c = z_n - z'_c$ числа зубьев через коэффициент y:"))
    doc.formula("z_k = A(D - E) y; quad z_c = B(D - E) y; quad z'_c = E(A + B) y; quad z_n = D(A + B) y", None)
    doc.p(t("4) The smallest y by Table 2.2 ($z_k >= 17$, $z_c >= 17$, $z'_c >= 20$, $z_n >= 85$) and the sizes "
            f"$Γ_1 = z_k + 2 z_c$, $Γ_2 = z_n$ for each split are in Tables {{tab:book_x1}} and {{tab:book_x2}}.",
            "4) Наименьшее y по табл. 2.2 ($z_k >= 17$, $z_c >= 17$, $z'_c >= 20$, $z_n >= 85$) и габариты "
            f"$Γ_1 = z_k + 2 z_c$, $Γ_2 = z_n$ для каждого разбиения приведены в таблицах {{tab:book_x1}} и "
            "{tab:book_x2}."))
    for tab, xname, name in (("2.3", "x_1", "book_x1"), ("2.4x2", "x_2", "book_x2")):
        rows = [rw for rw in st.rows if rw.table == tab]
        cap = t(f"Tooth numbers by the split ${xname}$ (Table {tab[:3]} of [1])",
                f"Числа зубьев по разбиению ${xname}$ (табл. {tab[:3]} [1])")
        if not rows:
            rows_cells = [["—"] * 9]
        else:
            rows_cells = [[str(rw.x), f"$({rw.b}/{rw.a}) dot ({rw.d}/{rw.e})$", f"${_fr(rw.y_min)}$",
                           *(str(zz) for zz in rw.teeth), str(rw.gamma1),
                           str(rw.gamma2) + (" *" if rw is st.chosen else "")] for rw in rows]
        doc.table(name, cap, [f"${xname}$", "$(B/A) dot (D/E)$", "$y_min$", "$z_k$", "$z_c$", "$z'_c$", "$z_n$",
                              "$Γ_1$", "$Γ_2$"], rows_cells, align=", ".join(["center"] * 9))
    ch = st.chosen
    xn = "x_1" if ch.table == "2.3" else "x_2"
    doc.p(t(f"5) The smallest $max(Γ_1, Γ_2) = {ch.size}$ is given by ${xn} = {ch.x}$ (marked *):",
            f"5) Наименьший габарит $max(Γ_1, Γ_2) = {ch.size}$ даёт ${xn} = {ch.x}$ (отмечено *):"))
    z = ch.teeth
    doc.formula(f"z_k = {z[0]}; quad z_c = {z[1]}; quad z'_c = {z[2]}; quad z_n = {z[3]}", None)


def _book_planets(c: Ctx, st) -> None:
    doc, t, q = c.doc, c.t, c.q
    zk = st.chosen.teeth[0]
    ks = ", ".join(str(k) for k in st.assembly_ks[:6]) + (" …" if len(st.assembly_ks) > 6 else "")
    doc.p(t("The possible numbers of planets by the assembly condition (2.4):",
            "Теоретически возможные числа сателлитов по условию сборки (2.4):"))
    den = "k" if st.assembly_c == 1 else f"{st.assembly_c} k"
    doc.formula(f"(z_k i^n_(k H))/k c = ({zk} dot {_fr(st.fraction)})/k c = {st.assembly_n}/({den}) c; "
                f"quad k = {ks}", "2.4")
    doc.p(t("The limit by the neighbouring condition (2.5), computed exactly:",
            "Граничное число сателлитов по условию соседства (2.5), вычисленное точно:"))
    big = max(st.chosen.teeth[1], st.chosen.teeth[2] if st.scheme == "2" else 0)
    doc.formula(f"sin π/k > (z_c + 2 h^*_a)/(z_k + z_c) = ({big} + 2)/({zk} + {st.chosen.teeth[1]}) = "
                f"{q(st.neighbour_q, decimals=3)}; quad k <= {st.neighbour_limit}", "2.5")
    extra = ""
    if st.k_max_exact != st.k_max:
        extra = t(f" (by the exact assembly condition {st.k_max_exact})", f" (по точному условию сборки {st.k_max_exact})")
    doc.p(t(f"The largest number of planets satisfying both: $k_\"max\" = {st.k_max}${extra}.",
            f"Наибольшее число сателлитов, удовлетворяющее обоим условиям: $k_\"наиб\" = {st.k_max}${extra}."))


def _conditions(c: Ctx) -> None:
    g = c.r.gears
    doc, t, q = c.doc, c.t, c.q
    ch = g.checks
    pl = t("pl", "пл")
    doc.h(2, t("Conditions of synthesis for the reducer taken", "Проверка условий синтеза принятого редуктора"))
    doc.p(t("1. The ratio (within the textbook's ±5 % unless another tolerance was set):",
            "1. Условие обеспечения передаточного отношения (с точностью, принятой в пособии, ±5 %):"))
    doc.formula(f'i = {_fr(ch.ratio_fraction)} = {q(ch.ratio, decimals=4)}', None)
    doc.formula(f'δ = (i/i_"{pl}" - 1) dot 100 % = '
                f'({q(ch.ratio, decimals=4)}/{q(ch.target, decimals=4)} - 1) dot 100 % = {q(ch.ratio_error_pct, decimals=2)} % ',
                None)
    multi = len(ch.stages) > 1
    for j, sc in enumerate(ch.stages, 1):
        st = sc.stage
        if multi:
            doc.p(t(f"Stage {j} ($i_{j} = {q(st.ratio, decimals=4)}$):", f"Ступень {j} ($i_{j} = {q(st.ratio, decimals=4)}$):"))
        zc2 = "z'_c" if st.z_planet2 is not None else "z_c"
        doc.p(t("2. Coaxiality:", "2. Условие соосности:"))
        doc.formula(f"z_k + z_c = {st.z_sun} + {st.z_planet} = {sc.coaxial_lhs}; quad z_n - {zc2} = {st.z_ring} - {st.zc2} = "
                    f"{sc.coaxial_rhs}", None)
        k = st.planets
        doc.p(t(f"3. Assembly (2.4) for $k = {k}$ planets:", f"3. Условие сборки (2.4) при $k = {k}$:"))
        if st.z_planet2 is None:
            doc.formula(f"(z_k + z_n)/k = ({st.z_sun} + {st.z_ring})/{k} = {q((st.z_sun + st.z_ring) / k, sig=4)}", "2.4")
        else:
            doc.formula(f"(z_k i^n_(k H))/k = {sc.assembly_book_n}/({sc.assembly_book_d} dot {k}) c; quad "
                        f"(z_k z'_c + z_c z_n)/(k gcd(z_c, z'_c)) = {sc.assembly_t}/({k} dot {sc.assembly_g}) = "
                        f"{q(sc.assembly_t / (k * sc.assembly_g), sig=4)}", "2.4")
            if sc.k_max != sc.k_max_book:
                doc.p(t(f"The exact condition (a double planet may be fitted turned by whole teeth) admits up to "
                        f"$k = {sc.k_max}$, the textbook's form up to $k = {sc.k_max_book}$.",
                        f"Точное условие (двойной сателлит можно установить с поворотом на целое число зубьев) "
                        f"допускает до $k = {sc.k_max}$, форма пособия — до $k = {sc.k_max_book}$."))
        zbig = max(st.z_planet, st.zc2)
        doc.p(t("4. Neighbouring (2.5):", "4. Условие соседства (2.5):"))
        doc.formula(f"sin π/{k} = {q(sc.neighbour_sin, decimals=4)} > (z_c + 2 h^*_a)/(z_k + z_c) = "
                    f"({zbig} + 2)/{st.z_sun + st.z_planet} = {q(sc.neighbour_q, decimals=4)}", "2.5")
        doc.p(t("5. No interference (Table 2.2 of [1]):", "5. Условие отсутствия интерференции (табл. 2.2 [1]):"))
        items = "; quad ".join(f"{_sym(i.symbol)} = {i.value} >= {i.limit}" for i in sc.interference)
        doc.formula(items, None)
        ok = sc.ok
        doc.p(t(f"All conditions hold{'' if ok else ' except those marked in the warnings'}; the assembly admits "
                f"$k = {', '.join(map(str, sc.assembly_ks_exact[:6]))}$ …, with the neighbouring condition "
                f"$k <= {sc.neighbour_limit}$, so {c.planets(k)} are taken.",
                f"Все условия {'выполняются' if ok else 'выполняются, кроме отмеченных в предупреждениях'}; условие "
                f"сборки допускает $k = {', '.join(map(str, sc.assembly_ks_exact[:6]))}$ …, условие соседства — "
                f"$k <= {sc.neighbour_limit}$; принято {c.planets(k)}."))


def _sym(symbol: str) -> str:
    """'z_n − z_c′' → typst math."""
    return symbol.replace("z_c′", "z'_c").replace("−", "-")


def _ratio_checks(c: Ctx) -> None:
    g = c.r.gears
    doc, t, q = c.doc, c.t, c.q
    ch = g.checks
    doc.h(2, t("Checking the ratio", "Проверка передаточного отношения"))
    doc.p(t("Analytically by (2.1), where $a = 1$ is the number of external meshes (for a single row $z'_c = z_c$):",
            "Аналитически по формуле (2.1), где $a = 1$ — число внешних зацеплений (для однорядного механизма "
            "$z'_c = z_c$):"))
    for j, (st, val) in enumerate(zip(g.planetary.stages, ch.ratio_formula_21), 1):
        zc2 = st.zc2
        idx = f"_{j}" if len(g.planetary.stages) > 1 else ""
        doc.formula(f"i{idx} = 1 - (-1)^a (z_c z_n)/(z_k z'_c) = 1 + ({st.z_planet} dot {st.z_ring})/({st.z_sun} dot {zc2}) = "
                    f"{q(val, decimals=4)}", "2.1")
    if len(ch.ratio_formula_21) > 1:
        doc.formula(f"i = i_1 i_2 = " + " dot ".join(q(x, decimals=4) for x in ch.ratio_formula_21)
                    + f" = {q(ch.ratio_formula_21_total, decimals=4)}", None)
    v = ch.velocity
    doc.p(t("Graphically by the velocity pictures (2.3): the ratio is the ratio of the tangents of the angles of the "
            f"sun's and the carrier's lines (Figure {{fig:gears_planetary}}):",
            "Графоаналитически по картинам скоростей (2.3): передаточное отношение равно отношению тангенсов углов "
            f"наклона линий распределения скоростей центрального колеса и водила (рисунок {{fig:gears_planetary}}):"))
    for j, s in enumerate(v.stages, 1):
        doc.formula(f'i = ("tg" φ_k)/("tg" φ_H) = ("tg" {c.qd(s.phi_k_deg, decimals=2)})/("tg" {c.qd(s.phi_h_deg, decimals=2)}) = '
                    f"{q(s.ratio, decimals=4)}", "2.3")
    doc.p(t("and on the angular-velocity picture by the segments cut by the rays of the sun and of the carrier:",
            "и по плану угловых скоростей — отношением отрезков, отсекаемых лучами центрального колеса и водила:"))
    doc.formula(f"i = (o k)/(o h) = {q(v.ok, decimals=2)}/{q(v.oh, decimals=2)} = {q(v.ratio, decimals=4)}", "2.3")
    c.fig("gears_planetary", t("Kinematic scheme of the planetary reducer and its velocity pictures",
                               "Кинематическая схема планетарного редуктора и картины скоростей"))
    k = g.planetary.planets
    doc.p(t(f"The assembly of the {k} planets is shown in Figure {{fig:gears_assembly}} (the angle between the planets "
            f"is $2β = 360°\\/k = {q(360 / k, sig=4)}°$).",
            f"Схема сборки редуктора с {k} сателлитами показана на рисунке {{fig:gears_assembly}} (угол между "
            f"сателлитами $2β = 360°\\/k = {q(360 / k, sig=4)}°$)."))
    c.fig("gears_assembly", t("Assembly of the planetary reducer", "Схема сборки планетарного редуктора"))


def _spur(c: Ctx) -> None:
    g = c.r.gears
    sp = g.spur
    doc, t, n, q = c.doc, c.t, c.n, c.q
    mm = t("mm", "мм")
    dd = t("d", "д")
    doc.h(2, t("The spur pair", "Расчёт простой зубчатой передачи"))
    doc.p(t(f"Zero gears (§2.3 of [1]): module $m = {q(sp.m_mm)}$ mm, pressure angle $α = {q(sp.alpha_deg)}°$, "
            f"$h^*_a = {q(sp.ha_star)}$, $c^* = {q(sp.c_star)}$, $x_1 = x_2 = 0$.",
            f"Передача из нулевых колёс (п. 2.3 [1]): модуль $m = {q(sp.m_mm)}$ мм, угол профиля "
            f"$α = {q(sp.alpha_deg)}°$, $h^*_a = {q(sp.ha_star)}$, $c^* = {q(sp.c_star)}$, $x_1 = x_2 = 0$."))
    doc.p(t("1–2. The ratio and the tooth numbers (the smaller gear has 17 teeth):",
            "1–2. Передаточное отношение и числа зубьев (меньшее колесо имеет 17 зубьев):"))
    if not sp.multiplier:
        doc.formula(f'i_"{dd}" = {q(sp.i_d, sig=4)}; quad z_1 = 17; quad z_2 = z_1 i_"{dd}" = 17 dot {q(sp.i_d, sig=4)} = '
                    f"{q(17 * sp.i_d, sig=4)} approx {sp.z2}; quad i = z_2/z_1 = {sp.z2}/{sp.z1} = {q(sp.i_actual, sig=4)}", None)
    else:
        doc.formula(f'i_"{dd}" = {q(sp.i_d, sig=4)} < 1; quad z_2 = 17; quad z_1 = z_2/i_"{dd}" = 17/{q(sp.i_d, sig=4)} = '
                    f"{q(17 / sp.i_d, sig=4)} approx {sp.z1}; quad i = z_2/z_1 = {sp.z2}/{sp.z1} = {q(sp.i_actual, sig=4)}", None)
    ca = math.cos(math.radians(sp.alpha_deg))
    m_ = q(sp.m_mm)
    mmu = c.u(mm)
    doc.p(t("3. Diameters of the pitch, base, tip and root circles:", "3. Диаметры делительных, основных, вершин и впадин:"))
    for i, z, dv, db, da, df in ((1, sp.z1, sp.d1_mm, sp.db1_mm, sp.da1_mm, sp.df1_mm), (2, sp.z2, sp.d2_mm, sp.db2_mm, sp.da2_mm, sp.df2_mm)):
        doc.formula(f"d_{i} = m z_{i} = {m_} dot {z} = {q(dv, decimals=2)} {mmu}; quad "
                    f"d_(b {i}) = d_{i} cos α = {q(dv, decimals=2)} dot {q(ca, decimals=4)} = {q(db, decimals=2)} {mmu}", None)
        doc.formula(f"d_(a {i}) = d_{i} + 2 h^*_a m = {q(dv, decimals=2)} + 2 dot {q(sp.ha_star)} dot {m_} = {q(da, decimals=2)} {mmu}; quad "
                    f"d_(f {i}) = d_{i} - 2(h^*_a + c^*) m = {q(df, decimals=2)} {mmu}", None)
    doc.p(t("4–10. Centre distance, pitches, tooth sizes:", "4–10. Межосевое расстояние, шаги и размеры зубьев:"))
    doc.formula(f"a = m(z_1 + z_2)/2 = {m_} dot ({sp.z1} + {sp.z2})/2 = {q(sp.a_mm, decimals=2)} {mmu}", None)
    doc.formula(f"p = π m = {q(sp.p_mm, decimals=3)} {mmu}; quad p_b = p cos α = {q(sp.pb_mm, decimals=3)} {mmu}; quad "
                f"s = e = (π m)/2 = {q(sp.s_mm, decimals=3)} {mmu}", None)
    doc.formula(f'τ_1 = (360 degree)/z_1 = "360°"/{sp.z1} = {c.qd(sp.tau1_deg, decimals=3)}; quad '
                f'τ_2 = "360°"/{sp.z2} = {c.qd(sp.tau2_deg, decimals=3)}', None)
    doc.formula(f"h = (2 h^*_a + c^*) m = {q(sp.h_mm, decimals=2)} {mmu}; quad h_d = 2 h^*_a m = {q(sp.hd_mm, decimals=2)} {mmu}; "
                f"quad C = c^* m = {q(sp.c_mm, decimals=2)} {mmu}", None)
    doc.p(t("11. Check:", "11. Проверка:"))
    doc.formula(f"a = d_(a 1)/2 + d_(f 2)/2 + C = {q(sp.da1_mm / 2, decimals=2)} + {q(sp.df2_mm / 2, decimals=2)} + "
                f"{q(sp.c_mm, decimals=2)} = {q(sp.check_a_12_mm, decimals=2)} {mmu}; quad "
                f"d_(a 1) - d_(f 1) = {q(sp.check_2h_1_mm, decimals=2)} = 2h", None)
    ok = t("the check holds", "проверка выполняется") if sp.check_ok else t("the check fails", "проверка не выполняется")
    doc.p(t(f"The centre distance and the tooth heights agree: {ok}.", f"Межосевое расстояние и высоты зубьев согласованы: {ok}."))
    if min(sp.z1, sp.z2) < sp.z_min_undercut:
        doc.p(t(f"With $α = 20°$ and $h^*_a = 1$ the undercut limit of a zero gear is $z_min = 2 h^*_a \\/ sin^2 α = "
                f"{q(sp.z_min_undercut, decimals=2)}$: the 17-tooth gear has a slight undercut of the root, which the "
                "textbook's rule $z >= 17$ accepts.",
                f"При $α = 20°$ и $h^*_a = 1$ предел подрезания нулевого колеса $z_min = 2 h^*_a \\/ sin^2 α = "
                f"{q(sp.z_min_undercut, decimals=2)}$: колесо с 17 зубьями имеет незначительный подрез ножки, "
                "допустимый по правилу пособия $z >= 17$."))
    doc.p(t("The transverse contact ratio is computed from the geometry (the active part $P_1 P_2$ of the line of "
            "action over the base pitch) instead of being measured on the drawing:",
            "Коэффициент торцевого перекрытия вычисляется по геометрии (активная линия зацепления $P_1 P_2$, "
            "отнесённая к основному шагу), а не измеряется на чертеже:"))
    doc.formula(f"g_α = sqrt(r_(a 1)^2 - r_(b 1)^2) + sqrt(r_(a 2)^2 - r_(b 2)^2) - a sin α = {q(sp.g_alpha_mm, decimals=2)} {mmu}; "
                f"quad ε_α = g_α/p_b = {q(sp.g_alpha_mm, decimals=2)}/{q(sp.pb_mm, decimals=3)} = {q(sp.eps_alpha, decimals=3)}", None)
    doc.formula(f"φ_(α 1) = ε_α τ_1 = {c.qd(sp.phi_alpha1_deg, decimals=2)}; quad φ_(α 2) = ε_α τ_2 = "
                f"{c.qd(sp.phi_alpha2_deg, decimals=2)}", None)
    eps = sp.eps_alpha
    share = (eps - 1) * 100
    doc.p(t(f"On the line of action the two double-pair zones $P_1 U_2 = U_1 P_2 = {q(sp.double_zone_mm, decimals=2)}$ mm "
            f"enclose the single-pair zone $U_2 U_1 = {q(sp.single_zone_mm, decimals=2)}$ mm. With $ε_α = "
            f"{q(eps, decimals=3)}$ two pairs of teeth are in mesh during {n(share, decimals=0)} % of the time of "
            "engagement of a tooth and one pair during the rest; "
            + ("since $ε_α >= 1,2$ the pair runs smoothly and quietly." if eps >= 1.2
               else "since $ε_α < 1,2$ the smoothness of the pair is reduced."),
            f"На линии зацепления зоны двухпарного зацепления $P_1 U_2 = U_1 P_2 = {q(sp.double_zone_mm, decimals=2)}$ мм "
            f"ограничивают зону однопарного зацепления $U_2 U_1 = {q(sp.single_zone_mm, decimals=2)}$ мм. При "
            f"$ε_α = {q(eps, decimals=3)}$ две пары зубьев находятся в зацеплении {n(share, decimals=0)} % времени "
            "зацепления одного зуба, остальное время — одна пара; "
            + ("так как $ε_α >= \"1,2\"$, передача работает плавно и бесшумно." if eps >= 1.2
               else "так как $ε_α < \"1,2\"$, плавность работы передачи снижена.")))
    c.fig("gears_mesh", t("Involute mesh of the spur pair", "Эвольвентное зацепление простой передачи"))
    if c.has("gears_mesh"):
        doc.p(t("The mesh with the line of action and the zones is shown in Figure {fig:gears_mesh}.",
                "Зацепление с линией зацепления и зонами показано на рисунке {fig:gears_mesh}."))


def _power(c: Ctx) -> None:
    g = c.r.gears
    doc, t, q = c.doc, c.t, c.q
    kr, dd = t("cr", "кр"), t("d", "д")
    doc.h(2, t("Power of the motor", "Потребная мощность двигателя"))
    if g.power is None:
        doc.p(t(f"The power of the motor (§2.6 of [1]) is $N_\"{dd}\" = M ω_\"{kr}\"\\/(η_1 η_2) dot 10^(-3)$ kW with "
                f"$η_1 = {q(g.eta1, sig=4)}$, $η_2 = {q(g.eta2)}$; the mean reduced moment M comes from sheet 2 and was not "
                "given, so the power is not computed here.",
                f"Потребная мощность двигателя (п. 2.6 [1]) $N_\"{dd}\" = M ω_\"{kr}\"\\/(η_1 η_2) dot 10^(-3)$ кВт при "
                f"$η_1 = {q(g.eta1, sig=4)}$, $η_2 = {q(g.eta2)}$; средний приведённый момент M определяется на 2-м "
                "листе проекта и в расчёт не передан, поэтому мощность здесь не вычислена."))
        return
    p = g.power
    doc.p(t("The power is the mean reduced moment of sheet 2 times the crank's angular speed, divided by the "
            "efficiencies of the reducer and the linkage (§2.6 of [1]):",
            "Потребная мощность — произведение среднего приведённого момента (2-й лист) на угловую скорость "
            "кривошипа с учётом КПД редуктора и рычажного механизма (п. 2.6 [1]):"))
    doc.formula(f'ω_"{kr}" = (π n_"{kr}")/30 = (π dot {q(g.crank_rpm)})/30 = {q(p.omega_cr_rad_s, decimals=3)} '
                f'{c.u(t("rad/s", "рад/с"))}', None)
    doc.formula(f'N_"{dd}" = (M ω_"{kr}")/(η_1 η_2) dot 10^(-3) = ({q(p.torque_nm, sig=5)} dot {q(p.omega_cr_rad_s, decimals=3)})/'
                f'({q(p.eta1, sig=4)} dot {q(p.eta2)}) dot 10^(-3) = {q(p.power_kw, decimals=3)} {c.u(t("kW", "кВт"))}', None)
    if p.rated_kw is not None:
        doc.p(t(f"A motor of the rated power {c.n(p.rated_kw)} kW at {g.motor_rpm} rpm is taken.",
                f"Принимается двигатель номинальной мощностью {c.n(p.rated_kw)} кВт с частотой вращения {g.motor_rpm} об/мин."))
    else:
        doc.p(t("The required power is above the largest motor of the standard series.",
                "Потребная мощность больше наибольшей в стандартном ряду."))
