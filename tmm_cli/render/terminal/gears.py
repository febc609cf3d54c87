"""Rich tables for sheet 4 in the order of the explanatory note (§2.2 → §2.6)."""

from __future__ import annotations

import math
from fractions import Fraction

from ...i18n.lang import pick
from ...i18n.numbers import num, plural

VARIANTS_RU = {"one": "вариант", "few": "варианта", "many": "вариантов", "other": "варианта"}
from .table import Table

OK = "✓"
FAIL = "✗"


def _ok(v: bool) -> str:
    return f"[green]{OK}[/]" if v else f"[red]{FAIL}[/]"


def _f(lang: str, x: float, nd: int = 3) -> str:
    """`x` with at most `nd` decimals, trailing zeros dropped; decimal comma under ru."""
    return num(round(float(x), nd), lang, sig=15, sci=False) if isinstance(x, float) else num(x, lang)


def _pct(lang: str, x: float) -> str:
    """A signed error in percent, "+1.25" / "−0.69"; one too small to show is "0.00", never "-0.00"."""
    text = num(x, lang, decimals=2)
    return text if text.startswith("-") or set(text) <= set("0,.") else "+" + text


def _frac(f: Fraction) -> str:
    return f"{f.numerator}/{f.denominator}" if f.denominator != 1 else f"{f.numerator}"


def _table(title: str, *cols: str, left: tuple[int, ...] = (0,)):
    t = Table(title=title, title_style="bold")
    for i, c in enumerate(cols):
        t.add_column(c, justify="left" if i in left else "right")
    return t


def _rot(lang: str, sense: str) -> str:
    return pick(lang, "counter-clockwise" if sense == "ccw" else "clockwise",
                "против часовой стрелки" if sense == "ccw" else "по часовой стрелке")


def _relative(lang: str, sense: str, motor: str) -> str:
    return pick(lang, " (as the motor)", " (как двигатель)") if sense == motor else \
        pick(lang, " (against the motor)", " (против двигателя)")


def _teeth_labels(lang: str, double: bool) -> list[str]:
    return ["z_k", "z_c", "z_c′", "z_n"] if double else ["z_k", "z_c", "z_n"]


def _print_motor(console, r, lang):
    t = _table(pick(lang, "Motor (§2.2, §2.6)", "Двигатель (п. 2.2, 2.6)"), pick(lang, "Quantity", "Величина"),
               pick(lang, "Value", "Значение"))
    t.add_row(pick(lang, "Crank speed n_cr, rpm", "Частота вращения кривошипа n_кр, об/мин"),
              _f(lang, r.crank_rpm) + (pick(lang, " (assumed, §2.4)", " (принято, п. 2.4)") if r.crank_rpm_assumed else ""))
    t.add_row(pick(lang, "Cam speed n_k, rpm", "Частота вращения кулачка n_к, об/мин"), _f(lang, r.cam_rpm))
    t.add_row(pick(lang, "Rule n_d ≥ 3·n_cr, rpm", "Условие n_д ≥ 3·n_кр, об/мин"), f"≥ {_f(lang, 3 * r.crank_rpm)}")
    t.add_row(pick(lang, "Standard speeds, rpm", "Стандартные частоты, об/мин"),
              ", ".join(f"[bold]{n}[/]" if n == r.motor_rpm else str(n) for n in r.motor_candidates))
    t.add_row(pick(lang, "Motor speed n_d, rpm", "Частота вращения двигателя n_д, об/мин"), f"[bold]{r.motor_rpm}[/]")
    if r.power is not None:
        p = r.power
        t.add_row(pick(lang, "Mean reduced moment M, N·m", "Приведённый момент M_пр, Н·м"), _f(lang, p.torque_nm))
        t.add_row("ω_кр = π·n_кр/30, " + pick(lang, "rad/s", "рад/с"), _f(lang, p.omega_cr_rad_s, 3))
        t.add_row("η1 · η2", f"{_f(lang, p.eta1, 4)} · {_f(lang, p.eta2, 2)}")
        t.add_row(pick(lang, "Power N = M·ω/(η1·η2)·10⁻³, kW (2.6)", "Мощность N_д = M·ω/(η1·η2)·10⁻³, кВт (2.6)"),
                  _f(lang, p.power_kw, 3))
        t.add_row(pick(lang, "Rated motor power, kW", "Мощность двигателя по ряду, кВт"),
                  f"[bold]{_f(lang, p.rated_kw, 2)}[/]" if p.rated_kw is not None else "—")
    else:
        t.add_row(pick(lang, "Power (2.6)", "Мощность (2.6)"),
                  pick(lang, "give the moment M (--torque)", "задайте момент M (--torque)"))
    console.print(t)


def _print_ratios(console, r, lang):
    t = _table(pick(lang, "Ratios and rotation", "Передаточные отношения и направления вращения"),
               pick(lang, "Mechanism", "Механизм"), pick(lang, "Formula", "Формула"), pick(lang, "Required", "Требуемое"),
               pick(lang, "Realised", "Полученное"), pick(lang, "Output turns", "Ведомое звено вращается"), left=(0, 1, 4))
    d = r.directions
    # one convention with results.json: a ratio is n_in/n_out as a magnitude; the senses of
    # rotation stand in their own column (the external pair reverses, the reducer keeps the sense)
    t.add_row(pick(lang, "Spur pair motor → cam", "Простая передача двигатель → кулачок"), "i_д = n_д/|n_к|",
              _f(lang, r.i_spur, 4), f"{_f(lang, abs(d.i_spur_signed), 4)} (z2/z1)",
              pick(lang, "cam: ", "кулачок: ") + _rot(lang, d.cam) + _relative(lang, d.cam, d.motor))
    t.add_row(pick(lang, "Planetary reducer motor → crank", "Планетарный редуктор двигатель → кривошип"),
              "i_пл = n_д/n_кр", _f(lang, r.i_planetary, 4), _f(lang, abs(d.i_planetary_signed), 4),
              pick(lang, "crank: ", "кривошип: ") + _rot(lang, d.crank) + _relative(lang, d.crank, d.motor))
    t.add_row(pick(lang, "Motor", "Двигатель"), "", "", "", _rot(lang, d.motor))
    console.print(t)


def _print_schemes(console, r, lang):
    t = _table(pick(lang, "Scheme choice (Fig. 2.4, §2.2)", "Выбор схемы (рис. 2.4, п. 2.2)"), "№",
               pick(lang, "Ratio range", "Диапазон i"), "η", pick(lang, "Ratio formula", "Формула i"),
               pick(lang, "Coaxiality", "Соосность"), pick(lang, "Chosen", "Выбор"), left=(0, 3, 4, 5))
    reason = {
        "le8": pick(lang, f"i_pl = {_f(lang, r.i_planetary, 3)} ≤ 8", f"i_пл = {_f(lang, r.i_planetary, 3)} ≤ 8"),
        "8to16": pick(lang, f"8 < i_pl = {_f(lang, r.i_planetary, 3)} ≤ 16", f"8 < i_пл = {_f(lang, r.i_planetary, 3)} ≤ 16"),
        "gt16": pick(lang, f"i_pl = {_f(lang, r.i_planetary, 3)} > 16: two stages, i1 ≈ √i_pl = {_f(lang, math.sqrt(r.i_planetary), 2)}",
                     f"i_пл = {_f(lang, r.i_planetary, 3)} > 16: две ступени, i1 ≈ √i_пл = {_f(lang, math.sqrt(r.i_planetary), 2)}"),
    }[r.scheme_reason]
    for s in r.schemes:
        chosen = s.key == r.scheme
        if chosen:
            mark = f"[bold green]◀ {reason}[/]"
        elif s.number in (4, 5):
            mark = pick(lang, "low η, for large i", "низкий КПД, для больших i")
        else:
            mark = ""
        t.add_row(str(s.number), f"{_f(lang, s.i_min)} … {_f(lang, s.i_max)}", f"{_f(lang, s.eta_max, 2)} … {_f(lang, s.eta_min, 2)}",
                  s.formula, s.coaxial, mark)
    console.print(t)


def _print_book_stage(console, st, lang, title):
    if st.scheme == "1":
        c = st.chosen
        t = _table(title, pick(lang, "Step", "Шаг"), pick(lang, "Computation", "Расчёт"), left=(0, 1))
        t.add_row("1", f"i = {_frac(st.fraction)};  z_n/z_k = i − 1 = {_frac(st.reduced)} = D/A;  D = {c.d}, A = {c.a}")
        t.add_row("2", f"z_c = (z_n − z_k)/2 = (D − A)/2·y = {_frac(Fraction(c.d - c.a, 2))}·y")
        t.add_row("3", f"z_k = {c.a}y,  z_c = {_frac(c.base[1])}y,  z_n = {c.d}y")
        t.add_row("4", f"{c.a}y ≥ 17;  {_frac(c.base[1])}y ≥ 20;  {c.d}y ≥ 85 → y_min = {_frac(c.y_min)}"
                  + pick(lang, " (all whole)", " (все целые)"))
        t.add_row("", f"[bold]z_k = {c.teeth[0]}, z_c = {c.teeth[1]}, z_n = {c.teeth[2]}[/]")
    else:
        t = _table(title, pick(lang, "Step", "Шаг"), pick(lang, "Computation", "Расчёт"), left=(0, 1))
        red = st.reduced
        t.add_row("1", f"i = {_frac(st.fraction)};  (z_c·z_n)/(z_k·z_c′) = i − 1 = {_frac(red)} = (B·D)/(A·E)")
        t.add_row("2", "1 < B/A ≤ 5;  2 < D/E ≤ 5")
        if st.x1_range:
            t.add_row("", f"B/A = x1/{red.denominator}, D/E = {red.numerator}/x1 → {st.x1_range[0]} ≤ x1 ≤ {st.x1_range[1]}")
        if st.x2_range:
            t.add_row("", f"B/A = {red.numerator}/x2, D/E = x2/{red.denominator} → {st.x2_range[0]} ≤ x2 ≤ {st.x2_range[1]}")
        t.add_row("3", "z_k = A(D − E)y;  z_c = B(D − E)y;  z_c′ = E(A + B)y;  z_n = D(A + B)y")
        t.add_row("4", "z_k ≥ 17;  z_c ≥ 17;  z_c′ ≥ 20;  z_n ≥ 85 → y_min;  Γ1 = z_k + 2z_c,  Γ2 = z_n")
        console.print(t)
        for tab, xname, lab in (("2.3", "x1", pick(lang, "Table 2.3 (x1 rows)", "Таблица 2.3 (x1)")),
                                ("2.4x2", "x2", pick(lang, "Table 2.4 (x2 rows; the book heads it x1)",
                                                     "Таблица 2.4 (x2; в пособии столбец ошибочно назван x1)"))):
            rows = [rw for rw in st.rows if rw.table == tab]
            if not rows:
                continue
            tt = _table(lab, xname, "(B/A)·(D/E)", "y_min", "z_k", "z_c", "z_c′", "z_n", "Γ1", "Γ2")
            for rw in rows:
                best = rw is st.chosen
                style = "bold green" if best else None
                tt.add_row(str(rw.x), f"({rw.b}/{rw.a})·({rw.d}/{rw.e})", _frac(rw.y_min),
                           *(str(z) for z in rw.teeth), str(rw.gamma1), str(rw.gamma2), style=style)
            console.print(tt)
        c = st.chosen
        t = _table("", pick(lang, "Step", "Шаг"), pick(lang, "Computation", "Расчёт"), left=(0, 1))
        t.add_row("5", pick(lang, "smallest max(Γ1, Γ2): ", "наименьший max(Γ1, Γ2): ")
                  + f"{'x1' if c.table == '2.3' else 'x2'} = {c.x}: [bold]z_k = {c.teeth[0]}, z_c = {c.teeth[1]}, "
                  f"z_c′ = {c.teeth[2]}, z_n = {c.teeth[3]}[/], Γ1 = {c.gamma1}, Γ2 = {c.gamma2}")
    zk = st.chosen.teeth[0]
    ks = ", ".join(str(k) for k in st.assembly_ks[:8]) + (" …" if len(st.assembly_ks) > 8 else "")
    t.add_row(pick(lang, "assembly", "сборка"),
              f"z_k·i/k·c = {zk}·{_frac(st.fraction)}/k·c = {st.assembly_n}/({st.assembly_c}·k)·c, c = {st.assembly_c} → k = {ks}")
    t.add_row(pick(lang, "neighbours", "соседство"),
              f"sin(π/k) > {_f(lang, st.neighbour_q, 3)} → k ≤ {st.neighbour_limit}"
              + pick(lang, " (computed exactly, not read from Table 2.1)", " (точно, а не по табл. 2.1)"))
    t.add_row(pick(lang, "k_max", "k_наиб"), f"[bold]{st.k_max}[/]" + (pick(lang, f"  (exact assembly condition: {st.k_max_exact})",
                                                        f"  (по точному условию сборки: {st.k_max_exact})")
                                                  if st.k_max_exact != st.k_max else ""))
    console.print(t)


def _print_book(console, r, lang):
    d = r.derivation
    if d is None:
        return
    sec = {"1": "§2.4", "2": "§2.5", "1+1": "§2.2, §2.4"}[d.scheme]
    rule = pick(lang, "the fraction given by the user", "дробь задана пользователем") if d.fraction_rule == "forced" else \
        pick(lang, "of the simple fractions (denominator ≤ 10) within tolerance, the one giving the smallest reducer",
             "из простых дробей (знаменатель ≤ 10) в пределах допуска — дающая наименьший редуктор")
    if d.fraction_rule == "exact":
        rule = pick(lang, "i_pl is itself a simple fraction, so the procedure starts from it (exact ratio)",
                    "i_пл само является простой дробью — расчёт начинается с неё (точное передаточное отношение)")
    console.print(f"[bold]{pick(lang, 'The book’s hand procedure', 'Ручная методика пособия')} ({sec})[/] — {rule}")
    if d.fraction_rule == "simple" and len(d.tried) > 1:
        tried = ", ".join(f"{f}→{n}" for f, n in sorted(d.tried, key=lambda x: x[1])[:10])
        console.print(pick(lang, f"  fractions tried (→ size): {tried}", f"  рассмотренные дроби (→ габарит): {tried}"))
    for j, st in enumerate(d.stages, 1):
        title = pick(lang, f"Stage {j}", f"Ступень {j}") if len(d.stages) > 1 else \
            pick(lang, "Derivation", "Расчёт")
        _print_book_stage(console, st, lang, title)
    if r.printed is not None:
        p = r.printed
        t = _table(pick(lang, f"The book’s printed answer (§{p.section}) rechecked",
                        f"Проверка ответа пособия (п. {p.section})"),
                   pick(lang, "Teeth", "Числа зубьев"), pick(lang, "Coaxiality", "Соосность"),
                   pick(lang, "Ratio", "Передаточное отношение"), left=(0, 1, 2))
        t.add_row("/".join(map(str, p.stage.teeth)), f"{p.coaxial_lhs} {'=' if p.coaxial_ok else '≠'} {p.coaxial_rhs} {_ok(p.coaxial_ok)}",
                  f"{_f(lang, p.ratio, 3)} {'=' if p.ratio_ok else '≠'} {_frac(p.fraction)} {_ok(p.ratio_ok)}")
        console.print(t)


def _print_search(console, r, lang):
    s = r.search
    double = r.scheme == "2"
    rule = {
        "smallest_3plus": pick(lang, "smallest with ≥ 3 planets", "наименьший с k ≥ 3"),
        "smallest_no3": pick(lang, "none takes 3 planets: the smallest", "k ≥ 3 невозможно: наименьший"),
        "forced_planets": pick(lang, f"smallest taking k = {s.forced_planets}", f"наименьший с k = {s.forced_planets}"),
    }[s.rule]
    if getattr(s, "select", "smallest") == "accurate":
        rule += pick(lang, ", then the most accurate ratio within one tooth of it",
                     ", затем самое точное отношение при габарите не более чем на 1 зуб больше")
    title = pick(lang, f"Exhaustive search: {s.n_sets} candidates within ±{_f(lang, s.tolerance_pct)} %, "
                       f"every wheel ≤ {s.z_max} teeth; size = max(Γ1, Γ2) = max(z_k + 2z_c, z_n); rule: {rule}",
                 f"Полный перебор: {plural(s.n_sets, lang, VARIANTS_RU)} в пределах ±{_f(lang, s.tolerance_pct)} %, все колёса ≤ {s.z_max} "
                 f"зубьев; габарит = max(Γ1, Γ2) = max(z_k + 2z_c, z_n); правило: {rule}")
    if r.scheme == "1+1":
        cols = [pick(lang, "Stage 1", "Ступень 1") + " z_k/z_c/z_n", pick(lang, "Stage 2", "Ступень 2") + " z_k/z_c/z_n"]
    else:
        cols = _teeth_labels(lang, double)
    t = _table(title, *cols, "i", pick(lang, "error, %", "ошибка, %"), pick(lang, "size", "габарит"), "k", "")
    for a in s.alternatives:
        carried = a == r.planetary
        if r.scheme == "1+1":
            cells = ["/".join(map(str, st.teeth)) + f" (i={_f(lang, st.ratio, 3)}, k={st.planets})" for st in a.stages]
        else:
            cells = [str(z) for z in a.stages[0].teeth]
        t.add_row(*cells, _f(lang, a.ratio, 4), _pct(lang, a.ratio_error_pct), str(a.size), str(a.planets),
                  pick(lang, "◀ carried", "◀ принят") if carried else "", style="bold green" if carried else None)
    console.print(t)


def _print_conditions(console, r, lang):
    ch = r.checks
    t = _table(pick(lang, "The five conditions of synthesis (§2.1.3) for the carried reducer",
                    "Пять условий синтеза (п. 2.1.3) для принятого редуктора"),
               pick(lang, "Condition", "Условие"), pick(lang, "Numbers", "Расчёт"), "", left=(0, 1))
    t.add_row(pick(lang, "1. Ratio", "1. Передаточное отношение"),
              f"i = {_frac(ch.ratio_fraction)} = {_f(lang, ch.ratio, 4)};  i_пл = {_f(lang, ch.target, 4)};  "
              f"{_pct(lang, ch.ratio_error_pct)} % (±{_f(lang, ch.tolerance_pct)} %)", _ok(ch.ratio_ok))
    multi = len(ch.stages) > 1
    for j, c in enumerate(ch.stages, 1):
        st = c.stage
        pre = (pick(lang, f"st. {j}: ", f"ст. {j}: ") if multi else "")
        zc2 = "z_c′" if st.z_planet2 is not None else "z_c"
        t.add_row(pre + pick(lang, "2. Coaxiality", "2. Соосность"),
                  f"z_k + z_c = {st.z_sun} + {st.z_planet} = {c.coaxial_lhs};  z_n − {zc2} = {st.z_ring} − {st.zc2} = {c.coaxial_rhs}",
                  _ok(c.coaxial_ok))
        k = st.planets
        if st.z_planet2 is None:
            exact = f"(z_k + z_n)/k = {st.z_sun + st.z_ring}/{k} = {_f(lang, (st.z_sun + st.z_ring) / k, 3)}"
        else:
            exact = (f"(z_k·z_c′ + z_c·z_n)/(k·gcd(z_c, z_c′)) = {c.assembly_t}/({k}·{c.assembly_g}) = "
                     f"{_f(lang, c.assembly_t / (k * c.assembly_g), 3)}")
        t.add_row(pre + pick(lang, "3. Assembly (exact)", "3. Сборка (точное)"), exact, _ok(c.assembly_exact_ok))
        book = (f"z_k·i = {c.assembly_book_n}/{c.assembly_book_d}; N/k = {c.assembly_book_n}/{k} = "
                f"{_f(lang, c.assembly_book_n / k, 3)}")
        differ = ""
        if c.k_max != c.k_max_book:
            differ = pick(lang, f"  — forms differ: exact k ≤ {c.k_max}, book k ≤ {c.k_max_book}",
                          f"  — формы различаются: точное k ≤ {c.k_max}, пособие k ≤ {c.k_max_book}")
        t.add_row(pre + pick(lang, "   book's form (2.4)", "   форма пособия (2.4)"), book + differ, _ok(c.assembly_book_ok))
        zbig = max(st.z_planet, st.zc2)
        t.add_row(pre + pick(lang, "4. Neighbours (2.5)", "4. Соседство (2.5)"),
                  f"sin(π/{k}) = {_f(lang, c.neighbour_sin, 4)} > (z_c + 2h_a*)/(z_k + z_c) = ({zbig} + 2)/{st.z_sun + st.z_planet}"
                  f" = {_f(lang, c.neighbour_q, 4)};  k ≤ {c.neighbour_limit}", _ok(c.neighbour_ok))
        items = ";  ".join(f"{i.symbol} = {i.value} ≥ {i.limit}" for i in c.interference)
        t.add_row(pre + pick(lang, "5. No interference (Table 2.2)", "5. Отсутствие интерференции (табл. 2.2)"), items,
                  _ok(c.interference_ok))
        t.add_row(pre + pick(lang, "Planets", "Число сателлитов"),
                  pick(lang, f"assembly admits k = {', '.join(map(str, c.assembly_ks_exact[:8]))}…; with neighbours k_max = {c.k_max}",
                       f"сборка допускает k = {', '.join(map(str, c.assembly_ks_exact[:8]))}…; с учётом соседства k_наиб = {c.k_max}")
                  + (pick(lang, f"; carried k = {k}", f"; принято k = {k}") if k != c.k_max else ""), "")
    console.print(t)


def _print_ratio_checks(console, r, lang):
    ch = r.checks
    v = ch.velocity
    t = _table(pick(lang, "Ratio check", "Проверка передаточного отношения"), pick(lang, "Method", "Способ"),
               pick(lang, "Computation", "Расчёт"), "i", left=(0, 1))
    per = "·".join(_f(lang, x, 4) for x in ch.ratio_formula_21)
    t.add_row(pick(lang, "Analytic (2.1)", "Аналитический (2.1)"),
              "i = 1 − (−1)^a·(z_c·z_n)/(z_k·z_c′), a = 1" + (f";  {per}" if len(ch.ratio_formula_21) > 1 else ""),
              _f(lang, ch.ratio_formula_21_total, 4))
    for j, s in enumerate(v.stages, 1):
        lab = pick(lang, f"Velocity picture, stage {j}", f"Картина скоростей, ступень {j}") if len(v.stages) > 1 else \
            pick(lang, "Velocity picture (2.3)", "Графоаналитический (2.3)")
        t.add_row(lab, f"tg φ_k / tg φ_H = tg {_f(lang, s.phi_k_deg, 2)}° / tg {_f(lang, s.phi_h_deg, 2)}°", _f(lang, s.ratio, 4))
    t.add_row(pick(lang, "Angular-velocity picture", "План угловых скоростей"),
              f"ok/oh = {_f(lang, v.ok, 2)}/{_f(lang, v.oh, 2)}", _f(lang, v.ratio, 4))
    console.print(t)


def _shift_text(g, lang: str) -> str:
    """"x1 = x2 = 0" for the book's zero pair, else the shifts (beyond the book)."""
    if not getattr(g, "shifted", False):
        return "x1 = x2 = 0"
    return f"x1 = {_f(lang, g.x1, 4)}, x2 = {_f(lang, g.x2, 4)}, a_w = {_f(lang, g.a_w_mm, 3)}"


def _print_spur_shift(console, r, lang):
    """The shifted spur pair (beyond the book): its geometry and the blocking-contour checks."""
    g = r.spur
    if not getattr(g, "shifted", False):
        return
    from .planetary import checks_table, pair_table

    console.print(pair_table(g.pair, ("1", "2"), lang, pick(lang, "Spur pair with profile shift (beyond the book)",
                                                             "Простая передача со смещением (сверх пособия)")))
    console.print(checks_table(g.blocking, ("1", "2"), (g.z1, g.z2), g.m_mm, lang,
                               pick(lang, "Blocking contour of the spur pair", "Блокирующий контур простой передачи")))


def _print_spur(console, r, lang):
    g = r.spur
    t = _table(pick(lang, f"Spur pair (§2.3): z1 = {g.z1}, z2 = {g.z2}, m = {_f(lang, g.m_mm)} mm, α = {_f(lang, g.alpha_deg)}°, "
                          f"h_a* = {_f(lang, g.ha_star)}, c* = {_f(lang, g.c_star)}, {_shift_text(g, lang)}",
                    f"Простая передача (п. 2.3): z1 = {g.z1}, z2 = {g.z2}, m = {_f(lang, g.m_mm)} мм, α = {_f(lang, g.alpha_deg)}°, "
                    f"h_a* = {_f(lang, g.ha_star)}, c* = {_f(lang, g.c_star)}, {_shift_text(g, lang)}"),
               pick(lang, "Item", "Пункт"), pick(lang, "Formula", "Формула"), pick(lang, "Gear 1", "Колесо 1"),
               pick(lang, "Gear 2", "Колесо 2"), left=(0, 1))
    mm = pick(lang, "mm", "мм")
    sh = getattr(g, "shifted", False)
    rows = [
        ("2", pick(lang, "teeth", "числа зубьев"),
         "z1 = 17" if g.z1 == 17 else pick(lang, "z1 = round(17/i_d)", "z1 = округл.(17/i_д)"), str(g.z1), str(g.z2)),
        ("3", pick(lang, f"pitch diameter, {mm}", f"делительный диаметр, {mm}"), "d = m·z", _f(lang, g.d1_mm, 2), _f(lang, g.d2_mm, 2)),
        ("3", pick(lang, f"base diameter, {mm}", f"основной диаметр, {mm}"), "d_b = d·cos α", _f(lang, g.db1_mm, 2), _f(lang, g.db2_mm, 2)),
        ("3", pick(lang, f"tip diameter, {mm}", f"диаметр вершин, {mm}"), "d_a = d + 2(h_a* + x − Δy)m" if sh else "d_a = d + 2h_a*·m", _f(lang, g.da1_mm, 2), _f(lang, g.da2_mm, 2)),
        ("3", pick(lang, f"root diameter, {mm}", f"диаметр впадин, {mm}"), "d_f = d − 2(h_a* + c* − x)m" if sh else "d_f = d − 2(h_a* + c*)m", _f(lang, g.df1_mm, 2), _f(lang, g.df2_mm, 2)),
        ("4", pick(lang, f"{'reference ' if sh else ''}centre distance, {mm}",
                    f"{'делительное ' if sh else ''}межосевое расстояние, {mm}"), "a = m(z1 + z2)/2", _f(lang, g.a_mm, 2), ""),
    ] + ([("4", pick(lang, f"working centre distance, {mm}", f"межосевое расстояние, {mm}"), "a_w = a·cos α/cos α_w",
           _f(lang, g.a_w_mm, 3), "")] if sh else []) + [
        ("5", pick(lang, f"pitch / base pitch, {mm}", f"шаг / основной шаг, {mm}"), "p = π·m;  p_b = p·cos α",
         _f(lang, g.p_mm, 3), _f(lang, g.pb_mm, 3)),
        ("6", pick(lang, f"tooth thickness = space, {mm}", f"толщина зуба = ширина впадины, {mm}"), "s = e = π·m/2",
         _f(lang, g.s_mm, 3), _f(lang, g.e_mm, 3)) if not sh else
        ("6", pick(lang, f"tooth thickness, {mm}", f"толщина зуба, {mm}"), "s = m(π/2 + 2x·tg α)",
         _f(lang, g.pair.s_mm[0], 3), _f(lang, g.pair.s_mm[1], 3)),
        ("7", pick(lang, "angular pitch, °", "угловой шаг, °"), "τ = 360/z", _f(lang, g.tau1_deg, 3), _f(lang, g.tau2_deg, 3)),
        ("8", pick(lang, f"tooth height, {mm}", f"высота зуба, {mm}"), "h = (2h_a* + c* − Δy)m" if sh else "h = (2h_a* + c*)m", _f(lang, g.h_mm, 2), ""),
        ("9", pick(lang, f"depth of engagement, {mm}", f"глубина захода, {mm}"), "h_d = (2h_a* − Δy)m" if sh else "h_d = 2h_a*·m", _f(lang, g.hd_mm, 2), ""),
        ("10", pick(lang, f"clearance, {mm}", f"радиальный зазор, {mm}"), "C = c*·m", _f(lang, g.c_mm, 2), ""),
        ("", pick(lang, f"root fillet radius, {mm}", f"радиус переходной кривой, {mm}"), "0.38·m", _f(lang, g.fillet_mm, 2), ""),
    ]
    for item, name, formula, a, b in rows:
        t.add_row(f"{item} {name}".strip(), formula, a, b)
    console.print(t)
    c = _table(pick(lang, "Check, item 11", "Проверка, пункт 11"), pick(lang, "Expression", "Выражение"),
               pick(lang, "Value, mm", "Значение, мм"), "")
    a = g.a_w_mm or g.a_mm  # the working centre distance (= a for a zero pair)
    c.add_row("(d1 + d2)/2" if not getattr(g, "shifted", False) else "(d_w1 + d_w2)/2", _f(lang, g.check_a_pitch_mm, 3), _ok(abs(g.check_a_pitch_mm - a) < 1e-6))
    c.add_row("d_a1/2 + d_f2/2 + C", _f(lang, g.check_a_12_mm, 3), _ok(abs(g.check_a_12_mm - a) < 1e-6))
    c.add_row("d_a2/2 + d_f1/2 + C", _f(lang, g.check_a_21_mm, 3), _ok(abs(g.check_a_21_mm - a) < 1e-6))
    c.add_row("d_a1 − d_f1 = 2h", f"{_f(lang, g.check_2h_1_mm, 3)} = {_f(lang, 2 * g.h_mm, 3)}", _ok(abs(g.check_2h_1_mm - 2 * g.h_mm) < 1e-6))
    c.add_row("d_a2 − d_f2 = 2h", f"{_f(lang, g.check_2h_2_mm, 3)} = {_f(lang, 2 * g.h_mm, 3)}", _ok(abs(g.check_2h_2_mm - 2 * g.h_mm) < 1e-6))
    console.print(c)
    e = _table(pick(lang, "Contact ratio and zones on the line of action (Fig. 2.3), from N1, mm",
                    "Коэффициент перекрытия и зоны на линии зацепления (рис. 2.3), от N1, мм"),
               pick(lang, "Quantity", "Величина"), pick(lang, "Value", "Значение"))
    e.add_row("α_w, °", _f(lang, g.alpha_w_deg, 2))
    e.add_row("N1N2 = a·sin α_w", _f(lang, g.n1n2_mm, 2))
    e.add_row(pick(lang, "P (pole)", "P (полюс)"), _f(lang, g.pole_mm, 2))
    e.add_row("P1, U2, U1, P2", f"{_f(lang, g.p1_mm, 2)}, {_f(lang, g.u2_mm, 2)}, {_f(lang, g.u1_mm, 2)}, {_f(lang, g.p2_mm, 2)}")
    e.add_row(pick(lang, "active line P1P2 = g_α", "активная линия P1P2 = g_α"), _f(lang, g.g_alpha_mm, 2))
    e.add_row(pick(lang, "double-pair zones P1U2 = U1P2", "зоны двухпарного зацепления P1U2 = U1P2"), _f(lang, g.double_zone_mm, 2))
    e.add_row(pick(lang, "single-pair zone U2U1", "зона однопарного зацепления U2U1"), _f(lang, g.single_zone_mm, 2))
    e.add_row("ε_α = g_α/p_b", f"[bold]{_f(lang, g.eps_alpha, 3)}[/] " + (_ok(True) if g.eps_alpha >= 1.2 else "[yellow]< 1.2[/]"))
    e.add_row("φ_α1 = ε_α·τ1, °", f"{_f(lang, g.phi_alpha1_deg, 2)}  (g_α/r_b1 = {_f(lang, g.phi_alpha1_geom_deg, 2)})")
    e.add_row("φ_α2 = ε_α·τ2, °", f"{_f(lang, g.phi_alpha2_deg, 2)}  (g_α/r_b2 = {_f(lang, g.phi_alpha2_geom_deg, 2)})")
    console.print(e)


_SUP = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def _sci(lang: str, x: float, nd: int = 3) -> str:
    """4.074·10⁴ style (the paper's way of printing stiffness)."""
    if x == 0 or not math.isfinite(x):
        return f"{x:g}"
    e = math.floor(math.log10(abs(x)))
    mant = x / 10 ** e
    if round(abs(mant), nd) >= 10:
        mant, e = mant / 10, e + 1
    return f"{num(mant, lang, decimals=nd)}·10{str(e).translate(_SUP)}"


def _print_stiffness(console, r, lang):
    """Beyond the course (`--stiffness`): the spur pair's mesh stiffness after Tarasik's paper, informative."""
    st = getattr(r, "spur_stiffness", None)
    if st is None:
        return
    s = st.mesh
    t = _table(pick(lang, "Mesh stiffness (beyond the course, informative): V. P. Tarasik's method",
                    "Жёсткость зацепления (сверх программы курса, справочно): методика В. П. Тарасика"),
               pick(lang, "Quantity", "Величина"), pick(lang, "Formula", "Формула"), pick(lang, "Gear 1", "Колесо 1"),
               pick(lang, "Gear 2", "Колесо 2"), left=(0, 1))
    mm, um = pick(lang, "mm", "мм"), pick(lang, "μm", "мкм")
    nmr = pick(lang, "N·m/rad", "Н·м/рад")
    spec = pick(lang, "N/(mm·μm)", "Н/(мм·мкм)")
    cb = pick(lang, "c_b", "c_и")
    rows = [
        (pick(lang, f"face width b_w, {mm}", f"ширина венца b_w, {mm}"), f"ψ_m·m = {_f(lang, st.psi_m)}·m",
         _f(lang, s.b_w_m * 1e3, 2), ""),
        (pick(lang, "moment on gear 1 M1, N·m", "момент на колесе 1 M1, Н·м"),
         pick(lang, "motor torque N/ω_d" if st.load == "motor" else "nominal (q of the paper)",
              "момент двигателя N/ω_д" if st.load == "motor" else "условный (q из статьи)"), _f(lang, s.torque1_nm, 2), ""),
        (pick(lang, "tangential force F, N", "окружная сила F, Н"), "F = M1/r_d1", _f(lang, s.force_n, 1), ""),
        (pick(lang, "line load q, N/mm", "погонная нагрузка q, Н/мм"), "q = F/b_w", _f(lang, s.line_load_n_per_m * 1e-3, 3), ""),
        (pick(lang, f"tooth thickness at tip s_a, {mm}", f"толщина зуба на вершине s_a, {mm}"), "(1)–(3)",
         _f(lang, s.s_a_m[0] * 1e3, 3), _f(lang, s.s_a_m[1] * 1e3, 3)),
        (pick(lang, f"… at pitch circle s_d, {mm}", f"… на делительной окружности s_d, {mm}"), "(1)",
         _f(lang, s.s_d_m[0] * 1e3, 3), _f(lang, s.s_d_m[1] * 1e3, 3)),
        (pick(lang, f"… at base circle s_b, {mm}", f"… на основной окружности s_b, {mm}"), "(1)",
         _f(lang, s.s_b_m[0] * 1e3, 3), _f(lang, s.s_b_m[1] * 1e3, 3)),
        (pick(lang, f"involute curvature ρ at pitch circle, {mm}", f"радиус кривизны эвольвенты ρ, {mm}"),
         "ρ = r_b·tg α_x (17)", _f(lang, s.rho_m[0] * 1e3, 3), _f(lang, s.rho_m[1] * 1e3, 3)),
        (pick(lang, f"bending deflection y at pitch circle, {um}", f"прогиб зуба y на делит. окружности, {um}"),
         "(9)–(11)", num(s.y_bend_m[0] * 1e6, lang, sig=4), num(s.y_bend_m[1] * 1e6, lang, sig=4)),
        (pick(lang, f"contact deformation y_H, {um}", f"контактная деформация y_H, {um}"), pick(lang, "Nakhatakyan (16)",
                                                                                          "Нахатакян (16)"),
         num(s.y_contact_m * 1e6, lang, sig=4), ""),
        (pick(lang, f"bending stiffness {cb}, {nmr}", f"изгибная жёсткость {cb}, {nmr}"),
         "M1/arctg(Σy/r_d1) (13)–(14)", _sci(lang, s.c_bend), ""),
        (pick(lang, f"contact stiffness c_H, {nmr}", f"контактная жёсткость c_H, {nmr}"),
         "M1/arctg(y_H/r_d1) (18)–(19)", _sci(lang, s.c_contact), ""),
        (pick(lang, f"mesh stiffness c, {nmr}", f"жёсткость зацепления c, {nmr}"),
         f"{cb}·c_H/({cb} + c_H) (20)", f"[bold]{_sci(lang, s.c)}[/]", ""),
        (pick(lang, "linear stiffness k = F/(Σy + y_H), N/m", "линейная жёсткость k = F/(Σy + y_H), Н/м"), "",
         _sci(lang, s.k), ""),
        (pick(lang, f"specific stiffness {cb}, c_H, c, {spec}", f"удельная жёсткость {cb}, c_H, c, {spec}"),
         "F/(y·b_w)·10⁻⁹", f"{_f(lang, s.c_spec_bend, 2)}, {_f(lang, s.c_spec_contact, 2)}, {_f(lang, s.c_spec, 2)}", ""),
    ]
    for row in rows:
        t.add_row(*row)
    console.print(t)
    from ...i18n.lang import note_text
    from ...i18n.messages_gears import MESSAGES

    console.print("  [dim]" + pick(lang, "Source: ", "Источник: ") + MESSAGES["stiffness_paper"][lang if lang == "ru" else "en"] + "[/]")
    for n in st.notes:
        console.print(f"  [dim]• {note_text(n, lang)}[/]")


def print_gears(console, result, lang: str) -> None:
    """Sheet 4 tables: motor, ratios, scheme choice, the book's derivation, the search, the five
    conditions, the ratio checks, the spur pair, and — beyond the course — its mesh stiffness."""
    _print_motor(console, result, lang)
    _print_ratios(console, result, lang)
    _print_schemes(console, result, lang)
    _print_book(console, result, lang)
    _print_search(console, result, lang)
    _print_conditions(console, result, lang)
    _print_ratio_checks(console, result, lang)
    _print_spur(console, result, lang)
    _print_spur_shift(console, result, lang)
    _print_stiffness(console, result, lang)
