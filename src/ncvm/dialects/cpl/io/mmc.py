"""Chapter 9: MMC, a part program talking to an external client (manual L5177-5217).

``r% = MMC(v1[,v2,...,v20])`` hands the names and values of up to 20 CPL variables to a client
(an HMI or PC application) and waits for its answer; the client may give the variables new values.
Result: 0 ok, 1 no client available (the program goes on at once), 2 error in the client.

In ncvm a client is any callable ``client(names, values) -> (rc, new_values)`` attached with
:meth:`Mmc.attach`; ``new_values`` maps a variable name to its new value (names not in the call
are ignored; values are written back only with rc 0). With no client attached MMC answers 1, as the control does when nobody listens.
A client that raises, or answers with an rc other than 0/1/2, counts as "error in the client" (2).
"""

from __future__ import annotations

from typing import Any, Callable, Sequence

from .errors import fail

MAX_VARIABLES = 20
OK, NO_CLIENT, CLIENT_ERROR = 0, 1, 2

Client = Callable[[list[str], list[Any]], "tuple[int, dict[str, Any]]"]


class Mmc:
    """The MMC connection of one run: at most one client, and a log of every call for the report."""

    def __init__(self, client: Client | None = None):
        self.client = client
        self.calls: list[tuple[list[str], list[Any], int]] = []

    def attach(self, client: Client | None) -> None:
        """Attach ``client`` (None detaches it)."""
        self.client = client

    def MMC(self, names: Sequence[str], values: Sequence[Any]) -> tuple[int, list[Any]]:  # noqa: N802
        """Send the variables; returns (result code, the variables' values afterwards, in order)."""
        names, values = list(names), list(values)
        if not 1 <= len(names) <= MAX_VARIABLES or len(values) != len(names):
            raise fail("MMC_TOO_MANY", f"{len(names)} variables")
        if self.client is None:
            rc, new = NO_CLIENT, values
        else:
            try:
                rc, changes = self.client(list(names), list(values))
                changes = dict(changes or {})
            except Exception:  # noqa: BLE001 - whatever goes wrong in the client is "error in the client"
                rc, changes = CLIENT_ERROR, {}
            if rc not in (OK, NO_CLIENT, CLIENT_ERROR):
                rc = CLIENT_ERROR
            if rc != OK:  # only an answer "ok" writes values back
                changes = {}
            new = [changes.get(n, v) for n, v in zip(names, values)]
        self.calls.append((names, values, rc))
        return rc, new
