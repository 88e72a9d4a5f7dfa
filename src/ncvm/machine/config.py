"""Loading a machine file (TOML) into a :class:`~ncvm.machine.model.Machine`.

The format is documented in docs/machine-file.md. A bad file gets a
:class:`UsageError` naming the file and the key, never a traceback.
"""

from __future__ import annotations

import tomllib
from importlib import resources
from pathlib import Path
from typing import Any

from ..diagnostics import UsageError
from .model import Axis, Machine, PlcImage, ScenarioEvent, SimClock, Tool

AXIS_KEYS = {"name": str, "kind": str, "min": float, "max": float, "rapid": float, "max_feed": float, "accel": float}
TOP_KEYS = {"machine", "axis", "offsets", "tool", "machine_data", "setting_data", "plc", "paths", "clock", "scenario",
            "cpl", "cl800", "sin800", "sympas", "din"}
DIALECT_SECTIONS = ("cpl", "cl800", "sin800", "sympas", "din")
#: the keys each fixed table may hold; anything else is a typo the user should hear about
TABLE_KEYS = {
    "machine": {"name", "units", "start_position"},
    "paths": {"program_path", "file_root"},
    "clock": {"start"},
    "plc": {"inputs", "outputs", "flags", "words"},
}
TOOL_KEYS = {"number", "length", "radius", "name"}


def default_machine_text() -> str:
    return resources.files("ncvm.machine").joinpath("default_machine.toml").read_text()


def load_machine(path: str | Path | None = None, base_dir: Path | None = None) -> Machine:
    """Load ``path`` or, when None, the built-in default 3-axis mill.

    Relative paths inside the file (program path, file root) are taken relative
    to the machine file's folder; for the built-in machine, to ``base_dir``
    (the program's folder) or the current directory.
    """
    if path is None:
        text, where, folder = default_machine_text(), "<built-in default machine>", base_dir or Path(".")
    else:
        p = Path(path)
        try:
            text = p.read_text(encoding="utf-8")
        except OSError as e:
            raise UsageError(f"cannot read machine file {p}: {e.strerror}") from None
        where, folder = str(p), p.parent
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise UsageError(f"{where}: not valid TOML: {e}") from None
    return machine_from_dict(data, where, folder)


def _num(where: str, key: str, value: Any, kind=float):
    if kind is float and isinstance(value, (int, float)) and not isinstance(value, bool):
        return float(value)
    if kind is int and isinstance(value, int) and not isinstance(value, bool):
        return value
    if kind is str and isinstance(value, str):
        return value
    raise UsageError(f"{where}: key '{key}' must be {kind.__name__}, got {value!r}")


def machine_from_dict(data: dict, where: str = "<dict>", folder: Path = Path(".")) -> Machine:
    for key in data:
        if key not in TOP_KEYS:
            raise UsageError(f"{where}: unknown key '{key}' (known: {', '.join(sorted(TOP_KEYS))})")
    for table, allowed in TABLE_KEYS.items():
        _only(where, table, data.get(table, {}), allowed)
    head = data.get("machine", {})
    if head.get("units", "mm") != "mm":
        raise UsageError(f"{where}: key 'machine.units' must be \"mm\" (machine files are metric; "
                         f"programs switch to inch with G70/G20)")
    m = Machine(name=str(head.get("name", "machine")), source=where)

    axes = data.get("axis")
    if not axes:
        raise UsageError(f"{where}: key 'axis' is missing: a machine needs at least one [[axis]]")
    for i, ax in enumerate(axes):
        kw = {}
        for key, value in ax.items():
            if key not in AXIS_KEYS:
                raise UsageError(f"{where}: unknown key 'axis[{i}].{key}'")
            kw[key] = _num(where, f"axis[{i}].{key}", value, AXIS_KEYS[key])
        if "name" not in kw:
            raise UsageError(f"{where}: key 'axis[{i}].name' is missing")
        if kw.get("kind", "linear") not in ("linear", "rotary"):
            raise UsageError(f"{where}: key 'axis[{i}].kind' must be 'linear' or 'rotary'")
        axis = Axis(**kw)
        if axis.min > axis.max:
            raise UsageError(f"{where}: key 'axis[{i}].min' is greater than max")
        for key in ("rapid", "max_feed", "accel"):
            if getattr(axis, key) <= 0:
                raise UsageError(f"{where}: key 'axis[{i}].{key}' must be positive")
        m.axes.append(axis)
    names = m.axis_names
    if len(set(names)) != len(names):
        raise UsageError(f"{where}: key 'axis': axis names repeat: {names}")

    n = len(m.axes)
    for table, values in data.get("offsets", {}).items():
        m.offsets[table] = _axis_vector(where, f"offsets.{table}", values, n)
    if "start_position" in head:
        m.start_position = _axis_vector(where, "machine.start_position", head["start_position"], n)

    for i, t in enumerate(data.get("tool", [])):
        _only(where, f"tool[{i}]", t, TOOL_KEYS)
        if "number" not in t:
            raise UsageError(f"{where}: key 'tool[{i}].number' is missing")
        tool = Tool(number=_num(where, f"tool[{i}].number", t["number"], int),
                    length=_num(where, f"tool[{i}].length", t.get("length", 0.0)),
                    radius=_num(where, f"tool[{i}].radius", t.get("radius", 0.0)),
                    name=str(t.get("name", "")))
        m.tools[tool.number] = tool

    m.machine_data = dict(data.get("machine_data", {}))
    m.setting_data = dict(data.get("setting_data", {}))
    plc = data.get("plc", {})
    m.plc = PlcImage(inputs=dict(plc.get("inputs", {})), outputs=dict(plc.get("outputs", {})),
                     flags=dict(plc.get("flags", {})), words=dict(plc.get("words", {})))
    clock = data.get("clock", {})
    m.clock = SimClock(start_epoch=_num(where, "clock.start", clock.get("start", 1_700_000_000.0)))

    paths = data.get("paths", {})
    m.program_path = [(folder / p) for p in paths.get("program_path", ["."])]
    m.file_root = folder / paths.get("file_root", "files")

    m.scenario = _scenario_events(where, data.get("scenario", []))

    for sec in DIALECT_SECTIONS:
        if sec in data:
            m.sections[sec] = data[sec]
    return m


def _scenario_events(where: str, entries: Any) -> list[ScenarioEvent]:
    if not isinstance(entries, list):
        raise UsageError(f"{where}: key 'scenario' must be an array of tables ([[scenario]])")
    events = []
    for i, ev in enumerate(entries):
        if not isinstance(ev, dict) or "time" not in ev or "kind" not in ev:
            raise UsageError(f"{where}: key 'scenario[{i}]' needs 'time' and 'kind'")
        rest = {k: v for k, v in ev.items() if k not in ("time", "kind")}
        events.append(ScenarioEvent(_num(where, f"scenario[{i}].time", ev["time"]), str(ev["kind"]), rest))
    return sorted(events, key=lambda e: e.time)


def load_scenario(path: str | Path) -> list[ScenarioEvent]:
    """A scenario file (``--scenario``): ``[[scenario]]`` tables as in a machine file, nothing else."""
    p = Path(path)
    try:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except OSError as e:
        raise UsageError(f"cannot read scenario file {p}: {e.strerror}") from None
    except tomllib.TOMLDecodeError as e:
        raise UsageError(f"{p}: not valid TOML: {e}") from None
    for key in data:
        if key != "scenario":
            raise UsageError(f"{p}: unknown key '{key}' (a scenario file holds only [[scenario]] tables)")
    return _scenario_events(str(p), data.get("scenario", []))


def _only(where: str, table: str, value: Any, allowed: set[str]) -> None:
    if not isinstance(value, dict):
        raise UsageError(f"{where}: key '{table}' must be a table")
    for key in value:
        if key not in allowed:
            raise UsageError(f"{where}: unknown key '{table}.{key}' (known: {', '.join(sorted(allowed))})")


def _axis_vector(where: str, key: str, values: Any, n: int) -> list[float]:
    if isinstance(values, dict):
        raise UsageError(f"{where}: key '{key}' must be a list of {n} numbers")
    if not isinstance(values, list) or len(values) != n:
        raise UsageError(f"{where}: key '{key}' must be a list of {n} numbers (one per axis)")
    return [_num(where, key, v) for v in values]
