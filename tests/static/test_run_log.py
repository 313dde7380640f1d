"""A static run's log (the command line and run.log) says each snap it survived where the path makes
it, as the DEM's log does (seventh user trial: a 10 m arch's 33 and 49 mm snaps showed there as
"stable" increments)."""

from __future__ import annotations

import json

from yadearch.case.config import preset
from yadearch.static.simulate import simulate_static

SHALLOW = {"embrace_deg": 70.0, "internal_radius_mm": 300.0, "thickness_mm": 20.0, "n_voussoirs": 30}


def test_each_snap_survived_is_in_the_log_with_its_fold_and_move(tmp_path):
    lines: list[str] = []  # what the command line shows and run.log keeps
    simulate_static(preset("set2").with_overrides(SHALLOW), tmp_path, log=lines.append)
    snaps = json.loads((tmp_path / "summary.json").read_text())["snaps"]
    said = [line for line in lines if "a snap between" in line]
    assert len(snaps) >= 2 and len(said) == len(snaps)
    for snap, line in zip(snaps, said):
        low, high = snap["fold_mm"]
        assert f"between {low:.3f} and {high:.3f} mm: a block moved {snap['move_mm']:.3f} mm" in line
