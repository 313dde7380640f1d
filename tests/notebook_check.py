"""Executing an example notebook as `scripts/run_notebooks.py` does, and checking that its outputs mean
what the committed ones say: the same kinds of output in every cell (a figure where there was a
figure) and the same numbers, paths aside, each to the tolerance the physics sets rather than to the
last digit a machine gives (issue 42): a displacement to du's bracket, a force to the equilibrium
tolerance, a rotation to the hinge threshold; counts, hinge numbers and inputs exactly."""

from __future__ import annotations

import importlib.util
import re

import pytest
from conftest import REPO

from yadearch.case.sections import NumericsConfig

NUMBER = re.compile(r"[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?")
PATH = re.compile(r"\S*/\S*")  # run folders live in a fresh temporary folder each time
UNIT = re.compile(r"(?:\s*-\s*[\d.]+)?\s*(mrad|mm|N)(?![/\w])")  # "12.6 N", "3.2 mm", "63.8-102.4 mm"
NUMERICS = NumericsConfig()
DU_BRACKET_MM = NUMERICS.du_tolerance_mm  # du and the path's displacements are located to this bracket
EQUILIBRIUM = NUMERICS.equilibrium_tolerance  # a force balances to this share of the contact forces ...
# ... on each block: a reaction sums the unbalance of the quickstart arch's blocks (9 voussoirs and a
# support; measured on an AMD EPYC: 12.444 N against the committed 12.485, 0.33 %)
BLOCKS_SUMMED = 10
HINGE_MRAD = NUMERICS.hinge_rotation_mrad  # rotations are told apart at the hinge threshold, ...
# ... or this share of a large one: a collapse state is read where a falling block passed the runaway
# bound, and its rotations move with the round-off of the fall (the quickstart's set-1 run on an AMD
# EPYC: 218, 573, 286 mrad against the committed 210, 562, 282, the same du and hinges)
FALLING_ROTATION = 0.05
EXACT = 1e-9  # counts, hinge numbers, inputs and bisection points: identical on every machine
MM, MRAD, FORCE, PLAIN = "mm", "mrad", "N", ""
COLUMN_KINDS = (("_mm", MM), ("_mrad", MRAD), ("_N", FORCE))  # a table column's kind from its unit


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


def _column_kind(name: str) -> str:
    return next((kind for suffix, kind in COLUMN_KINDS if name.endswith(suffix)), PLAIN)


def _table(text: str) -> list[tuple[float, str]] | None:
    """The numbers of a printed DataFrame with their column's kind (the row labels left out: a
    series' row number counts steps); None if `text` is not one."""
    lines = text.splitlines()
    names = list(re.finditer(r"\S+", lines[0])) if lines else []
    if len(lines) < 2 or not names or not all(re.match(r"[A-Za-z_]", n.group()) for n in names):
        return None
    found = []
    for line in lines[1:]:
        for match in NUMBER.finditer(line):
            if match.end() > names[0].start():  # right of the row label
                column = next((n for n in names if n.end() >= match.end()), names[-1])
                found.append((float(match.group()), _column_kind(column.group())))
    return found


def _text(text: str) -> list[tuple[float, str]]:
    """The numbers of printed text, each with the unit written after it."""
    text = PATH.sub("", text)
    found = []
    for match in NUMBER.finditer(text):
        unit = UNIT.match(text, match.end())
        found.append((float(match.group()), unit.group(1) if unit else PLAIN))
    return found


def _numbers(cell) -> list[tuple[float, str]]:
    found = []
    for output in cell.outputs:
        for text in (output.get("text", ""), output.get("data", {}).get("text/plain", "")):
            table = _table(text)
            found += table if table is not None else _text(text)
    return found


def _close(was: float, now: float, kind: str, largest_force: float) -> bool:
    rotation = max(HINGE_MRAD, FALLING_ROTATION * abs(was))
    tolerance = {MM: DU_BRACKET_MM, MRAD: rotation, FORCE: BLOCKS_SUMMED * EQUILIBRIUM * largest_force}.get(kind)
    return abs(now - was) <= tolerance if tolerance is not None else now == pytest.approx(was, rel=EXACT)


def assert_same_meaning(committed, executed) -> None:
    cells = [(a, b) for a, b in zip(committed.cells, executed.cells) if a.cell_type == "code"]
    assert len(cells) == sum(c.cell_type == "code" for c in executed.cells)
    for k, (was, now) in enumerate(cells):
        assert _kinds(now) == _kinds(was), f"code cell {k}: {_kinds(now)} instead of {_kinds(was)}"
        before, after = _numbers(was), _numbers(now)
        assert [kind for _, kind in after] == [kind for _, kind in before], (
            f"code cell {k}: other numbers ({len(after)} instead of {len(before)}): "
            f"{after[:40]} instead of {before[:40]}"
        )
        largest_force = max((abs(v) for v, kind in before if kind == FORCE), default=0.0)
        far = [(b, a, kind) for (b, kind), (a, _) in zip(before, after) if not _close(b, a, kind, largest_force)]
        assert not far, f"code cell {k}: (committed, now, unit) beyond the physics' tolerance: {far[:5]}"
    assert any("image/png" in o.get("data", {}) for _, now in cells for o in now.outputs)  # figures inline
