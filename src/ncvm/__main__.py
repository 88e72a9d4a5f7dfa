"""``python -m ncvm``: the same as the ``ncvm`` command."""

from .cli import main

main()
