"""summary.json as one type (results/summary.RunSummary): every summary the project has committed,
from both engines and every schema since the first, reads back and writes the same keys and values."""

from __future__ import annotations

import json
import subprocess

import pytest
from conftest import REPO

from yadearch.errors import RunFolderError
from yadearch.results.summary import DEM, RENAMED_KEYS, STATIC, HingeRef, RunSummary

MARKERS = ("schema_version", "complete")  # written by the run folder, not part of the summary
RETIRED = ("holds", "trigger_delta_mm")  # keys of early DEM runs that no reader uses any more


def committed_summaries() -> list[str]:
    listed = subprocess.run(
        ["git", "ls-files", "reports/**/summary.json"], cwd=REPO, capture_output=True, text=True, check=True
    ).stdout.split()
    return [path for path in listed if "command" not in json.loads((REPO / path).read_text())]


def test_every_committed_summary_reads_back_as_it_was_written():
    paths = committed_summaries()
    assert len(paths) > 100
    engines = set()
    for path in paths:
        written = json.loads((REPO / path).read_text())
        summary = RunSummary.from_json(written)
        engines.add(summary.engine)
        expected = {
            RENAMED_KEYS.get(k, k): v
            for k, v in written.items()
            if k not in MARKERS + RETIRED and not (v is None and k == "collapse_verdict")
        }
        expected.setdefault("engine", DEM)  # runs from before the static engine are DEM runs
        if isinstance(expected.get("loading"), dict):
            expected["loading"].setdefault("motion", "translation")  # ... and from before rotations
        back = summary.to_json()
        assert {k: back[k] for k in expected} == expected, path
        assert set(back) - set(expected) <= {
            "increments",
            "equilibria",
            "friction",
            "contact_model",
            "loading",
            "last_equilibrium_mm",
            "hinges_last_equilibrium",
        }, path
    assert engines == {DEM, STATIC}


def test_the_typed_fields_answer_what_readers_asked_the_dict_for():
    summary = RunSummary.from_json(
        {
            "du_mm": 87.99,
            "steps": 10,
            "wall_s": 1.0,
            "engine": STATIC,
            "iterations": 812,
            "collapsed": True,
            "hinges_at_collapse": [
                {"interface": 1, "side": "E"},
                {"interface": 9, "side": "I"},
                {"interface": 29, "side": "E"},
                {"interface": 56, "side": "E"},
            ],
            "hinges_detail": [{"interface": 29, "side": "E", "rotation_mrad": 40.0, "interfaces": [28, 29, 30]}],
        }
    )
    assert summary.hinge_labels == "1E 9I 29E 56E" and summary.cost == "static engine, 812 iterations"
    assert summary.paper_labels(56) == {
        HingeRef(1, "E"): "D",
        HingeRef(9, "I"): "A",
        HingeRef(29, "E"): "B",
        HingeRef(56, "E"): "C",
    }
    assert "steps_by_stage" not in summary.to_json()  # the DEM's fields stay out of a static run's file
    with pytest.raises(RunFolderError, match="did not collapse"):
        RunSummary(du_mm=None, hinges_at_collapse=(), steps=0, wall_s=0.0).collapsed_du_mm()


def test_the_paper_letters_follow_the_moving_support():
    """C is the extrados hinge at the support that moves, D at the fixed one: the left support
    moving mirrors the paper's letters (they were put at the paper's sides whatever moved)."""
    from yadearch.model.hinges import paper_labels

    hinges = [(1, "E", 5.0), (28, "E", 9.0), (48, "I", 12.0), (56, "E", 3.0)]
    assert paper_labels(hinges, 56) == {(1, "E"): "D", (56, "E"): "C", (48, "I"): "A", (28, "E"): "B"}
    assert paper_labels(hinges, 56, "left") == {(56, "E"): "D", (1, "E"): "C", (48, "I"): "A", (28, "E"): "B"}


def test_the_loading_records_what_its_motion_has():
    """A translation records its direction; a rotation its pivot and sense (no direction it did
    not follow); a path its rows; each reads back as it was written."""
    from yadearch.case.config import preset
    from yadearch.case.support import movement_overrides
    from yadearch.results.summary import LoadingInfo, loading_info

    def written(movement: str) -> dict:
        case = preset("set2").with_overrides(movement_overrides(movement))
        return loading_info(case.loading, 150.0).to_json()

    assert written("settlement")["direction_deg"] == -90.0
    tilt = written("abutment_tilt")
    assert "direction_deg" not in tilt and tilt["rotation_sense"] == "clockwise" and tilt["pivot_mm"][1] < 0
    path = written("settle_then_spread")
    assert "direction_deg" not in path and len(path["path_mm_mrad"]) >= 2
    for data in (tilt, path):
        assert LoadingInfo(**data).to_json() == data
