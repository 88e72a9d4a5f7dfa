"""The block skip ``/`` (DIN 66025; CPL and SINUMERIK alike): the operator's switch on the panel, the machine
file's ``[setting_data] block_skip``. Whether a ``/`` block ran is input from outside the program, so a
translation marks it FROZEN at the block (canon ``frozen``): its output has the path of the switch's
simulated setting (docs/translate.md)."""

from __future__ import annotations

from .canon import NOBODY, Src


def decision(on: bool) -> str:
    """What the switch decided for a ``/`` block, as a translation's FROZEN mark says it."""
    return (f"block skip '/' switched {'on' if on else 'off'} ([setting_data] block_skip = {str(on).lower()}): "
            f"this block is {'left out' if on else 'run'}")


def tell(canon, on: bool, src: Src) -> None:
    """A ``/`` block was met with the switch ``on`` (skipped) or off (run): a translation hears it."""
    if canon.frozen is not NOBODY:
        canon.frozen(decision(on), src)
