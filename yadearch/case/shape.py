"""The arch of a case's [geometry] (pure): its intrados curve, the checks that make a buildable arch,
each refused in one line naming the parameter, its value and what is accepted, and its SI blocks."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from yadearch.case.sections import GeometryConfig
from yadearch.errors import CaseError
from yadearch.model import units
from yadearch.model.geometry import (
    ArchGeometry,
    FacePoints,
    NotConvexError,
    arch_from_joints,
    arch_on_intrados,
    segmental_arch,
)
from yadearch.model.intrados import (
    MAX_RISE_OVER_SPAN,
    HalfEllipse,
    Intrados,
    circular,
    joint_obliquity_deg,
    pointed,
    three_centred,
)

MEASURED = "measured"  # geometry.shape of a surveyed arch (geometry.joint_points_mm)
MIN_MEASURED_JOINTS = 3  # two voussoirs at least
PIERS = "piers_mm"  # the piers a measured arch was put on (`case.piers`), recorded
FACE_POINTS = ("intrados_points_mm", "extrados_points_mm")  # a measured voussoir's corners between its joints
SIZES = {  # the [geometry] sizes each shape reads; thickness, depth, voussoirs and joints: every shape's
    "segmental": ("internal_radius_mm", "embrace_deg"),
    "pointed": ("span_mm", "pointed_radius_over_span"),
    "elliptical": ("span_mm", "rise_mm"),
    "three_centred": ("span_mm", "rise_mm"),
    MEASURED: ("joint_points_mm", *FACE_POINTS),
}
SURVEYED = {  # a surveyed arch's [geometry] values its survey sets, and how
    "thickness_mm": "its joints' mean length",
    "joint_orientation": "where its surveyed joints lie",
}
MIN_JOINT_ANGLE_DEG = 20.0  # a joint nearer the intrados tangent makes a sliver voussoir (joint > 2.9 t)

INTRADOS: dict[str, Callable[[GeometryConfig], Intrados]] = {
    "segmental": lambda g: circular(units.mm(g.internal_radius_mm), units.radians(g.embrace_deg)),
    "pointed": lambda g: pointed(units.mm(g.span_mm), g.pointed_radius_over_span),
    "elliptical": lambda g: HalfEllipse(units.mm(g.span_mm), units.mm(g.rise_mm)),
    "three_centred": lambda g: three_centred(units.mm(g.span_mm), units.mm(g.rise_mm)),
}
SIZED_BY = {
    "segmental": "geometry.internal_radius_mm",
    "pointed": "geometry.span_mm, pointed_radius_over_span",
    "elliptical": "geometry.span_mm, rise_mm",
    "three_centred": "geometry.span_mm, rise_mm",
}


def checked_intrados(g: GeometryConfig) -> Intrados:
    """The intrados of `g` (m), once the rise fits the span, the ring is thinner than the intrados's
    tightest radius and every joint crosses the ring at MIN_JOINT_ANGLE_DEG or more; else CaseError."""
    half_span = MAX_RISE_OVER_SPAN * g.span_mm
    rise, half_span_m = units.mm(g.rise_mm), MAX_RISE_OVER_SPAN * units.mm(g.span_mm)  # as the builders
    # compare them (m): a rise a rounding below half the span in mm may reach it in metres
    if g.shape == "elliptical" and rise > half_span_m:
        raise CaseError(
            f"geometry.rise_mm = {g.rise_mm:g} must be at most {half_span:g} mm (half of "
            f"geometry.span_mm = {g.span_mm:g}) for an elliptical arch"
        )
    if g.shape == "three_centred" and rise >= half_span_m:
        raise CaseError(
            f"geometry.rise_mm = {g.rise_mm:g} must be below {half_span:g} mm (half of "
            f"geometry.span_mm = {g.span_mm:g}) for a three-centred arch"
        )
    intrados = INTRADOS[g.shape](g)
    tightest_mm = units.to_mm(intrados.min_radius)
    if g.thickness_mm >= tightest_mm:
        raise CaseError(
            f"geometry.thickness_mm = {g.thickness_mm:g} must be below {tightest_mm:.6g} mm, the "
            f"smallest radius of curvature of this {g.shape} intrados ({SIZED_BY[g.shape]})"
        )
    angles = joint_obliquity_deg(intrados, g.n_voussoirs, g.joint_orientation)
    worst = int(np.argmin(angles))
    if angles[worst] < MIN_JOINT_ANGLE_DEG:
        raise CaseError(
            f"geometry.joint_orientation = {g.joint_orientation!r} makes interface {worst + 1} "
            f"meet the intrados at {angles[worst]:.3g} deg; joints must be at least "
            f"{MIN_JOINT_ANGLE_DEG:g} deg off its tangent ('normal' joints are at 90)"
        )
    return intrados


def build_arch(g: GeometryConfig) -> ArchGeometry:
    """The SI geometry of `g`; CaseError if it is not a buildable arch. The segmental arch with normal
    (= radial) joints is the paper's construction, bit for bit."""
    if g.shape == MEASURED:
        return measured_arch(g)
    given = [name for name in (*FACE_POINTS, PIERS) if getattr(g, name)]
    if given:
        raise CaseError(f"geometry.{given[0]} is for shape 'measured' only, got shape {g.shape!r}")
    intrados = checked_intrados(g)
    thickness, depth, support = units.mm(g.thickness_mm), units.mm(g.depth_mm), units.mm(g.support_length_mm)
    try:
        if g.shape == "segmental" and g.joint_orientation != "vertical":
            return segmental_arch(
                g.n_voussoirs, g.embrace_deg, units.mm(g.internal_radius_mm), thickness, depth, support
            )
        return arch_on_intrados(intrados, g.n_voussoirs, g.joint_orientation, thickness, depth, support)
    except ValueError as exc:
        raise CaseError(f"the arch cannot be built: {exc}") from None


def measured_arch(g: GeometryConfig) -> ArchGeometry:
    """The arch of surveyed joints (`joint_points_mm`, left to right): its voussoirs between them, its
    span and rise from the intrados corners; CaseError naming what is wrong."""
    rows = np.asarray(g.joint_points_mm, float)
    if len(rows) < MIN_MEASURED_JOINTS:
        raise CaseError(
            f"geometry.joint_points_mm must have at least {MIN_MEASURED_JOINTS} joints (rows) for shape "
            f"'measured', got {len(rows)}"
        )
    if g.n_voussoirs != len(rows) - 1:
        raise CaseError(
            f"geometry.n_voussoirs must be {len(rows) - 1} for {len(rows)} measured joints (one fewer), "
            f"got {g.n_voussoirs}"
        )
    points = units.mm(rows)
    intrados, extrados = points[:, 0:2], points[:, 2:4]
    backward = np.flatnonzero(np.diff(intrados[:, 0]) < 0.0)  # equal: a pier's vertical face
    if backward.size:
        raise CaseError(
            f"geometry.joint_points_mm: joint {backward[0] + 2}'s intrados corner is left of joint "
            f"{backward[0] + 1}'s; give the joints left to right"
        )
    springing = 0.5 * (intrados[0, 1] + intrados[-1, 1])
    faces = face_points(g)
    try:
        return arch_from_joints(
            list(zip(intrados, extrados)),
            units.mm(g.depth_mm),
            units.mm(g.support_length_mm),
            thickness=units.mm(g.thickness_mm),  # the nominal ring thickness (the joints' mean, `ya.measured_case`)
            span=float(intrados[-1, 0] - intrados[0, 0]),
            rise=float(intrados[:, 1].max() - springing),
            faces=faces,
        )
    except ValueError as exc:
        if isinstance(exc, NotConvexError) and exc.face_corners:
            raise CaseError(
                f"geometry.{' / '.join(FACE_POINTS)}: {exc} (each face's corners left to right, between its "
                "joints' corners, the voussoir convex)"
            ) from None
        raise CaseError(
            f"geometry.joint_points_mm: {exc} (is each row [x, y] of the intrados corner then of the extrados "
            "corner, the extrados above?)"
        ) from None


def face_points(g: GeometryConfig) -> dict[int, FacePoints]:
    """The measured voussoirs' corners between their joints (m), by voussoir number (1..n): the rows of
    `intrados_points_mm` and `extrados_points_mm`, in the order given; CaseError for a row that names
    no voussoir of the arch."""
    by_face = []
    for name in FACE_POINTS:
        rows = np.asarray(getattr(g, name), float).reshape(-1, 3)
        wrong = [v for v in rows[:, 0] if v != int(v) or not 1 <= v <= g.n_voussoirs]
        if wrong:
            raise CaseError(f"geometry.{name}: voussoir {wrong[0]:g} must be a whole number from 1 to {g.n_voussoirs}")
        by_face.append({int(v): units.mm(rows[rows[:, 0] == v, 1:3]) for v in np.unique(rows[:, 0])})
    inner, outer = by_face
    none = np.zeros((0, 2))
    return {v: FacePoints(inner.get(v, none), outer.get(v, none)) for v in sorted(set(inner) | set(outer))}


def refuse_unread_sizes(shape: str, given: set[str]) -> None:
    """CaseError in one line for a size `given` (a [geometry] key changed by hand) that `shape` does not
    read: `span_mm` on a segmental arch built the paper's arch unchanged, silently; on a surveyed arch
    (not being surveyed: its shape unchanged) the thickness and the joints' orientation its survey
    sets (the thickness, the joints' mean length, scales its runaway bound and snap floor)."""
    if shape == MEASURED and not given & {"shape", "joint_points_mm"}:  # not a survey being made
        surveyed = sorted(given & set(SURVEYED))
        if surveyed:
            raise CaseError(
                f"geometry.{surveyed[0]} of a surveyed arch is {SURVEYED[surveyed[0]]}, not set by hand; survey "
                "it again (`yadearch survey`) to change it, or drop it"
            )
    reads = SIZES.get(shape, ())
    for name in sorted(given):
        if any(name in sizes for sizes in SIZES.values()) and name not in reads:
            raise CaseError(
                f"geometry.{name} is not read by shape {shape!r}, which is sized by {', '.join(reads)}; "
                "set geometry.shape too, or drop it"
            )
