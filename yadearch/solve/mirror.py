"""Mirror images of a case about the crown's axis: the problems that are their own (two mirror
mechanisms, either of them the arch's answer, which one a run meets being the numerics' choice) and
the other branch of the rigid march where the problem is not (docs/atlas.md, "Are the answers facts
of the arch?")."""

from __future__ import annotations

from yadearch.case.config import ArchCase
from yadearch.case.held import held_multiplier
from yadearch.case.imperfect import amplitudes
from yadearch.case.shape import MEASURED
from yadearch.model.hinges import mirror_hinge_labels
from yadearch.model.movement import Movement
from yadearch.solve.rigid import rigid_arch

MIRRORED = {"right": "left", "left": "right"}  # the moving support of a case's mirror image


def mirror_image(case: ArchCase) -> ArchCase:
    """`case` with the other support moving the mirrored way: on a symmetric arch, the keystone's
    tie broken toward its other joint (the other branch of the rigid march)."""
    return case.with_overrides({"moving_support": MIRRORED[case.loading.moving_support]})


def _symmetric_arch(case: ArchCase) -> bool:
    """A parametric shape (a surveyed one is not its own mirror image) carrying no live load while its
    support moves (a held load is not mirrored with the movement)."""
    return case.geometry.shape != MEASURED and held_multiplier(case) == 0.0


def has_other_branch(case: ArchCase) -> bool:
    """Whether the rigid march of `case` has a second branch, the keystone's tie broken toward its
    other joint: an odd number of voussoirs without dimension errors (else there is no mirror image),
    one support moving, and a movement that is not its own mirror image (it moves vertically or turns)."""
    if not (case.geometry.n_voussoirs % 2 and case.loading.moving_support in MIRRORED and _symmetric_arch(case)):
        return False
    return amplitudes(case).perfect_dimensions and not rigid_arch(case).movement.mirror_is_itself


def is_own_mirror_image(case: ArchCase, movement: Movement) -> bool:
    """Whether `case` moved by `movement` is its own mirror image: a symmetric arch whose defects are
    their own mirror image, with no live load held, moved the mirror's way up to a rigid translation
    (spreading, closing, both supports alike). Its collapse then has two mirror mechanisms."""
    return _symmetric_arch(case) and amplitudes(case).mirror_symmetric and movement.mirror_is_itself


def mirror_hinges(case: ArchCase, movement: Movement, labels: list[str] | None) -> list[str] | None:
    """The mirror image of the hinges `labels` ("9I", "28E") where `case` is its own mirror image
    (`is_own_mirror_image`), as much the arch's answer as `labels`; None elsewhere, without hinges or
    for a mechanism that is its own mirror image."""
    if not labels or not is_own_mirror_image(case, movement):
        return None
    mirrored = mirror_hinge_labels(labels, case.geometry.n_voussoirs + 1)
    return None if set(mirrored) == set(labels) else mirrored  # a mechanism that is its own mirror image
