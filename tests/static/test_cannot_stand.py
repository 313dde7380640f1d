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
