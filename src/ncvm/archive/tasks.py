"""A batch's tasks: each program with everything its run reads, so that any process on any host runs it.

A task carries the text of the program, of every file of its search path the program may call (a file
whose name the program, its machine file -- the cycles of ``[cpl] calls`` -- or a file it brings along
mentions; a relative path it names, as a rw_SymPas include of a sub-folder; for SINUMERIK, every
sub-program of the search path, as they are called by the number of their ``%SPF`` header, indirectly
too), the machine file and the machine's file root,
the program's key script and scenario, and the batch's settings. The state every run starts from (the
``--state`` directory's permanent store and files) travels once in the settings.
"""

from __future__ import annotations

import os
import re
import sqlite3
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from ..diagnostics import UsageError
from ..machine.config import load_machine
from ..machine.state import STORE_NAME
from ..runtime.companions import KEYS_SUFFIX, SCENARIO_SUFFIX, beside
from .discover import Program

#: a program may mention another by any word of its text: names are taken generously, the files are small
_WORD = re.compile(r"[A-Za-z0-9_]+")
#: a relative path a program names (an include of a sub-folder): shipped when it is a file
_RELATIVE = re.compile(r"[A-Za-z0-9_.-]+(?:/[A-Za-z0-9_.-]+)+")
#: dialects whose sub-programs are called by the number in their header (``L20`` finds ``%SPF20``, ``L=R5``
#: the number R5 holds): every sub-program file of the search path travels with the task
_BY_NUMBER = ("sin800", "cl800")
_SPF_HEAD = re.compile(rb"\A\s*%\s*SPF", re.IGNORECASE)
#: files larger than this in a search folder are no program a run calls (never shipped)
MAX_CALLED_BYTES = 4 * 1024 * 1024


@dataclass
class Settings:
    """The options every run of the batch shares."""

    max_steps: int
    max_memory: int | None = None  # None: the default of a run
    #: a state directory every run uses in turn (writes stay there); None: each program its own temporary one
    shared_state: str | None = None
    #: the name of the file the batch wrote into the shared state directory: a run that does not find it
    #: there is on a host that does not share the directory, and refuses to run (its writes would be lost)
    share_token: str | None = None
    #: the state each program starts from when not shared: path inside the state directory -> content
    seed: dict[str, bytes] = field(default_factory=dict)
    seed_from: str | None = None  # where the seed was read (for the report)
    details: bool = False  # records carry the run's variables and output count too (the Python API)


@dataclass
class Task:
    """One program of the batch, self-contained."""

    index: int
    path: str  # the program as found (the report's name for it)
    dialect: str
    machine: str | None  # the machine file as found; None: the built-in machine
    base: str  # the directory of the batch's command line: paths are reported relative to it, as a run does
    files: dict[str, bytes]  # absolute path -> content
    file_root: str | None  # absolute path of the machine file's file root: its writes are reported
    own_folder_first: bool  # the machine file is from a folder above the program's: search the program's first
    keys: str | None  # absolute path of the key script (in files)
    scenario: str | None  # absolute path of the scenario file (in files)
    settings: Settings


def read_seed(state_dir: str | Path) -> dict[str, bytes]:
    """The permanent store (a consistent copy, as SQLite backs it up) and the files of ``state_dir``."""
    state = Path(state_dir)
    seed: dict[str, bytes] = {}
    store = state / STORE_NAME
    if store.is_file():
        with tempfile.TemporaryDirectory(prefix="ncvm-seed-") as tmp:
            copy = Path(tmp) / STORE_NAME
            try:
                src = sqlite3.connect(f"file:{store}?mode=ro", uri=True)
                dst = sqlite3.connect(copy)
                with src, dst:
                    src.backup(dst)
                src.close()
                dst.close()
            except sqlite3.Error as e:
                raise UsageError(f"--state {state}: cannot read the permanent store {store} ({e})") from None
            seed[STORE_NAME] = copy.read_bytes()
    for path in _files_below(state / "files"):
        seed[str(path.relative_to(state))] = path.read_bytes()
    return seed


def _files_below(folder: Path) -> list[Path]:
    if not folder.is_dir():
        return []
    return sorted(p for p in folder.rglob("*") if p.is_file() and not p.is_symlink())


class TaskBuilder:
    """Builds the tasks of a batch; reads each machine file once."""

    def __init__(self, settings: Settings, base: Path | None = None):
        self.settings = settings
        self.base = (base or Path.cwd()).absolute()
        self._machines: dict[Path, tuple[list[Path], Path, dict[str, bytes]] | UsageError] = {}
        self._folders: dict[Path, dict[str, list[Path]]] = {}  # folder -> its files by name, read once

    def task(self, index: int, program: Program) -> Task | UsageError:
        """The task of ``program``, or the usage error of its machine file (the batch reports it)."""
        path = program.path.absolute()
        files: dict[str, bytes] = {}
        file_root = None
        if program.machine is not None:
            loaded = self._machine(program.machine)
            if isinstance(loaded, UsageError):
                return loaded
            search, root, shipped = loaded
            files.update(shipped)
            file_root = str(root)
        else:
            search = []
        try:
            files[str(path)] = path.read_bytes()
        except OSError as e:
            return UsageError(f"cannot read {program.path}: {e.strerror}")
        mentions = [files[str(path)]] + ([files[str(program.machine.absolute())]] if program.machine else [])
        self._add_called(files, path, [path.parent, *search], mentions)
        if program.dialect in _BY_NUMBER:
            self._add_numbered(files, [path.parent, *search])
        extras = {}
        for suffix, side in beside(path).items():  # the one rule of every entry point
            files[str(side)] = side.read_bytes()
            extras[suffix] = str(side)
        return Task(index=index, path=str(program.path), dialect=program.dialect,
                    machine=str(program.machine) if program.machine else None, base=str(self.base), files=files,
                    file_root=file_root, own_folder_first=program.machine_above, keys=extras.get(KEYS_SUFFIX),
                    scenario=extras.get(SCENARIO_SUFFIX), settings=self.settings)

    def _add_called(self, files: dict[str, bytes], program: Path, folders: list[Path], mentions: list[bytes]) -> None:
        """Add every file of ``folders`` whose name (without extension) the program, its machine file, or a
        file added for it mentions, and every relative path they name: what it may call or include.
        Generous on purpose: a file too many costs little, one too few fails."""
        folders = list(dict.fromkeys(folders))
        listings = [self._files_by_name(folder) for folder in folders]
        todo, seen = list(mentions), set()
        while todo:
            text = todo.pop().decode("latin-1")
            candidates = [p for word in set(_WORD.findall(text.upper())) - seen
                          for listing in listings for p in listing.get(word, ())]
            seen.update(_WORD.findall(text.upper()))
            candidates += [folder / rel for rel in set(_RELATIVE.findall(text)) for folder in folders
                           if (folder / rel).resolve().is_relative_to(folder.resolve())]  # never ../ out of it
            for p in candidates:
                data = _small_file(p, files)
                if data is not None:
                    todo.append(data)

    def _add_numbered(self, files: dict[str, bytes], folders: list[Path]) -> None:
        """Add every SINUMERIK sub-program of ``folders`` (a ``.spf`` file or one with a ``%SPF`` header)."""
        for folder in dict.fromkeys(folders):
            for p in (p for named in self._files_by_name(folder).values() for p in named):
                if str(p.absolute()) in files:
                    continue
                if p.suffix.lower() == ".spf" or _SPF_HEAD.match(_head(p)):
                    _small_file(p, files)

    def _files_by_name(self, folder: Path) -> dict[str, list[Path]]:
        if folder not in self._folders:
            names: dict[str, list[Path]] = {}
            try:
                entries = sorted(folder.iterdir())
            except OSError:
                entries = []
            for p in entries:
                if p.is_file():
                    names.setdefault(p.name.split(".")[0].upper(), []).append(p)
            self._folders[folder] = names
        return self._folders[folder]

    def _machine(self, machine: Path):
        key = machine.absolute()
        if key not in self._machines:
            try:
                m = load_machine(key)
                shipped = {str(key): key.read_bytes()}
                root = Path(os.path.abspath(m.file_root))
                for p in _files_below(root):
                    if p.absolute() != key:
                        shipped[str(p.absolute())] = p.read_bytes()
                search = [Path(os.path.abspath(p)) for p in m.program_path]
                self._machines[key] = (search, root, shipped)
            except UsageError as e:
                self._machines[key] = e
            except OSError as e:
                self._machines[key] = UsageError(f"cannot read the machine file {machine}: {e.strerror}")
        return self._machines[key]


def _small_file(p: Path, files: dict[str, bytes]) -> bytes | None:
    """Add ``p`` to ``files`` when it is a regular file a run may call; its content, None when not added."""
    key = str(p.absolute())
    if key in files:
        return None
    try:
        if not p.is_file() or p.stat().st_size > MAX_CALLED_BYTES:
            return None
        files[key] = p.read_bytes()
    except OSError:
        return None
    return files[key]


def _head(p: Path) -> bytes:
    try:
        with open(p, "rb") as f:
            return f.read(64)
    except OSError:
        return b""
