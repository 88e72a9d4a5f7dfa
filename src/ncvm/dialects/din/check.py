"""``ncvm check`` of a DIN program a stretch at a time, as the run reads it (issue 18: a file of any length is
checked in bounded memory): every stretch's syntax errors, words for axes the machine lacks and block rules
broken go into a :class:`~ncvm.diagnostics.Diagnostics` (the first of them kept, the rest counted); what
is said once per program (the LinuxCNC extensions, the G functions and addresses the run refuses, the tools
the machine lacks) is gathered on the way and said at the end, each at its first block."""

from __future__ import annotations

from ...diagnostics import Diagnostic, Diagnostics
from ...nc.axiswords import din_missing_axes
from ...nc.toolcheck import ToolChanges
from .ngc import Extensions
from .support import Unsupported, block_errors, tool_blocks

# Diagnostics at the same place keep the order of the check that held the program whole: the folded
# extensions and the syntax errors, then the missing axes, the refused functions, the block rules, the tools.
_NC013, _SYNTAX, _AXES, _REFUSED, _RULES, _TOOLS = range(6)


def check_stretches(path: str, stretches, machine, profile, tape=None) -> Diagnostics:
    """The diagnostics of the program ``stretches`` (:class:`~ncvm.nc.block.DinStretch` es from its start), in
    line order; with what its ``tape`` marks say at the end (:class:`~ncvm.dialects.din.tape.Tape`, which the
    stretches went through: a program cut short, lines after its closing %)."""
    axes = machine.axis_names
    extensions = Extensions()
    refused = Unsupported(path, axes, profile)
    tools = ToolChanges(path, machine.tools)
    out = Diagnostics()  # counts what is left out as it goes
    kept = []  # (rank, diagnostic) in line order, the first out.limit of them
    said_once = []
    for stretch in stretches:
        line_at = stretch.line
        found = [(_SYNTAX, d) for d in stretch.diags if not extensions.take(d, line_at)]
        found += [(_AXES, d) for _i, _row, d in din_missing_axes(path, line_at, stretch.segments, axes)]
        found += [(_RULES, d) for d in block_errors(path, stretch.segments, line_at, axes, profile)]
        found.sort(key=_place)
        room = max(0, out.limit - len(kept))
        kept += found[:room]
        out.count_out(d for _rank, d in found[room:])
        refused.add(stretch.segments, line_at)
        said_once += [(_TOOLS, d) for d in tools.warnings(tool_blocks(stretch.segments, line_at))]
    folded = extensions.folded()
    said_once += [(_NC013, folded)] if folded is not None else []
    said_once += [(_REFUSED, d) for d in refused.warnings()]
    said_once += [(_SYNTAX, d) for d in (tape.diagnostics() if tape is not None else ())]
    merged = sorted(kept + said_once, key=_place)
    out.extend(d for _rank, d in merged[:out.limit])
    out.count_out(d for _rank, d in merged[out.limit:])
    return out


def _place(pair: tuple[int, Diagnostic]):
    rank, d = pair
    return d.span.line, d.span.column or 0, rank
