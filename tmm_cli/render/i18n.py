"""Language choice and the one place where notes become sentences (ru / en)."""

from __future__ import annotations

import locale
import os

from ..notes import Note

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


def pick(lang: str, en: str, ru: str) -> str:
    """The label in the chosen language: ``pick(lang, "Base radius", "Минимальный радиус")``."""
    return ru if lang == "ru" else en


def _catalogue() -> dict[str, dict[str, str]]:
    merged: dict[str, dict[str, str]] = {}
    for mod in ("messages_cam", "messages_gears", "messages_project", "messages_linkage", "messages_shifted"):
        try:
            module = __import__(f"tmm_cli.render.{mod}", fromlist=["MESSAGES"])
        except ImportError:
            continue
        merged.update(getattr(module, "MESSAGES", {}))
    return merged


def note_text(note: Note, lang: str) -> str:
    """The sentence for a note, formatted with its parameters; falls back to code + params."""
    entry = _catalogue().get(note.code)
    kwargs = note.kwargs
    if entry:
        template = entry.get(lang) or entry.get("en")
        try:
            return template.format(**kwargs)
        except (KeyError, IndexError, ValueError):
            pass
    args = ", ".join(f"{k}={v}" for k, v in note.params)
    return f"{note.code}" + (f" ({args})" if args else "")
