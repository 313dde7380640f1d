"""The parameter sections of a case, each field with its unit in its name, its accepted range and a
one-line description (the metadata `yadearch params` prints and validation reads)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any


def _num(low: float | None = None, high: float | None = None, *, low_open: bool = False,
         high_open: bool = False, doc: str = "") -> dict[str, Any]:
    """Field metadata: the accepted range of a number and a one-line description."""
    return {"low": low, "high": high, "low_open": low_open, "high_open": high_open, "doc": doc}


@dataclass
class GeometryConfig:
    """The arch (docs/theory.md, "Arch shapes"): its intrados shape, its voussoirs of equal intrados
    length and their joints, on two rigid support blocks."""

    shape: str = field(default="segmental", metadata={
        "choices": ("segmental", "pointed", "elliptical", "three_centred"),
        "doc": "intrados shape: 'segmental' (circular, by internal_radius_mm and embrace_deg; 180 = "
        "semicircular), 'pointed' (two-centred, by span_mm and pointed_radius_over_span), "
        "'elliptical' (half-ellipse) or 'three_centred' (basket-handle), both by span_mm and rise_mm"})
    n_voussoirs: int = field(default=55, metadata=_num(2, 1000, doc="number of voussoirs"))
    embrace_deg: float = field(default=125.0, metadata=_num(0, 180, low_open=True,
                                                             doc="angle of embrace (deg; segmental)"))
    internal_radius_mm: float = field(default=300.0, metadata=_num(0, 50_000, low_open=True,
                                                                   doc="intrados radius (mm; segmental)"))
    span_mm: float = field(default=600.0, metadata=_num(0, 100_000, low_open=True, doc="intrados (clear) "
                           "span between the springings (mm; pointed, elliptical, three_centred)"))
    rise_mm: float = field(default=200.0, metadata=_num(0, 50_000, low_open=True, doc="intrados rise above "
                           "the springing line (mm; elliptical: at most span/2, three_centred: below span/2)"))
    pointed_radius_over_span: float = field(default=1.0, metadata=_num(
        0.5, 10, doc="radius of each arc of a pointed arch over the span (0.5 = semicircle, 1 = "
        "equilateral; the rise is span x sqrt(ratio - 1/4))"))
    thickness_mm: float = field(default=24.0, metadata=_num(0, 10_000, low_open=True,
                                                            doc="ring thickness normal to the intrados (mm)"))
    depth_mm: float = field(default=120.0, metadata=_num(0, 50_000, low_open=True,
                                                         doc="out-of-plane depth (mm)"))
    support_length_mm: float = field(default=36.0, metadata=_num(0, 50_000, low_open=True,
                                     doc="extent of each support block beyond its springing face (mm)"))
    joint_orientation: str = field(default="normal", metadata={
        "choices": ("normal", "vertical", "radial"),
        "doc": "joints normal to the intrados (radial for a circle), vertical, or radial: through the "
        "centre of the ellipse, of the local arc for the other shapes (= normal)"})


@dataclass
class MaterialConfig:
    """Block material (paper §2): density, joint friction, and the blocks' own elasticity."""

    density_g_per_cm3: float = field(default=1.64, metadata=_num(0, 25, low_open=True,
                                                                 doc="block density (g/cm^3)"))
    friction_deg: float = field(default=41.2, metadata=_num(0, 90, high_open=True,
                                                            doc="joint friction angle (deg)"))
    young_MPa: float = field(default=941.0, metadata=_num(0, 1e6, low_open=True,
                             doc="block Young's modulus (MPa); used only if block_elasticity"))
    block_elasticity: bool = field(default=False, metadata={"doc": "fold the block's axial "
                                   "stiffness young/width in series into kn (off: rigid blocks)"})


@dataclass
class InterfaceConfig:
    """Dry-joint interface: no-tension Winkler normal stiffness kn and shear stiffness ks = ratio*kn."""

    kn_N_per_mm3: float = field(default=5.2, metadata=_num(0, 1e5, low_open=True,
                                doc="interface normal stiffness (N/mm^3)"))
    ks_over_kn: float = field(default=0.5, metadata=_num(0, 1, low_open=True,
                              doc="shear-to-normal stiffness ratio (paper: 0.5)"))


@dataclass
class LoadingConfig:
    """Self-weight, then a monotonic movement of one support or both (docs/movements.md): a
    translation in a direction or a rotation about a pivot, measured by the distance its springing
    point travels."""

    gravity_m_per_s2: float = field(default=9.81, metadata=_num(0, 100, low_open=True,
                                    doc="gravitational acceleration (m/s^2)"))
    moving_support: str = field(default="right", metadata={
        "choices": ("right", "left", "both"), "predates": "right",
        "doc": "the support that moves: 'right', 'left' (the mirror image of the right one's "
        "motion) or 'both' (mirror-symmetric about the arch's axis)"})
    support_motion: str = field(default="translation", metadata={
        "choices": ("translation", "rotation", "path"), "predates": "translation",
        "doc": "'translation' along support_direction_deg, 'rotation' about the pivot "
        "(rotation_pivot_dx_mm, rotation_pivot_dy_mm) in rotation_sense, or 'path' (path_mm_mrad)"})
    support_direction_deg: float = field(default=-90.0, metadata=_num(-180, 180,
                                            doc="direction of the right support's translation from +x "
                                                "(deg): -90 settlement, 0 spreading, 180 closing; the "
                                                "left support mirrors it"))
    rotation_pivot_dx_mm: float = field(default=0.0, metadata={**_num(
        -1e5, 1e5, doc="pivot of a rotating right support from its springing intrados point, along x "
        "(mm; the left support mirrors it)"), "predates": 0.0})
    rotation_pivot_dy_mm: float = field(default=0.0, metadata={**_num(
        -1e5, 1e5, doc="the same pivot's offset along y (mm; e.g. -200 = a pier's base 200 mm below)"),
        "predates": 0.0})
    rotation_sense: str = field(default="clockwise", metadata={
        "choices": ("clockwise", "counterclockwise"), "predates": "clockwise",
        "doc": "sense of the right support's rotation seen from the front (clockwise about a pivot "
        "below it moves the springing outward); the left support turns the other way"})
    path_mm_mrad: list = field(default_factory=list, metadata={
        "table_columns": ("dx_mm", "dy_mm", "rotation_mrad"), "predates": [],
        "doc": "support_motion 'path': rows [dx_mm, dy_mm, rotation_mrad] of the right support's "
        "springing point displacement and rotation (counter-clockwise), each reached in a straight "
        "line from the previous row (the first from rest); du is the distance along it and the run "
        "stops at its end"})
    max_support_displacement_mm: float = field(default=150.0, metadata=_num(0, 10_000, low_open=True,
                                     doc="stop without collapse beyond this support displacement (mm, "
                                         "along the path)"))


@dataclass
class NumericsConfig:
    """Numerical settings. None of them is physics: du must not depend on them (scripts/convergence.py)."""

    engine: str = field(default="dem", metadata={
        "choices": ("dem", "static"), "predates": "dem",
        "doc": "the solver: 'dem' = YADE's explicit dynamics with damping, relaxed to equilibrium after "
        "each support increment (the reference, and the only one for dynamics); 'static' = Newton's "
        "method on the same blocks and joint law, each increment solved as a static equilibrium "
        "(docs/theory.md, 'The static engine')"})
    support_rate_mm_per_s: float = field(default=80.0, metadata=_num(0, 1e4, low_open=True,
                                            doc="support speed during continuous loading (mm/s)"))
    rate_reference_kn_N_per_mm3: float = field(default=0.0, metadata={**_num(
        0, 1e5, doc="joints stiffer than this (N/mm^3) load more slowly: the support speed is "
        "support_rate x sqrt(this / kn); 0 = no scaling (the default: loading by equilibrium "
        "increments makes du independent of the speed, docs/numerics.md)"), "predates": 0.0})
    support_acceleration_mm_per_s2: float = field(default=640.0, metadata={**_num(
        0, 1e5, doc="acceleration and braking of the support at the start and end of each move (mm/s^2); "
        "0 = instantaneous. The same at any kn: it sets the inertial load of the moving arch (640 = "
        "0.065 g)"), "predates": 0.0})
    support_horizontal_acceleration_mm_per_s2: float = field(default=40.0, metadata={**_num(
        0, 1e5, doc="largest horizontal component of the support's acceleration (mm/s^2; 40 = 0.004 g): "
        "a horizontal jolt loads the arch like a ground acceleration, and at 640 mm/s^2 it throws a "
        "spreading arch out of its hinge migrations early (docs/validation.md); 0 = no limit"),
        "predates": 0.0})
    damping: float = field(default=0.2, metadata=_num(0, 1, high_open=True,
                           doc="YADE local (non-viscous) damping coefficient"))
    hold_damping: float = field(default=0.2, metadata=_num(0, 1, high_open=True,
                                doc="YADE local damping during the equilibrium holds that decide du; "
                                "fixed apart from `damping`, because it decides how fast a creeping "
                                "near-critical arch moves and so the hold's verdict"))
    timestep_safety: float = field(default=0.6, metadata=_num(0, 1, low_open=True,
                                   doc="time step as a fraction of the critical step of a joint"))
    threads: int = field(default=1, metadata=_num(1, 256, doc="OpenMP threads of the YADE process "
                         "(they speed up CGAL contacts, x1.8 with 2, not joint elements, x0.15-0.93 "
                         "with 2; runs are bit-reproducible with 1 only)"))
    contact_model: str = field(default="joint", metadata={
        "choices": ("joint", "cgal"), "predates": "cgal",
        "doc": "how the dry joints are computed: 'joint' = zero-thickness joint elements integrated "
        "exactly in numpy (33x the steps/s), 'cgal' = YADE's polyhedra intersection and volumetric "
        "law; the same Winkler law either way"})
    equilibrium_tolerance: float = field(default=1e-3, metadata=_num(0, 1, low_open=True,
                                         doc="YADE unbalanced force (mean resultant / mean contact "
                                         "force) below which the arch is in equilibrium"))
    gravity_ramp_periods: float = field(default=200.0, metadata=_num(0, 1e6, doc="gravity grows from 0 to "
                                        "full over this many periods of a voussoir vibrating on its "
                                        "joints (pi x critical time step), equally gentle at any kn; a "
                                        "sudden load overshoots"))
    selfweight_max_s: float = field(default=2.0, metadata=_num(0, 100, low_open=True,
                                    doc="simulated time allowed for the self-weight stage (s)"))
    hold_max_s: float = field(default=2.0, metadata=_num(0, 100, low_open=True,
                              doc="simulated time allowed to find equilibrium at a fixed support (s); "
                              "a near-critical arch can creep for longer than 0.5 s before it settles "
                              "(docs/numerics.md)"))
    hold_min_s: float = field(default=0.1, metadata=_num(0, 10, doc="simulated time a hold lasts at least "
                                                          "before it may end in equilibrium (s)"))
    still_speed_mm_per_s: float = field(default=0.5, metadata=_num(0, 1000, low_open=True,
                                        doc="blocks slower than this are at rest (mm/s)"))
    settle_speed_mm_per_s: float = field(default=0.01, metadata={**_num(
        0, 1000, low_open=True, doc="before du is bracketed, its lower state relaxes until every block is "
        "slower than this (mm/s): a state accepted while still creeping fails every move near "
        "collapse"), "predates": 1e9})
    runaway_mm: float = field(default=1.0, metadata=_num(0, 1000, low_open=True,
                              doc="block displacement at a fixed support that means no equilibrium (mm)"))
    first_increment_mm: float = field(default=1.0, metadata={**_num(
        0, 1000, low_open=True, doc="support displacement of the first loading increment (mm); each "
        "increment ends in a relaxation to equilibrium"), "predates": 0.0})
    max_increment_mm: float = field(default=2.5, metadata=_num(0, 1000, low_open=True,
                                    doc="largest loading increment (mm), reached while the arch "
                                    "follows the support (5 mm let a relaxation jump between two "
                                    "positions of hinge A: kn 1 gave 61.47 mm with 5, 69.09 with 2.5, "
                                    "69.21 with 1.25)"))
    increment_growth: float = field(default=1.5, metadata=_num(1, 10, doc="factor on the increment after "
                                    "one that ended in equilibrium"))
    du_tolerance_mm: float = field(default=0.1, metadata=_num(0, 10, low_open=True,
                                   doc="width of the bracket that locates du (mm)"))
    hinge_rotation_mrad: float = field(default=2.0, metadata=_num(0, 100, low_open=True,
                                       doc="relative joint rotation that counts as a hinge (mrad)"))
    series_every_steps: int = field(default=200, metadata=_num(1, 1e9, doc="steps between time-series rows"))
    progress_every_s: float = field(default=10.0, metadata=_num(0, 1e12, low_open=True,
                                    doc="wall seconds between progress lines"))
    max_steps: int = field(default=100_000_000, metadata={**_num(
        1, 1e12, doc="step budget of a run: a case whose estimated worst case exceeds it is refused "
        "before YADE starts, and a run that reaches it fails (docs/speed.md gives the steps the "
        "paper's cases take)"), "predates": 100_000_000})


@dataclass
class ImperfectionsConfig:
    """Geometric imperfections of the voussoirs' joint faces, dimensions and assembly (docs/theory.md), each a
    mean and a standard deviation drawn per joint or voussoir from `seed`; all zero = the perfect
    arch. The supports' faces stay perfect and where they were designed."""

    seed: int = field(default=0, metadata=_num(0, 2**32 - 1, doc="seed of the random draws (one seed, "
                      "one geometry)"))
    edge_shape: str = field(default="round", metadata={
        "choices": ("round", "chamfer"), "doc": "shape of the voussoirs' worn joint edges: 'round' "
        "(a quarter circle of radius edge_radius_mm) or 'chamfer' (a 45 deg cut of that leg)"})
    edge_radius_mm: float = field(default=0.0, metadata=_num(0, 1000, doc="mean size of the rounding or "
                                  "chamfer of each intrados and extrados edge of a voussoir's joint faces (mm)"))
    edge_radius_sd_mm: float = field(default=0.0, metadata=_num(0, 1000, doc="standard deviation of "
                                     "edge_radius_mm between edges (mm; drawn sizes below 0 count as 0)"))
    face_angle_mrad: float = field(default=0.0, metadata=_num(-1000, 1000, doc="mean angle between a "
                                   "joint's two faces (mrad; > 0: the joint touches at the intrados and "
                                   "gapes toward the extrados)"))
    face_angle_sd_mrad: float = field(default=0.0, metadata=_num(0, 1000, doc="standard deviation of "
                                      "face_angle_mrad between joints (mrad)"))
    face_bump_mm: float = field(default=0.0, metadata=_num(-1000, 1000, doc="mean out-of-flatness of a "
                                "joint (mm; > 0: convex faces touching mid-joint with the ends open by "
                                "this much, < 0: hollow faces touching at the ends)"))
    face_bump_sd_mm: float = field(default=0.0, metadata=_num(0, 1000, doc="standard deviation of "
                                   "face_bump_mm between joints (mm)"))
    voussoir_offset_mm: float = field(default=0.0, metadata={**_num(
        -1000, 1000, doc="mean assembly error of each voussoir: set higher (> 0, toward the extrados) or "
        "lower than its neighbours, its faces bearing on theirs offset along the joints (mm)"), "predates": 0.0})
    voussoir_offset_sd_mm: float = field(default=0.0, metadata={**_num(
        0, 1000, doc="standard deviation of voussoir_offset_mm between voussoirs (mm)"), "predates": 0.0})
    keystone_offset_mm: float = field(default=0.0, metadata={**_num(
        -1000, 1000, doc="the keystone set higher (> 0) or lower, in addition (mm; both middle voussoirs "
        "for an even count)"), "predates": 0.0})
    left_support_angle_mrad: float = field(default=0.0, metadata={**_num(
        -1000, 1000, doc="the left support set askew: its face turned against the first voussoir's (mrad; "
        "> 0: the springing joint touches at the intrados and gapes toward the extrados)"), "predates": 0.0})
    right_support_angle_mrad: float = field(default=0.0, metadata={**_num(
        -1000, 1000, doc="the same for the right support against the last voussoir (mrad)"), "predates": 0.0})
    voussoir_length_sd_mm: float = field(default=0.0, metadata={**_num(
        0, 1000, doc="standard deviation of the voussoirs' lengths along the arch (mm; taken about the "
        "set's mean, which the supports' spacing absorbs: each joint moves by the errors on its left)"),
        "predates": 0.0})
    voussoir_thickness_mm: float = field(default=0.0, metadata={**_num(
        -1000, 1000, doc="mean error of the voussoirs' thickness (mm; > 0 thicker: the intrados stays on "
        "the centering and the extrados stands out)"), "predates": 0.0})
    voussoir_thickness_sd_mm: float = field(default=0.0, metadata={**_num(
        0, 1000, doc="standard deviation of voussoir_thickness_mm between voussoirs (mm)"), "predates": 0.0})


SECTIONS: dict[str, type] = {
    "geometry": GeometryConfig,
    "material": MaterialConfig,
    "interface": InterfaceConfig,
    "loading": LoadingConfig,
    "numerics": NumericsConfig,
    "imperfections": ImperfectionsConfig,
}

# Former parameter names still read from case files, overrides and stored runs: (section, old) -> new.
RENAMED: dict[tuple[str, str], str] = {
    ("loading", "settlement_direction_deg"): "support_direction_deg",
    ("loading", "max_settlement_mm"): "max_support_displacement_mm",
    ("numerics", "settlement_rate_mm_per_s"): "support_rate_mm_per_s",
}
