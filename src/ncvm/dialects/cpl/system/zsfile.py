"""Axis ZS tables named by a path are files under the controller's file root (manual §4.3).

The manual calls them "ASCII tables" but gives no layout. ncvm writes this one (docs/decisions.md,
"Axis ZS table files"), in the control's file form like every CPL file (records ended by LF, then
the EOF marker ETX LF), so OPENR/INP#, FILESIZE, FILEDATE and ERASE see an ordinary file::

    ZS-TABLE MM STRICT=0
    G                    X                Y              U:R
    G54               22.0              0.0              0.0
    ...           one record per row G54..G59, G154..G159, G254..G259

Record 1: the table unit (MM or INCH, from MACODA 9020 00010 when the table was created) and the
classification (STRICT=0 or 1). Record 2: "G", then one axis name per column, ":R" marking a rotary
axis. Then 18 rows: the G address and one decimal number per column, in the table unit. Blanks
separate the fields; upper or lower case, CR LF line ends and a missing EOF marker are accepted.
A table is written whole into a temporary file beside it, synced, and renamed over the old one.
"""

from __future__ import annotations

import math
import re
import stat

from ....machine.files import Place
from ..errors import CplError
from .controller import ZS_ROWS

MAGIC = "ZS-TABLE"
UNITS = {"MM": "mm", "INCH": "inch"}
MAX_COLUMNS = 64  # the column index of FXC is 1..64 (L1736)
WIDTH = 16
#: a value as ncvm writes it (repr of a float); float() alone would also read "1_0" as 10
NUMBER = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")


def records_of(table: dict) -> list[str]:
    """The file's records for a table {"columns", "unit", "strict", "rows", "rotary"}."""
    rotary = set(table.get("rotary", ()))
    unit = next(word for word, u in UNITS.items() if u == table["unit"])
    heads = [f"{name}:R" if name in rotary else name for name in table["columns"]]
    out = [f"{MAGIC} {unit} STRICT={int(table.get('strict', 0))}",
           "G".ljust(5) + "".join(f" {h:>{WIDTH}}" for h in heads)]
    for row in ZS_ROWS:
        out.append(row.ljust(5) + "".join(f" {_number(v):>{WIDTH}}" for v in table["rows"][row]))
    return out


def _number(v: float) -> str:
    return repr(float(v))  # the shortest text that reads back as the same value


def parse(records: list[str], shown: str) -> dict:
    """A table from the file's records; a damaged file is CPL040 naming the record and the fault."""
    lines = [(i, r.split()) for i, r in enumerate(records, 1) if r.strip()]
    if len(lines) < 2:
        raise _damaged(shown, len(records) + 1, "the header records are missing")
    (n1, head), (n2, cols) = lines[0], lines[1]
    if len(head) != 3 or head[0].upper() != MAGIC or head[1].upper() not in UNITS \
            or head[2].upper() not in ("STRICT=0", "STRICT=1"):
        raise _damaged(shown, n1, f"expected '{MAGIC} MM|INCH STRICT=0|1'")
    if not cols or cols[0].upper() != "G":
        raise _damaged(shown, n2, "expected 'G' and the axis names")
    columns, rotary = [], []
    for word in cols[1:]:
        name, _, kind = word.upper().partition(":")
        if not name or kind not in ("", "R", "L") or name in columns:
            raise _damaged(shown, n2, f"column {word!r}")
        columns.append(name)
        if kind == "R":
            rotary.append(name)
    if len(columns) > MAX_COLUMNS:
        raise _damaged(shown, n2, f"{len(columns)} columns, at most {MAX_COLUMNS}")
    rows: dict[str, list[float]] = {}
    for n, words in lines[2:]:
        row = words[0].upper()
        if row not in ZS_ROWS or row in rows:
            raise _damaged(shown, n, f"row {words[0]!r} ({'twice' if row in rows else 'G54..G59, G154..G159, G254..G259'})")
        if len(words) - 1 != len(columns):
            raise _damaged(shown, n, f"{len(words) - 1} values for {len(columns)} columns")
        if not all(NUMBER.fullmatch(w) for w in words[1:]):
            raise _damaged(shown, n, "a value is no number")
        values = [float(w) for w in words[1:]]
        if not all(math.isfinite(v) for v in values):
            raise _damaged(shown, n, "a value is no finite number")
        rows[row] = values
    missing = [r for r in ZS_ROWS if r not in rows]
    if missing:
        raise _damaged(shown, len(records) + 1, f"rows missing: {', '.join(missing)}")
    return {"columns": columns, "unit": UNITS[head[1].upper()], "strict": int(head[2][-1]), "rows": rows,
            "rotary": rotary}


def _damaged(shown: str, record: int, why: str) -> CplError:
    return CplError("CPL040", f"axis ZS table {shown} is damaged (record {record}: {why})")


def read(files, place: Place) -> dict:
    """The table in the file at ``place``; CPL040 when it does not exist, cannot be read or is damaged."""
    shown = place.shown
    try:
        records = files.read_records(place)
    except (FileNotFoundError, NotADirectoryError):
        raise CplError("CPL040", f"axis ZS table {shown} does not exist") from None
    except OSError as e:
        raise CplError("CPL040", f"axis ZS table {shown} cannot be read ({e.strerror})") from None
    return parse(records, shown)


def write(files, place: Place, table: dict) -> None:
    """Write the whole table atomically (CplFiles.replace_records); a write-protected file or one a
    program has open for writing is not changed."""
    shown = place.shown
    st = files.stat_of(place)
    if files.open_for_writing(st):
        raise CplError("CPL040", f"axis ZS table {shown} is open for writing (OPENW)")
    if st is not None and stat.S_ISDIR(st.st_mode):
        raise CplError("CPL040", f"axis ZS table {shown} is a directory")
    if st is not None and not st.st_mode & stat.S_IWUSR:
        raise CplError("CPL040", f"axis ZS table {shown} is write-protected")
    try:
        files.replace_records(place, records_of(table))
    except OSError as e:
        raise CplError("CPL040", f"axis ZS table {shown} cannot be written ({e.strerror})") from None
