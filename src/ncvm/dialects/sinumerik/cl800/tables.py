"""CL 800 statements and functions as tables: name -> @ code, argument count (CL 800 manual §5.3, L1397-4590; §10, L6332-6824).

Argument kinds: ``v`` = a <Var> (R parameter or pointer, written), ``x`` = a <Value>
(constant, R parameter or pointer; any expression, evaluated into a temporary first),
``b`` = a bit access ``v.k`` (SET BIT / CLEAR BIT).
"""

from __future__ import annotations

#: functions usable inside expressions: name -> (@ code, number of arguments)   (§5.3.7, L3651-3912)
FUNCTIONS = {
    "ABS": ("610", 1), "SQRT": ("613", 1), "SQRTS": ("614", 2),
    "SIN": ("630", 1), "COS": ("631", 1), "TAN": ("632", 1), "ARC SIN": ("634", 1), "ANGLE": ("637", 2),
    "LN": ("640", 1), "INV LN": ("641", 1),
}

#: system memory reads ``v = NAME(args)``: name -> (@ code, number of arguments, registers written)
#: (§5.3.5, L2305-3032; §10.5, L6492-6612). Registers 0 = as many as the NC finds (ALNP).
SYS_READS = {
    "MDN": ("300", 1, 1), "MDNBY": ("301", 1, 1), "MDNBI": ("302", 2, 1),
    "MDZ": ("303", 2, 1), "MDZBY": ("304", 2, 1), "MDZBI": ("305", 3, 1),
    "MDP": ("306", 1, 1), "MDPBY": ("307", 1, 1), "MDPBI": ("308", 2, 1),
    "MDD": ("309", 1, 1), "MDDBY": ("30a", 2, 1), "MDDBI": ("30b", 3, 1),
    "SEN": ("310", 1, 1), "SENBY": ("311", 1, 1), "SENBI": ("312", 2, 1),
    "SEZ": ("313", 2, 1), "SEZBY": ("314", 2, 1), "SEZBI": ("315", 3, 1),
    "TOS": ("320", 3, 1),
    "ZOA": ("330", 3, 1), "ZOPR": ("331", 2, 1), "ZOE": ("332", 1, 1), "ZOD": ("333", 1, 1),
    "ZOPS": ("334", 1, 1), "ZOS": ("336", 1, 1), "ZOADW": ("337", 3, 1), "ZOPRDW": ("338", 3, 1),
    "PRSS": ("342", 2, 1), "PRVC": ("345", 2, 1), "PCDA": ("34b", 3, 1), "PCDS": ("34c", 3, 1),
    "ACPW": ("360", 1, 1), "ACPM": ("361", 1, 2), "ACP": ("362", 1, 2), "ACSP": ("363", 1, 1),
    "ACSS": ("364", 1, 1), "ACAS": ("367", 1, 5), "ACD": ("36a", 1, 1), "ACG": ("36b", 2, 1),
    "SOB": ("371", 2, 1), "PPCH": ("372", 0, 1),
    "PLCI": ("380", 3, 1), "PLCQ": ("381", 3, 1), "PLCF": ("382", 3, 1), "PLCW": ("383", 4, 1),
    "PLCIB": ("390", 2, 1), "PLCQB": ("391", 2, 1), "PLCPB": ("392", 2, 1), "PLCFB": ("393", 2, 1),
    "PLCDBL": ("394", 3, 1), "PLCDBR": ("395", 3, 1),
    "PLCIW": ("3a0", 3, 1), "PLCQW": ("3a1", 3, 1), "PLCPW": ("3a2", 3, 1), "PLCFW": ("3a3", 3, 1),
    "PLCT": ("3a4", 2, 1), "PLCC": ("3a5", 2, 1),
    "PLCDF": ("3b0", 5, 1), "PLCDB": ("3b1", 5, 1), "PLCDG": ("3b2", 3, 1),
    "ALNP": ("3c0", 0, 0), "ALNPZ": ("3d0", 0, 1),
    "RSDA": ("3e1", 3, 1), "RSDS": ("3e2", 3, 1), "RSDD": ("3e3", 3, 1), "AGS": ("3e4", 1, 1),
    "MIB": ("211", 1, 1),
}

#: multi-register NC functions, only as a whole right-hand side: name -> (@ code, arg kinds, registers)
#: (§5.3.8, L4109-4396). ``PREP REF`` output Rn..Rn+7, INT SEC Rm..Rm+2, PREP CYC v, v+1, MEAS M v, v+1.
NC_FUNCTIONS = {
    "PREP REF": ("710", "v", 8), "INT SEC": ("711", "vv", 3), "PREP CYC": ("713", "", 2),
    "MEAS M": ("720", "x", 2),
}

#: system memory writes ``NAME(args) = x``: name -> (@ code, number of arguments)   (§5.3.6, L3036-3579)
SYS_WRITES = {
    "MDN": ("400", 1), "MDNBY": ("401", 1), "MDNBI": ("402", 2),
    "MDZ": ("403", 2), "MDZBY": ("404", 2), "MDZBI": ("405", 3),
    "MDP": ("406", 1), "MDPBY": ("407", 1), "MDPBI": ("408", 2),
    "MDD": ("409", 1), "MDDBY": ("40a", 2), "MDDBI": ("40b", 3),
    "SEN": ("410", 1), "SENBY": ("411", 1), "SENBI": ("412", 2),
    "SEZ": ("413", 2), "SEZBY": ("414", 2), "SEZBI": ("415", 3),
    "TOS": ("420", 3), "TOAD": ("423", 3),
    "ZOA": ("430", 3), "ZOFA": ("431", 3), "ZOPR": ("432", 2), "ZOD": ("434", 1), "ZOPS": ("435", 1),
    "ZOADW": ("437", 3), "ZOFADW": ("438", 3), "ZOPRDW": ("439", 3), "ZOFPRDW": ("43a", 3),
    "PRAP": ("440", 1), "PRSS": ("442", 1), "PRAD": ("446", 0), "PANG": ("447", 0), "PRIP": ("448", 1),
    "PCDA": ("44b", 3), "PCDS": ("44c", 3),
    "PLCF": ("482", 3), "PLCW": ("483", 4), "PLCFB": ("493", 2), "PLCDBL": ("494", 3), "PLCDBR": ("495", 3),
    "PLCFW": ("4a3", 3), "PLCDF": ("4b0", 5), "PLCDB": ("4b1", 5), "PLCDG": ("4b2", 3),
    "ALNZ": ("4c0", 0), "SATC": ("4e1", 2),
    "MIB": ("212", 1),
}

#: procedure statements: name -> (@ code, argument kinds)   (§5.3.4-5.3.9)
PROCEDURES = {
    "CLEAR": ("200", "v"), "XCHG": ("202", "vv"), "CLEAR MIB": ("210", "xx"),
    "INC": ("620", "v"), "DEC": ("621", "v"), "TRUNC": ("622", "v"),
    "CLEAR BIT": ("660", "b"), "SET BIT": ("661", "b"),
    "POS MSYS": ("706", ""), "STOP DEC": ("714", ""), "STOP DEC1": ("715", ""),
    "REL": ("730", "xx"), "INTA": ("736", "xxx"),
    "WRT PIC": ("a15", "xx"), "RECALL PIC": ("a1b", ""), "PORT": ("a20", "x"),
    "OUTP ZOA": ("a25", "x"), "OUTP DATA": ("a26", "xxx"), "OUTP PARA": ("a27", "xxx"),
    "INP": ("a28", "x"), "OUTP ETX": ("a29", ""), "CHAN": ("a40", "x"),
}

#: two-word keywords: first word -> {second word: full name}; the error when the second word is missing
TWO_WORD = {
    "ARC": ({"SIN"}, "E061"), "INV": ({"LN"}, "E061"), "PREP": ({"REF", "CYC"}, "E061"),
    "INT": ({"SEC"}, "E021"), "STOP": ({"DEC", "DEC1"}, "E061"), "MEAS": ({"M"}, "E020"),
    "POS": ({"MSYS"}, "E022"), "WRT": ({"PIC"}, "E061"), "RECALL": ({"PIC"}, "E061"),
    "OUTP": ({"ZOA", "DATA", "PARA", "ETX"}, "E061"), "SET": ({"BIT"}, "E061"), "CLEAR": ({"BIT", "MIB"}, None),
}

#: comparison operator -> the x digit of @12x/@13x/@14x/@67x (L6421-6469, L6770-6772)
RELOPS = {"=": 1, "<>": 2, ">": 3, ">=": 4, "<": 5, "<=": 6}

#: logical operator -> @ code (L6753-6763)
LOGIC = {"OR": "650", "XOR": "651", "AND": "652", "NAND": "653", "ORB": "655", "XORB": "656",
         "ANDB": "657", "NANDB": "658"}
