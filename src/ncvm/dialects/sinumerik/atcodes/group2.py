"""Main group 2: general data transfer (planning guide ch.10, L6471-6490).
"""

from __future__ import annotations

from .row import AtCode

ROWS = (
    AtCode("200", "CLEAR", "V", 6479, "clear", cl800="procedure"),
    AtCode("201", "assignment", "VW", 6480, "assign"),
    AtCode("202", "XCHG", "VV", 6481, "xchg", cl800="procedure"),
    AtCode("203", "bit access", "VVK", 6482, "bit"),
    AtCode("210", "CLEAR MIB", "WW", 6488, "mib_clear", cl800="procedure"),
    AtCode("211", "MIB read", "VW", 6489, "mib_read", cl800="read", name="MIB"),
    AtCode("212", "MIB write", "WW", 6490, "mib_write", cl800="write", name="MIB"),
)
