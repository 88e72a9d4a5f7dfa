"""docs/profiles.md is the profile tables as they are (issue 14 §1: "one table per profile -- function,
group, meaning, manual line, status"): regenerate it with `make docs` when a table changes."""

from __future__ import annotations

from ncvm.nc.profiles import REFUSED
from ncvm.nc.profiles.doc import DOC, PROFILES, markdown


def test_profiles_doc_is_current():
    assert DOC.read_text(encoding="utf-8") == markdown(), "docs/profiles.md is stale: run `make docs`"


def test_every_row_of_every_profile_is_in_the_doc_with_its_status():
    text = DOC.read_text(encoding="utf-8")
    for p in PROFILES:
        section = text.split(f"## `{p.name}`", 1)[1].split("\n## ", 1)[0]
        for r in p.rows:
            assert f"| G{r.g:g} | " in section, (p.name, r.g)
        assert sum(1 for r in p.rows if r.status == REFUSED) == section.count(f"| {REFUSED} (")


def test_a_refused_row_names_its_code_and_stops_the_kernel():
    """Every row that refuses carries the code its run stops with; every row that runs carries none."""
    for p in PROFILES:
        for r in p.rows:
            assert (r.status == REFUSED) <= bool(r.code), (p.name, r.g)
            assert r.handler is not None or r.run != 0, (p.name, r.g)
