"""Hinge history, formation order, migration, sliding and mechanism on constructed joints.csv tables
(no simulation): the analysis must find exactly the hinges built in, for any threshold within x2."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from synthetic_runs import BuiltHinge, BuiltRun, paper_like_run

from yadearch.analysis.blocks import block_centroids, tangential_slip_mm
from yadearch.analysis.run import Thresholds
from yadearch.analysis.tracking import format_interfaces
from yadearch.model.geometry import polygon_centroid, segmental_arch
from yadearch.results.summary import RunSummary


def summary_of(analysis) -> list[tuple]:
    return [(t.paper_label, t.interface, t.final.interfaces, t.side) for t in analysis.tracks]


def test_finds_the_built_hinges_in_order_of_formation():
    a = paper_like_run().analyse()
    assert summary_of(a) == [
        ("A", 4, (4,), "I"),
        ("B", 7, (6, 7, 8, 9), "E"),
        ("C", 11, (11,), "E"),
        ("D", 1, (1,), "E"),
    ]
    assert [(label, seq) for label, _, seq in a.formation] == [
        ("A", "I"),
        ("B", "I-E"),
        ("C", "I-E-E"),
        ("D", "E-I-E-E"),
    ]
    formed = [delta for _, delta, _ in a.formation]
    assert formed[:3] == pytest.approx([5.0, 12.0, 20.0], abs=1.0)
    assert formed[3] == pytest.approx(30.05)  # the collapse record
    assert a.sequence == "E-I-E-E"
    assert a.mechanism == "asymmetric four-hinge mechanism, E-I-E-E, D at the left support"
    assert a.sliding == []
    assert all(t.migrations == [] for t in a.tracks)
    assert format_interfaces(a.tracks[1].final.interfaces) == "6-7-8-9"


def test_a_joint_rotated_by_compression_alone_has_not_formed_a_hinge():
    a = paper_like_run().analyse()
    c = a.tracks[2]
    assert c.per_record[0] is not None  # detected by rotation under self-weight already...
    assert a.history.delta_mm[c.formed_record] == pytest.approx(20.0, abs=1.0)  # ...formed when it opened


def test_loading_records_past_du_are_not_on_the_path():
    a = paper_like_run().analyse()
    assert list(a.history.stage[[0, 1, -1]]) == ["selfweight", "equilibrium", "collapse"]
    assert a.history.delta_mm[-2] <= 30.0
    assert np.all(np.diff(a.history.delta_mm) > 0)


def test_hinge_table_lists_every_hinge_at_every_record():
    a = paper_like_run().analyse()
    at_15 = a.hinges[np.isclose(a.hinges["delta_mm"], 15.0)]
    assert list(zip(at_15["interface"], at_15["side"], at_15["label"])) == [
        (4, "I", "A"),
        (7, "E", "B"),
        (11, "E", "C"),
    ]
    assert at_15["interfaces"].iloc[1] == "6-7-8-9"
    final = a.hinges[a.hinges["stage"] == "collapse"]
    assert list(final["label"]) == ["D", "A", "B", "C"]
    assert (final["opening_mm"] > 0.1).all()


@pytest.mark.parametrize("factor", [0.5, 2.0])
@pytest.mark.parametrize("name", ["rotation_mrad", "opening_mm", "max_jump"])
def test_result_does_not_flip_when_a_threshold_changes_by_two(name, factor):
    base = paper_like_run().analyse()
    default = getattr(Thresholds(), name)
    changed = type(default)(default * factor) if name != "max_jump" else max(1, round(default * factor))
    a = paper_like_run().analyse(dataclasses.replace(Thresholds(), **{name: changed}))
    assert summary_of(a) == summary_of(base)
    assert a.mechanism == base.mechanism
    assert [d for _, d, _ in a.formation] == pytest.approx([d for _, d, _ in base.formation], abs=1.0)


def migrating_run() -> BuiltRun:
    """An I hinge opens at 3, then closes while one at 6 opens: it migrates 3 -> 6 (near 18.5 mm,
    where 6 overtakes 3); an E hinge at the right support forms at 10."""
    return BuiltRun(
        [
            BuiltHinge({3: 1.0}, "I", opens_mm=5.0, fades_mm=(15.0, 19.0)),
            BuiltHinge({6: 1.0}, "I", opens_mm=15.0),
            BuiltHinge({11: 1.0}, "E", opens_mm=10.0),
        ]
    )


@pytest.mark.parametrize("factor", [0.5, 1.0, 2.0])
def test_a_hinge_that_moves_is_one_hinge_with_a_migration(factor):
    thresholds = Thresholds(rotation_mrad=2.0 * factor, opening_mm=0.02 * factor)
    a = migrating_run().analyse(thresholds)
    assert summary_of(a) == [("A", 6, (6,), "I"), ("C", 11, (11,), "E")]  # 11 E: at the moving support
    assert a.history.delta_mm[a.tracks[0].formed_record] == pytest.approx(5.0, abs=1.0)
    (move,) = a.tracks[0].migrations
    assert (move.from_interface, move.to_interface) == (3, 6)
    assert move.delta_mm == pytest.approx(18.5, abs=0.6)
    assert a.tracks[1].migrations == []
    assert a.mechanism.startswith("asymmetric two-hinge mechanism, I-E")


@pytest.mark.parametrize("factor", [0.5, 1.0, 2.0])
def test_a_joint_at_the_coulomb_cap_that_slipped_is_sliding(factor):
    run = dataclasses.replace(paper_like_run(), sliding={5: 0.999, 10: 0.999})
    slip = np.zeros(run.n_interfaces)
    slip[4], slip[9] = 1.5, 0.01  # 5 slipped; 10 sits at the cap but only sheared elastically
    thresholds = Thresholds(cap_tolerance=0.05 * factor, slip_mm=0.2 * factor)
    a = run.analyse(thresholds, slip_mm=slip)
    assert [s.interface for s in a.sliding] == [5]
    assert a.sliding[0].shear_ratio == pytest.approx(0.999)
    assert a.mechanism == "sliding at interface 5, with hinges E-I-E-E"


def test_without_snapshots_the_coulomb_cap_alone_marks_sliding():
    run = dataclasses.replace(paper_like_run(), sliding={5: 0.999})
    assert [s.interface for s in run.analyse().sliding] == [5]


def test_polygon_centroid_of_a_trapezoid_is_not_its_vertex_mean():
    trapezoid = np.array([[0.0, 0.0], [4.0, 0.0], [3.0, 1.0], [1.0, 1.0]])
    assert polygon_centroid(trapezoid) == pytest.approx([2.0, 4.0 / 9.0])
    assert trapezoid.mean(axis=0)[1] == pytest.approx(0.5)


def test_slip_is_the_relative_motion_along_the_joint_and_not_hinge_rotation():
    g = segmental_arch(4, 125.0, 0.3, 0.024, 0.12, 0.036)
    pos0 = block_centroids(g)
    joint = g.joints[2]  # between voussoirs 2 and 3
    along = (joint.extrados - joint.intrados) / np.linalg.norm(joint.extrados - joint.intrados)
    pos = pos0.copy()
    pos[3:] += 1e-3 * along  # everything right of joint 3 slides 1 mm outwards along it
    slip = tangential_slip_mm(g, {"pos_m": pos.tolist(), "rot_rad": [0.0] * len(pos)})
    assert slip == pytest.approx([0, 0, 1.0, 0, 0], abs=1e-9)

    theta = 0.05  # the blocks right of joint 3 turn about its intrados edge instead
    c, s = math.cos(theta), math.sin(theta)
    turned = pos0.copy()
    for b in range(3, len(pos0)):
        d = pos0[b] - joint.intrados
        turned[b] = joint.intrados + [c * d[0] - s * d[1], s * d[0] + c * d[1]]
    rot = [0.0] * 3 + [theta] * (len(pos0) - 3)
    slip = tangential_slip_mm(g, {"pos_m": turned.tolist(), "rot_rad": rot})
    assert abs(slip[2]) < 0.5 * theta**2 * 24.0


def test_a_joint_that_slid_below_its_friction_cap_is_flagged_as_sliding_during_the_moves():
    """The pointed arch at kn 300 loaded at 640 mm/s2: its apex slid 5.69 mm while no equilibrium
    used more than 0.66 of its friction; at 40 mm/s2 it slid 0.0001 mm (docs/validation.md)."""
    from yadearch.analysis.mechanism import slip_during_moves

    moves = {"max_friction_use": 0.66, "friction_interface": 29, "max_slip_mm": 5.69, "slip_interface": 29}
    warning = slip_during_moves(moves)
    assert warning is not None and "interface 29 slipped 5.69 mm" in warning and "\n" not in warning
    assert slip_during_moves({**moves, "max_slip_mm": 0.0001}) is None  # elastic shear only
    assert slip_during_moves({**moves, "max_friction_use": 1.0}) is None  # sliding at the cap is mechanics
    assert slip_during_moves({}) is None


def test_a_collapse_at_a_joints_friction_cap_is_said_to_be_limited_by_sliding():
    """A three-centred arch whose springing reached its friction cap just before du (fourth user trial:
    static 35.02, DEM 33.93 mm, rigid blocks 'sliding'): a note says so; a run far from its cap, none."""
    from yadearch.analysis.mechanism import friction_limited

    at_cap = {"max_friction_use": 0.99998, "friction_interface": 1, "friction_delta_mm": 34.98, "max_slip_mm": 0.0}
    note = friction_limited(_summary(du_mm=35.02, collapsed=True, friction=at_cap))
    assert note is not None and note.startswith("interface 1 reached 1.000 of its friction at 34.98 mm")
    assert friction_limited(_summary(du_mm=35.02, collapsed=True, friction={**at_cap, "max_friction_use": 0.6})) is None
    assert friction_limited(_summary(collapsed=False, friction=at_cap)) is None


def _summary(**fields) -> RunSummary:
    """A run summary with only `fields` set, as an older run or a partial record reads."""
    return RunSummary(**{"du_mm": None, "hinges_at_collapse": (), "steps": 0, "wall_s": 0.0, **fields})


def test_an_accepted_relaxation_that_moved_a_block_far_is_flagged_as_a_jump():
    """Spreading at kn 10000 with a 5 mm runaway distance: after 2.5 mm increments the relaxations
    moved blocks by about as much again and the hinges wandered off the rigid path; set 1's soft joints
    relax by 0.38 mm after 2.5 mm, and by 0.66 mm at 46.0 mm next to its fold at 47.13 mm, which is the
    path's own (docs/numerics.md)."""
    from yadearch.analysis.mechanism import relaxation_jump

    jumped = _summary(
        du_mm=27.91,
        relaxations={
            "runaway_mm": 5.0,
            "delta_mm": [1.0, 4.75, 17.25, 27.875],
            "increment_mm": [1.0, 2.25, 2.5, 0.625],
            "move_mm": [0.07, 1.17, 2.69, 1.5],
        },
    )
    warning = relaxation_jump(jumped)
    assert warning is not None and "to 17.25 mm moved a block 2.69 mm (2 such" in warning and "\n" not in warning
    assert "54% of the runaway bound (5 mm): the bound halved would end the path there" in warning
    soft = _summary(
        du_mm=47.13,
        relaxations={
            "runaway_mm": 1.0,
            "delta_mm": [7.25, 40.0, 46.0, 47.09],
            "increment_mm": [2.5, 2.5, 0.625, 0.156],
            "move_mm": [0.38, 0.3, 0.66, 0.06],
        },
    )
    assert relaxation_jump(soft) is None
    assert relaxation_jump(_summary()) is None  # a run from before the record


def test_an_unresolved_end_is_flagged_with_its_engines_own_numerics_and_a_runaway_is_not():
    from yadearch.analysis.mechanism import run_warnings
    from yadearch.results.summary import STATIC
    from yadearch.solve.stages import Verdict

    timed_out = run_warnings(_summary(collapse_verdict=Verdict.TIMEOUT))
    assert len(timed_out) == 1 and "numerics.hold_max_s" in timed_out[0] and "\n" not in timed_out[0]
    static = run_warnings(_summary(collapse_verdict=Verdict.TIMEOUT, engine=STATIC))
    assert len(static) == 1 and "unresolved" in static[0] and "hold_max_s" not in static[0]  # ignored there
    assert run_warnings(_summary(du_mm=27.3, collapse_verdict=Verdict.RUNAWAY)) == []
    assert run_warnings(_summary(du_mm=27.3)) == []  # a run from before the record


def test_a_du_first_that_rests_on_the_snap_floor_is_said():
    """The pointed arch at kn 10 000 (seventh user trial): a state landed 0.35 mm from its prediction at
    14.75 mm, under the 0.4 mm floor, and the floor halved moved du_first from 31.82 to 13.38 mm; set 2 at
    kn 1000: its first snap moved 0.277 mm, 1.2 floors, which the floor doubled would not count."""
    from yadearch.analysis.mechanism import snap_floor_near

    record = {"runaway_mm": 20.0, "snap_floor_mm": 0.4, "delta_mm": [5.0, 14.75, 30.0, 58.0],
              "increment_mm": [2.5] * 4, "move_mm": [0.05, 0.35, 0.1, 0.3]}  # fmt: skip
    near = _summary(du_mm=58.77, du_first_mm=31.82, relaxations=record, snaps=[])
    said = snap_floor_near(near)
    assert said is not None and "14.75 mm landed 0.350 mm from its prediction, 87% of the snap floor" in said
    far = _summary(du_mm=58.77, du_first_mm=31.82, relaxations={**record, "move_mm": [0.05, 0.1, 0.1, 0.3]})
    assert snap_floor_near(far) is None  # 0.3 mm at 58 mm is the fold's own, past 0.9 du
    first = {"fold_mm": [23.74, 23.80], "move_mm": 0.277}
    small = _summary(du_mm=111.51, du_first_mm=23.77, snaps=[first],
                     relaxations={**record, "snap_floor_mm": 0.24, "move_mm": [0.01] * 4})  # fmt: skip
    assert "1.2 times the snap floor (0.24 mm): the floor doubled would not count it" in snap_floor_near(small)
    assert snap_floor_near(_summary(du_mm=58.77, du_first_mm=31.82, relaxations={"runaway_mm": 20.0})) is None
