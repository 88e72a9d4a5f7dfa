"""Error numbers of rw_SymPas: the manual's compile errors 3 and 91, its run-time table (§6.8,
Table 40) and ncvm's own numbers for compile errors the manual names without a number."""

from __future__ import annotations

from ...diagnostics import Diagnostic, Span

#: compile errors: the manual's numbers where it has them, SPnnn where it does not
COMPILE_ERRORS = {
    "3": "identifier or label used before its declaration (manual §5.3.2, L662)",
    "91": "the return value of a function is not used (manual §5.3.6.2, L1138)",
    "SP001": "syntax error",
    "SP002": "name declared twice in the same block (L666)",
    "SP003": "incompatible types (L533-539)",
    "SP004": "label not defined, defined twice or jumped to from outside its block (L594, L936)",
    "SP005": "wrong number or kind of arguments",
    "SP006": "cannot be assigned (constant, read-only system parameter or qualifier)",
    "SP007": "include file not found or nested deeper than 15 levels (L2243)",
    "SP008": "not supported by rw_SymPas",
    "SP009": "forward declared routine never defined, or defined with another header",
    "SP010": "value out of range",
}

#: warnings (severity "warning"; never stop a run)
WARNINGS = {
    "W006": "constant clamped to the 32-bit range (L398, L402)",
    "W009": "':=' in a constant declaration accepted as '=' (manual example L741)",
    "W031": "qualifier 'jtvf' read as 'jtv' (L1464)",
    "W017": "';' before 'else' accepted (manual example L980)",
    "W035": "'=' accepted as ':=' for a system parameter in an argument list (L1880, L2091)",
}

#: run-time errors of the manual's table 40 (§6.8, L2259-2283); the code is the decimal number
RUNTIME_ERRORS = {
    1: "arithmetic operation invalid for the data type",
    2: "invalid data type",
    4: "invalid internal opcode",
    8: "stack overflow (program too big or recursion too deep)",
    16: "stack underflow",
    32: "unknown event handler",
    64: "invalid NC command",
    128: "address violation in the NC program",
    256: "address violation by a wrong parameter",
    512: "error using the AT interface",
    1024: "common variable outside the valid range",
    2048: "invalid index for a double access to the common buffer (not divisible by 8)",
    4096: "invalid SAP command",
    8192: "error in cutting-speed interpolation",
    16384: "illegal axes in G-code interpolation",
    32768: "invalid parameter in an arithmetic operation (e.g. mod 0)",
    65536: "more than 8 SSF commands in one spline line",
    131072: "G-code subprogram recursion depth exceeded",
}


class SympasError(Exception):
    """A compile error at a place in the source."""

    def __init__(self, code: str, message: str, file: str, line: int, col: int | None = None):
        super().__init__(message)
        self.code = code
        self.message = message
        self.span = Span(file, line, col)

    def diagnostic(self) -> Diagnostic:
        return Diagnostic(self.code, self.message, self.span)
