"""The static engine's answers stay those of the engine before issue 45's speed work (commit 8ecff91):
du, du_first, the outcome, the hinges, the collapse kind and the iterations and joint evaluations
(the same path), to the bit, on set 2, kn 1 and kn 100, three imperfect samples and three points of
the sensitivity study's Saltelli sample. The path's length is compared on the stack the reference was
made with (Debian's numpy 1.24): on another (the pip route's numpy 2 and its LAPACK) round-off may
take an iteration more or less on an imperfect arch, while the answers stay the same. `PYTHONPATH=.:tests python
tests/static/test_identical_answers.py` (on a checkout of 8ecff91) rewrites the reference."""

from __future__ import annotations

import json
import sys
import tempfile
from pathlib import Path

import numpy as np
import pytest
from conftest import DATA

from yadearch.case.config import ArchCase, preset
from yadearch.results.summary import RunSummary
from yadearch.static.simulate import simulate_static
from yadearch.studies.sensitivity.indices import PAPER_FACTORS, sobol_rows

REFERENCE = DATA / "static_answers.json"
SAMPLE_BUMP_SD_MM = 0.18  # the imperfection study's final case
SALTELLI_RUNS = (0, 5, 13)  # a base point's first run, a mixed one, and the next base point's last
REFERENCE_NUMPY = "1.24."  # the numpy the reference was made with (Debian 12's)
PATH_LENGTH = ("iterations", "joint_evaluations")  # to the bit only on the reference's stack


def cases() -> dict[str, ArchCase]:
    """The cases compared, by name."""
    static = preset("set2").with_overrides({"numerics.engine": "static", "numerics.run_files": "summary"})
    found = {"set2": static, "kn1": static.replace(kn_N_per_mm3=1.0), "kn100": static.replace(kn_N_per_mm3=100.0)}
    for seed in (0, 1, 2):
        found[f"imperfect{seed}"] = static.with_overrides(
            {"imperfections.face_bump_sd_mm": SAMPLE_BUMP_SD_MM, "imperfections.seed": seed}
        )
    rows = sobol_rows(PAPER_FACTORS, 8)
    for index in SALTELLI_RUNS:
        found[rows[index]["run"]] = static.with_overrides({k: v for k, v in rows[index].items() if k != "run"})
    return found


def answers(summary: RunSummary) -> dict:
    """What must not change: the physical answers and the path's length."""
    return {
        "du_mm": summary.du_mm,
        "du_first_mm": summary.du_first_mm,
        "outcome": summary.path_outcome,
        "hinges": summary.hinge_labels,
        "collapse_kind": summary.collapse_kind,
        "iterations": summary.iterations,
        "joint_evaluations": summary.joint_evaluations,
    }


@pytest.mark.parametrize("name", sorted(json.loads(REFERENCE.read_text())))
def test_the_static_engine_gives_the_reference_answers_to_the_bit(name):
    summary = simulate_static(cases()[name], None, log=lambda _: None)
    found, expected = answers(summary), json.loads(REFERENCE.read_text())[name]
    if not np.__version__.startswith(REFERENCE_NUMPY):
        found, expected = ({k: v for k, v in d.items() if k not in PATH_LENGTH} for d in (found, expected))
    assert found == expected


if __name__ == "__main__":  # with a run folder each, as every revision of simulate_static writes one
    with tempfile.TemporaryDirectory() as folder:
        found = {
            name: answers(simulate_static(case, Path(folder) / name, log=lambda _: None))
            for name, case in cases().items()
        }
    REFERENCE.write_text(json.dumps(found, indent=1) + "\n")
    sys.exit(0)
