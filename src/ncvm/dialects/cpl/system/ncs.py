"""NCS coupling of manual §4.14: MCODS (data services) and MCOPS (process services); AXP (§4.10).

MCODS fills a buffer (a field given by name; element 1 first, as the manual's BUF%(1)) and returns an NCS
status code (CPL manual §4.14, L2623-2684). The version variable is written back: a version of 0 delivers at once; the
same non-zero version blocks until the data changes, letting queued blocks execute; if nothing can change
the data it is the simulator deadlock error. Types not modelled here return 102 (not available).
"""

from __future__ import annotations

import zlib

from ....nc.spindle import CPL_GEARS
from ..errors import CplError
from ..io.strings import CharacterField
from .axes import kernel_index, nul
from .context import SystemContext
from .gfuncs import GEARS, additive_zs, external_shift, program_shift
from .offsets import push_to_kernel
from .sysdata import g_of_group

OK, NO_CHANNEL, BUSY, SYNTAX, NOT_AVAILABLE, NO_PROGRAM, MODE_REFUSED = 0, 1, 2, 18, 102, 6, 13
STARTED = 15  # search block impossible: the main program has already been started


class ControlReset(Exception):
    """MCOPS(2) on the program's own channel (or the whole system): the interpolator stops, the jobs not
    yet executed are discarded and the main program is exited (L3155-3166)."""

    def __init__(self, chan: int):
        super().__init__(f"control reset of {'the system' if chan == -2 else f'channel {chan}'}: "
                         "the main program is exited (MCOPS 2)")
#: M functions the NC kernel carries out itself; any other one is an auxiliary function the PLC acknowledges
KERNEL_M = frozenset((0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 30))
#: channel operating modes MCODS 31/48 and MCOPS 7 (CPL manual L2904-2911)
MODES = (1, 2, 4, 5, 6, 7, 10, 11, 12, 13, 14)


def _channels(c) -> list[int]:
    return sorted({a.channel for a in c.axes.values() if a.channel > 0})


def _sav_ipo(rt: SystemContext, ch: int) -> list[int]:
    """SAV and IPO state (CPL manual §4.14, L2687-3127): the own channel is active while blocks are prepared or queued."""
    if ch == rt.ctl.channel:
        return [3, 1 if rt.queue or rt.moving() else 3]
    return [2 if rt.ctl.ncs["selected"].get(ch) else 1, 3]


def _positions(rt: SystemContext, axes, mcs=True) -> list[float]:
    """MCS positions at the program's time, or (mcs=False) the programmed end points of the executed blocks."""
    pos = rt.executed_position() if mcs else rt.kernel.prog
    return [a.position if (i := kernel_index(rt, a)) is None else pos[i] for a in axes]


def _coordinates(rt: SystemContext, axes, wcs: bool) -> list[float]:
    """MCODS 71 (WCS) and 72 (BCS): the MCS without the axis zero shifts and the tool length (G92 and the
    program shifts G168/G268 stay in); the WCS also without the coordinate transformation G138, which lies
    between the two (manual L1323)."""
    k = rt.kernel
    rel = [m - o for m, o in zip(rt.executed_position(), k.offset_vec)]
    if wcs and k.transform is not None:
        rel = k.transform.to_wcs(rel)
    return [a.position if (i := kernel_index(rt, a)) is None else rel[i] + k.g92[i] + program_shift(rt, k, i)
            for a in axes]


def _data(rt: SystemContext, typ: int, ch: int, size: int, axisno, idno):
    """The data of service ``typ`` as a list (numbers) or a string; None = not available."""
    c, k = rt.ctl, rt.kernel
    system = [c.axes[i] for i in sorted(c.axes)]
    own = c.channel_axes(ch) if ch > 0 else system
    if typ == 1:
        return _positions(rt, system)
    if typ == 2:
        return [int(round(v * 10000)) for v in _positions(rt, system)]
    if typ == 3:
        f = k.feed * c.override["feed"] / 100.0
        return [f, f, f]
    if typ == 7:
        return [c.override["feed"] * 100.0]
    if typ == 9:  # the compensation group of the H word (L2835), -1 for none
        return [k.modal.get("H") or -1]
    if typ == 10:
        return [k.tool_length]
    if typ == 13:  # the table G22 K selected (L2851); three blanks for none (G22 K0)
        table = k.modal.get("G22", 4)
        return f"K{table}" if table else "   "
    if typ == 14:
        return c.zs_active
    if typ == 15:  # the active row of each group G53..G59, G153..G159, G253..G259 (L2856), in mm
        st = c.g_active
        rows = (int(k.work_offset[1:]) if k.work_offset else None, st.zs16, st.zs17)
        return [additive_zs(c, g, a.name) if g else 0.0 for g in rows for a in own]
    if typ == 18:
        return [0 if k.scale != 1.0 else 1]
    if typ == 24:
        return [rt.prepared_kernel().feed]
    if typ == 26:
        return [1] * len(system)
    if typ == 29:
        return [0]
    if typ == 30:
        return str(rt.linked.main.prog.path) if ch == c.channel else rt.ctl.ncs["selected"].get(ch, "")
    if typ == 31:
        return [rt.ctl.ncs["mode"].get(ch, 5)]
    if typ == 32:
        return _sav_ipo(rt, ch)
    if typ in (33, 59, 60):
        return "".join(a.name[:8].ljust(8) + "\0" for a in (system if ch == -1 else own))
    if typ == 35:
        return [p - a.lag for p, a in zip(_positions(rt, system), system)]
    if typ == 43:
        return [a.channel if a.channel > 0 else -1 for a in system]
    if typ == 44:
        n = len(_channels(c))
        return [n, n, n]
    if typ == 45:
        return [len(system), len(system), 1]
    if typ == 53:
        return [2 if a.rotary else (1 if k.scale == 1.0 else 0) for a in own]
    if typ == 58:
        return [a.channel for a in system]
    if typ == 71:
        return _coordinates(rt, own, wcs=True)
    if typ in (73, 74):
        return _positions(rt, own)
    if typ == 76:
        return _positions(rt, own, mcs=False)
    if typ == 87:  # b0 dwell, b1 auxiliary function awaiting acknowledgement, b12 waiting block preparation
        dwell, aux = _status(rt, 39, ch, system, own)[0], _status(rt, 40, ch, system, own)[0]
        return [dwell | aux << 1 | ((1 << 12) if rt.queue else 0)]
    return _more(rt, typ, ch, system, own, axisno, idno)


def _spindle_speed(rt: SystemContext) -> float:
    """The commanded speed with the potentiometer, held within the permissible range (MCODS 19/20)."""
    c, k = rt.ctl, rt.kernel
    if not k.spindle_dir:
        return 0.0
    return min(max(k.speed * c.override["spindle"] / 100.0, c.spindle["min"]), c.spindle["max"])


def _more(rt: SystemContext, typ: int, ch: int, system, own, axisno, idno):
    """Further services: lags, spindles, in-position and travel flags, end points, distance to go."""
    c, k = rt.ctl, rt.kernel
    moving = bool(rt.queue) or rt.moving()
    if typ == 4:
        return [a.lag for a in system]
    if typ in (5, 36):
        return [_spindle_speed(rt)]
    if typ == 25:
        return [float(rt.prepared_kernel().speed)]
    if typ in (6, 47):
        flag = [1 if not (moving and a.channel == c.channel) else 0 for a in system]
        return flag if typ == 6 else [1 - f for f in flag]
    if typ == 8:
        return [c.override["spindle"] * 100.0]
    if typ in (16, 23, 77):
        p = rt.prepared_kernel()
        out = []
        for a in own if typ == 77 else system:
            i = kernel_index(rt, a)
            if i is None:
                out.append(a.position)
            elif typ == 23:
                out.append(p.prog[i] + p.g92[i])
            else:
                out.append(p.machine_pos[i] - (p.g92[i] if typ == 16 else 0.0))
        return out
    if typ == 46:
        how, where = rt.ctl.ncs["return"].get(ch, (1, 3))
        return [how, where, 1 if rt.ctl.ncs["recording"].get(ch, True) else 0]
    if typ == 48:
        return [rt.ctl.ncs["mode"].get(a.channel, 5) if a.channel > 0 else 0 for a in own]
    if typ == 52:
        return external_shift(c, c.g_active)
    if typ == 61:
        return [2 if a.rotary else 1 for a in own]
    if typ == 63:
        return [{1: 1, -1: 3, 0: 5}[k.spindle_dir]] + [0] * 7
    if typ in (72, 75):
        bcs = _coordinates(rt, own, wcs=False)
        return bcs if typ == 72 else [v - a.lag for v, a in zip(bcs, own)]
    if typ in (79, 80):
        return [1 if typ == 80 or not (moving and a.channel == c.channel) else 0 for a in own]
    if typ == 81:
        return [2 if a.rotary else (1 if k.scale == 1.0 else 0) for a in own]
    if typ == 82:
        return [len(own), len(own), len(own)]
    if typ == 37:  # program values: the MCS without the axis zero shifts and without G92
        out, now = [], rt.executed_position()
        for a in system:
            i = kernel_index(rt, a)
            tool = k.tool_length if i is not None and i == k.tool_axis else 0.0
            out.append(a.position if i is None else k.prog[i] + tool + now[i] - k.machine_pos[i])
        return out
    if typ == 38:
        return [p - a.lag for p, a in zip(_positions(rt, system), system)]
    if typ in (55, 56, 57, 62):
        return _drive(rt, typ, system, axisno, idno)
    if typ == 68:
        skip = 1 if rt.block_skip else 0
        return [skip, skip]
    if typ == 69:  # the NC kernel stops at every M1: optional stop is activated, and its input is set
        return [1, 1]
    if typ in (89, 90):  # the simulated machine has no online correction: per coordinate 0.0 / inactive (0)
        return [0.0 if typ == 89 else 0 for _ in own]
    if typ == 78:
        return "".join(a.name[:8].ljust(8) + "\0" for a in own)
    if typ == 83:
        p = rt.prepared_kernel()
        now = rt.executed_position()
        return [p.machine_pos[i] - now[i] if (i := kernel_index(rt, a)) is not None else 0.0 for a in own]
    return _status(rt, typ, ch, system, own)


def _status(rt: SystemContext, typ: int, ch: int, system, own):
    """Compensations, spindle limits and gears, jog speeds, messages, potentiometers, waiting states."""
    c, k = rt.ctl, rt.kernel
    if typ in (11, 12):  # tool radius compensation: G41/G42 of G group 8
        active = g_of_group(k, 8) != 40
        return [(k.tool if active else -1) if typ == 11 else 0.0]
    if typ in (19, 20):
        return [c.spindle["max" if typ == 19 else "min"]]
    if typ == 27:  # linear axes mm/min, rotary axes rpm
        return [a.jog / 360.0 if a.rotary else a.jog for a in system]
    if typ == 28:
        return c.message
    if typ in (39, 40, 67):  # dwell / auxiliary function awaiting acknowledgement / gear change
        head = rt.executing_block()
        spindles = [0] * 7 if typ == 67 else []  # 67: one value per spindle, 8 places
        if head is None:
            return [0] + spindles
        if typ == 39:
            return [1 if 4 in head.g else 0]
        pending = GEARS if typ == 67 else [m for m in head.m if m not in KERNEL_M]
        return [1 if any(m in pending for m in head.m) else 0] + spindles
    if typ == 50:  # 1/100 %: the channel potentiometer for the channel's axes, else the axis potentiometer
        axis = c.override["axis"] * 100.0
        if ch == -1:
            return [axis] * len(system)
        return [c.override["feed"] * 100.0] * len(own) + [axis for a in system if a.channel == 0]
    if typ == 51:  # radius, length of the selected external compensation (TC table 0 stores [L3, R])
        length, radius = c.tc_external.get(c.g_active.external, [0.0, 0.0]) if c.g_active.external else (0.0, 0.0)
        return [radius, length]
    if typ == 54:  # R, L3, L1, L2, TO, type of the selected general compensation
        if not c.g_active.general:
            return [0.0] * 6
        v = c.tc_general.get(c.g_active.general, [0.0] * 8)
        return [v[1], v[0], v[2], v[3], v[4], v[5]]
    if typ == 64:
        return [c.g_active.gear] + [0] * 7
    if typ == 65:
        return [c.spindle["group"]] + [0] * 7
    if typ == 66:  # 1 automatic gear selection (M40), 0 a gear chosen by hand
        return [1 if CPL_GEARS.is_auto(c.g_active.gear) else 0] + [0] * 7
    if typ == 70:
        return [rt.ctl.ncs["reselect"].get(ch, 1)]
    return None


DRIVE_TEXTS = {55: "S-0-0030", 56: "S-0-0140", 57: "S-0-0141"}  # manufacturer version, controller, motor


def _drive(rt: SystemContext, typ, system, axisno, idno):
    """55-57: a drive's identification texts (axisno, 0 = axis 1); 62: SERCOS ``idno`` of every axis from
    the cyclic telegram (S-0-0051 the actual position), -2147483648 where the telegram lacks it."""
    c = rt.ctl
    if typ in DRIVE_TEXTS:
        ax = c.axes.get(axisno or 1)
        if ax is None:
            return None
        return str(c.sercos.get(ax.index, {}).get(DRIVE_TEXTS[typ], ""))[:40]
    if idno.__class__ is not int:
        return None
    key = f"S-0-{idno:04d}"
    out = []
    for a in system:
        if key == "S-0-0051":
            i = kernel_index(rt, a)
            out.append(int(round(((a.position if i is None else rt.executed_position()[i]) - a.lag) * 10000)))
        else:
            v = c.sercos.get(a.index, {}).get(key)
            out.append(v if isinstance(v, int) else -2147483648)
    return out


def f_mcods(rt: SystemContext, typ, chan, version, buffer, size, axisno=None, idno=None, p1=None):
    """MCODS(type,chan,version,buffer,size[,axisno[,idno[,P1]]]) -> (status, new version)."""
    c = rt.ctl
    typ, chan, size = (_whole(v) for v in (typ, chan, size))
    if chan > 0 and chan not in _channels(c):
        return NO_CHANNEL, version
    data = _data(rt, typ, chan, size, axisno, idno)
    if data is None:
        return (SYNTAX if typ in (17, 21, 22, 84, 85, 86, 88) else NOT_AVAILABLE), version
    ver = _version(data)
    if version not in (0, None) and int(version) == ver:
        while rt.execute_next():  # block until the data changes: execution goes on
            data = _data(rt, typ, chan, size, axisno, idno)
            ver = _version(data)
            if ver != int(version):
                break
        else:
            raise CplError("CPL039", f"MCODS({typ}): the data cannot change while the program waits for it")
    _fill(buffer, data, size)
    return OK, ver


def _whole(v) -> int:
    """An integer expression of MCODS: the manual's example 5 (L3342) passes REAL variables holding whole
    numbers (``CHAN=SD(8)``, ``IDCHAX=43``, ``SIZE=16``), so such a REAL counts as its integer."""
    if v.__class__ is float and v.is_integer():
        return int(v)
    if v.__class__ is not int:
        raise CplError("CPL032", "MCODS type, channel and size are INTEGER")
    return v


def _version(data) -> int:
    return (zlib.crc32(repr(data).encode()) & 0xFFFFFF) or 1  # exact in a REAL variable


def _fill(ref, data, size: int) -> None:
    """Write the data into the buffer (field, type) from element 1 on, as the manual's BUF%(1)."""
    buffer, ty = ref if isinstance(ref, tuple) else (ref, None)
    if isinstance(data, str):
        if not isinstance(buffer, CharacterField):
            raise CplError("CPL032", "MCODS: this service needs a DIMensioned character field")
        if size > buffer.size:
            raise CplError("CPL023", f"MCODS size {size} is larger than the field ({buffer.size})")
        buffer.assign(data[:size])
        return
    if not isinstance(buffer, list) or ty not in ("I", "R", "D"):
        raise CplError("CPL032", "MCODS: this service needs a numeric variable or field")
    if size > len(buffer) - 1:
        raise CplError("CPL023", f"MCODS size {size} is larger than the field ({len(buffer) - 1})")
    for n, v in enumerate(data[:size], 1):
        buffer[n] = int(round(v)) if ty == "I" else float(v)


def f_mcops(rt: SystemContext, fct, chan, p1=None, p2=None, p3=None, p4=None):
    """MCOPS(fct,chan[,p1..p4]): a process service on a channel; returns an NCS status code (L3128-3231)."""
    c = rt.ctl
    st = rt.ctl.ncs
    if chan != -2 and chan not in _channels(c):
        return NO_CHANNEL
    own = chan == c.channel
    if fct == 1:  # cancel distance to go: the prepared blocks are prepared again with the new corrections
        if own:
            push_to_kernel(rt)
        return OK
    if fct in (2, 5):  # type 2: no automatic program re-selection (MCODS 70)
        for ch in (_channels(c) if chan == -2 else [chan]):
            st["reselect"][ch] = 0 if p1 == 2 else 1
    if fct == 2:  # control reset: errors of the channel cleared, offsets of the channel re-read
        c.errors[:] = [e for e in c.errors if chan != -2 and e["channel"] not in (chan, -1)]
        st["selected"].pop(chan, None)
        if own or chan == -2:
            rt.queue.clear()  # jobs not yet executed are discarded (L3159)
            push_to_kernel(rt)
            raise ControlReset(chan)
        return OK
    if fct == 3:
        if own:
            return STARTED
        return OK if st["selected"].get(chan) else 10
    if fct == 4:
        if own:
            return 11
        name = nul(p1)
        private = (rt.session.options.state_dir, *rt.machine.own_files())  # a program folder may hold them
        if rt.machine.find_program(name, (".cpl", ".CPL"), ignore_case=False, private=private) is None:
            return NO_PROGRAM
        st["selected"][chan] = name
        return OK
    if fct == 5:
        if own:
            return BUSY
        st["selected"].pop(chan, None)
        return OK
    if fct == 6:
        if own:
            return 9
        return OK if st["selected"].get(chan) else 10
    if fct == 7:
        if p1 not in MODES:
            return SYNTAX
        if own and p1 not in (5, 6, 7, 10):
            return MODE_REFUSED  # a program is running: only automatic sub-modes
        st["mode"][chan] = p1
        return OK
    if fct == 8:
        if p1 not in (1, 2, 3) or p2 not in (1, 2, 3):
            return SYNTAX
        st["return"][chan] = (p1, p2)
        return OK
    if fct == 9:
        st["recording"][chan] = False
        return OK
    return SYNTAX


def f_axp(rt: SystemContext, axis, value, axtype=1):
    """AXP: NC text '<axis name><value>' for an axis given by number (L2352-2376)."""
    c = rt.ctl
    if axis.__class__ is not int:
        raise CplError("CPL032", "AXP needs an axis number")
    if axtype == 0:
        ax = c.axes.get(axis)
    else:
        logical = c.channel_axes(c.channel)
        ax = logical[axis - 1] if 1 <= axis <= len(logical) else None
    if ax is None:
        raise CplError("1938", f"axis {axis} is not configured")
    v = nul(value)
    text = f"{v:.4f}".rstrip("0").rstrip(".") if isinstance(v, float) else str(v)
    return f"{ax.name}{'=' if len(ax.name) > 1 else ''}{text}"
