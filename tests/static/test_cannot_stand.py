"""An arch that does not stand under its own weight is told why: its joints too soft for a shape
that stands on rigid blocks, or a ring too thin for its shape whatever the joints."""

from __future__ import annotations

from pathlib import Path

import pytest

from yadearch.case.config import preset
from yadearch.errors import YadearchError
from yadearch.static.simulate import simulate_static

SEMICIRCLE = {"embrace_deg": 180.0, "engine": "static", "run_files": "summary"}


@pytest.mark.parametrize(
    "thickness_mm, kn, why",
    [
        (36.0, 0.25, "rigid blocks of this shape stand: its joints at kn 0.25 N/mm3 are too soft"),
        (24.0, 5.2, "rigid blocks of this shape do not stand either"),  # t/R 0.08 < 0.107 (Heyman)
    ],
)
def test_the_message_says_whether_rigid_blocks_would_stand(tmp_path: Path, thickness_mm, kn, why) -> None:
    case = preset("set2").with_overrides({**SEMICIRCLE, "thickness_mm": thickness_mm, "kn_N_per_mm3": kn})
    with pytest.raises(YadearchError, match="does not stand under its own weight") as error:
        simulate_static(case, tmp_path / "run", log=lambda line: None)
    assert why in str(error.value) and "\n" not in str(error.value)


def test_a_shape_that_rigid_blocks_hold_only_by_friction_is_told_so(tmp_path: Path) -> None:
    """A shallow ring of vertical joints at 20 degrees: rigid blocks stand (the LP's friction cones), with
    90 % of tan(friction) they do not, and the static engine's joints slide it down at any kn; the message
    advised a stiffer kn (seventh user trial: kn 10 000 and 100 000 fell too)."""
    shallow = {"embrace_deg": 70.0, "thickness_mm": 20.0, "n_voussoirs": 30, "joint_orientation": "vertical"}
    case = preset("set2").with_overrides({**shallow, "friction_deg": 20.0, "engine": "static", "run_files": "summary"})
    for kn in (5.2, 10_000.0):
        with pytest.raises(YadearchError, match="does not stand under its own weight") as error:
            simulate_static(case.with_overrides({"kn_N_per_mm3": kn}), tmp_path / f"kn{kn:g}", log=lambda line: None)
        assert "rigid blocks of this shape stand only by friction" in str(error.value)
