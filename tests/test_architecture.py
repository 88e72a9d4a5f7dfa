"""The layer rules of docs/architecture.md, read from the imports of every module in src/ncvm.

runtime/ and nc/ never import sinks/; machine/ never imports dialects/, cli or api; sinks/ never import
dialects/; no dialect package imports another; no import cycles among module-level imports.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"
PACKAGE = SRC / "ncvm"

#: imports that break a rule today, each with the work that removes it (none may be added)
KNOWN: dict[tuple[str, str], str] = {}

#: import cycles that exist today, each removed by issue 13 (none may be added)
KNOWN_CYCLES: set[tuple[str, ...]] = set()


def module_name(path: Path) -> str:
    parts = path.relative_to(SRC).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _is_type_checking(node: ast.If) -> bool:
    return isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING"


def top_level_imports(path: Path) -> set[str]:
    """Modules of ncvm imported when ``path`` is imported (not inside functions or TYPE_CHECKING)."""
    name = module_name(path)
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found: set[str] = set()

    def visit(body):
        for node in body:
            if isinstance(node, ast.If) and not _is_type_checking(node):
                visit(node.body + node.orelse)
            elif isinstance(node, ast.Try):
                visit(node.body + node.orelse + node.finalbody)
            elif isinstance(node, ast.Import):
                found.update(a.name for a in node.names if a.name.startswith("ncvm"))
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = package.split(".")[:len(package.split(".")) - node.level + 1]
                    target = ".".join(base + ([node.module] if node.module else []))
                else:
                    target = node.module or ""
                if not target.startswith("ncvm"):
                    continue
                for alias in node.names:  # `from . import x` may name a submodule
                    sub = f"{target}.{alias.name}"
                    found.add(sub if _module_path(sub) else target)

    visit(ast.parse(path.read_text(encoding="utf-8")).body)
    found.discard(name)
    return found


def _module_path(name: str) -> Path | None:
    base = SRC.joinpath(*name.split("."))
    for p in (base.with_suffix(".py"), base / "__init__.py"):
        if p.is_file():
            return p
    return None


GRAPH = {module_name(p): top_level_imports(p) for p in sorted(PACKAGE.rglob("*.py"))}


def _layer(name: str) -> str:
    parts = name.split(".")
    return parts[1] if len(parts) > 1 else ""


def _dialect(name: str) -> str | None:
    """The dialect package a module belongs to (dialects/base.py and the registry belong to none)."""
    parts = name.split(".")
    if len(parts) > 2 and parts[1] == "dialects" and (PACKAGE / "dialects" / parts[2]).is_dir():
        return parts[2]
    return None


def broken_rule(src: str, dst: str) -> str | None:
    a, b = _layer(src), _layer(dst)
    if a in ("runtime", "nc") and b == "sinks":
        return f"{a}/ imports sinks/"
    if a == "machine" and b in ("dialects", "cli", "api"):
        return f"machine/ imports {b}"
    if a == "sinks" and b == "dialects":
        return "sinks/ imports dialects/"
    da, db = _dialect(src), _dialect(dst)
    if da and db and da != db:
        return f"dialect {da} imports dialect {db}"
    return None


def test_the_graph_sees_the_modules():
    assert len(GRAPH) > 100
    assert "ncvm.nc.canon" in GRAPH["ncvm.nc.kernel"]


def test_no_import_breaks_a_layer_rule():
    broken = {(src, dst): rule for src, deps in GRAPH.items() for dst in deps
              if (rule := broken_rule(src, dst)) and (src, dst) not in KNOWN}
    assert not broken, "\n".join(f"{s} -> {d}: {r}" for (s, d), r in sorted(broken.items()))


def test_the_known_exceptions_still_exist():
    """An exception that is gone leaves the list, so it cannot come back unnoticed."""
    gone = [pair for pair in KNOWN if pair[1] not in GRAPH.get(pair[0], ())]
    assert not gone


def _package_edge(src: str, dst: str) -> bool:
    """A package and its own submodules import each other by Python's package mechanics, not as a cycle."""
    return src.startswith(dst + ".") or dst.startswith(src + ".")


def test_no_import_cycles():
    graph = {m: {d for d in deps if d in GRAPH and not _package_edge(m, d)} for m, deps in GRAPH.items()}
    state: dict[str, int] = {}
    cycles: list[list[str]] = []

    def walk(node: str, path: list[str]) -> None:
        state[node] = 1
        for dep in sorted(graph[node]):
            if state.get(dep) == 1:
                cycles.append(path[path.index(dep):] + [dep])
            elif dep not in state:
                walk(dep, path + [dep])
        state[node] = 2

    for module in graph:
        if module not in state:
            walk(module, [module])
    new = [c for c in cycles if tuple(c) not in KNOWN_CYCLES]
    assert not new, "\n".join(" -> ".join(c) for c in new)
    assert {tuple(c) for c in cycles} >= KNOWN_CYCLES  # a cycle that is gone leaves the list


@pytest.mark.parametrize("rule_case", [("ncvm.nc.kernel", "ncvm.sinks.plot"), ("ncvm.machine.model", "ncvm.api"),
                                       ("ncvm.dialects.cpl.runtime", "ncvm.dialects.sympas.values")])
def test_the_rules_would_see_a_breach(rule_case):
    assert broken_rule(*rule_case)
