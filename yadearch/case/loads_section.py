"""The [loads] section of a case: a live load grown to collapse, its shape, and the backfill's dead loads
(`yadearch loads`, docs/loads.md)."""

from __future__ import annotations

from dataclasses import dataclass, field

from yadearch.case.fields import choice_meta, number_meta, table_meta
from yadearch.model.dispersal import DISPERSALS
from yadearch.model.loads import LIVE_LOADS, LOAD_SHAPES


@dataclass
class LoadsConfig:
    """A live load besides the self-weight, grown to collapse by the rigid-block limit analysis
    (`yadearch loads`, docs/theory.md "Loads"): a vertical load on the extrados, concentrated or spread,
    or a horizontal acceleration of every voussoir."""

    live_load: str = field(
        default="none",
        metadata=choice_meta(
            LIVE_LOADS,
            "'vertical' (a load on the extrados at load_position_over_span, spread over "
            "load_width_mm; its capacity in N) or 'horizontal_acceleration' (each voussoir pushed by "
            "its weight x the multiplier toward acceleration_toward; its capacity in g); 'none'",
            predates="none",
        ),
    )
    load_position_over_span: float = field(
        default=0.25,
        metadata={
            **number_meta(
                0,
                1,
                doc="where the vertical load's centre stands: its horizontal distance from the left "
                "springing's intrados point over the intrados span (0.25: the quarter span)",
            ),
            "predates": 0.25,
        },
    )
    load_voussoir: int = field(
        default=0,
        metadata={
            **number_meta(
                0,
                10000,
                doc="put the vertical load's centre over voussoir k instead (its extrados's middle, voussoirs "
                "counted from the left springing, 1 to n_voussoirs); 0: at load_position_over_span",
            ),
            "predates": 0,
        },
    )
    load_width_mm: float = field(
        default=0.0,
        metadata={
            **number_meta(
                0,
                1e5,
                doc="horizontal width the vertical load spreads over, uniformly (mm; 0: concentrated; "
                "the span: a uniform load)",
            ),
            "predates": 0.0,
        },
    )
    load_inclination_deg: float = field(
        default=0.0,
        metadata={
            **number_meta(
                -90,
                90,
                doc="the vertical load's angle from the downward vertical (degrees; positive leans it "
                "toward the right, as a braking or a raking force would push; 0: vertical); its magnitude "
                "grows, its capacity is in N along it",
            ),
            "predates": 0.0,
        },
    )
    further_loads: list = field(
        default_factory=list,
        metadata=table_meta(
            ("offset_mm", "ratio"),
            "more loads on the extrados beside the vertical load, one row each: its centre's "
            "horizontal offset from the load's (mm, + to the right) and its magnitude over the load's "
            "(> 0); each spreads, leans and moves with it (a tandem axle 150 mm apart: [[150, 1]]); the "
            "capacity is the first load's",
        ),
    )
    acceleration_toward: str = field(
        default="right",
        metadata={"choices": ("right", "left"), "predates": "right", "doc": "the horizontal acceleration's direction"},
    )
    load_shape: str = field(
        default="uniform",
        metadata=choice_meta(
            LOAD_SHAPES,
            "how a spread vertical load is distributed over load_width_mm: 'uniform', 'rising' "
            "(a triangle from zero at its left edge) or 'falling' (from its peak at the left edge to zero)",
            predates="uniform",
        ),
    )
    held_load_N: float = field(
        default=0.0,
        metadata={
            **number_meta(
                0,
                1e5,
                doc="a run with a vertical live load (`yadearch run`): the load the arch carries while its "
                "support moves, applied after the self-weight (N; 0: none): du under a load",
            ),
            "predates": 0.0,
        },
    )
    held_acceleration_g: float = field(
        default=0.0,
        metadata={
            **number_meta(
                0,
                10,
                doc="a run with a horizontal acceleration (`yadearch run`): the acceleration held while the "
                "support moves, applied after the self-weight (g; 0: none)",
            ),
            "predates": 0.0,
        },
    )
    fill_depth_mm: float = field(
        default=0.0,
        metadata={
            **number_meta(
                0,
                1e5,
                doc="backfill: depth of the level fill above the extrados' highest point (mm; 0: no fill); "
                "its weight and lateral pressure are dead loads on the voussoirs (docs/loads.md)",
            ),
            "predates": 0.0,
        },
    )
    load_dispersal: str = field(
        default="none",
        metadata=choice_meta(
            DISPERSALS,
            "with backfill, a vertical live load stands on the fill's surface and reaches the extrados "
            "'spread' uniformly at load_dispersal_deg either side, or as 'boussinesq' (an elastic "
            "half-plane's stress under a line load, cut at load_dispersal_deg); 'none': on the extrados",
            predates="none",
        ),
    )
    load_dispersal_deg: float = field(
        default=30.0,
        metadata={
            **number_meta(
                0,
                60,
                low_open=True,
                doc="the dispersal's angle from the vertical (deg): the spread's slope (26.57: 2 vertical to "
                "1 horizontal) or where Boussinesq's stress is cut",
            ),
            "predates": 30.0,
        },
    )
    fill_density_g_per_cm3: float = field(
        default=2.0,
        metadata={**number_meta(0, 10, low_open=True, doc="the backfill's density (g/cm3)"), "predates": 2.0},
    )
    fill_lateral_coefficient: float = field(
        default=0.0,
        metadata={
            **number_meta(
                0,
                10,
                doc="the backfill's lateral pressure coefficient K (horizontal pressure K x its unit weight "
                "x depth below its surface on the extrados; e.g. 1 - sin(phi) at rest; 0: none)",
            ),
            "predates": 0.0,
        },
    )
    fill_passive_coefficient: float = field(
        default=0.0,
        metadata={
            **number_meta(
                0,
                50,
                doc="the backfill's passive coefficient Kp: where the arch sways into the fill, the fill pushes "
                "back up to Kp x its unit weight x depth (RING's passive restraint, e.g. a third of "
                "(1 + sin(phi)) / (1 - sin(phi)) mobilised); 0: none, else larger than fill_lateral_coefficient",
            ),
            "predates": 0.0,
        },
    )
    fill_passive_displacement_mm: float = field(
        default=1.0,
        metadata={
            **number_meta(
                0,
                1e4,
                low_open=True,
                doc="how far a face moves into the fill to mobilise its whole passive pressure (mm): the "
                "static engine's and the DEM's fill spring (the rigid analysis mobilises it at once)",
            ),
            "predates": 1.0,
        },
    )
