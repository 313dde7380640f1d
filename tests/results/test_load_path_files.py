"""A live load's path on disk (results/load_path.py): what one engine writes reads back as the same
answer, and a study resumes only from the files of the very same case and settlement."""

from __future__ import annotations

import json
import math

import numpy as np
import pandas as pd
import pytest

from yadearch.case.config import ArchCase
from yadearch.errors import RunFolderError
from yadearch.results.load_path import (
    load_path_file,
    read_load_path,
    read_load_path_folder,
    stored_load_path,
    write_load_path,
    write_load_path_folder,
)
from yadearch.results.rundir import LOAD_PATH_FILE, is_load_path_folder
from yadearch.results.states import read_states, state_entry, write_states
from yadearch.solve.load_path_result import LoadPath

CASE = ArchCase(name="point_0.3").with_overrides({"live_load": "vertical", "n_voussoirs": 15})


def _path(engine: str) -> LoadPath:
    curve = pd.DataFrame(
        {"multiplier": [0.0, 1.5], "load_displacement_mm": [0.0, 0.1], "min_stiffness_N_per_m": [9.0, 1.0]}
    )
    return LoadPath(
        capacity=7.96,
        first_loss=6.5,
        outcome="collapse",
        unit="N",
        hinges=("3I", "6E", "12I", "16E"),
        kind=None,
        curve=curve,
        after_mm=0.0,
        reach=7.95,
        iterations=103_320,
        rigid=math.nan,
        rigid_hinges=(),
        rigid_note="the arch does not stand",
        engine=engine,
    )


def test_a_load_path_reads_back_as_written(tmp_path):
    for engine in ("dem", "static"):
        written = _path(engine)
        write_load_path(tmp_path, written, CASE)
        read = read_load_path(tmp_path, CASE.name)
        assert read.curve.equals(written.curve)
        assert math.isnan(read.rigid)
        assert {k: v for k, v in vars(read).items() if k not in ("curve", "rigid")} == {
            k: v for k, v in vars(written).items() if k not in ("curve", "rigid")
        }


def test_the_static_engines_branches_read_back_as_words(tmp_path):
    """A curve with the static engine's `branch` column (past the peak: descending) and why its
    descending branch ended read back as written, the other columns numbers."""
    written = _path("static")
    curve = pd.concat([written.curve, pd.DataFrame({"multiplier": [0.75], "load_displacement_mm": [0.4],
                                                    "min_stiffness_N_per_m": [-2.0]})], ignore_index=True)  # fmt: skip
    curve["branch"] = ["ascending", "ascending", "descending"]
    written = LoadPath(**{**vars(written), "curve": curve, "descent_end": "fallen", "descent_hinges": ("3I", "7E")})
    write_load_path(tmp_path, written, CASE)
    read = read_load_path(tmp_path, CASE.name)
    assert read.curve.equals(written.curve) and (read.descent_end, read.descent_hinges) == ("fallen", ("3I", "7E"))


def test_names_with_dots_keep_their_own_files(tmp_path):
    other = CASE.with_overrides({"name": "point_0.4"})
    write_load_path(tmp_path, _path("dem"), CASE)
    write_load_path(tmp_path, _path("static"), other)
    assert (
        read_load_path(tmp_path, CASE.name).engine == "dem" and read_load_path(tmp_path, other.name).engine == "static"
    )
    assert len(list(tmp_path.glob("*_load_path.json"))) == 2


def test_a_study_resumes_only_from_the_same_case_and_settlement(tmp_path):
    write_load_path(tmp_path, _path("dem"), CASE)
    assert stored_load_path(tmp_path, CASE, 0.0) is not None
    assert stored_load_path(tmp_path, CASE, 5.0) is None
    assert stored_load_path(tmp_path, CASE.with_overrides({"interface.kn_N_per_mm3": 0.25}), 0.0) is None
    load_path_file(tmp_path, CASE.name, ".csv").unlink()
    assert stored_load_path(tmp_path, CASE, 0.0) is None  # half a result is no result


def test_a_study_resumes_from_a_path_stored_before_a_parameter_was_added(tmp_path):
    """A stored case without a parameter added since is the case with that parameter at its old value."""
    write_load_path(tmp_path, _path("dem"), CASE)
    file = load_path_file(tmp_path, CASE.name, ".json")
    data = json.loads(file.read_text())
    del data["case"]["loads"]["fill_passive_coefficient"]  # a path written before the fill's passive push
    file.write_text(json.dumps(data))
    assert stored_load_path(tmp_path, CASE, 0.0) is not None
    assert stored_load_path(tmp_path, CASE.with_overrides({"fill_passive_coefficient": 1.0}), 0.0) is None


def _states(load: tuple[float, str] | None) -> list[dict]:
    pose = np.zeros((3, 2)), np.zeros(3)
    return [state_entry("selfweight", 2, 1.2, *pose, load), state_entry("equilibrium", 5, 1.2, *pose, load)]


def test_states_keep_a_load_paths_loads_and_a_frame_says_which(tmp_path):
    """states.npz of a load path reads back with each state's load and its unit, labelled by the load;
    a support's run's has none, labelled by its displacement."""
    write_states(tmp_path / "states.npz", _states((0.1234567, "g")))
    loaded = read_states(tmp_path)
    write_states(tmp_path / "states.npz", _states(None))
    moved = read_states(tmp_path)
    assert loaded is not None and moved is not None
    assert loaded.load_unit == "g" and loaded.load is not None and loaded.load.tolist() == [0.1234567, 0.1234567]
    assert loaded.place(0) == "load 0.1235 g" and moved.load is None and moved.place(1) == "δ = 1.20 mm"


def test_a_load_path_folder_is_one_while_its_answer_is_there(tmp_path):
    """The folder reads as a run named by its answer (no du) while load_path.json, written last, is
    there; without it, it is no load path's folder; a damaged answer is one line."""
    written = _path("static")
    rows = [{"stage": "selfweight", "step": 2}, {"stage": "equilibrium", "step": 5}]
    folder = write_load_path_folder(tmp_path, written, CASE, rows, rows, {}, _states((1.0, "N")))
    assert folder == load_path_file(tmp_path, CASE.name) and is_load_path_folder(folder)
    run = read_load_path_folder(folder)
    assert run.summary.name == CASE.name and run.summary.collapsed and run.summary.du_mm is None
    assert [h.label for h in run.summary.hinges_at_collapse] == list(written.hinges)
    assert run.load_path is not None and run.load_path["collapse_multiplier"] == written.capacity
    from yadearch.api.results import RunResult

    assert RunResult(run).capacity == (written.capacity, written.unit)  # the API's answer of a load path
    (folder / LOAD_PATH_FILE).write_text("{")
    with pytest.raises(RunFolderError, match="cannot be read as a load path's answer") as error:
        read_load_path_folder(folder)
    assert "\n" not in str(error.value)
    (folder / LOAD_PATH_FILE).unlink()
    assert not is_load_path_folder(folder)
