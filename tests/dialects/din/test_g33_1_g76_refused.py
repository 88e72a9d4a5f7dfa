"""din G33.1 (rigid tapping) and G76 (threading cycle): LinuxCNC runs them, ncvm does not yet; the run stops
at the block naming the function, and ``ncvm check`` warns of it in the "not supported by ncvm" category
(docs/decisions.md, "Issue 14: G33.1 and G76")."""

from __future__ import annotations

import pytest

from ncvm.api import check, run
from ncvm.machine.config import machine_from_dict
from ncvm.runtime.session import RunOptions

MACHINE = {"axis": [{"name": a} for a in "XYZ"]}


@pytest.mark.parametrize(("block", "meaning"), [("G33.1 Z-10 K1.5", "rigid tapping"),
                                                ("G76 P1.5 Z-20 I-1 J0.5 K1", "threading cycle")])
def test_refused_by_name_at_run_and_in_check(tmp_path, block, meaning):
    path = tmp_path / "p.ngc"
    path.write_text(f"G21 G18 G90\nS500 M3\nG0 X10 Z5\n{block}\nM2\n")
    result, _ = run(path, machine=machine_from_dict(MACHINE), options=RunOptions(state_dir=tmp_path / "s"))
    g = block.split()[0]
    assert result["error"]["code"] == "NC004" and result["error"]["line"] == 4
    assert result["error"]["message"].startswith(f"{g} (") and meaning in result["error"]["message"]
    assert "not supported by ncvm" in result["error"]["message"]
    assert result["position"] == {"X": 10.0, "Y": 0.0, "Z": 5.0}
    diags = check(path, dialect="din", machine=machine_from_dict(MACHINE))
    assert [(d.code, d.severity, d.span.line) for d in diags] == [("NC004", "warning", 4)]
    assert meaning in diags[0].message and "not supported by ncvm: the run stops here" in diags[0].message
