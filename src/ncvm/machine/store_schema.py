"""What the permanent store may hold, per namespace: the rules ``ncvm state import`` checks a file against.

One schema per store kind, built from the nodes of the machine-file schema (:mod:`.schema`, :mod:`.sections`)
and the limits of the manuals, so an imported value is one the control itself could have kept: a CPL
INTEGER in 32 bits, a REAL exactly binary32, a DOUBLE finite; a ZS table with its columns, unit, strict
flag and all 18 rows of one value per column (CPL manual §4.3); compensation groups of [H, D]; tool
database fields 3..49 typed as TDA reads them (8 and 49 strings of at most 31 characters, the others
INTEGER, manual §4.5); the SINUMERIK 800's data areas, tool offsets P0..P15, zero offsets of one value per
axis, rotations of the settable (1-4) and programmable (1-2) groups, the MIB of 500 R values (the 850/880's
0-499, CL 800 manual @211/@212) and central R parameters R900..R999, both within +/-99999999 (L7079).
Every number must be finite: no control holds NaN or infinity.
"""

from __future__ import annotations

import math
import struct
from dataclasses import dataclass
from typing import Any

from .schema import Check, Ctx, Field, Flag, ListOf, Node, Number, SchemaError, Table, Text, join, unique
from .sections import DATA_AREA, R_LIMIT, UNIT, ZO_NAMES, ZS_ROWS

#: the MIB addresses of the largest control (850/880: 0-499); the store keeps all of them
MIB_SIZE = 500
#: TDA fields a program reaches (1 and 2 are sector and place, the record's key) and the string ones
TDA_FIELDS, TDA_STRINGS = range(3, 50), ("8", "49")
_F32 = struct.Struct("f")


def _finite(value, path: str) -> float:
    if value.__class__ not in (int, float):
        raise SchemaError(path, value, "must be a number")
    try:
        finite = math.isfinite(value)
    except OverflowError:  # a whole number beyond every double
        finite = False
    if not finite:
        raise SchemaError(path, value, "must be a finite number (no control holds NaN or infinity)")
    return value


@dataclass(frozen=True)
class Double(Node):
    """A finite binary64 number of any magnitude (a CPL DOUBLE, a position, an offset)."""

    def check(self, value, path, ctx):
        _finite(value, path)

    def type_text(self):
        return "a number"

    def json(self):
        return {"type": "number"}


@dataclass(frozen=True)
class Real32(Double):
    """A CPL REAL: a binary32 value, held exactly (0.1 is 0.10000000149011612)."""

    def check(self, value, path, ctx):
        v = float(_finite(value, path))
        if abs(v) > 3.4028234663852886e38 or _F32.unpack(_F32.pack(v))[0] != v:
            raise SchemaError(path, value, "is not a REAL (binary32) value")


@dataclass(frozen=True)
class RValue(Double):
    """A SINUMERIK R parameter: within +/-99999999 (L7079), as every value the NC assigns."""

    def check(self, value, path, ctx):
        if abs(_finite(value, path)) > R_LIMIT:
            raise SchemaError(path, value, "is beyond the R parameter range +/-99999999")


@dataclass(frozen=True)
class Int32(Node):
    """A CPL INTEGER (32 bits), also a TDA field: 7, never 7.0, "7" or true."""

    def check(self, value, path, ctx):
        if value.__class__ is not int or not -2**31 <= value <= 2**31 - 1:
            raise SchemaError(path, value, "is not an INTEGER in -2147483648..2147483647")

    def type_text(self):
        return "an INTEGER"

    def json(self):
        return {"type": "integer", "minimum": -2**31, "maximum": 2**31 - 1}


def foreign_character(text: str) -> int | None:
    """Index of the first character of ``text`` no CPL character variable holds, or None.

    The control keeps one byte a character: the ASCII set of CPL manual A.5 (L5594) and the codes 128..255
    that INKEY gives for panel keys (L4631) and CHR$ makes, as program files are read (Latin-1). Code 0 is
    NUL, no value (L758-762), never a character inside a string (docs/decisions.md, "Characters a
    permanent string holds").
    """
    return next((i for i, c in enumerate(text) if not "\x01" <= c <= "\xff"), None)


@dataclass(frozen=True)
class Chars(Node):
    """A string of at most ``most`` characters (a CPL CHARACTER variable, a TDA string field), each one
    byte of the control, codes 1..255 (:func:`foreign_character`)."""

    most: int

    def check(self, value, path, ctx):
        if value.__class__ is not str or len(value) > self.most:
            raise SchemaError(path, value, f"must be a string of at most {self.most} characters")
        bad = foreign_character(value)
        if bad is not None:
            raise SchemaError(path, value, f"character {bad + 1} (U+{ord(value[bad]):04X}) is not one the "
                                           "control holds: one byte, codes 1..255 only")

    def type_text(self):
        return f"a string of at most {self.most} one-byte characters (codes 1..255)"

    def json(self):
        return {"type": "string", "maxLength": self.most, "pattern": "^[\\u0001-\\u00ff]*$"}


@dataclass(frozen=True)
class Nullable(Node):
    """``null`` (a value not set yet) or ``node``."""

    node: Node

    def check(self, value, path, ctx):
        if value is not None:
            self.node.check(value, path, ctx)

    def type_text(self):
        return f"{self.node.type_text()} or null"

    def json(self):
        return {"anyOf": [self.node.json(), {"type": "null"}]}


@dataclass(frozen=True)
class ByKey(Node):
    """A table whose keys say what their values are: the first ``(key, value)`` rule whose key fits."""

    rules: tuple[tuple[Text, Node], ...]
    keys_doc: str

    def node_of(self, key: str) -> Node | None:
        for pattern, node in self.rules:
            try:
                pattern.check(key, "", NO_AXES)
            except SchemaError:
                continue
            return node
        return None

    def check(self, value, path, ctx):
        if not isinstance(value, dict):
            raise SchemaError(path, value, "must be an object")
        for key, v in value.items():
            node = self.node_of(key)
            if node is None:
                raise SchemaError(join(path, key), v, f"unknown key: not {self.keys_doc}")
            node.check(v, join(path, key), ctx)

    def type_text(self):
        return "a table"

    def json(self):
        return {"type": "object"}


NO_AXES = Ctx()
DOUBLE, REAL, INT32, R_VALUE = Double(), Real32(), Int32(), RValue()


# -- cpl.perm: @1..@100 INTEGER, @_R(1..100) DOUBLE, declared @NAME (CPL manual §2.4.3) -------------------
ELEMENTS: dict[str, Node] = {"INT": INT32, "REAL": REAL, "DOUBLE": DOUBLE, "BOOL": Flag()}


@dataclass(frozen=True)
class Declared(Node):
    """A declared permanent variable: ``{"type", "dims", "value"}``, the value of the declared shape (a
    field of n elements holds n + 1, index 0..n; a CHAR of length n is a string of at most n)."""

    def check(self, value, path, ctx):
        if not isinstance(value, dict) or set(value) != {"type", "dims", "value"}:
            raise SchemaError(path, value, 'a declared variable is an object of "type", "dims" and "value"')
        typ, dims = value["type"], value["dims"]
        if typ not in (*ELEMENTS, "CHAR"):
            raise SchemaError(join(path, "type"), typ, "must be INT, REAL, DOUBLE, BOOL or CHAR")
        limit = 1024 if typ == "CHAR" else 65535
        if not isinstance(dims, list) or len(dims) > 2 or any(d.__class__ is not int or not 1 <= d <= limit
                                                                for d in dims):
            raise SchemaError(join(path, "dims"), dims, f"must be a list of at most 2 sizes in 1..{limit}")
        self.shape(typ, dims).check(value["value"], join(path, "value"), ctx)

    @staticmethod
    def shape(typ: str, dims: list[int]) -> Node:
        if typ == "CHAR":  # a string of dims[-1] characters, or a field of dims[0] + 1 of them
            text = Nullable(Chars(dims[-1] if dims else 1))
            return text if len(dims) <= 1 else ListOf(text, dims[0] + 1, dims[0] + 1)
        node: Node = Nullable(ELEMENTS[typ])
        for n in reversed(dims):
            node = ListOf(node, n + 1, n + 1)
        return node

    def type_text(self):
        return "a declared variable"

    def json(self):
        return {"type": "object"}


CPL_PERM = ByKey((
    (Text(pattern=r"@([1-9]|[1-9][0-9]|100)"), Nullable(INT32)),
    (Text(pattern=r"@_R\(([1-9]|[1-9][0-9]|100)\)"), Nullable(DOUBLE)),
    (Text(pattern=r"@[A-Z][A-Z0-9_]{0,15}"), Declared()),
), "a permanent variable (@1..@100, @_R(1..100), or @NAME of up to 16 characters)")


# -- cpl.zs: the database ZS tables V1..V3 and the active one (CPL manual §4.3; zsfile.py's layout) ----------
AXIS_NAME = Text(pattern=r"[^\s:a-z]+", shape="an axis name in capitals")


def _rows_match_columns(table: dict, path: str, ctx: Ctx) -> None:
    n = len(table["columns"])
    for row, values in table["rows"].items():
        if len(values) != n:
            raise SchemaError(join(join(path, "rows"), row), values,
                              f"must give {n} values, one per column ({', '.join(table['columns'])})")
    for name in table.get("rotary", ()):
        if name not in table["columns"]:
            raise SchemaError(join(path, "rotary"), name, "is not one of the columns")


ZS_TABLE = Table((
    Field("columns", ListOf(AXIS_NAME, 1, 64, checks=(unique("", "column"),)), "axis names", required=True),
    Field("unit", UNIT, "unit of the values", required=True),
    Field("strict", Number(integer=True, min=0, max=1), "strict table", required=True),
    Field("rows", Table(tuple(Field(r, ListOf(DOUBLE), f"row {r}", required=True) for r in ZS_ROWS)),
          "G54..G59, G154..G159, G254..G259", required=True),
    Field("rotary", ListOf(AXIS_NAME), "the rotary axes among the columns"),
), checks=(Check("a row has one value per column", _rows_match_columns),))
TABLE_NAME = Text(nonempty=True)
CPL_ZS = Table(other=ZS_TABLE, keys=TABLE_NAME, keys_doc="table name")

# -- cpl.tc: compensation tables K4, K5 and named ones: group -> [H length, D radius] (manual §4.4) -------
GROUP = Text(pattern=r"0|[1-9][0-9]*", shape="a group number")
CPL_TC = Table(other=Table(other=ListOf(DOUBLE, 2, 2), keys=GROUP, keys_doc="group"), keys=TABLE_NAME,
               keys_doc="table name")

# -- cpl.tdb: records "sector,place" of fields 3..49 (manual §4.5, L1895-1966) --------------------------
TDA_RECORD = ByKey((
    (Text(choices=TDA_STRINGS), Chars(31)),
    (Text(choices=tuple(str(f) for f in TDA_FIELDS)), INT32),
), "a tool database field 3..49")
CPL_TDB = Table(other=TDA_RECORD, keys=Text(pattern=r"[1-9][0-9]*,[1-9][0-9]*", shape='"sector,place"'),
                keys_doc="record")


# -- sin800: the NC data the SINUMERIK 800 keeps in battery-backed memory ---------------------------------
def _one_per_axis(offsets: dict, path: str, ctx: Ctx) -> None:
    """Every zero offset has one value per axis: as many as the others (the machine decides how many)."""
    first = next(iter(offsets), None)
    for name, values in offsets.items():
        if len(values) != len(offsets[first]):
            raise SchemaError(join(path, name), values, f"must give one value per axis, as {first} "
                                                        f"({len(offsets[first])})")


ZO_KEYS = (*ZO_NAMES, *(f"{g}.{part}" for g in ZO_NAMES[:4] for part in ("coarse", "fine")))
SIN800 = Table((
    *(Field(area, Table(other=DOUBLE, keys=DATA_AREA.keys, keys_doc="address"), area) for area in
      ("nc_md", "cycle_md", "plc_md", "drive_md", "nc_sd", "cycle_sd")),
    Field("to", Table(other=ListOf(DOUBLE, 16, 16), keys=Text(pattern=r"(0|[1-9][0-9]*):[1-9][0-9]*",
                                                              shape='"area:D" such as "0:1"'), keys_doc="tool offset"),
          "tool offsets P0..P15"),
    Field("zo", Table(other=ListOf(DOUBLE, 1), keys=Text(choices=ZO_KEYS), keys_doc="zero offset",
                      checks=(Check("one value per axis", _one_per_axis),)), "zero offsets"),
    Field("rot", Table(other=DOUBLE, keys=Text(pattern=r"settable:[1-4]|programmable:[12]",
                                               shape='"settable:1".."settable:4", "programmable:1" or "2"'),
                       keys_doc="rotation"), "rotation angles"),
    Field("mib", ListOf(R_VALUE, MIB_SIZE, MIB_SIZE), "MIB 0-499, R values"),
    Field("central_r", Table(other=R_VALUE, keys=Text(pattern=r"9[0-9][0-9]", shape="900 .. 999"),
                             keys_doc="central R parameter"), "central R parameters R900..R999"),
))

#: namespace -> the schema of its entries (key -> value)
STORE: dict[str, Node] = {"cpl.perm": CPL_PERM, "cpl.zs": CPL_ZS, "cpl.tc": CPL_TC, "cpl.tdb": CPL_TDB,
                          "sin800": SIN800}


def normal(node: Node, value: Any) -> Any:
    """A checked value as the store holds it: a number where the control holds a floating-point one is a
    float (an edited ``5`` in a DOUBLE reads back as ``5.0``, as a run would have written it)."""
    if isinstance(node, Nullable):
        return None if value is None else normal(node.node, value)
    if isinstance(node, Double) or isinstance(node, Number) and not node.integer:
        return float(value)
    if isinstance(node, ListOf):
        return [normal(node.item, v) for v in value]
    if isinstance(node, Declared):
        return {**value, "value": normal(Declared.shape(value["type"], value["dims"]), value["value"])}
    if isinstance(node, (Table, ByKey)):
        return {k: normal(_node_at(node, k), v) for k, v in value.items()}
    return value


def _node_at(node: Table | ByKey, key: str) -> Node:
    if isinstance(node, ByKey):
        return node.node_of(key)
    return next((f.type for f in node.fields if f.name == key), node.other)

