"""The campaigns notebook (static engine, no YADE) runs from top to bottom and its outputs mean what
the committed ones say: the same tables, numbers and figures."""

from __future__ import annotations

import copy as copy_module
import re

import pytest
from conftest import REPO
from notebook_check import assert_same_meaning, execute

nbformat = pytest.importorskip("nbformat")


def test_the_campaigns_notebook_runs_and_says_what_it_committed(tmp_path):
    committed, executed = execute("campaigns.ipynb", tmp_path)
    assert_same_meaning(committed, executed)


def _perturbed(notebook, cell: int, old: str, new: str):
    """A copy of `notebook` whose code cell `cell` prints `new` where it printed `old`."""
    copy = nbformat.from_dict(copy_module.deepcopy(notebook))
    code = [c for c in copy.cells if c.cell_type == "code"][cell]
    for output in code.outputs:
        for holder, key in ((output, "text"), (output.get("data", {}), "text/plain")):
            if old in holder.get(key, ""):
                holder[key] = holder[key].replace(old, new, 1)
                return copy
    raise AssertionError(f"{old!r} is not in code cell {cell}")


ROW = r"^\d+\s+[\d.]+\s+"  # a row of the loading curve's tail: its index, delta_mm, then the columns
REACTION = (2, ROW + r"([\d.]+)\s")  # left_Ry_N of the tail's first row
CROWN = (2, ROW + r"[\d.]+\s+[\d.]+\s+(-[\d.]+)")  # crown_dy_mm of that row
ROTATION = (1, r"(\d+) mrad")  # the hinges' rotations


def _printed(notebook, where: tuple[int, str], last: bool = False) -> str:
    """The first (or `last`) number the quickstart's code cell `where[0]` prints that `where[1]`
    captures, as printed."""
    code = [c for c in notebook.cells if c.cell_type == "code"][where[0]]
    text = "".join(o.get("text", "") + o.get("data", {}).get("text/plain", "") for o in code.outputs)
    found = re.findall(where[1], text, flags=re.MULTILINE)
    return found[-1] if last else found[0]


@pytest.mark.parametrize(
    "where, last, change, same",
    [  # the quickstart's committed outputs (a DEM run), changed as another CPU may or may not change them
        (REACTION, False, 0.001246, True),  # a reaction in its 4th digit: within the equilibrium tolerance
        (REACTION, False, 0.3, False),  # by 0.3 N: beyond it (10 blocks x 1e-3 of the largest force, 0.19 N)
        (CROWN, False, -0.01, True),  # the crown's displacement within du's bracket (0.1 mm)
        (CROWN, False, -0.2, False),
        (ROTATION, True, 2, True),  # the smallest hinge's rotation within the hinge threshold (2 mrad)
        (ROTATION, True, 5, False),
        (ROTATION, False, 0.037, True),  # the largest one (a falling block's) within 5 % (notebook_check)
        (ROTATION, False, 0.06, False),
    ],
)
def test_numbers_are_compared_to_the_tolerance_the_physics_sets(where, last, change, same):
    committed = nbformat.read(REPO / "examples" / "quickstart.ipynb", as_version=4)
    old = _printed(committed, where, last)
    if where is ROTATION:  # whole mrad: the small one moved by mrad, the large one by a fraction of itself
        new = f" {int(old) + (change if last else round(change * int(old)))} mrad"
        old = f" {old} mrad"  # a whole number: " 83 mrad", not the end of " 283 mrad"
    else:
        new = f"{float(old) + change:.{len(old.split('.')[1])}f}"
    changed = _perturbed(committed, where[0], old, new)
    if same:
        assert_same_meaning(committed, changed)
    else:
        with pytest.raises(AssertionError, match=f"code cell {where[0]}"):
            assert_same_meaning(committed, changed)


@pytest.mark.parametrize(
    "cell, old, new",
    [  # what may never change, whatever the CPU
        (1, "2I A", "3I A"),  # hinges are identical everywhere
        (5, "51 states", "52 states"),  # and so are counts
        (7, "DEM 115.18 mm", "DEM 115.38 mm"),  # du beyond its bracket
    ],
)
def test_hinges_counts_and_du_are_compared_exactly(cell, old, new):
    committed = nbformat.read(REPO / "examples" / "quickstart.ipynb", as_version=4)
    with pytest.raises(AssertionError, match=f"code cell {cell}"):
        assert_same_meaning(committed, _perturbed(committed, cell, old, new))
