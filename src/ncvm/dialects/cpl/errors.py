"""CPL error numbers and texts.

The manual numbers two messages (RUNTIME ERROR 2153, 2167) and shows a few
more in a GETERR screen (1869, 1938, 1970). Every other error it names has
only a text; those get a stable ``CPLnnn`` code here with the manual's text as
the message (the manual's own error numbers where it gives them). A reviewer can hold this table against the manual.
"""

from __future__ import annotations

from ...diagnostics import NCVM_CODES, Diagnostic, RuntimeFault, Span

#: code -> (manual text, manual place)
CODES: dict[str, tuple[str, str]] = {
    "2167": ("RUNTIME ERROR 2167 = MISSING", "§2.4.1 L437-447"),
    "2153": ("RUNTIME ERROR 2153 NESTING TOO DEEP", "§2.5.1 L782, §5.8 L3773"),
    "1869": ("variable not installed. Memory full.", "§2.4.3 L558, GETERR L2573"),
    "1938": ("axis index programmed is not configured", "§4.2 L1337, GETERR L2577"),
    "1970": ("axis is assigned to another channel", "§4.2 L1402, L1428, GETERR L2579"),
    "CPL001": ("syntax error", "§2-3 grammar"),
    "CPL002": ("jump destination not found", "§2.3 linking, §2.5.6"),
    "CPL003": ("jump destination not unique", "§2.5.6 (CPL manual L3397-3398; L4053; L4262)"),
    "CPL004": ("block structure incomplete", "§2.5.5-2.5.7"),
    "CPL005": ("sub-program not found", "§2.3, §3"),
    "CPL006": ("recursive sub-program call not possible", "§3 L1067"),
    "CPL007": ("sub-program nesting deeper than 7 levels", "§2.1 L323"),
    "CPL008": ("more than 10 nested CASE constructs", "§2.5.7 L1044"),
    "CPL009": ("a CPL block that includes WAIT must not contain a ':'", "§4.1 L1201"),
    "CPL010": ("jump into a FOR loop from outside", "CPL manual §2.5.5, L988-1005"),
    "CPL011": ("duplicate LABEL constant in CASE", "CPL manual §2.5.5, L1029-1046"),
    "CPL012": ("invalid variable name", "§2.4.3"),
    "CPL013": ("address calling a sub-program must not use [ ]", "§2.1.1 L371"),
    "CPL014": ("the CALL instruction must appear in its own separate CPL block", "§3.3 L1086"),
    "CPL020": ("VARIABLE NOT ASSIGNED", "§2.5 NUL (CPL manual §2.5, L758-769)"),
    "CPL021": ("INVALID ASSIGNMENT", "§5 L3545"),
    "CPL022": ("INVALID FIELD LIMIT", "§5.1 L3358"),
    "CPL023": ("INVALID PARAMETER", "§5.2 L3390, §6 L4237-4286, graphics value ranges"),
    "CPL024": ("CHARACTER FIELD NOT ASSIGNED", "§5.3 L3427"),
    "CPL025": ("inadmissible assignment to a non-dimensioned string variable", "§5 L3609-3614, L3789"),
    "CPL026": ("invalid variable", "§3.4 L1159 (PDIM)"),
    "CPL027": ("INVALID INTEGER VALUE", "§6.4 L4130 (INP#), CPL manual §2.4.3, L650-737"),
    "CPL028": ("division by zero", "runtime error"),
    "CPL029": ("runtime error", "§2.5.1 (SQRT of a negative number, function domain)"),
    "CPL030": ("sub-program excluded from linking (DIN) contains CPL", "§3.3 L1104"),
    "CPL031": ("field index out of range", "§2.4.3 fields"),
    "CPL032": ("type mismatch", "CPL manual §2.4.3, L650-737; §2.5, L738-770"),
    "CPL033": ("permanent variable cannot be deleted, only overwritten", "§2.5 L769"),
    "CPL034": ("definable permanent variable not declared", "§2.4.3 L548-570"),
    "CPL035": ("field not dimensioned", "§2.4.3 L702"),
    "CPL036": ("parameter is read-only", "CPL manual §3.4, L1122-1179"),
    "CPL037": ("function not available in this version", "later issue (chapter 4)"),
    "CPL038": ("declaration file error", "§2.4.3 L615-637"),
    "CPL039": ("WAIT condition can never be met (simulator deadlock)", "CPL manual §4.1, L1186-1239"),
    "CPL041": ("SERCOS SERVICE CHANNEL IS LOCKED", "§4.9 L2156"),
    "CPL042": ("INVALID FLOAT VALUE", "§6.4 L4130 (INP#), a REAL or DOUBLE result beyond its range"),
    "CPL040": ("runtime error", "chapter 4: system data not available or not allowed"),
}


def text(code: str) -> str:
    return CODES[code][0]


class CplError(Exception):
    """A run-time error raised inside generated code; the runtime adds file and line."""

    def __init__(self, code: str, detail: str = "", column: int | None = None):
        self.code = code
        self.detail = detail
        self.column = column  # where in the line, when it is not where the statement starts (a word)
        super().__init__(f"{code}: {message(code, detail)}")


def nul_used() -> CplError:
    """NUL where a value is needed: RUNTIME ERROR VARIABLE NOT ASSIGNED (CPL manual §2.5, L758-769)."""
    return CplError("CPL020", NUL_USED)


#: the detail of CPL020 where a NUL value is used in an expression
NUL_USED = "NUL used in an expression"


def message(code: str, detail: str = "") -> str:
    base = CODES[code][0] if code in CODES else NCVM_CODES.get(code, code)
    return f"{base}: {detail}" if detail else base


def diag(code: str, detail: str, file: str, line: int, column: int | None = None, cpl_line: int | None = None,
         ) -> Diagnostic:
    msg = message(code, detail)
    if cpl_line is not None:
        msg += f" (CPL line {cpl_line})"
    return Diagnostic(code, msg, Span(file, line, column))


def fault(code: str, detail: str, file: str, line: int, cpl_line: int | None = None,
          text: str | None = None, column: int | None = None) -> RuntimeFault:
    msg = text if text is not None else message(code, detail)
    if cpl_line is not None:
        msg += f" (CPL line {cpl_line})"
    return RuntimeFault(code, msg, Span(file, line, column))
