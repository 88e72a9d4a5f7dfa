"""Durations as the summary line and the plot title show them."""

from __future__ import annotations


def hms(seconds: float) -> str:
    """``m:ss.sss``, or ``h:mm:ss.sss`` from an hour on."""
    m, s = divmod(seconds, 60.0)
    h, m = divmod(int(m), 60)
    return f"{h}:{m:02d}:{s:06.3f}" if h else f"{m}:{s:06.3f}"
