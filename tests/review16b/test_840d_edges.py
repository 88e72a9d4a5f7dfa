"""Issue 16 rule 1: "tool length as `G43 H<n>` (LinuxCNC/ISO) or the target's equivalent ... A header comment
lists the offsets and tools the simulation used, so the user can set up the new control."

On the SINUMERIK 880 a D number is a tool offset of its own (D1..D818, any tool may use it); on an 840D
`D<n>` is cutting edge n *of the active tool*, and `T<n> M6` activates the new tool's edge D1 by itself.
The program below keeps D1 (85.1 mm) active for tool 2. The 840D translation writes `T2 M6` and nothing
else, and its header asks only for "tool offset D1: length 85.1 mm" without naming a tool: set up as told
(T1 D1 = 85.1), the 840D drills with T2's own D1 (a new tool's edge starts at length 0): 85.1 mm deeper
than the old control, into the part. The header must name every tool/edge pair the moves used.
"""

from pathlib import Path

from .helpers import translate

MACHINE = (Path(__file__).parents[2] / "examples" / "sin800" / "machine.toml").read_text().replace(
    'name = "drill 8.5"\n', 'name = "drill 8.5"\n\n[[tool]]\nnumber = 2\nname = "drill 6"\n', 1)

TWO_TOOLS_ONE_D = """%MPF2
N10 G17 G71 G90 G54 G94
N20 T1 M6 D1
N30 G0 X0 Y0 Z50
N40 G1 Z-2 F100
N50 G0 Z50
N60 T2 M6 D1
N70 G0 X20 Y0 Z50
N80 G1 Z-2 F100
N90 G0 Z50
N100 M30
"""


def test_840d_header_names_the_d1_length_for_each_tool_that_used_it(tmp_path):
    (tmp_path / "machine.toml").write_text(MACHINE)
    rc, text, err = translate(tmp_path, TWO_TOOLS_ONE_D, "tools.mpf", "--target", "sinumerik840d",
                              "--machine", str(tmp_path / "machine.toml"), out_name="out.mpf")
    assert rc == 0, err
    header = [line for line in text.splitlines() if line.startswith(";")]
    assert any("T2" in line and "D1" in line and "85.1" in line for line in header), (
        "the 840D setup never says that tool 2's edge D1 must be 85.1 mm long:\n" + text)
