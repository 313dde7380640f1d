"""The DEM's self-weight on an arch at the edge of standing, the sensitivity study's sample b00006_01
(tests/data/edge_of_standing.toml): the static model's self-weight path folds at 0.82 g
(tests/solve/test_edge_of_standing.py), and a DEM run once accepted its self-weight state while it
still crept at 0.3 mm/s. The DEM now accepts only a state that passes the path's settling test
(blocks slower than settle_speed_mm_per_s) with a positive definite static tangent; this one still
moves after three holds, so it is refused, as the static engine refuses it (docs/validation-engines.md, "Arches
at the edge of standing")."""

from __future__ import annotations

import pytest
from conftest import REPO, needs_yade

from yadearch.case.config import load_case
from yadearch.errors import CANNOT_STAND, RunFailedError

pytestmark = [needs_yade, pytest.mark.yade]

CASE = REPO / "tests" / "data" / "edge_of_standing.toml"
QUIET = {"progress_every_s": 1e9, "numerics.engine": "dem"}


def test_the_dem_does_not_accept_a_creeping_self_weight_state():
    from yadearch.dem.runner import Runner

    runner = Runner(load_case(CASE).with_overrides(QUIET), log=lambda line: None)
    try:
        with pytest.raises(RunFailedError) as refused:
            runner.selfweight()
    finally:
        runner.close()
    message = str(refused.value)
    assert CANNOT_STAND in message or "unresolved: the self-weight state still creeps" in message, message
