"""Drawings shared by the worker processes of one `tmm batch`: nothing drawn twice.

A worker keeps the drawings that depend only on part of a row (the reducer's two figures, which
depend only on the reducer; a spur mesh) in its own memory already (``report._from_cache``). This
adds a folder of the operating system's temporary space, made by the batch before its workers
start and removed by it at the end, through which a drawing one worker made serves the others:

- a drawing is published as a folder named by its key's digest, renamed into place whole, so a
  reader sees all of its files or none;
- the first worker to need a drawing claims it (a file made with O_EXCL) and draws it; a worker
  that finds it claimed by another puts it off to the end of its row and then takes it from the
  folder — or, if it is not there within `wait_s` (the other worker failed or was stopped), draws
  it itself. So two workers never both draw what one of them is drawing.

Never in the user's output folder; the files are bytes this program wrote (PNG, SVG).
"""

from __future__ import annotations

import hashlib
import os
import shutil
import time
from pathlib import Path


class SharedFigures:
    """The folder `root` (made by the batch, private to this user) as a cache of drawings."""

    def __init__(self, root: str | Path, wait_s: float = 20.0):
        self.root = Path(root)
        self.wait_s = wait_s

    @staticmethod
    def _name(key) -> str:
        return hashlib.sha256(repr(key).encode("utf-8")).hexdigest()[:32]

    def get(self, key) -> dict | None:
        """The files {name: bytes} of the drawing `key`, if a worker published it."""
        folder = self.root / self._name(key)
        try:
            return {p.name: p.read_bytes() for p in folder.iterdir()}
        except OSError:  # not published (yet), or the batch is over
            return None

    def claim(self, key) -> bool:
        """True for the first worker to ask (it is to draw `key`), False for every other."""
        try:
            os.close(os.open(self.root / (self._name(key) + ".claim"), os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o600))
        except FileExistsError:
            return False
        except OSError:  # the folder is gone: draw, share nothing
            return True
        return True

    def put(self, key, files: dict) -> None:
        """Publish the drawing `key` (all its files at once); quietly nothing if the folder is gone."""
        name = self._name(key)
        part = self.root / f".{name}.{os.getpid()}"
        try:
            part.mkdir()
            for file_name, data in files.items():
                (part / file_name).write_bytes(data)
            part.rename(self.root / name)
        except OSError:
            shutil.rmtree(part, ignore_errors=True)

    def wait(self, key) -> dict | None:
        """The drawing `key` once another worker publishes it, or None after `wait_s`."""
        end = time.monotonic() + self.wait_s
        delay = 0.005
        while True:
            got = self.get(key)
            if got is not None or time.monotonic() >= end:
                return got
            time.sleep(delay)
            delay = min(0.05, delay * 2)

