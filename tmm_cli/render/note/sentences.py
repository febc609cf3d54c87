"""The run's notes (assumptions, warnings) as sentences of the note: no command-line syntax,
real subscripts, decimal commas under ru.

The sentences come from the message catalogues through :func:`~tmm_cli.i18n.lang.note_text`;
they are written for the terminal, so some carry a hint such as "(--torque)". A few are replaced
here by wording for a document; in the rest the hints are dropped.
"""

from __future__ import annotations

import re

from ...i18n.lang import note_text

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
_SYMBOL = re.compile(r"(?<![A-Za-zА-Яа-яёα-ωΑ-Ω])([A-Za-zА-Яа-яα-ωΑ-Ω])_([A-Za-zА-Яа-яёα-ω0-9′]+(?:\.[A-Za-zа-я]+)*)(\*?)")
_NUMBER = re.compile(r"(?<![\d.])\d+(?:\.\d+)+(?![\d])")
_REFWORD = re.compile(r"(п\.|§|табл\.|рис\.|Table|Fig\.|Figure|section|item)\s*$")


def _decimal_commas(text: str) -> str:
    """1.25 → 1,25 in numbers, but not in references: п. 2.4, табл. 1.1, (1.28), §1.3.1."""
    def fix(m: re.Match) -> str:
        s = m.group(0)
        if s.count(".") > 1 or _REFWORD.search(text[:m.start()]):
            return s
        before, after = text[m.start() - 1:m.start()], text[m.end():m.end() + 1]
        if re.fullmatch(r"[12]\.\d{1,2}", s) and (before in "(–" and after in ")–,"):
            return s  # an equation number (1.9), (1.9)–(1.18)
        return s.replace(".", ",")

    return _NUMBER.sub(fix, text)


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

    >>> for_note("Задайте момент M (--torque), r_0 = 12.50 мм (1.28), n_кр и 2h_a*", "ru")
    'Задайте момент M, $r_0$ = 12,50 мм (1.28), $n_("кр")$ и 2$h_a^*$'
    >>> for_note("(149.3 × 132.9 мм), п. 1.3.1, табл. 1.1, (1.9)–(1.18), x ≥ 0.0057), -2.85 %", "ru")
    '(149,3 × 132,9 мм), п. 1.3.1, табл. 1.1, (1.9)–(1.18), x ≥ 0,0057), −2,85 %'
    """
    text = _HINT.sub("", text)
    text = _FLAG.sub(lambda m: m.group(1).replace("-", " "), text)
    if lang == "ru":
        text = _decimal_commas(text)
    text = re.sub(r"(?<![\w−-])-(?=\d)", "−", text)
    text = re.sub(r"\(\s*[−+]?0([,.])00 %\)", lambda m: f"(< 0{m.group(1)}01 %)", text)
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
