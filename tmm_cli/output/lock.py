"""The lock of a batch's output folder: ``.tmm-batch.lock`` holding the batch's pid.

Two batches never write into one folder at once: the lock file is held with ``flock`` while the
batch runs (where the system has it), and names the batch's process. A lock file left by a batch
that was killed (``kill -9``, a power cut) names a process that is gone: the next batch takes it
over and says so. The descriptor is closed in the batch's worker processes
(:func:`held_descriptors`), so a worker that outlived its batch could never keep the folder locked.
"""

from __future__ import annotations

import os
import stat
from contextlib import contextmanager
from pathlib import Path

from ..errors import TmmError

LOCK_FILE = ".tmm-batch.lock"
_HELD: set[int] = set()  # descriptors of the locks this process holds


def held_descriptors() -> list[int]:
    """The descriptors of the locks held here (a forked worker closes its copies)."""
    return sorted(_HELD)


def _alive(pid: int) -> bool:
    from .folder import pid_alive

    return pid_alive(pid)


def _read_pid(fd: int) -> int:
    try:
        os.lseek(fd, 0, os.SEEK_SET)
        return int(os.read(fd, 64).split()[0])
    except (OSError, ValueError, IndexError):
        return 0


@contextmanager
def batch_lock(folder: Path, what: str = "tmm batch", say=None):
    """Hold the lock of `folder` for the block; TmmError at once if a live batch holds it.

    `say(pid)` is called when a stale lock (its process gone) is taken over.
    """
    path = Path(folder) / LOCK_FILE
    for _ in range(10):  # a lock file unlinked by its batch between our open and our flock: open again
        fd = _lock(folder, path, what, say)
        try:
            st, lst = os.fstat(fd), os.lstat(path)
            if (st.st_dev, st.st_ino) == (lst.st_dev, lst.st_ino):
                break
        except OSError:
            pass
        os.close(fd)
    else:  # pragma: no cover - never seen
        raise TmmError(f"cannot lock {folder}; try again")
    _HELD.add(fd)
    try:
        yield
    finally:
        try:
            st = os.fstat(fd)
            lst = os.lstat(path)
            if (st.st_dev, st.st_ino) == (lst.st_dev, lst.st_ino):
                os.unlink(path)
        except OSError:
            pass
        _HELD.discard(fd)
        os.close(fd)


def _lock(folder: Path, path: Path, what: str, say) -> int:
    """Open and lock the lock file; its descriptor (the pid written in it)."""
    flags = os.O_RDWR | os.O_CREAT | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_CLOEXEC", 0)
    try:
        fd = os.open(path, flags, 0o644)
    except OSError as exc:
        raise TmmError(f"cannot lock {folder} ({exc.strerror}); remove {path} if it is not tmm's lock, or choose "
                       f"another --out") from None
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            raise TmmError(f"cannot lock {folder} ({path} is not a regular file); remove it or choose another --out")
        try:
            import fcntl
        except ImportError:  # pragma: no cover - Windows: the pid alone
            fcntl = None
        locked = False
        if fcntl is not None:
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
                locked = True
            except BlockingIOError:
                pid = _read_pid(fd)
                raise TmmError(f"another {what} is writing into {folder} (process {pid}); wait for it to finish or "
                               f"choose another --out") from None
            except OSError:
                pass  # a file system without locks: the pid alone
        pid = _read_pid(fd)
        if pid and pid != os.getpid():
            if not locked and _alive(pid):  # no flock here (Windows, some network file systems): the pid alone
                raise TmmError(f"another {what} is writing into {folder} (process {pid}); wait for it to finish or "
                               f"choose another --out")
            if say is not None:
                say(pid)
        os.ftruncate(fd, 0)
        os.lseek(fd, 0, os.SEEK_SET)
        os.write(fd, f"{os.getpid()}\n".encode())
    except BaseException:
        os.close(fd)
        raise
    return fd
