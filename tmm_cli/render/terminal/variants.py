"""Rich tables for Table 1.2: the whole list and one row explained."""

from __future__ import annotations

from ...i18n import N_, tr, trc
from ...i18n.numbers import num
from ...variants import Variant

SCHEME_WORDS = {
    1: N_("translating roller follower, force closure (spring)"),
    2: N_("translating roller follower, form closure (grooved cam)"),
    3: N_("oscillating roller follower (rocker), force closure (spring)"),
    4: N_("oscillating roller follower (rocker), form closure (grooved cam)"),
}
LAW_WORDS = {
    1: N_("constant acceleration (parabolic)"),
    2: N_("linearly decreasing acceleration"),
    3: N_("cosine acceleration (harmonic)"),
    4: N_("sine acceleration (cycloidal)"),
}


def scheme_words(scheme: int, lang: str) -> str:
    return tr(lang, SCHEME_WORDS[scheme])


def law_words(law: int, lang: str) -> str:
    return tr(lang, LAW_WORDS[law])


def rotation_words(v: Variant, lang: str) -> str:
    if v.ccw:
        return tr(lang, "counter-clockwise (n_k > 0)")
    return tr(lang, "clockwise (n_k < 0)")


def stroke_text(v: Variant, lang: str = "en") -> str:
    return f"{_g(v.stroke, lang)}°" if v.is_rocker else f"{_g(v.stroke, lang)} " + tr(lang, "m")


def _g(x, lang: str) -> str:
    """A table value as the book prints it (up to 6 significant digits), decimal comma under ru."""
    return num(x, lang, sig=6, sci=False)


def print_variant_table(console, table: dict[int, Variant], lang: str) -> None:
    from rich.table import Table

    t = Table(title=tr(lang, "Table 1.2 — variants of sheet 3"), header_style="bold")
    for head in (
        tr(lang, "No."),
        trc(lang, "column, short", "Scheme"),
        tr(lang, "l_BC, m"),
        "ν_max, °",
        tr(lang, "n_k, rpm"),
        tr(lang, "S_max, m / γ_max, °"),
        trc(lang, "column, short", "Law"),
        "φ_у, °",
        "φ_дс, °",
        "φ_в, °",
        "φ_бс, °",
    ):
        t.add_column(head, justify="right")
    for n in sorted(table):
        v = table[n]
        t.add_row(
            str(n), str(v.scheme), "—" if v.l_bc_m is None else _g(v.l_bc_m, lang), _g(v.nu_max_deg, lang),
            _g(v.n_cam_rpm, lang), stroke_text(v, lang), str(v.law), _g(v.phi_rise_deg, lang),
            _g(v.phi_far_dwell_deg, lang), _g(v.phi_return_deg, lang), _g(v.phi_near_dwell_deg, lang),
        )
    console.print(t)
    console.print(tr(lang, "Schemes: 1, 2 translating follower; 3, 4 rocker; 1, 3 spring (force closure); 2, 4 grooved cam (form closure)."))


def print_variant_detail(console, v: Variant, lang: str) -> None:
    from rich.table import Table

    t = Table(title=tr(lang, "Variant {number}").format(number=v.number), header_style="bold", show_lines=False)
    t.add_column(tr(lang, "Field"))
    t.add_column(tr(lang, "Value"), justify="right")
    t.add_column(tr(lang, "Meaning"))
    t.add_row(trc(lang, "field", "Scheme"), str(v.scheme), scheme_words(v.scheme, lang))
    if v.is_rocker:
        t.add_row("l_BC", f"{_g(v.l_bc_m, lang)} " + tr(lang, "m"), tr(lang, "rocker length"))
        t.add_row("γ_max", f"{_g(v.stroke, lang)}°", trc(lang, "field", "rocker swing"))
    else:
        t.add_row("S_max", f"{_g(v.stroke, lang)} " + tr(lang, "m"), trc(lang, "field", "follower stroke"))
    t.add_row("ν_max", f"{_g(v.nu_max_deg, lang)}°", tr(lang, "maximum allowed pressure angle"))
    t.add_row("n_k", f"{_g(v.n_cam_rpm, lang)} " + tr(lang, "rpm"), rotation_words(v, lang))
    t.add_row("ω_k", f"{num(v.omega_cam, lang, decimals=3)} " + tr(lang, "rad/s"), "ω_k = π·|n_k|/30 (1.5)")
    t.add_row(tr(lang, "Law"), str(v.law), law_words(v.law, lang))
    t.add_row("φ_у", f"{_g(v.phi_rise_deg, lang)}°", trc(lang, "field", "rise"))
    t.add_row("φ_дс", f"{_g(v.phi_far_dwell_deg, lang)}°", trc(lang, "field", "far dwell"))
    t.add_row("φ_в", f"{_g(v.phi_return_deg, lang)}°", trc(lang, "field", "return"))
    t.add_row("φ_бс", f"{_g(v.phi_near_dwell_deg, lang)}°", tr(lang, "near dwell = 360° − (φ_у + φ_дс + φ_в)"))
    t.add_row("φ_р", f"{_g(v.phi_working_deg, lang)}°", tr(lang, "working angle (1.3)"))
    console.print(t)
