"""The NC's data: machine and setting data, tool and zero offsets, MIB, PLC, inputs, alarms.

Loaded from the machine file's ``[sin800]`` section (docs/sin800.md), then
overlaid with what earlier runs stored (the NC keeps these in battery-backed
memory: here the SQLite store, namespace ``sin800``). Bytes are held as
digit-coded patterns (``00010010`` is the number 10010, CL 800 manual §2.1-2.2, L395-495; §4.2, L830-848; §5.2.1, L1164-1303).
"""

from __future__ import annotations

import math
from decimal import Decimal
from typing import Any

from ...diagnostics import UsageError
from ...machine.sections import R_LIMIT
from .errors import Cl800Error
from .options import Options, options

NAMESPACE = "sin800"
#: data areas kept by address (word or byte address -> number)
AREAS = ("nc_md", "cycle_md", "plc_md", "drive_md", "nc_sd", "cycle_sd")
PERSISTED = (*AREAS, "to", "zo", "rot", "mib", "central_r")
#: the MD (@30x/@40x) and SD (@31x/@41x) areas by the last digit of the code: (area, width, (lo, hi)
#: address range); width: word, byte, bit (L6500-6522, L6624-6646)
MD_SD = {
    "0": ("nc_md", "word", (0, 4999)), "1": ("nc_md", "byte", (5000, 6999)), "2": ("nc_md", "bit", (5000, 6999)),
    "3": ("cycle_md", "word", (0, 4149)), "4": ("cycle_md", "byte", (800, 8049)),
    "5": ("cycle_md", "bit", (800, 8049)),
    "6": ("plc_md", "word", (0, 5999)), "7": ("plc_md", "byte", (2000, 8999)), "8": ("plc_md", "bit", (2000, 8999)),
    "9": ("drive_md", "word", (0, 4960)), "a": ("drive_md", "byte", (2440, 4630)),
    "b": ("drive_md", "bit", (2440, 4630)),
}
SD = {
    "0": ("nc_sd", "word", (0, 4999)), "1": ("nc_sd", "byte", (5000, 9999)), "2": ("nc_sd", "bit", (5000, 9999)),
    "3": ("cycle_sd", "word", (0, 499)), "4": ("cycle_sd", "byte", (800, 949)), "5": ("cycle_sd", "bit", (800, 949)),
}
CHANNEL_ARG = {"cycle_md", "cycle_sd"}


#: the smallest magnitude of an R value other than 0 (L7079): the NC holds 8 decimal places
R_SMALLEST = 0.00000001
#: the central R parameters, which the NC keeps across power-off (the state directory's ``central_r``)
CENTRAL_R = range(900, 1000)


def r_value(value: float) -> float:
    """A function result as an R value: beyond +/-99999999 (L7079), or inf/NaN, it is the "CL 800 error";
    below the smallest magnitude +/-0.00000001 it is what the NC holds, rounded to 8 decimal places
    (0 or +/-0.00000001)."""
    if -R_LIMIT <= value <= R_LIMIT:
        if -R_SMALLEST < value < R_SMALLEST:
            return round(value, 8) + 0.0  # (no -0.0)
        return value
    raise Cl800Error(f"{fixed(value)} is outside the R parameter range +/-99999999")


def held(value: float) -> float:
    """A value read or measured into an R parameter as the NC holds it: below the smallest magnitude
    +/-0.00000001 (L7079) rounded to 8 decimal places (an actual position of 3e-15 reads 0)."""
    if -R_SMALLEST < value < R_SMALLEST:
        return round(value, 8) + 0.0
    return float(value)


def fixed(value: float) -> str:
    """A number as the control shows it: fixed notation, no exponent, no trailing zeros (99999999.4)."""
    if not math.isfinite(value):
        return str(value)
    text = format(Decimal(repr(value)), "f")
    return text[:-2] if text.endswith(".0") else text


def nc8(value: float) -> float:
    """Strict NC numerics (ncvm's reading; the CL 800 manual is silent): 8 significant decimal digits in the range +/-0.00000001 to
    +/-99999999 (L7079); a larger value is the "CL 800 error"."""
    return r_value(round(float(f"{value:.8g}"), 8)) + 0.0  # no -0.0


def whole(v: float) -> int:
    """An operand that must be a whole number (the CL 800 error otherwise)."""
    n = int(v)
    if n != v:
        raise Cl800Error(f"{v:g} is not a whole number")
    return n


def in_range(what: str, v: float, lo: int, hi: int) -> int:
    """A whole-number operand within ``lo``..``hi`` (the CL 800 error otherwise)."""
    n = whole(v)
    if not lo <= n <= hi:
        raise Cl800Error(f"{what} {n} outside {lo}-{hi}")
    return n


def pattern_to_int(value: float) -> int:
    """A digit-coded pattern (e.g. 10010.0) as its 8-bit integer."""
    if value < 0 or value != int(value):
        raise Cl800Error(f"{value:g} is not a bit pattern")
    text = str(int(value))
    if len(text) > 8 or any(c not in "01" for c in text):
        raise Cl800Error(f"{text} is not a bit pattern (at most 8 digits 0/1)")
    return int(text, 2)


def int_to_pattern(bits: int) -> float:
    return float(int(bin(bits & 0xFF)[2:]))


def _pattern_value(where: str, key: str, v: Any) -> float:
    if isinstance(v, str):
        text = v.strip()
        if text.upper().startswith("B"):
            text = text[1:]
        if not text or any(c not in "01" for c in text) or len(text) > 8:
            raise UsageError(f"{where}: key '{key}' must be a bit pattern like \"00010010\"")
        return float(int(text))
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        return float(v)
    raise UsageError(f"{where}: key '{key}' must be a number or a bit pattern string")


#: per control: the highest MIB address (the range @211/@212 check)
MIB_TOP = {"810": 249, "820": 249, "850": 499, "880": 499}


class NcData:
    """Everything a program reaches through main groups 2, 3 and 4 besides the R parameters."""

    def __init__(self, n_axes: int):
        self.n_axes = n_axes
        self.control = "880"
        self.channel = 1
        self.areas: dict[str, dict[str, float]] = {a: {} for a in AREAS}
        self.to: dict[str, list[float]] = {}  # "area:d" -> P0..P15
        self.to_area = 0
        # zero offsets: settable G54..G57 coarse/fine, programmable G58/G59, external, DRF, PRESET
        self.zo: dict[str, list[float]] = {}
        self.rot: dict[str, float] = {}  # "settable:g" / "programmable:g" -> angle
        self.preset_loaded: list[float] | None = None  # ZOPS written by the program, effective at its end
        self.mib = [0.0] * 500
        self.inputs = [0, 0, 0]  # external input bytes 1 and 2 (index 0 unused)
        self.plc: dict[int, dict[str, dict]] = {}
        self.alarms: list[tuple[int, int]] = []  # (number, channel)
        self.sob: dict[str, float] = {}
        self.central_r: dict[str, float] = {}
        self.gear = 1  # gear stage of the master spindle at power-on (AGS)
        self.gears: list[float] = []  # maximum speed of each gear stage (M40, limit under G96)
        self.v24_input = ""  # what INP reads from the V24 port (module v24's tape format)
        self.dirty: set[str] = set()  # the keys of PERSISTED changed and not yet in the store
        #: the permanent store the run writes the NC data through to (:meth:`changed`); None: kept in memory
        self.store = None

    # -- loading ---------------------------------------------------------
    @classmethod
    def from_machine(cls, machine) -> "NcData":
        data = cls(len(machine.axes))
        sec = options(machine)
        where = f"{machine.source}: [sin800]"
        data.control = sec.control
        data.channel = sec.channel
        data.to_area = sec.to_area
        for area in AREAS:
            for addr, v in sec.area(area).items():
                data.areas[area][str(addr)] = _pattern_value(where, f"sin800.{area}.{addr}", v)
        for i, t in enumerate(sec.tool_offsets):
            if "d" not in t or "p" not in t:
                raise UsageError(f"{where}: key 'sin800.tool_offsets[{i}]' needs 'd' and 'p' (P0..P15)")
            p = [float(x) for x in t["p"]] + [0.0] * 16
            data.to[f"{int(t.get('area', 0))}:{int(t['d'])}"] = p[:16]
        for name, v in sec.zero_offsets.items():
            if isinstance(v, dict):
                for part in ("coarse", "fine"):
                    if part in v:
                        data.zo[f"{name.upper()}.{part}"] = data._vector(where, f"zero_offsets.{name}.{part}",
                                                                         v[part])
            else:
                data.zo[name.upper()] = data._vector(where, f"zero_offsets.{name}", v)
        for kind, angles in sec.rotation.items():
            for g, a in enumerate(angles, 1):
                data.rot[f"{kind}:{g}"] = float(a)
        for addr, v in sec.mib.items():
            data.mib[int(addr)] = float(v)
        for byte, v in sec.inputs.items():
            data.inputs[int(byte)] = pattern_to_int(_pattern_value(where, f"sin800.inputs.{byte}", v))
        for plc_no, areas in sec.plc.items():
            data.plc[int(plc_no)] = {k.upper(): dict(v) for k, v in areas.items()}
        for a in sec.alarms:
            data.alarms.append((int(a), data.channel))
        data.sob = {str(k): float(v) for k, v in sec.sob.items()}
        data._check_ranges(where, sec)
        data._load_gears(where, sec)
        data.v24_input = sec.v24_input
        for name, v in sec.r.items():
            n = int(str(name).upper().lstrip("R"))
            if n >= 900:
                data.central_r[str(n)] = float(v)
        return data

    def _load_gears(self, where: str, sec: Options) -> None:
        self.gears = [float(g) for g in sec.gears]
        gear = sec.gear
        top = len(self.gears) or 5
        if not 1 <= gear <= top:
            raise UsageError(f"{where}: key 'sin800.gear' must be a gear stage 1-{top}")
        self.gear = gear

    def _vector(self, where: str, key: str, v) -> list[float]:
        if not isinstance(v, list) or len(v) != self.n_axes:
            raise UsageError(f"{where}: key 'sin800.{key}' must be a list of {self.n_axes} numbers")
        return [float(x) for x in v]

    def overlay(self, stored: dict[str, Any], state_dir: str) -> None:
        """What earlier runs left in the store wins over the machine file; a zero offset kept for a machine
        of another number of axes (an imported store) is refused rather than applied to the wrong axes."""
        for name, values in stored.get("zo", {}).items():
            if len(values) != self.n_axes:
                raise UsageError(f"the permanent store of {state_dir} holds zero offset {name} with {len(values)} "
                                 f"values, this machine has {self.n_axes} axes: it was kept for another machine "
                                 f"(ncvm state reset, or import a file exported on this machine)")
        self._machine_zo = {k: list(v) for k, v in self.zo.items()}
        self._machine_rot = dict(self.rot)
        for area in AREAS:
            self.areas[area].update(stored.get(area, {}))
        self.to.update(stored.get("to", {}))
        self.zo.update(stored.get("zo", {}))
        self.rot.update(stored.get("rot", {}))
        self.central_r.update(stored.get("central_r", {}))
        if "mib" in stored:
            self.mib = [float(x) for x in stored["mib"]]

    def carried_offsets(self, stored: dict[str, Any], axes: list[str]) -> list[str]:
        """The zero offsets and rotation angles earlier runs left in the store that differ from the machine
        file: the NC keeps them (docs/sin800.md "The NC state"), and they move this program's toolpath."""
        out = []
        for name, values in sorted(stored.get("zo", {}).items()):
            if name == "PRESET" or name not in self.zo:
                continue
            start = self._machine_zo.get(name, [0.0] * self.n_axes)
            words = " ".join(f"{a}{v:g}" for a, v, w in zip(axes, values, start) if v != w)
            if words:
                out.append(f"{name.replace('.', ' ')} {words}")
        for key, angle in sorted(stored.get("rot", {}).items()):
            if angle != self._machine_rot.get(key, 0.0):
                kind, group = key.split(":")
                out.append(f"{kind} rotation {group} {angle:g} deg")
        return out

    def changed(self, *keys: str) -> None:
        """The statement running changed NC data ``keys`` (and whatever else is marked ``dirty``): the NC keeps
        them, so they are in the store before the statement returns, in one transaction (docs/decisions.md,
        "SINUMERIK: NC data and central R written through")."""
        self.dirty.update(keys)
        if self.store is not None and self.dirty:
            with self.store.batch():
                for key, value in self.persisted().items():
                    self.store.put(NAMESPACE, key, value)
            self.dirty.clear()

    def persisted(self) -> dict[str, Any]:
        out: dict[str, Any] = {}
        for key in self.dirty:
            if key in self.areas:
                out[key] = self.areas[key]
            elif key in ("to", "zo", "rot", "mib"):  # central_r: written by central.CentralR as stores happen
                out[key] = getattr(self, key)
        return out

    def _check_ranges(self, where: str, sec: Options) -> None:
        """What the control has no room for, or cannot read as a byte, is refused at the start: a program
        would meet it only as a CL 800 error at the line that reads it (or not at all)."""
        c = self.control
        beyond = [a for a in sec.mib if int(a) > MIB_TOP[c]]
        if beyond:
            raise UsageError(f"{where}: key 'sin800.mib.{beyond[0]}': the {c} has MIB 0-{MIB_TOP[c]}")
        ranges = [*MD_SD.values(), *SD.values()]
        for area, width, (lo, hi) in ranges:
            words = [r for a, w, r in ranges if a == area and w == "word"]
            for addr, v in self.areas[area].items() if width == "byte" else ():
                n = int(addr) if addr.isdigit() else -1
                if lo <= n <= hi and not any(wlo <= n <= whi for wlo, whi in words):
                    try:
                        pattern_to_int(v)
                    except Cl800Error as e:
                        raise UsageError(f"{where}: key 'sin800.{area}.{addr}' = {v:g}: address {addr} holds a "
                                         f"byte ({e})") from None

    def inch_basic_system(self) -> bool:
        """NC MD bit 5002.4: inch is the basic setting of the NC (L2324-2326)."""
        return bool(pattern_to_int(self.areas["nc_md"].get("5002", 0.0)) >> 4 & 1)

    # -- zero offsets ----------------------------------------------------
    def zo_vec(self, name: str) -> list[float]:
        return self.zo.setdefault(name, [0.0] * self.n_axes)

    def preset(self) -> list[float]:
        """The PRESET offsets as ZOPS reads them: what the program loaded, else the effective ones."""
        return self.preset_loaded if self.preset_loaded is not None else self.zo_vec("PRESET")

    def load_preset(self, axis: int, value: float) -> None:
        """ZOPS(axis) = value: the PRESET offset becomes effective after program end or reset (L3240)."""
        if self.preset_loaded is None:
            self.preset_loaded = list(self.zo_vec("PRESET"))
        self.preset_loaded[axis] = value

    def preset_takes_effect(self) -> None:
        """Program end (M2/M30, the last block) or reset: the loaded PRESET offsets are effective."""
        if self.preset_loaded is not None:
            self.zo["PRESET"] = self.preset_loaded
            self.preset_loaded = None
            self.changed("zo")

    def additive(self) -> list[float]:
        """Programmable (G58 + G59), external, DRF and PRESET offsets, summed per axis."""
        out = [0.0] * self.n_axes
        for name in ("G58", "G59", "EXTERNAL", "DRF", "PRESET"):
            if name in self.zo:
                out = [a + b for a, b in zip(out, self.zo[name])]
        return out
