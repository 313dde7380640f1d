"""Problems that are their own mirror image (yadearch/solve/mirror.py): which they are, and that the
mirror mechanism a summary names is the one other numerics meet, at the same du."""

from __future__ import annotations

import pytest

from yadearch.case.config import preset
from yadearch.solve.mirror import is_own_mirror_image, mirror_hinges
from yadearch.solve.rigid import rigid_arch
from yadearch.static.simulate import simulate_static

# the atlas's semicircle closing at t/R 0.15 (kn 5.2): its hinges flip to the mirror image with the
# increments doubled (docs/atlas.md)
CLOSING_SEMICIRCLE = {"embrace_deg": 180.0, "thickness_mm": 45.0, "support_direction_deg": 180.0}
DOUBLED_INCREMENTS = {"numerics.first_increment_mm": 2.0, "numerics.max_increment_mm": 5.0}
DU_TOLERANCE = 0.01  # the two mirror mechanisms' du, relative


def _own_mirror_image(overrides: dict) -> bool:
    case = preset("set2").with_overrides(overrides)
    return is_own_mirror_image(case, rigid_arch(case).movement)


@pytest.mark.parametrize(
    ("overrides", "itself"),
    [
        ({"support_direction_deg": 0.0}, True),  # spreading: the mirror is the other support spreading
        ({"support_direction_deg": 180.0}, True),  # closing
        ({"moving_support": "both", "support_direction_deg": 0.0}, True),  # both supports spreading
        ({}, False),  # the paper's settlement: its mirror is the other support settling
        ({"support_direction_deg": -45.0}, False),
        ({"support_direction_deg": 0.0, "keystone_offset_mm": 0.5}, True),  # a symmetric defect
        ({"support_direction_deg": 0.0, "face_bump_sd_mm": 0.1}, False),  # defects drawn at random
        ({"support_direction_deg": 0.0, "voussoir_length_sd_mm": 0.1}, False),
        ({"support_direction_deg": 0.0, "live_load": "vertical", "held_load_N": 1.0}, False),
    ],
)
def test_which_problems_are_their_own_mirror_image(overrides, itself):
    assert _own_mirror_image(overrides) is itself


def test_mirror_hinges_face_each_other_across_the_crown():
    case = preset("set2").with_overrides({"support_direction_deg": 0.0})
    movement = rigid_arch(case).movement
    assert mirror_hinges(case, movement, ["1E", "12I", "27E", "44I"]) == ["13I", "30E", "45I", "56E"]
    assert mirror_hinges(case, movement, []) is None
    settling = preset("set2")
    assert mirror_hinges(settling, rigid_arch(settling).movement, ["1E", "9I", "29E", "56E"]) is None


def test_the_named_mirror_mechanism_is_what_other_increments_meet():
    base = preset("set2").with_overrides({**CLOSING_SEMICIRCLE, "numerics.engine": "static"})
    default = simulate_static(base, None, log=lambda _: None)
    doubled = simulate_static(base.with_overrides(DOUBLED_INCREMENTS), None, log=lambda _: None)
    assert default.mirror_hinges and doubled.mirror_hinges
    assert default.hinge_labels.split() != doubled.hinge_labels.split()  # the numerics picked the other one
    assert doubled.hinge_labels.split() == default.mirror_hinges
    assert default.hinge_labels.split() == doubled.mirror_hinges
    assert abs(doubled.du_mm / default.du_mm - 1.0) < DU_TOLERANCE  # 11.20 / 11.18 mm
    assert "or the mirror image" in default.hinge_text


def test_a_mechanism_that_is_its_own_mirror_image_names_no_other():
    case = preset("set2").with_overrides({"support_direction_deg": 0.0})
    assert mirror_hinges(case, rigid_arch(case).movement, ["1E", "20I", "37I", "56E"]) is None
