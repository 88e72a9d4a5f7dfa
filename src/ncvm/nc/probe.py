"""Probing: a move toward a target that stops where the probe switches (LinuxCNC's STRAIGHT_PROBE).

The scenario says where the probe switches (machine coordinates of some axes); a measuring block's
straight move is cut there: :func:`trip_on_path` finds the switch point on the block's path,
:func:`stop_words` rewrites the block's axis words so the move ends at it. What was measured is a
:class:`ProbeLatch`; the control announces it to the sinks with the canon call ``probe`` just before
the move (:func:`announce`). Used by CPL's measuring blocks G75/G275/G375 and SINUMERIK's MEAS M.
"""

from __future__ import annotations

from ..records import Record


class ProbeLatch(Record):
    """What the last probe move measured: ``position`` holds the machine coordinates of the measured
    axes when the probe switched (by axis name), None when it did not switch; ``code`` is the measuring
    function that took it (the control's own number, e.g. CPL's G75)."""

    __slots__ = ("code", "position")

    def __init__(self, code: int = 0, position: dict[str, float] | None = None):
        self.code = code
        self.position = position


class OffPath(ValueError):
    """The probe event's position cannot be reached on the block's path (the message says why)."""


def trip_on_path(given: dict[str, float], start: dict[str, float], end: dict[str, float]) -> dict[str, float]:
    """Machine positions of the moving axes (``start`` -> ``end``) when the probe switches: those
    ``given`` names; the others on the block's straight path at the point the given ones locate."""
    pos = {n: float(v) for n, v in given.items() if n in start}
    known = next((n for n in pos if abs(end[n] - start[n]) > 1e-12), None)
    out = {}
    for name in start:
        if name in pos:
            out[name] = pos[name]
        elif known is None:
            raise OffPath(f"the probe event gives no position for axis {name}")
        else:
            t = (pos[known] - start[known]) / (end[known] - start[known])
            if not -1e-9 <= t <= 1.0 + 1e-9:
                raise OffPath(f"the probe position {known} = {pos[known]:g} is not on the block's path "
                              f"({start[known]:g} to {end[known]:g})")
            out[name] = start[name] + t * (end[name] - start[name])
    return out


def stop_words(kernel, words: dict, stop: dict[str, float]) -> None:
    """End a block's move where the axes of ``stop`` stop (machine coordinates): the block's axis words
    become the program position of that point (the other machine axes on the block's straight path there)
    under the kernel's offsets and transformation. Under a rotation a machine axis is another program axis:
    under a transformation each program axis whose position at that point is not where it stands gets its
    word, also one the block does not name (CPL G38 R90: a probe move in program X stops at a machine Y)."""
    names = kernel.axis_names
    start = dict(zip(names, kernel.machine_pos))
    end = _machine_end(kernel, words)
    try:
        switch = trip_on_path(stop, start, end)
    except OffPath:  # not on the path: the stopping axes where the event says, the others where they stand
        switch = {name: stop.get(name, p) for name, p in start.items()}
    target = kernel.program_position([switch[name] for name in names])
    for name, i in kernel.axis_of.items():
        if name in words or (kernel.transform is not None and abs(target[i] - kernel.prog[i]) > 1e-9):
            words[name] = (target[i] if kernel.absolute else target[i] - kernel.prog[i]) / kernel.unit_of(name)


def announce(canon, latch: ProbeLatch, src, target: dict[str, float] | None = None) -> None:
    """The canon call of a probe move, made just before its (cut) move goes out; ``target`` as in
    :meth:`ncvm.nc.canon.CanonSink.probe`."""
    canon.probe(None if latch.position is None else dict(latch.position), target, src)


def programmed_end(kernel, words: dict) -> dict[str, float]:
    """The machine end point of a block's straight move as programmed (before :func:`stop_words` cuts it),
    for the axes the block names."""
    end = _machine_end(kernel, words)
    return {name: v for name, v in end.items() if name in words}


def _machine_end(kernel, words: dict) -> dict[str, float]:
    """The machine end point of a block's straight move as programmed, every axis."""
    prog, _ = kernel._target(words, False)
    base = prog if kernel.transform is None else kernel.transform.forward(prog)
    return {name: base[i] + kernel.offset_vec[i] for name, i in kernel.axis_of.items()}
