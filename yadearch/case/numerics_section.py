"""The [numerics] section of a case: how either engine solves it, none of it physics."""

from __future__ import annotations

from dataclasses import dataclass, field

from yadearch.case.fields import choice_meta, number_meta

FULL_RUN_FILES = "full"  # numerics.run_files: every table, state and snapshot of the run
SUMMARY_RUN_FILES = "summary"  # numerics.run_files: case.toml, summary.json and run.log only
# a block moving half the ring's thickness at a fixed support has run away: far beyond any hinge snap
# (a snap moves blocks by a few hundredths of the thickness), well short of a fallen arch
RUNAWAY_THICKNESS_RATIO = 0.5
LEAST_BRACKET = 0.01  # a relative bracket narrows to this x du_tolerance_mm at most (a du near 0)
SNAP_THICKNESS_RATIO = 0.01  # a state this x the ring's thickness off its branch's prediction is on another branch
STATIC_ENGINE = "static"  # numerics.engine: Newton's method on the same blocks and joints
NO_INCREMENTS_CHECK = "none"  # numerics.increments_check: the path solved once
HALVED_INCREMENTS_CHECK = "halved"  # ... and again with the increments halved (static engine)
SCENE_PATH_STATES = "scene"  # numerics.support_path_states: the DEM's path compares its holds' own states
STATIC_PATH_STATES = "static"  # ... the static model's stable equilibria that its holds sit in
AUTO_PATH_STATES = "auto"  # ... 'static' with the joint elements, 'scene' with CGAL contacts (no static model)
JOINT_CONTACTS = "joint"  # numerics.contact_model: zero-thickness joint elements (the static model's law)


@dataclass
class NumericsConfig:
    """Numerical settings. None of them is physics: du must not depend on them (scripts/convergence.py)."""

    engine: str = field(
        default="dem",
        metadata={
            "choices": ("dem", STATIC_ENGINE),
            "predates": "dem",
            "doc": "the solver: 'dem' = YADE's explicit dynamics with damping, relaxed to equilibrium after "
            "each support increment (the reference, and the only one for dynamics); 'static' = Newton's "
            "method on the same blocks and joint law, each increment solved as a static equilibrium "
            "(docs/theory.md, 'The static engine')",
        },
    )
    support_rate_mm_per_s: float = field(
        default=80.0, metadata=number_meta(0, 1e4, low_open=True, doc="support speed during continuous loading (mm/s)")
    )
    rate_reference_kn_N_per_mm3: float = field(
        default=0.0,
        metadata=number_meta(
            0,
            1e5,
            doc="joints stiffer than this (N/mm^3) load more slowly: the support speed is "
            "support_rate x sqrt(this / kn); 0 = no scaling (the default: loading by equilibrium "
            "increments makes du independent of the speed, docs/numerics.md)",
            predates=0.0,
        ),
    )
    support_acceleration_mm_per_s2: float = field(
        default=640.0,
        metadata=number_meta(
            0,
            1e5,
            doc="acceleration and braking of the support at the start and end of each move (mm/s^2); 0 = "
            "instantaneous. The same at any kn: it sets the inertial load of the moving arch (640 = 0.065 g)",
            predates=0.0,
        ),
    )
    support_horizontal_acceleration_mm_per_s2: float = field(
        default=5.0,
        metadata=number_meta(
            0,
            1e5,
            doc="largest horizontal component of the support's acceleration (mm/s^2; 5 = 0.0005 g): "
            "a horizontal jolt loads the arch like a ground acceleration; at 40 mm/s^2 it moved a "
            "pointed arch's du 5.5 %, at 2.5-10 du stays within 1 % (docs/numerics.md); 0 = no limit",
            predates=0.0,
        ),
    )
    damping: float = field(
        default=0.2, metadata=number_meta(0, 1, high_open=True, doc="YADE local (non-viscous) damping coefficient")
    )
    hold_damping: float = field(
        default=0.2,
        metadata=number_meta(
            0,
            1,
            high_open=True,
            doc="YADE local damping during the equilibrium holds that decide du; fixed apart from `damping`, "
            "because it decides how fast a creeping near-critical arch moves and so the hold's verdict",
        ),
    )
    timestep_safety: float = field(
        default=0.6,
        metadata=number_meta(0, 1, low_open=True, doc="time step as a fraction of the critical step of a joint"),
    )
    threads: int = field(
        default=1,
        metadata=number_meta(
            1,
            256,
            doc="OpenMP threads of the YADE process (they speed up CGAL contacts, x1.8 with 2, not joint "
            "elements, x0.15-0.93 with 2; runs are bit-reproducible with 1 only)",
        ),
    )
    contact_model: str = field(
        default="joint",
        metadata={
            "choices": ("joint", "cgal"),
            "predates": "cgal",
            "doc": "how the dry joints are computed: 'joint' = zero-thickness joint elements integrated "
            "exactly in numpy (33x the steps/s), 'cgal' = YADE's polyhedra intersection and volumetric "
            "law; the same Winkler law either way",
        },
    )
    equilibrium_tolerance: float = field(
        default=1e-3,
        metadata=number_meta(
            0,
            1,
            low_open=True,
            doc="YADE unbalanced force (mean resultant / mean contact force) below which the arch is in equilibrium",
        ),
    )
    gravity_ramp_periods: float = field(
        default=200.0,
        metadata=number_meta(
            0,
            1e6,
            doc="gravity grows from 0 to full over this many periods of a voussoir vibrating on its joints "
            "(pi x critical time step), equally gentle at any kn; a sudden load overshoots",
        ),
    )
    selfweight_max_s: float = field(
        default=2.0,
        metadata=number_meta(0, 100, low_open=True, doc="simulated time allowed for the self-weight stage (s)"),
    )
    hold_max_s: float = field(
        default=2.0,
        metadata=number_meta(
            0,
            100,
            low_open=True,
            doc="simulated time allowed to find equilibrium at a fixed support (s); a near-critical arch can "
            "creep for longer than 0.5 s before it settles (docs/numerics.md)",
        ),
    )
    hold_min_s: float = field(
        default=0.1,
        metadata=number_meta(0, 10, doc="simulated time a hold lasts at least before it may end in equilibrium (s)"),
    )
    still_speed_mm_per_s: float = field(
        default=0.5, metadata=number_meta(0, 1000, low_open=True, doc="blocks slower than this are at rest (mm/s)")
    )
    settle_speed_mm_per_s: float = field(
        default=0.01,
        metadata=number_meta(
            0,
            1000,
            low_open=True,
            doc="before du is bracketed, its lower state relaxes until every block is slower than this "
            "(mm/s): a state accepted while still creeping fails every move near collapse",
            predates=1e9,
        ),
    )
    runaway_thickness_ratio: float = field(
        default=RUNAWAY_THICKNESS_RATIO,
        metadata={  # a run before it had a runaway length in mm: no value of this reproduces it
            **number_meta(
                0,
                100,
                low_open=True,
                doc="a block moving this many ring thicknesses at a fixed support has run away (no "
                "equilibrium); a snap that re-settles closer is survived however far it moves, so du rests "
                "on it only where a snap lands nearly that far (the run warns; docs/numerics.md)",
            ),
            "predates": None,
        },
    )
    snap_thickness_ratio: float = field(
        default=SNAP_THICKNESS_RATIO,
        metadata=number_meta(
            0,
            0.5,
            low_open=True,
            doc="a state that puts a block further than this many ring thicknesses from where its branch "
            "predicts it (the static engine's continuation, the DEM's trend and static check; the rigid "
            "march's re-seating) is on another branch: the path snapped, and the fold before it is "
            "du_first; the resolution of du_first, snaps smaller than it go uncounted (docs/numerics.md)",
        ),
    )
    first_increment_mm: float = field(
        default=1.0,
        metadata=number_meta(
            0,
            1000,
            low_open=True,
            doc="support displacement of the first loading increment (mm); each increment ends in a "
            "relaxation to equilibrium",
            predates=0.0,
        ),
    )
    max_increment_mm: float = field(
        default=2.5,
        metadata=number_meta(
            0,
            1000,
            low_open=True,
            doc="largest loading increment (mm), reached while the arch follows the support; larger ones let "
            "a relaxation jump between two positions of hinge A (docs/validation.md)",
        ),
    )
    increment_growth: float = field(
        default=1.5, metadata=number_meta(1, 10, doc="factor on the increment after one that ended in equilibrium")
    )
    du_tolerance_mm: float = field(
        default=0.1, metadata=number_meta(0, 10, low_open=True, doc="width of the bracket that locates du (mm)")
    )
    du_tolerance_ratio: float = field(
        default=0.0,
        metadata=number_meta(
            0,
            0.1,
            doc="the bracket that locates du, and each fold, at most this fraction of its upper end too; 0 = "
            "du_tolerance_mm alone; 0.005 holds a short du within 1 % when the bracket is halved or doubled "
            "(docs/numerics.md)",
            predates=0.0,
        ),
    )
    hinge_rotation_mrad: float = field(
        default=2.0,
        metadata=number_meta(0, 100, low_open=True, doc="relative joint rotation that counts as a hinge (mrad)"),
    )
    series_every_steps: int = field(default=200, metadata=number_meta(1, 1e9, doc="steps between time-series rows"))
    progress_every_s: float = field(
        default=10.0, metadata=number_meta(0, 1e12, low_open=True, doc="wall seconds between progress lines")
    )
    max_steps: int = field(
        default=100_000_000,
        metadata=number_meta(
            1,
            1e12,
            doc="step budget of a run: a case whose estimated worst case exceeds it is refused "
            "before YADE starts, and a run that reaches it fails (docs/speed.md gives the steps the "
            "paper's cases take)",
            predates=100_000_000,
        ),
    )
    run_files: str = field(
        default=FULL_RUN_FILES,
        metadata=choice_meta(
            (FULL_RUN_FILES, SUMMARY_RUN_FILES),
            "what the run folder keeps: 'full' = its tables, states and snapshots (figures, analysis, "
            "movies); 'summary' = case.toml, summary.json and run.log, for campaigns of thousands of "
            "runs (a twentieth of the disk, docs/speed.md); changes no result",
            predates=FULL_RUN_FILES,
        ),
    )
    increments_check: str = field(
        default=NO_INCREMENTS_CHECK,
        metadata=choice_meta(
            (NO_INCREMENTS_CHECK, HALVED_INCREMENTS_CHECK),
            "static engine only: 'halved' solves the path again from the same start with the increments "
            "halved and reports how far du and du_first move (summary.json increments_check; resolved "
            "within 1 %); twice the solver's time. `yadearch run` turns it on for a static run "
            "(docs/numerics.md)",
            predates=NO_INCREMENTS_CHECK,
        ),
    )
    support_path_states: str = field(
        default=AUTO_PATH_STATES,
        metadata=choice_meta(
            (SCENE_PATH_STATES, STATIC_PATH_STATES, AUTO_PATH_STATES),
            "DEM only: the states a support movement's path compares to tell a snap: 'scene' = the holds' "
            "own, 'static' = the static model's stable equilibria they sit in, a branch predicted from one "
            "state along its tangent, as the DEM's load paths do; 'auto' = 'static' with the joint "
            "elements, 'scene' with CGAL contacts (docs/numerics.md, 'Collapse')",
            predates=SCENE_PATH_STATES,
        ),
    )

    @property
    def path_states(self) -> str:
        """The states the DEM's path compares (`resolved_path_states`)."""
        return resolved_path_states(self.support_path_states, self.contact_model)

    @property
    def keeps_tables(self) -> bool:
        """True if the run folder keeps its tables, states and snapshots (run_files = 'full')."""
        return self.run_files == FULL_RUN_FILES


def resolved_path_states(support_path_states: str, contact_model: str) -> str:
    """The states a DEM path compares: 'auto' read as 'static' with the joint elements and as 'scene'
    with CGAL contacts, which have no static model; the other values as they are."""
    if support_path_states != AUTO_PATH_STATES:
        return support_path_states
    return STATIC_PATH_STATES if contact_model == JOINT_CONTACTS else SCENE_PATH_STATES
