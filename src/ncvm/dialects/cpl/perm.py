"""Permanent variables (manual §2.4.3): @1..@100 INTEGER, the DOUBLE field @_R(1..100), and the definable
permanent variables declared in ``wmhperm.dat`` / ``anwperm.dat`` in the machine's file root.

All of them live in the SQLite store (namespace ``cpl.perm``), written through on every assignment, so
a run killed at any moment keeps the last value. At start-up (the first use in a run) the declaration
files are read: declared variables that do not exist yet are created, existing ones keep their values,
definable variables no longer declared are deleted, and the memory budget of the manual is enforced.
"""

from __future__ import annotations

import re

from ...machine.files import FileRoot, FileRootError, Place
from ...source import lines
from .errors import CplError
from .io.files import EOF_MARKER
from .io.strings import CharacterField
from .values import to_bool, to_double, to_int, to_real, to_str

NS = "cpl.perm"
DECL_FILES = ("wmhperm.dat", "anwperm.dat")
#: bytes left for definable permanent variables (manual L580-613: 102,400 - 800 - 24 - 823 - 40 - 35)
MEMORY = 100_678
ELEMENT_SIZE = {"INT": 4, "REAL": 4, "DOUBLE": 8, "BOOL": 1, "CHAR": 1}
SUFFIX_OF = {"INT": "%", "REAL": "", "DOUBLE": "!", "BOOL": "?", "CHAR": "$"}
CONVERT = {"INT": to_int, "REAL": to_real, "DOUBLE": to_double, "BOOL": to_bool, "CHAR": to_str}
DECL = re.compile(r"^\s*DEF\s+(INT|REAL|DOUBLE|BOOL|CHAR)\s*@([A-Z][A-Z0-9_]*)\s*(?:\(\s*(\d+)\s*(?:,\s*(\d+)\s*)?\))?"
                  r"\s*(?:;.*)?$", re.I)


class DeclError(Exception):
    def __init__(self, code: str, message: str, file: str, line: int):
        self.code = code
        self.message = message
        self.file = file
        self.line = line


def read_declarations(root: FileRoot) -> dict[str, tuple[str, list[int]]]:
    """name (16 significant characters) -> (type, dims) from the declaration files in ``root``."""
    out: dict[str, tuple[str, list[int]]] = {}
    for fname in DECL_FILES:
        place = root.find(fname, ignore_case=True)
        if place is None:
            continue
        path = str(root.path_of(place))
        for no, line in enumerate(lines(_declaration_text(root, place, path)), 1):
            if not line.strip():
                continue
            m = DECL.match(line)
            if m is None:
                raise DeclError("CPL038", f"not a declaration 'DEF <type> @<name>[(n[,m])] [;comment]': {line.strip()}",
                                path, no)
            typ, name = m.group(1).upper(), m.group(2).upper()[:16]
            dims = [int(x) for x in (m.group(3), m.group(4)) if x is not None]
            limit = 1024 if typ == "CHAR" else 65535
            if any(not 1 <= d <= limit for d in dims):
                raise DeclError("CPL022", f"@{name}: field size outside 1..{limit}", path, no)
            if out.get(name, (typ, dims)) != (typ, dims):  # the same 16 significant characters: one variable
                raise DeclError("CPL038", f"@{name} is declared again with another type or size", path, no)
            out[name] = (typ, dims)
    used = sum(_size(name, typ, dims) for name, (typ, dims) in out.items())
    if used > MEMORY:
        raise DeclError("1869", f"definable permanent variables need {used} bytes, {MEMORY} are available",
                        str(root.path), 0)
    return out


def _declaration_text(root: FileRoot, place: Place, path: str) -> str:
    """A declaration file's text. It is never read through a symbolic link (one planted in the file root
    would hand the start-up another file's lines), nor from a FIFO, device or socket: such an entry is
    a declaration file error, not an empty declaration -- that would delete every variable it declares.
    The text ends at the EOF marker of the control's file form, as a file written with OPENW has it."""
    try:
        return root.read_bytes(place, follow=False).decode("latin-1").partition(EOF_MARKER[0])[0]
    except FileRootError as e:
        raise DeclError("CPL038", f"{e} (INVALID FILE NAME)", path, 0) from None
    except OSError as e:
        raise DeclError("CPL038", f"{place.shown} cannot be read ({e.strerror})", path, 0) from None


def _size(name: str, typ: str, dims: list[int]) -> int:
    n = 1
    for d in dims:
        n *= d
    if typ == "CHAR" and len(dims) == 1:
        n = dims[0]
    return len(name) + 20 + n * ELEMENT_SIZE[typ]


def _empty(typ: str, dims: list[int]):
    if typ == "CHAR":
        if len(dims) <= 1:
            return None
        return [None] * (dims[0] + 1)
    if not dims:
        return None
    if len(dims) == 1:
        return [None] * (dims[0] + 1)
    return [[None] * (dims[1] + 1) for _ in range(dims[0] + 1)]


class Permanents:
    """Reads and writes permanent variables; ``touched`` lists the ones this run used (for the report)."""

    def __init__(self, session):
        self.session = session
        self.root = FileRoot(session.machine.file_root, (session.options.state_dir,))
        self._store = None
        self.decls: dict[str, tuple[str, list[int]]] = {}
        self.values: dict[str, object] = {}
        self.touched: dict[str, str] = {}  # key -> name shown in the report
        #: told of the first read of each permanent variable this run has not written: run-time input left by
        #: earlier runs (``ncvm translate`` marks the path that follows it FROZEN); None: nobody asks
        self.on_outside = None
        self._this_run: set[str] = set()  # the permanent variables read or written so far

    def _read(self, key: str, value, name: str):
        """``value`` of permanent variable ``key``, read by the program (``name`` as it spells it)."""
        self.touched[key] = name
        if self.on_outside is not None and key not in self._this_run:
            self._this_run.add(key)
            self.on_outside(f"permanent variable {name} read as {'NUL' if value is None else value!r}, "
                            "left by earlier runs")
        return value

    def _wrote(self, key: str, name: str) -> None:
        self.touched[key] = name
        self._this_run.add(key)

    @property
    def store(self):
        if self._store is None:
            self._start()
        return self._store

    def _ensure(self) -> None:
        if self._store is None:
            self._start()

    def _start(self) -> None:
        """Start-up processing of the declaration files (manual L554-558)."""
        store = self.session.store
        self.decls = read_declarations(self.root)
        existing = store.items(NS)
        with store.batch():
            for key, val in list(existing.items()):
                if key.startswith("@") and not key[1:].isdigit() and not key.startswith("@_R("):
                    name = key[1:]
                    decl = self.decls.get(name)
                    if decl is None or val.get("type") != decl[0] or val.get("dims") != decl[1]:
                        store.delete(NS, key)
                        existing.pop(key, None)
            for name, (typ, dims) in self.decls.items():
                if "@" + name not in existing:
                    store.put(NS, "@" + name, {"type": typ, "dims": dims, "value": _empty(typ, dims)})
        self.values = {k: v for k, v in store.items(NS).items()}
        self._store = store

    # -- @1 .. @100 ---------------------------------------------------------------------
    def get_n(self, n: int):
        self._ensure()
        key = f"@{n}"
        return self._read(key, self.values.get(key), key)

    def set_n(self, n: int, v) -> None:
        if v is None:
            raise CplError("CPL033", f"@{n} = NUL")
        v = to_int(v)
        key = f"@{n}"
        self.store.put(NS, key, v)
        self.values[key] = v
        self._wrote(key, key)

    # -- @_R(1..100) ----------------------------------------------------------------------
    def _r_key(self, i) -> str:
        if i.__class__ is not int or not 1 <= i <= 100:
            raise CplError("CPL031", f"@_R({i}): the index is 1..100")
        return f"@_R({i})"

    def get_r(self, i):
        self._ensure()
        key = self._r_key(i)
        return self._read(key, self.values.get(key), key)

    def set_r(self, i, v) -> None:
        key = self._r_key(i)
        if v is None:
            raise CplError("CPL033", f"{key} = NUL")
        v = to_double(v)
        self.store.put(NS, key, v)
        self.values[key] = v
        self._wrote(key, key)

    # -- definable ----------------------------------------------------------------------------
    def _decl(self, name: str, suffix: str):
        self._ensure()
        decl = self.decls.get(name)
        if decl is None:
            raise CplError("CPL034", f"@{name} is not declared in {' or '.join(DECL_FILES)}")
        typ, dims = decl
        if SUFFIX_OF[typ] != suffix:
            raise CplError("CPL034", f"@{name} is declared {typ}: write it as @{name}{SUFFIX_OF[typ]}")
        return typ, dims

    def _slot(self, name: str, typ: str, dims: list[int], idx: tuple):
        """(container, index) of one element, or (None, None) for a simple variable."""
        want = len(dims) - 1 if typ == "CHAR" else len(dims)
        if len(idx) != want:
            raise CplError("CPL031", f"@{name} needs {want} ind{'ex' if want == 1 else 'ices'}")
        for i, d in zip(idx, dims):
            if i.__class__ is not int or not 0 <= i <= d:
                raise CplError("CPL031", f"@{name}: index {i} outside 0..{d}")
        return idx

    def get_d(self, name: str, suffix: str, idx: tuple):
        typ, dims = self._decl(name, suffix)
        idx = self._slot(name, typ, dims, idx)
        key = "@" + name
        v = self.values[key]["value"]
        for i in idx:
            v = v[i]
        return self._read(key, v, key + suffix)

    def set_d(self, name: str, suffix: str, idx: tuple, v) -> None:
        typ, dims = self._decl(name, suffix)
        idx = self._slot(name, typ, dims, idx)
        if v is None:
            raise CplError("CPL033", f"@{name}{suffix} = NUL")
        v = CONVERT[typ](v)
        if typ == "CHAR":
            v = v[: dims[-1]] if dims else v[:1]
            if "\x00" in v:  # the store keeps codes 1..255, the same rule as `ncvm state import`
                raise CplError("CPL033", f"@{name}$ would hold CHR$(0) as character {v.index(chr(0)) + 1}: "
                                         "NUL is no value (L758-762)")
        key = "@" + name
        rec = self.values[key]
        if not idx:
            rec["value"] = v
        else:
            box = rec["value"]
            for i in idx[:-1]:
                box = box[i]
            box[idx[-1]] = v
        self.store.put(NS, key, rec)
        self._wrote(key, key + suffix)

    def char_field(self, name: str, idx: tuple) -> PermanentField:
        """A permanent character field (``DEF CHAR @NAME(n)``, or a row of ``@NAME(rows,n)``) as a field
        that INP# and MID$(...)= write into; each change goes through to the store."""
        typ, dims = self._decl(name, "$")
        idx = self._slot(name, typ, dims, idx)
        return PermanentField(self, name, idx, dims[-1] if dims else 1, self.get_d(name, "$", idx))

    def report(self) -> dict:
        out = {}
        for key, shown in self.touched.items():
            v = self.values.get(key)
            out[shown] = v["value"] if isinstance(v, dict) else v
        return out


class PermanentField(CharacterField):
    """A character field whose text is a permanent variable: assigning NUL is CPL033, as for set_d."""

    __slots__ = ("perm", "name", "idx")

    def __init__(self, perm: Permanents, name: str, idx: tuple, size: int, text: str | None):
        super().__init__(size)
        self.perm, self.name, self.idx = perm, name, idx
        self._text = text

    def assign(self, value) -> None:
        super().assign(value)
        self.perm.set_d(self.name, "$", self.idx, self._text)

    def write(self, start: int, count: int | None, value) -> None:
        before = self._text
        super().write(start, count, value)
        if self._text != before:
            self.perm.set_d(self.name, "$", self.idx, self._text)
