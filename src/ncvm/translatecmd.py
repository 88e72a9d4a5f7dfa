"""``ncvm translate``: a program's motion as a modern control's program (built when named or listed: cli.py,
``_Guarded.LAZY``)."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from . import cli
from .diagnostics import render_all
from .outpaths import Output, check_outputs
from .termstyle import say


@click.command(name="translate", epilog=cli.exits_text("translate"))
@click.argument("program", type=click.Path(dir_okay=False))
@click.option("-o", "out", type=click.Path(dir_okay=False), required=True, help="The program to write.")
@click.option("--target", type=click.Choice(["linuxcnc", "sinumerik840d", "iso"]), default="linuxcnc",
              show_default=True, help="The control the translation is for.")
@click.option("--frame", type=click.Choice(["work", "machine"]), default="work", show_default=True,
              help="work: the program's zero offsets and tool lengths; machine: the simulated machine's "
                   "coordinates with everything included.")
@click.option("--source-comments", is_flag=True, help="End every line with a (file:line) comment.")
@cli.DIALECT_OPT
@cli.MACHINE_OPT
@click.option("--state", "state_dir", type=click.Path(file_okay=False), default=cli.DEFAULT_STATE, show_default=True,
              help="State directory (permanent store, controller files).")
@click.option("--scenario", type=click.Path(dir_okay=False, exists=True),
              help="What happens over simulated time (probe trigger points, inputs), as for run.")
@click.option("--keys", type=click.Path(dir_okay=False, exists=True), help="The operator's key presses, as for run.")
@click.option("--max-steps", type=click.IntRange(min=1), default=100_000_000, show_default=True,
              help="Stop a runaway program after this many statements and blocks.")
def translate_cmd(program, out, target, frame, source_comments, dialect, machine, state_dir, scenario, keys,
                  max_steps):
    """Translate PROGRAM for a modern control: it runs on the simulated controller and its motion is
    written as TARGET's program (docs/translate.md); a failed run writes nothing."""
    from . import api
    from .runtime.session import RunOptions
    from .translate import Terminated, TranslationRefused, translate

    cli.check_program(program)
    inputs = {"program": program, **cli.machine_input(program, machine), "--scenario": scenario, "--keys": keys}
    machine = api.machine_for(program, machine or cli.folder_machine(program, say=True), Path(state_dir))
    check_outputs([Output("-o", out)], inputs, state=state_dir, program_path=machine.program_path,
                  file_root=str(machine.file_root))
    options = RunOptions(state_dir=Path(state_dir), max_steps=max_steps, scenario=Path(scenario) if scenario else None,
                         keys=cli.read_key_script(keys) if keys else None)
    try:
        done = translate(program, out, target, frame, source_comments, dialect, machine, options)
    except TranslationRefused as e:
        say(e.diagnostic.render())
        sys.exit(cli.EXIT_FAULT)
    except Terminated as e:  # the shell's convention for a command ended by a signal
        say(f"ncvm: error {e.code}: {e}")
        sys.exit(128 + e.signum)
    for v in done.warnings:  # the run's soft limits: the translation makes the same moves
        say(f"warning: {v}")
    for text in render_all(done.diagnostics):  # where the file differs from the simulated run (TRN003)
        say(text)
    click.echo(f"ncvm: wrote {done.path} for {done.target.title}: {done.lines} lines, {done.moves} moves, "
               f"{done.probes} probe moves, {done.frozen} frozen decisions", err=True)
