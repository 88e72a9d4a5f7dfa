"""A G58/G59 block: its axis words are the programmable zero offset, its other words keep their meaning.

G58/G59 (the programmable zero offset ZOPR, group 1 = G58, 2 = G59, L3207-3214, L6657) belong to the
control's internal G group 6 with G04, G92 and G74 (L7388-7431): block-wise functions whose axis words are
their data. Before, a feed in such a block stopped the run with "G58: F is not an axis"; the manual gives
the F word (and S, M, T, D) its meaning in any block, so `G58 X10 F100` sets the offset and the feed
(docs/decisions.md, "G58/G59 blocks").
"""

from __future__ import annotations

from sin800_helpers import run_mpf


def test_g58_block_with_a_feed_sets_offset_and_feed_L7388(tmp_path):
    r = run_mpf(tmp_path, "%MPF1\nN10 G58 X10 F100\nN20 G1 X5\nN30 M30\n", ok=True)
    assert r["position"]["X"] == 5.0
    assert r["motion"]["bounds"]["X"] == [0.0, 15.0]  # the move ends at 10 + 5 in machine coordinates
    assert abs(r["cycle_time_s"] - 9.0) < 0.01  # 15 mm at the F100 of the G58 block: 9 s


def test_g59_block_with_spindle_and_m_words_L7388(tmp_path):
    r = run_mpf(tmp_path, "%MPF1\nN10 G59 Y-4 S500 M3 F200\nN20 G1 Y6\nN30 M30\n", ok=True)
    assert r["position"]["Y"] == 6.0
    assert r["motion"]["bounds"]["Y"] == [0.0, 2.0]
    assert abs(r["cycle_time_s"] - 0.6) < 0.01  # 2 mm at F200


def test_g58_axis_words_do_not_move_L3207(tmp_path):
    r = run_mpf(tmp_path, "%MPF1\nN10 G58 X10 Y3 F100\nN20 M30\n", ok=True)
    assert r["motion"]["feed_moves"] == 0 and r["motion"]["rapid_moves"] == 0
    assert r["position"] == {"X": -10.0, "Y": -3.0, "Z": 0.0}
