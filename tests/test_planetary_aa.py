"""Seed 000's AA̅ synthesis (gears/aa_bar.py, `tmm planetary`): the paper's numbers, the divisibility
rule proven by brute force from the general equations, the feasible range of C, independent
rechecks of the exported JSON, and hostile inputs driving the CLI."""

import json
import math
from fractions import Fraction

import numpy as np
import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli
from tmm_cli.errors import TmmError
from tmm_cli.gears.aa_bar import c_range, divisibility, family, synthesize, teeth_for
from tmm_cli.output.folder import MANIFEST
from cli_helpers import assert_one_line_error

SEED_ARGS = ["planetary", "--ratio", "1/10", "--c", "26/25", "--planets", "3", "--module", "5", "--x1", "-0.4",
             "--x2", "0.4"]


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])




# ----------------------------------------------------------------------------------------------
# the paper's example


def test_seed_000_acceptance_numbers():
    d = synthesize(Fraction(1, 10), Fraction(26, 25), 3, 5.0, -0.4, 0.4, z_min=18, z_max=180)
    assert d.div.multiples == (30, 5, 10) and d.div.z1_step == 30
    assert d.teeth == (30, 48, 48, 27)
    assert d.family == (1, 2, 3)
    assert [teeth_for(d.div, n) for n in d.family] == [(30, 48, 48, 27), (60, 96, 96, 54), (90, 144, 144, 81)]
    assert d.ratio_check == Fraction(1, 10)
    assert round(d.pair12.alpha_w_deg, 6) == 20.0 and round(d.a_w_mm, 6) == 195.0
    assert round(d.pair34.alpha_w_deg, 3) == 25.371
    assert round(d.c_check, 4) == 1.04
    assert round(d.x_sum[1], 3) == 1.700 and round(d.x[3], 3) == 1.300
    assert d.x[2] == d.x[1] == 0.4
    assert math.isclose(d.pair34.a_w_mm, 195.0, rel_tol=1e-12)  # both stages at one centre distance
    assert math.isclose(d.velocity.ratio, 0.1, rel_tol=1e-12)


def test_seed_000_blocking_verdicts():
    """The seed asserts the shifts lie inside the blocking contours but shows no check. Computed:
    pair 1-2 passes every line; in pair 3-4 the planet's tip reaches 0.14 mm (along the line of
    action) below the involute's lower limit of wheel 4 (x4 = 1.3): fillet interference."""
    d = synthesize(Fraction(1, 10), Fraction(26, 25), 3, 5.0, -0.4, 0.4)
    assert d.checks12.ok
    assert d.checks34.undercut == (False, False) and d.checks34.pointed == (False, False)
    assert d.checks34.eps_ok and d.checks34.interference == (False, True)
    assert d.neighbours.ok
    assert any(n.code == "shift_interference" for n in d.notes)


# ----------------------------------------------------------------------------------------------
# the divisibility rule, proven by brute force over (i, C, k) from the general equations


def _brute(i: Fraction, c: Fraction, k: int, n: int) -> np.ndarray:
    """Every Z1 ≤ n for which the general equations give whole positive Z2 = Z3, Z4 and k planets
    fit: Z4 = Z1(1 − i); coaxiality Z1 + Z2 = C(Z2 + Z4), i.e. Z2(Q − P) = P·Z4 − Q·Z1 for C = P/Q;
    assembly (Z1 − Z4)/k whole."""
    a, b, p, q = i.numerator, i.denominator, c.numerator, c.denominator
    z1 = np.arange(1, n + 1, dtype=np.int64)
    z4_ok = (z1 * (b - a)) % b == 0
    z4 = z1 * (b - a) // b
    num = p * z4 - q * z1
    z2_ok = (num % (q - p) == 0) & (num // (q - p) > 0)
    asm_ok = ((z1 - z4) % k == 0)
    return z1[z4_ok & z2_ok & asm_ok & (z4 > 0)]


def _cases():
    for b in range(2, 11):
        for a in range(1, b):
            if math.gcd(a, b) != 1:
                continue
            i = Fraction(a, b)
            lo, hi = c_range(i)
            for q in range(1, 9):
                for p in range(q + 1, 3 * q):
                    c = Fraction(p, q)
                    if c.denominator != q or not lo < c < hi:
                        continue
                    for k in (1, 2, 3, 4, 5):
                        yield i, c, k


def test_divisibility_rule_by_brute_force():
    n_cases = 0
    for i, c, k in _cases():
        step = divisibility(i, c, k).z1_step
        sols = _brute(i, c, k, 3 * step)
        assert list(sols) == [step, 2 * step, 3 * step], (i, c, k, step, sols[:5])
        z = teeth_for(divisibility(i, c, k), 1)
        assert 1 - Fraction(z[1] * z[3], z[0] * z[2]) == i  # the ratio
        assert Fraction(z[0] + z[1], z[2] + z[3]) == c  # coaxiality: C = (Z1 + Z2)/(Z3 + Z4)
        n_cases += 1
    assert n_cases > 300


def test_c_outside_its_range_has_no_tooth_set():
    for i in (Fraction(1, 10), Fraction(1, 3), Fraction(2, 5)):
        lo, hi = c_range(i)
        for c in (Fraction(9, 10), Fraction(1), hi, hi + Fraction(1, 7), Fraction(3)):
            if c == 1:
                continue  # C = 1 makes the coaxiality Z1 = Z4: no mechanism with i ≠ 0
            p, q = c.numerator, c.denominator
            z1 = np.arange(1, 2000)
            z4 = z1 * (1 - i)
            z2 = (c * z4 - z1) / (1 - c)
            assert all(v <= 0 for v in z2[:50]), (i, c)
            with pytest.raises(TmmError, match="feasible range"):
                synthesize(i, c, 3)


def test_the_printed_list_of_multiples_is_not_reliable():
    """The seed's sentence 'Z1 is a multiple of (kB; Bc − Ac; B)' gives a fractional Z2 for some C."""
    bad = []
    for i, c, k in _cases():
        b, p, q = i.denominator, c.numerator, c.denominator
        z1 = math.lcm(k * b, abs(q - p), b)
        z2 = Fraction(z1) * (c - c * i - 1) / (1 - c)
        if z2.denominator != 1:
            bad.append((i, c, k))
    assert (Fraction(1, 10), Fraction(26, 25), 3) not in bad  # the paper's own example happens to work
    assert len(bad) > 10


def test_family_respects_the_limits():
    div = divisibility(Fraction(1, 10), Fraction(26, 25), 3)
    assert family(div, 18, 180) == (1, 2, 3)
    assert family(div, 28, 180) == (2, 3)  # 27 < 28 drops the first
    assert family(div, 18, 90) == (1,)


# ----------------------------------------------------------------------------------------------
# the command line and its JSON, rechecked independently


def test_cli_json_interface(tmp_path):
    res = run(*SEED_ARGS, "--z-min", 18, "--z-max", 180, "--json", "--no-plots", "--out", tmp_path)
    assert res.exit_code == 0, res.output
    d = json.loads(res.stdout)
    assert d["teeth"] == [30, 48, 48, 27]
    assert d["family"] == [1, 2, 3]
    assert d["a_w_mm"] == 195.0
    assert [round(v, 3) for v in d["alpha_w_deg"]] == [20.0, 25.371]
    assert [round(v, 3) for v in d["x"]] == [-0.4, 0.4, 0.4, 1.3]
    assert [round(v, 3) for v in d["x_sum"]] == [0.0, 1.7]
    assert d["ratio"] == {"fraction": "1/10", "value": 0.1}
    assert len(d["pairs"]) == 2
    for p in d["pairs"]:
        for key in ("eps_alpha", "s_a_mm", "undercut", "interference", "pointed"):
            assert key in p
        assert len(p["s_a_mm"]) == 2 and len(p["undercut"]) == 2
    assert isinstance(d["warnings"], list) and d["warnings"]
    assert d["c_feasible"]["max"] == "10/9"
    assert (tmp_path / "planetary" / "planetary.json").is_file()


def test_exported_numbers_rechecked(tmp_path):
    """From the JSON alone: α_w34 from the centre distance, x_Σ34 from α_w34, zero backlash in
    both meshes, ε_α from the exported tip and base circles, neighbouring."""
    res = run(*SEED_ARGS, "--json", "--no-plots", "--out", tmp_path)
    d = json.loads(res.stdout)
    m, alpha = 5.0, math.radians(20.0)
    z1, z2, z3, z4 = d["teeth"]
    aw = d["a_w_mm"]
    a34 = math.acos(m * (z3 + z4) / 2 * math.cos(alpha) / aw)
    assert math.isclose(math.degrees(a34), d["alpha_w_deg"][1], abs_tol=1e-5)

    def inv(t):
        return math.tan(t) - t

    xs34 = (inv(a34) - inv(alpha)) * (z3 + z4) / (2 * math.tan(alpha))
    assert math.isclose(xs34, d["x_sum"][1], abs_tol=1e-5)
    for p in d["pairs"]:
        za, zb = p["teeth"]
        aw_p = math.radians(p["alpha_w_deg"])
        sw = []
        for z, x in zip(p["teeth"], p["x"]):
            dd = m * z
            s = m * (math.pi / 2 + 2 * x * math.tan(alpha))
            rw = dd / 2 * math.cos(alpha) / math.cos(aw_p)
            sw.append(2 * rw * (s / dd + inv(alpha) - inv(aw_p)))
        p_w = 2 * math.pi * (p["dw_mm"][0] / 2) / za
        assert math.isclose(sum(sw), p_w, rel_tol=1e-5)
        (ra1, ra2), (rb1, rb2) = [v / 2 for v in p["da_mm"]], [v / 2 for v in p["db_mm"]]
        eps = (math.sqrt(ra1 ** 2 - rb1 ** 2) + math.sqrt(ra2 ** 2 - rb2 ** 2) - aw * math.sin(aw_p)) / (
            math.pi * m * math.cos(alpha))
        assert math.isclose(eps, p["eps_alpha"], abs_tol=1e-5)
    # the planet is one gear with one tip circle
    assert d["pairs"][0]["da_mm"][1] == d["pairs"][1]["da_mm"][0] == d["planet_da_mm"]
    assert d["neighbours"]["ok"] == (d["planet_da_mm"] < 2 * aw * math.sin(math.pi / 3))


def test_cli_family_and_figures(tmp_path):
    res = run(*SEED_ARGS, "--family", 2, "--out", tmp_path, "--lang", "ru")
    assert res.exit_code == 0, res.output
    assert "60/96/96/54" in res.stdout
    files = sorted(p.name for p in (tmp_path / "planetary").iterdir() if p.name != MANIFEST)
    assert files == ["planetary.json", "planetary_mechanism.png", "planetary_velocity.png"]
    d = json.loads((tmp_path / "planetary" / "planetary.json").read_text(encoding="utf-8"))
    assert d["teeth"] == [60, 96, 96, 54] and d["family_multiple"] == 2


def test_many_planets_break_neighbouring(tmp_path):
    res = run("planetary", "--ratio", "1/10", "--c", "26/25", "--planets", "6", "--x1", "-1", "--x2", "1", "--json",
              "--no-plots", "--out", tmp_path)
    d = json.loads(res.stdout)
    assert d["teeth"][0] % 60 == 0
    assert d["neighbours"]["ok"] is False
    assert any("оседств" in w or "eighbour" in w for w in d["warnings"])


@pytest.mark.parametrize("args,words", [
    (["--ratio", "0/3", "--c", "26/25"], ["positive fraction"]),
    (["--ratio", "abc", "--c", "26/25"], ["positive fraction"]),
    (["--ratio", "3/2", "--c", "26/25"], ["less than 1"]),
    (["--ratio", "1/10", "--c", "-1/2"], ["positive fraction"]),
    (["--ratio", "1/10", "--c", "9/8"], ["feasible range", "10/9"]),
    (["--ratio", "1/10", "--c", "1/1"], ["feasible range"]),
    (["--ratio", "1/10", "--c", "26/25", "--z-max", "40"], ["no tooth set"]),
    (["--ratio", "1/10", "--c", "26/25", "--family", "5"], ["--family 5"]),
    (["--ratio", "1/10", "--c", "26/25", "--x1", "1.5", "--x2", "-1.5"], ["pointed", "gear 4"]),
    (["--ratio", "1/10", "--c", "26/25", "--x1", "2.2", "--x2", "0"], ["pointed"]),
    (["--ratio", "1/10", "--c", "26/25", "--planets", "0"], ["planets"]),
    (["--ratio", "1/10", "--c", "26/25", "--module", "0"], ["module"]),
])
def test_bad_input_one_line_exit_2_no_files(tmp_path, args, words):
    res = run("planetary", *args, "--out", tmp_path)
    assert_one_line_error(res, *words)
    assert not (tmp_path / "planetary").exists()


def test_tmm_gears_points_to_tmm_planetary_when_the_zero_reducer_is_poor(tmp_path):
    from tmm_cli.gears.design import design_gears

    r = design_gears(-1000, 50)  # the zero-gear reducer misses i_pl = 14.4 by −4.8 %
    hint = next(n for n in r.notes if n.code == "aa_bar_hint").kwargs
    res = run("planetary", "--ratio", hint["i"], "--c", hint["c"], "--x1", hint["x1"], "--x2", hint["x2"], "--json",
              "--no-plots", "--out", tmp_path)
    d = json.loads(res.stdout)
    assert "/".join(map(str, d["teeth"])) == hint["teeth"]
    assert all(p["ok"] for p in d["pairs"]) and d["neighbours"]["ok"] and not d["warnings"]
    assert abs(1 / d["ratio"]["value"] / 14.4 - 1) < 0.005
    assert not any(n.code == "aa_bar_hint" for n in design_gears(-1000, 220, ratio=(13, 4)).notes)


def test_the_printed_simplified_z2_formula_is_wrong():
    """The seed prints Z2 = Z1·(Ac(B − A) − Bc)/(Bc − Ac) after simplifying (1); it drops a factor B.
    For its own example it would give Z2 = −6270, not 48; equation (1) itself gives 48."""
    a, b, ac, bc, z1 = 1, 10, 26, 25, 30
    printed = Fraction(z1 * (ac * (b - a) - bc), bc - ac)
    i, c = Fraction(a, b), Fraction(ac, bc)
    general = z1 * (c - c * i - 1) / (1 - c)
    assert printed == -6270 and general == 48


@pytest.mark.parametrize("z_min, z_max", [(0, 180), (-3, 180), (40, 30)])
def test_empty_or_toothless_limits_are_refused(z_min, z_max):
    """A gear has at least one tooth: --z-min 0 is refused as an empty range, as is z_max < z_min."""
    with pytest.raises(TmmError, match=r"tooth limits .* are empty; give 1 ≤ --z-min ≤ --z-max"):
        synthesize(Fraction(1, 10), Fraction(26, 25), 3, z_min=z_min, z_max=z_max)
