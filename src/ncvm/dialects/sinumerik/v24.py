"""V24 data output and input of the SINUMERIK 800 (manual §5.3.9.2, L4466-4560).

OUTP ZOA, OUTP DATA and OUTP PARA write lines in one punched-tape text format, and INP reads the same
format back, so what one NC outputs another reads in. One line per item; its start names the data:

====================  =====================================  ====================
type (OUTP DATA/INP)  line                                   source
====================  =====================================  ====================
1 / 2                 the program text (``%MPF<n>``/``%SPF<n>``)  program path
5  NC machine data    ``MD<address>=<value>``                [sin800] nc_md
6  tool offsets       ``D<n> P0=<v> P1=<v> ...``             TO area of the channel
7  zero offsets       ``G54 X<v> Y<v> ...`` / ``G54 ROT <a>``  settable ZO, rotation
8  setting data       ``SD<address>=<value>``                [sin800] nc_sd
9  PLC machine data   ``MDP<address>=<value>``               [sin800] plc_md
10 R parameters       ``R<n>=<value>``                       R0-R999
====================  =====================================  ====================

Bytes are written as their digit-coded pattern (``MD5002=10000``). Only addresses that hold data in
the simulated NC are output (docs/decisions.md).
"""

from __future__ import annotations

import re
from pathlib import Path

from ...machine.files import heads
from ...source import lines, read_text
from .errors import Cl800Error

OUTPUT_TYPES = {1: "main programs", 2: "subroutines", 5: "NC machine data", 6: "tool offsets",
                8: "setting data", 9: "PLC machine data"}
INPUT_TYPES = {0: "any data", 1: "main programs", 2: "subroutines", 3: "clear programs", 5: "NC machine data",
               6: "tool offsets", 7: "zero offsets", 8: "setting data", 9: "PLC machine data", 10: "R parameters"}
AREA_OF_TYPE = {5: ("nc_md", "MD"), 8: ("nc_sd", "SD"), 9: ("plc_md", "MDP")}

_LINE = re.compile(r"(?:(?P<area>MDP|MD|SD)(?P<addr>\d+)|R(?P<r>\d+))=(?P<value>[-+]?[\d.]+)$")
_TO = re.compile(r"D(\d+)((?:\s+P\d+=[-+]?[\d.]+)+)$")
_ZO = re.compile(r"G5([4-7])\s+(.*)$")
#: the files of a program folder that may hold a program (found by its %MPF/%SPF header)
PROGRAM_SUFFIXES = (".spf", ".mpf", ".txt", "")
_PROGRAM = re.compile(r"\s*%\s*(MPF|SPF)\s*(\d+)", re.I)


def fmt(v: float) -> str:
    return f"{v:.10g}"


def zo_lines(data, offset, axis_names: list[str], channel: int) -> list[str]:
    """OUTP ZOA: channel 0 = the settable zero offsets G54-G57 (coarse + fine); a channel number = the
    angles of that channel's settable coordinate rotation (L4490-4502)."""
    if channel == 0:
        out = []
        for g in (1, 2, 3, 4):
            name = f"G{53 + g}"
            if f"{name}.coarse" in data.zo or f"{name}.fine" in data.zo:
                vec = [c + f for c, f in zip(data.zo_vec(f"{name}.coarse"), data.zo_vec(f"{name}.fine"))]
            else:
                vec = list(offset(name))
            out.append(name + "".join(f" {a}{fmt(v)}" for a, v in zip(axis_names, vec)))
        return out
    return [f"G{53 + g} ROT {fmt(data.rot.get(f'settable:{g}', 0.0))}" for g in (1, 2, 3, 4)]


def data_lines(data, programs, kind: int, start: int, end: int) -> list[str]:
    """OUTP DATA (type, start, end): the items of one data type with addresses start..end (L4504-4524)."""
    if kind not in OUTPUT_TYPES:
        raise Cl800Error(f"OUTP DATA: data type {kind} is not one of {', '.join(map(str, OUTPUT_TYPES))}")
    if start > end:
        raise Cl800Error(f"OUTP DATA: start address {start} is after the end address {end}")
    if kind in AREA_OF_TYPE:
        area, prefix = AREA_OF_TYPE[kind]
        table = data.areas[area]
        addrs = sorted(int(a) for a in table if a.isdigit() and start <= int(a) <= end)
        return [f"{prefix}{a}={fmt(table[str(a)])}" for a in addrs]
    if kind == 6:
        out = []
        for d in range(start, end + 1):
            p = data.to.get(f"{data.to_area}:{d}")
            if p is None:
                continue
            last = max([i for i, v in enumerate(p) if v != 0.0], default=0)
            out.append(f"D{d} " + " ".join(f"P{i}={fmt(p[i])}" for i in range(last + 1)))
        return out
    out = []
    for path in programs("MPF" if kind == 1 else "SPF", start, end):
        out.extend(lines(read_text(path)))
    return out


def find_programs(folders: list[Path], kind: str, start: int, end: int) -> list[Path]:
    """Programs %<kind><n> with start <= n <= end along the program path, by number."""
    found: dict[int, Path] = {}
    for p, head in heads(folders, PROGRAM_SUFFIXES):
        m = _PROGRAM.match(head)
        if m and m.group(1).upper() == kind and start <= int(m.group(2)) <= end:
            found.setdefault(int(m.group(2)), p)
    return [found[n] for n in sorted(found)]


def read_in(channel, kind: int, text: str) -> None:
    """INP (type): load the V24 input into the NC; a line of another type than ``kind`` (0 = no check)
    is the CL 800 error (L4540-4560)."""
    if kind not in INPUT_TYPES:
        raise Cl800Error(f"INP: data type {kind} is not one of {', '.join(map(str, INPUT_TYPES))}")
    data = channel.data
    for raw in lines(text):
        line = raw.strip()
        if not line:
            continue
        found, apply = _parse(channel, line)
        if kind not in (0, found):
            raise Cl800Error(f"INP({kind}): the V24 input holds {INPUT_TYPES[found]} ({line}), "
                             f"not {INPUT_TYPES[kind]}")
        apply()
    data.changed("nc_md", "nc_sd", "plc_md", "to", "zo")


def _parse(channel, line: str):
    """(data type, function that stores the line) for one input line."""
    data = channel.data
    m = _LINE.match(line)
    if m and m.group("r") is not None:
        n = int(m.group("r"))
        if n > 999:
            raise Cl800Error(f"INP: R{n} does not exist")
        return 10, lambda: channel.load_r(n, float(m.group("value")))
    if m:
        area, kind = {"MD": ("nc_md", 5), "SD": ("nc_sd", 8), "MDP": ("plc_md", 9)}[m.group("area")]
        return kind, lambda: data.areas[area].__setitem__(str(int(m.group("addr"))), float(m.group("value")))
    m = _TO.match(line)
    if m:
        def put_to():
            p = data.to.setdefault(f"{data.to_area}:{int(m.group(1))}", [0.0] * 16)
            for word in m.group(2).split():
                i, v = word[1:].split("=")
                if int(i) > 15:
                    raise Cl800Error(f"INP: tool offset P{i} does not exist (P0-P15)")
                p[int(i)] = float(v)
        return 6, put_to
    m = _ZO.match(line)
    if m:
        return 7, lambda: _put_zo(channel, int(m.group(1)), m.group(2))
    if _PROGRAM.match(line):
        raise Cl800Error("INP: reading programs in over V24 is not simulated")
    raise Cl800Error(f"INP: V24 input line '{line}' is not in tape format")


def _put_zo(channel, g: int, rest: str) -> None:
    data = channel.data
    words = rest.split()
    if words[:1] == ["ROT"] and len(words) == 2:
        data.rot[f"settable:{g - 3}"] = float(words[1])
        data.dirty.add("rot")
        return
    name = f"G5{g}"
    coarse, fine = data.zo_vec(f"{name}.coarse"), data.zo_vec(f"{name}.fine")
    names = sorted(channel.kernel.axis_of, key=len, reverse=True)
    for word in words:
        axis = next((a for a in names if word.startswith(a) and _number(word[len(a):])), None)
        if axis is None:
            raise Cl800Error(f"INP: '{word}' is not an axis value")
        coarse[channel.kernel.axis_of[axis]] = float(word[len(axis):])
        fine[channel.kernel.axis_of[axis]] = 0.0
    channel.offsets.apply()


def _number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True
