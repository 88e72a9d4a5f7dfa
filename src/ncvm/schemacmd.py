"""``ncvm machine-schema``: the JSON Schema of machine files (built when named or listed: cli.py,
``_Guarded.LAZY``)."""

from __future__ import annotations

import click

from .cli import exits_text


@click.command(name="machine-schema", epilog=exits_text("machine-schema"))
@click.option("--markdown", is_flag=True, help="The reference tables of docs/machine-file.md instead.")
def machine_schema(markdown):
    """Print the JSON Schema of machine files (for editors)."""
    from .machine.docgen import json_text
    from .machine.docgen import markdown as tables

    click.echo(tables() if markdown else json_text(), nl=False)
