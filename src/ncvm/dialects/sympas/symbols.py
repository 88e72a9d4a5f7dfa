"""Names a rw_SymPas program can use: its own declarations and the predefined ones.

The predefined tables (system parameters, axis qualifiers, built-in functions
and commands) are data, so each row can be held against the manual.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

NUMERIC = ("integer", "single", "double", "timer")
REAL = ("single", "double")
INTLIKE = ("integer", "timer")


@dataclass(eq=False)
class Var:
    name: str
    ty: str
    py: str
    is_global: bool
    in_routine: bool = False


@dataclass(eq=False)
class Const:
    name: str
    ty: str
    value: object


@dataclass(eq=False)
class Routine:
    name: str
    params: list
    result: str | None
    py: str
    node: object = None
    forward_node: object = None
    defined: bool = False
    is_event: bool = False
    result_var: Var | None = None


@dataclass(eq=False)
class Label:
    name: str
    index: int = -1
    defined: bool = False
    decl: object = None


@dataclass(eq=False)
class AxisSpec:
    """A predefined axis specifier (A1, A2 ... or the names of the machine file)."""

    name: str
    number: int


@dataclass(eq=False)
class SysParam:
    name: str
    ty: str
    writable: bool
    scope: str  # "sys" or "task"


@dataclass(eq=False)
class Builtin:
    """A predefined function or command; ``form`` is the argument form of rw_SymPas manual §6.6, L1620-2233"""

    name: str
    form: str  # "F" function, "X" procedure with expressions, "N","K","E","V","S","SP","SP+"
    result: str | None = None
    params: tuple = ()
    axes: tuple = (1, 99)  # min, max axis items
    wait: bool = False
    extra: tuple = field(default_factory=tuple)  # system parameters allowed inline (SP+)
    section: str = ""


# -- system parameters (Table 32, L1283-1318, and CLOCK L732) ------------------------------------------
SYSPARAMS: dict[str, SysParam] = {}


def _sp(names: str, ty: str, writable: bool, scope: str) -> None:
    for n in names.split():
        SYSPARAMS[n] = SysParam(n, ty, writable, scope)


_sp("BOARDTYPE NOA OSVERSION", "integer", False, "sys")
_sp("CFLAG ERRORREG MODEREG", "integer", True, "sys")
_sp("CLOCK", "timer", False, "sys")
_sp("GFAUX", "double", True, "sys")
_sp("IRQPC LEDGN LEDRD LEDYL", "boolean", True, "sys")
_sp("DTCA1 DTCA2 DTCA3 LET LST PHI PN1 PN2 PN3 TRAC TROVR TROVRST TRTVL TRVL", "double", True, "task")
_sp("NFRAX PU SSFP TU", "integer", True, "task")

COMMON_RE = re.compile(r"^C([ID])(\d{1,3})$")


def sysparam(name: str) -> SysParam | None:
    sp = SYSPARAMS.get(name)
    if sp is None:
        m = COMMON_RE.match(name)
        if m and (len(m.group(2)) == 1 or m.group(2)[0] != "0"):
            return SysParam(name, "integer" if m.group(1) == "I" else "double", True, "sys")
    return sp


# -- axis qualifiers (Table 37, L1422-1497; CFLAGS L1361) ----------------------------------------------
QUALIFIERS: dict[str, tuple[str, bool]] = {}
for _n in "aux dv epc lp lpndx lsm mcis poserr pprev rp rv tp zerooffset axst".split():
    QUALIFIERS[_n] = ("integer" if _n in ("epc", "lsm", "mcis", "axst") else "double", False)
for _n in ("dp dpoffset dvoffset effradius gf gfax hac hvl ipw jac jerkrel jovr jtv jvl kd kfca kfcv ki kp kpl "
           "maxacc maxvel mdvel mpe sdec sll slr slsp").split():
    QUALIFIERS[_n] = ("double", True)
for _n in "an digi digo gcr ifs mcp sf CFLAGS".split():
    QUALIFIERS[_n] = ("integer", True)
QUALIFIER_ALIASES = {"jtvf": "jtv", "cflags": "CFLAGS"}
#: structured (bit) qualifiers (Table 38): name -> (word qualifier, writable)
BIT_QUALIFIERS = {"digib": ("digi", False), "digob": ("digo", True), "ifsb": ("ifs", False),
                  "axstb": ("axst", False)}

EVENTS = ("EVEO", "EVDNR", "EVLSH", "EVLSS", "EVMPE", "EVUI")  # priority order, highest first (L1598)

# -- built-in functions and commands (§6.6) ------------------------------------------------------------
BUILTINS: dict[str, Builtin] = {}


def _b(names: str, form: str, **kw) -> None:
    for n in names.split():
        BUILTINS[n] = Builtin(n, form, **kw)


_b("ABS ACOS ASIN ATAN COS COSH EXP LN SIN SINH SQR SQRT TAN TANH", "F", result="double", params=("double",))
_b("POWER", "F", result="double", params=("double", "double"))
_b("RDCBD", "F", result="double", params=("integer",))
_b("RDCBI", "F", result="integer", params=("integer",))
_b("RDCBS", "F", result="single", params=("integer",))
_b("WRCBD", "X", params=("integer", "double"))
_b("WRCBI", "X", params=("integer", "integer"))
_b("WRCBS", "X", params=("integer", "single"))
_b("WT", "X", params=("integer",))
_b("ABORT STOP RS", "N")
_b("CONTCNCT STARTCNCT STEPCNCT STOPCNCT STOPTOSS", "K", axes=(0, 3))
_b("AZO", "K", axes=(0, 4))
_b("ENEV DISEV", "E")
_b("WRITE WRITELN", "V")
_b("CL CLV OL RA JHL JHR JS MS SSMS UF UTROVR LPRS RPTODP", "S")
_b("JHLW JHRW JSW MSW SSMSW", "S", wait=True)
_b("LPR", "S", axes=(1, 1))
_b("JA JR JHI SHP SZPA SZPR MLA MLR SMLA SMLR", "SP")
_b("JAW JRW JHIW MLAW MLRW", "SP", wait=True)
_CIRCLE = ("PHI",)
_b("MCA MCR SMCA SMCR", "SP+", axes=(2, 2), extra=_CIRCLE)
_b("MCAW MCRW", "SP+", axes=(2, 2), extra=_CIRCLE, wait=True)
_3D = ("PHI", "PN1", "PN2", "PN3", "DTCA1", "DTCA2", "DTCA3")
_b("MCA3D MCR3D SMCA3D SMCR3D", "SP+", axes=(3, 3), extra=_3D)
_b("MCA3DW MCR3DW", "SP+", axes=(3, 3), extra=_3D, wait=True)
_HELIX = ("PHI", "DTCA1", "DTCA2")
_b("MHA MHR SMHA SMHR", "SP+", axes=(3, 99), extra=_HELIX)
_b("MHAW MHRW", "SP+", axes=(3, 99), extra=_HELIX, wait=True)
_b("SSF", "SP+", extra=("SSFP",))
CASTS = ("BOOLEAN", "INTEGER", "SINGLE", "DOUBLE")
