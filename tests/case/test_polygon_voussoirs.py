"""Voussoirs of more than four corners (a curved extrados drawn as a polygon, a springer's bed and back):
a survey of blocks keeps every corner (`geometry.intrados_points_mm`, `extrados_points_mm`); the blocks
weigh their polygons' area (a closed form for arcs); the static engine holds them in equilibrium; a
load on the extrados stands on the polygon, the fill presses on a vertical back; corners that change
nothing change no answer; what cannot be built is refused in one line (docs/movements.md)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import REPO
from surveys import curved_extrados, surveyed_blocks

from yadearch.api.measured import measured_case, on_piers
from yadearch.case.config import case_from_dict, preset
from yadearch.case.mechanics import arch_geometry, backfill, live_load
from yadearch.errors import CaseError
from yadearch.model import units
from yadearch.model.backfill import backfill_points, fill_surface
from yadearch.model.loads import extrados_chain, extrados_segments, live_load_points
from yadearch.solve import banded
from yadearch.solve.limit import limit_analysis
from yadearch.solve.static_path import StaticLoading
from yadearch.solve.statics import static_arch
from yadearch.static.records import StaticRecords

SMALL = {"geometry.n_voussoirs": 15, "numerics.engine": "static"}
HINGE_ROTATION = 1e-3  # rad; the records need one, the reactions do not depend on it
ON_THE_CHORD_MM = 1e-4  # a corner this far outside a straight face: a face that is still straight


@pytest.fixture(scope="module")
def base():
    return preset("set2").with_overrides(SMALL)


def _segment(radius: float, angle: float) -> float:
    """The area between a circle's arc of `angle` and its chord."""
    return 0.5 * radius**2 * (angle - math.sin(angle))


def test_a_curved_extrados_weighs_the_annulus_and_its_chords(base):
    """Each voussoir: four joint corners and three on the extrados arc. The blocks weigh density x g x
    depth x (annular sector + the intrados's 15 chord segments - the extrados's 60 arc segments left
    out), a closed form, to 1e-9; every corner of the survey is a corner of its block."""
    case = measured_case(curved_extrados(base, 3), base=base)
    geometry = arch_geometry(case)
    assert [len(b) for b in geometry.voussoirs] == [2 * 7] * 15
    assert len(case.geometry.extrados_points_mm) == 45 and case.geometry.intrados_points_mm == []
    g = base.geometry
    r, outer = units.mm(g.internal_radius_mm), units.mm(g.internal_radius_mm + g.thickness_mm)
    embrace, n = math.radians(g.embrace_deg), g.n_voussoirs
    area = 0.5 * (outer**2 - r**2) * embrace + n * _segment(r, embrace / n) - 4 * n * _segment(outer, embrace / n / 4)
    unit_weight = units.density(case.material.density_g_per_cm3) * case.loading.gravity_m_per_s2
    arch = static_arch(case)
    assert arch.weight[1:-1].sum() == pytest.approx(unit_weight * units.mm(g.depth_mm) * area, rel=1e-9)
    chain = extrados_chain(geometry, 5)
    assert len(chain) == 5 and np.allclose(np.linalg.norm(chain, axis=1), outer, rtol=1e-12)


def test_polygon_voussoirs_stand_with_the_supports_carrying_their_weight(base):
    """Under its self-weight the curved-extrados arch reaches a stable equilibrium whose vertical
    reactions carry the voussoirs' weight to 1e-6; it is heavier than the chord arch, by the arcs'
    segments."""
    loading = StaticLoading.of(measured_case(curved_extrados(base, 3), base=base))
    state = loading.selfweight()
    assert banded.positive_definite(state.stiffness)
    row = StaticRecords(loading.arch, HINGE_ROTATION).series_columns(state)
    weight = float(loading.arch.weight[1:-1].sum())
    assert row["left_Ry_N"] + row["right_Ry_N"] == pytest.approx(weight, rel=1e-6)
    assert weight > float(static_arch(base).weight[1:-1].sum())


def test_corners_on_straight_faces_change_no_answer(base):
    """A corner in the middle of each voussoir's extrados and intrados, ON_THE_CHORD_MM off the straight
    face (convex): the same static du to 1e-4 and hinges, the same rigid limit to 1e-4."""
    survey = surveyed_blocks(base)
    for block in survey["blocks"]:
        if "support" not in block:
            a_in, b_in, b_out, a_out = np.array(block["corners"])
            below = _off_the_chord(a_in, b_in, ON_THE_CHORD_MM)
            above = _off_the_chord(b_out, a_out, ON_THE_CHORD_MM)
            block["corners"] = [
                a_in.tolist(),
                below.tolist(),
                b_in.tolist(),
                b_out.tolist(),
                above.tolist(),
                a_out.tolist(),
            ]
    cornered = measured_case(survey, base=base)
    assert len(cornered.geometry.intrados_points_mm) == len(cornered.geometry.extrados_points_mm) == 15
    plain = measured_case(surveyed_blocks(base), base=base)
    (du, hinges), (du_plain, hinges_plain) = _du(cornered), _du(plain)
    assert du == pytest.approx(du_plain, rel=1e-4) and hinges == hinges_plain
    assert limit_analysis(cornered).du_rigid_mm == pytest.approx(limit_analysis(plain).du_rigid_mm, rel=1e-4)


def test_a_load_stands_on_an_extrados_corner(base):
    """A point load above an extrados corner acts at that corner, on the arc, not on the chord below it."""
    case = measured_case(curved_extrados(base, 1), base=base)
    geometry = arch_geometry(case)
    corner = extrados_chain(geometry, 8)[1]
    span = geometry.joints[-1].intrados[0] - geometry.joints[0].intrados[0]
    where = float((corner[0] - geometry.joints[0].intrados[0]) / span)
    loaded = case.with_overrides({"loads.live_load": "vertical", "loads.load_position_over_span": where})
    points = live_load_points(
        geometry, static_arch(loaded).centroid0, static_arch(loaded).weight, live_load(loaded, geometry)
    )
    assert points.block.tolist() == [8] and np.allclose(points.point[0], corner, atol=1e-12)


def test_the_fill_presses_a_springers_vertical_back(base):
    """A springer whose extrados rises vertically from its springing joint's corner, then runs level to
    its other joint: the fill pushes that back toward the span with K x unit weight x depth x its mean
    height under the fill's level x its height (a trapezoid of pressure), and weighs nothing on it."""
    case = _springer_with_a_back(base).with_overrides(
        {"loads.fill_depth_mm": 50.0, "loads.fill_lateral_coefficient": 0.5, "loads.fill_density_g_per_cm3": 2.0}
    )
    geometry = arch_geometry(case)
    bottom, top = extrados_chain(geometry, 1)[:2]
    assert bottom[0] == pytest.approx(top[0], abs=1e-12) and top[1] > bottom[1]
    fill = backfill(case)
    points = backfill_points(geometry, fill)
    surface = fill_surface(geometry, fill)
    on_back = [k for k in range(len(points.block)) if points.block[k] == 1 and points.force[k, 1] == 0.0]
    assert len(on_back) == 1
    mean_height = surface - 0.5 * (bottom[1] + top[1])
    expected = fill.lateral_coefficient * fill.unit_weight * geometry.depth * mean_height * (top[1] - bottom[1])
    assert points.force[on_back[0]] == pytest.approx([expected, 0.0], rel=1e-12)


def test_piers_keep_a_measured_voussoirs_corners(base):
    """An arch of polygon voussoirs on piers: each voussoir the same polygon, numbered one further."""
    case = measured_case(curved_extrados(base, 2), base=base)
    piers = on_piers(case, 100.0, 80.0)
    assert [row[0] for row in piers.geometry.extrados_points_mm] == [
        row[0] + 1 for row in case.geometry.extrados_points_mm
    ]
    for a, b in zip(arch_geometry(case).voussoirs, arch_geometry(piers).voussoirs[1:-1]):
        assert a.shape == b.shape and np.abs(a - b).max() < 1e-12


@pytest.mark.parametrize(
    ("overrides", "said"),
    [
        ({"geometry.extrados_points_mm": [[3, 0.0, 0.0]]}, "voussoir 3 of this arch is not a convex polygon of 5"),
        ({"geometry.extrados_points_mm": [[16, 0.0, 330.0]]}, "voussoir 16 must be a whole number from 1 to 15"),
        ({"imperfections.voussoir_length_sd_mm": 0.3}, "must be 0 for voussoirs of more than four corners"),
    ],
    ids=["inside the block", "no such voussoir", "dimension errors"],
)
def test_polygons_that_make_no_arch_are_refused_in_one_line(base, overrides, said):
    case = measured_case(curved_extrados(base, 1), base=base)
    with pytest.raises(CaseError, match=said) as error:
        arch_geometry(case.with_overrides(overrides))
    assert "\n" not in str(error.value)


CORNER = {"extrados_points_mm": [[1, 0.0, 330.0]]}


def test_face_corners_on_a_parametric_arch_are_refused(base):
    with pytest.raises(CaseError, match="extrados_points_mm is for shape 'measured' only, got shape 'segmental'"):
        arch_geometry(case_from_dict({**base.to_dict(), "geometry": {**base.to_dict()["geometry"], **CORNER}}))
    with pytest.raises(CaseError, match="extrados_points_mm is not read by shape 'segmental'"):  # set by hand
        base.with_overrides({f"geometry.{key}": value for key, value in CORNER.items()})


def _off_the_chord(a: np.ndarray, b: np.ndarray, out_mm: float) -> np.ndarray:
    """The middle of the chord a -> b (a counter-clockwise face) moved `out_mm` outward (to its right)."""
    along = (b - a) / np.linalg.norm(b - a)
    return (a + b) / 2.0 + out_mm * np.array([along[1], -along[0]])


def _du(case) -> tuple[float, list]:
    loading = StaticLoading.of(case)
    loading.selfweight()
    path = loading.follow()
    return path.du, loading.fold_mode(path.upper).labels


def _springer_with_a_back(case):
    """`case` with its first voussoir a springer: its extrados rises vertically from the springing
    joint's extrados corner to the level of its other joint's, then runs level to it (one more corner)."""
    survey = surveyed_blocks(case)
    springer = min((b for b in survey["blocks"] if "support" not in b), key=lambda b: min(c[0] for c in b["corners"]))
    a_in, b_in, b_out, a_out = np.array(springer["corners"])
    springer["corners"] = [a_in.tolist(), b_in.tolist(), b_out.tolist(), [a_out[0], b_out[1]], a_out.tolist()]
    return measured_case(survey, base=case)


def test_the_example_survey_settles_toward_its_rigid_limit_as_its_joints_stiffen():
    """examples/surveyed_arch.json (nine voussoirs with arcs for extrados between two springers with a
    level bed and a vertical back): every block keeps its corners; the static du grows with kn toward the
    rigid march's, within 3 % of it at kn 10 000 (measured: 21.82, 37.60 and 38.60 mm, docs/movements.md)."""
    case = measured_case(REPO / "examples" / "surveyed_arch.json", base=preset("set2"))
    geometry = arch_geometry(case)
    assert [len(b) // 2 for b in geometry.voussoirs] == [5] + [6] * 9 + [5]
    assert geometry.joints[0].normal == pytest.approx([0.0, 1.0])  # the springer's level bed
    soft, _ = _du(case.with_overrides({"numerics.engine": "static"}))
    stiff, _ = _du(case.with_overrides({"numerics.engine": "static", "kn_N_per_mm3": 10_000.0}))
    rigid = limit_analysis(case).du_rigid_mm
    assert 1e3 * soft < 1e3 * stiff < rigid and 1e3 * stiff == pytest.approx(rigid, rel=0.03)


def test_a_table_of_the_blocks_corners_is_the_same_survey(tmp_path):
    """The example survey as a CSV, a row a corner (block, x_mm, y_mm, support), the blocks' rows in order
    round each: the same joints and face corners as the JSON; a block marked twice or a table of neither
    form is refused in one line, naming the block by its label."""
    import json

    import pandas as pd

    survey = REPO / "examples" / "surveyed_arch.json"
    rows = []
    for k, block in enumerate(json.loads(survey.read_text())["blocks"]):
        rows += [
            {"block": f"B{k}", "x_mm": x, "y_mm": y, "support": block.get("support", "")} for x, y in block["corners"]
        ]
    table = tmp_path / "corners.csv"
    pd.DataFrame(rows).to_csv(table, index=False)
    from_json, from_csv = measured_case(survey), measured_case(table)
    for key in ("joint_points_mm", "intrados_points_mm", "extrados_points_mm"):
        assert getattr(from_csv.geometry, key) == getattr(from_json.geometry, key)
    rows[0]["support"], rows[1]["support"] = "left", "right"
    with pytest.raises(CaseError, match="block B0 is marked left and right") as error:
        measured_case(pd.DataFrame(rows))
    assert "\n" not in str(error.value)
    with pytest.raises(CaseError, match=r"or block, x_mm, y_mm \(a row a block's corner\); missing"):
        measured_case(pd.DataFrame({"x": [1.0]}))


def test_the_fill_pushes_every_face_of_a_curved_extrados_toward_the_ring(base):
    """Each extrados face drawn as several segments takes the fill's pressure toward the ring (the side its
    chain leaves on its right), so each half's horizontal thrust is Rankine's K gamma d (H^2 - h^2) / 2,
    whatever side of the voussoir's centroid a segment lies."""
    case = measured_case(curved_extrados(base, 2), base=base).with_overrides(
        {"loads.fill_depth_mm": 50.0, "loads.fill_lateral_coefficient": 0.3}
    )
    geometry = arch_geometry(case)
    fill = backfill(case)
    points = backfill_points(geometry, fill)
    surface = fill_surface(geometry, fill)
    crest = max(float(p[1]) for _, a, b in extrados_segments(geometry) for p in (a, b))
    springing = surface - float(geometry.joints[0].extrados[1])
    side = fill.lateral_coefficient * fill.unit_weight * geometry.depth * (springing**2 - (surface - crest) ** 2) / 2
    middle = 0.5 * (geometry.joints[0].extrados[0] + geometry.joints[-1].extrados[0])
    left, right = points.force[points.point[:, 0] < middle, 0], points.force[points.point[:, 0] > middle, 0]
    assert (left >= 0.0).all() and (right <= 0.0).all()
    assert left.sum() == pytest.approx(side, rel=1e-9) and -right.sum() == pytest.approx(side, rel=1e-9)
