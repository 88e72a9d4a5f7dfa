"""Checks of a run's motion, and how a front end registers one without knowing the sinks.

The API builds the toolpath recorder and the soft-limit check (sinks/) and hands the session a
:class:`Checks`; a front end adds its own through it: a :class:`MotionCheck` it built itself, or the
control's protection zones (:class:`Area`, e.g. CPL work areas and dead ranges, manual ch. 4), which
the check the API supplied watches. Each check is told of the recorded moves a window at a time and
reports its first violations at the end, in ``limit_violations``; the run goes on.
"""

from __future__ import annotations

from typing import Any, Callable, NamedTuple, Protocol, Sequence

from .. import records
from ..nc.canon import Src
from ..records import Record

DEAD, WORK = "dead range", "work area"


class Area(NamedTuple):
    """A protection zone: an axis-parallel rectangle ``centre ± size / 2`` on two machine axes (machine
    coordinates, mm). A move may not enter a DEAD one nor leave a WORK one."""

    number: int  # 1.. as the control counts them
    kind: str  # DEAD or WORK
    axes: tuple[str, str]
    centre: tuple[float, float]
    size: tuple[float, float]


class Violation(Protocol):
    """One reported violation: where it happened first and what it was. A dataclass with a ``file`` is
    reported at its place in the user's source and under the program's axis name (Checks.violations)."""

    line: int

    def message(self) -> str: ...


class MotionCheck(Protocol):
    """A check of the recorded moves: it asks the recorder to show it them (``recorder.watch(check)``)."""

    def observe(self, moves: Any, lo: int, hi: int) -> None:
        """Moves ``lo``..``hi`` of the recorder's window (``moves.window()``, ``moves.src(i)`` ...)."""
        ...

    def first(self) -> Sequence[Violation]:
        """The first violation of each thing checked, in program order (every move seen)."""
        ...


#: builds the check of some areas on the machine axes named (the API supplies it: sinks.areas.zone_check)
AreaCheckFactory = Callable[[Sequence[Area], Sequence[str]], MotionCheck]


class Checks:
    """The checks of one run, reported in the order they were added."""

    def __init__(self, area_check: AreaCheckFactory | None = None):
        self._area_check = area_check
        self._checks: list[MotionCheck] = []

    def add(self, check: MotionCheck) -> None:
        self._checks.append(check)

    def add_areas(self, areas: Sequence[Area], axis_names: Sequence[str]) -> None:
        """Watch the moves for ``areas`` from now on (before the first move: the start is not checked)."""
        if not areas:
            return
        if self._area_check is None:  # a session built without sinks records no moves: say so, never pass silently
            raise RuntimeError("this session records no moves: protection zones cannot be checked")
        self.add(self._area_check(areas, axis_names))

    def violations(self, place: Callable[[Src], Src] | None = None,
                   labels: dict[str, str] | None = None) -> list[Violation]:
        """Every check's first violations, check by check; ``place`` maps where each happened (a ``Src``)
        to where it stands in the user's source (``Session.source_place``), ``labels`` the machine's axis
        names to the program's (``Session.axis_labels``)."""
        return [_as_reported(v, place, labels) for check in self._checks for v in check.first()]


def _as_reported(v: Any, place: Callable[[Src], Src] | None, labels: dict[str, str] | None) -> Any:
    """Violation ``v`` at its place in the source and under the program's axis name; one that names an
    axis so says it is in machine coordinates, where limits are."""
    record = isinstance(v, Record)
    if not (record or hasattr(type(v), "__dataclass_fields__")) or not hasattr(v, "file"):  # is_dataclass
        return v  # a front end's own report that names no place
    changes: dict[str, Any] = {}
    if place is not None:
        src = place(Src(v.file, v.line))
        changes.update(file=src.file, line=src.line)
    if labels and "axis" in (v._fields() if record else type(v).__dataclass_fields__):
        changes.update(axis=labels.get(v.axis, v.axis), frame="machine")
    if not changes:
        return v
    if record:
        return records.replace(v, **changes)
    import dataclasses  # a front end's dataclass violation: its module imported dataclasses (start-up)

    return dataclasses.replace(v, **changes)
