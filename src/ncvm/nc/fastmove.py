"""The straight-move hot path (G0/G1), generated per machine with one unrolled line per axis.

Straight moves are most of what any program does, so the kernel compiles this
function once for its machine's axes instead of looping over axis lists:
target from the block's words, machine end point, and the move handed to the path planner
(:mod:`ncvm.nc.planner`) as one row of its deltas and feed: the planner works out the path
speed and acceleration of :func:`ncvm.nc.dynamics.path_limits` column-wise (same formula).
"""

from __future__ import annotations

import math


def make_linear(axis_names: tuple[str, ...], rotary: frozenset[str] = frozenset()):
    """``linear(kernel, motion, words, src)`` for these axes; same result as the general path. The words of
    the ``rotary`` axes are degrees in every unit: inch (``k.scale``) does not scale them."""
    n = len(axis_names)
    if n == 0:
        return lambda k, motion, words, src: None  # a controller without axes has nothing to move
    idx = range(n)
    lines = ["def linear(k, motion, words, src):",
             "    if k.spindle_bound:",
             "        k.spindle_update(src)  # G96: the speed for the radius here; G95: the feed for it",
             "    get = words.get",
             "    sc = k.scale",
             "    ab = k.absolute",
             f"    {', '.join(f'p{i}' for i in idx)}{',' if n == 1 else ''} = k.prog",
             "    moved = False"]
    for i, name in enumerate(axis_names):
        lines += [f"    v = get({name!r})",
                  "    if v is not None:",
                  "        moved = True",
                  *(() if name in rotary else ("        if sc != 1.0:", "            v *= sc")),
                  f"        p{i} = v if ab else p{i} + v"]
    lines += ["    if not moved:",
              "        return",
              f"    {', '.join(f'o{i}' for i in idx)}{',' if n == 1 else ''} = k.offset_vec",
              "    start = k.machine_pos",
              f"    {', '.join(f's{i}' for i in idx)}{',' if n == 1 else ''} = start",
              *(f"    e{i} = p{i} + o{i}" for i in idx),
              f"    end = ({', '.join(f'e{i}' for i in idx)},)",
              *(f"    d{i} = e{i} - s{i}" for i in idx),
              f"    length = _sqrt({' + '.join(f'd{i} * d{i}' for i in idx)})",
              "    if motion == 0:",
              "        v = _INF",
              "    else:",
              "        feed = k.feed",
              "        if feed <= 0.0:",
              "            k.fault('NC006', k.no_feed_message(1), src)",
              "        v = feed",
              "    if length > 0.0:",
              "        pl = k.planner",
              "        rows = pl.rows",
              f"        rows += (-1.0, v, 0.0, 3 if motion == 0 else k.exact, {', '.join(f'd{i}' for i in idx)})",
              "        if len(rows) > pl.limit:",
              "            pl.commit()",
              "    if motion == 0:",
              "        k.canon.rapid(start, end, src)",
              "    else:",
              "        k.canon.feed(start, end, feed, src)",
              f"    k.prog = [{', '.join(f'p{i}' for i in idx)}]",
              "    k.machine_pos = end"]
    namespace = {"_sqrt": math.sqrt, "_INF": math.inf}
    exec(compile("\n".join(lines) + "\n", f"<ncvm linear move {'/'.join(axis_names)}>", "exec"), namespace)
    return namespace["linear"]
