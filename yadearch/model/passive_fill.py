"""The fill's passive resistance (pure numpy and numba, SI): where the arch sways into its backfill, the
fill pushes back harder than its at-rest pressure, up to Kp x unit weight x depth (RING's passive
restraint; Gilbert 2007, docs/loads.md "The fill's passive resistance").

Each extrados face under the fill (`model.backfill.fill_faces`) gets a horizontal spring at the point
where its at-rest pressure acts: the face's outward displacement u there from the spring's reference
(the undeformed arch, until the fill yields) mobilises q = (Kp - K) x the face's pressure resultant per
K x min(u / u_p, 1), nothing where it moves away (the at-rest pressure stays), u_p being how far the
face must move for the whole of it. The
rigid-block analysis takes the limit (q anywhere between 0 and its capacity, the spring rigid-plastic);
the static engine and the DEM take the spring, elastic-plastic: a face pushed further than u_p has
compressed the fill for good (`yielded` moves its reference with it, the history each state carries,
as a joint carries its shear), so that moving back its push falls off over u_p instead of returning
along the loading line. Within a step the force is a function of the pose alone (the tangent stays
symmetric)."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numba import njit

from yadearch.model.backfill import Backfill, fill_faces
from yadearch.model.geometry import ArchGeometry
from yadearch.model.joint_tangent import BLOCK_DOFS

BLOCK, ARM_X, ARM_Y, OUTWARD, REFERENCE_X, CAPACITY, STIFFNESS = range(7)  # a spring's columns
SPRING_COLUMNS = 7
YIELDING = 1.0 - 1e-9  # a spring mobilised to this fraction of its capacity is yielding: one a state has
# just yielded (`yielded`) sits on its cap to round-off, and its tangent is the plastic one (pushed on,
# the fill gives) whichever side the last bit falls; its force stays continuous
SpringTangent = Callable[[np.ndarray, float], "np.ndarray | None"]  # poses, lever -> every block's tangent or None


def no_springs() -> np.ndarray:
    """A springs table without springs: a fill that does not resist, or no fill."""
    return np.zeros((0, SPRING_COLUMNS))


def passive_springs(geometry: ArchGeometry, centroids: np.ndarray, fill: Backfill) -> np.ndarray:
    """(k, SPRING_COLUMNS) the fill's passive springs at full gravity (none where it does not resist):
    block, arm from the block's centroid (x, y, unturned), outward sign (+1: the face looks toward +x),
    the point's x in the undeformed arch (the reference, until the fill yields: `yielded`), the capacity (N)
    and the stiffness capacity / u_p (N/m)."""
    if not fill.resists:
        return no_springs()
    extra = fill.passive_coefficient - fill.lateral_coefficient
    rows = []
    for face in fill_faces(geometry, fill):
        capacity = extra * face.mean * face.height
        if capacity == 0.0:
            continue
        arm = face.point - centroids[face.block, :2]
        rows.append(
            (face.block, arm[0], arm[1], -face.inward, face.point[0], capacity, capacity / fill.passive_displacement)
        )
    return np.array(rows, float).reshape(-1, SPRING_COLUMNS)


def spring_points(springs: np.ndarray, centroids: np.ndarray) -> np.ndarray:
    """(k, 2) where the springs act in the undeformed arch whose blocks' centroids are `centroids`."""
    return centroids[springs[:, BLOCK].astype(int), :2] + springs[:, ARM_X : ARM_Y + 1]


def scaled(springs: np.ndarray, share: float) -> np.ndarray:
    """The springs at `share` of full gravity: the fill's pressures, so capacity and stiffness, scale with it."""
    out = springs.copy()
    out[:, CAPACITY] *= share
    out[:, STIFFNESS] *= share
    return out


@njit(cache=True)
def _turned_arm(spring, turn):
    """The spring's arm from its block's centroid turned by `turn` (rad): x, y (m)."""
    c, s = np.cos(turn), np.sin(turn)
    return c * spring[ARM_X] - s * spring[ARM_Y], s * spring[ARM_X] + c * spring[ARM_Y]


@njit(cache=True)
def spring_state(spring, x, turn):
    """One spring on its block at centroid x `x` (m) and rotation `turn` (rad): (force x on the block,
    the turned arm's x and y, the spring's tangent stiffness dq/du)."""
    arm_x, arm_y = _turned_arm(spring, turn)
    outward = spring[OUTWARD]
    pushed = outward * (x + arm_x - spring[REFERENCE_X])  # the face's displacement into the fill
    mobilised = spring[STIFFNESS] * pushed
    if pushed <= 0.0:
        return 0.0, arm_x, arm_y, 0.0
    if mobilised >= YIELDING * spring[CAPACITY]:
        return -outward * min(mobilised, spring[CAPACITY]), arm_x, arm_y, 0.0
    return -outward * mobilised, arm_x, arm_y, spring[STIFFNESS]


@njit(cache=True)
def yielded(springs, poses):
    """The springs after the blocks reach `poses` (n_blocks, 3: x, y, rotation): where a face has pushed
    further than u_p (capacity / stiffness) into the fill, the fill has yielded and the spring's reference
    moves with the face, u_p behind it; elsewhere nothing changes. The force at `poses` is the same
    before and after: this is the history a state hands to the next."""
    out = springs.copy()
    for k in range(springs.shape[0]):
        b = int(springs[k, BLOCK])
        arm_x, _ = _turned_arm(springs[k], poses[b, 2])
        point, outward = poses[b, 0] + arm_x, springs[k, OUTWARD]
        reach = springs[k, CAPACITY] / springs[k, STIFFNESS]
        if outward * (point - springs[k, REFERENCE_X]) > reach:
            out[k, REFERENCE_X] = point - outward * reach
    return out


@njit(cache=True)
def spring_terms(spring, x, turn, lever):
    """One spring's generalised force on its block (x, and moment / `lever`) and its tangent K = -dR/du
    there (xx, x-rotation, rotation-rotation; the rotation's coordinate is the angle x `lever`)."""
    force, arm_x, arm_y, tangent = spring_state(spring, x, turn)
    coupling = -tangent * arm_y / lever
    turning = (arm_x * force + tangent * arm_y * arm_y) / lever**2
    return force, -arm_y * force / lever, tangent, coupling, turning


@njit(cache=True)
def add_passive(residual, stiffness, springs, pos, rot, lever, band):
    """The springs' forces and moments added to the free blocks' residual (generalised: moment / `lever`)
    and their tangent to the band `stiffness` (K = -dR/du; supports, the first and last block, are driven)."""
    last = pos.shape[0] - 1
    for k in range(springs.shape[0]):
        b = int(springs[k, BLOCK])
        if b == 0 or b == last:
            continue
        force, moment, tangent, coupling, turning = spring_terms(springs[k], pos[b, 0], rot[b], lever)
        row = BLOCK_DOFS * (b - 1)
        residual[row] += force
        residual[row + 2] += moment
        stiffness[band, row] += tangent
        stiffness[band - 2, row + 2] += coupling  # K[x, rotation]
        stiffness[band + 2, row] += coupling  # K[rotation, x]
        stiffness[band, row + 2] += turning


@njit(cache=True)
def block_forces(springs, poses):
    """(n_blocks, 3) the springs' force x, force y (none) and moment about each centroid at `poses`
    (n_blocks, 3: x, y, rotation), as the DEM puts them on its bodies every step (compiled whole)."""
    out = np.zeros((poses.shape[0], 3))
    for k in range(springs.shape[0]):
        b = int(springs[k, BLOCK])
        force, moment, _, _, _ = spring_terms(springs[k], poses[b, 0], poses[b, 2], 1.0)
        out[b, 0] += force
        out[b, 2] += moment
    return out


def block_stiffness(springs: np.ndarray, poses: np.ndarray, lever: float) -> np.ndarray:
    """(3 n_blocks, 3 n_blocks) the springs' tangent on every block's x, y and rotation x `lever` (N/m),
    for the DEM's stability test."""
    out = np.zeros((BLOCK_DOFS * poses.shape[0],) * 2)
    for spring in springs:
        b = int(spring[BLOCK])
        _, _, tangent, coupling, turning = spring_terms(spring, poses[b, 0], poses[b, 2], lever)
        x, rotation = BLOCK_DOFS * b, BLOCK_DOFS * b + 2
        out[x, x] += tangent
        out[x, rotation] += coupling
        out[rotation, x] += coupling
        out[rotation, rotation] += turning
    return out
