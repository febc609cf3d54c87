"""Ctrl-C, SIGTERM and SIGHUP: stop at once, leave no temporary folder, exit 130 / 143 / 129.

The main process turns SIGTERM and SIGHUP (the terminal closed) into :class:`Interrupted` (a
KeyboardInterrupt, as Ctrl-C is), so every ``finally`` runs: staging folders vanish and `tmm batch`
writes the summary of what finished. Batch worker processes ignore Ctrl-C and SIGHUP (the main
process decides) and on SIGTERM end the child processes they started (typst), remove their staging
folder and exit at once; a worker whose parent died also removes what the batch shared with it.
"""

from __future__ import annotations

import os
import signal
from contextlib import contextmanager

EXIT_CODES = {signal.SIGINT: 130, signal.SIGTERM: 143}
if hasattr(signal, "SIGHUP"):
    EXIT_CODES[signal.SIGHUP] = 129
STOPPING = tuple(EXIT_CODES)  # the signals a run stops on


class Interrupted(KeyboardInterrupt):
    """Ctrl-C or SIGTERM; `exit_code` is 130 or 143."""

    def __init__(self, signum: int = signal.SIGINT, message: str = ""):
        super().__init__(message)
        self.signum = signum
        self.message = message

    @property
    def exit_code(self) -> int:
        return EXIT_CODES.get(self.signum, 130)


_RECEIVED: list[int] = []  # the signals this process was stopped by (see :func:`received`)


def _raise(signum, frame):
    _RECEIVED.append(signum)
    raise Interrupted(signum)


def received() -> Interrupted | None:
    """The interruption of this run, if a signal arrived: whatever error surfaced after it is its
    consequence, not a bug (a KeyboardInterrupt raised inside a C extension can come out as
    another error: matplotlib turned one into "ValueError: Invalid affine transformation matrix")."""
    return Interrupted(_RECEIVED[-1]) if _RECEIVED else None


@contextmanager
def handle_signals():
    """In the main process: SIGINT, SIGTERM and SIGHUP raise :class:`Interrupted` (handlers restored
    after; a signal ignored when the run began, as under nohup, stays ignored)."""
    _RECEIVED.clear()  # a new run (tests run many in one process)
    try:
        old = {}
        for s in STOPPING:
            if s != signal.SIGINT and signal.getsignal(s) is signal.SIG_IGN:
                continue
            old[s] = signal.signal(s, _raise)
    except ValueError:  # not the main thread (e.g. an embedding program): leave signals alone
        yield
        return
    try:
        yield
    finally:
        for s, h in old.items():
            signal.signal(s, h)


_CHILDREN: set[tuple[int, int]] = set()  # (starter, child): processes started here that must not outlive it (typst)
_PARENT: list[int] = []  # a batch worker's parent
_ORPHANED: list = []  # what a worker removes when its parent is gone


def add_child(pid: int) -> None:
    _CHILDREN.add((os.getpid(), pid))


def remove_child(pid: int) -> None:
    _CHILDREN.discard((os.getpid(), pid))


def kill_children() -> None:
    """Kill the child processes this process started (not those of a process it was forked from)."""
    me = os.getpid()
    for starter, pid in list(_CHILDREN):
        if starter == me:
            try:
                os.kill(pid, signal.SIGKILL if hasattr(signal, "SIGKILL") else signal.SIGTERM)
            except OSError:
                pass
        _CHILDREN.discard((starter, pid))


def _worker_exit(signum, frame):
    from .folder import remove_active_staging

    kill_children()
    remove_active_staging()
    if _PARENT and os.getppid() != _PARENT[0]:  # the batch is gone: no one else will clean up
        for clean in _ORPHANED:
            try:
                clean()
            except Exception:
                pass
    os._exit(EXIT_CODES.get(signum, 143))


def worker_init(parent_pid: int | None = None, orphaned=()) -> None:
    """Initializer of batch worker processes; `orphaned` are called if the worker is stopped after
    its parent `parent_pid` died (the parent's own clean-up never ran)."""
    import warnings

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    if hasattr(signal, "SIGHUP"):
        signal.signal(signal.SIGHUP, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, _worker_exit)
    warnings.simplefilter("ignore", RuntimeWarning)
    _PARENT[:] = [parent_pid] if parent_pid else []
    _ORPHANED[:] = list(orphaned)


class Stopped(Exception):
    """An :class:`Interrupted` (or plain KeyboardInterrupt) carried past click, which would turn
    it into "Aborted!" with exit status 1."""

    def __init__(self, exc: BaseException):
        super().__init__(str(exc))
        self.message = getattr(exc, "message", "") or "interrupted"
        self.exit_code = getattr(exc, "exit_code", 130)
