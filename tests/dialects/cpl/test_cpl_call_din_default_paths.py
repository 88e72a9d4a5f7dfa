"""``CALL name DIN`` of a program the running program wrote, with the machine's default paths.

L1097: a CALL ... DIN program is excluded from linking, so a program may write it (OPENW/PRN#/CLOSE, LJUST
L4003) and then call it. On the control both are one file memory (§6.1). With ncvm's defaults
(``program_path = ["."]``, ``file_root = "files"``) the file lands in the file root, the CALL looks only
along the program path, and the run stops with ``CPL005 sub-program not found: SUB1`` although the file
was just written -- the message does not say where it looked or where SUB1 is. The existing test of this
feature passes only because its machine adds the file root to the program path.
"""

from __future__ import annotations

from pathlib import Path

from ncvm.api import run
from ncvm.runtime.session import RunOptions

MACHINE = '[[axis]]\nname = "X"\n[[axis]]\nname = "Y"\n[[axis]]\nname = "Z"\n'
WRITER = ('10 LJUST\n20 OPENW(1,"SUB1",200)\n30 PRN#(1,"N10 G1 F1000 X",12.5," Y",3.0)\n40 PRN#(1,"N20 M30")\n'
          '50 CLOSE(1)\n60 CALL SUB1 DIN\n70 WAIT\n80 X = MPOS(1)\nM30\n')


def _run(main: Path, tmp_path: Path) -> dict:
    (tmp_path / "machine.toml").write_text(MACHINE)
    main.parent.mkdir(parents=True, exist_ok=True)
    main.write_text(WRITER)
    result, _ = run(main, dialect="cpl", machine=tmp_path / "machine.toml",
                    options=RunOptions(state_dir=tmp_path / ".s"))
    return result


def test_call_din_of_a_written_program_with_default_paths_main_in_the_file_root_l1097(tmp_path: Path):
    result = _run(tmp_path / "files" / "gen.cpl", tmp_path)
    assert (tmp_path / "files" / "SUB1").exists()
    assert result["error"] is None, result["error"]
    assert result["variables"]["X"] == 12.5


def test_call_din_not_found_says_where_it_looked_l1097(tmp_path: Path):
    """If the default stays as it is, the refusal must at least say that SUB1 is in the file root but not on
    the program path (today: only 'sub-program not found: SUB1')."""
    result = _run(tmp_path / "gen.cpl", tmp_path)
    if result["error"] is not None:
        assert "program_path" in result["error"]["message"] or "file root" in result["error"]["message"], \
            result["error"]
