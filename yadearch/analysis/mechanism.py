"""What kind of collapse: sliding joints (Coulomb cap reached and real slip) or a hinge mechanism,
described as the paper does ("asymmetric four-hinge mechanism, E-I-E-E, D at the left support")."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from yadearch.analysis.tracking import HingeTrack, sequence
from yadearch.case.paper import model_values_text
from yadearch.results.check_text import unresolved_warning
from yadearch.results.summary import STATIC, RunSummary
from yadearch.solve.stages import Verdict

CAP_TOLERANCE = 0.05  # |shear| >= (1 - this) tan(phi) |normal| counts as at the Coulomb cap
SLIP_THRESHOLD_MM = 0.2  # tangential slip that is sliding, not elastic shear (ks) deformation
JUMP_FRACTION = 0.5  # a relaxation moving a block this fraction of its increment...
JUMP_FLOOR = 0.1  # ...and at least this fraction of runaway_mm is a jump to another state
NEAR_LIMIT = 0.9  # beyond this fraction of du the path's states move fast (a fold): no jump is judged there
NEAR_BOUND = 0.5  # a jump this fraction of the runaway bound: the bound halved (an invariance check) ends the path
HINGE_COUNT_NAMES = {1: "one", 2: "two", 3: "three", 4: "four", 5: "five", 6: "six"}


@dataclass(frozen=True)
class SlidingJoint:
    """A joint at the Coulomb cap in the final state; slip_mm is None when no snapshot shows it."""

    interface: int
    shear_ratio: float  # |shear| / (tan(phi) |normal|)
    slip_mm: float | None


def slip_during_moves(
    friction: dict, slip_threshold_mm: float = SLIP_THRESHOLD_MM, cap_tolerance: float = CAP_TOLERANCE
) -> str | None:
    """A warning when a run's joint slipped more than `slip_threshold_mm` although no equilibrium
    state brought any joint to its friction cap (summary.json's `friction`): it slid while the
    support moved, so the moves' inertia may be part of the answer (docs/numerics.md), or while the
    joint was open; None otherwise."""
    slip, use = friction.get("max_slip_mm"), friction.get("max_friction_use")
    if slip is None or use is None or slip < slip_threshold_mm or use >= 1.0 - cap_tolerance:
        return None
    return (
        f"interface {friction.get('slip_interface')} slipped {slip:.2f} mm although no equilibrium state "
        f"used more than {use:.2f} of any joint's friction: it slid while the support moved (the moves' "
        "inertia is then part of du: check with a lower numerics.support_acceleration_mm_per_s2) or "
        "while the joint was open"
    )


def friction_limited(summary: RunSummary, cap_tolerance: float = CAP_TOLERANCE) -> str | None:
    """A note when a collapsed run's equilibria brought a joint to its friction cap (summary.json's
    `friction`): the collapse is then limited by sliding there, not by its hinges alone, and the
    engines' slip laws (the DEM's shear spring, the static engine's cap) may part by a few %."""
    use = summary.friction.get("max_friction_use")
    if not summary.collapsed or use is None or use < 1.0 - cap_tolerance:
        return None
    at, slip = summary.friction.get("friction_delta_mm", math.nan), summary.friction.get("max_slip_mm", 0.0)
    return (
        f"interface {summary.friction.get('friction_interface')} reached {use:.3f} of its friction at "
        f"{at:.2f} mm (slip {slip:.2f} mm): "
        "the collapse is limited by sliding there, not by the hinges alone; the engines' slip laws may "
        "part by a few % on such an arch, and rigid blocks call it sliding (`yadearch limit`)"
    )


def near_bound(move_mm: float, runaway_mm: float) -> str | None:
    """The words for a snap that moved a block `move_mm`, at least NEAR_BOUND of the runaway bound
    `runaway_mm` (a shorter bound would have called it the collapse, so du rests on the bound); None
    for a shorter snap. A static run's relaxations and the rigid march's re-seatings alike."""
    if move_mm < NEAR_BOUND * runaway_mm:
        return None
    return (
        f"{move_mm / runaway_mm:.0%} of the runaway bound ({runaway_mm:g} mm): the bound halved would end "
        "the path there, so du rests on numerics.runaway_thickness_ratio"
    )


def relaxation_jump(summary: RunSummary, fraction: float = JUMP_FRACTION, near_limit: float = NEAR_LIMIT) -> str | None:
    """A warning when, short of `near_limit` x du, the relaxation of an accepted increment moved a
    block by at least `fraction` of the increment (and JUMP_FLOOR of the runaway distance; summary.json's
    `relaxations`): the arch did not follow the support but jumped to that state (a snap to another
    branch), so du may depend on `runaway_mm` and on the increments (docs/numerics.md). Close to du
    the equilibrium moves fast with the support (the fold): larger relaxations there are the path's."""
    relaxations = summary.relaxations or {}
    end = summary.du_mm or summary.last_equilibrium_mm
    if not relaxations.get("move_mm") or end is None:
        return None
    runaway_mm = relaxations["runaway_mm"]
    jumps = [
        (move, delta, step)
        for delta, step, move in zip(relaxations["delta_mm"], relaxations["increment_mm"], relaxations["move_mm"])
        if delta <= near_limit * end and move >= max(fraction * step, JUMP_FLOOR * runaway_mm)
    ]
    if not jumps:
        return None
    move, delta, step = max(jumps)
    near = near_bound(move, runaway_mm)
    bound = f"; it is {near}" if near else ""
    return (
        f"the relaxation after the {step:.2f} mm increment to {delta:.2f} mm moved a block {move:.2f} mm "
        f"({len(jumps)} such before {near_limit:g} du): the arch snapped rather than followed its path there "
        f"(survived: du_first_mm and summary.json's snaps mark the snaps, du is where the path ends){bound}"
    )


def snap_floor_near(summary: RunSummary, near: float = NEAR_BOUND, near_limit: float = NEAR_LIMIT) -> str | None:
    """A warning when du_first rests on the snap floor (`relaxations.snap_floor_mm`, the static engine's):
    before it (and short of `near_limit` x du, where the fold's own states move fast) an accepted state
    landed at least `near` of the floor from its prediction, which the floor halved counts as a snap;
    or the snap that sets du_first moved less than the floor / `near`, which the floor doubled does not."""
    relaxations = summary.relaxations or {}
    floor, first = relaxations.get("snap_floor_mm"), summary.du_first_mm
    if floor is None or first is None or summary.du_mm is None:
        return None
    end = min(first, near_limit * summary.du_mm)
    below = [
        (move, delta)
        for delta, move in zip(relaxations["delta_mm"], relaxations["move_mm"])
        if delta < end and near * floor <= move < floor
    ]
    setting = "so du_first rests on numerics.snap_thickness_ratio"
    if below:
        move, delta = max(below)
        return (
            f"the state at {delta:.2f} mm landed {move:.3f} mm from its prediction, {move / floor:.0%} of the snap "
            f"floor ({floor:.3g} mm): the floor halved would count it as a snap before du_first ({first:.2f} mm), "
            f"{setting}"
        )
    snaps = summary.snaps or []
    snap = snaps[0] if snaps and math.isclose(0.5 * sum(snaps[0]["fold_mm"]), first, abs_tol=1e-9) else None
    if snap is not None and snap["move_mm"] < floor / near:
        return (
            f"the snap that sets du_first ({first:.2f} mm) moved a block {snap['move_mm']:.3f} mm, "
            f"{snap['move_mm'] / floor:.1f} times the snap floor ({floor:.3g} mm): the floor doubled would not "
            f"count it, {setting}"
        )
    return None


def collapse_by_timeout(summary: RunSummary) -> str | None:
    """A warning when the path ended where the engine found neither an equilibrium nor a runaway: an
    unresolved run (no du, never a collapse), with the numerics that decide it in the engine that ran."""
    if summary.collapse_verdict != Verdict.TIMEOUT:
        return None
    if summary.engine == STATIC:
        remedy = (
            "the static descent found neither after its retries (docs/theory.md, 'The static engine'); "
            "the DEM (--engine dem) follows the same arch by its dynamics"
        )
    else:
        remedy = "a larger numerics.hold_max_s lets the holds go on longer"
    return f"unresolved: past the last stable state the arch reached neither an equilibrium nor a runaway; {remedy}"


def run_warnings(summary: RunSummary) -> list[str]:
    """The warnings a finished run's summary.json calls for: the paper's model values on another arch,
    slip during the moves, a collapse limited by friction, jumps in the path, a collapse read from a
    timeout, an answer its increments check moved."""
    warnings = (
        model_values_text(summary.paper_model_values) if summary.paper_model_values else None,
        slip_during_moves(summary.friction),
        friction_limited(summary),
        relaxation_jump(summary),
        snap_floor_near(summary),
        collapse_by_timeout(summary),
        unresolved_warning(summary.increments_check, _bracket_width(summary)),
    )
    return [w for w in warnings if w]


def _bracket_width(summary: RunSummary) -> float | None:
    """How wide the run's bracket of du is (mm; None without one)."""
    bracket = summary.du_bracket_mm
    return None if bracket is None or None in bracket else float(bracket[1]) - float(bracket[0])


def sliding_joints(
    normal_N: np.ndarray,
    shear_N: np.ndarray,
    friction_deg: float,
    slip_mm: np.ndarray | None = None,
    cap_tolerance: float = CAP_TOLERANCE,
    slip_threshold_mm: float = SLIP_THRESHOLD_MM,
) -> list[SlidingJoint]:
    """Joints (one state) whose shear force sits at the friction cap and, when the slip is known,
    that slipped more than `slip_threshold_mm` (mm)."""
    mu = math.tan(math.radians(friction_deg))
    normal = np.nan_to_num(np.abs(np.asarray(normal_N, float)))
    shear = np.nan_to_num(np.abs(np.asarray(shear_N, float)))
    ratio = np.divide(shear, mu * normal, out=np.zeros_like(shear), where=normal > 0)
    sliding = []
    for k in np.flatnonzero(ratio >= 1.0 - cap_tolerance):
        slip = None if slip_mm is None else float(slip_mm[k])
        if slip is None or abs(slip) >= slip_threshold_mm:
            sliding.append(SlidingJoint(int(k) + 1, float(ratio[k]), slip))
    return sliding


def _place(interface: int, n_interfaces: int) -> str:
    if interface == 1:
        return "the left support"
    if interface == n_interfaces:
        return "the right support"
    return f"interface {interface}"


def is_symmetric(tracks: list[HingeTrack], n_interfaces: int, tolerance: int = 1) -> bool:
    """True if every hinge has a mirror image (interface k <-> n+2-k, same side) within `tolerance`."""

    def mirrored(t: HingeTrack) -> bool:
        return any(
            o.side == t.side and abs(o.interface - (n_interfaces + 1 - t.interface)) <= tolerance for o in tracks
        )

    return bool(tracks) and all(mirrored(t) for t in tracks)


def describe_mechanism(
    tracks: list[HingeTrack], sliding: list[SlidingJoint], n_interfaces: int, collapsed: bool
) -> str:
    """One line: the collapse mechanism in the paper's words."""
    if sliding:
        where = ", ".join(str(s.interface) for s in sliding)
        text = f"sliding at interface{'s' if len(sliding) > 1 else ''} {where}"
        return text + (f", with hinges {sequence(tracks)}" if tracks else "")
    if not tracks:
        return "no hinges" if collapsed else "no collapse, no hinges"
    count = HINGE_COUNT_NAMES.get(len(tracks), str(len(tracks)))
    symmetry = "symmetric" if is_symmetric(tracks, n_interfaces) else "asymmetric"
    last = tracks[-1]
    where = f", {last.paper_label} at {_place(last.interface, n_interfaces)}" if last.paper_label else ""
    text = f"{symmetry} {count}-hinge mechanism, {sequence(tracks)}{where}"  # the last hinge named by its letter
    return text if collapsed else f"no collapse; {text.replace(' mechanism', ' pattern')}"
