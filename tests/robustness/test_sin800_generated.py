"""Generated valid SINUMERIK 800 programs: run-time faults make sense, and CL 800 runs like its object file.

Mutation fuzzing (test_mutations.py) mostly stops at read errors. Here a small
grammar writes programs that read and compile cleanly: hand-written @ code
part programs (R words, @ codes of the table with operands of the right kind,
loops with @13x/@14x/@100, CASE, push/pop, L calls with P passes) and CL 800
sources (declarations, expressions, IF/CASE/WHILE/REPEAT/FOR, system memory
reads and writes). Each is run with a small step limit; a fault must come from
the NC's own checks, never from a Python error caught on the way, and a CL 800
source must give the same result document as its compiled object file.

The regression tests below hold the minimal programs of the bugs the
generator found.
"""

from __future__ import annotations

import random
import shutil
from pathlib import Path

import pytest

import ncvm.api as api
from ncvm.api import compile_program, run
from ncvm.diagnostics import RuntimeFault
from ncvm.dialects.sinumerik.atcodes import AT_CODES
from ncvm.runtime.session import RunOptions

MACHINE = Path(__file__).parent.parent / "programs" / "sin800" / "machine.toml"
#: where a fault may come from: the NC's own checks, the arc geometry, a division by zero in an R word
EXPECTED_ORIGINS = {"Cl800Error", "ArcError", "ZeroDivisionError"}
SAME = ("status", "output", "variables", "position", "motion", "cycle_time_s", "steps", "limit_violations")


# -- hand-written @ code part programs ---------------------------------------------------------------
_JUMPS = {c for c in AT_CODES if c[:2] in ("10", "11", "12", "13", "14", "15", "16", "18", "19")}
_PLAIN = sorted(c for c in AT_CODES if c not in _JUMPS | {"040", "041", "042", "043"})
_R = [0, 1, 2, 3, 10, 11, 20, 50, 51, 60, 70, 90, 91, 98, 99, 100, 299, 700, 900, 950, 998, 999]


class AtCodeProgram:
    """Blocks of R words, DIN words and @ codes; WHILE/REPEAT/IF/CASE jumps, push/pop and L calls."""

    def __init__(self, rnd: random.Random):
        self.rnd = rnd
        self.n = 100

    def const(self) -> str:
        rnd = self.rnd
        v = rnd.choice([0, 1, 2, 3, 4, 5]) if rnd.random() < 0.6 else rnd.choice(
            [7, 10, 100, 255, 1000, 2240, 4999, 5001, -1, -5, 0.5, 2.25, 99999999, round(rnd.uniform(-99, 99), 3)])
        return f"{v:g}"

    def operand(self, kind: str) -> str:
        kind = self.rnd.choice({"V": "RP", "W": "KRP"}.get(kind, kind))
        return "K" + self.const() if kind == "K" else f"{kind}{self.rnd.choice(_R)}"

    def arith(self) -> str:
        rnd = self.rnd
        terms = []
        for i in range(rnd.randint(1, 4)):
            op = rnd.choice(["", "-"] if i == 0 else "+-*/")
            v = f"R{rnd.choice(_R)}" if op != "/" and rnd.random() < 0.5 else self.const().lstrip("-")
            terms.append(op + ("4" if op == "/" and float(v) == 0 else v))
        return f"R{rnd.choice(_R)}=" + "".join(terms)

    def din(self) -> str:
        rnd = self.rnd
        words = [rnd.choice(["G0", "G1", "G90", "G91", "G17", "G54", "G4 X0.1"])]
        for ax in "XYZ":
            if rnd.random() < 0.4:
                words.append(f"{ax}=-R{rnd.choice(_R)}" if rnd.random() < 0.5 else f"{ax}{rnd.uniform(-50, 50):.3f}")
        if rnd.random() < 0.2:
            words.append(rnd.choice(["M3 S1000", "M5", "M8", "T1 D1", "D0", "F=R10", "S=R11", "M0"]))
        return " ".join(words)

    def item(self) -> str:
        r = self.rnd.random()
        if r < 0.45:
            return self.arith()
        if r < 0.6:
            code = self.rnd.choice(_PLAIN)
            return " ".join([f"@{code}"] + [self.operand(k) for k in AT_CODES[code].kinds])
        return self.din()

    def number(self) -> int:
        self.n += 10
        return self.n

    def block(self, lines: list[str], depth: int, subs: list[int]) -> None:
        rnd, r = self.rnd, self.rnd.random()
        if depth < 2 and r < 0.1:  # WHILE: test at the start, @100 back
            a, cnt = self.number(), f"R{rnd.choice([1, 2, 60])}"
            lines.append(f"{cnt}=0")
            at = len(lines)
            lines.append("")
            for _ in range(rnd.randint(1, 3)):
                self.block(lines, depth + 1, subs)
            b = self.number()
            lines[at] = f"N{a} @13{rnd.choice('123456')} {cnt} K{rnd.randint(0, 4)} K{b}"
            lines += [f"@620 {cnt}", f"@100 K-{a}", f"N{b} {self.item()}"]
        elif depth < 2 and r < 0.2:  # REPEAT: test at the end, jump back
            a, cnt = self.number(), f"R{rnd.choice([4, 5, 61])}"
            lines += [f"{cnt}=0", f"N{a} @620 {cnt}"]
            for _ in range(rnd.randint(1, 3)):
                self.block(lines, depth + 1, subs)
            lines.append(f"@14{rnd.choice('1345')} {cnt} K{rnd.randint(1, 4)} K-{a}")
        elif depth < 2 and r < 0.27:  # IF: jump over the branch
            b = self.number()
            lines.append(f"@12{rnd.choice('123456')} R{rnd.choice(_R)} {self.operand('W')} K{b}")
            self.block(lines, depth + 1, subs)
            lines.append(f"N{b} {self.item()}")
        elif depth < 2 and r < 0.32:  # CASE
            targets, end = [self.number() for _ in range(rnd.randint(1, 3))], self.number()
            pairs = " ".join(f"{self.operand('W')} K{t}" for t in targets)
            lines.append(f"@111 R{rnd.choice(_R)} {pairs} @100 K{end}")
            lines += [f"N{t} {self.item()} @100 K{end}" for t in targets]
            lines.append(f"N{end} {self.item()}")
        elif r < 0.38 and subs:
            lines.append(f"L{rnd.choice(subs)}" + (f" P{rnd.randint(1, 3)}" if rnd.random() < 0.5 else ""))
        elif r < 0.46:  # push/pop: a block range or a list
            if rnd.random() < 0.5:
                a = rnd.choice([50, 60, 70, 80])
                regs = f"R{a} R{a + rnd.randint(0, 9)}"
                push, pop = f"@041 {regs}", f"@043 {regs}"
            else:
                rs = sorted(rnd.sample(range(100), rnd.randint(1, 4)))
                regs = f"K{len(rs)} " + " ".join(f"R{x}" for x in rs)
                push, pop = f"@040 {regs}", f"@042 {regs}"
            lines.append(f"{push} {self.item()}")
            self.block(lines, depth + 1, subs)
            lines.append(pop)
        else:
            lines.append(" ".join(self.item() for _ in range(rnd.randint(1, 3))))


def at_code_program(seed: int) -> dict[str, str]:
    """A main program %MPF1 and up to two sub-programs it calls; file name -> text."""
    rnd = random.Random(seed)
    files, subs = {}, []
    for num in range(20, 20 + rnd.randint(0, 2)):
        gen, lines = AtCodeProgram(rnd), []
        for _ in range(rnd.randint(1, 4)):
            gen.block(lines, 1, [])
        files[f"L{num}.spf"] = f"%SPF{num}\n" + "\n".join(lines) + "\nM17\n"
        subs.append(num)
    gen, lines = AtCodeProgram(rnd), ["G90 G0 X0 Y0 Z0 F1000 R1=1 R2=2 R10=1000 R11=500 R91=5"]
    for _ in range(rnd.randint(2, 10)):
        gen.block(lines, 0, subs)
    files["P1.mpf"] = "%MPF1\n" + "\n".join([*lines, "M30"]) + "\n"
    return files


# -- CL 800 sources -------------------------------------------------------------------------------------
_HEADER = """PROGRAM {num};
CHANNEL NC 0;
PAR REAL: R1, R2:=depth, R3;
PAR INTEGER: R6, R7:=count;
PAR REAL: R10, R11, R12, R13, R14, R20, R21;
LOCAL REAL: R50, R51:=len_x, R52;
LOCAL INTEGER: R53, R54, R55, R56, R57, R58, R59;
LOCAL PATTERN: R60, R61;
LOCAL BOOLEAN: R62, R63;
POINTER: R64;
LABEL: top, done;
BEGIN
"""
_REALS, _INTS, _PATS, _BOOLS = ["R1", "R2", "R3", "R50", "R51", "R52"], ["R6", "R7", "R53", "R54"], \
    ["R60", "R61"], ["R62", "R63"]
_SYS_READ = ["MDN (2240)", "MDNBI (5002, 4)", "SEN (0)", "TOS (0, 1, 1)", "TOS (0, 1, 2)", "ZOA (1, 1, 0)",
             "ZOPR (1, 1)", "ZOS (1)", "ZOD (2)", "ACPW (1)", "ACPW (3)", "ACD (0)", "ACG (0, 0)", "PPCH",
             "ALNPZ ()", "PLCIB (1, 0)", "PLCF (1, 3, 1)", "PLCT (1, 3)", "PLCC (1, 2)", "SOB (0, 1)", "AGS (0)",
             "PRSS (0, 0)", "ACSS (0)", "MDNBY (5001)", "ZOADW (0, 1, 1)", "PLCDF (1, 10, 1, 2, 1)", "MIB (3)",
             "PLCDG (1, 10, 0)", "PLCW (1, 10, 0, 3)", "PLCDBL (1, 10, 2)", "ACP (1)"]
_SYS_WRITE = ["MDN (2241)", "ZOA (1, 1, 1)", "TOS (0, 3, 1)", "ZOPR (2, 2)", "SEN (10)", "TOAD (0, 1, 1)",
              "ZOFA (1, 2, 1)", "ZOADW (0, 1, 1)", "MIB (7)"]


class Cl800Program:
    """Statements with nested control structures over typed, declared R parameters."""

    def __init__(self, rnd: random.Random):
        self.rnd = rnd
        self.counters = ["R55", "R56", "R57", "R58"]

    def num(self) -> str:
        r = self.rnd
        return r.choice([str(r.randint(0, 20)), f"{r.uniform(-50, 50):.3f}", "0.5", "1000", "-3"])

    def leaf(self) -> str:
        r, x = self.rnd, self.rnd.random()
        if x < 0.45:
            return r.choice([*_REALS, *_INTS, "depth", "len_x", "count"])
        if x < 0.8:
            return self.num()
        if x < 0.9:
            return f"{r.choice(['SIN', 'COS', 'ABS', 'TAN'])} ({self.arith(1)})"
        if x < 0.95:
            return f"SQRT (ABS ({self.arith(1)}))"
        return f"{r.choice(['ANGLE', 'SQRTS'])} ({self.leaf()}, {self.leaf()})"

    def arith(self, depth: int = 0) -> str:
        r = self.rnd
        if depth > 1 or r.random() < 0.55:
            return self.leaf()
        op, a, b = r.choice("+-*/+*"), self.arith(depth + 1), self.arith(depth + 1)
        b = r.choice(["2", "0.5", "-4"]) if op == "/" else b
        return f"({a} {op} {b})" if r.random() < 0.3 else f"{a} {op} {b}"

    def pattern(self) -> str:
        r, x = self.rnd, self.rnd.random()
        if x < 0.3:
            return "B" + "".join(r.choice("01") for _ in range(r.randint(1, 8)))
        if x < 0.6:
            return r.choice(_PATS)
        if x < 0.7:
            return f"NOT {r.choice(_PATS)}"
        return f"{r.choice(_PATS)} {r.choice(['AND', 'OR', 'XOR', 'NAND'])} {self.pattern()}"

    def cond(self, depth: int = 0) -> str:
        r, x = self.rnd, self.rnd.random()
        if x < 0.5:
            return f"{self.arith(1)} {r.choice(['=', '<>', '>', '>=', '<', '<='])} {self.arith(1)}"
        if x < 0.7:
            return r.choice(_BOOLS) if x < 0.6 else f"{r.choice(_PATS)}.{r.randint(0, 7)}"
        if depth < 2:
            return f"{self.cond(depth + 1)} {r.choice(['ANDB', 'ORB', 'XORB', 'NANDB'])} {self.cond(depth + 1)}"
        return r.choice(_BOOLS)

    def statement(self, depth: int) -> str:
        r, x = self.rnd, self.rnd.random()
        otherwise = f" ELSE {self.simple()};" if r.random() < 0.5 else ""
        if depth < 3 and x < 0.08:
            return f"IF {self.cond()} THEN\n{self.block(depth + 1)};\n{otherwise} ENDIF"
        if depth < 3 and x < 0.1:
            inp = f"{r.choice(['', 'NOT '])}{r.choice(['1', '2'])}.{r.randint(0, 7)}"
            return f"IF INT {inp} THEN\n{self.block(depth + 1)};\n{otherwise} ENDIF"
        if depth < 3 and x < 0.11:
            return f"WHILE INT NOT 1.3 DO BEGIN (:G4 F{r.choice([1, 5])}:); LF; {self.simple()}; END"
        if depth < 3 and x < 0.14:
            alts = "\n".join(f"= {k}: {self.simple()};" for k in r.sample(range(5), r.randint(1, 3)))
            other = f" OTHERWISE: {self.simple()};" if r.random() < 0.5 else ""
            return f"CASE {r.choice([*_INTS, 'count'])} {alts}{other} ENDCASE"
        if depth < 3 and x < 0.2 and self.counters:
            c = self.counters.pop()
            body, lim, kind = self.block(depth + 1), r.randint(0, 4), r.random()
            self.counters.append(c)
            if kind < 0.33:
                return f"{c} = 0; WHILE {c} < {lim} DO BEGIN {body}; INC ({c}); END"
            if kind < 0.66:
                return f"{c} = 0; REPEAT {body}; INC ({c}); UNTIL {c} >= {lim}"
            return f"FOR {c} := {r.randint(0, 2)} {r.choice(['TO', 'DOWNTO'])} {lim} DO {body}"
        return self.simple()

    def block(self, depth: int) -> str:
        n = self.rnd.randint(1, 3)
        if n == 1:
            return self.statement(depth)
        return "BEGIN\n" + ";\n".join(self.statement(depth) for _ in range(n)) + ";\nEND"

    def simple(self) -> str:
        r, x = self.rnd, self.rnd.random()
        choices = [
            (0.3, lambda: f"{r.choice([*_REALS, 'depth', 'len_x'])} = {self.arith()}"),
            (0.38, lambda: f"{r.choice(_PATS)} = {self.pattern()}"),
            (0.45, lambda: f"{r.choice(_BOOLS)} = {self.cond()}"),
            (0.55, lambda: f"{r.choice(_REALS)} = {r.choice(_SYS_READ)}"),
            (0.6, lambda: f"{r.choice(_SYS_WRITE)} = {self.arith(1)}"),
            (0.65, lambda: f"{r.choice(['SET', 'CLEAR'])} BIT ({r.choice(_PATS)}.{r.randint(0, 7)})"),
            (0.72, lambda: f"PRAP ({r.randint(1, 3)}) = {self.arith(1)}; (:G1 F1000:); LF"),
            (0.78, lambda: f"(:G91 G1 X{r.randint(-5, 5)} F500:); LF"),
            (0.82, lambda: f"R64 = {r.choice(['50', '51', '1', '6'])}; [R64] = {self.arith(1)}"),
            (0.86, lambda: f"{r.choice(_INTS)} = {r.randint(-3, 6)}"),
            (0.9, lambda: f"XCHG ({r.choice(_REALS)}, {r.choice(_REALS)})"),
            (0.93, lambda: f"{r.choice(['INC', 'DEC', 'TRUNC'])} ({r.choice(_REALS + _INTS)})"),
            (0.94, lambda: "STOP DEC"),
            (0.955, lambda: f"{r.choice(_REALS)} = {r.choice(['LN', 'INV LN', 'ARC SIN'])} ({self.arith(1)})"),
            (0.97, lambda: f"R{r.choice([10, 20])} = {r.choice(['ACAS', 'ACPM', 'ACP'])} ({r.randint(1, 3)})"),
        ]
        return next((make for limit, make in choices if x < limit), lambda: f"CLEAR ({r.choice(_REALS)})")()


def cl800_program(seed: int) -> tuple[int, str]:
    """(program number, source text) with lines short enough for the editor (79 characters)."""
    rnd = random.Random(seed)
    gen, num = Cl800Program(rnd), rnd.randint(100, 900)
    init = " ".join(f"{v} = {gen.num()};" for v in _REALS + _INTS) + " R60 = B1010; R61 = B111;"
    stmts = [gen.statement(0) for _ in range(rnd.randint(2, 8))]
    if rnd.random() < 0.3:  # first-level labels, a bounded backward GOTO and a forward one
        i = rnd.randrange(len(stmts))
        stmts[i:i] = ["R59 = 0", f"top: {stmts[i]}", "INC (R59)", "IF R59 < 3 THEN GOTO top; ENDIF",
                      "IF R1 > 0 THEN GOTO done; ENDIF", "R3 = 7", "done: R52 = R59"]
    return num, _HEADER.format(num=num) + _wrap(init + "\n" + ";\n".join(stmts) + ";\nEND.\n")


def _wrap(text: str, width: int = 70) -> str:
    """Break lines at blanks outside DIN text (:...:)."""
    out = []
    for line in text.split("\n"):
        while len(line) > width:
            cut = line.rfind(" ", 0, width)
            if line.count("(:", 0, cut) > line.count(":)", 0, cut):
                cut = line.find("(:")
            if cut <= 0:
                break
            out.append(line[:cut])
            line = line[cut:].lstrip(" ")
        out.append(line)
    return "\n".join(out)


# -- running them ---------------------------------------------------------------------------------------
@pytest.fixture
def origins(monkeypatch):
    """The Python exception each run-time fault was raised from (None: raised as a fault directly)."""
    seen: list = []
    guarded = api.run_guarded

    def spy(session, runner):
        def wrapped():
            try:
                runner()
            except RuntimeFault as f:
                seen.append(f.__cause__ or f.__context__)
                raise
        return guarded(session, wrapped)

    monkeypatch.setattr(api, "run_guarded", spy)
    return seen


def _folder(tmp_path: Path, name: str, files: dict[str, str]) -> Path:
    folder = tmp_path / name
    folder.mkdir()
    shutil.copy(MACHINE, folder / "machine.toml")
    for file, text in files.items():
        (folder / file).write_text(text, encoding="latin-1")
    return folder


def _run(path: Path, dialect: str | None = None) -> dict:
    options = RunOptions(state_dir=path.parent / f".{path.stem}", max_steps=3000)
    return run(path, dialect=dialect, machine=path.parent / "machine.toml", options=options)[0]


def _origin_ok(origin) -> bool:
    return origin is None or type(origin).__name__ in EXPECTED_ORIGINS


@pytest.mark.parametrize("seed", range(40))
def test_generated_at_code_program_runs_or_faults_sensibly(tmp_path, origins, seed):
    files = at_code_program(seed)
    folder = _folder(tmp_path, "p", files)
    api.check(folder / "P1.mpf", machine=folder / "machine.toml")
    result = _run(folder / "P1.mpf")
    assert all(_origin_ok(o) for o in origins), f"{files}\nfault {result['error']} came from {origins}"


@pytest.mark.parametrize("seed", range(25))
def test_generated_cl800_source_runs_like_its_object_file(tmp_path, origins, seed):
    number, text = cl800_program(seed)
    folder = _folder(tmp_path, "p", {"p.cl8": text})
    # warnings only: the STOP DEC lint (SIN010) judges the generated reads of actual values (issue 15)
    diags = api.check(folder / "p.cl8", machine=folder / "machine.toml")
    assert [d for d in diags if d.severity != "warning" or d.code != "SIN010"] == [], text
    obj = compile_program(folder / "p.cl8", folder / f"L{number}.spf", machine=folder / "machine.toml")
    by_source, by_object = _run(folder / "p.cl8"), _run(obj, dialect="sin800")
    assert all(_origin_ok(o) for o in origins), f"{text}\nfault {by_source['error']} came from {origins}"
    for key in SAME:
        assert by_source[key] == by_object[key], (key, text)
    assert (by_source["error"] is None) == (by_object["error"] is None), text
    if by_source["error"]:
        for key in ("code", "message"):
            assert by_source["error"][key] == by_object["error"][key], (key, text)
        # the source run names the CL 800 statement, with the object block it stopped in (issue 15)
        assert f" line {by_object['error']['line']}: " in by_source["error"]["stack"][0], text


def test_generators_are_deterministic_and_valid():
    assert at_code_program(7) == at_code_program(7) and cl800_program(7) == cl800_program(7)
    assert at_code_program(7) != at_code_program(8)
    assert all(len(line) <= 79 for seed in range(25) for line in cl800_program(seed)[1].split("\n"))


@pytest.mark.parametrize("text, message", [
    # @3b1 PLCDB with 0 data words read no word and stopped with "invalid literal for int()"
    ("@3b1 R10 K1 K10 K0 K0 K101", "number of data words 0 outside 1-3"),
    ("@3b0 R10 K1 K10 K0 K3 K1", "number of data words 3 outside 1-2"),
    # SQRT/LN/ARC SIN outside their domain stopped with "arithmetic error (math domain error)"
    ("R1=-4 @613 R2 R1", "SQRT(-4): no square root of a negative number"),
    ("@640 R2 K0", "LN(0): no logarithm of zero or a negative number"),
    ("@634 R2 K1.5", "ARC SIN(1.5): the sine must lie between -1 and 1"),
    ("@641 R2 K1000", "INV LN(1000): the result is outside the R parameter range +/-99999999 (L7079)"),
])
def test_fault_names_the_users_mistake(run_text, text, message):
    result = run_text(f"%MPF1\n{text}\nM30\n", name="P1.mpf", dialect="sin800")
    assert result["error"]["code"] == "CL800"
    assert result["error"]["message"] == f"CL 800 error: {message}"
    assert result["error"]["line"] == 2


# 11 locals R50-R60 and 24 temporaries R76-R99 (one per bracket level): as one @040 K35 list the push did
# not fit a block and the valid program failed with S064; now each range is pushed by its own @041.
MANY_TEMPORARIES = """PROGRAM 5;
CHANNEL NC 0;
PAR REAL: R1, R2;
LOCAL REAL: R50, R51, R52, R53, R54, R55, R56, R57, R58, R59, R60;
BEGIN
R50 = 1; R60 = 2;
R2 = (((((((((((((((((((((((R1 + 1) * 2) + 1) * 2) + 1) * 2) + 1) * 2)
+ 1) * 2) + 1) * 2) + 1) * 2) + 1) * 2) + 1) * 2) + 1) * 2) + 1) * 2)
+ 1) * R50 + R60;
END.
"""


def test_push_set_too_long_for_one_block_is_split(tmp_path):
    src = tmp_path / "p.cl8"
    src.write_text(MANY_TEMPORARIES, encoding="latin-1")
    obj = compile_program(src, tmp_path / "L5.spf").read_text(encoding="latin-1").split("\n")
    assert obj[1].startswith("@041 R50 R60 @041 R76 R99 ")
    assert obj[-3].endswith(" @043 R76 R99 @043 R50 R60 M17")  # popped in the reverse order (then the mark)
    by_source, _ = run(src, options=RunOptions(state_dir=tmp_path / "a"))
    by_object, _ = run(tmp_path / "L5.spf", dialect="sin800", options=RunOptions(state_dir=tmp_path / "b"))
    # R1 = 0: 11 times x -> (x + 1) * 2 gives 2**12 - 2 = 4094; (4094 + 1) * R50 + R60 = 4095 * 1 + 2
    assert by_source["error"] is None and by_source["variables"]["R2"] == 4097.0
    assert by_source["variables"] == by_object["variables"]
    assert by_source["variables"]["R50"] == by_source["variables"]["R60"] == 0.0  # restored by the pops
