"""A static worker solves with its caller's copy of yadearch (yadearch/children.py), never with one in
the working folder: `python -m` puts that folder first on a child's path, and a campaign started in one
checkout beside another installed copy solved its runs with the other's code (a case field the other
lacked failed every run)."""

from __future__ import annotations

import os

from yadearch.case.config import preset
from yadearch.children import PACKAGE_ROOT, child_environment
from yadearch.static.pool import solve_batch, stop_workers

TIMEOUT_S = 300.0


def test_a_worker_imports_its_callers_yadearch_not_the_working_folders(tmp_path, monkeypatch):
    """With a broken `yadearch` package in the working folder, a worker still solves set 2 with 15
    voussoirs (98.77 mm, docs/movements.md)."""
    broken = tmp_path / "yadearch"
    broken.mkdir()
    (broken / "__init__.py").write_text("raise ImportError('the working folder is not the caller')\n")
    monkeypatch.chdir(tmp_path)
    stop_workers()  # a worker started before would not show it
    try:
        case = preset("set2").with_overrides({"n_voussoirs": 15, "engine": "static"})
        [answer] = solve_batch([case.to_dict()], TIMEOUT_S)
    finally:
        stop_workers()
    assert round(answer["summary"]["du_mm"], 2) == 98.77


def test_a_childs_path_starts_with_this_package(monkeypatch):
    monkeypatch.setenv("PYTHONPATH", "/somewhere/else")
    env = child_environment(threads=2)
    assert env["PYTHONPATH"].split(os.pathsep) == [PACKAGE_ROOT, "/somewhere/else"]
    assert env["OMP_NUM_THREADS"] == "2"
