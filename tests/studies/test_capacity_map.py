"""`ya.capacity` on the static engine (a 9-voussoir arch, seconds): the directions, the map's files,
and the mechanics the map must show."""

from __future__ import annotations

import pandas as pd
import pytest

import yadearch as ya
from yadearch.studies.capacity.directions import directions


def test_directions_every_step_from_spreading_to_closing_and_bad_steps_refused():
    assert directions(45) == (0.0, -45.0, -90.0, -135.0, -180.0)
    assert len(directions(5)) == 37
    for bad in (0, -15, 7, 100):
        with pytest.raises(ValueError, match="step_deg must divide 180"):
            directions(bad)


def test_a_static_capacity_map_writes_its_files_and_settlement_is_the_strongest_direction(tmp_path):
    """Measured on 9 voussoirs at kn 5.2: spreading 25.57 mm, settlement 122.29 mm, closing 95.96 mm."""
    case = ya.preset("set2").with_overrides({"n_voussoirs": 9})
    table = ya.capacity(case, tmp_path, step_deg=90, engine="static", jobs=2, rigid=False)
    assert list(table["direction_deg"]) == [0.0, -90.0, -180.0]
    assert (table["status"] == "done").all()
    du = table.set_index("direction_deg")["du_mm"]
    settled = ya.run(case, out=tmp_path / "settle", engine="static", figures=False)
    assert du[-90.0] == pytest.approx(settled.du_mm, rel=1e-9)  # the same case, the same answer
    assert du[-90.0] > 2 * du[0.0]  # an arch carries a settlement far better than a spreading
    assert du[-90.0] > du[-180.0]
    assert pd.read_csv(tmp_path / "capacity.csv")["du_mm"].tolist() == pytest.approx(du.tolist())
    assert (tmp_path / "capacity_map.png").stat().st_size > 0
    assert "static engine" in (tmp_path / "capacity.md").read_text()


def test_the_rigid_limits_are_solved_once_per_arch_and_direction(tmp_path, monkeypatch):
    """A rerun reads the rigid limits back (no analysis runs); another arch in the same cache is
    solved for itself."""
    import yadearch.studies.capacity.campaign as capacity_map
    from yadearch.case.config import preset

    cache, values = tmp_path / "rigid_limits.csv", (0.0, -90.0)
    case = preset("set2").with_overrides({"n_voussoirs": 15})
    first = capacity_map.rigid_limits(case, values, cache, progress=False)
    assert set(first) == set(values) and first[0.0].du_mm is not None

    def no_analysis(*args, **kwargs):
        raise AssertionError("solved again")

    monkeypatch.setattr(capacity_map, "limit_analysis", no_analysis)
    again = capacity_map.rigid_limits(case.with_overrides({"kn_N_per_mm3": 100}), values, cache, progress=False)
    assert {d: r.hinges for d, r in again.items()} == {d: r.hinges for d, r in first.items()}
    assert [again[d].du_mm for d in values] == pytest.approx([first[d].du_mm for d in values], rel=1e-5)
    with pytest.raises(AssertionError, match="solved again"):
        capacity_map.rigid_limits(case.with_overrides({"thickness_mm": 30}), values, cache, progress=False)
