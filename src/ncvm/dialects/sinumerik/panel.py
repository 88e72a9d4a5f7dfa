"""Main group a: the operator panel and the V24 port (@a15-@a40; manual §5.3.9, L4440-4560).

WRT PIC / RECALL PIC / CHAN act on the operator panel (shown in the output); PORT, OUTP ... and INP on the
V24 port, in the tape format of v24.py. Without PORT the interface selected at the operator panel is used.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from . import v24
from .errors import Cl800Error
from .ncdata import in_range as _rng
from .ncdata import whole as _i

if TYPE_CHECKING:
    from .runtime import Channel


class Panel:
    """``menus``: the menus WRT PIC called, for RECALL PIC; ``v24``: the lines output on the V24 port."""

    def __init__(self, channel: Channel):
        self.channel = channel
        self.menus: list[str] = []
        self.v24: list[str] = []

    def io(self, code: str, args: tuple) -> None:
        ch = self.channel
        say = ch.session.say
        if code == "a15":
            sector = ("user", "standard")[_rng("sector (0 user / 1 standard)", args[0], 0, 1)]
            self.menus.append(f"{sector} menu {_rng('menu number', args[1], 1, 254)}")
            say(f"[panel] {self.menus[-1]}")
        elif code == "a1b":
            if len(self.menus) > 1:
                self.menus.pop()
                say(f"[panel] {self.menus[-1]}")
            elif self.menus:
                self.menus.pop()
                say("[panel] the display shown before the first WRT PIC")
        elif code == "a40":
            say(f"[panel] channel {_rng('channel', args[0], 1, 16)}")
        elif code == "a20":
            self.v24.append(f"PORT {_rng('V24 interface', args[0], 1, 4)}")
        elif code == "a25":
            n = _rng("channel", args[0], 0, 16)
            if n:
                ch.memory.own_channel(n)
            self.v24.extend(v24.zo_lines(ch.data, ch.session.machine.offset, ch.kernel.axis_names, n))
        elif code == "a26":
            folders = ch.session.machine.program_path
            self.v24.extend(v24.data_lines(ch.data, lambda kind, a, b: v24.find_programs(folders, kind, a, b),
                                           _i(args[0]), _i(args[1]), _i(args[2])))
        elif code == "a27":
            ch.memory.own_channel(args[0])
            lo, hi = _rng("R number", args[1], 0, 999), _rng("R number", args[2], 0, 999)
            for n in range(lo, hi + 1):
                self.v24.append(f"R{n}={v24.fmt(ch.R[n])}")
        elif code == "a28":
            v24.read_in(ch, _i(args[0]), ch.data.v24_input)
            ch.data.v24_input = ""
        elif code == "a29":
            self.v24.append("\x03")
        else:
            raise Cl800Error(f"@{code} is not available")
