"""Collapse decided by mechanics, not by numerical settings (docs/numerics.md, "Collapse"): a snap
that re-settles is survived whatever the runaway bound, a solver failure is never a collapse, du rises
toward the rigid value as the joints stiffen, and the collapse's hinges and kind come from its mode."""

from __future__ import annotations

from pathlib import Path

import pytest

from yadearch.case.config import ArchCase, preset
from yadearch.errors import CaseError
from yadearch.results.summary import RunSummary
from yadearch.solve.path import PathResult, PathStep
from yadearch.solve.stages import Outcome, Verdict
from yadearch.static.simulate import simulate_static

# a semicircle whose spreading support makes a hinge snap by 1.2-1.3 mm at 20.5 mm (docs/numerics.md)
SPREADING_SEMICIRCLE = {
    "embrace_deg": 180.0,
    "internal_radius_mm": 277.5,
    "thickness_mm": 45.0,
    "friction_deg": 60.0,
    "support_direction_deg": 0.0,
    "kn_N_per_mm3": 100.0,
}
SNAP_AT_MM = 20.49  # where the hinge snaps (the former static answer, with a 1 mm runaway constant)
DEM_DU_MM = 30.34  # the DEM's du of the same arch (docs/validation.md)
BRACKET_MM = 0.1  # du_tolerance_mm: the width of every bracket


def static_run(tmp_path: Path, name: str, overrides: dict) -> RunSummary:
    case = preset("set2").with_overrides({**overrides, "numerics.run_files": "summary"})
    return simulate_static(case.replace(name=name), tmp_path / name, log=lambda line: None)


@pytest.mark.parametrize("ratio", [0.25, 1.0])
def test_a_snap_that_resettles_is_survived_whatever_the_runaway_bound(tmp_path: Path, ratio: float) -> None:
    """The runaway bound halved and doubled from its default (0.5 ring thickness) moves neither du
    nor du_first: both are facts of the arch; du_first is the snap, du the DEM's answer."""
    default = static_run(tmp_path, "default", SPREADING_SEMICIRCLE)
    other = static_run(tmp_path, f"r{ratio}", {**SPREADING_SEMICIRCLE, "runaway_thickness_ratio": ratio})
    assert default.outcome == other.outcome == Outcome.COLLAPSE
    assert other.du_mm == pytest.approx(default.du_mm, rel=0.01)
    assert other.du_first_mm == pytest.approx(default.du_first_mm, rel=0.01)
    assert default.du_first_mm == pytest.approx(SNAP_AT_MM, abs=BRACKET_MM)
    assert default.du_mm == pytest.approx(DEM_DU_MM, abs=BRACKET_MM)
    assert default.snaps and default.snaps[0]["move_mm"] > 1.0  # the snap, recorded with its size


def test_the_thick_semicircle_that_timed_out_collapses_near_the_rigid_value(tmp_path: Path) -> None:
    """At kn 1000 this ring's descents used to time out at 1.98 mm and were read as collapse; retried,
    the path carries on to a collapse within 10 % of the rigid march's ~79 mm."""
    summary = static_run(
        tmp_path,
        "thick",
        {
            **SPREADING_SEMICIRCLE,
            "internal_radius_mm": 270.0,
            "thickness_mm": 60.0,
            "friction_deg": 70.0,
            "kn_N_per_mm3": 1000.0,
        },
    )
    assert summary.outcome == Outcome.COLLAPSE and summary.collapse_verdict == Verdict.RUNAWAY
    assert summary.du_mm == pytest.approx(79.0, rel=0.1)
    assert summary.du_first_mm is not None and summary.du_first_mm <= summary.du_mm


# the atlas's semicircle t/R 0.15 (reports/atlas), spreading: symmetric, so its path meets a symmetric
# bifurcation at the keystone's two joints whose antisymmetric mode is nearly neutral (-0.04 N/m)
ATLAS_SEMICIRCLE = {
    "embrace_deg": 180.0,
    "internal_radius_mm": 300.0,
    "span_mm": 600.0,
    "thickness_mm": 45.0,
    "support_direction_deg": 0.0,
}
ATLAS_SEMICIRCLE_DEM_MM = 20.02  # the DEM's du, 1E 12I 29E 45I 56E (reports/atlas/atlas.csv)


def test_a_symmetric_arch_leaves_its_bifurcation_and_collapses_where_the_dem_does(tmp_path: Path) -> None:
    """Kicked off the symmetric saddle by a hair, the descent came back to a state that still passed
    for an equilibrium and the run ended unresolved at 9.8 mm; kicked far enough for the mode's negative
    stiffness to push 10x the converged residual, it takes one side and collapses on the DEM's hinges."""
    summary = static_run(tmp_path, "semicircle", ATLAS_SEMICIRCLE)
    assert summary.outcome == Outcome.COLLAPSE
    assert summary.du_mm == pytest.approx(ATLAS_SEMICIRCLE_DEM_MM, abs=BRACKET_MM)
    assert summary.hinge_labels == "1E 12I 29E 45I 56E"


def test_a_stiff_thick_ring_collapses_at_the_rigid_value_not_unresolved(tmp_path: Path) -> None:
    """An elliptical ring at t/R 0.25 and kn 10 000 spreading: past the rigid collapse (74.86 mm) its
    descent crawls down a valley of stiff joints; carrying the shear from go to go it runs away, where
    one elastic step from the last state left it unresolved at 74.83 mm."""
    summary = static_run(
        tmp_path,
        "ellipse",
        {
            "shape": "elliptical",
            "span_mm": 600.0,
            "rise_mm": 200.0,
            "thickness_mm": 75.0,
            "support_direction_deg": 0.0,
            "kn_N_per_mm3": 10000.0,
        },
    )
    assert summary.outcome == Outcome.COLLAPSE and summary.collapse_verdict == Verdict.RUNAWAY
    assert summary.du_mm == pytest.approx(74.86, rel=0.01)


def test_a_self_weight_still_falling_goes_on_and_a_solver_failure_is_not_cannot_stand(tmp_path: Path) -> None:
    """Set 2 with face angles of s.d. 32 mrad (seed 123, reports/imperfections/amplitudes): its
    self-weight descent moved a block 18.8 mm in its budget and was read as an arch that cannot stand;
    going on while it falls, it settles and the arch collapses under the movement. A campaign row whose
    self-weight the solver leaves unresolved is `unresolved`, not `cannot stand`."""
    from yadearch.studies.campaigns.table import RunSpec, failed_row

    summary = static_run(tmp_path, "rough", {"face_angle_sd_mrad": 32.0, "seed": 123})
    assert summary.outcome == Outcome.COLLAPSE and summary.du_mm is not None and summary.du_mm > 30.0
    spec = RunSpec("rough", {}, tmp_path, preset("set2"))
    row = failed_row(spec, "run 'rough' failed: unresolved: the self-weight descent found neither", 1.0)
    assert row["outcome"] == Outcome.UNRESOLVED
    assert (
        failed_row(spec, "run 'rough' failed: the arch does not stand under its own weight", 1.0)["outcome"]
        == Outcome.CANNOT_STAND
    )


def test_stiffer_joints_carry_an_inclined_movement_further(tmp_path: Path) -> None:
    """Set 2 moving at -45 deg: du rises with kn toward the rigid march's 40.82 mm (the old answers,
    22.99 / 31.82 / 21.12 / 25.18 mm, stopped at the first snap: they are du_first now)."""
    du = [
        static_run(tmp_path, f"k{kn}", {"support_direction_deg": -45.0, "kn_N_per_mm3": kn}).du_mm
        for kn in (100, 1000, 10000)
    ]
    assert du == sorted(du)
    assert du[-1] == pytest.approx(40.82, rel=0.05)


def test_the_paper_arch_collapses_by_a_four_hinge_mechanism(tmp_path: Path) -> None:
    """Set 2: no snap on the way (du_first = du), the mechanism's hinges the paper's (Table 1)."""
    summary = static_run(tmp_path, "set2", {})
    assert summary.du_first_mm == summary.du_mm
    assert summary.collapse_kind == "four-hinge mechanism"
    assert summary.collapse_mode_hinges is not None and summary.collapse_mode_hinges[0] == "1E"
    assert summary.collapse_mode_hinges[-1] == "56E"


def test_the_shallow_arch_collapses_by_four_hinges_after_a_snap(tmp_path: Path) -> None:
    """Embrace 75 deg (the issue's two-hinge 'mechanism', 5I 51E): a four-hinge mechanism whose mode
    turns the joints the collapse names, past a snap (du_first < du) that the path survives."""
    summary = static_run(tmp_path, "shallow", {"embrace_deg": 75.0})
    assert summary.collapse_kind == "four-hinge mechanism"
    assert summary.du_first_mm is not None and summary.du_mm is not None
    assert summary.du_first_mm < summary.du_mm
    named = summary.hinge_labels.split()
    mode = summary.collapse_mode_hinges or []
    assert len(named) == len(mode) == 4
    assert all(a[-1] == b[-1] and abs(int(a[:-1]) - int(b[:-1])) <= 1 for a, b in zip(named, mode))


def test_a_timeout_at_the_bracket_is_unresolved_never_collapse() -> None:
    """A path whose last failure is a solver's timeout has no du: its outcome is unresolved."""
    path = PathResult(lower=0.01, upper=0.0101, steps=[PathStep(0.01, 0.0101, Verdict.TIMEOUT)])
    assert path.unresolved and not path.collapsed and path.outcome == Outcome.UNRESOLVED
    runaway = PathResult(lower=0.01, upper=0.0101, steps=[PathStep(0.01, 0.0101, Verdict.RUNAWAY)])
    assert runaway.collapsed and runaway.outcome == Outcome.COLLAPSE


def test_the_retired_millimetre_runaway_is_refused_with_its_replacement() -> None:
    with pytest.raises(CaseError, match="runaway_thickness_ratio"):
        ArchCase().with_overrides({"numerics.runaway_mm": 5.0})
