"""Which files of the command line are programs, which are skipped and why, and which machine each one uses.

An archive is a tree of folders. Every program uses the nearest ``machine.toml`` upwards from its own
folder, up to the folder named on the command line (unless one machine file is given for all). A file
with a program extension is a program; a file without an extension is classified by its content (the
dialect detector); any other file (machine files, key scripts, listings, data) is not looked at.

Sub-programs are not main programs: a folder's ``main.txt`` (one file name a line, as in examples/) lists
its main programs and makes every other program of that folder a sub-program; without it, a SINUMERIK
sub-program file (``.spf``), a program that another program calls from its folder or its machine's
program path (CPL ``CALL NAME`` and ``P NAME[...]``, DIN ``o<name> call``, a rw_SymPas include), and the
cycles a machine file maps an address to (``[cpl] calls``) are sub-programs. The files in a machine's file
root are the controller's data (what programs read and write with OPENW/PRN#), not programs.

Folders are entered through symbolic links too (a machine's folder linked from the file server), each real
folder once. A file with a program extension that cannot be read as one (a FIFO, a link to nothing) is
listed as skipped with the reason.
"""

from __future__ import annotations

import os
import re
import stat
from dataclasses import dataclass
from pathlib import Path

from ..diagnostics import UsageError
from ..dialects import EXTENSIONS, detect_dialect
from ..machine.config import load_machine
from ..machine.model import Machine
from ..source import read_head, read_text

MACHINE_FILE = "machine.toml"
MAIN_LIST = "main.txt"
#: extensions of sub-program files: a SINUMERIK 800 %SPF is called by its L number, never started alone
SUBPROGRAM_EXTENSIONS = (".spf",)
#: how a program calls another by name, per dialect (the name is the called file's stem, any case)
CALLS = {
    "cpl": re.compile(r"\b(?:CALL|P)\s+([A-Za-z_]\w*)", re.IGNORECASE),
    "din": re.compile(r"\bo<([^>]+)>\s*call\b", re.IGNORECASE),
}
#: how a program includes a file by its path relative to its own folder (the name with its extension)
INCLUDES = {"sympas": re.compile(r"\{\s*!\s*([^}\s]+)\s*\}")}
#: a CL 800 external list (EXTERNAL ... ENDEXTERN): the data a program's header names, not a program
_EXTERNAL_LIST = re.compile(r"\A(?:\s|\(\*.*?\*\))*EXTERNAL\b", re.IGNORECASE | re.DOTALL)


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
    named = [Path(os.path.abspath(arg)) for arg in args if Path(arg).is_dir()]
    for arg in args:
        path = Path(arg)
        if path.is_dir():
            _folder(path, dialect, machine, found, seen, named)
        elif path.is_file():
            if path.resolve() in seen:
                continue
            seen.add(path.resolve())
            # a file named on the command line is a program: one of unknown language is a usage error
            kind = dialect or detect_dialect(path, _head_of(path))
            program = _program(path, kind, path.parent, machine)
            found.programs.append(program)
            found.all_programs.append(program)
        else:
            raise UsageError(f"no such program: {arg}")
    return found


def nothing_found(found: Found, args) -> str | None:
    """The warning of a batch that found no program at all (an empty folder, one of data only), else None."""
    if found.all_programs:
        return None
    return (f"ncvm: warning: no programs found in {', '.join(map(str, args))} (a program has a program extension, "
            f"or no extension and the content of one)")


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
        own_folder_first(m, program.path)
    return m


def own_folder_first(machine: Machine, program: Path) -> None:
    """Search ``program``'s own folder for its sub-programs before the program path of a machine file from a
    folder above, unless the program path holds it already (then the search, and its error's list of
    folders, are those of ``ncvm run PROGRAM --machine FILE``)."""
    folder = program.parent
    if all(Path(p).resolve() != folder.resolve() for p in machine.program_path):
        machine.program_path.insert(0, folder)


def outermost(path: Path, named: list[Path]) -> Path | None:
    """The uppermost folder of ``named`` (absolute) that holds ``path``: the bound of its machine file search,
    whatever the order the folders were named in."""
    here = Path(os.path.abspath(path))
    holders = [folder for folder in named if here.is_relative_to(folder)]
    return min(holders, key=lambda f: len(f.parts)) if holders else None


def walk(root: Path) -> list[Path]:
    """The entries below ``root`` in path order, entering linked folders, each real folder once; folders
    whose name starts with a dot (a state directory .ncvm, version control) are never part of the archive."""
    out: list[Path] = []
    visited = {root.resolve()}
    for top, dirs, files in os.walk(root, followlinks=True):
        keep = []
        for d in sorted(dirs):
            real = (Path(top) / d).resolve()
            if not d.startswith(".") and real not in visited:
                visited.add(real)
                keep.append(d)
        dirs[:] = keep
        out += [Path(top) / f for f in files if not f.startswith(".")]
    return sorted(out)


def _folder(root: Path, dialect: str | None, machine: str | Path | None, found: Found, seen: set[Path],
            named: list[Path]) -> None:
    files: list[tuple[Path, str]] = []
    file_roots: dict[Path, Path | None] = {}
    for path in walk(root):
        if path.suffix and path.suffix.lower() not in EXTENSIONS:
            continue
        unreadable = _not_a_file(path)
        if unreadable:
            found.skipped.append(Skipped(path, unreadable))
            continue
        if path.resolve() in seen:
            continue
        seen.add(path.resolve())
        bound = outermost(path, named) or root
        owner = Path(machine) if machine else nearest_machine(path, bound)
        data = _file_root(owner, file_roots)
        if data is not None and path.resolve().is_relative_to(data):
            found.skipped.append(Skipped(path, f"in the file root of {owner}: the controller's data, not a program"))
            continue
        kind = _classify(path, dialect)
        if isinstance(kind, Skipped):
            found.skipped.append(kind)
        else:
            files.append((path, kind))
    programs = [_program(path, kind, outermost(path, named) or root, machine) for path, kind in files]
    subs = _subprograms(programs)
    found.skipped += _missing_mains({p.path.parent for p in programs} | {root})
    for program in programs:
        found.all_programs.append(program)
        if program.path in subs:
            found.skipped.append(Skipped(program.path, subs[program.path]))
        else:
            found.programs.append(program)


def _not_a_file(path: Path) -> str | None:
    """Why ``path`` cannot be read as a program (None: a regular file, or a link to one)."""
    try:
        mode = path.stat().st_mode
    except FileNotFoundError:
        return f"a link to {os.readlink(path)}, which does not exist" if path.is_symlink() else "vanished"
    except OSError as e:
        return f"cannot be read ({e.strerror})"
    if stat.S_ISREG(mode):
        return None
    if stat.S_ISDIR(mode):
        return "a folder"
    kind = "a FIFO" if stat.S_ISFIFO(mode) else "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode) else \
        "a socket" if stat.S_ISSOCK(mode) else "not a regular file"
    return f"{kind}, not a program file"


def _missing_mains(folders: set[Path]) -> list[Skipped]:
    """The main programs a folder's main.txt lists whose file is not there: named, so none is missed silently."""
    out = []
    for folder in sorted(folders):
        listing = folder / MAIN_LIST
        if not listing.is_file():
            continue
        present = {p.name.lower() for p in folder.iterdir()}
        for name in _main_names(listing):
            if name not in present:
                out.append(Skipped(folder / name, f"listed as a main program in {listing}, but there is no such file"))
    return out


def _main_names(listing: Path) -> list[str]:
    return [name.strip().lower() for name in read_text(listing).splitlines() if name.strip()]


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


def _head_of(path: Path) -> str:
    """The head of a program named on the command line, for the dialect detector (source.read_head)."""
    try:
        return read_head(path)
    except OSError as e:
        raise UsageError(f"cannot read {path}: {e.strerror}") from None


def _classify(path: Path, dialect: str | None) -> str | Skipped:
    """The dialect of ``path``, or why it is skipped (an extensionless file that is not a program)."""
    if dialect:
        return dialect
    if path.suffix.lower() in EXTENSIONS:
        return EXTENSIONS[path.suffix.lower()]
    try:
        text = read_head(path)
    except OSError as e:
        return Skipped(path, f"no extension and not readable ({e.strerror})")
    if "\0" in text:
        return Skipped(path, "no extension and binary content: not a program")
    try:
        return detect_dialect(path, text)
    except UsageError as e:
        detail = str(e).split(": ", 1)[-1].split(";")[0]
        return Skipped(path, f"no extension and the content is no program of a known dialect ({detail})")


def _subprograms(programs: list[Program]) -> dict[Path, str]:
    """The sub-programs among the programs found below one folder named, each with the reason."""
    subs: dict[Path, str] = {}
    listed = {}
    for folder in {p.path.parent for p in programs}:
        listing = folder / MAIN_LIST
        if listing.is_file():
            listed[folder] = (listing, set(_main_names(listing)))
    for p in programs:
        if p.path.parent in listed:
            listing, main = listed[p.path.parent]
            if p.path.name.lower() not in main:
                subs[p.path] = f"sub-program: not listed in {listing}"
        elif p.path.suffix.lower() in SUBPROGRAM_EXTENSIONS:
            subs[p.path] = "sub-program: a SINUMERIK sub-program file (.spf) is called, never started alone"
    for p in programs:  # checked as the CL 800 data they are, never run
        if p.dialect == "cl800" and _EXTERNAL_LIST.match(_text_head(p.path)):
            subs[p.path] = "a CL 800 external list (EXTERNAL ... ENDEXTERN): the data a program's header names"
    by_place = {(p.path.parent.resolve(), p.path.stem.lower()): p for p in programs}
    by_file = {p.path.resolve(): p for p in programs}
    machines: dict[Path | None, tuple[list[Path], set[str]]] = {}
    for caller in programs:
        folders, cycles = _search(caller, machines)
        called = [(name, f"called by {caller.path.name}") for name in _called(caller)]
        called += [(name, f"the cycle {caller.machine} maps an address to") for name in cycles]
        for name, why in called:
            callee = next((by_place[(f, name.lower())] for f in folders if (f, name.lower()) in by_place), None)
            if _decided(callee, caller, subs, listed):
                subs[callee.path] = f"sub-program: {why}"
        pattern = INCLUDES.get(caller.dialect)
        for name in pattern.findall(_text(caller.path)) if pattern else ():
            callee = by_file.get((caller.path.parent / name).resolve())
            if _decided(callee, caller, subs, listed):
                subs[callee.path] = f"sub-program: included by {caller.path.name}"
    return subs


def _decided(callee: Program | None, caller: Program, subs: dict, listed: dict) -> bool:
    """``callee`` becomes a sub-program by this call: a folder's main.txt has the last word."""
    return (callee is not None and callee is not caller and callee.path not in subs
            and callee.path.parent not in listed)


def _text_head(path: Path) -> str:
    try:
        return read_head(path)
    except OSError:
        return ""


def _called(program: Program) -> list[str]:
    pattern = CALLS.get(program.dialect)
    return [name.strip() for name in pattern.findall(_text(program.path))] if pattern else []


def _text(path: Path) -> str:
    try:
        return read_text(path)
    except OSError:
        return ""


def _search(program: Program, cache: dict) -> tuple[list[Path], set[str]]:
    """The folders (resolved) ``program`` finds sub-programs in, and the cycles of its machine file."""
    if program.machine not in cache:
        folders, cycles = [], set()
        if program.machine is not None:
            try:
                m = load_machine(program.machine)
                folders = [Path(f).resolve() for f in m.program_path]
                calls = (m.sections.get("cpl") or {}).get("calls") or {}
                cycles = {str(v["program"] if isinstance(v, dict) else v) for v in calls.values()}
            except (UsageError, OSError):
                pass
        cache[program.machine] = (folders, cycles)
    folders, cycles = cache[program.machine]
    return [program.path.parent.resolve(), *folders], cycles
