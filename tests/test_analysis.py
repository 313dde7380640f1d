"""Hinge history, formation order, migration, sliding and mechanism on constructed joints.csv tables
(no simulation): the analysis must find exactly the hinges built in, for any threshold within x2."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field

import numpy as np
import pandas as pd
import pytest

from yadearch.analysis import Thresholds, analyse_history
from yadearch.analysis.blocks import block_centroids, polygon_centroid, tangential_slip_mm
from yadearch.analysis.tracking import format_interfaces
from yadearch.model.geometry import segmental_arch

JOINT_MM = 24.0
FRICTION_DEG = 41.2
MU = math.tan(math.radians(FRICTION_DEG))
SQUEEZE_MM = 0.02  # both edges of every joint overlap this much under the thrust
GROWTH_MRAD_PER_MM = 4.0
RUNAWAY_MM = 2.0  # the collapse record shows the arch this far past du


@dataclass
class BuiltHinge:
    """A hinge built into a synthetic history: weights per interface, pivot side, delta it opens at;
    `preload_mrad` rotates the joint by compression alone from the start (soft joints);
    `fades_mm` (start, end) lets it close again (for migrations)."""

    weights: dict[int, float]
    side: str
    opens_mm: float
    preload_mrad: float = 0.0
    fades_mm: tuple[float, float] | None = None

    def rotation_mrad(self, delta: float) -> float:
        if delta < self.opens_mm:
            grown = 0.3 * delta / self.opens_mm
        else:
            grown = 0.5 + GROWTH_MRAD_PER_MM * (delta - self.opens_mm)
        if self.fades_mm is not None:
            start, end = self.fades_mm
            grown *= float(np.clip((end - delta) / (end - start), 0.0, 1.0))
        return grown


@dataclass
class BuiltRun:
    hinges: list[BuiltHinge]
    n_interfaces: int = 11
    du_mm: float = 30.0
    record_every_mm: float = 0.5
    sliding: dict[int, float] = field(default_factory=dict)  # interface -> |shear| / (mu normal)

    def records(self) -> list[tuple[str, float, float]]:
        """(stage, recorded delta, delta that sets the state): self-weight, the loading's equilibria
        below du (as the runner records them), the collapse record just past du showing the
        run-away arch."""
        loading = np.arange(1, int(self.du_mm / self.record_every_mm)) * self.record_every_mm
        return ([("selfweight", 0.0, 0.0)] + [("equilibrium", d, d) for d in loading]
                + [("collapse", self.du_mm + 0.05, self.du_mm + RUNAWAY_MM)])

    def joints(self) -> pd.DataFrame:
        rows = []
        for step, (stage, delta, state) in enumerate(self.records()):
            for k in range(1, self.n_interfaces + 1):
                intrados = extrados = -SQUEEZE_MM
                for h in self.hinges:
                    w = h.weights.get(k, 0.0)
                    squeeze, gap = w * h.preload_mrad * 1e-3 * JOINT_MM, w * h.rotation_mrad(state) * 1e-3 * JOINT_MM
                    if h.side == "I":
                        intrados, extrados = intrados - squeeze, extrados + gap
                    else:
                        intrados, extrados = intrados + gap, extrados - squeeze
                normal = 20.0
                ratio = self.sliding.get(k, 0.2) if stage == "collapse" else 0.2
                rows.append({"stage": stage, "step": 100 * step, "delta_mm": delta, "interface": k,
                             "rotation_rad": (intrados - extrados) / JOINT_MM,
                             "opening_intrados_mm": intrados, "opening_extrados_mm": extrados,
                             "force_position": 0.5, "normal_force_N": normal,
                             "shear_force_N": -ratio * MU * normal})
        return pd.DataFrame(rows)

    def analyse(self, thresholds: Thresholds = Thresholds(), slip_mm: np.ndarray | None = None):
        return analyse_history(self.joints(), JOINT_MM, FRICTION_DEG, self.du_mm, True, slip_mm, thresholds)


def paper_like_run() -> BuiltRun:
    """I hinge at 4, spread E hinge 6-7-8-9 (peak 7), E at the right support (rotated by compression
    from the start), then E at the left support only at collapse: E-I-E-E, D at the left support."""
    return BuiltRun([
        BuiltHinge({4: 1.0}, "I", opens_mm=5.0),
        BuiltHinge({6: 0.6, 7: 1.0, 8: 0.8, 9: 0.55}, "E", opens_mm=12.0),
        BuiltHinge({11: 1.0}, "E", opens_mm=20.0, preload_mrad=3.0),
        BuiltHinge({1: 1.0}, "E", opens_mm=30.5),
    ])


def summary_of(analysis) -> list[tuple]:
    return [(t.label, t.interface, t.final.interfaces, t.side) for t in analysis.tracks]


def test_finds_the_built_hinges_in_order_of_formation():
    a = paper_like_run().analyse()
    assert summary_of(a) == [("A", 4, (4,), "I"), ("B", 7, (6, 7, 8, 9), "E"), ("C", 11, (11,), "E"),
                             ("D", 1, (1,), "E")]
    assert [(label, seq) for label, _, seq in a.formation] == [
        ("A", "I"), ("B", "I-E"), ("C", "I-E-E"), ("D", "E-I-E-E")]
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
    assert list(zip(at_15["interface"], at_15["side"], at_15["label"])) == [(4, "I", "A"), (7, "E", "B"),
                                                                         (11, "E", "C")]
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
    return BuiltRun([
        BuiltHinge({3: 1.0}, "I", opens_mm=5.0, fades_mm=(15.0, 19.0)),
        BuiltHinge({6: 1.0}, "I", opens_mm=15.0),
        BuiltHinge({11: 1.0}, "E", opens_mm=10.0),
    ])


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
    assert abs(slip[2]) < 0.5 * theta ** 2 * 24.0
