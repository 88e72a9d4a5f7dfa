"""The card's commands (§6.6), one module per command group, each a set of functions over the card's parts.

Generated code calls ``_C_<name>(card, tk, items, loc[, target])`` (values.namespace); a W form returns the
generator the task runs to wait.
"""

from __future__ import annotations

from . import control, jog, paths, spooled, stops
from .paths import fast_line

COMMANDS = {**paths.COMMANDS, **spooled.COMMANDS, **jog.COMMANDS, **stops.COMMANDS, **control.COMMANDS}

__all__ = ["COMMANDS", "fast_line"]
