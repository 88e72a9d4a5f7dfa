"""Main group 1: branching (planning guide ch.10, L6415-6470).

``expr``: the condition under which the code *jumps* to its block number (ncvm's reading; the CL 800 manual is silent), over the
compared values ``{a}`` and ``{b}``.
"""

from __future__ import annotations

from .row import AtCode

ROWS = (
    AtCode("100", "GOTO", "J", 6429, "goto"),
    AtCode("111", "CASE", None, 6433, "case"),
    AtCode("121", "IF", "VWK", 6437, "branch", expr="not ({a} == {b})"),
    AtCode("122", "IF", "VWK", 6437, "branch", expr="not ({a} != {b})"),
    AtCode("123", "IF", "VWK", 6437, "branch", expr="not ({a} > {b})"),
    AtCode("124", "IF", "VWK", 6437, "branch", expr="not ({a} >= {b})"),
    AtCode("125", "IF", "VWK", 6437, "branch", expr="not ({a} < {b})"),
    AtCode("126", "IF", "VWK", 6437, "branch", expr="not ({a} <= {b})"),
    AtCode("131", "WHILE", "VWK", 6441, "branch", expr="not ({a} == {b})"),
    AtCode("132", "WHILE", "VWK", 6441, "branch", expr="not ({a} != {b})"),
    AtCode("133", "WHILE", "VWK", 6441, "branch", expr="not ({a} > {b})"),
    AtCode("134", "WHILE", "VWK", 6441, "branch", expr="not ({a} >= {b})"),
    AtCode("135", "WHILE", "VWK", 6441, "branch", expr="not ({a} < {b})"),
    AtCode("136", "WHILE", "VWK", 6441, "branch", expr="not ({a} <= {b})"),
    AtCode("141", "REPEAT UNTIL", "VWK", 6451, "branch", expr="not ({a} == {b})"),
    AtCode("142", "REPEAT UNTIL", "VWK", 6451, "branch", expr="not ({a} != {b})"),
    AtCode("143", "REPEAT UNTIL", "VWK", 6451, "branch", expr="not ({a} > {b})"),
    AtCode("144", "REPEAT UNTIL", "VWK", 6451, "branch", expr="not ({a} >= {b})"),
    AtCode("145", "REPEAT UNTIL", "VWK", 6451, "branch", expr="not ({a} < {b})"),
    AtCode("146", "REPEAT UNTIL", "VWK", 6451, "branch", expr="not ({a} <= {b})"),
    AtCode("151", "FOR TO", "VWK", 6455, "branch", expr="{a} > {b}"),
    AtCode("161", "FOR DOWNTO", "VWK", 6459, "branch", expr="{a} < {b}"),
    AtCode("187", "IF INT", "WWK", 6463, "branch", expr="not _rt.ext_input({a}, {b}, {line}, {col})"),
    AtCode("188", "IF INT NOT", "WWK", 6465, "branch", expr="_rt.ext_input({a}, {b}, {line}, {col})"),
    AtCode("197", "WHILE INT", "WWK", 6468, "branch", expr="not _rt.ext_input({a}, {b}, {line}, {col})"),
    AtCode("198", "WHILE INT NOT", "WWK", 6469, "branch", expr="_rt.ext_input({a}, {b}, {line}, {col})"),
)
