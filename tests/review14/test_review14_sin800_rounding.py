"""The SINUMERIK radius address on a straight block rounds the corner to the next straight block (CL 800
manual §5.3.8.2, the contour ``N5 X400 Y50 B100`` L4237; docs/sin800.md "Contour roundings"); where ncvm
cannot make the rounding it stops with NC009, and the message must name the real reason."""

from __future__ import annotations

HEAD = "%MPF12\nN10 G71 G90 G94 G17\nN30 G0 X750 Y50 Z0\nN40 G1 X400 Y50 B100 F1000\n"


def _stop(ncvm_run, between: str) -> str:
    result, _, _ = ncvm_run("p.mpf", HEAD + between + "N50 X300 Y300\nN99 M30\n")
    assert result["status"] == "error" and result["error"]["code"] == "NC009", result
    return result["error"]["message"]


def test_m_function_block_between_is_named_not_called_a_zero_length_line(ncvm_run):
    """The manual's corner (L4237: 350 mm along X, then 269.3 mm to X300 Y300) with ``N45 M8`` between.
    ncvm refuses (acceptable) but says "a rounding needs two lines of non-zero length", although both lines
    are long: the user looks for a geometry fault that is not there. A ``G4 X1`` block between gets the
    right message ("block N45 has G or M functions a rounding does not pass"); M8 should be named the same."""
    message = _stop(ncvm_run, "N45 M8\n")
    assert "non-zero length" not in message and "N45" in message, message


def test_feed_only_block_between_is_named_not_called_a_zero_length_line(ncvm_run):
    """``N45 F500`` between the two lines of the manual's corner: the same misleading "two lines of
    non-zero length"; the block that stops the rounding is N45."""
    message = _stop(ncvm_run, "N45 F500\n")
    assert "non-zero length" not in message and "N45" in message, message
