"""CPL blocks that ``ncvm check`` passes clean and ``ncvm run`` refuses, with every word a literal the check
reads.

Issue 14 §5: "a clean check means the run will not stop on an unsupported function"; the check's own help:
"Check programs for every error the control would report"."""

from __future__ import annotations

import pytest
from review14d_run import check, run, write

HEAD = "N20 G0 X0 Y0 Z0\n"


@pytest.mark.parametrize("blocks, code", [
    # G20 plane switchover (L2372) to main axis X, secondary axis Z: "not supported by ncvm" (the run names
    # the planes it runs); both axes are literal words of the block
    ("N30 G20 X0 Z0\nN40 G2 X10 Z0 R5 F100\n", "NC004"),
    # H: "compensation group 1..48" of the selected table (L1573, docs/decisions.md); H99 is a literal
    ("N30 H99 Z0\n", "NC009"),
    # G22 K<n>: K4, K5 or K0 (docs/decisions.md, "Typ3 G22 K<n>"); K7 is a literal
    ("N30 G22 K7\n", "NC009"),
], ids=["g20-x-z", "h99", "g22-k7"])
def test_check_sees_what_the_run_refuses_in_a_literal_block(tmp_path, blocks, code):
    text = HEAD + blocks + "N90 M30\n"
    write(tmp_path, {"p.cpl": text})
    result, _rows, _stderr = run(tmp_path, "p.cpl", text)
    assert result["error"]["code"] == code, result["error"]
    proc = check(tmp_path, "p.cpl", "cpl")
    assert " 0 diagnostic(s)" not in proc.stderr, f"check is clean; the run stops: {result['error']['message']}"
