"""The campaigns notebook (static engine, no YADE) runs from top to bottom and its outputs mean what
the committed ones say: the same tables, numbers and figures."""

from __future__ import annotations

from notebook_check import assert_same_meaning, execute


def test_the_campaigns_notebook_runs_and_says_what_it_committed(tmp_path):
    committed, executed = execute("campaigns.ipynb", tmp_path)
    assert_same_meaning(committed, executed)
