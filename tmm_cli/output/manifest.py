"""The manifest ``.tmm-files.json``: which files of a folder `tmm` wrote, their bytes, and which command.

Every file is recorded with the sha256 of the bytes written and the commands whose last run wrote
it (``by``: ``project``, ``cam``, ``gears``, ``batch`` …). A file whose bytes differ from its hash
was changed by someone since: it is the user's now and is never overwritten nor deleted. A
command removes a stale file only when it is the last command to claim it, so `tmm cam` into a
project's folder never deletes the project's figures or sheets.

Version 1 manifests (a list of names, no hashes) are read as files of any command with unknown
bytes: they behave as before.
"""

from __future__ import annotations

import hashlib
import json
import os
from pathlib import Path

from .atomic import atomic_write, is_real_file

MANIFEST = ".tmm-files.json"
_READ = os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_CLOEXEC", 0) | getattr(os, "O_BINARY", 0) \
    | getattr(os, "O_NONBLOCK", 0)
MAX_MANIFEST_BYTES = 8 << 20  # a manifest of a 1000-student batch is ~100 kB


def plain_name(name) -> bool:
    """A single path component that is not ours (``..``, ``/etc/passwd`` and the manifest are not)."""
    return (isinstance(name, str) and name not in ("", ".", "..", MANIFEST) and "/" not in name and "\\" not in name
            and "\x00" not in name)


def digest(path) -> str | None:
    """sha256 (hex) of the regular file `path`, read without following a link; None if it is not one.

    >>> import tempfile, pathlib
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = pathlib.Path(d) / "a"; _ = p.write_bytes(b"abc"); digest(p)[:16]
    'ba7816bf8f01cfea'
    """
    try:
        fd = os.open(path, _READ)
    except OSError:
        return None
    try:
        import stat

        if not stat.S_ISREG(os.fstat(fd).st_mode):
            return None
        h = hashlib.sha256()
        while True:
            chunk = os.read(fd, 1 << 20)
            if not chunk:
                return h.hexdigest()
            h.update(chunk)
    except OSError:
        return None
    finally:
        os.close(fd)


def _entry(value) -> dict:
    """A manifest entry as read: {"sha256": hex or None, "by": tuple of writers or None (any)}."""
    if not isinstance(value, dict):
        return {"sha256": None, "by": None}
    sha = value.get("sha256")
    by = value.get("by")
    return {"sha256": sha if isinstance(sha, str) and len(sha) == 64 else None,
            "by": tuple(sorted({w for w in by if isinstance(w, str) and w})) if isinstance(by, list) else None}


def read_manifest(folder: Path) -> dict:
    """{"files": set of names, "dirs": set of relative paths, "entries": {name: entry}} that this
    program wrote into `folder` (an entry: {"sha256": …, "by": (writers…) or None}).

    An unreadable or foreign manifest counts as empty: then nothing is removed nor replaced.
    """
    p = Path(folder) / MANIFEST
    entries, dirs = {}, set()
    if is_real_file(p):
        try:
            fd = os.open(p, _READ)
            try:
                raw = os.read(fd, MAX_MANIFEST_BYTES + 1)
            finally:
                os.close(fd)
            data = json.loads(raw.decode("utf-8")) if len(raw) <= MAX_MANIFEST_BYTES else {}
        except (OSError, ValueError, RecursionError):
            data = {}
        if isinstance(data, dict) and data.get("tool") == "tmm":
            files = data.get("files", [])
            if isinstance(files, dict):
                entries = {n: _entry(v) for n, v in files.items() if plain_name(n)}
            elif isinstance(files, list):
                entries = {n: _entry(None) for n in files if plain_name(n)}
            raw_dirs = data.get("dirs", [])
            if isinstance(raw_dirs, list):
                dirs = {d for d in raw_dirs if isinstance(d, str) and d and all(plain_name(c) for c in d.split("/"))}
    return {"files": set(entries), "dirs": dirs, "entries": entries}


def write_manifest(folder: Path, files=(), dirs=(), entries: dict | None = None) -> None:
    """Record (atomically) the files and sub-folders this program wrote into `folder`; `entries`
    gives the hash and writers of each file (a file without one is recorded as of any writer)."""
    entries = entries or {}
    out = {}
    for name in sorted(set(files)):
        e = entries.get(name) or {}
        item = {}
        if e.get("sha256"):
            item["sha256"] = e["sha256"]
        if e.get("by") is not None:
            item["by"] = sorted(e["by"])
        out[name] = item
    data = {"tool": "tmm", "version": 2,
            "note": "files written by tmm (sha256 of the bytes written, the commands that wrote them); tmm replaces "
                    "or removes only these, and only while their bytes are unchanged",
            "files": out, "dirs": sorted(set(dirs))}
    atomic_write(folder, MANIFEST, (json.dumps(data, ensure_ascii=False, indent=1) + "\n").encode("utf-8"))


def unchanged(path, entry: dict | None) -> bool:
    """Whether the file at `path` is a regular file holding the bytes this program wrote (a manifest
    without a hash, an older tmm's, is trusted)."""
    if entry is None or not is_real_file(path):
        return False
    return entry.get("sha256") is None or digest(path) == entry["sha256"]


def claims(entry: dict | None, writer: str | None) -> bool:
    """Whether `writer`'s last run wrote the file (an entry of unknown writers counts for any)."""
    return entry is not None and (entry.get("by") is None or writer is None or writer in entry["by"])
