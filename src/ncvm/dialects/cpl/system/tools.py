"""Tool compensation TC (manual §4.4) and the tool database TDA (manual §4.5).

Compensation table K4 is the machine's tool table (H = length, D = radius per group), so a length a
program writes is the one the NC kernel applies at the next G43; K5 and ASCII tables are kept beside it.
Tables and database records changed by a program are kept in the session store (cpl.tc, cpl.tdb).
"""

from __future__ import annotations

from ....machine.model import Tool
from ..errors import CplError
from ..values import sv
from .axes import nul
from .context import SystemContext

INCH = 25.4
STANDARD_TABLES = {4: "K4", 5: "K5"}
GENERAL_FIELDS = 8  # L(2)3, R, L(2)1, L(2)2, TO, type (read only), Euler angles 1 and 2


def setup(rt: SystemContext) -> None:
    """K4 and the machine's tool table agree (persisted K4 values win); the H word reads the tables."""
    for group, (h, d) in rt.ctl.tc_tables["K4"].items():
        _to_machine(rt, group, h, d)

    def length(kernel, table: int, group: int, src) -> float:
        """H<group>: the length compensation H of the table G22 K<table> selected (K4 at power-on, 0 none)."""
        if not table:
            return 0.0
        h = rt.ctl.tc_tables[STANDARD_TABLES[table]].get(group, (0.0, 0.0))[0]
        return h * INCH if rt.ctl.tc_unit == "inch" else h

    rt.kernel.length_compensation = length


def _to_machine(rt: SystemContext, group: int, h: float, d: float) -> None:
    unit = rt.ctl.tc_unit
    h, d = (h * INCH, d * INCH) if unit == "inch" else (h, d)
    tool = rt.machine.tools.get(group)
    if tool is None:
        rt.machine.tools[group] = Tool(group, h, d)
    else:
        tool.length, tool.radius = h, d


def _kind(group) -> str:
    if group.__class__ is not int:
        raise CplError("CPL032", f"compensation group {group!r}")
    if 1 <= group <= 48:
        return "standard"
    if 145 <= group <= 845 and group % 100 == 45:
        return "external"
    if 147 <= group <= 847 and group % 100 == 47:
        return "general"
    raise CplError("CPL023", f"compensation group {group}: 1..48, G145..G845 or G147..G847")


def _sel(sel, most: int) -> tuple[int, bool]:
    sel = nul(sel)
    if sel.__class__ is not int or not 1 <= abs(sel) <= most:
        raise CplError("CPL023", f"compensation selection {sel!r}: 1..{most} (negative = add)")
    return abs(sel) - 1, sel < 0


def _std_table(c, table) -> str:
    if table is None:
        return c.tc_last
    if table.__class__ is int:
        if table not in STANDARD_TABLES:
            raise CplError("CPL023", f"compensation table {table}: 4 (K4), 5 (K5) or a file name")
        return STANDARD_TABLES[table]
    if isinstance(table, str):
        if table not in c.tc_tables:
            raise CplError("CPL040", f"compensation table {table!r} does not exist")
        return table
    raise CplError("CPL032", f"compensation table {table!r}")


def _unit(unit):
    if unit is None:
        return None
    if unit not in (0, 2):
        raise CplError("CPL023", f"unit {unit}: 0 mm, 2 inch")
    return "mm" if unit == 0 else "inch"


def _conv(v: float, src: str, dst) -> float:
    if dst is None or dst == src:
        return v
    return v * INCH if src == "inch" else v / INCH


def f_tc(rt: SystemContext, sel, group=None, table=None, unit=None):
    """TC read: a table value in ``unit``; TC(sel) alone = the active compensation at block preparation."""
    c = rt.ctl
    if group is None:
        col, _ = _sel(sel, 2)
        k = rt.prepared_kernel()
        if col == 0:
            return k.tool_length / k.scale
        tool = rt.machine.tools.get(k.tool)
        return (tool.radius if tool else 0.0) / k.scale
    kind = _kind(group)
    if kind == "standard":
        col, _ = _sel(sel, 2)
        values = c.tc_tables[_std_table(c, table)].get(group, [0.0, 0.0])
        return _conv(values[col], c.tc_unit, _unit(unit))
    if table not in (0, None):
        raise CplError("CPL023", "external and general compensation use table 0")
    scale = rt.prepared_kernel().scale
    if kind == "external":
        col, _ = _sel(sel, 2)
        return c.tc_external.get(group, [0.0, 0.0])[col] / scale
    col, _ = _sel(sel, GENERAL_FIELDS)
    v = c.tc_general.get(group, [0.0] * GENERAL_FIELDS)[col]
    return v if col >= 4 else v / scale


def p_tc_set(rt: SystemContext, sel, group=None, table=None, unit=None, value=None):
    """TC(...)=value: replace (sel > 0) or add (sel < 0), converting from ``unit`` to the table unit."""
    c = rt.ctl
    value = nul(value)
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise CplError("CPL032", "TC needs a numeric value")
    if group is None:
        raise CplError("CPL023", "TC write needs a compensation group")
    kind = _kind(group)
    if kind == "standard":
        col, inc = _sel(sel, 2)
        name = _std_table(c, table)
        values = c.tc_tables[name].setdefault(group, [0.0, 0.0])
        u = _unit(unit)
        v = value if u is None else _conv(value, u, c.tc_unit)
        values[col] = (values[col] if inc else 0.0) + v
        c.persist("cpl.tc", name, {str(g): vals for g, vals in c.tc_tables[name].items()})
        if name == "K4":
            _to_machine(rt, group, *values)
            rt.forget_prepared()
        return
    if table not in (0, None):
        raise CplError("CPL023", "external and general compensation use table 0")
    if unit is not None:
        raise CplError("CPL023", "external and general compensation take no unit (G70/G71 decide)")
    scale = rt.prepared_kernel().scale
    if kind == "external":
        col, inc = _sel(sel, 2)
        values = c.tc_external.setdefault(group, [0.0, 0.0])
        v = value * scale
    else:
        col, inc = _sel(sel, GENERAL_FIELDS)
        if col == 5:
            raise CplError("CPL040", "the compensation type (selection 6) can only be read")
        values = c.tc_general.setdefault(group, [0.0] * GENERAL_FIELDS)
        v = value if col >= 4 else value * scale
    values[col] = (values[col] if inc else 0.0) + v


# -- tool database -----------------------------------------------------------------------------------
STRING_FIELDS = (8, 49)


def _tda_key(c, sector, place, fld, tooltab):
    if not c.tdb:
        raise CplError("CPL040", "no tool database is configured ([cpl] tool_database)")
    if tooltab != 1:
        raise CplError("CPL023", f"tool table {tooltab}: only 1")
    if fld.__class__ is not int or not 1 <= fld <= 49:
        raise CplError("CPL023", f"tool database field {fld!r}: 1..49")
    if fld in (1, 2):
        raise CplError("CPL040", "fields 1 (sector) and 2 (place) cannot be accessed")
    key = (nul(sector), nul(place))
    if key not in c.tdb:
        raise CplError("CPL040", f"tool database has no sector {sector} place {place}")
    return key


def f_tda(rt: SystemContext, sector, place, fld, tooltab=1):
    """TDA read: INTEGER fields 3-7 and 9-48, STRING fields 8 and 49 (L1895-1966)."""
    c = rt.ctl
    key = _tda_key(c, sector, place, fld, tooltab)
    return c.tdb[key].get(fld, "" if fld in STRING_FIELDS else 0)


def p_tda_set(rt: SystemContext, sector, place, fld, tooltab=1, value=None):
    """TDA(...)=value: the value's type must match the field's (INTEGER, or a STRING of at most 31)."""
    c = rt.ctl
    key = _tda_key(c, sector, place, fld, tooltab)
    value = nul(value)
    value = sv(value)
    if fld in STRING_FIELDS:
        if not isinstance(value, str):
            raise CplError("CPL021", f"field {fld} is a STRING field")
        if len(value) > 31:
            raise CplError("CPL023", f"field {fld}: at most 31 characters")
        if "\x00" in value:  # the store keeps codes 1..255, the same rule as `ncvm state import`
            raise CplError("CPL023", f"field {fld}: CHR$(0) is NUL, no value (L758-762)")
    elif value.__class__ is not int:
        raise CplError("CPL021", f"field {fld} is an INTEGER field")
    c.tdb[key][fld] = value
    c.persist("cpl.tdb", f"{key[0]},{key[1]}", {str(k): v for k, v in c.tdb[key].items()})
