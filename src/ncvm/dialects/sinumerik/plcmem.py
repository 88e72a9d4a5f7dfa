"""The channel's PLC (SINUMERIK 850/880): its I/Q/P/F bytes, data words, timers and counters as the NC
program reads (@38x-@3bx) and writes (@48x-@4bx) them (manual L2729-2924, L3366-3561).

The bytes and data blocks are the NC data's ``plc`` tables (the machine file's ``[sin800.plc.<n>]``);
the timers and counters run in simulated time (:mod:`.plc`). Before the NC looks at a PLC, the scripted
events up to now happen (``advance``).
"""

from __future__ import annotations

import math
import struct
from collections.abc import Callable

from .errors import Cl800Error
from .ncdata import R_LIMIT, NcData, int_to_pattern, pattern_to_int
from .ncdata import in_range as _rng
from .ncdata import whole as _i
from .plc import PlcClock

PLC_BIT_AREA = {"380": "I", "381": "Q", "382": "F", "482": "F"}
PLC_BYTE_AREA = {"390": "I", "391": "Q", "392": "P", "393": "F", "493": "F"}
PLC_WORD_AREA = {"3a0": "I", "3a1": "Q", "3a2": "P", "3a3": "F", "4a3": "F"}


class Plc:
    """The PLCs of the control as one channel sees them."""

    def __init__(self, data: NcData, timers: PlcClock, clock, advance: Callable[[], None],
                 say: Callable[[str], None]):
        self.data = data
        self.say = say  # the operator's message line (the NC alarm of an overflowing read)
        self.timers = timers
        self.clock = clock  # the machine's simulated clock (``now``)
        self.advance = advance  # the scenario up to now
        timers.write_bit = self.bit

    def number(self, v: float) -> int:
        """The PLC number; scripted PLC events up to now have happened when the NC looks at a PLC."""
        if self.data.control not in ("850", "880"):
            raise Cl800Error("PLC access needs a SINUMERIK 850 or 880")
        n = _rng("PLC number", v, 1, 4 if self.data.control == "880" else 2)
        self.advance()
        return n

    def _plc(self, v: float) -> dict:
        return self.data.plc.setdefault(self.number(v), {})

    def _put_byte(self, plc_no: int, area: str, byte: int, bits: int, when: float | None = None) -> None:
        """Store a PLC I/Q/P/F byte; rising edges of bits wired to timers and counters drive them."""
        plc = self.data.plc.setdefault(plc_no, {})
        old = self._byte(plc, area, byte, True)
        plc.setdefault(area, {})[str(byte)] = int_to_pattern(bits)
        now = self.clock.now if when is None else when
        self.timers.byte_changed(plc_no, area, byte, old, bits & 0xFF, now)

    def _byte(self, plc: dict, area: str, byte: int, writing: bool = False) -> int:
        table = plc.setdefault(area, {})
        if str(byte) not in table:
            if area == "P" and not writing:
                raise Cl800Error(f"peripheral byte {byte} does not exist: the PLC goes to STOP")
            return 0
        v = table[str(byte)]
        return pattern_to_int(float(v)) if isinstance(v, (int, float)) else int(str(v), 2)

    def bit(self, plc_no: int, area: str, byte: int, bit: int, value: int, when: float | None = None) -> None:
        """Set or clear one PLC bit (at time ``when``, default now)."""
        bits = self._byte(self.data.plc.setdefault(plc_no, {}), area, byte, True)
        self._put_byte(plc_no, area, byte, bits | (1 << bit) if value else bits & ~(1 << bit), when)

    def _dw(self, plc: dict, db: float, dw: float) -> int:
        b = _i(db)
        if not (1 <= b <= 255 or 1000 <= b <= 1255):
            raise Cl800Error(f"data block {b} outside DB 1-255 / DX 1000-1255")
        words = plc.setdefault("DB", {}).get(str(b))
        n = _rng("data word", dw, 0, 2043)
        if words is None or n >= len(words):
            raise Cl800Error(f"DB{b} DW{n} does not exist in the PLC")
        return int(words[n]) & 0xFFFF

    def data_word(self, v: float, db: float, dw: float) -> int:
        """Data word DW<dw> of data block DB<db> of PLC <v> (an M function's answer, ``m_functions``)."""
        return self._dw(self._plc(v), db, dw)

    def read(self, code: str, args: tuple):
        plc = self._plc(args[0])
        if code in PLC_BIT_AREA:
            top = 255 if PLC_BIT_AREA[code] == "F" else 127
            return float((self._byte(plc, PLC_BIT_AREA[code], _rng("byte", args[1], 0, top))
                          >> _rng("bit", args[2], 0, 7)) & 1)
        if code == "383":
            return float((self._dw(plc, args[1], args[2]) >> _rng("bit", args[3], 0, 15)) & 1)
        if code in PLC_BYTE_AREA:
            top = 255 if PLC_BYTE_AREA[code] == "F" else 127
            return int_to_pattern(self._byte(plc, PLC_BYTE_AREA[code], _rng("byte", args[1], 0, top)))
        if code in ("394", "395"):
            w = self._dw(plc, args[1], args[2])
            return int_to_pattern(w >> 8 if code == "394" else w & 0xFF)
        if code in PLC_WORD_AREA:
            area = PLC_WORD_AREA[code]
            n = _rng("word", args[1], 0, 254 if area == "F" else 126)
            word = (self._byte(plc, area, n) << 8) | self._byte(plc, area, n + 1)
            return _from_dim(word, 16, _i(args[2]))
        if code in ("3a4", "3a5"):
            no, number = _i(args[0]), _rng("timer/counter number", args[1], 0, 255)
            if code == "3a4":  # seconds, 2 digits after the decimal point (L2852)
                return self.timers.timer_seconds(no, number, self.clock.now)
            return self.timers.counter_value(no, number)
        if code in ("3b0", "3b1", "3b2"):
            # no. of DW: PLCDF 1/2 (L2870-2894), PLCDB 1-3 (L2896-2924), as for the writes @4b0/@4b1
            n = 2 if code == "3b2" else _rng("number of data words", args[3], 1, 3 if code == "3b1" else 2)
            words = [self._dw(plc, args[1], args[2] + k) for k in range(n)]
            if code == "3b2":
                return self._into_r(code, struct.unpack(">f", struct.pack(">HH", *words))[0])
            if code == "3b1":
                digits = "".join(f"{w:04x}" for w in words)
                if any(c not in "0123456789" for c in digits):
                    raise Cl800Error(f"DB data {digits} is not BCD")
                return self._into_r(code, _scale(int(digits), _i(args[4]) % 100))
            raw = 0
            for w in words:
                raw = (raw << 16) | w
            return self._into_r(code, _from_dim(raw, 16 * n, _i(args[4]) % 10))
        raise Cl800Error(f"@{code} is not available")

    def _into_r(self, code: str, value: float) -> float:
        """A PLC value read into an R parameter: beyond +/-99999999 (L7079) "the maximum value [is] entered
        into the R parameter and an NC alarm issued, which does not interrupt the program" (L727)."""
        if -R_LIMIT <= value <= R_LIMIT:
            return value
        if value != value:  # a PLC float that is no number (NaN): no maximum to enter
            raise Cl800Error(f"@{code}: the PLC value is not a number")
        clamped = math.copysign(R_LIMIT, value)
        self.say(f"NC alarm: @{code} read {value:g} from the PLC, beyond the R parameter range: {clamped:g} "
                 "entered (the program goes on, L727)")
        return clamped

    def write(self, code: str, where: tuple, value: float) -> None:
        no = self.number(where[0])
        plc = self.data.plc.setdefault(no, {})
        if code == "482":
            byte = _rng("byte", where[1], 0, 255)
            if value not in (0.0, 1.0):
                raise Cl800Error(f"bit value {value:g} is not 0 or 1")
            self.bit(no, "F", byte, _rng("bit", where[2], 0, 7), int(value))
        elif code == "483":
            w = self._dw(plc, where[1], where[2])
            k = _rng("bit", where[3], 0, 15)
            if value not in (0.0, 1.0):
                raise Cl800Error(f"bit value {value:g} is not 0 or 1")
            self._set_dw(plc, where[1], where[2], w | (1 << k) if value else w & ~(1 << k))
        elif code == "493":
            self._put_byte(no, "F", _rng("byte", where[1], 0, 255), pattern_to_int(value))
        elif code in ("494", "495"):
            w = self._dw(plc, where[1], where[2])
            b = pattern_to_int(value)
            w = (b << 8) | (w & 0xFF) if code == "494" else (w & 0xFF00) | b
            self._set_dw(plc, where[1], where[2], w)
        elif code == "4a3":
            n = _rng("word", where[1], 0, 254)
            raw = _to_dim(value, 16, _i(where[2]))
            self._put_byte(no, "F", n, raw >> 8)
            self._put_byte(no, "F", n + 1, raw & 0xFF)
        elif code in ("4b0", "4b1", "4b2"):
            if code == "4b2":
                words = list(struct.unpack(">HH", struct.pack(">f", value)))
            elif code == "4b1":
                n = _rng("number of data words", where[3], 1, 3)
                v = round(abs(value) * 10 ** max(0, _i(where[4]) % 100 - 1))
                digits = f"{v:0{4 * n}d}"
                if len(digits) > 4 * n:
                    raise Cl800Error(f"{value:g} does not fit {n} BCD data words")
                words = [int(digits[4 * k:4 * k + 4], 16) for k in range(n)]
            else:
                n = _rng("number of data words", where[3], 1, 2)
                raw = _to_dim(value, 16 * n, _i(where[4]) % 10)
                words = [(raw >> (16 * (n - 1 - k))) & 0xFFFF for k in range(n)]
            for k, w in enumerate(words):
                self._dw(plc, where[1], where[2] + k)
                self._set_dw(plc, where[1], where[2] + k, w)
        else:
            raise Cl800Error(f"@{code} is not available")

    def _set_dw(self, plc: dict, db: float, dw: float, value: int) -> None:
        plc["DB"][str(_i(db))][_i(dw)] = value & 0xFFFF

    def set_event(self, ev) -> None:
        """A scripted change of a PLC I/Q/P/F bit or byte (``[[scenario]]`` kind "plc", a PlcChange)."""
        if ev.bit is not None:
            self.bit(ev.plc, ev.area, ev.byte, ev.bit, 1 if ev.value is None or ev.value else 0, ev.time)
            return
        value = 0 if ev.value is None else ev.value
        self._put_byte(ev.plc, ev.area, ev.byte,
                       int(value, 2) if isinstance(value, str) else pattern_to_int(float(value)), ev.time)


def _scale(raw: int, dim: int) -> float:
    return float(raw) if dim <= 1 else raw / 10 ** (dim - 1)


def _from_dim(raw: int, bits: int, dim: int) -> float:
    if dim >= 100:
        digits = f"{raw:0{bits // 4}x}"
        if any(c not in "0123456789" for c in digits):
            raise Cl800Error(f"{digits} is not BCD")
        return _scale(int(digits), dim - 100)
    if raw >= 1 << (bits - 1):
        raw -= 1 << bits
    return _scale(raw, dim % 10)


def _to_dim(value: float, bits: int, dim: int) -> int:
    if dim >= 100:
        v = round(abs(value) * 10 ** max(0, dim - 101))
        return int(f"{v:0{bits // 4}d}", 16)
    raw = round(value * 10 ** max(0, dim % 10 - 1))
    if not -(1 << (bits - 1)) <= raw < (1 << (bits - 1)):
        raise Cl800Error(f"{value:g} overflows a {bits}-bit PLC value")
    return raw & ((1 << bits) - 1)
