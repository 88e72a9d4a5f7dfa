"""ADDI-DATA rw_SymPas: stand-alone programs (SAP) for the APCI-8001/8008 card, in 4 CNC tasks.

check: lexer -> parser -> checker (compile errors with the manual's numbers).
run: each program compiles to Python generator functions (codegen), loaded
into its task ({$TASK n}) on the simulated card, which runs the tasks on one
deterministic 64 us clock and sends the path through the canon interface.
"""

from __future__ import annotations

import re
from pathlib import Path

from ...diagnostics import CompileFailed, Diagnostic, Span, UsageError
from ...nc.canon import Src
from ...source import read_text
from ..base import Dialect
from . import qualifiers
from .card import Card
from .checker import Checker
from .codegen import CodeGen
from .commands import COMMANDS, fast_line
from .errors import SympasError
from .lexer import Lexer
from .motion import TICKS_PER_S
from .options import sympas_config
from .parser import Parser
from .scheduler import QUIET_S
from .values import namespace

#: the card's commands and qualifiers in the generated code's globals (codegen: _C_<name>(card, tk, items, loc))
_CARD_CALLS = {"_C_" + name: fn for name, fn in COMMANDS.items()} | {
    "_fast_line": fast_line, "_get_qual": qualifiers.get_qual, "_set_qual": qualifiers.set_qual,
    "_get_bit": qualifiers.get_bit, "_set_bit": qualifiers.set_bit}
_SNIFF = re.compile(r"\b(begin|end\.|procedure|writeln|MLAW?|MLRW?|JAW?|STARTCNCT|\{\$TASK)\b", re.I)


class Unit:
    """One compiled program: its Python code and the map back to the source."""

    def __init__(self, prog, checker, src, pyname: str, locs):
        self.prog = prog
        self.checker = checker
        self.src = src
        self.pyname = pyname
        self.locs = locs
        self.code = src.compile()
        self.task = prog.task
        self.stepping = False  # compiled with a check point after every statement (STEPCNCT)
        self.srcs = [Src(f, line) for f, line in locs]
        self.shared_writes: frozenset[str] = frozenset()  # the card's registers its statements assign

    def namespace(self, card) -> dict:
        ns = namespace(card)
        ns.update(_CARD_CALLS)
        exec(self.code, ns)
        return ns

    def variables(self, tk) -> dict:
        """The main block's variables by declared name: shared ones from the namespace, the rest from
        the block's locals (kept when it ended, failed, or is still suspended)."""
        local = tk.main_locals
        if local is None and tk.gen is not None and tk.gen.gi_frame is not None:
            local = tk.gen.gi_frame.f_locals
        local = local or {}
        out = {}
        for v in self.checker.globals:
            out[v.name] = tk.ns.get(v.py) if v.in_routine else local.get(v.py, tk.ns.get(v.py))
        return out


def compile_units(path: str, text: str, machine, warnings: list | None = None, stepping: bool = False) -> list[Unit]:
    cfg = sympas_config(machine)

    def warn(code, msg, node):
        if warnings is not None:
            warnings.append(Diagnostic(code, msg, _span(node), severity="warning"))

    def finder(name):
        p = machine.find_program(name)
        return p

    toks = Lexer(finder, warn).tokens(path, text)
    progs = Parser(toks, warn).programs()
    checkers = []
    for prog in progs:
        chk = Checker(cfg.axis_names, warn)
        chk.program(prog)
        checkers.append(chk)
    stepping = stepping or any(chk.steps_tasks for chk in checkers)
    units = []
    for k, (prog, chk) in enumerate(zip(progs, checkers)):
        pyname = f"<sympas:{path}#{k}>"
        gen = CodeGen(pyname, chk, prog, stepping)
        src = gen.generate()
        unit = Unit(prog, chk, src, pyname, gen.locs)
        unit.shared_writes = frozenset(gen.shared_writes)
        unit.stepping = stepping
        units.append(unit)
    return units


def _span(node):
    return Span(node.file, node.line, node.col)


#: the frame of each figure of the result: the position as the program reads it (dp, with the zero
#: offsets in force at the end), the program's bounds each move with the zero offsets it ran with, the
#: toolpath and the limits as the machine's axes move
FRAMES = {"position": "program", "bounds_program": "program", "motion.bounds": "machine",
          "motion.bounds_program": "program", "limit_violations": "machine"}


class SympasDialect(Dialect):
    id = "sympas"

    def sniff(self, text: str) -> int:
        hits = len(_SNIFF.findall(text[:20000]))
        return min(100, hits * 15)

    def check(self, path, text, machine, all_errors=False):
        warnings: list[Diagnostic] = []
        try:
            compile_units(path, text, machine, warnings)
        except SympasError as e:
            return warnings + [e.diagnostic()]
        return warnings

    def run(self, path, text, session):
        try:
            cfg = sympas_config(session.machine)
            # the program's axis names (A1 ...) in the result, a compile error's too: positions, bounds, limits
            session.axis_labels = {m: p for m, p in zip(session.machine.axis_names, cfg.axis_names) if m != p}
            texts = [(path, text)]
            for extra in cfg.load:
                p = session.machine.find_program(extra) or Path(path).parent / extra
                if not p.is_file():
                    raise UsageError(f"sympas.load: program '{extra}' not found")
                texts.append((str(p), read_text(p)))
            units = [u for f, t in texts for u in compile_units(f, t, session.machine)]
            if any(u.stepping for u in units) and not all(u.stepping for u in units):
                # STEPCNCT in one file: every task may be stepped, so all get a check point per line
                units = [u for f, t in texts for u in compile_units(f, t, session.machine, stepping=True)]
        except SympasError as e:
            raise CompileFailed([e.diagnostic()]) from None
        card = Card(session, cfg)
        session.controller = card
        tasks = card.scheduler.tasks
        main = units[0]
        for u in units:
            n = u.task if u.task is not None else 0
            if tasks[n].unit is not None:
                raise CompileFailed([Diagnostic("SP010", f"two programs are loaded into task {n}",
                                                _span(u.prog))])
            tasks[n].load(u)
            for loc in u.locs[1:]:  # an included file two tasks share counts for the lower-numbered one
                if card.task_at.get(loc, n) >= n:
                    card.task_at[loc] = n
        main_task = tasks[main.task if main.task is not None else 0]
        main_task.start(0.0)
        card.scheduler.main = main_task
        try:
            card.scheduler.run()
        finally:
            session.steps.steps += card.scheduler.steps
            card.scheduler.steps = 0
            end = card.finish()
            if card.recordings:
                session.extra["recordings"] = {card.names[ax]: rec.to_json(card.names[ax])
                                               for ax, rec in sorted(card.recordings.items())}
            session.machine.clock.now = end / TICKS_PER_S
            if card.scheduler.left_running:
                session.extra.setdefault("ended", "ended with task(s) " + ", ".join(
                    str(t.number) for t in card.scheduler.left_running) + " still looping")
            for tk in card.scheduler.left_running:
                where = tk.where()
                place = f" at {where[0]}:{where[1]}" if where else ""
                card.say(f"task {tk.number} still running{place} when the run ended: task {main_task.number} "
                         f"has ended and nothing moved for {QUIET_S:g} s (docs/sympas.md)", tk.number)
            for tk in tasks:
                if tk.line and not tk.tskinfo & 2:
                    card.say(tk.line, tk.number)  # an unterminated WRITE string is still shown
                    tk.tskinfo |= 2
            session.extra["sympas"] = summary = card.summary()  # after the last line is said
            session.extra["frames"] = FRAMES
            session.extra["bounds_program"] = {name: a["bounds_program"] for name, a in summary["axes"].items()
                                               if a["bounds_program"] is not None}
            if main_task.ns is not None:
                session.variables = main.variables(main_task)
            pos = [a.m for a in card.axes]
            session.kernel.place(pos, [m - card.user_shift(a) for m, a in zip(pos, card.axes)])


DIALECT = SympasDialect()
