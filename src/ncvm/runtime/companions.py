"""A program's own inputs beside it: ``<name>.keys`` (the operator's key presses) and ``<name>.scenario.toml``
(what happens over simulated time), the convention of examples/.

One rule for every entry point (``ncvm run``, a batch, ``ncvm.run``, ``ncvm.batch``): a file of these names
beside the program is used unless the caller names one (``--keys``/``--scenario``, ``keys=``/``scenario=``).
"""

from __future__ import annotations

from pathlib import Path

KEYS_SUFFIX = ".keys"
SCENARIO_SUFFIX = ".scenario.toml"


def beside(program: str | Path) -> dict[str, Path]:
    """The companion files that exist beside ``program``, by suffix."""
    path = Path(program)
    found = {}
    for suffix in (KEYS_SUFFIX, SCENARIO_SUFFIX):
        side = path.with_name(path.stem + suffix)
        if side.is_file():
            found[suffix] = side
    return found
