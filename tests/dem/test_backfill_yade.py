"""Backfill in the DEM (dem/dead_load.py) against the static engine on one model: a 15-voussoir
segmental arch under 20 mm of fill over its crown (2 g/cm3). The fill's equivalent loads grow with
gravity and stay on the blocks: the self-weight state's supports carry the voussoirs and the fill; the
settlement's du (the fill's weight alone, K 0) and a quarter-span point load's capacity (with the
fill's lateral pressure, K 0.3), standing on the extrados or on the fill's surface and dispersed
through it, land within 1 % of the static engine's on the same hinges (measured: 106.04 against 106.20
mm on 1E 4I 12E 16I; the dispersed load 27.448 N in both, Boussinesq; docs/loads.md, "Backfill", "A
load through the fill")."""

from __future__ import annotations

import math

import pytest
from conftest import needs_yade

from yadearch.case.config import ArchCase
from yadearch.solve.load_path import static_load_path
from yadearch.solve.statics import static_arch

pytestmark = [needs_yade, pytest.mark.yade]

FILLED = {
    "n_voussoirs": 15,
    "friction_deg": 80.0,
    "interface.kn_N_per_mm3": 5.2,
    "fill_depth_mm": 20.0,
    "fill_lateral_coefficient": 0.3,
}
ENGINES_TOLERANCE = 0.01  # the two engines on one model (docs/validation-engines.md)


def test_a_filled_arch_settles_where_the_static_engine_says(tmp_path):
    from yadearch.api import run

    base = ArchCase(name="filled").with_overrides({**FILLED, "fill_lateral_coefficient": 0.0})
    static = run(base.with_overrides({"numerics.engine": "static"}), out=tmp_path / "static", figures=False)
    dem = run(base.with_overrides({"numerics.engine": "dem"}), out=tmp_path / "dem", figures=False)
    selfweight = dem.summary.selfweight
    # the supports carry the voussoirs and the fill (the hold's tolerance), as the static engine's do
    assert selfweight["fill_weight_N"] == pytest.approx(static.summary.selfweight["fill_weight_N"], rel=1e-9)
    carried = selfweight["arch_weight_N"] + selfweight["fill_weight_N"]
    assert selfweight["vertical_reaction_sum_N"] == pytest.approx(carried, rel=base.numerics.equilibrium_tolerance)
    assert static.summary.collapsed and dem.summary.collapsed
    assert math.isclose(dem.summary.du_mm, static.summary.du_mm, rel_tol=ENGINES_TOLERANCE), (
        dem.summary.du_mm,
        static.summary.du_mm,
    )
    assert dem.summary.hinge_labels == static.summary.hinge_labels


@pytest.mark.parametrize("dispersal", ["none", "boussinesq"])
def test_a_filled_arch_carries_a_point_load_as_the_static_engine_says(dispersal):
    from yadearch.dem.load_ramp import dem_load_path

    case = ArchCase(name="filled_point").with_overrides(
        {
            **FILLED,
            "live_load": "vertical",
            "load_position_over_span": 0.25,
            "load_dispersal": dispersal,
            "progress_every_s": 1e9,
        }
    )
    static = static_load_path(case)
    dem, _records, _defects = dem_load_path(case, log=lambda line: None)
    assert dem.outcome == static.outcome == "collapse"
    assert math.isclose(dem.capacity, static.capacity, rel_tol=ENGINES_TOLERANCE), (dem.capacity, static.capacity)
    assert dem.hinges == static.hinges
    # the fill stays on the blocks: the supports carry it beside the voussoirs and the load (to the
    # holds' tolerance summed over the voussoirs, as tests/dem/test_load_ramp_yade.py reads it)
    arch = static_arch(case)
    weight, fill = float(arch.weight[1:-1].sum()), -float(arch.dead[:, 1].sum())
    balance = case.geometry.n_voussoirs * case.numerics.equilibrium_tolerance
    carried = dem.curve["vertical_reactions_N"] - dem.curve["multiplier"]
    assert (abs(carried / (weight + fill) - 1.0) < balance).all(), carried.tolist()
