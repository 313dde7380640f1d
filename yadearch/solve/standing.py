"""Whether an arch stands at rest, and why not: rigid blocks under their own weight (`stands`), the
words for an arch that does not stand (`why_not_standing`), and what the rigid march refuses before it
starts (a held load rigid blocks do not carry, a compliant march on joints too soft to stand)."""

from __future__ import annotations

import math

from yadearch.case.config import ArchCase
from yadearch.case.held import HELD_SETTINGS, held_multiplier, unheld
from yadearch.case.shape import MEASURED
from yadearch.errors import CANNOT_STAND, CaseError, YadearchError
from yadearch.solve.limit_lp import solve_statics
from yadearch.solve.rigid import LimitError, RigidArch, at_rest, rigid_arch

FRICTION_MARGIN = 0.9  # rigid blocks that fall with this share of tan(friction) stand by friction alone


def stands(case: ArchCase) -> bool:
    """Whether the undeformed arch admits an equilibrium (thrust line inside, friction enough)."""
    arch = rigid_arch(unheld(case))  # under its own weight (and the fill's), as a run's self-weight
    return solve_statics(arch, at_rest(arch)).feasible


def refuse_uncarried_held_load(case: ArchCase, arch: RigidArch) -> None:
    """CaseError in one line for a held live load larger than the rigid arch's capacity (it stood
    without it): the march would say the arch admits no equilibrium at rest."""
    held = held_multiplier(case)
    if held == 0.0 or solve_statics(arch, at_rest(arch)).feasible or not stands(case):
        return
    from yadearch.solve.load_lp import load_analysis  # a capacity's LP, for this message only

    capacity = load_analysis(unheld(case))
    raise CaseError(
        f"loads.{HELD_SETTINGS[case.loads.live_load]} = {held:g}: rigid blocks do not carry it (they collapse at "
        f"{capacity.multiplier:.4g} {capacity.unit} on {capacity.hinge_labels}: `yadearch loads`); hold less"
    )


def refuse_compliant_that_cannot_stand(case: ArchCase) -> None:
    """LimitError where the static engine finds that joints of the case's kn do not let the arch stand
    under its own weight: the compliant march folds the joints beside its hinges only and ignores the
    whole arch's deformation, so it would give a du that no arch of that stiffness reaches."""
    from yadearch.solve.static_path import StaticLoading  # the compliant model's self-weight, for this check only
    from yadearch.solve.static_state import StaticEngineError

    if not stands(case):  # rigid blocks do not stand either: the march says why, joints apart
        return
    try:
        StaticLoading.of(case).selfweight()
    except StaticEngineError as exc:
        if CANNOT_STAND not in str(exc):
            return  # the static engine's self-weight unresolved: no claim either way
        raise LimitError(
            f"kn_N_per_mm3 = {case.interface.kn_N_per_mm3:g}: the static engine finds that on these joints this arch "
            f"does not stand under its own weight ({why_not_standing(case)}), so the compliant march (which ignores "
            "the whole arch's deformation) has no du here; rigid blocks: `yadearch limit` without --compliant"
        ) from None


def why_not_standing(case: ArchCase) -> str:
    """For the message of an arch that does not stand under its own weight: whether rigid blocks of
    the same shape would (then its joints are too soft for it: the compliance folds the ring) or not
    (then the ring is too thin or the friction too low for its shape, whatever the joints)."""
    try:
        rigid = stands(case)
    except (LimitError, YadearchError):
        return ""
    less = math.degrees(math.atan(FRICTION_MARGIN * math.tan(math.radians(case.material.friction_deg))))
    if rigid and not stands(case.with_overrides({"friction_deg": less})):
        return (
            f"rigid blocks of this shape stand only by friction (with {FRICTION_MARGIN:.0%} of tan(friction_deg) "
            "they do not): joints that slide as they deform carry less than the rigid analysis's; a higher "
            "friction_deg, or joints closer to radial, stand"
        )
    if rigid:
        return (
            f"rigid blocks of this shape stand: its joints at kn {case.interface.kn_N_per_mm3:g} N/mm3 are too "
            "soft for it (their compliance folds the ring); a stiffer kn or a thicker ring stands"
        )
    return f"rigid blocks of this shape do not stand either: {too_weak(case)}"


def too_weak(case: ArchCase) -> str:
    """Why rigid blocks of `case` do not stand, for its message: the ring or the friction, or blocks
    other than a parametric ring's (its piers, a surveyed block) too narrow for the thrust."""
    weak = "the ring is too thin or the friction too low"
    if case.geometry.piers_mm:
        return f"{weak}, or its piers ({case.geometry.piers_mm[0][1]:g} mm wide) too narrow for its thrust"
    return f"{weak}, or a surveyed block too narrow for the thrust" if case.geometry.shape == MEASURED else weak
