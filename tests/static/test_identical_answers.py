"""The static engine's answers stay those of the engine before issue 45's speed work (commit 8ecff91):
du, du_first, the outcome, the hinges, the collapse kind and the iterations and joint evaluations
(the same path), to the bit, on set 2, kn 1 and kn 100, three imperfect samples and three points of
the sensitivity study's Saltelli sample. `python tests/static/test_identical_answers.py` rewrites the
reference, only ever from that engine."""

from __future__ import annotations

import json
import sys

import pytest
from conftest import DATA

from yadearch.case.config import ArchCase, preset
from yadearch.static.simulate import simulate_static
from yadearch.studies.sensitivity.indices import PAPER_FACTORS, sobol_rows

REFERENCE = DATA / "static_answers.json"
SAMPLE_BUMP_SD_MM = 0.18  # the imperfection study's final case
SALTELLI_RUNS = (0, 5, 13)  # a base point's first run, a mixed one, and the next base point's last


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


def answers(case: ArchCase) -> dict:
    """What must not change: the physical answers and the path's length."""
    s = simulate_static(case, None, log=lambda _: None)
    return {
        "du_mm": s.du_mm,
        "du_first_mm": s.du_first_mm,
        "outcome": s.path_outcome,
        "hinges": s.hinge_labels,
        "collapse_kind": s.collapse_kind,
        "iterations": s.iterations,
        "joint_evaluations": s.joint_evaluations,
    }


@pytest.mark.parametrize("name", sorted(json.loads(REFERENCE.read_text())))
def test_the_static_engine_gives_the_reference_answers_to_the_bit(name):
    assert answers(cases()[name]) == json.loads(REFERENCE.read_text())[name]


if __name__ == "__main__":
    REFERENCE.write_text(json.dumps({name: answers(case) for name, case in cases().items()}, indent=1) + "\n")
    sys.exit(0)
