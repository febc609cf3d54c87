"""Numbers and counts for a reader: CLDR (Babel) decides the decimal sign and the plural forms."""

import pytest
from babel import Locale
from babel.numbers import get_decimal_symbol

from tmm_cli.i18n.numbers import DECIMAL_SIGN, PLURAL_RULES, num, plural, plural_category
from tmm_cli.i18n.lang import note_text
from tmm_cli.notes import Note

VARIANTS = {"one": "вариант", "few": "варианта", "many": "вариантов"}


def test_decimal_signs_are_cldr_s():
    for lang, sign in DECIMAL_SIGN.items():
        assert get_decimal_symbol(Locale.parse(lang)) == sign


def test_plural_rules_are_cldr_s():
    """The embedded rules are Babel's locale data, and pick the same category for 0 … 2000."""
    for lang, rules in PLURAL_RULES.items():
        cldr = Locale.parse(lang).plural_form
        assert cldr.rules == rules
        assert all(plural_category(n, lang) == cldr(n) for n in range(2001))


@pytest.mark.parametrize("n,word", [(1, "вариант"), (2, "варианта"), (5, "вариантов"), (11, "вариантов"),
                                    (21, "вариант"), (22, "варианта"), (68, "вариантов"), (101, "вариант"),
                                    (111, "вариантов"), (183, "варианта"), (201, "вариант")])
def test_russian_plural_for_every_count(n, word):
    assert plural(n, "ru", VARIANTS) == f"{n} {word}"


def test_small_numbers_and_signed_zero():
    assert num(9.4246e-05, "ru", sig=3) == "9,42·10⁻⁵"
    assert num(-0.001, "ru", decimals=2) == "0,00"
    assert num(25.0, "ru", decimals=2) == "25,00"


def test_note_numbers_follow_the_reader():
    note = Note.make("ratio_error", "warning", i="3.1795", target="3.2727", err="-0.00", tol="5", rpm="226.5", want="220")
    ru = note_text(note, "ru")
    assert "3,1795" in ru and "(0,00 %" in ru and "-0" not in ru
    en = note_text(note, "en")
    assert "3.1795" in en and "(0.00 %" in en


def test_pressure_angle_at_its_limit_shows_the_third_decimal():
    from tmm_cli.render.terminal.cam import _nu

    assert _nu("ru", 25.001, 25) == "25,001"
    assert _nu("ru", 25.0, 25) == "25,00"
    assert _nu("en", 24.5, 25) == "24.50"


def test_percent_error_never_minus_zero():
    from tmm_cli.render.figures.gears import percent
    from tmm_cli.render.terminal.gears import _pct

    assert _pct("en", -0.001) == "0.00" and _pct("ru", 1.254) == "+1,25" and _pct("ru", -2.85) == "-2,85"
    assert percent(-0.001, "ru") == "0,00 %" and percent(-2.85, "ru") == "−2,85 %"


def test_ratios_in_the_table_are_the_json_magnitudes():
    import io

    from rich.console import Console

    from tmm_cli.gears.design import design_gears
    from tmm_cli.render.data.gears import gears_to_json
    from tmm_cli.render.terminal.gears import print_gears

    r = design_gears(-1000, crank_rpm=220)
    doc = gears_to_json(r, "en")
    c = Console(width=200, file=io.StringIO(), record=True, color_system=None)
    print_gears(c, r, "en")
    text = c.export_text()
    i_actual = doc["spur"]["i_actual"]
    assert i_actual > 0 and f"{i_actual:.4f} (z2/z1)" in text
    assert f"{doc['planetary']['ratio']:.4f}" in text and "-0.7" not in text
