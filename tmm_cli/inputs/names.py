"""One rule from a student's name to a file or folder name, shared by `tmm batch` and `tmm check`.

A roster is written by people (and sometimes by a prankster): names may carry control
characters, path separators, ``..``, look like our own folders (``variant-40``), be 300 characters
long, or differ only in letter case (``Ivanov`` / ``IVANOV``, one file on Windows and macOS). The
rule below turns any name into a safe, short, single path component, and :func:`file_names`
reports two names that would share one file, so a student never reads or overwrites another's.
"""

from __future__ import annotations

import re
import unicodedata

from ..limits import FILE_NAME_CHARS, NAME_CHARS

# characters that end a line in some reader: str.splitlines() splits on all of these
LINE_BREAKS = "\n\r\v\f\x1c\x1d\x1e\x85\u2028\u2029"
# our own names, and Windows's device names (COM¹…COM³ and LPT¹…LPT³ with superscript digits too,
# which Python's \d does not match): a file named so opens the device on Windows
_RESERVED = re.compile(r"(variant-.*|summary|check|con|prn|aux|nul|conin\$?|conout\$?|clock\$?|com[0-9¹²³]|lpt[0-9¹²³])",
                       re.IGNORECASE)


def clean_text(text: str, limit: int | None = None) -> str:
    """Text as it may be shown or written: NFC, line breaks and tabs as spaces, other control
    and format characters removed, spaces collapsed, cut to `limit` characters.

    >>> clean_text("Rene\\u0301\\u2028Ivanov\\x00\\x1b[31m")
    'René Ivanov[31m'
    """
    text = unicodedata.normalize("NFC", str(text))
    out = []
    for ch in text:
        if ch in LINE_BREAKS or ch == "\t":
            out.append(" ")
        elif unicodedata.category(ch) in ("Cc", "Cf", "Cs", "Co", "Cn", "Zl", "Zp"):
            continue
        else:
            out.append(ch)
    text = " ".join("".join(out).split())
    return text[:limit] if limit else text


# shown, never obeyed: what a terminal or a browser would act on (C0/C1 controls, DEL, line and
# paragraph separators, the bidirectional overrides and isolates that reorder what follows)
_SHOWN_AS_CODE = re.compile("[\x00-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069]")


def visible(text) -> str:
    r"""Text as it may be shown on a terminal or a page: every control character as its code
    (``\x1b``), so an ESC cannot clear the screen nor a line break forge an output line.

    >>> print(visible("a\nb\x1b[2J\u202e"))
    a\x0ab\x1b[2J\u202e
    """
    def code(m):
        c = ord(m.group(0))
        return f"\\x{c:02x}" if c < 0x100 else f"\\u{c:04x}"
    return _SHOWN_AS_CODE.sub(code, str(text))


def display_name(raw: str) -> str:
    """A roster name as shown and written to summaries (clean text, at most NAME_CHARS)."""
    return clean_text(raw, NAME_CHARS)


def file_name(name: str) -> str:
    """The file/folder name for a student: ``<name>.toml`` in --answers-dir, ``<name>/`` in a batch.

    Letters (any script), digits, '.', '-' and '_' stay; every other run of characters becomes
    one '_'; leading dots and separators go; at most FILE_NAME_CHARS characters; a name that would
    look like one of our own files or folders (``variant-40``, ``summary``) or a reserved Windows
    name (``CON``) gets the prefix ``student-``. '' when nothing is left.

    >>> file_name("Иванов И. И.")
    'Иванов_И._И'
    >>> file_name("../secret/creds")
    'secret_creds'
    >>> file_name("variant-40")
    'student-variant-40'
    >>> file_name("COM¹"), file_name("lpt².txt"), file_name("Comte")
    ('student-COM¹', 'student-lpt².txt', 'Comte')
    >>> file_name("=HYPERLINK(\\"http://x\\")")
    'HYPERLINK_http_x'
    """
    text = clean_text(name)
    text = re.sub(r"[^\w.-]+", "_", text, flags=re.UNICODE)
    text = re.sub(r"_{2,}", "_", text).strip("._- ")
    text = text[:FILE_NAME_CHARS].rstrip("._- ")
    if _RESERVED.fullmatch(text.split(".")[0].rstrip(" ") if text else ""):
        text = f"student-{text}"
    return text


def collision_key(fname: str) -> str:
    """Two names with one key share a file on a case-insensitive file system (Windows, macOS)."""
    return unicodedata.normalize("NFC", fname).casefold()
