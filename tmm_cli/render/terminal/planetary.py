"""Rich tables for shifted pairs (their geometry and blocking-contour checks) and for the AA̅
synthesis of `tmm planetary` (seed 000). Numbers through ``num`` (decimal comma under ru)."""

from __future__ import annotations

from ...i18n import tr, trc
from ...i18n.numbers import num

OK = "[green]✓[/]"
FAIL = "[red]✗[/]"


def _ok(v: bool) -> str:
    return OK if v else FAIL


def _n(x, lang, d=3):
    return num(x, lang, decimals=d, minus="−")


def _frac(f) -> str:
    return f"{f.numerator}/{f.denominator}" if f.denominator != 1 else f"{f.numerator}"


def _table(title: str, *cols: str, left=(0,)):
    from rich.table import Table

    t = Table(title=title, title_justify="left", title_style="bold")
    for j, c in enumerate(cols):
        t.add_column(c, justify="left" if j in left else "right", overflow="fold")
    return t


def pair_table(g, names: tuple[str, str], lang: str, title: str):
    """Geometry of one shifted pair: the formulas of gears/shifted.py with their numbers."""
    mm = tr(lang, "mm")
    t = _table(title, tr(lang, "Quantity"), tr(lang, "Formula"),
               tr(lang, "Gear {names}").format(names=names[0]), tr(lang, "Gear {names}").format(names=names[1]),
               left=(0, 1))
    rows = [
        (trc(lang, "singular", "teeth"), "z", str(g.z[0]), str(g.z[1])),
        (tr(lang, "shift coefficient"), "x", _n(g.x[0], lang), _n(g.x[1], lang)),
        (tr(lang, "shift sum"), "x_Σ = x1 + x2", _n(g.x_sum, lang, 4), ""),
        (tr(lang, "working pressure angle, °"), "inv α_w = inv α + 2x_Σ·tg α/(z1 + z2)",
         _n(g.alpha_w_deg, lang, 3), ""),
        (tr(lang, "reference centre distance, {mm}").format(mm=mm), "a = m(z1 + z2)/2",
         _n(g.a_mm, lang), ""),
        (tr(lang, "centre distance, {mm}").format(mm=mm), "a_w = a·cos α/cos α_w",
         f"[bold]{_n(g.a_w_mm, lang)}[/]", ""),
        (tr(lang, "centre-distance change"), "y = (a_w − a)/m",
         _n(g.y, lang, 4), ""),
        (tr(lang, "tip reduction"), "Δy = x_Σ − y", _n(g.dy, lang, 4), ""),
        (tr(lang, "pitch diameter, {mm}").format(mm=mm), "d = m·z", _n(g.d_mm[0], lang), _n(g.d_mm[1], lang)),
        (tr(lang, "base diameter, {mm}").format(mm=mm), "d_b = d·cos α", _n(g.db_mm[0], lang),
         _n(g.db_mm[1], lang)),
        (tr(lang, "working diameter, {mm}").format(mm=mm), "d_w = d·cos α/cos α_w", _n(g.dw_mm[0], lang),
         _n(g.dw_mm[1], lang)),
        (tr(lang, "tip diameter, {mm}").format(mm=mm), "d_a = d + 2(h_a* + x − Δy)m",
         _n(g.da_mm[0], lang), _n(g.da_mm[1], lang)),
        (tr(lang, "root diameter, {mm}").format(mm=mm), "d_f = d − 2(h_a* + c* − x)m",
         _n(g.df_mm[0], lang), _n(g.df_mm[1], lang)),
        (tr(lang, "thickness on the pitch circle, {mm}").format(mm=mm),
         "s = m(π/2 + 2x·tg α)", _n(g.s_mm[0], lang), _n(g.s_mm[1], lang)),
        (tr(lang, "thickness on the working circle, {mm}").format(mm=mm),
         "s_w = 2r_w(s/d + inv α − inv α_w)", _n(g.sw_mm[0], lang), _n(g.sw_mm[1], lang)),
        (tr(lang, "thickness on the tip circle, {mm}").format(mm=mm),
         "s_a = 2r_a(s/d + inv α − inv α_a)", _n(g.sa_mm[0], lang), _n(g.sa_mm[1], lang)),
        (tr(lang, "transverse contact ratio"),
         "ε_α = (√(r_a1² − r_b1²) + √(r_a2² − r_b2²) − a_w·sin α_w)/p_b", f"[bold]{_n(g.eps_alpha, lang)}[/]", ""),
    ]
    for r in rows:
        t.add_row(*r)
    return t


def checks_table(pc, names: tuple[str, str], teeth: tuple[int, int], m: float, lang: str, title: str):
    """The blocking-contour lines of one pair: number, limit, verdict."""
    mm = tr(lang, "mm")
    t = _table(title, tr(lang, "Condition"), tr(lang, "Value"), tr(lang, "Limit"),
               "", left=(0,))
    for c in pc.checks:
        who = " ({gear} {name}, z = {z})".format(gear=tr(lang, "gear"), name=names[c.gear - 1], z=teeth[c.gear - 1]) \
            if c.gear else ""
        if c.code == "undercut":
            label = tr(lang, "no undercut: x ≥ h_a*(17 − z)/17")
            val, lim = _n(c.value, lang), "≥ " + _n(c.limit, lang)
        elif c.code == "tip_thickness":
            label = tr(lang, "tip thickness s_a ≥ 0.25·m, {mm}").format(mm=mm)
            val, lim = _n(c.value, lang), "≥ " + _n(c.limit, lang)
        elif c.code == "eps_alpha":
            label = tr(lang, "contact ratio ε_α ≥ 1.2 (hard limit 1.05)")
            val, lim = _n(c.value, lang), "≥ " + _n(c.limit, lang, 2)
        else:
            label = tr(lang, "no fillet interference: contact starts beyond the involute's lower limit, {mm}").format(mm=mm)
            val, lim = _n(c.value, lang), "≥ " + _n(c.limit, lang)
        t.add_row(label + who, val, lim, _ok(c.ok) if not c.hard else "[red]✗✗[/]")
    return t


def print_planetary(console, d, lang: str, examples=()) -> None:
    """Everything `tmm planetary` prints: the synthesis, both pairs, the checks, the ratio checks."""
    lo, hi = d.c_feasible
    div = d.div
    t = _table(tr(lang, "Planetary mechanism AA̅ with different meshing angles (S. N. Kavetsky, Vestnik NTU KhPI, 2010): tooth numbers"),
               tr(lang, "Step"), tr(lang, "Computation"), left=(0, 1))
    t.add_row(trc(lang, "data", "given"),
              f"i = i_1H⁽⁴⁾ = {_frac(d.i)};  C = cos α_w12/cos α_w34 = {_frac(d.c)} = {num(float(d.c), lang, sig=6)};  "
              f"k = {d.planets};  {d.z_min} ≤ Z ≤ {d.z_max}")
    t.add_row(tr(lang, "feasible C"),
              f"1 < C < 1/(1 − i) = {_frac(hi)} ≈ {num(float(hi), lang, decimals=4)}  {OK}")
    t.add_row(tr(lang, "equations"),
              "Z4 = Z1(1 − i);  Z2 = Z3 = Z1(C − C·i − 1)/(1 − C);  Z1·i/k " + tr(lang, "whole"))
    t.add_row(tr(lang, "Z1 multiple of"),
              tr(lang, "assembly k·B/gcd(A, k·B) = {m_assembly};  coaxiality {m_coaxial};  ratio B = {m_ratio}").format(m_assembly=div.m_assembly, m_coaxial=div.m_coaxial, m_ratio=div.m_ratio)
              + "  →  Z1_min = " + tr(lang, "lcm") + f" = [bold]{div.z1_step}[/]")
    fam = ", ".join(f"×{n}: {'/'.join(str(z) for z in _teeth(div, n))}" for n in d.family)
    t.add_row(tr(lang, "family"), fam)
    t.add_row(tr(lang, "chosen"), f"[bold]Z1 = {d.teeth[0]}, Z2 = Z3 = {d.teeth[1]}, Z4 = {d.teeth[3]}[/]"
              + f"  (×{d.multiple})")
    t.add_row(tr(lang, "ratio check"),
              f"1 − Z2·Z4/(Z1·Z3) = 1 − {d.teeth[1]}·{d.teeth[3]}/({d.teeth[0]}·{d.teeth[2]}) = {_frac(d.ratio_check)}  "
              + _ok(d.ratio_check == d.i))
    v = d.velocity
    t.add_row(tr(lang, "velocity picture"),
              f"i = tg φ1/tg φ_H = tg {_n(v.phi_1_deg, lang, 3)}°/tg {_n(v.phi_h_deg, lang, 3)}° = "
              f"{num(v.ratio, lang, decimals=6)}  " + _ok(abs(v.ratio - float(d.i)) < 1e-9))
    console.print(t)
    if examples:
        e = _table(tr(lang, "Other feasible C for i = {i}, k = {planets} (smallest tooth sets)").format(i=_frac(d.i), planets=d.planets),
                   "C", "Z1/Z2/Z3/Z4", left=(0, 1))
        for c, teeth in examples:
            e.add_row(f"{_frac(c)} ≈ {num(float(c), lang, decimals=4)}", "/".join(map(str, teeth)))
        console.print(e)
    s = _table(tr(lang, "Shifts from the common centre distance (Kavetsky, 2010, Fig. 2)"),
               tr(lang, "Step"), tr(lang, "Computation"), left=(0, 1))
    p12, p34 = d.pair12, d.pair34
    s.add_row("1", f"x_Σ12 = x1 + x2 = {_n(d.x[0], lang)} + {_n(d.x[1], lang)} = {_n(p12.x_sum, lang)};  "
                   f"α_w12 = [bold]{_n(p12.alpha_w_deg, lang)}°[/]")
    s.add_row("2", f"a_w = m(Z1 + Z2)/2·cos α/cos α_w12 = [bold]{_n(d.a_w_mm, lang)} " + tr(lang, "mm") + "[/]")
    s.add_row("3", f"a_w34 = a_w;  x3 = x2 = {_n(d.x[2], lang)} " + tr(lang, "(linked planet)"))
    s.add_row("3.1", f"cos α_w34 = m(Z3 + Z4)/2·cos α/a_w → α_w34 = [bold]{_n(p34.alpha_w_deg, lang)}°[/];  "
                     f"cos α_w12/cos α_w34 = {num(d.c_check, lang, decimals=4)}")
    s.add_row("3.2", f"x_Σ34 = (inv α_w34 − inv α)(Z3 + Z4)/(2 tg α) = [bold]{_n(p34.x_sum, lang)}[/]")
    s.add_row("3.3", f"x4 = x_Σ34 − x3 = [bold]{_n(d.x[3], lang)}[/]")
    console.print(s)
    console.print(pair_table(p12, ("1", "2"), lang, tr(lang, "Pair 1-2")))
    console.print(pair_table(p34, ("3", "4"), lang, tr(lang, "Pair 3-4")))
    m = d.module_mm
    console.print(checks_table(d.checks12, ("1", "2"), p12.z, m, lang,
                               tr(lang, "Blocking contour, pair 1-2")))
    console.print(checks_table(d.checks34, ("3", "4"), p34.z, m, lang,
                               tr(lang, "Blocking contour, pair 3-4")))
    nb = d.neighbours
    n = _table(tr(lang, "Neighbouring with the real tip circles"),
               tr(lang, "Condition"), tr(lang, "Value"), "", left=(0, 1))
    n.add_row(f"d_a < 2a_w·sin(π/k)", f"{_n(nb.value, lang)} < {_n(nb.limit, lang)}", _ok(nb.ok))
    console.print(n)


def _teeth(div, n):
    from ...gears.aa_bar import teeth_for

    return teeth_for(div, n)
