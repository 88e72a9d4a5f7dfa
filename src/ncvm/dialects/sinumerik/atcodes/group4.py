"""Main group 4: R parameter -> system memory; the value written is the last operand (planning guide ch.10, L6614-6704).

``run``: the function (of the channel's part) that writes the value (``Channel.write``); @44x are setpoints of the
block record (codegen), @44b/@44c the drives' control bits.
"""

from __future__ import annotations

from .row import AtCode

ROWS = (
    AtCode("400", "MDN", "WW", 6624, "write", run="memory.md_write", cl800="write"),
    AtCode("401", "MDNBY", "WW", 6625, "write", run="memory.md_write", cl800="write"),
    AtCode("402", "MDNBI", "WWW", 6626, "write", run="memory.md_write", cl800="write"),
    AtCode("403", "MDZ", "WWW", 6627, "write", run="memory.md_write", cl800="write"),
    AtCode("404", "MDZBY", "WWW", 6628, "write", run="memory.md_write", cl800="write"),
    AtCode("405", "MDZBI", "WWWW", 6629, "write", run="memory.md_write", cl800="write"),
    AtCode("406", "MDP", "WW", 6630, "write", run="memory.md_write", cl800="write"),
    AtCode("407", "MDPBY", "WW", 6631, "write", run="memory.md_write", cl800="write"),
    AtCode("408", "MDPBI", "WWW", 6632, "write", run="memory.md_write", cl800="write"),
    AtCode("409", "MDD", "WW", 6633, "write", run="memory.md_write", cl800="write"),
    AtCode("40a", "MDDBY", "WWW", 6634, "write", run="memory.md_write", cl800="write"),
    AtCode("40b", "MDDBI", "WWWW", 6635, "write", run="memory.md_write", cl800="write"),
    AtCode("410", "SEN", "WW", 6641, "write", run="memory.sd_write", cl800="write"),
    AtCode("411", "SENBY", "WW", 6642, "write", run="memory.sd_write", cl800="write"),
    AtCode("412", "SENBI", "WWW", 6643, "write", run="memory.sd_write", cl800="write"),
    AtCode("413", "SEZ", "WWW", 6644, "write", run="memory.sd_write", cl800="write"),
    AtCode("414", "SEZBY", "WWW", 6645, "write", run="memory.sd_write", cl800="write"),
    AtCode("415", "SEZBI", "WWWW", 6646, "write", run="memory.sd_write", cl800="write"),
    AtCode("420", "TOS", "WWWW", 6650, "write", run="offsets.to_write", cl800="write"),
    AtCode("423", "TOAD", "WWWW", 6651, "write", run="offsets.to_write", cl800="write"),
    AtCode("430", "ZOA", "WWWW", 6655, "write", run="offsets.zo_write", cl800="write"),
    AtCode("431", "ZOFA", "WWWW", 6656, "write", run="offsets.zo_write", cl800="write"),
    AtCode("432", "ZOPR", "WWW", 6657, "write", run="offsets.zo_write", cl800="write"),
    AtCode("434", "ZOD", "WW", 6658, "write", run="offsets.zo_write", cl800="write"),
    AtCode("435", "ZOPS", "WW", 6659, "write", run="offsets.zo_write", cl800="write"),
    AtCode("437", "ZOADW", "WWWW", 6660, "write_rotation", run="offsets.zo_write", cl800="write"),
    AtCode("438", "ZOFADW", "WWWW", 6661, "write_rotation", run="offsets.zo_write", cl800="write"),
    AtCode("439", "ZOPRDW", "WWWW", 6662, "write_rotation", run="offsets.zo_write", cl800="write"),
    AtCode("43a", "ZOFPRDW", "WWWW", 6663, "write_rotation", run="offsets.zo_write", cl800="write"),
    AtCode("440", "PRAP", "WW", 6669, "setpoint", cl800="write"),
    AtCode("442", "PRSS", "WW", 6670, "setpoint", cl800="write"),
    AtCode("446", "PRAD", "W", 6671, "setpoint", cl800="write"),
    AtCode("447", "PANG", "W", 6672, "setpoint", cl800="write"),
    AtCode("448", "PRIP", "WW", 6673, "setpoint", cl800="write"),
    AtCode("44b", "PCDA", "WWWW", 6674, "setpoint", run="memory.drive_write", cl800="write"),
    AtCode("44c", "PCDS", "WWWW", 6675, "setpoint", run="memory.drive_write", cl800="write"),
    AtCode("482", "PLCF", "WWWW", 6679, "write", run="plc.write", cl800="write"),
    AtCode("483", "PLCW", "WWWWW", 6680, "write", run="plc.write", cl800="write"),
    AtCode("493", "PLCFB", "WWW", 6684, "write", run="plc.write", cl800="write"),
    AtCode("494", "PLCDBL", "WWWW", 6685, "write", run="plc.write", cl800="write"),
    AtCode("495", "PLCDBR", "WWWW", 6686, "write", run="plc.write", cl800="write"),
    AtCode("4a3", "PLCFW", "WWWW", 6690, "write", run="plc.write", cl800="write"),
    AtCode("4b0", "PLCDF", "WWWWWW", 6694, "write", run="plc.write", cl800="write"),
    AtCode("4b1", "PLCDB", "WWWWWW", 6695, "write", run="plc.write", cl800="write"),
    AtCode("4b2", "PLCDG", "WWWW", 6696, "write", run="plc.write", cl800="write"),
    AtCode("4c0", "ALNZ", "W", 6700, "write", run="memory.alnz", cl800="write"),
    AtCode("4e1", "SATC", "WWW", 6704, "write", run="memory.satc", cl800="write"),
)
