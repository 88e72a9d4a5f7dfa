"""The central R parameters R900-R999 written through to the permanent store as the program writes them.

The NC keeps them across power-off (the CL 800 manual's central R parameters, one set in the communication
RAM, L425-431; docs/sin800.md "The NC state"), so a store into one is in the store before the next statement,
as a CPL permanent variable is: a run killed at any moment keeps every value it wrote (docs/decisions.md, "SINUMERIK: NC data and central R written
through"). What the store holds after each write is what the end of the run used to write then: the key
``central_r`` holds the central R that are not 0 or that the machine file or an earlier run set, unless that
is exactly what the run started from, when the key is left as the run found it.
"""

from __future__ import annotations

from typing import Any

from .ncdata import CENTRAL_R, NAMESPACE

FIRST = CENTRAL_R.start
KEY = "central_r"


class CentralR:
    """Writes R900-R999 to the store when one differs from what was last written (``kept``)."""

    def __init__(self, R: list[float], start: dict[str, float], stored: dict[str, Any], store):
        self.R = R
        self.start = dict(start)  # machine file and earlier runs: what the run starts from
        self.names = [str(n) for n in CENTRAL_R]
        self.started = [name in self.start for name in self.names]  # kept in the entry even when 0
        self.found = stored.get(KEY)  # the store's own entry as the run found it (None: none)
        self.store = store
        #: the values the store's entry stands for: those the run started from, then those last written (a value
        #: the power-on rounds, strict_nc, differs from its start and is written at the first check, as before)
        self.kept = [start.get(str(n), 0.0) for n in CENTRAL_R]

    def put(self, n: int, value: float) -> None:
        """A store into central R ``n`` by name (generated code): held in the R array, written when changed."""
        self.R[n] = value
        if value != self.kept[n - FIRST]:
            self.write()

    def check(self) -> None:
        """After the NC wrote R parameters by number (a read, a pop, results of an NC function ...)."""
        if self.R[FIRST:] != self.kept:
            self.write()

    def write(self) -> None:
        """The store's entry as of now; ``kept`` follows only once it is written (a Ctrl-C in between leaves
        it to the end of the run's :meth:`check`)."""
        now = self.R[FIRST:]
        central = {name: v for name, v, started in zip(self.names, now, self.started) if v != 0.0 or started}
        if central != self.start:
            self.store.put(NAMESPACE, KEY, central)
        elif self.found is None:
            self.store.delete(NAMESPACE, KEY)
        else:
            self.store.put(NAMESPACE, KEY, self.found)
        self.kept = now
