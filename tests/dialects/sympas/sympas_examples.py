"""Helpers of the manual example tests: a program around a body, a machine of n axes, check errors."""

from __future__ import annotations

from ncvm.api import check

SEC = 15625


def prog(body: str, decls: str = "") -> str:
    return f"program T;\n{decls}\nbegin\n{body}\nend.\n"


def axes_toml(n: int, limit: float = 1000.0, names=None, extra: str = "") -> str:
    """A machine with n axes of +-limit (the default test machine has 3 axes of +-1000 mm)."""
    out = "".join(f'[[axis]]\nname = "{c}"\nmin = {-limit}\nmax = {limit}\n' for c in "XYZUVW"[:n])
    sympas = extra
    if names:
        sympas = "axis_names = [" + ", ".join(f'"{x}"' for x in names) + "]\n" + sympas
    return out + ("[sympas]\n" + sympas if sympas else "")


def errors_of(tmp_path, text: str) -> list:
    p = tmp_path / "chk.sap"
    p.write_text(text, encoding="latin-1")
    return [(d.code, d.span.line if d.span else None) for d in check(p) if d.severity == "error"]
