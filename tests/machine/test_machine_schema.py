"""Machine files are validated, every key: malformed files end with a usage error naming the key path and the
value (never a traceback); every machine file of the repository loads; the generated docs and JSON Schema are
current and agree with the loader."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import jsonschema
import pytest

from ncvm.diagnostics import UsageError
from ncvm.machine.config import load_machine, load_scenario
from ncvm.machine.docgen import BEGIN, END, json_schema, json_text, markdown
from ncvm.machine.spec import section_defaults

ROOT = Path(__file__).parents[2]
MACHINES = sorted(p for p in ROOT.glob("**/*.toml") if p.name != "pyproject.toml" and ".venv" not in p.parts
                  and not p.name.endswith(".scenario.toml"))
SCENARIOS = sorted(ROOT.glob("examples/**/*.scenario.toml"))

AXES = "".join(f'[[axis]]\nname = "{n}"\nmin = -100.0\nmax = 100.0\n' for n in "XYZ")


def cases():
    """(TOML text, what the message must hold). A text starting with '!' is the whole file; else the file
    also has the three axes X Y Z (soft limits -100..100), before an [[axis]] text, else after it."""
    deep_tables = "[" + ".".join(["a"] * 500) + "]\nb = 1\n"
    rows = [
        # the file's structure and [[axis]]
        ("[machin]\n", "machin = {}: unknown key (known: machine, axis,"),
        ("colour = 1\n", "colour = 1: unknown key"),
        ("!axis = 5\n", "axis = 5: must be an array of tables, not an integer"),
        ('![axis]\nname = "X"\n', 'axis = { name = "X" }: must be an array of tables, not a table'),
        ("!axis = []\n", "axis = []: must have at least one entry"),
        ("![machine]\nname = 'no axes'\n", "axis: is missing"),
        ("![[axis]]\nkind = 'linear'\n", "axis[0].name: is missing"),
        ("!axis = [1, 2]\n", "axis[0] = 1: must be a table, not an integer"),
        ("[[axis]]\nname = 5\n", "axis[3].name = 5: must be a string, not an integer"),
        ('[[axis]]\nname = ""\n', 'axis[3].name = "": must be a letter, then letters, digits or _'),
        ('[[axis]]\nname = "1X"\n', 'axis[3].name = "1X": must be a letter'),
        ('[[axis]]\nname = "x"\n', 'axis[3].name = "x": repeats axis[0]: axis name must differ'),
        ('[[axis]]\nname = "A"\nkind = "round"\n', 'axis[3].kind = "round": must be one of "linear", "rotary"'),
        ('[[axis]]\nname = "A"\nmin = "low"\n', 'axis[3].min = "low": must be a number, not a string'),
        ('[[axis]]\nname = "A"\nmin = nan\n', "axis[3].min = nan: must be a finite number (NaN and infinity"),
        ('[[axis]]\nname = "A"\nmax = inf\n', "axis[3].max = inf: must be a finite number"),
        ('[[axis]]\nname = "A"\nmax = -inf\n', "axis[3].max = -inf: must be a finite number"),
        ('[[axis]]\nname = "A"\nmin = 5.0\nmax = 1.0\n', "axis[3].min = 5.0: is greater than max = 1.0"),
        ('[[axis]]\nname = "A"\nrapid = 0\n', "axis[3].rapid = 0: must be positive"),
        ('[[axis]]\nname = "A"\nrapid = -5.0\n', "axis[3].rapid = -5.0: must be positive"),
        ('[[axis]]\nname = "A"\nmax_feed = 0.0\n', "axis[3].max_feed = 0.0: must be positive"),
        ('[[axis]]\nname = "A"\nmax_feed = nan\n', "axis[3].max_feed = nan: must be a finite number"),
        ('[[axis]]\nname = "A"\naccel = 0\n', "axis[3].accel = 0: must be positive"),
        ('[[axis]]\nname = "A"\naccel = -1\n', "axis[3].accel = -1: must be positive"),
        ('[[axis]]\nname = "A"\naccel = inf\n', "axis[3].accel = inf: must be a finite number"),
        ('[[axis]]\nname = "A"\nmax_speed = 3\n', "axis[3].max_speed = 3: unknown key (known: name, kind,"),
        ('[[axis]]\nname = "A"\nrapid = true\n', "axis[3].rapid = true: must be a number, not a boolean"),
        # [machine]
        ("machine = 5\n", "machine = 5: must be a table, not an integer"),
        ("[machine]\ncolour = 1\n", "machine.colour = 1: unknown key (known: name, units, start_position)"),
        ("[machine]\nunits = 'inch'\n", 'machine.units = "inch": must be one of "mm"'),
        ("[machine]\nunits = 1\n", "machine.units = 1: must be a string"),
        ("[machine]\nname = 5\n", "machine.name = 5: must be a string"),
        ("[machine]\nstart_position = [0, 0]\n", "machine.start_position = [0, 0]: must give 3 values, one per axis"),
        ("[machine]\nstart_position = [0, 0, nan]\n", "machine.start_position[2] = nan: must be a finite number"),
        ("[machine]\nstart_position = [0, 0, 999]\n",
         "machine.start_position[2] = 999: lies outside the soft limits of axis Z (-100 to 100)"),
        ("[machine]\nstart_position = [-101, 0, 0]\n", "machine.start_position[0] = -101: lies outside"),
        ("[machine]\nstart_position = 'home'\n", 'machine.start_position = "home": must be an array of numbers'),
        ("[machine]\nstart_position = { X = 1 }\n", "machine.start_position = { X = 1 }: must be an array"),
        # [offsets]
        ("offsets = 5\n", "offsets = 5: must be a table, not an integer"),
        ("[offsets]\nG99 = [0, 0, 0]\n", "offsets.G99 = [0, 0, 0]: unknown key: a G54 ... G59 here must be one of"),
        ("[offsets]\ng54 = [0, 0, 0]\n", "offsets.g54 = [0, 0, 0]: unknown key"),
        ("[offsets]\nG54 = [1, 2]\n", "offsets.G54 = [1, 2]: must give 3 values, one per axis (X, Y, Z)"),
        ("[offsets]\nG54 = [1, 2, 'x']\n", 'offsets.G54[2] = "x": must be a number, not a string'),
        ("[offsets]\nG55 = [1, 2, nan]\n", "offsets.G55[2] = nan: must be a finite number"),
        ("[offsets]\nG54 = 5\n", "offsets.G54 = 5: must be an array of numbers"),
        # [[tool]]
        ("[[tool]]\nlength = 3\n", "tool[0].number: is missing"),
        ("[[tool]]\nnumber = -1\n", "tool[0].number = -1: must be zero or positive"),
        ("[[tool]]\nnumber = 1.5\n", "tool[0].number = 1.5: must be an integer, not a number"),
        ("[[tool]]\nnumber = '1'\n", 'tool[0].number = "1": must be an integer, not a string'),
        ("[[tool]]\nnumber = 1\n[[tool]]\nnumber = 1\n", "tool[1].number = 1: repeats tool[0]: tool number must differ"),
        ("[[tool]]\nnumber = 1\nlenght = 3\n", "tool[0].lenght = 3: unknown key (known: number, length, radius"),
        ("[[tool]]\nnumber = 1\nradius = -3\n", "tool[0].radius = -3: must be zero or positive"),
        ("[[tool]]\nnumber = 1\nradius = nan\n", "tool[0].radius = nan: must be a finite number"),
        ("[[tool]]\nnumber = 1\nlength = inf\n", "tool[0].length = inf: must be a finite number"),
        ("tool = 5\n", "tool = 5: must be an array of tables"),
        ("[[tool]]\nnumber = 1\nname = 3\n", "tool[0].name = 3: must be a string"),
        # [machine_data], [setting_data], [plc], [clock], [paths]
        ("[machine_data]\nfoo = 1\n", "machine_data.foo = 1: unknown key (no dialect reads [machine_data]"),
        ("machine_data = 5\n", "machine_data = 5: must be a table"),
        ("[setting_data]\nblock_skip = 'yes'\n", 'setting_data.block_skip = "yes": must be true or false'),
        ("[setting_data]\nfoo = 1\n", "setting_data.foo = 1: unknown key (known: block_skip)"),
        ("[plc]\nmarkers = {}\n", "plc.markers = {}: unknown key (known: inputs, outputs, flags, words)"),
        ("[plc]\ninputs = 5\n", "plc.inputs = 5: must be a table"),
        ('[plc]\ninputs = { "E1.0" = "on" }\n', 'plc.inputs."E1.0" = "on": must be true/false or an integer'),
        ("[plc]\nwords = { W1 = 1.5 }\n", "plc.words.W1 = 1.5: must be an integer"),
        ("[plc]\nflags = { M1 = nan }\n", "plc.flags.M1 = nan: must be an integer, not a number"),
        ("[clock]\nstart = 'monday'\n", 'clock.start = "monday": must be a number, not a string'),
        ("[clock]\nstart = nan\n", "clock.start = nan: must be a finite number"),
        ("[clock]\nstart = -1\n", "clock.start = -1: must be 0 to 253402300799"),
        ("[clock]\nstart = 1e300\n", "clock.start = 1e+300: must be 0 to 253402300799"),
        ("[clock]\ntz = 'UTC'\n", 'clock.tz = "UTC": unknown key (known: start)'),
        ("[paths]\nfile_root = 5\n", "paths.file_root = 5: must be a string, not an integer"),
        ("[paths]\nprogram_path = 5\n", "paths.program_path = 5: must be an array of strings"),
        ("[paths]\nprogram_path = [5]\n", "paths.program_path[0] = 5: must be a string"),
        ("[paths]\nfile_root = ''\n", 'paths.file_root = "": must be a path (not empty)'),
        ("[paths]\nprogram_dir = 'x'\n", 'paths.program_dir = "x": unknown key (known: program_path, file_root)'),
        ("paths = []\n", "paths = []: must be a table, not an array"),
        # [[scenario]]
        ("scenario = 5\n", "scenario = 5: must be an array of tables"),
        ("[scenario]\ntime = 1\n", "scenario = { time = 1 }: must be an array of tables, not a table"),
        ("scenario = [1]\n", "scenario[0] = 1: must be a table"),
        ("[[scenario]]\nkind = 'input'\n", "scenario[0].time: is missing"),
        ("[[scenario]]\ntime = 1\n", "scenario[0].kind: is missing (one of input, probe,"),
        ("[[scenario]]\ntime = 1\nkind = 'teleport'\n", 'scenario[0].kind = "teleport": must be one of "input"'),
        ("[[scenario]]\ntime = -1\nkind = 'input'\n", "scenario[0].time = -1: must be zero or positive"),
        ("[[scenario]]\ntime = nan\nkind = 'input'\n", "scenario[0].time = nan: must be a finite number"),
        ("[[scenario]]\ntime = inf\nkind = 'input'\n", "scenario[0].time = inf: must be a finite number"),
        ("[[scenario]]\ntime = 'soon'\nkind = 'input'\n", 'scenario[0].time = "soon": must be a number'),
        ("[[scenario]]\ntime = 1\nkind = 'input'\nvalue = 'on'\n", 'scenario[0].value = "on": must be true/false'),
        ("[[scenario]]\ntime = 1\nkind = 'input'\nbyte = 3\n", "scenario[0].byte = 3: must be 1 to 2"),
        ("[[scenario]]\ntime = 1\nkind = 'input'\ncolour = 1\n", "scenario[0].colour = 1: unknown key (known: time"),
        ("[[scenario]]\ntime = 1\nkind = 'probe'\nW = 1.0\n",
         "scenario[0].W = 1.0: unknown key: a axis name (CPL: where the probe switches"),
        ("[[scenario]]\ntime = 1\nkind = 'probe'\nX = nan\n", "scenario[0].X = nan: must be a finite number"),
        ("[[scenario]]\ntime = 1\nkind = 'fixed_stop'\nX = 'far'\n", 'scenario[0].X = "far": must be a number'),
        ("[[scenario]]\ntime = 1\nkind = 'timer'\nnumber = 1\nbase = 0.5\n",
         "scenario[0].base = 0.5: must be one of 0.01, 0.1, 1, 10"),
        ("[[scenario]]\ntime = 1\nkind = 'counter'\nnumber = 1\nvalue = 1000\n", "scenario[0].value = 1000: must be 0"),
        ("[[scenario]]\ntime = 1\nkind = 'plc'\narea = 'Z'\n", 'scenario[0].area = "Z": must be one of "I"'),
        ("[[scenario]]\ntime = 1\nkind = 'alarm'\n", "scenario[0].number: is missing"),
        ("[[scenario]]\ntime = 1\nkind = 'ci'\nindex = 1000\n", "scenario[0].index = 1000: must be 0 to 999"),
        ("[[scenario]]\ntime = 1\nkind = 'sercos'\nlocked = 1\n", "scenario[0].locked = 1: must be true or false"),
        # [cpl]
        ("cpl = 5\n", "cpl = 5: must be a table"),
        ("[cpl]\nzs_tabels = {}\n", "cpl.zs_tabels = {}: unknown key (known: lookahead, calls,"),
        ("[cpl]\nlookahead = -1\n", "cpl.lookahead = -1: must be zero or positive"),
        ("[cpl]\nlookahead = 1.5\n", "cpl.lookahead = 1.5: must be an integer"),
        ("[cpl]\nchannel = 0\n", "cpl.channel = 0: must be >= 1"),
        ('[cpl]\naxes = [{ name = "X", kanal = 1 }]\n', "cpl.axes[0].kanal = 1: unknown key"),
        ('[cpl]\naxes = ["X", "x"]\n', 'cpl.axes[1] = "x": repeats cpl.axes[0]: axis name must differ'),
        ('[cpl]\naxes = [{ name = "X", type = "spiral" }]\n', 'cpl.axes[0].type = "spiral": must be one of'),
        ('[cpl]\naxes = [{ name = "X", jog = 0 }]\n', "cpl.axes[0].jog = 0: must be positive"),
        ('[cpl]\naxes = [{ name = "X", index = 2 }, "Y"]\n', "cpl.axes[1] = 2: repeats cpl.axes[0]: physical axis number must differ"),
        ("[cpl]\nzs_unit = 'cm'\n", 'cpl.zs_unit = "cm": must be one of "mm", "inch"'),
        ("[cpl]\nzs_tables = { V2 = { G53 = [1.0] } }\n", "cpl.zs_tables.V2.G53 = [1.0]: unknown key"),
        ('[cpl]\ntc_tables = { K5 = { "10" = [1, 2, 3] } }\n', 'cpl.tc_tables.K5.10 = [1, 2, 3]: must have 1 to 2 entries'),
        ('[cpl]\nplc = { "Q:1" = 1 }\n', 'cpl.plc."Q:1" = 1: unknown key'),
        ("[cpl]\noverride = { rapid = 50 }\n", "cpl.override.rapid = 50: unknown key"),
        ("[cpl]\nspindle = { group = 5 }\n", "cpl.spindle.group = 5: must be 0 to 4"),
        ("[cpl]\nspindle = { min = 100, max = 50 }\n", "cpl.spindle.min = 100: is greater than max = 50"),
        ("[cpl]\ndate_format = 'YY.MM.DD'\n", 'cpl.date_format = "YY.MM.DD": must be one of "DD.MM", "DD.MM.YY"'),
        ("[cpl]\nareas = [{ type = 'forbidden' }]\n", 'cpl.areas[0].type = "forbidden": must be one of'),
        ("[cpl]\nareas = [" + ", ".join(["{}"] * 11) + "]\n", "cpl.areas = [{}, {}, {}, {}, {}, {}, {}, {}, ...]: "
                                                              "must have at most 10 entries"),
        ("[cpl]\ncalls = { G81 = 5 }\n", "cpl.calls.G81 = 5: must be a program name or a table"),
        ("[cpl]\ncalls = { X81 = 'CYC' }\n", 'cpl.calls.X81 = "CYC": unknown key: a address here'),
        ("[cpl]\ncalls = { G81 = { modal = true } }\n", "cpl.calls.G81.program: is missing"),
        ("[cpl]\nerrors = [{ number = 1, category = 11 }]\n", "cpl.errors[0].category = 11: must be 0 to 10"),
        ("[cpl]\ntool_database = [{ sector = 1 }]\n", "cpl.tool_database[0].place: is missing"),
        # [cl800]
        ("[cl800]\nstrict = 'yes'\n", 'cl800.strict = "yes": must be true or false'),
        ("[cl800]\ncontrol = '840'\n", 'cl800.control = "840": must be one of "810", "820", "850", "880"'),
        ("[cl800]\ncontrol = 880\n", "cl800.control = 880: must be a string"),
        ("[cl800]\nfoo = 1\n", "cl800.foo = 1: unknown key (known: strict, control)"),
        # [sin800]
        ("[sin800]\nm0 = 'explode'\n", 'sin800.m0 = "explode": must be one of "stop", "continue"'),
        ("[sin800]\nstrict_nc = 'yes'\n", 'sin800.strict_nc = "yes": must be true or false'),
        ("[sin800]\nchannel = 0\n", "sin800.channel = 0: must be 1 to 16"),
        ("[sin800]\nmax_call_depth = 0\n", "sin800.max_call_depth = 0: must be >= 1"),
        ("[sin800]\ndecode_ahead = -1\n", "sin800.decode_ahead = -1: must be zero or positive"),
        ("[sin800]\ngears = [0]\n", "sin800.gears[0] = 0: must be positive"),
        ("[sin800]\ngear = 6\n", "sin800.gear = 6: must be 1 to 5"),
        ("[sin800]\nr = { R1000 = 1 }\n", "sin800.r.R1000 = 1: unknown key: a R parameter here must be R0 .. R999"),
        ("[sin800]\nr = { R10 = nan }\n", "sin800.r.R10 = nan: must be a finite number"),
        ("[sin800]\nzero_offsets = { G99 = [0, 0, 0] }\n", "sin800.zero_offsets.G99 = [0, 0, 0]: unknown key"),
        ("[sin800]\nzero_offsets = { G54 = [1, 2] }\n", "sin800.zero_offsets.G54 = [1, 2]: must give 3 values"),
        ("[sin800]\nzero_offsets = { G54 = { coarse = [1, 2, 3], medium = [0, 0, 0] } }\n",
         "sin800.zero_offsets.G54.medium = [0, 0, 0]: unknown key (known: coarse, fine)"),
        ("[sin800]\nzero_offsets = { DRF = { coarse = [1, 2, 3] } }\n",
         "sin800.zero_offsets.DRF = { coarse = [1, 2, 3] }: only the settable offsets G54..G57 have coarse and fine"),
        ("[cpl]\nzs_tables = { V2 = { columns = ['X'], G54 = [1, 2] } }\n",
         "cpl.zs_tables.V2.G54 = [1, 2]: has more values than the 1 columns"),
        ('[sin800]\nnc_md = { "2240" = nan }\n', 'sin800.nc_md.2240 = nan: must be a finite number'),
        ('[sin800]\nnc_md = { "5001" = "00020010" }\n', 'sin800.nc_md.5001 = "00020010": must be a bit pattern such as "00010010"'),
        ('[sin800]\ninputs = { "3" = "00000001" }\n', 'sin800.inputs.3 = "00000001": unknown key: a input byte here must be one of "1", "2"'),
        ('[sin800.plc.5]\nI = { "0" = "00000001" }\n', 'sin800.plc.5 = { I = { 0 = "00000001" } }: unknown key'),
        ('[sin800.plc.1]\nX = { "0" = 1 }\n', 'sin800.plc.1.X = { 0 = 1 }: unknown key (known: I, Q, P, F,'),
        ('[sin800.plc.1]\nDB = { "10" = [70000] }\n', 'sin800.plc.1.DB.10[0] = 70000: must be 0 to 65535'),
        ("[sin800]\ntool_offsets = [{ p = [1, 2] }]\n", "sin800.tool_offsets[0].d: is missing"),
        ("[sin800]\nv24_input = 5\n", "sin800.v24_input = 5: must be a string"),
        ("[sin800]\nalarms = [-1]\n", "sin800.alarms[0] = -1: must be zero or positive"),
        ("[sin800]\nfoo = 1\n", "sin800.foo = 1: unknown key (known: control, channel, m0,"),
        ('[sin800.m_functions."20"]\nR10 = "hello"\n',
         'sin800.m_functions.20.R10 = "hello": must be PLC data such as "DB20.DW1" or "PLC2.DB20.DW1"'),
        ('[sin800.m_functions."20"]\nR10 = "PLC5.DB20.DW1"\n', 'R10 = "PLC5.DB20.DW1": must be PLC data'),
        # [sympas]
        ("[sympas]\ncounts_per_unit = 0\n", "sympas.counts_per_unit = 0: must be positive"),
        ("[sympas]\ntask_slice_ticks = 0\n", "sympas.task_slice_ticks = 0: must be positive"),
        ("[sympas]\nservo_ticks = -1\n", "sympas.servo_ticks = -1: must be positive"),
        ("[sympas]\nstatements_per_tick = 0\n", "sympas.statements_per_tick = 0: must be >= 1"),
        ("[sympas]\ntrac = 0\n", "sympas.trac = 0: must be positive"),
        ("[sympas]\ntrvl = nan\n", "sympas.trvl = nan: must be a finite number"),
        ("[sympas]\nevent_trigger = 'sometimes'\n", 'sympas.event_trigger = "sometimes": must be one of "level"'),
        ("[sympas]\nbusy_move = 'queue'\n", 'sympas.busy_move = "queue": must be one of "refuse", "override"'),
        ("[sympas]\naxis_names = ['A', 'B']\n", 'sympas.axis_names = ["A", "B"]: must give 3 values'),
        ("[sympas]\naxis_names = ['A', 'B', 'NINECHARS']\n", 'sympas.axis_names[2] = "NINECHARS": must have 1 to 8'),
        ("[sympas]\naxis_names = ['A', 'B', 'A']\n", 'sympas.axis_names[2] = "A": repeats sympas.axis_names[0]'),
        ("[sympas]\ninputs = [{ axis = 'A1', bit = 1, function = 'XX' }]\n",
         'sympas.inputs[0].function = "XX": must be one of "EO"'),
        ("[sympas]\ninputs = [{ axis = 'A1', bit = 33, function = 'EO' }]\n", "sympas.inputs[0].bit = 33: must be 1"),
        ("[sympas]\naxst_bits = { bogus = 3 }\n", "sympas.axst_bits.bogus = 3: unknown key (known: profile_end,"),
        ("[sympas]\naxst_bits = { homed = 40 }\n", "sympas.axst_bits.homed = 40: must be 0 to 31"),
        ("[sympas]\naxst_bits = { homed = 1 }\n", "sympas.axst_bits.homed = 1: is also the bit of in_position (its default)"),
        ("[sympas]\naxst_bits = { eo = 20, dnr = 20 }\n", "sympas.axst_bits.dnr = 20: is also the bit of eo"),
        ("[sympas]\nssf_codes = { write_ci = 5, spool_halt = 5 }\n", "sympas.ssf_codes.spool_halt = 5: is also the code of write_ci"),
        ("[sympas]\nindex_period = nan\n", "sympas.index_period = nan: must be a finite number"),
        ("[sympas]\nsoft_limit_reaction = 'X'\n", 'sympas.soft_limit_reaction = "X": must be one of "SMD"'),
        ("[sympas]\nclock_start = -1\n", "sympas.clock_start = -1: must be 0 to 4294967295"),
        ("[sympas]\nzero_offsets = { 1 = [5.0] }\n", 'sympas.zero_offsets.1 = [5.0]: must give 3 values'),
        ("[sympas]\nfoo = 1\n", "sympas.foo = 1: unknown key (known: axis_names,"),
        # [din], deep nesting, not TOML
        ("[din]\nfoo = 1\n", "din.foo = 1: unknown key (known: arc_radius_tolerance, arc_radius_tolerance_inch, "
                                "arc_radius_relative, profile)"),
        ("din = 5\n", "din = 5: must be a table"),
        (deep_tables, "a = { a = { a = { ... } } }: unknown key"),
        ("!x = " + "[" * 3000 + "]" * 3000 + "\n", "not valid TOML: arrays or inline tables nested too deeply"),
        ("!x = " + "{a=" * 3000 + "1" + "}" * 3000 + "\n", "not valid TOML: arrays or inline tables nested too"),
        ("[[axis]\nname = 'A'\n", "not valid TOML"),
        ('![machine]\nname = "a"\nname = "b"\n', 'Cannot overwrite a value (at line 3, column 11): name = "b"'),
        ('[cpl]\nlookahead = 1\n[cpl]\nchannel = 1\n', "Cannot declare ('cpl',) twice (at line 3, column 5): [cpl]"),
        # finite but absurd magnitudes: sums and squares overflowed, divisions by them gave NaN cycle times
        ('[[axis]]\nname = "A"\naccel = 5e-324\n', "axis[3].accel = 5e-324: must be positive and at least 1e-09"),
        ('[[axis]]\nname = "A"\nrapid = 1e-300\n', "axis[3].rapid = 1e-300: must be positive and at least 1e-09"),
        ("[offsets]\nG54 = [1.7e308, 0.0, 0.0]\n", "offsets.G54[0] = 1.7e+308: must lie between -1e+15 and 1e+15"),
        ('[[axis]]\nname = "A"\nmin = -1' + "0" * 400 + "\n", "axis[3].min = -1000000000000000000000000000000"),
        ('[[axis]]\nname = "A"\nrapid = 1' + "0" * 400 + "\n", "must lie between -1e+15 and 1e+15"),
        ("[[tool]]\nnumber = 1" + "0" * 30 + "\n", "tool[0].number = 1" + "0" * 30 + ": must lie between"),
        ("[[tool]]\nnumber = 1" + "0" * 5000 + "\n", "not valid TOML: an integer with thousands of digits"),
        ("[sympas]\nservo_ticks = 1e-20\n", "sympas.servo_ticks = 1e-20: must be positive and at least 1e-09"),
    ]
    return [(text[1:] if text.startswith("!") else AXES + text if text.startswith("[[axis]]") else text + AXES,
             expected) for text, expected in rows]


CASES = cases()


def _write(tmp_path: Path, text: str) -> Path:
    p = tmp_path / "bad.toml"
    p.write_text(text, encoding="utf-8")
    return p


def test_there_are_over_a_hundred_malformed_files():
    assert len(CASES) >= 150


@pytest.mark.parametrize("text, expected", CASES, ids=[f"{i:03d}" for i in range(len(CASES))])
def test_malformed_machine_file_names_key_and_value(tmp_path, text, expected):
    p = _write(tmp_path, text)
    with pytest.raises(UsageError) as e:
        load_machine(p)
    message = str(e.value)
    assert message.startswith(f"{p}: ")
    assert expected in message


#: a sample through the real command line: the issue's crashes and silent acceptances (a piece of each file)
CLI_SAMPLE = ["axis = 5", "offsets = 5", "file_root = 5", "program_path = 5", "counts_per_unit = 0",
              "scenario = 5", "teleport", "m0 = 'explode'", "strict_nc = 'yes'", "G99", "number = -1",
              "[din]", "start_position = [0, 0, 999]", "lookahead = -1", "accel = 5e-324", "1.7e308",
              "0" * 400]


def _cli_rows():
    return [next((text, expected) for text, expected in CASES if piece in text) for piece in CLI_SAMPLE]


def test_malformed_machine_files_through_the_cli(tmp_path):
    prog = tmp_path / "part.din"
    prog.write_text("G0 X1\nM2\n")
    env = {**os.environ, "NCVM_DEBUG": "0"}
    for i, (text, expected) in enumerate(_cli_rows()):
        bad = tmp_path / f"bad{i}.toml"
        bad.write_text(text, encoding="utf-8")
        r = subprocess.run([sys.executable, "-m", "ncvm", "run", str(prog), "--machine", str(bad),
                            "--state", str(tmp_path / "st")], capture_output=True, text=True, env=env, timeout=120)
        assert r.returncode == 2, (text, r.stderr)
        assert r.stderr.startswith(f"ncvm: error: {bad}: machine file error: ") and expected in r.stderr, r.stderr
        assert "Traceback" not in r.stderr and r.stdout == ""


def test_scenario_file_is_checked_against_the_machine_axes(tmp_path):
    p = tmp_path / "s.toml"
    p.write_text("[[scenario]]\ntime = 0\nkind = 'probe'\nQ = 1.0\n")
    with pytest.raises(UsageError, match=r"scenario file error: scenario\[0\]\.Q = 1\.0: unknown key"):
        load_scenario(p, ("X", "Y", "Z"))
    assert load_scenario(p, ("X", "Q"))[0].position == {"Q": 1.0}
    p.write_text("[[scenario]]\ntime = 1\nkind = 'input'\n[axis]\nname = 'X'\n")
    with pytest.raises(UsageError, match=r"axis = \{ name = \"X\" \}: unknown key \(known: scenario; a scenario file holds only"):
        load_scenario(p)


@pytest.mark.parametrize("kind", ["fifo", "device", "huge"])
def test_a_machine_file_that_never_ends_is_refused_at_once(tmp_path, kind):
    """A FIFO blocked the run, /dev/zero was read until memory ran out."""
    p = tmp_path / "m.toml"
    if kind == "fifo":
        os.mkfifo(p)
    elif kind == "device":
        p = Path("/dev/zero")
    else:
        with p.open("wb") as f:
            f.truncate(17 * 2 ** 20)  # sparse: 17 MB of NUL bytes
    why = "larger than 16 MB" if kind == "huge" else "not a file"
    with pytest.raises(UsageError, match=f"cannot read machine file {p}: {why}"):
        load_machine(p)
    with pytest.raises(UsageError, match=f"cannot read scenario file {p}: {why}"):
        load_scenario(p)


def test_line_ends_of_old_editors_load(tmp_path):
    p = tmp_path / "m.toml"
    p.write_bytes(b"[machine]\r\nname = 'crlf'\r" + AXES.encode())
    assert load_machine(p).name == "crlf"


def test_a_machine_file_with_a_byte_order_mark_loads(tmp_path):
    """Windows editors save UTF-8 with a byte-order mark; TOML parsers take it as a stray character."""
    p = tmp_path / "bom.toml"
    p.write_bytes(("\ufeff[machine]\nname = 'bom'\n" + AXES).encode("utf-8"))
    m = load_machine(p)
    assert m.name == "bom" and [a.name for a in m.axes] == ["X", "Y", "Z"]


@pytest.mark.parametrize("path", MACHINES, ids=lambda p: str(p.relative_to(ROOT)))
def test_every_machine_file_of_the_repository_loads_and_fits_the_json_schema(path):
    m = load_machine(path)
    assert m.axes
    import tomllib

    jsonschema.validate(tomllib.loads(path.read_text()), json_schema())


@pytest.mark.parametrize("path", SCENARIOS, ids=lambda p: p.name)
def test_example_scenarios_load(path):
    assert load_scenario(path, ("X", "Y", "Z"))


def test_the_json_schema_is_valid_and_rejects_what_the_loader_rejects():
    import tomllib

    schema = json_schema()
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    # every check of the loader that a JSON Schema can state: not NaN (JSON has none), not a count or a limit
    # taken from the [[axis]] list, not a rule across keys or entries
    unstated = ("nan", "one per axis", "must give 3 values", "repeats", "is greater than", "lies outside", "is also the",
                "a axis name", "coarse and fine")
    for text, expected in CASES:
        if any(u in expected for u in unstated):
            continue
        try:
            data = tomllib.loads(text)
        except (tomllib.TOMLDecodeError, RecursionError, ValueError):
            continue
        assert not validator.is_valid(data), text[:200]


def test_docs_and_json_schema_are_generated_from_the_schema():
    doc = (ROOT / "docs" / "machine-file.md").read_text(encoding="utf-8")
    block = doc.split(BEGIN, 1)[1].split(END, 1)[0]
    assert block.strip() == markdown().strip(), "docs/machine-file.md is stale: run `make docs`"
    assert (ROOT / "docs" / "machine-file.schema.json").read_text(encoding="utf-8") == json_text(), \
        "docs/machine-file.schema.json is stale: run `make docs`"
    assert json.loads(json_text())["properties"]["sin800"]["properties"]["m0"]["enum"] == ["stop", "continue"]


def test_cli_prints_the_json_schema():
    r = subprocess.run([sys.executable, "-m", "ncvm", "machine-schema"], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and json.loads(r.stdout) == json_schema()


def test_declared_defaults_are_the_ones_the_dialects_use():
    from ncvm.dialects.sinumerik.cl800 import OPTIONS
    from ncvm.dialects.sympas.options import AXST_BITS, DEFAULTS, SSF_CODES

    declared = section_defaults("sympas")
    for key, value in DEFAULTS.items():
        if key in ("axis_names", "axst_bits", "ssf_codes"):
            continue
        assert declared[key] == value, key
    assert set(declared) == set(DEFAULTS)
    assert {k: v.default for k, v in _fields("sympas", "axst_bits").items()} == AXST_BITS
    assert {k: v.default for k, v in _fields("sympas", "ssf_codes").items()} == SSF_CODES
    assert section_defaults("cl800") == OPTIONS


def _fields(section: str, key: str) -> dict:
    """The keys of the table (or of the tables in the array) ``section.key``."""
    from ncvm.machine.schema import Either, ListOf, Table
    from ncvm.machine.spec import MACHINE_FILE

    sec = next(f.type for f in MACHINE_FILE.fields if f.name == section)
    node = next(f.type for f in sec.fields if f.name == key)
    node = node.item if isinstance(node, ListOf) else node
    node = next(o for o in node.options if isinstance(o, Table)) if isinstance(node, Either) else node
    return {f.name: f for f in node.fields}


def test_cpl_lookahead_0_is_documented_as_the_block_buffer():
    """`[cpl] lookahead = 0` (the default) is the bounded block buffer, no longer "no limit"."""
    from ncvm.dialects.cpl.runtime import BLOCK_BUFFER

    text = json_schema()["properties"]["cpl"]["properties"]["lookahead"]["description"]
    assert "no limit" not in text and f"{BLOCK_BUFFER:,}" in text and f"{BLOCK_BUFFER // 2:,}" in text, text
