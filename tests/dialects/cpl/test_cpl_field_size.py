"""DIM: a numeric field holds at most 65536 elements, both dimensions together (manual §2.4.3 L702)."""

from __future__ import annotations

import pytest

from ncvm.api import check


@pytest.mark.parametrize(("dims", "ok"), [("65536", True), ("256,256", True), ("257,256", False),
                                          ("65536,2", False), ("65536,65536", False)])
def test_numeric_field_size_is_the_product_of_its_dimensions(tmp_path, dims, ok):
    path = tmp_path / "p.cpl"
    path.write_text(f"10 DIM A%({dims})\nM30\n")
    errors = [d for d in check(path) if d.severity == "error"]
    if ok:
        assert errors == []
    else:
        assert [d.code for d in errors] == ["CPL022"]
        assert errors[0].message.startswith("INVALID FIELD LIMIT")
        assert "at most 65536 elements" in errors[0].message


def test_the_largest_field_runs(run_text):
    r = run_text("10 DIM A%(256,256)\n20 A%(256,256) = 7\n30 B% = A%(256,256)\nM30\n", name="p.cpl")
    assert r["status"] == "ok" and r["variables"]["B%"] == 7
