"""The worker processes of a batch: each runs one row at a time; a worker that dies fails its row only.

The parent hands every worker one row, waits on all of them at once (their result pipes and
their process sentinels), and gives the next row to whoever answers. A worker killed in the
middle (the OOM killer, a `kill -9`, a crash in a C library) costs exactly the row it was running:
that row is reported failed with the signal, a new worker takes its place and the rows not done
go on. (concurrent.futures marks every pending row of a broken pool failed: one killed worker
failed 38 rows of 40.)

Workers die with their parent: on Linux the kernel sends them SIGTERM when the parent dies
(PR_SET_PDEATHSIG), elsewhere a thread notices the parent is gone; their pipe to the parent also
ends. A worker holds no descriptor of the parent's but its own pipe (a forked worker closes the
others, and the parent's lock), so nothing a dead batch held stays held.

Processes are forked only on Linux, where fork is the platform's way; elsewhere (macOS, Windows)
they are spawned: the task and initializer must be importable functions.
"""

from __future__ import annotations

import os
import signal
import sys
import time
from collections import deque

START_FAILURES = 3  # workers in a row that die before finishing any row: the rest cannot run


def start_method() -> str:
    """'fork' on Linux (the platform's default), 'spawn' elsewhere."""
    return "fork" if sys.platform.startswith("linux") else "spawn"


def die_with_parent(parent_pid: int) -> None:
    """Make this process get SIGTERM when `parent_pid` (its parent) is gone."""
    if sys.platform.startswith("linux"):
        try:
            import ctypes

            libc = ctypes.CDLL(None, use_errno=True)
            if libc.prctl(1, int(signal.SIGTERM), 0, 0, 0) == 0:  # PR_SET_PDEATHSIG
                if os.getppid() != parent_pid:  # the parent died before the call
                    os.kill(os.getpid(), signal.SIGTERM)
                return
        except (OSError, AttributeError):
            pass
    if os.name != "posix":  # pragma: no cover - Windows: the pipe's end tells an idle worker
        return
    import threading

    def watch():
        while os.getppid() == parent_pid:
            time.sleep(0.2)
        os.kill(os.getpid(), signal.SIGTERM)

    threading.Thread(target=watch, name="tmm-parent-watch", daemon=True).start()


def _serve(conn, task, init, init_args, parent_pid: int, close_fds) -> None:
    """A worker: close what is not its own, set itself to die with its parent, then run rows."""
    for fd in close_fds:
        try:
            os.close(fd)
        except OSError:
            pass
    init(parent_pid, *init_args)
    die_with_parent(parent_pid)
    while True:
        try:
            msg = conn.recv()
        except (EOFError, OSError):  # the parent is gone
            break
        if msg is None:
            break
        i, args = msg
        try:
            conn.send(("start", i))  # the row is under way: if this worker dies now, the row failed
            result = task(*args)
            conn.send(("done", i, result))
        except OSError:
            break


class _Worker:
    def __init__(self, proc, conn):
        self.proc, self.conn = proc, conn
        self.row: int | None = None  # the row given to it
        self.started = False  # whether it said it began that row
        self.finished = 0


class Workers:
    """Up to `n` worker processes running `task(*items[i])` for every row; see the module's text.

    `init(parent_pid, *init_args)` runs first in every worker. :meth:`run` calls `on_result(i,
    result)` for each row done and `on_death(i, exitcode, pid)` for a row whose worker died;
    :meth:`stop` ends every worker now. `dead_pids` lists the workers that ended without being
    asked to (their staging folders are the caller's to sweep).
    """

    def __init__(self, n: int, task, init, init_args=(), method: str | None = None, inherit=()):
        import multiprocessing as mp

        self.ctx = mp.get_context(method or start_method())
        self.forked = self.ctx.get_start_method() == "fork"
        self.n, self.task, self.init, self.init_args = n, task, init, tuple(init_args)
        self.inherit = tuple(inherit)  # the parent's descriptors a forked worker must close (locks)
        self.live: list[_Worker] = []
        self.dead_pids: list[int] = []
        self.all_pids: list[int] = []
        self._failures = 0

    def _start(self) -> _Worker:
        parent_end, child_end = self.ctx.Pipe()
        close = ([w.conn.fileno() for w in self.live] + [parent_end.fileno()] + list(self.inherit)) if self.forked else []
        proc = self.ctx.Process(target=_serve, args=(child_end, self.task, self.init, self.init_args, os.getpid(), close),
                                daemon=True, name="tmm-batch-worker")
        proc.start()
        child_end.close()
        w = _Worker(proc, parent_end)
        self.live.append(w)
        self.all_pids.append(proc.pid)
        return w

    def _feed(self, w: _Worker, items, pending: deque) -> None:
        if not pending:
            w.row = None
            try:
                w.conn.send(None)
            except OSError:
                pass
            return
        i = pending.popleft()
        w.row, w.started = i, False
        try:
            w.conn.send((i, items[i]))
        except OSError:  # it died meanwhile: its sentinel tells
            pass

    def run(self, items: list, on_result, on_death) -> None:
        from multiprocessing.connection import wait

        pending = deque(range(len(items)))
        for _ in range(min(self.n, len(items))):
            self._feed(self._start(), items, pending)
        while True:
            busy = [w for w in self.live if w.row is not None]
            if not busy:
                break
            waiting = {}
            for w in busy:
                waiting[w.conn] = w
                waiting[w.proc.sentinel] = w
            for obj in wait(list(waiting)):
                w = waiting[obj]
                if w not in self.live or w.row is None:
                    continue
                broken = False
                while w.row is not None and w.conn.poll():  # what it said before anything else
                    got = self._receive(w)
                    if got is None:
                        broken = True
                        break
                    if got[0] == "start":
                        w.started = got[1] == w.row
                        self._failures = 0
                        continue
                    _, i, result = got
                    w.row = None
                    w.finished += 1
                    self._failures = 0
                    on_result(i, result)
                if broken or obj is w.proc.sentinel or not w.proc.is_alive():
                    self._died(w, items, pending, on_death)
                elif w.row is None:
                    self._feed(w, items, pending)
        self._join()

    @staticmethod
    def _receive(w: _Worker):
        try:
            return w.conn.recv()
        except Exception:  # EOF, a broken pipe, a truncated message: the worker died
            return None

    def _died(self, w: _Worker, items, pending: deque, on_death) -> None:
        self.live.remove(w)
        w.proc.join(5)
        if w.proc.is_alive():  # its pipe broke but it lives on: end it
            w.proc.kill()
            w.proc.join(5)
        w.conn.close()
        self.dead_pids.append(w.proc.pid)
        if w.row is not None and w.started:
            on_death(w.row, w.proc.exitcode, w.proc.pid)
        elif w.row is not None:  # it died before it began the row: the row is still to do
            pending.appendleft(w.row)
        if w.finished == 0 and not w.started:  # it never began a row: it could not start
            self._failures += 1
        if self._failures >= START_FAILURES:  # workers die before doing anything: the rest cannot run
            while pending:
                on_death(pending.popleft(), w.proc.exitcode, w.proc.pid)
        if pending and len([x for x in self.live if x.row is not None]) < self.n:
            self._feed(self._start(), items, pending)

    def _join(self) -> None:
        deadline = time.monotonic() + 10.0
        for w in self.live:
            w.proc.join(max(0.0, deadline - time.monotonic()))
        self.stop()

    def stop(self) -> list[int]:
        """End every worker now: SIGTERM (each removes its staging folder), then SIGKILL after a
        second; returns the pids of all the workers there were."""
        procs = [w.proc for w in self.live]
        for p in procs:
            if p.is_alive():
                try:
                    p.terminate()
                except Exception:
                    pass
        deadline = time.monotonic() + 1.0
        for p in procs:
            p.join(max(0.0, deadline - time.monotonic()))
        for p in procs:
            if p.is_alive():
                p.kill()
                p.join(1.0)
        for w in self.live:
            w.conn.close()
        self.live = []
        return list(self.all_pids)
