"""The @ code table of the SINUMERIK 800 (planning guide ch.10, L6332-6824), one module per
main group. Each row (:class:`.row.AtCode`) carries the code, the CL 800 statement it comes from, the
operand kinds, the manual line, the code generator's lowering and the channel's run-time function; the
CL 800 compiler (``cl800.tables``) reads its statement names from the same rows.
"""

from __future__ import annotations

from . import group0, group1, group2, group3, group4, group6, group7, groupa
from .row import AtCode

AT_CODES: dict[str, AtCode] = {row.code: row for group in (group0, group1, group2, group3, group4, group6, group7,
                                                             groupa) for row in group.ROWS}

__all__ = ["AT_CODES", "AtCode"]
