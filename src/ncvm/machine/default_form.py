"""The built-in default machine file (default_machine.toml) as tomllib parses it: a run on that machine
imports no TOML parser (tomllib's import and the parse take about 6 ms of a 0.1 s start-up, issue 18).

config.py still reads the file on every run and takes this form only when the file reads exactly as
:data:`TEXT`; an edited file is parsed and checked as any machine file. tests/machine/test_default_form.py
checks that :data:`TEXT` is the file and :func:`data` tomllib's parse of it: change the three together.
"""

TEXT = """\
# ncvm built-in default machine: a 3-axis vertical mill (X Y Z), metric.
# Every key is documented in docs/machine-file.md.
[machine]
name = "default 3-axis mill"
units = "mm"

[[axis]]
name = "X"
kind = "linear"
min = -500.0
max = 500.0
rapid = 10000.0      # mm/min
max_feed = 5000.0    # mm/min
accel = 1000.0       # mm/s^2

[[axis]]
name = "Y"
kind = "linear"
min = -400.0
max = 400.0
rapid = 10000.0
max_feed = 5000.0
accel = 1000.0

[[axis]]
name = "Z"
kind = "linear"
min = -300.0
max = 200.0
rapid = 8000.0
max_feed = 4000.0
accel = 800.0

[offsets]
# zero offsets G54..G59, one value per axis in axis order
G54 = [0.0, 0.0, 0.0]

[[tool]]
number = 1
length = 50.0
radius = 5.0

[[tool]]
number = 2
length = 75.0
radius = 3.0

[paths]
program_path = ["."]
file_root = "files"
"""


def data() -> dict:
    """A new parse each call, as tomllib gives (the machine built from it may keep its lists)."""
    return {'machine': {'name': 'default 3-axis mill', 'units': 'mm'},
            'axis': [{'name': 'X',
                      'kind': 'linear',
                      'min': -500.0,
                      'max': 500.0,
                      'rapid': 10000.0,
                      'max_feed': 5000.0,
                      'accel': 1000.0},
                     {'name': 'Y',
                      'kind': 'linear',
                      'min': -400.0,
                      'max': 400.0,
                      'rapid': 10000.0,
                      'max_feed': 5000.0,
                      'accel': 1000.0},
                     {'name': 'Z',
                      'kind': 'linear',
                      'min': -300.0,
                      'max': 200.0,
                      'rapid': 8000.0,
                      'max_feed': 4000.0,
                      'accel': 800.0}],
            'offsets': {'G54': [0.0, 0.0, 0.0]},
            'tool': [{'number': 1, 'length': 50.0, 'radius': 5.0}, {'number': 2, 'length': 75.0, 'radius': 3.0}],
            'paths': {'program_path': ['.'], 'file_root': 'files'}}
