"""``ncvm run`` with several programs or folders: the batch as the command line gives it."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import click

from ..diagnostics import UsageError
from ..progress import Progress
from ..runtime.memory import parse_size
from ..termstyle import say
from . import report
from .batch import run_batch
from .discover import discover, nothing_found


def run_batch_command(programs, dialect, machine, state_dir, as_json, max_steps, max_memory, jobs, cluster,
                      report_file, shared_state, single_only: list[str]) -> None:
    """Run the batch, print its end on stderr (the report document on stdout with --json), write the report;
    exit 1 when a program failed."""
    if single_only:
        raise UsageError(f"{', '.join(single_only)} take(s) one program; a batch runs each program with its "
                         f"own <name>.keys and <name>.scenario.toml when they exist (docs/batch.md)")
    if jobs and cluster:
        raise UsageError("--jobs and --cluster exclude each other: the cluster's workers run the programs")
    if report_file and Path(report_file).suffix.lower() not in report.FORMATS:
        raise UsageError(f"--report {report_file}: give a .json, .csv or .xml file")
    if machine and not Path(machine).is_file():
        raise UsageError(f"no such machine file: {machine}")
    if not state_dir.strip():
        raise UsageError("--state is empty; give the state directory (default .ncvm)")
    found = discover(programs, dialect, machine)
    # the programs done, their moves and simulated time, on a terminal (after half a second)
    with Progress(sys.stderr.isatty() and not as_json, total=len(found.programs), delay=0.5) as progress:
        doc = run_batch(programs, dialect, machine, jobs=jobs, cluster=cluster, state=state_dir,
                        shared_state=shared_state, max_steps=max_steps,
                        max_memory=parse_size(max_memory) if max_memory is not None else None, found=found,
                        on_record=progress.done)
    if report_file:
        report.write(doc, report_file)
    if as_json:
        click.echo(json.dumps(doc, indent=2))
    else:
        for line in report.summary_lines(doc):
            say(line)
        if nothing_found(found, programs):
            say(nothing_found(found, programs))
        if report_file:
            say(f"ncvm: report written to {report_file}")
    sys.exit(1 if report.failed(doc) else 0)
