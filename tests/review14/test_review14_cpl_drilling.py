"""CPL: G81 calls the drilling cycle 99999081 (CPL manual §3.1 L1075), a modal sub-program that "will
continue to be automatically executed after each traversing movement prescribed by a DIN block" (§3.2
L1083) until G80. A block that does not traverse must not drill again."""

from __future__ import annotations

from review14_helpers import moves

CYCLE = "N1 G91\nN2 G1 Z[P1] F[P2]\nN3 G0 Z[-P1]\nN4 G90\nN5 M30\n"
HEAD = "N10 G90 G17 G94\nN20 S1000 M3\nN30 G0 X0 Y0 Z10\nN40 G81 [-5, 100] X10\n"


def _holes(ncvm_run, between: str) -> list[float]:
    result, rows, _ = ncvm_run("main.cpl", HEAD + between + "N60 G80 X30\nN70 M30\n", {"99999081": CYCLE})
    assert result["status"] == "ok", result["error"]
    return [m[1] for m in moves(rows) if m[4] == "99999081" and m[0] == "feed"]


def test_g92_set_actual_value_block_does_not_drill(ncvm_run):
    """G92 is "set actual value" on the Typ3 osa (L2813, the AXO example L1402 ``N20 G92 X75 Y125``): it
    shifts, nothing moves. ``N45 G92 X0`` after the hole at X10, then ``N50 X5`` (= X15 on the machine):
    two holes. ncvm drills X10 a second time at the G92 block: three."""
    assert _holes(ncvm_run, "N45 G92 X0\nN50 X5\n") == [10.0, 15.0]


def test_dwell_block_does_not_drill(ncvm_run):
    """``N45 G4 X1`` is a dwell of 1 s (ncvm reads G4's time from X, docs/decisions.md "Dwell word"): no
    traversing movement, so no cycle. ncvm dwells and then drills the hole at X10 again (the SINUMERIK front
    end keeps ``G04 X1`` from drilling)."""
    assert _holes(ncvm_run, "N45 G4 X1\nN50 X20\n") == [10.0, 20.0]


def test_a_new_cycle_selection_replaces_the_old_one_at_its_block(ncvm_run):
    """``N50 G84 [-8, 100] X30`` while G81 is modal: the new modal call replaces the old one (§3.2 L1083, "until
    they are deselected"; docs/cpl.md: "a new G81..G86 block transfers new ones"; docs/decisions.md: "A new
    selection while one is active replaces it before its call runs"). At X30 only 99999084 (tapping) runs.
    ncvm first runs the old drilling cycle 99999081 at X30 with the tap in the spindle, then 99999084."""
    result, rows, _ = ncvm_run("main.cpl", "N10 G90 G17 G94\nN20 S1000 M3\nN30 G0 X0 Y0 Z10\n"
                               "N40 G81 [-5, 100] X10\nN50 G84 [-8, 100] X30\nN60 G80 X40\nN70 M30\n",
                               {"99999081": CYCLE, "99999084": CYCLE})
    assert result["status"] == "ok", result["error"]
    cycles = [(m[1], m[4], m[3]) for m in moves(rows) if m[4].startswith("9999908") and m[0] == "feed"]
    assert cycles == [(10.0, "99999081", 5.0), (30.0, "99999084", 2.0)], cycles


def test_reselecting_g81_with_new_parameters_drills_once(ncvm_run):
    """``N55 G81 [A, 100] X30`` with A changed from -5 to -8: one hole at X30 with the new depth (Z2).
    ncvm drills X30 twice: with the old parameters (Z5), then with the new ones (Z2)."""
    result, rows, _ = ncvm_run("main.cpl", "N10 G90 G17 G94\nN20 S1000 M3\nN30 G0 X0 Y0 Z10\n10 A = -5\n"
                               "N40 G81 [A, 100] X10\n20 A = -8\nN50 X20\nN55 G81 [A, 100] X30\nN60 G80 X40\n"
                               "N70 M30\n", {"99999081": CYCLE})
    assert result["status"] == "ok", result["error"]
    holes = [(m[1], m[3]) for m in moves(rows) if m[4] == "99999081" and m[0] == "feed"]
    assert holes == [(10.0, 5.0), (20.0, 5.0), (30.0, 2.0)], holes
