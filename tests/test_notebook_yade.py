"""The quickstart notebook runs from top to bottom (real YADE runs of a coarse arch, about a minute),
so that it cannot rot, and its outputs mean what the committed ones say."""

from __future__ import annotations

import pytest
from conftest import needs_yade
from notebook_check import assert_same_meaning, execute

pytestmark = [needs_yade, pytest.mark.yade]


def test_the_quickstart_notebook_runs_and_says_what_it_committed(tmp_path):
    committed, executed = execute("quickstart.ipynb", tmp_path)
    assert_same_meaning(committed, executed)
    printed = "".join(o.get("text", "") for cell in executed.cells if cell.cell_type == "code" for o in cell.outputs)
    assert "RunResult(" in printed and "kn = " in printed
