"""The WS 800 A's message numbers and texts (manual §9.2, L6116-6310)."""

from __future__ import annotations

from ....diagnostics import Diagnostic, Span

#: number -> text as the manual prints it (OCR slips of the plain-text edition corrected)
MESSAGES = {
    "W001": "Warning: Comment text open!",
    "W002": "Warning: DIN code open!",
    "E001": '";" expected',
    "E002": '":" expected',
    "E003": '":=" expected',
    "E004": '"=" expected',
    "E005": '"(" expected',
    "E006": '")" expected',
    "E007": '"[" expected',
    "E008": '"]" expected',
    "E009": '"," expected',
    "E010": '"." expected',
    "E011": '"PROGRAM" expected',
    "E012": '"CHANNEL" expected',
    "E013": '"NC" or "COM" expected',
    "E014": '"EXTERNAL" expected',
    "E015": '"CENTRAL" expected',
    "E016": '"GLOBAL" expected',
    "E017": '"OTHERWISE" or "ENDCASE" expected',
    "E019": '"ELSE" or "ENDIF" expected',
    "E020": '"M" expected',
    "E021": '"SEC" expected',
    "E022": '"MSYS" expected',
    "E023": '"DO" expected',
    "E024": '"UNTIL" expected',
    "E025": '"WITH" expected',
    "E027": "Constant expected",
    "E028": "String expected",
    "E029": "File name expected",
    "E030": "Comparison operator expected",
    "E031": "Blank or other separator expected",
    "E032": "Ident. designation incorrect",
    "E033": "Password incorrect",
    "E034": "File name not correct",
    "E035": "Only one file name per line",
    "E036": "Variable name double",
    "E037": "Variable name not declared",
    "E038": "Variable name exceeds 25 characters",
    "E039": "Variable names in program header are illegal",
    "E040": "Number at the start of a variable name illegal",
    "E041": "Parameter not declared",
    "E042": "Parameter doubled",
    "E043": "Parameter in program header illegal",
    "E044": "R parameter with bit in declaration illegal",
    "E045": "% in string illegal",
    "E046": "String exceeds 120 characters",
    "E047": "Bit information not permissible",
    "E048": "Real numbers in program header illegal",
    "E049": "Real number outside limits",
    "E050": "Integer outside limits",
    "E051": "Bit pattern outside limits",
    "E052": "Maximum of 5 digits before the decimal point permitted",
    "E053": "Character illegal",
    "E054": "Symbol cannot be used",
    "E055": "End of comment without start",
    "E056": "End of DIN code without start",
    "E057": "DIN code end :) must be located in one line",
    "E058": "Maximum block level exceeded",
    "E060": "Program was not correctly terminated",
    "E061": "Syntax error",
    "E100": "Label used twice",
    "E200": "File not available",
    "E208": "Line length maximum one screen line",
    "E300": "File cannot be compiled",
    "S050": "Illegal label for GOTO",
    "S051": '"ENDEXTERN" not found',
    "S064": "Excessive block length of destination code",
    "S075": "Label of a programmed GOTO missing",
    "S120": "Block number too high",
    "S125": "Too few intermediate locations for brackets",
    "S126": "Too few intermediate locations for multiplication and division before addition and subtraction",
    "S127": "Too few intermediate locations for functions",
}


class CompilerMessage(Exception):
    """One WS 800 A message at a source position; becomes a Diagnostic."""

    def __init__(self, code: str, file: str, line: int, col: int | None = None, detail: str = "",
                 end_col: int | None = None):
        super().__init__(code)
        self.code, self.file, self.line, self.col, self.detail, self.end_col = code, file, line, col, detail, end_col

    def diagnostic(self) -> Diagnostic:
        base = MESSAGES.get(self.code)  # None for ncvm's own codes (NEST001): the detail says it all
        text = f"{base} ({self.detail})" if base and self.detail else base or self.detail
        severity = "warning" if self.code.startswith("W") else "error"
        return Diagnostic(self.code, text, Span(self.file, self.line, self.col, self.end_col), severity)
