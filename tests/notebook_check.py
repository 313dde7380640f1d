"""Executing an example notebook as `scripts/run_notebooks.py` does, and checking that its outputs mean
what the committed ones say: the same kinds of output in every cell (a figure where there was a
figure) and the same numbers, paths aside."""

from __future__ import annotations

import importlib.util
import re

import pytest
from conftest import REPO

NUMBER = re.compile(r"[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?")
PATH = re.compile(r"\S*/\S*")  # run folders live in a fresh temporary folder each time
RELATIVE = 1e-6


def execute(name: str, tmp_path):
    """The committed notebook `examples/NAME` and a copy of it executed now."""
    nbformat = pytest.importorskip("nbformat")
    pytest.importorskip("nbclient")
    pytest.importorskip("ipykernel")
    spec = importlib.util.spec_from_file_location("run_notebooks", REPO / "scripts" / "run_notebooks.py")
    runner = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(runner)
    committed = nbformat.read(REPO / "examples" / name, as_version=4)
    return committed, runner.execute_notebook(REPO / "examples" / name, tmp_path / name)


def _kinds(cell) -> list[tuple]:
    return [(o.output_type, o.get("name") or tuple(sorted(o.get("data", {})))) for o in cell.outputs]


def _numbers(cell) -> list[float]:
    texts = [o.get("text", "") for o in cell.outputs] + [o.get("data", {}).get("text/plain", "") for o in cell.outputs]
    return [float(n) for text in texts for n in NUMBER.findall(PATH.sub("", text))]


def assert_same_meaning(committed, executed) -> None:
    cells = [(a, b) for a, b in zip(committed.cells, executed.cells) if a.cell_type == "code"]
    assert len(cells) == sum(c.cell_type == "code" for c in executed.cells)
    for k, (was, now) in enumerate(cells):
        assert _kinds(now) == _kinds(was), f"code cell {k}: {_kinds(now)} instead of {_kinds(was)}"
        assert _numbers(now) == pytest.approx(_numbers(was), rel=RELATIVE), f"code cell {k}"
    assert any("image/png" in o.get("data", {}) for _, now in cells for o in now.outputs)  # figures inline
