"""Arches other than the paper's settling arch under a passive fill, in the static engine with each
numerical setting halved and doubled (the atlas's variants and reading): whether du and du_first are facts of the
arch where the fill's springs reach their caps, kinks of the path a coarse march could read as folds
(reports/loads/passive, arches_numerics.csv; docs/loads.md)."""

from __future__ import annotations

import itertools
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.studies.atlas.invariance import invariance_table, variants
from yadearch.studies.campaigns.executors import open_pool
from yadearch.studies.campaigns.grid import RUN_COLUMN
from yadearch.studies.campaigns.runner import run_campaign
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


def arches_numerics_table(runs: Path, jobs: int = 2) -> pd.DataFrame:
    """Every arch of ARCHES at each of ARCHES_KN with every numerical variant (the default first), a lean
    static campaign in `runs` (resumed: a rerun reads back what it finished), `jobs` at a time: a row a
    run, its outcome, du, du_first and hinges or why it failed."""
    base = passive_case("paper", SWEPT_KP, live_load="none").with_overrides({"numerics.engine": "static"})
    planned, rows = [], []
    for (k, arch), kn in itertools.product(enumerate(ARCHES), ARCHES_KN):
        for variant, overrides in variants(base).items():  # the numerics are every arch's
            rows.append({RUN_COLUMN: f"arch{k}-kn{kn:g}-{variant}", **ARCHES[arch], "kn_N_per_mm3": kn, **overrides})
            planned.append({"arch": arch, "kn_N_per_mm3": kn, "variant": variant})
    with open_pool(jobs) as pool:
        results = run_campaign(base, rows, runs, pool, timeout_s=RUN_TIMEOUT_S, progress=False, folders=False)
    found = results.set_index(RUN_COLUMN)
    return pd.DataFrame([{**plan, **_answer(found.loc[row[RUN_COLUMN]])} for plan, row in zip(planned, rows)])


def _answer(result: pd.Series) -> dict[str, Any]:
    """A campaign's row as the table's columns: the answers, or the failure's reason."""
    if result["status"] != "done":
        return {"outcome": "failed", "failure": result["reason"]}
    return {
        "outcome": result["outcome"],
        "du_mm": result["du_mm"],
        "du_first_mm": result["du_first_mm"],
        "hinges": result["hinges"],
        "failure": "",
    }


def arches_verdicts(table: pd.DataFrame) -> pd.DataFrame:
    """One row an arch and stiffness, read as the atlas reads its own (`studies.atlas.invariance`): the
    default's answers, the largest relative move of each over the settings halved and doubled and the
    setting making it, the variants whose outcome differs, and the answers with the increments refined."""
    cases = table["arch"] + " (kn " + table["kn_N_per_mm3"].map("{:g}".format) + ")"
    return invariance_table(table.assign(**{RUN_COLUMN: cases + "-" + table["variant"]}))
