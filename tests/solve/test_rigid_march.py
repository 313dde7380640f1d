"""The rigid march survives snaps and gives one answer on any machine (issue 41, item 3): hinges that
re-seat at a fixed support into a new equilibrium are followed, ties between candidate hinges are
broken by a stated tolerance, runaway is bounded by the ring's thickness, and the result reports
du_first_mm (the first limit point) beside du_mm (the end of the quasi-static path)."""

from __future__ import annotations

import json

import pytest

import yadearch as ya
from yadearch.case.config import ArchCase
from yadearch.cli.commands import main
from yadearch.solve.limit import limit_analysis
from yadearch.solve.reseat import TIE_FRACTION

TOLERANCE_MM = 1e-3  # limit_analysis's default bisection width


def coarse(direction_deg: float, **overrides) -> ArchCase:
    """The paper arch in 15 voussoirs moving its right support toward `direction_deg`."""
    return ya.preset("set2").replace(n_voussoirs=15, support_direction_deg=direction_deg, **overrides)


def semicircle(n_voussoirs: int) -> ArchCase:
    """A semicircle of centre-line radius 300 mm at t/R = 0.2 whose right support spreads."""
    return ya.preset("set2").replace(
        embrace_deg=180.0,
        internal_radius_mm=270.0,
        thickness_mm=60.0,
        n_voussoirs=n_voussoirs,
        support_direction_deg=0.0,
    )


def test_a_spreading_semicircle_of_100_voussoirs_survives_its_symmetric_snap():
    """Spreading a semicircle moves both haunch hinges to their next joints at the same support
    displacement (a tie the mirror symmetry makes exact): the march re-seats one, then the other, and
    goes on, so 100 voussoirs collapse with 55 (it stopped at that snap, 71.96 mm, 10 % early)."""
    coarse_ring, fine_ring = (limit_analysis(semicircle(n)) for n in (55, 100))
    assert fine_ring.du_mm == pytest.approx(coarse_ring.du_mm, rel=0.02)
    assert fine_ring.du_first_mm < fine_ring.du_mm
    (snap,) = fine_ring.snaps
    assert snap.at_mm == pytest.approx(fine_ring.du_first_mm)
    assert snap.largest_move_mm < semicircle(100).geometry.thickness_mm
    before, after = (set(h.split()) for h in (snap.hinges_before, snap.hinges_after))
    assert len(before - after) == 2 and len(after - before) == 2  # both haunches moved
    assert coarse_ring.du_first_mm == coarse_ring.du_mm and not coarse_ring.snaps


@pytest.mark.parametrize("direction_deg", [-150.0, -30.0])
def test_perturbed_inputs_give_the_same_du_and_hinges(direction_deg):
    """Under an inclined movement the keystone's two joints tie to first order, and the kinematic LP
    took either by round-off (141.70 or 87.26 mm at -150 deg on two machines): the energy a step on
    decides, and inputs perturbed by 1e-12 (far below TIE_FRACTION's 1e-9) give the same answer, as
    does the mirror image (the keystone's tie the other way round)."""
    assert TIE_FRACTION >= 1e3 * 1e-12
    base = limit_analysis(coarse(direction_deg))
    g = coarse(direction_deg).geometry
    for perturbed in (
        coarse(direction_deg * (1 + 1e-12)),
        coarse(direction_deg * (1 - 1e-12)),
        coarse(direction_deg, thickness_mm=g.thickness_mm * (1 + 1e-12)),
        coarse(direction_deg, internal_radius_mm=g.internal_radius_mm * (1 + 2e-12)),
        coarse(direction_deg, internal_radius_mm=g.internal_radius_mm * (1 - 1e-12)),
    ):
        other = limit_analysis(perturbed)
        assert other.du_mm == pytest.approx(base.du_mm, abs=TOLERANCE_MM)
        assert other.du_first_mm == pytest.approx(base.du_first_mm, abs=TOLERANCE_MM)
        assert other.collapse_hinges == base.collapse_hinges
        assert [h.label for h in other.hinge_history] == [h.label for h in base.hinge_history]
    assert base.mirror_du_rigid_mm == pytest.approx(base.du_mm, abs=TOLERANCE_MM)


def test_runaway_is_a_multiple_of_the_thickness_that_does_not_move_du():
    """A re-seating is survived however far it moves within the runaway bound, which is geometry (a
    multiple of the ring's thickness); halving or doubling it leaves du within 1 %."""
    case = coarse(0.0)
    du = {k: limit_analysis(case, runaway_thicknesses=k, mirror=False) for k in (0.5, 1.0, 2.0)}
    assert du[1.0].snaps and max(s.largest_move_mm for s in du[1.0].snaps) > 1.0  # beyond a DEM's 1 mm
    for k in (0.5, 2.0):
        assert du[k].du_mm == pytest.approx(du[1.0].du_mm, rel=0.01)
    with pytest.raises(ValueError, match="runaway"):
        limit_analysis(case, runaway_thicknesses=0.0)


def test_the_march_takes_the_engines_runaway_bound_and_says_when_du_rests_on_it(tmp_path, capsys):
    """du has one definition in the three solvers: the march's runaway bound is the case's
    numerics.runaway_thickness_ratio (0.5 ring thickness), as the static engine's and the DEM's (it was
    1.0 of its own). The shallow arch (embrace 75 deg) re-seats at 108.44 mm moving a block 15.11 mm:
    past half of its 24 mm ring, so the default bound ends the path there; at one thickness it lands
    and collapses at 112.88 mm, and `limit` warns that du rests on the bound."""
    shallow = ya.preset("set2").replace(embrace_deg=75.0)
    assert limit_analysis(shallow, mirror=False).du_mm == pytest.approx(108.44, abs=0.01)
    wide = limit_analysis(shallow.replace(runaway_thickness_ratio=1.0), mirror=False)
    assert wide.du_mm == pytest.approx(112.88, abs=0.01) and wide.snaps[0].largest_move_mm == pytest.approx(
        15.11, abs=0.01
    )
    args = ["limit", "--preset", "set2", "--set", "embrace_deg=75", "--set", "numerics.runaway_thickness_ratio=1"]
    assert main([*args, "--no-figures", "--out", str(tmp_path)]) == 0
    assert "du rests on numerics.runaway_thickness_ratio" in capsys.readouterr().out


def test_du_first_is_the_first_snap_and_every_snap_is_in_the_history():
    """Each snap survived is a limit point of the path: the first (past the snap floor) is du_first_mm, each moves the
    hinges it names, and the hinges that start there carry its largest block move."""
    result = limit_analysis(coarse(0.0), mirror=False)
    assert result.snaps[0].largest_move_mm > result.snap_floor_mm  # past the floor: a loss of stability
    assert result.du_first_mm == pytest.approx(result.snaps[0].at_mm)
    assert result.du_first_mm <= result.du_mm == result.du_rigid_mm
    for snap in result.snaps:
        started = {h.label for h in result.hinge_history if h.jump_mm == pytest.approx(snap.largest_move_mm)}
        assert started and started <= set(snap.hinges_after.split()) - set(snap.hinges_before.split())


def test_a_re_seating_under_the_snap_floor_is_no_loss_of_stability_as_in_the_other_engines():
    """du_first has one definition in the three solvers: the first snap that moves a block further than
    numerics.snap_thickness_ratio ring thicknesses (the static engine's and the DEM's floor), or the
    collapse. The paper's arch re-seats 33E -> 32E at 8.38 mm moving a block 0.11 mm, under its 0.24 mm
    floor: du_first = du, as the static engine's set 2 (87.99 = 87.99 mm); a tenth of the floor counts it."""
    result = limit_analysis(ya.preset("set2"), mirror=False)
    (snap,) = result.snaps
    assert snap.largest_move_mm < result.snap_floor_mm == pytest.approx(0.01 * 24.0)
    assert result.du_first_mm == result.du_mm
    finer = limit_analysis(ya.preset("set2").replace(snap_thickness_ratio=0.001), mirror=False)
    assert finer.du_first_mm == pytest.approx(snap.at_mm) and finer.du_mm == result.du_mm


def test_json_and_cli_report_du_first_and_the_snaps(tmp_path, capsys):
    out = tmp_path / "limit"
    args = ["limit", "--preset", "set2", "--set", "n_voussoirs=15", "--set", "support_direction_deg=0"]
    assert main([*args, "--set", "name=spread", "--out", str(out)]) == 0
    data = json.loads((out / "spread.json").read_text())
    assert data["du_first_mm"] < data["du_mm"] == data["du_rigid_mm"]
    assert data["snaps"] and {"at_mm", "largest_move_mm", "hinges_before", "hinges_after"} <= set(data["snaps"][0])
    assert "du_first" in capsys.readouterr().out


def test_a_tie_far_from_the_lps_hinges_is_followed_where_the_weights_sit_lower(tmp_path):
    """A semicircle (t/R 0.15) whose right support moves down and in at -135 deg: the thrust line
    touches the ring at joints far apart, and the LP's 1E 14I 56E ties to first order with 14I 43I 56E,
    a hinge 42 joints away, whose weights sit lower a step on. The march follows the lower one (it
    searched one or two joints from the LP's hinges and gave 35.05 mm) and collapses where nearly rigid
    joints do: the static engine at kn 100 000 on the same linkage, within 1 % (measured 25.21 / 25.10)."""
    case = ya.preset("set2").replace(
        embrace_deg=180.0, support_motion="translation", support_direction_deg=-135.0, thickness_mm=45.0
    )
    rigid = limit_analysis(case, mirror=False)
    assert {h.label for h in rigid.hinge_history if h.from_mm == 0.0} == {"14I", "43I", "56E"}
    stiff = case.with_overrides({"numerics.engine": "static", "interface.kn_N_per_mm3": 1e5})
    static = ya.run(stiff, out=tmp_path / "static", figures=False).summary
    assert static.collapsed and rigid.du_mm == pytest.approx(static.du_mm, rel=0.01)
