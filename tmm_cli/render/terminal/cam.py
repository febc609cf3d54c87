"""Rich tables of sheet 3 (the cam): input, motion table, scales, dimensions, ψ angles, checks."""

from __future__ import annotations

import math

from ...cam.design import CamResult
from ...cam.laws import law_impacts
from ...i18n import N_, tr
from ...i18n.numbers import num
from .table import Table
from .variants import law_words, rotation_words, scheme_words

OK = "[green]✓[/green]"  # the same marks as the gear tables
BAD = "[red]✗[/red]"
WARN = "[yellow]![/yellow]"


def _table(title: str, *cols: tuple[str, str]):
    t = Table(title=title, header_style="bold")
    for name, justify in cols:
        t.add_column(name, justify=justify)
    return t


def _g(lang: str, x: float, nd: int = 4) -> str:
    """`nd` significant digits; 9,42·10⁻⁵ for the small scales (never 9.4246e-05)."""
    return num(x, lang, sig=nd)


def _n(lang: str, x, spec: str) -> str:
    """`x` as the format `spec` would print it (g, .2f, +.2f, .4g), in the reader's notation."""
    if spec == "g":
        return num(x, lang, sig=6, sci=False)
    if spec.endswith("g"):
        return num(x, lang, sig=int(spec[1:-1]), sci=False)
    text = num(x, lang, decimals=int(spec.lstrip("+")[1:-1]))
    if spec.startswith("+") and not text.startswith("-") and not set(text) <= set("0,."):
        text = "+" + text
    return text


def _nu(lang: str, x: float, limit: float) -> str:
    """A pressure angle beside its limit: 2 decimals, 3 when 2 would hide that it passes the limit."""
    nd = 3 if round(x, 2) == round(limit, 2) and abs(x - limit) >= 5e-4 else 2
    return num(x, lang, decimals=nd)


def _input_table(r: CamResult, lang: str):
    v, m = r.variant, r.motion
    t = _table(
        tr(lang, "Variant {number}: input data (Table 1.2)").format(number=v.number),
        (tr(lang, "Quantity"), "left"),
        (tr(lang, "Value"), "right"),
        (tr(lang, "Note"), "left"),
    )
    t.add_row(tr(lang, "Scheme"), str(v.scheme), scheme_words(v.scheme, lang))
    impacts = law_impacts(v.law)
    t.add_row(
        tr(lang, "Acceleration law"),
        str(v.law),
        law_words(v.law, lang)
        + "; "
        + (tr(lang, "soft impacts (a jumps)") if impacts == "soft" else tr(lang, "no impacts")),
    )
    if v.is_rocker:
        t.add_row("γ_max", f"{_n(lang, v.stroke, 'g')}°", tr(lang, "rocker swing"))
        t.add_row("l_BC", f"{_n(lang, v.l_bc_m * 1000, 'g')} " + tr(lang, "mm"), tr(lang, "rocker length"))
    else:
        t.add_row("S_max", f"{_n(lang, v.stroke * 1000, 'g')} " + tr(lang, "mm"), tr(lang, "follower stroke"))
    t.add_row("ν_max", f"{_n(lang, v.nu_max_deg, 'g')}°", tr(lang, "allowed pressure angle (1.19)"))
    t.add_row("n_k", f"{_n(lang, v.n_cam_rpm, 'g')} " + tr(lang, "rpm"), rotation_words(v, lang))
    t.add_row("ω_k", f"{_n(lang, m.omega, '.3f')} " + tr(lang, "rad/s"), "ω_k = π·|n_k|/30 (1.5)")
    t.add_row("φ_у", f"{_n(lang, v.phi_rise_deg, 'g')}°", tr(lang, "rise"))
    t.add_row("φ_дс", f"{_n(lang, v.phi_far_dwell_deg, 'g')}°", tr(lang, "far dwell"))
    t.add_row("φ_в", f"{_n(lang, v.phi_return_deg, 'g')}°", tr(lang, "return"))
    t.add_row("φ_бс", f"{_n(lang, v.phi_near_dwell_deg, 'g')}°", tr(lang, "near dwell = 360° − φ_р"))
    t.add_row("φ_р", f"{_n(lang, v.phi_working_deg, 'g')}°", "φ_у + φ_дс + φ_в (1.3)")
    t.add_row("T", f"{_n(lang, m.period_s * 1000, '.3f')} " + tr(lang, "ms"), tr(lang, "one cam turn"))
    return t


_PHASE = {"rise": N_("rise"), "far_dwell": N_("far dwell"), "return": N_("return"), "near_dwell": N_("near dwell")}


def _motion_table(r: CamResult, lang: str):
    m, v = r.motion, r.variant
    steps = f"{_n(lang, m.table_step_rise_deg, 'g')}° / {_n(lang, m.table_step_return_deg, 'g')}°"
    title = tr(lang, "Follower motion (step rise/return {steps})").format(steps=steps)
    if v.is_rocker:
        cols = [
            ("№", "right"), ("φ, °", "right"), (tr(lang, "t, ms"), "right"),
            ("γ, °", "right"), (tr(lang, "ω, rad/s"), "right"), (tr(lang, "ε, rad/s²"), "right"),
            (tr(lang, "S_B, mm"), "right"), (tr(lang, "V_B, m/s"), "right"), (tr(lang, "a_B, m/s²"), "right"),
            (tr(lang, "phase"), "left"),
        ]
    else:
        cols = [
            ("№", "right"), ("φ, °", "right"), (tr(lang, "t, ms"), "right"),
            (tr(lang, "S, mm"), "right"), (tr(lang, "V, m/s"), "right"), (tr(lang, "a, m/s²"), "right"),
            (tr(lang, "phase"), "left"),
        ]
    t = _table(title, *cols)
    for row in m.table:
        ph = tr(lang, _PHASE[row.phase])
        if v.is_rocker:
            t.add_row(
                str(row.index), f"{_n(lang, row.phi_deg, 'g')}", f"{_n(lang, row.t_s * 1000, '.3f')}",
                f"{_n(lang, math.degrees(row.s), '.3f')}", f"{_n(lang, row.v, '.3f')}", f"{_n(lang, row.a, '.1f')}",
                f"{_n(lang, row.s_b_m * 1000, '.3f')}", f"{_n(lang, row.v_b_m_s, '.4f')}", f"{_n(lang, row.a_b_m_s2, '.2f')}", ph,
            )
        else:
            t.add_row(str(row.index), f"{_n(lang, row.phi_deg, 'g')}", f"{_n(lang, row.t_s * 1000, '.3f')}", f"{_n(lang, row.s * 1000, '.3f')}", f"{_n(lang, row.v, '.4f')}", f"{_n(lang, row.a, '.2f')}", ph)
    return t


def _maxima_table(r: CamResult, lang: str):
    m, v = r.motion, r.variant
    mx = m.maxima
    rocker = v.is_rocker
    vu, au = (tr(lang, "rad/s"), tr(lang, "rad/s²")) if rocker else (tr(lang, "m/s"), tr(lang, "m/s²"))
    vs, as_ = ("ω", "ε") if rocker else ("V", "a")
    t = _table(
        tr(lang, "Extremes on rise and return"),
        (tr(lang, "Quantity"), "left"),
        (tr(lang, "Rise"), "right"),
        (tr(lang, "Return"), "right"),
    )
    t.add_row(f"{vs}_max, {vu}", f"{_n(lang, mx.v_rise_max, '.4f')} (φ = {_n(lang, mx.phi_v_rise_max_deg, '.1f')}°)", f"{_n(lang, mx.v_return_min, '.4f')} (φ = {_n(lang, mx.phi_v_return_min_deg, '.1f')}°)")
    t.add_row(f"{as_}_max, {au}", f"{_n(lang, mx.a_rise_max, '.2f')}", f"{_n(lang, mx.a_return_max, '.2f')}")
    t.add_row(f"{as_}_min, {au}", f"{_n(lang, mx.a_rise_min, '.2f')}", f"{_n(lang, mx.a_return_min, '.2f')}")
    if rocker:
        l = v.l_bc_m
        t.add_row(tr(lang, "V_B max, m/s (1.6)"), f"{_n(lang, mx.v_rise_max * l, '.4f')}", f"{_n(lang, mx.v_return_min * l, '.4f')}")
        t.add_row(tr(lang, "a_B max, m/s² (1.6)"), f"{_n(lang, max(abs(mx.a_rise_max), abs(mx.a_rise_min)) * l, '.2f')}", f"{_n(lang, max(abs(mx.a_return_max), abs(mx.a_return_min)) * l, '.2f')}")
    t.add_row(
        "|a_в.max / a_у.max| (1.7)",
        f"{_n(lang, mx.accel_ratio, '.6f')}",
        f"(φ_у/φ_в)² = {_n(lang, mx.accel_ratio_book, '.6f')}",
    )
    return t


def _scales_table(r: CamResult, lang: str):
    s, v = r.motion.scales, r.variant
    mm = tr(lang, "mm")
    t = _table(
        tr(lang, "Drawing scales (1.9)–(1.18)"),
        (tr(lang, "Scale"), "left"),
        (tr(lang, "Value"), "right"),
        (tr(lang, "Unit / formula"), "left"),
    )
    t.add_row(tr(lang, "layout"), f"b = {_n(lang, s.b_mm, 'g')} {mm}, Y_Smax = {_n(lang, s.y_s_max_mm, 'g')} {mm}", f"H_V = {_n(lang, s.h_v_mm, 'g')} {mm}, H_a = {_n(lang, s.h_a_mm, 'g')} {mm}")
    t.add_row("k_φ", _g(lang, s.k_phi_deg_mm, 5), tr(lang, "deg/mm = φ_р/b (1.9)"))
    t.add_row("k_t", _g(lang, s.k_t_s_mm, 5), tr(lang, "s/mm = φ_р/(6·|n_k|·b) (1.10)"))
    if v.is_rocker:
        t.add_row(tr(lang, "k_γ deg"), _g(lang, s.k_gamma_deg_mm, 5), tr(lang, "deg/mm = γ_max/Y_γmax (1.14)"))
        t.add_row(tr(lang, "k_γ rad"), _g(lang, s.k_s, 5), tr(lang, "rad/mm = k_γ deg·π/180 (1.15)"))
        t.add_row("k_ω", _g(lang, s.k_v, 5), tr(lang, "rad/s per mm = k_γ rad/(k_t·H_V) (1.16)"))
        t.add_row("k_ε", _g(lang, s.k_a, 5), tr(lang, "rad/s² per mm = k_ω/(k_t·H_a) (1.17)"))
        t.add_row("k_S", _g(lang, s.k_s_b, 5), tr(lang, "m/mm = k_γ rad·l_BC (1.18)"))
        t.add_row("k_V", _g(lang, s.k_v_b, 5), tr(lang, "m/s per mm = k_ω·l_BC (1.18)"))
        t.add_row("k_a", _g(lang, s.k_a_b, 5), tr(lang, "m/s² per mm = k_ε·l_BC (1.18)"))
    else:
        t.add_row("k_S", _g(lang, s.k_s, 5), tr(lang, "m/mm = S_max/Y_Smax (1.11)"))
        t.add_row("k_V", _g(lang, s.k_v, 5), tr(lang, "m/s per mm = k_S/(k_t·H_V) (1.12)"))
        t.add_row("k_a", _g(lang, s.k_a, 5), tr(lang, "m/s² per mm = k_V/(k_t·H_a) (1.13)"))
    t.add_row("Y_V max", f"{_n(lang, s.y_v_max_mm, '.1f')}", mm)
    t.add_row("Y_a.у.max", f"{_n(lang, s.y_a_rise_max_mm, '.1f')}", mm)
    t.add_row("Y_a.в.max", f"{_n(lang, s.y_a_return_max_mm, '.1f')}", f"{mm} = Y_a.у.max·(φ_у/φ_в)² (1.8)")
    return t


def _dims_table(r: CamResult, lang: str):
    z, p, v = r.sizing, r.profile, r.variant
    mm = tr(lang, "mm")
    t = _table(
        tr(lang, "Main dimensions (1.19)–(1.25), roller (1.28)"),
        (tr(lang, "Quantity"), "left"),
        (tr(lang, "Chosen (exact zone)") if r.source == "program" else tr(lang, "Your choice"), "right"),
        (tr(lang, "Book's vertex"), "right"),
        (tr(lang, "Note"), "left"),
    )
    t.add_row("r_0", f"{_n(lang, z.r0_m * 1000, '.2f')} {mm}", f"{_n(lang, z.book_r0_m * 1000, '.2f')} {mm}", tr(lang, "pitch-curve base radius |O B0|"))
    if v.is_rocker:
        t.add_row("l_OC", f"{_n(lang, z.l_oc_m * 1000, '.2f')} {mm}", f"{_n(lang, z.book_l_oc_m * 1000, '.2f')} {mm}", tr(lang, "cam centre to rocker pivot"))
        t.add_row("l_BC", f"{_n(lang, v.l_bc_m * 1000, '.2f')} {mm}", "", tr(lang, "given"))
        sw = tr(lang, "same way as the cam") if z.swing == "same" else tr(lang, "opposite to the cam")
        other = "" if z.r0_other_swing_m is None else tr(lang, "other swing: r_0 = {v} mm").format(v=_n(lang, z.r0_other_swing_m * 1000, '.2f'))
        t.add_row(tr(lang, "swing on rise"), sw, "", other)
    else:
        t.add_row("e", f"{_n(lang, z.e_m * 1000, '+.2f')} {mm}", f"{_n(lang, z.book_e_m * 1000, '+.2f')} {mm}", tr(lang, "e > 0: follower axis right of O (follower above the cam)"))
    t.add_row(
        tr(lang, "ν max on rise"),
        f"{_n(lang, z.nu_rise_max_deg, '.2f')}°",
        f"{_n(lang, z.book_nu_rise_max_deg, '.2f')}°",
        f"ν_max = {_n(lang, v.nu_max_deg, 'g')}°",
    )
    t.add_row(
        tr(lang, "ν max on return"),
        f"{_n(lang, z.nu_return_max_deg, '.2f')}°",
        f"{_n(lang, z.book_nu_return_max_deg, '.2f')}°",
        tr(lang, "not limited (spring)") if z.closure == "force" else f"ν_max = {_n(lang, v.nu_max_deg, 'g')}°",
    )
    rule = {"book": "0.2·r_0 (1.28)", "limited": tr(lang, "0.8·ρ_min (0.2·r_0 too large)"),
            "student": tr(lang, "your --roller")}.get(p.roller_rule, "")
    if lang == "ru":
        rule = rule.replace("0.2·r_0 (1.28)", "0,2·r_0 (1.28)")
    t.add_row("r_р", f"{_n(lang, p.roller_m * 1000, '.2f')} {mm}", f"{_n(lang, p.roller_book_m * 1000, '.2f')} {mm}", rule)
    t.add_row("r_0 − r_р", f"{_n(lang, p.working_min_radius_m * 1000, '.2f')} {mm}", "", tr(lang, "smallest radius of the working profile"))
    t.add_row(tr(lang, "far-dwell radius"), f"{_n(lang, p.r_far_m * 1000, '.2f')} {mm}", "", tr(lang, "pitch curve"))
    return t


def _psi_table(r: CamResult, lang: str):
    p, v = r.profile, r.variant
    t = _table(
        tr(lang, "Profile angles (1.1)–(1.4)"),
        (tr(lang, "Angle"), "left"),
        ("ψ, °", "right"),
        ("φ, °", "right"),
    )
    t.add_row("ψ_у", f"{_n(lang, p.psi_rise_deg, '.2f')}", f"{_n(lang, v.phi_rise_deg, 'g')}")
    t.add_row("ψ_дс", f"{_n(lang, abs(p.psi_far_deg), '.2f')}", f"{_n(lang, v.phi_far_dwell_deg, 'g')}")
    t.add_row("ψ_в", f"{_n(lang, p.psi_return_deg, '.2f')}", f"{_n(lang, v.phi_return_deg, 'g')}")
    t.add_row("ψ_бс", f"{_n(lang, p.psi_near_deg, '.2f')}", f"{_n(lang, v.phi_near_dwell_deg, 'g')}")
    t.add_row("ψ_р = φ_р (1.4)", f"{_n(lang, p.psi_working_deg, '.2f')}", f"{_n(lang, v.phi_working_deg, 'g')}")
    return t


_SIZE_NAMES = {
    "r0": ("r_0", N_("base radius of T")),
    "e": ("e", N_("offset")),
    "l_oc": ("l_OC", N_("centre distance")),
    "l_bc": ("l_BC", N_("rocker length")),
    "roller": ("r_р", N_("roller radius (1.28)")),
    "working_min_radius": ("r_0 − r_р", N_("smallest radius of D1")),
    "far_dwell_radius": ("R_дс", N_("far-dwell radius of T")),
    "stroke": ("S_max", N_("stroke")),
}


def _drawing_table(r: CamResult, lang: str):
    d, v = r.drawing, r.variant
    mm = tr(lang, "mm")
    t = _table(
        tr(lang, "Profile drawing scale (Table 1.1), (1.26)–(1.27)"),
        (tr(lang, "Quantity"), "left"),
        (tr(lang, "Real, {mm}").format(mm=mm), "right"),
        (tr(lang, "At k_S, {mm}").format(mm=mm), "right"),
        (tr(lang, "At k_Sk, {mm}").format(mm=mm), "right"),
        (tr(lang, "Note"), "left"),
    )
    w, h = d.extent_mm
    m_sign = tr(lang, "M")
    t.add_row(
        f"{m_sign} {d.scale}", "", "", f"k_Sk = {_n(lang, d.k_sk, 'g')}",
        tr(lang, "m/mm; largest for a {field_mm}×{field_mm} mm field").format(field_mm=_n(lang, d.field_mm, 'g')),
    )
    t.add_row(
        "k_S = k_S′", "", _g(lang, d.k_s, 5), f"k_S/k_Sk = {_n(lang, d.k_s / d.k_sk, '.4g')}",
        tr(lang, "m/mm, {formula}; k_S′ = k_S (§1.3.1)").format(formula="k_S_B (1.18)" if v.is_rocker else "(1.11)"),
    )
    t.add_row("", "", "y_Si, x_i", "y_Sik, x_ik", "y_Sik = (k_S/k_Sk)·y_Si (1.26); x_ik = (k_S′/k_Sk)·x_i (1.27)")
    t.add_row(
        tr(lang, "cam with roller"),
        f"{_n(lang, d.width_m * 1000, '.1f')} × {_n(lang, d.height_m * 1000, '.1f')}", "", f"{_n(lang, w, '.1f')} × {_n(lang, h, '.1f')}",
        (OK if d.fits else BAD) + " " + tr(lang, "≤ {field_mm} {mm}").format(field_mm=_n(lang, d.field_mm, 'g'), mm=mm),
    )
    for s in d.sizes:
        sym, name = _SIZE_NAMES[s.name]
        if s.name == "stroke" and v.is_rocker:
            sym, name = "S_B max", N_("arc γ_max·l_BC (1.6)")
        sign = "+" if s.name == "e" else ""
        t.add_row(sym, f"{_n(lang, s.length_m * 1000, sign + '.2f')}", f"{_n(lang, s.at_k_s_mm, sign + '.2f')}", f"{_n(lang, s.drawn_mm, sign + '.2f')}", f"({s.formula}) " + tr(lang, name))
    return t


def _checks_table(r: CamResult, lang: str):
    z, p, v, m = r.sizing, r.profile, r.variant, r.motion
    mm = tr(lang, "mm")
    t = _table(
        tr(lang, "Checks"),
        ("", "center"),
        (tr(lang, "Condition"), "left"),
        (tr(lang, "Value"), "left"),
    )
    lim = v.nu_max_deg + 0.01
    t.add_row(OK if z.nu_rise_max_deg <= lim else BAD, tr(lang, "ν ≤ ν_max on rise (1.19)"), f"{_nu(lang, z.nu_rise_max_deg, v.nu_max_deg)}° ≤ {_n(lang, v.nu_max_deg, 'g')}°")
    if z.closure == "form":
        t.add_row(OK if z.nu_return_max_deg <= lim else BAD, tr(lang, "ν ≤ ν_max on return (1.19)"), f"{_nu(lang, z.nu_return_max_deg, v.nu_max_deg)}° ≤ {_n(lang, v.nu_max_deg, 'g')}°")
    else:
        t.add_row(OK, tr(lang, "return by the spring (no jamming)"), f"ν ≤ {_n(lang, z.nu_return_max_deg, '.1f')}°")
    book_nu = z.book_nu_rise_max_deg if z.closure == "force" else max(z.book_nu_rise_max_deg, z.book_nu_return_max_deg)
    t.add_row(
        OK if book_nu <= v.nu_max_deg + 0.05 else WARN,
        tr(lang, "book's vertex keeps ν ≤ ν_max"),
        f"{_n(lang, book_nu, '.2f')}°",
    )
    rho = p.roller_max_m
    mark = BAD if p.undercut else (WARN if p.roller_m > 0.8 * rho else OK)
    what = tr(lang, "r_р < ρ_min (no undercut)")
    val = f"{_n(lang, p.roller_m * 1000, '.2f')} {mm} {'<' if not p.undercut else '≥'} {_n(lang, rho * 1000, '.2f')} {mm}"
    t.add_row(mark, what, val)
    if p.undercut and p.r0_for_rule_m is not None:
        fix = f"l_OC = {_n(lang, p.fix_l_oc_m * 1000, '.2f')} {mm}" if v.is_rocker else f"e = {_n(lang, p.fix_e_m * 1000, '+.2f')} {mm}"
        t.add_row("→", tr(lang, "fix: larger cam"), f"r_0 = {_n(lang, p.r0_for_rule_m * 1000, '.2f')} {mm}, {fix}")
    ch = r.checks
    if ch is not None and ch.pivot_ok is not None:
        t.add_row(OK if ch.pivot_ok else BAD, tr(lang, "pivot C outside the cam's sweep"),
                  f"l_OC = {_n(lang, ch.l_oc_m * 1000, '.2f')} {mm} {'>' if ch.pivot_ok else '≤'} {_n(lang, ch.body_m * 1000, '.2f')} {mm}")
    convex, concave = tr(lang, "convex"), tr(lang, "concave")
    conv = f"ρ_min {convex} = {_n(lang, p.rho_min_convex_m * 1000, '.2f')} {mm}"
    if p.rho_min_concave_m is not None:
        conv += f"; {concave} = {_n(lang, p.rho_min_concave_m * 1000, '.2f')} {mm}"
    t.add_row("", tr(lang, "pitch curve radius of curvature"), conv)
    ok = abs(p.psi_working_deg - v.phi_working_deg) < 1e-6
    t.add_row(OK if ok else BAD, "ψ_р = φ_р (1.4)", f"{_n(lang, p.psi_working_deg, '.4f')}° = {_n(lang, v.phi_working_deg, 'g')}°")
    mx = m.maxima
    ok = abs(mx.accel_ratio - mx.accel_ratio_book) < 1e-9
    t.add_row(OK if ok else BAD, "|a_в.max/a_у.max| = (φ_у/φ_в)² (1.7)", f"{_n(lang, mx.accel_ratio, '.6f')} = {_n(lang, mx.accel_ratio_book, '.6f')}")
    return t


def print_cam(console, result: CamResult, lang: str, *, include_input: bool = True) -> None:
    """Print sheet 3's tables to a rich Console (the shell prints the notes, once, at the end)."""
    makers = (_motion_table, _maxima_table, _scales_table, _dims_table, _psi_table, _drawing_table, _checks_table)
    if include_input:
        makers = (_input_table,) + makers
    for make in makers:
        console.print(make(result, lang))


def print_cam_input(console, result: CamResult, lang: str) -> None:
    """The input-data table alone (the project report opens with it)."""
    console.print(_input_table(result, lang))
