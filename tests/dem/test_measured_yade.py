"""A surveyed arch in real YADE (about 50 s each): a 15-voussoir ring given as its joints' corners, 24 mm
thick at the crown and 36 mm at the springings, and the paper's ring of 15 voussoirs whose extrados are
arcs (seven-corner polyhedra), collapse in the DEM where the static engine puts them: du within 1 %, the
same hinges and the same kind of collapse (measured: 141.59 and 141.59 mm, both on 1E 3I 10E 16E; the arcs in
docs/movements.md)."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import needs_yade
from surveys import curved_extrados, thicker_at_the_haunches

from yadearch.api.measured import measured_case
from yadearch.case.config import preset
from yadearch.model.hinges import same_hinges
from yadearch.static.simulate import simulate_static

pytestmark = [needs_yade, pytest.mark.yade]

ENGINES_TOLERANCE = 0.01  # the DEM against the static engine on one model (docs/validation-engines.md)


def _collapses_where_the_static_engine_says(case, folder: Path) -> float:
    """The DEM's du of `case` (mm), once it is asserted to collapse within ENGINES_TOLERANCE of the static
    engine, on the same hinges."""
    from yadearch.dem.runner import Runner

    static = simulate_static(case.with_overrides({"numerics.engine": "static"}), folder, log=lambda _line: None)
    dem = Runner(case.with_overrides({"progress_every_s": 1e9}), log=lambda _line: None).run()
    assert static.collapsed and dem.collapsed
    assert dem.du_mm == pytest.approx(static.du_mm, rel=ENGINES_TOLERANCE)
    assert same_hinges([h.to_json() for h in dem.hinges_at_collapse], [h.to_json() for h in static.hinges_at_collapse])
    assert dem.collapse_kind == static.collapse_kind is not None  # read alike: the fold's motion to the runaway
    return dem.du_mm


def test_a_surveyed_ring_of_varying_thickness_collapses_where_the_static_engine_says(tmp_path: Path) -> None:
    base = preset("set2").with_overrides({"geometry.n_voussoirs": 15})
    surveyed = measured_case(thicker_at_the_haunches(base), base=base)
    du = _collapses_where_the_static_engine_says(surveyed, tmp_path / "static")
    assert du > 120.0  # thicker haunches carry the settlement beyond the uniform ring's 98.77 mm


def test_voussoirs_with_a_curved_extrados_collapse_where_the_static_engine_says(tmp_path: Path) -> None:
    """Seven-corner voussoirs (three corners on each extrados arc) are YADE polyhedra as they are: the DEM
    collapses within 1 % of the static engine, on the same hinges."""
    base = preset("set2").with_overrides({"geometry.n_voussoirs": 15})
    _collapses_where_the_static_engine_says(measured_case(curved_extrados(base, 3), base=base), tmp_path / "static")
