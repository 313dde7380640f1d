"""A live load grown to collapse by the static engine (solve/load_path.py): its tangent with the load's
own stiffness, equilibrium of the supports with the weights and the load at every state, stiff joints
leading to the rigid-block capacity, invariance of the capacity to the path's increments, and the
residual capacity of a settled arch (docs/loads.md)."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from conftest import differenced_tangent

from yadearch.case.config import preset
from yadearch.case.mechanics import runaway_length
from yadearch.solve import banded
from yadearch.solve.load_lp import load_analysis, residual_capacity
from yadearch.solve.load_path import live_work, load_settings, load_the_live_load, static_load_path
from yadearch.solve.path import follow_path, path_settings
from yadearch.solve.static_path import StaticLoading
from yadearch.solve.statics import static_arch

QUARTER = {"live_load": "vertical", "load_position_over_span": 0.25}
ACCELERATION = {"live_load": "horizontal_acceleration"}
SMALL = {"n_voussoirs": 15}  # a small arch: fast, the same mechanics
FD_STEP = 1e-9  # m: the load stiffness is smooth, the joints at this state elastic
STIFF_KN = 10_000.0
RIGID_TOLERANCE = 0.02  # stiff static within 2 % of the rigid capacity (issue 44)
NUMERICS_TOLERANCE = 0.01  # a result moves by at most 1 % when only the numerics change


def _loaded(overrides: dict, kn: float = 5.2) -> StaticLoading:
    """The arch of `overrides` under its self-weight, its path's parameter the live load's multiplier."""
    case = preset("set2").with_overrides({**overrides, "interface.kn_N_per_mm3": kn})
    loading = StaticLoading(static_arch(case), path_settings(case.numerics, 10.0), runaway_length(case))
    loading.selfweight()
    load_the_live_load(loading, load_settings(load_analysis(case).multiplier, case.numerics.increment_growth))
    return loading


def test_the_live_load_adds_its_own_stiffness_to_the_tangent():
    """With the live load on, K = -dR/du of the free blocks (the arm of a load above a block's
    centroid turns with it: a softening moment) against central differences of the residual, at a
    state turned off the self-weight's."""
    loading = _loaded({**SMALL, **QUARTER})
    arch, state = loading.arch, loading.accepted[0]
    u = state.u.copy()
    u[arch.free_dofs[2::3]] += 0.05 * arch.length  # every voussoir turned by 50 mrad
    shear = state.forces.shear_force
    multiplier = 5.0
    _, _, band = arch.free_state(u, state.u, shear, multiplier=multiplier)
    stiffness = banded.to_dense(band)
    differences = differenced_tangent(arch, u, state.u, shear, FD_STEP, multiplier=multiplier)
    _, _, unloaded = arch.free_state(u, state.u, shear)
    load_part = stiffness - banded.to_dense(unloaded)
    assert np.abs(load_part).max() > 0.0  # the load's own stiffness is there ...
    assert np.abs(stiffness - differences).max() < 1e-5 * np.abs(stiffness).max()  # ... and exact


LEAN = math.radians(30.0)
CARRIED = {  # the loads' total per unit multiplier, as the supports take it (x, y up): 1 N down, ...
    "quarter-span load": (QUARTER, (0.0, 1.0)),
    "leaning 30 deg": ({**QUARTER, "load_inclination_deg": 30.0}, (-math.sin(LEAN), math.cos(LEAN))),
    "tandem and a half": ({**QUARTER, "further_loads": [[60.0, 1.0], [120.0, 0.5]]}, (0.0, 2.5)),
}


@pytest.mark.parametrize("name", CARRIED)
def test_the_supports_carry_the_weights_and_the_load_at_every_state(name):
    overrides, per_multiplier = CARRIED[name]
    loading = _loaded({**SMALL, **overrides})
    follow_path(loading, loading.settings)
    arch = loading.arch
    weight = arch.weight[1:-1].sum()
    assert len(loading.accepted) >= 5
    for state in loading.accepted:
        onto_supports = state.forces.block_force[[0, -1]].sum(axis=0)  # the arch's push on its supports
        expected = np.array([0.0, weight]) + state.lam * np.array(per_multiplier)
        assert np.allclose(-onto_supports, expected, atol=1e-7 * weight), (state.lam, onto_supports)


@pytest.mark.parametrize("overrides", [QUARTER, ACCELERATION], ids=["quarter-span load", "acceleration"])
def test_stiff_joints_carry_the_rigid_blocks_capacity(overrides):
    """The paper's arch with kn 10 000 N/mm3: within 2 % of the rigid-block load multiplier, on the
    same mechanism within a joint (measured: -1.7 % and -1.3 %)."""
    case = preset("set2").with_overrides({**overrides, "interface.kn_N_per_mm3": STIFF_KN})
    rigid = load_analysis(case)
    path = static_load_path(case)
    assert path.outcome == "collapse" and path.first_loss == path.capacity
    assert -RIGID_TOLERANCE < path.capacity / rigid.multiplier - 1.0 < 0.0
    assert path.rigid == rigid.multiplier
    assert len(path.hinges) == len(rigid.pivots)
    for static, rigid_hinge in zip(path.hinges, rigid.hinge_labels.split()):  # within a joint, on the same face
        assert abs(int(static[:-1]) - int(rigid_hinge[:-1])) <= 1 and static[-1] == rigid_hinge[-1], (
            path.hinges,
            rigid.hinge_labels,
        )


def test_the_capacity_does_not_move_with_the_path_increments():
    """Increments and bracket halved and doubled: the quarter-span capacity of set 2 within 1 %; the
    compliant joints carry less than rigid blocks (7.39 against 9.92 N)."""
    case = preset("set2").with_overrides(QUARTER)
    rigid = load_analysis(case).multiplier
    capacities = [static_load_path(case, scale=factor * rigid).capacity for factor in (0.5, 1.0, 2.0)]
    assert max(capacities) / min(capacities) - 1.0 < NUMERICS_TOLERANCE, capacities
    assert capacities[1] < 0.8 * rigid


def test_a_settled_arch_carries_its_load_past_the_load_that_first_moves_rigid_blocks():
    """After 44 mm of settlement the rigid arch's open hinges are pins, and 0.29 N moves it; the same
    arch on the static path (its hinges re-seat) collapses under 4.75 N, below its capacity at rest."""
    case = preset("set2").with_overrides(QUARTER)
    settled = static_load_path(case, after_mm=44.0)
    at_rest = static_load_path(case)
    assert settled.outcome == "collapse"
    assert settled.rigid == residual_capacity(case, 44.0).multiplier
    assert 5.0 * settled.rigid < settled.capacity < 0.8 * at_rest.capacity
    curve = settled.curve[settled.curve["branch"] == "ascending"]  # load control, up to the peak
    assert (np.diff(curve["multiplier"]) > 0).all() and (np.diff(curve["load_displacement_mm"]) > 0).all()
    assert curve["load_displacement_mm"].iloc[0] == 0.0


def test_the_load_displacement_is_the_work_of_the_load():
    """A vertical load's displacement along itself is its point's downward movement: the whole arch
    lowered by 1 mm moves a 1 N load 1 mm; a turn about a block's centroid moves it by the arm's turn."""
    loading = _loaded({**SMALL, **QUARTER})
    arch, u0 = loading.arch, loading.accepted[0].u
    lowered = u0.reshape(-1, 3).copy()
    lowered[:, 1] -= 1e-3
    assert math.isclose(live_work(arch, u0, lowered.ravel()), 1e-3, rel_tol=1e-12)


def test_the_command_writes_the_load_path_and_refuses_bad_input_in_one_line(tmp_path, capsys):
    """`yadearch loads --engine static`: both answers in one line, the curve, JSON and figure written;
    a movement the arch does not carry, or a negative one, refused in one line."""
    import json

    from yadearch.cli.commands import main

    base = ["loads", "--preset", "set2", "--set", "live_load=vertical", "--set", "n_voussoirs=15", "--engine", "static"]
    assert main([*base, "--out", str(tmp_path)]) == 0
    said = capsys.readouterr().out
    assert "static engine: collapse at" in said and "rigid blocks:" in said and "past the peak down to" in said
    written = json.loads((tmp_path / "custom_load_path.json").read_text())
    assert written["outcome"] == "collapse" and written["collapse_multiplier"] < written["rigid_multiplier"]
    assert written["descending_branch_end"] == "fallen"
    branches = pd.read_csv(tmp_path / "custom_load_path.csv")["branch"]
    assert branches.iloc[0] == "ascending" and branches.iloc[-1] == "descending"
    assert {"pdf", "png", "csv", "json"} <= {p.suffix[1:] for p in tmp_path.glob("custom_load_path.*")}
    assert (tmp_path / "custom_load_path" / "states.npz").is_file() and "custom_load_path/ (yadearch animate" in said
    for after, words in (("500", "does not carry its support movement to 500 mm"), ("-1", "in [0, 10000]")):
        assert main([*base, "--after-mm", after, "--out", str(tmp_path)]) != 0
        said = capsys.readouterr()
        message = (said.out + said.err).strip()
        assert words in message and len(message.splitlines()) == 1, message


def test_the_static_influence_line_is_symmetric_and_below_rigid_blocks(tmp_path):
    """A point load at 1/4, 1/2 and 3/4 of a small symmetric arch on the static path: the two quarter
    points carry the same load (within 0.1 %), every point less than rigid blocks do."""
    import yadearch as ya

    table = ya.load_influence(preset("set2").with_overrides(SMALL), 3, out=tmp_path, engine="static")
    assert table.loc[~table["sampled"], "collapse_load_N"].max() < table.loc[table["sampled"], "collapse_load_N"].min()
    table = table[table["sampled"]]  # the critical positions refined between them aside
    loads = table["collapse_load_N"].to_numpy()
    assert loads[0] == pytest.approx(loads[2], rel=1e-3)
    assert (table["outcome"] == "collapse").all() and (loads < table["rigid_load_N"].to_numpy()).all()
    assert (tmp_path / "set2_influence.csv").is_file() and (tmp_path / "set2_influence.png").is_file()


def test_the_dem_load_path_refuses_what_it_cannot_follow_in_one_line(tmp_path, capsys):
    """`yadearch loads --engine dem` refuses, before YADE starts, CGAL contacts and no live load, each
    in one line; the API refuses an unknown engine and a DEM path or influence line without
    a folder to write it to."""
    import yadearch as ya
    from yadearch.cli.commands import main
    from yadearch.errors import CaseError

    base = ["loads", "--preset", "set2", "--set", "n_voussoirs=15", "--engine", "dem", "--out", str(tmp_path)]
    refusals = (
        (["--set", "live_load=vertical", "--set", "numerics.contact_model=cgal"], "numerics.contact_model = 'cgal'"),
        ([], "loads.live_load is 'none'"),
    )
    for extra, words in refusals:
        assert main([*base, *extra]) != 0
        said = capsys.readouterr()
        message = (said.out + said.err).strip()
        assert words in message and len(message.splitlines()) == 1, message
    case = preset("set2").with_overrides({**SMALL, **QUARTER})
    with pytest.raises(CaseError, match="engine must be one of static, dem, got 'fem'"):
        ya.load_path(case, engine="fem")
    with pytest.raises(CaseError, match="out: the DEM's load path is written to a folder"):
        ya.load_path(case, engine="dem")
    with pytest.raises(CaseError, match="out: the DEM's influence line keeps its load paths in a folder"):
        ya.load_influence(case, 3, engine="dem")
    with pytest.raises(CaseError, match="engine must be one of rigid, static, dem, got 'fem'"):
        ya.load_influence(case, 3, engine="fem")
