"""Colours of what ncvm says on a terminal: diagnostics, warnings, the summary lines.

Colour is on when the stream is a terminal, ``NO_COLOR`` is unset or empty (https://no-color.org) and
``TERM`` is not ``dumb``; ``ncvm --color`` / ``--no-color`` decide instead. A pipe or a file gets the plain
text, byte for byte what it got before colours existed. The colours are click's ANSI styles: no library
is loaded for them.
"""

from __future__ import annotations

import os
import re
import sys

import click

#: set by ``ncvm --color`` (True) / ``--no-color`` (False); None: decide by the stream
forced: bool | None = None

#: the patterns are compiled by ``re`` when colour is first used (its cache), not by every start-up (issue 18)
HEADER = r"(?m)^(?P<place>\S+:\d+(?::\d+)?: )?(?P<kind>error|warning|note)(?P<code> [^:\s]+)?:"
CARET = r"(?m)^(\s*)(\^+)\s*$"
KIND_COLOUR = {"error": "red", "warning": "yellow", "note": "cyan"}
#: a summary line's verdict: good, bad
VERDICTS = (
    (r"ended normally|(?<= )0 with errors", "green"),
    (r"stopped with error \S+|\d+ with errors|\d+ with limit violations|\d+ failed", "red"),
)


def enabled(err: bool = True) -> bool:
    """Whether stderr (``err``) or stdout gets colours."""
    if forced is not None:
        return forced
    if os.environ.get("NO_COLOR") or os.environ.get("TERM") == "dumb":
        return False
    stream = sys.stderr if err else sys.stdout
    try:
        return stream is not None and stream.isatty()
    except (ValueError, OSError, AttributeError):
        return False


def styled(text: str) -> str:
    """``text`` with its diagnostic headers, carets and summary verdicts in colour."""
    text = re.sub(HEADER, _header, text)
    text = re.sub(CARET, lambda m: m.group(1) + click.style(m.group(2), fg="green", bold=True), text)
    for pattern, colour in VERDICTS:
        text = re.sub(pattern, lambda m, c=colour: click.style(m.group(0), fg=c, bold=True), text)
    return text


def _header(m: re.Match) -> str:
    place = click.style(m.group("place"), bold=True) if m.group("place") else ""
    kind = click.style(m.group("kind") + (m.group("code") or ""), fg=KIND_COLOUR[m.group("kind")], bold=True)
    return f"{place}{kind}:"


def say(text: str) -> None:
    """One message on stderr, in colour where :func:`enabled` says so."""
    colour = enabled()
    click.echo(styled(text) if colour else text, err=True, color=colour)
