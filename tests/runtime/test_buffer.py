"""The block buffer: prepared blocks wait, the oldest execute when it overflows, WAIT / STOP DEC drain it."""

from __future__ import annotations

from ncvm.runtime.buffer import BlockBuffer


def test_a_look_ahead_executes_the_oldest_block_once_more_than_ahead_wait():
    done: list = []
    buf = BlockBuffer(2, done.append)
    assert [buf.put(n) for n in range(5)] == [False, False, True, True, True]
    assert done == [0, 1, 2] and list(buf) == [3, 4] and buf.executed == 3


def test_a_bulk_buffer_spills_its_older_half_together():
    runs: list = []
    buf = BlockBuffer(9, None, spill=5, execute_many=runs.append)
    for n in range(12):
        buf.put(n)
    assert runs == [[0, 1, 2, 3, 4]] and list(buf) == [5, 6, 7, 8, 9, 10, 11] and buf.executed == 5
    buf.drain()
    assert runs[-1] == [5, 6, 7, 8, 9, 10, 11] and not buf and buf.executed == 12
    buf.drain()  # an empty buffer drains too (the WAIT still brings the program's time forward)
    assert runs[-1] == []


def test_draining_one_by_one_leaves_the_later_blocks_waiting_while_each_executes():
    seen: list = []
    buf = BlockBuffer(10, lambda blk: seen.append((blk, list(buf))))
    for n in range(3):
        buf.put(n)
    buf.drain()
    assert seen == [(0, [1, 2]), (1, [2]), (2, [])] and buf.executed == 3


def test_executing_the_oldest_one_by_one_stops_at_an_empty_buffer():
    done: list = []
    buf = BlockBuffer(10, done.append)
    buf.put("a")
    buf.put("b")
    buf.execute_oldest(5)
    assert done == ["a", "b"] and not buf
