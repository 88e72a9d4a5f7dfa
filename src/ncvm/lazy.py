"""Heavy libraries imported at their first use, so that ``ncvm --version``, ``ncvm check`` and a short run
start quickly (issue 18: numpy alone costs a start-up of ~130 ms).

``np = lazy("numpy")`` gives a stand-in whose first attribute lookup imports numpy and copies its names onto
the stand-in: later lookups are plain attribute lookups, as fast as on the module itself. Annotations
(``np.ndarray``) cost nothing under ``from __future__ import annotations``.
"""

from __future__ import annotations

import importlib


class LazyModule:
    """A module imported when one of its names is first used."""

    def __init__(self, name: str):
        self.__dict__["_lazy_name"] = name

    def __getattr__(self, attr: str):
        from .runtime.memory import outside_limit  # the import is the library's memory, not the program's

        with outside_limit():
            module = importlib.import_module(self.__dict__["_lazy_name"])
        self.__dict__.update(vars(module))
        return getattr(module, attr)

    def __repr__(self) -> str:
        return f"<lazy module {self.__dict__['_lazy_name']!r}>"


def lazy(name: str) -> LazyModule:
    return LazyModule(name)
