"""The one @ code table: each row names its main group's module, a lowering the code generator has, a
run-time function the channel has, and the CL 800 compiler's statement tables are read from the rows."""

from __future__ import annotations

import pytest

from ncvm.dialects.sinumerik import atcodes
from ncvm.dialects.sinumerik.atcodes import AT_CODES
from ncvm.dialects.sinumerik.cl800 import tables
from ncvm.dialects.sinumerik.codegen import UnitCodegen
from ncvm.dialects.sinumerik.cycles import Cycles
from ncvm.dialects.sinumerik.memory import SystemMemory
from ncvm.dialects.sinumerik.offsets import Offsets
from ncvm.dialects.sinumerik.panel import Panel
from ncvm.dialects.sinumerik.plcmem import Plc
from ncvm.dialects.sinumerik.positions import Positions
from ncvm.dialects.sinumerik.runtime import Channel
from ncvm.dialects.sinumerik.spindle import Spindle

#: the channel's parts a row's run-time function may belong to (``plc.read``)
PARTS = {"": Channel, "memory": SystemMemory, "plc": Plc, "spindle": Spindle, "offsets": Offsets,
         "positions": Positions, "cycles": Cycles, "panel": Panel}

ROWS = sorted(AT_CODES.values(), key=lambda r: r.code)


@pytest.mark.parametrize("row", ROWS, ids=lambda r: r.code)
def test_each_row_has_its_lowering_and_run_time_function(row):
    assert row.code in {r.code for r in getattr(atcodes, f"group{row.code[0]}").ROWS}
    assert callable(getattr(UnitCodegen, f"lower_{row.lower}"))
    if row.run is not None:  # a function of the channel or of one of its parts (``plc.read``)
        part, _, name = row.run.rpartition(".")
        assert callable(getattr(PARTS[part], name))
    # the channel's entry points dispatch by the row: every code they receive has a run-time function
    if row.lower in ("read", "write", "write_rotation", "nc_refs", "stop_dec", "io", "io_out", "io_in"):
        assert row.run is not None
    assert (row.expr is not None) == (row.lower in ("branch", "math"))


def test_the_cl800_tables_are_the_rows():
    """Every CL 800 statement the compiler knows is a row of the table with the same code and operands."""
    named = {(r.cl800, r.cl800_name): r for r in ROWS if r.cl800}
    assert len(named) == sum(1 for r in ROWS if r.cl800)
    for form, table in (("function", tables.FUNCTIONS), ("read", tables.SYS_READS), ("write", tables.SYS_WRITES),
                        ("nc_function", tables.NC_FUNCTIONS), ("procedure", tables.PROCEDURES)):
        for name, (code, *_rest) in table.items():
            assert named[form, name].code == code
    assert tables.SYS_READS["MIB"] == ("211", 1, 1) and tables.SYS_WRITES["MIB"] == ("212", 1)
    assert tables.SYS_READS["ACAS"] == ("367", 1, 5) and tables.SYS_READS["ALNP"] == ("3c0", 0, 0)
    assert tables.NC_FUNCTIONS["PREP REF"] == ("710", "v", 8) and tables.NC_FUNCTIONS["MEAS M"] == ("720", "x", 2)
    assert tables.PROCEDURES["SET BIT"] == ("661", "b") and tables.PROCEDURES["INTA"] == ("736", "xxx")
    assert tables.LOGIC == {"OR": "650", "XOR": "651", "AND": "652", "NAND": "653", "ORB": "655", "XORB": "656",
                            "ANDB": "657", "NANDB": "658"}
    assert (len(tables.FUNCTIONS), len(tables.SYS_READS), len(tables.SYS_WRITES), len(tables.NC_FUNCTIONS),
            len(tables.PROCEDURES)) == (10, 67, 48, 4, 22)
