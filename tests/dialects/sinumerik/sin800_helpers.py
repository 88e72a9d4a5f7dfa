"""What the SINUMERIK 800 tests share: a machine file text, a run of a program text on it, R parameters."""

from __future__ import annotations

from pathlib import Path

from ncvm.api import run
from ncvm.runtime.session import RunOptions


def machine(axes: str = "XYZ", control: str = "880", extra: str = "") -> str:
    """A machine file: the axes, then ``[sin800]`` with the control model and ``extra`` lines of it."""
    return "".join(f'[[axis]]\nname = "{a}"\n' for a in axes) + f'[sin800]\ncontrol = "{control}"\n' + extra


MACHINE = machine()


def run_mpf(tmp_path: Path, text: str, extra: str = "", *, machine_text: str = MACHINE, name: str = "prog.mpf",
            files: dict | None = None, state: str = ".ncvm", ok: bool = False, session: bool = False):
    """Run ``text`` as ``name`` on ``machine_text`` + ``extra``: the JSON result (and the session if asked);
    ``ok`` asserts that it ran without error."""
    (tmp_path / "machine.toml").write_text(machine_text + extra)
    for fname, body in (files or {}).items():
        (tmp_path / fname).write_text(body)
    path = tmp_path / name
    path.write_text(text)
    result, sess = run(path, dialect="sin800", machine=tmp_path / "machine.toml",
                       options=RunOptions(state_dir=tmp_path / state, keep_toolpath=session))
    if ok:
        assert result["status"] == "ok", result["error"]
    return (result, sess) if session else result


def R(result: dict, n: int) -> float:
    """R parameter ``n`` as the run left it (0 when never written)."""
    return result["variables"].get(f"R{n}", 0.0)


def input_event(time: float, bit: int, value: int = 1, byte: int = 1) -> str:
    """A scenario event: PLC input byte.bit changes at ``time`` seconds."""
    return f'[[scenario]]\ntime = {time}\nkind = "input"\nbyte = {byte}\nbit = {bit}\nvalue = {value}\n'
