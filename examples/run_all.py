"""Run every example program on its folder's machine.toml (else the built-in machine), one plot each.

Used by ``make run``. Sub-programs (files that a main program calls) are listed
in each dialect folder's ``main.txt`` when only some files are main programs. A
program's ``<name>.keys`` (operator key presses) and ``<name>.scenario.toml``
(inputs and probe trigger points over time) are used when they exist.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ncvm.api import run
from ncvm.diagnostics import UsageError
from ncvm.dialects import EXTENSIONS
from ncvm.runtime.session import RunOptions
from ncvm.sinks.plotview import plot_run

HERE = Path(__file__).parent


def main_programs(folder: Path) -> list[Path]:
    listing = folder / "main.txt"
    if listing.is_file():
        return [folder / name.strip() for name in listing.read_text().splitlines() if name.strip()]
    return sorted(p for p in folder.iterdir() if p.suffix.lower() in EXTENSIONS)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="out")
    args = ap.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    failures = 0
    for folder in sorted(p for p in HERE.iterdir() if p.is_dir() and p.name != "machines"):
        for program in main_programs(folder):
            machine = folder / "machine.toml"
            keys = program.with_suffix(".keys")  # a dialog program comes with the operator's key presses
            dialog = keys.is_file()
            scenario = program.with_suffix(".scenario.toml")  # and a measuring one with its probe trigger points
            shot = out / f"{folder.name}_{program.stem}_screen.png"
            try:
                result, session = run(program, machine=machine if machine.is_file() else None,
                                      options=RunOptions(state_dir=out / ".ncvm", plot=True, keys=keys if dialog else None,
                                                         screen=shot if dialog else None,
                                                         scenario=scenario if scenario.is_file() else None))
            except UsageError as e:
                print(f"{program}: {e}", file=sys.stderr)
                failures += 1
                continue
            plot = out / f"{folder.name}_{program.stem}.png"
            plot_run(plot, program, result, session)
            m = result["motion"]
            status = result["status"] if not result["error"] else f"error {result['error']['code']}: " \
                                                                   f"{result['error']['message']}"
            print(f"{program.relative_to(HERE)}: {status}; {m['rapid_moves'] + m['feed_moves'] + m['arc_moves']} "
                  f"moves, feed path {m['feed_length']:.1f} mm, cycle time {result['cycle_time_s']:.1f} s -> {plot}")
            if dialog and shot.is_file():
                print(f"    screen -> {shot}")
            for line in result["output"][:5]:
                print(f"    | {line}")
            failures += result["status"] != "ok"
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
