"""A grammar-based generator of random but valid CPL programs (tests/robustness/test_cpl_generated.py uses it).

Each program declares and assigns its variables before use, keeps types apart (INTEGER targets only get INTEGER
expressions), DIMensions its fields, and calls generated sub-programs with parameters. Run-time faults a user can
cause (an index past a DIM, a square root of a negative number, ...) may still happen; the test tells those apart
from internal errors by where the Python exception was raised.
"""

from __future__ import annotations

import random

INTS = ["I%", "J%", "K%", "N%"]
REALS = ["R", "S", "XV"]
DOUBLES = ["D!", "E!"]
BOOLS = ["B?", "C?"]
FIELDS = ["A$", "T$"]          # DIM A$(20), T$(20): character fields
SVARS = ["Q$"]                 # a non-dimensioned string variable
NFIELD = "F"                   # DIM F(5): a REAL field
IFIELD = "G%"                  # DIM G%(3,3): an INTEGER field
BIG = ["2147483647", "2147483648.0", "-2147483649.0", "99999999999999999999.5", "1000000000000000000000000.0",
       "(1000000000000000000000000000000.0 * E!)", "0.0000001", "(D! * 100000000000000000000.0)"]
NUMBERS = ["12", "-3.5", " 007", "+ 42X", "0.25", "99"]
TRIM_OPTIONS = ["", ',"L"', ',"R"']
WORDS = ["ABC", "X1.5", " 12 ", "HELLO", "", "-3.25MM", "007", "A B C"]


class Gen:
    """One program: ``main()`` gives the main text, ``subs`` the sub-programs it calls (name -> text)."""

    def __init__(self, rnd: random.Random, depth: int = 0, name: str = "MAIN"):
        self.r = rnd
        self.depth = depth
        self.name = name
        self.line = 0
        self.out: list[str] = []
        self.subs: dict[str, str] = {}
        self.loop_vars: list[str] = []
        self.files = 0
        self.counter = [0]  # sub-programs made so far, shared by the whole program

    # -- expressions ---------------------------------------------------------------------------
    def int_expr(self, d: int = 0) -> str:
        r = self.r
        c = r.randrange(14 if d < 3 else 4)
        if c == 0:
            return str(r.randint(0, 20))
        if c == 1:
            return r.choice(INTS)
        if c == 2:
            return f"{IFIELD}({r.randint(0, 3)},{r.randint(0, 3)})"
        if c == 3:
            return str(r.randint(-5, 99))
        if c == 4:
            return f"({self.int_expr(d + 1)} {r.choice('+-*')} {self.int_expr(d + 1)})"
        if c == 5:
            return f"INT({self.num_expr(d + 1)})"
        if c == 6:
            return f"ROUND({self.num_expr(d + 1)})"
        if c == 7:
            return f"LEN({self.str_expr(d + 1)})"
        if c == 8:
            return f"ASC({self.str_expr(d + 1)})"
        if c == 9:
            return f"INSTR({self.str_expr(d + 1)},{self.str_expr(d + 1)})"
        if c == 10:
            return f"ABS({self.int_expr(d + 1)})"
        if c == 11:
            return f"-{self.int_expr(d + 1)}"
        if c == 12:
            return f"({self.int_expr(d + 1)} {r.choice(['AND', 'OR', 'XOR'])} {self.int_expr(d + 1)})"
        return f"INSTR({self.str_expr(d + 1)},{self.str_expr(d + 1)},{r.randint(1, 6)})"

    def num_expr(self, d: int = 0) -> str:
        r = self.r
        c = r.randrange(13 if d < 3 else 4)
        if c == 0:
            if r.random() < 0.1:  # large values: the edges of the REAL, DOUBLE and INTEGER ranges
                return r.choice(BIG)
            return f"{r.uniform(-100, 100):.3f}"
        if c == 1:
            return r.choice(REALS + DOUBLES)
        if c == 2:
            return self.int_expr(d + 1)
        if c == 3:
            return f"{NFIELD}({r.randint(0, 5)})"
        if c == 4:
            return f"({self.num_expr(d + 1)} {r.choice('+-*/')} {self.num_expr(d + 1)})"
        if c == 5:
            return f"{r.choice(['SIN', 'COS', 'TAN', 'ATAN'])}({self.num_expr(d + 1)})"
        if c == 6:
            return f"SQRT(ABS({self.num_expr(d + 1)}))"
        if c == 7:
            return f"ABS({self.num_expr(d + 1)})"
        if c == 8:
            return f'VAL("{r.choice(NUMBERS)}")' if r.random() < 0.8 else f"VAL({self.str_expr(d + 1)})"
        if c == 9:
            return f"{r.choice(['ASIN', 'ACOS'])}({r.uniform(-1, 1):.3f})"
        if c == 10:
            return f"SQRT({r.uniform(0, 50):.2f})"
        if c == 11:
            return f"-{self.num_expr(d + 1)}"
        return f"({self.num_expr(d + 1)})"

    def bool_expr(self, d: int = 0) -> str:
        r = self.r
        c = r.randrange(8 if d < 3 else 3)
        if c == 0:
            return r.choice(["TRUE", "FALSE"])
        if c == 1:
            return r.choice(BOOLS)
        if c == 2:
            return f"({self.num_expr(d + 1)} {r.choice(['<', '>', '<=', '>=', '=', '<>'])} {self.num_expr(d + 1)})"
        if c == 3:
            return f"({self.bool_expr(d + 1)} {r.choice(['AND', 'OR', 'XOR'])} {self.bool_expr(d + 1)})"
        if c == 4:
            return f"NOT {self.bool_expr(d + 1)}"
        if c == 5:
            return f"({self.str_expr(d + 1)} {r.choice(['<', '>', '=', '<>'])} {self.str_expr(d + 1)})"
        if c == 6:
            return f"({r.choice(INTS + SVARS + REALS)} {r.choice(['=', '<>'])} NUL)"
        return f"({self.int_expr(d + 1)} = {self.int_expr(d + 1)})"

    def str_expr(self, d: int = 0) -> str:
        """A string expression that is not a concatenation (those may only go to character fields)."""
        r = self.r
        c = r.randrange(10 if d < 3 else 3)
        if c == 0:
            return f'"{r.choice(WORDS)}"'
        if c == 1:
            return r.choice(FIELDS)
        if c == 2:
            return r.choice(SVARS)
        if c == 3:
            n = f",{r.randint(1, 8)}" if r.random() < 0.6 else ""
            return f"MID$({r.choice(FIELDS)},{r.randint(1, 8)}{n})"
        if c == 4:
            return f"CHR$({r.randint(32, 126) if r.random() < 0.8 else r.randint(0, 255)})"
        if c == 5:
            return f"CHR$(65 + ABS({self.int_expr(d + 1)}) - ABS({self.int_expr(d + 1)}))"
        if c == 6:
            return f"TRIM$({self.str_expr(d + 1)}{r.choice(TRIM_OPTIONS)})"
        if c == 7:
            return f'MID$("{r.choice(WORDS)}",{r.randint(1, 4)})'
        if c == 8:
            return f"MID$({self.str_expr(d + 1)},{r.randint(1, 3)},{r.choice(['1', '2', self.int_expr(d + 1)])})"
        return r.choice(FIELDS)

    def field_expr(self) -> str:
        """A string expression for a character field: concatenations and STR$ allowed."""
        r = self.r
        c = r.randrange(5)
        if c == 0:
            return f"{self.str_expr()} + {self.str_expr()}"
        if c == 1:
            return f"STR$({self.num_expr()})"
        if c == 2:
            return f'STR$("{r.choice(["##.###", "V=###", "#", "##.#"])}",{self.num_expr()})'
        if c == 3:
            return f"STR$({self.int_expr()})"
        return self.str_expr()

    # -- statements ---------------------------------------------------------------------------------
    def emit(self, text: str) -> None:
        self.line += 10
        self.out.append(f"{self.line} {text}")

    def assignment(self) -> str:
        r = self.r
        c = r.randrange(11)
        if c == 0:
            return f"{r.choice(INTS)} = {self.int_expr()}"
        if c == 1:
            return f"{r.choice(REALS + DOUBLES)} = {self.num_expr()}"
        if c == 2:
            return f"{r.choice(BOOLS)} = {self.bool_expr()}"
        if c == 3:
            return f"{r.choice(FIELDS)} = {self.field_expr()}"
        if c == 4:
            return f"{r.choice(SVARS)} = {self.str_expr()}"
        if c == 5:
            return f"{NFIELD}({r.randint(0, 5)}) = {self.num_expr()}"
        if c == 6:
            return f"{IFIELD}({r.randint(0, 3)},{r.randint(0, 3)}) = {self.int_expr()}"
        if c == 7:
            n = f",{r.randint(1, 5)}" if r.random() < 0.5 else ""
            return f"MID$({r.choice(FIELDS)},{r.randint(1, 3)}{n}) = {self.str_expr()}"
        if c == 8:
            return f"#GL% = #GL% + {self.int_expr()}"
        if c == 9:
            return f"{r.choice(SVARS)} = MID$({r.choice(FIELDS)},{r.randint(1, 5)},{r.randint(1, 5)})"
        return f"{r.choice(REALS)} = {r.choice(INTS)}"

    def simple(self) -> str:
        r = self.r
        c = r.randrange(6)
        if c <= 3:
            return self.assignment()
        if c == 4:
            return f'DSP({r.randint(1, 20)},{r.randint(1, 40)},"V=####.##",{self.num_expr()})'
        return f'PRN#(0,{self.str_expr()},{self.num_expr()})'

    def block(self, budget: int) -> None:
        r = self.r
        while budget > 0:
            budget -= 1
            c = r.randrange(17)
            if c <= 5 or self.depth_now > 3:
                stmts = [self.simple() for _ in range(r.randint(1, 3))]
                self.emit(" : ".join(stmts))
            elif c == 6:
                self.emit(f"IF {self.bool_expr()} THEN")
                self.block_in(budget // 2)
                if r.random() < 0.5:
                    self.emit("ELSE")
                    self.block_in(budget // 3)
                self.emit("ENDIF")
            elif c == 7:
                self.emit(f"CASE {self.int_expr()} OF")
                labels = r.sample(range(-2, 8), r.randint(1, 3))
                for lab in labels:
                    self.emit(f"LABEL {lab}")
                    self.block_in(budget // 3)
                if r.random() < 0.5:
                    self.emit(f"OTHERWISE {self.simple()}")
                self.emit("ENDCASE")
            elif c == 8:
                v = f"L{len(self.loop_vars)}%"
                self.loop_vars.append(v)
                step = f" STEP {r.choice(['1', '2', '-1', '3'])}" if r.random() < 0.5 else ""
                self.emit(f"FOR {v} = {r.randint(-2, 4)}{step} TO {r.randint(-2, 6)}")
                self.block_in(budget // 3)
                self.emit(f"NEXT {v}" if r.random() < 0.5 else "NEXT")
            elif c == 9:
                v = f"W{len(self.loop_vars)}%"
                self.loop_vars.append(v)
                self.emit(f"{v} = 0")
                self.emit(f"WHILE ({v} < {r.randint(0, 4)}) AND {self.bool_expr(2)} DO")
                self.emit(f"{v} = {v} + 1")
                self.block_in(budget // 3)
                self.emit("END")
            elif c == 10:
                v = f"U{len(self.loop_vars)}%"
                self.loop_vars.append(v)
                self.emit(f"{v} = 0")
                self.emit("REPEAT")
                self.emit(f"{v} = {v} + 1")
                self.block_in(budget // 3)
                self.emit(f"UNTIL ({v} >= {r.randint(1, 4)}) OR {self.bool_expr(2)}")
            elif c == 11 and self.depth < 2:
                self.call()
            elif c == 12:
                self.nc()
            elif c == 13:
                self.emit(r.choice(["WAIT", f"WAIT(,{r.randint(0, 50)})", f"WAIT(,{r.randint(0, 50)},K%)"]))
            elif c == 14 and self.depth == 0:
                r.choice([self.file_io, self.random_file])()
            elif c == 15:
                r.choice([self.goto, self.extras, self.view, self.real_for, self.nested_case])()
            else:
                self.emit(f'PRN#(0,"{r.choice(["#", "##.##", "N=###", "X"])}",{self.num_expr()},{r.choice(BOOLS)})')

    depth_now = 0

    def block_in(self, budget: int) -> None:
        self.depth_now += 1
        self.block(max(budget, 1))
        self.depth_now -= 1

    def nc(self) -> None:
        r = self.r
        words = [f"G{r.choice([0, 1])}"]
        for ax in r.sample(["X", "Y", "Z"], r.randint(1, 3)):
            words.append(f"{ax}[{self.num_expr(2)}]" if r.random() < 0.7 else f"{ax}{r.randint(-50, 50)}")
        words.append(f"F[{r.randint(100, 2000)}]")
        if r.random() < 0.3:
            words.append(r.choice([f"S[{r.randint(0, 3000)}]", "M3", f"M[{r.choice([3, 4, 5])}]", "WAIT"]))
        self.out.append(f"N{self.line + 5} " + " ".join(words))

    def call(self) -> None:
        r = self.r
        self.counter[0] += 1
        name = f"SUB{self.counter[0]}"
        kinds = [r.choice("irdsb") for _ in range(r.randint(0, 4))]
        sub = Gen(r, self.depth + 1, name)
        sub.counter = self.counter
        sub.prologue()
        reads = []
        for k, kind in enumerate(kinds, 1):
            target = {"i": "I%", "r": "R", "d": "D!", "s": "Q$", "b": "B?"}[kind]
            view = {"i": f"P{k}%", "r": f"P{k}", "d": f"P{k}!", "s": f"P{k}$", "b": f"P{k}?"}[kind]
            reads.append(f"{target} = {view}")
        if r.random() < 0.3:
            k = len(kinds) + 1
            reads.append(f"C? = (P{k} = NUL)")
        if r.random() < 0.3 and kinds and kinds[0] in "ir":
            reads.append("D! = P1! : R = P1")
        if reads:
            sub.emit(" : ".join(reads))
        sub.block(r.randint(2, 8))
        sub.out.append("M30")
        self.subs[name] = "\n".join(sub.out) + "\n"
        self.subs.update(sub.subs)
        args = []
        for kind in kinds:
            args.append({"i": self.int_expr, "r": self.num_expr, "d": self.num_expr,
                         "s": lambda: f'"{r.choice(WORDS)}"' if r.random() < 0.5 else r.choice(SVARS),
                         "b": self.bool_expr}[kind]())
        self.emit(f"CALL {name}" + (f" [{', '.join(args)}]" if args else ""))

    def file_io(self) -> None:
        r = self.r
        self.files += 1
        fname = f"GF{self.files}"
        n = r.randint(1, 9)
        self.emit(f'OPENW({n},"{fname}",{r.choice([130, 500, 2000])})')
        for _ in range(r.randint(1, 4)):
            template = r.choice(['"V=##.###"', '"T "', '"#"'])
            tail = r.choice(["", ";", ",B?", ",A$"])
            self.emit(f"PRN#({n},{template},{self.num_expr()}{tail})")
        self.emit(f"CLOSE({n})")
        self.emit(f'OPENR({n},"{fname}")')
        self.emit(f"WHILE NOT EOF({n}) DO")
        target = r.choice(["A$", "T$", "R", "D!", "I%", "A$,R", "R,I%"])
        self.emit(f"INP#({n},{target})")
        self.emit("END")
        self.emit(f"CLOSE({n})")
        if r.random() < 0.5:
            self.emit(f'I% = ERASE("{fname}")')

    def goto(self) -> None:
        self.labels = getattr(self, "labels", 0) + 1
        label = f".J{self.name}{self.labels}"[:12]
        self.emit(f"IF {self.bool_expr()} THEN GOTO {label} ENDIF")
        self.emit(self.simple())
        self.emit(f"{label} : {self.simple()}")

    def extras(self) -> None:
        r = self.r
        stmts = [
            f"@{r.randint(1, 100)} = {self.int_expr()}",
            f"@_R({r.randint(1, 100)}) = {self.num_expr()}",
            f"I% = @{r.randint(1, 100)}",
            f"D! = @_R({r.randint(1, 100)})",
            f"H$({r.randint(1, 3)}) = {self.field_expr()}",
            f"I% = LEN(H$({r.randint(1, 3)}))",
            f"A$ = MID$(H$({r.randint(1, 3)}),{r.randint(1, 4)})",
            f"DD!({r.randint(0, 4)}) = {self.num_expr()}",
            f"BB?({r.randint(0, 2)}) = {self.bool_expr()}",
            f"C? = BB?({r.randint(0, 2)})",
            f"E! = DD!({r.randint(0, 4)}) * {self.num_expr()}",
            f"#GS$ = {self.str_expr()}",
            f"A$ = #GS$ + {self.str_expr()}",
            f"#GR! = {self.num_expr()}",
            f"R = #GR! + {self.num_expr()}",
            f"I% = BCD({r.randint(0, 9999)}) : J% = BIN(BCD({r.randint(0, 9999)}))",
            f"I% = INSTR({self.str_expr()},{self.str_expr()},{r.randint(1, 30)})",
            f"I% = LEN(MID$({r.choice(FIELDS)},{r.randint(1, 30)}))",
            f"I% = ASC(MID$({r.choice(FIELDS)},{r.randint(1, 30)}))",
            f"T$ = TRIM$(MID$({r.choice(FIELDS)},{r.randint(1, 30)}))",
            f"R = VAL(MID$({r.choice(FIELDS)},{r.randint(1, 25)}))",
            f"I% = ROUND({self.num_expr()} * {r.choice(['1000', '100000', '1'])})",
            f"A$ = STR$({r.choice(BOOLS + INTS + DOUBLES)})",
            f'T$ = STR$("{r.choice(["#.#", "####", "##.####", "-#.#"])}",{self.num_expr()})',
            f"DSP({r.randint(1, 20)},{r.randint(1, 40)},{self.str_expr()},{r.choice(BOOLS)},{self.num_expr()})",
            f"PRN#(0,{r.choice(BOOLS + FIELDS + SVARS + INTS + DOUBLES)},{self.str_expr()})",
            r.choice(["LJUST", "NJUST"]),
            f"LIN({self.num_expr()},{self.num_expr()},{self.num_expr()},{self.num_expr()})",
            f"CIR({r.randint(0, 600)},{r.randint(0, 370)},{self.num_expr()})",
            f"GPR({r.randint(0, 600)},{r.randint(0, 400)},{self.str_expr()})",
            f"GMD({r.randint(0, 4)}) : COL({r.randint(1, 3)})",
            f'DSP({r.randint(1, 20)},{r.randint(1, 40)},"{r.choice(["##", "#.###", "X"])}",{self.num_expr()},B?)',
            f"I% = ASC(CHR$({r.randint(0, 255)}))",
            f"C? = ({self.str_expr()} <= {self.str_expr()})",
            f"R = {self.int_expr()} / {r.randint(1, 9)}",
            f"E! = {r.choice(['1.0', '123456789.123456', '0.000001'])} + D!",
            f"I% = NOT {self.int_expr()}",
            f"N% = {self.int_expr()} * {r.choice(['65536', '1000000', '-2147483647'])}",
        ]
        self.emit(" : ".join(r.sample(stmts, r.randint(1, 3))))

    def view(self) -> None:
        """MID$ into a string variable is a live view of its character field (CPL manual §2.4.3, L711-728; §5, L3344-3834)."""
        r = self.r
        source = r.choice(FIELDS + [f"H$({r.randint(1, 3)})"])
        self.emit(f"Q$ = MID$({source},{r.randint(1, 6)},{r.randint(1, 6)})")
        self.emit(f"{r.choice(FIELDS)} = {self.field_expr()}")
        self.emit("PRN#(0,Q$,LEN(Q$)) : I% = INSTR(Q$,A$) : T$ = Q$ + Q$")

    def real_for(self) -> None:
        r = self.r
        v = r.choice(["RC", "DC!"])
        self.emit(f"FOR {v} = {r.uniform(-2, 2):.2f} STEP {r.choice(['0.25', '0.5', '-0.5', '1'])} TO "
                  f"{r.uniform(-2, 2):.2f}")
        self.emit(f"F({r.randint(0, 5)}) = {v} * 2")
        self.emit("NEXT")

    def nested_case(self) -> None:
        r = self.r
        self.emit(f"CASE {self.int_expr()} OF")
        self.emit(f"LABEL {r.randint(-3, 3)}, {r.randint(4, 9)} : CASE ROUND({self.num_expr()}) OF")
        self.emit(f"LABEL 0 : {self.simple()}")
        self.emit(f"OTHERWISE {self.simple()}")
        self.emit("ENDCASE")
        self.emit(f"OTHERWISE {self.simple()}")
        self.emit("ENDCASE")

    def random_file(self) -> None:
        r = self.r
        self.files += 1
        fname = f"RF{self.files}"
        n = r.randint(1, 9)
        rec = r.randint(4, 30)
        self.emit(f'OPENW({n},"{fname}",{r.choice([130, 500, 2000])},"REMARK",{rec})')
        for _ in range(r.randint(1, 5)):
            item = r.choice([f'"V=##.###",{self.num_expr()}', "A$", "B?", "I%", "D!", "T$;", f'"{r.choice(WORDS)}"'])
            self.emit(f"PRN#({n},{item})")
        if r.random() < 0.5:
            self.emit(f"SEEK({n},{r.randint(0, 4)})")
            self.emit(f"PRN#({n},{r.choice(FIELDS)};)")
        self.emit(f"I% = FILEPOS({n},{r.randint(1, 3)})")
        self.emit(f"CLOSE({n})")
        self.emit(f'OPENR({n},"{fname}",{rec})')
        self.emit(f"J% = FILESIZE({n},{r.randint(1, 4)}) : K% = FILEPOS({n})")
        self.emit(f"SEEK({n},{r.randint(1, 3)},{r.randint(1, rec + 1)})")
        self.emit(f"WHILE NOT EOF({n}) DO")
        target = r.choice(["A$", "T$;", "R", "D!", "I%", "B?", "A$,R", "MID$(A$,1,1)", "H$(2)", "F(1),G%(1,1)"])
        self.emit(f"INP#({n},{target})")
        self.emit("END")
        self.emit(f"CLOSE({n})")
        if r.random() < 0.3:
            self.emit(f'OPENW({n},"{fname}")')
            self.emit(f"REWRITE({n})")
            self.emit(f"PRN#({n},{self.str_expr()})")
            self.emit(f"CLOSE({n})")
        self.emit(f'I% = ERASE("{fname}")')

    def prologue(self) -> None:
        self.emit(f"DIM A$(20) : DIM T$(20) : DIM {NFIELD}(5) : DIM {IFIELD}(3,3)")
        self.emit("I% = 1 : J% = 2 : K% = 3 : N% = 4")
        self.emit("R = 1.5 : S = -2.25 : XV = 10 : D! = 0.125 : E! = 7")
        self.emit('B? = TRUE : C? = FALSE : A$ = "HELLO WORLD" : T$ = " 12.5 X" : Q$ = "QQ"')
        self.emit("FOR Z% = 0 TO 5 : F(Z%) = Z% * 1.5 : NEXT")
        self.emit("FOR Z% = 0 TO 3 : FOR Y% = 0 TO 3 : G%(Z%,Y%) = Z% + Y% : NEXT : NEXT")
        self.emit("#GL% = 0 : DIM H$(3,8) : DIM DD!(4) : DIM BB?(2) : #GS$ = \"G\" : #GR! = 0.5")
        self.emit('H$(1) = "ROW1" : H$(2) = "12 TRUE" : H$(3) = "" : DD!(0) = 1 : DD!(1) = 2 : DD!(2) = 3 : DD!(3) = 4 : DD!(4) = 5')
        self.emit("BB?(0) = FALSE : BB?(1) = TRUE : BB?(2) = FALSE")

    def main(self) -> str:
        self.prologue()
        self.block(self.r.randint(5, 20))
        self.out.append("M30")
        return "\n".join(self.out) + "\n"


def program(seed) -> tuple[str, dict[str, str]]:
    """The main program and its sub-programs for one seed."""
    g = Gen(random.Random(seed))
    return g.main(), g.subs
