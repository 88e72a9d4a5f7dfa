"""SINUMERIK threads G33-G35 (CL 800 manual L7397, internal G group 0; issue 14 part 3: "the move's time
follows the spindle speed"; docs/sin800.md "Threads G33-G35": the lead I/J/K is modal, G34/G35 change it by F
per revolution, travel = lead*n +- F*n^2/2). Times below are computed by hand on a machine whose rapid
(60 m/min) and acceleration make the positioning moves take 0.01 s per 10 mm."""

from __future__ import annotations

import pytest
from review14_helpers import MACHINE

HEAD = "%MPF11\nN10 G71 G90 G94 G18\nN20 S600 M3\nN30 G0 X10 Z0\n"
PASS2 = "N45 G0 X20\nN46 Z0\nN47 X9.5\n"  # retract, back to the start, infeed for the second pass


def test_second_g34_pass_starts_at_the_programmed_lead(ncvm_run):
    """Two passes of the same increasing-lead thread, K1 F0.1 over 20 mm: each pass is
    n = (-1 + sqrt(1 + 2*0.1*20)) / 0.1 = 12.3607 revolutions = 1.23607 s at 600 rev/min. The second pass
    names no K, so the modal K1 applies (docs: the lead is modal) and cuts the same thread:
    2 * 1.23607 + 0.05 s of positioning = 2.5227 s (as ncvm gives with K1 written again). ncvm starts the
    second pass at the lead where the first one ended (2.236 mm), 0.764 s: after the G0 blocks a new pass
    silently cuts another thread over the first."""
    result, _, _ = ncvm_run("p.mpf", HEAD + "N40 G34 Z-20 K1 F0.1\n" + PASS2 + "N50 G34 Z-20 F0.1\nN99 M30\n")
    assert result["status"] == "ok", result["error"]
    assert result["cycle_time_s"] == pytest.approx(2.5227, abs=2e-3)


def test_thread_faster_than_the_axis_can_follow_is_not_silently_slowed(ncvm_run):
    """G33 Z-60 K2 at S3000: the axis must run 2 * 3000 = 6000 mm/min, the machine's Z allows 5000. On the
    control the spindle leads and the axis follows it; the thread of lead 2 cannot be cut (the 8xx stops
    with an alarm; time by the spindle: 30 revolutions = 0.6 s). ncvm caps the feed at 5000 mm/min, times
    the thread 0.72 s (a lead of 1.667 mm) and ends normally without a word: a silently wrong thread.
    Expected: an error, or at least a warning naming the thread."""
    slow_z = MACHINE.replace("max_feed = 60000.0", "max_feed = 5000.0")
    result, _, stderr = ncvm_run("p.mpf", "%MPF60\nN10 G71 G90 G94 G18\nN20 S3000 M3\nN30 G0 X10 Z0\n"
                                 "N40 G33 Z-60 K2\nN99 M30\n", machine=slow_z)
    assert result["status"] == "error" or "G33" in stderr, (result, stderr)
