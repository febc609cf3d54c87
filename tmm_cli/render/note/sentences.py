"""The run's notes (assumptions, warnings) as sentences of the note: no command-line syntax,
real subscripts, decimal commas under ru.

The sentences come from the message catalogues through :func:`~tmm_cli.render.i18n.note_text`;
they are written for the terminal, so some carry a hint such as "(--torque)". A few are replaced
here by wording for a document; in the rest the hints are dropped.
"""

from __future__ import annotations

import re

from ..i18n import note_text

# sentences that ask the user to do something at the terminal, reworded for a document
_FOR_NOTE = {
    "crank_default": {
        "en": "The crank speed of the linkage is taken as n_cr = {rpm:g} rpm, the textbook's own example (§2.2, §2.4); "
              "it should be replaced by the crank speed of sheet 1.",
        "ru": "Частота вращения кривошипа принята n_кр = {rpm:g} об/мин, как в примере пособия (п. 2.2, 2.4); "
              "её следует заменить частотой вращения кривошипа по 1-му листу проекта.",
    },
    "efficiency": {
        "en": "Efficiencies for the motor power (§2.6): η1 = {eta1} for scheme {scheme} (0.96 per single- or double-row "
              "stage; two stages 0.96²), η2 = {eta2} for the linkage.",
        "ru": "КПД для расчёта мощности двигателя (п. 2.6): η1 = {eta1} для схемы {scheme} (0,96 на однорядную или "
              "двухрядную ступень; две ступени — 0,96²), η2 = {eta2} для рычажного механизма.",
    },
}

_HINT = re.compile(r"\s*\((?:[^()]*?)--[a-z][^()]*\)")
_FLAG = re.compile(r"--([a-z][a-z-]*)")
_SYMBOL = re.compile(r"(?<![A-Za-zА-Яа-яёα-ωΑ-Ω0-9])([A-Za-zА-Яа-яα-ωΑ-Ω])_([A-Za-zА-Яа-яёα-ω0-9′]+(?:\.[A-Za-zа-я]+)*)(\*?)")
# a decimal point in a number, not in a section, table, figure or equation reference
_DECIMAL = re.compile(r"(?<!п\. )(?<!§)(?<!табл\. )(?<!рис\. )(?<!Table )(?<!Fig\. )(?<![\d.(])(\d+)\.(\d+)(?![\d.)])")


def _sub(m: re.Match) -> str:
    base, sub, star = m.group(1), m.group(2), m.group(3)
    if len(sub) == 1 and not re.match(r"[А-Яа-яё]", sub):
        body = f"{base}_{sub}"
    else:
        body = f'{base}_("{sub}")'
    if star:
        body += "^*"
    return f"${body}$"


def for_note(text: str, lang: str) -> str:
    """A terminal sentence made fit for the note (mini markup: plain text with $math$).

    >>> for_note("Задайте момент M (--torque), r_0 = 12.50 мм (1.28), n_кр и h_a*", "ru")
    'Задайте момент M, $r_0$ = 12,50 мм (1.28), $n_("кр")$ и $h_a^*$'
    """
    text = _HINT.sub("", text)
    text = _FLAG.sub(lambda m: m.group(1).replace("-", " "), text)
    if lang == "ru":
        text = _DECIMAL.sub(r"\1,\2", text)
    text = _SYMBOL.sub(_sub, text)
    parts = re.split(r"(\$[^$]*\$)", text)
    return "".join(p if p.startswith("$") else p.replace("_", " ") for p in parts)


def note_sentence(note, lang: str) -> str:
    """The sentence of a Note for the note (mini markup)."""
    entry = _FOR_NOTE.get(note.code)
    if entry:
        try:
            return for_note(entry[lang if lang in entry else "en"].format(**note.kwargs), lang)
        except (KeyError, IndexError, ValueError):
            pass
    return for_note(note_text(note, lang), lang)
