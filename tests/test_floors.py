"""The dependency floors of pyproject.toml are true: tmm installs in a fresh venv with every
dependency pinned to its floor, its main commands run and the test suite passes; the same with
the newest releases. Marked `floors` (minutes: two venvs, two suites): ``pytest -m floors``, or
``TMM_FLOORS=1 pytest tests/test_floors.py``; ``-s`` shows what was installed and how long each
command took. TMM_FLOORS_PYTHON / TMM_NEWEST_PYTHON choose the interpreters, TMM_FLOORS_TESTS
(all, figures, none) how much of the suite runs in the venvs. The work is tools/floors.py's."""

import os
import re
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
import floors as tool  # noqa: E402


def _version(v: str) -> tuple:
    return tuple(int(x) for x in re.findall(r"\d+", v)[:3]) + (0,) * (3 - len(re.findall(r"\d+", v)[:3]))


def test_every_dependency_declares_a_floor_and_the_figure_hooks_start_at_matplotlibs():
    """Each requirement is a plain name>=version (what the floors test pins), and the matplotlib
    hooks' tested range (render/figures/agg.py) begins at the declared matplotlib floor."""
    from tmm_cli.render.figures import agg

    floors = tool.floors()
    assert {"numpy", "scipy", "click", "rich", "matplotlib", "babel", "ezdxf", "typst", "pypdf"} <= set(floors)
    assert _version(floors["matplotlib"]) == agg.TESTED[0]
    assert tool.constraints({"click": "8.2"}) == "click==8.2\n"


@pytest.mark.floors
@pytest.mark.parametrize("mode", ["floors", "newest"])
def test_installs_runs_and_passes(mode):
    python = os.environ.get("TMM_FLOORS_PYTHON" if mode == "floors" else "TMM_NEWEST_PYTHON") or None
    out = tool.check(mode, python=python, tests=os.environ.get("TMM_FLOORS_TESTS", "all"), log=lambda s: None)
    floors = tool.floors()
    for name, version in out["versions"].items():
        if mode == "floors":
            assert _version(version) == _version(floors[name]), (name, version)
        else:
            assert _version(version) >= _version(floors[name]), (name, version)
    print(f"\n{mode}: python {out['python']}: " + ", ".join(f"{n} {v}" for n, v in out["versions"].items()))
    print(f"matplotlib hooks in use: {out['hooks']}")
    print("\n".join(out["smoke"]))
    print(out["tests"])
    assert "passed" in out["tests"] or out["tests"] == "tests not run"
