"""Rigid-block limit analysis of the arch under a moving support: the kn -> infinity reference of the DEM
(Gilbert's rigid-block LP as in LimitState RING; Portioli & Cascini 2017 for settlements).

The march (`solve.march`) follows the three-hinge mechanism the support drives; at each limit point (no
admissible equilibrium further on) the hinges re-seat at the fixed support where an energy check finds a
new equilibrium (`solve.reseat`), until none does. A DEM run at kn 300 loaded gently passes snaps of
1.1-1.3 mm (docs/validation.md), so every re-seating is survived, however far it moves, unless a block
moves further than `numerics.runaway_thickness_ratio` ring thicknesses first, the static engine's and
the DEM's bound (geometry, not a millimetre constant).
du (du_mm, also du_rigid_mm) is the end of that quasi-static path, du_first_mm its first limit point
whose snap moves a block further than the static engine's and the DEM's snap floor
(`numerics.snap_thickness_ratio` ring thicknesses), or the collapse. Without the snaps the paper arch
would "collapse" at 8.4 mm, where its extrados hinge moves from 33E to 32E. With `kn_N_per_mm3` the
joints beside the hinges fold at their finite-stiffness margin (`solve.compliant`): the DEM's du at that
stiffness.
"""

from __future__ import annotations

import math
import re
import time
from collections.abc import Callable, Sequence
from dataclasses import replace
from typing import Any

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.errors import ArgumentTypeError, CaseError
from yadearch.model import units
from yadearch.model.hinges import mirror_hinge_labels
from yadearch.solve.limit_result import LimitResult, interface_forces
from yadearch.solve.march import March
from yadearch.solve.mirror import has_other_branch, mirror_image
from yadearch.solve.reseat import penetrates
from yadearch.solve.rigid import (
    SIDES,
    LimitError,
    MarchStopped,
    Pivot,
    Placement,
    RigidArch,
    at_rest,
    close_linkage,
    rigid_arch,
)
from yadearch.solve.standing import refuse_compliant_that_cannot_stand, refuse_uncarried_held_load, too_weak

DEFAULT_STEP_MM = 0.5  # support step between equilibrium checks
DEFAULT_TOLERANCE_MM = 1e-3  # width of the bisection bracket that locates a limit
HINGE_LABEL = re.compile(r"(\d+)([IE])")  # a hinge as the results name it: interface (1-based) and side


def limit_analysis(
    case: ArchCase,
    step_mm: float = DEFAULT_STEP_MM,
    tolerance_mm: float = DEFAULT_TOLERANCE_MM,
    max_displacement_mm: float | None = None,
    max_snap_mm: float | None = None,
    mirror: bool = True,
    compliant: bool = False,
    runaway_thicknesses: float | None = None,
    start_hinges: Sequence[str] | str | None = None,
    start_mm: float = 0.0,
    progress: Callable[[float], None] | None = None,
    mirror_progress: Callable[[float], None] | None = None,
) -> LimitResult:
    """The support displacement du_rigid at which the rigid arch of `case` loses its last admissible equilibrium,
    its hinge history and its last admissible state (see the module docstring). A re-seating that moves a block
    further than `runaway_thicknesses` ring thicknesses (default: the case's numerics.runaway_thickness_ratio,
    as the other engines) runs away (the collapse). `max_snap_mm` is for comparing with a DEM run only: a snap
    moving a block further than the run's runaway distance is then the collapse, as the run counts it (default:
    every snap that re-seats is survived; docs/validation.md). On an odd number of voussoirs a movement whose
    mirror image differs (a support that turns or moves vertically) is solved mirrored too
    (`mirror_du_rigid_mm`; `mirror` false: not): the keystone's two joints tie, and each branch has its own
    limit. `compliant`: the joints beside the hinges fold at the margin the case's kn allows
    (`solve.compliant`), giving the du a DEM run of that stiffness should find instead of the rigid one.
    `start_hinges` ("1E 35I 56E"): leave rest on that linkage instead of the LP's (another engine's, to see
    where the rigid blocks take it), refused in one line unless the support drives it with an admissible
    equilibrium; its hinges name this branch, so the mirror image is not solved. `start_mm`: placed that far
    along it from rest (the path before is not followed), for a linkage that becomes admissible only there.
    `progress` is told each admitted support position (mm), `mirror_progress` the mirrored branch's, solved
    after the case's (default: `progress`)."""
    settings = (step_mm, tolerance_mm, max_displacement_mm, max_snap_mm, compliant, runaway_thicknesses, progress)
    if compliant:
        refuse_compliant_that_cannot_stand(case)
    result, arch = _solve(case, *settings, start_hinges, start_mm)
    if start_hinges is not None or not (mirror and has_other_branch(case)):
        return result
    try:
        told = mirror_progress if mirror_progress is not None else progress
        mirrored, _ = _solve(mirror_image(case), *settings[:-1], told)
    except LimitError as exc:
        return replace(result, mirror_collapse_mode=f"failed: {exc}")
    return replace(
        result,
        mirror_du_rigid_mm=mirrored.du_rigid_mm,
        mirror_collapse_mode=mirrored.collapse_mode,
        mirror_collapse_hinges=tuple(mirror_hinge_labels(mirrored.collapse_hinges, arch.n_joints)),
        wall_s=result.wall_s + mirrored.wall_s,
    )


def _solve(
    case: ArchCase,
    step_mm: float,
    tolerance_mm: float,
    max_displacement_mm: float | None,
    max_snap_mm: float | None,
    compliant: bool,
    runaway_thicknesses: float | None,
    progress: Callable[[float], None] | None,
    start_hinges: Sequence[str] | str | None = None,
    start_mm: float = 0.0,
) -> tuple[LimitResult, RigidArch]:
    """`limit_analysis` of `case` as it stands (the keystone's tie broken toward its left joint), and
    the rigid arch it solved."""
    start = time.perf_counter()
    arch = rigid_arch(case)
    if len(arch.passive):
        raise LimitError(
            f"loads.fill_passive_coefficient = {case.loads.fill_passive_coefficient:g}: the rigid march under a "
            "support movement does not take the fill's passive resistance (the load capacity, the static "
            "engine and the DEM do); set it to 0 for the rigid march"
        )
    refuse_uncarried_held_load(case, arch)
    snap_cap = math.inf if max_snap_mm is None else max_snap_mm
    kn = units.stiffness_per_volume(case.interface.kn_N_per_mm3) if compliant else None
    if runaway_thicknesses is None:  # the static engine's and the DEM's bound: one definition of du
        runaway_thicknesses = case.numerics.runaway_thickness_ratio
    if not runaway_thicknesses > 0.0:
        raise ValueError(f"runaway_thicknesses must be positive, got {runaway_thicknesses}")
    runaway = runaway_thicknesses * arch.geometry.thickness
    start_pivots = () if start_hinges is None else named_linkage(start_hinges, arch.n_joints)
    floor_mm = units.to_mm(case.numerics.snap_thickness_ratio * arch.geometry.thickness)  # the engines' snap floor
    march = March(arch, units.mm(step_mm), units.mm(tolerance_mm), runaway, kn, snap_cap, start_pivots, floor_mm)
    if progress is not None:
        march.progress = lambda delta: progress(units.to_mm(delta))
    limit = min(units.mm(max_displacement_mm or case.loading.max_support_displacement_mm), arch.movement.length)
    placed = _check_start(march, start_pivots, units.mm(start_mm), limit) if start_pivots or start_mm else None
    origin = placed if placed is not None else at_rest(arch)
    if not march.admissible(origin):
        raise LimitError(f"the arch admits no equilibrium at rest: {too_weak(case)}")
    last, read_at, mechanism, chain = march.run(limit, origin)
    if read_at is None and last.delta < limit - units.mm(tolerance_mm):
        raise MarchStopped(
            f"the march stopped at {units.to_mm(last.delta):.3f} mm, short of {units.to_mm(limit):g} mm: its "
            f"linkage {' '.join(p.label for p in mechanism.pivots)} can move no further and no limit was read"
        )
    mode, hinges = "none", tuple(p.label for p in mechanism.pivots)
    new: tuple[str, ...] = ()
    if read_at is not None:
        if chain is not None and chain.power < 0 and len(chain.pivots) > 3:
            mode = "snap" if march.snap_collapse_mm is not None else "hinging"
            hinges = tuple(p.label for p in chain.pivots)
            new = tuple(p.label for p in chain.pivots if p not in mechanism.pivots)
        else:
            mode = "sliding" if march.statics(read_at, friction=False).feasible else "hinging"
    forces, reactions = interface_forces(arch, march.statics(last, refine=True))
    use = np.array([f.friction_use for f in forces])
    du = units.to_mm(last.delta) if mode != "none" else None
    return LimitResult(
        name=case.name,
        du_mm=du,
        du_first_mm=None if march.first_limit is None else units.to_mm(march.first_limit),
        du_rigid_mm=du,
        collapse_mode=mode,
        hinge_history=tuple(march.history),
        collapse_hinges=hinges,
        new_at_collapse=new,
        forces=forces,
        reactions_N=reactions,
        max_friction_use=float(use.max()),
        max_friction_interface=int(np.argmax(use)) + 1,
        rotation_rad=tuple(float(r) for r in last.rot),
        shift_mm=tuple((units.to_mm(float(x)), units.to_mm(float(y))) for x, y in last.shift),
        support_direction_deg=case.loading.support_direction_deg,
        snaps=tuple(march.reseated),
        runaway_thicknesses=runaway_thicknesses,
        max_snap_mm=None if math.isinf(snap_cap) else snap_cap,
        snap_collapse_mm=march.snap_collapse_mm,
        snap_floor_mm=floor_mm,
        step_mm=step_mm,
        tolerance_mm=tolerance_mm,
        compliant_kn_N_per_mm3=case.interface.kn_N_per_mm3 if compliant else None,
        compliant_largest_margin_mm=units.to_mm(march.largest_margin) if compliant else None,
        n_lp=march.n_lp,
        wall_s=time.perf_counter() - start,
        start_hinges=tuple(p.label for p in start_pivots) or None,
        start_mm=start_mm if start_pivots else None,
        **_closest_edge(march, hinges),
    ), arch


def named_linkage(labels: Sequence[str] | str, n_joints: int) -> tuple[Pivot, ...]:
    """Three hinges named as the results name them ("1E 35I 56E", or a list of labels), left to right;
    ArgumentTypeError for neither, CaseError unless three distinct interfaces of 1..n_joints, side I or E."""
    is_list = isinstance(labels, (list, tuple)) and all(isinstance(label, str) for label in labels)
    if not (isinstance(labels, str) or is_list):
        raise ArgumentTypeError(
            f"start_hinges must be three hinge labels such as '1E 35I 56E' (a str, or a list of str), got "
            f"{type(labels).__name__} {labels!r:.40}"
        )
    texts = [text for label in ([labels] if isinstance(labels, str) else labels) for text in label.split()]
    matches = [HINGE_LABEL.fullmatch(t.strip().upper()) for t in texts]
    pivots = {
        int(m[1]) - 1: Pivot(int(m[1]) - 1, SIDES.index(m[2])) for m in matches if m and 0 < int(m[1]) <= n_joints
    }
    if len(texts) != 3 or len(pivots) != 3:
        raise CaseError(
            f"start_hinges must be three hinges on distinct interfaces of 1..{n_joints}, each side I or E "
            f"(e.g. '1E 35I 56E'), got {texts!r:.80}"
        )
    return tuple(pivots[j] for j in sorted(pivots))


def _check_start(march: March, pivots: tuple[Pivot, ...], start: float, limit: float) -> Placement | None:
    """Where the march on a named linkage begins: rest, or `start` (m) along it; CaseError in one line
    unless the support drives the arch on it and the rigid arch holds an admissible equilibrium there
    (from rest: at the march's first step, where the march first checks it, so that a linkage a thrust
    line misses by a hair at the very start is still followed)."""
    if not pivots:
        raise CaseError("start_mm places the arch along a named linkage: give start_hinges too")
    if not (math.isfinite(start) and 0.0 <= start < limit):
        raise CaseError(f"start_mm must be in [0, {units.to_mm(limit):g}) mm, got {units.to_mm(start):g}")
    rest, named = at_rest(march.arch), " ".join(p.label for p in pivots)
    placed = close_linkage(march.arch, rest, pivots, start) if start > 0.0 else rest
    probe = march.moved(placed, march.start, march.step) if placed is not None and march.start else None
    where = f"{units.to_mm(start):g} mm along them" if start > 0.0 else f"{units.to_mm(march.step):g} mm from rest"
    span = march.arch.geometry.span
    if (
        placed is None
        or probe is None
        or (start > 0.0 and penetrates(march.arch, rest, placed, start / span))
        or penetrates(march.arch, placed, probe, march.step / span)
    ):
        raise CaseError(
            f"start_hinges {named}: the support cannot move the arch on these hinges ({where}) without "
            "blocks passing through each other (a hinge on the wrong side?)"
        )
    if not march.admissible(probe if start == 0.0 else placed):
        raise CaseError(
            f"start_hinges {named}: the rigid arch has no admissible equilibrium on these hinges {where} "
            "(no thrust line fits them)"
        )
    return placed if start > 0.0 else None


def _closest_edge(march: March, hinges: tuple[str, ...]) -> dict[str, Any]:
    """The nearest approach of a thrust to a hinge side's corner at a joint that never hinged (the
    march's `closest`; a joint that became a hinge reached its corner by design), as LimitResult's fields."""
    hinged = set(hinges) | {record.label for record in march.history}
    kept = {pivot: near for pivot, near in march.closest.items() if pivot.label not in hinged}
    if not kept:
        return {}
    pivot, (distance, delta) = min(kept.items(), key=lambda item: (item[1][0], item[0]))
    return {
        "closest_edge_joint": pivot.label,
        "closest_edge_mm": units.to_mm(distance),
        "closest_edge_at_mm": units.to_mm(delta),
    }
