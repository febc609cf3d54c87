"""Acceptance audit of issue 12 (profile-shifted gears; `tmm planetary`, seed 000's AA̅ synthesis).

Each test is named after the bullet it proves and drives the CLI. Every number is recomputed here
from the textbook formulas (inv α_w by bisection, a_w = a·cos α/cos α_w, s_y = 2r_y(s/d + inv α −
inv α_y), ε_α from the exported circles), not with tmm_cli.gears.
"""

import json
import math
from fractions import Fraction

import pytest


ALPHA = math.radians(20.0)
SEED = ["--ratio", "1/10", "--c", "26/25", "--planets", "3", "--module", "5", "--x1", "-0.4", "--x2", "0.4"]


from cli_helpers import run, run_json  # noqa: E402


def inv(a):
    return math.tan(a) - a


def alpha_w(z1, z2, x_sum):
    """Solve inv α_w = inv α + 2x_Σ·tg α/(z1 + z2) by bisection (independent of the program's Newton)."""
    target = inv(ALPHA) + 2 * x_sum * math.tan(ALPHA) / (z1 + z2)
    lo, hi = 1e-6, math.radians(89.0)
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if inv(mid) < target else (lo, mid)
    return (lo + hi) / 2


def thickness(r_y, rb, s, d):
    """s_y = 2r_y(s/d + inv α − inv α_y), α_y = acos(r_b/r_y)."""
    return 2 * r_y * (s / d + inv(ALPHA) - inv(math.acos(rb / r_y)))


def check_pair(z1, z2, m, x1, x2, p, planet=None):
    """A pair's exported numbers against the formulas: α_w, a_w, zero backlash, s_a, ε_α.
    `planet`: index of the AA̅ planet in the pair, whose tip circle is the smaller of the two its
    meshes allow (so at most the formula's)."""
    aw = alpha_w(z1, z2, x1 + x2)
    a = m * (z1 + z2) / 2
    assert p["alpha_w_deg"] == pytest.approx(math.degrees(aw), abs=1e-5)
    assert p["a_w_mm"] == pytest.approx(a * math.cos(ALPHA) / math.cos(aw), rel=1e-6)
    # reverse: x_Σ from a_w
    cos_w = a * math.cos(ALPHA) / p["a_w_mm"]
    xs = (inv(math.acos(cos_w)) - inv(ALPHA)) * (z1 + z2) / (2 * math.tan(ALPHA))
    assert xs == pytest.approx(x1 + x2, abs=1e-5)
    d = (m * z1, m * z2)
    rb = tuple(di * math.cos(ALPHA) / 2 for di in d)
    s = tuple(m * (math.pi / 2 + 2 * x * math.tan(ALPHA)) for x in (x1, x2))
    rw = tuple(di * math.cos(ALPHA) / math.cos(aw) / 2 for di in d)
    sw = [thickness(rw[i], rb[i], s[i], d[i]) for i in (0, 1)]
    assert sw[0] + sw[1] == pytest.approx(math.pi * 2 * rw[0] / z1, rel=1e-6)  # s_w1 + s_w2 = p_w
    ra = tuple(x / 2 for x in p["da_mm"])
    for i in (0, 1):
        assert p["s_a_mm"][i] == pytest.approx(thickness(ra[i], rb[i], s[i], d[i]), abs=2e-5)
    # tip circles: d_a = d + 2(h_a* + x − Δy)m, Δy = x_Σ − y
    y = (p["a_w_mm"] - a) / m
    for i, x in enumerate((x1, x2)):
        formula = d[i] + 2 * (1 + x - (x1 + x2 - y)) * m
        if i == planet:
            assert p["da_mm"][i] <= formula + 1e-4
        else:
            assert p["da_mm"][i] == pytest.approx(formula, abs=1e-4)
    g = math.sqrt(ra[0] ** 2 - rb[0] ** 2) + math.sqrt(ra[1] ** 2 - rb[1] ** 2) - p["a_w_mm"] * math.sin(aw)
    assert p["eps_alpha"] == pytest.approx(g / (math.pi * m * math.cos(ALPHA)), abs=2e-6)


# --- Acceptance numbers (the paper's example) --------------------------------------------------

def test_acceptance_numbers_teeth_family_multiples_and_ratio():
    d = run_json("planetary", *SEED)
    assert d["teeth"] == [30, 48, 48, 27] and d["family"] == [1, 2, 3]
    assert (d["multiples"]["assembly"], d["multiples"]["coaxiality"], d["multiples"]["ratio"]) == (30, 5, 10)
    assert d["multiples"]["z1_min"] == 30
    z1, z2, z3, z4 = d["teeth"]
    assert 1 - Fraction(z2 * z4, z1 * z3) == Fraction(1, 10)
    assert d["ratio"]["fraction"] == "1/10" and d["ratio"]["value"] == pytest.approx(0.1)
    assert (z1 + z4) % 3 == 0  # assembly with k = 3 (the sun and the fixed wheel, equally spaced planets)
    # common centre distance: m(z1 + z2)/2·cos α/cos α_w12 = m(z3 + z4)/2·cos α/cos α_w34
    m = 5.0
    c = Fraction(26, 25)
    assert (z1 + z2) * Fraction(1) == (z3 + z4) * c  # (z1 + z2)·cos α_w12 … ⇔ (z1+z2)/(z3+z4) = C
    assert d["a_w_mm"] == pytest.approx(195.0, abs=1e-9)
    assert d["alpha_w_deg"][0] == pytest.approx(20.0, abs=1e-9)
    assert d["alpha_w_deg"][1] == pytest.approx(25.371, abs=1e-3)
    cos_ratio = math.cos(math.radians(d["alpha_w_deg"][0])) / math.cos(math.radians(d["alpha_w_deg"][1]))
    assert cos_ratio == pytest.approx(1.04, abs=1e-8)  # α_w34 exported to 1e-6°
    assert d["x"][:3] == [-0.4, 0.4, 0.4]
    assert d["x_sum"][1] == pytest.approx(1.700, abs=1e-3) and d["x"][3] == pytest.approx(1.300, abs=1e-3)
    # the second pair's x_Σ from the common a_w (reverse formula, here)
    cos34 = m * (z3 + z4) / 2 * math.cos(ALPHA) / d["a_w_mm"]
    xs34 = (inv(math.acos(cos34)) - inv(ALPHA)) * (z3 + z4) / (2 * math.tan(ALPHA))
    assert d["x_sum"][1] == pytest.approx(xs34, abs=1e-5)


def test_acceptance_every_formula_checked_independently_on_both_pairs():
    d = run_json("planetary", *SEED)
    z1, z2, z3, z4 = d["teeth"]
    x1, x2, x3, x4 = d["x"]
    p12, p34 = d["pairs"]
    check_pair(z1, z2, 5.0, x1, x2, p12, planet=1)
    check_pair(z3, z4, 5.0, x3, x4, p34, planet=0)


def test_family_option_takes_the_kth_multiple():
    d = run_json("planetary", *SEED, "--family", 2)
    assert d["teeth"] == [2 * z for z in (30, 48, 48, 27)]
    # ×3 is within the tooth limits, but x_Σ34 grows with the teeth: wheel 4 turns pointed
    res = run("planetary", *SEED, "--family", 3, "--no-plots", "--lang", "en")
    assert res.exit_code == 2 and "pointed" in res.stderr and len(res.stderr.strip().splitlines()) == 1


# --- Interface to keep -------------------------------------------------------------------------

def test_interface_planetary_json_keys():
    d = run_json("planetary", *SEED, "--z-min", 18, "--z-max", 180)
    for key in ("teeth", "family", "a_w_mm", "alpha_w_deg", "x", "x_sum", "ratio", "pairs", "warnings"):
        assert key in d, key
    assert set(d["ratio"]) >= {"fraction", "value"}
    for p in d["pairs"]:
        assert {"eps_alpha", "s_a_mm", "undercut", "interference", "pointed"} <= set(p)
        assert len(p["s_a_mm"]) == 2


def test_interface_gears_shift_keys_beside_the_spur_keys():
    for extra in (["--shift", "0.3,-0.3"], ["--shift", "auto"], ["--aw", "420"]):
        s = run_json("gears", "--variant", 17, *extra)["gears"]["spur"]
        assert {"x1", "x2", "a_w_mm", "alpha_w_deg", "z1", "z2", "a_mm", "eps_alpha"} <= set(s)
    s = run_json("gears", "--variant", 17, "--aw", "420")["gears"]["spur"]
    assert s["a_w_mm"] == pytest.approx(420.0, abs=1e-6)
    assert s["alpha_w_deg"] == pytest.approx(math.degrees(math.acos(s["a_mm"] * math.cos(ALPHA) / 420.0)), abs=1e-6)


def test_default_stays_the_books_zero_pair_and_suggests_a_shift_below_17_teeth():
    g = run_json("gears", "--variant", 17)["gears"]
    assert g["spur"]["x1"] == 0 and g["spur"]["x2"] == 0
    assert g["spur"]["a_w_mm"] == pytest.approx(g["spur"]["a_mm"])
    zmin = min(g["spur"]["z1"], g["spur"]["z2"])
    if zmin < 17.1:  # 2/sin²α = 17.1: the shift that removes the undercut is said
        assert any("shift x ≥" in w for w in g["warnings"] + g["assumptions"])
    if zmin == 17:  # the book's own smallest gear (§2.3) is said, not flagged as a warning
        assert not any("shift x ≥" in w for w in g["warnings"])


@pytest.mark.parametrize("x1, x2", [(0.0, 0.0), (0.5, 0.2), (0.3, -0.3), (0.8, 0.5), (-0.2, 0.6)])
def test_grid_alpha_w_a_w_forward_reverse_and_eps_from_the_profiles(x1, x2):
    s = run_json("gears", "--variant", 17, "--shift", f"{x1},{x2}")["gears"]["spur"]
    check_pair(s["z1"], s["z2"], s["m_mm"], x1, x2, dict(s["shifted"], eps_alpha=s["eps_alpha"]))


# --- Must hold: bad input, one line, exit 2, nothing half-written ------------------------------

BAD = [
    (["planetary", "--ratio", "-1/10", "--c", "26/25"], ["ratio"]),
    (["planetary", "--ratio", "1/0", "--c", "26/25"], ["ratio"]),
    (["planetary", "--ratio", "3/2", "--c", "26/25"], ["less than 1"]),
    (["planetary", "--ratio", "1/10", "--c", "0/1"], ["C"]),
    (["planetary", "--ratio", "1/10", "--c", "2/1"], ["feasible range", "10/9"]),
    (["planetary", "--ratio", "1/10", "--c", "1/1"], ["feasible range"]),
    (["planetary", "--ratio", "1/10", "--c", "26/25", "--z-max", "40"], ["no tooth set"]),
    (["planetary", "--ratio", "1/10", "--c", "26/25", "--x1", "5"], ["pointed"]),
    (["gears", "--variant", "17", "--shift", "-1.5,1.5"], ["pointed"]),
    (["gears", "--variant", "17", "--aw", "10"], ["cannot be reached"]),
    (["gears", "--variant", "17", "--aw", "1000"], ["shift sum", "tip"]),
    (["gears", "--variant", "17", "--shift", "0.3"], ["--shift"]),
]


@pytest.mark.parametrize("args, words", BAD)
def test_bad_input_one_line_exit_2_nothing_written(tmp_path, args, words):
    out = tmp_path / "new" / "deep"
    res = run(*args, "--out", out, "--lang", "en")
    assert res.exit_code == 2, res.output
    err = res.stderr.strip()
    assert "Traceback" not in res.output and len(err.splitlines()) == 1 and err.startswith("tmm: error:"), err
    for w in words:
        assert w in err, (w, err)
    assert not (tmp_path / "new").exists()


def test_feasible_c_stated_for_the_ratio():
    d = run_json("planetary", *SEED)
    assert d["c_feasible"]["max"] == "10/9" and d["c_feasible"]["min"] == "1/1"
    for ex in d["c_feasible"]["examples"]:
        c = Fraction(ex["c"])
        assert 1 < c < Fraction(10, 9)
        z1, z2, z3, z4 = ex["teeth"]
        assert 1 - Fraction(z2 * z4, z1 * z3) == Fraction(1, 10) and Fraction(z1 + z2, z3 + z4) == c


# --- Must hold: `tmm check` learns the spur-pair shift keys -------------------------------------

def test_check_learns_the_spur_shift_keys_and_checks_the_students_own_shifted_pair(tmp_path):
    s = run_json("gears", "--variant", 17, "--shift", "0.5,0.2")["gears"]["spur"]
    f = tmp_path / "a.toml"
    f.write_text(f"x1 = 0.5\nx2 = 0.2\na_w_mm = {s['a_w_mm']:.2f}\nalpha_w_deg = {s['alpha_w_deg']:.2f}\n"
                 f"eps_alpha = {s['eps_alpha']:.3f}\n", encoding="utf-8")
    res = run("check", "--variant", 17, "--answers", f, "--json", "--lang", "en")
    rows = {r["key"]: r["status"] for r in json.loads(res.stdout)["rows"]}
    assert all(rows[k] == "pass" for k in ("x1", "x2", "a_w_mm", "alpha_w_deg", "eps_alpha")), rows
    # a wrong a_w for those shifts fails; the zero pair's a_w with those shifts fails too
    f.write_text(f"x1 = 0.5\nx2 = 0.2\na_w_mm = {s['a_mm']}\n", encoding="utf-8")
    res = run("check", "--variant", 17, "--answers", f, "--json", "--lang", "en", "--rtol", "1")
    rows = {r["key"]: r["status"] for r in json.loads(res.stdout)["rows"]}
    assert rows["a_w_mm"] == "fail"
    # no shifts given: the book's zero pair
    f.write_text(f"a_w_mm = {s['a_mm']}\n", encoding="utf-8")
    res = run("check", "--variant", 17, "--answers", f, "--json", "--lang", "en")
    rows = {r["key"]: r["status"] for r in json.loads(res.stdout)["rows"]}
    assert rows["a_w_mm"] == "pass"
