"""Running linked CPL programs: call frames, globals, permanents, the motion queue, WAIT, faults.

Block preparation runs ahead of block execution (manual §4.1): CPL statements run at once,
NC blocks go into a motion queue that the NC kernel executes in simulated time only when a WAIT, the
program end or the look-ahead depth drains it. Functions such as MPOS therefore see the executed
position, stale without a WAIT, exactly as the manual's WAIT example says. The depth is ``[cpl]
lookahead`` blocks; without it the queue is the block buffer of BLOCK_BUFFER blocks, whose older half is
executed at once (column-wise) when it is full, so no program can queue without bound.

The program has its own time (``t_prep``): a WAIT(,ms) or a WAIT for an input moves it on, and execution
runs up to it. The kernel executes whole blocks, so the block under way at that time has been executed to
its end; the executed-state readers (MPOS, WPOS, CLOCK, IC, MCODS ...) see the machine at the program's
time all the same: ``executed_position`` interpolates the axes along that block's move (nc.midmove).
"""

from __future__ import annotations

import functools
import itertools
import math
import re
from pathlib import Path

from ...diagnostics import CompileFailed, Frame, RuntimeFault, Span
from ...machine.eventqueue import EventQueue, of_type, refuse
from ...nc import blockskip, cutter
from ...nc.block import Block, DinSyntaxError, as_block, columnar, parse_din_line, plain_row
from ...nc.canon import NOBODY, CanonSink, Src
from ...nc.midmove import MotionRecorder, position_at
from ...nc.plainrun import execute_segments, plain_segments
from ...nc.profiles.typ3osa import TYP3OSA
from ...runtime.buffer import BlockBuffer
from ...runtime.locate import generated_frames, running_line
from ...runtime.memory import out_of_memory
from . import values as V
from .axiswords import check_words, refused_blocks, refusing
from .builtins import FUNCTIONS
from .checker import check
from .codegen import HELPER_NAMES, generate
from .errors import CplError, fault, message, nul_used
from .io import strings as S
from .io.context import CplIO
from .io.errors import CplRuntimeError
from .io.values import CplText, Double
from .linker import MAX_SUB_NESTING, LinkResult, call_table, find_din_program, where_looked
from .options import options
from .perm import DeclError, Permanents
from .pyfaults import program_error
from .system import SYSTEM_PROCS
from .system import setup as system_setup
from .system.controller import load_controller
from .system.gfuncs import Typ3Block, activate, prepare
from .system.ncs import ControlReset
from .system.plc import f_ic
from .system.positions import MEASURING_G, check_probe_events, probe_block
from .unlinked import link_late, run_unlinked

_EXTENDED = re.compile(r"\s*([A-Za-z][A-Za-z0-9_]*[0-9_][A-Za-z0-9_]*)\s*=\s*([-+]?(?:\d+\.?\d*|\.\d+))\s*$")
#: blocks prepared ahead of execution without ``[cpl] lookahead`` (the manual gives no size; docs/decisions.md)
BLOCK_BUFFER = 20_000
#: the path control's G codes (nc.kernel.ISO_PATH_CODES): G61 exact stop, G62 continuous path (the
#: power-on state), one group of the SD(1) table (L2302); G60 is the contour shift here (docs/decisions.md)
CPL_PATH_CODES = {61: "exact", 62: "continuous"}


class ProgramClock:
    """The simulated clock as the program reads it: at the program's time (CplRuntime.t_prep), which may
    lie inside a block the kernel has already executed to its end."""

    def __init__(self, rt):
        self._rt = rt
        self.start_epoch = rt.machine.clock.start_epoch

    @property
    def now(self) -> float:
        return self._rt.t_prep


class KeptMessage(CanonSink):
    """The controller keeps the last executed MSG text (MCODS 28)."""

    def __init__(self, ctl):
        self.ctl = ctl

    def message(self, text: str, src: Src) -> None:
        self.ctl.message = text


class EndProgram(Exception):
    """M2/M30 reached: the program (or sub-program) ends here."""


class CplRuntime:
    def __init__(self, session, linked: LinkResult):
        self.session = session
        self.machine = session.machine
        self.kernel = session.kernel
        self.kernel.use_profile(TYP3OSA)  # the Bosch Typ3 osa G table (nc/profiles/typ3osa.py)
        # G41/G42 take the radius from the D numbers / TC selection (manual's G41/G42): not read yet, refused
        self.kernel.cutter_radius = cutter.refusal("the tool radius of the CPL control's D number / TC selection")
        self.kernel.path_codes = CPL_PATH_CODES
        self.linked = linked
        self.lookahead = options(self.machine).lookahead
        self.block_skip = bool(self.machine.setting_data.get("block_skip", True))
        self.io = CplIO.for_session(session, typ2=linked.main.prog.typ2)
        self.io.files.clock = ProgramClock(self)  # files the program writes are dated at its time
        session.screen = self.io.screen
        self._pictures = 0
        if session.options.screen_dir is not None:
            self.io.screen.on_wait = self.save_wait_picture
        self.io.screen.on_input = self.frozen
        self.globals: dict = {}
        self.perm = Permanents(session)
        if self.kernel.canon.frozen is not NOBODY:  # a translation marks what earlier runs left behind
            self.perm.on_outside = self.io.files.on_outside = self.frozen
        #: the motion queue: ``lookahead`` blocks, else the block buffer, whose older half executes when
        #: it is full; ``enqueue`` queues an NC block (or a plain row)
        if self.lookahead > 0:
            self.queue = BlockBuffer(self.lookahead, self.execute_queued, execute_many=self.execute_run)
            self.enqueue = self.queue_limited
        else:
            self.queue = BlockBuffer(BLOCK_BUFFER - 1, self.execute_queued, spill=BLOCK_BUFFER - BLOCK_BUFFER // 2,
                                     execute_many=self.execute_run)
            self.enqueue = self.queue.put
        self.row_words: set[str] = set()  # the addresses the plain rows of the units made so far have
        self._shadow = None  # the NC state after every prepared block (see prepared_kernel)
        #: inputs read while blocks wait in the queue: (blocks executed before it, what, where), told to the
        #: canon when execution reaches the block prepared after the read (canon calls keep program order)
        self._frozen_due: list[tuple[int, str, Src | None]] = []
        self._shadow_at = 0
        self.modal = [None]
        self.calls = call_table(self.machine)
        self._modal_busy = False
        self.stack: list[tuple[str, int]] = []  # (path, line of the call) for each active sub-program
        #: the running programs, main first (a call of one of them is recursion, §3 L1067); ERASE answers 3
        #: and FILEACCESS sets bit 16 for them (§6 L4396, L4424)
        self.active: list[str] = [linked.main.prog.path]
        self.io.files.active = self.active
        self.io.files.enter_directory_of(linked.main.prog.path, self.machine.file_root_origin)
        self.hook = session.options.hook
        self._fns: dict = {}
        self._codes: dict = {}
        self._t_follows = False
        self.t_prep = self.machine.clock.now
        #: the block still moving at the program's time: (block, position before it, its recorded motion,
        #: the executed count after it); see executed_position
        self.running = None
        #: the interface-bit changes still to come; IC reads apply those up to the program's time
        self._events = EventQueue(_interface_events(self.machine.scenario))
        self.ctl = load_controller(self.machine, lambda: session.store)  # chapter 4 controller state
        #: the main program's local variables at a fault (generated code fills it in)
        self.fault_locals: dict = {}
        self.sys_procs = {name: row[0] for name, row in SYSTEM_PROCS.items()}
        session.canon.add(KeptMessage(self.ctl))  # the shadow kernel has its own canon
        system_setup(self)
        self._probing = any(getattr(w, "address", None) == "G" and (w.value in MEASURING_G or w.expr is not None)
                            for u in linked.units.values() for st in u.prog.stmts for w in getattr(st, "words", ()))

    # -- units ----------------------------------------------------------------------
    def unit(self, path: str):
        fn = self._fns.get(path)
        if fn is not None:
            return fn
        ln = self.linked.units[path]
        hook = self.hook is not None
        uc = ln.unit if not hook else None
        if uc is None:
            types, diags = check(ln)
            uc, diags = (None, diags) if diags else generate(ln, types, hook)
            if diags:
                raise CompileFailed(diags)
            if not hook:
                ln.unit = uc
        ns: dict = {}
        exec(uc.code, ns)
        fn = ns["make"](self.helpers(path), self.constants(path, uc.consts))
        self._fns[path] = fn
        self._codes[path] = uc
        self.row_words |= uc.row_words
        return fn

    def constants(self, path: str, consts: list) -> list:
        out = []
        for c in consts:
            if c[0] == "src":
                out.append(Src(path, c[1]))
            elif c[0] == "plain row":
                out.append(plain_row(c[1], path))
            else:
                _, g, m, words, n, msg, line = c
                out.append(Block(g, m, dict(words), n, msg, Src(path, line)))
        return out

    def helpers(self, path: str) -> dict:
        h = {
            "_rt": self, "_st": self.session.steps, "_G": self.globals, "_PM": self.perm, "_EP": EndProgram,
            "_f32": V.f32, "_m32": memoryview(bytearray(4)).cast("f"), "_toi": V.to_int, "_tor": V.to_real, "_wtor": V.word_real, "_tod": V.to_double, "_tob": V.to_bool,
            "_tos": V.to_str, "_bad_assign": _bad_assign, "_cond": V.cond, "_logic": V.logic, "_lnot": V.lnot,
            "_ix": V.index, "_sv": V.sv, "_view": S.mid_for_variable, "_setf": _setf, "_midw": _midw, "_dim": _dim,
            "_pdim": _pdim, "_pstr": _pstr, "_gfield": self.gfield, "_gset_s": self.gset_s, "_pint": _pint,
            "_call": functools.partial(self.call, path),
            "_q": self.enqueue_probe if self._probing else self.enqueue,
            "_qr": self.enqueue,  # a plain row (nc.block)
            "_NaN": math.nan,
            "_drain": self.drain, "_wait": self.wait, "_Block": Block, "_loose": self.loose,
            "_word": V.word, "_mval": _mval, "_modal": self.modal,
            "_modal_call": lambda line: self.modal_call(path, line), "_q3": self.enqueue_typ3,
            "_runaway": lambda line: self.session.steps.runaway(path, line),
            "_hook": self._hook_for(path), "_caseval": _caseval, "_nocall": self.nocall,
            "_msin": math.sin, "_mcos": math.cos, "_matan": math.atan, "_msqrt": math.sqrt,
            "_io": self.io, "_Dbl": Double, "_SView": S.StringView, "_nn": V.not_nul,
        }
        for name, b in FUNCTIONS.items():
            h[f"_F_{name.replace('$', '_S')}"] = b.impl
        refused = refused_blocks(self.linked.units[path].prog, self.kernel.axis_of)
        if refused:  # blocks naming an axis the machine lacks (error 1938); other units enqueue unchecked
            for name in ("_q", "_qr", "_q3"):
                h[name] = refusing(self, h[name], refused)
        assert set(h) == set(HELPER_NAMES), set(h) ^ set(HELPER_NAMES)
        return h

    def _hook_for(self, path: str):
        hook = self.hook
        if hook is None:
            return None

        def call(line: int, local_vars: dict) -> None:
            uc = self._codes.get(path)
            shown = {s: V.report(local_vars.get(py)) for py, s in (uc.report if uc else [])
                     if local_vars.get(py) is not None}
            hook(path, line, shown)

        return call

    # -- the run ----------------------------------------------------------------------
    def run_main(self) -> None:
        main = self.linked.main.prog.path
        result: dict = {}
        try:
            try:
                try:
                    if self.linked.main.prog.din_only:  # "(DIN)" in its first line: started without linking (§3.3)
                        run_unlinked(self, main, Path(main).name)
                    else:
                        result = self.unit(main)((), True)
                except ControlReset as reset:  # MCOPS(2) on the own channel: the main program is exited
                    self.session.say(str(reset))
                finally:
                    try:
                        self.session.variables = self.report(result or self.fault_locals)
                    except MemoryError as again:
                        if not isinstance(again.__context__, MemoryError):
                            raise
                        # out of memory already: the run stops at the statement that reached the limit
            except CompileFailed as e:  # a sub-program linked when first called does not compile
                raise self.execute_prepared(e) from None
            except Exception as e:  # noqa: BLE001 - the program stopped: the blocks it prepared still run
                raise self.execute_prepared(self.as_fault(e)) from None
            self.drain()
            self.io.end_program(png=self.session.options.screen)
            self.kernel.end_program(Src(main, max(1, len(self.linked.main.prog.stmts) and
                                                     self.linked.main.prog.stmts[-1].line)))
        except Exception as e:  # noqa: BLE001 - every failure of generated code becomes a RUNTIME ERROR
            self.finish_io_at_fault()
            f = self.as_fault(e)  # ncvm's own errors (and CompileFailed) are raised again here
            if f.span is None:
                f.span = Span(main, 1, 1)
            elif f.span.column is None and f.span.file in self.linked.units:  # an NC block the kernel refused
                f.span = Span(f.span.file, f.span.line, self.first_column(f.span.file, f.span.line))
            raise f from None

    def as_fault(self, e: Exception) -> RuntimeFault:
        """The RUNTIME ERROR that ``e`` is (a declaration error of the permanents included); ncvm's own
        errors are raised again (:meth:`to_fault`)."""
        if isinstance(e, RuntimeFault):
            return e
        if isinstance(e, DeclError):
            return RuntimeFault(e.code, message(e.code, e.message), Span(e.file, max(e.line, 1), 1))
        return self.to_fault(e)

    def execute_prepared(self, stop: Exception) -> Exception:
        """The program stopped with ``stop`` (a RUNTIME ERROR, the step limit): the NC blocks it prepared
        before were already transferred to execution and run to their end, as they do when the program ends
        (docs/decisions.md, "A run that stops keeps the blocks it prepared"). A fault of one of them is
        earlier in the program and is the one reported; else ``stop``. Running out of memory again keeps
        ``stop``."""
        try:
            self.drain()
        except MemoryError:
            return stop
        except Exception as e:  # noqa: BLE001 - a prepared block's own fault, reported in place of ``stop``
            return self.as_fault(e)
        return stop

    def finish_io_at_fault(self) -> None:
        """A run that faults still closes its files (what PRN# wrote stays) and saves --screen."""
        try:
            self.io.files.close_all()
        except Exception:  # noqa: BLE001 - the fault that stopped the run is the one to report
            pass
        if self.session.options.screen is not None:
            self.io.screen.save_png(self.session.options.screen)

    def save_wait_picture(self) -> None:
        """--screen-dir: the screen as the operator sees it when SFK or INP waits (screen_001.png, ...)."""
        self._pictures += 1
        folder = Path(self.session.options.screen_dir)
        folder.mkdir(parents=True, exist_ok=True)
        self.io.screen.save_png(folder / f"screen_{self._pictures:03d}.png")

    def report(self, result: dict) -> dict:
        out = {k: V.report(v) for k, v in result.items() if v is not None}
        for k, v in self.globals.items():
            out[k] = V.report(v)
        out.update(self.perm.report())
        return out

    def to_fault(self, e: BaseException) -> RuntimeFault:
        """The RUNTIME ERROR that stopped the program; any other Python error is ncvm's and is raised again
        (an internal error, never shown as the program's error: pyfaults)."""
        sources = {path: uc.src for path, uc in self._codes.items()}
        if isinstance(e, CplError):
            code, detail = e.code, e.detail
        elif isinstance(e, CplRuntimeError):
            code, detail = e.code, ""
        elif isinstance(e, MemoryError):  # the run's memory limit (runtime.memory), reported where it was reached
            code, detail = "RUN006", ""
        elif isinstance(e, RecursionError):  # CPL006/CPL007 stop the program's own nesting at the CALL
            raise RuntimeError(f"Python's recursion limit was reached inside ncvm ({e})") from e
        else:
            found = program_error(e, sources)
            if found is None:
                raise e
            code, detail = found
        codes = self._codes
        frames = [(g.filename, g.line, codes[g.filename].cpl_lines.get(g.line), g.col)
                  for g in generated_frames(e.__traceback__, sources)]
        text = e.message if isinstance(e, CplRuntimeError) else message(code, detail) if code != "RUN006" \
            else out_of_memory(self.session.options.max_memory).message
        if not frames:
            return RuntimeFault(code, text, None)
        file, line, cpl, col = frames[-1]
        col = getattr(e, "column", None) or col
        f = fault(code, detail, file, line, cpl, text=text, column=col or self.first_column(file, line))
        f.stack = [Frame(Path(p).name, Span(p, ln, c or self.first_column(p, ln))) for p, ln, _, c in frames]
        return f

    def frozen(self, what: str, scenario: bool = False) -> None:
        """The run read ``what`` from outside the program (a key, an input; ``scenario``: a machine input that
        only a scenario says): canon ``frozen`` at the CPL line running now (nothing where no sink listens)."""
        if self.kernel.canon.frozen is NOBODY:
            return
        where = running_line({path: uc.src for path, uc in self._codes.items()})
        self._frozen_at(what, Src(*where) if where else None, scenario)

    def block_skip_read(self, src: Src) -> None:
        """A ``/`` block is met: the block skip switch decides whether it runs (a translation marks it)."""
        if self.kernel.canon.frozen is not NOBODY:
            self._frozen_at(blockskip.decision(self.block_skip), src)

    def _frozen_at(self, what: str, src: Src | None, scenario: bool = False) -> None:
        """Canon ``frozen`` when execution reaches the blocks prepared after now."""
        if self.queue:  # the blocks prepared before the read execute first
            self._frozen_due.append((self.queue.executed + len(self.queue), what, src, scenario))
        else:
            self.kernel.canon.frozen(what, src, scenario)

    def _tell_frozen(self, executed: int) -> None:
        """Tell the canon the inputs read before block number ``executed`` (counted from 0) was prepared."""
        due = self._frozen_due
        while due and due[0][0] <= executed:
            _, what, src, scenario = due.pop(0)
            self.kernel.canon.frozen(what, src, scenario)

    def first_column(self, path: str, line: int) -> int:
        """Where the first statement of a physical line starts (a fault in lines generated for no one statement)."""
        unit = self.linked.units.get(path)
        cols = [s.col for s in unit.prog.stmts if s.line == line and s.col] if unit is not None else []
        return min(cols, default=1)

    # -- sub-programs -----------------------------------------------------------------------
    def call(self, caller: str, name: str, args: tuple, din: bool, line: int) -> None:
        stack, active, units = self.stack, self.active, self.linked.units
        if len(stack) >= MAX_SUB_NESTING:
            raise CplError("CPL007", f"CALL {name}")
        target = self.linked.resolve.get((caller, name))
        if target is None:
            found = find_din_program(self.machine, name, (self.session.options.state_dir,))
            if found is None:
                raise CplError("CPL005", f"{name} ({where_looked(self.machine)})")
            target = str(found)
        if target in active:
            raise CplError("CPL006", name)
        if caller not in units or units[caller].prog.din_only:  # a caller run unlinked
            args = tuple(UnlinkedString(a) if a.__class__ is str else a for a in args)
        stack.append((caller, line))
        active.append(target)
        try:
            if not din and target not in units:
                link_late(self, target)  # reached only through a program excluded from linking
            if target in units and not din:
                (self._fns.get(target) or self.unit(target))(args, False)
            else:
                run_unlinked(self, target, name)  # excluded from linking (manual §3.3)
        except EndProgram:
            pass
        finally:
            stack.pop()
            active.pop()

    def nocall(self, address: str, value):
        """An address that calls a sub-program may not take its value from [ ] (manual §2.1.1 L371)."""
        value = V.word(value)
        key = f"{address}{int(value) if value == int(value) else value}"
        if key in self.calls:
            raise CplError("CPL013", f"{address}[...] gives {key}, which calls {self.calls[key][0]}")
        return value

    def modal_call(self, caller: str, line: int) -> None:
        """After a traversing block: run the modal sub-program again, but not from inside itself."""
        name, args = self.modal[0]
        if self._modal_busy:
            return
        self._modal_busy = True
        try:
            self.call(caller, name, args, False, line)
        finally:
            self._modal_busy = False

    # -- globals ------------------------------------------------------------------------------
    def gfield(self, key: str):
        f = self.globals.get(key)
        if f is None or not isinstance(f, (list, S.CharacterField, S.CharacterTable)):
            raise CplError("CPL035", f"{key} is not DIMensioned")
        return f

    def gset_s(self, key: str, value, chained: bool) -> None:
        cur = self.globals.get(key)
        if isinstance(cur, S.CharacterField):
            _setf(cur, value)
        elif chained:
            raise CplError("CPL025", f"{key} is not DIMensioned")
        elif value is None:
            self.globals.pop(key, None)
        else:
            self.globals[key] = value

    # -- NC blocks and the motion queue ---------------------------------------------------------
    @property
    def executed(self) -> int:
        """Blocks taken from the queue and executed so far."""
        return self.queue.executed

    @property
    def t_prep(self) -> float:
        """The program's own time (s): where block preparation stands in simulated time. After preparation
        waited for execution it is the clock's time, read (and so the waiting moves timed: an exact stop)
        only when something reads it."""
        if self._t_follows:
            self._t_follows = False
            self._t_prep = max(self._t_prep, self.machine.clock.now)
        return self._t_prep

    @t_prep.setter
    def t_prep(self, value: float) -> None:
        self._t_prep, self._t_follows = value, False

    def queue_limited(self, blk) -> None:
        """The look-ahead is full: preparation waits until the oldest block has been executed."""
        if self.queue.put(blk):
            self._t_follows = True

    def enqueue_probe(self, blk) -> None:
        """Measuring blocks (G75, G275, G375) are executed before preparation goes on (manual §4.2, SD(9) L2309)."""
        if MEASURING_G.intersection(blk.g):
            self.drain()  # the kernel stands at the block's start when the probe move is announced
            self.queue.append(probe_block(self, blk))
            self.drain()
        else:
            self.enqueue(blk)

    def enqueue_typ3(self, blk) -> None:
        """A block that may carry a Typ3 G function the kernel does not know (G168, G268, G131, ...)."""
        blk = prepare(self, blk)
        if self._probing:
            self.enqueue_probe(blk)
        else:
            self.enqueue(blk)

    def execute_queued(self, blk) -> None:
        """The queue's "execute one" step: nothing executes after the program end."""
        if self._frozen_due:
            self._tell_frozen(self.queue.executed - 1)
        if not self.kernel.ended:
            self.execute_block(blk)

    def execute_block(self, blk) -> None:
        """Execute one queued block; a Typ3 block also activates the G-function state prepared with it."""
        if blk.__class__ is Typ3Block:
            activate(self, self.kernel, blk)
        else:
            self.kernel.execute(as_block(blk))

    def drain(self) -> None:
        """WAIT without parameters: stop preparation until every block before it has been executed (the axes
        stop: an exact stop)."""
        self.queue.drain()
        if self._frozen_due:
            self._tell_frozen(self.queue.executed)
        self.kernel.planner.stop()

    def execute_run(self, blocks: list) -> None:
        """Execute the oldest queued blocks, taken out together (runs of plain blocks column-wise);
        preparation waits for them."""
        first = self.queue.executed - len(blocks)  # the number of the first of them
        while self._frozen_due and self._frozen_due[0][0] < first + len(blocks):
            k = max(0, self._frozen_due[0][0] - first)  # an input read before block ``k`` of these was prepared
            if k:
                self.execute_blocks(blocks[:k])
            blocks, first = blocks[k:], first + k
            self._tell_frozen(first)
        self.execute_blocks(blocks)
        self._t_follows = True  # preparation waited for these blocks (t_prep)

    def execute_blocks(self, blocks: list) -> None:
        """Execute ``blocks`` in order: a few (a WAIT after every block or two) one by one by the kernel, more
        as runs of plain rows column-wise (the columns cost more to set up than a few blocks take)."""
        segments = plain_segments(blocks, self.row_words) if columnar(len(blocks)) else blocks
        execute_segments(self.kernel, segments, self.execute_block)

    def prepared_kernel(self):
        """The NC state after every *prepared* block: what CPOS and AXO read (manual §4.2.1, values at
        block preparation), while MPOS reads the executed state. A scratch copy of the kernel runs the
        blocks still in the queue, with no canon output and its own clock and PLC image."""
        if self._shadow is None or self._shadow_at < self.executed:
            shadow = self.kernel.fork()
            self._shadow, self._shadow_at = shadow, self.executed
        # the blocks prepared since, taken from the new end of the queue (skipping the older ones would cost
        # the length of the queue at every CPOS)
        pending = len(self.queue) - (self._shadow_at - self.executed)
        for blk in reversed(list(itertools.islice(reversed(self.queue), pending))):
            if blk.__class__ is Typ3Block:
                activate(self, self._shadow, blk)
            else:
                self._shadow.execute(as_block(blk))
            self._shadow_at += 1
        return self._shadow

    def forget_prepared(self) -> None:
        """Offsets or tool tables changed under the prepared blocks: the prepared state is built again."""
        self._shadow = None

    def loose(self, g, m, words, loose, n, msg, src):
        """A block with standalone [A$] words: each value is NC text such as "G1" (manual L2110)."""
        g, m, words = list(g), list(m), dict(words)
        for val in loose:
            val = V.sv(val)
            if val.__class__ is not str:
                if val is None:
                    raise nul_used()
                raise CplError("CPL032", "a standalone [ ] in an NC block must give NC text")
            ext = _EXTENDED.match(val)
            if ext:  # an extended address such as AXP's "X2=10.5" (manual §4.10)
                words[ext.group(1).upper()] = float(ext.group(2))
                continue
            try:
                blk = parse_din_line(val, src)
            except DinSyntaxError as e:
                raise CplError("CPL001", f"NC text {val!r}: {e.message}") from None
            if blk is None:
                continue
            g.extend(blk.g)
            m.extend(blk.m)
            words.update(blk.words)
        check_words(self, g, words)
        return Block(tuple(g), tuple(m), words, n, msg, src)

    # -- the executed state at the program's time ---------------------------------------------
    def moving(self) -> bool:
        """Whether a block is still being executed at the program's time (it ends later)."""
        return self.machine.clock.now > self.t_prep and self.running is not None \
            and self.running[3] == self.executed

    def executed_position(self) -> tuple:
        """The machine position (MCS, per kernel axis) at the program's time: inside the block still moving
        then, the point its move has reached; else where the executed blocks left the axes."""
        if not self.moving():
            return self.kernel.machine_pos
        _, before, moves, _ = self.running
        return position_at(moves, self.kernel.dyn, self.t_prep, before)

    def executing_block(self):
        """The block the channel is executing at the program's time: the one still moving, else the oldest
        one in the motion queue; None when the channel stands idle."""
        blk = self.running[0] if self.moving() else (self.queue[0] if self.queue else None)
        return as_block(blk)

    def execute_next(self) -> bool:
        """The program waits for execution to go on (MCODS with an unchanged version): to the end of the block
        still moving, else through the next queued block. False when nothing is left to execute."""
        clock = self.machine.clock
        if not clock.now > self.t_prep:
            if not self.queue or self.kernel.ended:
                return False
            self.queue.execute_one()
        self.t_prep = max(self.t_prep, clock.now)
        return True

    # -- WAIT with parameters (manual §4.1) ---------------------------------------------------
    def advance(self, t_end: float) -> float:
        """Let execution run until simulated time ``t_end``, then idle: the blocks that start before it are
        executed (whole, by the kernel); the last of them may still be moving at ``t_end`` (see running).
        Returns how long the machine stood idle (every block done) before ``t_end``."""
        clock = self.machine.clock
        queue, kernel = self.queue, self.kernel
        if queue and clock.now < t_end and not kernel.ended:
            with MotionRecorder(kernel.canon, clock) as rec:
                while queue and clock.now < t_end and not kernel.ended:
                    blk, before = queue[0], kernel.machine_pos
                    rec.moves.clear()
                    self.queue.execute_one()
            self.running = (blk, before, list(rec.moves), self.executed)
        idle = 0.0
        if clock.now < t_end:
            idle = t_end - clock.now
            clock.now = t_end
        self.t_prep = t_end
        return idle

    def _stand(self, t_end: float) -> None:
        """WAIT until ``t_end``: the time the machine stands after its blocks is a dwell of the canon at the WAIT
        (a translation writes the target's G4 there: the next block waits for it, e.g. a spindle coming up to
        speed before the plunge)."""
        idle = self.advance(t_end)
        if idle > 1e-9 and self.kernel.canon.dwell is not NOBODY:
            where = running_line({path: uc.src for path, uc in self._codes.items()})
            self.kernel.canon.dwell(idle, Src(*where) if where else None)

    def ic(self, args: tuple) -> bool:
        return f_ic(self, *args)

    def _apply_events(self, t: float) -> None:
        for ev in self._events.due(t):
            self.machine.plc.inputs[ev.address] = ev.value
            self.frozen(f"scenario event at {ev.time:g} s: {ev.said()}")

    def wait(self, ic, neg: bool, state, duration):
        """0: condition met at the call; 1: the duration ran out; 2: the condition became true while waiting."""
        if duration is not None and (duration.__class__ is not int or duration < 0):
            if duration is None:
                raise nul_used()
            raise CplError("CPL023", f"WAIT duration {duration!r}: an INTEGER number of milliseconds")
        start = self.t_prep
        deadline = None if duration is None else start + duration / 1000.0
        if ic is None:
            self._stand(deadline)
            return 1
        if state is None:
            raise nul_used()

        def met() -> bool:
            v = self.ic(ic)
            return (not v if neg else v) == state

        if met():
            return 0
        events = self._events
        while (te := events.next_time()) is not None and (deadline is None or te <= deadline):
            self._stand(max(te, start))  # IC applies the event at its time
            if met():
                return 2
        if deadline is not None:
            self._stand(deadline)
            return 1
        raise CplError("CPL039", "no scenario event sets the input")


def _bad_assign(detail: str):
    raise CplError("CPL021", detail)


def _setf(field, value) -> None:
    if not isinstance(field, S.CharacterField):
        raise CplError("CPL035", "character field used before its DIM")
    if value is not None and not isinstance(value, (str, CplText)):
        raise CplError("CPL021", f"{V.type_name(value)} value assigned to a character field")
    field.assign(value)


def _midw(field, start, count, value) -> None:
    """MID$(field, start[, count]) = value (manual §5.3)."""
    if field is None:
        raise CplError("CPL035", "MID$ target")
    if value is None:
        raise nul_used()
    S.mid_write(field, start, count, value)


def _dim(current, sizes: tuple, kind: str):
    """DIM: a second DIM with the same sizes keeps the field; other sizes are an error (CPL manual §2.4.3, L680-707; §5.1, L3350-3370)."""
    if current is not None and (isinstance(current, (list, S.CharacterField, S.CharacterTable))):
        have = _sizes(current)
        if have == list(sizes):
            return current
        raise CplError("CPL022", f"field already DIMensioned with sizes {have}")
    return V.new_field(list(sizes), kind)


def _sizes(f) -> list[int]:
    if isinstance(f, S.CharacterField):
        return [f.size]
    if isinstance(f, S.CharacterTable):
        return [len(f.rows) - 1, f.rows[0].size]
    if f and isinstance(f[0], list):
        return [len(f) - 1, len(f[0]) - 1]
    return [len(f) - 1]


class UnlinkedString(str):
    """A string constant passed by a program selected without linking ("(DIN)" in its first line): the
    sub-program can take it only through PDIM (manual §3.4 L1149-1159)."""


def _pdim(params: tuple, n: int, size: int) -> tuple:
    """PDIM Pn$(size): the parameter as a string of at most ``size`` characters (the new parameter tuple)."""
    v = params[n - 1] if n <= len(params) else None
    if v is not None and (not isinstance(v, str) or len(v) > size):
        raise CplError("CPL026", f"PDIM P{n}$({size}) for {v!r}")
    if isinstance(v, UnlinkedString):
        return params[:n - 1] + (str(v),) + params[n:]
    return params


def _pstr(v):
    """Pn$: a string parameter; from an unlinked caller it needs PDIM first ("invalid variable")."""
    if isinstance(v, UnlinkedString):
        raise CplError("CPL026", f"string constant {str(v)!r} from a program selected without linking needs PDIM")
    return V.to_str(v)


def _pint(v):
    """Parameter Pn% (CPL manual §3.4, L1122-1179): a whole-numbered REAL passes as INTEGER, other REAL values do not."""
    if v.__class__ is float and v.is_integer():
        return int(v)
    return V.to_int(v)


def _mval(v) -> int:
    if v.__class__ is float and v.is_integer():
        return int(v)
    if v.__class__ is int:
        return v
    raise CplError("CPL032", f"M value {v!r}")


def _caseval(v):
    if v.__class__ is int:
        return v
    if v is None:
        raise nul_used()
    raise CplError("CPL032", f"CASE selector {v!r} is not INTEGER")


def _interface_events(events: list) -> list:
    """The scenario's interface-bit changes, after refusing (by name) every event the CPL control cannot use.
    The event types are imported only for a scenario that has events (start-up, issue 18)."""
    if not events:
        return []
    from ...machine.scenario import FixedStop, InterfaceBit, ProbeSwitch, SercosLock

    refuse(events, (InterfaceBit, ProbeSwitch, FixedStop, SercosLock), "CPL control")
    check_probe_events(events)
    return of_type(events, InterfaceBit)
