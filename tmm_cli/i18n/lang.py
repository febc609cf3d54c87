"""Language choice and the one place where notes become sentences (ru / en)."""

from __future__ import annotations

import locale
import os
import re

from ..notes import Note
from . import tr

LANGS = ("ru", "en")


def default_lang() -> str:
    """'ru' when the locale says Russian (LANG/LC_ALL/LC_MESSAGES ru_*), else 'en'."""
    for var in ("LC_ALL", "LC_MESSAGES", "LANG", "LANGUAGE"):
        val = os.environ.get(var, "")
        if val:
            return "ru" if val.lower().startswith("ru") else "en"
    try:
        loc = locale.getlocale()[0] or ""
    except ValueError:  # pragma: no cover - exotic locale strings
        loc = ""
    return "ru" if loc.lower().startswith("ru") else "en"


_CATALOGUE: dict[str, str] = {}


def _catalogue() -> dict[str, str]:
    """Every note's sentence (code -> English msgid, the messages_* modules), gathered once."""
    if not _CATALOGUE:
        from importlib import import_module
        from pathlib import Path

        for path in sorted(Path(__file__).parent.glob("messages_*.py")):
            _CATALOGUE.update(import_module(f"{__package__}.{path.stem}").MESSAGES)
    return _CATALOGUE


_NUMBER = re.compile(r"[+-]?\d+\.\d+")


class _Number(float):
    """A float parameter of a note that formats itself for the reader (decimal comma under ru)."""

    lang = "en"

    def __format__(self, spec: str) -> str:
        text = format(float(self), spec)
        return _reader_number(text, self.lang)


def _reader_number(text: str, lang: str) -> str:
    """"-0.00" → "0.00" (a value rounded to zero has no sign); "2.85" → "2,85" under ru."""
    if re.fullmatch(r"[+-]0(\.0*)?", text):
        text = text[1:]
    return text.replace(".", ",") if lang == "ru" else text


def _param(value, lang: str):
    if isinstance(value, float) and not isinstance(value, bool):
        num = _Number(value)
        num.lang = lang
        return num
    if isinstance(value, str) and _NUMBER.fullmatch(value):
        return _reader_number(value, lang)
    return value


def note_text(note: Note, lang: str) -> str:
    """The sentence for a note, formatted with its parameters; falls back to code + params.

    Numeric parameters read as the reader writes them: "2,85" under ru, never "-0.00".
    """
    entry = _catalogue().get(note.code)
    kwargs = {k: _param(v, lang) for k, v in note.kwargs.items()}
    if entry:
        template = tr(lang, entry)
        try:
            return template.format(**kwargs)
        except (KeyError, IndexError, ValueError):
            pass
    args = ", ".join(f"{k}={v}" for k, v in note.params)
    return f"{note.code}" + (f" ({args})" if args else "")


def _scripts(text: str) -> set[str]:
    """The alphabets `text`'s letters come from: 'cyrillic', 'latin' (others ignored)."""
    out = set()
    for ch in text:
        if "\u0400" <= ch <= "\u04ff":
            out.add("cyrillic")
        elif ch.isascii() and ch.isalpha():
            out.add("latin")
    return out


def name_script_notes(name: str, lang: str) -> tuple[Note, ...]:
    """A warning when a mechanism's `name` (the student's text, printed as given on the sheets and
    in the note) has no letter of the language's alphabet but letters of the other one: a Latin
    name on a Russian note, a Cyrillic one on an English note.

    >>> [n.code for n in name_script_notes("Crank-slider", "ru")]
    ['mechanism_name_script']
    >>> name_script_notes("Механизм ДВС V8", "ru"), name_script_notes("", "ru")
    ((), ())
    """
    have = _scripts(name or "")
    want = "cyrillic" if lang == "ru" else "latin"
    if not have or want in have:
        return ()
    return (Note.make("mechanism_name_script", "warning", name=name),)
