"""Main group a: I/O statements (planning guide ch.10, L6801-6824).

``run``: the function ``Channel.io`` calls (the ``panel`` part: operator panel and V24).
"""

from __future__ import annotations

from .row import AtCode

ROWS = (
    AtCode("a15", "WRT PIC", "WW", 6809, "io", run="panel.io", cl800="procedure"),
    AtCode("a1b", "RECALL PIC", "", 6810, "io", run="panel.io", cl800="procedure"),
    AtCode("a20", "PORT", "W", 6814, "io", run="panel.io", cl800="procedure"),
    AtCode("a25", "OUTP ZOA", "W", 6815, "io", run="panel.io", cl800="procedure"),
    AtCode("a26", "OUTP DATA", "WWW", 6816, "io", run="panel.io", cl800="procedure"),
    AtCode("a27", "OUTP PARA", "WWW", 6817, "io_out", run="panel.io", cl800="procedure"),
    AtCode("a28", "INP", "W", 6818, "io_in", run="panel.io", cl800="procedure"),
    AtCode("a29", "OUTP ETX", "", 6819, "io", run="panel.io", cl800="procedure"),
    AtCode("a40", "CHAN", "W", 6823, "io", run="panel.io", cl800="procedure"),
)
