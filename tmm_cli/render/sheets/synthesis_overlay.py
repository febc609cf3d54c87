"""Sheet 1 draws the synthesis' construction over the scheme when the mechanism file records its
task (`tmm synth`, issue 33): the angle θ between the crank's positions at the two extreme
positions (crank-slider: the rays from O to the slider's extreme positions; crank-rocker: the rays
from A to the rocker's ends C₁, C₂, the chord C₁C₂ and the locus circle through A, C₁, C₂), or the
slotted link's swing ψ = θ with the sagitta of the arc of B. Called from one line of the scheme
field (:mod:`.linkage_sheet`); the points are the extreme positions `tmm linkage` solved, so the
construction lies on the drawn mechanism.
"""

from __future__ import annotations

import math

import numpy as np

from ...i18n import tr
from ...i18n.numbers import num
from ...linkage.synthesis_file import recorded_synthesis

MM = 1000.0


def sheet_name(s, lang: str) -> str:
    """Sheet 1's name in the title block: the synthesis named too when the file records it."""
    rec = recorded_synthesis(s.mechanism)
    if rec is not None and rec.matches:
        return tr(lang, "Synthesis and kinematic analysis of the lever mechanism")
    return tr(lang, "Kinematic analysis of the lever mechanism")


def _extreme_points(s, joint: str) -> list[complex]:
    """`joint` [real mm] at the start and at the end of the working stroke."""
    c = s.cycle
    out = []
    for which in ("start", "end"):
        p = next((p for p in c.positions if p.extreme == which), None)
        if p is None:
            return []
        out.append(complex(c.kin.z[joint][p.index]) * MM)
    return out


def _angle_dim(sh, f, centre: complex, a: complex, b: complex, radius_real: float, text: str, within) -> None:
    """The angle at `centre` between the rays to `a` and `b` (the smaller one), dimensioned."""
    q = np.array(f.p(centre.real, centre.imag))
    a0, a1 = math.degrees(math.atan2((a - centre).imag, (a - centre).real)), math.degrees(
        math.atan2((b - centre).imag, (b - centre).real))
    if (a1 - a0) % 360.0 > 180.0:
        a0, a1 = a1, a0
    r = max(radius_real * f.scale, 8.0)
    sh.dim_arc(q, r, a0 % 360.0, a0 % 360.0 + (a1 - a0) % 360.0, text, within=within, priority=6)


def _circumcircle(a: complex, b: complex, c: complex) -> tuple[complex, float] | None:
    d = 2.0 * (a.real * (b.imag - c.imag) + b.real * (c.imag - a.imag) + c.real * (a.imag - b.imag))
    if abs(d) < 1e-12:
        return None
    aa, bb, cc = abs(a) ** 2, abs(b) ** 2, abs(c) ** 2
    ux = (aa * (b.imag - c.imag) + bb * (c.imag - a.imag) + cc * (a.imag - b.imag)) / d
    uy = (aa * (c.real - b.real) + bb * (a.real - c.real) + cc * (b.real - a.real)) / d
    centre = complex(ux, uy)
    return centre, abs(a - centre)


def _dim(sh, f, a: complex, b: complex, side: complex, gap_mm: float, text: str, within) -> None:
    """A linear dimension between the real points `a`, `b` [mm], its line `gap_mm` [sheet mm] off
    towards the side of the unit vector `side`."""
    pa, pb = np.array(f.p(a.real, a.imag)), np.array(f.p(b.real, b.imag))
    sh.dim_linear(pa, pb, np.array([side.real, side.imag]) * gap_mm, text, within=within, priority=6)


def _mark(f, z: complex, text: str, within) -> None:
    f.label(text, (z.real, z.imag), within=within, priority=5)


def _locus_arc(f, centre: complex, radius: float, pts: list[complex]) -> tuple[float, float]:
    """The locus circle drawn as its arc through `pts` (the crank's centre and the rocker's ends) and
    a margin beyond them — not the whole circle, which runs off the field. Returns the arc's angles [deg]."""
    angs = sorted(math.degrees(math.atan2((z - centre).imag, (z - centre).real)) % 360.0 for z in pts)
    gaps = [(angs[(i + 1) % len(angs)] - angs[i]) % 360.0 for i in range(len(angs))]
    k = int(np.argmax(gaps))  # the arc leaves out the largest gap between the points
    a0, span = angs[(k + 1) % len(angs)], 360.0 - gaps[k]
    margin = min(15.0, gaps[k] / 3.0)
    t = np.radians(np.linspace(a0 - margin, a0 + span + margin, 181))
    z = centre + radius * np.exp(1j * t)
    f.poly(np.column_stack([z.real, z.imag]), "Осевые")
    return a0, span


def draw_construction(sh, f, s, lang: str, within) -> None:
    rec = recorded_synthesis(s.mechanism)
    if rec is None or not rec.matches:
        return
    m, kind, syn = s.mechanism, rec.task.type, rec.synthesis
    deg = "°"
    theta = num(math.degrees(syn.theta), lang, decimals=2) + deg

    def mm(x: float) -> str:
        return num(x, lang, decimals=1)

    if kind == "crank-slider":
        o = m.frame[m.crank.pivot] * MM
        bs = _extreme_points(s, m.groups[0].joints[1])
        if len(bs) < 2:
            return
        bs = sorted(bs, key=lambda b: -abs(b - o))  # B₁ the far extreme position, as the derivation
        guide = (bs[1] - bs[0]) / abs(bs[1] - bs[0]) if abs(bs[1] - bs[0]) > 1e-9 else 1 + 0j
        normal = 1j * guide
        foot = bs[0] + ((o - bs[0]) * guide.conjugate()).real * guide  # the foot of the perpendicular from O
        away = normal if ((o - foot) * normal.conjugate()).real < 0 else -normal  # from the guide, away from O
        for i, b in enumerate(bs, 1):
            _mark(f, b, f"B_{{{i}}}", within)
        _dim(sh, f, bs[0], bs[1], away, 9.0, "H = " + mm(syn.stroke * MM), within)
        if syn.offset > 1e-9:
            f.line((o.real, o.imag), (foot.real, foot.imag), "Тонкие")
            _dim(sh, f, o, foot, -guide if ((o - bs[0]) * guide.conjugate()).real > 0 else guide, 6.0,
                 "e = " + mm(syn.offset * MM), within)
        if syn.theta < 1e-6:
            return
        for b in bs:
            f.line((o.real, o.imag), (b.real, b.imag), "Тонкие")
        _angle_dim(sh, f, o, bs[0], bs[1], 0.6 * min(abs(b - o) for b in bs), "θ = " + theta, within)
    elif kind == "crank-rocker":
        a = m.frame[m.crank.pivot] * MM
        d = m.frame[m.groups[0].joints[2]] * MM
        cs = _extreme_points(s, m.groups[0].joints[1])
        if len(cs) < 2:
            return
        # C₁ the folded extreme position (AC₁ = l_BC − l_AB), C₂ the extended one, as the derivation
        cs = sorted(cs, key=lambda z: abs(z - a))
        for z in cs:
            f.line((a.real, a.imag), (z.real, z.imag), "Тонкие")
        f.line((cs[0].real, cs[0].imag), (cs[1].real, cs[1].imag), "Тонкие")
        for i, z in enumerate(cs, 1):
            _mark(f, z, f"C_{{{i}}}", within)
        out = (cs[0] + cs[1]) / 2.0 - d
        out = out / abs(out) if abs(out) > 1e-9 else 1j
        _dim(sh, f, cs[0], cs[1], out, 7.0, "C_{1}C_{2} = " + mm(abs(cs[1] - cs[0])), within)
        circ = _circumcircle(a, cs[0], cs[1])
        if circ is not None:
            centre, radius = circ
            a0, span = _locus_arc(f, centre, radius, [a, cs[0], cs[1]])
            mid = math.radians(a0 + span / 2.0)
            rim = centre + radius * complex(math.cos(mid), math.sin(mid))
            f.line((centre.real, centre.imag), (rim.real, rim.imag), "Тонкие")
            f.label("R = " + mm(radius), ((centre.real + rim.real) / 2, (centre.imag + rim.imag) / 2),
                    within=within, priority=4)
        _angle_dim(sh, f, a, cs[0], cs[1], 0.45 * min(abs(z - a) for z in cs), "θ = " + theta, within)
        _angle_dim(sh, f, d, cs[0], cs[1], 0.4 * abs(cs[0] - d),
                   "ψ = " + num(math.degrees(syn.swing), lang, decimals=2) + deg, within)
    else:
        o2 = m.frame[m.groups[0].joints[1]] * MM
        bs = _extreme_points(s, "B")
        if len(bs) < 2:
            return
        link = abs(bs[0] - o2)
        _angle_dim(sh, f, o2, bs[0], bs[1], 0.3 * link, "ψ = θ = " + theta, within)
        chord_mid = (bs[0] + bs[1]) / 2.0
        up = (chord_mid - o2) / abs(chord_mid - o2)
        top = o2 + up * link
        f.line((bs[0].real, bs[0].imag), (bs[1].real, bs[1].imag), "Тонкие")
        f.line((chord_mid.real, chord_mid.imag), (top.real, top.imag), "Тонкие")
        # the sagitta as a dimension: its line beside the sagitta, off towards the side away from the ram
        c_end = _extreme_points(s, m.groups[-1].joints[1])
        side = -1j * up
        if c_end and ((c_end[0] - chord_mid) * side.conjugate()).real > 0:
            side = -side
        _dim(sh, f, chord_mid, top, side, 5.0, "f = " + num(syn.sagitta * MM, lang, decimals=1), within)
