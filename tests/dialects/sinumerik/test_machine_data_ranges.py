"""Machine-file data the control has no room for, or cannot read as a byte, is refused before the run."""

from __future__ import annotations

import pytest
from sin800_helpers import machine, run_mpf

from ncvm.diagnostics import UsageError

PROG = "%MPF1\nN10 R1=1 M30\n"


@pytest.mark.parametrize("control, extra, message", [
    # 5002 is read at power-on (bit 4: inch): the run crashed with "bug in ncvm"
    ("880", 'nc_md = { "5002" = 1.5 }\n', r"key 'sin800\.nc_md\.5002' = 1\.5: address 5002 holds a byte \(1\.5 is not"),
    ("880", 'nc_md = { "5100" = 102 }\n', r"key 'sin800\.nc_md\.5100' = 102: address 5100 holds a byte"),
    ("880", 'nc_sd = { "5000" = 12 }\n', r"key 'sin800\.nc_sd\.5000' = 12: address 5000 holds a byte"),
    ("880", 'cycle_sd = { "900" = 3 }\n', r"key 'sin800\.cycle_sd\.900' = 3: address 900 holds a byte"),
    ("810", 'mib = { "300" = 1 }\n', r"key 'sin800\.mib\.300': the 810 has MIB 0-249"),
])
def test_data_the_control_cannot_hold_is_refused_naming_key_and_value(tmp_path, control, extra, message):
    with pytest.raises(UsageError, match=message):
        run_mpf(tmp_path, PROG, extra, machine_text=machine("XYZ", control))


@pytest.mark.parametrize("control, extra", [
    ("880", 'nc_md = { "5002" = "00010000", "2240" = 1.5, "5100" = 10010 }\nmib = { "499" = 7 }\n'),
    ("810", 'mib = { "249" = 7 }\ncycle_md = { "900" = 1.5 }\n'),  # cycle MD 900 may be a word
])
def test_data_within_the_control_loads(tmp_path, control, extra):
    run_mpf(tmp_path, PROG, extra, machine_text=machine("XYZ", control), ok=True)
