"""ncvm benchmarks (not tests): each case several times, min and median, and the rate.

    python bench/run.py [--repeat N] [--only SUBSTR] [--large] [--json [FILE]]

Cases come from the modules ``bench/cases_*.py``; each defines ``cases()``
returning ``{name: Case}``. Peer cases (``rs274_<case>``) run LinuxCNC's
``rs274`` on the same work when it is installed. Whole-process cases (``proc_*``, bench/cases_process.py)
run the ``ncvm`` command in a child process and report its CPU time (min and median columns), peak
memory and the ratio to rs274 on a second line. ``--large`` adds the cases of 10,000,000 moves (``proc_*_10m_*``:
a few minutes, a 340 MB DIN file written once under bench/.work).
"""

from __future__ import annotations

import argparse
import contextlib
import importlib.util
import json
import statistics
import sys
import time
from pathlib import Path

HERE = Path(__file__).parent
sys.path.insert(0, str(HERE))

import benchlib  # noqa: E402
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
    extra = case.figures() if case.figures else {}
    times, cpus, figures = [], [], []
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        got = case.run()
        times.append(time.perf_counter() - t0)
        cpus.append(time.process_time() - c0)
        if got:
            figures.append(got)
    if figures:  # a whole-process case: the ncvm child's CPU time, and figures of its own
        summary = summarise(figures)
        cpu = sorted(f["ncvm_cpu_s"] for f in figures)
        return {"median_s": summary["ncvm_cpu_s"], "min_s": cpu[0], "rate": case.count / summary["ncvm_cpu_s"],
                "unit": case.unit, "clock": "cpu", **summary, **extra}
    med, lo, cpu = statistics.median(times), min(times), statistics.median(cpus)
    # CPU time of this process too: on a shared machine the wall clock also counts the other users' work
    out = {"median_s": med, "min_s": lo, "rate": case.count / med, "unit": case.unit}
    if case.in_process and cpu:
        out.update(cpu_median_s=cpu, cpu_rate=case.count / cpu)
    return {**out, **extra}


def summarise(figures: list[dict]) -> dict:
    """Medians of each figure over the runs; with a peer, the ratio of the median CPU times."""
    out = {k: statistics.median(f[k] for f in figures) for k in figures[0]}
    if "rs274_cpu_s" in out:
        out["speedup_vs_rs274"] = out["rs274_cpu_s"] / out["ncvm_cpu_s"]  # > 1: ncvm is faster
    return out


def details(r: dict) -> str:
    """The second line of a whole-process case: CPU, memory and the peer's figures."""
    parts = [f"ncvm cpu {r['ncvm_cpu_s']:.3f} s, peak {r['ncvm_peak_rss_mb']:.0f} MB"]
    if "rs274_cpu_s" in r:
        parts.append(f"rs274 cpu {r['rs274_cpu_s']:.3f} s, peak {r['rs274_peak_rss_mb']:.0f} MB")
        ratio = r["speedup_vs_rs274"]
        parts.append(f"ncvm {ratio:.2f}x faster" if ratio >= 1 else f"ncvm {1 / ratio:.2f}x rs274's time")
    return "  " + " | ".join(parts)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--only", default="")
    ap.add_argument("--large", action="store_true", help="also the cases of 10,000,000 moves (minutes)")
    ap.add_argument("--json", dest="json_file", nargs="?", const="-",
                    help="write the figures as JSON to FILE (without FILE: to stdout, the table to stderr)")
    args = ap.parse_args()
    benchlib.LARGE["on"] = args.large
    if args.json_file == "-":  # stdout is the JSON document alone: the table goes to stderr
        with contextlib.redirect_stdout(sys.stderr):
            results = table(args)
        print(json.dumps({"cases": results}, indent=2))
        return 0
    results = table(args)
    if args.json_file:
        Path(args.json_file).write_text(json.dumps({"cases": results}, indent=2))
    return 0


def table(args) -> dict:
    """Measure the chosen cases, printing a row (and a line of figures) each; returns the figures."""
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
        if r.get("clock") == "cpu":
            print(details(r), flush=True)
        elif r.get("cpu_rate"):
            print(f"  cpu {r['cpu_median_s']:.4f} s median, {r['cpu_rate']:,.0f} {r['unit']} by CPU time", flush=True)
    return results


if __name__ == "__main__":
    sys.exit(main())
