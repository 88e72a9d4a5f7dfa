"""Linking, as the control does it before a program may start (manual §2.3).

For the program and every sub-program it reaches: syntax, structure pairing (IF/ELSE/ENDIF,
CASE/LABEL/OTHERWISE/ENDCASE, FOR/NEXT, WHILE/END, REPEAT/UNTIL), jump targets, sub-program existence,
no recursion. The result of a program (its "link table") is cached by content, so an unchanged program
is not linked again.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

from ...diagnostics import Diagnostic
from ...machine.files import find_in
from ...machine.model import Machine
from ...records import Record
from ...source import read_text
from . import ast as A
from .errors import diag
from .options import options
from .parser import parse_program

MAX_CASE_NESTING = 10
#: sub-program levels below the main program (manual §2.1 L325: "CPL permits a maximum 7-fold nesting depth")
MAX_SUB_NESTING = 7
SUB_EXTENSIONS = (".cpl", ".CPL")  # names are case-sensitive (§6.1.1); the extension is ncvm's, in either case


def find_din_program(machine: Machine, name: str, private: tuple[Path, ...] = ()) -> Path | None:
    """A ``CALL name DIN`` sub-program: along the program path, then in the file root. On the control the
    programs and the files a program writes are one file memory (§6.1), so a program may write an NC
    program with OPENW/PRN# and call it (L1097, L4003)."""
    found = machine.find_program(name, SUB_EXTENSIONS, ignore_case=False, private=private)
    if found is None:
        found = find_in([machine.file_root], [name, *(name + ext for ext in SUB_EXTENSIONS)], False,
                        private + machine.own_files())
    return found


def where_looked(machine: Machine) -> str:
    """The folders a CALL looks in, for its CPL005."""
    return f"program path: {', '.join(str(p) for p in machine.program_path)}; file root: {machine.file_root}"

#: how often a program was really linked (tests check that unchanged programs are taken from the cache)
LINK_STATS = {"linked": 0}


class Linked(Record):
    """A linked program: statements, structure pairs, resolved jumps, called programs."""

    __slots__ = ("prog", "key", "pair", "jumps", "calls", "fields", "uses_goto", "modal_calls", "diagnostics", "unit",
                 "prog_fors")

    def __init__(self, prog: A.Program, key: str, pair: dict | None = None, jumps: dict | None = None,
                 calls: list | None = None, fields: dict | None = None, uses_goto: bool = False,
                 modal_calls: bool = False, diagnostics: list | None = None, unit: object = None,
                 prog_fors: dict | None = None):
        self.prog = prog
        self.key = key
        self.pair = {} if pair is None else pair  # stmt index -> dict of partner indices
        self.jumps = {} if jumps is None else jumps  # Goto stmt index -> target stmt index
        self.calls = [] if calls is None else calls  # (program name as written, din flag, stmt)
        self.fields = {} if fields is None else fields  # local VarName -> dims count, for every DIMed local
        self.uses_goto = uses_goto
        self.modal_calls = modal_calls  # the machine maps some address to a modal sub-program
        self.diagnostics = [] if diagnostics is None else diagnostics
        self.unit = unit  # the generated code (set by codegen, cached with the link table)
        self.prog_fors = {} if prog_fors is None else prog_fors  # stmt index -> the FOR loops open there (_pair)


_CACHE: dict[str, Linked] = {}


#: manual §3.1 L1071-1074: "the programs for the drilling cycles (99999081 through 99999086) are permanently
#: assigned to the functions G81 through G86"; drilling cycles stay active until G80 (modal, §3.2)
DRILLING_CYCLES = {f"G8{i}": (f"9999908{i}", True) for i in range(1, 7)}


def call_table(machine: Machine) -> dict:
    """[cpl] calls: address -> program, with the modal flag (e.g. G81 = {program = "CYC81", modal = true}),
    over the drilling cycles every control has (an entry of the machine file replaces one of them)."""
    out = dict(DRILLING_CYCLES)
    for key, val in options(machine).calls.items():
        if isinstance(val, str):
            out[key.upper()] = (val, False)
        else:
            out[key.upper()] = (str(val["program"]), bool(val.get("modal", False)))
    return out


def link_one(path: str, text: str, calls: dict, tables=None) -> Linked:
    """The link table of one program: from this process's cache, from ``tables`` (the ``.I`` files kept
    from earlier runs, linktables.py) or made now."""
    key = hashlib.sha256(("\0".join([path, repr(sorted(calls.items())), text])).encode("latin-1", "replace"))
    key = key.hexdigest()
    hit = _CACHE.get(key) or (tables.load(path, key) if tables is not None else None)
    if hit is not None:
        _CACHE[key] = hit
        return hit
    LINK_STATS["linked"] += 1
    prog = parse_program(path, text, calls)
    ln = Linked(prog, key, modal_calls=any(modal for _, modal in calls.values()))
    ln.diagnostics.extend(prog.diagnostics)
    if not prog.diagnostics:
        _pair(ln)
        _jumps(ln)
        _collect(ln)
    _CACHE[key] = ln
    return ln


def _err(ln: Linked, code: str, detail: str, s: A.Stmt) -> None:
    ln.diagnostics.append(diag(code, detail, ln.prog.path, s.line, s.col or None, s.cpl))


#: the statement that ends a WHILE or REPEAT loop: (its opener, the error without one, its key in ln.pair)
_LOOP_ENDS = {A.WEnd: (A.While, "END without WHILE", "while"), A.Until: (A.Repeat, "UNTIL without REPEAT", "repeat")}


def _pair(ln: Linked) -> None:
    stmts = ln.prog.stmts
    stack: list[int] = []
    fors: list[int] = []
    ln.prog_fors = {}
    case_depth = 0
    for i, s in enumerate(stmts):
        ln.prog_fors[i] = tuple(fors)
        t = type(s)
        top = stmts[stack[-1]] if stack else None
        if t is A.If:
            stack.append(i)
            ln.pair[i] = {"else": None, "end": None}
        elif t is A.Else:
            if not isinstance(top, A.If) or ln.pair[stack[-1]]["else"] is not None:
                _err(ln, "CPL004", "ELSE without IF ... THEN", s)
                continue
            ln.pair[stack[-1]]["else"] = i
            ln.pair[i] = {"if": stack[-1]}
        elif t is A.EndIf:
            if not isinstance(top, A.If):
                _err(ln, "CPL004", "ENDIF without IF", s)
                continue
            j = stack.pop()
            ln.pair[j]["end"] = i
            e = ln.pair[j]["else"]
            if e is not None:
                ln.pair[e]["end"] = i
        elif t is A.Case:
            case_depth += 1
            if case_depth > MAX_CASE_NESTING:
                _err(ln, "CPL008", f"CASE nesting {case_depth}", s)
            stack.append(i)
            ln.pair[i] = {"arms": [], "otherwise": None, "end": None, "seen": set()}
        elif t is A.CaseLabel or t is A.Otherwise:
            if not isinstance(top, A.Case):
                _err(ln, "CPL004", f"{'LABEL' if t is A.CaseLabel else 'OTHERWISE'} outside CASE ... ENDCASE", s)
                continue
            info = ln.pair[stack[-1]]
            if info["otherwise"] is not None:
                _err(ln, "CPL004", "OTHERWISE must be the last arm of CASE", s)
                continue
            if t is A.CaseLabel:
                for v in s.values:
                    if v in info["seen"]:
                        _err(ln, "CPL011", f"LABEL {v} twice", s)
                    info["seen"].add(v)
                info["arms"].append(i)
            else:
                info["otherwise"] = i
            ln.pair[i] = {"case": stack[-1]}
        elif t is A.EndCase:
            if not isinstance(top, A.Case):
                _err(ln, "CPL004", "ENDCASE without CASE", s)
                continue
            j = stack.pop()
            case_depth -= 1
            ln.pair[j]["end"] = i
            for arm in ln.pair[j]["arms"] + ([ln.pair[j]["otherwise"]] if ln.pair[j]["otherwise"] else []):
                ln.pair[arm]["end"] = i
            first = min(ln.pair[j]["arms"] + [ln.pair[j]["otherwise"] or i])
            for k in range(j + 1, first):
                if not isinstance(stmts[k], A.LabelDef):
                    _err(ln, "CPL004", "statement between CASE ... OF and the first LABEL", stmts[k])
                    break
        elif t is A.For:
            stack.append(i)
            fors.append(i)
            ln.pair[i] = {"end": None}
        elif t is A.Next:
            if not isinstance(top, A.For):
                _err(ln, "CPL004", "NEXT without FOR", s)
                continue
            if s.var is not None and s.var.var != top.var.var:
                _err(ln, "CPL004", f"NEXT {s.var.var.display} does not match FOR {top.var.var.display}", s)
            j = stack.pop()
            fors.pop()
            ln.pair[j]["end"] = i
            ln.pair[i] = {"for": j}
        elif t is A.While or t is A.Repeat:
            stack.append(i)
            ln.pair[i] = {"end": None}
        elif t in _LOOP_ENDS:
            opener, without, key = _LOOP_ENDS[t]
            if not isinstance(top, opener):
                _err(ln, "CPL004", without, s)
                continue
            j = stack.pop()
            ln.pair[j]["end"] = i
            ln.pair[i] = {key: j}
    ln.prog_fors[len(stmts)] = tuple(fors)
    closers = {A.If: "ENDIF", A.Case: "ENDCASE", A.For: "NEXT", A.While: "END", A.Repeat: "UNTIL"}
    for j in stack:
        s = stmts[j]
        _err(ln, "CPL004", f"{type(s).__name__.upper()} without {closers[type(s)]}", s)


def _jumps(ln: Linked) -> None:
    prog = ln.prog
    for i, s in enumerate(prog.stmts):
        if not isinstance(s, A.Goto):
            continue
        ln.uses_goto = True
        table, shown = {"line": (prog.lines, str(s.target)), "n": (prog.nblocks, f"N{s.target}"),
                        "label": (prog.labels, f".{s.target}")}[s.kind]
        where = table.get(s.target, [])
        if not where:
            _err(ln, "CPL002", f"GOTO {shown}", s)
            continue
        if len(where) > 1:
            _err(ln, "CPL003", f"GOTO {shown}: {len(where)} blocks carry it", s)
            continue
        t = where[0]
        inner = set(ln.prog_fors.get(t, ())) - set(ln.prog_fors.get(i, ()))
        if inner:
            _err(ln, "CPL010", f"GOTO {shown}", s)
            continue
        ln.jumps[i] = t


def _collect(ln: Linked) -> None:
    for s in ln.prog.stmts:
        if isinstance(s, A.CallStmt):
            ln.calls.append((s.name, s.din, s))
        elif isinstance(s, A.NcBlock) and s.call is not None:
            ln.calls.append((s.call[0], False, s))
        elif isinstance(s, A.Dim):
            for var, sizes in s.items:
                if var.cls == "L":
                    ln.fields[var] = len(sizes)


class LinkResult(Record):
    __slots__ = ("main", "units", "resolve", "diagnostics")

    def __init__(self, main: Linked, units: dict, resolve: dict, diagnostics: list):
        self.main = main
        self.units = units  # resolved path -> Linked
        self.resolve = resolve  # (caller path, name as written) -> resolved path; a CALL ... DIN is found when it runs
        self.diagnostics = diagnostics


def link(path: str, text: str, machine: Machine, tables=None) -> LinkResult:
    """Link ``path`` and every sub-program it reaches; diagnostics for everything that is wrong. ``tables``:
    the link tables kept from earlier runs (linktables.py), if any."""
    calls = call_table(machine)
    main = link_one(path, text, calls, tables)
    units = {path: main}
    resolve: dict = {}
    diags: list[Diagnostic] = list(main.diagnostics)

    def visit(ln: Linked, chain: list[str]) -> None:
        for name, din, s in ln.calls:
            if din:  # excluded from linking (§3.3 L1097): found when it is called, so a program may write it first
                continue
            found = machine.find_program(name, SUB_EXTENSIONS, ignore_case=False)
            if found is None:
                diags.append(diag("CPL005", f"{name} (program path: "
                                  f"{', '.join(str(p) for p in machine.program_path)})",
                                  ln.prog.path, s.line, s.col or None, s.cpl))
                continue
            sub_path = str(found)
            resolve[(ln.prog.path, name)] = sub_path
            if sub_path in chain or Path(sub_path).resolve() == Path(ln.prog.path).resolve():
                diags.append(diag("CPL006", f"{name} calls itself (via {' -> '.join(Path(c).name for c in chain)})",
                                  ln.prog.path, s.line, s.col or None, s.cpl))
                continue
            if sub_path in units:
                continue
            try:
                sub_text = read_text(sub_path)
            except OSError as e:
                diags.append(diag("CPL005", f"{name}: {e.strerror}", ln.prog.path, s.line, s.col or None, s.cpl))
                continue
            sub = link_one(sub_path, sub_text, calls, tables)
            if sub.prog.din_only:
                continue  # excluded from linking by "(DIN)" in its first line (manual §3.3)
            units[sub_path] = sub
            diags.extend(sub.diagnostics)
            visit(sub, chain + [sub_path])

    visit(main, [path])
    diags.extend(_too_deep(main, units, resolve))
    return LinkResult(main, units, resolve, diags)


def _too_deep(main: Linked, units: dict, resolve: dict) -> list[Diagnostic]:
    """CPL007 at the call that opens an 8th sub-program level (manual §2.1 L325: at most 7-fold nesting),
    found in the linked call chains before anything runs; a CALL ... DIN and what it reaches are not linked,
    so only the run finds a level they add."""
    longest: dict[str, tuple[int, tuple]] = {}  # path -> (levels below it, ((caller, call, callee name), ...))

    def below(ln: Linked) -> tuple[int, tuple]:
        path = ln.prog.path
        if path not in longest:
            longest[path] = (0, ())  # the call graph has no cycle here (CPL006 was reported otherwise)
            best = (0, ())
            for name, din, s in ln.calls:
                sub = units.get(resolve.get((path, name))) if not din else None
                if sub is not None:
                    depth, chain = below(sub)
                    if depth + 1 > best[0]:
                        best = (depth + 1, ((ln, s, name),) + chain)
            longest[path] = best
        return longest[path]

    depth, chain = below(main)
    if depth <= MAX_SUB_NESTING:
        return []
    caller, s, name = chain[MAX_SUB_NESTING]
    via = " -> ".join(Path(c.prog.path).name for c, _s, _n in chain[:MAX_SUB_NESTING + 1])
    return [diag("CPL007", f"the call of {name} would be level {MAX_SUB_NESTING + 1} (via {via})",
                 caller.prog.path, s.line, s.col or None, s.cpl)]
