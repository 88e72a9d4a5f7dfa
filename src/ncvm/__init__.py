"""ncvm: check, run, compile, debug and translate legacy CNC high-level language programs.

Dialects: plain DIN 66025 (``din``), Bosch Rexroth CPL (``cpl``), Siemens CL 800
(``cl800``) and SINUMERIK 800 @ code NC programs (``sin800``), ADDI-DATA
rw_SymPas (``sympas``). See :mod:`ncvm.api` for the Python API.
"""

__version__ = "0.1.0"

__all__ = ["__version__", "check", "compile_program", "run"]


def __getattr__(name: str):
    """``ncvm.run`` and its siblings import the API at first use: ``ncvm --version`` needs none of it."""
    if name in ("check", "compile_program", "run"):
        from . import api
        return getattr(api, name)
    raise AttributeError(f"module 'ncvm' has no attribute {name!r}")
