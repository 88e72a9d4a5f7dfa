"""The CPL run-time errors and warnings of manual chapters 5-9, as one exception class and a table.

The manual names these errors by text only (it numbers just 2153 and 2167), so each
gets a stable project code. One error has one code: the chapter-5 string errors, INVALID PARAMETER
(also of the graphics functions), INVALID INTEGER VALUE and INVALID FLOAT VALUE share the language's codes
(CPL021-CPL025, CPL027, CPL042, see ``cpl/errors.py``), the others are grouped by manual chapter (CPL6xx files, CPL7xx dialog,
CPL8xx graphics, CPL9xx MMC); the message is the manual's text. The CPL front end
turns :class:`CplRuntimeError` into :class:`ncvm.diagnostics.RuntimeFault`
(``RuntimeFault(err.code, err.message, span, stack)``).
"""

from __future__ import annotations

from typing import Callable

from ....records import FrozenRecord

#: name -> (code, manual text, manual reference)
ERRORS: dict[str, tuple[str, str, str]] = {
    # chapter 5, strings
    "NESTING_TOO_DEEP": ("2153", "NESTING TOO DEEP", "L3773"),
    "INVALID_FIELD_LIMIT": ("CPL022", "INVALID FIELD LIMIT", "L3358"),
    "INVALID_PARAMETER": ("CPL023", "INVALID PARAMETER", "L3390, L3415, L3461, L4237, L4286, L4338"),
    "CHARACTER_FIELD_NOT_ASSIGNED": ("CPL024", "CHARACTER FIELD NOT ASSIGNED", "L3427, L3646, L3694"),
    "INVALID_ASSIGNMENT": ("CPL021", "INVALID ASSIGNMENT", "L3545"),
    "INADMISSIBLE_ASSIGNMENT": ("CPL025", "Inadmissible assignment to a non-dimensioned STRING variable",
                                "L3520, L3609-3614, L3789-3793"),
    # chapter 6, files
    "INVALID_LOGICAL_NUMBER": ("CPL601", "INVALID LOGICAL NUMBER", "L3912"),
    "ILLEGAL_FILE_SIZE": ("CPL602", "ILLEGAL FILE SIZE", "L3918"),
    "INVALID_COMPONENT_LENGTH": ("CPL603", "INVALID COMPONENT LENGTH", "L3921, L3935, L3993"),
    "BLOCK_EXCEEDS_1024": ("CPL604", "BLOCK EXCEEDS 1024 BYTES", "L4033, L4059"),
    "INVALID_INTEGER_VALUE": ("CPL027", "INVALID INTEGER VALUE", "L4130"),  # the language's error
    "INVALID_FLOAT_VALUE": ("CPL042", "INVALID FLOAT VALUE", "L4130"),  # the language's error
    "INVALID_FILE_NUMBER": ("CPL607", "INVALID FILE NUMBER", "L4209, L4276, L4315"),
    "INVALID_COMPONENT": ("CPL608", "INVALID COMPONENT", "L4282"),
    "INVALID_FILE_NAME": ("CPL609", "INVALID FILE NAME", "L4387"),
    "FILE_NOT_OPEN": ("CPL610", "FILE NOT OPEN", "L4106 (REWRITE: 'to overwrite a file, it must be open')"),
    "FILE_ALREADY_OPEN": ("CPL611", "FILE ALREADY OPEN FOR WRITING", "L3897"),
    "FILE_NOT_FOUND": ("CPL612", "FILE DOES NOT EXIST", "L3895 (OPENR of a missing file)"),
    "WRONG_ACCESS": ("CPL613", "FILE NOT OPENED FOR THIS ACCESS", "L4109, L4268, L4309"),
    "FILE_MEMORY_FULL": ("CPL614", "FILE MEMORY FULL", "(simulator: [cpl] file_space, docs/decisions.md)"),
    "FILE_NOT_WRITTEN": ("CPL615", "FILE CANNOT BE WRITTEN", "(simulator: the host refused the write)"),
    # warnings (the program continues)
    "PRN_FORMAT_INCORRECT": ("CPL620", "PRN FORMAT INCORRECT", "L4035"),
    "FILE_NOT_ERASED": ("CPL621", "FILE NOT ERASED", "L4396"),
    # chapter 7, dialog
    "INVALID_LINE_OR_COLUMN": ("CPL701", "Invalid line or column number in CPL command", "L4549"),
    "MAX_STRING_LENGTH": ("CPL702", "maximum string length exceeded", "L4557"),
    "FORMAT_NOT_PERMITTED": ("CPL703", "format not permitted", "L4559"),
    "INP_WITHOUT_PRN": ("CPL704", "INP without a PRN of the same variable in DLG..ENDDLG", "L4768"),
    "KEY_SCRIPT_EMPTY": ("CPL705", "waiting for a key, but the key script is exhausted", "(simulator)"),
    "KEY_SCRIPT_SYNTAX": ("CPL706", "key script line not understood", "(simulator)"),
    # chapter 8, graphics
    "INVALID_GRAPHICS_VALUE": ("CPL023", "INVALID PARAMETER", "L4929, L4958, L4994, L5063 (value range)"),
    "WINDOW_RATIO": ("CPL802", "MWD side ratio differs from the GWD window", "L5007"),
    "BITMAP_MISSING": ("CPL803", "cplbmp\\{name}.bmp is not existing", "L5153"),
    # chapter 9
    "MMC_TOO_MANY": ("CPL901", "MMC: at most 20 CPL variables", "L5203"),
}


class CplRuntimeError(Exception):
    """A run-time error of a CPL I/O function: the code and the manual's message."""

    def __init__(self, code: str, message: str):
        self.code = code
        self.message = message
        super().__init__(f"{code}: {message}")


class CplWarning(FrozenRecord):
    """A warning the control shows while the program goes on (e.g. PRN FORMAT INCORRECT)."""

    __slots__ = ("code", "message")

    def __init__(self, code: str, message: str):
        self.code = code
        self.message = message


WarnFn = Callable[[CplWarning], None]


def fail(key: str, detail: str = "", **fmt) -> CplRuntimeError:
    """The error ``key`` of :data:`ERRORS`, ready to raise; ``detail`` is appended after ': '."""
    code, text, _ref = ERRORS[key]
    text = text.format(**fmt) if fmt else text
    return CplRuntimeError(code, f"{text}: {detail}" if detail else text)


def warning(key: str, detail: str = "", **fmt) -> CplWarning:
    code, text, _ref = ERRORS[key]
    text = text.format(**fmt) if fmt else text
    return CplWarning(code, f"{text}: {detail}" if detail else text)
