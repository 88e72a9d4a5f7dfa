"""The chapter 4 system functions see a run through system.context.SystemContext: every member of the
runtime they read is named there, and the runtime (the one implementation) has every member named."""

from __future__ import annotations

import ast
import inspect
import re
from pathlib import Path

from ncvm.dialects.cpl.runtime import CplRuntime
from ncvm.dialects.cpl.system.context import SystemContext

SYSTEM = Path(__file__).resolve().parents[3] / "src" / "ncvm" / "dialects" / "cpl" / "system"


def protocol_members() -> set[str]:
    return set(SystemContext.__annotations__) | {n for n, v in vars(SystemContext).items() if callable(v) and not n.startswith("__")}


def runtime_members() -> set[str]:
    """Methods of CplRuntime and the attributes its methods assign on ``self``."""
    tree = ast.parse(Path(inspect.getfile(CplRuntime)).read_text(encoding="utf-8"))
    cls = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "CplRuntime")
    found = {n.name for n in cls.body if isinstance(n, ast.FunctionDef)}
    for node in ast.walk(cls):
        if isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Store) \
                and isinstance(node.value, ast.Name) and node.value.id == "self":
            found.add(node.attr)
    return found


def used_members() -> set[str]:
    """What the system modules read of the run (``rt.<member>``)."""
    return {m for p in SYSTEM.glob("*.py") for m in re.findall(r"\brt\.(\w+)", p.read_text(encoding="utf-8"))}


def test_the_context_names_exactly_what_the_system_modules_read():
    assert used_members() == protocol_members()


def test_the_runtime_has_every_member_of_the_context():
    assert protocol_members() <= runtime_members(), sorted(protocol_members() - runtime_members())
