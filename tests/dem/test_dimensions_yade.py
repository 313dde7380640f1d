"""Voussoirs with dimension errors on real YADE (a 15-voussoir version of the paper's arch): built
touching, they stand under their own weight with every joint closed and carrying compression, and no
joint overlaps beyond its elastic closure."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import needs_yade

from yadearch.case.config import preset
from yadearch.model import units

pytestmark = [needs_yade, pytest.mark.yade]

COARSE = {"n_voussoirs": 15, "equilibrium_tolerance": 1e-4, "progress_every_s": 1e9}
ERRORS = {"voussoir_length_sd_mm": 0.5, "voussoir_thickness_sd_mm": 1.0, "seed": 2}
OVERLAP_TOLERANCE = 1.5  # no joint closes more than this times the perfect arch's largest closure


def _settled(overrides: dict) -> tuple[dict, dict, np.ndarray]:
    """Self-weight info, joint snapshot and each joint's largest overlap (mm) of a coarse set 1 arch."""
    from yadearch.dem.runner import Runner

    runner = Runner(preset("set1").with_overrides({**COARSE, **overrides}), log=lambda line: None)
    try:
        info = runner.selfweight()
        snap, _ = runner.recorder.joint_snapshot()
    finally:
        runner.close()
    js = snap["js"]
    return info, snap, -units.to_mm(np.minimum(js.opening_intrados, js.opening_extrados))


@pytest.mark.parametrize("contact_model", ["joint", "cgal"])
def test_voussoirs_with_dimension_errors_stand_in_contact_under_their_weight(contact_model):
    _, _, perfect = _settled({"contact_model": contact_model})
    info, snap, overlap = _settled({**ERRORS, "contact_model": contact_model})
    assert info["vertical_reaction_sum_N"] == pytest.approx(info["arch_weight_N"], rel=0.005)
    print(contact_model, perfect.round(4), overlap.round(4), snap["normal"].round(3))
    assert (overlap > 0.0).all() and (snap["normal"] > 0.0).all()  # every joint touches and carries
    assert overlap.max() < OVERLAP_TOLERANCE * perfect.max()
