"""``ncvm compile``: a CL 800 program to @ code (built when named or listed: cli.py, ``_Guarded.LAZY``)."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from . import cli
from .diagnostics import CompileFailed, render_all
from .outpaths import Output, check_outputs
from .termstyle import say


@click.command(name="compile", epilog=cli.exits_text("compile"))
@click.argument("source", type=click.Path(dir_okay=False))
@click.option("-o", "out", type=click.Path(dir_okay=False), help="Object program to write.")
@click.option("--xref", type=click.Path(dir_okay=False), is_flag=False, flag_value="",
              help="Write the cross-reference listing (default name: the source's, .lst) and no object "
                   "program unless -o names one.")
@click.option("--force", is_flag=True, help="Overwrite the object file (without -o) or listing (--xref alone) ncvm names even if ncvm did "
                   "not write it or it was edited since.")
@cli.DIALECT_OPT
@cli.MACHINE_OPT
def compile_cmd(source, out, xref, force, dialect, machine):
    """Compile SOURCE (CL 800 to @ code).

    Without --machine the machine.toml in the source's folder is used (named on stderr), as by check and run.
    """
    from . import api

    cli.check_program(source)
    xref_named = xref != ""
    if xref == "":
        xref = str(Path(source).with_suffix(".lst"))  # the listing has the source's file name (CL 800 L361)
    # compile has no state directory of its own, but a run's default one is no place for its files either
    check_outputs([Output("-o", out), Output("--xref", xref)], {"program": source, **cli.machine_input(source, machine)},
                  state=cli.DEFAULT_STATE)
    machine = machine or cli.folder_machine(source, say=True)
    try:
        path = api.compile_program(source, out, xref, dialect, machine, force=force, xref_named=xref_named)
    except CompileFailed as e:
        for text in render_all(e.diagnostics):
            say(text)
        sys.exit(cli.EXIT_FAULT)
    click.echo(f"ncvm: wrote {path}", err=True)
