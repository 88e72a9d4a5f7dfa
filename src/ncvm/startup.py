"""The ``ncvm`` command's entry point (the console script and ``python -m ncvm``): start-up without the cyclic
garbage collector going over what start-up loads.

Loading click and the CLI makes tens of thousands of objects (modules, functions, classes, click's commands)
that live as long as the process. At the collector's default thresholds it went over them about 25 times
before a one-block run ended, and once more at exit: about a tenth of the instructions of ``ncvm run`` of
``M2`` (issue 18). So the first threshold is raised while the CLI loads, and what it made is then frozen
(``gc.freeze``: moved where no collection looks) before the thresholds are put back and the command runs:
the command and the program run under the collector as always. A cycle of garbage made while loading is
kept to the end of the process (a few objects of the libraries' own set-up).
"""

from __future__ import annotations

import gc

#: the first threshold while the CLI loads (objects allocated and not freed between two collections of the
#: youngest generation; the default is 700): loading it for a run of ``M2`` makes about 18,000
LOADING_THRESHOLD = 100_000


def main() -> None:
    thresholds = gc.get_threshold()
    gc.set_threshold(LOADING_THRESHOLD, *thresholds[1:])
    try:
        from .cli import main as command

        gc.freeze()
    finally:
        gc.set_threshold(*thresholds)
    command()
