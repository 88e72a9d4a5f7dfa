"""CPL run-time I/O: formatted output, strings, files, the operator screen, graphics and MMC.

These modules know nothing about the CPL parser; the CPL code generator calls them
(see docs/cpl-io.md for the calling conventions). Manual chapters 5-9.
"""
