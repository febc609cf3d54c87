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

from ...i18n.numbers import num
from ...linkage.synthesis_file import recorded_synthesis

MM = 1000.0


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


def draw_construction(sh, f, s, lang: str, within) -> None:
    rec = recorded_synthesis(s.mechanism)
    if rec is None or not rec.matches:
        return
    m, kind = s.mechanism, rec.task.type
    deg = "°"
    theta = num(math.degrees(rec.synthesis.theta), lang, decimals=2) + deg
    if kind == "crank-slider":
        o = m.frame[m.crank.pivot] * MM
        bs = _extreme_points(s, m.groups[0].joints[1])
        if len(bs) < 2 or rec.synthesis.theta < 1e-6:
            return
        for b in bs:
            f.line((o.real, o.imag), (b.real, b.imag), "Тонкие")
        _angle_dim(sh, f, o, bs[0], bs[1], 0.6 * min(abs(b - o) for b in bs), "θ = " + theta, within)
    elif kind == "crank-rocker":
        a = m.frame[m.crank.pivot] * MM
        cs = _extreme_points(s, m.groups[0].joints[1])
        if len(cs) < 2:
            return
        for z in cs:
            f.line((a.real, a.imag), (z.real, z.imag), "Тонкие")
        f.line((cs[0].real, cs[0].imag), (cs[1].real, cs[1].imag), "Тонкие")
        circ = _circumcircle(a, cs[0], cs[1])
        if circ is not None:
            f.circle((circ[0].real, circ[0].imag), circ[1], "Осевые")
        _angle_dim(sh, f, a, cs[0], cs[1], 0.45 * min(abs(z - a) for z in cs), "θ = " + theta, within)
    else:
        o2 = m.frame[m.groups[0].joints[1]] * MM
        bs = _extreme_points(s, "B")
        if len(bs) < 2:
            return
        link = abs(bs[0] - o2)
        _angle_dim(sh, f, o2, bs[0], bs[1], 0.3 * link, "ψ = θ = " + theta, within)
        chord_mid = (bs[0] + bs[1]) / 2.0
        top = o2 + (chord_mid - o2) / abs(chord_mid - o2) * link
        f.line((bs[0].real, bs[0].imag), (bs[1].real, bs[1].imag), "Тонкие")
        f.line((chord_mid.real, chord_mid.imag), (top.real, top.imag), "Тонкие")
        f.label("f = " + num(rec.synthesis.sagitta * MM, lang, decimals=1), ((chord_mid.real + top.real) / 2,
                                                                            (chord_mid.imag + top.imag) / 2),
                within=within, priority=4)
