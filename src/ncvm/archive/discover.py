"""Which files of the command line are programs, which are skipped and why, and which machine each one uses.

An archive is a tree of folders. Every program uses the nearest ``machine.toml`` upwards from its own
folder, up to the folder named on the command line (unless one machine file is given for all). A file
with a program extension is a program; a file without an extension is classified by its content (the
dialect detector); any other file (machine files, key scripts, listings, data) is not looked at.

Sub-programs are not main programs: a folder's ``main.txt`` (one file name a line, as in examples/) lists
its main programs and makes every other program of that folder a sub-program; without it, a SINUMERIK
sub-program file (``.spf``) and a program that another program of the folder calls (CPL ``CALL NAME``,
DIN ``o<name> call``) are sub-programs. The files in a machine's file root are the controller's data
(what programs read and write with OPENW/PRN#), not programs.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from ..diagnostics import UsageError
from ..dialects import EXTENSIONS, detect_dialect
from ..machine.config import load_machine
from ..machine.model import Machine
from ..source import read_text

MACHINE_FILE = "machine.toml"
MAIN_LIST = "main.txt"
#: extensions of sub-program files: a SINUMERIK 800 %SPF is called by its L number, never started alone
SUBPROGRAM_EXTENSIONS = (".spf",)
#: how a program calls another by name, per dialect (the name is the called file's stem, any case)
CALLS = {
    "cpl": re.compile(r"\bCALL\s+([A-Za-z_]\w*)", re.IGNORECASE),
    "din": re.compile(r"\bo<([^>]+)>\s*call\b", re.IGNORECASE),
}
#: the largest extensionless file read to classify it: programs are text of a few MB at most
MAX_SNIFF_BYTES = 4 * 1024 * 1024


@dataclass(frozen=True)
class Program:
    """A main program of the batch."""

    path: Path
    dialect: str
    machine: Path | None  # its machine file; None: the built-in machine
    root: Path  # the folder (or file) named on the command line it was found under
    #: the machine file was found in a folder above the program's: the program's own folder is searched
    #: for sub-programs first, then the machine's program path
    machine_above: bool = False


@dataclass(frozen=True)
class Skipped:
    """A file found in a folder that is not run, and why."""

    path: Path
    reason: str


@dataclass
class Found:
    programs: list[Program]
    skipped: list[Skipped]
    #: every program file found, main or sub-program (``ncvm check`` checks them all)
    all_programs: list[Program]

    @property
    def checked(self) -> set[Path]:
        return {p.path for p in self.all_programs}


def nearest_machine(program: Path, root: Path) -> Path | None:
    """The ``machine.toml`` nearest to ``program`` upwards, not above ``root``."""
    folder = program.parent
    root = root.resolve()
    while True:
        candidate = folder / MACHINE_FILE
        if candidate.is_file():
            return candidate
        if folder.resolve() == root or folder.resolve() == folder.resolve().parent:
            return None
        folder = folder.parent


def discover(args: list[str] | tuple[str, ...], dialect: str | None = None,
             machine: str | Path | None = None) -> Found:
    """The programs named and found below the folders named, in command-line order then by path.

    A file named on the command line is always a main program; a name that is neither file nor folder is
    a usage error.
    """
    found = Found([], [], [])
    seen: set[Path] = set()
    for arg in args:
        path = Path(arg)
        if path.is_dir():
            _folder(path, dialect, machine, found, seen)
        elif path.is_file():
            if path.resolve() in seen:
                continue
            seen.add(path.resolve())
            # a file named on the command line is a program: one of unknown language is a usage error
            kind = dialect or detect_dialect(path, _read(path))
            program = _program(path, kind, path.parent, machine)
            found.programs.append(program)
            found.all_programs.append(program)
        else:
            raise UsageError(f"no such program: {arg}")
    return found


def _program(path: Path, dialect: str, root: Path, machine: str | Path | None) -> Program:
    if machine:
        return Program(path, dialect, Path(machine), root)
    found = nearest_machine(path, root)
    above = found is not None and found.parent.resolve() != path.parent.resolve()
    return Program(path, dialect, found, root, above)


def machine_of(program: Program) -> Machine | None:
    """The machine ``program`` runs on (None: the built-in one, which searches the program's folder)."""
    if program.machine is None:
        return None
    m = load_machine(program.machine)
    if program.machine_above:
        m.program_path.insert(0, program.path.parent)
    return m


def _folder(root: Path, dialect: str | None, machine: str | Path | None, found: Found, seen: set[Path]) -> None:
    folders: dict[Path, list[tuple[Path, str]]] = {}
    file_roots: dict[Path, Path | None] = {}
    for path in sorted(root.rglob("*")):
        rel = path.relative_to(root)
        if any(part.startswith(".") for part in rel.parts) or not path.is_file():
            continue  # a state directory (.ncvm), version control: never part of the archive
        if path.resolve() in seen:
            continue
        if path.suffix and path.suffix.lower() not in EXTENSIONS:
            continue
        seen.add(path.resolve())
        owner = Path(machine) if machine else nearest_machine(path, root)
        data = _file_root(owner, file_roots)
        if data is not None and path.resolve().is_relative_to(data):
            found.skipped.append(Skipped(path, f"in the file root of {owner}: the controller's data, not a program"))
            continue
        kind = _classify(path, dialect)
        if isinstance(kind, Skipped):
            found.skipped.append(kind)
        else:
            folders.setdefault(path.parent, []).append((path, kind))
    for folder, files in folders.items():
        subs = _subprograms(folder, files)
        for path, kind in files:
            program = _program(path, kind, root, machine)
            found.all_programs.append(program)
            if path in subs:
                found.skipped.append(Skipped(path, subs[path]))
            else:
                found.programs.append(program)


def _file_root(machine: Path | None, cache: dict[Path, Path | None]) -> Path | None:
    """The file root of a machine file (None: the built-in machine's is in the state directory, or the
    file does not load, which its programs' runs report)."""
    if machine is None:
        return None
    if machine not in cache:
        try:
            cache[machine] = load_machine(machine).file_root.resolve()
        except (UsageError, OSError):
            cache[machine] = None
    return cache[machine]


def _read(path: Path) -> str:
    try:
        return read_text(path)
    except OSError as e:
        raise UsageError(f"cannot read {path}: {e.strerror}") from None


def _classify(path: Path, dialect: str | None) -> str | Skipped:
    """The dialect of ``path``, or why it is skipped (an extensionless file that is not a program)."""
    if dialect:
        return dialect
    if path.suffix.lower() in EXTENSIONS:
        return EXTENSIONS[path.suffix.lower()]
    try:
        if path.stat().st_size > MAX_SNIFF_BYTES:
            return Skipped(path, f"no extension and larger than {MAX_SNIFF_BYTES // 2**20} MB: not a program")
        text = read_text(path)
    except (OSError, UnicodeDecodeError, ValueError) as e:
        return Skipped(path, f"no extension and not readable as text ({getattr(e, 'strerror', None) or e})")
    if "\0" in text:
        return Skipped(path, "no extension and binary content: not a program")
    try:
        return detect_dialect(path, text)
    except UsageError as e:
        detail = str(e).split(": ", 1)[-1].split(";")[0]
        return Skipped(path, f"no extension and the content is no program of a known dialect ({detail})")


def _subprograms(folder: Path, files: list[tuple[Path, str]]) -> dict[Path, str]:
    """The sub-programs among the programs of one folder, each with the reason."""
    listing = folder / MAIN_LIST
    if listing.is_file():
        main = {name.strip().lower() for name in read_text(listing).splitlines() if name.strip()}
        return {p: f"sub-program: not listed in {listing}" for p, _ in files if p.name.lower() not in main}
    subs = {p: "sub-program: a SINUMERIK sub-program file (.spf) is called, never started alone"
            for p, _ in files if p.suffix.lower() in SUBPROGRAM_EXTENSIONS}
    by_stem = {p.stem.lower(): p for p, _ in files}
    for caller, kind in files:
        pattern = CALLS.get(kind)
        if pattern is None:
            continue
        try:
            text = read_text(caller)
        except (OSError, UnicodeDecodeError, ValueError):
            continue
        for name in pattern.findall(text):
            callee = by_stem.get(name.strip().lower())
            if callee is not None and callee != caller and callee not in subs:
                subs[callee] = f"sub-program: called by {caller.name}"
    return subs
