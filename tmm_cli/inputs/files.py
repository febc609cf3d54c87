"""Reading a file a user names: a regular file only, its size checked before a byte is read.

The file is opened non-blocking, so a FIFO (or a device) given as a roster, answers file or
``tmm.toml`` is refused at once instead of hanging until someone writes into it; its size is
taken from the open descriptor (no race with a file swapped meanwhile) and checked against the
limit before reading, and no more than the limit is ever read.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

from ..errors import TmmError

_FLAGS = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0) | getattr(os, "O_BINARY", 0)


def size_text(n: int) -> str:
    """A byte count as people say it.

    >>> size_text(64 << 10), size_text(1 << 20), size_text(1000)
    ('64 KiB', '1 MiB', '1000 bytes')
    """
    for unit, shift in (("GiB", 30), ("MiB", 20), ("KiB", 10)):
        if n >= 1 << shift and n % (1 << shift) == 0:
            return f"{n >> shift} {unit}"
    return f"{n} bytes"


def read_file(path: str | Path, what: str, max_bytes: int) -> bytes:
    """The bytes of the regular file `path` (a link to one is followed), at most `max_bytes`;
    TmmError naming `what` for a missing file, a folder, a FIFO or device, or a file over the limit.

    >>> read_file("/dev/null", "roster x.csv", 10)
    Traceback (most recent call last):
    tmm_cli.errors.TmmError: roster x.csv is not a regular file (a device, a pipe or a socket); give a file
    """
    try:
        fd = os.open(path, _FLAGS)
    except FileNotFoundError:
        raise TmmError(f"{what} does not exist; check the path") from None
    except IsADirectoryError:
        raise TmmError(f"{what} is a folder, not a file; give the file") from None
    except OSError as exc:
        raise TmmError(f"{what} cannot be read ({exc.strerror or exc.__class__.__name__}); check the path") from None
    try:
        st = os.fstat(fd)
        if stat.S_ISDIR(st.st_mode):
            raise TmmError(f"{what} is a folder, not a file; give the file")
        if not stat.S_ISREG(st.st_mode):
            raise TmmError(f"{what} is not a regular file (a device, a pipe or a socket); give a file")
        if st.st_size > max_bytes:
            raise TmmError(f"{what} is {st.st_size} bytes, over the limit of {max_bytes} bytes ({size_text(max_bytes)}); "
                           f"is it the right file? (limits: docs/limits.md)")
        chunks, left = [], max_bytes + 1
        while left > 0:
            chunk = os.read(fd, min(left, 1 << 20))
            if not chunk:
                break
            chunks.append(chunk)
            left -= len(chunk)
    except OSError as exc:
        raise TmmError(f"{what} cannot be read ({exc.strerror or exc.__class__.__name__}); check the path") from None
    finally:
        os.close(fd)
    raw = b"".join(chunks)
    if len(raw) > max_bytes:  # a file that grew meanwhile
        raise TmmError(f"{what} is over the limit of {max_bytes} bytes; is it the right file? (limits: docs/limits.md)")
    return raw
