"""The parameter sections of a case, each field with its unit in its name, its accepted range and a
one-line description (the metadata `yadearch params` prints and validation reads); [numerics] and
[imperfections] live in modules of their own."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field, fields
from typing import Any

from yadearch.case.fields import accepted_text, choice_meta, number_meta, table_meta
from yadearch.case.imperfections_section import ImperfectionsConfig
from yadearch.case.loads_section import LoadsConfig
from yadearch.case.materials import PRESET_CHOICES
from yadearch.case.numerics_section import NumericsConfig


def _face_points(face: str, example: str) -> Any:
    """A measured voussoir's corners on its `face` ('intrados' or 'extrados') between its joints: a table
    of rows [voussoir, x_mm, y_mm]."""
    return field(
        default_factory=list,
        metadata=table_meta(
            ("voussoir", "x_mm", "y_mm"),
            f"shape 'measured': a voussoir's corners on its {face} face between its two joints (mm), left "
            f"to right, one row a corner ({example}); none: a straight face",
        ),
    )


@dataclass
class GeometryConfig:
    """The arch (docs/theory.md, "Arch shapes"): its intrados shape, its voussoirs of equal intrados
    length and their joints, on two rigid support blocks."""

    shape: str = field(
        default="segmental",
        metadata={
            "choices": ("segmental", "pointed", "elliptical", "three_centred", "measured"),
            "doc": "intrados shape: 'segmental' (circular, by internal_radius_mm and embrace_deg; 180 = "
            "semicircular), 'pointed' (two-centred, by span_mm and pointed_radius_over_span), "
            "'elliptical' (half-ellipse) or 'three_centred' (basket-handle), both by span_mm and rise_mm; "
            "'measured': the joints as surveyed (joint_points_mm), every other size taken from them",
        },
    )
    joint_points_mm: list = field(
        default_factory=list,
        metadata=table_meta(
            ("x_intrados_mm", "y_intrados_mm", "x_extrados_mm", "y_extrados_mm"),
            "shape 'measured': each joint's intrados and extrados corners (mm), left springing to "
            "right springing, one row a joint (voussoirs = rows - 1); a surveyed arch, its thickness "
            "varying as the corners do (`ya.measured_case` reads them from a CSV)",
        ),
    )
    intrados_points_mm: list = _face_points("intrados", "a springer's upright face below the curve")
    extrados_points_mm: list = _face_points("extrados", "a curved extrados, a springer's back")
    piers_mm: list = field(
        default_factory=list,
        metadata=table_meta(
            ("height_mm", "width_mm"),
            "shape 'measured': the piers `yadearch piers` put under the arch (one row; its first and last "
            "blocks), a record that names them and refuses piers on piers; none: no piers",
        ),
    )
    n_voussoirs: int = field(default=55, metadata=number_meta(2, 1000, doc="number of voussoirs"))
    embrace_deg: float = field(
        default=125.0, metadata=number_meta(0, 180, low_open=True, doc="angle of embrace (deg; segmental)")
    )
    internal_radius_mm: float = field(
        default=300.0, metadata=number_meta(0, 50_000, low_open=True, doc="intrados radius (mm; segmental)")
    )
    span_mm: float = field(
        default=600.0,
        metadata=number_meta(
            0,
            100_000,
            low_open=True,
            doc="intrados (clear) span between the springings (mm; pointed, elliptical, three_centred)",
        ),
    )
    rise_mm: float = field(
        default=200.0,
        metadata=number_meta(
            0,
            50_000,
            low_open=True,
            doc="intrados rise above the springing line (mm; elliptical: at most span/2, three_centred: below span/2)",
        ),
    )
    pointed_radius_over_span: float = field(
        default=1.0,
        metadata=number_meta(
            0.5,
            10,
            doc="radius of each arc of a pointed arch over the span (0.5 = semicircle, 1 = "
            "equilateral; the rise is span x sqrt(ratio - 1/4))",
        ),
    )
    thickness_mm: float = field(
        default=24.0, metadata=number_meta(0, 10_000, low_open=True, doc="ring thickness normal to the intrados (mm)")
    )
    depth_mm: float = field(
        default=120.0, metadata=number_meta(0, 50_000, low_open=True, doc="out-of-plane depth (mm)")
    )
    support_length_mm: float = field(
        default=36.0,
        metadata=number_meta(
            0, 50_000, low_open=True, doc="extent of each support block beyond its springing face (mm)"
        ),
    )
    joint_orientation: str = field(
        default="normal",
        metadata={
            "choices": ("normal", "vertical", "radial"),
            "doc": "joints normal to the intrados (radial for a circle), vertical, or radial: through the "
            "centre of the ellipse, of the local arc for the other shapes (= normal)",
        },
    )


@dataclass
class MaterialConfig:
    """Block material (paper §2): density, joint friction, and the blocks' own elasticity."""

    density_g_per_cm3: float = field(
        default=1.64, metadata=number_meta(0, 25, low_open=True, doc="block density (g/cm^3)")
    )
    friction_deg: float = field(
        default=41.2, metadata=number_meta(0, 90, high_open=True, doc="joint friction angle (deg)")
    )
    young_MPa: float = field(
        default=941.0,
        metadata=number_meta(0, 1e6, low_open=True, doc="block Young's modulus (MPa); used only if block_elasticity"),
    )
    block_elasticity: bool = field(
        default=False,
        metadata={"doc": "fold the block's axial stiffness young/width in series into kn (off: rigid blocks)"},
    )
    preset: str = field(
        default="",
        metadata=choice_meta(
            PRESET_CHOICES,
            "a named material (docs/materials.md): its density and friction, unless the case gives them; "
            "'' for the case's own values",
        ),
    )


@dataclass
class InterfaceConfig:
    """Dry-joint interface: no-tension Winkler normal stiffness kn and shear stiffness ks = ratio*kn."""

    kn_N_per_mm3: float = field(
        default=5.2, metadata=number_meta(0, 1e5, low_open=True, doc="interface normal stiffness (N/mm^3)")
    )
    ks_over_kn: float = field(
        default=0.5, metadata=number_meta(0, 1, low_open=True, doc="shear-to-normal stiffness ratio (paper: 0.5)")
    )


@dataclass
class LoadingConfig:
    """Self-weight, then a monotonic movement of one support or both (docs/movements.md): a
    translation in a direction or a rotation about a pivot, measured by the distance its springing
    point travels."""

    gravity_m_per_s2: float = field(
        default=9.81, metadata=number_meta(0, 100, low_open=True, doc="gravitational acceleration (m/s^2)")
    )
    moving_support: str = field(
        default="right",
        metadata={
            "choices": ("right", "left", "both"),
            "predates": "right",
            "doc": "the support that moves: 'right', 'left' (the mirror image of the right one's "
            "motion) or 'both' (mirror-symmetric about the arch's axis)",
        },
    )
    support_motion: str = field(
        default="translation",
        metadata={
            "choices": ("translation", "rotation", "path"),
            "predates": "translation",
            "doc": "'translation' along support_direction_deg, 'rotation' about the pivot "
            "(rotation_pivot_dx_mm, rotation_pivot_dy_mm) in rotation_sense, or 'path' (path_mm_mrad)",
        },
    )
    support_direction_deg: float = field(
        default=-90.0,
        metadata=number_meta(
            -180,
            180,
            doc="direction of the right support's translation from +x "
            "(deg): -90 settlement, 0 spreading, 180 closing; the "
            "left support mirrors it",
        ),
    )
    rotation_pivot_dx_mm: float = field(
        default=0.0,
        metadata={
            **number_meta(
                -1e5,
                1e5,
                doc="pivot of a rotating right support from its springing intrados point, along x "
                "(mm; the left support mirrors it)",
            ),
            "predates": 0.0,
        },
    )
    rotation_pivot_dy_mm: float = field(
        default=0.0,
        metadata={
            **number_meta(
                -1e5, 1e5, doc="the same pivot's offset along y (mm; e.g. -200 = a pier's base 200 mm below)"
            ),
            "predates": 0.0,
        },
    )
    rotation_sense: str = field(
        default="clockwise",
        metadata={
            "choices": ("clockwise", "counterclockwise"),
            "predates": "clockwise",
            "doc": "sense of the right support's rotation seen from the front (clockwise about a pivot "
            "below it moves the springing outward); the left support turns the other way",
        },
    )
    path_mm_mrad: list = field(
        default_factory=list,
        metadata=table_meta(
            ("dx_mm", "dy_mm", "rotation_mrad"),
            "support_motion 'path': rows [dx_mm, dy_mm, rotation_mrad] of the right support's "
            "springing point displacement and rotation (counter-clockwise), each reached in a straight "
            "line from the previous row (the first from rest); du is the distance along it and the run "
            "stops at its end",
        ),
    )
    max_support_displacement_mm: float = field(
        default=150.0,
        metadata=number_meta(
            0, 10_000, low_open=True, doc="stop without collapse beyond this support displacement (mm, along the path)"
        ),
    )


SECTIONS: dict[str, type] = {
    "geometry": GeometryConfig,
    "material": MaterialConfig,
    "interface": InterfaceConfig,
    "loading": LoadingConfig,
    "numerics": NumericsConfig,
    "imperfections": ImperfectionsConfig,
    "loads": LoadsConfig,
}

# Former parameter names still read from case files, overrides and stored runs: (section, old) -> new.
# parameters of former versions that no longer exist: read from a stored case and dropped, refused
# when a user sets them, with why
RETIRED: dict[tuple[str, str], str] = {
    ("numerics", "runaway_mm"): "the runaway bound is geometric now: numerics.runaway_thickness_ratio "
    "(a block moving this many ring thicknesses), docs/numerics.md",
}
RENAMED: dict[tuple[str, str], str] = {
    ("loading", "settlement_direction_deg"): "support_direction_deg",
    ("loading", "max_settlement_mm"): "max_support_displacement_mm",
    ("numerics", "settlement_rate_mm_per_s"): "support_rate_mm_per_s",
}


def parameter_accepted() -> dict[str, str]:
    """What each parameter accepts, in words, by qualified name (`case.fields.accepted_text`)."""
    return {f"{name}.{f.name}": accepted_text(f.metadata) for name, cls in SECTIONS.items() for f in fields(cls)}


def parameter_docs() -> list[tuple[str, str, str]]:
    """(qualified name, default, description) of every parameter, for `yadearch params`."""
    rows = []
    for section_name, cls in SECTIONS.items():
        for f in fields(cls):
            default = f.default_factory() if f.default_factory is not dataclasses.MISSING else f.default
            rows.append((f"{section_name}.{f.name}", repr(default), f.metadata.get("doc", "")))
    return rows
