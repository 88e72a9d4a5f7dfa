"""The channel at run time: R parameters, push stack, calls, and the helpers generated code calls.

One :class:`Channel` per run. Generated units (see codegen) receive it as
``_rt``; hot operations (R arithmetic, jumps, comparisons) are inline Python,
everything that touches NC data goes through the channel: its entry points
``read``/``write``/``nc_function``/``io`` call the run-time function the @ code's
row names (``row.run``), a method of one of the channel's parts.
"""

from __future__ import annotations

import math
import re
import sys
from functools import partial
from operator import attrgetter

from ...diagnostics import Frame, RuntimeFault, Span, UsageError
from ...machine.scenario import (
    Alarm,
    EventQueue,
    ExternalInput,
    PlcChange,
    PlcCounter,
    PlcTimer,
    ProbeSwitch,
    of_type,
    refuse,
)
from ...nc import blockskip
from ...nc.block import Block
from ...nc.canon import NOBODY, CanonSink, Src
from ...nc.kernel import INCH
from ...nc.planner import STOP_END
from ...nc.profiles.sinumerik8xx import SINUMERIK8XX
from ...nc.spindle import SINUMERIK_GEARS, Gearbox
from ...runtime.buffer import BlockBuffer
from ...runtime.locate import generated_frames, raised_by_generated
from . import feeds
from .atcodes import AT_CODES
from .central import CentralR
from .cycles import Cycles
from .drilling import Drilling
from .errors import Cl800Error
from .meas import meas_m
from .memory import SystemMemory
from .ncdata import MIB_TOP, R_LIMIT, NcData, held, int_to_pattern, nc8, pattern_to_int, r_value
from .offsets import Offsets
from .options import options
from .panel import Panel
from .plc import PlcClock
from .plcmem import Plc
from .positions import Positions
from .probe import Probe
from .rel_inta import RelInta
from .rotation import angle_address, rotate_for, rotation_active, shape_block
from .rounding import CornerRounding
from .spindle import GEAR_M, Spindle

DEG = math.pi / 180.0
_PLC_SOURCE = re.compile(r"^(?:PLC(\d)\.)?DB(\d+)\.DW(\d+)$")
#: project alarm codes (the manual names only "CL 800 error" and the cycle alarms 4000-5299)
ALARMS = {
    "CL800": "CL 800 error (operand out of range, missing data, arithmetic error)",
    "SIN001": "block cannot be read",
    "SIN002": "unknown @ code",
    "SIN003": "wrong operands for the @ code",
    "SIN004": "jump target block not found in the search direction",
    "SIN006": "push/pop stack error",
    "SIN007": "waiting for an input that never changes",
    "SIN010": "warning: actual value read or measurement used without STOP DEC after motion",
    "RUN002": "sub-program not found",
    "RUN003": "sub-program nesting too deep",
}


def _ptr(value: float) -> int:
    n = int(value)
    if n != value or not 0 <= n <= 999:
        raise Cl800Error(f"pointer value {value:g} is not an R parameter number (0-999)")
    return n


def _bad_angle(function: str, x: float) -> float:
    """SIN and COS take angles of -360 to +360 degrees (L3779, L3800); the generated code checks the range
    in line and calls this beyond it."""
    raise Cl800Error(f"{function}({x:g}): the angle must lie between -360 and +360 degrees")


def _int(value: float) -> int:
    n = int(value)
    if n != value:
        raise Cl800Error(f"{value:g} is not a whole number")
    return n


NAMESPACE_GLOBALS = {
    "_Block": Block, "_int": _int, "_ptr": _ptr, "_hypot": math.hypot, "_sin": math.sin,
    "_cos": math.cos, "_sqrt": math.sqrt, "_trunc": math.trunc, "_DEG": DEG, "_bad_angle": _bad_angle,
    "_nc8": nc8, "_r_value": r_value, "_meas_m": meas_m,
}

#: @ code -> the run-time function its row names, on the channel or one of its parts (``plc.read``)
_RUN = {code: attrgetter(row.run) for code, row in AT_CODES.items() if row.run}


#: the path control's G codes (kernel.ISO_PATH_CODES): G60 exact stop (the power-on state), G64 continuous
#: path, G09 exact stop at the end of its block (docs/decisions.md)
SINUMERIK_PATH_CODES = {9: "block", 60: "exact", 64: "continuous"}

#: the scenario events the SINUMERIK channel reads
SINUMERIK_EVENTS = (ExternalInput, PlcChange, PlcTimer, PlcCounter, Alarm, ProbeSwitch)



def _told_linear(linear, k, motion: int, words: dict, src) -> None:
    """The generated G0/G1 fast path under a translation: the canon first hears the block's axis words
    (``programmed``, as the kernel's block path says them), so that an axis standing where it is is written."""
    k.canon.programmed(tuple(a for a in words if a in k.axis_of), src)
    linear(k, motion, words, src)

class PlcAnswers(CanonSink):
    """The PLC's answer to an M function it is handed (canon ``aux``), after the sinks have recorded it."""

    def __init__(self, answer):
        self.answer = answer

    def aux(self, code: str, src: Src) -> None:
        self.answer(code)


class Channel:
    """One NC channel running a main program and its sub-programs; its parts hold the NC data and the @ code
    functions (docs/architecture.md, SINUMERIK)."""

    def __init__(self, session, data: NcData, loader, stored: dict | None = None):
        self.session = session
        self.kernel = session.kernel
        self.execute = session.kernel.execute
        self.counter = session.steps
        self.data = data
        self.loader = loader  # number -> compiled unit (or None)
        sec = options(session.machine)
        skip = sec.block_skip
        self.block_skip = bool(session.machine.setting_data.get("block_skip", True) if skip is None else skip)
        # M0: the run goes on as after the operator's cycle start, unless [sin800] m0 = "stop"
        self.m0_stops = self.kernel.m0_stops = sec.m0 == "stop"
        self.max_depth = sec.max_call_depth
        self.radius_address = sec.radius_address  # B or U: the circle radius (machine data)
        self.memory = SystemMemory(data, session.say, sec.cycle_alarm_stop)
        # decode-ahead (ncvm's reading; the CL 800 manual is silent): 0 = lockstep; N = up to N decoded blocks wait for execution
        self.decode_ahead = sec.decode_ahead
        self.strict = sec.strict_nc  # R stores rounded to 8 digits (ncvm's reading; the CL 800 manual is silent)
        self.write_line = 0  # the block of the @ write running now (write)
        self.buffer = BlockBuffer(self.decode_ahead, self.execute)  # route() keeps its step on the current path
        self.pending_r: dict[int, float] = {}  # PLC answers and measured values not yet seen by decoding
        self.R = [0.0] * 1000
        self.written: set[int] = set()
        for name, v in sec.r.items():
            self.R[int(str(name).upper().lstrip("R"))] = float(v)
        for k, v in data.central_r.items():
            self.R[int(k)] = float(v)
        #: central R non-zero in the state directory, not yet read: number -> the value an earlier run left
        self.left: dict[int, float] = {}
        self._power_on_r(session.machine.source)
        #: R900-R999 written through to the store (``stored``: what the store held at the start)
        self.central = CentralR(self.R, data.central_r, stored or {}, session.store)
        self.push_stack: list[tuple[tuple[int, ...], list[float]]] = []
        self.frames: list[Frame] = []
        self._paths: list[str] = []  # the file of each running unit, as ``frames``
        self.halted = False
        self.ess_enabled = False
        self.positions = Positions(self)
        self.offsets = Offsets(self)
        self.kernel.cutter_radius = self.offsets.cutter_radius  # G41/G42: the radius of the TO area's offset D
        self.kernel.use_profile(SINUMERIK8XX)  # the 810-880 G groups (nc/profiles/sinumerik8xx.py)
        feeds.setup(self.kernel)  # G94-G97, the threads G33-G35
        self.drilling = Drilling(self)  # G80-G89: the drilling cycles L81-L89
        self.kernel.g_handlers.update(self.drilling.handlers())
        self.kernel.path_codes = SINUMERIK_PATH_CODES
        self.kernel.exact = STOP_END  # G60 until the program selects G64
        if self.kernel.canon.path_control is not NOBODY:  # the power-on G60, for a translation to write
            self.kernel.canon.path_control("exact", None, None)
        self.cycles = Cycles(self)
        self.rel_inta = RelInta(self)
        self.panel = Panel(self)
        self.angle_used = False  # a block carried the angle address (PANG, @447)
        #: (first plane axis, second plane axis, degrees) of the rotation set as the kernel's transform, or None
        self.rotation_key: tuple | None = None
        self.rounding = CornerRounding(self)  # a radius on a G1 block rounds the corner to the next block
        self.route()
        refuse(session.machine.scenario, SINUMERIK_EVENTS, "SINUMERIK control")
        self.scenario = EventQueue(session.machine.scenario)  # the scenario events still to come
        self.probe = Probe(self.scenario, self.advance_scenario)
        self.plc_clock = PlcClock(f"{session.machine.source}: [sin800]", data.plc)
        self.plc = Plc(data, self.plc_clock, session.machine.clock, self.advance_scenario, session.say)
        for ev in of_type(session.machine.scenario, PlcTimer, PlcCounter):
            self.plc_clock.parse_event(ev)  # faults in the scenario before the run
        self.m_functions = {f"M{int(k)}": dict(v) for k, v in sec.m_functions.items()}
        gearbox = Gearbox(self.kernel, SINUMERIK_GEARS, data.gear, data.gears, Cl800Error, "[sin800] gears")
        self.spindle = Spindle(self.kernel, data, self.buffer, gearbox)
        # G96 takes the radius from X; axis 1 may be programmed as a diameter (as for PREP CYC)
        self.kernel.css_diameter = self.kernel.css_axis == 0 and bool(data.areas["nc_md"].get("diameter_axis1", 0.0))
        session.canon.add(PlcAnswers(self.answer_m))
        if data.inch_basic_system():  # G70 is the power-on state (MDNBI(5002,4), L2324-2326)
            self.kernel.scale = INCH
        self.offsets.apply()

    def answer_m(self, code: str) -> None:
        """M functions the PLC answers: gear stages (M40-M45), R parameters it loads (m_functions),
        timers and counters wired to them."""
        self.advance_scenario()  # what the PLC did before this block
        self.plc_clock.m_function(code, self.session.machine.clock.now)
        if code in GEAR_M:
            self.spindle.gearbox.select(GEAR_M[code])
        if code in self.m_functions:
            self.m_function(code)

    def _power_on_r(self, source: str) -> None:
        """R parameters from the machine file and the store lie within +/-99999999 (L7079), as every R
        value; under strict_nc they keep 8 significant digits too."""
        R = self.R
        keep = nc8 if self.strict else r_value
        for n, v in enumerate(R):
            if v != 0.0:
                try:
                    R[n] = keep(v)
                except Cl800Error as e:
                    raise UsageError(f"{source}: [sin800] R{n}: {e}") from None

    # -- how decoded blocks reach the kernel ---------------------------------
    def route(self) -> None:
        """Pick the execution path: straight to the kernel, or shaped first (rotation, angle address);
        through the decode buffer when decoding runs ahead. Generated code re-reads ``execute`` and
        ``linear`` after rotation writes and calls."""
        k = self.kernel
        shaped = self.angle_used or rotation_active(self)
        if not shaped and self.rotation_key is not None:  # every angle is 0 again
            k.set_transform(None)
            self.rotation_key = None
        self.execute_now = self.execute_shaped if shaped else k.execute
        self.linear = self.linear_shaped if shaped else k.linear
        if self.rounding.used:  # the corner rounding sees every block first
            self.rounding.inner, self.rounding.inner_linear = self.execute_now, self.linear
            self.execute_now, self.linear = self.rounding.execute, self.rounding.linear
        if k.canon.programmed is not NOBODY:  # a translation writes the block's axis words, not only those that move
            self.linear = partial(_told_linear, self.linear)
        self.execute = self.decode_into_buffer if self.decode_ahead > 0 else self.execute_now
        self.buffer.execute = self.execute_now

    def execute_shaped(self, block: Block) -> None:
        rotate_for(self, block)
        key = angle_address(self) if self.angle_used else None
        self.kernel.execute(shape_block(self, block, key, turn=False))

    def linear_shaped(self, k, motion: int, words: dict, src) -> None:
        """The generated G0/G1 fast path while a rotation is selected: the kernel's transformed path."""
        rotate_for(self, Block((), (), words, None, None, src))
        k.linear(k, motion, words, src)

    def execute_angle(self, block: Block) -> None:
        """A block with the programmed angle (PANG or the angle address word)."""
        self.use_angle()
        self.execute(block)

    def use_angle(self) -> None:
        """From the first block with the programmed angle on, blocks are shaped before the kernel."""
        if not self.angle_used:
            self.angle_used = True
            self.route()

    def use_rounding(self) -> None:
        """From the first block with the circle radius on, blocks pass the corner rounding (rounding.py)."""
        if not self.rounding.used:
            self.rounding.used = True
            self.route()

    def angle_key(self) -> str:
        return angle_address(self)

    # -- decode-ahead (manual L4287-4334) --------------------
    def decode_into_buffer(self, block: Block) -> None:
        """A decoded block waits in the NC buffer; the oldest executes once more than N are waiting.
        Blocks that stop or end the program (M0/M1/M2/M30) empty the buffer at once."""
        self.buffer.put(block)
        if any(m in (0, 1, 2, 30) for m in block.m):
            self.buffer.drain()

    def run_buffer(self) -> None:
        """Execute every decoded block still waiting (decoding needs the executed state)."""
        self.buffer.drain()

    def execute_decoded(self, stop: Exception) -> Exception:
        """Decoding stopped with ``stop`` (an alarm, the step limit): the blocks decoded before it were handed
        to execution and run to their end, as at the program end (docs/decisions.md, "A run that stops keeps
        the blocks it prepared"); an alarm of one of them is earlier in the program and is the one returned,
        else ``stop``. A block waiting for the next one to round its corner stays undone: it never came."""
        try:
            self.run_buffer()
        except RuntimeFault as earlier:
            return earlier
        except Cl800Error as e:
            return RuntimeFault("CL800", f"CL 800 error: {e}")
        except MemoryError:
            return stop
        return stop

    def stop_dec(self) -> None:
        """@714 STOP DEC: decoding waits until the buffer is empty; R parameters loaded by the PLC or by
        MEAS M meanwhile become visible to the blocks that follow."""
        self.run_buffer()
        self.rounding.finish()
        self.kernel.planner.stop()  # decoding waits for the axes: they stop
        R = self.R
        if self.pending_r:
            for n, v in self.pending_r.items():
                R[n] = v
            self.pending_r.clear()
            self.central.check()

    def stop_dec_now(self, args: tuple) -> None:
        """STOP DEC (@714)."""
        self.stop_dec()  # lockstep (decode_ahead = 0): the buffer is always empty

    def stop_dec1(self, args: tuple) -> None:
        """STOP DEC1 (@715) waits only while a coordinate rotation is selected (L4330-4334)."""
        if rotation_active(self):
            self.stop_dec()

    def load_r(self, n: int, value: float) -> None:
        """An R parameter written by execution (PLC answer, measured value), not by decoding."""
        value = nc8(value) if self.strict else held(value)
        if self.decode_ahead > 0:
            self.pending_r[n] = value
        else:
            self.R[n] = value
            self.central.check()

    # -- the @ codes of main groups 3, 4, 7 and a (CL 800 manual §10.5, L6484-6604; §5.3.9, L4438-4590; §10.10, L6801-6824) ----------
    def read(self, code: str, target: int, args: tuple) -> None:
        """A read: the value goes to R<target> (and on, for multi-register results)."""
        value = _RUN[code](self)(code, args)
        row = AT_CODES[code]
        if row.run == "plc.read" and self.kernel.canon.frozen is not NOBODY:  # input from outside the program: a translation marks the block it leads to
            got = " ".join(f"{v:g}" for v in value) if isinstance(value, list) else f"{value:g}"
            self.kernel.canon.frozen(f"PLC read @{code} ({row.statement}) into R{target}: {got}, the simulated "
                                     "PLC's ([sin800.plc])", None)
        R = self.R
        fix = nc8 if self.strict else held
        if isinstance(value, list):
            if target + len(value) > 1000:
                raise Cl800Error(f"result registers R{target}..R{target + len(value) - 1} do not exist")
            for i, v in enumerate(value):
                R[target + i] = fix(v)
        else:
            R[target] = fix(value)
        self.central.check()

    def store(self, first: int, values: list[float]) -> None:
        """Results of an NC function into R<first>... (8 significant digits under strict_nc)."""
        fix = nc8 if self.strict else held
        self.R[first:first + len(values)] = [fix(v) for v in values]
        self.central.check()

    def write(self, code: str, args: tuple, line: int = 0) -> None:
        """A write, the value last; ``line``: the block that writes (:attr:`write_line`, the source of what
        the write changes, e.g. the active tool length)."""
        self.write_line = line
        if AT_CODES[code].lower != "write_rotation":
            # data written by decoding serves the blocks decoded after it; rotation angles act at once,
            # even on blocks already decoded (L4325-4334)
            self.run_buffer()
        *where, value = args
        _RUN[code](self)(code, tuple(where), value)

    def nc_function(self, code: str, args: tuple, line: int) -> None:
        _RUN[code](self)(args)

    def io(self, code: str, args: tuple) -> None:
        _RUN[code](self)(code, args)

    # -- running units ---------------------------------------------------
    def run_unit(self, unit, frame_name: str, call_span: Span | None) -> int:
        """Run a compiled unit; faults get the unit's line and the call stack."""
        self.frames.append(Frame(frame_name, call_span))
        self._paths.append(unit.path)
        try:
            return unit.fn(self)
        except RuntimeFault as f:
            self._locate(f, unit)
            raise
        except Cl800Error as e:
            f = RuntimeFault("CL800", f"CL 800 error: {e}")
            self._locate(f, unit)
            raise f from None
        except (ZeroDivisionError, ValueError, OverflowError) as e:
            if not raised_by_generated(e.__traceback__, {unit.source.filename: unit.source}):
                raise  # raised inside ncvm (its helpers raise Cl800Error for the program's faults): an internal error
            text = "division by zero" if isinstance(e, ZeroDivisionError) else f"arithmetic error ({e})"
            f = RuntimeFault("CL800", f"CL 800 error: {text}")
            self._locate(f, unit)
            raise f from None
        finally:
            self.frames.pop()
            self._paths.pop()

    def _locate(self, f: RuntimeFault, unit) -> None:
        if f.span is None:
            frames = generated_frames(sys.exc_info()[2], {unit.source.filename: unit.source})
            if frames:
                f.span = Span(unit.path, frames[-1].line, frames[-1].col)
        if not f.stack:
            f.stack = [Frame(fr.unit, None) for fr in self.frames]
            for i in range(len(self.frames) - 1):
                f.stack[i] = Frame(self.frames[i].unit, self.frames[i + 1].span)
            f.stack[-1] = Frame(self.frames[-1].unit, f.span)

    def call(self, number: int, passes: int, line: int) -> None:
        """``L<n> P<k>``: run sub-program n k times (ncvm's reading; the CL 800 manual is silent)."""
        span = Span(self._current_path(), line)
        if len(self.frames) > self.max_depth:
            raise RuntimeFault("RUN003", f"L{number}: sub-program nesting deeper than {self.max_depth} levels",
                               span)
        unit = self.loader(number)
        if unit is None:
            raise RuntimeFault("RUN002", f"sub-program L{number} not found (looked for L{number}.spf and "
                                         f"%SPF{number} files along the program path)", span)
        for _ in range(max(1, passes)):
            if self.run_unit(unit, f"L{number}", span):
                self.halted = True
                return

    def block_skip_read(self, line: int) -> None:
        """A ``/`` block is met: the block skip switch decides whether it runs (a translation marks it)."""
        blockskip.tell(self.kernel.canon, self.block_skip, self.src(line))

    def central_read(self, line: int, reads: tuple) -> None:
        """The program reads central R parameters ((number, value now) each): the first read of one an earlier
        run left, while it still holds that value, is input from outside the program, marked FROZEN at this
        block by a translation; one the program wrote before reading it is its own."""
        for n, value in reads:
            left = self.left.pop(n, None)
            if left is not None and value == left:
                self.kernel.canon.frozen(f"central R parameter R{n}={value:g} left by earlier runs", self.src(line))

    def _current_path(self) -> str:
        return self._paths[-1] if self._paths else ""

    def src(self, line: int) -> Src:
        """Where a canon call of the running unit comes from."""
        return Src(self._current_path(), line)

    def halt(self) -> bool:
        """After M0/M1/M2/M30: True when the run stops here."""
        k = self.kernel
        if k.ended:
            self.halted = True
            return True
        if k.stopped_at == "M0" and self.m0_stops:
            self.halted = True  # the kernel's stop line says so
            return True
        k.stopped_at = None
        return False

    def runaway(self, line: int):
        self.counter.runaway(self._current_path(), line)

    def no_block(self, number: int, line: int):
        direction = "backward" if number < 0 else "forward"
        raise RuntimeFault("SIN004", f"@100: block N{abs(number)} not found searching {direction}")

    def dynamic_target(self, table: dict, value: float, index: int, line: int) -> int:
        number = _int(value)
        candidates = table.get(abs(number), [])
        if number < 0:
            for i, label in reversed(candidates):
                if i <= index:
                    return label
        else:
            for i, label in candidates:
                if i > index:
                    return label
        self.no_block(number, line)

    def m_function(self, code: str) -> None:
        """``[sin800] m_functions``: the PLC answers an M function by loading R parameters (e.g. M94 -> R60)."""
        self.advance_scenario()
        for reg, source in self.m_functions[code].items():
            n = int(str(reg).upper().lstrip("R"))
            if isinstance(source, str):
                m = _PLC_SOURCE.match(source.strip().upper())
                if m is None:
                    raise Cl800Error(f"{code}: cannot read PLC data '{source}' (write DB<n>.DW<m> or PLC<k>.DB<n>.DW<m>)")
                value = float(self.plc.data_word(float(m.group(1) or 1), float(m.group(2)), float(m.group(3))))
                self.kernel.canon.frozen(f"the PLC's answer to {code}: R{n} = {value:g} from {source}, the "
                                         "simulated PLC's ([sin800.plc])", None)
            else:
                value = float(source)
            self.load_r(n, value)

    def debug_block(self, line: int) -> None:
        """Debug builds: the step hook sees each block before it runs, with the R parameters set."""
        R = self.R
        self.counter.hook(self._current_path(), line, {f"R{n}": v for n, v in enumerate(R) if v != 0.0})

    def fault(self, code: str, message: str, line: int):
        raise RuntimeFault(code, message)

    def refuse_axis(self, refusal: tuple[str, str], line: int, column: int | None = None):
        """A word for an axis the machine lacks (NC011) or an address ncvm reads not (NC007), as (code, message):
        refused after the blocks decoded before it ran, at the word, where ``ncvm check`` shows it."""
        self.run_buffer()
        raise RuntimeFault(*refusal, Span(self._current_path(), line, column))

    # -- main groups 0 and 2 ---------------------------------------------
    def ess(self) -> None:
        self.ess_enabled = True

    def push(self, regs: tuple[int, ...], line: int) -> None:
        R = self.R
        self.push_stack.append((regs, [R[n] for n in regs]))
        for n in regs:
            R[n] = 0.0
        self.central.check()

    def pop(self, regs: tuple[int, ...], line: int) -> None:
        if not self.push_stack:
            raise RuntimeFault("SIN006", "pop (@042/@043) with an empty push stack")
        saved, values = self.push_stack.pop()
        if saved != regs:
            def names(r):
                return " ".join(f"R{n}" for n in r) or "no R parameters"

            raise RuntimeFault("SIN006", f"pop of {names(regs)} does not match the last push of {names(saved)}")
        for n, v in zip(regs, values):
            self.R[n] = v
        self.central.check()

    def xchg(self, a: int, b: int) -> None:
        R = self.R
        R[a], R[b] = R[b], R[a]
        self.central.check()

    def bit(self, pattern: float, k: int) -> float:
        if not 0 <= k <= 7:
            raise Cl800Error(f"bit number {k} is not 0-7")
        return float((pattern_to_int(pattern) >> k) & 1)

    def set_bit(self, pattern: float, k: int, value: int) -> float:
        if not 0 <= k <= 7:
            raise Cl800Error(f"bit number {k} is not 0-7")
        bits = pattern_to_int(pattern)
        bits = bits | (1 << k) if value else bits & ~(1 << k)
        return int_to_pattern(bits)

    def pattern_op(self, op: str, a: float, b: float) -> float:
        x, y = pattern_to_int(a), pattern_to_int(b)
        r = {"OR": x | y, "XOR": x ^ y, "AND": x & y, "NAND": ~(x & y), "NOT": ~x}[op]
        return int_to_pattern(r & 0xFF)

    def _mib_index(self, v: float) -> int:
        n = _int(v)
        top = MIB_TOP[self.data.control]
        if not 0 <= n <= top:
            raise Cl800Error(f"MIB address {n} outside 0-{top}")
        return n

    def mib_clear(self, a: float, b: float) -> None:
        lo, hi = self._mib_index(a), self._mib_index(b)
        for i in range(lo, hi + 1):
            self.data.mib[i] = 0.0
        self.data.changed("mib")

    def mib_read(self, a: float) -> float:
        return self.data.mib[self._mib_index(a)]

    def mib_write(self, a: float, v: float) -> None:
        self.data.mib[self._mib_index(a)] = v
        self.data.changed("mib")

    # -- main group 6 helpers --------------------------------------------
    def tan(self, x: float) -> float:
        """TAN takes 0 to +/-89.999999, +/-90.00001 to 269.9999 and +/-270.0001 to +/-360 degrees (L3821):
        near the poles the result would leave the R range."""
        a = abs(x)
        if a > 360.0 or 89.999999 < a < 90.00001 or 269.9999 < a < 270.0001:
            raise Cl800Error(f"TAN({x:.10g}) is not defined: the angle must lie in 0 to +/-89.999999, +/-90.00001 "
                             "to 269.9999 or +/-270.0001 to +/-360 degrees")
        return math.sin(x * DEG) / math.cos(x * DEG)

    def sqrt(self, x: float) -> float:
        if x < 0.0:
            raise Cl800Error(f"SQRT({x:g}): no square root of a negative number")
        return math.sqrt(x)

    def arc_sin(self, x: float) -> float:
        if not -1.0 <= x <= 1.0:
            raise Cl800Error(f"ARC SIN({x:g}): the sine must lie between -1 and 1")
        return math.asin(x) / DEG

    def ln(self, x: float) -> float:
        if x <= 0.0:
            raise Cl800Error(f"LN({x:g}): no logarithm of zero or a negative number")
        return math.log(x)

    def inv_ln(self, x: float) -> float:
        if x <= 709.0:  # e**709.8 is the largest double
            value = math.exp(x)
            if value <= R_LIMIT:
                return value
        raise Cl800Error(f"INV LN({x:g}): the result is outside the R parameter range +/-99999999 (L7079)")

    def angle(self, a: float, b: float) -> float:
        d = math.degrees(math.atan2(a, b))
        return d + 360.0 if d < 0.0 else d

    # -- external inputs and the scenario --------------------------------
    def advance_scenario(self, where: Src | None = None) -> None:
        """Scripted events and PLC timers running out, in time order, up to the current simulated time;
        ``where``: the statement that reads them (None: they are marked at the block they lead to)."""
        now = self.session.machine.clock.now
        expire = self.plc_clock.expire
        for ev in self.scenario.due(now):
            expire(ev.time)
            self._apply_event(ev)
            self.kernel.canon.frozen(f"scenario event at {ev.time:g} s: {ev.said()}", where)
        expire(now)

    def _apply_event(self, ev) -> None:
        kind = ev.__class__
        if kind is ExternalInput:
            if ev.value:
                self.data.inputs[ev.byte] |= 1 << ev.bit
            else:
                self.data.inputs[ev.byte] &= ~(1 << ev.bit)
        elif kind is PlcChange:
            self.plc.set_event(ev)
        elif kind is PlcTimer or kind is PlcCounter:
            self.plc_clock.act(*self.plc_clock.parse_event(ev), ev.time)
        elif kind is Alarm:
            self.data.alarms.append((ev.number, self.data.channel))
        elif kind is ProbeSwitch:
            self.probe.probes.append(ev)

    def ext_input(self, byte: float, bit: float, line: int | None = None, column: int | None = None) -> bool:
        """External input ``byte``.``bit``; ``line``, ``column``: the @ code whose decision reads it (IF INT,
        WHILE INT), named by a translation's FROZEN mark (None: the block it leads to)."""
        b, k = _int(byte), _int(bit)
        if b not in (1, 2) or not 0 <= k <= 7:
            raise Cl800Error(f"external input {b}.{k} does not exist (byte 1/2, bit 0-7)")
        where = None if line is None else self.session.source_place(self.src(line), column)
        self.advance_scenario(where)
        value = bool((self.data.inputs[b] >> k) & 1)
        self.kernel.canon.frozen(f"external input {b}.{k} read as {int(value)}", where, True)  # True: a scenario says it
        return value

    def wait_input(self, byte: int, bit: int, level: bool, what: str) -> None:
        """Simulated time runs on until the scripted input reaches ``level``."""
        clock = self.session.machine.clock
        while self.ext_input(byte, bit) != level:
            if not self.scenario:
                raise RuntimeFault("SIN007", f"{what}: input {byte}.{bit} never becomes {int(level)} "
                                             f"(no further scenario event)")
            clock.advance(self.scenario.next_time() - clock.now)
