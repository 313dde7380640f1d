"""An arch on its piers (real abutments): the case's arch with a pier under each springing, a block
that can slide or overturn on its own base joint, standing on the ground the supports move, as a
measured arch (docs/movements.md, "An arch on its piers")."""

from __future__ import annotations

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.case.mechanics import arch_geometry
from yadearch.case.shape import FACE_POINTS, MEASURED
from yadearch.errors import CaseError
from yadearch.model import units

MAX_PIER_TO_SPAN = 10.0  # a pier taller or wider than this x the span is a tower, not a pier


def pier_case(case: ArchCase, pier_height_mm: float, pier_width_mm: float) -> ArchCase:
    """`case`'s arch on two piers `pier_height_mm` tall, from the springing's intrados corner down, and
    `pier_width_mm` wide at the base, from the span side outward: each pier's span-side face is vertical,
    its outer face runs from its base to the springing joint's extrados corner, and its base is a joint
    on the ground (the support); the case's nominal ring thickness stays (the runaway bound and the
    snap floor scale with it). CaseError in one line for a size outside its range."""
    if case.geometry.piers_mm:
        (height, width), *_ = case.geometry.piers_mm
        raise CaseError(
            f"the case is on piers already ({height:g} mm tall, {width:g} mm wide, geometry.piers_mm): put the "
            "arch without them on piers"
        )
    geometry = arch_geometry(case)
    span_mm = units.to_mm(geometry.span)
    for name, value in (("pier_height_mm", pier_height_mm), ("pier_width_mm", pier_width_mm)):
        if not 0.0 < value <= MAX_PIER_TO_SPAN * span_mm:
            raise CaseError(f"{name} must be in (0, {MAX_PIER_TO_SPAN * span_mm:g}] mm for this arch, got {value!r}")
    ends = [(units.to_mm(j.intrados), units.to_mm(j.extrados)) for j in geometry.joints]
    outward = [ends[0][0][0] - ends[0][1][0], ends[-1][1][0] - ends[-1][0][0]]  # each springing joint's reach out
    least = max(outward)
    if pier_width_mm <= least:
        raise CaseError(
            f"pier_width_mm must be more than {least:.2f} mm for this arch (its springing joints reach that far "
            f"out from the intrados), got {pier_width_mm!r}"
        )
    (left_in, _), (right_in, _) = ends[0], ends[-1]
    left_base = [left_in[0], left_in[1] - pier_height_mm, left_in[0] - pier_width_mm, left_in[1] - pier_height_mm]
    right_base = [right_in[0], right_in[1] - pier_height_mm, right_in[0] + pier_width_mm, right_in[1] - pier_height_mm]
    rows = [left_base] + [[*inner, *outer] for inner, outer in ends] + [right_base]
    return case.with_overrides(
        {
            "geometry.shape": MEASURED,
            "geometry.joint_points_mm": np.asarray(rows, float).tolist(),
            "geometry.n_voussoirs": len(rows) - 1,
            "geometry.piers_mm": [[float(pier_height_mm), float(pier_width_mm)]],
            # a measured voussoir's face corners: its number one further, the left pier first
            **{f"geometry.{face}": [[v + 1, x, y] for v, x, y in getattr(case.geometry, face)] for face in FACE_POINTS},
        }
    )
