"""Active system data of manual §4.9: SD, SDR, MCA, NCF (CPL manual §4.9, L2052-2351).

Index 1 of the "last programmed / active" pairs reads the prepared NC state (the runtime's prepared
kernel), index 2 the executed one (the NC kernel), as CPL manual §4.9, L2214-2300 maps them.
"""

from __future__ import annotations

import math

from ....nc.cutter import active_g
from ....nc.profiles.typ3osa import TYP3OSA
from ..errors import CplError
from ..values import sv
from .axes import nul
from .context import SystemContext
from .controller import MAX_AREAS, SD13_OF_MODE
from .gfuncs import N_LOGICAL
from .positions import probe_switched
from .transforms import active_group

#: G group (the SD(1) supplementary table, L2302-2306) -> the G numbers in it, from the typ3osa profile
G_GROUPS = {}
for _row in TYP3OSA.rows:
    if _row.group:
        G_GROUPS.setdefault(int(_row.group), []).append(_row.g)
GROUP_OF = {g: grp for grp, gs in G_GROUPS.items() for g in gs}
PLANE_AXES = {17: (1, 2), 18: (3, 1), 19: (2, 3)}


def g_of_group(k, group: int, typ3=None) -> int:
    """The G number the kernel state (and the Typ3 G-function state ``typ3`` that goes with it) has in G
    group ``group``; -1 for a group it does not apply."""
    if group == 28 and typ3 is not None:
        return typ3.external or 146  # external tool compensation G145..G845, G146 = none
    if group == 30 and typ3 is not None:
        return typ3.external_zs  # external zero shift G160/G260/G360, G167 = none
    if group == 16 and typ3 is not None:
        return typ3.zs16  # G154..G159, G153 = none
    if group == 17 and typ3 is not None:
        return typ3.zs17  # G254..G259, G253 = none
    if group == 2:
        return k.motion
    if group == 3:
        return 71 if k.scale == 1.0 else 70
    if group == 4:
        return 90 if k.absolute else 91
    if group == 8:
        return active_g(k)
    if group == 10:
        return k.modal.get("10", k.plane)  # G20, or the plane G17..G19
    if group == 15:
        return int(k.work_offset[1:]) if k.work_offset else 53
    if group == 20:
        return 61 if k.exact else 62  # the path mode (CPL_PATH_CODES): exact stop or continuous path
    if group == 7:
        return 95 if k.per_rev else 94  # feed per minute or per revolution (L2817); the kernel refuses G93
    if group in (18, 19):
        return active_group(k, group)
    if str(group) in TYP3OSA.defaults:  # the groups whose active function is all ncvm keeps of them
        return k.active_in(str(group))
    if 1 <= group <= 48:
        return -1
    raise CplError("CPL023", f"G group {group}: 1..48")


def _pair(rt: SystemContext, which):
    if which not in (1, 2):
        raise CplError("CPL023", f"index {which}: 1 (last programmed) or 2 (active)")
    return rt.prepared_kernel() if which == 1 else rt.kernel


def _spindle(k) -> int:
    return {1: 3, -1: 4, 0: 0}[k.spindle_dir]


def f_sd(rt: SystemContext, group, i1=None, i2=None, i3=None):
    """SD: system data as INTEGER (L2196-2312)."""
    c = rt.ctl
    group = nul(group)
    if group == 1:
        if i2 not in (1, 2):
            raise CplError("CPL040" if i2 == 3 else "CPL023", "SD(1,g,1|2): 3 (power-on state) is not available")
        g = nul(i1)
        if g.__class__ is not int and g.__class__ is not float:
            raise CplError("CPL023", f"G group {g!r}: 1..48")
        # 1 = active (executed), 2 = last programmed (prepared), L2218
        if i2 == 1:
            return g_of_group(rt.kernel, g, c.g_active)
        return g_of_group(rt.prepared_kernel(), g, c.g_programmed)
    if group == 2 or group == 202:
        key = {1: "feed", 3: "spindle", 4: "spindle2"}.get(i1 if group == 2 else {1: 3, 2: 4}.get(i1))
        if key is None:
            raise CplError("CPL040", f"SD({group},{i1}) is not available")
        return c.override[key]
    if group == 5:
        k = _pair(rt, 2 if i2 in (None, 1, 3) else 1)
        if i1 == 1:
            feed = k.feed / k.scale * (c.override["feed"] / 100.0 if i2 in (None, 1) else 1.0)
            return math.ceil(feed - 1e-9)
        if i1 == 2 and i2 in (None, 1):
            return math.ceil(max(a.rapid for a in rt.machine.axes) / k.scale - 1e-9) if rt.machine.axes else 0
        if i1 == 3:
            speed = k.speed * (c.override["spindle"] / 100.0 if i2 in (None, 1) else 1.0)
            return math.ceil(speed - 1e-9) if k.spindle_dir or i2 == 2 else 0
        if i1 == 4:
            return 0  # the machine model has one spindle
        raise CplError("CPL023", f"SD(5,{i1},{i2})")
    if group == 8:
        return c.channel
    if group == 9:
        return probe_switched(rt)
    if group == 10:
        k = _pair(rt, nul(i1))
        return k.tool_axis + 1 if k.tool_axis is not None else 0
    if group == 11:
        k = _pair(rt, {1: 1, 2: 2}.get(i2, 0) if i2 is not None else 1)
        first, second = PLANE_AXES.get(k.plane, (1, 2))
        return first if i1 == 1 else second
    if group == 12:
        if i1 in (1, 2):
            return _spindle(rt.kernel if i1 == 1 else rt.prepared_kernel())
        if i1 in (3, 4):
            return -1  # no 2nd spindle
        raise CplError("CPL023", f"SD(12,{i1})")
    if group == 13:  # the machining mode of the own channel (automatic unless MCOPS 7 changed it, L2241)
        return SD13_OF_MODE.get(c.ncs["mode"].get(c.channel, 5), 1)
    if group == 14:
        return c.macoda[601000010][0]
    if group == 15:
        return 0
    if group == 20:
        return len(c.channel_axes(c.channel))
    if group == 21:
        return len(c.channel_axes(nul(i1)))
    if group in (22, 23, 24, 25):
        return _axis_numbers(rt, group, i1, i2)
    if group in (205, 212):
        k = rt.kernel if i1 in (1, 3) else rt.prepared_kernel()
        if i2 not in (None, 1):
            return 0 if group == 205 else -1
        return math.ceil(k.speed - 1e-9) if group == 205 else _spindle(k)
    if group in TYP3_GROUPS:
        if group == 131 and i1 not in (1, 2):
            raise CplError("CPL023", f"SD(131,{i1}): 1 (last programmed) or 2 (active)")
        return _whole(_typ3(rt, group, i1, i2))
    if group == 200:
        return _area(rt, i1, i2)
    raise CplError("CPL040", f"SD({group}) is not available in this simulation")


TYP3_GROUPS = (68, 168, 268, 131, 328, 581)


def _whole(v):
    """An SD value as INTEGER: a length or an angle rounded half away from zero."""
    if v.__class__ is int:
        return v
    return int(math.copysign(math.floor(abs(v) + 0.5), v))


def _length(rt: SystemContext, kernel, n: int, mm: float) -> float:
    """mm of logical axis n -> programming units (rotary axes: degrees)."""
    ax = rt.ctl.channel_axes(rt.ctl.channel)[n - 1]
    return mm if ax.rotary else mm / kernel.scale


def _logical(rt: SystemContext, a) -> int:
    n = len(rt.ctl.channel_axes(rt.ctl.channel))
    if a.__class__ is not int or not 1 <= a <= min(n, N_LOGICAL):
        raise CplError("1938", f"logical axis {a!r} is not applied (1..{min(n, N_LOGICAL)})")
    return a


def _typ3(rt: SystemContext, group, i1, i2):
    """Groups 68/168/268 (coordinate shifts), 131 (G131), 328 (G328), 581 (axis coupling): REAL values."""
    c = rt.ctl
    if group in (68, 168, 268):
        if i1 not in (1, 2):
            raise CplError("CPL023", f"SD({group},{i1}): 1 (last programmed) or 2 (active)")
        st, k = (c.g_programmed, rt.prepared_kernel()) if i1 == 1 else (c.g_active, rt.kernel)
        n = _logical(rt, i2)
        mm = (st.g168[n - 1] if group != 268 else 0.0) + (st.g268[n - 1] if group != 168 else 0.0)
        return _length(rt, k, n, mm)
    if group == 131:
        if i1 in (1, 2):
            return (c.g_programmed if i1 == 1 else c.g_active).rotation_axis
        if i1 in (3, 4):
            st = c.g_active
            return float(st.offset_angle if i1 == 3 else st.adaptation_angle)
        raise CplError("CPL023", f"SD(131,{i1}): 1 programmed, 2 active axis; 3 offset, 4 adaptation angle")
    if group == 328:
        st, k = c.g_programmed, rt.prepared_kernel()
        if i1 in (None, 1):
            return st.barrier / k.scale
        if i1 == 2:
            return st.corners / k.scale
        raise CplError("CPL023", f"SD(328,{i1}): 1 precision barrier, 2 distance between corners")
    return _coupling(rt, i1, i2)


def _coupling(rt: SystemContext, i1, i2):
    """Group 581: SD(581,0,m) = m if logical axis m is a master; SD(581,s,0..3) for slave s."""
    st, k = rt.ctl.g_programmed, rt.prepared_kernel()
    if i1 == 0:
        m = _logical(rt, i2)
        return m if any(cp[1] == m for cp in st.coupling) else 0
    s = _logical(rt, i1)
    if i2 not in (0, 1, 2, 3):
        raise CplError("CPL023", f"SD(581,{s},{i2}): 0 master, 1 slave shift, 2 factor, 3 master shift")
    cp = next((cp for cp in st.coupling if cp[0] == s), None)
    if cp is None:
        return 0 if i2 == 0 else 0.0
    if i2 == 0:
        return cp[1]
    if i2 == 2:
        return cp[3]
    return _length(rt, k, s if i2 == 1 else cp[1], cp[2] if i2 == 1 else cp[4])


def _area(rt: SystemContext, i1, i2):
    """Group 200: work areas and dead ranges of the channel ([cpl] areas), values in programming units."""
    areas = rt.ctl.areas
    if i1 == 1 and i2 is None:
        return sum(1 for a in areas if a["active"])
    if i1 not in (1, 2, 3, 11, 12, 21, 22):
        raise CplError("CPL023", f"SD(200,{i1}): 1, 2, 3, 11, 12, 21 or 22")
    if i2.__class__ is not int or not 1 <= i2 <= MAX_AREAS:
        raise CplError("CPL023", f"SD(200,{i1},{i2!r}): area 1..{MAX_AREAS}")
    area = areas[i2 - 1] if i2 <= len(areas) else None
    if i1 in (1, 2):
        return 1 if area and area["active"] else 0
    if i1 == 3:
        return area["type"] if area else 0
    if area is None:
        return 0
    value = (area["centre"] if i1 < 20 else area["extent"])[i1 % 10 - 1]
    ax = rt.ctl.by_name(area["axes"][i1 % 10 - 1])
    return _whole(value if ax.rotary else value / rt.kernel.scale)


def _axis_numbers(rt: SystemContext, group, i1, i2):
    c = rt.ctl
    logical = c.channel_axes(c.channel if group != 24 else nul(i2))
    if group in (22, 25):
        ax = c.by_name(i1) if isinstance(i1, str) else c.axes.get(i1)
        if ax is None:
            raise CplError("1938", f"physical axis {i1!r} is not configured")
        if group == 25:
            return ax.channel
        if ax not in logical:
            raise CplError("1970", f"axis {ax.name} is not on channel {c.channel}")
        return logical.index(ax) + 1
    if isinstance(i1, str):
        ax = next((a for a in logical if a.name == i1.upper()), None)
    else:
        ax = logical[i1 - 1] if i1.__class__ is int and 1 <= i1 <= len(logical) else None
    if ax is None:
        raise CplError("1938", f"logical axis {i1!r} is not configured")
    return ax.index


def f_sdr(rt: SystemContext, group, i1=None, i2=None):
    """SDR: system data as REAL (L2313-2351)."""
    c = rt.ctl
    group = nul(group)
    if group in (2, 202):
        return float(f_sd(rt, group, i1))
    if group == 1:
        logical = c.channel_axes(c.channel)
        if i1.__class__ is not int or not 1 <= i1 <= len(logical):
            raise CplError("1938", f"SDR(1,{i1}): machining axis not applied")
        return 0.0  # no block search has run (L2316)
    if group in (68, 168, 268, 328, 581) or group == 131 and i1 in (3, 4):
        return float(_typ3(rt, group, i1, i2))
    raise CplError("CPL040", f"SDR({group}) is not available in this simulation")


#: old MACODA numbers (up to V4.x) -> new ones (A.4, L5566-5593)
OLD_MACODA = {100100001: 100300001, 100100002: 100300002, 100100003: 100100001, 100100004: 100300004,
              100100005: 100300005, 101000003: 101000011, 101000004: 101000012, 101500001: 101500002,
              101500006: 101500100, 101500007: 101500001}


def f_mca(rt: SystemContext, param, index, chan=None):
    """MCA: a MACODA value; index 0-based; chan own channel by default, -1 = basic setting (L2054-2089)."""
    c = rt.ctl
    param = nul(param)
    number = OLD_MACODA.get(param, param)
    if number not in c.macoda:
        raise CplError("CPL040", f"MACODA parameter {param} does not exist")
    if chan is not None and chan != -1 and not c.channel_axes(chan):
        raise CplError("CPL040", f"MACODA channel {chan} does not exist")
    values = c.macoda[number]
    if index.__class__ is not int or not 0 <= index < len(values):
        raise CplError("CPL040", f"MACODA {param} has no individual parameter {index}")
    return values[index]


def f_ncf(rt: SystemContext, text):
    """NCF: the text of the last programmed function of the modal group of ``text`` (L2090-2113)."""
    text = sv(nul(text))
    if not isinstance(text, str) or not text.upper().startswith("G") or not text[1:].isdigit():
        raise CplError("CPL040", f"NCF({text!r}): unknown NC function")
    group = GROUP_OF.get(int(text[1:]))
    if group is None:
        raise CplError("CPL040", f"NCF({text!r}): unknown NC function")
    g = g_of_group(rt.prepared_kernel(), group, rt.ctl.g_programmed)
    return "" if g < 0 else f"G{g}"
