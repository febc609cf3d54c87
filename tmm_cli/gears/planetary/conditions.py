"""One planetary stage and its conditions (§2.1.3): coaxiality, assembly (the exact form and the
book's (2.4)), neighbouring (2.5) and Table 2.2; a design is one stage or two in series.

Size measure (the book's §2.5): Γ1 = z_k + 2·z_c (row 1: sun and two planets across) and
Γ2 = z_n (the ring); the reducer's radial size is max(Γ1, Γ2) pitch diameters in modules. For
scheme 1 both are z_n. For two stages it is the larger of the stages' sizes (one module assumed).
"""

from __future__ import annotations

import math
from fractions import Fraction

from ...records import record

K_MAX = 40  # no set within search.Z_MAX fits more planets (neighbouring): 19/183 > sin(π/31)
HA_STAR = 1
# Table 2.2 (h_a* = 1)
Z_EXT_EXT = 17  # external gear in an external mesh
Z_EXT_INT = 20  # external gear in an internal mesh
Z_RING = 85  # internal gear
Z_DIFF = 8  # internal minus external
REL_EPS = 1e-12  # relative slack of a ratio window (the search, the book's simple fractions)


# ----------------------------------------------------------------------------------------------
# one stage and its conditions


@record
class Stage:
    """Tooth numbers of one planetary stage and its number of planets.

    ``z_planet2`` is z_c′ of the double-row scheme 2 (None for a single-row stage).
    """

    z_sun: int
    z_planet: int
    z_planet2: int | None
    z_ring: int
    planets: int

    @property
    def zc2(self) -> int:
        """z_c′, equal to z_c for a single-row stage (the book's note to (2.1))."""
        return self.z_planet if self.z_planet2 is None else self.z_planet2

    @property
    def ratio_fraction(self) -> Fraction:
        """i_kH^n = 1 + z_c·z_n/(z_k·z_c′) exactly, (2.1) with a = 1 external mesh."""
        return 1 + Fraction(self.z_planet * self.z_ring, self.z_sun * self.zc2)

    @property
    def ratio(self) -> float:
        return float(self.ratio_fraction)

    @property
    def gamma1(self) -> int:
        """Γ1 = z_k + 2·z_c (§2.5)."""
        return self.z_sun + 2 * self.z_planet

    @property
    def gamma2(self) -> int:
        """Γ2 = z_n (§2.5)."""
        return self.z_ring

    @property
    def size(self) -> int:
        return max(self.gamma1, self.gamma2)

    @property
    def teeth(self) -> tuple[int, ...]:
        if self.z_planet2 is None:
            return (self.z_sun, self.z_planet, self.z_ring)
        return (self.z_sun, self.z_planet, self.z_planet2, self.z_ring)


def neighbour_ratio(z_sun: int, z_planet: int, z_planet2: int | None = None) -> Fraction:
    """Right side of (2.5): (z_big + 2h_a*)/(z_k + z_c), z_big the larger planet.

    The larger planet meshes with the sun (external, z_k + z_c) or the ring (internal, z_n − z_c′);
    both are 2a/m, the same centre distance, so one form serves.

    >>> neighbour_ratio(40, 25), float(neighbour_ratio(34, 56, 50))
    (Fraction(27, 65), 0.6444444444444445)
    """
    big = max(z_planet, z_planet if z_planet2 is None else z_planet2)
    return Fraction(big + 2 * HA_STAR, z_sun + z_planet)


def neighbour_ok(k: int, z_sun: int, z_planet: int, z_planet2: int | None = None) -> bool:
    """(2.5) computed exactly: sin(π/k) > (z_big + 2h_a*)/(z_k + z_c) (strict: a gap remains).

    sin(π/k) is rational only for k = 1, 2, 6; those are compared exactly, the rest can't tie.

    >>> [k for k in range(2, 10) if neighbour_ok(k, 40, 25)]   # §2.4: 27/65 = 0.415
    [2, 3, 4, 5, 6, 7]
    """
    q = neighbour_ratio(z_sun, z_planet, z_planet2)
    if k <= 1:
        return True
    if k == 2:
        return q < 1
    if k == 6:
        return q < Fraction(1, 2)
    return math.sin(math.pi / k) > float(q)


def neighbour_limit(z_sun: int, z_planet: int, z_planet2: int | None = None) -> int:
    """The largest k satisfying (2.5) (the book's k_гр is read loosely; see METHOD.md errata).

    >>> neighbour_limit(40, 25), neighbour_limit(34, 56, 50)
    (7, 4)
    """
    k = 1
    while k < K_MAX and neighbour_ok(k + 1, z_sun, z_planet, z_planet2):
        k += 1
    return k


def assembly_value(z_sun: int, z_planet: int, z_planet2: int | None, z_ring: int) -> tuple[int, int]:
    """(T, g) of the exact assembly condition: k planets fit iff k·g divides T, with
    T = z_k·z_c′ + z_c·z_n and g = gcd(z_c, z_c′) (single row: T/g = z_k + z_n)."""
    zc2 = z_planet if z_planet2 is None else z_planet2
    return z_sun * zc2 + z_planet * z_ring, math.gcd(z_planet, zc2)


def assembly_ok(k: int, z_sun: int, z_planet: int, z_planet2: int | None, z_ring: int) -> bool:
    """Exact assembly condition (METHOD.md, from (2.4)): k·gcd(z_c, z_c′) | z_k·z_c′ + z_c·z_n.

    Scheme 1: (z_k + z_n)/k integer.

    >>> [k for k in range(2, 14) if assembly_ok(k, 40, 25, None, 90)]   # §2.4: 130 = 2·5·13
    [2, 5, 10, 13]
    """
    t, g = assembly_value(z_sun, z_planet, z_planet2, z_ring)
    return t % (k * g) == 0


def assembly_book(z_sun: int, z_planet: int, z_planet2: int | None, z_ring: int) -> tuple[int, int]:
    """The book's (2.4) as N/D: z_k·i = N/D in lowest terms; it admits k when k | N.

    >>> assembly_book(40, 25, None, 90), assembly_book(34, 56, 50, 120)
    ((130, 1), (842, 5))
    """
    st = Stage(z_sun, z_planet, z_planet2, z_ring, 1)
    f = z_sun * st.ratio_fraction
    return f.numerator, f.denominator


def divisors(n: int, upto: int | None = None) -> tuple[int, ...]:
    """Divisors ≥ 2 of n (up to ``upto``): the book's 'theoretically possible numbers of planets'.

    >>> divisors(130)
    (2, 5, 10, 13, 26, 65, 130)
    """
    n = abs(n)
    out = [d for d in range(2, (n if upto is None else min(n, upto)) + 1) if n % d == 0]
    return tuple(out)


def max_planets(z_sun: int, z_planet: int, z_planet2: int | None, z_ring: int, book_form: bool = False) -> int:
    """The largest k satisfying assembly and neighbouring (1 if none ≥ 2 does).

    >>> max_planets(40, 25, None, 90)
    5
    """
    lim = neighbour_limit(z_sun, z_planet, z_planet2)
    n_book = assembly_book(z_sun, z_planet, z_planet2, z_ring)[0]
    for k in range(lim, 1, -1):
        ok = (n_book % k == 0) if book_form else assembly_ok(k, z_sun, z_planet, z_planet2, z_ring)
        if ok:
            return k
    return 1


@record
class InterferenceItem:
    """One row of Table 2.2: what, the value, the limit."""

    what: str  # "sun_ext", "planet_ext", "planet_int", "ring", "ring_minus_planet"
    symbol: str
    value: int
    limit: int

    @property
    def ok(self) -> bool:
        return self.value >= self.limit


def interference_items(z_sun: int, z_planet: int, z_planet2: int | None, z_ring: int) -> tuple[InterferenceItem, ...]:
    """Table 2.2 for a stage. Single row: the planet meshes internally too, so z_c ≥ 20.

    >>> [i.limit for i in interference_items(40, 25, None, 90)]
    [17, 20, 85, 8]
    """
    if z_planet2 is None:
        return (
            InterferenceItem("sun_ext", "z_k", z_sun, Z_EXT_EXT),
            InterferenceItem("planet_int", "z_c", z_planet, Z_EXT_INT),
            InterferenceItem("ring", "z_n", z_ring, Z_RING),
            InterferenceItem("ring_minus_planet", "z_n − z_c", z_ring - z_planet, Z_DIFF),
        )
    return (
        InterferenceItem("sun_ext", "z_k", z_sun, Z_EXT_EXT),
        InterferenceItem("planet_ext", "z_c", z_planet, Z_EXT_EXT),
        InterferenceItem("planet_int", "z_c′", z_planet2, Z_EXT_INT),
        InterferenceItem("ring", "z_n", z_ring, Z_RING),
        InterferenceItem("ring_minus_planet", "z_n − z_c′", z_ring - z_planet2, Z_DIFF),
    )


@record
class StageChecks:
    """Conditions 2–5 of §2.1.3 for one stage, with their numbers."""

    stage: Stage
    coaxial_lhs: int  # z_k + z_c
    coaxial_rhs: int  # z_n − z_c′
    coaxial_ok: bool
    assembly_t: int  # z_k·z_c′ + z_c·z_n
    assembly_g: int  # gcd(z_c, z_c′)
    assembly_exact_ok: bool  # for stage.planets
    assembly_book_n: int  # z_k·i = N/D
    assembly_book_d: int
    assembly_book_ok: bool
    assembly_ks_exact: tuple[int, ...]  # k ≥ 2 admitted by the exact condition, up to K_MAX
    assembly_ks_book: tuple[int, ...]
    neighbour_q: float  # right side of (2.5)
    neighbour_sin: float  # sin(π/k) for stage.planets
    neighbour_ok: bool
    neighbour_limit: int
    k_max: int  # largest k with exact assembly and neighbouring
    k_max_book: int  # the same with the book's assembly form
    interference: tuple[InterferenceItem, ...]

    @property
    def interference_ok(self) -> bool:
        return all(i.ok for i in self.interference)

    @property
    def assembly_c(self) -> int:
        """The smallest whole c of (2.4) with (z_k·i/k)·c a whole number: the carrier is turned by
        c·2β between fitting two planets (the book's sample sheet: φ_H1 = c·2β).

        >>> c = check_stage(Stage(40, 25, None, 90, 5))
        >>> c.assembly_c, c.carrier_turn_deg
        (1, 72.0)
        """
        k, n, d = self.stage.planets, self.assembly_book_n, self.assembly_book_d
        return (d * k) // math.gcd(n, d * k)

    @property
    def carrier_turn_deg(self) -> float:
        """φ_H1 = c·2β = c·360°/k [deg], the carrier's turn between fitting two planets."""
        return self.assembly_c * 360.0 / self.stage.planets

    @property
    def assembly_forms_differ(self) -> bool:
        return self.k_max != self.k_max_book or self.assembly_exact_ok != self.assembly_book_ok

    @property
    def ok(self) -> bool:
        return self.coaxial_ok and self.assembly_exact_ok and self.neighbour_ok and self.interference_ok


def check_stage(stage: Stage) -> StageChecks:
    """Coaxiality, assembly (exact and the book's form), neighbouring (2.5) and Table 2.2.

    >>> c = check_stage(Stage(40, 25, None, 90, 5))
    >>> c.coaxial_ok, c.assembly_exact_ok, c.neighbour_limit, c.k_max, c.ok
    (True, True, 7, 5, True)
    """
    zk, zc, zc2o, zn, k = stage.z_sun, stage.z_planet, stage.z_planet2, stage.z_ring, stage.planets
    zc2 = stage.zc2
    t, g = assembly_value(zk, zc, zc2o, zn)
    nb, db = assembly_book(zk, zc, zc2o, zn)
    lim = neighbour_limit(zk, zc, zc2o)
    ks_exact = tuple(j for j in range(2, K_MAX + 1) if t % (j * g) == 0)
    ks_book = tuple(j for j in range(2, K_MAX + 1) if nb % j == 0)
    k_max = max([j for j in ks_exact if j <= lim], default=1)
    k_max_book = max([j for j in ks_book if j <= lim], default=1)
    return StageChecks(
        stage=stage, coaxial_lhs=zk + zc, coaxial_rhs=zn - zc2, coaxial_ok=(zk + zc == zn - zc2),
        assembly_t=t, assembly_g=g, assembly_exact_ok=(t % (k * g) == 0),
        assembly_book_n=nb, assembly_book_d=db, assembly_book_ok=(nb % k == 0),
        assembly_ks_exact=ks_exact, assembly_ks_book=ks_book,
        neighbour_q=float(neighbour_ratio(zk, zc, zc2o)), neighbour_sin=math.sin(math.pi / k),
        neighbour_ok=neighbour_ok(k, zk, zc, zc2o), neighbour_limit=lim,
        k_max=k_max, k_max_book=k_max_book, interference=interference_items(zk, zc, zc2o, zn),
    )


# ----------------------------------------------------------------------------------------------
# designs


@record
class PlanetaryDesign:
    """A reducer: scheme key and its stages (one, or two in series for "1+1")."""

    scheme: str
    stages: tuple[Stage, ...]
    target: float  # required i_pl

    @property
    def ratio_fraction(self) -> Fraction:
        f = Fraction(1)
        for s in self.stages:
            f *= s.ratio_fraction
        return f

    @property
    def ratio(self) -> float:
        return float(self.ratio_fraction)

    @property
    def ratio_error_pct(self) -> float:
        return (self.ratio / self.target - 1.0) * 100.0

    @property
    def size(self) -> int:
        return max(s.size for s in self.stages)

    @property
    def planets(self) -> int:
        return min(s.planets for s in self.stages)

    @property
    def total_teeth(self) -> int:
        return sum(sum(s.teeth) for s in self.stages)


def stage_ratio_split_key(stages: tuple[Stage, ...]) -> float:
    if len(stages) < 2:
        return 0.0
    return abs(math.log(stages[0].ratio) - math.log(stages[1].ratio))
