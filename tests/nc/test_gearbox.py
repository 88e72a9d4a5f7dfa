"""The gearbox model (nc/spindle.py): each control's gear M functions as data, the G96 limit a stage sets."""

from __future__ import annotations

import math

import pytest

from ncvm.nc.spindle import CPL_GEARS, SINUMERIK_GEARS, Gearbox


def test_each_control_has_its_own_gear_m_functions():
    assert CPL_GEARS.codes == {40, 41, 42, 43, 44, 48}  # M48 neutral, no M45
    assert SINUMERIK_GEARS.codes == {40, 41, 42, 43, 44, 45}
    assert CPL_GEARS.is_auto(40) and not CPL_GEARS.is_auto(41) and not CPL_GEARS.is_auto(48)


class Spindle:
    def __init__(self, speed: float):
        self.speed, self.max_speed = speed, math.inf

    def spindle_speed(self) -> float:
        return self.speed


def test_a_stage_sets_the_speed_limit_and_m40_chooses_it_from_the_speed():
    k = Spindle(-900.0)
    box = Gearbox(k, SINUMERIK_GEARS, 1, [500.0, 1000.0, 4000.0])
    assert k.max_speed == 500.0
    box.select(43)
    assert (box.active(), k.max_speed) == (3, 4000.0)
    box.select(40)
    assert (box.active(), k.max_speed) == (2, 4000.0)  # the lowest stage reaching 900 rev/min; limit: the top
    with pytest.raises(ValueError, match="M45: gear stage 5 has no maximum speed in the gear table"):
        box.select(45)


def test_without_maxima_no_stage_limits_the_speed_and_neutral_is_refused():
    k = Spindle(100.0)
    box = Gearbox(k, CPL_GEARS, 1, [])
    box.select(44)
    assert (box.active(), k.max_speed) == (4, math.inf)
    with pytest.raises(ValueError, match="M48: a neutral gear stage is not simulated"):
        box.select(48)
