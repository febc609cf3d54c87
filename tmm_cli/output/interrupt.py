"""Ctrl-C and SIGTERM: stop at once, leave no temporary folder, exit 130 / 143.

The main process turns SIGTERM into :class:`Interrupted` (a KeyboardInterrupt, as Ctrl-C is), so
every ``finally`` runs: staging folders vanish and `tmm batch` writes the summary of what
finished. Batch worker processes ignore Ctrl-C (the main process decides) and on SIGTERM remove
their staging folder and exit at once.
"""

from __future__ import annotations

import os
import signal
from contextlib import contextmanager

EXIT_CODES = {signal.SIGINT: 130, signal.SIGTERM: 143}


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
    """In the main process: SIGINT and SIGTERM raise :class:`Interrupted` (handlers restored after)."""
    _RECEIVED.clear()  # a new run (tests run many in one process)
    try:
        old = {s: signal.signal(s, _raise) for s in (signal.SIGINT, signal.SIGTERM)}
    except ValueError:  # not the main thread (e.g. an embedding program): leave signals alone
        yield
        return
    try:
        yield
    finally:
        for s, h in old.items():
            signal.signal(s, h)


def _worker_exit(signum, frame):
    from .folder import remove_active_staging

    remove_active_staging()
    os._exit(EXIT_CODES.get(signum, 143))


def worker_init() -> None:
    """Initializer of batch worker processes."""
    import warnings

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, _worker_exit)
    warnings.simplefilter("ignore", RuntimeWarning)


class Stopped(Exception):
    """An :class:`Interrupted` (or plain KeyboardInterrupt) carried past click, which would turn
    it into "Aborted!" with exit status 1."""

    def __init__(self, exc: BaseException):
        super().__init__(str(exc))
        self.message = getattr(exc, "message", "") or "interrupted"
        self.exit_code = getattr(exc, "exit_code", 130)
