"""A folder that is not a run is named for what it is: missing, or a campaign's (its table, no summary)."""

from __future__ import annotations

import pytest

from yadearch.errors import RunFolderError
from yadearch.results.rundir import CAMPAIGN_TABLE, read_summary


def test_a_missing_folder_and_a_campaigns_folder_are_told_apart_from_an_unfinished_run(tmp_path):
    with pytest.raises(RunFolderError, match="no such folder"):
        read_summary(tmp_path / "nope")
    (tmp_path / CAMPAIGN_TABLE).write_text("run,status\n")
    with pytest.raises(RunFolderError, match="a campaign's folder .results.csv.; give one of its runs' folders"):
        read_summary(tmp_path)
    empty = tmp_path / "empty"
    empty.mkdir()
    with pytest.raises(RunFolderError, match="no summary.json"):
        read_summary(empty)
