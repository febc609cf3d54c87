"""Planetary reducer synthesis: the five conditions of §2.1.3, the exhaustive search, the book's
hand procedure (§2.4, §2.5) and the checks by (2.1) and by the velocity pictures (2.3).

Symbols follow the book: k — the driving sun (z_k), c — the planet (z_c; scheme 2 also c′, z_c′),
n — the fixed ring (z_n), H — the carrier (output), k — also the number of planets. Scheme keys:
"1" single-row, "2" double-row, "1+1" two single-row stages in series (Fig. 2.4 scheme 3).

Size measure (the book's §2.5): Γ1 = z_k + 2·z_c (row 1: sun and two planets across) and
Γ2 = z_n (the ring); the reducer's radial size is max(Γ1, Γ2) pitch diameters in modules. For
scheme 1 both are z_n. For two stages it is the larger of the stages' sizes (one module assumed).

Search bounds: every tooth number satisfying Table 2.2 with a size ≤ Z_MAX = 200 teeth. Table 2.2
forces z_n ≥ 85, the book's own designs are 90 (§2.4) and up to 190 (§2.5, Table 2.3 row 10), and
the smallest design for every i_pl from 3 to 24 (crank 30 … 960 rpm) is below 130; 200 keeps all of
them with room for forced fractions while the scheme-2 table stays at ~4·10⁵ sets.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache

import numpy as np

from ...errors import TmmError

Z_MAX = 200
K_MAX = 40  # no set within Z_MAX fits more planets (neighbouring): 19/183 > sin(π/31)
HA_STAR = 1
# Table 2.2 (h_a* = 1)
Z_EXT_EXT = 17  # external gear in an external mesh
Z_EXT_INT = 20  # external gear in an internal mesh
Z_RING = 85  # internal gear
Z_DIFF = 8  # internal minus external
REL_EPS = 1e-12
SELECT_SLACK = 1  # "accurate": compare the sets at most this many teeth larger than the smallest
SELECT_RULES = ("accurate", "smallest")
STAGE_RANGE_1 = (3.0, 8.0)  # Fig. 2.4, scheme 1: the ratio range of one single-row stage


# ----------------------------------------------------------------------------------------------
# one stage and its conditions


@dataclass(frozen=True)
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


@dataclass(frozen=True)
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


@dataclass(frozen=True)
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


@dataclass(frozen=True)
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


# ----------------------------------------------------------------------------------------------
# tables of all tooth sets (precomputed once per process)


@dataclass(frozen=True)
class _Table:
    zk: np.ndarray
    zc: np.ndarray
    zc2: np.ndarray
    zn: np.ndarray
    num: np.ndarray  # ratio numerator  z_k·z_c′ + z_c·z_n  (i = num/den)
    den: np.ndarray  # z_k·z_c′
    ratio: np.ndarray
    log_ratio: np.ndarray
    size: np.ndarray
    t: np.ndarray  # assembly T
    g: np.ndarray  # gcd(z_c, z_c′)
    kneigh: np.ndarray  # neighbouring limit
    total: np.ndarray


def _kneigh(zbig: np.ndarray, a: np.ndarray) -> np.ndarray:
    q = (zbig + 2 * HA_STAR) / a
    k = np.ones(q.shape, dtype=np.int64)
    for j in range(2, K_MAX + 1):
        if j == 2:
            ok = (zbig + 2 * HA_STAR) < a
        elif j == 6:
            ok = 2 * (zbig + 2 * HA_STAR) < a
        else:
            ok = math.sin(math.pi / j) > q
        k = np.where(ok & (k == j - 1), j, k)
    return k


def _finish(zk, zc, zc2, zn) -> _Table:
    zk, zc, zc2, zn = (np.asarray(v, dtype=np.int64) for v in (zk, zc, zc2, zn))
    den = zk * zc2
    num = den + zc * zn
    ratio = num / den
    t = num
    g = np.gcd(zc, zc2)
    size = np.maximum(zk + 2 * zc, zn)
    kn = _kneigh(np.maximum(zc, zc2), zk + zc)
    return _Table(zk, zc, zc2, zn, num, den, ratio, np.log(ratio), size, t, g, kn, zk + zc + zn + np.where(zc2 != zc, zc2, 0))


@lru_cache(maxsize=1)
def scheme1_table() -> _Table:
    """All single-row sets with Table 2.2 satisfied, coaxial by construction, z_n ≤ Z_MAX."""
    zk, zc = np.meshgrid(np.arange(Z_EXT_EXT, Z_MAX + 1), np.arange(Z_EXT_INT, Z_MAX + 1), indexing="ij")
    zk, zc = zk.ravel(), zc.ravel()
    zn = zk + 2 * zc
    m = (zn >= Z_RING) & (zn <= Z_MAX) & (zn - zc >= Z_DIFF)
    return _finish(zk[m], zc[m], zc[m], zn[m])


@lru_cache(maxsize=1)
def scheme2_table() -> _Table:
    """All double-row sets (Table 2.2, coaxial by construction) with max(Γ1, Γ2) ≤ Z_MAX."""
    parts = []
    zc2_all = np.arange(Z_EXT_INT, Z_MAX + 1)
    for zc in range(Z_EXT_EXT, (Z_MAX - Z_EXT_EXT) // 2 + 1):
        zk = np.arange(Z_EXT_EXT, Z_MAX - 2 * zc + 1)
        if zk.size == 0:
            continue
        zkg, zc2g = np.meshgrid(zk, zc2_all, indexing="ij")
        zn = zkg + zc + zc2g
        m = (zn >= Z_RING) & (zn <= Z_MAX) & (zn - zc2g >= Z_DIFF)
        parts.append((zkg[m], np.full(int(m.sum()), zc), zc2g[m], zn[m]))
    zk = np.concatenate([p[0] for p in parts])
    zc = np.concatenate([p[1] for p in parts])
    zc2 = np.concatenate([p[2] for p in parts])
    zn = np.concatenate([p[3] for p in parts])
    return _finish(zk, zc, zc2, zn)


def _kbest(tab: _Table, idx: np.ndarray) -> np.ndarray:
    """Largest k with exact assembly and neighbouring, for the sets ``idx``."""
    t, g, kn = tab.t[idx], tab.g[idx], tab.kneigh[idx]
    best = np.ones(idx.shape, dtype=np.int64)
    kmax = int(kn.max()) if kn.size else 1
    for k in range(2, kmax + 1):
        ok = (kn >= k) & (t % (k * g) == 0)
        best = np.where(ok, k, best)
    return best


def _admits(tab: _Table, idx: np.ndarray, k: int) -> np.ndarray:
    return (tab.kneigh[idx] >= k) & (tab.t[idx] % (k * tab.g[idx]) == 0)


def _stage_from(tab: _Table, i: int, k: int, double: bool) -> Stage:
    return Stage(int(tab.zk[i]), int(tab.zc[i]), int(tab.zc2[i]) if double else None, int(tab.zn[i]), int(k))


# ----------------------------------------------------------------------------------------------
# the search


@dataclass(frozen=True)
class SearchResult:
    """Outcome of the exhaustive search in the chosen scheme.

    ``rule``: "smallest_3plus" (smallest with ≥ 3 planets), "smallest_no3" (none within tolerance
    takes 3, so the smallest), "forced_planets" (the smallest admitting the forced count).
    """

    scheme: str
    target: float
    tolerance_pct: float
    forced_ratio: Fraction | None
    forced_planets: int | None
    z_max: int
    n_sets: int  # tooth sets (or stage pairs) within tolerance that satisfy conditions 1, 2, 5
    carried: PlanetaryDesign
    smallest_any: PlanetaryDesign  # smallest regardless of planets (max planets it admits)
    alternatives: tuple[PlanetaryDesign, ...]
    rule: str
    select: str = "smallest"  # "accurate" | "smallest": which of the planets-rule pool is carried
    smallest: PlanetaryDesign | None = None  # the smallest of that pool (the carried one under "smallest")
    stage_range_ok: bool | None = None  # two stages: every stage within Fig. 2.4's 3…8 (None: one stage)
    # one stage, carried ratio not exact: the smallest set of the pool more accurate than the carried
    # one, and the smallest exact one (None: none within the tolerance and z_max) — the sets the
    # selection rule passed over because they are larger
    more_accurate: PlanetaryDesign | None = None
    exact: PlanetaryDesign | None = None


def _window(target: float, tol_pct: float, forced: Fraction | None) -> tuple[float, float]:
    if forced is not None:
        v = float(forced)
        return v * (1 - 1e-9), v * (1 + 1e-9)
    return target * (1 - tol_pct / 100.0) * (1 - REL_EPS), target * (1 + tol_pct / 100.0) * (1 + REL_EPS)


def _exact_mask(tab: _Table, idx: np.ndarray, forced: Fraction) -> np.ndarray:
    return tab.num[idx] * forced.denominator == tab.den[idx] * forced.numerator


def _single_candidates(tab: _Table, target: float, tol_pct: float, forced: Fraction | None) -> np.ndarray:
    lo, hi = _window(target, tol_pct, forced)
    idx = np.nonzero((tab.ratio >= lo) & (tab.ratio <= hi))[0]
    if forced is not None:
        idx = idx[_exact_mask(tab, idx, forced)]
    return idx


def _order_single(tab: _Table, idx: np.ndarray, k: np.ndarray, target: float) -> np.ndarray:
    err = np.abs(tab.ratio[idx] / target - 1.0)
    errq = np.round(err, 12)
    return np.lexsort((tab.total[idx], -k, errq, tab.size[idx]))


def _search_single(scheme: str, target: float, tol_pct: float, forced: Fraction | None, planets: int | None,
                   n_alt: int, select: str = "smallest") -> SearchResult:
    double = scheme == "2"
    tab = scheme2_table() if double else scheme1_table()
    idx = _single_candidates(tab, target, tol_pct, forced)
    if idx.size == 0:
        raise _NoCandidates(scheme)
    kb = _kbest(tab, idx)
    any_order = _order_single(tab, idx, kb, target)
    i_any = idx[any_order[0]]
    smallest_any = PlanetaryDesign(scheme, (_stage_from(tab, i_any, kb[any_order[0]], double),), target)
    if planets is not None:
        adm = _admits(tab, idx, planets)
        if not adm.any():
            raise _NoPlanets(int(kb.max()))
        pool, kpool, rule = idx[adm], np.full(int(adm.sum()), planets), "forced_planets"
    elif (kb >= 3).any():
        pool, kpool, rule = idx[kb >= 3], kb[kb >= 3], "smallest_3plus"
    else:
        pool, kpool, rule = idx, kb, "smallest_no3"
    order = _order_single(tab, pool, kpool, target)
    designs = [PlanetaryDesign(scheme, (_stage_from(tab, pool[j], kpool[j], double),), target) for j in order[:n_alt]]
    smallest = designs[0]
    carried = smallest
    if select == "accurate":
        j = _most_accurate(tab.size[pool], np.abs(tab.ratio[pool] / target - 1.0), kpool, tab.total[pool])
        carried = PlanetaryDesign(scheme, (_stage_from(tab, pool[j], kpool[j], double),), target)
    alts = list(designs)
    for extra in (carried, smallest_any):
        if extra not in alts and (extra is carried or smallest_any.size < carried.size):
            alts.append(extra)
    alts.sort(key=lambda d: (d.size, abs(d.ratio_error_pct), -d.planets))
    more, exact = _larger_better(tab, pool, kpool, target, carried, double)
    return SearchResult(scheme, target, tol_pct, forced, planets, Z_MAX, int(idx.size), carried, smallest_any,
                        tuple(alts), rule, select, smallest, more_accurate=more, exact=exact)


def _larger_better(tab, pool: np.ndarray, kpool: np.ndarray, target: float, carried: PlanetaryDesign, double: bool):
    """(smallest set of `pool` with a smaller ratio error than `carried`, smallest exact set), each
    None when there is none or the carried ratio is already exact; ties by more planets, fewer teeth."""
    err = np.round(np.abs(tab.ratio[pool] / target - 1.0), 12)
    e0 = round(abs(carried.ratio / target - 1.0), 12)
    if e0 == 0.0:
        return None, None
    out = []
    for mask in (err < e0 - 1e-9, err == 0.0):
        if not mask.any():
            out.append(None)
            continue
        sub = np.nonzero(mask)[0]
        j = sub[np.lexsort((tab.total[pool][sub], -kpool[sub], err[sub], tab.size[pool][sub]))[0]]
        out.append(PlanetaryDesign(carried.scheme, (_stage_from(tab, pool[j], kpool[j], double),), target))
    return out[0], out[1]


def _most_accurate(size: np.ndarray, err: np.ndarray, k: np.ndarray, total: np.ndarray) -> int:
    """Index of the "accurate" choice: among the sets at most SELECT_SLACK teeth larger than the
    smallest, the smallest ratio error; ties by size, more planets, fewer teeth in all.

    >>> _most_accurate(np.array([86, 87, 90]), np.array([0.0455, 0.0, 0.0]), np.array([4, 4, 5]), np.array([1, 1, 1]))
    1
    """
    near = size <= size.min() + SELECT_SLACK
    errq = np.where(near, np.round(err, 12), np.inf)
    return int(np.lexsort((total, -k, size, errq))[0])


class _NoCandidates(Exception):
    def __init__(self, scheme: str):
        self.scheme = scheme


class _NoPlanets(Exception):
    def __init__(self, most: int):
        self.most = most


def _pairs(tab: _Table, pool: np.ndarray, lo: float, hi: float, size_cap: int) -> tuple[np.ndarray, np.ndarray]:
    """All ordered pairs (a, b) of sets in ``pool`` with sizes ≤ size_cap and lo ≤ r_a·r_b ≤ hi,
    stage 1 (a, motor side) taking the larger ratio."""
    p = pool[tab.size[pool] <= size_cap]
    if p.size == 0:
        return np.empty(0, np.int64), np.empty(0, np.int64)
    order = np.argsort(tab.log_ratio[p], kind="stable")
    p = p[order]
    lr = tab.log_ratio[p]
    llo, lhi = math.log(lo), math.log(hi)
    j0 = np.searchsorted(lr, llo - lr, side="left")
    j1 = np.searchsorted(lr, lhi - lr, side="right")
    # stage 1 takes the larger (or equal) ratio: b index ≤ a index in sorted order
    j1 = np.minimum(j1, np.arange(p.size) + 1)
    cnt = np.maximum(j1 - j0, 0)
    total = int(cnt.sum())
    if total == 0:
        return np.empty(0, np.int64), np.empty(0, np.int64)
    a_pos = np.repeat(np.arange(p.size), cnt)
    starts = np.repeat(j0, cnt)
    offs = np.arange(total) - np.repeat(np.cumsum(cnt) - cnt, cnt)
    b_pos = starts + offs
    return p[a_pos], p[b_pos]


def _count_pairs(tab: _Table, lo: float, hi: float) -> int:
    """Number of unordered stage pairs (stage 1 the larger ratio) within [lo, hi]."""
    lr = np.sort(tab.log_ratio)
    j0 = np.searchsorted(lr, math.log(lo) - lr, side="left")
    j1 = np.minimum(np.searchsorted(lr, math.log(hi) - lr, side="right"), np.arange(lr.size) + 1)
    return int(np.maximum(j1 - j0, 0).sum())


def _min_pair_size(tab: _Table, pool: np.ndarray, lo: float, hi: float) -> int | None:
    sizes = np.unique(tab.size[pool])
    if sizes.size == 0:
        return None
    # feasibility is monotone in the size cap: bisect on the distinct sizes
    def feasible(cap: int) -> bool:
        p = pool[tab.size[pool] <= cap]
        lr = np.sort(tab.log_ratio[p])
        j = np.searchsorted(lr, math.log(lo) - lr, side="left")
        ok = j < lr.size
        return bool(np.any(lr[np.minimum(j, lr.size - 1)][ok] <= math.log(hi) - lr[ok]))
    if not feasible(int(sizes[-1])):
        return None
    lo_i, hi_i = 0, sizes.size - 1
    while lo_i < hi_i:
        mid = (lo_i + hi_i) // 2
        if feasible(int(sizes[mid])):
            hi_i = mid
        else:
            lo_i = mid + 1
    return int(sizes[lo_i])


def _pair_designs(tab: _Table, pool: np.ndarray, kpool_of: dict | np.ndarray, target: float, tol_pct: float,
                  forced: Fraction | None, n_alt: int, margin: int = 6,
                  select: str = "smallest") -> list[PlanetaryDesign]:
    """Stage pairs within tolerance, smallest first ("smallest"), or led by the most accurate pair
    at most SELECT_SLACK teeth larger than the smallest ("accurate", then the rest smallest first)."""
    lo, hi = _window(target, tol_pct, forced)
    cap = Z_MAX if forced is not None else _min_pair_size(tab, pool, lo, hi)
    if cap is None:
        return []
    a, b = _pairs(tab, pool, lo, hi, min(cap + margin, Z_MAX))
    if forced is not None and a.size:
        ex = (tab.num[a] * tab.num[b] * forced.denominator == tab.den[a] * tab.den[b] * forced.numerator)
        a, b = a[ex], b[ex]
    if a.size == 0:
        return []
    ka, kb = kpool_of[a], kpool_of[b]
    size = np.maximum(tab.size[a], tab.size[b])
    err = np.round(np.abs(tab.ratio[a] * tab.ratio[b] / target - 1.0), 12)
    split = np.round(np.abs(tab.log_ratio[a] - tab.log_ratio[b]), 12)
    kmin = np.minimum(ka, kb)
    order = np.lexsort((tab.total[a] + tab.total[b], split, -kmin, err, size))
    picks = list(order[:n_alt])
    if select == "accurate":
        near = size <= size.min() + SELECT_SLACK
        first = int(np.lexsort((tab.total[a] + tab.total[b], split, -kmin, size, np.where(near, err, np.inf)))[0])
        picks = [first] + [j for j in picks if j != first][: n_alt - 1]
    out = []
    for j in picks:
        out.append(PlanetaryDesign("1+1", (_stage_from(tab, a[j], ka[j], False), _stage_from(tab, b[j], kb[j], False)),
                                   target))
    return out


def _search_two(target: float, tol_pct: float, forced: Fraction | None, planets: int | None, n_alt: int,
                select: str = "smallest") -> SearchResult:
    """Two scheme-1 stages; each stage kept within Fig. 2.4's range 3…8 when any pair allows it
    (``stage_range_ok``), else the whole table is searched."""
    tab = scheme1_table()
    every = np.arange(tab.zk.size)
    kall = _kbest(tab, every)
    lo_r, hi_r = STAGE_RANGE_1
    in_range = every[(tab.ratio >= lo_r * (1 - REL_EPS)) & (tab.ratio <= hi_r * (1 + REL_EPS))]
    range_ok = True
    allidx = in_range
    any_designs = _pair_designs(tab, allidx, kall, target, tol_pct, forced, 1)
    if not any_designs:
        range_ok, allidx = False, every
        any_designs = _pair_designs(tab, allidx, kall, target, tol_pct, forced, 1)
    if not any_designs:
        raise _NoCandidates("1+1")
    smallest_any = any_designs[0]
    if planets is not None:
        adm = _admits(tab, allidx, planets)
        kp = np.where(_admits(tab, every, planets), planets, 0)
        designs = _pair_designs(tab, allidx[adm], kp, target, tol_pct, forced, n_alt, select=select)
        if not designs:
            raise _NoPlanets(smallest_any.planets)
        rule = "forced_planets"
    else:
        designs = _pair_designs(tab, allidx[kall[allidx] >= 3], kall, target, tol_pct, forced, n_alt, select=select)
        rule = "smallest_3plus"
        if not designs:
            designs = _pair_designs(tab, allidx, kall, target, tol_pct, forced, n_alt, select=select)
            rule = "smallest_no3"
    carried = designs[0]
    smallest = min(designs, key=lambda d: (d.size, abs(d.ratio_error_pct), -d.planets))
    alts = list(designs)
    if smallest_any.size < carried.size and smallest_any not in alts:
        alts.append(smallest_any)
    alts.sort(key=lambda d: (d.size, abs(d.ratio_error_pct), -d.planets))
    lo, hi = _window(target, tol_pct, forced)
    n = _count_pairs(tab, lo, hi) if forced is None else len(designs)
    return SearchResult("1+1", target, tol_pct, forced, planets, Z_MAX, n, carried, smallest_any, tuple(alts), rule,
                        select, smallest, range_ok)


def closest_ratio(scheme: str, target: float) -> PlanetaryDesign:
    """The design (any planets) whose ratio is nearest to ``target`` within the search bounds."""
    tab = scheme1_table() if scheme != "2" else scheme2_table()
    if scheme != "1+1":
        j = int(np.argmin(np.abs(tab.log_ratio - math.log(target))))
        kb = _kbest(tab, np.array([j]))[0]
        return PlanetaryDesign(scheme, (_stage_from(tab, j, kb, scheme == "2"),), target)
    lr = np.sort(tab.log_ratio)
    order = np.argsort(tab.log_ratio)
    want = math.log(target) - lr
    j = np.clip(np.searchsorted(lr, want), 1, lr.size - 1)
    cand = np.stack([j - 1, j], axis=1)
    d = np.abs(lr[cand] - want[:, None])
    best = np.unravel_index(np.argmin(d), d.shape)
    a, b = order[best[0]], order[cand[best]]
    ka, kb = _kbest(tab, np.array([a, b]))
    st = sorted([_stage_from(tab, a, ka, False), _stage_from(tab, b, kb, False)], key=lambda s: -s.ratio)
    return PlanetaryDesign("1+1", tuple(st), target)


def search_designs(scheme: str, target: float, tol_pct: float = 5.0, forced: Fraction | None = None,
                   planets: int | None = None, n_alt: int = 6, select: str = "smallest") -> SearchResult:
    """Exhaustive search over all tooth sets of the scheme within Z_MAX (conditions 1, 2, 5 by
    construction and filter), planets by 3 and 4. ``select="smallest"`` carries the smallest by
    max(Γ1, Γ2); ``select="accurate"`` (the program's default, :func:`design_gears`) carries the most
    accurate ratio among the sets at most one tooth (SELECT_SLACK) larger than the smallest — a
    teacher trades one tooth of size for an exact ratio, not 4.5 % of ratio for one tooth.

    >>> r = search_designs("1", 720 / 140, select="accurate")  # i = 36/7 (variant 3 at 140 rpm)
    >>> r.carried.stages[0].teeth, r.carried.planets, r.smallest.stages[0].teeth
    ((21, 33, 87), 4, (22, 32, 86))

    Raises the internal exceptions ``_NoCandidates`` / ``_NoPlanets``; :func:`design_gears`
    turns them into messages.

    >>> r = search_designs("1", 720 / 220, forced=Fraction(13, 4))
    >>> r.carried.stages[0], r.rule
    (Stage(z_sun=40, z_planet=25, z_planet2=None, z_ring=90, planets=5), 'smallest_3plus')
    """
    if select not in SELECT_RULES:
        raise TmmError(f"selection rule '{select}' is unknown; use 'accurate' or 'smallest'")
    if scheme == "1+1":
        return _search_two(target, tol_pct, forced, planets, n_alt, select)
    return _search_single(scheme, target, tol_pct, forced, planets, n_alt, select)


# ----------------------------------------------------------------------------------------------
# the book's hand procedure (§2.4, §2.5)


@dataclass(frozen=True)
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


@dataclass(frozen=True)
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


@dataclass(frozen=True)
class BookDerivation:
    """The book's procedure, for the fraction(s) it starts from.

    ``fraction_rule``: "forced" (the user's fraction), "exact" (i_pl itself is a fraction with a
    denominator ≤ 10, e.g. 36/7 or 12/1: the book starts from it), "simple" (of the simple
    fractions with a denominator ≤ 10 within tolerance, the one whose procedure gives the smallest
    reducer).
    ``tried``: (fraction as text, size) for every simple fraction tried ("f1·f2" for two stages).
    """

    scheme: str
    fraction_rule: str
    stages: tuple[BookStage, ...]
    tried: tuple[tuple[str, int], ...]

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
    """
    exact = exact_fraction(target)
    if scheme in ("1", "2"):
        if forced is not None:
            st = _book_one(scheme, forced)
            return BookDerivation(scheme, "forced", (st,), ((str(forced), st.chosen.size),)) if st else None
        if exact is not None:  # i itself is a simple fraction (36/7, 12/1): the book starts from it
            st = _book_one(scheme, exact)
            if st is not None:
                return BookDerivation(scheme, "exact", (st,), ((str(exact), st.chosen.size),))
        tried, best = [], None
        for f in simple_fractions(target, tol_pct):
            st = _book_one(scheme, f)
            if st is None:
                continue
            tried.append((str(f), st.chosen.size))
            key = (st.chosen.size, abs(float(f) / target - 1))
            if best is None or key < best[0]:
                best = (key, st)
        if best is None:
            return None
        return BookDerivation(scheme, "simple", (best[1],), tuple(tried))
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
# the checks: (2.1) and the velocity pictures (2.3)


@dataclass(frozen=True)
class VelocityStage:
    """Linear-velocity picture of one stage in module units (radius r = z/2 per module).

    Points: A — sun/planet mesh at r_A = r_k; C — planet centre at r_C = r_k + r_c; B — the
    planet c′ / ring mesh at r_B = r_n (zero velocity). Velocities are drawn lengths (scale μ):
    v_A = ω_k·r_A·μ; the planet's line runs from (r_B, 0) through (r_A, v_A); v_C on it at r_C.
    φ_k, φ_H — angles of the sun's and carrier's lines to the vertical (radius) axis.
    """

    r_sun: float
    r_planet: float
    r_planet2: float
    r_ring: float
    r_a: float
    r_c: float
    r_b: float
    v_a: float
    v_c: float
    phi_k_deg: float
    phi_h_deg: float
    ratio: float  # tg φ_k / tg φ_H


@dataclass(frozen=True)
class VelocityPicture:
    """The linear-velocity picture of all stages and the angular-velocity picture (pole at
    distance ``pole_mm`` from the line on which the rays of each link cut segments ok, oh)."""

    stages: tuple[VelocityStage, ...]
    pole: float
    ok: float  # segment of the driving sun k
    oh: float  # segment of the output carrier H
    ratio: float  # ok/oh


def velocity_picture(stages: tuple[Stage, ...], v_a_first: float | None = None, pole: float | None = None) -> VelocityPicture:
    """Build the velocity pictures from the geometry and read the ratio off them, (2.3):
    i = tg φ_k / tg φ_H = ok/oh. Nothing here uses (2.1).

    Drawing choices (the ratio does not depend on them): V_A of the first stage is drawn
    max(r_A·tg 60°, r_max/2) long; the pole of the angular picture is 0.8·r_max from its line, or
    closer so that the picture (from c to k) is at most 1.5·r_max wide.

    >>> v = velocity_picture((Stage(40, 25, None, 90, 5),))
    >>> round(v.ratio, 12), round(v.stages[0].ratio, 12)
    (3.25, 3.25)
    """
    out = []
    r_max = max(max(s.z_ring, s.z_sun + 2 * s.z_planet) / 2 for s in stages)
    r_a0 = stages[0].z_sun / 2
    if v_a_first is None:
        v_a_first = max(r_a0 * math.tan(math.radians(60)), r_max / 2)
    omega = v_a_first / r_a0  # drawn length per unit radius: the sun's line through O
    for s in stages:
        rk, rc, rc2, rn = s.z_sun / 2, s.z_planet / 2, s.zc2 / 2, s.z_ring / 2
        r_a, r_c, r_b = rk, rk + rc, rn
        v_a = omega * r_a
        # planet block's line: zero at r_b, v_a at r_a (a straight line through both points)
        v_c = v_a * (r_b - r_c) / (r_b - r_a)
        phi_k = math.atan2(v_a, r_a)
        phi_h = math.atan2(v_c, r_c)
        out.append(VelocityStage(rk, rc, rc2, rn, r_a, r_c, r_b, v_a, v_c, math.degrees(phi_k), math.degrees(phi_h),
                                 math.tan(phi_k) / math.tan(phi_h)))
        omega = v_c / r_c  # the next stage's sun turns with this carrier
    if pole is None:
        width = math.tan(math.radians(out[0].phi_k_deg)) + max(s.v_a / (s.r_b - s.r_a) for s in out)
        pole = min(0.8 * r_max, 1.5 * r_max / width)
    ok = pole * math.tan(math.radians(out[0].phi_k_deg))
    oh = pole * math.tan(math.radians(out[-1].phi_h_deg))
    return VelocityPicture(tuple(out), pole, ok, oh, ok / oh)


@dataclass(frozen=True)
class DesignChecks:
    """The five conditions for the carried design, and the two ratio checks."""

    ratio: float
    ratio_fraction: Fraction
    target: float
    ratio_error_pct: float
    tolerance_pct: float
    ratio_ok: bool
    stages: tuple[StageChecks, ...]
    ratio_formula_21: tuple[float, ...]  # per stage, by (2.1): 1 − (−1)^a·z_c·z_n/(z_k·z_c′)
    ratio_formula_21_total: float
    velocity: VelocityPicture

    @property
    def ok(self) -> bool:
        return self.ratio_ok and all(s.ok for s in self.stages)


def ratio_21(stage: Stage, a: int = 1) -> float:
    """(2.1): i_kH^n = 1 − (−1)^a·(z_c·z_n)/(z_k·z_c′), a = number of external meshes (1 here).

    >>> ratio_21(Stage(40, 25, None, 90, 5))
    3.25
    """
    return 1 - (-1) ** a * (stage.z_planet * stage.z_ring) / (stage.z_sun * stage.zc2)


def check_design(design: PlanetaryDesign, tol_pct: float) -> DesignChecks:
    """All conditions of §2.1.3 and both ratio checks for a design."""
    per = tuple(ratio_21(s) for s in design.stages)
    tot = math.prod(per)
    err = design.ratio_error_pct
    return DesignChecks(
        ratio=design.ratio, ratio_fraction=design.ratio_fraction, target=design.target, ratio_error_pct=err,
        tolerance_pct=tol_pct, ratio_ok=abs(err) <= tol_pct * (1 + 1e-9) + 1e-9,
        stages=tuple(check_stage(s) for s in design.stages), ratio_formula_21=per, ratio_formula_21_total=tot,
        velocity=velocity_picture(design.stages),
    )


# ----------------------------------------------------------------------------------------------
# the book's printed answers (for the notes)


BOOK_PRINTED = {
    ("1", Fraction(13, 4)): ("2.4", Stage(40, 25, None, 90, 5)),
    ("2", Fraction(53, 5)): ("2.5", Stage(34, 56, 50, 120, 2)),
}
"""The answers printed in §2.4 and §2.5 (z_k, z_c, [z_c′,] z_n, k)."""


@dataclass(frozen=True)
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
