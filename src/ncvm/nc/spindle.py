"""The spindle's gear stages: each control's gear M functions as data, one gearbox model.

The NC kernel runs the spindle itself (S, M3/M4/M5, G96/G97 with ``kernel.max_speed`` as the speed
limit under G96). A gear stage sets that limit: M41, M42 ... select stage 1, 2 ..., M40 lets the
control choose the stage from the commanded speed, and CPL's M48 puts the gearbox in neutral. Which M
functions a control has is its :class:`GearTable` (CPL: M40-M44, M48; SINUMERIK: M40-M45); the maximum
speed of each stage comes from the machine file (SINUMERIK ``[sin800] gears``; CPL records the M
function for MCODS 64/66 and sets no limit).
"""

from __future__ import annotations

from ..records import FrozenRecord

#: stage numbers of a gear table beside 1, 2, ...: chosen from the speed (M40), neutral (CPL M48)
AUTO, NEUTRAL = 0, -1


class GearTable(FrozenRecord):
    """A control's gear M functions: M number -> stage (1.., :data:`AUTO` or :data:`NEUTRAL`)."""

    __slots__ = ("stages",)

    def __init__(self, stages: dict[int, int]):
        self.stages = stages

    @property
    def codes(self) -> frozenset[int]:
        """The gear M numbers (a block with one of them is a gear change)."""
        return frozenset(self.stages)

    def is_auto(self, m: int) -> bool:
        """``m`` lets the control choose the stage from the speed (M40)."""
        return self.stages.get(m) == AUTO


#: CPL (manual §4, MCODS 64-67): M40 automatic gear range, M41-M44 gear 1-4, M48 neutral
CPL_GEARS = GearTable({40: AUTO, 41: 1, 42: 2, 43: 3, 44: 4, 48: NEUTRAL})
#: SINUMERIK (docs/decisions.md): M40 automatic, M41-M45 stage 1-5
SINUMERIK_GEARS = GearTable({40: AUTO, 41: 1, 42: 2, 43: 3, 44: 4, 45: 5})


class Gearbox:
    """The active gear stage of the master spindle and the speed limit it sets for G96.

    ``maxima``: the maximum speed (rev/min) of stage 1, 2, ...; without them no stage limits the speed.
    ``error(message)`` builds the control's own error for a stage the maxima do not cover; ``source`` names
    where the maxima come from (for that message)."""

    def __init__(self, kernel, table: GearTable, stage: int, maxima: list[float], error=ValueError,
                 source: str = "the gear table"):
        self.kernel = kernel
        self.table = table
        self.maxima = maxima
        self.error = error
        self.source = source
        self.auto = False
        self.stage = stage
        self._limit()

    def select(self, m: int) -> None:
        """An executed gear M function (``m`` in the table)."""
        stage = self.table.stages[m]
        if stage == NEUTRAL:  # no control that limits the speed by stage has a neutral M function
            raise self.error(f"M{m}: a neutral gear stage is not simulated")
        if stage == AUTO:
            self.auto = True
        else:
            if self.maxima and stage > len(self.maxima):
                raise self.error(f"M{m}: gear stage {stage} has no maximum speed in {self.source}")
            self.auto = False
            self.stage = stage
        self._limit()

    def active(self) -> int:
        """Under M40 the lowest stage whose maximum speed reaches the commanded speed (else the top one)."""
        if self.auto and self.maxima:
            speed = abs(self.kernel.spindle_speed())
            self.stage = next((i for i, top in enumerate(self.maxima, 1) if speed <= top), len(self.maxima))
        return self.stage

    def _limit(self) -> None:
        k = self.kernel
        if not self.maxima:
            return
        k.max_speed = max(self.maxima) if self.auto else self.maxima[self.stage - 1]
