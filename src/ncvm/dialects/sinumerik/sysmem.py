"""Main groups 3, 4, 7 and a as the channel runs them (digest §4.3-4.7).

Reads are ``read(code, target, args)`` (the result goes to R<target>, and on
for multi-register results); writes are ``write(code, args)`` with the value
last; both, and ``nc_function``, call the run-time function the code's row
names: on the channel's parts (``memory``, ``plc``, ``spindle``) or here,
where the kernel and the program are needed: zero offsets and positions, the
G state, PREP REF / INT SEC, REL / INTA, MEAS M, the operator panel and V24.
"""

from __future__ import annotations

import math
from operator import attrgetter

from ...diagnostics import RuntimeFault
from ...machine.scenario import ExternalInput
from ...nc import cutter
from ...nc.block import Block
from ...nc.canon import Src
from ...nc.dynamics import trapezoid_distance, trapezoid_time
from ...nc.kernel import PLANES
from ...nc.probe import ProbeLatch, announce
from . import v24
from .atcodes import AT_CODES
from .contour import check_window, contour_elements, intersect
from .errors import Cl800Error
from .inta_path import arc_path, straight_path
from .ncdata import in_range as _rng
from .ncdata import nc8
from .ncdata import whole as _i
from .rotation import angle_address, block_frame, machine_frame, program_frame, program_point
from .spindle import MASTER_SPINDLE

#: G group -> its G functions, the first the power-on state (ACG, @36b)
ACG_GROUPS = {0: (0, 1, 10, 11, 2, 3, 33, 34, 35, 6, 12, 13, 5, 7), 1: (9,), 2: (17, 18, 19, 16), 3: (40, 41, 42),
              4: (53,), 5: (54, 55, 56, 57), 6: (4, 25, 26, 58, 59, 92, 74), 7: (60, 63, 64, 62), 8: (70, 71),
              9: tuple(range(80, 90)), 10: (90, 91, 68), 11: (94, 95, 96, 97), 13: (50, 51)}

#: @ code -> the channel's run-time function of its row (``plc.read``: a function of the channel's PLC)
_RUN = {code: attrgetter(row.run) for code, row in AT_CODES.items() if row.run}


class SysMem:
    """Mixed into the channel: the @ codes that need its kernel and program (offsets, positions, NC
    functions, probing, I/O)."""

    def __init__(self):
        self.contours: dict[int, list] = {}
        self.g16_plane: tuple[int, int, int] | None = None
        self.g16_minus = (False, False, False)
        self._paths: list[str] = []
        self._inta_until: float | None = None  # when the input of the last INTA block fired

    # -- axes --------------------------------------------------------------
    def _axis(self, v: float) -> int:
        """Axis number 1..n (manual: 1-24 on the 880) -> axis index."""
        return _rng("axis number", v, 1, self.kernel.n_axes) - 1

    def axis_name(self, v: float, line: int) -> str:
        return self.kernel.axis_names[self._axis(v)]

    def centre_name(self, v: float, line: int) -> str:
        name = self.axis_name(v, line)
        centre = {"X": "I", "Y": "J", "Z": "K"}.get(name)
        if centre is None:
            raise Cl800Error(f"PRIP: axis {name} has no interpolation parameter")
        return centre

    # -- offsets ---------------------------------------------------------
    def apply_offsets(self) -> None:
        """Settable ZO = coarse + fine into the machine's G54..G57; the rest as additive offsets."""
        self.run_buffer()  # offsets apply to the blocks decoded after the change, not to those waiting
        m = self.session.machine
        d = self.data
        for g in (54, 55, 56, 57):
            name = f"G{g}"
            if f"{name}.coarse" in d.zo or f"{name}.fine" in d.zo:
                c, f = d.zo_vec(f"{name}.coarse"), d.zo_vec(f"{name}.fine")
                m.offsets[name] = [a + b for a, b in zip(c, f)]
        self.kernel.set_additive_offset(d.additive())

    def _zo_changed(self) -> None:
        self.data.dirty.add("zo")
        self.apply_offsets()

    def programmable_zo(self, group: int, words: list, line: int) -> None:
        vec = self.data.zo_vec(f"G{57 + group}")
        for name, value in words:
            if name not in self.kernel.axis_of:
                raise Cl800Error(f"G{57 + group}: {name} is not an axis")
            vec[self.kernel.axis_of[name]] = value * self.kernel.scale
        self._zo_changed()

    def select_d(self, d: float, line: int) -> None:
        """D word: tool offset D of the channel's TO area; length = P2 + P5 + P8 on the tool axis."""
        self.run_buffer()
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
        self.kernel.set_tool_length(length, _src(self, line))

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
            kernel.fault("NC005", f"G{g}: cutter radius compensation for tool type {tool_type} of D{n} (turning or "
                         "5D tools, cutting positions) is not supported by ncvm", src)
        return sum(p[i] for i in (4, 7) if i < len(p))

    def g16(self, letters: list, line: int) -> None:
        self.run_buffer()
        axes = []
        minus = []
        for name, neg in letters:
            if name not in self.kernel.axis_of:
                raise Cl800Error(f"G16: {name} is not an axis")
            axes.append(self.kernel.axis_of[name] + 1)
            minus.append(neg)
        if len(axes) < 2:
            raise Cl800Error("G16 needs at least two axes")
        while len(axes) < 3:
            axes.append(0)
        while len(minus) < 3:
            minus.append(False)
        self.g16_plane = tuple(axes[:3])
        self.g16_minus = tuple(minus[:3])
        plane = {(1, 2): 17, (3, 1): 18, (2, 3): 19}.get((axes[0], axes[1]))
        if plane:
            self.kernel.plane = plane

    # -- reads (main group 3) ---------------------------------------------
    def read(self, code: str, target: int, args: tuple) -> None:
        value = self._read(code, target, args)
        R = self.R
        fix = nc8 if self.strict else float
        if isinstance(value, list):
            if target + len(value) > 1000:
                raise Cl800Error(f"result registers R{target}..R{target + len(value) - 1} do not exist")
            for i, v in enumerate(value):
                R[target + i] = fix(v)
        else:
            R[target] = fix(value)

    def store(self, first: int, values: list[float]) -> None:
        """Results of an NC function into R<first>... (8 significant digits under strict_nc)."""
        fix = nc8 if self.strict else float
        self.R[first:first + len(values)] = [fix(v) for v in values]

    def _read(self, code: str, target: int, args: tuple):
        return _RUN[code](self)(code, args)

    def acpw(self, code: str, args: tuple) -> float:
        """ACPW (@360): the actual position in the workpiece system."""
        return self.kernel.workpiece_position()[self.kernel.axis_names[self._axis(args[0])]]

    def acp(self, code: str, args: tuple):
        """ACPM / ACP (@361/@362): the machine position; of a rotary axis the angle and the turns."""
        i = self._axis(args[0])
        pos = self.kernel.machine_pos[i] / self.kernel.scale
        if self.session.machine.axes[i].rotary:
            return [pos % 360.0, float(math.floor(pos / 360.0))]
        return pos

    def acas(self, code: str, args: tuple) -> list[float]:
        """ACAS (@367): the axes of the plane (G16) and the master spindle."""
        self.memory.own_channel(args[0])
        plane = self.g16_plane or {17: (1, 2, 3), 18: (3, 1, 2), 19: (2, 3, 1)}[self.kernel.plane]
        out = [float(a + (128 if m else 0)) for a, m in zip(plane, self.g16_minus)]
        return out + [0.0, float(MASTER_SPINDLE)]

    def acd(self, code: str, args: tuple) -> float:
        """ACD (@36a): the active D number."""
        self.memory.own_channel(args[0])
        return float(self.tool_d)

    def acg(self, code: str, args: tuple) -> float:
        """ACG (@36b): the active G function of a group."""
        self.memory.own_channel(args[0])
        return self._acg(_rng("G group", args[1], 0, 23))

    def zo_read(self, code: str, args: tuple) -> float:
        d = self.data
        if code == "330":
            g = _rng("ZO group", args[0], 1, 4)
            cf = _rng("coarse/fine", args[2], 0, 1)
            return d.zo_vec(f"G{53 + g}.{'fine' if cf else 'coarse'}")[self._axis(args[1])] \
                if f"G{53 + g}.coarse" in d.zo or f"G{53 + g}.fine" in d.zo or cf == 1 \
                else (self.session.machine.offset(f"G{53 + g}")[self._axis(args[1])] if cf == 0 else 0.0)
        if code == "331":
            return d.zo_vec(f"G{57 + _rng('ZO group', args[0], 1, 2)}")[self._axis(args[1])]
        if code == "334":
            return d.preset()[self._axis(args[0])]
        if code in ("332", "333"):
            return d.zo_vec("EXTERNAL" if code == "332" else "DRF")[self._axis(args[0])]
        if code == "336":
            i = self._axis(args[0])
            k = self.kernel
            wo = self.session.machine.offset(k.work_offset)[i] if k.work_offset else 0.0
            total = wo + sum(d.zo.get(n, [0.0] * d.n_axes)[i] for n in ("G58", "G59", "EXTERNAL"))
            if i == k.tool_axis:
                total += k.tool_length
            return total
        if code in ("337", "338"):
            self.memory.channel_args("cycle_md", args[:1])
            kind = "settable" if code == "337" else "programmable"
            g = _rng("rotation group", args[1], 1, 4 if code == "337" else 2)
            return d.rot.get(f"{kind}:{g}", 0.0)
        raise Cl800Error(f"@{code} is not available")

    def _acg(self, group: int) -> float:
        k = self.kernel
        state = {0: k.motion, 2: k.plane, 5: int(k.work_offset[1:]) if k.work_offset else 0,
                 3: cutter.active_g(k), 8: 70 if k.scale != 1.0 else 71, 10: 90 if k.absolute else 91}
        if group in state:
            return float(state[group])
        return float(ACG_GROUPS.get(group, (0,))[0])

    # -- writes (main group 4) -------------------------------------------
    def write(self, code: str, args: tuple) -> None:
        if AT_CODES[code].lower != "write_rotation":
            # data written by decoding serves the blocks decoded after it; rotation angles act at once,
            # even on blocks already decoded (L4325-4334)
            self.run_buffer()
        *where, value = args
        _RUN[code](self)(code, tuple(where), value)

    def to_write(self, code: str, where: tuple, value: float) -> None:
        """TOS / TOAD (@420/@423): set or add to a tool offset parameter."""
        p = self.memory.to_entry(where)
        i = _rng("TO parameter P", where[2], 0, 15)
        p[i] = value if code == "420" else p[i] + value
        self.data.dirty.add("to")
        if self.tool_d and _i(where[1]) == self.tool_d:
            self.select_d(self.tool_d, 0)

    def alnz(self, code: str, where: tuple, value: float) -> None:
        """ALNZ (@4c0): raise a cycle alarm."""
        self.cycle_alarm(value)

    def zo_write(self, code: str, where: tuple, value: float) -> None:
        d = self.data
        if code in ("430", "431"):
            g = _rng("ZO group", where[0], 1, 4)
            i = self._axis(where[1])
            cf = _rng("coarse/fine", where[2], 0, 1)
            name = f"G{53 + g}"
            if f"{name}.coarse" not in d.zo:
                d.zo[f"{name}.coarse"] = list(self.session.machine.offset(name))
            vec = d.zo_vec(f"{name}.{'fine' if cf else 'coarse'}")
            vec[i] = value if code == "430" else vec[i] + value
        elif code == "432":
            d.zo_vec(f"G{57 + _rng('ZO group', where[0], 1, 2)}")[self._axis(where[1])] = value
        elif code == "434":
            d.zo_vec("DRF")[self._axis(where[0])] = value
        elif code == "435":
            d.load_preset(self._axis(where[0]), value)
            return
        elif code in ("437", "438", "439", "43a"):
            self.memory.channel_args("cycle_md", tuple(where[:1]))
            kind = "settable" if code in ("437", "438") else "programmable"
            g = _rng("rotation group", where[1], 1, 4 if kind == "settable" else 2)
            key = f"{kind}:{g}"
            d.rot[key] = value if code in ("437", "439") else d.rot.get(key, 0.0) + value
            d.dirty.add("rot")
            self.route()  # a rotation now selected (or cleared) changes how blocks reach the kernel
            return
        self._zo_changed()

    def cycle_alarm(self, value: float) -> None:
        n = _i(value)
        top5 = 5299 if self.data.control == "880" else 5099
        if not (4000 <= n <= 4299 or 5000 <= n <= top5):
            raise Cl800Error(f"cycle alarm {n} outside 4000-4299, 5000-{top5}")
        self.data.alarms.append((n, self.data.channel))
        self.session.say(f"cycle alarm {n}")
        if n <= 4299 and self.cycle_alarm_stop:
            raise RuntimeFault(str(n), f"cycle alarm {n} (ALNZ)")

    def rotation_active(self) -> bool:
        """A settable or programmable coordinate rotation is selected (some angle is not 0)."""
        return any(a != 0.0 for a in self.data.rot.values())

    # -- main group 7 ------------------------------------------------------
    def nc_function(self, code: str, args: tuple, line: int) -> None:
        _RUN[code](self)(args)

    def stop_dec_now(self, args: tuple) -> None:
        """STOP DEC (@714)."""
        self.stop_dec()  # lockstep (decode_ahead = 0): the buffer is always empty

    def stop_dec1(self, args: tuple) -> None:
        """STOP DEC1 (@715) waits only while a coordinate rotation is selected (L4330-4334)."""
        if self.rotation_active():
            self.stop_dec()

    def prep_cyc(self, args: tuple) -> None:
        """PREP CYC (@713): the unit factor and the diameter flag into R<v>, R<v+1>."""
        target = args[0]
        check_window(target, 2, ((0, 98), (900, 998)), "PREP CYC output")  # L4268
        diameter = self.data.areas["nc_md"].get("diameter_axis1", 0.0)
        self.store(target, [1.0 if self.kernel.scale == 1.0 else 0.03937, 2.0 if diameter else 1.0])

    def prep_ref_args(self, args: tuple) -> None:
        """PREP REF (@710) with the R numbers of its operands."""
        self.prep_ref(int(args[0]), int(args[1]))

    # -- PREP REF / INT SEC ------------------------------------------------
    def _plane_axes(self) -> tuple[str, str]:
        k = self.kernel
        if self.g16_plane:
            h, v = self.g16_plane[0], self.g16_plane[1]
            return k.axis_names[h - 1], k.axis_names[v - 1]
        a, b = PLANES[k.plane][:2]
        return a, b

    def prep_ref(self, rn: int, rm: int) -> None:
        """@710 Rn Rm: the next contour element of sub-program R[m] into Rn..Rn+7."""
        check_window(rm, 4, ((0, 197), (900, 997)), "PREP REF input")
        check_window(rn, 8, ((0, 192), (900, 992)), "PREP REF output")
        R = self.R
        cursor = self.contours.get(rm)
        if R[rm + 3] == 1.0 or cursor is None:
            number = _i(R[rm])
            unit = self.loader(number)
            if unit is None:
                raise RuntimeFault("RUN002", f"PREP REF: contour sub-program L{number} not found")
            cursor = [contour_elements(unit.program, self._plane_axes(), (R[rm + 1], R[rm + 2]), R), 0]
            self.contours[rm] = cursor
            R[rm + 3] = 0.0
        elements, i = cursor
        if i >= len(elements):
            last = elements[-1] if elements else [R[rm + 1], R[rm + 2]] * 2 + [0.0, 0.0, 1.0, 2.0]
            self.store(rn, last[2:4] + last[2:4] + [0.0, 0.0, last[6], 2.0])
            return
        self.store(rn, elements[i])
        cursor[1] = i + 1

    def int_sec(self, rm: int, rn: int, g: tuple, words: dict, line: int) -> None:
        """@711 Rm Rn Rr: intersect element Rn..Rn+7 with the path to this block's destination.

        The element (PREP REF's output: the contour as programmed), the destination and the result are
        in the program's frame; so is the start point, the current position turned back by the
        block's coordinate rotation."""
        check_window(rn, 8, ((0, 192), (900, 992)), "INT SEC input")
        check_window(rm, 3, ((0, 197), (900, 997)), "INT SEC output")
        self.run_buffer()  # the path starts at the end point of the blocks decoded so far
        h_name, v_name = self._plane_axes()
        if h_name not in words or v_name not in words:
            raise Cl800Error(f"INT SEC needs both axes {v_name} and {h_name} of the destination in its block")
        theta = block_frame(self, Block(tuple(g), (), words, None, None, None))[3]
        h, v = program_point(self, h_name, v_name, theta)
        hit = intersect(self.R[rn:rn + 8], (v, h), (words[v_name], words[h_name]))
        self.store(rm, [0.0] if hit is None else [1.0, hit[0], hit[1]])

    # -- REL / INTA (L4400-4436) ---------------------------------------------
    def read_in_inhibit(self, byte: float, bit: float, line: int) -> None:
        """@730 REL: once its block has reached its position, decoding waits for input byte.bit to become 1
        (a 0->1 change; no wait when it is 1 already). Every block decoded so far executes first."""
        self.run_buffer()
        self.wait_input(_i(byte), _i(bit), True, "REL")

    def inta(self, axis: float, byte: float, bit: float, g: tuple, words: dict, line: int) -> dict:
        """@736 INTA: the block's words, cut where the motion stops when input byte.bit reaches the level
        (bit >= 0: 1, bit < 0: 0); unchanged when the position is reached first. Axis 0 = all axes of the
        block; the axes interpolating with the named one stop with it, which here are all of them (both
        plane axes of a circle). The path is cut on the traversing axes (under a rotation both plane
        axes), a circle as an arc with the same centre and a shorter sweep, and handed back in the
        program's frame."""
        self.run_buffer()  # the block starts where the blocks before it end
        k = self.kernel
        ax = _rng("INTA axis number", axis, 0, 24)
        b, n = _i(byte), _i(bit)
        level = n >= 0 and not (n == 0 and math.copysign(1.0, bit) < 0)
        n = abs(n)
        self.ext_input(b, n)  # checks byte 1/2, bit 0-7
        if ax > k.n_axes:
            raise Cl800Error(f"INTA: axis {ax} does not exist")
        self._inta_until = None
        turned, frame = machine_frame(self, g, words)  # the block in the frame of the machine axes
        path = self._inta_path(g, turned)
        if path is None or not path.axes or (ax and k.axis_names[ax - 1] not in path.axes):
            return words
        now = self.session.machine.clock.now
        hit = self._input_time(b, n, level, now + trapezoid_time(path.length, path.speed, path.accel))
        self._inta_until = hit
        if hit is None:
            return words
        travelled = trapezoid_distance(path.length, path.speed, path.accel, hit - now)
        cut = path.cut(travelled / path.length if path.length else 0.0)
        angle = angle_address(self) if self.angle_used else None  # resolved into the axis words
        out = {n: v for n, v in words.items() if n not in k.axis_of and n != angle and n not in path.replaces}
        out.update(cut if 53 in g else program_frame(cut, frame))
        return out

    def _inta_path(self, g: tuple, turned: dict):
        """The INTA block's path as the kernel will run it; None for a block the kernel rejects (it then
        reports the fault when the block executes)."""
        k = self.kernel
        motion = next((x for x in reversed(g) if x in (0, 1, 2, 3)), k.motion)
        scale = 25.4 if 70 in g else (1.0 if 71 in g else k.scale)
        machine = 53 in g
        relative = not machine and (False if 90 in g else (True if 91 in g else not k.absolute))
        prog = k.shown_position()  # the turned frame, as the block's words are
        start = [(k.machine_pos[i] if machine else prog[i]) / scale for i in range(k.n_axes)]
        feed = turned["F"] * scale if "F" in turned else k.feed  # mm/min
        if motion < 2:
            return straight_path(k, motion == 0, turned, start, scale, relative, feed)
        plane = next((x for x in reversed(g) if x in (17, 18, 19)), k.plane)
        return arc_path(k, motion == 2, plane, turned, start, scale, relative, feed)

    def inta_done(self) -> None:
        """After an INTA block: simulated time has reached the moment the input fired."""
        clock = self.session.machine.clock
        if self._inta_until is not None and clock.now < self._inta_until:
            clock.advance(self._inta_until - clock.now)
        self._inta_until = None

    def _input_time(self, byte: int, bit: int, level: bool, until: float) -> float | None:
        """When external input byte.bit first has ``level``, from now to ``until``; None if not before."""
        now = self.session.machine.clock.now
        if self.ext_input(byte, bit) == level:
            return now
        for ev in self._scenario:
            if ev.time > until:
                break
            if ev.__class__ is ExternalInput and ev.byte == byte and ev.bit == bit and ev.value == level:
                return max(ev.time, now)
        return None

    # -- MEAS M --------------------------------------------------------------
    def meas(self, target: int, probe: float, g: tuple, words: dict, line: int) -> dict:
        """@720: the block's axes move until the probe switches; their actual values relative to machine
        zero go to R<target>... (L4357-4396). The traversing axes are those of the block as it reaches the
        interpolation: under a coordinate rotation a plane axis word moves both axes of the plane. The
        block's words come back cut at the trigger point, in the program's frame."""
        self.run_buffer()  # the measuring block starts where the blocks before it end
        probe = _i(probe)
        k = self.kernel
        if probe not in (1, 2):
            raise Cl800Error(f"MEAS M: probe input {probe} is not 1 or 2")
        machine = 53 in g
        turned, frame = machine_frame(self, g, words)
        moving = sorted((n for n in turned if n in k.axis_of), key=k.axis_of.get)
        if len(moving) > 2:
            raise Cl800Error(f"MEAS M: at most 2 axes may move in the measuring block ({', '.join(moving)})")
        if next((x for x in reversed(g) if x in (0, 1, 2, 3)), k.motion) not in (0, 1):
            raise Cl800Error("MEAS M needs G00 or G01")
        scale = 25.4 if 70 in g else (1.0 if 71 in g else k.scale)
        absolute = True if 90 in g else (False if 91 in g else k.absolute)
        start = {n: k.machine_pos[k.axis_of[n]] for n in moving}
        shown = k.shown_position()  # the turned frame, as the block's words are
        end = {}
        for name in moving:
            i = k.axis_of[name]
            value = turned[name] * scale
            end[name] = value if machine else k.offset_vec[i] + (value if absolute else shown[i] + value)
        hit = self.probe.trigger_point(self.probe.hit(probe), start, end)
        announce(k.canon, ProbeLatch(probe, dict(hit)), _src(self, line))
        angle = angle_address(self) if self.angle_used else None  # resolved into the axis words
        out = {n: v for n, v in words.items() if n not in k.axis_of and n != angle}
        cut = {}
        reg = target
        axes = self.session.machine.axes
        for name in moving:
            i = k.axis_of[name]
            # seen by decoding only after STOP DEC; a rotary axis as position within a rotation and number
            # of rotations (L4366-4369), as ACPM
            values = [hit[name] % 360.0, float(math.floor(hit[name] / 360.0))] if axes[i].rotary \
                else [hit[name] / scale]
            for value in values:
                if reg > 999:
                    raise Cl800Error(f"MEAS M: result register R{reg} does not exist")
                self.load_r(reg, value)
                reg += 1
            prog = hit[name] - (0.0 if machine else k.offset_vec[i])
            cut[name] = prog / scale if absolute or machine else (prog - shown[i]) / scale
        out.update(cut if machine else program_frame(cut, frame))
        return out

    # -- main group a: operator panel and V24 -------------------------------
    def io(self, code: str, args: tuple) -> None:
        """WRT PIC / RECALL PIC / CHAN on the operator panel (shown in the output); PORT, OUTP ... and INP
        on the V24 port (module v24). Without PORT the interface selected at the operator panel is used."""
        if code == "a15":
            sector = ("user", "standard")[_rng("sector (0 user / 1 standard)", args[0], 0, 1)]
            self.panel.append(f"{sector} menu {_rng('menu number', args[1], 1, 254)}")
            self.session.say(f"[panel] {self.panel[-1]}")
        elif code == "a1b":
            if len(self.panel) > 1:
                self.panel.pop()
                self.session.say(f"[panel] {self.panel[-1]}")
            elif self.panel:
                self.panel.pop()
                self.session.say("[panel] the display shown before the first WRT PIC")
        elif code == "a40":
            self.session.say(f"[panel] channel {_rng('channel', args[0], 1, 16)}")
        elif code == "a20":
            self.v24.append(f"PORT {_rng('V24 interface', args[0], 1, 4)}")
        elif code == "a25":
            ch = _rng("channel", args[0], 0, 16)
            if ch:
                self.memory.own_channel(ch)
            self.v24.extend(v24.zo_lines(self.data, self.session.machine.offset, self.kernel.axis_names, ch))
        elif code == "a26":
            folders = self.session.machine.program_path
            self.v24.extend(v24.data_lines(self.data, lambda kind, a, b: v24.find_programs(folders, kind, a, b),
                                           _i(args[0]), _i(args[1]), _i(args[2])))
        elif code == "a27":
            self.memory.own_channel(args[0])
            lo, hi = _rng("R number", args[1], 0, 999), _rng("R number", args[2], 0, 999)
            for n in range(lo, hi + 1):
                self.v24.append(f"R{n}={v24.fmt(self.R[n])}")
        elif code == "a28":
            v24.read_in(self, _i(args[0]), self.data.v24_input)
            self.data.v24_input = ""
        elif code == "a29":
            self.v24.append("\x03")
        else:
            raise Cl800Error(f"@{code} is not available")


def _src(channel, line: int):
    return Src(channel._current_path(), line)
