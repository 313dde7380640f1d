"""The static engine (pure Python, no YADE): its tangent is the exact derivative of its forces, its
dual-number kernel is the DEM's joint law, a single joint follows the no-tension Winkler closed form,
a block slides on an incline at the friction angle, and the paper's arches collapse where the DEM and
the rigid-block limit put them, the descent telling a survived snap from a collapse."""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest
from conftest import REPO, stacked_pairs
from scipy.optimize import brentq

from yadearch.case.config import preset
from yadearch.case.mechanics import runaway_length
from yadearch.errors import RunFolderError
from yadearch.model import units
from yadearch.model.geometry import ArchGeometry, Joint, prism
from yadearch.model.joint_law import JointLaw, joint_forces
from yadearch.model.joint_table import joint_table
from yadearch.model.joint_tangent import joint_tangent
from yadearch.model.movement import Movement
from yadearch.model.passive_fill import SPRING_COLUMNS
from yadearch.results.rundir import is_complete, read_run, read_summary
from yadearch.results.summary import HingeRef
from yadearch.solve.limit import limit_analysis
from yadearch.solve.newton import Solver, SolverSettings, largest_move
from yadearch.solve.path import path_settings
from yadearch.solve.stages import Verdict
from yadearch.solve.static_path import StaticLoading
from yadearch.solve.statics import StaticArch, static_arch
from yadearch.static.simulate import simulate_static

IMPERFECT = {
    "imperfections.face_bump_mm": 0.05,
    "imperfections.face_bump_sd_mm": 0.02,
    "imperfections.edge_radius_mm": 0.5,
    "imperfections.seed": 3,
}
FD_STEP = 1e-11  # m: a 0.3 m coordinate rounds to ~6e-17 m, ~1e-6 of the difference it spans
MM = 1e-3


def _quiet(_line: str) -> None:
    pass


def _loading(case) -> StaticLoading:
    arch = static_arch(case)
    return StaticLoading(
        arch, path_settings(case.numerics, case.loading.max_support_displacement_mm), runaway_length(case)
    )


@pytest.fixture(scope="module", params=["perfect", "imperfect"])
def selfweight(request):
    """The set 2 arch (perfect, or with bumped faces and worn edges on every joint) under its own weight."""
    case = preset("set2") if request.param == "perfect" else preset("set2").with_overrides(IMPERFECT)
    loading = _loading(case)
    return request.param, loading.arch, loading.selfweight()


def _mixed_state(arch: StaticArch, u: np.ndarray, seed: int = 0):
    """`u` with every voussoir nudged (0.3 um, rotations ~4e-5 rad) so that joints open in part, a
    history `u_before` 0.2 um away, and shear forces 0.98 of their Coulomb cap with random signs: the
    joints the motion pushes toward their cap slip, the others stay elastic."""
    rng = np.random.default_rng(seed)
    n = arch.n_blocks
    moved = u.reshape(-1, 3).copy()
    moved[1:-1, 0:2] += rng.normal(0.0, 0.3e-6, (n - 2, 2))
    moved[1:-1, 2] += rng.normal(0.0, 1.0e-6, n - 2)
    before = moved.copy()
    before[1:-1, 0:2] += rng.normal(0.0, 0.2e-6, (n - 2, 2))
    moved, before = moved.ravel(), before.ravel()
    normal = arch.evaluate(moved, moved, np.zeros(len(arch.table.left))).forces.normal_force
    shear = 0.98 * arch.law.tan_friction * normal * rng.choice([-1.0, 1.0], len(normal))
    return moved, before, shear


def test_stiffness_is_the_central_difference_of_the_generalised_forces(selfweight):
    """K = -dF/du of the whole arch (supports included) against central differences of F with steps
    of 1e-11 m, at a state with joints fully closed, partly open, elastic in shear and sliding at
    their Coulomb cap (and, imperfect, every joint through the gapped-overlap branch): within 1e-5 of
    the largest stiffness (the differences' round-off is ~1e-6 of it at that step)."""
    kind, arch, state = selfweight
    u, before, shear = _mixed_state(arch, state.u)
    joints = arch.evaluate(u, before, shear)
    f = joints.forces
    cap = arch.law.tan_friction * f.normal_force
    touching = f.normal_force > 0.0
    sliding = f.plastic_slip > 0.0
    assert touching.all()
    assert sliding.sum() >= 3  # on the cap: the shear row is tan(phi) x the normal row's
    assert (touching & (np.abs(f.shear_force) < 0.999 * cap)).sum() >= 3  # elastic shear
    assert np.allclose(np.abs(f.shear_force[sliding]), cap[sliding], rtol=1e-12, atol=0.0)
    touching_share = f.compressed_length / arch.table.length  # slightly < 1 closed: its faces slipped
    assert (touching_share < 0.99).sum() >= 3  # partly open
    if kind == "perfect":
        assert (touching_share > 1.0 - 1e-4).sum() >= 3  # and fully closed joints
    else:
        assert arch.table.imperfect.all()
    stiffness = arch.stiffness(joints)
    differences = np.empty_like(stiffness)
    for k in range(len(u)):
        up, down = u.copy(), u.copy()
        up[k] += FD_STEP
        down[k] -= FD_STEP
        forward = arch.generalised_forces(arch.evaluate(up, before, shear))
        backward = arch.generalised_forces(arch.evaluate(down, before, shear))
        differences[:, k] = -(forward - backward) / (2.0 * FD_STEP)
    scale = float(np.abs(stiffness).max())
    assert float(np.abs(differences - stiffness).max()) <= 1e-5 * scale


def test_dual_kernel_gives_the_dem_kernels_forces(selfweight):
    """The dual-number kernel is the DEM's joint law term for term: with velocity x dt = the motion
    since the `_before` state, every output of `joint_forces` (normal and shear force, point, touching
    length, plastic slip, blocks' forces and torques) equals `joint_tangent`'s to 1e-12 relative."""
    _, arch, state = selfweight
    u, before, shear = _mixed_state(arch, state.u, seed=1)
    pos, rot = arch.poses(u)
    pos_before, rot_before = arch.poses(before)
    pos, rot = np.ascontiguousarray(pos), np.ascontiguousarray(rot)
    pos_before, rot_before = np.ascontiguousarray(pos_before), np.ascontiguousarray(rot_before)
    dual = joint_tangent(arch.table, arch.law, pos, rot, pos_before, rot_before, shear).forces
    dem = joint_forces(arch.table, arch.law, pos, rot, pos - pos_before, rot - rot_before, shear, 1.0)
    assert (dem.plastic_slip > 0.0).any() and (dem.normal_force > 0.0).all()
    for name in (
        "normal_force",
        "shear_force",
        "point",
        "compressed_length",
        "plastic_slip",
        "block_force",
        "block_torque",
    ):
        expected, got = getattr(dem, name), getattr(dual, name)
        scale = float(np.nanmax(np.abs(expected)))
        assert np.allclose(got, expected, rtol=0.0, atol=1e-12 * scale, equal_nan=True), name


# ---- a single joint: the no-tension Winkler moment-rotation ------------------------------------------
KN, KS, TAN_PHI = 5.2e9, 2.6e9, math.tan(math.radians(41.2))  # set 2's joints (SI)
JOINT, HEIGHT, DEPTH = 0.024, 0.02, 0.12  # the paper's joint length and depth (m)
AXIAL = 12.0  # N: about the paper arch's thrust


def _turned_joint(theta: float, closure: float) -> tuple[float, float, float]:
    """A block turned by `theta` about the middle of its joint face and pressed `closure` into a fixed
    one: the joint's normal force, its moment about the joint's middle (positive against the turn)
    and its touching length."""
    geometry = stacked_pairs([0.0], JOINT, HEIGHT, DEPTH)
    centroids = np.array([block.mean(axis=0) for block in geometry.blocks])
    table = joint_table(geometry, centroids)
    pos = centroids[:, :2].copy()
    c, s = math.cos(theta), math.sin(theta)
    x, y = pos[1]
    pos[1] = (c * x - s * y, s * x + c * y - closure)
    forces = joint_forces(
        table,
        JointLaw(KN, KS, TAN_PHI, DEPTH),
        pos,
        np.array([0.0, theta]),
        np.zeros((2, 2)),
        np.zeros(2),
        np.zeros(1),
        1.0,
    )
    middle = np.array([0.0, -0.5 * closure])  # between the two faces' middles
    arm, force = pos[1] - middle, forces.block_force[1]
    moment = forces.block_torque[1] + arm[0] * force[1] - arm[1] * force[0]
    return float(forces.normal_force[0]), -float(moment), float(forces.compressed_length[0])


@pytest.mark.parametrize("ratio", [0.3, 0.9, 1.1, 3.0, 10.0])
def test_joint_moment_rotation_is_the_no_tension_winkler_closed_form(ratio):
    """Under a fixed normal force N a joint of length L, depth d and stiffness kn turned by theta
    carries M = kn d L^3 theta / 12 while closed (theta <= 2N/(kn d L^2): the resultant within the
    kern), then, open, a triangle of pressure over c = sqrt(2N/(kn d theta)) with M = N (L/2 - c/3).
    The closure giving N is solved for; M and the touching length within 1e-6 (the joint law's finite
    rotation differs from the closed form by ~theta^2 ~ 1e-7 at 10 x the opening rotation)."""
    opening = 2.0 * AXIAL / (KN * DEPTH * JOINT**2)  # 6.7e-5 rad
    theta = ratio * opening
    closure = brentq(
        lambda z: _turned_joint(theta, z)[0] - AXIAL,
        -0.5 * theta * JOINT,
        AXIAL / (KN * DEPTH * JOINT) + theta * JOINT,
        xtol=1e-22,
        rtol=1e-15,
        maxiter=500,
    )
    normal, moment, touching = _turned_joint(theta, closure)
    assert normal == pytest.approx(AXIAL, rel=1e-9)
    if theta <= opening:
        assert moment == pytest.approx(KN * DEPTH * JOINT**3 * theta / 12.0, rel=1e-6)
        assert touching == pytest.approx(JOINT, rel=1e-6)
    else:
        contact = math.sqrt(2.0 * AXIAL / (KN * DEPTH * theta))
        assert moment == pytest.approx(AXIAL * (JOINT / 2.0 - contact / 3.0), rel=1e-6)
        assert touching == pytest.approx(contact, rel=1e-6)


# ---- a block on an inclined joint -----------------------------------------------------------------
FRICTION = math.radians(41.2)
SLIDER = (0.05, 0.02, 0.1)  # width along the joint, height, depth (m)


def _inclines(alpha: float) -> StaticArch:
    """Two blocks of 50 x 20 mm (depth 100 mm), each resting on a fixed base along a joint inclined by
    `alpha`: blocks 0 (base) and 1 (block) on the left, 2 (block) and 3 (base) 0.2 m to the right, so
    that the second joint is numbered from the block to the base (normal pointing down, handedness
    -1). Two free blocks, since the static engine frees blocks 1..n-2 and `solve.banded.general`
    cannot store a matrix of 2 to 4 rows (a single free block's 3 x 3 tangent)."""
    along = np.array([math.cos(alpha), math.sin(alpha)])
    normal = np.array([-math.sin(alpha), math.cos(alpha)])
    width, height, depth = SLIDER
    outlines, joints = [], []
    for k, x in enumerate((0.0, 0.2)):
        a, b = np.array([x, 0.0]) - 0.5 * width * along, np.array([x, 0.0]) + 0.5 * width * along
        base = [a - height * normal, b - height * normal, b, a]
        block = [a, b, b + height * normal, a + height * normal]
        outlines += [base, block] if k == 0 else [block, base]
        joints.append(Joint(k + 1, 0, 1, a, b, normal) if k == 0 else Joint(k + 1, 2, 3, a, b, -normal))
    geometry = ArchGeometry(
        [prism(o, depth) for o in outlines],
        joints,
        thickness=width,
        depth=depth,
        span=0.2 + width,
        rise=height,
        voussoir_width=width,
        longest_joint=width,
    )
    centroids = np.array([np.mean(o, axis=0) for o in outlines])
    weight = np.array([0.0, 1.0, 1.0, 0.0]) * 1640.0 * 9.81 * width * height * depth
    return StaticArch(
        geometry,
        joint_table(geometry, centroids, None),
        JointLaw(KN, KS, math.tan(FRICTION), depth),
        weight,
        centroids,
        Movement(left=None, right=None),
        None,
        np.zeros((len(weight), 4)),  # no live load
        np.zeros((len(weight), 4)),  # no backfill
        np.zeros((0, SPRING_COLUMNS)),  # nor its passive resistance
    )


def _rows(local: np.ndarray, normal: np.ndarray, along: np.ndarray, handedness: float, n: float, t: float):
    """The derivatives of a joint's normal and shear force from its local tangent (the rows of its
    force on the right block, F = N n + T e): n and e turn with the blocks' mean rotation phi (e turns
    into h n, n into -h e), so dN = n.dF - h T dphi and dT = e.dF + h N dphi."""
    d_phi = np.array([0.0, 0.0, 0.5, 0.0, 0.0, 0.5])
    d_force = local[3:5, :]
    return normal @ d_force - handedness * t * d_phi, along @ d_force + handedness * n * d_phi


@pytest.mark.parametrize("alpha_deg", [20.0, 40.2, 42.2, 50.0])
def test_block_on_an_incline_slides_at_the_friction_angle(alpha_deg):
    """The descent from the blocks just touching their bases: below phi = 41.2 deg a stable
    equilibrium where each joint carries its block's weight (1e-8) with |T| / N = tan(alpha) (1e-5:
    a block's tilt of ~1e-6 rad mixes N and T), touches over the length the resultant's eccentricity
    leaves (1e-5) and has that length's elastic shear stiffness ks d c (1e-4); above it no
    equilibrium: the blocks slide straight down the slope the runaway distance with |T| = tan(phi) N,
    and the tangent's shear row is then tan(phi) times its normal row."""
    alpha = math.radians(alpha_deg)
    arch = _inclines(alpha)
    start = arch.at_rest()
    found = Solver(arch, SolverSettings()).descend(start, start, np.zeros(2), runaway=MM)
    f = found.joints.forces
    along = np.array([math.cos(alpha), math.sin(alpha)])
    turned = found.u.reshape(-1, 3)[:, 2] / arch.length
    if alpha < FRICTION:
        assert found.verdict == Verdict.STABLE and found.stable()
    else:
        assert found.verdict == Verdict.RUNAWAY
    for j, block in enumerate((1, 2)):
        n, t = float(f.normal_force[j]), float(f.shear_force[j])
        turn = 0.5 * float(turned[block])  # the joint's mean direction: half the block's turn (bases fixed)
        rotate = np.array([[math.cos(turn), -math.sin(turn)], [math.sin(turn), math.cos(turn)]])
        h = float(arch.table.handedness[j])
        d_normal, d_shear = _rows(found.joints.local[j], rotate @ arch.table.normal0[j], rotate @ along, h, n, t)
        if alpha < FRICTION:
            assert f.block_force[block] == pytest.approx([0.0, arch.weight[block]], abs=1e-8 * arch.weight[block])
            assert abs(t) / n == pytest.approx(math.tan(alpha), rel=1e-5)
            assert f.plastic_slip[j] == 0.0
            # the weight's line through the centroid meets the joint (h/2) tan(alpha) downhill of its
            # middle: past the kern (L/6, from 39.8 deg) the joint opens to 3 (L/2 - e)
            eccentricity = 0.5 * SLIDER[1] * math.tan(alpha)
            touching = min(SLIDER[0], 3.0 * (0.5 * SLIDER[0] - eccentricity))
            assert f.compressed_length[j] == pytest.approx(touching, rel=1e-5)
            # sliding the joint's right face along it meets the touching length's shear stiffness
            assert -(d_shear[3:5] @ (rotate @ along)) == pytest.approx(KS * SLIDER[2] * touching, rel=1e-4)
        else:
            assert abs(t) == pytest.approx(math.tan(FRICTION) * n, rel=1e-12) and f.plastic_slip[j] > 0.0
            moved = (found.u - start).reshape(-1, 3)[block, 0:2]
            assert moved @ along < -0.999 * np.linalg.norm(moved)  # straight down the slope
            assert d_shear == pytest.approx(
                math.copysign(math.tan(FRICTION), t) * d_normal, abs=1e-9 * float(np.abs(d_normal).max())
            )
    if alpha >= FRICTION:
        assert found.moved >= MM


# ---- the paper's arches ----------------------------------------------------------------------------
def _labels(hinges: tuple[HingeRef, ...]) -> list[str]:
    return [h.label for h in hinges]


@pytest.mark.parametrize("name", ["set1", "set2"])
def test_static_path_of_the_paper_arch_meets_the_dem(name, tmp_path):
    """The static engine's whole run of the paper's arch against the DEM's committed run
    (reports/NAME/summary.json): du within 1 %; the same four hinges at collapse, the crown hinge of
    set 1 (kn 0.25, spread over three joints in both) within one interface, inside the DEM's spread;
    under self-weight the supports' vertical reactions carry the arch's weight (1e-6) and their
    horizontal reactions cancel, the thrust within 2 % of the DEM's (whose holds end at an unbalanced
    force of a few 1e-4); every accepted state has a positive definite tangent stiffness."""
    dem = read_summary(REPO / "reports" / name)
    summary = simulate_static(preset(name), tmp_path / name, log=_quiet)
    assert summary.collapsed and summary.collapse_verdict == Verdict.RUNAWAY
    assert summary.du_mm == pytest.approx(dem.du_mm, rel=0.01)
    ours, theirs = summary.hinges_at_collapse, dem.hinges_at_collapse
    if name == "set2":
        assert _labels(ours) == _labels(theirs) == ["1E", "9I", "29E", "56E"]
    else:
        assert [h.side for h in ours] == [h.side for h in theirs]
        assert all(abs(a.interface - b.interface) <= 1 for a, b in zip(ours, theirs))
        spread = {d["interface"]: d["interfaces"] for d in dem.hinges_detail}
        assert all(a.interface in spread[b.interface] for a, b in zip(ours, theirs))
    weight = summary.selfweight["arch_weight_N"]
    assert weight == pytest.approx(dem.selfweight["arch_weight_N"], rel=1e-9)
    assert summary.selfweight["vertical_reaction_sum_N"] == pytest.approx(weight, rel=1e-6)
    assert abs(summary.selfweight["horizontal_reaction_sum_N"]) <= 1e-6 * weight
    assert summary.selfweight["thrust_N"] == pytest.approx(dem.selfweight["thrust_N"], rel=0.02)
    with (tmp_path / name / "series.csv").open() as f:
        rows = [r for r in csv.DictReader(f) if r["stage"] == "equilibrium"]
    assert len(rows) == summary.equilibria >= 10
    assert all(float(r["min_stiffness_N_per_m"]) > 0.0 for r in rows)


@pytest.fixture(scope="module")
def coarse(tmp_path_factory):
    """The paper's geometry in 15 voussoirs: the rigid limit, and static runs at kn 300 and 1000 N/mm3."""
    case = preset("set2").with_overrides({"geometry.n_voussoirs": 15})
    root = tmp_path_factory.mktemp("coarse")
    runs = {kn: simulate_static(case.replace(kn_N_per_mm3=kn), root / f"kn{kn}", log=_quiet) for kn in (300, 1000)}
    return limit_analysis(case), runs


def test_stiff_joints_approach_the_rigid_limit(coarse):
    """kn -> infinity is the rigid-block limit: at kn 1000 N/mm3 the static du is within 3 % of the
    rigid du (106.82 mm) on the same four hinges (each within one interface); softer joints fold
    earlier: du at kn 300 < du at kn 1000 < the rigid du."""
    rigid, runs = coarse
    stiff, soft = runs[1000], runs[300]
    assert rigid.collapse_mode == "hinging"
    assert stiff.du_mm == pytest.approx(rigid.du_rigid_mm, rel=0.03)
    ours = _labels(stiff.hinges_at_collapse)
    assert len(ours) == len(rigid.collapse_hinges) == 4
    for a, b in zip(ours, rigid.collapse_hinges):
        assert a[-1] == b[-1] and abs(int(a[:-1]) - int(b[:-1])) <= 1
    assert soft.du_mm < stiff.du_mm < rigid.du_rigid_mm


def test_a_run_that_keeps_only_its_summary_computes_the_same(coarse, tmp_path):
    """numerics.run_files = 'summary' changes what the folder keeps, not what the run computes: du and
    the hinges of the full run to the bit, a complete folder of case.toml and summary.json only, whose
    tables a reader is refused in one line."""
    case = preset("set2").with_overrides({"geometry.n_voussoirs": 15, "numerics.run_files": "summary"})
    lean = simulate_static(case.replace(kn_N_per_mm3=300), tmp_path / "lean", log=_quiet)
    full = coarse[1][300]
    assert lean.du_mm == full.du_mm and lean.hinges_at_collapse == full.hinges_at_collapse
    assert sorted(p.name for p in (tmp_path / "lean").iterdir()) == ["case.toml", "summary.json"]
    assert is_complete(tmp_path / "lean")
    with pytest.raises(RunFolderError, match="kept only its summary"):
        read_run(tmp_path / "lean")


@pytest.fixture(scope="module")
def set2_path():
    """Set 2 followed to collapse by the static engine's oracle."""
    loading = _loading(preset("set2"))
    loading.selfweight()
    return loading, loading.follow()


def test_increments_either_side_of_du_are_stable_then_runaway(set2_path):
    """From the last accepted state (du's lower bracket end, 87.95 mm) a support a quarter of the way
    to the bracket's upper end finds a stable equilibrium within a few um of its prediction, and the
    upper end itself (0.08 mm further) runs away: no equilibrium."""
    loading, path = set2_path
    assert path.collapsed and path.upper - path.lower <= units.mm(0.1)
    assert loading.accepted[-1].lam == path.lower
    below = path.lower + 0.25 * (path.upper - path.lower)
    assert loading.try_increment(below) == Verdict.STABLE
    loading.accept()
    reached = loading.accepted[-1]
    assert reached.lam == below and reached.move < 0.01 * MM and reached.min_stiffness > 0.0
    loading.discard()  # the path's states stay as they were
    assert loading.accepted[-1].lam == path.lower
    assert loading.try_increment(path.upper) == Verdict.RUNAWAY
    assert loading.failures[path.upper].moved >= units.mm(1.0)


@pytest.mark.parametrize("block", [9, 28, 45])
def test_descent_survives_a_kick_but_not_the_state_past_du(set2_path, block):
    """Kick one voussoir 0.05 mm down in the last equilibrium before collapse (and half-way along the
    path): the descent brings the arch back to the very same equilibrium (within 1 um, far inside the
    1 mm runaway), a snap survived; with the support past du the same descent runs away."""
    loading, path = set2_path
    for index in (len(loading.accepted) - 1, len(loading.accepted) // 2):
        state, before = loading.accepted[index], loading.accepted[index - 1]
        kicked = state.u.copy()
        kicked[3 * block + 1] -= 0.05 * MM
        found = loading.solver.descend(kicked, before.u, before.forces.shear_force, runaway=MM)
        assert found.verdict == Verdict.STABLE and found.stable()
        assert largest_move(found.u, state.u) < 1e-6
    base = loading.accepted[-1]
    past = loading.arch.with_supports(base.u, path.upper)
    found = loading.solver.descend(past, base.u, base.forces.shear_force, runaway=MM)
    assert found.verdict == Verdict.RUNAWAY and found.moved >= MM


WEDGED_ARCH = REPO / "tests/data/wedged_arch"  # face angles s.d. 8 mrad: the case and a DEM run's self-weight state


def test_self_weight_of_a_wedged_arch_is_the_dems_equilibrium():
    """Face angles of 8 mrad make joints that close under the self-weight while they slide: with the
    shear carried from load step to load step the static engine stands the arch in a stable
    equilibrium within 0.25 mm of the DEM's (counting each step's sliding from the blocks at rest, it
    found none: a block 1.4 mm away at 0.9 g, no equilibrium at full gravity)."""
    import json

    from yadearch.case.config import load_case
    from yadearch.solve.banded import smallest_eigenvalue

    case = load_case(WEDGED_ARCH / "case.toml")
    arch = static_arch(case)
    loading = StaticLoading(arch, path_settings(case.numerics, 150.0), runaway_length(case))
    state = loading.selfweight()
    dem = json.loads((WEDGED_ARCH / "selfweight.json").read_text())
    dem_u = np.column_stack([np.array(dem["pos_m"])[:, :2], np.array(dem["rot_rad"]) * arch.length]).ravel()
    assert largest_move(state.u, dem_u) < units.mm(0.25)
    weight = float(np.abs(arch.loads()).sum())
    assert state.residual < 1e-6 * weight
    _, _, stiffness = loading.solver.state(state.u, state.u, state.forces.shear_force)
    assert smallest_eigenvalue(stiffness) > 0.0
