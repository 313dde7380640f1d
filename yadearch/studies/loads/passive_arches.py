"""Arches other than the paper's settling arch under a passive fill, in the static engine with each
numerical setting halved and doubled (the atlas's variants and reading): whether du and du_first are facts of the
arch where the fill's springs reach their caps, kinks of the path a coarse march could read as folds
(reports/loads/passive, arches_numerics.csv; docs/loads.md)."""

from __future__ import annotations

import itertools
from concurrent.futures import ThreadPoolExecutor
from typing import Any

import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.results.summary import RunSummary
from yadearch.static.pool import solve_batch
from yadearch.studies.atlas.invariance import invariance_table, variants
from yadearch.studies.campaigns.grid import RUN_COLUMN
from yadearch.studies.loads.passive import SWEPT_KP, passive_case

SEMICIRCLE = {"embrace_deg": 180.0, "internal_radius_mm": 277.5, "thickness_mm": 45.0}
ARCHES: dict[str, dict[str, Any]] = {  # each arch and movement: its overrides of the paper's settling arch
    "semicircle spreading": {**SEMICIRCLE, "support_direction_deg": 0.0},
    "semicircle at -45 deg": {**SEMICIRCLE, "support_direction_deg": -45.0},
    "paper, left support settling": {"moving_support": "left"},
    "paper at -45 deg": {"support_direction_deg": -45.0},
}
ARCHES_KN = (5.2, 10_000.0)  # the paper's set 2 and nearly rigid joints
RUN_TIMEOUT_S = 600.0


def arch_case(arch: str, kn: float) -> ArchCase:
    """`arch` (one of ARCHES) under the paper's fill at Kp SWEPT_KP, settling or moving, static, at `kn`."""
    overrides = {**ARCHES[arch], "interface.kn_N_per_mm3": kn, "numerics.engine": "static"}
    return passive_case("paper", SWEPT_KP, live_load="none").with_overrides(overrides)


def arches_numerics_table(jobs: int = 2) -> pd.DataFrame:
    """Every arch of ARCHES at each of ARCHES_KN with every numerical variant (the default first), solved in
    `jobs` static workers (no run folder): a row a run, its outcome, du, du_first and hinges or its failure."""
    runs = []
    for arch, kn in itertools.product(ARCHES, ARCHES_KN):
        case = arch_case(arch, kn)
        for variant, overrides in variants(case).items():
            numerics = {f"numerics.{key}": value for key, value in overrides.items()}
            runs.append(({"arch": arch, "kn_N_per_mm3": kn, "variant": variant}, case.with_overrides(numerics)))
    shares = [runs[k::jobs] for k in range(jobs)]  # run k is share k % jobs's (k // jobs)th
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        answers = list(pool.map(lambda share: solve_batch([c.to_dict() for _, c in share], RUN_TIMEOUT_S), shares))
    return pd.DataFrame([{**found, **_answer(answers[k % jobs][k // jobs])} for k, (found, _) in enumerate(runs)])


def _answer(answer: dict[str, Any]) -> dict[str, Any]:
    """A worker's answer as the table's columns."""
    if "summary" not in answer:
        return {"outcome": "failed", "failure": answer.get("error") or answer.get("interrupted")}
    summary = RunSummary.from_json(answer["summary"])
    return {
        "outcome": summary.path_outcome,
        "du_mm": summary.du_mm,
        "du_first_mm": summary.du_first_mm,
        "hinges": summary.hinge_labels,
        "failure": "",
    }


def arches_verdicts(table: pd.DataFrame) -> pd.DataFrame:
    """One row an arch and stiffness, read as the atlas reads its own (`studies.atlas.invariance`): the
    default's answers, the largest relative move of each over the settings halved and doubled and the
    setting making it, the variants whose outcome differs, and the answers with the increments refined."""
    cases = table["arch"] + " (kn " + table["kn_N_per_mm3"].map("{:g}".format) + ")"
    return invariance_table(table.assign(**{RUN_COLUMN: cases + "-" + table["variant"]}))
