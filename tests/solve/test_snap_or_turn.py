"""A path that turns sharply is not a snap (docs/atlas.md, "Two of the floor's snaps"): where the
descent from past a located fold lands off the branch's prediction by more than the snap floor, it is
tried again from 16 times nearer the fold; a landing that shrinks with that distance is the path
turning onto a branch that continues it, and du_first does not stop there. A snap lands as far."""

from __future__ import annotations

import pytest

from yadearch.case.config import ArchCase
from yadearch.results.summary import collapse_fields
from yadearch.solve.static_path import StaticLoading
from yadearch.studies.atlas.grid import Geometry, engine_base

HALVED_FLOOR = 0.005  # the snap floor halved (ring thicknesses): these paths' sharp turns land past it
SAME = 0.01  # du_first within 1 % of its value at the default floor


def atlas_case(shape: str, movement: str, thickness_over_radius: float, kn: float, floor: float | None) -> ArchCase:
    """One arch of the atlas on the static engine, with the snap floor `floor` (None: the default)."""
    overrides = {**Geometry(shape, movement, thickness_over_radius).overrides(), "kn_N_per_mm3": kn}
    if floor is not None:
        overrides["numerics.snap_thickness_ratio"] = floor
    return engine_base("static", {}).with_overrides(overrides)


def answers(case: ArchCase) -> dict:
    loading = StaticLoading.of(case)
    loading.selfweight()
    path = loading.follow()
    return collapse_fields(path, loading.arch.movement, loading.first_loss)


@pytest.mark.parametrize(
    ("shape", "movement", "ratio", "kn", "turn_mm"),
    [
        ("segmental", "closing", 0.08, 100.0, 3.29),  # the smallest eigenvalue crosses zero at 3.288 mm
        ("semicircular", "closing", 0.15, 5.2, 4.77),
    ],
)
def test_a_sharp_turn_is_not_a_first_loss_of_stability(shape, movement, ratio, kn, turn_mm):
    default = answers(atlas_case(shape, movement, ratio, kn, None))
    halved = answers(atlas_case(shape, movement, ratio, kn, HALVED_FLOOR))
    assert default["outcome"] == halved["outcome"] == "collapse"
    assert halved["du_first_mm"] > turn_mm + 1.0  # the path goes on past its turn without a snap
    assert halved["du_first_mm"] == pytest.approx(default["du_first_mm"], rel=SAME)


def test_a_snap_is_still_a_snap():
    """The spreading paper arch at kn 5.2 t/R 0.25 snaps at 47.1 mm by 1.7 mm (docs/atlas.md): counted."""
    found = answers(atlas_case("segmental", "spreading", 0.25, 5.2, None))
    assert found["du_first_mm"] == pytest.approx(47.1, abs=0.3)
    assert found["du_first_mm"] < found["du_mm"]
