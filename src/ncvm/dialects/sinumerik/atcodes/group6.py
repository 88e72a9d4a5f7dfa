"""Main group 6: mathematical and logical functions (planning guide ch.10, L6708-6772).

``expr``: the Python expression of the result over ``{x}``, ``{y}`` (the operands after the target),
``{me}`` (the target) and ``{k}`` (the bit number).
"""

from __future__ import annotations

from .row import AtCode

ROWS = (
    AtCode("610", "ABS", "VW", 6724, "math", expr="abs({x})", cl800="function"),
    AtCode("613", "SQRT", "VW", 6725, "math", expr="(_sqrt({x}) if {x} >= 0.0 else _rt.sqrt({x}))", cl800="function"),
    AtCode("614", "SQRTS", "VWW", 6726, "math", expr="_hypot({x}, {y})", overflows=True, cl800="function"),
    AtCode("620", "INC", "V", 6730, "math", expr="{me} + 1.0", overflows=True, cl800="procedure"),
    AtCode("621", "DEC", "V", 6731, "math", expr="{me} - 1.0", overflows=True, cl800="procedure"),
    AtCode("622", "TRUNC", "V", 6732, "math", expr="float(_trunc({me}))", cl800="procedure"),
    AtCode("630", "SIN", "VW", 6737, "math", expr="(_sin({x} * _DEG) if -360.0 <= {x} <= 360.0 else _bad_angle('SIN', {x}))", underflows=True, cl800="function"),
    AtCode("631", "COS", "VW", 6738, "math", expr="(_cos({x} * _DEG) if -360.0 <= {x} <= 360.0 else _bad_angle('COS', {x}))", underflows=True, cl800="function"),
    AtCode("632", "TAN", "VW", 6739, "math", expr="_rt.tan({x})", underflows=True, cl800="function"),
    AtCode("634", "ARC SIN", "VW", 6740, "math", expr="_rt.arc_sin({x})", underflows=True, cl800="function"),
    AtCode("637", "ANGLE", "VWW", 6741, "math", expr="_rt.angle({x}, {y})", underflows=True, cl800="function"),
    AtCode("640", "LN", "VW", 6746, "math", expr="_rt.ln({x})", underflows=True, cl800="function"),
    AtCode("641", "INV LN", "VW", 6747, "math", expr="_rt.inv_ln({x})", underflows=True, cl800="function"),
    AtCode("650", "OR", "VVW", 6753, "math", expr="_rt.pattern_op('OR', {x}, {y})", cl800="logic"),
    AtCode("651", "XOR", "VVW", 6754, "math", expr="_rt.pattern_op('XOR', {x}, {y})", cl800="logic"),
    AtCode("652", "AND", "VVW", 6755, "math", expr="_rt.pattern_op('AND', {x}, {y})", cl800="logic"),
    AtCode("653", "NAND", "VVW", 6756, "math", expr="_rt.pattern_op('NAND', {x}, {y})", cl800="logic"),
    AtCode("654", "NOT", "VW", 6757, "math", expr="_rt.pattern_op('NOT', {x}, 0.0)"),
    AtCode("655", "ORB", "VVW", 6759, "math", expr="(1.0 if ({x} != 0.0 or {y} != 0.0) else 0.0)", cl800="logic"),
    AtCode("656", "XORB", "VVW", 6760, "math", expr="(1.0 if (({x} != 0.0) != ({y} != 0.0)) else 0.0)", cl800="logic"),
    AtCode("657", "ANDB", "VVW", 6761, "math", expr="(1.0 if ({x} != 0.0 and {y} != 0.0) else 0.0)", cl800="logic"),
    AtCode("658", "NANDB", "VVW", 6762, "math", expr="(0.0 if ({x} != 0.0 and {y} != 0.0) else 1.0)", cl800="logic"),
    AtCode("659", "NOTB", "VW", 6763, "math", expr="(0.0 if {x} != 0.0 else 1.0)"),
    AtCode("660", "CLEAR BIT", "VK", 6767, "math", expr="_rt.set_bit({me}, {k}, 0)", cl800="procedure", args="b"),
    AtCode("661", "SET BIT", "VK", 6768, "math", expr="_rt.set_bit({me}, {k}, 1)", cl800="procedure", args="b"),
    AtCode("670", "comparison", "VVW", 6772, "math", expr="(1.0 if {x} != 0.0 else 0.0)"),
    AtCode("671", "comparison", "VVW", 6772, "math", expr="(1.0 if {x} == {y} else 0.0)"),
    AtCode("672", "comparison", "VVW", 6772, "math", expr="(1.0 if {x} != {y} else 0.0)"),
    AtCode("673", "comparison", "VVW", 6772, "math", expr="(1.0 if {x} > {y} else 0.0)"),
    AtCode("674", "comparison", "VVW", 6772, "math", expr="(1.0 if {x} >= {y} else 0.0)"),
    AtCode("675", "comparison", "VVW", 6772, "math", expr="(1.0 if {x} < {y} else 0.0)"),
    AtCode("676", "comparison", "VVW", 6772, "math", expr="(1.0 if {x} <= {y} else 0.0)"),
)
