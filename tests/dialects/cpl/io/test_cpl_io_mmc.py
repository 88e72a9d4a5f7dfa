"""Chapter 9 MMC: no client gives 1; an attached client answers and may change the variables."""

from __future__ import annotations

import pytest

from ncvm.dialects.cpl.io.errors import CplRuntimeError
from ncvm.dialects.cpl.io.mmc import Mmc
from ncvm.dialects.cpl.io.strings import CharacterField

NAMES = ["PROGNAME$", "INTPAR%", "REALPAR"]


def example_values():
    # L5209-5217: DIM PROGNAME$(50): PROGNAME$="WinProg": INTPAR%=1: REALPAR=1.1
    prog = CharacterField(50)
    prog.assign("WinProg")
    return [prog.text, 1, 1.1]


def test_d10_no_client_answers_1_and_leaves_the_variables():
    mmc = Mmc()
    rc, values = mmc.MMC(NAMES, example_values())
    assert rc == 1 and values == ["WinProg", 1, 1.1]


def test_d10_client_round_trip():
    seen = {}

    def client(names, values):
        seen.update(zip(names, values))
        return 0, {"INTPAR%": 2, "UNKNOWN": 5}

    mmc = Mmc()
    mmc.attach(client)
    rc, values = mmc.MMC(NAMES, example_values())
    assert rc == 0 and values == ["WinProg", 2, 1.1]
    assert seen == {"PROGNAME$": "WinProg", "INTPAR%": 1, "REALPAR": 1.1}
    # IF I% = 0 THEN IF INTPAR% = 2 THEN ... : the program sees the client's value
    assert values[NAMES.index("INTPAR%")] == 2
    mmc.attach(None)
    assert mmc.MMC(NAMES, example_values())[0] == 1
    assert [c[2] for c in mmc.calls] == [0, 1]


def test_client_errors_give_2():
    def broken(names, values):
        raise RuntimeError("client crashed")

    assert Mmc(broken).MMC(["A"], [1]) == (2, [1])
    assert Mmc(lambda n, v: (7, {"A": 3})).MMC(["A"], [1]) == (2, [1])
    assert Mmc(lambda n, v: (2, {"A": 3})).MMC(["A"], [1]) == (2, [1])  # only "ok" writes back


def test_at_most_20_variables():
    names = [f"V{i}%" for i in range(21)]
    with pytest.raises(CplRuntimeError) as err:
        Mmc().MMC(names, list(range(21)))
    assert err.value.code == "CPL901"
    assert Mmc().MMC(names[:20], list(range(20)))[0] == 1
