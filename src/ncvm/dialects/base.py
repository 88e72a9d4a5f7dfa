"""What every dialect front end provides. Each dialect is a package with a module-level ``DIALECT``."""

from __future__ import annotations

from pathlib import Path

from ..diagnostics import Diagnostic, UsageError
from ..machine.model import Machine
from ..runtime.session import Session


class Dialect:
    """A language front end: check, run, and (where the control had one) compile."""

    id = ""
    #: reads its program from the file a stretch at a time: :meth:`run` gets ``text`` None (the API does not
    #: read the file whole for it when the file's name or the caller names the dialect)
    streams = False

    def sniff(self, text: str) -> int:
        """How sure (0-100) that ``text`` is a program of this dialect."""
        return 0

    def check(self, path: str, text: str, machine: Machine, all_errors: bool = False) -> list[Diagnostic]:
        """Every diagnostic the control would report before running (syntax, links)."""
        raise NotImplementedError

    def run(self, path: str, text: str, session: Session) -> None:
        """Run the program; raises CompileFailed before the start or RuntimeFault during the run.

        Sets ``session.variables`` to the main program's variables as they stand when it ends. ``text`` is
        None for a dialect that :attr:`streams`: it reads ``path`` itself.
        """
        raise NotImplementedError

    def compile(self, path: str, text: str, machine: Machine, out: Path | None, xref: Path | None,
                force: bool = False, xref_named: bool = True) -> Path:
        raise UsageError(f"dialect '{self.id}' has no compiler: its programs run as they are")
