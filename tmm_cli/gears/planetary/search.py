"""The exhaustive search: tables of all tooth sets of a scheme (numpy, precomputed once per
process), the selection of the carried design among them, and the set nearest to a ratio.

Search bounds: every tooth number satisfying Table 2.2 with a size ≤ Z_MAX = 200 teeth. Table 2.2
forces z_n ≥ 85, the book's own designs are 90 (§2.4) and up to 190 (§2.5, Table 2.3 row 10), and
the smallest design for every i_pl from 3 to 24 (crank 30 … 960 rpm) is below 130; 200 keeps all of
them with room for forced fractions while the scheme-2 table stays at ~4·10⁵ sets.
"""

from __future__ import annotations

import math
from fractions import Fraction
from functools import lru_cache

import numpy as np

from ...errors import TmmError
from ...records import record
from .conditions import (
    HA_STAR,
    K_MAX,
    REL_EPS,
    Z_DIFF,
    Z_EXT_EXT,
    Z_EXT_INT,
    Z_RING,
    PlanetaryDesign,
    Stage,
)

Z_MAX = 200
SELECT_SLACK = 1  # "accurate": compare the sets at most this many teeth larger than the smallest
SELECT_RULES = ("accurate", "smallest")
STAGE_RANGE_1 = (3.0, 8.0)  # Fig. 2.4, scheme 1: the ratio range of one single-row stage


# ----------------------------------------------------------------------------------------------
# tables of all tooth sets (precomputed once per process)


@record
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


@record
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
