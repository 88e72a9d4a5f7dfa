"""Loading a machine file (TOML) into a :class:`~ncvm.machine.model.Machine`.

The format is declared once in spec.py and sections.py (and documented from
there in docs/machine-file.md). A bad file gets a :class:`UsageError`
``FILE: machine file error: KEY = VALUE: what is wrong``, never a traceback.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any, Mapping, Sequence, TypeVar

from ..diagnostics import UsageError
from .model import Axis, Machine, MotionData, PlcImage, SimClock, Tool

# The schema (schema.py, sections.py, spec.py) is imported where a file or a section is checked: the built-in
# machine's precomputed form, checked by tests/machine/test_default_form.py, and a machine without a section for
# the program's dialect need no check at start-up (issue 18).


def default_machine_text() -> str:
    # read beside this module: importlib.resources would import zipfile and more on every run (issue 18)
    return (Path(__file__).parent / "default_machine.toml").read_text(encoding="utf-8")


def load_machine(path: str | Path | None = None, base_dir: Path | None = None) -> Machine:
    """Load ``path`` or, when None, the built-in default 3-axis mill.

    Relative paths inside the file (program path, file root) are taken relative
    to the machine file's folder; for the built-in machine, to ``base_dir``
    (the program's folder) or the current directory.
    """
    if path is None:
        return _default_machine(base_dir or Path("."))
    p = Path(path)
    return machine_from_dict(_parse(p, "machine file"), str(p), p.parent)


#: the largest machine or scenario file read: far beyond any real one, and /dev/zero is not read forever
MAX_BYTES = 16 * 1024 * 1024


def _parse(p: Path, what: str) -> dict:
    try:
        if not p.is_file():  # a FIFO or a device would block the run, or never end
            raise UsageError(f"cannot read {what} {p}: not a file")
        with p.open("rb") as f:
            data = f.read(MAX_BYTES + 1)
        if len(data) > MAX_BYTES:
            raise UsageError(f"cannot read {what} {p}: larger than {MAX_BYTES // 2 ** 20} MB")
        # newlines as a text-mode read gives them; the byte-order mark of Windows editors dropped
        text = re.sub(r"\r\n?", "\n", data.decode("utf-8")).removeprefix("\ufeff")
    except OSError as e:
        raise UsageError(f"cannot read {what} {p}: {e.strerror}") from None
    except UnicodeDecodeError as e:
        raise UsageError(f"{p}: not valid TOML: not UTF-8 text (byte {e.start})") from None
    return _loads(text, str(p))


def _default_machine(folder: Path) -> Machine:
    """The built-in machine: from the file's precomputed form (a valid machine file without dialect sections,
    tests/machine/test_default_form.py) while the file reads as that form was made from, else from the file
    parsed and checked as any machine file."""
    from . import default_form

    where, text = "<built-in default machine>", default_machine_text()
    if text == default_form.TEXT:
        return _build(default_form.data(), where, folder, sections={})
    return machine_from_dict(_loads(text, where), where, folder)


def _loads(text: str, where: str) -> dict:
    import tomllib  # only for a machine or scenario file other than the built-in one (about 5 ms, issue 18)

    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise UsageError(f"{where}: not valid TOML: {e}{_quoted_line(text, str(e))}") from None
    except RecursionError:
        raise UsageError(f"{where}: not valid TOML: arrays or inline tables nested too deeply") from None
    except ValueError:  # Python reads no integer of more than 4300 digits
        raise UsageError(f"{where}: not valid TOML: an integer with thousands of digits") from None


def _quoted_line(text: str, message: str) -> str:
    """The line a TOML error points at (a repeated key is named there, not in the parser's message)."""
    at = re.search(r"\(at line (\d+), column \d+\)", message)
    lines = text.splitlines()
    if not at or not 0 < int(at.group(1)) <= len(lines):
        return ""
    line = lines[int(at.group(1)) - 1].strip()
    return f": {line[:77] + '...' if len(line) > 80 else line}" if line else ""


def _checked(node, data: dict, where: str, ctx=None, what: str = "machine file") -> None:
    from .schema import NO_AXES, SchemaError, validate

    try:
        validate(node, data, NO_AXES if ctx is None else ctx)
    except SchemaError as e:
        raise UsageError(f"{where}: {what} error: {e}") from None


def _context(data: dict, where: str):
    """The axes, checked first: other keys (offsets, start position, scenario axes) refer to them."""
    from .schema import MISSING, Ctx
    from .spec import MACHINE_FILE

    axes = data.get("axis", MISSING)
    _checked(MACHINE_FILE, {"axis": axes} if axes is not MISSING else {}, where)
    return Ctx(tuple(a["name"] for a in axes),
               tuple((float(a.get("min", -1.0e9)), float(a.get("max", 1.0e9))) for a in axes))


def machine_from_dict(data: dict, where: str = "<dict>", folder: Path = Path(".")) -> Machine:
    """A :class:`Machine` from a parsed machine file, checked against the schema (spec.py) first."""
    from .sections import DIALECT_SECTIONS
    from .spec import MACHINE_FILE

    _checked(MACHINE_FILE, data, where, _context(data, where))
    return _build(data, where, folder, {sec.name: data[sec.name] for sec in DIALECT_SECTIONS if sec.name in data})


def _build(data: dict, where: str, folder: Path, sections: dict[str, Any]) -> Machine:
    """The machine a checked machine file describes; ``sections``: its dialect sections."""
    head = data.get("machine", {})
    m = Machine(name=head.get("name", "machine"), source=where)
    m.axes = [Axis(**{k: (float(v) if k in NUMERIC_AXIS_KEYS else v) for k, v in ax.items()}) for ax in data["axis"]]
    m.offsets = {table: [float(v) for v in values] for table, values in data.get("offsets", {}).items()}
    if "start_position" in head:
        m.start_position = [float(v) for v in head["start_position"]]
    for t in data.get("tool", []):
        m.tools[t["number"]] = Tool(t["number"], float(t.get("length", 0.0)), float(t.get("radius", 0.0)),
                                    t.get("name", ""))
    m.setting_data = dict(data.get("setting_data", {}))
    plc = data.get("plc", {})
    m.plc = PlcImage(inputs=dict(plc.get("inputs", {})), outputs=dict(plc.get("outputs", {})),
                     flags=dict(plc.get("flags", {})), words=dict(plc.get("words", {})))
    m.clock = SimClock(start_epoch=float(data.get("clock", {}).get("start", 1_700_000_000.0)))
    m.motion = MotionData(**data.get("motion", {}))
    paths = data.get("paths", {})
    m.program_path = [(folder / p) for p in paths.get("program_path", ["."])]
    m.file_root = folder / paths.get("file_root", "files")
    if data.get("scenario"):  # the event classes are imported only for a machine that has events
        from .scenario import from_tables

        m.scenario = from_tables(data["scenario"])
    m.sections = sections
    return m


NUMERIC_AXIS_KEYS = ("min", "max", "rapid", "max_feed", "accel")

Options = TypeVar("Options")


def dialect_options(cls: type[Options], sections: Mapping[str, Any], dialect: str,
                    axes: Sequence[Axis] = ()) -> Options:
    """The ``[dialect]`` section of a machine's ``sections`` as the dataclass ``cls`` the dialect declares
    its options in (its fields are the section's keys, with the defaults of sections.py). The section is
    checked against its schema first: a Machine built in Python has not been through the loader.
    ``axes``: the machine's axes, for keys with a value per axis."""
    section = dict(sections.get(dialect) or {})
    if not section:  # the declared defaults (tests/machine/test_dialect_sections.py): nothing to check
        return cls()
    from .schema import Ctx, SchemaError, validate
    from .sections import SECTIONS

    ctx = Ctx(tuple(a.name for a in axes), tuple((a.min, a.max) for a in axes))
    try:
        validate(SECTIONS[dialect], section, ctx, path=dialect)
    except SchemaError as e:
        raise UsageError(f"machine file error: {e}") from None
    return cls(**section)


def load_scenario(path: str | Path, axis_names: tuple[str, ...] = ()) -> list:
    """A scenario file (``--scenario``): ``[[scenario]]`` tables as in a machine file, nothing else.
    Events that name axes (probe, fixed_stop) are checked against ``axis_names``."""
    p = Path(path)
    from .schema import Ctx
    from .spec import SCENARIO_FILE

    data = _parse(p, "scenario file")
    _checked(SCENARIO_FILE, data, str(p), Ctx(tuple(axis_names)), "scenario file")
    from .scenario import from_tables

    return from_tables(data.get("scenario", []))
