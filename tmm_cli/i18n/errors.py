"""Our error messages in the reader's language.

The core raises :class:`~tmm_cli.errors.TmmError` with an English sentence (an f-string that names
the value and the fix). Its translation is a template in the catalogue under the context
``error``: the English template (``"{p} does not exist; check the path"``) is the msgid, the Russian
one (``"{p} не существует; проверьте путь"``) its msgstr. At the edge the message is matched
against the English templates, the most specific (the most fixed text) first, and the fields are
put into the Russian one; the places a message names ("answers file x.toml line 3") and the
system's reasons ("Permission denied") are translated too. `tests/test_i18n_errors.py` checks that
every raise site has a template.
"""

from __future__ import annotations

import re
import struct
from functools import cache

from . import N_, LOCALE_DIR, DOMAIN, tr, trc

# the places a message names, and the system's reasons: (pattern, msgid with {0}, {1}… for its groups)
_PLACES = (
    (r"^answers file (.*)$", N_("answers file {0}")),
    (r"^roster (.*)$", N_("roster {0}")),
    (r"^variants file (.*)$", N_("variants file {0}")),
    (r"^note template (.*)$", N_("note template {0}")),
    (r"^linkage input (.*)$", N_("linkage input {0}")),
    (r"^standard output$", N_("standard output")),
    (r"^(\d+) KiB$", N_("{0} KiB")), (r"^(\d+) MiB$", N_("{0} MiB")), (r"^(\d+) GiB$", N_("{0} GiB")),
    (r"^killed by (SIG\w+)$", N_("killed by {0}")),  # a batch worker's end (teacher/batch.py)
    (r"^exit status (\d+)$", N_("exit status {0}")),
    (r"^typst needed more memory than the limit of (\d+) MiB$", N_("typst needed more memory than the limit of {0} MiB")),
    (r"^typst stopped \((.*)\)$", N_("typst stopped ({0})")),
    (r"^typst ran longer than the limit of ([\d.]+) s$", N_("typst ran longer than the limit of {0} s")),
    (r"(\S) line (\d+)", N_("{0} line {1}")),  # "table.csv line 3" → "table.csv, строка 3"
    (r"(\S) bore (\d+)$", N_("{0} bore {1}")),  # a measurement card's row (tmm carrier)
    (r"^link (\d+)", N_("link {0}")),  # a dimensional chain's link (tmm chain)
    (r" \(variant (\d+)\)", N_(" (variant {0})")),
    (r"^the ratio i$", N_("the ratio i")),
    (r"^Permission denied$", N_("Permission denied")),
    (r"^No such file or directory$", N_("No such file or directory")),
    (r"^Read-only file system$", N_("Read-only file system")),
    (r"^No space left on device$", N_("No space left on device")),
    (r"^Is a directory$", N_("Is a directory")),
    (r"^Not a directory$", N_("Not a directory")),
    (r"^Disk quota exceeded$", N_("Disk quota exceeded")),
    (r"^File name too long$", N_("File name too long")),
)


def template_pattern(template: str) -> str:
    """An English message template ("{what} is {x}; give …") as a regular expression with named
    groups; a field named twice matches the same text again.

    >>> template_pattern("{w}:{x}/{x}")
    '(?P<w>.*?):(?P<x>.*?)/(?P=x)'
    """
    out, seen = [], set()
    for literal, field in re.findall(r"([^{]*)(?:\{(\w+)\})?", template):
        out.append(re.escape(literal.replace("{{", "{").replace("}}", "}")))
        if field:
            out.append(f"(?P={field})" if field in seen else f"(?P<{field}>.*?)")
            seen.add(field)
    return "".join(out)


def _mo_entries(lang: str):
    """(msgid, msgstr) of the compiled catalogue, read as the .mo format lays them out (GNU gettext
    manual, "The Format of GNU MO Files")."""
    data = (LOCALE_DIR / lang / "LC_MESSAGES" / f"{DOMAIN}.mo").read_bytes()
    order = "<" if struct.unpack("<I", data[:4])[0] == 0x950412DE else ">"
    _, count, ids_at, strs_at = struct.unpack(order + "4I", data[4:20])
    for i in range(count):
        n, at = struct.unpack(order + "2I", data[ids_at + 8 * i: ids_at + 8 * i + 8])
        msgid = data[at:at + n].decode("utf-8")
        n, at = struct.unpack(order + "2I", data[strs_at + 8 * i: strs_at + 8 * i + 8])
        yield msgid, data[at:at + n].decode("utf-8")


@cache
def _templates(lang: str) -> list:
    """The catalogue's error templates of `lang` compiled, the most specific first (built on the
    first error: compiling them costs ~50 ms, not for `--help`)."""
    found = []
    for msgid, msgstr in _mo_entries(lang):
        context, sep, template = msgid.partition("\x04")
        if sep and context == "error" and msgstr:
            fixed = len(re.sub(r"\{\w+\}", "", template))
            found.append((-fixed, template, re.compile(template_pattern(template) + r"\Z", re.S), msgstr))
    found.sort(key=lambda t: (t[0], t[1]))
    return [(pattern, msgstr) for _, _, pattern, msgstr in found]


@cache
def _places(lang: str) -> list:
    return [(re.compile(p), tr(lang, msgid)) for p, msgid in _PLACES]


def _place(text: str, lang: str) -> str:
    """The place named in a message (a file, its line, a variant) in `lang`."""
    for pattern, template in _places(lang):
        text = pattern.sub(lambda m: template.format(*m.groups()), text)
    return text


@cache
def _click_invalid(lang: str):
    """click's frame around our message, "Invalid value for '--x': {message}", in `lang`."""
    frame = trc(lang, "click", "Invalid value for {param_hint}: {message}")
    head = re.escape(frame.split("{param_hint}")[0].rstrip())
    return re.compile(rf"({head}(?: [^:]*)?: )(.*)\Z", re.S)


_DECIMAL = re.compile(r"[+-]?\d+\.\d+(?:e[+-]?\d+)?")


def _decimal(field: str, lang: str) -> str:
    """A field that is a number alone ("0.3", "34.88") with the reader's decimal sign ("0,3" under
    ru); any other field (a path, a key, a list) as it stands."""
    return field.replace(".", ",") if lang == "ru" and _DECIMAL.fullmatch(field) else field


def translate_error(message: str, lang: str = "ru") -> str:
    """Our English error sentence in `lang`, if the catalogue knows it (else unchanged).

    >>> translate_error("variant 99 is not in the table; choose a variant from 1 to 68")
    'варианта 99 нет в таблице; выберите вариант от 1 до 68'
    >>> translate_error("Недопустимое значение '--jobs': 0 is out of range; give a whole number from 1 to 64 (docs/limits.md)")
    "Недопустимое значение '--jobs': 0 вне допустимого диапазона; задайте целое число от 1 до 64 (docs/limits.md)"
    """
    text = " ".join(str(message).split())
    if lang == "en":
        return text
    for pattern, template in _templates(lang):
        m = pattern.match(text)
        if m:  # "table.csv line 3" inside a quoted place → "table.csv, строка 3"
            parts = {k: _decimal(_place(v or "", lang), lang) for k, v in m.groupdict().items()}
            if "rest" in parts:  # a message inside a message ("roster line 3: <the row's error>")
                parts["rest"] = translate_error(parts["rest"], lang)
            return template.format(**parts)
    m = _click_invalid(lang).match(text)  # "Недопустимое значение '--crank-rpm': -5 is out of range; …"
    if m and translate_error(m.group(2), lang) != m.group(2):
        return m.group(1) + translate_error(m.group(2), lang)
    return text


def error_text(message: str, lang: str) -> str:
    """An error shown inside a table (a roster row's, a student's) in the output language."""
    return translate_error(message, lang)
