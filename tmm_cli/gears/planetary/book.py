"""The book's hand procedure: §2.4 (scheme 1) and §2.5 (scheme 2) from a simple fraction, two
stages by §2.4 twice, the choice of that fraction, and the recheck of the answers the book prints.
"""

from __future__ import annotations

import math
from fractions import Fraction

from ...records import record
from .conditions import (
    REL_EPS,
    Z_DIFF,
    Z_EXT_EXT,
    Z_EXT_INT,
    Z_RING,
    Stage,
    divisors,
    max_planets,
    neighbour_limit,
    neighbour_ratio,
)

# ----------------------------------------------------------------------------------------------
# the book's hand procedure (§2.4, §2.5)


@record
class BookRow:
    """One row of the book's procedure: the factors, the multiplier y_min and the tooth numbers.

    ``table`` is "2.4" for §2.4 (scheme 1), "2.3" (x1 rows) or "2.4x2" (x2 rows) for §2.5 — the
    book heads both §2.5 tables with x1; the second is x2. ``base`` is the tooth numbers per unit
    y; ``g`` their common factor (y may then be a fraction: the book's y is a proportionality
    coefficient, and all tooth numbers only need to be whole).
    """

    table: str
    x: int | None
    a: int  # A
    b: int | None  # B (scheme 2)
    d: int  # D
    e: int | None  # E (scheme 2)
    base: tuple[Fraction, ...]  # z per unit y: (z_k, z_c, [z_c′,] z_n)
    y_min: Fraction
    teeth: tuple[int, ...]  # (z_k, z_c, [z_c′,] z_n)
    gamma1: int
    gamma2: int

    @property
    def size(self) -> int:
        return max(self.gamma1, self.gamma2)


@record
class BookStage:
    """The book's derivation for one stage: fraction, rows, the chosen row and its planets."""

    scheme: str  # "1" or "2"
    fraction: Fraction  # i as a simple fraction (p/q)
    reduced: Fraction  # (p − q)/q = D/A (scheme 1) or (B·D)/(A·E) (scheme 2)
    x1_range: tuple[int, int] | None
    x2_range: tuple[int, int] | None
    rows: tuple[BookRow, ...]
    chosen: BookRow
    assembly_n: int  # z_k·i = N/c
    assembly_c: int
    assembly_ks: tuple[int, ...]  # divisors of N ≥ 2 (the book's list k1, k2, …)
    neighbour_q: float
    neighbour_limit: int  # exact largest k by (2.5) (the book reads Table 2.1 loosely)
    k_max: int  # largest k in assembly_ks within neighbour_limit (book form)
    k_max_exact: int

    @property
    def stage(self) -> Stage:
        t = self.chosen.teeth
        if self.scheme == "1":
            return Stage(t[0], t[1], None, t[2], self.k_max_exact)
        return Stage(t[0], t[1], t[2], t[3], self.k_max_exact)


def _y_min(ints: tuple[int, ...], den: int, limits: tuple[int, ...]) -> tuple[Fraction, tuple[int, ...]]:
    """Smallest y making every z = (ints/den)·y whole and at least its limit; returns (y, z).

    Whole numbers need y = j·den/g (g = gcd of ints), so z = (ints/g)·j; integer arithmetic only.
    """
    g = math.gcd(*ints)
    prim = [v // g for v in ints]
    j = max(1, max(-(-lim // pv) for pv, lim in zip(prim, limits)))
    return Fraction(den * j, g), tuple(pv * j for pv in prim)


def book_scheme1(fraction: Fraction) -> BookStage | None:
    """§2.4 steps 1–5: z_n/z_k = i − 1 = D/A; z_c = (D − A)/2·y; y_min from Table 2.2.

    >>> b = book_scheme1(Fraction(13, 4))
    >>> b.chosen.teeth, b.chosen.y_min, b.assembly_ks[:4], b.neighbour_limit, b.k_max
    ((40, 25, 90), Fraction(10, 1), (2, 5, 10, 13), 7, 5)
    """
    red = fraction - 1
    if red <= 1:
        return None
    d_, a_ = red.numerator, red.denominator
    base = (Fraction(a_), Fraction(d_ - a_, 2), Fraction(d_))
    lims = (Z_EXT_EXT, Z_EXT_INT, Z_RING)
    y, teeth = _y_min((2 * a_, d_ - a_, 2 * d_), 2, lims)
    if teeth[2] - teeth[1] < Z_DIFF:  # never for D > A, kept for completeness
        return None
    row = BookRow("2.4", None, a_, None, d_, None, base, y, teeth, teeth[0] + 2 * teeth[1], teeth[2])
    return _book_planets("1", fraction, red, None, None, (row,), row)


def _ranges(p: int, q: int) -> tuple[tuple[int, int], tuple[int, int]]:
    """§2.5 step 2: 1 < x1/Q ≤ 5, 2 < P/x1 ≤ 5 and 1 < P/x2 ≤ 5, 2 < x2/Q ≤ 5 for P/Q = i − 1."""
    x1_lo = max(q + 1, math.ceil(Fraction(p, 5)))
    x1_hi = min(5 * q, math.ceil(Fraction(p, 2)) - 1)
    x2_lo = max(math.ceil(Fraction(p, 5)), 2 * q + 1)
    x2_hi = min(p - 1, 5 * q)
    return (x1_lo, x1_hi), (x2_lo, x2_hi)


def _row2(table: str, x: int, ba: Fraction, de: Fraction) -> BookRow | None:
    a_, b_ = ba.denominator, ba.numerator
    d_, e_ = de.numerator, de.denominator
    ints = (a_ * (d_ - e_), b_ * (d_ - e_), e_ * (a_ + b_), d_ * (a_ + b_))
    base = tuple(Fraction(v) for v in ints)
    lims = (Z_EXT_EXT, Z_EXT_EXT, Z_EXT_INT, Z_RING)
    y, teeth = _y_min(ints, 1, lims)
    # z_n − z_c′ = z_k + z_c ≥ 34: Table 2.2's last row holds by itself
    return BookRow(table, x, a_, b_, d_, e_, base, y, teeth, teeth[0] + 2 * teeth[1], teeth[3])


def book_scheme2(fraction: Fraction) -> BookStage | None:
    """§2.5 steps 1–5: (B·D)/(A·E) = i − 1 = P/Q split by the cross factors x1 (Table 2.3:
    B/A = x1/Q, D/E = P/x1) and x2 (Table 2.4: B/A = P/x2, D/E = x2/Q), then z_k = A(D − E)y,
    z_c = B(D − E)y, z_c′ = E(A + B)y, z_n = D(A + B)y with y_min from Table 2.2; the row with the
    smallest max(Γ1, Γ2) wins.

    >>> b = book_scheme2(Fraction(53, 5))
    >>> b.x1_range, b.x2_range
    ((10, 23), (11, 25))
    >>> r10 = [r for r in b.rows if r.table == "2.3" and r.x == 10][0]
    >>> r10.teeth, r10.gamma1, r10.gamma2          # the book's worked row x1 = 10
    ((38, 76, 30, 144), 190, 144)
    """
    red = fraction - 1
    p, q = red.numerator, red.denominator
    (x1a, x1b), (x2a, x2b) = _ranges(p, q)
    rows = []
    for x in range(x1a, x1b + 1):
        r = _row2("2.3", x, Fraction(x, q), Fraction(p, x))
        if r is not None:
            rows.append(r)
    for x in range(x2a, x2b + 1):
        r = _row2("2.4x2", x, Fraction(p, x), Fraction(x, q))
        if r is not None:
            rows.append(r)
    if not rows:
        return None
    chosen = min(rows, key=lambda r: (r.size, r.gamma1 + r.gamma2))
    return _book_planets("2", fraction, red, (x1a, x1b) if x1a <= x1b else None,
                         (x2a, x2b) if x2a <= x2b else None, tuple(rows), chosen)


def _book_planets(scheme: str, fraction: Fraction, red: Fraction, r1, r2, rows, chosen: BookRow) -> BookStage:
    t = chosen.teeth
    zk, zc = t[0], t[1]
    zc2 = None if scheme == "1" else t[2]
    zn = t[-1]
    f = zk * fraction  # the book writes z_k·i with the fraction it aims at
    n, c = f.numerator, f.denominator
    ks = divisors(n, upto=max(n, 2))
    lim = neighbour_limit(zk, zc, zc2)
    k_max = max([k for k in ks if k <= lim], default=1)
    k_exact = max_planets(zk, zc, zc2, zn)
    return BookStage(scheme, fraction, red, r1, r2, tuple(rows), chosen, n, c, ks,
                     float(neighbour_ratio(zk, zc, zc2)), lim, k_max, k_exact)


@record
class BookDerivation:
    """The book's procedure, for the fraction(s) it starts from.

    ``fraction_rule`` (one stage): "forced" (the user's fraction), "exact" (i_pl itself is a
    fraction with a denominator ≤ 10, e.g. 36/7 or 12/1: the book starts from it), "convergent"
    (the last convergent of i_pl's continued fraction with a denominator ≤ 10 — the book's "simple
    fraction" of §2.4: 720/220 = 36/11 → 3, 10/3, 13/4 → 13/4), "nearest" (that convergent is
    outside the tolerance or its procedure fails: the nearest simple fraction within tolerance
    whose procedure succeeds). Two stages: "simple" (of the pairs of simple fractions near √i_pl,
    the one whose procedure gives the smallest reducer), or "exact"/"forced" for the product.
    ``tried``: (fraction as text, size) for every fraction whose procedure was carried through,
    in the order tried ("f1·f2" for two stages); ``convergents``: i_pl's convergents with a
    denominator ≤ 10 (one stage), the last one first tried.
    """

    scheme: str
    fraction_rule: str
    stages: tuple[BookStage, ...]
    tried: tuple[tuple[str, int], ...]
    convergents: tuple[Fraction, ...] = ()

    @property
    def design_stages(self) -> tuple[Stage, ...]:
        return tuple(s.stage for s in self.stages)

    @property
    def ratio_fraction(self) -> Fraction:
        f = Fraction(1)
        for s in self.stages:
            f *= s.stage.ratio_fraction
        return f

    @property
    def size(self) -> int:
        return max(s.chosen.size for s in self.stages)


def simple_fractions(target: float, tol_pct: float, max_den: int = 10) -> list[Fraction]:
    """Fractions p/q (q ≤ max_den, lowest terms, > 1) within ±tol of target, nearest first.

    >>> [str(f) for f in simple_fractions(720 / 220, 5.0, 4)]
    ['13/4', '10/3']
    """
    out = set()
    for q in range(1, max_den + 1):
        for p in range(max(q + 1, math.floor(target * (1 - tol_pct / 100) * q)), math.ceil(target * (1 + tol_pct / 100) * q) + 1):
            f = Fraction(p, q)
            if f > 1 and abs(float(f) / target - 1) <= tol_pct / 100 + REL_EPS:
                out.add(f)
    return sorted(out, key=lambda f: (abs(float(f) / target - 1), f.denominator))


def _book_one(scheme: str, f: Fraction) -> BookStage | None:
    return book_scheme1(f) if scheme == "1" else book_scheme2(f)


def book_derivation(scheme: str, target: float, tol_pct: float, forced: Fraction | None) -> BookDerivation | None:
    """The book's hand procedure for the scheme: §2.4 for "1", §2.5 for "2", §2.4 twice for
    "1+1" (stage 1 near √i_pl as §2.2 says, stage 2 the rest).

    >>> d = book_derivation("1", 720 / 220, 5.0, Fraction(13, 4))
    >>> d.stages[0].chosen.teeth, d.fraction_rule
    ((40, 25, 90), 'forced')
    >>> d = book_derivation("1", 720 / 220, 5.0, None)  # §2.4's own example: 720/220 → 13/4
    >>> str(d.stages[0].fraction), d.fraction_rule, d.stages[0].chosen.teeth
    ('13/4', 'convergent', (40, 25, 90))
    """
    exact = exact_fraction(target)
    if scheme in ("1", "2"):
        if forced is not None:
            st = _book_one(scheme, forced)
            return BookDerivation(scheme, "forced", (st,), ((str(forced), st.chosen.size),)) if st else None
        conv = tuple(convergents(target))
        first = conv[-1] if conv and abs(float(conv[-1]) / target - 1) <= tol_pct / 100 + REL_EPS else None
        order = ([first] if first is not None else []) + [f for f in simple_fractions(target, tol_pct) if f != first]
        tried = []
        for f in order:
            st = _book_one(scheme, f)
            if st is None:
                continue
            tried.append((str(f), st.chosen.size))
            rule = "exact" if f == exact else ("convergent" if f == first else "nearest")
            return BookDerivation(scheme, rule, (st,), tuple(tried), conv)
        return None
    # two stages
    total = forced if forced is not None else exact
    if total is not None and forced is None:
        d = _book_two(target, tol_pct, total)
        if d is not None:
            return BookDerivation("1+1", "exact", d[0], d[1])
    return None if (d := _book_two(target, tol_pct, forced)) is None else BookDerivation(
        "1+1", "forced" if forced is not None else "simple", d[0], d[1])


def exact_fraction(target: float, max_den: int = 10) -> Fraction | None:
    """i as a fraction with a denominator ≤ max_den when it is one (to 1e-12), else None.

    >>> exact_fraction(720 / 140), exact_fraction(720 / 60), exact_fraction(720 / 220)
    (Fraction(36, 7), Fraction(12, 1), None)
    """
    f = Fraction(target).limit_denominator(max_den)
    return f if abs(float(f) - target) <= 1e-12 * target else None


def convergents(target: float, max_den: int = 10) -> list[Fraction]:
    """The convergents of target's continued fraction with a denominator ≤ max_den, in order: the
    best approximations by simple fractions (each closer than any fraction with a smaller
    denominator). §2.4 turns 720/220 = 36/11 into 13/4, its last convergent below 11.

    >>> [str(f) for f in convergents(720 / 220)]
    ['3', '10/3', '13/4']
    >>> [str(f) for f in convergents(720 / 140)], [str(f) for f in convergents(720 / 67)]
    (['5', '36/7'], ['10', '11', '32/3', '43/4'])
    """
    x = Fraction(target).limit_denominator(10 ** 6)  # the float's ratio of two speeds
    out: list[Fraction] = []
    h0, h1, k0, k1 = 0, 1, 1, 0  # h_{-2}, h_{-1}, k_{-2}, k_{-1}
    while True:
        a = math.floor(x)
        h0, h1, k0, k1 = h1, a * h1 + h0, k1, a * k1 + k0
        if k1 > max_den:
            return out
        out.append(Fraction(h1, k1))
        if x == a:
            return out
        x = 1 / (x - a)


def _book_two(target: float, tol_pct: float, total: Fraction | None):
    """§2.4 twice (stage 1 near √i, stage 2 the rest); with ``total`` the product is exactly it."""
    root = math.sqrt(float(total) if total is not None else target)
    tol_half = tol_pct / 2
    tried, best = [], None
    for f1 in simple_fractions(root, tol_half):
        s1 = book_scheme1(f1)
        if s1 is None:
            continue
        if total is not None:
            cands2 = [total / f1]
        else:
            cands2 = simple_fractions(target / float(f1), tol_half)
        for f2 in cands2:
            s2 = book_scheme1(f2)
            if s2 is None:
                continue
            err = abs(float(f1 * f2) / target - 1)
            if err > tol_pct / 100 + REL_EPS:
                continue
            size = max(s1.chosen.size, s2.chosen.size)
            tried.append((f"{f1}·{f2}", size))
            key = (size, err)
            if best is None or key < best[0]:
                best = (key, (s1, s2))
    if best is None:
        return None
    stages = tuple(sorted(best[1], key=lambda s: -s.fraction))
    return stages, tuple(sorted(tried, key=lambda t: t[1])[:12])


# ----------------------------------------------------------------------------------------------
# the book's printed answers (for the notes)


BOOK_PRINTED = {
    ("1", Fraction(13, 4)): ("2.4", Stage(40, 25, None, 90, 5)),
    ("2", Fraction(53, 5)): ("2.5", Stage(34, 56, 50, 120, 2)),
}
"""The answers printed in §2.4 and §2.5 (z_k, z_c, [z_c′,] z_n, k)."""


@record
class PrintedCheck:
    section: str
    stage: Stage
    fraction: Fraction
    coaxial_lhs: int
    coaxial_rhs: int
    ratio: float
    coaxial_ok: bool
    ratio_ok: bool
    matches_procedure: bool  # the procedure carried through gives the same teeth


def check_printed(scheme: str, fraction: Fraction, procedure: BookStage | None) -> PrintedCheck | None:
    """Recheck the book's printed answer for this scheme and fraction, if the book prints one.

    >>> c = check_printed("2", Fraction(53, 5), None)
    >>> c.coaxial_lhs, c.coaxial_rhs, round(c.ratio, 2), c.coaxial_ok, c.ratio_ok
    (90, 70, 4.95, False, False)
    """
    entry = BOOK_PRINTED.get((scheme, fraction))
    if entry is None:
        return None
    sec, st = entry
    ratio = st.ratio
    same = procedure is not None and procedure.chosen.teeth == st.teeth
    return PrintedCheck(sec, st, fraction, st.z_sun + st.z_planet, st.z_ring - st.zc2, ratio,
                        st.z_sun + st.z_planet == st.z_ring - st.zc2, abs(ratio / float(fraction) - 1) < 1e-9, same)
