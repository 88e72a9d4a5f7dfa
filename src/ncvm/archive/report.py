"""The report of a batch: one JSON document, and the same as CSV (a row a program) and JUnit XML.

A program fails when it stopped with an error or violated a limit (travel, work area); a skipped file
(not a program, a sub-program) is listed with the reason and fails nothing.
"""

from __future__ import annotations

import csv
import io
import json
import re
import xml.etree.ElementTree as ET
from collections import Counter
from pathlib import Path

from ..diagnostics import UsageError
from .discover import Skipped

FORMATS = (".json", ".csv", ".xml")
FAILED = ("error", "limit_violation")
#: the columns of the CSV report: flat, one row per program (skipped files too, with the reason)
CSV_COLUMNS = ("path", "dialect", "machine", "status", "error_code", "error_message", "error_file", "error_line",
               "error_column", "cycle_time_s", "steps", "rapid_moves", "feed_moves", "arc_moves", "rapid_length",
               "feed_length", "limit_violations", "output_lines", "permanent_writes", "state", "worker")


def document(records: list[dict], skipped: list[Skipped], how: dict) -> dict:
    """The whole report: the programs in the order found, the skipped files, the summary."""
    status = Counter(r["status"] for r in records)
    machines = Counter(r["machine"] for r in records)
    summary = {
        "programs": len(records),
        "ok": status["ok"],
        "failed": sum(status[s] for s in FAILED),
        "errors": status["error"],
        "limit_violations": status["limit_violation"],
        "skipped": len(skipped),
        "with_permanent_writes": sum(1 for r in records if _writes(r)),
        "cycle_time_s": round(sum(r["cycle_time_s"] or 0.0 for r in records), 6),
        "steps": sum(r["steps"] or 0 for r in records),
        "machines": dict(sorted(machines.items())),
        **how,
    }
    return {"programs": records, "skipped": [{"path": str(s.path), "reason": s.reason} for s in skipped],
            "summary": summary}


def failed(doc: dict) -> bool:
    return doc["summary"]["failed"] > 0


def write(doc: dict, path: str | Path) -> None:
    """Write the report as its file name's extension says (.json, .csv or .xml)."""
    path = Path(path)
    render = {".json": to_json, ".csv": to_csv, ".xml": to_junit}.get(path.suffix.lower())
    if render is None:
        raise UsageError(f"--report {path}: give a .json, .csv or .xml file")
    try:
        path.write_text(render(doc), encoding="utf-8")
    except OSError as e:
        raise UsageError(f"--report {path}: cannot write: {e.strerror}") from None


def to_json(doc: dict) -> str:
    return json.dumps(doc, indent=2) + "\n"


def to_csv(doc: dict) -> str:
    out = io.StringIO()
    writer = csv.DictWriter(out, CSV_COLUMNS, lineterminator="\n")
    writer.writeheader()
    for r in doc["programs"]:
        e, m = r["error"] or {}, r["motion"] or {}
        writer.writerow({
            "path": r["path"], "dialect": r["dialect"], "machine": r["machine"], "status": r["status"],
            "error_code": e.get("code"), "error_message": e.get("message"), "error_file": e.get("file"),
            "error_line": e.get("line"), "error_column": e.get("column"), "cycle_time_s": r["cycle_time_s"],
            "steps": r["steps"], **{k: m.get(k) for k in ("rapid_moves", "feed_moves", "arc_moves", "rapid_length",
                                                         "feed_length")},
            "limit_violations": " | ".join(r["limit_violations"]), "output_lines": len(r["output_lines"]),
            "permanent_writes": _writes(r), "state": r.get("state"), "worker": r.get("worker")})
    for s in doc["skipped"]:
        writer.writerow({"path": s["path"], "status": "skipped", "error_message": s["reason"]})
    return out.getvalue()


def to_junit(doc: dict) -> str:
    """JUnit XML as CI systems read it: a test case per program, failing on an error or a limit violation."""
    s = doc["summary"]
    suite = ET.Element("testsuite", name="ncvm", tests=str(s["programs"] + s["skipped"]),
                       failures=str(s["failed"]), errors="0", skipped=str(s["skipped"]),
                       time=f"{s.get('wall_time_s', 0.0):.3f}")
    for r in doc["programs"]:
        case = ET.SubElement(suite, "testcase", classname=r["dialect"], name=r["path"],
                             time=f"{r.get('wall_time_s', 0.0):.3f}")
        if r["error"]:
            e = r["error"]
            failure = ET.SubElement(case, "failure", type=e["code"] or "error", message=e["message"])
            failure.text = f"{location(e, '')}error {e['code']}: {e['message']}"
        elif r["limit_violations"]:
            failure = ET.SubElement(case, "failure", type="limit_violation", message=r["limit_violations"][0])
            failure.text = "\n".join(r["limit_violations"])
        ET.SubElement(case, "system-out").text = _case_out(r)
    for skipped in doc["skipped"]:
        case = ET.SubElement(suite, "testcase", classname="skipped", name=skipped["path"], time="0")
        ET.SubElement(case, "skipped", message=skipped["reason"])
    _xml_safe(suite)
    ET.indent(suite)
    return ET.tostring(suite, encoding="unicode", xml_declaration=True) + "\n"


#: the characters XML 1.0 forbids (C0 controls but tab, line feed and carriage return; the surrogates; FFFE,
#: FFFF): a program's output or a damaged line may hold them, the report writes them as ``\\xHH``
_NOT_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")


def _xml_safe(element: ET.Element) -> None:
    """Write every forbidden character of ``element``'s texts and attributes as ``\\xHH`` (well-formed XML)."""
    escape = lambda text: _NOT_XML.sub(lambda m: f"\\x{ord(m.group()):02x}", text) if text else text  # noqa: E731
    for e in element.iter():
        e.text, e.tail = escape(e.text), escape(e.tail)
        for key, value in e.attrib.items():
            e.attrib[key] = escape(value)


def location(error: dict, otherwise: str) -> str:
    """``file:line:col: `` of an error, ``file:line: `` when the control names a line only, else ``otherwise``."""
    if not (error["file"] and error["line"]):
        return otherwise
    column = f"{error['column']}:" if error["column"] is not None else ""
    return f"{error['file']}:{error['line']}:{column} "


def _case_out(r: dict) -> str:
    if "diagnostics" in r:  # a check: what it found, not a run's figures
        return "\n".join([f"machine: {r['machine']}"] + [_diagnostic_line(d) for d in r["diagnostics"]])
    lines = [f"machine: {r['machine']}", f"cycle time: {r['cycle_time_s']:.3f} s, {r['steps']} steps"]
    writes = _writes(r)
    if writes:
        lines.append(f"permanent writes: {writes}")
    return "\n".join(lines + r["output_lines"][:20])


def _writes(r: dict) -> int:
    w = r.get("permanent_writes") or {}
    return len(w.get("store", ())) + len(w.get("files", ()))


def summary_lines(doc: dict) -> list[str]:
    """The end of a batch on stderr: one line per failed program, the machine files, the totals."""
    lines = []
    for r in doc["programs"]:
        if r["status"] == "error":
            e = r["error"]
            lines.append(f"{location(e, r['path'] + ': ')}error {e['code']}: {e['message']}")
        elif r["status"] == "limit_violation":
            lines.append(f"{r['path']}: warning: {r['limit_violations'][0]}")
    for s in doc["skipped"]:
        lines.append(f"{s['path']}: skipped: {s['reason']}")
    s = doc["summary"]
    lines += machine_lines(s["machines"])
    if s["with_permanent_writes"]:
        lines.append(f"ncvm: {s['with_permanent_writes']} program(s) wrote permanent data ({s['state']}); "
                     f"the report lists each write")
    failed_part = f", {s['errors']} with errors, {s['limit_violations']} with limit violations" if s["failed"] else ""
    lines.append(f"ncvm: {s['programs']} program(s) run{failed_part}, {s['ok']} ok, {s['skipped']} skipped, "
                 f"{s['wall_time_s']:.1f} s")
    return lines


def machine_lines(machines: dict[str, int]) -> list[str]:
    """How many programs used each machine file."""
    return [f"ncvm: {n} program(s) on " + ("the built-in machine" if m == "built-in" else f"machine file {m}")
            for m, n in sorted(machines.items())]


def check_record(path: str, dialect: str, machine: str, diagnostics: list[dict],
                 not_shown: str | None = None, errors_not_shown: int = 0) -> dict:
    """The report record of a program ``ncvm check`` checked: status ``error`` with its first error, or
    ``ok``; the fields of a run (cycle time, steps, motion) are null, every diagnostic kept under
    ``diagnostics``. ``not_shown``: what the check says of the diagnostics it left out; when only they hold
    errors (``errors_not_shown``), the record's error is that line."""
    error = next(({k: d[k] for k in ("code", "message", "file", "line", "column")}
                  for d in diagnostics if d["severity"] == "error"), None)
    if error is None and errors_not_shown:
        error = {"code": "", "message": not_shown, "file": path, "line": None, "column": None}
    return {"path": path, "dialect": dialect, "machine": machine, "status": "error" if error else "ok",
            "error": error, "cycle_time_s": None, "steps": None, "motion": None, "limit_violations": [],
            "output_lines": [], "diagnostics": diagnostics}


def _diagnostic_line(d: dict) -> str:
    where = f"{d['file']}:{d['line']}:{d['column']}: " if d["file"] and d["line"] else ""
    return f"{where}{d['severity']} {d['code']}: {d['message']}"
