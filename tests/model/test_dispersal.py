"""A live load's dispersal through the fill (model.dispersal, docs/loads.md "A load through the fill"):
the kernels against their closed forms; through the whole load pipeline a point load spread at the
slope rule is the undispersed strip load as wide as the spread, the loads balance, Boussinesq's
stress lies between the point and the spread, the arch carries a dispersed load better in every
solver that takes it; what has no fill to disperse through is refused in one line."""

from __future__ import annotations

import math

import numpy as np
import pytest

from yadearch.case.config import preset
from yadearch.case.mechanics import arch_geometry, backfill, live_load
from yadearch.errors import CaseError
from yadearch.model.backfill import fill_surface
from yadearch.model.dispersal import BOUSSINESQ, SPREAD, Dispersal, dispersed_share
from yadearch.model.loads import extrados_height, extrados_segments, live_load_points
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.statics import static_arch

ANGLE = math.radians(30.0)
FILL = {"live_load": "vertical", "fill_depth_mm": 100.0, "load_position_over_span": 0.3}


@pytest.mark.parametrize("kind", [SPREAD, BOUSSINESQ])
def test_a_kernel_shares_the_whole_load_symmetrically(kind):
    """Over the whole reach the shares add to 1; each half takes 1/2, its resultant the half's centroid
    of pressure: for the spread the half's middle, for Boussinesq depth sin^2(angle) / (angle + sin(2
    angle) / 2) from the load (the first moment of cos^2 over its integral)."""
    dispersal = Dispersal(kind, ANGLE, level=1.0)
    depth, reach = 0.2, 0.2 * math.tan(ANGLE)
    whole, at = dispersed_share(dispersal, 0.0, depth, -1.0, 1.0)
    assert whole == pytest.approx(1.0, rel=1e-12) and at == pytest.approx(0.0, abs=1e-15)
    half, at = dispersed_share(dispersal, 0.0, depth, 0.0, 1.0)
    assert half == pytest.approx(0.5, rel=1e-12)
    expected = reach / 2.0 if kind == SPREAD else depth * math.sin(ANGLE) ** 2 / (ANGLE + math.sin(2 * ANGLE) / 2)
    assert at == pytest.approx(expected, rel=1e-12)
    assert dispersed_share(dispersal, 0.0, depth, reach * 1.001, 1.0)[0] == 0.0  # nothing beyond the angle


def test_boussinesq_is_more_concentrated_than_the_spread():
    """Under the load Boussinesq's stress (cos^2 of the ray's angle) puts more of the load on the middle
    third of the reach than the uniform spread's third."""
    depth, reach = 0.2, 0.2 * math.tan(ANGLE)
    middle = [
        dispersed_share(Dispersal(k, ANGLE, 1.0), 0.0, depth, -reach / 3, reach / 3)[0] for k in (SPREAD, BOUSSINESQ)
    ]
    assert middle[0] == pytest.approx(1.0 / 3.0, rel=1e-12) and middle[1] > middle[0]


def test_a_point_load_spread_at_the_slope_is_the_strip_as_wide_as_its_spread():
    """Through the whole pipeline: a point load on 100 mm of fill spread at 30 deg reaches the extrados
    as the undispersed uniform strip 2 h tan(30) wide centred under it (h the fill above the extrados
    there): the same force on each voussoir (to 1e-12 N) at the same point (to 1e-12 m)."""
    case = preset("set2").with_overrides({**FILL, "load_dispersal": "spread", "load_dispersal_deg": 30.0})
    geometry = arch_geometry(case)
    arch = static_arch(case)
    spread = live_load_points(geometry, arch.centroid0, arch.weight, live_load(case, geometry))
    x = geometry.joints[0].intrados[0] + 0.3 * geometry.span
    depth = fill_surface(geometry, backfill(case)) - extrados_height(extrados_segments(geometry), x)
    strip = case.with_overrides({"load_dispersal": "none", "load_width_mm": 2e3 * depth * math.tan(ANGLE)})
    plain = live_load_points(geometry, arch.centroid0, arch.weight, live_load(strip, geometry))
    assert spread.block.tolist() == plain.block.tolist() and len(spread.block) > 3
    assert np.abs(spread.force - plain.force).max() < 1e-12
    assert np.abs(spread.point - plain.point).max() < 1e-12


@pytest.mark.parametrize("kind", ["spread", "boussinesq"])
def test_a_dispersed_load_stays_a_unit_load_and_is_carried_better(kind):
    """The dispersed 1 N, wholly over the ring at 0.3 of the span, is 1 N on the voussoirs; the rigid
    capacity under it exceeds the capacity of the same load standing on the extrados."""
    case = preset("set2").with_overrides({**FILL, "load_dispersal": kind})
    geometry = arch_geometry(case)
    arch = static_arch(case)
    points = live_load_points(geometry, arch.centroid0, arch.weight, live_load(case, geometry))
    assert points.force[:, 1].sum() == pytest.approx(-1.0, rel=1e-12) and np.all(points.force[:, 0] == 0.0)
    on_extrados = load_analysis(case.with_overrides({"load_dispersal": "none"})).multiplier
    assert load_analysis(case).multiplier > 1.1 * on_extrados


@pytest.mark.parametrize(
    ("overrides", "said"),
    [
        ({"live_load": "vertical", "load_dispersal": "spread"}, "needs a fill to disperse through"),
        (
            {"live_load": "horizontal_acceleration", "fill_depth_mm": 50.0, "load_dispersal": "boussinesq"},
            "load_dispersal is read with loads.live_load = 'vertical' only",
        ),  # fmt: skip
        (
            {"live_load": "vertical", "fill_depth_mm": 50.0, "load_dispersal": "spread", "load_dispersal_deg": 75.0},
            "load_dispersal_deg must be",
        ),  # fmt: skip
    ],
    ids=["no fill", "an acceleration", "too wide"],
)
def test_a_dispersal_with_nothing_to_disperse_is_refused_in_one_line(overrides, said):
    with pytest.raises(CaseError, match=said) as error:
        case = preset("set2").with_overrides(overrides)
        live_load(case, arch_geometry(case))
    assert "\n" not in str(error.value)
