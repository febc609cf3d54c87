"""The command line in the reader's language: every command's and option's help, click's own
messages and metavars, from the catalogue (the English help is the msgid; click's messages are
msgids under the context ``click``).

Imported only under ``--lang ru`` / a Russian locale, so ``tmm --help`` in English pays nothing.
"""

from __future__ import annotations

import inspect
import re
from contextlib import contextmanager

from . import tr, translations


def _command_help(lang: str, help_text: str | None) -> str | None:
    if not help_text:
        return help_text
    return tr(lang, inspect.cleandoc(help_text))


class _DefaultWithComma(str):
    """"по умолчанию: {default}" whose number takes a decimal comma (click formats the default as
    ``str(5.0)``): ``[по умолчанию: 5,0]``."""

    def format(self, *args, **kwargs):
        kwargs = {k: re.sub(r"(?<=\d)\.(?=\d)", ",", v) if isinstance(v, str) else v for k, v in kwargs.items()}
        return str.format(self, *args, **kwargs)


def _click_gettext(lang: str):
    catalogue = translations(lang)

    def gettext(message: str) -> str:
        text = catalogue.pgettext("click", message)
        return _DefaultWithComma(text) if message == "default: {default}" else text

    def ngettext(singular: str, plural: str, n: int) -> str:
        # click's messages count like English (one, or several): the catalogue's "one" and "many" forms
        return catalogue.npgettext("click", singular, plural, 1 if n == 1 else 5)

    return gettext, ngettext


def _version_callback(lang: str):
    def version(ctx, param, value):
        """`tmm --version` in the reader's language (click's message is fixed when the option is
        declared)."""
        if not value or ctx.resilient_parsing:
            return
        from importlib.metadata import version as installed

        import click

        click.echo(translations(lang).pgettext("click", "%(prog)s, version %(version)s")
                   % {"prog": "tmm", "version": installed("tmm")})
        ctx.exit()

    return version


def _commands(cmd, path: str):
    yield path, cmd
    for name, sub in getattr(cmd, "commands", {}).items():
        yield from _commands(sub, f"{path} {name}")


@contextmanager
def translated(cli, lang: str):
    """Within the block, `cli`'s help texts and click's messages are in `lang`; afterwards English
    again (tests run many commands in one process)."""
    import click.core
    import click.decorators
    import click.exceptions
    import click.formatting
    import click.parser
    import click.types
    import click.utils

    saved: list[tuple[object, str, object]] = []

    def put(obj, attr, value):
        saved.append((obj, attr, getattr(obj, attr)))
        setattr(obj, attr, value)

    catalogue = translations(lang)
    for _path, cmd in _commands(cli, "tmm"):
        put(cmd, "help", _command_help(lang, cmd.help))
        put(cmd, "short_help", None)
        for attr in ("options_metavar", "subcommand_metavar"):
            value = getattr(cmd, attr, None)
            if value:
                put(cmd, attr, catalogue.pgettext("click", value))
        # click caches the -h/--help option of a command: never let a translated one outlive the block
        cached = getattr(cmd, "_help_option", None)
        saved.append((cmd, "_help_option", cached))
        if cached is not None and cached.help:  # click's own option: its help is click's msgid
            put(cached, "help", catalogue.pgettext("click", cached.help))
        for param in cmd.params:
            if param.name == "version" and getattr(param, "is_flag", False):
                put(param, "callback", _version_callback(lang))
            if getattr(param, "help", None):
                put(param, "help", tr(lang, param.help))
    gettext, ngettext = _click_gettext(lang)
    modules = (click.core, click.decorators, click.exceptions, click.formatting, click.parser, click.types,
               click.utils)
    for m in modules:
        for name, fn in (("_", gettext), ("ngettext", ngettext)):
            if hasattr(m, name):
                put(m, name, fn)
    try:
        yield
    finally:
        for obj, attr, value in reversed(saved):
            setattr(obj, attr, value)
