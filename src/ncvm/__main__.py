"""``python -m ncvm``: the same as the ``ncvm`` command."""

from .startup import main

main()
