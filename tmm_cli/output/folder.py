"""Writing results to disk, atomically, and removing only what this program wrote.

Everything is first written into a staging folder beside the target and moved into place at the
end, so an error part-way leaves no half-written file. Every folder `tmm` writes into keeps a
manifest, ``.tmm-files.json``, of the files it put there: a later run removes an old file of its
own that it did not write again (a figure of an earlier run with other options), and nothing
else. A file `tmm` did not write is never deleted nor overwritten; a symbolic link is never
followed to delete or write anything. A staging folder is removed on error, on Ctrl-C and on
SIGTERM; one left by a killed run (``.variant-17.tmp-…`` with our mark inside and a dead process)
is removed by the next run that writes beside it.
"""

from __future__ import annotations

import fnmatch
import json
import os
import re
import shutil
import stat
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

from ..errors import TmmError

FIGURE_FORMATS = ("png", "svg", "pdf")
MANIFEST = ".tmm-files.json"
STAGING_MARK = ".tmm-staging"  # inside each staging folder: the writer's pid
_ACTIVE: set[str] = set()  # staging folders and temporary files of this process (removed on a signal)


# checks and folders ------------------------------------------------------------------------------


def ensure_writable_dir(path: Path) -> Path:
    """Check, creating nothing, that the folder `path` exists or can be created and written.

    The nearest existing ancestor must be a writable folder; TmmError otherwise. Folders are made
    only when files are written (:func:`staged_dir`), so a run that fails leaves none behind.
    """
    path = Path(path)
    probe = path
    while not os.path.lexists(probe):
        if probe.parent == probe:
            break
        probe = probe.parent
    if not probe.is_dir():
        raise TmmError(f"cannot write to output folder {path} ({probe} is not a folder); choose a folder with --out")
    if not os.access(probe, os.W_OK | os.X_OK):
        raise TmmError(f"cannot write to output folder {path} (Permission denied); choose a writable folder with --out")
    return path


def make_dirs(path: Path) -> list[Path]:
    """Create `path` and its missing parents; return the folders created, outermost first."""
    path = Path(path)
    missing = []
    probe = path
    while not os.path.lexists(probe):
        missing.append(probe)
        if probe.parent == probe:
            break
        probe = probe.parent
    if not probe.is_dir():
        raise TmmError(f"cannot write to output folder {path} ({probe} is not a folder); choose a folder with --out")
    created = []
    try:
        for d in reversed(missing):
            d.mkdir()
            created.append(d)
    except OSError as exc:
        remove_empty_dirs(created)
        raise TmmError(f"cannot create output folder {path} ({exc.strerror}); choose a writable folder with --out") from None
    return created


def remove_empty_dirs(created: list[Path]) -> None:
    """Remove the folders a failed run created (innermost first), if they are still empty."""
    for d in reversed(created):
        try:
            os.rmdir(d)
        except OSError:
            break


def _is_real_dir(p: Path) -> bool:
    try:
        return stat.S_ISDIR(os.lstat(p).st_mode)
    except OSError:
        return False


def _is_real_file(p: Path) -> bool:
    try:
        return stat.S_ISREG(os.lstat(p).st_mode)
    except OSError:
        return False


@contextmanager
def lock_dir(folder: Path, wait: bool = True, what: str = "tmm"):
    """Hold an exclusive lock on the folder itself (flock on its descriptor; no lock file).

    With `wait` False a folder another run holds gives a TmmError at once. Where the system has
    no flock (Windows) the block runs unlocked.
    """
    try:
        import fcntl
    except ImportError:  # pragma: no cover - Windows
        yield
        return
    fd = os.open(folder, os.O_RDONLY)
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | (0 if wait else fcntl.LOCK_NB))
        except BlockingIOError:
            raise TmmError(f"another {what} is writing into {folder}; wait for it to finish or choose another --out") from None
        except OSError:
            pass  # a file system without locks: go on unlocked
        yield
    finally:
        os.close(fd)


# the manifest ------------------------------------------------------------------------------------


def _plain(name) -> bool:
    return isinstance(name, str) and name not in ("", ".", "..", MANIFEST) and "/" not in name and "\\" not in name and "\x00" not in name


def read_manifest(folder: Path) -> dict:
    """{"files": set of names, "dirs": set of relative paths} this program wrote into `folder`.

    An unreadable or foreign manifest counts as empty: then nothing is removed.
    """
    p = Path(folder) / MANIFEST
    files, dirs = set(), set()
    if _is_real_file(p):
        try:
            data = json.loads(p.read_text(encoding="utf-8"))
        except (OSError, ValueError, RecursionError):
            data = {}
        if isinstance(data, dict) and data.get("tool") == "tmm":
            files = {n for n in data.get("files", []) if _plain(n)}
            dirs = {d for d in data.get("dirs", []) if isinstance(d, str) and d and all(_plain(c) for c in d.split("/"))}
    return {"files": files, "dirs": dirs}


def write_manifest(folder: Path, files=(), dirs=()) -> None:
    """Record (atomically) the files and sub-folders this program wrote into `folder`."""
    folder = Path(folder)
    data = {"tool": "tmm", "note": "files written by tmm; tmm removes only these", "files": sorted(set(files)),
            "dirs": sorted(set(dirs))}
    with _temp_file(folder / f".{MANIFEST}.tmp-{os.getpid()}") as tmp:
        tmp.write_text(json.dumps(data, ensure_ascii=False, indent=1) + "\n", encoding="utf-8")
        os.replace(tmp, folder / MANIFEST)


@contextmanager
def _temp_file(tmp: Path) -> Iterator[Path]:
    """A temporary file beside its target, removed however the block ends: on an error, and from a
    signal handler too (:func:`remove_active_staging`): a batch worker stopped between writing it
    and moving it into place left ``..tmm-files.json.tmp-PID`` behind."""
    _ACTIVE.add(str(tmp))  # before the file exists: a signal can come at any moment after this
    try:
        yield tmp
    finally:
        remove_temp_file(tmp)
        _ACTIVE.discard(str(tmp))


def remove_temp_file(tmp: Path) -> None:
    """Remove the file `tmp` if it is a file (never a folder, nothing followed); quietly."""
    if _is_real_file(tmp) or os.path.islink(tmp):
        try:
            os.unlink(tmp)
        except OSError:
            pass


def refuse_foreign(target: Path, names, manifest: set[str]) -> None:
    for name in sorted(names):
        dst = target / name
        if os.path.lexists(dst) and (name not in manifest or not _is_real_file(dst)):
            raise TmmError(f"{dst} was not written by tmm (it is not in {MANIFEST}); tmm never overwrites "
                           f"such a file: move it away or choose another --out")


# staging -----------------------------------------------------------------------------------------


STALE_AFTER_S = 24 * 3600  # a staging folder this old is stale whoever wrote it
_STAGING_NAME = re.compile(r"\..+\.tmp-(\d+)-[0-9a-f]{8}")  # see _new_staging


def _pid_alive(pid: int) -> bool:
    if os.name == "nt":  # os.kill(pid, 0) would terminate the process on Windows: trust the age alone
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError, ValueError):
        return True
    return True


def is_our_staging(p: Path) -> bool:
    """A real folder named ``.NAME.tmp-…`` holding our mark."""
    return p.name.startswith(".") and ".tmp-" in p.name and _is_real_dir(p) and _is_real_file(p / STAGING_MARK)


def remove_stale_staging(parent: Path, only_dead: bool = True, dead_pids=()) -> list[Path]:
    """Remove staging folders of ours in `parent` whose writer is gone (a dead pid, one of
    `dead_pids`, or older than a day), or all of ours when `only_dead` is False."""
    import time

    removed = []
    try:
        entries = list(Path(parent).iterdir())
    except OSError:
        return removed
    for p in entries:
        if not is_our_staging(p):
            m = _STAGING_NAME.fullmatch(p.name)
            if m and int(m.group(1)) in dead_pids and _is_real_dir(p):  # a killed worker's, before its mark
                shutil.rmtree(p, ignore_errors=True)
                removed.append(p)
            continue
        try:
            pid = int((p / STAGING_MARK).read_text().split()[0])
        except (OSError, ValueError, IndexError):  # the mark being written right now (empty): the pid in the name
            m = _STAGING_NAME.fullmatch(p.name)
            pid = int(m.group(1)) if m else -1
        try:
            old_enough = time.time() - os.lstat(p / STAGING_MARK).st_mtime > STALE_AFTER_S
        except OSError:
            old_enough = False
        if only_dead and pid > 0 and pid != os.getpid() and pid not in dead_pids and not old_enough and _pid_alive(pid):
            continue
        if pid == os.getpid() and str(p) in _ACTIVE and only_dead:
            continue
        shutil.rmtree(p, ignore_errors=True)
        removed.append(p)
    return removed


def remove_active_staging() -> None:
    """Remove this process's staging folders and temporary files (called from signal handlers
    before exiting)."""
    for p in list(_ACTIVE):
        if _is_real_dir(Path(p)):
            shutil.rmtree(p, ignore_errors=True)
        else:
            remove_temp_file(Path(p))
        _ACTIVE.discard(p)


@contextmanager
def staged_dir(target: Path, owns: tuple[str, ...] = ()) -> Iterator[Path]:
    """Yield an empty staging folder; on success its files move into `target`, on error it vanishes.

    Files are moved one by one with :func:`os.replace` (atomic per file), only after everything
    was written, so a failed run leaves no half-written file and keeps what `target` had; the
    folders it had to create are removed again. `owns` lists glob patterns of the files this
    command writes: an older file matching them that this run did not write again is removed
    only if the manifest says this program wrote it. A file of the same name that this program
    did not write, or a `target` that is a symbolic link, is refused with a TmmError.
    """
    target = Path(target)
    if os.path.islink(target):
        raise TmmError(f"{target} is a symbolic link; tmm writes only into real folders: remove the link or choose another --out")
    if os.path.lexists(target) and not _is_real_dir(target):
        raise TmmError(f"{target} exists and is not a folder; move it away or choose another --out")
    parent = target.parent
    created = make_dirs(parent)
    try:
        remove_stale_staging(parent)
        tmp = _new_staging(parent, target.name)
    except OSError as exc:
        remove_empty_dirs(created)
        raise TmmError(f"cannot write to output folder {parent} ({exc.strerror}); choose a writable folder with --out") from None
    try:
        (tmp / STAGING_MARK).write_text(f"{os.getpid()}\n")
        yield tmp
        fresh = {item.name for item in tmp.iterdir()} - {STAGING_MARK}
        try:
            if not os.path.lexists(target):
                target.mkdir()
                created.append(target)
        except OSError as exc:
            raise TmmError(f"cannot create {target} ({exc.strerror}); choose a writable folder with --out") from None
        with lock_dir(target):  # two runs into one folder: one commits after the other
            _commit(tmp, target, fresh, owns)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        remove_empty_dirs(created)
        raise
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
        _ACTIVE.discard(str(tmp))


def _new_staging(parent: Path, name: str) -> Path:
    """Create the empty staging folder ``parent/.NAME.tmp-PID-XXXXXXXX``, registered for removal
    on a signal before it exists (a batch worker stopped between ``mkdtemp`` and the registration
    left one behind under load); the pid in its name lets the batch recognise a killed worker's
    folder before its mark is written."""
    while True:
        tmp = Path(parent) / f".{name}.tmp-{os.getpid()}-{os.urandom(4).hex()}"
        _ACTIVE.add(str(tmp))
        try:
            os.mkdir(tmp, 0o700)
            return tmp
        except FileExistsError:
            _ACTIVE.discard(str(tmp))
        except BaseException:  # mkdir failed, or a signal came just after it
            try:
                os.rmdir(tmp)
            except OSError:
                pass
            _ACTIVE.discard(str(tmp))
            raise


def _commit(tmp: Path, target: Path, fresh: set[str], owns) -> None:
    """Move the staged files into `target` and drop this program's stale files (manifest ∩ owns)."""
    if not _is_real_dir(target):
        raise TmmError(f"{target} is not a real folder; choose another --out")
    old = read_manifest(target)
    refuse_foreign(target, fresh, old["files"])
    try:
        stale = {n for n in old["files"] - fresh if any(fnmatch.fnmatchcase(n, pat) for pat in owns)}
        write_manifest(target, old["files"] | fresh, old["dirs"])  # a crash below leaves a true superset
        for name in sorted(fresh):
            os.replace(tmp / name, target / name)
        for name in stale:
            if _is_real_file(target / name):
                (target / name).unlink()
        write_manifest(target, (old["files"] - stale) | fresh, old["dirs"])
    except OSError as exc:
        raise TmmError(f"cannot write into {target} ({exc.strerror}); choose a writable folder with --out") from None


def write_owned(folder: Path, name: str, data: bytes) -> Path:
    """Write one file (summary.csv, check.md) into `folder` atomically and record it as ours.

    Refused (TmmError) when a file of that name exists that this program did not write.
    """
    folder = Path(folder)  # the --out folder the user named (it may be a link the user made)
    make_dirs(folder)
    man = read_manifest(folder)
    refuse_foreign(folder, [name], man["files"])
    try:
        write_manifest(folder, man["files"] | {name}, man["dirs"])
        with _temp_file(folder / f".{name}.tmp-{os.getpid()}") as tmp:
            tmp.write_bytes(data)
            os.replace(tmp, folder / name)
    except OSError as exc:
        raise TmmError(f"cannot write {folder / name} ({exc.strerror}); choose a writable folder with --out") from None
    return folder / name


def remove_written_tree(root: Path, rel: str) -> bool:
    """Remove the folder `root/rel` that this program wrote: only the files its manifest lists,
    then the folder (and `rel`'s parents below `root`) when empty. Never follows a symbolic link.
    Returns True when the folder is gone, False when something not ours keeps it.
    """
    root = Path(root)
    parts = rel.split("/")
    if not all(_plain(c) for c in parts):
        return False
    chain = [root.joinpath(*parts[: i + 1]) for i in range(len(parts))]
    if not all(_is_real_dir(p) for p in chain):
        return not any(os.path.lexists(p) for p in chain[-1:])
    folder = chain[-1]
    man = read_manifest(folder)
    for sub in sorted(man["dirs"], reverse=True):
        remove_written_tree(folder, sub)
    for name in man["files"]:
        if _is_real_file(folder / name):
            (folder / name).unlink()
    remove_stale_staging(folder, only_dead=True)
    if _is_real_file(folder / MANIFEST):
        leftovers = [p for p in folder.iterdir() if p.name != MANIFEST]
        if not leftovers:
            (folder / MANIFEST).unlink()
    for d in reversed(chain):
        try:
            os.rmdir(d)
        except OSError:
            return d != folder and not os.path.lexists(folder)
    return True


# writers -----------------------------------------------------------------------------------------


def staged_names(tmp: Path) -> list[str]:
    """The names of the files written so far into the staging folder `tmp` (its mark left out), sorted."""
    return sorted(p.name for p in Path(tmp).iterdir() if p.name != STAGING_MARK)


def write_text(path: Path, text: str) -> None:
    Path(path).write_text(text, encoding="utf-8")


