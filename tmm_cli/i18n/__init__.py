"""Every user-facing string through gettext: the English text is the msgid, the Russian lives in
``i18n/locale/ru/LC_MESSAGES/tmm.po`` (compiled to ``tmm.mo`` beside it, committed; a test checks it
is current and complete — ``python tools/catalog.py`` extracts, merges and compiles).

    >>> tr("ru", "Value"), tr("en", "Value")
    ('Значение', 'Value')
    >>> ntr("ru", "{teeth}, k = {planets} planet", "{teeth}, k = {planets} planets", 3).format(teeth="38/24/86", planets=3)
    '38/24/86, k = 3 сателлита'

Only the standard library's gettext is loaded at run time (Babel is for building the catalogue).
"""

from __future__ import annotations

import gettext
from functools import cache
from pathlib import Path

LOCALE_DIR = Path(__file__).resolve().parent / "locale"
DOMAIN = "tmm"


@cache
def translations(lang: str) -> gettext.NullTranslations:
    """The compiled catalogue of `lang` (English is the msgids themselves)."""
    if lang == "en":
        return gettext.NullTranslations()
    with open(LOCALE_DIR / lang / "LC_MESSAGES" / f"{DOMAIN}.mo", "rb") as f:
        return gettext.GNUTranslations(f)


def tr(lang: str, msgid: str) -> str:
    """`msgid` (English) in `lang`."""
    return msgid if lang == "en" else translations(lang).gettext(msgid)


def trc(lang: str, context: str, msgid: str) -> str:
    """`msgid` in `lang` where the same English has another translation elsewhere (msgctxt)."""
    return msgid if lang == "en" else translations(lang).pgettext(context, msgid)


def ntr(lang: str, singular: str, plural: str, n: int) -> str:
    """The form of `singular`/`plural` for the count `n` by the plural rule of `lang`."""
    if lang == "en":
        return singular if n == 1 else plural
    return translations(lang).ngettext(singular, plural, abs(int(n)))


def N_(msgid: str) -> str:
    """Marks a msgid kept in a table for translation later (gettext_noop)."""
    return msgid
