"""A grammar-based generator of random but valid rw_SymPas programs (manual §5.3, §6.4-6.6).

Every program it writes should pass ``ncvm check``; running it may fault only with
the faults the generator knowingly allows (see ``Program.allowed``). Straight-line
W moves of task 0 are followed in a model, so the final axis positions can be checked.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, field

AXES = ["A1", "A2", "A3"]
NUM = ("integer", "single", "double")

MACHINE = """
[[axis]]
name = "X"
min = -100000.0
max = 100000.0
[[axis]]
name = "Y"
min = -100000.0
max = 100000.0
[[axis]]
name = "Z"
min = -100000.0
max = 100000.0

[sympas]
inputs = [{axis = "A1", bit = 1, function = "EO"}, {axis = "A1", bit = 2, function = "UI"}]
ref_positions = {A1 = -5.0, A2 = -5.0, A3 = 3.0}
"""


@dataclass
class Program:
    text: str
    machine: str
    #: final positions (the program's axis name -> value, as the result reports them) the W moves of task 0 must leave
    expected: dict[str, float] = field(default_factory=dict)
    #: run-time error codes this program may legitimately end with
    allowed: set[str] = field(default_factory=set)
    #: the error code the probe at the end of task 0 must end the run with (None: no probe)
    fault: str | None = None


#: statements at the end of task 0 that must fault with the manual's number (§6.8, Table 40);
#: each gets the declarations ``pz: integer; pd: double; VA: AXIS;`` and function ``Deep``
PROBES = [
    ("pz := 0; pz := 7 mod pz", "32768"),
    ("pz := 0; pz := 7 / pz", "32768"),
    ("pd := 0.0; pd := 1.5 / pd", "32768"),
    ("pd := RDCBD(4)", "2048"),
    ("WRCBD(12, 1.0)", "2048"),
    ("pz := RDCBI(2)", "256"),
    ("WRCBI(1000, 1)", "256"),
    ("pz := Deep(100000)", "8"),
    ("VA.an := 7; MLA(VA := 1.0)", "256"),
    ("VA.an := -1; JS(VA)", "256"),
]


@dataclass
class Scope:
    vars: dict[str, str]  # name -> type
    loopvars: list[str]
    func: tuple[str, str] | None = None  # (name, result type) of the function whose body this is
    label: list[str] = field(default_factory=list)  # declared labels not yet placed


class Gen:
    def __init__(self, seed):
        self.r = random.Random(seed)
        self.globals: dict[str, str] = {}
        self.consts: dict[str, str] = {}
        self.routines: list[tuple[str, list[str], str | None]] = []  # name, param types, result type
        self.depth = 0
        self.events: list[str] = []
        self.positions: dict[str, float | None] = {a: 0.0 for a in AXES}
        self.track = True
        self.n = 0
        self.fault: str | None = None
        self.control: list[int] = []  # tasks this task may stop, continue, step and restart
        self.axisvar = False
        self.frozen: set[str] = set()  # recursion counters: never assigned, so the recursion ends

    # --- names and literals
    def name(self, prefix):
        self.n += 1
        return f"{prefix}{self.n}"

    def lit(self, t):
        r = self.r
        if t == "boolean":
            return r.choice(["TRUE", "FALSE"])
        if t in ("integer", "timer"):
            return str(r.choice([0, 1, 2, 3, 7, 10, 100, 255, r.randint(0, 10000)]))
        return r.choice(["0.5", "1.0", "2.25", "1e2", "3.5e-1", f"{r.uniform(0, 1000):.3f}"])

    def pos(self):
        return round(self.r.uniform(-200, 200), 3)

    # --- expressions
    def var_of(self, scope, t):
        names = [n for n, ty in {**self.globals, **scope.vars}.items() if ty == t]
        names += [n for n in scope.loopvars if t == "integer"]
        names += [n for n, ty in self.consts.items() if ty == t]
        return self.r.choice(names) if names else None

    def expr(self, scope, t, d=0):
        r = self.r
        if d > 3 or r.random() < 0.3:
            v = self.var_of(scope, t) if r.random() < 0.6 else None
            if v is None and t == "single" and d > 0:
                return f"SINGLE({self.lit(t)})"  # a real literal is double; inside an operation it would widen
            return v or self.lit(t)
        k = r.random()
        if t == "boolean":
            if k < 0.35:
                nt = r.choice(["integer", "double", "single"])
                return f"({self.expr(scope, nt, d + 1)} {r.choice(['=', '<>', '<', '>', '<=', '>='])} " \
                       f"{self.expr(scope, nt, d + 1)})"
            if k < 0.6:
                return f"({self.expr(scope, t, d + 1)} {r.choice(['and', 'or', 'xor'])} {self.expr(scope, t, d + 1)})"
            if k < 0.7:
                return f"not {self.expr(scope, t, d + 1)}"
            if k < 0.8:
                return f"BOOLEAN({self.expr(scope, 'integer', d + 1)})"
            if k < 0.9:
                return f"{r.choice(AXES)}.{r.choice(['digob', 'axstb'])}.{r.randint(1, 8)}"
            return self.call(scope, t, d) or "TRUE"
        if t == "integer":
            if k < 0.4:
                op = r.choice(["+", "-", "*", "and", "or", "xor"])
                return f"({self.expr(scope, t, d + 1)} {op} {self.expr(scope, t, d + 1)})"
            if k < 0.5:
                return f"({self.expr(scope, t, d + 1)} {r.choice(['/', 'mod'])} {r.randint(1, 9)})"
            if k < 0.6:
                return f"({self.expr(scope, t, d + 1)} {r.choice(['shl', 'shr'])} {r.randint(0, 31)})"
            if k < 0.7:
                return f"INTEGER({self.expr(scope, r.choice(['double', 'single', 'boolean']), d + 1)})"
            if k < 0.75:
                return f"-{self.expr(scope, t, d + 1)}"
            if k < 0.8:
                return f"{r.choice(['CI', 'CI'])}{r.randint(0, 20)}"
            if k < 0.85:
                return f"RDCBI({4 * r.randint(0, 249)})"
            if k < 0.9:
                return "A1.digo"
            return self.call(scope, t, d) or self.lit(t)
        # single/double
        if k < 0.4:
            op = r.choice(["+", "-", "*"])
            other = r.choice(NUM if t == "double" else ("integer", "single"))
            return f"({self.expr(scope, other, d + 1)} {op} {self.expr(scope, t, d + 1)})"
        if k < 0.5:
            div = self.lit("double") if t == "double" else f"SINGLE({self.lit('double')})"
            return f"({self.expr(scope, t, d + 1)} / {div})"
        if t == "double" and k < 0.6:
            fn = r.choice(["ABS", "SIN", "COS", "ATAN", "SQR", "EXP", "TANH", "SINH"])
            return f"{fn}({self.expr(scope, r.choice(NUM), d + 1)} / 1000.0)"
        if k < 0.7:
            return f"{t.upper()}({self.expr(scope, r.choice(['integer', 'boolean', 'single']), d + 1)})"
        if t == "double" and k < 0.8:
            return r.choice([f"{r.choice(AXES)}.{q}" for q in ("dp", "rp", "tp")] + ["CD3", "TRVL", "RDCBD(8)"])
        if k < 0.9:
            return f"RDCBS({4 * r.randint(0, 249)})" if t == "single" else "RDCBD(16)"
        return self.call(scope, t, d) or f"SINGLE({self.lit(t)})"

    def call(self, scope, t, d):
        cands = [x for x in self.routines if x[2] == t]
        if not cands or d > 2:
            return None
        name, params, _ = self.r.choice(cands)
        if scope.func and scope.func[0] == name:
            return None  # recursion only through the bounded pattern
        return name + self.args(scope, params, d)

    def args(self, scope, params, d=2):
        if not params:
            return self.r.choice(["", "()"])
        return "(" + ", ".join(self.expr(scope, p, d + 1) for p in params) + ")"

    # --- statements
    def assign_target(self, scope):
        names = [(n, ty) for n, ty in {**self.globals, **scope.vars}.items() if ty != "timer" and n not in self.frozen]
        if scope.func:
            names.append(scope.func)
        if not names or self.r.random() < 0.1:
            return f"CI{self.r.randint(0, 20)}", "integer"
        return self.r.choice(names)

    def stmt(self, scope, motion=True):
        """One statement (several joined by ';' come wrapped in begin ... end)."""
        s = self._stmt(scope, motion)
        return f"begin {s} end" if ";" in s and not s.startswith(("begin", "for", "if", "while")) else s

    def _stmt(self, scope, motion=True):
        r = self.r
        self.depth += 1
        try:
            k = r.random()
            if self.depth > 3:
                k = r.random() * 0.4
            if k < 0.3:
                n, t = self.assign_target(scope)
                src = t if t != "double" else r.choice(NUM)
                src = src if t != "single" else r.choice(["integer", "single"])
                return f"{n} := {self.expr(scope, src)}"
            if k < 0.36:
                return self.misc(scope)
            if k < 0.42:
                return f"{r.choice(['write', 'writeln'])}('v', {self.expr(scope, r.choice(NUM + ('boolean',)))})"
            if k < 0.5 and self.routines:
                procs = [x for x in self.routines if x[2] is None]
                if procs:
                    name, params, _ = r.choice(procs)
                    return name + self.args(scope, params)
            if k < 0.6 and motion:
                self.track = False
                return self.motion(scope)
            if k < 0.62:
                return f"if {self.expr(scope, 'boolean')} then {self.stmt(scope, motion)}" + (
                    f" else {self.stmt(scope, motion)}" if r.random() < 0.5 else "")
            if k < 0.72:
                lv = self.loopvar(scope)
                if lv is None:
                    return "WT(1)"
                a, b = r.randint(-3, 3), r.randint(-3, 5)
                to = r.choice(["to", "downto"])
                if to == "downto":
                    a, b = b, a
                body = self.stmt(Scope(scope.vars, [x for x in scope.loopvars if x != lv], scope.func), motion)
                return f"for {lv} := {a} {to} {b} do {body}"
            if k < 0.8:
                lv = self.loopvar(scope)
                if lv is None:
                    return "WT(2)"
                inner = Scope(scope.vars, [x for x in scope.loopvars if x != lv], scope.func)
                if r.random() < 0.5:
                    return f"begin {lv} := 0; while {lv} < {r.randint(0, 4)} do begin {self.stmt(inner, motion)}; " \
                           f"{lv} := {lv} + 1 end end"
                return f"begin {lv} := 0; repeat {self.stmt(inner, motion)}; {lv} := {lv} + 1 " \
                       f"until {lv} >= {r.randint(1, 4)} end"
            if k < 0.87:
                return "begin " + "; ".join(self.stmt(scope, motion) for _ in range(r.randint(0, 3))) + " end"
            if k < 0.9:
                return self.case(scope, motion)
            if k < 0.94 and "tm" in self.globals and not scope.func:
                return f"begin tm := CLOCK + {r.randint(0, 200)}; repeat WT({r.randint(1, 9)}) until CLOCK > tm end"
            if k < 0.96 and self.control:
                t = r.choice(self.control)
                return r.choice([f"STOPCNCT({t})", f"CONTCNCT({t})", f"STEPCNCT({t})", f"STOPTOSS({t})",
                                 f"STARTCNCT({t})"])
            if k < 0.97 and self.axisvar and motion:
                self.track = False
                return f"for VB.an := 0 to 2 do {r.choice(['JS', 'MS', 'SSMS'])}(VB)"
            return f"WT({r.randint(0, 50)})"
        finally:
            self.depth -= 1

    def case(self, scope, motion):
        # rw_SymPas has no CASE statement (Table 21 has no 'case'): an if-else-if chain stands in for it
        sel = self.expr(scope, "integer")
        arms = [f"if ({sel}) mod 4 = {i} then {self.stmt(scope, motion)}" for i in range(self.r.randint(1, 3))]
        return " else ".join(arms)

    def loopvar(self, scope):
        free = scope.loopvars
        return self.r.choice(free) if free else None

    def misc(self, scope):
        r = self.r
        k = r.random()
        if k < 0.2:
            return f"WRCBI({4 * r.randint(0, 249)}, {self.expr(scope, 'integer')})"
        if k < 0.35:
            return f"WRCBS({4 * r.randint(0, 249)}, {self.expr(scope, r.choice(['integer', 'single']))})"
        if k < 0.5:
            return f"WRCBD({8 * r.randint(0, 124)}, {self.expr(scope, r.choice(NUM))})"
        if k < 0.6:
            return f"CD{r.randint(0, 9)} := {self.expr(scope, r.choice(NUM))}"
        if k < 0.7 and self.events:
            return f"{r.choice(['ENEV', 'DISEV'])}({r.choice(self.events)})"
        if k < 0.8:
            return f"A{r.randint(1, 3)}.digob.{r.randint(1, 8)} := {self.expr(scope, 'boolean')}"
        if k < 0.9:
            return f"TROVR := {r.choice(['0.5', '1.0', '1.2'])}; UTROVR({', '.join(self.axes())})"
        t = r.choice(["integer", "timer"])
        return f"tm := CLOCK + {r.randint(0, 100)}" if t == "timer" and "tm" in self.globals else "WT(3)"

    def axes(self, lo=1, hi=3):
        return self.r.sample(AXES, self.r.randint(lo, hi))

    def motion(self, scope, wait=None):
        """A motion command; with ``wait`` given, a W command whose targets the model follows."""
        r = self.r
        if wait:
            k = r.random()
            ax = self.axes()
            if k < 0.3:
                items = {a: self.pos() for a in ax}
                for a, v in items.items():
                    self.positions[a] = v
                return f"MLAW({', '.join(f'{a} := {v}' for a, v in items.items())})"
            if k < 0.5:
                items = {a: self.pos() / 4 for a in ax}
                for a, v in items.items():
                    p = self.positions[a]
                    self.positions[a] = None if p is None else p + v
                return f"MLRW({', '.join(f'{a} := {v}' for a, v in items.items())})"
            if k < 0.6:
                items = {a: self.pos() for a in ax}
                self.positions.update(items)
                return f"JAW({', '.join(f'{a} := {v}' for a, v in items.items())})"
            if k < 0.7:
                items = {a: self.pos() / 4 for a in ax}
                for a, v in items.items():
                    p = self.positions[a]
                    self.positions[a] = None if p is None else p + v
                return f"JRW({', '.join(f'{a} := {v}' for a, v in items.items())})"
            if k < 0.85:
                # spooled lines, started together
                out = []
                for _ in range(r.randint(1, 3)):
                    items = {a: self.pos() for a in ax}
                    if r.random() < 0.5:
                        self.positions.update(items)
                        out.append(f"SMLA({', '.join(f'{a} := {v}' for a, v in items.items())})")
                    else:
                        for a, v in items.items():
                            p = self.positions[a]
                            self.positions[a] = None if p is None else p + v
                        out.append(f"SMLR({', '.join(f'{a} := {v}' for a, v in items.items())})")
                out.append(f"SSMSW({', '.join(ax)})")
                return "; ".join(out)
            if k < 0.88:
                a, b = r.sample(AXES, 2)
                # a full circle (PHI 360) returns to the start point
                return f"MCRW({a} := {self.pos() / 8}, {b} := {self.pos() / 8}, PHI := 360.0)"
            if k < 0.9 and None not in (self.positions[AXES[0]], self.positions[AXES[1]]):
                cx, cy = self.positions[AXES[0]] + self.pos() / 8, self.positions[AXES[1]] + self.pos() / 8
                return f"MCAW(A1 := {cx}, A2 := {cy}, PHI := {r.choice(['360.0', '-720.0'])})"
            if k < 0.93:
                a, b, c = r.sample(AXES, 3)
                dz = self.pos() / 8
                p = self.positions[c]
                self.positions[c] = None if p is None else p + dz
                return f"MHRW({a} := {self.pos() / 8}, {b} := {self.pos() / 8}, PHI := 360.0, {c} := {dz})"
            if k < 0.95:
                a = r.choice(AXES)
                self.positions[a] = v = self.pos()
                return f"SHP({a} := {v})"
            if k < 0.97:
                # edge cases: zero-length moves, circles of radius 0, stops and spooler starts on idle axes
                a, b, c = r.sample(AXES, 3)
                return r.choice([f"MLRW({a} := 0.0)", f"JRW({a} := 0)", f"MCRW({a} := 0.0, {b} := 0.0, PHI := 90.0)",
                                 f"MHRW({a} := 0.0, {b} := 0.0, PHI := 180.0, {c} := 0.0)", f"SSMSW({a})",
                                 f"MSW({a}, {b})", f"JSW({c})", f"SMLR({a} := 0.0); SSMSW({a})",
                                 f"SSF({a} := 1, SSFP := 1001); SMLR({a} := 0.0); SSMSW({a})",
                                 f"MCRW({a} := 1.0, {b} := 0.0, PHI := 0.0)"])
            ax = r.sample(AXES, 1)[0]
            self.positions[ax] = None
            return f"{r.choice(['JHLW', 'JHRW'])}({ax})"
        if r.random() < 0.35:
            return self.chaos(scope)
        k = r.random()
        ax = self.axes()
        items = ", ".join(f"{a} := {self.expr(scope, r.choice(NUM))}" for a in ax)
        if k < 0.15:
            return f"{r.choice(['MLA', 'MLR', 'MLAW', 'MLRW', 'JA', 'JR', 'JAW', 'JRW', 'SMLA', 'SMLR'])}({items})"
        if k < 0.3:
            return f"{r.choice(['JS', 'JSW', 'MS', 'MSW', 'SSMS', 'SSMSW', 'UTROVR'])}({', '.join(ax)})"
        if k < 0.4:
            a, b = r.sample(AXES, 2)
            return f"{r.choice(['MCA', 'MCR', 'MCRW', 'SMCR', 'SMCA'])}({a} := {self.pos()}, {b} := {self.pos()}, " \
                   f"PHI := {self.expr(scope, 'double')})"
        if k < 0.5:
            a, b, c = r.sample(AXES, 3)
            return f"{r.choice(['MHA', 'MHR', 'MHRW', 'SMHR'])}({a} := {self.pos()}, {b} := {self.pos()}, " \
                   f"PHI := {r.choice(['90.0', '-180.0', '0.0'])}, {c} := {self.pos()})"
        if k < 0.6:
            return f"{r.choice(['JHL', 'JHR', 'JHLW', 'JHRW'])}({r.choice(AXES)})"
        if k < 0.7:
            return f"TRVL := {r.choice(['10.0', '100.0', '500.0'])}; TRAC := {r.choice(['100.0', '1000.0'])}"
        if k < 0.8:
            return f"JHI({r.choice(AXES)} := {r.choice(['1.0', '-2.0', '5.0'])})"
        if k < 0.9:
            return f"SHP({r.choice(AXES)} := {self.pos()})"
        if k < 0.85:
            return self.chaos(scope)
        return f"{r.choice(AXES)}.jac := 1000.0; {r.choice(AXES)}.jvl := {r.choice(['50.0', '200.0'])}"

    def chaos(self, scope):
        """System parameters and axis commands that change how later moves run (units, mode bits,
        target velocities, zero points, loop state): the model does not follow them."""
        r = self.r
        a, b = r.sample(AXES, 2)
        return r.choice([
            f"MODEREG := {r.choice([1, 2, 0x20, 0x41, 0x81, 0x100, 0x8000, 0x10000020, 0x20000000, 0x4000000, 0x800])}",
            f"PU := {r.randint(0, 7)}", f"TU := {r.randint(0, 2)}", f"TRTVL := {r.choice(['0.0', '5.0', '50.0'])}",
            f"{a}.jtv := {r.choice(['0.0', '10.0'])}", f"SZPA({a} := {self.pos()})", f"SZPR({a} := {self.pos()})",
            f"AZO({r.randint(0, 4)})", f"CL({a}, {b})", f"OL({a})", f"CLV({a}); JS({a})", f"RA({a})",
            f"LPR({a})", f"LPRS({a}, {b})", f"NFRAX := {r.randint(0, 7)}",
            f"TROVRST := {r.choice(['0.0', '0.1'])}", f"JHI({a} := {r.choice(['1.0', '-3.0'])})",
            f"SSF({a} := {r.randint(0, 9)}, SSFP := {r.choice([1, 1000, 1001, 7])})",
            f"{a}.kp := 5.0; {a}.ki := 0.0; {a}.kd := 0.0; {a}.kpl := 0.0; {a}.kfca := 0.0; {a}.kfcv := 0.0; UF({a})",
            f"PN1 := 1.0; PN2 := 0.0; PN3 := {r.choice(['1.0', '0.0'])}; "
            f"{r.choice(['MCA3D', 'MCR3D', 'SMCR3D', 'MCR3DW'])}(A1 := {self.pos()}, A2 := 0.0, A3 := 0.0, PHI := 90.0)",
            f"DTCA1 := {self.pos() / 8}; DTCA2 := 0.0; {r.choice(['MHA', 'MHR', 'SMHR', 'MHRW'])}"
            f"(A1 := {self.pos() / 8}, A2 := 0.0, PHI := {r.choice(['1.0', '-1e-100'])}, A3 := 10.0, "
            f"DTCA1 := {self.pos() / 8}, DTCA2 := 0.0)",
        ])

    # --- declarations
    def decl_vars(self, n, names_prefix="g"):
        out = {}
        for _ in range(n):
            out[self.name(names_prefix)] = self.r.choice(["boolean", "integer", "single", "double", "integer"])
        return out

    def var_part(self, vs):
        if not vs:
            return ""
        return "var " + " ".join(f"{n}: {t};" for n, t in vs.items()) + "\n"

    def routine(self):
        r = self.r
        name = self.name("R")
        params = {self.name("p"): r.choice(["integer", "double", "boolean", "single"]) for _ in range(r.randint(0, 3))}
        self.frozen |= {n for n, t in params.items() if t == "integer"}
        result = r.choice([None, None, "integer", "double", "boolean"])
        local = self.decl_vars(r.randint(0, 3), "l")
        loops = [self.name("i") for _ in range(2)]
        scope = Scope({**params, **local}, loops, (name, result) if result else None)
        head = "procedure" if result is None else "function"
        plist = ""
        if params:
            plist = "(" + "; ".join(f"{n}: {t}" for n, t in params.items()) + ")"
        body = [self.stmt(scope, motion=r.random() < 0.3) for _ in range(r.randint(1, 4))]
        if result:
            body.append(f"{name} := {self.expr(scope, result)}")
        rec = ""
        ints = [n for n, t in params.items() if t == "integer"]
        if ints and r.random() < 0.6:
            # bounded recursion through the first integer parameter
            p = ints[0]
            others = [self.expr(Scope({}, []), t) if n != p else f"{p} - 1" for n, t in params.items()]
            call = f"{name}({', '.join(others)})"
            if result:
                rec = f"if ({p} > 0) and ({p} < 6) then {name} := {call}"
                body.append(rec)
            else:
                body.append(f"if ({p} > 0) and ({p} < 6) then {call}")
        decl = self.var_part({**local, **{lv: "integer" for lv in loops}})
        text = f"{head} {name}{plist}{': ' + result if result else ''};\n{decl}begin\n  " + ";\n  ".join(body) + "\nend;\n"
        self.routines.append((name, list(params.values()), result))
        return text

    def event_handlers(self):
        out = ""
        for ev in self.r.sample(["EVEO", "EVUI"], self.r.randint(0, 2)):
            scope = Scope({}, [])
            body = [f"CI{self.r.randint(30, 40)} := CI{self.r.randint(30, 40)} + 1", f"writeln('{ev} ', CLOCK)",
                    f"DISEV({ev})"]
            if self.r.random() < 0.3:
                body.insert(1, self.stmt(scope, motion=False))
            if not self.track and self.r.random() < 0.3:
                body.insert(1, self.r.choice(["ABORT", "STOP", "MLRW(A3 := 1.0)", "JSW(A1)", "MSW(A1, A2)"]))
            out += f"procedure {ev};\nbegin\n  " + ";\n  ".join(body) + "\nend;\n"
            self.events.append(ev)
        return out

    def task_program(self, task, others):
        """One program of a task: declarations, routines and a main block."""
        r = self.r
        self.globals = self.decl_vars(r.randint(1, 5))
        self.globals["tm"] = "timer"
        self.control = list(others)
        self.axisvar = r.random() < 0.3
        self.consts = {}
        self.routines = []
        self.events = []
        loops = [self.name("k") for _ in range(3)]
        consts = ""
        if r.random() < 0.5:
            c = self.name("C")
            self.consts[c] = "integer"
            consts = f"const {c} = {r.randint(0, 100)};\n"
        decls = self.var_part({**self.globals, **{lv: "integer" for lv in loops}})
        routines = self.event_handlers() + "".join(self.routine() for _ in range(r.randint(0, 4)))
        labels = [self.name("L") for _ in range(r.randint(0, 2))]
        if labels:
            decls = f"label {', '.join(labels)};\n" + decls
            labels = labels[:1]  # one goto loop; a label declared and not placed is allowed
        if self.axisvar:
            decls += "var VB: AXIS;\n"
        scope = Scope({}, loops, None, list(labels))
        body = []
        if self.events:
            body += [f"ENEV({e})" for e in self.events]
        if task == 0:
            body.append(f"TRVL := {r.choice(['50.0', '200.0', '1000.0'])}; TRAC := {r.choice(['500.0', '5000.0'])}")
            for t in others:
                body.append(f"STARTCNCT({t})")
        for _ in range(r.randint(2, 8)):
            if scope.label and r.random() < 0.3:
                # a goto loop: labels stand in the block's own statement sequence (L936)
                lv, lab = scope.loopvars[0], scope.label.pop()
                inner = Scope(scope.vars, scope.loopvars[1:], None)
                body += [f"{lv} := 0", f"{lab}: {self.stmt(inner, motion=task == 0 and r.random() < 0.2)}",
                         f"{lv} := {lv} + 1", f"if {lv} < {r.randint(1, 3)} then goto {lab}"]
            elif task == 0 and self.track and r.random() < 0.4:
                body.append(self.motion(scope, wait=True))
            else:
                body.append(self.stmt(scope, motion=r.random() < 0.5))
        if task == 0:
            for t in others:
                body.append(r.choice([f"STOPCNCT({t})", f"WT(100); STOPCNCT({t})"]))
            if self.track:
                body.append(self.motion(scope, wait=True))
            if r.random() < 0.25:
                probe, self.fault = r.choice(PROBES)
                body.append(probe)
                decls += "var pz: integer; pd: double; VA: AXIS;\n"
                routines += "function Deep(n: integer): integer;\nbegin\n  if n > 0 then Deep := Deep(n - 1) + 1\nend;\n"
        if task and r.random() < 0.3:
            body.append(r.choice(["STOP", "ABORT", "WT(5000)"]))
        header = f"{{$TASK {task}}}\n" if others or task else ""
        return f"{header}program T{task};\n{consts}{decls}{routines}begin\n  " + ";\n  ".join(body) + "\nend.\n"

    def program(self) -> Program:
        r = self.r
        others = r.sample([1, 2, 3], r.choice([0, 0, 1, 2]))
        texts = [self.task_program(0, others)]
        track, positions = self.track, dict(self.positions)
        for t in others:
            self.track = False
            texts.append(self.task_program(t, []))
        scen = ""
        for _ in range(r.randint(0, 5)):
            scen += f'\n[[scenario]]\ntime = {r.choice([r.uniform(0, 0.05), r.uniform(0, 2)]):.3f}\nkind = "input"\naxis = "A1"\n' \
                    f'bit = {r.randint(1, 2)}\nvalue = {r.choice(["true", "false"])}\n'
        expected = {}
        if track and not others:
            expected = {a: v for a, v in positions.items() if v is not None}
        return Program("".join(texts), MACHINE + scen, expected, {"32768"}, self.fault)


def generate(seed) -> Program:
    return Gen(seed).program()
