"""The card's scheduler carries out scenario events (machine/scenario.EventQueue, seconds) and its own
timed actions (ticks) in one time order, an event before an action of the same tick."""

from __future__ import annotations

import math
from types import SimpleNamespace

from ncvm.dialects.sympas.motion import TICKS_PER_S
from ncvm.dialects.sympas.options import Options
from ncvm.dialects.sympas.scheduler import Scheduler
from ncvm.machine.scenario import CommonInteger, EventQueue


def _scheduler() -> Scheduler:
    card = SimpleNamespace(cfg=Options(), axes=[])
    return Scheduler(card, card.cfg, SimpleNamespace(limit=10 ** 9, steps=0))


def test_events_and_timed_actions_in_one_time_order():
    sched = _scheduler()
    done = []
    sched.set_events(EventQueue([CommonInteger(2.0, index=2), CommonInteger(1.0, index=1)]),
                     lambda ev: done.append(f"event {ev.index}"))
    sched.add_timed(1.5 * TICKS_PER_S, lambda: done.append("action 1.5"))
    sched.add_timed(1.0 * TICKS_PER_S, lambda: done.append("action 1"))
    assert sched.next_timed() == 1.0 * TICKS_PER_S
    sched.apply_timed(1.6 * TICKS_PER_S)
    assert done == ["event 1", "action 1", "action 1.5"] and sched.timed_done == 3
    assert sched.next_timed() == 2.0 * TICKS_PER_S
    sched.apply_timed(math.inf)
    assert done[-1] == "event 2" and sched.next_timed() == math.inf
    sched.apply_timed(math.inf)  # nothing left: nothing happens
    assert sched.timed_done == 4


def test_the_queue_pops_its_next_event():
    a, b = CommonInteger(3.0, index=1), CommonInteger(1.0, index=2)
    q = EventQueue([a, b])
    assert q.pop() == b and q.next_time() == 3.0 and q.pop() == a and not q
