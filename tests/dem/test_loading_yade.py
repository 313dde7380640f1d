"""The equilibrium-path loading of the paper's set 1 arch in real YADE (about 20 s a run): every
accepted state is a static equilibrium, and du does not move with the size of the loading
increments (reports/robustness: kn 0.25, base and increment_x0.5)."""

from __future__ import annotations

import pandas as pd
import pytest
from conftest import HAS_YADE, needs_yade

from yadearch.case.config import preset
from yadearch.model.hinges import same_hinges
from yadearch.results.rundir import STIFFNESS_COLUMN
from yadearch.results.summary import RunSummary

pytestmark = [needs_yade, pytest.mark.yade]

QUIET = {"progress_every_s": 1e9}
DU_TOLERANCE = 0.01  # du may move by 1 % at most when only the numerics change


def run(overrides: dict) -> tuple[RunSummary, pd.DataFrame]:
    from yadearch.dem.runner import Runner

    runner = Runner(preset("set1").with_overrides({**QUIET, **overrides}), log=lambda line: None)
    summary = runner.run()
    return summary, pd.DataFrame(runner.records.series)


@pytest.fixture(scope="module")
def base_run():
    if not HAS_YADE:
        pytest.skip("no YADE")
    return run({})


def test_every_accepted_state_of_the_loading_is_a_static_equilibrium(base_run):
    summary, series = base_run
    assert summary.collapsed and summary.collapse_verdict == "runaway"  # a mechanism ran away
    weight = summary.selfweight["arch_weight_N"]
    path = series[series["stage"] == "equilibrium"]
    assert len(path) == summary.equilibria >= 5
    assert (path["delta_mm"].diff().dropna() > 0).all()  # monotonic along the support path
    assert (path["delta_mm"] < summary.du_mm).all()
    tolerance = preset("set1").numerics.equilibrium_tolerance
    assert (path["unbalanced"] < tolerance).all()
    carried = (path["left_Ry_N"] + path["right_Ry_N"]) / weight
    assert carried.sub(1.0).abs().max() < 0.01  # the supports carry the weight: nothing accelerates
    assert (path["left_Rx_N"] + path["right_Rx_N"]).abs().max() < 0.01 * path["left_Rx_N"].abs().min()


def test_the_loading_follows_its_path_instead_of_jumping_between_states(base_run):
    """Quasi-static: short of the fold, the blocks relax into place after each accepted move by much
    less than the move; toward du the equilibrium moves faster with the support (a jump to another
    branch is flagged, docs/numerics.md)."""
    from yadearch.analysis.mechanism import JUMP_FRACTION, NEAR_LIMIT, relaxation_jump

    summary, _ = base_run
    table = pd.DataFrame({k: summary.relaxations[k] for k in ("delta_mm", "increment_mm", "move_mm")})
    assert len(table) >= summary.equilibria and (table["increment_mm"] > 0).all()
    far = table[table["delta_mm"] <= NEAR_LIMIT * summary.du_mm]
    assert (far["move_mm"] < JUMP_FRACTION * far["increment_mm"]).all(), table.to_dict("list")
    assert table["move_mm"].max() > far["move_mm"].max()
    assert relaxation_jump(summary) is None


def test_every_accepted_state_is_stable_and_the_last_one_near_the_limit_point(base_run):
    """The tangent stiffness of the free blocks is positive definite at every equilibrium of the
    loading, and its smallest eigenvalue falls toward zero as du (a fold of the path) approaches."""
    _, series = base_run
    path = series[series["stage"] == "equilibrium"]
    stiffness = path[STIFFNESS_COLUMN]
    assert (stiffness > 0).all(), stiffness.tolist()
    assert stiffness.iloc[-1] < 0.25 * stiffness.max(), stiffness.tolist()


def test_du_does_not_move_with_the_loading_increment(base_run):
    summary, _ = base_run
    num = preset("set1").numerics
    halved, _ = run(
        {"first_increment_mm": 0.5 * num.first_increment_mm, "max_increment_mm": 0.5 * num.max_increment_mm}
    )
    assert halved.du_mm == pytest.approx(summary.du_mm, rel=DU_TOLERANCE)
    assert same_hinges(halved.hinges_detail, summary.hinges_detail)
