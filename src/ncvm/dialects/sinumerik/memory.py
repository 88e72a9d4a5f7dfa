"""The channel's system memory (planning guide ch.10; CL 800 manual §10.5, L6484-6604; §10.6, L6605-6705): machine and setting data, tool
offsets, the drives' status and control bits, status bits and alarms, as @ codes of main groups 3 and 4
read and write them.

Each area's row (``ncdata.MD_SD`` / ``ncdata.SD``) names the data area, the access width and the address
range of manual ch.10; a value outside a range, or another channel's data, is the NC alarm "CL 800 error".
"""

from __future__ import annotations

from collections.abc import Callable

from ...diagnostics import RuntimeFault
from .errors import Cl800Error
from .ncdata import CHANNEL_ARG, MD_SD, SD, NcData, int_to_pattern, pattern_to_int
from .ncdata import in_range as _rng
from .ncdata import whole as _i

#: programmed control words of digital drives, read (@34b/@34c) and written (@44b/@44c): name, unit, top byte
DRIVE_CONTROL = {"34b": ("PCDA", "axis", 1), "44b": ("PCDA", "axis", 1), "34c": ("PCDS", "spindle", 5),
                 "44c": ("PCDS", "spindle", 5)}  # first argument is the channel (0 = own)


class SystemMemory:
    """The NC data of one channel as its @ code reads and writes see them."""

    def __init__(self, data: NcData, say: Callable[[str], None], cycle_alarm_stop: bool):
        self.data = data
        self.say = say  # a message in the run's output
        self.cycle_alarm_stop = cycle_alarm_stop  # ALNZ 4000-4299 stop the program ([sin800])

    def md_read(self, code: str, args: tuple):
        """MDN ... MDDBI (@300-@30b): machine data; the last digit of the code names the area."""
        return self._mem_read(*MD_SD[code[2]], args)

    def sd_read(self, code: str, args: tuple):
        """SEN ... SEZBI (@310-@315): setting data."""
        return self._mem_read(*SD[code[2]], args)

    def to_read(self, code: str, args: tuple) -> float:
        """TOS (@320): a tool offset parameter."""
        return self.to_entry(args)[_rng("TO parameter P", args[2], 0, 15)]

    def sob(self, code: str, args: tuple) -> float:
        """SOB (@371): a status bit of the machine file's ``sob`` table."""
        self.own_channel(args[0], independent=99)
        d = self.data
        return d.sob.get(f"{_i(args[0])}:{_i(args[1])}", d.sob.get(str(_i(args[1])), 0.0))

    def ppch(self, code: str, args: tuple) -> float:
        """PPCH (@372): the channel number."""
        return float(self.data.channel)

    def alnp(self, code: str, args: tuple):
        """ALNP (@3c0): the pending alarms, number + channel/100 each."""
        return [n + ch / 100.0 for n, ch in self.data.alarms] or 0.0

    def alnpz(self, code: str, args: tuple) -> float:
        """ALNPZ (@3d0): the number of pending alarms."""
        return float(len(self.data.alarms))

    def alnz(self, code: str, where: tuple, value: float) -> None:
        """ALNZ (@4c0): raise a cycle alarm; 4000-4299 stop the program unless ``cycle_alarm_stop`` is off."""
        n = _i(value)
        top5 = 5299 if self.data.control == "880" else 5099
        if not (4000 <= n <= 4299 or 5000 <= n <= top5):
            raise Cl800Error(f"cycle alarm {n} outside 4000-4299, 5000-{top5}")
        self.data.alarms.append((n, self.data.channel))
        self.say(f"cycle alarm {n}")
        if n <= 4299 and self.cycle_alarm_stop:
            raise RuntimeFault(str(n), f"cycle alarm {n} (ALNZ)")

    def _data_area(self, area: str, width: str, rng: tuple) -> tuple:
        """The address range of an MD/SD area on this control; the CL 800 error where the control has no
        such data (ch.6 table L4817-4845: cycle MD/SD on the 850/880 only, drive MD on the 810/820 only;
        PLC MD words 0-1999 and bytes 2000-3999 on the 810/820, 0-5999 and 6000-8999 on the 850/880,
        L6506-6508)."""
        control = self.data.control
        small = control in ("810", "820")
        if area in ("cycle_md", "cycle_sd") and small:
            raise Cl800Error(f"cycle {'machine' if area == 'cycle_md' else 'setting'} data exist on the "
                             f"SINUMERIK 850/880 only, not on the {control}")
        if area == "drive_md" and not small:
            raise Cl800Error(f"drive machine data exist on the SINUMERIK 810/820 only, not on the {control}")
        if area == "plc_md":
            return ((0, 1999) if small else (0, 5999)) if width == "word" else ((2000, 3999) if small else (6000, 8999))
        return rng

    def _mem_read(self, area: str, width: str, rng: tuple, args: tuple):
        rng = self._data_area(area, width, rng)
        args = self.channel_args(area, args)
        table = self.data.areas[area]
        addr = _rng(f"{area} address", args[0], *rng)
        if width == "word":
            return table.get(str(addr), 0.0)
        if area == "drive_md":  # MDDBY(w, hl): low (0) / high (1) byte of a word
            word = int(table.get(str(addr), 0.0))
            hl = _rng("byte (0 low / 1 high)", args[1], 0, 1)
            byte = (word >> (8 * hl)) & 0xFF
            if width == "byte":
                return int_to_pattern(byte)
            return float((byte >> _rng("bit", args[2], 0, 7)) & 1)
        pattern = table.get(str(addr), 0.0)
        if width == "byte":
            return pattern
        return float((pattern_to_int(pattern) >> _rng("bit", args[1], 0, 7)) & 1)

    def channel_args(self, area: str, args: tuple) -> tuple:
        if area in CHANNEL_ARG:
            self.own_channel(args[0])
            return args[1:]
        return args

    def own_channel(self, v: float, independent: int | None = None) -> None:
        """A channel operand (0 = own channel, 0-16): the simulated NC CPU runs only this channel, so any
        other channel's system memory is on another CPU, the "CL 800 error" (L2351, L2553, L2693).
        ``independent``: the number that means channel-independent data (SOB: 99)."""
        ch = _i(v)
        if ch == independent:
            return
        _rng("channel", ch, 0, 16)
        if ch not in (0, self.data.channel):
            raise Cl800Error(f"channel {ch} is not on this NC CPU")

    def to_entry(self, args: tuple) -> list[float]:
        top_area = {"810": 0, "820": 0, "850": 8, "880": 16}[self.data.control]
        area = _rng("TO area", args[0], 0, top_area)
        if area == 0:
            area = self.data.to_area
        d = _rng("D number", args[1], 1, {"810": 99, "820": 99, "850": 409, "880": 818}[self.data.control])
        key = f"{area}:{d}"
        if key not in self.data.to:
            self.data.to[key] = [0.0] * 16
        return self.data.to[key]

    def drive_read(self, code: str, args: tuple) -> float:
        """RSDA/RSDS/RSDD: status bits of the digital drives, from the machine file (``sob`` keys
        ``3e1:axis:byte:bit`` ...); PCDA/PCDS: the programmed control bits, as PCDA/PCDS wrote them."""
        if code in DRIVE_CONTROL:
            return self.data.sob.get(self._control_bit(code, args), 0.0)
        key = f"{code}:{':'.join(str(_i(a)) for a in args)}"
        return self.data.sob.get(key, 0.0)

    def _control_bit(self, code: str, args: tuple, writing: bool = False) -> str:
        """The key of one bit of a programmed control word of a digital drive: PCDA (axis 1-24, byte 0/1,
        bit 0-7, written 4-6) or PCDS (spindle 1-10, byte 0-5, bit 0-7) (L2571-2587, L6543-6544, L6674)."""
        name, units, top_byte = DRIVE_CONTROL[code]
        unit = _rng(f"{name} {units} number", args[0], 1, 24 if units == "axis" else 10)
        byte = _rng(f"{name} byte", args[1], 0, top_byte)
        bit = _rng(f"{name} bit", args[2], *((4, 6) if writing and name == "PCDA" else (0, 7)))
        return f"{name}:{unit}:{byte}:{bit}"

    def md_write(self, code: str, where: tuple, value: float) -> None:
        """MDN ... MDDBI (@400-@40b): machine data; the last digit of the code names the area."""
        self._mem_write(*MD_SD[code[2]], where, value)

    def sd_write(self, code: str, where: tuple, value: float) -> None:
        """SEN ... SEZBI (@410-@415): setting data."""
        self._mem_write(*SD[code[2]], where, value)

    def _mem_write(self, area: str, width: str, rng: tuple, where: tuple, value: float) -> None:
        d = self.data
        rng = self._data_area(area, width, rng)
        where = self.channel_args(area, where)
        addr = _rng(f"{area} address", where[0], *rng)
        table = d.areas[area]
        if width == "word":
            table[str(addr)] = float(value)
        elif area == "drive_md":  # MDDBY/MDDBI(w, hl[, bit]): a byte of a drive MD word
            word = int(table.get(str(addr), 0.0))
            shift = 8 * _rng("byte (0 low / 1 high)", where[1], 0, 1)
            byte = (word >> shift) & 0xFF
            if width == "byte":
                byte = pattern_to_int(value)
            else:
                if value not in (0.0, 1.0):
                    raise Cl800Error(f"bit value {value:g} is not 0 or 1")
                bit = _rng("bit", where[2], 0, 7)
                byte = byte | (1 << bit) if value else byte & ~(1 << bit)
            table[str(addr)] = float((word & ~(0xFF << shift)) | (byte << shift))
        elif width == "byte":
            pattern_to_int(value)
            table[str(addr)] = float(value)
        else:
            bit = _rng("bit", where[1], 0, 7)
            if value not in (0.0, 1.0):
                raise Cl800Error(f"bit value {value:g} is not 0 or 1")
            bits = pattern_to_int(table.get(str(addr), 0.0))
            bits = bits | (1 << bit) if value else bits & ~(1 << bit)
            table[str(addr)] = int_to_pattern(bits)
        d.changed(area)

    def drive_write(self, code: str, where: tuple, value: float) -> None:
        """PCDA / PCDS (@44b/@44c): a programmed control bit of a digital drive."""
        if value not in (0.0, 1.0):
            raise Cl800Error(f"bit value {value:g} is not 0 or 1")
        self.data.sob[self._control_bit(code, where, writing=True)] = float(value)

    def satc(self, code: str, where: tuple, value: float) -> None:
        """SATC (L3562-3579, L6704): kept per spindle and gear stage."""
        spindle, gear = _rng("spindle", where[0], 0, 6), _rng("gear stage", where[1], 1, 8)
        self.data.sob[f"SATC:{spindle}:{gear}"] = float(_rng("acceleration time constant", value, 0, 16000))
