"""Stops (§6.6): JS/JSW with the axes' sdec, MS/MSW on the path."""

from __future__ import annotations

from .common import then_wait


def _stop(card, tk, axes, wait: bool, path: bool):
    t = tk.time
    for ax in axes:
        a = card.check_axis(ax)
        mv = a.move
        if mv is not None and mv.t1 > t:
            if path and card.sys["MODEREG"] & 0x8000:
                f, ts = card.units(tk)
                dec = tk.sysp["TRAC"] * f / (ts * ts)
            else:
                dec = min(card.axes[x].q["sdec"] for x in mv.axes)
            mv.stop(t, dec)
            for x in mv.axes:
                card.axes[x].target = mv.final()[mv.axes.index(x)]
        a.spool.clear()
    return then_wait(card, tk, axes, wait)


def js(card, tk, axes, loc):
    return _stop(card, tk, axes, False, False)


def jsw(card, tk, axes, loc):
    return _stop(card, tk, axes, True, False)


def ms(card, tk, axes, loc):
    return _stop(card, tk, axes, False, True)


def msw(card, tk, axes, loc):
    return _stop(card, tk, axes, True, True)


#: the commands of this group by name (codegen calls them as _C_<name>)
COMMANDS = {"js": js, "jsw": jsw, "ms": ms, "msw": msw}
