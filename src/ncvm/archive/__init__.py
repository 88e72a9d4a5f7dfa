"""Batch runs of whole archives: find the programs, run them here, in a local pool or on a dask cluster,
report them (docs/batch.md).

The batch machinery (process pools, reports, the permanent store's copies) is imported when a batch runs:
``ncvm check`` uses :mod:`.discover` alone and stays quick to start (issue 18).
"""

from __future__ import annotations

__all__ = ["default_jobs", "discover", "run_batch"]


def __getattr__(name: str):
    if name in __all__:
        from . import batch

        return getattr(batch, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
