"""The shape of the code (docs/architecture.md): imports point one way, down the floors below, and
no two modules import each other, directly or around a circle — imports inside functions count.

A new room (a top-level module or package of tmm_cli) must be given its floor in FLOORS.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "tmm_cli"

# floor of each room: a room imports only rooms on lower floors (and itself)
FLOORS = {
    "errors": 0, "records": 0,
    "notes": 1, "limits": 1,
    "i18n": 2, "inputs": 2, "output": 2, "data": 2,
    "variants": 3,
    "cam": 4, "gears": 4, "linkage": 4, "accuracy": 4,  # the chapters: pure computation
    "project": 5,
    "render": 6,
    "teacher": 7,
    "commands": 8,
    "cli": 9, "__main__": 10, "__init__": 0,
}
CHAPTERS = {"cam", "gears", "linkage", "accuracy"}


def _module(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


def _imports(path: Path) -> set[str]:
    """The tmm_cli modules `path` imports, anywhere in it (a name imported from a package counts as
    its submodule when there is one)."""
    me = _module(path)
    package = me if path.name == "__init__.py" else me.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.startswith("tmm_cli"))
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if not target.startswith("tmm_cli"):
                continue
            for alias in node.names:
                sub = f"{target}.{alias.name}"
                found.add(sub if sub in MODULES else target)
    return found


FILES = sorted(PACKAGE.rglob("*.py"))
MODULES = {_module(p) for p in FILES}
GRAPH = {_module(p): _imports(p) - {_module(p)} for p in FILES}


def _room(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "__init__"


def test_every_room_has_a_floor():
    assert {_room(m) for m in MODULES} <= set(FLOORS), {_room(m) for m in MODULES} - set(FLOORS)


@pytest.mark.parametrize("module", sorted(GRAPH))
def test_imports_point_down(module):
    here = _room(module)
    up = sorted(t for t in GRAPH[module] if _room(t) != here and FLOORS[_room(t)] >= FLOORS[here]
                and _room(t) != "__init__")
    assert not up, f"{module} imports {up}: a room on its own floor or above (see docs/architecture.md)"


def test_the_chapters_do_not_know_the_shell():
    """cam/, gears/, linkage/, accuracy/ compute: no printing, plotting, files or languages."""
    for module, targets in GRAPH.items():
        if _room(module) in CHAPTERS:
            shell = sorted(t for t in targets if _room(t) not in CHAPTERS | {"errors", "records", "notes", "limits", "variants"})
            assert not shell, (module, shell)


def test_no_circle():
    """No module reaches itself through the imports (Tarjan's strongly connected components)."""
    index, low, stack, on, circles = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in GRAPH.get(v, ()):
            if w not in GRAPH:
                continue
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                circles.append(sorted(component))

    for v in sorted(GRAPH):
        if v not in index:
            visit(v)
    assert not circles, circles


def test_the_scan_sees_the_imports():
    """The test would pass on an empty graph: check it reads what is there."""
    assert "tmm_cli.commands.options" in GRAPH["tmm_cli.commands.cam"]
    assert "tmm_cli.cam.design" in GRAPH["tmm_cli.commands.cam"]  # imported inside the command
    assert "tmm_cli.records" in GRAPH["tmm_cli.cam.motion"]
