"""The canon fan-out: sinks given at construction, listeners added and removed while a run goes on."""

from __future__ import annotations

import numpy as np

from ncvm.nc.canon import Canon, CanonSink, MoveBatch, Src

SRC = Src("p.nc", 1)


class Log(CanonSink):
    """Records the calls it overrides, tagged with its name, into a shared list."""

    def __init__(self, name: str, log: list):
        self.name, self.log = name, log

    def rapid(self, start, end, src):
        self.log.append((self.name, "rapid", end))

    def message(self, text, src):
        self.log.append((self.name, "message", text))


class Messages(CanonSink):
    def __init__(self, log: list):
        self.log = log

    def message(self, text, src):
        self.log.append(("messages", "message", text))


def test_listeners_are_called_after_the_sinks_in_the_order_added():
    log: list = []
    canon = Canon([Log("sink", log)])
    canon.add(Log("first", log))
    canon.add(Log("second", log))
    canon.message("hello", SRC)
    canon.rapid((0.0,), (1.0,), SRC)
    assert log == [("sink", "message", "hello"), ("first", "message", "hello"), ("second", "message", "hello"),
                   ("sink", "rapid", (1.0,)), ("first", "rapid", (1.0,)), ("second", "rapid", (1.0,))]


def test_a_listener_takes_only_the_calls_it_overrides():
    log: list = []
    canon = Canon([Log("sink", log)])
    rapid_before = canon.rapid
    canon.add(Messages(log))
    assert canon.rapid is rapid_before  # the motion calls stay bound straight to the one sink
    canon.rapid((0.0,), (2.0,), SRC)
    canon.message("m", SRC)
    assert log == [("sink", "rapid", (2.0,)), ("sink", "message", "m"), ("messages", "message", "m")]


def test_removing_a_listener_restores_the_calls_without_it():
    log: list = []
    sink = Log("sink", log)
    canon = Canon([sink])
    listener = canon.add(Log("listener", log))
    canon.remove(listener)
    assert canon.rapid == sink.rapid and canon.listeners == []
    canon.message("x", SRC)
    assert log == [("sink", "message", "x")]


def test_a_canon_without_receivers_ignores_calls_and_a_listener_alone_is_bound_directly():
    log: list = []
    canon = Canon([])
    canon.message("nobody", SRC)
    listener = canon.add(Log("only", log))
    assert canon.message == listener.message
    canon.message("one", SRC)
    assert log == [("only", "message", "one")]


def test_a_batch_of_moves_reaches_a_motion_listener_as_single_calls():
    log: list = []
    canon = Canon([])
    canon.add(Log("listener", log))
    batch = MoveBatch(np.array([0, 0], dtype=np.int8), np.zeros((2, 1)), np.array([[1.0], [3.0]]),
                      np.zeros(2), "p.nc", np.array([4, 5]))
    canon.move_batch(batch)
    assert log == [("listener", "rapid", (1.0,)), ("listener", "rapid", (3.0,))]
