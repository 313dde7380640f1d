"""du and du_first are facts of the arch, not of the numerics (docs/numerics.md, "Collapse"): every
numerical setting of the static engine halved and doubled (the increments, the bracket, the solver's
tolerance, its largest step and its iteration budgets) moves neither by more than 1 %, on an arch
whose path snaps before it collapses (the spreading semicircle), on the paper's set 2 and on a thin
pointed arch that collapses after 0.16 mm (its bracket relative, `du_tolerance_ratio`: 0.1 mm would be
60 % of du, and halving or doubling it moves du by 20 %)."""

from __future__ import annotations

from dataclasses import replace

import pytest
from test_collapse_mechanics import SPREADING_SEMICIRCLE

from yadearch.case.config import ArchCase, preset
from yadearch.results.summary import collapse_fields
from yadearch.solve.newton import SolverSettings
from yadearch.solve.stages import Outcome
from yadearch.solve.static_path import StaticLoading
from yadearch.studies.atlas.grid import Geometry

INVARIANCE = 0.01  # the standard: a result that moves more than 1 % is not a result
PATH_SETTINGS = ("first_increment_mm", "max_increment_mm", "du_tolerance_mm", "du_tolerance_ratio")
DEFAULT_SOLVER = SolverSettings()


def scaled_path(case: ArchCase, factor: float) -> ArchCase:
    """`case` with every increment setting and the bracket width times `factor`."""
    return case.with_overrides({k: getattr(case.numerics, k) * factor for k in PATH_SETTINGS})


def scaled_solver(factor: float) -> SolverSettings:
    """The solver's tolerance, largest step and iteration budgets times `factor`."""
    return replace(
        DEFAULT_SOLVER,
        tolerance=DEFAULT_SOLVER.tolerance * factor,
        max_step=DEFAULT_SOLVER.max_step * factor,
        newton_iterations=round(DEFAULT_SOLVER.newton_iterations * factor),
        descent_iterations=round(DEFAULT_SOLVER.descent_iterations * factor),
    )


def outcome(case: ArchCase, solver: SolverSettings = DEFAULT_SOLVER) -> dict:
    """The static path of `case` with `solver`: its outcome, du and du_first (mm)."""
    loading = StaticLoading.of(case, solver)
    loading.selfweight()
    path = loading.follow()
    return collapse_fields(path, loading.arch.movement, loading.first_loss)


RELATIVE_BRACKET = 0.005  # numerics.du_tolerance_ratio: du's bracket at most 0.5 % of du


def relative_atlas_arch(shape: str, movement: str, thickness_over_radius: float, kn: float) -> ArchCase:
    """An arch and movement of the atlas at `kn`, its bracket relative (RELATIVE_BRACKET)."""
    geometry = Geometry(shape, movement, thickness_over_radius)
    return preset("set2").with_overrides(
        {**geometry.overrides(), "kn_N_per_mm3": kn, "du_tolerance_ratio": RELATIVE_BRACKET}
    )


CASES = {
    "spreading semicircle, kn 100": preset("set2").with_overrides(SPREADING_SEMICIRCLE),
    "set 2": preset("set2"),
    "thin pointed arch tilting, kn 100": relative_atlas_arch("pointed", "tilt", 0.08, 100.0),  # du 0.16 mm
}


@pytest.fixture(scope="module", params=list(CASES))
def reference(request) -> tuple[ArchCase, dict]:
    case = CASES[request.param]
    return case, outcome(case)


@pytest.mark.parametrize("factor", [0.5, 2.0])
def test_increments_and_bracket_halved_and_doubled(reference, factor: float) -> None:
    case, default = reference
    varied = outcome(scaled_path(case, factor))
    assert varied["outcome"] == default["outcome"] == Outcome.COLLAPSE
    assert varied["du_mm"] == pytest.approx(default["du_mm"], rel=INVARIANCE)
    assert varied["du_first_mm"] == pytest.approx(default["du_first_mm"], rel=INVARIANCE)


@pytest.mark.parametrize("factor", [0.5, 2.0])
def test_solver_tolerance_step_and_budgets_halved_and_doubled(reference, factor: float) -> None:
    case, default = reference
    varied = outcome(case, scaled_solver(factor))
    assert varied["outcome"] == default["outcome"] == Outcome.COLLAPSE
    assert varied["du_mm"] == pytest.approx(default["du_mm"], rel=INVARIANCE)
    assert varied["du_first_mm"] == pytest.approx(default["du_first_mm"], rel=INVARIANCE)


def test_a_snap_before_collapse_is_located_to_the_relative_bracket() -> None:
    """The static engine's fold bisection (du_first) ends at du_tolerance_ratio of the fold's position too:
    the atlas's semicircle tilting at t/R 0.15 and kn 100 first snaps near 1.9 mm and collapses near 4.2 mm;
    its first fold's bracket is 0.5 % of 1.9 mm, not the 0.1 mm of du_tolerance_mm."""
    found = outcome(relative_atlas_arch("semicircular", "tilt", 0.15, 100.0))
    low, high = found["du_first_bracket_mm"]
    assert found["outcome"] == Outcome.COLLAPSE and high < 0.6 * found["du_mm"]  # a snap survived first
    assert high - low <= RELATIVE_BRACKET * high < 0.1


@pytest.mark.parametrize("ratio", [0.25, 1.0])
def test_the_mechanism_at_collapse_does_not_move_with_the_runaway_bound(ratio: float) -> None:
    """The thick segmental arch spreading at kn 5.2 (t/R 0.25; the atlas's
    segmental-spreading-t75-kn5.2): read where the run's own bound stopped the fall, half the bound
    read three hinges and a snap-through, the default four; read where the fall has moved a block
    half the ring's thickness whatever the bound, the hinges at collapse, the mode and the kind are
    the default's (`StaticLoading.collapse_fall`)."""
    from yadearch.static.simulate import simulate_static

    case = Geometry("segmental", "spreading", 0.25).row(5.2)
    case.pop("run")
    base = preset("set2").with_overrides({**case, "numerics.engine": "static", "numerics.increments_check": "none"})
    default = simulate_static(base, None, log=lambda _: None)
    other = simulate_static(base.with_overrides({"numerics.runaway_thickness_ratio": ratio}), None, log=lambda _: None)
    assert other.du_mm == default.du_mm
    assert other.collapse_kind == default.collapse_kind == "four-hinge mechanism"
    assert other.collapse_mode_hinges == default.collapse_mode_hinges
    assert other.hinge_labels == default.hinge_labels
