"""Dimensional chains (seed 003, second article; issue 23), checked against sums done by hand."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tmm_cli.accuracy.chain import solve_chain, t_for_risk
from tmm_cli.accuracy.chain_input import parse_chain
from tmm_cli.errors import TmmError

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
ARCMIN = math.pi / 10800


def toml(*links, name="c", units=None):
    head = f'name = "{name}"\n' + (f'units = "{units}"\n' if units else "")
    body = ""
    for link in links:
        body += "[[link]]\n" + "".join(f"{k} = {v!r}\n".replace("'", '"') for k, v in link.items())
    return head + body


THREE = toml({"name": "A", "nominal": 100.0, "es": 0.1, "ei": -0.1, "sign": "+"},
             {"name": "B", "nominal": 40.0, "es": 0.0, "ei": -0.05, "sign": "-"},
             {"name": "C", "nominal": 59.5, "es": 0.02, "ei": -0.02, "sign": "-"})


def mm(x):
    return x * 1e3


def test_three_links_by_hand():
    """A − B − C = 100 − 40 − 59.5 = 0.5 mm.
    Worst case: ES = 0.1 − (−0.05) − (−0.02) = 0.17, EI = −0.1 − 0 − 0.02 = −0.12, T = 0.29
    = 0.2 + 0.05 + 0.04; limits 0.67 and 0.38.
    Probabilistic, all normal, t = 3: T = 3·√((0.04 + 0.0025 + 0.0016)/9) = √0.0441 = 0.21;
    E_c = 0 − (−0.025) − 0 = 0.025; ES = 0.13, EI = −0.08; limits 0.63 and 0.42."""
    res = solve_chain(parse_chain(THREE))
    assert mm(res.nominal) == pytest.approx(0.5)
    w, p = res.worst_case, res.probabilistic
    assert [mm(v) for v in (w.es, w.ei, w.tolerance, w.max, w.min)] == pytest.approx([0.17, -0.12, 0.29, 0.67, 0.38])
    assert p.t == pytest.approx(3.0, abs=1e-4) and p.risk_percent == 0.27
    assert [mm(v) for v in (p.es, p.ei, p.tolerance, p.max, p.min)] == pytest.approx(
        [0.13, -0.08, 0.21, 0.63, 0.42], abs=2e-6)  # t = 2.99998, not 3
    # shares: worst case 0.2/0.29; variance 0.04/0.0441
    assert res.shares[0].worst_case == pytest.approx(0.2 / 0.29)
    assert res.shares[0].probabilistic == pytest.approx(0.04 / 0.0441)
    assert res.largest_worst_case == res.largest_probabilistic == "A"
    assert sum(s.worst_case for s in res.shares) == pytest.approx(1)
    assert not res.probabilistic_exceeds_worst_case


def test_distributions_asymmetry_and_risk_by_hand():
    """A = 50 (+0.3/+0.1, uniform, α = 0.2), B = 20 (±0.1, triangle, decreasing), P = 1 %:
    t = 2.5758; T = t·√(0.2²/3 + 0.2²/6) = t·√0.02 = 0.364278;
    E_c = (0.2 + 0.2·0.2/2) − 0 = 0.22; ES = 0.402139, EI = 0.037861.
    Worst case: ES = 0.3 + 0.1 = 0.4, EI = 0.1 − 0.1 = 0."""
    text = toml({"name": "A", "nominal": 50.0, "es": 0.3, "ei": 0.1, "sign": "+", "distribution": "uniform",
                 "asymmetry": 0.2},
                {"name": "B", "nominal": 20.0, "es": 0.1, "ei": -0.1, "sign": "-", "distribution": "triangle"})
    res = solve_chain(parse_chain(text), risk_percent=1.0)
    p = res.probabilistic
    assert p.t == pytest.approx(2.575829, abs=1e-6)
    assert mm(p.tolerance) == pytest.approx(0.364278, abs=1e-6)
    assert mm(p.middle) == pytest.approx(0.22)
    assert [mm(p.es), mm(p.ei), mm(p.max), mm(p.min)] == pytest.approx([0.402139, 0.037861, 30.402139, 30.037861],
                                                                       abs=1e-6)
    assert [mm(res.worst_case.es), mm(res.worst_case.ei)] == pytest.approx([0.4, 0.0], abs=1e-12)
    assert res.largest_probabilistic == "A"  # 0.04/3 against 0.04/6


def test_one_uniform_link_probabilistic_exceeds_worst_case():
    """One uniform link: t·√(T²/3) = 1.73·T > T; the result says so."""
    res = solve_chain(parse_chain(toml({"name": "A", "nominal": 10.0, "es": 0.1, "ei": 0.0, "sign": "+",
                                        "distribution": "uniform"})))
    assert res.probabilistic.tolerance == pytest.approx(res.worst_case.tolerance * t_for_risk(0.27) / math.sqrt(3))
    assert res.probabilistic_exceeds_worst_case


def test_angular_chain_with_a_hub_clearance_by_hand():
    """Chain (5): α_0 = α_1 + α_2 + α_3 (±2′, ±3′, ±4′) and the hub's turn in its clearance,
    δ = 0.02 mm over l = 40 mm: β = arctg(0.0005) = 1.71887′ (0 ± β).
    Worst case T = 2·(2 + 3 + 4 + 1.71887) = 21.43775′; probabilistic (normal, t = 3)
    T = √(4² + 6² + 8² + 3.43775²) = √127.8181 = 11.30567′."""
    text = toml({"name": "alpha1", "nominal": 0.0, "es": 2.0, "ei": -2.0, "sign": "+"},
                {"name": "alpha2", "nominal": 0.0, "es": 3.0, "ei": -3.0, "sign": "+"},
                {"name": "alpha3", "nominal": 0.0, "es": 4.0, "ei": -4.0, "sign": "+"},
                {"name": "beta", "clearance": 0.02, "length": 40.0, "sign": "+"}, units="arcmin")
    chain = parse_chain(text)
    beta = chain.links[3]
    assert beta.es / ARCMIN == pytest.approx(1.718873, abs=1e-6) and beta.ei == -beta.es
    res = solve_chain(chain)
    assert res.worst_case.tolerance / ARCMIN == pytest.approx(21.437747, abs=1e-6)
    assert res.probabilistic.tolerance / ARCMIN == pytest.approx(11.30567 * t_for_risk(0.27) / 3, abs=1e-5)
    assert res.nominal == 0.0
    assert res.largest_probabilistic == "alpha3"


def test_the_articles_examples_in_docs():
    """docs/examples: chain (1)/(3) (radial mesh clearance of a keyed pair) and (5)/(6) (tooth
    direction with one and with two key joints). Numbers chosen for the example (the article gives
    none); the sums are done here by hand from the file's values."""
    radial = solve_chain(parse_chain((EXAMPLES / "chain-radial-1.toml").read_text(encoding="utf-8")))
    # Δ = A − (r1 + δ11 + S11) − (r2 + δ21 + S21 + δ22 + S22) = 125 − 27.5 − 96.875
    assert mm(radial.nominal) == pytest.approx(0.625)
    assert [k.name for k in radial.chain.links] == ["A", "r1", "δ11", "S11", "r2", "δ21", "S21", "δ22", "S22"]
    # ES = 0.032 − (−0.010 + 0 − 0.095 − 0.025 + 0 − 0.020 + 0 − 0.100) = 0.282
    # EI = −0.032 − (−0.0035 + 0.0105 + 0 − 0.0125 + 0.0195 + 0 + 0.0125 + 0) = −0.0585
    assert mm(radial.worst_case.es) == pytest.approx(0.282)
    assert mm(radial.worst_case.ei) == pytest.approx(-0.0585)
    assert mm(radial.worst_case.min) == pytest.approx(0.5665)
    one = solve_chain(parse_chain((EXAMPLES / "chain-angular-5.toml").read_text(encoding="utf-8")))
    two = solve_chain(parse_chain((EXAMPLES / "chain-angular-6.toml").read_text(encoding="utf-8")))
    # the article's conclusion: one key joint instead of two halves the tooth-direction error
    assert two.worst_case.tolerance == pytest.approx(2 * one.worst_case.tolerance)
    assert len(one.chain.links) == 4 and len(two.chain.links) == 9
    assert one.chain.angular and one.chain.units == "arcmin"


@settings(max_examples=50, deadline=None)
@given(st.lists(st.tuples(st.floats(0, 500), st.floats(-1, 1), st.floats(0, 1), st.sampled_from("+-"),
                          st.sampled_from(["normal", "triangle", "uniform"])), min_size=1, max_size=12),
       st.floats(0.01, 20))
def test_properties(links, risk):
    text = toml(*({"name": f"L{i}", "nominal": a, "es": ei + t, "ei": ei, "sign": s, "distribution": d}
                  for i, (a, ei, t, s, d) in enumerate(links)))
    res = solve_chain(parse_chain(text), risk)
    w, p = res.worst_case, res.probabilistic
    total = sum(t for _, _, t, _, _ in links)
    assert mm(w.tolerance) == pytest.approx(total, abs=1e-9)
    assert w.min <= res.nominal + p.middle <= w.max or math.isclose(w.min, w.max, abs_tol=1e-12)
    # reversing every direction mirrors the closing link
    flipped = text.replace('sign = "+"', 'sign = "x"').replace('sign = "-"', 'sign = "+"').replace('sign = "x"',
                                                                                                  'sign = "-"')
    back = solve_chain(parse_chain(flipped), risk)
    assert back.nominal == pytest.approx(-res.nominal, abs=1e-12)
    assert back.worst_case.es == pytest.approx(-w.ei, abs=1e-12)
    assert back.probabilistic.tolerance == pytest.approx(p.tolerance, abs=1e-12)


GOOD = THREE


@pytest.mark.parametrize("text, words", [
    ('name = "x"\n', "has no links"),
    ("", "has no links"),
    ("[[link\n", "not valid TOML"),
    ('name = "x"\ncolour = 3\n', "unknown key 'colour'"),
    ('units = "inch"\n' + GOOD.split("\n", 1)[1], "units is 'inch'"),
    (GOOD.replace('sign = "-"', 'sign = "minus"', 1), "sign is 'minus'"),
    (GOOD.replace('sign = "+"\n', "", 1), "sign is None"),
    (GOOD.replace("es = 0.1", "es = -0.2"), "es = -0.2 is below ei = -0.1"),
    (GOOD.replace("nominal = 40.0", "nominal = -40.0"), "nominal is -40"),
    (GOOD.replace("nominal = 40.0", "nominal = nan"), "give a finite number"),
    (GOOD.replace("nominal = 40.0", "nominal = inf"), "give a finite number"),
    (GOOD.replace("nominal = 40.0", 'nominal = "40"'), "nominal is '40'; give a number"),
    (GOOD.replace("nominal = 40.0\n", ""), "nominal is missing"),
    (GOOD.replace('name = "B"', 'name = "A"'), "used twice"),
    (GOOD.replace('name = "B"\n', ""), "has no name"),
    (GOOD.replace("es = 0.0\n", "es = 0.0\ntol = 1\n"), "unknown key 'tol'"),
    (GOOD + 'distribution = "gauss"\n', "distribution is 'gauss'"),
    (GOOD + "asymmetry = 1.5\n", "asymmetry is 1.5"),
    (GOOD + "clearance = 0.02\nlength = 40\n", "set the chain's units to an angle"),
    ('units = "deg"\n[[link]]\nname = "b"\nclearance = 0.02\nsign = "+"\n', "length is missing"),
    ('units = "deg"\n[[link]]\nname = "b"\nclearance = 0.0\nlength = 40\nsign = "+"\n', "must be positive"),
    ('units = "deg"\n[[link]]\nname = "b"\nclearance = 50\nlength = 40\nsign = "+"\n', "not smaller than the length"),
    ('units = "deg"\n[[link]]\nname = "b"\nclearance = 0.02\nlength = 40\nnominal = 0\nsign = "+"\n', "not both"),
    ('[link]\nname = "A"\n', "not [link]"),
    ("x = '" + "a" * 300000 + "'", "larger than"),
    ("\n".join(f'[[link]]\nname = "L{i}"\nnominal = 1\nes = 0\nei = 0\nsign = "+"' for i in range(201)), "201 links"),
])
def test_bad_chains(text, words):
    with pytest.raises(TmmError) as info:
        parse_chain(text)
    assert words in str(info.value)
    assert "\n" not in str(info.value).strip() or "TOML" in str(info.value)


@pytest.mark.parametrize("risk", [0.0, -1.0, 60.0, float("nan"), float("inf")])
def test_bad_risk(risk):
    with pytest.raises(TmmError, match="--risk is"):
        solve_chain(parse_chain(THREE), risk)
