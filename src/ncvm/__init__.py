"""ncvm: check, run, compile, debug and translate legacy CNC high-level language programs.

Dialects: plain DIN 66025 (``din``), Bosch Rexroth CPL (``cpl``), Siemens CL 800
(``cl800``) and SINUMERIK 800 @ code NC programs (``sin800``), ADDI-DATA
rw_SymPas (``sympas``). The Python API (docs/api.md)::

    import ncvm
    result = ncvm.run("part.cpl", moves=True)
    print(result.status, result.cycle_time_s, result.moves_frame())
"""

__version__ = "0.1.0"

#: name -> the module that defines it; imported at first use, so that ``ncvm --version`` loads none of it
_API = {
    "run": "public", "check": "public", "batch": "public", "Batch": "public",
    "RunResult": "api", "compile_program": "api", "RunOptions": "runtime.session", "Diagnostic": "diagnostics",
    "UsageError": "diagnostics",
    "Machine": "machine.model", "load_machine": "machine.config", "MotionSummary": "sinks.toolpath",
}

__all__ = ["__version__", *_API]


def __getattr__(name: str):
    """The API's names import their module at first use: ``ncvm --version`` needs none of it."""
    if name in _API:
        from importlib import import_module

        return getattr(import_module(f".{_API[name]}", __name__), name)
    raise AttributeError(f"module 'ncvm' has no attribute {name!r}")


def __dir__():
    return sorted([*globals(), *_API])
