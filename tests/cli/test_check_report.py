"""``ncvm check --report FILE``: the report of ``run --report`` (.json, .csv, JUnit .xml) for a check,
a program per entry, parsed back (issue 17)."""

from __future__ import annotations

import csv
import json
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

NCVM = [sys.executable, "-c", "from ncvm.cli import main; main()"]


@pytest.fixture
def archive(tmp_path) -> Path:
    (tmp_path / "a").mkdir()
    (tmp_path / "a" / "good.cpl").write_text("10 A% = 1\nN20 G1 X10 F600\nM30\n")
    (tmp_path / "a" / "bad.cpl").write_text("10 A% = \nM30\n")
    (tmp_path / "a" / "README").write_text("not a program\n")
    return tmp_path


def check(archive, name):
    return subprocess.run([*NCVM, "check", "a", "--report", name], cwd=archive, capture_output=True, text=True,
                          timeout=120)


def test_json_report_of_a_check(archive):
    out = check(archive, "r.json")
    assert out.returncode == 1 and "ncvm: report written to r.json" in out.stderr
    doc = json.loads((archive / "r.json").read_text())
    by_path = {p["path"]: p for p in doc["programs"]}
    bad, good = by_path["a/bad.cpl"], by_path["a/good.cpl"]
    assert bad["status"] == "error" and bad["error"]["code"] == "CPL001" and bad["error"]["line"] == 1
    assert bad["diagnostics"][0]["code"] == "CPL001"
    assert good["status"] == "ok" and good["error"] is None and good["cycle_time_s"] is None  # nothing ran
    assert doc["skipped"][0]["path"] == "a/README"
    s = doc["summary"]
    assert (s["programs"], s["ok"], s["failed"], s["skipped"], s["command"]) == (2, 1, 1, 1, "check")
    assert s["cycle_time_s"] is None and s["steps"] is None


def test_csv_and_junit_reports_of_a_check(archive):
    assert check(archive, "r.csv").returncode == 1
    rows = {r["path"]: r for r in csv.DictReader((archive / "r.csv").open())}
    assert rows["a/bad.cpl"]["error_code"] == "CPL001" and rows["a/good.cpl"]["status"] == "ok"
    assert rows["a/README"]["status"] == "skipped"
    assert check(archive, "r.xml").returncode == 1
    suite = ET.parse(archive / "r.xml").getroot()
    assert (suite.get("tests"), suite.get("failures"), suite.get("skipped")) == ("3", "1", "1")
    failure = suite.find("testcase[@name='a/bad.cpl']/failure")
    assert failure.get("type") == "CPL001" and failure.text.startswith("a/bad.cpl:1:")
    assert suite.find("testcase[@name='a/good.cpl']/failure") is None


def test_a_report_of_an_unknown_kind_is_a_usage_error_before_checking(archive):
    out = check(archive, "r.txt")
    assert out.returncode == 2 and "give a .json, .csv or .xml file" in out.stderr
    assert "CPL001" not in out.stderr
