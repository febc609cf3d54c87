"""Writing results to disk, atomically, and replacing or removing only what this program wrote.

Everything is first written into a staging folder beside the target and moved into place at the
end, so an error part-way leaves no half-written file. Every folder `tmm` writes into keeps a
manifest, ``.tmm-files.json`` (output/manifest.py), of the files it put there, with the sha256 of
their bytes and the commands that wrote them:

- a later run replaces a file of its own, and removes one it did not write again (a figure of an
  earlier run with other options) only if no other command's last run claims it; so `tmm cam`
  into a project's folder never deletes the project's files;
- a file whose bytes changed since `tmm` wrote it is the user's now: it is kept, the new version
  is written beside it (``note.typ`` → ``note.new.typ``) and the run says so; ``--force`` replaces
  it after keeping a copy (``note.typ.bak``);
- a file `tmm` did not write is never deleted nor overwritten (the run stops with one line);
- a symbolic link is never followed to delete or write anything: one at a final name is replaced,
  never its target.

A staging folder is removed on error, on Ctrl-C and on SIGTERM; one left by a killed run
(``.variant-17.tmp-…`` with our mark inside and a dead process) is removed by the next run that
writes beside it, and so are the temporary files of a dead writer.
"""

from __future__ import annotations

import fnmatch
import os
import shutil
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

from ..errors import TmmError
from ..records import record
from .atomic import _ACTIVE, TEMP_NAME, atomic_write, is_real_dir, is_real_file, remove_active, remove_temp_file
from .manifest import MANIFEST, claims, digest, plain_name, read_manifest, unchanged, write_manifest

__all__ = ["MANIFEST", "read_manifest", "write_manifest", "remove_temp_file", "staged_dir", "write_owned", "Kept"]

FIGURE_FORMATS = ("png", "svg", "pdf")
STAGING_MARK = ".tmm-staging"  # inside each staging folder: the writer's pid
_is_real_dir, _is_real_file, _plain = is_real_dir, is_real_file, plain_name  # the names other modules used


@record
class Kept:
    """A file of the user's found where this run writes: `beside` is the name the new version got
    (``note.new.typ``), or `backup` the copy kept before it was replaced (``--force``)."""

    folder: str
    name: str
    beside: str = ""
    backup: str = ""


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


def check_inside(root: Path, target: Path) -> None:
    """Every folder from below `root` down to `target` that exists is a real folder, not a link
    (a student folder planted as a link out of a batch's --out); TmmError otherwise."""
    root, target = Path(root), Path(target)
    try:
        rel = target.relative_to(root)
    except ValueError:
        raise TmmError(f"{target} is not inside {root}; choose another --out") from None
    probe = root
    for part in rel.parts:
        probe = probe / part
        if not os.path.lexists(probe):
            return
        if not is_real_dir(probe):
            raise TmmError(f"{probe} is a symbolic link or not a folder; tmm writes only into real folders inside "
                           f"{root}: remove it or choose another --out")


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
    fd = os.open(folder, os.O_RDONLY | getattr(os, "O_CLOEXEC", 0))
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


def refuse_foreign(target: Path, names, manifest: set[str]) -> None:
    """TmmError for the first of `names` that exists in `target` but is not in its manifest."""
    for name in sorted(names):
        dst = Path(target) / name
        if os.path.lexists(dst) and name not in manifest:
            raise TmmError(f"{dst} was not written by tmm (it is not in {MANIFEST}); tmm never overwrites "
                           f"such a file: move it away or choose another --out")


# the user's files where we write -----------------------------------------------------------------


def beside_name(name: str, n: int = 1) -> str:
    """The name of the new version written beside a file of the user's.

    >>> beside_name("note.typ"), beside_name("summary.csv", 2), beside_name("README")
    ('note.new.typ', 'summary.new2.csv', 'README.new')
    """
    stem, dot, ext = name.rpartition(".")
    tag = "new" if n == 1 else f"new{n}"
    return f"{stem}.{tag}.{ext}" if dot and stem else f"{name}.{tag}"


def _free_beside(folder: Path, name: str, entries: dict, taken: set[str]) -> str:
    """A name beside `name` that is free, or a file of ours with its bytes unchanged."""
    for n in range(1, 1000):
        cand = beside_name(name, n)
        if cand in taken:
            continue
        if not os.path.lexists(folder / cand) or unchanged(folder / cand, entries.get(cand)):
            return cand
    raise TmmError(f"too many new versions of {folder / name} beside it; move them away")


def _free_backup(folder: Path, name: str) -> str:
    for n in range(1, 1000):
        cand = f"{name}.bak" if n == 1 else f"{name}.bak{n}"
        if not os.path.lexists(folder / cand):
            return cand
    raise TmmError(f"too many backups of {folder / name} beside it; move them away")


def _placement(folder: Path, names, entries: dict, force: bool) -> tuple[dict, list[Kept]]:
    """Where each new file goes: {name: final name}, and the user's files met on the way.

    A name that exists but is not in the manifest is refused (TmmError, before anything changed).
    A file of ours whose bytes changed (or a link, or anything not a regular file, at its name) is
    kept and the new version goes beside it; with `force`, a regular file or link is moved to a
    backup name first (that happens in :func:`_make_backups`)."""
    refuse_foreign(folder, names, set(entries))
    dest, kept, taken = {}, [], set()
    for name in sorted(names):
        dst = folder / name
        if not os.path.lexists(dst) or unchanged(dst, entries.get(name)):
            dest[name] = name
        elif force and (is_real_file(dst) or os.path.islink(dst)):
            dest[name] = name
            kept.append(Kept(str(folder), name, backup=_free_backup(folder, name)))
        else:
            dest[name] = _free_beside(folder, name, entries, taken | set(names))
            kept.append(Kept(str(folder), name, beside=dest[name]))
        taken.add(dest[name])
    return dest, kept


def _make_backups(folder: Path, kept: list[Kept]) -> None:
    for k in kept:
        if k.backup:
            os.rename(folder / k.name, folder / k.backup)  # a link is renamed as a link


# staging -----------------------------------------------------------------------------------------


STALE_AFTER_S = 24 * 3600  # a staging folder this old is stale whoever wrote it


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


pid_alive = _pid_alive


def is_our_staging(p: Path) -> bool:
    """A real folder named ``.NAME.tmp-…`` holding our mark."""
    return p.name.startswith(".") and ".tmp-" in p.name and is_real_dir(p) and is_real_file(p / STAGING_MARK)


def remove_stale_staging(parent: Path, only_dead: bool = True, dead_pids=()) -> list[Path]:
    """Remove staging folders of ours in `parent` whose writer is gone (a dead pid, one of
    `dead_pids`, or older than a day), or all of ours when `only_dead` is False; and our temporary
    files (``.NAME.tmp-PID-XXXXXXXX``) whose writer is dead or one of `dead_pids`."""
    import time

    removed = []
    try:
        entries = list(Path(parent).iterdir())
    except OSError:
        return removed
    for p in entries:
        if str(p) in _ACTIVE:
            continue
        if not is_our_staging(p):
            m = TEMP_NAME.fullmatch(p.name)
            if not m:
                continue
            pid = int(m.group(1))
            dead = pid in dead_pids or (pid != os.getpid() and not _pid_alive(pid))
            if dead and is_real_dir(p) and pid in dead_pids:  # a killed worker's, before its mark
                shutil.rmtree(p, ignore_errors=True)
                removed.append(p)
            elif dead and is_real_file(p):  # a temporary file of a killed writer
                remove_temp_file(p)
                removed.append(p)
            continue
        try:
            pid = int((p / STAGING_MARK).read_text().split()[0])
        except (OSError, ValueError, IndexError):  # the mark being written right now (empty): the pid in the name
            m = TEMP_NAME.fullmatch(p.name)
            pid = int(m.group(1)) if m else -1
        try:
            old_enough = time.time() - os.lstat(p / STAGING_MARK).st_mtime > STALE_AFTER_S
        except OSError:
            old_enough = False
        if only_dead and pid > 0 and pid != os.getpid() and pid not in dead_pids and not old_enough and _pid_alive(pid):
            continue
        shutil.rmtree(p, ignore_errors=True)
        removed.append(p)
    return removed


def remove_active_staging() -> None:
    """Remove this process's staging folders and temporary files (called from signal handlers
    before exiting)."""
    remove_active()


@contextmanager
def staged_dir(target: Path, owns: tuple[str, ...] = (), writer: str | None = None, force: bool = False,
               kept: list | None = None, root: Path | None = None, spare: list | None = None) -> Iterator[Path]:
    """Yield an empty staging folder; on success its files move into `target`, on error it vanishes.

    Files are moved one by one with :func:`os.replace` (atomic per file), only after everything
    was written, so a failed run leaves no half-written file and keeps what `target` had; the
    folders it had to create are removed again. `owns` lists glob patterns of the files the
    command `writer` writes: an older file matching them that this run did not write again is
    removed only if the manifest says `writer` wrote it, no other command's last run claims it,
    and its bytes are unchanged. A file of the same name that this program did not write, or a
    `target` that is a symbolic link, is refused with a TmmError; a file the user changed is kept
    and the new version written beside it (or, with `force`, replaced after a backup): each such
    file is appended to `kept` (:class:`Kept`). With `root`, every folder between it and `target`
    must be a real folder (a batch's student folders). `spare` (read when the files move in, so the
    caller may fill it while writing): glob patterns of older files that stay even though this run
    did not write them again (a note that failed keeps the folder's last good note).
    """
    target = Path(target)
    if root is not None:
        check_inside(root, target)
    if os.path.islink(target):
        raise TmmError(f"{target} is a symbolic link; tmm writes only into real folders: remove the link or choose another --out")
    if os.path.lexists(target) and not is_real_dir(target):
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
        try:
            (tmp / STAGING_MARK).write_text(f"{os.getpid()}\n")
            yield tmp
            fresh = {item.name for item in tmp.iterdir()} - {STAGING_MARK}
            if root is not None:
                check_inside(root, target)
            if not os.path.lexists(target):
                target.mkdir()
                created.append(target)
        except OSError as exc:  # a full disk, a name too long, a folder gone: one line
            raise _write_error(target, exc) from None
        with lock_dir(target):  # two runs into one folder: one commits after the other
            found = _commit(tmp, target, fresh, owns, writer, force, spare or ())
        if kept is not None:
            kept.extend(found)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        remove_empty_dirs(created)
        raise
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
        _ACTIVE.discard(str(tmp))


def _write_error(where: Path, exc: OSError) -> TmmError:
    what = exc.strerror or exc.__class__.__name__
    return TmmError(f"cannot write into {where} ({what}); choose a writable folder with --out")


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


def _commit(tmp: Path, target: Path, fresh: set[str], owns, writer: str | None, force: bool, spare=()) -> list[Kept]:
    """Move the staged files into `target` and drop this writer's stale files; returns the user's
    files met (kept, or backed up under `force`)."""
    if not is_real_dir(target):
        raise TmmError(f"{target} is not a real folder; choose another --out")
    old = read_manifest(target)
    entries = dict(old["entries"])
    dest, kept = _placement(target, fresh, entries, force)
    hashes = {name: digest(tmp / name) for name in fresh}
    written = set(dest.values())
    try:
        _make_backups(target, kept)  # first: the user's version is safe whatever happens below
        # then a true superset: a crash below leaves every file listed (the new ones of unknown bytes)
        interim = dict(entries)
        for name, final in dest.items():
            interim[final] = {"sha256": None, "by": None}
        write_manifest(target, set(interim), old["dirs"], interim)
        backed = {k.name for k in kept if k.backup}
        for name, final in sorted(dest.items()):
            os.replace(tmp / name, target / final)
            entries[final] = {"sha256": hashes[name], "by": _writers(None if final in backed else entries.get(final), writer)}
        for name in sorted(set(old["entries"]) - written - {k.name for k in kept}):
            if any(fnmatch.fnmatchcase(name, pat) for pat in owns) and claims(entries[name], writer) \
                    and not any(fnmatch.fnmatchcase(name, pat) for pat in spare):
                _drop_claim(target, name, entries, writer)
        write_manifest(target, set(entries), old["dirs"], entries)
    except OSError as exc:
        raise _write_error(target, exc) from None
    return kept


def _writers(previous: dict | None, writer: str | None):
    """The writers of a file `writer` has just written over `previous` (its entry, if it was ours)."""
    if writer is None:
        return None
    if previous is None or previous.get("by") is None:
        return (writer,)
    return tuple(sorted(set(previous["by"]) | {writer}))


def _drop_claim(folder: Path, name: str, entries: dict, writer: str | None) -> None:
    """`writer`'s last run no longer wrote `name`: take its claim away; the last claim gone, the
    file goes too — unless its bytes changed (the user's now: kept, still listed)."""
    e = entries[name]
    rest = () if e.get("by") is None or writer is None else tuple(w for w in e["by"] if w != writer)
    if rest:
        entries[name] = {**e, "by": rest}
        return
    path = folder / name
    if not os.path.lexists(path):
        del entries[name]
    elif unchanged(path, e):
        path.unlink()
        del entries[name]
    else:
        entries[name] = {**e, "by": ()}


def write_owned(folder: Path, name: str, data: bytes, writer: str | None = None, force: bool = False,
                kept: list | None = None) -> Path:
    """Write one file (summary.csv, check.md) into `folder` atomically and record it as ours;
    returns the path written.

    Refused (TmmError) when a file of that name exists that this program did not write; a file of
    that name the user changed is kept and the new version goes beside it (``summary.new.csv``),
    or with `force` it is replaced after a backup; either is appended to `kept`.
    """
    folder = Path(folder)  # the --out folder the user named (it may be a link the user made)
    make_dirs(folder)
    man = read_manifest(folder)
    entries = dict(man["entries"])
    dest, found = _placement(folder, [name], entries, force)
    final = dest[name]
    try:
        _make_backups(folder, found)
        interim = {**entries, final: {"sha256": None, "by": None}}
        write_manifest(folder, set(interim), man["dirs"], interim)
        atomic_write(folder, final, data)
        import hashlib

        backed = {k.name for k in found if k.backup}
        entries[final] = {"sha256": hashlib.sha256(data).hexdigest(),
                          "by": _writers(None if final in backed else entries.get(final), writer)}
        write_manifest(folder, set(entries), man["dirs"], entries)
    except OSError as exc:
        raise TmmError(f"cannot write {folder / final} ({exc.strerror}); choose a writable folder with --out") from None
    if kept is not None:
        kept.extend(found)
    return folder / final


def remove_written_tree(root: Path, rel: str, writer: str | None = None) -> bool:
    """Remove the folder `root/rel` that this program wrote: only the files its manifest lists as
    `writer`'s (and no other command's) with their bytes unchanged, then the folder (and `rel`'s
    parents below `root`) when empty. Never follows a symbolic link. Returns True when the folder
    is gone, False when something not ours keeps it.
    """
    root = Path(root)
    parts = rel.split("/")
    if not all(plain_name(c) for c in parts):
        return False
    chain = [root.joinpath(*parts[: i + 1]) for i in range(len(parts))]
    if not all(is_real_dir(p) for p in chain):
        return not any(os.path.lexists(p) for p in chain[-1:])
    folder = chain[-1]
    man = read_manifest(folder)
    for sub in sorted(man["dirs"], reverse=True):
        remove_written_tree(folder, sub, writer)
    entries = dict(man["entries"])
    for name in sorted(man["entries"]):
        if claims(entries[name], writer):
            _drop_claim(folder, name, entries, writer)
    remove_stale_staging(folder, only_dead=True)
    if is_real_file(folder / MANIFEST):
        leftovers = [p for p in folder.iterdir() if p.name != MANIFEST]
        if not leftovers:
            (folder / MANIFEST).unlink()
        elif entries != man["entries"]:
            write_manifest(folder, set(entries), man["dirs"], entries)
    for d in reversed(chain):
        try:
            os.rmdir(d)
        except OSError:
            return d != folder and not os.path.lexists(folder)
    return True


def folder_writers(folder: Path) -> set[str]:
    """The commands whose files the folder's manifest lists ('?' for an older tmm's, unknown)."""
    out = set()
    for e in read_manifest(folder)["entries"].values():
        out.update(e["by"] if e.get("by") is not None else ("?",))
    return out


# writers -----------------------------------------------------------------------------------------


def staged_names(tmp: Path) -> list[str]:
    """The names of the files written so far into the staging folder `tmp` (its mark left out), sorted."""
    return sorted(p.name for p in Path(tmp).iterdir() if p.name != STAGING_MARK)


def final_names(names, kept) -> list[str]:
    """The names as they landed: a file of the user's kept makes its new version land beside it.

    >>> final_names(["a.png", "note.typ"], [Kept("f", "note.typ", beside="note.new.typ")])
    ['a.png', 'note.new.typ']
    """
    moved = {k.name: k.beside for k in kept if k.beside}
    return sorted(moved.get(n, n) for n in names)


def write_text(path: Path, text: str) -> None:
    Path(path).write_text(text, encoding="utf-8")
