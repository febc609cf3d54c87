"""Writing results to disk, atomically: a run either leaves all its files or none.

Everything is first written into a staging folder beside the target and moved into place at the
end, so an error part-way leaves no half-written file.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

from ..errors import TmmError

FIGURE_FORMATS = ("png", "svg", "pdf")


def ensure_writable_dir(path: Path) -> Path:
    """Create `path` (and parents) and check that files can be written there; TmmError if not."""
    path = Path(path)
    try:
        path.mkdir(parents=True, exist_ok=True)
        probe = tempfile.NamedTemporaryFile(dir=path, prefix=".tmm-probe-", delete=True)
        probe.close()
    except OSError as exc:
        reason = exc.strerror or exc.__class__.__name__
        raise TmmError(f"cannot write to output folder {path} ({reason}); choose a writable folder with --out") from None
    return path


@contextmanager
def staged_dir(target: Path, owns: tuple[str, ...] = ()) -> Iterator[Path]:
    """Yield an empty staging folder; on success its files move into `target`, on error it vanishes.

    Files are moved one by one with :func:`os.replace` (atomic per file), only after everything
    was written, so a failed run leaves no half-written file and keeps what `target` had.
    `owns` lists glob patterns of the files this command writes: older files matching them that
    this run did not write again (a figure of an earlier run with other options) are removed,
    so the folder never mixes results of two runs.
    """
    target = Path(target)
    parent = ensure_writable_dir(target.parent)
    tmp = Path(tempfile.mkdtemp(prefix=f".{target.name}.tmp-", dir=parent))
    try:
        yield tmp
        try:
            target.mkdir(exist_ok=True)
            fresh = {item.name for item in tmp.iterdir()}
            for pattern in owns:
                for stale in target.glob(pattern):
                    if stale.is_file() and stale.name not in fresh:
                        stale.unlink()
            for item in sorted(tmp.iterdir()):
                os.replace(item, target / item.name)
        except OSError as exc:
            raise TmmError(
                f"cannot write into {target} ({exc.strerror}); choose a writable folder with --out"
            ) from None
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def write_json(path: Path, obj) -> None:
    Path(path).write_text(json.dumps(obj, ensure_ascii=False, indent=2) + "\n", encoding="utf-8")


def write_text(path: Path, text: str) -> None:
    Path(path).write_text(text, encoding="utf-8")


def save_figures(folder: Path, figures: dict, fmt: str = "png", dpi: int = 120) -> list[Path]:
    """Save matplotlib Figures as ``folder/<name>.<fmt>``; returns the paths in order."""
    paths = []
    for name, fig in figures.items():
        p = Path(folder) / f"{name}.{fmt}"
        fig.savefig(p, format=fmt, dpi=dpi)  # every figure uses the constrained layout
        paths.append(p)
    return paths
