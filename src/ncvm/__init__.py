"""ncvm: check, run, compile, debug and translate legacy CNC high-level language programs.

Dialects: plain DIN 66025 (``din``), Bosch Rexroth CPL (``cpl``), Siemens CL 800
(``cl800``) and SINUMERIK 800 @ code NC programs (``sin800``), ADDI-DATA
rw_SymPas (``sympas``). See :mod:`ncvm.api` for the Python API.
"""

__version__ = "0.1.0"

from .api import check, compile_program, run  # noqa: E402

__all__ = ["__version__", "check", "compile_program", "run"]
