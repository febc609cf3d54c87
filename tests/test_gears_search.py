"""The carried reducer rechecked by an independent checker, and a separate brute force for
the smallest reducer, over crank speeds 30 … 960 rpm."""

import math
from fractions import Fraction

import pytest

from tmm_cli.gears.design import design_gears

MOTORS = (720, 920, 1420, 2880)


def required_ratio(n_cr):
    n_d = next(n for n in MOTORS if n >= 3 * n_cr)
    return n_d, n_d / n_cr


# ---------------------------------------------------------------- independent checker (tests/reference_gears.py)

from reference_gears import max_planets, planet_fits, stage_ok, willis  # noqa: E402


def recheck(result, tol=5.0):
    pl = result.planetary
    i = Fraction(1)
    for st in pl.stages:
        double = st.z_planet2 is not None
        zc2 = st.z_planet2 if double else st.z_planet
        assert stage_ok(st.z_sun, st.z_planet, zc2, st.z_ring, st.planets, double), st
        i *= willis(st.z_sun, st.z_planet, zc2, st.z_ring)
    assert abs(float(i) / result.i_planetary - 1) <= tol / 100 + 1e-12
    assert float(i) == pytest.approx(pl.ratio, rel=1e-12)
    assert result.checks.velocity.ratio == pytest.approx(float(i), rel=1e-9)
    assert result.checks.ok


def test_every_crank_speed_30_to_960_gives_a_valid_design():
    schemes = set()
    for n_cr in range(30, 961):
        r = design_gears(1000, n_cr)
        schemes.add(r.scheme)
        recheck(r)
        n_d, i = required_ratio(n_cr)
        assert r.motor_rpm == n_d
        exp = "1" if i <= 8 else ("2" if i <= 16 else "1+1")
        assert r.scheme == exp
        if r.planetary.planets < 3:
            assert any(n.code == "few_planets" for n in r.notes)
    assert schemes == {"1", "2", "1+1"}


# ---------------------------------------------------------------- brute force, written separately


def brute_single(i_req, tol, double, with_list=False):
    """Smallest max(z_k + 2z_c, z_n) with ≥ 3 planets if any (else any), by direct enumeration;
    with_list: also every candidate (size, zk, zc, zc2, zn) of that planets pool."""
    lo, hi = i_req * (1 - tol / 100), i_req * (1 + tol / 100)
    cands = []
    for zk in range(17, 201):
        for zc in range(17 if double else 20, 101):
            if zk + 2 * zc > 200:
                break
            if not double:
                zn = zk + 2 * zc
                if zn >= 85 and lo <= 1 + zn / zk <= hi:
                    cands.append((zn, zk, zc, zc, zn))
                continue
            # i − 1 = z_c(z_k + z_c + z_c′)/(z_k·z_c′) decreases with z_c′: solve for its range
            lo_c2 = zc * (zk + zc) / ((hi - 1) * zk - zc) if (hi - 1) * zk > zc else None
            if lo_c2 is None:
                continue
            hi_c2 = zc * (zk + zc) / ((lo - 1) * zk - zc) if (lo - 1) * zk > zc else 1e9
            for zc2 in range(max(20, math.ceil(lo_c2 - 1e-9)), min(200, math.floor(hi_c2 + 1e-9)) + 1):
                zn = zk + zc + zc2
                if zn < 85 or zn > 200:
                    continue
                r = float(willis(zk, zc, zc2, zn))
                if lo - 1e-12 <= r <= hi + 1e-12:
                    cands.append((max(zk + 2 * zc, zn), zk, zc, zc2, zn))
    cands.sort()
    if with_list:
        pool = [c for c in cands if c[0] <= cands[0][0] + 12 and max_planets(*c[1:]) >= 3]
        if pool:
            return pool[0][0], True, pool
        return cands[0][0], False, cands
    for size, zk, zc, zc2, zn in cands:
        if max_planets(zk, zc, zc2, zn) >= 3:
            return size, True
    return (cands[0][0], False) if cands else (None, False)


def brute_two(i_req, tol, stage_range=(3.0, 8.0)):
    """Smallest two-stage size with ≥ 3 planets, each stage's ratio within Fig. 2.4's 3…8."""
    lo, hi = i_req * (1 - tol / 100), i_req * (1 + tol / 100)
    sets = []
    for zk in range(17, 201):
        for zc in range(20, 101):
            zn = zk + 2 * zc
            if zn > 200:
                break
            if zn >= 85 and stage_range[0] <= 1 + zn / zk <= stage_range[1]:
                sets.append((zn, 1 + zn / zk, (zk, zc, zn)))
    sets.sort()
    good3 = {}
    for size in sorted({s[0] for s in sets}):
        pool = [s for s in sets if s[0] <= size]
        pool3 = []
        for s in pool:
            key = s[2]
            if key not in good3:
                zk, zc, zn = key
                good3[key] = max_planets(zk, zc, zc, zn) >= 3
            if good3[key]:
                pool3.append(s)
        rs = sorted(s[1] for s in pool3)
        import bisect

        for r in rs:
            j = bisect.bisect_left(rs, lo / r - 1e-12)
            if j < len(rs) and rs[j] <= hi / r + 1e-12:
                return size
    return None


SAMPLE_1 = [96, 100, 120, 150, 180, 220, 240, 241, 300, 307, 400, 480, 700, 960]
SAMPLE_2 = [45, 52, 60, 67, 80, 89]
SAMPLE_11 = [30, 36, 44]


@pytest.mark.parametrize("n_cr", SAMPLE_1 + SAMPLE_2)
def test_no_smaller_reducer_by_brute_force(n_cr):
    """--select smallest (the pre-issue-8 rule) carries the smallest reducer."""
    r = design_gears(1000, n_cr, select="smallest")
    size, has3 = brute_single(r.i_planetary, 5.0, double=r.scheme == "2")
    assert r.planetary.size == size
    assert (r.planetary.planets >= 3) == has3


@pytest.mark.parametrize("n_cr", SAMPLE_1 + SAMPLE_2)
def test_accurate_choice_by_brute_force(n_cr):
    """The default rule (issue 8): the most accurate ratio among the sets at most one tooth larger
    than the smallest (≥ 3 planets when any set takes 3)."""
    r = design_gears(1000, n_cr)
    smin, has3, pool = brute_single(r.i_planetary, 5.0, double=r.scheme == "2", with_list=True)
    near = [c for c in pool if c[0] <= smin + 1]
    best = min(abs(float(willis(*c[1:])) / r.i_planetary - 1) for c in near)
    recheck(r)
    assert r.planetary.size <= smin + 1
    assert abs(r.planetary.ratio / r.i_planetary - 1) == pytest.approx(best, abs=1e-12)
    assert (r.planetary.planets >= 3) == has3


@pytest.mark.parametrize("n_cr", SAMPLE_11)
def test_no_smaller_two_stage_reducer_by_brute_force(n_cr):
    r = design_gears(1000, n_cr, select="smallest")
    assert r.scheme == "1+1"
    assert r.planetary.planets >= 3
    assert r.planetary.size == brute_two(r.i_planetary, 5.0)
    assert all(3.0 <= s.ratio <= 8.0 for s in r.planetary.stages)


@pytest.mark.parametrize("n_cr", SAMPLE_11 + [40])
def test_two_stage_accurate_and_within_range_by_brute_force(n_cr):
    """Two stages: each within 3…8 (Fig. 2.4), the most accurate pair within one tooth of the smallest."""
    r = design_gears(1000, n_cr)
    smin = brute_two(r.i_planetary, 5.0)
    lo, hi = r.i_planetary * 0.95, r.i_planetary * 1.05
    sets = [(zk, zc, zk + 2 * zc) for zk in range(17, smin + 2) for zc in range(20, 100)
            if 85 <= zk + 2 * zc <= smin + 1 and 3.0 <= 1 + (zk + 2 * zc) / zk <= 8.0]
    sets = [t for t in sets if max_planets(t[0], t[1], t[1], t[2]) >= 3]
    best = min(abs((1 + a[2] / a[0]) * (1 + b[2] / b[0]) / r.i_planetary - 1)
               for a in sets for b in sets if lo <= (1 + a[2] / a[0]) * (1 + b[2] / b[0]) <= hi)
    recheck(r)
    assert all(3.0 <= s.ratio <= 8.0 for s in r.planetary.stages)
    assert r.planetary.size <= smin + 1
    assert abs(r.planetary.ratio / r.i_planetary - 1) == pytest.approx(best, abs=1e-12)
    assert any(n.code == "two_stage_range_ok" for n in r.notes)


def test_forced_planets_are_honoured():
    r = design_gears(1000, 220, planets=3)
    assert all(s.planets == 3 for s in r.planetary.stages)
    recheck(r)


def test_checker_agrees_with_books_numbers():
    # §2.4: 40/25/90 takes 2, 5, 10, 13 … by assembly, neighbours limit 7 → 5
    assert [k for k in range(2, 14) if planet_fits(k, 40, 25, 25, 90)] == [2, 5, 10, 13]
    assert max_planets(40, 25, 25, 90) == 5
    # a double-planet set where turning the block by whole teeth admits 3 though z_k·i = 212
    assert planet_fits(3, 20, 64, 42, 126) and not 212 % 3 == 0


@pytest.mark.parametrize("n_cr", [130, 158, 165, 186])
def test_the_sets_passed_over_are_what_they_are_named(n_cr):
    """Under the accurate rule the note names the sets passed over because they are larger: the
    smallest one more accurate than the carried set, and the smallest exact one (n_cr = 165:
    1000/165 = 200/33 is met exactly by a larger set). Checked by their ratios against the target."""
    from tmm_cli.gears.planetary.search import search_designs

    target = 1000 / n_cr
    r = search_designs("1", target, select="accurate")
    e0 = abs(r.carried.ratio / target - 1)
    assert r.more_accurate is not None and abs(r.more_accurate.ratio / target - 1) < e0
    if n_cr == 165:
        assert r.exact is not None and r.exact.ratio == pytest.approx(target, rel=1e-12)
        assert r.exact.size >= r.more_accurate.size and r.exact != r.more_accurate
    else:
        assert r.exact is None


def test_closest_ratio_beyond_the_range_is_the_largest_stage_twice():
    """Far above every ratio the search reaches, the nearest two-stage (1+1) reducer is the largest
    single-row stage repeated; the nearest single stage is that stage."""
    from tmm_cli.gears.planetary.search import closest_ratio

    one = closest_ratio("1", 1e6).ratio
    assert closest_ratio("1+1", 1e6).ratio == pytest.approx(one ** 2, rel=1e-12)
    assert closest_ratio("1", 1.0001).ratio < closest_ratio("1", 4.0).ratio < one


@pytest.mark.parametrize("n_cr", [30, 120, 220, 500])
def test_book_comparison_note_agrees_with_the_sizes(n_cr):
    """The note comparing the book's derivation with the search says 'smaller' exactly when the
    carried set is smaller than the book's, 'same' when equal (sizes from the note itself)."""
    r = design_gears(1000, n_cr)
    note = next(x for x in r.notes if x.code.startswith("book_vs_search"))
    size, book = note.kwargs["size"], note.kwargs["book_size"]
    if size < book:
        assert note.code == "book_vs_search_smaller"
    elif size == book:
        assert note.code == "book_vs_search_same"
    else:
        assert note.code in ("book_vs_search_book_smaller", "book_vs_search_accurate")
