"""`tmm carrier` and `tmm chain` (issue 23): the JSON keys, the files, the languages, and bad input
as one line with nothing written."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from cli_helpers import assert_one_line_error, run, run_json
from tmm_cli.accuracy.card import parse_card
from tmm_cli.accuracy.carrier import fit_carrier

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
CARD = EXAMPLES / "carrier-5.csv"
MISREAD = EXAMPLES / "carrier-5-misread.csv"
BORE_KEYS = {"bore", "y", "z", "y_prime", "z_prime", "radial_um", "tangential_um", "radial_prime_um",
             "tangential_prime_um", "skew_um"}


# ---------------------------------------------------------------------------------------- carrier

def test_carrier_json_has_the_issues_keys_and_the_cores_numbers(tmp_path):
    doc = run_json("carrier", CARD, "--radius", 125, "--out", tmp_path)
    for key in ("bores", "residuals_um", "rms_um", "suspect", "chord_only_tangential_um"):
        assert key in doc, key
    assert len(doc["bores"]) == 5
    for bore in doc["bores"]:
        assert BORE_KEYS <= set(bore)
    fit = fit_carrier(parse_card(CARD.read_text(encoding="utf-8")), 0.125)
    assert [b["radial_um"] for b in doc["bores"]] == pytest.approx([b.radial * 1e6 for b in fit.bores])
    assert [b["y_prime"] for b in doc["bores"]] == pytest.approx([b.y_prime * 1e3 for b in fit.bores])
    assert doc["bores"][0]["z"] == 0.0
    assert doc["chord_only_tangential_um"][0] == 0.0 and len(doc["chord_only_tangential_um"]) == 5
    assert doc["chord_only_tangential_um"][3] == pytest.approx(-103.8, abs=0.05)  # docs/accuracy.md
    assert doc["bores"][3]["tangential_um"] == pytest.approx(-33.1, abs=0.05)
    assert set(doc["residuals_um"]) == {f"{k}{i}" for k in ("R", "R_prime", "h", "h_prime", "s", "e") for i in range(1, 6)}
    assert doc["rms_um"] == pytest.approx(fit.rms * 1e6)
    assert doc["suspect"] == [] and doc["excluded"] == []
    assert all(b["within"] is None for b in doc["bores"])


def test_carrier_files_and_json_agree(tmp_path):
    res = run("carrier", CARD, "--radius", 125, "--out", tmp_path, "--json", "--lang", "en")
    assert res.exit_code == 0, res.output
    folder = tmp_path / "carrier"
    assert sorted(p.name for p in folder.iterdir() if not p.name.startswith(".")) == ["carrier.json", "carrier.png"]
    assert json.loads((folder / "carrier.json").read_text(encoding="utf-8")) == json.loads(res.stdout)


def test_carrier_misread_then_excluded(tmp_path):
    doc = run_json("carrier", MISREAD, "--radius", 125, "--out", tmp_path)
    assert doc["suspect"] == ["h3"]
    assert any("--exclude h3" in n for n in doc["notes"])
    assert doc["residuals_um"]["h3"] > 0 and doc["standardised_residuals"]["h3"] > doc["suspect_threshold"]
    again = run_json("carrier", MISREAD, "--radius", 125, "--exclude", "h3", "--out", tmp_path)
    clean = run_json("carrier", CARD, "--radius", 125, "--out", tmp_path)
    assert again["suspect"] == [] and again["excluded"] == ["h3"]
    assert not any("--exclude" in n for n in again["notes"])
    # without the misread chord the bores are the clean card's, within its uncertainty
    for a, b in zip(again["bores"], clean["bores"]):
        assert a["tangential_um"] == pytest.approx(b["tangential_um"], abs=3 * max(b["u_tangential_um"], 0.1))


def test_carrier_tolerances_give_verdicts(tmp_path):
    doc = run_json("carrier", CARD, "--radius", 125, "--tol-radial", 25, "--tol-tangential", 30, "--out", tmp_path)
    assert [b["within"] for b in doc["bores"]] == [True, False, True, False, True]
    assert doc["tolerances_um"] == {"radial": 25.0, "tangential": 30.0}


def test_carrier_tables_in_russian_and_english(tmp_path):
    ru = run("carrier", MISREAD, "--radius", 125, "--out", tmp_path, "--lang", "ru", "--no-plots")
    assert ru.exit_code == 0, ru.output
    assert "Водило: 5 расточек" in ru.output and "Подозрительные измерения: h3" in ru.output
    assert "-16,1 ±" in ru.output or "-11,5 ±" in ru.output  # decimal commas
    assert "--exclude h3" in ru.output and "реконструкции" in ru.output
    en = run("carrier", CARD, "--radius", 125, "--out", tmp_path, "--lang", "en", "--no-plots")
    assert en.exit_code == 0, en.output
    assert "Planet carrier: 5 bores" in en.output and "No measurement stands out" in en.output
    assert "Водило" not in en.output


def test_carrier_figure_is_drawn(tmp_path):
    from tmm_cli.render.figures.carrier import carrier_figure, magnification, nice_below

    fit = fit_carrier(parse_card(CARD.read_text(encoding="utf-8")), 0.125)
    k, largest = magnification(fit)
    assert k == 1000.0 and 0.2 * 125 <= k * largest * 1e3 <= 0.35 * 125  # a round factor, arrows a fifth of R
    fig = carrier_figure(fit, "ru")
    texts = [t.get_text() for t in fig.axes[0].texts] + [fig.axes[0].get_title()]
    assert any("1000" in t for t in texts) and any("мкм" in t for t in texts)
    assert nice_below(0.00731) == 0.005 and nice_below(3.0) == 2.0


# ------------------------------------------------------------------------------------------ chain

def chain_json(*args):
    """`tmm chain ARGS --json --lang en` (it draws no figure, so has no --no-plots): its document."""
    res = run("chain", *args, "--json", "--lang", "en")
    assert res.exit_code == 0, res.output
    return json.loads(res.stdout)


def test_chain_json_has_the_issues_keys(tmp_path):
    doc = chain_json(EXAMPLES / "chain-radial-1.toml", "--out", tmp_path)
    closing = doc["closing"]
    assert closing["nominal"] == pytest.approx(0.625)
    for method in ("worst_case", "probabilistic"):
        assert {"es", "ei", "tolerance", "max", "min"} <= set(closing[method])
    assert closing["worst_case"]["es"] == 0.282 and closing["worst_case"]["ei"] == -0.0585
    assert closing["probabilistic"]["risk_percent"] == 0.27
    assert closing["probabilistic"]["t"] == pytest.approx(3.0, abs=1e-4)
    assert doc["largest_contributor"] == {"worst_case": "S22", "probabilistic": "S22"}
    assert doc["units"] == "mm" and len(doc["links"]) == 9
    assert (tmp_path / "chain" / "chain-radial-1.json").exists()


def test_chain_risk_option(tmp_path):
    doc = chain_json(EXAMPLES / "chain-angular-5.toml", "--risk", 1, "--out", tmp_path)
    p = doc["closing"]["probabilistic"]
    assert p["risk_percent"] == 1.0 and p["t"] == pytest.approx(2.5758, abs=1e-4)
    beta = doc["links"][3]
    assert beta["beta_from"] == {"clearance_mm": 0.0105, "length_mm": 45.0}
    assert beta["es"] == pytest.approx(math.degrees(math.atan(0.0105 / 45)) * 60)
    assert any("0 ± β" in n for n in doc["notes"])


def test_chain_warns_when_the_probabilistic_method_gives_more(tmp_path):
    one = tmp_path / "one.toml"
    one.write_text('[[link]]\nname = "A"\nnominal = 10\nes = 0.1\nei = 0\nsign = "+"\ndistribution = "uniform"\n',
                   encoding="utf-8")
    doc = chain_json(one, "--out", tmp_path)
    assert doc["probabilistic_exceeds_worst_case"] is True
    assert doc["notes"] == ["The probabilistic tolerance 0.1732 exceeds the worst case 0.1: too few links (or uniform "
                            "ones) for the probabilistic method; take the worst case."]


def test_chain_tables_in_russian(tmp_path):
    res = run("chain", EXAMPLES / "chain-radial-1.toml", "--out", tmp_path, "--lang", "ru")
    assert res.exit_code == 0, res.output
    assert "Замыкающее звено, мм" in res.output and "максимума-минимума" in res.output
    assert "0,625" in res.output and "Наибольший вклад: S22" in res.output


# ------------------------------------------------------------------------------------ bad input

def assert_russian_error(res, *words):
    """Exit 2, one line `tmm: ошибка: …` naming `words`."""
    assert res.exit_code == 2, (res.exit_code, res.output)
    err = res.stderr.strip()
    assert len(err.splitlines()) == 1 and err.startswith("tmm: ошибка: "), err
    for w in words:
        assert w in err, (w, err)


@pytest.mark.parametrize("args, words", [
    (["--radius", 0], "'--radius'"),
    (["--radius", "nan"], "'--radius'"),
    (["--radius", 125, "--tol-radial", -5], "'--tol-radial'"),
    (["--radius", 125, "--exclude", "h9"], "--exclude h9"),
    ([], "--radius"),
])
def test_carrier_bad_options(tmp_path, args, words):
    res = run("carrier", CARD, *args, "--out", tmp_path / "o", "--lang", "en")
    assert_one_line_error(res, words)
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("text, words", [
    ("bore,R,R_prime,h,h_prime,s\n1,125,125,216.5,216.5,0\n2,125,125,216.5,216.5,0\n", "2 bore rows"),
    ("bore,R,R_prime,h,h_prime\n1,125,125,216.5,216.5\n", "column 's' is missing"),
    ("bore,R,R_prime,h,h_prime,s\n1,125,125,260,216.5,0\n2,125,125,216.5,216.5,0\n3,125,125,216.5,216.5,0\n",
     "longer than R1 + R3"),
    ("bore,R,R_prime,h,h_prime,s\n1,-125,125,216.5,216.5,0\n2,125,125,216.5,216.5,0\n3,125,125,216.5,216.5,0\n",
     "must be positive"),
    ("bore,R,R_prime,h,h_prime,s\n1,inf,125,216.5,216.5,0\n2,125,125,216.5,216.5,0\n3,125,125,216.5,216.5,0\n",
     "not a number"),
])
def test_bad_cards_one_line_nothing_written(tmp_path, text, words):
    card = tmp_path / "card.csv"
    card.write_text(text, encoding="utf-8")
    res = run("carrier", card, "--radius", 125, "--out", tmp_path / "o", "--lang", "en")
    assert_one_line_error(res, words)
    assert not (tmp_path / "o").exists()


def test_bad_card_in_russian(tmp_path):
    card = tmp_path / "card.csv"
    card.write_text("bore,R,R_prime,h,h_prime,s\n1,125,125,260,216.5,0\n2,125,125,216.5,216.5,0\n"
                    "3,125,125,216.5,216.5,0\n", encoding="utf-8")
    res = run("carrier", card, "--radius", 125, "--out", tmp_path / "o", "--lang", "ru")
    assert_russian_error(res, "расточка 1: h = 260 мм, больше R1 + R3 = 250 мм (хорда не длиннее диаметра)")
    missing = run("carrier", tmp_path / "none.csv", "--radius", 125, "--out", tmp_path / "o", "--lang", "ru")
    assert_russian_error(missing, "не существует")
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("text, words", [
    ('name = "x"\n', "has no links"),
    ('[[link]]\nname = "A"\nnominal = 1\nes = 0\nei = 0.1\nsign = "+"\n', "es = 0 is below ei = 0.1"),
    ('[[link]]\nname = "A"\nnominal = 1\nes = 0.1\nei = 0\nsign = "*"\n', "sign is '*'"),
    ("[[link\n", "not valid TOML"),
])
def test_bad_chains_one_line_nothing_written(tmp_path, text, words):
    chain = tmp_path / "c.toml"
    chain.write_text(text, encoding="utf-8")
    res = run("chain", chain, "--out", tmp_path / "o", "--lang", "en")
    assert_one_line_error(res, words)
    assert not (tmp_path / "o").exists()


def test_bad_chain_in_russian_and_bad_risk(tmp_path):
    chain = tmp_path / "c.toml"
    chain.write_text('[[link]]\nname = "A"\nnominal = 1\nes = 0\nei = 0.1\nsign = "+"\n', encoding="utf-8")
    res = run("chain", chain, "--out", tmp_path / "o", "--lang", "ru")
    assert_russian_error(res, "звено 1 ('A'): es = 0 меньше ei = 0,1")  # decimal commas in Russian (issue 33, B10)
    risk = run("chain", EXAMPLES / "chain-radial-1.toml", "--risk", 0, "--out", tmp_path / "o", "--lang", "ru")
    assert_russian_error(risk, "'--risk'", "вне допустимого диапазона")
    assert not (tmp_path / "o").exists()
