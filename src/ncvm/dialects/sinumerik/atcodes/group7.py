"""Main group 7: NC-specific functions (planning guide ch.10, L6774-6799).

``run``: the function (of the channel or its part) for the codes executed through ``Channel.nc_function``.
"""

from __future__ import annotations

from .row import AtCode

ROWS = (
    AtCode("706", "POS MSYS", "", 6782, "pos_msys", cl800="procedure"),
    AtCode("710", "PREP REF", "VV", 6786, "nc_refs", run="cycles.prep_ref_args", cl800="nc_function", regs=8),
    AtCode("711", "INT SEC", "VVV", 6787, "int_sec", cl800="nc_function", regs=3),
    AtCode("713", "PREP CYC", "V", 6788, "nc_refs", run="cycles.prep_cyc", cl800="nc_function", regs=2),
    AtCode("714", "STOP DEC", "", 6789, "stop_dec", run="stop_dec_now", cl800="procedure"),
    AtCode("715", "STOP DEC1", "", 6790, "stop_dec", run="stop_dec1", cl800="procedure"),
    AtCode("720", "MEAS M", "VW", 6794, "meas_m", cl800="nc_function", regs=2),
    AtCode("730", "REL", "WW", 6798, "rel", cl800="procedure"),
    AtCode("736", "INTA", "WWW", 6799, "inta", cl800="procedure"),
)
