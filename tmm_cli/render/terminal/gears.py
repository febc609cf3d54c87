"""Rich tables for sheet 4 in the order of the explanatory note (§2.2 → §2.6)."""

from __future__ import annotations

import math
from fractions import Fraction

from ...i18n import ntr, tr
from ...i18n.numbers import num
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
    return (tr(lang, "counter-clockwise") if sense == "ccw" else tr(lang, "clockwise"))


def _relative(lang: str, sense: str, motor: str) -> str:
    return tr(lang, " (as the motor)") if sense == motor else \
        tr(lang, " (against the motor)")


def _teeth_labels(lang: str, double: bool) -> list[str]:
    return ["z_k", "z_c", "z_c′", "z_n"] if double else ["z_k", "z_c", "z_n"]


def _print_motor(console, r, lang):
    t = _table(tr(lang, "Motor (§2.2, §2.6)"), tr(lang, "Quantity"),
               tr(lang, "Value"))
    t.add_row(tr(lang, "Crank speed n_cr, rpm"),
              _f(lang, r.crank_rpm) + (tr(lang, " (assumed, §2.4)") if r.crank_rpm_assumed else ""))
    t.add_row(tr(lang, "Cam speed n_k, rpm"), _f(lang, r.cam_rpm))
    t.add_row(tr(lang, "Rule n_d ≥ 3·n_cr, rpm"), f"≥ {_f(lang, 3 * r.crank_rpm)}")
    t.add_row(tr(lang, "Standard speeds, rpm"),
              ", ".join(f"[bold]{n}[/]" if n == r.motor_rpm else str(n) for n in r.motor_candidates))
    t.add_row(tr(lang, "Motor speed n_d, rpm"), f"[bold]{r.motor_rpm}[/]")
    if r.power is not None:
        p = r.power
        t.add_row(tr(lang, "Mean reduced moment M, N·m"), _f(lang, p.torque_nm))
        t.add_row("ω_кр = π·n_кр/30, " + tr(lang, "rad/s"), _f(lang, p.omega_cr_rad_s, 3))
        t.add_row("η1 · η2", f"{_f(lang, p.eta1, 4)} · {_f(lang, p.eta2, 2)}")
        t.add_row(tr(lang, "Power N = M·ω/(η1·η2)·10⁻³, kW (2.6)"),
                  _f(lang, p.power_kw, 3))
        t.add_row(tr(lang, "Rated motor power, kW"),
                  f"[bold]{_f(lang, p.rated_kw, 2)}[/]" if p.rated_kw is not None else "—")
    else:
        t.add_row(tr(lang, "Power (2.6)"),
                  tr(lang, "give the moment M (--torque)"))
    console.print(t)


def _print_ratios(console, r, lang):
    t = _table(tr(lang, "Ratios and rotation"),
               tr(lang, "Mechanism"), tr(lang, "Formula"), tr(lang, "Required"),
               tr(lang, "Realised"), tr(lang, "Output turns"), left=(0, 1, 4))
    d = r.directions
    # one convention with results.json: a ratio is n_in/n_out as a magnitude; the senses of
    # rotation stand in their own column (the external pair reverses, the reducer keeps the sense)
    t.add_row(tr(lang, "Spur pair motor → cam"), "i_д = n_д/|n_к|",
              _f(lang, r.i_spur, 4), f"{_f(lang, abs(d.i_spur_signed), 4)} (z2/z1)",
              tr(lang, "cam: ") + _rot(lang, d.cam) + _relative(lang, d.cam, d.motor))
    t.add_row(tr(lang, "Planetary reducer motor → crank"),
              "i_пл = n_д/n_кр", _f(lang, r.i_planetary, 4), _f(lang, abs(d.i_planetary_signed), 4),
              tr(lang, "crank: ") + _rot(lang, d.crank) + _relative(lang, d.crank, d.motor))
    t.add_row(tr(lang, "Motor"), "", "", "", _rot(lang, d.motor))
    console.print(t)


def _print_schemes(console, r, lang):
    t = _table(tr(lang, "Scheme choice (Fig. 2.4, §2.2)"), "№",
               tr(lang, "Ratio range"), "η", tr(lang, "Ratio formula"),
               tr(lang, "Coaxiality"), tr(lang, "Chosen"), left=(0, 3, 4, 5))
    reason = {
        "le8": tr(lang, "i_pl = {i_planetary} ≤ 8").format(i_planetary=_f(lang, r.i_planetary, 3)),
        "8to16": tr(lang, "8 < i_pl = {i_planetary} ≤ 16").format(i_planetary=_f(lang, r.i_planetary, 3)),
        "gt16": tr(lang, "i_pl = {i_planetary} > 16: two stages, i1 ≈ √i_pl = {i_planetary2}").format(i_planetary=_f(lang, r.i_planetary, 3), i_planetary2=_f(lang, math.sqrt(r.i_planetary), 2)),
    }[r.scheme_reason]
    for s in r.schemes:
        chosen = s.key == r.scheme
        if chosen:
            mark = f"[bold green]◀ {reason}[/]"
        elif s.number in (4, 5):
            mark = tr(lang, "low η, for large i")
        else:
            mark = ""
        t.add_row(str(s.number), f"{_f(lang, s.i_min)} … {_f(lang, s.i_max)}", f"{_f(lang, s.eta_max, 2)} … {_f(lang, s.eta_min, 2)}",
                  s.formula, s.coaxial, mark)
    console.print(t)


def _print_book_stage(console, st, lang, title):
    if st.scheme == "1":
        c = st.chosen
        t = _table(title, tr(lang, "Step"), tr(lang, "Computation"), left=(0, 1))
        t.add_row("1", f"i = {_frac(st.fraction)};  z_n/z_k = i − 1 = {_frac(st.reduced)} = D/A;  D = {c.d}, A = {c.a}")
        t.add_row("2", f"z_c = (z_n − z_k)/2 = (D − A)/2·y = {_frac(Fraction(c.d - c.a, 2))}·y")
        t.add_row("3", f"z_k = {c.a}y,  z_c = {_frac(c.base[1])}y,  z_n = {c.d}y")
        t.add_row("4", f"{c.a}y ≥ 17;  {_frac(c.base[1])}y ≥ 20;  {c.d}y ≥ 85 → y_min = {_frac(c.y_min)}"
                  + tr(lang, " (all whole)"))
        t.add_row("", f"[bold]z_k = {c.teeth[0]}, z_c = {c.teeth[1]}, z_n = {c.teeth[2]}[/]")
    else:
        t = _table(title, tr(lang, "Step"), tr(lang, "Computation"), left=(0, 1))
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
        for tab, xname, lab in (("2.3", "x1", tr(lang, "Table 2.3 (x1 rows)")),
                                ("2.4x2", "x2", tr(lang, "Table 2.4 (x2 rows; the book heads it x1)"))):
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
        t = _table("", tr(lang, "Step"), tr(lang, "Computation"), left=(0, 1))
        t.add_row("5", tr(lang, "smallest max(Γ1, Γ2): ")
                  + f"{'x1' if c.table == '2.3' else 'x2'} = {c.x}: [bold]z_k = {c.teeth[0]}, z_c = {c.teeth[1]}, "
                  f"z_c′ = {c.teeth[2]}, z_n = {c.teeth[3]}[/], Γ1 = {c.gamma1}, Γ2 = {c.gamma2}")
    zk = st.chosen.teeth[0]
    ks = ", ".join(str(k) for k in st.assembly_ks[:8]) + (" …" if len(st.assembly_ks) > 8 else "")
    t.add_row(tr(lang, "assembly"),
              f"z_k·i/k·c = {zk}·{_frac(st.fraction)}/k·c = {st.assembly_n}/({st.assembly_c}·k)·c, c = {st.assembly_c} → k = {ks}")
    t.add_row(tr(lang, "neighbours"),
              f"sin(π/k) > {_f(lang, st.neighbour_q, 3)} → k ≤ {st.neighbour_limit}"
              + tr(lang, " (computed exactly, not read from Table 2.1)"))
    t.add_row(tr(lang, "k_max"), f"[bold]{st.k_max}[/]" + (tr(lang, "  (exact assembly condition: {k_max_exact})").format(k_max_exact=st.k_max_exact)
                                                  if st.k_max_exact != st.k_max else ""))
    console.print(t)


def _print_book(console, r, lang):
    d = r.derivation
    if d is None:
        return
    sec = {"1": "§2.4", "2": "§2.5", "1+1": "§2.2, §2.4"}[d.scheme]
    rule = {
        "forced": tr(lang, "the fraction given by the user"),
        "convergent": tr(lang, "the last convergent of i_pl's continued fraction with a denominator ≤ 10"),
        "nearest": tr(lang, "the nearest simple fraction (denominator ≤ 10) within tolerance whose procedure succeeds"),
    }.get(d.fraction_rule, tr(lang, "of the simple fractions (denominator ≤ 10) within tolerance, the one giving the smallest reducer"))
    if d.convergents:
        rule += tr(lang, " (convergents: {list})").format(list=", ".join(str(f) for f in d.convergents))
    if d.fraction_rule == "exact":
        rule = tr(lang, "i_pl is itself a simple fraction, so the procedure starts from it (exact ratio)")
    heading = tr(lang, "The book’s hand procedure")
    console.print(f"[bold]{heading} ({sec})[/] — {rule}")
    if d.fraction_rule == "simple" and len(d.tried) > 1:
        tried = ", ".join(f"{f}→{n}" for f, n in sorted(d.tried, key=lambda x: x[1])[:10])
        console.print(tr(lang, "  fractions tried (→ size): {tried}").format(tried=tried))
    for j, st in enumerate(d.stages, 1):
        title = tr(lang, "Stage {j}").format(j=j) if len(d.stages) > 1 else \
            tr(lang, "Derivation")
        _print_book_stage(console, st, lang, title)
    if r.printed is not None:
        p = r.printed
        t = _table(tr(lang, "The book’s printed answer (§{section}) rechecked").format(section=p.section),
                   tr(lang, "Teeth"), tr(lang, "Coaxiality"),
                   tr(lang, "Ratio"), left=(0, 1, 2))
        t.add_row("/".join(map(str, p.stage.teeth)), f"{p.coaxial_lhs} {'=' if p.coaxial_ok else '≠'} {p.coaxial_rhs} {_ok(p.coaxial_ok)}",
                  f"{_f(lang, p.ratio, 3)} {'=' if p.ratio_ok else '≠'} {_frac(p.fraction)} {_ok(p.ratio_ok)}")
        console.print(t)


def _print_search(console, r, lang):
    s = r.search
    double = r.scheme == "2"
    rule = {
        "smallest_3plus": tr(lang, "smallest with ≥ 3 planets"),
        "smallest_no3": tr(lang, "none takes 3 planets: the smallest"),
        "forced_planets": tr(lang, "smallest taking k = {forced_planets}").format(forced_planets=s.forced_planets),
    }[s.rule]
    if getattr(s, "select", "smallest") == "accurate":
        rule += tr(lang, ", then the most accurate ratio within one tooth of it")
    title = ntr(lang, "Exhaustive search: {n_sets} candidate within ±{tolerance_pct} %, every wheel ≤ {z_max} teeth; "
                      "size = max(Γ1, Γ2) = max(z_k + 2z_c, z_n); rule: {rule}",
                "Exhaustive search: {n_sets} candidates within ±{tolerance_pct} %, every wheel ≤ {z_max} teeth; "
                "size = max(Γ1, Γ2) = max(z_k + 2z_c, z_n); rule: {rule}",
                s.n_sets).format(n_sets=s.n_sets, tolerance_pct=_f(lang, s.tolerance_pct), z_max=s.z_max, rule=rule)
    if r.scheme == "1+1":
        cols = [tr(lang, "Stage 1") + " z_k/z_c/z_n", tr(lang, "Stage 2") + " z_k/z_c/z_n"]
    else:
        cols = _teeth_labels(lang, double)
    t = _table(title, *cols, "i", tr(lang, "error, %"), tr(lang, "size"), "k", "")
    for a in s.alternatives:
        carried = a == r.planetary
        if r.scheme == "1+1":
            cells = ["/".join(map(str, st.teeth)) + f" (i={_f(lang, st.ratio, 3)}, k={st.planets})" for st in a.stages]
        else:
            cells = [str(z) for z in a.stages[0].teeth]
        t.add_row(*cells, _f(lang, a.ratio, 4), _pct(lang, a.ratio_error_pct), str(a.size), str(a.planets),
                  tr(lang, "◀ carried") if carried else "", style="bold green" if carried else None)
    console.print(t)


def _print_conditions(console, r, lang):
    ch = r.checks
    t = _table(tr(lang, "The five conditions of synthesis (§2.1.3) for the carried reducer"),
               tr(lang, "Condition"), tr(lang, "Numbers"), "", left=(0, 1))
    t.add_row(tr(lang, "1. Ratio"),
              f"i = {_frac(ch.ratio_fraction)} = {_f(lang, ch.ratio, 4)};  i_пл = {_f(lang, ch.target, 4)};  "
              f"{_pct(lang, ch.ratio_error_pct)} % (±{_f(lang, ch.tolerance_pct)} %)", _ok(ch.ratio_ok))
    multi = len(ch.stages) > 1
    for j, c in enumerate(ch.stages, 1):
        st = c.stage
        pre = (tr(lang, "st. {j}: ").format(j=j) if multi else "")
        zc2 = "z_c′" if st.z_planet2 is not None else "z_c"
        t.add_row(pre + tr(lang, "2. Coaxiality"),
                  f"z_k + z_c = {st.z_sun} + {st.z_planet} = {c.coaxial_lhs};  z_n − {zc2} = {st.z_ring} − {st.zc2} = {c.coaxial_rhs}",
                  _ok(c.coaxial_ok))
        k = st.planets
        if st.z_planet2 is None:
            exact = f"(z_k + z_n)/k = {st.z_sun + st.z_ring}/{k} = {_f(lang, (st.z_sun + st.z_ring) / k, 3)}"
        else:
            exact = (f"(z_k·z_c′ + z_c·z_n)/(k·gcd(z_c, z_c′)) = {c.assembly_t}/({k}·{c.assembly_g}) = "
                     f"{_f(lang, c.assembly_t / (k * c.assembly_g), 3)}")
        t.add_row(pre + tr(lang, "3. Assembly (exact)"), exact, _ok(c.assembly_exact_ok))
        book = (f"z_k·i = {c.assembly_book_n}/{c.assembly_book_d}; N/k = {c.assembly_book_n}/{k} = "
                f"{_f(lang, c.assembly_book_n / k, 3)}")
        differ = ""
        if c.k_max != c.k_max_book:
            differ = tr(lang, "  — forms differ: exact k ≤ {k_max}, book k ≤ {k_max_book}").format(k_max=c.k_max, k_max_book=c.k_max_book)
        t.add_row(pre + tr(lang, "   book's form (2.4)"), book + differ, _ok(c.assembly_book_ok))
        zbig = max(st.z_planet, st.zc2)
        t.add_row(pre + tr(lang, "4. Neighbours (2.5)"),
                  f"sin(π/{k}) = {_f(lang, c.neighbour_sin, 4)} > (z_c + 2h_a*)/(z_k + z_c) = ({zbig} + 2)/{st.z_sun + st.z_planet}"
                  f" = {_f(lang, c.neighbour_q, 4)};  k ≤ {c.neighbour_limit}", _ok(c.neighbour_ok))
        items = ";  ".join(f"{i.symbol} = {i.value} ≥ {i.limit}" for i in c.interference)
        t.add_row(pre + tr(lang, "5. No interference (Table 2.2)"), items,
                  _ok(c.interference_ok))
        t.add_row(pre + tr(lang, "Planets"),
                  tr(lang, "assembly admits k = {str}…; with neighbours k_max = {k_max}").format(str=', '.join(map(str, c.assembly_ks_exact[:8])), k_max=c.k_max)
                  + (tr(lang, "; carried k = {k}").format(k=k) if k != c.k_max else ""), "")
    console.print(t)


def _print_ratio_checks(console, r, lang):
    ch = r.checks
    v = ch.velocity
    t = _table(tr(lang, "Ratio check"), tr(lang, "Method"),
               tr(lang, "Computation"), "i", left=(0, 1))
    per = "·".join(_f(lang, x, 4) for x in ch.ratio_formula_21)
    t.add_row(tr(lang, "Analytic (2.1)"),
              "i = 1 − (−1)^a·(z_c·z_n)/(z_k·z_c′), a = 1" + (f";  {per}" if len(ch.ratio_formula_21) > 1 else ""),
              _f(lang, ch.ratio_formula_21_total, 4))
    for j, s in enumerate(v.stages, 1):
        lab = tr(lang, "Velocity picture, stage {j}").format(j=j) if len(v.stages) > 1 else \
            tr(lang, "Velocity picture (2.3)")
        t.add_row(lab, f"tg φ_k / tg φ_H = tg {_f(lang, s.phi_k_deg, 2)}° / tg {_f(lang, s.phi_h_deg, 2)}°", _f(lang, s.ratio, 4))
    t.add_row(tr(lang, "Angular-velocity picture"),
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

    console.print(pair_table(g.pair, ("1", "2"), lang, tr(lang, "Spur pair with profile shift (beyond the book)")))
    console.print(checks_table(g.blocking, ("1", "2"), (g.z1, g.z2), g.m_mm, lang,
                               tr(lang, "Blocking contour of the spur pair")))


def _print_spur(console, r, lang):
    g = r.spur
    t = _table(tr(lang, "Spur pair (§2.3): z1 = {z1}, z2 = {z2}, m = {m_mm} mm, α = {alpha_deg}°, h_a* = {ha_star}, c* = {c_star}, {g}").format(z1=g.z1, z2=g.z2, m_mm=_f(lang, g.m_mm), alpha_deg=_f(lang, g.alpha_deg), ha_star=_f(lang, g.ha_star), c_star=_f(lang, g.c_star), g=_shift_text(g, lang)),
               tr(lang, "Item"), tr(lang, "Formula"), tr(lang, "Gear 1"),
               tr(lang, "Gear 2"), left=(0, 1))
    mm = tr(lang, "mm")
    sh = getattr(g, "shifted", False)
    rows = [
        ("2", tr(lang, "teeth"),
         "z1 = 17" if g.z1 == 17 else tr(lang, "z1 = round(17/i_d)"), str(g.z1), str(g.z2)),
        ("3", tr(lang, "pitch diameter, {mm}").format(mm=mm), "d = m·z", _f(lang, g.d1_mm, 2), _f(lang, g.d2_mm, 2)),
        ("3", tr(lang, "base diameter, {mm}").format(mm=mm), "d_b = d·cos α", _f(lang, g.db1_mm, 2), _f(lang, g.db2_mm, 2)),
        ("3", tr(lang, "tip diameter, {mm}").format(mm=mm), "d_a = d + 2(h_a* + x − Δy)m" if sh else "d_a = d + 2h_a*·m", _f(lang, g.da1_mm, 2), _f(lang, g.da2_mm, 2)),
        ("3", tr(lang, "root diameter, {mm}").format(mm=mm), "d_f = d − 2(h_a* + c* − x)m" if sh else "d_f = d − 2(h_a* + c*)m", _f(lang, g.df1_mm, 2), _f(lang, g.df2_mm, 2)),
        ("4", (tr(lang, "reference centre distance, {mm}") if sh else tr(lang, "centre distance, {mm}")).format(mm=mm),
         "a = m(z1 + z2)/2", _f(lang, g.a_mm, 2), ""),
    ] + ([("4", tr(lang, "working centre distance, {mm}").format(mm=mm), "a_w = a·cos α/cos α_w",
           _f(lang, g.a_w_mm, 3), "")] if sh else []) + [
        ("5", tr(lang, "pitch / base pitch, {mm}").format(mm=mm), "p = π·m;  p_b = p·cos α",
         _f(lang, g.p_mm, 3), _f(lang, g.pb_mm, 3)),
        ("6", tr(lang, "tooth thickness = space, {mm}").format(mm=mm), "s = e = π·m/2",
         _f(lang, g.s_mm, 3), _f(lang, g.e_mm, 3)) if not sh else
        ("6", tr(lang, "tooth thickness, {mm}").format(mm=mm), "s = m(π/2 + 2x·tg α)",
         _f(lang, g.pair.s_mm[0], 3), _f(lang, g.pair.s_mm[1], 3)),
        ("7", tr(lang, "angular pitch, °"), "τ = 360/z", _f(lang, g.tau1_deg, 3), _f(lang, g.tau2_deg, 3)),
        ("8", tr(lang, "tooth height, {mm}").format(mm=mm), "h = (2h_a* + c* − Δy)m" if sh else "h = (2h_a* + c*)m", _f(lang, g.h_mm, 2), ""),
        ("9", tr(lang, "depth of engagement, {mm}").format(mm=mm), "h_d = (2h_a* − Δy)m" if sh else "h_d = 2h_a*·m", _f(lang, g.hd_mm, 2), ""),
        ("10", tr(lang, "clearance, {mm}").format(mm=mm), "C = c*·m", _f(lang, g.c_mm, 2), ""),
        ("", tr(lang, "root fillet radius, {mm}").format(mm=mm), "0.38·m", _f(lang, g.fillet_mm, 2), ""),
    ]
    for item, name, formula, a, b in rows:
        t.add_row(f"{item} {name}".strip(), formula, a, b)
    console.print(t)
    c = _table(tr(lang, "Check, item 11"), tr(lang, "Expression"),
               tr(lang, "Value, mm"), "")
    a = g.a_w_mm or g.a_mm  # the working centre distance (= a for a zero pair)
    c.add_row("(d1 + d2)/2" if not getattr(g, "shifted", False) else "(d_w1 + d_w2)/2", _f(lang, g.check_a_pitch_mm, 3), _ok(abs(g.check_a_pitch_mm - a) < 1e-6))
    c.add_row("d_a1/2 + d_f2/2 + C", _f(lang, g.check_a_12_mm, 3), _ok(abs(g.check_a_12_mm - a) < 1e-6))
    c.add_row("d_a2/2 + d_f1/2 + C", _f(lang, g.check_a_21_mm, 3), _ok(abs(g.check_a_21_mm - a) < 1e-6))
    c.add_row("d_a1 − d_f1 = 2h", f"{_f(lang, g.check_2h_1_mm, 3)} = {_f(lang, 2 * g.h_mm, 3)}", _ok(abs(g.check_2h_1_mm - 2 * g.h_mm) < 1e-6))
    c.add_row("d_a2 − d_f2 = 2h", f"{_f(lang, g.check_2h_2_mm, 3)} = {_f(lang, 2 * g.h_mm, 3)}", _ok(abs(g.check_2h_2_mm - 2 * g.h_mm) < 1e-6))
    console.print(c)
    e = _table(tr(lang, "Contact ratio and zones on the line of action (Fig. 2.3), from N1, mm"),
               tr(lang, "Quantity"), tr(lang, "Value"))
    e.add_row("α_w, °", _f(lang, g.alpha_w_deg, 2))
    e.add_row("N1N2 = a·sin α_w", _f(lang, g.n1n2_mm, 2))
    e.add_row(tr(lang, "P (pole)"), _f(lang, g.pole_mm, 2))
    e.add_row("P1, U2, U1, P2", f"{_f(lang, g.p1_mm, 2)}, {_f(lang, g.u2_mm, 2)}, {_f(lang, g.u1_mm, 2)}, {_f(lang, g.p2_mm, 2)}")
    e.add_row(tr(lang, "active line P1P2 = g_α"), _f(lang, g.g_alpha_mm, 2))
    e.add_row(tr(lang, "double-pair zones P1U2 = U1P2"), _f(lang, g.double_zone_mm, 2))
    e.add_row(tr(lang, "single-pair zone U2U1"), _f(lang, g.single_zone_mm, 2))
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
    t = _table(tr(lang, "Mesh stiffness (beyond the course, informative): V. P. Tarasik's method"),
               tr(lang, "Quantity"), tr(lang, "Formula"), tr(lang, "Gear 1"),
               tr(lang, "Gear 2"), left=(0, 1))
    mm, um = tr(lang, "mm"), tr(lang, "μm")
    nmr = tr(lang, "N·m/rad")
    spec = tr(lang, "N/(mm·μm)")
    cb = tr(lang, "c_b")
    rows = [
        (tr(lang, "face width b_w, {mm}").format(mm=mm), f"ψ_m·m = {_f(lang, st.psi_m)}·m",
         _f(lang, s.b_w_m * 1e3, 2), ""),
        (tr(lang, "moment on gear 1 M1, N·m"),
         (tr(lang, "motor torque N/ω_d") if st.load == "motor" else tr(lang, "nominal (q of the paper)")), _f(lang, s.torque1_nm, 2), ""),
        (tr(lang, "tangential force F, N"), "F = M1/r_d1", _f(lang, s.force_n, 1), ""),
        (tr(lang, "line load q, N/mm"), "q = F/b_w", _f(lang, s.line_load_n_per_m * 1e-3, 3), ""),
        (tr(lang, "tooth thickness at tip s_a, {mm}").format(mm=mm), "(1)–(3)",
         _f(lang, s.s_a_m[0] * 1e3, 3), _f(lang, s.s_a_m[1] * 1e3, 3)),
        (tr(lang, "… at pitch circle s_d, {mm}").format(mm=mm), "(1)",
         _f(lang, s.s_d_m[0] * 1e3, 3), _f(lang, s.s_d_m[1] * 1e3, 3)),
        (tr(lang, "… at base circle s_b, {mm}").format(mm=mm), "(1)",
         _f(lang, s.s_b_m[0] * 1e3, 3), _f(lang, s.s_b_m[1] * 1e3, 3)),
        (tr(lang, "involute curvature ρ at pitch circle, {mm}").format(mm=mm),
         "ρ = r_b·tg α_x (17)", _f(lang, s.rho_m[0] * 1e3, 3), _f(lang, s.rho_m[1] * 1e3, 3)),
        (tr(lang, "bending deflection y at pitch circle, {um}").format(um=um),
         "(9)–(11)", num(s.y_bend_m[0] * 1e6, lang, sig=4), num(s.y_bend_m[1] * 1e6, lang, sig=4)),
        (tr(lang, "contact deformation y_H, {um}").format(um=um), tr(lang, "Nakhatakyan (16)"),
         num(s.y_contact_m * 1e6, lang, sig=4), ""),
        (tr(lang, "bending stiffness {cb}, {nmr}").format(cb=cb, nmr=nmr),
         "M1/arctg(Σy/r_d1) (13)–(14)", _sci(lang, s.c_bend), ""),
        (tr(lang, "contact stiffness c_H, {nmr}").format(nmr=nmr),
         "M1/arctg(y_H/r_d1) (18)–(19)", _sci(lang, s.c_contact), ""),
        (tr(lang, "mesh stiffness c, {nmr}").format(nmr=nmr),
         f"{cb}·c_H/({cb} + c_H) (20)", f"[bold]{_sci(lang, s.c)}[/]", ""),
        (tr(lang, "linear stiffness k = F/(Σy + y_H), N/m"), "",
         _sci(lang, s.k), ""),
        (tr(lang, "specific stiffness {cb}, c_H, c, {spec}").format(cb=cb, spec=spec),
         "F/(y·b_w)·10⁻⁹", f"{_f(lang, s.c_spec_bend, 2)}, {_f(lang, s.c_spec_contact, 2)}, {_f(lang, s.c_spec, 2)}", ""),
    ]
    for row in rows:
        t.add_row(*row)
    console.print(t)
    from ...i18n.lang import note_text
    from ...i18n.messages_gears import MESSAGES, PAPER

    console.print("  [dim]" + tr(lang, "Source: ") + tr(lang, MESSAGES[PAPER]) + "[/]")
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
