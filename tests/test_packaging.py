"""What the package declares: every module it imports from outside the standard library is a dependency in
pyproject.toml (a wheel installed into a clean environment must run; .ci/wheel tries it for real)."""

from __future__ import annotations

import ast
import re
import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
#: import name -> distribution name, where they differ
DISTRIBUTION = {"PIL": "pillow"}


def _imported(tree: ast.AST) -> set[str]:
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name.split(".")[0] for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names.add(node.module.split(".")[0])
    return names


def test_every_import_of_the_package_is_a_declared_dependency():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    extras = [d for group in project.get("optional-dependencies", {}).values() for d in group]  # ncvm[cluster]
    declared = {re.split(r"[<>=!~;\[ ]", d, maxsplit=1)[0].lower() for d in project["dependencies"] + extras}
    used = set()
    for path in (ROOT / "src" / "ncvm").rglob("*.py"):
        used |= _imported(ast.parse(path.read_text(encoding="utf-8"), str(path)))
    outside = {n for n in used if n not in sys.stdlib_module_names and n != "ncvm" and n != "__future__"}
    missing = sorted(n for n in outside if DISTRIBUTION.get(n, n).lower() not in declared)
    assert not missing, f"imported but not declared in pyproject.toml: {missing}"
    assert "pillow" in declared  # the CPL screen draws with PIL


def test_the_license_the_package_names_is_in_the_repository():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert project["license"] == "MIT"
    text = (ROOT / "LICENSE").read_text()
    assert text.startswith("MIT License") and "Copyright (c) the ncvm authors" in text
    assert project["license-files"] == ["LICENSE"]
