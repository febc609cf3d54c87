"""Install tmm in a fresh virtual environment with every dependency at its declared floor (or at
its newest release) and try it: a smoke of the main commands, then the test suite.

    python tools/floors.py floors                  # every dependency pinned to the floor pyproject.toml declares
    python tools/floors.py newest                  # every dependency at its newest release (pip install -U)
    python tools/floors.py constraints             # print the floors as pip constraints (name==version)
    python tools/floors.py floors --pin click==8.2.0 --venv /tmp/v --tests none   # try another floor

The floors are read from ``[project] dependencies`` and the ``test`` extra of pyproject.toml: each
must be ``name>=version`` (a dependency with no floor is an error). Transitive dependencies are left
to pip, as a user's install leaves them. The pinned dependencies come as wheels only: a floor with
no wheel for that Python is a floor nobody can install, and building numpy from source is no test.

The floors are installed with the lowest Python the package allows (``requires-python``:
``python3.11`` if it is on PATH; newer Pythons have no wheels of the old releases), the newest
releases with the Python that runs this. `tests/test_floors.py` runs both (marked ``floors``:
``pytest -m floors``, or ``TMM_FLOORS=1 pytest tests/test_floors.py``).
"""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "docs" / "examples"
_FLOOR = re.compile(r"^\s*([A-Za-z0-9][A-Za-z0-9._-]*)\s*>=\s*([0-9][0-9A-Za-z.+-]*)\s*$")


def requirements(pyproject: Path = ROOT / "pyproject.toml", extras: tuple[str, ...] = ("test",)) -> list[str]:
    """The requirement strings of the package and of its `extras`, as written."""
    project = tomllib.loads(pyproject.read_text(encoding="utf-8"))["project"]
    reqs = list(project.get("dependencies", []))
    for extra in extras:
        reqs += project.get("optional-dependencies", {}).get(extra, [])
    return reqs


def floors(pyproject: Path = ROOT / "pyproject.toml", extras: tuple[str, ...] = ("test",)) -> dict[str, str]:
    """{name: floor version} of every requirement; each must be a plain ``name>=version``.

    >>> import tempfile, pathlib
    >>> p = pathlib.Path(tempfile.mkdtemp()) / "pyproject.toml"
    >>> _ = p.write_text('[project]\\ndependencies = ["numpy>=1.25.2", "click >= 8.2"]\\n'
    ...                  '[project.optional-dependencies]\\ntest = ["pypdf>=7.1"]\\n')
    >>> floors(p)
    {'numpy': '1.25.2', 'click': '8.2', 'pypdf': '7.1'}
    """
    out = {}
    for req in requirements(pyproject, extras):
        m = _FLOOR.match(req)
        if not m:
            raise ValueError(f"{req!r} in {pyproject.name}: a dependency needs a plain floor, name>=version")
        out[m.group(1).lower()] = m.group(2)
    return out


def constraints(pins: dict[str, str]) -> str:
    """pip constraints pinning each name to its version."""
    return "".join(f"{name}=={version}\n" for name, version in pins.items())


def _run(cmd: list[str], log, cwd: Path | None = None, env: dict | None = None, ok=(0,)) -> subprocess.CompletedProcess:
    t0 = time.perf_counter()
    done = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, encoding="utf-8", errors="replace")
    log(f"$ {' '.join(map(str, cmd))}  -> exit {done.returncode} in {time.perf_counter() - t0:.1f} s")
    if done.returncode not in ok:
        raise RuntimeError(f"{' '.join(map(str, cmd))} exited {done.returncode}\n--- stdout\n{done.stdout[-4000:]}"
                           f"\n--- stderr\n{done.stderr[-4000:]}")
    return done


def make_venv(venv: Path, python: str, log) -> Path:
    """A virtual environment at `venv` (made with `python` unless it is there); its python."""
    py = venv / "bin" / "python"
    if not py.exists():
        _run([python, "-m", "venv", str(venv)], log)
        _run([str(py), "-m", "pip", "install", "-q", "--upgrade", "pip"], log)
    return py


def install(py: Path, mode: str, pins: dict[str, str], log) -> dict[str, str]:
    """tmm with its test extra into the venv of `py`: `mode` "floors" pins every dependency to
    `pins` (its floor, or what --pin said), "newest" upgrades everything. Returns {name: version}
    of the dependencies as installed."""
    pip = [str(py), "-m", "pip", "install", "-q", "--disable-pip-version-check"]
    target = f"{ROOT}[test]"
    if mode == "floors":
        with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as fh:
            fh.write(constraints(pins))
        try:
            # wheels only for the pinned dependencies; tmm itself (a folder) is built by pip as usual
            _run(pip + ["--only-binary", ",".join(pins), "--constraint", fh.name, target], log)
        finally:
            os.unlink(fh.name)
    else:
        _run(pip + ["--upgrade", "--upgrade-strategy", "eager", target], log)
    names = list(floors())
    code = ("import importlib.metadata as m, json, sys; "
            "print(json.dumps({n: m.version(n) for n in sys.argv[1:]}))")
    import json

    return json.loads(_run([str(py), "-c", code, *names], log).stdout)


def smoke(py: Path, log) -> list[str]:
    """The main commands, run from the venv's `tmm` in an empty folder: each must exit as expected
    and write its files. Returns one line per command."""
    tmm = str(py.parent / "tmm")
    env = {**os.environ, "MPLBACKEND": "Agg", "PYTHONIOENCODING": "utf-8"}
    env.pop("PYTHONPATH", None)
    e = EXAMPLES
    commands = [  # (arguments, expected exit, files that must exist afterwards)
        (["--help"], 0, []),
        (["project", "--variant", "17", "--out", "p"], 0,
         ["p/variant-17/results.json", "p/variant-17/cam_profile.png", "p/variant-17/gears_mesh.png",
          "p/variant-17/note.pdf", "p/variant-17/sheet3.pdf", "p/variant-17/sheet4.dxf"]),
        (["--lang", "en", "cam", "--variant", "3", "--out", "c"], 0, ["c/variant-03/cam.json", "c/variant-03/cam_motion.png"]),
        (["gears", "--variant", "65", "--out", "g"], 0, ["g/variant-65/gears.json", "g/variant-65/gears_planetary.png"]),
        (["batch", "--variants", "1-3", "--no-plots", "--out", "b"], 0, ["b/summary.csv"]),
        (["check", "--variant", "17", "--crank-rpm", "95", "--answers", str(e / "answers-Ivanov.toml")], 0, []),
        (["check", "--roster", str(e / "roster.csv"), "--answers-dir", str(e / "answers"), "--out", "k"], 1,
         ["k/check.csv"]),  # two of the three example students do not pass: exit 1 by design
        (["linkage", str(e / "shaper.toml"), "--out", "l"], 0, ["l/linkage/linkage.json", "l/linkage/linkage_diagrams.png"]),
        (["carrier", str(e / "carrier-5.csv"), "--radius", "125", "--out", "r"], 0, ["r/carrier/carrier.json", "r/carrier/carrier.png"]),
        (["note", "p/variant-17"], 0, ["p/variant-17/note.pdf"]),
        (["assign", "--roster", str(e / "roster.csv"), "--out", "a"], 0, ["a/assignments.pdf", "a/assignment-Ivanov.pdf"]),
    ]
    lines = []
    with tempfile.TemporaryDirectory(prefix="tmm-smoke-") as d:
        cwd = Path(d)
        for args, rc, files in commands:
            t0 = time.perf_counter()
            done = _run([tmm, *args], log, cwd=cwd, env=env, ok=(rc,))
            missing = [f for f in files if not (cwd / f).is_file() or (cwd / f).stat().st_size == 0]
            if missing:
                raise RuntimeError(f"tmm {' '.join(args)} wrote no {', '.join(missing)}\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
            if done.stderr.strip() and rc == 0:
                raise RuntimeError(f"tmm {' '.join(args)} wrote to stderr:\n{done.stderr[-3000:]}")
            lines.append(f"tmm {' '.join(args)}: exit {rc}, {time.perf_counter() - t0:.1f} s")
    return lines


def suite(py: Path, tests: str, log) -> str:
    """The test suite (`tests` "all"), the figure tests ("figures") or nothing ("none"), run by
    the venv's pytest on this folder's code (the smoke tried the package as installed). Returns pytest's closing line."""
    if tests == "none":
        return "tests not run"
    if tests == "figures":
        paths = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "tests").glob("test_*figure*.py"))
        paths += ["tests/test_project_two_processes.py", "tmm_cli/render/figures"]
    else:
        paths = []
    # the tests collect the doctests of this folder's modules: tmm installed from here in
    # editable mode (as CI does; the dependencies stay as they are), else pytest refuses them
    _run([str(py), "-m", "pip", "install", "-q", "--disable-pip-version-check", "--no-deps", "-e", str(ROOT)], log)
    env = {**os.environ, "MPLBACKEND": "Agg", "PYTHONIOENCODING": "utf-8"}
    env.pop("PYTHONPATH", None)
    env.pop("TMM_FLOORS", None)
    # -p no:warnings: the old releases' deprecation warnings (pyparsing's, thousands) would bury the failures
    done = _run([str(py.parent / "pytest"), "-q", "-p", "no:cacheprovider", "-p", "no:warnings", *paths], log,
                cwd=ROOT, env=env, ok=(0, 1))
    tail = [ln for ln in done.stdout.splitlines() if ln.strip()][-1:]
    if done.returncode:
        failures = done.stdout[done.stdout.find("= FAILURES ="):][:6000]
        summary = done.stdout[done.stdout.find("short test summary info"):][-4000:]
        raise RuntimeError(f"the tests failed:\n{failures}\n...\n{summary}\n{done.stderr[-2000:]}")
    return tail[0] if tail else ""


def lowest_python(pyproject: Path = ROOT / "pyproject.toml") -> str:
    """The interpreter of the lowest Python the package allows (``requires-python = ">=3.11"`` →
    ``python3.11``) if it is on PATH, else this one."""
    import shutil

    spec = tomllib.loads(pyproject.read_text(encoding="utf-8"))["project"].get("requires-python", "")
    m = re.match(r"\s*>=\s*(\d+)\.(\d+)", spec)
    found = shutil.which(f"python{m.group(1)}.{m.group(2)}") if m else None
    return found or sys.executable


def check(mode: str, python: str | None = None, venv: Path | None = None, pins: dict[str, str] | None = None,
          tests: str = "all", log=print) -> dict:
    """Install (see :func:`install`), smoke and test; returns what was installed and what ran.
    `python` is by default the lowest Python the package allows for the floors, this one for the
    newest releases."""
    wanted = {**floors(), **(pins or {})}
    python = python or (lowest_python() if mode == "floors" else sys.executable)
    with tempfile.TemporaryDirectory(prefix=f"tmm-{mode}-") as d:
        py = make_venv(venv or Path(d) / "venv", python, log)
        versions = install(py, mode, wanted, log)
        if mode == "floors":
            off = {n: v for n, v in versions.items() if _norm(v) != _norm(wanted[n])}
            if off:
                raise RuntimeError(f"pip installed {off} instead of the floors {wanted}")
        python_version = _run([str(py), "-c", "import sys; print(sys.version.split()[0])"], log).stdout.strip()
        hooks = _run([str(py), "-c", "from tmm_cli.render.figures import agg; print(' '.join(sorted(agg.hooks())) or 'none')"],
                     log, cwd=Path(d)).stdout.strip()
        return {"python": python_version, "versions": versions, "hooks": hooks, "smoke": smoke(py, log),
                "tests": suite(py, tests, log)}


def _norm(version: str) -> tuple:
    """'8.2' and '8.2.0' alike."""
    parts = [int(p) if p.isdigit() else p for p in re.split(r"[.]", version)]
    while parts and parts[-1] == 0:
        parts.pop()
    return tuple(parts)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mode", choices=("floors", "newest", "constraints"))
    ap.add_argument("--python", help="the interpreter to make the venv with (default: the lowest Python the "
                                     "package allows for the floors, if on PATH; this one for the newest)")
    ap.add_argument("--venv", type=Path, help="make (or reuse) the venv here instead of a temporary one")
    ap.add_argument("--pin", action="append", default=[], metavar="NAME==VERSION", help="another floor to try")
    ap.add_argument("--tests", choices=("all", "figures", "none"), default="all")
    args = ap.parse_args()
    pins = dict(p.lower().split("==", 1) for p in args.pin)
    if args.mode == "constraints":
        sys.stdout.write(constraints({**floors(), **pins}))
        return
    t0 = time.perf_counter()
    out = check(args.mode, args.python, args.venv, pins, args.tests, log=lambda s: print(s, file=sys.stderr, flush=True))
    print(f"python {out['python']}: " + ", ".join(f"{n} {v}" for n, v in out["versions"].items()))
    print(f"matplotlib hooks in use (render/figures/agg.py): {out['hooks']}")
    print("\n".join(out["smoke"]))
    print(out["tests"])
    print(f"{args.mode}: passed in {time.perf_counter() - t0:.0f} s")


if __name__ == "__main__":
    main()
