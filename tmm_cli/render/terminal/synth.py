"""`tmm synth` in the terminal: the derivation (formula = substitution = result), the construction's
steps, the lengths found and the check by `tmm linkage` beside the task."""

from __future__ import annotations

import math

from ...i18n import N_, tr
from ...i18n.numbers import num
from ...linkage.synthesis import RockerSynthesis, SliderSynthesis, rocker_construction_frame
from ..data.synth import checks

TITLES = {"crank-slider": N_("Synthesis of the crank-slider mechanism"),
          "crank-rocker": N_("Synthesis of the crank-rocker mechanism"),
          "slotted-link": N_("Synthesis of the slotted-link mechanism of a shaper")}

MECHANISM_NAMES = {"crank-slider": N_("Crank-slider mechanism"), "crank-rocker": N_("Crank-rocker mechanism"),
                   "slotted-link": N_("Slotted-link mechanism of a shaper")}


def _mm(x: float, lang: str) -> str:
    return num(x * 1000.0, lang, decimals=2)


def _deg(x: float, lang: str, decimals: int = 3) -> str:
    return num(math.degrees(x), lang, decimals=decimals) + "°"


def _k(x: float, lang: str) -> str:
    return num(x, lang, sig=6)


def _m3(x: float, lang: str) -> str:
    return num(x * 1000.0, lang, decimals=3)


def _pivot_lines(syn, lang: str, mm: str) -> list[str]:
    """The pivot A on the locus and the distances AC₁, AC₂, l_AD from its coordinates (origin D, y
    along the bisector of the swing), each formula = substitution = result."""
    p = rocker_construction_frame(syn)
    c1, c2, a, o = p["C1"], p["C2"], p["A"], p["O"]
    half, th = _deg(syn.swing / 2.0, lang), _deg(syn.theta, lang)
    sign = "−" if o.imag < c1.imag else "+"
    phi = math.atan2(a.imag - o.imag, a.real - o.real)
    xa, ya = _m3(a.real, lang), _m3(a.imag, lang)

    def dist(name, c):
        return (f"{name} = √((x_A − x_{name[1:]})² + (y_A − y_C)²) = √(({xa} − ({_m3(c.real, lang)}))² + "
                f"({ya} − {_m3(c.imag, lang)})²) = {_m3(abs(a - c), lang)} {mm}")

    return [f"y_C = l_CD·cos(ψ/2) = {_mm(syn.rocker, lang)}·cos {half} = {_m3(c1.imag, lang)} {mm}, "
            f"x_C₁ = {_m3(c1.real, lang)} {mm}, x_C₂ = {_m3(c2.real, lang)} {mm}",
            f"y_O = y_C {sign} R·cos θ = {_m3(c1.imag, lang)} {sign} {_m3(syn.radius, lang)}·cos {th} = "
            f"{_m3(o.imag, lang)} {mm}",
            f"φ_A = {_deg(phi, lang)}: x_A = R·cos φ_A = {xa} {mm}, y_A = y_O + R·sin φ_A = {ya} {mm}",
            dist("AC₁", c1), dist("AC₂", c2),
            f"l_AD = √(x_A² + y_A²) = √({xa}² + {ya}²) = {_mm(syn.frame, lang)} {mm}"]


def _mu_lines(syn, lang: str) -> list[str]:
    out = []
    for i, (sign, bd) in enumerate((("−", syn.frame - syn.crank), ("+", syn.frame + syn.crank)), 1):
        cos_mu = (syn.coupler ** 2 + syn.rocker ** 2 - bd ** 2) / (2.0 * syn.coupler * syn.rocker)
        mu = math.acos(max(-1.0, min(1.0, cos_mu)))
        out.append(f"cos μ{'₁₂'[i - 1]} = (l_BC² + l_CD² − (l_AD {sign} l_AB)²)/(2·l_BC·l_CD) = "
                   f"({_mm(syn.coupler, lang)}² + {_mm(syn.rocker, lang)}² − ({_mm(syn.frame, lang)} {sign} "
                   f"{_mm(syn.crank, lang)})²)/(2·{_mm(syn.coupler, lang)}·{_mm(syn.rocker, lang)}) = "
                   f"{num(cos_mu, lang, decimals=4)}, μ{'₁₂'[i - 1]} = {_deg(mu, lang, 2)}")
    return out


def derivation(result, lang: str) -> list[str]:
    """The formulas with their substitutions and results, lengths in mm, in the order of the work."""
    syn, v = result.synthesis, result.task.values
    mm = tr(lang, "mm")
    lines = []
    theta_line = (f"θ = 180°·(K − 1)/(K + 1) = 180°·({_k(syn.time_ratio, lang)} − 1)/({_k(syn.time_ratio, lang)} + 1) "
                  f"= {_deg(syn.theta, lang)}")
    if isinstance(syn, SliderSynthesis):
        h = _mm(syn.stroke, lang)
        if syn.mode == "lambda":
            lines += [f"l_OA = H/2 = {h}/2 = {_mm(syn.crank, lang)} {mm}",
                      f"l_AB = l_OA/λ = {_mm(syn.crank, lang)}/{num(syn.lam, lang, sig=6)} = {_mm(syn.rod, lang)} {mm}",
                      f"K = 1 (e = 0)"]
        elif syn.mode == "time_ratio":
            half = _deg(syn.theta / 2.0, lang)
            e = _mm(syn.offset, lang)
            lines += [theta_line,
                      f"e < H·ctg θ = {h}·ctg {_deg(syn.theta, lang)} = {_mm(syn.stroke / math.tan(syn.theta), lang)} {mm}",
                      f"l_OA = ½·√(H² − 2·H·e·tg(θ/2)) = ½·√({h}² − 2·{h}·{e}·tg {half}) = {_mm(syn.crank, lang)} {mm}",
                      f"l_AB = ½·√(H² + 2·H·e·ctg(θ/2)) = ½·√({h}² + 2·{h}·{e}·ctg {half}) = {_mm(syn.rod, lang)} {mm}",
                      f"λ = l_OA/l_AB = {_mm(syn.crank, lang)}/{_mm(syn.rod, lang)} = {num(syn.lam, lang, decimals=4)}"]
        else:
            lines += [f"H = √((l_AB + l_OA)² − e²) − √((l_AB − l_OA)² − e²), l_AB = l_OA/λ: "
                      f"l_OA = {_mm(syn.crank, lang)} {mm}",
                      f"l_AB = l_OA/λ = {_mm(syn.crank, lang)}/{num(syn.lam, lang, sig=6)} = {_mm(syn.rod, lang)} {mm}",
                      f"θ = arctg(e/x_B2) − arctg(e/x_B1) = arctg({_mm(syn.offset, lang)}/{_mm(syn.x_near, lang)}) − "
                      f"arctg({_mm(syn.offset, lang)}/{_mm(syn.x_far, lang)}) = {_deg(syn.theta, lang)}",
                      f"K = (180° + θ)/(180° − θ) = {num(syn.time_ratio, lang, decimals=4)}"]
    elif isinstance(syn, RockerSynthesis):
        c = _mm(syn.rocker, lang)
        chord = 2.0 * syn.rocker * math.sin(syn.swing / 2.0)
        a1, a2 = abs(syn.A - syn.C1), abs(syn.A - syn.C2)
        lines += [theta_line,
                  f"C₁C₂ = 2·l_CD·sin(ψ/2) = 2·{c}·sin {_deg(syn.swing / 2.0, lang)} = {_m3(chord, lang)} {mm}",
                  f"R = C₁C₂/(2·sin θ) = {_m3(chord, lang)}/(2·sin {_deg(syn.theta, lang)}) = {_m3(syn.radius, lang)} {mm}",
                  *_pivot_lines(syn, lang, mm),
                  f"l_AB = (AC₂ − AC₁)/2 = ({_m3(a2, lang)} − {_m3(a1, lang)})/2 = {_mm(syn.crank, lang)} {mm}",
                  f"l_BC = (AC₂ + AC₁)/2 = ({_m3(a2, lang)} + {_m3(a1, lang)})/2 = {_mm(syn.coupler, lang)} {mm}",
                  *_mu_lines(syn, lang),
                  "γ_min = min(μ₁, 180° − μ₁, μ₂, 180° − μ₂) = " + f"{_deg(syn.gamma_min, lang, 2)}" + (
                      f" ≥ γ = {num(v['min_transmission_deg'], lang, sig=6)}°" if syn.gamma_task is not None else "")]
    else:
        half = _deg(syn.theta / 2.0, lang)
        lines += [theta_line.replace("θ =", "ψ = θ =", 1),
                  f"l_O1A = l_O1O2·sin(θ/2) = {_mm(syn.frame, lang)}·sin {half} = {_mm(syn.crank, lang)} {mm}",
                  f"l_O2B = H/(2·sin(ψ/2)) = {_mm(syn.stroke, lang)}/(2·sin {half}) = {_mm(syn.link, lang)} {mm}",
                  f"f = l_O2B·(1 − cos(ψ/2)) = {_mm(syn.link, lang)}·(1 − cos {half}) = {_mm(syn.sagitta, lang)} {mm}",
                  f"h = l_O2B − f/2 = {_mm(syn.link, lang)} − {_mm(syn.sagitta, lang)}/2 = {_mm(syn.guide, lang)} {mm}",
                  f"l_BC = {num(syn.rod_ratio, lang, sig=6)}·l_O2B = {_mm(syn.rod, lang)} {mm}",
                  f"α_max = arcsin(f/(2·l_BC)) = {_deg(syn.rod_angle, lang, 2)}"]
    return lines


def steps(result, lang: str) -> list[str]:
    """The construction's steps, as a drafter does them on the sheet."""
    syn = result.synthesis
    if isinstance(syn, SliderSynthesis):
        if syn.mode == "lambda":
            return [tr(lang, "The central crank-slider: the guide passes through O; the stroke is twice the crank.")]
        return [tr(lang, "Draw the guide at the distance e from O; B₁ and B₂ are the slider's extreme positions, B₁B₂ = H."),
                tr(lang, "From O the stroke B₁B₂ is seen at the angle θ: OB₁ = l_AB + l_OA, OB₂ = l_AB − l_OA."),
                tr(lang, "Hence l_OA = (OB₁ − OB₂)/2 and l_AB = (OB₁ + OB₂)/2.")]
    if isinstance(syn, RockerSynthesis):
        return [tr(lang, "Draw the rocker CD in its two extreme positions C₁D and C₂D, ψ apart."),
                tr(lang, "Draw the circle through C₁ and C₂ on which the chord C₁C₂ subtends θ: the locus of the crank's pivot A."),
                tr(lang, "Choose A on the locus (by the frame l_AD or by the largest smallest transmission angle)."),
                tr(lang, "AC₁ = l_BC − l_AB, AC₂ = l_BC + l_AB (crank and coupler in line at the extreme positions).")]
    return [tr(lang, "The slotted link's extreme positions are tangent to the crank circle: it swings by ψ = θ."),
            tr(lang, "The ram's stroke is the chord of the arc of B: H = 2·l_O2B·sin(ψ/2)."),
            tr(lang, "The ram's guide passes through the middle of the sagitta f of that arc.")]


def check_table(result, lang: str):
    from rich.table import Table

    t = Table(title=tr(lang, "Check: tmm linkage's analysis of the mechanism written"), header_style="bold",
              title_justify="left")
    for name, justify in ((tr(lang, "Quantity"), "left"), (tr(lang, "Task"), "right"),
                          (tr(lang, "tmm linkage"), "right"), ("", "left")):
        t.add_column(name, justify=justify)
    names = {"stroke_m": (tr(lang, "Stroke H, mm"), 1000.0, 3), "swing_deg": (tr(lang, "Swing ψ, °"), 1.0, 4),
             "time_ratio": (tr(lang, "Time ratio K"), 1.0, 5), "gamma_min_deg": (tr(lang, "Smallest transmission angle γ_min, °"), 1.0, 2)}
    for key, c in checks(result).items():
        label, scale, dec = names[key]
        task = "—" if c["task"] is None else num(c["task"] * scale, lang, decimals=dec)
        t.add_row(label, task, num(c["linkage"] * scale, lang, decimals=dec), "✓" if c["ok"] else "✗")
    return t


def print_synth(console, result, lang: str) -> None:
    from . import escape

    title, construction = tr(lang, TITLES[result.task.type]), tr(lang, "Construction")
    console.print(f"[bold]{escape(title)}[/]")
    for line in derivation(result, lang):
        console.print("  " + escape(line))
    console.print(f"[bold]{escape(construction)}[/]")
    for i, line in enumerate(steps(result, lang), 1):
        console.print(f"  {i}. " + escape(line))
    console.print(check_table(result, lang))
