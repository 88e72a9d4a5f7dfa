"""``ncvm check``: every error the control would report, for programs and whole archives (built when named
or listed: cli.py, ``_Guarded.LAZY``)."""

from __future__ import annotations

import sys
from collections import Counter
from pathlib import Path

import click

from . import cli
from .cli import DIALECT_OPT, EXIT_FAULT, EXIT_OK, MACHINE_OPT, exits_text
from .diagnostics import CompileFailed, Diagnostics, UsageError, render_all
from .lazy import lazy
from .source import program_name
from .termstyle import say

json = lazy("json")  # --json output only


@click.command(epilog=exits_text("check"))
@click.argument("programs", nargs=-1, required=True, type=click.Path())
@DIALECT_OPT
@MACHINE_OPT
@click.option("--json", "as_json", is_flag=True, help="Diagnostics as one JSON document.")
@click.option("--all", "all_errors", is_flag=True, help="Go on after the first error and list every one.")
@click.option("--report", "report_file", type=click.Path(dir_okay=False),
              help="Write the report as run --report does (.json, .csv or JUnit .xml), a program per entry.")
def check(programs, dialect, machine, as_json, all_errors, report_file):
    """Check programs for every error the control would report; exit 1 when any was found.

    A folder stands for every program file below it (known extensions; a file without one when its content
    is a program), so a whole archive is checked at once, sub-programs too; each program uses the nearest
    machine.toml upwards (up to the folder named) unless --machine is given.
    """
    from . import api
    from .archive import report as reports
    from .archive.discover import discover, machine_of, nothing_found

    if report_file and Path(report_file).suffix.lower() not in reports.FORMATS:
        raise UsageError(f"--report {report_file}: give a .json, .csv or .xml file")
    report, records, failed = [], [], False
    found = _piped(programs, dialect, machine) or discover(programs, dialect, machine)
    for program in found.all_programs:
        try:
            diags = api.check(program.path, program.dialect, machine_of(program), all_errors)
        except CompileFailed as e:
            diags = Diagnostics.capped(e.diagnostics)
        errors = diags.errors()
        failed |= bool(errors)
        report.append({"file": program_name(program.path), "ok": not errors,
                       "machine": str(program.machine or "built-in"), "diagnostics": [d.to_json() for d in diags]})
        if diags.left_out:  # the counts of the diagnostics past the first MAX_KEPT (docs/decisions.md)
            report[-1]["not_shown"] = dict(diags.left_out)
        records.append(reports.check_record(program_name(program.path), program.dialect, report[-1]["machine"],
                                            report[-1]["diagnostics"], diags.not_shown(),
                                            diags.left_out.get("error", 0)))
        if not as_json:
            for text in render_all(diags):
                say(text)
            if diags.left_out:
                say(f"{program_name(program.path)}: {diags.not_shown()}")
    not_checked = [s for s in found.skipped if s.path not in found.checked]
    skipped = [{"file": str(s.path), "reason": s.reason} for s in not_checked]
    if report_file:
        doc = reports.document(records, not_checked, {"command": "check"})
        doc["summary"].update(cycle_time_s=None, steps=None)  # nothing ran
        reports.write(doc, report_file)
    if as_json:
        click.echo(json.dumps({"files": report, "skipped": skipped}, indent=2))
    else:
        for s in skipped:
            click.echo(f"{s['file']}: skipped: {s['reason']}", err=True)
        if len(report) > 1:  # an archive: which machine file the programs used
            for line in reports.machine_lines(Counter(r["machine"] for r in report)):
                click.echo(line, err=True)
        n = sum(len(r["diagnostics"]) + sum(r.get("not_shown", {}).values()) for r in report)
        bad = sum(1 for r in report if not r["ok"])
        with_errors = f", {bad} with errors" if bad else ""
        not_programs = f", {len(skipped)} file(s) skipped" if skipped else ""
        say(f"ncvm: {len(report)} program(s) checked{with_errors}, {n} diagnostic(s){not_programs}")
        if nothing_found(found, programs):
            say(nothing_found(found, programs))
        if report_file:
            say(f"ncvm: report written to {report_file}")
    sys.exit(EXIT_FAULT if failed else EXIT_OK)


def _piped(programs, dialect: str | None, machine: str | None):
    """The one program of a check that reads it from a pipe (``-``: stdin, or a FIFO; -d din), on the machine
    given, else its folder's (the current folder for stdin) as ``ncvm run`` takes it; None for files."""
    from .archive.discover import Found, Program

    if not any(cli.piped_program(p, dialect) for p in programs):
        return None
    if len(programs) > 1:
        cli.alone(programs, "is checked")
    path = Path(programs[0])
    own = machine or cli.folder_machine(programs[0])
    program = Program(path, dialect, Path(own) if own else None, path.parent)
    return Found([program], [], [program])
