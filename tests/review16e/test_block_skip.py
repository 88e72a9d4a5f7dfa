"""Issue 16 item 3 "Say what was frozen: where the program's path depended on run-time input (operator
keys, ...) the output marks the block". The block skip `/` (docs/din.md; CPL and SINUMERIK alike) is the
operator's switch on the panel (machine file `[setting_data] block_skip`). The translation writes the
path of the switch's simulated setting and drops the `/`: a skipped block vanishes, a block run becomes
unconditional, and no comment says so. LinuxCNC, the 840D and Fanuc-style controls all read `/`; the
optional block must stay optional (`/` kept) or be marked FROZEN naming its line."""

from __future__ import annotations

import pytest

from tests.review16e.helpers import bare_machine, translate, write

SKIP_ON = bare_machine("skip mill", """\
[setting_data]
block_skip = {flag}
""")

DIN = "N10 G21 G90 G17 G54\nN20 G0 X0 Y0 Z5\n/N30 G0 X100\nN40 G1 Z-1 F100\nN50 M30\n"
CPL = "N10 G90 G17 G54\nN20 G0 X0 Y0 Z5\n/N30 G0 X100\nN40 G1 Z-1 F100\nN50 M30\n"


@pytest.mark.parametrize("target", ["linuxcnc", "sinumerik840d", "iso"])
@pytest.mark.parametrize("flag", ["true", "false"])
@pytest.mark.parametrize(("name", "program"), [("skip.din", DIN), ("skip.cpl", CPL)], ids=["din", "cpl"])
def test_block_skip_kept_or_marked(tmp_path, name, program, flag, target):
    write(tmp_path, {"machine.toml": SKIP_ON.format(flag=flag), name: program})
    rc, out, err = translate(tmp_path, name, "-m", "machine.toml", "--target", target)
    assert rc == 0, err
    lines = out.splitlines()
    kept = any(line.startswith("/") and "X100" in line for line in lines)
    marked = any("FROZEN" in line and f"{name}:3" in line for line in lines)
    assert kept or marked, out
