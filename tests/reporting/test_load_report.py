"""`yadearch report` takes a live load's path folder as it takes a run folder (issue 44): its answer
in the overview and a section (first loss, collapse, hinges, the rigid blocks' load) with its
load-displacement figure; a folder whose answer is unreadable is refused before anything is written."""

from __future__ import annotations

import pytest

import yadearch as ya
from yadearch.errors import RunFolderError
from yadearch.results.rundir import LOAD_PATH_FILE


def test_a_load_path_folder_is_reported_with_its_answer_and_figure(tmp_path):
    case = ya.preset("set2").replace(n_voussoirs=15, live_load="vertical")
    path = ya.load_path(case, out=tmp_path / "loads", descend_to=None)
    report = ya.report([tmp_path / "loads" / "custom_load_path"], tmp_path / "report")
    text = report.read_text()
    assert "## Live loads" in text
    assert f"| {path.first_loss:.4g} N | {path.capacity:.4g} N | {' '.join(path.hinges)} |" in text
    assert (tmp_path / "report" / "custom_load_path" / "figures" / "load_path.png").is_file()
    assert "![load path](custom_load_path/figures/load_path.png)" in text


def test_an_unreadable_answer_is_refused_before_anything_is_written(tmp_path):
    folder = tmp_path / "x_load_path"
    folder.mkdir()
    (folder / LOAD_PATH_FILE).write_text("{not json")
    with pytest.raises(RunFolderError, match="cannot be read as a load path's answer"):
        ya.report([folder], tmp_path / "report")
    assert not (tmp_path / "report").exists()
