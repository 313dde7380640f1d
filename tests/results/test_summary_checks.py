"""summary.json is validated by type and range when a run folder is read (issue 42): a damaged value
is one line naming the key and the value, from `open_run`, `report` and every reader of the folder."""

from __future__ import annotations

import json
import math
import shutil

import pytest
from conftest import REPO

import yadearch as ya
from yadearch.errors import RunFolderError
from yadearch.results.rundir import SUMMARY_FILE, is_complete, summary_problem
from yadearch.results.summary_checks import OUTCOMES, summary_values_problem
from yadearch.solve import stages

RUN = REPO / "reports" / "set2"
GOOD = json.loads((RUN / SUMMARY_FILE).read_text())


def test_every_committed_summary_passes_the_checks():
    summaries = sorted(REPO.glob("reports/**/summary.json"))
    assert len(summaries) > 100
    for path in summaries:
        assert summary_values_problem(json.loads(path.read_text())) is None, path


def test_the_outcomes_are_the_engines_own():
    outcome = getattr(stages, "Outcome", None)  # the static engine's outcomes, where this version has them
    if outcome is not None:
        assert set(OUTCOMES) == {o.value for o in outcome}


@pytest.mark.parametrize(
    "change, words",
    [
        ({"du_mm": "48.9"}, "du_mm must be a finite number >= 0 mm or null, got '48.9'"),
        ({"du_mm": math.nan}, "du_mm must be a finite number >= 0 mm or null, got nan"),
        ({"du_mm": math.inf}, "du_mm must be a finite number"),
        ({"du_mm": -0.5}, "du_mm must be a finite number"),
        ({"du_mm": True}, "du_mm must be a finite number"),
        ({"du_first_mm": "x"}, "du_first_mm must be a finite number"),
        ({"du_bracket_mm": [90.0, 80.0]}, "du_bracket_mm must be [low, high]"),
        ({"du_bracket_mm": [1.0]}, "du_bracket_mm must be [low, high]"),
        ({"du_components_mm": [1.0, math.nan]}, "du_components_mm must be [dx, dy]"),
        ({"outcome": "exploded"}, "outcome must be one of collapse, stands, unresolved, cannot stand, got 'exploded'"),
        ({"outcome": "stands"}, "du_mm must be a number exactly when outcome is 'collapse'"),
        ({"outcome": "collapse", "du_mm": None}, "du_mm must be a number exactly when outcome is 'collapse'"),
        ({"engine": "fem"}, "engine must be one of dem, static"),
        ({"collapsed": "yes"}, "collapsed must be true or false"),
        ({"collapse_verdict": 3}, "collapse_verdict must be text or null"),
        ({"hinges_at_collapse": [{"interface": 0, "side": "I"}]}, "hinges_at_collapse must hold"),
        ({"hinges_at_collapse": [{"interface": 3, "side": "X"}]}, "hinges_at_collapse must hold"),
        ({"hinges_at_collapse": "1E 9I"}, "hinges_at_collapse must be a list"),
        ({"steps": -1}, "steps must be an integer >= 0"),
        ({"steps": 1.5}, "steps must be an integer >= 0"),
        ({"wall_s": math.nan}, "wall_s must be a finite number"),
        ({"table_rows": {"series.csv": "many"}}, "table_rows must map"),
    ],
)
def test_a_damaged_value_is_one_line_naming_the_key_and_the_value(change, words, tmp_path):
    assert words in summary_values_problem({**GOOD, **change})
    folder = tmp_path / "run"
    folder.mkdir()
    shutil.copy(RUN / "case.toml", folder / "case.toml")
    (folder / SUMMARY_FILE).write_text(json.dumps({**GOOD, **change}))  # NaN and Infinity as Python writes them
    assert words in summary_problem(folder) and not is_complete(folder)  # a campaign runs it again
    with pytest.raises(RunFolderError, match="is not a complete run folder: summary.json: ") as error:
        ya.open_run(folder)
    assert words in str(error.value) and "\n" not in str(error.value)


def test_a_run_that_stands_or_is_unresolved_has_no_du_and_a_newer_key_is_left_alone():
    assert summary_values_problem({**GOOD, "outcome": "collapse"}) is None
    for outcome in ("stands", "unresolved", "cannot stand"):
        assert summary_values_problem({**GOOD, "outcome": outcome, "du_mm": None, "du_first_mm": 40.0}) is None
    assert summary_values_problem({**GOOD, "a_key_from_a_newer_version": [1, "x"]}) is None


def test_states_cut_short_are_one_line_from_open_run(tmp_path):
    folder = tmp_path / "run"
    shutil.copytree(RUN, folder, ignore=shutil.ignore_patterns("figures"))
    data = (folder / "states.npz").read_bytes()
    for cut in (len(data) // 2, len(data) - 10, 30):
        (folder / "states.npz").write_bytes(data[:cut])
        with pytest.raises(
            RunFolderError, match=r"states.npz cannot be read .*cut short or changed; run the case again"
        ):
            _ = ya.open_run(folder).states
