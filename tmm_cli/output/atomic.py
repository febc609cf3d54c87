"""Temporary files beside their target, and the atomic replace that puts them in place.

A temporary name is ``.NAME.tmp-PID-XXXXXXXX``: the writer's pid (so a batch can sweep a killed
worker's) and eight random hex digits, created with O_CREAT | O_EXCL | O_NOFOLLOW, so a file or a
symbolic link someone planted under a name they guessed is never opened, let alone written
through. It is registered for removal before it exists (a signal can come at any moment after
that) and removed however the block ends; :func:`os.replace` then moves it over the final name,
which replaces a symbolic link found there, never the file the link points to.
"""

from __future__ import annotations

import os
import re
import stat
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

_ACTIVE: set[str] = set()  # staging folders and temporary files of this process (removed on a signal)
TEMP_NAME = re.compile(r"\..+\.tmp-(\d+)-[0-9a-f]{8}")  # a staging folder or a temporary file of ours

_OPEN_NEW = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_CLOEXEC", 0) \
    | getattr(os, "O_BINARY", 0)


def temp_name(folder: Path, name: str) -> Path:
    """A fresh name ``folder/.NAME.tmp-PID-XXXXXXXX`` (nothing is created)."""
    return Path(folder) / f".{name}.tmp-{os.getpid()}-{os.urandom(4).hex()}"


def is_real_file(p) -> bool:
    try:
        return stat.S_ISREG(os.lstat(p).st_mode)
    except (OSError, ValueError):
        return False


def is_real_dir(p) -> bool:
    try:
        return stat.S_ISDIR(os.lstat(p).st_mode)
    except (OSError, ValueError):
        return False


def remove_temp_file(tmp: Path) -> None:
    """Remove the file or link `tmp` (never a folder, nothing followed); quietly."""
    if is_real_file(tmp) or os.path.islink(tmp):
        try:
            os.unlink(tmp)
        except OSError:
            pass


@contextmanager
def temp_file(folder: Path, name: str) -> Iterator[tuple[int, Path]]:
    """An open descriptor and the path of a new temporary file for `name` in `folder`.

    The file is removed when the block ends unless it was moved away (an error, a signal: see
    :func:`remove_active`); the descriptor is closed.
    """
    while True:
        tmp = temp_name(folder, name)
        _ACTIVE.add(str(tmp))  # before the file exists
        try:
            fd = os.open(tmp, _OPEN_NEW, 0o666)
            break
        except FileExistsError:
            _ACTIVE.discard(str(tmp))
        except BaseException:
            _ACTIVE.discard(str(tmp))
            raise
    try:
        yield fd, tmp
    finally:
        try:
            os.close(fd)
        except OSError:
            pass
        remove_temp_file(tmp)
        _ACTIVE.discard(str(tmp))


def write_all(fd: int, data: bytes) -> None:
    view = memoryview(data)
    while view:
        n = os.write(fd, view)
        view = view[n:]


def atomic_write(folder: Path, name: str, data: bytes) -> Path:
    """Write `data` to ``folder/name`` at once: a temporary file, then :func:`os.replace` (a link at
    the final name is replaced, never written through). OSError as it comes."""
    with temp_file(folder, name) as (fd, tmp):
        write_all(fd, data)
        os.replace(tmp, Path(folder) / name)
    return Path(folder) / name


def remove_active() -> None:
    """Remove this process's staging folders and temporary files (from signal handlers)."""
    import shutil

    for p in list(_ACTIVE):
        if is_real_dir(p):
            shutil.rmtree(p, ignore_errors=True)
        else:
            remove_temp_file(Path(p))
        _ACTIVE.discard(p)
