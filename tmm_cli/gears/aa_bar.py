"""Seed 000 (Kavetsky, 2010): synthesis of the planetary mechanism AA̅ with different meshing angles
of its two stages, then the profile shifts of both pairs and their blocking-contour checks.

The mechanism: sun 1 (input) meshes planet 2; the planet is one gear (linked wheels, Z3 = Z2,
x3 = x2) and meshes the fixed central wheel 4; both meshes are external; the carrier H is the
output. Equations (notation of the seed, i = i_1H^(4), C = cos α_w12/cos α_w34):

* ratio:        i = 1 − Z2·Z4/(Z1·Z3) = 1 − Z4/Z1                     → Z4 = Z1(1 − i);
* coaxiality:   a_w12 = a_w34 ⇔ (Z1 + Z2)·cos α_w34 = (Z3 + Z4)·cos α_w12 ⇔ Z1 + Z2 = C(Z2 + Z4)
                                                                        → Z2 = Z1(C − C·i − 1)/(1 − C);
* assembly:     k planets at 360°/k: the sun turns by a whole number of teeth while the carrier
                turns by 360°/k with wheel 4 fixed, Z1·i/k = (Z1 − Z4)/k whole (exact for one
                planet gear: its phase cancels between its two meshes).

Z2 > 0 with 0 < i < 1 requires 1 < C < 1/(1 − i): the feasible range of C.

The divisibility rule (derived here, proven by brute force in tests/test_planetary_aa.py): with
i = A/B and C = P/Q in lowest terms, Z1 must be a multiple of each of

* B (Z4 whole; gcd(B − A, B) = 1),
* B(P − Q)/gcd(Q·B − P(B − A), B(P − Q)) (Z2 whole),
* B·k/gcd(A, B·k) (assembly),

and of their least common multiple, which is the smallest Z1; every multiple of it is a solution.
This is what the seed's MathCad sheet computes; its printed sentence "Z1 is a multiple of (kB;
Bc − Ac; B)" is not (for C = 26/25, i = 1/10 it would not allow Z1 = 30).
"""

from __future__ import annotations

import math
import re
from fractions import Fraction

from ..errors import TmmError
from ..notes import Note
from ..records import record
from .blocking import Check, PairChecks, check_neighbours, check_pair, pair_notes
from .shifted import (
    ALPHA_DEG,
    C_STAR,
    HA_STAR,
    PairGeometry,
    pair_geometry,
    require_working,
    shift_sum_for_distance,
)

Z_MIN = 18
Z_MAX = 180

_FRACTION_RE = re.compile(r"^\s*(\d+(?:\.\d*)?|\.\d+)\s*(?:/\s*(\d+(?:\.\d*)?|\.\d+)\s*)?$")


def parse_fraction(text: str, what: str, example: str) -> Fraction:
    """A positive exact fraction from "p/q" or a decimal ("1/10", "0.1", "26/25", "1.04").

    >>> parse_fraction("1/10", "i", "1/10"), parse_fraction("1.04", "C", "26/25"), parse_fraction("104/100", "C", "")
    (Fraction(1, 10), Fraction(26, 25), Fraction(26, 25))
    """
    m = _FRACTION_RE.match(str(text) if text is not None else "")
    if not m:
        raise TmmError(f"cannot read {what} = {text!r}: write it as a positive fraction, e.g. {example}")
    num = Fraction(m.group(1))
    den = Fraction(m.group(2)) if m.group(2) is not None else Fraction(1)
    if num <= 0 or den <= 0:
        raise TmmError(f"{what} = {text!r} must be a positive fraction, e.g. {example}")
    return num / den


def c_range(i: Fraction) -> tuple[Fraction, Fraction]:
    """Open interval of feasible C for the ratio i: 1 < C < 1/(1 − i) (Z2 > 0 in the coaxiality).

    >>> c_range(Fraction(1, 10))
    (Fraction(1, 1), Fraction(10, 9))
    """
    return Fraction(1), 1 / (1 - i)


@record
class Divisibility:
    """The multiples Z1 must take and the tooth numbers per unit of Z1."""

    i: Fraction
    c: Fraction
    planets: int
    m_ratio: int  # B: Z4 = Z1(B − A)/B whole
    m_coaxial: int  # Z2 whole
    m_assembly: int  # Z1·i/k whole
    z1_step: int  # lcm of the three: the smallest Z1
    z2_per_z1: Fraction
    z4_per_z1: Fraction

    @property
    def multiples(self) -> tuple[int, int, int]:
        """In the seed's order: assembly (k·B/…), coaxiality, ratio (B)."""
        return self.m_assembly, self.m_coaxial, self.m_ratio


def divisibility(i: Fraction, c: Fraction, planets: int) -> Divisibility:
    """The divisibility rule for Z1 (see the module docstring).

    Seed 000's example, i = 1/10, C = 26/25, k = 3: multiples 30, 5, 10; Z1_min = 30, Z2 = 48, Z4 = 27.

    >>> d = divisibility(Fraction(1, 10), Fraction(26, 25), 3)
    >>> d.multiples, d.z1_step, d.z1_step * d.z2_per_z1, d.z1_step * d.z4_per_z1
    ((30, 5, 10), 30, Fraction(48, 1), Fraction(27, 1))
    """
    a, b = i.numerator, i.denominator
    p, q = c.numerator, c.denominator
    num = q * b - p * (b - a)  # Z2/Z1 = num/den
    den = b * (p - q)
    m_coax = abs(den) // math.gcd(num, den)
    m_asm = b * planets // math.gcd(a, b * planets)
    step = math.lcm(b, m_coax, m_asm)
    return Divisibility(i=i, c=c, planets=planets, m_ratio=b, m_coaxial=m_coax, m_assembly=m_asm, z1_step=step,
                        z2_per_z1=Fraction(num, den), z4_per_z1=Fraction(b - a, b))


def teeth_for(div: Divisibility, multiple: int) -> tuple[int, int, int, int]:
    """(Z1, Z2, Z3, Z4) of the ``multiple``-th family member (Z3 = Z2, linked planet)."""
    z1 = div.z1_step * multiple
    z2 = div.z2_per_z1 * z1
    z4 = div.z4_per_z1 * z1
    assert z2.denominator == 1 and z4.denominator == 1
    return z1, int(z2), int(z2), int(z4)


def family(div: Divisibility, z_min: int = Z_MIN, z_max: int = Z_MAX) -> tuple[int, ...]:
    """The multiples n whose set Z1 = n·Z1_step … has every wheel within z_min … z_max.

    >>> family(divisibility(Fraction(1, 10), Fraction(26, 25), 3))
    (1, 2, 3)
    """
    out = []
    n = 1
    while True:
        t = teeth_for(div, n)
        if min(t) > z_max:
            break
        if z_min <= min(t) and max(t) <= z_max:
            out.append(n)
        if t[0] > z_max and min(t) > z_max:
            break
        n += 1
        if n > 100000:  # pragma: no cover - cannot happen with z_max finite
            break
    return tuple(out)


@record
class AAVelocity:
    """The velocity picture along the line from the central axis through a planet's centre, with
    ω_H = 1 rad/s (velocities in mm/s): the planet's velocity is zero at the pitch point P34
    (radius r_w4, wheel 4 fixed) and V_C = ω_H·a_w at its centre; at P12 (radius r_w1) it equals
    the sun's ω1·r_w1. i = ω1/ω_H = tg φ1/tg φ_H."""

    r_w1_mm: float
    r_w4_mm: float
    a_w_mm: float
    r_planet_top_mm: float  # a_w + r_a,planet: the top of the planet in the picture
    v_c: float
    v_p12: float
    phi_1_deg: float
    phi_h_deg: float
    ratio: float


@record
class AABarDesign:
    """The synthesis result: tooth numbers, shifts, both pairs, their checks and the velocity picture."""

    i: Fraction
    c: Fraction
    planets: int
    module_mm: float
    alpha_deg: float
    ha_star: float
    c_star: float
    z_min: int
    z_max: int
    div: Divisibility
    family: tuple[int, ...]
    multiple: int
    teeth: tuple[int, int, int, int]
    x: tuple[float, float, float, float]
    pair12: PairGeometry
    pair34: PairGeometry
    checks12: PairChecks
    checks34: PairChecks
    neighbours: Check
    da_planet_mm: float
    c_feasible: tuple[Fraction, Fraction]
    ratio_check: Fraction  # 1 − Z2Z4/(Z1Z3)
    c_check: float  # cos α_w12/cos α_w34 from the angles
    velocity: AAVelocity
    notes: tuple[Note, ...]

    @property
    def a_w_mm(self) -> float:
        return self.pair12.a_w_mm

    @property
    def alpha_w_deg(self) -> tuple[float, float]:
        return self.pair12.alpha_w_deg, self.pair34.alpha_w_deg

    @property
    def x_sum(self) -> tuple[float, float]:
        return self.pair12.x_sum, self.pair34.x_sum


def _velocity(p12: PairGeometry, p34: PairGeometry, da_planet: float) -> AAVelocity:
    r1 = p12.dw_mm[0] / 2
    r4 = p34.dw_mm[1] / 2
    aw = p12.a_w_mm
    vc = aw * 1.0
    v12 = vc * (r1 - r4) / (aw - r4)
    return AAVelocity(r_w1_mm=r1, r_w4_mm=r4, a_w_mm=aw, r_planet_top_mm=aw + da_planet / 2, v_c=vc, v_p12=v12,
                      phi_1_deg=math.degrees(math.atan2(v12, r1)), phi_h_deg=math.degrees(math.atan2(vc, aw)),
                      ratio=(v12 / r1) / (vc / aw))


def synthesize(i: Fraction, c: Fraction, planets: int, module_mm: float = 5.0, x1: float = 0.0, x2: float = 0.0,
               z_min: int = Z_MIN, z_max: int = Z_MAX, multiple: int | None = None,
               alpha_deg: float = ALPHA_DEG, ha_star: float = HA_STAR, c_star: float = C_STAR) -> AABarDesign:
    """Seed 000 end to end: tooth numbers (Fig. 1 of the seed), then the shifts (Fig. 2).

    >>> d = synthesize(Fraction(1, 10), Fraction(26, 25), 3, 5.0, -0.4, 0.4)
    >>> d.teeth, d.family, round(d.a_w_mm, 6), [round(a, 3) for a in d.alpha_w_deg]
    ((30, 48, 48, 27), (1, 2, 3), 195.0, [20.0, 25.371])
    >>> [round(v, 3) for v in d.x], [round(v, 3) for v in d.x_sum], d.ratio_check, round(d.c_check, 6)
    ([-0.4, 0.4, 0.4, 1.3], [0.0, 1.7], Fraction(1, 10), 1.04)
    """
    i, c = Fraction(i), Fraction(c)
    if i <= 0:
        raise TmmError(f"the ratio i = {i} must be a positive fraction, e.g. --ratio 1/10")
    if i >= 1:
        raise TmmError(f"the ratio i = {i} of the AA̅ mechanism must be less than 1 (i = 1 − Z4/Z1 with Z4 > 0); "
                       "e.g. --ratio 1/10")
    if int(planets) != planets or planets < 1:
        raise TmmError(f"number of planets must be a whole number ≥ 1, got {planets!r}; e.g. --planets 3")
    planets = int(planets)
    if not (math.isfinite(module_mm) and module_mm > 0):
        raise TmmError(f"module must be a positive number of mm, got {module_mm!r}; e.g. --module 5")
    for name, v in (("x1", x1), ("x2", x2)):
        if not math.isfinite(v):
            raise TmmError(f"shift {name} must be a number, got {v!r}; e.g. --{name} 0.4")
    if z_min < 1 or z_max < z_min:
        raise TmmError(f"tooth limits {z_min} … {z_max} are empty; give 1 ≤ --z-min ≤ --z-max, e.g. --z-min 18 --z-max 180")
    lo, hi = c_range(i)
    if not lo < c < hi:
        shown = f"{c}" if c.denominator == 1 else f"{c} = {float(c):.4g}"
        raise TmmError(f"C = {shown} is outside its feasible range for i = {i}: 1 < C < 1/(1 − i) = "
                       f"{hi} ≈ {float(hi):.4f} (else Z2 ≤ 0); choose C inside it, e.g. --c "
                       f"{_suggest_c(i)}")
    div = divisibility(i, c, planets)
    fam = family(div, z_min, z_max)
    if not fam:
        t = teeth_for(div, 1)
        raise TmmError(f"no tooth set within {z_min} … {z_max} teeth: the smallest for i = {i}, C = {c}, k = {planets} is "
                       f"Z = {'/'.join(map(str, t))} (Z1 a multiple of {div.z1_step}); widen --z-min/--z-max or choose "
                       "a simpler C")
    if multiple is None:
        multiple = fam[0]
    elif multiple not in fam:
        raise TmmError(f"--family {multiple} is not within the tooth limits {z_min} … {z_max}; the family is "
                       f"{', '.join('×' + str(n) for n in fam)}")
    teeth = teeth_for(div, multiple)
    z1, z2, z3, z4 = teeth
    m = float(module_mm)
    notes: list[Note] = []
    # stage 1-2 from the given shifts; stage 3-4 from the common centre distance, x3 = x2
    p12 = pair_geometry(z1, z2, m, x1, x2, alpha_deg, ha_star, c_star)
    a_w = p12.a_w_mm
    try:
        _, xs34 = shift_sum_for_distance(z3, z4, m, a_w, alpha_deg)
    except TmmError:
        raise TmmError(f"the centre distance a_w = {a_w:.3f} mm of the first pair is too small for Z3 + Z4 = {z3 + z4}; "
                       "increase x1 + x2") from None
    x3 = x2
    x4 = xs34 - x3
    p34 = pair_geometry(z3, z4, m, x3, x4, alpha_deg, ha_star, c_star)
    # the planet is one gear: one tip circle, the smaller of the two the meshes allow (radial clearance in both)
    da_pl = min(p12.da_nominal_mm[1], p34.da_nominal_mm[0])
    if abs(p12.da_nominal_mm[1] - p34.da_nominal_mm[0]) > 1e-9:
        notes.append(Note.make("aa_planet_tip", "assumption", da=f"{da_pl:.3f}", da12=f"{p12.da_nominal_mm[1]:.3f}",
                               da34=f"{p34.da_nominal_mm[0]:.3f}"))
    p12 = pair_geometry(z1, z2, m, x1, x2, alpha_deg, ha_star, c_star, da_mm=(p12.da_nominal_mm[0], da_pl))
    p34 = pair_geometry(z3, z4, m, x3, x4, alpha_deg, ha_star, c_star, da_mm=(da_pl, p34.da_nominal_mm[1]))
    for g, names in ((p12, ("1", "2")), (p34, ("3", "4"))):
        for j in range(2):
            if g.sa_mm[j] <= 0:
                raise TmmError(f"the shifts make gear {names[j]} (Z = {g.z[j]}, x = {g.x[j]:.3f}) pointed: its tip "
                               f"thickness would be s_a = {g.sa_mm[j]:.3f} mm ≤ 0; "
                               + ("a larger planet shift --x2 leaves less of x_Σ34 = "
                                  f"{p34.x_sum:.3f} to wheel 4, a negative first pair (x1 + x2 < 0) lowers "
                                  "α_w34, or choose a smaller C" if names[j] == "4" else
                                  "choose a smaller shift for it"))
    # a tip inside its root circle is no gear; ε_α < 1 stays the blocking contour's hard warning (the
    # seed's own ×2 family has ε_α34 = 0.958)
    require_working(p12, "1-2", contact=False)
    require_working(p34, "3-4", contact=False)
    ch12, ch34 = check_pair(p12), check_pair(p34)
    nb = check_neighbours(a_w, planets, da_pl)
    notes += pair_notes("1-2", ch12, (z1, z2), m) + pair_notes("3-4", ch34, (z3, z4), m)
    if not nb.ok:
        notes.append(Note.make("aa_neighbours", k=planets, da=f"{nb.value:.3f}", limit=f"{nb.limit:.3f}"))
    ratio_check = 1 - Fraction(z2 * z4, z1 * z3)
    c_check = math.cos(math.radians(p12.alpha_w_deg)) / math.cos(math.radians(p34.alpha_w_deg))
    return AABarDesign(
        i=i, c=c, planets=planets, module_mm=m, alpha_deg=alpha_deg, ha_star=ha_star, c_star=c_star, z_min=z_min,
        z_max=z_max, div=div, family=fam, multiple=multiple, teeth=teeth, x=(x1, x2, x3, x4), pair12=p12, pair34=p34,
        checks12=ch12, checks34=ch34, neighbours=nb, da_planet_mm=da_pl, c_feasible=(lo, hi), ratio_check=ratio_check,
        c_check=c_check, velocity=_velocity(p12, p34, da_pl), notes=tuple(notes),
    )


def _suggest_c(i: Fraction) -> str:
    """A simple C inside the feasible range (the midpoint's nearest fraction with a small denominator)."""
    lo, hi = c_range(i)
    mid = (lo + hi) / 2
    for den in range(2, 101):
        f = Fraction(round(mid * den), den)
        if lo < f < hi:
            return f"{f.numerator}/{f.denominator}"
    return f"{mid.limit_denominator(1000)}"  # pragma: no cover


def feasible_c_examples(i: Fraction, planets: int, z_min: int = Z_MIN, z_max: int = Z_MAX, max_den: int = 40,
                        count: int = 8) -> tuple[tuple[Fraction, tuple[int, int, int, int]], ...]:
    """Simple fractions C = P/Q (Q ≤ ``max_den``) inside 1 < C < 1/(1 − i) that give a tooth set within
    the limits, the smallest Z1 first (the seed's advice: two-digit C keeps Z1 under 100).

    >>> [(str(c), t) for c, t in feasible_c_examples(Fraction(1, 10), 3, count=3)]
    [('20/19', (30, 30, 30, 27)), ('19/18', (30, 27, 27, 27)), ('18/17', (30, 24, 24, 27))]
    """
    lo, hi = c_range(i)
    seen = set()
    out = []
    for q in range(1, max_den + 1):
        for p in range(math.floor(lo * q) + 1, math.ceil(hi * q)):
            f = Fraction(p, q)
            if f in seen or not lo < f < hi:
                continue
            seen.add(f)
            div = divisibility(i, f, planets)
            fam = family(div, z_min, z_max)
            if fam:
                out.append((f, teeth_for(div, fam[0])))
    out.sort(key=lambda e: (e[1][0], max(e[1]), e[0]))
    return tuple(out[:count])


@record
class ReducerSuggestion:
    """An AA̅ mechanism driven at its carrier (motor on H, output on sun 1, wheel 4 fixed) that
    gives a required reducer ratio i_H1 = 1/i more exactly than the zero-gear reducer, with shifts
    x1 = −x2 (a height-corrected first pair, α_w12 = α, as the seed advises) that pass every line
    of the blocking contour and the neighbouring condition."""

    i: Fraction  # i_1H^(4); the reducer ratio is 1/i
    c: Fraction
    teeth: tuple[int, int, int, int]
    x1: float
    x2: float
    ratio_error_pct: float
    alpha_w34_deg: float


SUGGEST_X2 = (0.0, 0.2, 0.4, 0.6, 0.8, 1.0)


def suggest_for_reducer(i_reducer: float, planets: int = 3, tolerance_pct: float = 0.5, z_min: int = Z_MIN,
                        z_max: int = Z_MAX, max_alpha_w34_deg: float = 30.0,
                        tries: int = 300) -> ReducerSuggestion | None:
    """The AA̅ mechanism (seed 000) with the smallest ratio error, then the smallest wheels, for a
    reducer ratio i_H1 = ``i_reducer`` > 1: i = 1/i_H1 as a fraction with a denominator ≤ 60 within
    ``tolerance_pct``, C = P/Q (Q ≤ 30) giving α_w34 ≤ 30° (first pair at α), k planets, every wheel
    within the limits, and a planet shift x2 ∈ {0, 0.2 … 1} (x1 = −x2) with which every blocking
    line and the neighbouring condition hold. None when nothing fits.

    >>> s = suggest_for_reducer(10.0)
    >>> s.i, s.c, s.ratio_error_pct, s.teeth, s.x2
    (Fraction(1, 10), Fraction(22, 21), 0.0, (30, 36, 36, 27), 0.6)
    >>> suggest_for_reducer(720 / 220) is None  # small ratios need C > 1.085 (α_w34 > 30°)
    True
    """
    if not i_reducer > 1:
        return None
    target = 1.0 / i_reducer
    fracs = set()
    for b in range(2, 61):
        for a in (math.floor(target * b), math.ceil(target * b)):
            if 0 < a < b:
                f = Fraction(a, b)
                if abs(1 / float(f) / i_reducer - 1) * 100 <= tolerance_pct + 1e-12:
                    fracs.add(f)
    cos_a = math.cos(math.radians(ALPHA_DEG))
    c_max_angle = Fraction(cos_a / math.cos(math.radians(max_alpha_w34_deg))).limit_denominator(10 ** 6)
    cands = []
    for f in fracs:
        lo, hi = c_range(f)
        top = min(hi, c_max_angle)
        err = (1 / float(f) / i_reducer - 1) * 100
        for q in range(1, 31):
            for p in range(q + 1, math.ceil(top * q)):
                c = Fraction(p, q)
                if c.denominator != q or not lo < c < top:
                    continue
                div = divisibility(f, c, planets)
                fam = family(div, z_min, z_max)
                if fam:
                    t = teeth_for(div, fam[0])
                    cands.append((round(abs(err), 9), max(t), t, f, c, err))
    cands.sort(key=lambda e: e[:3])
    for _, _, t, f, c, err in cands[:tries]:
        for x2 in SUGGEST_X2:
            try:
                d = synthesize(f, c, planets, 1.0, -x2, x2, z_min, z_max, None)
            except TmmError:
                continue
            if d.teeth == t and d.checks12.ok and d.checks34.ok and d.neighbours.ok:
                return ReducerSuggestion(i=f, c=c, teeth=t, x1=-x2 + 0.0, x2=x2, ratio_error_pct=round(err, 9),
                                         alpha_w34_deg=d.pair34.alpha_w_deg)
    return None
