"""``ncvm state``: the permanent memory of the simulated control from the command line.

``show`` lists what the store holds, ``reset`` clears it, ``export`` / ``import`` copy it to and from a
JSON file (:mod:`ncvm.machine.state_io`). What changes the store (reset, import) takes the state
directory's lock as a run does, so it never writes under a running program; what only reads it
(show, export) reads one snapshot and may run beside a run.

Exit codes: 0 done, 1 a reset not confirmed, 2 usage error (a bad file to import, a reset without a
terminal and without --yes, a state directory in use, a store that cannot be read or written).
"""

from __future__ import annotations

import sys
from pathlib import Path

import click

from .diagnostics import UsageError
from .lazy import lazy

json = lazy("json")  # ncvm state show only

STATE_OPT = click.option("--state", "state_dir", type=click.Path(file_okay=False), default=".ncvm", show_default=True,
                         help="State directory whose permanent store is meant.")
EXIT_CODES = ("Exit codes: 0 done, 1 a reset not confirmed, 2 usage error (a bad file, a state directory in use, "
              "a store that cannot be read or written), 70 internal error (a bug in ncvm).")


def _store_path(state_dir: str) -> Path:
    from .machine.state import STORE_NAME

    if not state_dir.strip():
        raise UsageError("--state is empty; give the state directory (default .ncvm)")
    return Path(state_dir) / STORE_NAME


def _content(state_dir: str) -> dict:
    """What the store holds; ``{}`` when no run has kept anything there yet (no store file: none is made)."""
    from .machine.store import Store

    if not _store_path(state_dir).exists():
        return {}
    store = Store(state_dir)
    try:
        return store.dump()
    finally:
        store.close()


@click.group(name="state", epilog=EXIT_CODES)
def state():
    """The permanent memory of the simulated control (the store in the state directory): permanent
    variables, R parameters, tool and zero offset tables as the runs left them."""


@state.command(epilog=EXIT_CODES)
@STATE_OPT
@click.option("--json", "as_json", is_flag=True, help="Print the store as the export file does.")
def show(state_dir, as_json):
    """List everything the permanent store holds, by namespace."""
    from .machine.state_io import NAMESPACES, document

    content = _content(state_dir)
    if as_json:
        click.echo(document(content), nl=False)
        return
    if not content:
        click.echo(f"ncvm: the permanent store of {state_dir} is empty (no run has kept anything there)", err=True)
        return
    for namespace, entries in content.items():
        click.echo(f"{namespace}: {NAMESPACES.get(namespace, 'kept by another ncvm')}")
        for key, value in entries.items():
            if isinstance(value, dict) and not _declared(value):  # a table: one line per entry
                click.echo(f"  {key}:")
                for sub, item in value.items():
                    click.echo(f"    {sub} = {json.dumps(item)}")
            else:
                click.echo(f"  {_entry(key, value)}")
    n = sum(len(entries) for entries in content.values())
    click.echo(f"ncvm: {n} entr{'y' if n == 1 else 'ies'} in {_store_path(state_dir)}", err=True)


def _entry(key: str, value) -> str:
    """One line: a declared CPL variable with its type and size, every other value as JSON."""
    if _declared(value):
        dims = f"({','.join(map(str, value['dims']))})" if value["dims"] else ""
        return f"{key} {value['type']}{dims} = {json.dumps(value['value'])}"
    return f"{key} = {json.dumps(value)}"


def _declared(value) -> bool:
    return isinstance(value, dict) and set(value) == {"type", "dims", "value"}


@state.command(epilog=EXIT_CODES)
@STATE_OPT
@click.option("--yes", "-y", is_flag=True, help="Clear without asking.")
def reset(state_dir, yes):
    """Clear the permanent store: the next run starts from the machine file, as after a memory reset."""
    from .machine.state import StateLock
    from .machine.store import Store

    path = _store_path(state_dir)
    from .cli import _stdin_is_terminal

    if not yes and not _stdin_is_terminal():
        raise UsageError(f"ncvm state reset clears {path}: confirm it at a terminal, or give --yes")
    if not path.exists():
        click.echo(f"ncvm: nothing to reset: {state_dir} has no permanent store", err=True)
        return
    with StateLock(state_dir):
        store = Store(state_dir)
        try:
            n = sum(len(entries) for entries in store.dump().values())
            if not yes and not click.confirm(f"Clear the {n} entries of the permanent store {path}?", err=True):
                click.echo("ncvm: nothing cleared", err=True)
                sys.exit(1)
            store.replace({})
        finally:
            store.close()
    click.echo(f"ncvm: cleared {n} entr{'y' if n == 1 else 'ies'} from {path}", err=True)


@state.command(name="export", epilog=EXIT_CODES)
@click.argument("file", type=click.Path(dir_okay=False, allow_dash=True))
@STATE_OPT
def export_cmd(file, state_dir):
    """Write the permanent store to FILE (JSON; - for stdout), exactly as it holds it."""
    from .machine.state_io import document
    from .outpaths import Output, check_outputs

    text = document(_content(state_dir))
    if file == "-":
        click.echo(text, nl=False)
        return
    check_outputs([Output("FILE", file)], {}, state=state_dir)  # never over the store or into its directory
    try:
        Path(file).write_text(text, encoding="utf-8")
    except OSError as e:
        raise UsageError(f"cannot write {file}: {e.strerror}") from None
    click.echo(f"ncvm: wrote {file}", err=True)


@state.command(name="import", epilog=EXIT_CODES)
@click.argument("file", type=click.Path(dir_okay=False, allow_dash=True))
@STATE_OPT
def import_cmd(file, state_dir):
    """Make the permanent store hold exactly what FILE (written by export) holds; the file is checked
    whole first, and the store is replaced all at once or not at all."""
    from .machine.state import StateLock
    from .machine.state_io import parse
    from .machine.store import Store

    shown = "stdin" if file == "-" else file
    try:
        raw = sys.stdin.buffer.read() if file == "-" else Path(file).read_bytes()
        text = raw.decode("utf-8")
    except OSError as e:
        raise UsageError(f"cannot read {shown}: {e.strerror}") from None
    except UnicodeDecodeError as e:
        raise UsageError(f"{shown}: not UTF-8 text (byte {e.start + 1})") from None
    content = parse(text, shown)
    _store_path(state_dir)
    with StateLock(state_dir):
        store = Store(state_dir)
        try:
            store.replace(content)
        finally:
            store.close()
    n = sum(len(entries) for entries in content.values())
    click.echo(f"ncvm: imported {n} entr{'y' if n == 1 else 'ies'} into {_store_path(state_dir)}", err=True)

