"""Build the translation catalogue (a developer's tool; Babel does the work).

    python tools/catalog.py            # extract the msgids, merge them into tmm.po, compile tmm.mo
    python tools/catalog.py --check    # exit 1 if tmm.po or tmm.mo is not current or incomplete

The msgids come from the code (``tr(lang, MSGID)``, ``trc(lang, CTX, MSGID)``, ``ntr(lang,
SINGULAR, PLURAL, n)``, ``N_(MSGID)``; the note's ``t``, ``tc``, ``nt``) and from the command line
itself (every command's help and every option's help, read from the click tree). A translator edits
only ``tmm.po``; new msgids arrive in it untranslated and the check (run by the tests) names them.

The code's msgids are read by our own walk over Python's syntax tree (``calls_in``), not by Babel's
extractor: Babel's is a tokenizer that guesses calls, and its guesses change between releases (2.19
took the subscript ``t["link"]`` for a call of ``t`` and glued two docstrings into one msgid), so
the same code gave two catalogues. The syntax tree says exactly which calls there are, on every
Python and every Babel. Babel still reads, merges, writes and compiles the catalogue. The .po is
written sorted by msgid with file-only locations, so a change of code moves no other message (and
two branches that add messages rarely touch the same lines).
"""

from __future__ import annotations

import ast
import io
import sys
from pathlib import Path

from tmm_cli.i18n import DOMAIN, LOCALE_DIR

PACKAGE = Path(__file__).resolve().parents[1] / "tmm_cli"
# t, tc, nt: the note's Ctx.t(msgid), Ctx.tc(context, msgid), Ctx.nt(singular, plural, n) (its language is the Ctx's)
KEYWORDS = {"tr": (2,), "trc": ((2, "c"), 3), "ntr": (2, 3), "N_": None, "t": (1,), "tc": ((1, "c"), 2), "nt": (1, 2)}
# Kept by hand, not extracted: "error" — our error messages as templates ("{p} does not exist; …"): they
# are f-strings at the raise sites, matched against these at the edge (i18n/errors.py; the tests check
# that every raise site has one); "click" — click's own messages (its msgids); "system" — the
# operating system's reasons (strerror); "place" — the places errors name ("answers file {p}").
KEPT_CONTEXTS = ("error", "click", "system", "place")
LANGS = ("ru",)
FIXED_DATE = __import__("datetime").datetime(2026, 1, 1, tzinfo=__import__("datetime").timezone.utc)
HEADER = "Translations of tmm, the TMM course-project calculator. The English text is the msgid."


def po_path(lang: str) -> Path:
    return LOCALE_DIR / lang / "LC_MESSAGES" / f"{DOMAIN}.po"


def mo_path(lang: str) -> Path:
    return po_path(lang).with_suffix(".mo")


def _literal(node) -> str | None:
    """The text of a string literal (implicit concatenation included; an f-string only when it has no
    substitution, as gettext would see it), else None."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.JoinedStr) and all(isinstance(v, ast.Constant) for v in node.values):
        return "".join(v.value for v in node.values)
    return None


def calls_in(source: str):
    r"""(line, message, context) of every translation call in a module's source: a call — a name or
    an attribute (``c.t``) — named as a key of KEYWORDS, whose message arguments are string literals.
    A subscript (``t["link"]``), a call with a variable for its msgid, a docstring are not messages.

    >>> src = 'tr(lang, "Value")\nt["link"]\nc.t("Stroke")\ntrc(lang, "column", "Scheme")\n'
    >>> src += 'ntr(lang, "{n} tooth", "{n} teeth", n)\ntr(lang, name)\n"a docstring"\nt(1)\n'
    >>> list(calls_in(src))
    [(1, 'Value', None), (3, 'Stroke', None), (4, 'Scheme', 'column'), (5, ('{n} tooth', '{n} teeth'), None)]
    """
    found = []
    for node in ast.walk(ast.parse(source)):
        if not isinstance(node, ast.Call):
            continue
        func = node.func
        name = func.id if isinstance(func, ast.Name) else func.attr if isinstance(func, ast.Attribute) else None
        if name not in KEYWORDS:
            continue
        context, messages = None, []
        for spec in KEYWORDS[name] or (1,):
            position, is_context = (spec[0], True) if isinstance(spec, tuple) else (spec, False)
            text = _literal(node.args[position - 1]) if len(node.args) >= position else None
            if is_context:
                context = text if text is not None else False
            else:
                messages.append(text)
        if context is False or not messages or any(m is None for m in messages) or not messages[0]:
            continue
        found.append((node.lineno, node.col_offset, messages[0] if len(messages) == 1 else tuple(messages), context))
    return [(line, message, context) for line, _, message, context in sorted(found, key=lambda f: f[:2])]


def extracted():
    """The template catalogue: every msgid the code and the command line use, with their places."""
    from babel.messages.catalog import Catalog

    template = Catalog(domain=DOMAIN)
    for path in sorted(PACKAGE.rglob("*.py")):
        where = f"tmm_cli/{path.relative_to(PACKAGE).as_posix()}"
        for line, message, context in calls_in(path.read_text(encoding="utf-8")):
            template.add(message, locations=[(where, line)], context=context)
    for msgid, where in click_texts():
        template.add(msgid, locations=[(where, 0)])
    return template


def click_texts():
    """(text, where) for every command's help and every option's help of the `tmm` command line."""
    import click

    from tmm_cli.cli import cli

    import inspect

    def walk(cmd, path):
        if cmd.help:
            yield inspect.cleandoc(cmd.help), f"cli:{path}"
        for p in cmd.params:
            if isinstance(p, click.Option) and p.help:
                yield p.help, f"cli:{path} {p.opts[0]}"
        for name, sub in sorted(getattr(cmd, "commands", {}).items()):
            yield from walk(sub, f"{path} {name}")

    yield from walk(cli, "tmm")


def merged(lang: str, template):
    """tmm.po of `lang` brought up to `template`: translations kept, new msgids empty, gone ones
    dropped (never guessed: no fuzzy matching)."""
    from babel.messages.catalog import Catalog
    from babel.messages.pofile import read_po

    path = po_path(lang)
    if path.exists():
        with open(path, "rb") as f:
            catalog = read_po(f, locale=lang, domain=DOMAIN)
    else:
        catalog = Catalog(locale=lang, domain=DOMAIN)
    kept = [m for m in catalog if m.id and m.context in KEPT_CONTEXTS]
    catalog.update(template, no_fuzzy_matching=True, update_header_comment=False)
    catalog.obsolete.clear()
    for m in kept:
        catalog[m.id] = m  # (the context is part of the message)
    catalog.header_comment = "# " + HEADER
    catalog.project, catalog.version = "tmm", ""
    catalog.msgid_bugs_address, catalog.last_translator, catalog.language_team = "", "tmm", "ru"
    catalog.creation_date = catalog.revision_date = FIXED_DATE  # the file changes only with its text
    catalog.fuzzy = False
    return catalog


def po_bytes(catalog) -> bytes:
    from babel.messages.pofile import write_po

    buf = io.BytesIO()
    write_po(buf, catalog, width=100, omit_header=False, sort_output=True, include_previous=False,
             include_lineno=False)
    return buf.getvalue()


def mo_bytes(catalog) -> bytes:
    from babel.messages.mofile import write_mo

    buf = io.BytesIO()
    write_mo(buf, catalog, use_fuzzy=False)
    return buf.getvalue()


def untranslated(catalog) -> list[str]:
    out = []
    for m in catalog:
        if not m.id:
            continue
        strings = m.string if isinstance(m.string, tuple) else (m.string,)
        if not all(strings) or m.fuzzy:
            out.append(m.id[0] if isinstance(m.id, tuple) else m.id)
    return out


def written_by(po: bytes) -> str | None:
    """The Generated-By line of a .po file ("Babel 2.18.0"), or None.

    >>> written_by(b'msgid ""\\nmsgstr ""\\n"Generated-By: Babel 2.18.0\\\\n"\\n')
    'Babel 2.18.0'
    """
    import re

    m = re.search(rb'"Generated-By: ([^"\\]*)', po)
    return m.group(1).decode() if m else None


def same_messages(a: bytes, b: bytes) -> bool:
    """Whether two .po files hold the same messages in the same order (context, msgid, translation,
    fuzzy), whichever Babel wrote them."""
    from babel.messages.pofile import read_po

    def messages(data: bytes):
        return [(m.context, m.id, m.string, m.fuzzy) for m in read_po(io.BytesIO(data)) if m.id]

    return bool(a) and messages(a) == messages(b)


def same_translations(a: bytes, b: bytes) -> bool:
    """Whether two .mo files translate the same messages the same way (the header aside)."""
    from babel.messages.mofile import read_mo

    def text(x) -> str:  # Babel < 2.13 reads a context as bytes
        return x.decode("utf-8") if isinstance(x, bytes) else str(x or "")

    def table(data: bytes):
        return sorted((text(m.context), text(m.id), text(m.string)) for m in read_mo(io.BytesIO(data)) if m.id)

    return bool(a) and table(a) == table(b)


def main(argv: list[str]) -> int:
    check = "--check" in argv
    template = extracted()
    status = 0
    for lang in LANGS:
        catalog = merged(lang, template)
        po, mo = po_bytes(catalog), mo_bytes(catalog)
        missing = untranslated(catalog)
        if check:
            have_po = po_path(lang).read_bytes() if po_path(lang).exists() else b""
            have_mo = mo_path(lang).read_bytes() if mo_path(lang).exists() else b""
            # byte for byte where this Babel wrote the files; another Babel writes the header and the
            # locations its own way (2.17 wraps a location with spaces in U+2068/U+2069), so there
            # the messages are compared (the floors test runs the oldest Babel the package allows)
            exact = written_by(have_po) == written_by(po)
            if not (have_po == po if exact else same_messages(have_po, po)):
                print(f"{po_path(lang)} is not current: run python tools/catalog.py")
                status = 1
            if not (have_mo == mo if exact else same_translations(have_mo, mo)):
                print(f"{mo_path(lang)} is not compiled from {po_path(lang).name}: run python tools/catalog.py")
                status = 1
        else:
            po_path(lang).parent.mkdir(parents=True, exist_ok=True)
            po_path(lang).write_bytes(po)
            mo_path(lang).write_bytes(mo)
        for msgid in missing:
            print(f"{lang}: no translation for {msgid!r}")
        status = status or (1 if missing and check else 0)
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
