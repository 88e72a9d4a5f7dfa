"""ncvm benchmarks (not tests): each case several times, min and median, and the rate.

    python bench/run.py [--repeat N] [--only SUBSTR] [--json FILE]

Cases come from the modules ``bench/cases_*.py``; each defines ``cases()``
returning ``{name: Case}``. Peer cases (``rs274_<case>``) run LinuxCNC's
``rs274`` on the same work when it is installed.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import statistics
import sys
import time
from pathlib import Path

HERE = Path(__file__).parent
sys.path.insert(0, str(HERE))

from benchlib import Case  # noqa: E402


def discover() -> dict[str, Case]:
    found: dict[str, Case] = {}
    for path in sorted(HERE.glob("cases_*.py")):
        spec = importlib.util.spec_from_file_location(path.stem, path)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        found.update(module.cases())
    return found


def measure(case: Case, repeat: int) -> dict:
    if case.setup:
        case.setup()
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        case.run()
        times.append(time.perf_counter() - t0)
    med, lo = statistics.median(times), min(times)
    return {"median_s": med, "min_s": lo, "rate": case.count / med, "unit": case.unit}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--only", default="")
    ap.add_argument("--json", dest="json_file")
    args = ap.parse_args()
    results = {}
    print(f"{'case':28} {'min s':>10} {'median s':>10} {'rate':>14}  unit")
    for name, case in discover().items():
        if args.only not in name:
            continue
        if case.available and not case.available():
            print(f"{name:28} {'(skipped: ' + case.why_unavailable + ')'}")
            continue
        r = measure(case, case.repeat or args.repeat)
        results[name] = r
        print(f"{name:28} {r['min_s']:10.4f} {r['median_s']:10.4f} {r['rate']:14,.0f}  {r['unit']}", flush=True)
    if args.json_file:
        Path(args.json_file).write_text(json.dumps({"cases": results}, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
