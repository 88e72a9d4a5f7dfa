"""Plain DIN 66025 / ISO 6983 programs: read every block, then run them through the kernel."""

from __future__ import annotations

import re

from ...diagnostics import CompileFailed
from ...nc.block import read_din_program
from ..base import Dialect

_DIN_LINE = re.compile(r"^\s*(N\d+\s*)?([GMXYZFST]-?\d|\(|%|/|$)", re.I)


class DinDialect(Dialect):
    id = "din"
    title = "plain DIN 66025 / ISO 6983"
    extensions = (".din", ".ngc", ".nc", ".iso")

    def sniff(self, text: str) -> int:
        lines = [ln for ln in text.splitlines()[:200] if ln.strip()]
        if not lines:
            return 0
        hits = sum(1 for ln in lines if _DIN_LINE.match(ln))
        return int(100 * hits / len(lines))

    def check(self, path, text, machine, all_errors=False):
        return read_din_program(path, text)[1]

    def run(self, path, text, session):
        blocks, diags = read_din_program(path, text)
        if diags:
            raise CompileFailed(diags)
        execute = session.kernel.execute
        kernel = session.kernel
        skip_active = bool(session.machine.setting_data.get("block_skip", True))
        counter = session.steps
        limit = counter.limit - counter.steps
        hook = counter.hook  # single-block stepping and breakpoints; None unless a debugger is attached
        done = 0
        try:
            for blk, skip in blocks:
                if skip and skip_active:
                    continue
                done += 1
                if done > limit:
                    done -= 1
                    counter.runaway(blk.src.file, blk.src.line)
                if hook is not None:
                    hook(blk.src.file, blk.src.line, kernel.workpiece_position())
                execute(blk)
                if kernel.ended:
                    break
        finally:
            counter.steps += done
        if not kernel.ended and blocks:
            kernel.end_program(blocks[-1][0].src)


DIALECT = DinDialect()
