"""Zero offsets and the tool offset of the channel: G54-G59, external ZO, DRF, preset, the D word, and the
@ codes that read and write them (ZOA ... ZOPRDW @330-@338 / @430-@43a, TOS/TOAD @420/@423, ACD @36a;
planning guide ch.10, L6530-6537, L6650-6663; CL 800 manual §10.5, L6484-6604; §10.6, L6605-6705).

Offsets written by decoding serve the blocks decoded after the change, so each change first executes the
blocks still waiting in the decode buffer.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...diagnostics import RuntimeFault
from .errors import Cl800Error
from .ncdata import in_range as _rng
from .ncdata import whole as _i
from .positions import axis_index

if TYPE_CHECKING:
    from .runtime import Channel


class Offsets:
    """The zero offsets (kept in ``NcData``) as the kernel applies them, and the selected D number."""

    def __init__(self, channel: Channel):
        self.channel = channel
        self.kernel = channel.kernel
        self.data = channel.data
        self.machine = channel.session.machine
        self.tool_d = 0  # the active D number

    def apply(self) -> None:
        """Settable ZO = coarse + fine into the machine's G54..G57; the rest as additive offsets."""
        self.channel.run_buffer()  # offsets apply to the blocks decoded after the change, not to those waiting
        m = self.machine
        d = self.data
        for g in (54, 55, 56, 57):
            name = f"G{g}"
            if f"{name}.coarse" in d.zo or f"{name}.fine" in d.zo:
                c, f = d.zo_vec(f"{name}.coarse"), d.zo_vec(f"{name}.fine")
                m.offsets[name] = [a + b for a, b in zip(c, f)]
        self.kernel.set_additive_offset(d.additive())

    def _changed(self) -> None:
        self.data.dirty.add("zo")  # (kept for the end of the run should a waiting block fault in apply)
        self.apply()
        self.data.changed()

    def programmable_zo(self, group: int, words: list, line: int) -> None:
        for name, _ in words:
            if name not in self.kernel.axis_of:
                raise Cl800Error(f"G{57 + group}: {name} is not an axis")
        # the blocks decoded before it execute first: where one faults, this offset is never written (nor kept)
        self.channel.run_buffer()
        vec = self.data.zo_vec(f"G{57 + group}")
        for name, value in words:
            vec[self.kernel.axis_of[name]] = value * self.kernel.unit_of(name)
        self._changed()

    def select_d(self, d: float, line: int) -> None:
        """D word: tool offset D of the channel's TO area; length = P2 + P5 + P8 on the tool axis."""
        self.channel.run_buffer()
        n = _i(d)
        comp = self.kernel.comp
        if comp is not None and not comp.leaving and n != self.tool_d:
            raise RuntimeFault("NC005", f"D{n}: another tool offset while G41/G42 is on is not supported by ncvm "
                               "(G40 first)")
        self.tool_d = n
        if n == 0:
            length = 0.0
        else:
            p = self.data.to.get(f"{self.data.to_area}:{n}")
            if p is None:
                raise RuntimeFault("NC008", f"D{n}: no tool offset D{n} in TO area {self.data.to_area}")
            tool_type = int(p[1])
            length = p[3] + p[6] + p[9] if 1 <= tool_type <= 9 else p[2] + p[5] + p[8]
        self.kernel.set_tool_length(length, self.channel.src(line), n)

    def cutter_radius(self, kernel, g: int, words, src) -> float:
        """G41/G42: the radius of the selected tool offset D, P4 + P7 (geometry + wear) of a shank or angle
        cutter or a grinding wheel (types 20-39, 50-59), 0 for a drill (10-19) or without D (table L615)."""
        n = self.tool_d
        if not n:
            return 0.0
        p = self.data.to.get(f"{self.data.to_area}:{n}")
        if p is None:
            kernel.fault("NC008", f"D{n}: no tool offset D{n} in TO area {self.data.to_area}", src)
        tool_type = int(p[1]) if len(p) > 1 else 0
        if 10 <= tool_type <= 19:
            return 0.0
        if not (20 <= tool_type <= 39 or 50 <= tool_type <= 59):
            kernel.fault("NC005", f"G{g}: cutter radius compensation for tool type {tool_type} of D{n} is not "
                         "supported by ncvm (it compensates cutters and grinding wheels, types 20-39 and 50-59)", src)
        return sum(p[i] for i in (4, 7) if i < len(p))

    def acd(self, code: str, args: tuple) -> float:
        """ACD (@36a): the active D number."""
        self.channel.memory.own_channel(args[0])
        return float(self.tool_d)

    def zo_read(self, code: str, args: tuple) -> float:
        d = self.data
        k = self.kernel
        if code == "330":
            g = _rng("ZO group", args[0], 1, 4)
            cf = _rng("coarse/fine", args[2], 0, 1)
            return d.zo_vec(f"G{53 + g}.{'fine' if cf else 'coarse'}")[axis_index(k, args[1])] \
                if f"G{53 + g}.coarse" in d.zo or f"G{53 + g}.fine" in d.zo or cf == 1 \
                else (self.machine.offset(f"G{53 + g}")[axis_index(k, args[1])] if cf == 0 else 0.0)
        if code == "331":
            return d.zo_vec(f"G{57 + _rng('ZO group', args[0], 1, 2)}")[axis_index(k, args[1])]
        if code == "334":
            return d.preset()[axis_index(k, args[0])]
        if code in ("332", "333"):
            return d.zo_vec("EXTERNAL" if code == "332" else "DRF")[axis_index(k, args[0])]
        if code == "336":
            i = axis_index(k, args[0])
            wo = self.machine.offset(k.work_offset)[i] if k.work_offset else 0.0
            total = wo + sum(d.zo.get(n, [0.0] * d.n_axes)[i] for n in ("G58", "G59", "EXTERNAL"))
            if i == k.tool_axis:
                total += k.tool_length
            return total
        if code in ("337", "338"):
            self.channel.memory.channel_args("cycle_md", args[:1])
            kind = "settable" if code == "337" else "programmable"
            g = _rng("rotation group", args[1], 1, 4 if code == "337" else 2)
            return d.rot.get(f"{kind}:{g}", 0.0)
        raise Cl800Error(f"@{code} is not available")

    def zo_write(self, code: str, where: tuple, value: float) -> None:
        d = self.data
        if code in ("430", "431"):
            g = _rng("ZO group", where[0], 1, 4)
            i = axis_index(self.kernel, where[1])
            cf = _rng("coarse/fine", where[2], 0, 1)
            name = f"G{53 + g}"
            if f"{name}.coarse" not in d.zo:
                d.zo[f"{name}.coarse"] = list(self.machine.offset(name))
            vec = d.zo_vec(f"{name}.{'fine' if cf else 'coarse'}")
            vec[i] = value if code == "430" else vec[i] + value
        elif code == "432":
            d.zo_vec(f"G{57 + _rng('ZO group', where[0], 1, 2)}")[axis_index(self.kernel, where[1])] = value
        elif code == "434":
            d.zo_vec("DRF")[axis_index(self.kernel, where[0])] = value
        elif code == "435":
            d.load_preset(axis_index(self.kernel, where[0]), value)
            return
        elif code in ("437", "438", "439", "43a"):
            self.channel.memory.channel_args("cycle_md", tuple(where[:1]))
            kind = "settable" if code in ("437", "438") else "programmable"
            g = _rng("rotation group", where[1], 1, 4 if kind == "settable" else 2)
            key = f"{kind}:{g}"
            d.rot[key] = value if code in ("437", "439") else d.rot.get(key, 0.0) + value
            d.dirty.add("rot")
            self.channel.route()  # a rotation now selected (or cleared) changes how blocks reach the kernel
            d.changed()
            return
        self._changed()

    def to_write(self, code: str, where: tuple, value: float) -> None:
        """TOS / TOAD (@420/@423): set or add to a tool offset parameter."""
        p = self.channel.memory.to_entry(where)
        i = _rng("TO parameter P", where[2], 0, 15)
        p[i] = value if code == "420" else p[i] + value
        self.data.changed("to")
        if self.tool_d and _i(where[1]) == self.tool_d:
            self.select_d(self.tool_d, self.channel.write_line)
