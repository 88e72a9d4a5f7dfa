"""The generated archive and its batch run in this process, shared by the batch and the cluster tests."""

from __future__ import annotations

import os

import pytest

from ncvm.archive import run_batch

from .generate import make_archive

#: what differs between two runs of the same program by nature: where and how long it ran
VOLATILE = ("worker", "wall_time_s")


def stable(records):
    return [{k: v for k, v in r.items() if k not in VOLATILE} for r in records]


def in_folder(folder, f, *args, **kwargs):
    """``f(...)`` run from ``folder``: the batch's paths relative to the archive, as a shop would run it."""
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        return f(*args, **kwargs)
    finally:
        os.chdir(cwd)


@pytest.fixture(scope="package")
def archive(tmp_path_factory):
    return make_archive(tmp_path_factory.mktemp("archive"))


@pytest.fixture(scope="package")
def in_process(archive):
    """The whole archive in this process."""
    return in_folder(archive.root, run_batch, ["."], jobs=1)
