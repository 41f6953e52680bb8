"""The house's shape: no import circles anywhere in yaseer, and the BASIC machine's wings
importing only the wings above them (errors, arithmetic, dialects, source, compile, machine).

Every ``import`` counts, at module level or inside a function (a deferred import is still a
dependency a reader must follow)."""

from __future__ import annotations

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent.parent / "yaseer"
WINGS = ("errors", "arithmetic", "dialects", "source", "compile", "machine")


def module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def imported_modules(path: Path, known: set[str]) -> set[str]:
    """The yaseer modules ``path`` imports (``from a.b import c`` counts as a.b.c when that is a
    module, else as a.b)."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            submodules = {f"{node.module}.{alias.name}" for alias in node.names} & known
            found.update(submodules)
            if len(submodules) < len(node.names):
                found.add(node.module)
    return {name for name in found if name in known}


def import_graph() -> dict[str, set[str]]:
    paths = {module_name(p): p for p in PACKAGE.rglob("*.py")}
    known = set(paths)
    graph = {}
    for name, path in paths.items():
        # importing a.b.c runs a/__init__ and a/b/__init__ too, but those only matter when they import
        graph[name] = {m for m in imported_modules(path, known) if m != name}
    return graph


def circles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan)."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def wing_of(module: str) -> str | None:
    parts = module.split(".")
    if parts[:2] != ["yaseer", "basic"] or len(parts) < 3:
        return None
    return parts[2]


def test_no_import_circles():
    assert circles(import_graph()) == []


def test_the_circle_finder_finds_a_circle():
    assert circles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]


def test_each_wing_imports_only_the_wings_above_it():
    wrong = []
    for module, imported in import_graph().items():
        wing = wing_of(module)
        if wing not in WINGS:
            continue
        for other in imported:
            other_wing = wing_of(other)
            if other_wing in WINGS and WINGS.index(other_wing) > WINGS.index(wing):
                wrong.append(f"{module} imports {other}")
    assert wrong == []


def test_basic_holds_only_its_wings():
    """New modules go into the wing of their stage, not beside them."""
    loose = sorted(p.name for p in (PACKAGE / "basic").glob("*.py") if p.name not in ("__init__.py", "errors.py"))
    assert loose == []
    assert sorted(p.name for p in (PACKAGE / "basic").iterdir() if p.is_dir() and p.name != "__pycache__") == sorted(
        WINGS[1:])


def test_the_machine_knows_nothing_of_mechanisms_and_linkages_nothing_of_basic():
    graph = import_graph()
    for module, imported in graph.items():
        if module.startswith("yaseer.basic"):
            assert not any(m.startswith(("yaseer.linkages", "yaseer.binding", "yaseer.animation")) for m in imported), module
        if module.startswith("yaseer.linkages"):
            assert not any(m.startswith("yaseer.basic") for m in imported), module
