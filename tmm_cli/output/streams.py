"""Standard output and error as the shell hands them over: closed, failing, or narrower than our text.

`tmm` prints Russian with Greek symbols (ε_α, ≥, ν). Under an output encoding that cannot hold a
character (``PYTHONIOENCODING=cp1251``, an old Windows console) it is written as near as the
encoding goes — ``ε`` as ``e``, ``≥`` as ``>=``, else ``?`` — instead of a UnicodeEncodeError.
A closed standard output is found before any work; one that fails while printing (a full device,
a pipe whose reader left) is pointed at the null device, so the exit does not fail on it again.
"""

from __future__ import annotations

import os
import sys

NEAREST = {"α": "a", "β": "b", "γ": "g", "δ": "d", "ε": "e", "ζ": "z", "η": "eta", "θ": "th", "λ": "l", "μ": "mu",
           "ν": "nu", "π": "pi", "ρ": "r", "σ": "s", "τ": "t", "φ": "phi", "ψ": "psi", "ω": "w", "Δ": "D", "Σ": "S",
           "Ω": "W", "≥": ">=", "≤": "<=", "≈": "~", "≠": "!=", "−": "-", "–": "-", "—": "-", "·": "*", "×": "x",
           "°": "deg", "±": "+-", "√": "sqrt", "∞": "inf", "→": "->", "←": "<-", "…": "...", "«": '"', "»": '"',
           "✘": "x", "✔": "v", "✓": "v", "✗": "x", "⚠": "!", "ℹ": "i", "•": "*", "²": "2", "³": "3", "¹": "1",
           "₁": "1", "₂": "2"}
HANDLER = "tmm-nearest"


def nearest(err: UnicodeEncodeError):
    """A codecs error handler: each character the encoding cannot hold, as near as it can.

    >>> import codecs; codecs.register_error(HANDLER, nearest)
    >>> "ε_α ≥ 1,05 ✓ Ж".encode("cp1251", HANDLER).decode("cp1251")
    'e_a >= 1,05 v Ж'
    """
    import unicodedata

    out = []
    for ch in err.object[err.start:err.end]:
        sub = NEAREST.get(ch)
        if sub is None:
            sub = unicodedata.normalize("NFKD", ch).encode("ascii", "ignore").decode() or "?"
        try:
            sub.encode(err.encoding)
        except (UnicodeEncodeError, LookupError):
            sub = "?"
        out.append(sub)
    return "".join(out), err.end


def tolerate_narrow_encodings() -> None:
    """Standard output and error in an encoding other than UTF-*: write what it cannot hold as near
    as it can (a stream whose errors are already set by the user is left as it is)."""
    import codecs

    try:
        codecs.lookup_error(HANDLER)
    except LookupError:
        codecs.register_error(HANDLER, nearest)
    for stream in (sys.stdout, sys.stderr):
        if stream is None or getattr(stream, "errors", "strict") != "strict" or not hasattr(stream, "reconfigure"):
            continue
        encoding = (getattr(stream, "encoding", "") or "").lower().replace("_", "-")
        if not encoding.startswith("utf"):
            try:
                stream.reconfigure(errors=HANDLER)
            except (ValueError, OSError, AttributeError):
                pass


def stdout_closed() -> bool:
    """Whether standard output is closed (``tmm … >&-``); a stream without a descriptor (a test's
    capture) is open."""
    if sys.stdout is None:
        return True
    try:
        fd = sys.stdout.fileno()
    except (OSError, ValueError, AttributeError):
        return False
    try:
        os.fstat(fd)
    except OSError:
        return True
    return False


def stdout_failed(exc: OSError) -> bool:
    """Whether standard output is what could not be written (the error came from printing, or its
    buffer does not flush); it is then pointed at the null device."""
    import traceback

    printing = exc.filename is None and any(f.filename.replace("\\", "/").endswith(("rich/console.py", "click/utils.py"))
                                            for f in traceback.extract_tb(exc.__traceback__))
    try:
        sys.stdout.flush()
    except (OSError, ValueError, AttributeError):
        printing = True
    if printing:
        silence_stdout()
    return printing


def silence_stdout() -> None:
    """Point standard output at the null device (what is still buffered goes nowhere)."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError, AttributeError):
        pass
