"""Main group 0: program structure (planning guide ch.10, L6384-6413).
"""

from __future__ import annotations

from .row import AtCode

ROWS = (
    AtCode("00f", "ESS", "", 6397, "ess"),
    AtCode("040", "push", None, 6408, "push"),
    AtCode("041", "push block", "RR", 6409, "push"),
    AtCode("042", "pop", None, 6410, "pop"),
    AtCode("043", "pop block", "RR", 6411, "pop"),
)
