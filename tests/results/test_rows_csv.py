"""The run folder's tables are written without pandas (`atomic.write_rows_atomically`): the file is the
one pandas' `to_csv` writes for every kind of value a run's rows hold, and it reads back the same."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from yadearch.atomic import write_csv_atomically, write_rows_atomically
from yadearch.results.rundir import TABLE_FLOAT_FORMAT
from yadearch.solve.stages import Stage

ROWS = [
    {"stage": Stage.EQUILIBRIUM, "step": 7, "delta_mm": 1.0, "force": 11.607407123, "tiny": 3.3e-15, "flag": True},
    {
        "stage": Stage.SELFWEIGHT,
        "step": np.int64(2),
        "delta_mm": np.float64(0.0),
        "force": -0.0,
        "flag": np.bool_(False),
    },
    {"stage": "collapse", "step": 9, "delta_mm": 88.03125, "force": float("nan"), "tiny": None, "hinges": "1E 9I, 56E"},
    {"stage": 'quoted "stage"', "step": 10, "delta_mm": np.float32(1.5), "force": float("inf"), "tiny": 1e300},
]  # fmt: skip


@pytest.mark.parametrize("float_format", [TABLE_FLOAT_FORMAT, "%.6g"])
def test_the_rows_file_is_the_file_pandas_writes(tmp_path, float_format):
    ours = write_rows_atomically(tmp_path / "ours.csv", ROWS, float_format=float_format)
    theirs = write_csv_atomically(tmp_path / "theirs.csv", pd.DataFrame(ROWS))
    if float_format != "%.6g":
        pd.DataFrame(ROWS).to_csv(theirs, index=False, float_format=float_format)
    assert ours.read_bytes() == theirs.read_bytes()
    back = pd.read_csv(ours)
    assert list(back.columns) == ["stage", "step", "delta_mm", "force", "tiny", "flag", "hinges"]
    assert back["delta_mm"].tolist() == pytest.approx([1.0, 0.0, 88.03125, 1.5], rel=1e-5)
    assert back["hinges"].iloc[2] == "1E 9I, 56E"


def test_no_rows_give_an_empty_table(tmp_path):
    assert write_rows_atomically(tmp_path / "empty.csv", []).read_text() == "\n"
    assert pd.DataFrame([]).to_csv(index=False) == "\n"
