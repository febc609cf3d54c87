"""Typesetting the note in a child process: bounded memory, Ctrl-C within a second, one line on failure.

typst compiles in native code that holds Python's signal handlers off until it returns (Ctrl-C
was ignored for the whole compile) and allocates as much memory as a template asks for (a hostile
one ended in SIGABRT with a Rust backtrace). So the compile runs in a child Python: its memory is
limited with ``resource.setrlimit`` where the system allows (RLIMIT_DATA on Linux, RLIMIT_AS on
other Unix systems; Windows: no limit), Ctrl-C or SIGTERM in the parent kill it at once, and on
Linux it dies with its parent. Whatever happens, the caller gets a TmmError of one line: typst's
message and where it points, or the memory limit, or the signal that stopped it; never the
child's output nor any file's content.

typst is a sandbox here (docs/limits.md): packages are off — the child's home, data and cache
folders are an empty folder of its own (no ``@local`` package, nothing from ``$HOME``), its package
paths point there and its network goes to a closed port (no ``@preview`` download); typst reads
only the files under the root it is given (the folder of files tmm wrote, or for `tmm note` a copy
of the folder's regular files); a compile that runs longer than ``limits.TYPST_SECONDS`` is killed.
"""

from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

from ... import limits
from ...errors import TmmError

_CHILD = "import sys; from tmm_cli.render.note.typeset import _child_main; _child_main(sys.argv[1:])"
# The fonts the note is set in, shipped with tmm (SIL OFL 1.1, see fonts/LICENSE-*.txt): the system's
# fonts are not consulted, so the pages break alike everywhere, and a font tmm does not ship is an
# error, not a silent fallback.
FONTS_DIR = Path(__file__).with_name("fonts")
FONT_FAMILIES = ("Liberation Serif", "STIX Math")
RECYCLE_AFTER = 32  # compiles one child serves (typst's caches grow): then a fresh one


class _Child:
    """The typst process of this process: compiles one note per request (a line of JSON on its
    stdin, the answer a line on its stdout), so a batch worker loads the fonts once, not per row.
    Its stderr goes to a temporary file (read only to tell why it died: never a pipe that could
    fill up)."""

    def __init__(self, memory: int):
        import tempfile

        from ...output.interrupt import add_child

        self.memory, self.owner, self.served = memory, os.getpid(), 0
        self.err = tempfile.TemporaryFile()
        self.home = tempfile.mkdtemp(prefix="tmm-typst-")  # empty: no packages, nothing of the user's
        self.proc = subprocess.Popen([sys.executable, "-c", _CHILD, str(memory), self.home], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, stderr=self.err, env=sandbox_env(self.home),
                                     close_fds=True)
        add_child(self.proc.pid)

    def ask(self, request: dict) -> dict:
        """The child's answer; on its death a dict {"died": reason}."""
        self.served += 1
        seconds = limits.TYPST_SECONDS
        try:
            self.proc.stdin.write((json.dumps(request) + "\n").encode("utf-8"))
            self.proc.stdin.flush()
            if not _wait_readable(self.proc.stdout, seconds):
                self.kill()
                return {"died": f"typst ran longer than the limit of {seconds:g} s"}
            line = self.proc.stdout.readline()
        except (BrokenPipeError, OSError):
            line = b""
        if line:
            try:
                return json.loads(line.decode("utf-8"))
            except ValueError:  # not an answer: end it
                self.proc.kill()
        self.proc.wait()  # it is gone (or going): why, from its exit and its stderr
        self.err.seek(0)
        why = _reason(self.proc.returncode, self.err.read(1 << 16), self.memory)
        self.kill()
        return {"died": why}

    def kill(self) -> None:
        from ...output.interrupt import remove_child

        try:
            self.proc.kill()
        except OSError:
            pass
        self.proc.wait()
        remove_child(self.proc.pid)
        self._clean()

    def close(self) -> None:
        from ...output.interrupt import remove_child

        try:
            self.proc.stdin.close()
            self.proc.wait(2)
        except (OSError, subprocess.TimeoutExpired):
            self.proc.kill()
            self.proc.wait()
        remove_child(self.proc.pid)
        self._clean()

    def _clean(self) -> None:
        import shutil

        if not self.err.closed:
            self.err.close()
        shutil.rmtree(self.home, ignore_errors=True)


# the child's environment: a home of its own (typst looks for @local packages in the data folder and
# caches @preview ones in the cache folder, both under it) and no way out to the network
_HOME_VARS = ("HOME", "USERPROFILE", "XDG_DATA_HOME", "XDG_CACHE_HOME", "XDG_CONFIG_HOME", "APPDATA", "LOCALAPPDATA",
              "TYPST_PACKAGE_PATH", "TYPST_PACKAGE_CACHE_PATH")
_PROXY_VARS = ("HTTPS_PROXY", "https_proxy", "HTTP_PROXY", "http_proxy", "ALL_PROXY", "all_proxy")
_NO_NETWORK = "http://127.0.0.1:9"  # the discard port: a refused connection, at once


def sandbox_env(home: str) -> dict:
    """The typst child's environment: `home` (an empty folder) for every home, data and cache
    folder, every proxy pointing at a closed local port, no proxy exceptions."""
    env = dict(os.environ, RUST_BACKTRACE="0", PYTHONIOENCODING="utf-8")
    env.update({k: home for k in _HOME_VARS})
    env.update({k: _NO_NETWORK for k in _PROXY_VARS})
    for k in ("NO_PROXY", "no_proxy", "SSL_CERT_FILE", "SSL_CERT_DIR"):
        env.pop(k, None)
    return env


def _wait_readable(stream, seconds: float) -> bool:
    """True when `stream` has something to read within `seconds` (select; where pipes cannot be
    selected, Windows, True at once: no time limit there)."""
    if os.name == "nt":  # pragma: no cover
        return True
    import select
    import time

    end = time.monotonic() + seconds
    while True:
        left = end - time.monotonic()
        if left <= 0:
            return False
        try:
            ready, _, _ = select.select([stream], [], [], left)
        except InterruptedError:  # pragma: no cover - PEP 475 retries; kept for old kernels
            continue
        return bool(ready)


_CHILDREN: list[_Child] = []  # this process's (a forked process starts its own)


def _child() -> _Child:
    limit = limits.TYPST_MEMORY_BYTES
    if _CHILDREN:
        c = _CHILDREN[0]
        if c.owner != os.getpid():  # inherited through a fork: not ours to talk to
            _CHILDREN.clear()
        elif c.memory != limit or c.served >= RECYCLE_AFTER or c.proc.poll() is not None:
            _CHILDREN.clear()
            c.close()
    if not _CHILDREN:
        if not _ATEXIT:
            import atexit

            atexit.register(_close_child)
            _ATEXIT.append(True)
        _CHILDREN.append(_Child(limit))
    return _CHILDREN[0]


_ATEXIT: list = []


def _close_child() -> None:
    if _CHILDREN and _CHILDREN[0].owner == os.getpid():
        _CHILDREN.pop().close()


def typeset(root: Path, source: str, output: str, shown: Path | None = None) -> Path:
    """Compile ``root/source`` to ``root/output`` with typst's root at `root`; TmmError (one line)
    on any failure. `shown` replaces `root` in a message (a private copy's path means nothing to
    the user)."""
    root = Path(root)
    try:
        child = _child()
    except OSError as exc:
        raise TmmError(f"the note could not be typeset (cannot start typst: {exc.strerror}); check the note template "
                       f"or {source}") from None
    try:
        answer = child.ask({"root": os.path.abspath(root), "source": source, "output": output})  # its cwd may differ
    except BaseException:  # Ctrl-C, SIGTERM: the compile ends now, not when typst is done
        _CHILDREN.clear()
        child.kill()
        raise
    if "died" in answer:
        _CHILDREN.clear()
    if answer.get("ok"):
        return root / output
    why = answer.get("died") or " ".join(str(answer.get("message") or "typst failed").split())[:300]
    if shown is not None:
        why = why.replace(os.path.abspath(root), str(shown)).replace(str(root), str(shown))
    raise TmmError(f"the note could not be typeset ({why}); check the note template or {source}")


PAGES_LABEL = "tmm-pages"
PAGES_SOURCE = """#include "{source}"
#context [#metadata((pages: query(heading.where(outlined: true)).filter(h => h.level <= 2).map(h => counter(page).at(h.location()).first()), total: counter(page).final().first())) <tmm-pages>]
"""


def page_numbers(root: Path, source: str = "note.typ") -> dict | None:
    """The pages of the note as typst lays it out: {"pages": the page of each heading of the
    contents (levels 1–2, in order), "total": the number of pages}, or None when it cannot be had
    (the DOCX then goes without them). A private source beside `source` includes it and asks typst
    (one more layout, in the same child)."""
    root = Path(root)
    probe = root / ".tmm-pages.typ"
    child = None
    try:
        probe.write_text(PAGES_SOURCE.format(source=source), encoding="utf-8")
        child = _child()
        answer = child.ask({"root": os.path.abspath(root), "source": probe.name, "query": "<" + PAGES_LABEL + ">"})
    except OSError:
        return None
    except BaseException:  # Ctrl-C, SIGTERM: the child ends now
        _CHILDREN.clear()
        if child is not None:
            child.kill()
        raise
    finally:
        probe.unlink(missing_ok=True)
    if "died" in answer:
        _CHILDREN.clear()
    value = answer.get("value") if answer.get("ok") else None
    if not isinstance(value, dict) or not isinstance(value.get("pages"), list):
        return None
    return value


def _reason(code: int, err: bytes, memory: int) -> str:
    """Why the child died, in a few words (never its output).

    >>> _reason(-6, b"memory allocation of 268435472 bytes failed\\nstack backtrace: ...", 2 << 30)
    'typst needed more memory than the limit of 2048 MiB'
    >>> _reason(-9, b"", 2 << 30), _reason(3, b"", 2 << 30)
    ('typst stopped (SIGKILL)', 'typst stopped (exit status 3)')
    """
    if b"memory allocation of" in err or b"MemoryError" in err or b"out of memory" in err.lower():
        return f"typst needed more memory than the limit of {memory >> 20} MiB"
    if code is not None and code < 0:
        try:
            name = signal.Signals(-code).name
        except ValueError:
            name = f"signal {-code}"
        return f"typst stopped ({name})"
    return f"typst stopped (exit status {code})"


def _typst_error(exc: Exception) -> str:
    """'unknown variable: n1 at note.typ:2:7' from a typst error (its diagnostic names the place)."""
    message = getattr(exc, "message", None) or next((ln.strip() for ln in str(exc).splitlines() if ln.strip()),
                                                     exc.__class__.__name__)
    where = re.search(r"┌─\s*(\S+:\d+:\d+)", str(getattr(exc, "diagnostic", "") or ""))
    return f"{message} at {where.group(1)}" if where else str(message)


def _limit_memory(limit: int) -> None:
    try:
        import resource
    except ImportError:  # pragma: no cover - Windows
        return
    which = resource.RLIMIT_DATA if sys.platform.startswith("linux") else getattr(resource, "RLIMIT_AS", None)
    if which is None:  # pragma: no cover
        return
    try:
        soft, hard = resource.getrlimit(which)
        cap = limit if hard == resource.RLIM_INFINITY else min(limit, hard)
        resource.setrlimit(which, (cap, hard))
    except (ValueError, OSError):  # not allowed here: go on unlimited
        pass


def _compile(typst, source: str, **kw):
    """typst.compile_with_warnings; its package paths where the installed typst takes them (0.15 and
    later; before, the child's environment alone keeps the packages away)."""
    try:
        return typst.compile_with_warnings(source, **kw)
    except TypeError as exc:
        if "package" not in str(exc):
            raise
        kw.pop("package_path", None)
        kw.pop("package_cache_path", None)
        return typst.compile_with_warnings(source, **kw)


def _child_main(argv: list[str]) -> None:
    """The child: `memory_bytes` `home`; then for each request line {"root", "source", "output"} one
    answer line {"ok": true} or {"message": …}, until its stdin ends."""
    memory, home = argv
    if signal.getsignal(signal.SIGINT) is signal.default_int_handler:  # Ctrl-C kills it even inside typst
        signal.signal(signal.SIGINT, signal.SIG_DFL)
    if sys.platform.startswith("linux"):
        try:
            import ctypes

            ctypes.CDLL(None).prctl(1, int(signal.SIGKILL), 0, 0, 0)  # PR_SET_PDEATHSIG: die with the parent
        except (OSError, AttributeError):
            pass
    _limit_memory(int(memory))
    out = sys.stdout

    def answer(obj: dict) -> None:
        out.write(json.dumps(obj, ensure_ascii=False) + "\n")
        out.flush()

    try:
        import typst
    except ImportError:
        typst = None
    for line in sys.stdin:
        request = json.loads(line)
        if typst is None:
            answer({"message": "the typst package is missing; reinstall tmm (pip install tmm)"})
            continue
        base = Path(request["root"])
        if request.get("query"):
            try:
                value = typst.query(str(base / request["source"]), request["query"], field="value", one=True,
                                    root=str(base), font_paths=[str(FONTS_DIR)], ignore_system_fonts=True)
                answer({"ok": True, "value": json.loads(value) if isinstance(value, str) else value})
            except MemoryError:
                answer({"message": "memory"})
            except Exception as exc:  # typst.TypstError and its relatives
                answer({"message": _typst_error(exc)})
            continue
        try:
            _, warnings = _compile(typst, str(base / request["source"]), output=str(base / request["output"]),
                                   root=str(base), font_paths=[str(FONTS_DIR)], ignore_system_fonts=True,
                                   package_path=home, package_cache_path=home)
        except MemoryError:
            answer({"message": f"typst needed more memory than the limit of {int(memory) >> 20} MiB"})
        except Exception as exc:  # typst.TypstError and its relatives
            answer({"message": _typst_error(exc)})
        else:
            fonts = [str(getattr(w, "message", w)) for w in warnings if "unknown font family" in str(getattr(w, "message", w))]
            if fonts:
                (base / request["output"]).unlink(missing_ok=True)
                answer({"message": f"{fonts[0]}; tmm ships {' and '.join(FONT_FAMILIES)} only"})
            else:
                answer({"ok": True})


# a typst root holding only regular files ----------------------------------------------------------


_OPEN_SRC = os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0)


def _copy_regular(src: Path, dst: Path, budget: list[int]) -> bool:
    """Copy the regular file `src` (never through a link) to the new file `dst`; False if it is
    not one or cannot be read; TmmError when the copies pass the byte budget."""
    import stat

    try:
        fd = os.open(src, _OPEN_SRC)
    except OSError:
        return False
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            return False
        budget[0] -= st.st_size
        if budget[0] < 0:
            raise TmmError(f"the folder of the note holds more than {limits.NOTE_FOLDER_BYTES >> 20} MiB of files; keep "
                           f"the note in a folder of its own")
        with open(dst, "xb") as out:
            while chunk := os.read(fd, 1 << 20):
                out.write(chunk)
        return True
    except OSError:
        return False
    finally:
        os.close(fd)


def _fill(src: Path, dst: Path, depth: int, count: list[int], budget: list[int]) -> None:
    """Put into `dst` a hard link to (or a copy of) every regular file under `src`, following no
    link and skipping hidden entries (our staging folders, the manifest, .git)."""
    import stat

    try:
        entries = list(os.scandir(src))
    except OSError:
        return
    for e in entries:
        if e.name.startswith("."):
            continue
        try:
            st = e.stat(follow_symlinks=False)
        except OSError:
            continue
        if stat.S_ISDIR(st.st_mode):
            if depth > 0:
                os.mkdir(dst / e.name, 0o700)
                _fill(src / e.name, dst / e.name, depth - 1, count, budget)
            continue
        if not stat.S_ISREG(st.st_mode):
            continue  # a link, a FIFO, a device: typst never sees it
        count[0] -= 1
        if count[0] < 0:
            raise TmmError(f"the folder of the note holds more than {limits.NOTE_FOLDER_FILES} files; keep the note in a "
                           f"folder of its own")
        target = dst / e.name
        try:
            os.link(src / e.name, target, follow_symlinks=False)
            if stat.S_ISREG(os.lstat(target).st_mode):
                continue
            os.unlink(target)  # it became a link after we looked: not that
        except (OSError, NotImplementedError):  # another file system (EXDEV), no hard links (FAT), Windows
            pass
        _copy_regular(src / e.name, target, budget)


_PACKAGE = re.compile(r"""(?:import|include)\s*\(?\s*"(@[^"\n]{0,80})""")


def _refuse_packages(root: Path, source: str, shown: Path) -> None:
    """TmmError naming `source` when it imports a typst package: the sandbox has none (the note
    needs none; what a department's style needs is copied into the folder). A package imported
    any other way fails in the sandbox itself."""
    for path in (root / source,):
        try:
            text = path.read_text(encoding="utf-8", errors="replace")
        except OSError:
            continue
        m = _PACKAGE.search(text)
        if m:
            where = shown / path.relative_to(root)
            line = text.count("\n", 0, m.start()) + 1
            raise TmmError(f"{where}:{line} imports the typst package {m.group(1)}; tmm compiles with packages off "
                           f"(nothing outside the folder is read): copy the files the note needs into its folder")


def typeset_in_copy(folder: Path, source: str, pdf: Path) -> Path:
    """`tmm note`: compile ``folder/source`` with a typst root that holds only the regular files of
    `folder` (hard links, or copies), so a symbolic link planted in the folder leads typst nowhere;
    the PDF replaces `pdf` at once (a link there is replaced, never written through)."""
    from ...output.folder import _ACTIVE, _new_staging

    folder = Path(folder)
    try:
        root = _new_staging(folder, "note")
    except OSError as exc:
        raise TmmError(f"cannot write {pdf} ({exc.strerror})") from None
    try:
        _fill(folder, root, limits.NOTE_FOLDER_DEPTH, [limits.NOTE_FOLDER_FILES], [limits.NOTE_FOLDER_BYTES])
        if not (root / source).is_file():
            raise TmmError(f"{folder / source} is not a regular file; tmm compiles only a real note.typ (not a link)")
        _refuse_packages(root, source, folder)
        out = f".out-{os.urandom(4).hex()}.pdf"
        typeset(root, source, out, shown=folder)
        try:
            os.replace(root / out, pdf)
        except OSError as exc:
            raise TmmError(f"cannot write {pdf} ({exc.strerror})") from None
    finally:
        import shutil

        shutil.rmtree(root, ignore_errors=True)
        _ACTIVE.discard(str(root))
    return pdf
