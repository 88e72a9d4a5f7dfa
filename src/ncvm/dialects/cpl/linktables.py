"""Link tables kept from one run to the next, as the control keeps ``<program>.I`` files (manual §2.3
L411-428, §6.1.1 L3851: the link table's name is the program's plus two characters; CPL manual §2.2-2.3, L407-428; §3.3, L1083-1121).

A link table holds the linked program (statements, structure pairs, jump targets, called programs) and its
generated code. It is reused while the program's text, the machine's call table and ncvm's own CPL code
are those it was made from (its key says so); otherwise the program is linked again and the table
rewritten. The tables live in the run's state directory (``<state>/link``), never inside the controller's
file root, where a CPL program could write one.
"""

from __future__ import annotations

import hashlib
import os
import pickle
import sys
from pathlib import Path

from ...runtime import codegen as _codegen

_FINGERPRINT: str | None = None


def fingerprint() -> str:
    """What a link table depends on besides the program: this Python (the code is marshalled) and the
    source of the CPL front end and the code emitter."""
    global _FINGERPRINT
    if _FINGERPRINT is None:
        h = hashlib.sha256(sys.version.encode())
        for f in sorted([*Path(__file__).parent.rglob("*.py"), Path(_codegen.__file__)]):
            h.update(f.read_bytes())
        _FINGERPRINT = h.hexdigest()
    return _FINGERPRINT


class LinkTables:
    """The folder of ``.I`` files of one state directory."""

    def __init__(self, folder: Path, file_root: Path | None, read_only: bool = False):
        self.folder = folder
        self.read_only = read_only  # a translation reads the tables of earlier runs and writes none
        root = file_root.resolve() if file_root is not None else None
        here = folder.resolve()
        #: a folder a CPL program can write into is never read: its tables could hold any code
        self.usable = root is None or not (here == root or root in here.parents)

    def path(self, program: str) -> Path:
        return self.folder / (Path(program).name + ".I")

    def load(self, program: str, key: str):
        """The program's link table if it was made from this key, else None."""
        if not self.usable:
            return None
        try:
            stored_key, linked = pickle.loads(self.path(program).read_bytes())
        except Exception:  # noqa: BLE001 - no table, a damaged one or one of another version: link again
            return None
        return linked if stored_key == key + fingerprint() else None

    def save(self, program: str, key: str, linked) -> None:
        """Write the table whole or not at all (a crash never leaves half a table)."""
        import tempfile  # here, not at the top: the runs that reuse a table never import it (start-up, issue 18)

        if not self.usable or self.read_only:
            return
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
            data = pickle.dumps((key + fingerprint(), linked))
            fd, tmp = tempfile.mkstemp(dir=self.folder, suffix=".tmp")
            with os.fdopen(fd, "wb") as f:
                f.write(data)
            os.replace(tmp, self.path(program))
        except OSError:
            pass  # a read-only state directory: the program is linked on every run
