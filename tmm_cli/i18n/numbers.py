"""Numbers and counts as a reader of the chosen language expects them (ru: decimal comma).

One place for every number that a person reads: the terminal, figures, text files, the drawing
sheets and the note. JSON keeps plain numbers and never comes through here.

The decimal sign and the plural rules come from CLDR through Babel (imported lazily);
significant digits and the ``·10⁻⁵`` form of very small and very large numbers are ours.
"""

from __future__ import annotations

import math
from functools import lru_cache

_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


@lru_cache(maxsize=4)
def _locale(lang: str):
    from babel import Locale

    return Locale.parse("ru" if lang == "ru" else "en")


# CLDR's decimal symbols of our two languages, as Babel gives them (tests/test_i18n_numbers.py
# checks they still agree): loading Babel's locale data costs 30–100 ms, a third of a whole
# `tmm project --json` run, for one character. Other languages still ask Babel.
DECIMAL_SIGN = {"ru": ",", "en": "."}


@lru_cache(maxsize=4)
def _decimal_sign(lang: str) -> str:
    if lang in DECIMAL_SIGN:
        return DECIMAL_SIGN[lang]
    from babel.numbers import get_decimal_symbol

    return get_decimal_symbol(_locale(lang))


def num(x, lang: str, decimals: int | None = None, sig: int = 4, sci: bool = True, minus: str = "-") -> str:
    """`x` as text for a reader of `lang`.

    With `decimals`, a fixed number of decimals; otherwise `sig` significant digits with trailing
    zeros dropped. Magnitudes below 1e-3 or from 1e6 up take the form ``9,42·10⁻⁵`` unless
    `sci` is False. Non-finite values read "—". `minus` is the sign used for negatives (the note
    and the sheets pass the typographic "−").

    >>> num(0.875, "ru")
    '0,875'
    >>> num(9.4246e-05, "ru", sig=3)
    '9,42·10⁻⁵'
    >>> num(-20.6512, "en", decimals=2)
    '-20.65'
    >>> num(48.0, "ru", sig=4)
    '48'
    >>> num(12345.678, "ru", decimals=1)
    '12345,7'
    """
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "—"
    if isinstance(x, bool):
        x = int(x)
    if isinstance(x, int) and decimals is None:
        text = str(abs(x))
        return (minus if x < 0 else "") + text
    x = float(x)
    ax = abs(x)
    if decimals is None and sci and ax != 0.0 and (ax < 1e-3 or ax >= 1e6):
        exp = int(math.floor(math.log10(ax)))
        mant = ax / 10 ** exp
        if round(mant, sig - 1) >= 10:
            mant, exp = mant / 10, exp + 1
        body = _fixed(mant, sig - 1, lang, strip=True)
        return (minus if x < 0 else "") + f"{body}·10{str(exp).translate(_SUPERSCRIPT)}"
    if decimals is None:
        if ax == 0.0:
            return "0"
        decimals = max(0, sig - 1 - int(math.floor(math.log10(ax))))
        body = _fixed(ax, decimals, lang, strip=True)
    else:
        body = _fixed(ax, decimals, lang, strip=False)
    if set(body) <= set("0,."):  # rounded to zero: no "-0,00"
        return body
    return (minus if x < 0 else "") + body


def small_pct(x: float, lang: str, minus: str = "−") -> str:
    """A difference in % to the digits it has, with its relation: two decimals from 0,1 % up, else
    two significant digits (no «0,00 %» for 0,0042 %); below 10⁻⁹ % — a computer's rounding, not a
    value — «< 10⁻⁹»; exactly 0 «= 0» (the note's :meth:`Ctx.pct_digits` keeps the same rule).

    >>> small_pct(-0.0042, "ru"), small_pct(0.4567, "ru"), small_pct(0.0, "ru"), small_pct(1.2e-14, "ru")
    ('= −0,0042', '= 0,46', '= 0', '< 10⁻⁹')
    """
    x = float(x)
    a = abs(x)
    if a == 0.0:
        return "= 0"
    if a < 1e-9:
        return "< 10⁻⁹"
    return "= " + num(x, lang, decimals=2 if a >= 0.1 else 1 - math.floor(math.log10(a)), minus=minus)


def _fixed(ax: float, decimals: int, lang: str, strip: bool) -> str:
    text = f"{ax:.{decimals}f}"
    if strip and "." in text:
        text = text.rstrip("0").rstrip(".")
    return text.replace(".", _decimal_sign(lang))


# CLDR's plural rules of our two languages, as Babel's locale data gives them (the test
# tests/test_i18n_numbers.py checks they still agree), evaluated by Babel's own rule engine: this
# spares the 30–150 ms of loading the locale data for two short rules. Other languages ask Babel.
PLURAL_RULES = {
    "ru": {"few": "v in 0 and i mod 10 in 2..4 and i mod 100 not in 12..14",
           "many": "v in 0 and i mod 10 in 0 or v in 0 and i mod 10 in 5..9 or v in 0 and i mod 100 in 11..14",
           "one": "v in 0 and i mod 10 in 1 and i mod 100 not in 11"},
    "en": {"one": "i in 1 and v in 0"},
}


@lru_cache(maxsize=4)
def _plural_rule(lang: str):
    if lang in PLURAL_RULES:
        from babel.plural import PluralRule

        return PluralRule(PLURAL_RULES[lang])
    return _locale(lang).plural_form


def plural_category(n: int, lang: str) -> str:
    """CLDR plural category of `n` ('one', 'few', 'many', 'other').

    >>> [plural_category(n, "ru") for n in (1, 3, 5, 21, 183, 201)]
    ['one', 'few', 'many', 'one', 'few', 'one']
    """
    return _plural_rule(lang)(abs(int(n)))


def plural(n: int, lang: str, forms: dict[str, str]) -> str:
    """"183 варианта": `n` and the noun form CLDR's plural rule of `lang` picks from `forms`.

    `forms` maps categories to words; a missing category falls back to 'other', then 'many'.

    >>> forms = {"one": "вариант", "few": "варианта", "many": "вариантов"}
    >>> [plural(n, "ru", forms) for n in (183, 201, 5)]
    ['183 варианта', '201 вариант', '5 вариантов']
    >>> plural(2, "en", {"one": "variant", "other": "variants"})
    '2 variants'
    """
    cat = plural_category(n, lang)
    word = forms.get(cat) or forms.get("other") or forms.get("many") or next(iter(forms.values()))
    return f"{n} {word}"
