"""A newcomer's second review of issue 19 from a fresh clone: each defect found, one failing test each.

The plots are rendered from the examples (copied into a temporary folder, run as ``make run`` runs them)
and asserted on the figure or on the pixels of the saved PNG.
"""

from __future__ import annotations

import itertools
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


def ncvm(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "ncvm", *args], cwd=cwd, capture_output=True, text=True,
                          timeout=300)


def summary_line(stderr: str) -> str:
    lines = [line for line in stderr.splitlines() if line.startswith(("ncvm: ended", "ncvm: stopped"))]
    assert lines, stderr
    return lines[-1]


def plotted(program: Path, tmp_path: Path):
    """Run ``program`` on its folder's machine file as ``make run`` does; its figure (matplotlib) and result."""
    from ncvm.api import run
    from ncvm.runtime.session import RunOptions
    from ncvm.sinks.plotview import figure, plot_title

    machine = program.parent / "machine.toml"
    scenario = program.with_suffix(".scenario.toml")  # measlog.cpl's probe trigger points, as make run uses them
    result, session = run(program, machine=machine if machine.is_file() else None,
                          options=RunOptions(state_dir=tmp_path / "state", plot=True,
                                             scenario=scenario if scenario.is_file() else None))
    assert result["status"] == "ok", result["error"]
    violations = [v for v in session.checks.violations() if getattr(v, "point", None) is not None]
    return figure(session.plot, plot_title(program, result, session.machine.name), violations), result


def example(tmp_path: Path, name: str) -> Path:
    shutil.copytree(EXAMPLES, tmp_path / "examples")
    return tmp_path / "examples" / name


def legend_texts(fig) -> list[str]:
    return [t.get_text() for t in fig.legend_box.get_legend().get_texts()]


# --- item 2: the summary line ------------------------------------------------------------------------------


def test_summary_line_of_a_six_axis_machine_is_at_most_160_characters(tmp_path):
    """Issue 19 item 2: "the summary line is 200 characters" (docs/decisions.md: "at most about 160").
    One bound per axis makes it grow with the machine: a six-axis mill (X Y Z A B C) gives 202 characters."""
    axes = "".join(f'\n[[axis]]\nname = "{n}"\nkind = "{k}"\nmin = -9999.0\nmax = 9999.0\nrapid = 20000.0\n'
                   f'max_feed = 9000.0\naccel = 2000.0\n'
                   for n, k in zip("XYZABC", ["linear"] * 3 + ["rotary"] * 3))
    (tmp_path / "machine.toml").write_text('[machine]\nname = "six-axis mill"\n' + axes)
    (tmp_path / "six_axes.din").write_text(
        "N10 G90 G0 X-1234.56 Y-1234.56 Z-1234.56 A-1234.56 B-1234.56 C-1234.56\n"
        "N20 G1 X1234.56 Y1234.56 Z1234.56 A1234.56 B1234.56 C1234.56 F9000\nN30 M30\n")
    done = ncvm("run", "six_axes.din", "--state", "st", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    line = summary_line(done.stderr)
    assert len(line) <= 160, f"{len(line)} characters: {line}"


def test_summary_line_bounds_say_their_frame_or_are_the_programs(tmp_path):
    """Issue 19 item 2: "everything is drawn in machine coordinates without saying so ... a long rapid is drawn
    from machine zero". The plot of examples/sin800/flange.mpf now shows the program's X -37..37, but the
    summary line under it says X[0,186.98] Y[0,136.95] Z[0,135.1]: machine coordinates (G54 150/100, tool
    length 85) and machine zero where the run began, without a word saying so."""
    program = example(tmp_path, "sin800/flange.mpf")
    done = ncvm("run", str(program), "--state", str(tmp_path / "st"), cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    line = summary_line(done.stderr)
    lo, hi = (float(v) for v in re.search(r"\bX\[(-?[\d.]+),(-?[\d.]+)\]", line).groups())
    assert "machine" in line or (lo >= -40 and hi <= 40), line


# --- item 2: the plots -------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", ["cl800/deep_hole.cl8", "cpl/partcount.cpl", "cpl/measlog.cpl"])
def test_3d_view_axis_titles_overlap_no_other_text(tmp_path, name):
    """Issue 19 item 2: "XY plus side views and a 3-D view that is readable". With equal scales a path that is
    long in one axis and short in another becomes a needle, and the 3-D view's axis titles are written over
    each other or over the tick numbers: deep_hole.cl8 "X (work)" over "Y (work)", partcount.cpl "X (work)"
    over the Z tick "0", measlog.cpl "X (work)" over its own tick "0" (seen in out/*.png of `make run`)."""
    program = example(tmp_path, name)
    fig, _ = plotted(program, tmp_path)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    ax = fig.views["3-D"]
    titles, ticks = {}, {}
    for axis_name, axis in (("x", ax.xaxis), ("y", ax.yaxis), ("z", ax.zaxis)):
        titles[f"{axis_name} title {axis.label.get_text()!r}"] = axis.label.get_window_extent(renderer)
        low, high = sorted(axis.get_view_interval())
        for at, tick in zip(axis.get_majorticklocs(), axis.get_ticklabels()):
            if tick.get_visible() and tick.get_text() and low <= at <= high:
                ticks[f"{axis_name} tick {tick.get_text()!r}"] = tick.get_window_extent(renderer)
    clashes = [(a, b) for (a, ea), (b, eb) in itertools.combinations(titles.items(), 2) if ea.overlaps(eb)]
    clashes += [(a, b) for a, ea in titles.items() for b, eb in ticks.items() if ea.overlaps(eb)]
    assert not clashes, clashes


def test_a_rapid_from_a_point_the_program_named_is_drawn(tmp_path):
    """Issue 19 item 2 / README "Plots": only "the rapids at the beginning that leave from where the simulated
    run began (a position the program never named) are not drawn". `G0 X40 Y0 Z50` then `G0 Z2`: the second
    rapid leaves from X40 Y0 Z50, every axis named by the program, yet it is dropped because Y0 happens to be
    the start's Y; the legend says "2 rapids from the start position" and the start mark sits at Z2.
    examples/cpl/flange.cpl shows the same: "3 rapids from the start position", the third from X40 Y0 Z50."""
    (tmp_path / "approach.din").write_text("N10 G90 G0 X40 Y0 Z50\nN20 G0 Z2\nN30 G1 Z-5 F100\nN40 G0 Z50\n"
                                           "N50 M30\n")
    fig, _ = plotted(tmp_path / "approach.din", tmp_path)
    notes = [t for t in legend_texts(fig) if "from the start" in t]
    assert notes and notes[0].startswith("1 rapid "), notes
    starts = [line for line in fig.views["XZ"].lines if line.get_marker() == "o" and line.get_color() == "green"]
    assert starts and (starts[0].get_xdata()[0], starts[0].get_ydata()[0]) == (40, 50)


def test_start_mark_is_visible_when_the_program_ends_where_it_began(tmp_path):
    """Issue 19 item 2: "start/end and limit violations marked". When a program ends where it began
    (examples/sympas/two_tasks.sap, pick_place.sap; cl800/deep_hole.cl8) the red end square is drawn over the
    green start dot of the same size in every view: the PNG shows no start at all, only "end"."""
    import numpy as np
    from PIL import Image

    program = example(tmp_path, "sympas/two_tasks.sap")
    fig, _ = plotted(program, tmp_path)
    png = tmp_path / "two_tasks.png"
    fig.savefig(png, dpi=100)
    box = fig.views["XY"].get_window_extent()
    pixels = np.asarray(Image.open(png).convert("RGB")).astype(int)
    height = pixels.shape[0]
    top_view = pixels[int(height - box.y1):int(height - box.y0), int(box.x0):int(box.x1)]
    green = (np.abs(top_view - np.array([0, 128, 0])) <= 40).all(axis=2).sum()  # matplotlib's "green"
    assert green >= 10, f"{green} green pixels of the start mark in the top view"


# --- item 4: commands that protect the user's files ---------------------------------------------------------


def test_refusal_to_overwrite_a_listing_names_the_option_that_names_a_listing(tmp_path):
    """Issue 19 item 4: refuse to overwrite a file ncvm did not write. For a hand-edited listing
    (`ncvm compile P.cl8 --xref` beside an edited P.lst) the refusal says "give another name with -o", but -o
    names the object program; the listing is named with `--xref LISTING`, and `--xref` alone writes no object."""
    shutil.copy(EXAMPLES / "cl800" / "hole_pattern.cl8", tmp_path)
    assert ncvm("compile", "hole_pattern.cl8", "--xref", cwd=tmp_path).returncode == 0
    listing = tmp_path / "hole_pattern.lst"
    listing.write_text("my notes\n" + listing.read_text())
    done = ncvm("compile", "hole_pattern.cl8", "--xref", cwd=tmp_path)
    assert done.returncode == 2, done.stderr
    assert listing.read_text().startswith("my notes")
    assert "--xref" in done.stderr, done.stderr


# --- item 1: self-contained --------------------------------------------------------------------------------


def test_user_docs_do_not_send_the_reader_to_issues_the_clone_does_not_hold():
    """Issue 19 item 1: "A clone must hold everything it refers to". The user documentation still explains
    itself by the project's issue numbers, which a newcomer with a clone cannot look up: docs/sin800.md "the NC
    side of CL 800 (issue 5)", docs/profiles.md "(issue 14)", docs/planner.md "Until issue 18",
    docs/performance.md's title. (A quoted heading of docs/decisions.md, which the clone holds, is fine.)"""
    pages = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
    found = [f"{page.relative_to(ROOT)}:{number}: {line.strip()[:90]}"
             for page in pages if page.name != "decisions.md"
             for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1)
             if re.search(r'(?<!")\b[Ii]ssues? \d+', line)]
    assert not found, "\n".join(found)
