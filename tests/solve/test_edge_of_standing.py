"""An arch at the edge of standing, the sensitivity study's sample b00006_01 (57 voussoirs, kn 14.5
N/mm3, face bumps s.d. 0.19 mm, tests/data/edge_of_standing.toml): its static self-weight path folds
below full gravity, so the static engine's "cannot stand" is the model's quasi-static answer
(docs/validation-engines.md, "Arches at the edge of standing"; the DEM's self-weight accepts it creeping)."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import REPO

from yadearch.case.config import load_case
from yadearch.solve import banded
from yadearch.solve.gravity_ramp import SELFWEIGHT_FALL
from yadearch.solve.path import path_settings
from yadearch.solve.static_path import StaticLoading
from yadearch.solve.static_state import StaticEngineError
from yadearch.solve.statics import static_arch

CASE = REPO / "tests" / "data" / "edge_of_standing.toml"
GRAVITY_STEP = 0.02  # a fifth of the engine's own load step


@pytest.fixture(scope="module")
def loading():
    case = load_case(CASE)
    arch = static_arch(case)
    return StaticLoading(arch, path_settings(case.numerics, 10.0), 1e-3)


def test_the_self_weight_path_folds_below_full_gravity(loading):
    """Gravity in steps of 0.02 g, each by Newton from the last state with the joints' shear carried
    (the engine's self-weight in finer steps): every state up to 0.82 g is stable, the tangent's
    smallest eigenvalue falls as sqrt(g_fold - g) near it with g_fold between 0.82 and 0.84 g, and no
    stable state follows the fold; the engine's own self-weight refuses the arch in one line."""
    arch, solver = loading.arch, loading.solver
    u = arch.with_supports(arch.at_rest(), 0.0)
    shear = np.zeros(len(arch.table.left))
    eigenvalue = {}
    gravity = GRAVITY_STEP
    first = solver.descend(u, u, shear, SELFWEIGHT_FALL, gravity=gravity)  # untouched joints: no stiffness
    u, shear = first.u, first.joints.forces.shear_force
    while True:
        gravity = round(gravity + GRAVITY_STEP, 6)
        found = solver.newton(u, u, shear, gravity=gravity)
        if found is None or not found.stable():
            break
        eigenvalue[gravity] = banded.smallest_eigenvalue(found.stiffness)
        u, shear = found.u, found.joints.forces.shear_force
    assert max(eigenvalue) == 0.82 and gravity == 0.84
    near = [0.76, 0.78, 0.8, 0.82]
    slope, intercept = np.polyfit(near, [eigenvalue[g] ** 2 for g in near], 1)  # lambda^2 linear: a fold
    assert slope < 0 and 0.82 < -intercept / slope < 0.84
    with pytest.raises(StaticEngineError, match="does not stand under its own weight"):
        loading.selfweight()
