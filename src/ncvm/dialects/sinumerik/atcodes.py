"""The @ code table of the SINUMERIK 800 (planning guide ch.10, L6332-6824; digest §5.4).

One row per code: the CL 800 statement it comes from, the operand notation
and the manual line. Operand notation letters (manual §10.1.3, L6375-6382):
``K`` <Const> (constant only), ``R`` <R-Par> (R parameter only), ``V`` <Var>
(R parameter or pointer), ``W`` <Value> (constant, R parameter or pointer),
``J`` the jump operand of ``@100`` (constant or R parameter). ``None`` marks
the codes with a variable operand list (``@040``/``@042``, ``@111``).
"""

from __future__ import annotations

from dataclasses import dataclass

from .errors import ReadError


@dataclass(frozen=True, slots=True)
class AtSpec:
    statement: str
    kinds: str | None
    line: int

    @property
    def count(self) -> int | None:
        return None if self.kinds is None else len(self.kinds)

    def check(self, code: str, ops, col: int) -> None:
        if self.kinds is None:
            _check_variable(code, ops, col)
            return
        if len(ops) != len(self.kinds):
            raise ReadError(col, f"@{code} ({self.statement}) needs {len(self.kinds)} operand(s) "
                                 f"({' '.join(_NAMES[k] for k in self.kinds) or 'none'}), got {len(ops)}", "SIN003")
        for i, (op, k) in enumerate(zip(ops, self.kinds)):
            if op.kind not in _ALLOWED[k]:
                raise ReadError(col, f"@{code} ({self.statement}): operand {i + 1} must be {_NAMES[k]}, "
                                     f"not {op.kind}", "SIN003")
        if code in ("041", "043") and ops[0].value > ops[1].value:
            raise ReadError(col, f"@{code} ({self.statement}): R{int(ops[0].value)} to R{int(ops[1].value)} is no "
                                 "range (the first R parameter must come first)", "SIN003")


_ALLOWED = {"K": "K", "R": "R", "V": "RP", "W": "KRP", "J": "KR"}
_NAMES = {"K": "<Const>", "R": "<R-Par>", "V": "<Var>", "W": "<Value>", "J": "<Const>/<R-Par>"}


def _check_variable(code: str, ops, col: int) -> None:
    if code in ("040", "042"):
        if not ops or ops[0].kind != "K" or ops[0].value != int(ops[0].value) or ops[0].value < 1:
            raise ReadError(col, f"@{code}: K<n> (number of R parameters) expected first", "SIN003")
        if len(ops) != 1 + int(ops[0].value) or any(o.kind != "R" for o in ops[1:]):
            raise ReadError(col, f"@{code}: K{int(ops[0].value)} must be followed by {int(ops[0].value)} "
                                 f"R parameters", "SIN003")
    elif code == "111":
        if len(ops) < 3 or len(ops) % 2 == 0 or ops[0].kind not in "RP":
            raise ReadError(col, "@111 (CASE): <Var> followed by pairs of <Value> <Const block no.>", "SIN003")
        for o in ops[2::2]:
            if o.kind != "K":
                raise ReadError(col, "@111 (CASE): each jump target must be a constant block number", "SIN003")


def _s(statement: str, kinds: str | None, line: int) -> AtSpec:
    return AtSpec(statement, kinds, line)


AT_CODES: dict[str, AtSpec] = {
    # main group 0: program structure (L6384-6413)
    "00f": _s("ESS", "", 6397),
    "040": _s("push", None, 6408), "041": _s("push block", "RR", 6409),
    "042": _s("pop", None, 6410), "043": _s("pop block", "RR", 6411),
    # main group 1: branching (L6415-6470)
    "100": _s("GOTO", "J", 6429), "111": _s("CASE", None, 6433),
    **{f"12{x}": _s("IF", "VWK", 6437) for x in "123456"},
    **{f"13{x}": _s("WHILE", "VWK", 6441) for x in "123456"},
    **{f"14{x}": _s("REPEAT UNTIL", "VWK", 6451) for x in "123456"},
    "151": _s("FOR TO", "VWK", 6455), "161": _s("FOR DOWNTO", "VWK", 6459),
    "187": _s("IF INT", "WWK", 6463), "188": _s("IF INT NOT", "WWK", 6465),
    "197": _s("WHILE INT", "WWK", 6468), "198": _s("WHILE INT NOT", "WWK", 6469),
    # main group 2: general data transfer (L6471-6490)
    "200": _s("CLEAR", "V", 6479), "201": _s("assignment", "VW", 6480), "202": _s("XCHG", "VV", 6481),
    "203": _s("bit access", "VVK", 6482), "210": _s("CLEAR MIB", "WW", 6488), "211": _s("MIB read", "VW", 6489),
    "212": _s("MIB write", "WW", 6490),
    # main group 3: system memory -> R parameter (L6492-6612)
    "300": _s("MDN", "VW", 6500), "301": _s("MDNBY", "VW", 6501), "302": _s("MDNBI", "VWW", 6502),
    "303": _s("MDZ", "VWW", 6503), "304": _s("MDZBY", "VWW", 6504), "305": _s("MDZBI", "VWWW", 6505),
    "306": _s("MDP", "VW", 6506), "307": _s("MDPBY", "VW", 6507), "308": _s("MDPBI", "VWW", 6508),
    "309": _s("MDD", "VW", 6509), "30a": _s("MDDBY", "VWW", 6510), "30b": _s("MDDBI", "VWWW", 6511),
    "310": _s("SEN", "VW", 6517), "311": _s("SENBY", "VW", 6518), "312": _s("SENBI", "VWW", 6519),
    "313": _s("SEZ", "VWW", 6520), "314": _s("SEZBY", "VWW", 6521), "315": _s("SEZBI", "VWWW", 6522),
    "320": _s("TOS", "VWWW", 6526),
    "330": _s("ZOA", "VWWW", 6530), "331": _s("ZOPR", "VWW", 6531), "332": _s("ZOE", "VW", 6532),
    "333": _s("ZOD", "VW", 6533), "334": _s("ZOPS", "VW", 6534), "336": _s("ZOS", "VW", 6535),
    "337": _s("ZOADW", "VWWW", 6536), "338": _s("ZOPRDW", "VWWW", 6537),
    "342": _s("PRSS", "VWW", 6541), "345": _s("PRVC", "VWW", 6542), "34b": _s("PCDA", "VWWW", 6543),
    "34c": _s("PCDS", "VWWW", 6544),
    "360": _s("ACPW", "VW", 6549), "361": _s("ACPM", "VW", 6550), "362": _s("ACP", "VW", 6551),
    "363": _s("ACSP", "VW", 6552), "364": _s("ACSS", "VW", 6553), "367": _s("ACAS", "VW", 6554),
    "36a": _s("ACD", "VW", 6555), "36b": _s("ACG", "VWW", 6556),
    "371": _s("SOB", "VWW", 6561), "372": _s("PPCH", "V", 6562),
    "380": _s("PLCI", "VWWW", 6566), "381": _s("PLCQ", "VWWW", 6567), "382": _s("PLCF", "VWWW", 6568),
    "383": _s("PLCW", "VWWWW", 6569),
    "390": _s("PLCIB", "VWW", 6573), "391": _s("PLCQB", "VWW", 6574), "392": _s("PLCPB", "VWW", 6575),
    "393": _s("PLCFB", "VWW", 6576), "394": _s("PLCDBL", "VWWW", 6577), "395": _s("PLCDBR", "VWWW", 6578),
    "3a0": _s("PLCIW", "VWWW", 6584), "3a1": _s("PLCQW", "VWWW", 6585), "3a2": _s("PLCPW", "VWWW", 6586),
    "3a3": _s("PLCFW", "VWWW", 6587), "3a4": _s("PLCT", "VWW", 6588), "3a5": _s("PLCC", "VWW", 6589),
    "3b0": _s("PLCDF", "VWWWWW", 6593), "3b1": _s("PLCDB", "VWWWWW", 6594), "3b2": _s("PLCDG", "VWWW", 6595),
    "3c0": _s("ALNP", "V", 6599), "3d0": _s("ALNPZ", "V", 6603),
    "3e1": _s("RSDA", "VWWW", 6609), "3e2": _s("RSDS", "VWWW", 6610), "3e3": _s("RSDD", "VWWW", 6611),
    "3e4": _s("AGS", "VW", 6612),
    # main group 4: R parameter -> system memory (L6614-6704); the value written is the last operand
    "400": _s("MDN", "WW", 6624), "401": _s("MDNBY", "WW", 6625), "402": _s("MDNBI", "WWW", 6626),
    "403": _s("MDZ", "WWW", 6627), "404": _s("MDZBY", "WWW", 6628), "405": _s("MDZBI", "WWWW", 6629),
    "406": _s("MDP", "WW", 6630), "407": _s("MDPBY", "WW", 6631), "408": _s("MDPBI", "WWW", 6632),
    "409": _s("MDD", "WW", 6633), "40a": _s("MDDBY", "WWW", 6634), "40b": _s("MDDBI", "WWWW", 6635),
    "410": _s("SEN", "WW", 6641), "411": _s("SENBY", "WW", 6642), "412": _s("SENBI", "WWW", 6643),
    "413": _s("SEZ", "WWW", 6644), "414": _s("SEZBY", "WWW", 6645), "415": _s("SEZBI", "WWWW", 6646),
    "420": _s("TOS", "WWWW", 6650), "423": _s("TOAD", "WWWW", 6651),
    "430": _s("ZOA", "WWWW", 6655), "431": _s("ZOFA", "WWWW", 6656), "432": _s("ZOPR", "WWW", 6657),
    "434": _s("ZOD", "WW", 6658), "435": _s("ZOPS", "WW", 6659), "437": _s("ZOADW", "WWWW", 6660),
    "438": _s("ZOFADW", "WWWW", 6661), "439": _s("ZOPRDW", "WWWW", 6662), "43a": _s("ZOFPRDW", "WWWW", 6663),
    "440": _s("PRAP", "WW", 6669), "442": _s("PRSS", "WW", 6670), "446": _s("PRAD", "W", 6671),
    "447": _s("PANG", "W", 6672), "448": _s("PRIP", "WW", 6673), "44b": _s("PCDA", "WWWW", 6674),
    "44c": _s("PCDS", "WWWW", 6675),
    "482": _s("PLCF", "WWWW", 6679), "483": _s("PLCW", "WWWWW", 6680),
    "493": _s("PLCFB", "WWW", 6684), "494": _s("PLCDBL", "WWWW", 6685), "495": _s("PLCDBR", "WWWW", 6686),
    "4a3": _s("PLCFW", "WWWW", 6690),
    "4b0": _s("PLCDF", "WWWWWW", 6694), "4b1": _s("PLCDB", "WWWWWW", 6695), "4b2": _s("PLCDG", "WWWW", 6696),
    "4c0": _s("ALNZ", "W", 6700), "4e1": _s("SATC", "WWW", 6704),
    # main group 6: mathematical and logical functions (L6708-6772)
    "610": _s("ABS", "VW", 6724), "613": _s("SQRT", "VW", 6725), "614": _s("SQRTS", "VWW", 6726),
    "620": _s("INC", "V", 6730), "621": _s("DEC", "V", 6731), "622": _s("TRUNC", "V", 6732),
    "630": _s("SIN", "VW", 6737), "631": _s("COS", "VW", 6738), "632": _s("TAN", "VW", 6739),
    "634": _s("ARC SIN", "VW", 6740), "637": _s("ANGLE", "VWW", 6741),
    "640": _s("LN", "VW", 6746), "641": _s("INV LN", "VW", 6747),
    "650": _s("OR", "VVW", 6753), "651": _s("XOR", "VVW", 6754), "652": _s("AND", "VVW", 6755),
    "653": _s("NAND", "VVW", 6756), "654": _s("NOT", "VW", 6757),
    "655": _s("ORB", "VVW", 6759), "656": _s("XORB", "VVW", 6760), "657": _s("ANDB", "VVW", 6761),
    "658": _s("NANDB", "VVW", 6762), "659": _s("NOTB", "VW", 6763),
    "660": _s("CLEAR BIT", "VK", 6767), "661": _s("SET BIT", "VK", 6768),
    **{f"67{x}": _s("comparison", "VVW", 6772) for x in "0123456"},
    # main group 7: NC-specific functions (L6774-6799)
    "706": _s("POS MSYS", "", 6782), "710": _s("PREP REF", "VV", 6786), "711": _s("INT SEC", "VVV", 6787),
    "713": _s("PREP CYC", "V", 6788), "714": _s("STOP DEC", "", 6789), "715": _s("STOP DEC1", "", 6790),
    "720": _s("MEAS M", "VW", 6794), "730": _s("REL", "WW", 6798), "736": _s("INTA", "WWW", 6799),
    # main group a: I/O statements (L6801-6824)
    "a15": _s("WRT PIC", "WW", 6809), "a1b": _s("RECALL PIC", "", 6810), "a20": _s("PORT", "W", 6814),
    "a25": _s("OUTP ZOA", "W", 6815), "a26": _s("OUTP DATA", "WWW", 6816), "a27": _s("OUTP PARA", "WWW", 6817),
    "a28": _s("INP", "W", 6818), "a29": _s("OUTP ETX", "", 6819), "a40": _s("CHAN", "W", 6823),
}

#: comparison digit of @12x/@13x/@14x/@67x -> Python operator (L6772)
COMPARE = {"1": "==", "2": "!=", "3": ">", "4": ">=", "5": "<", "6": "<="}
