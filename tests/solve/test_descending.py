"""The descending branch of the static engine's load path past its limit point (solve/descending.py):
every state an equilibrium, the four-hinge mechanism's load falling as it turns, stiff joints following
the rigid mechanism's own softening, a snap-back passed, and the peak and first loss unchanged by it
(docs/loads.md)."""

from __future__ import annotations

import numpy as np
import pytest

from yadearch.case.config import preset
from yadearch.errors import CampaignError
from yadearch.solve.descending import DescentEnd, descend
from yadearch.solve.four_bar import rigid_softening
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.load_path import (
    DESCENDING,
    live_work,
    load_scale,
    load_settings,
    load_the_live_load,
    static_load_path,
)
from yadearch.solve.path import follow_path
from yadearch.solve.static_path import StaticLoading

POINT = {"n_voussoirs": 15, "live_load": "vertical", "load_position_over_span": 0.3}  # the small arch's case
STIFF_KN = 10_000.0  # N/mm3
RIGID_AGREEMENT = 0.01  # stiff joints within 1 % of the rigid mechanism's multiplier (measured: 0.4 %) ...
COMPARED_MM = (0.3, 5.0)  # ... over this range of the load's displacement (mm; the peak's elastic part first)
TURNS = np.linspace(0.0, 0.1, 401)  # rad: the rigid mechanism's first segment, far past the range compared


def _collapsed(overrides: dict) -> tuple[StaticLoading, float]:
    """The case's load path followed to its collapse (the loading at its last stable state) and its capacity."""
    case = preset("set2").with_overrides(overrides)
    loading = StaticLoading.of(case)
    loading.selfweight()
    load_the_live_load(loading, load_settings(load_scale(load_analysis(case)), case.numerics.increment_growth))
    path = follow_path(loading, loading.settings)
    assert path.collapsed
    return loading, path.du


def test_past_the_peak_every_state_is_an_equilibrium_and_the_mechanism_carries_less_as_it_turns():
    """The 15-voussoir arch under a point load at 0.3 of its span (kn 5.2): the descending branch goes from
    the peak down to half the capacity, each state balancing its multiplier (the residual, evaluated
    afresh from the state before, within the solver's tolerance), the load falling at every step while
    its point goes down."""
    loading, capacity = _collapsed(POINT)
    descent = descend(loading, capacity)
    assert descent.end == DescentEnd.FALLEN and len(descent.states) >= 5
    arch, solver = loading.arch, loading.solver
    before = loading.accepted[-1]
    for state in descent.states:
        residual = arch.free_state(state.u, before.u, before.forces.shear_force, multiplier=state.lam)[1]
        assert np.abs(residual).max() <= solver.converged
        before = state
    lams = np.array([loading.accepted[-1].lam] + [s.lam for s in descent.states])
    peak = int(np.argmax(lams))
    assert abs(lams[peak] / capacity - 1.0) < 1e-3  # the fold the load control bracketed to 0.1 %
    assert (np.diff(lams[peak:]) < 0.0).all()
    start = loading.accepted[0].u
    moved = [live_work(arch, start, s.u) for s in descent.states]
    assert (np.diff(moved) > 0.0).all()
    assert descent.states[-1].lam <= 0.5 * capacity and min(s.min_stiffness for s in descent.states[-3:]) < 0.0


def test_stiff_joints_follow_the_rigid_mechanisms_softening():
    """With kn 10 000 N/mm3 the descending branch of the same arch turns on the rigid mechanism's hinges,
    from the peak to its end, and carries, at each displacement of the load from 0.3 to 5 mm, the
    multiplier the rigid four-bar balances by virtual work at that displacement, within 1 %."""
    case = preset("set2").with_overrides({**POINT, "interface.kn_N_per_mm3": STIFF_KN})
    path = static_load_path(case, descend_to=0.3)
    rigid = load_analysis(case)
    assert path.hinges == path.descent_hinges == tuple(rigid.hinge_labels.split())
    moved, multiplier = rigid_softening(case, path.hinges, TURNS)
    assert multiplier[0] == pytest.approx(rigid.multiplier, rel=1e-6)  # the mechanism is the rigid capacity's
    past = path.curve[path.curve["branch"] == DESCENDING]
    compared = past[past["load_displacement_mm"].between(*COMPARED_MM)]
    assert len(compared) >= 5 and compared["load_displacement_mm"].max() > 0.9 * COMPARED_MM[1]
    expected = np.interp(compared["load_displacement_mm"], 1e3 * moved, multiplier)
    assert np.abs(compared["multiplier"].to_numpy() / expected - 1.0).max() < RIGID_AGREEMENT


def test_the_peak_and_the_first_loss_do_not_move_with_the_descending_branch():
    """The capacity, first loss, hinges and Newton iterations of the paper's arch under its quarter-span
    load are those of the load-controlled path, to the last digit (7.39 N, reports/loads)."""
    case = preset("set2").with_overrides({"live_load": "vertical", "load_position_over_span": 0.25})
    alone, traced = static_load_path(case, descend_to=None), static_load_path(case)
    assert (traced.capacity, traced.first_loss, traced.hinges, traced.iterations) == (
        alone.capacity,
        alone.first_loss,
        alone.hinges,
        alone.iterations,
    )
    assert f"{traced.capacity:.3g}" == "7.39" and traced.descent_end == DescentEnd.FALLEN
    assert alone.descent_end == "" and (alone.curve["branch"] != DESCENDING).all()


def test_the_arc_length_passes_a_snap_back_of_a_soft_arch():
    """The paper's arch at kn 0.25 N/mm3 (set 1) under its quarter-span load snaps back past its peak: the
    load's displacement turns back while the load falls; the branch goes on to half the capacity."""
    case = preset("set2").with_overrides(
        {"live_load": "vertical", "load_position_over_span": 0.25, "interface.kn_N_per_mm3": 0.25}
    )
    path = static_load_path(case)
    past = path.curve[path.curve["branch"] == DESCENDING]
    moved = past["load_displacement_mm"].to_numpy()
    assert path.descent_end == DescentEnd.FALLEN
    assert (np.diff(moved) < 0.0).any() and moved[-1] < moved.max()
    assert (np.diff(past["multiplier"]) < 0.0).all()


def test_a_fraction_outside_zero_to_one_is_refused_in_one_line(capsys):
    import yadearch as ya
    from yadearch.cli.commands import main

    case = preset("set2").with_overrides(POINT)
    with pytest.raises(CampaignError, match=r"descend_to must be a number in \[0, 1\] \(or None\), got 1.5"):
        ya.load_path(case, descend_to=1.5)
    base = ["loads", "--preset", "set2", "--set", "live_load=vertical", "--engine", "static"]
    assert main([*base, "--descend-to", "-0.1"]) != 0
    said = capsys.readouterr()
    message = (said.out + said.err).strip()
    assert "'--descend-to': must be a number in [0, 1], got '-0.1'" in message and len(message.splitlines()) == 1


def test_a_branch_that_rises_above_the_capacity_puts_it_in_doubt_in_words():
    """A 6 m limestone semicircle (ring 400 mm, 41 voussoirs, 1 m deep) on soft joints (kn 5) under a
    quarter-span load: past the load control's peak (1180.36 N) the branch rises to 1182.46 N, so the
    load control stopped short of its peak. `descent_end` said "rose" and nothing else did (ninth user
    trial); the path's warnings (which `yadearch loads` prints) say that the capacity is in doubt."""
    semicircle = {"internal_radius_mm": 3000.0, "embrace_deg": 180.0, "thickness_mm": 400.0, "n_voussoirs": 41}
    semicircle |= {"depth_mm": 1000.0, "support_length_mm": 600.0, "kn_N_per_mm3": 5.0, "live_load": "vertical"}
    case = preset("set2").with_overrides({**semicircle, "material.preset": "limestone"})
    path = static_load_path(case)
    assert path.descent_end == DescentEnd.ROSE and path.curve["multiplier"].max() > path.capacity
    (said,) = path.warnings
    assert said.startswith(f"past the peak the load rose to {path.curve['multiplier'].max():.4g} N, above the capacity")
    assert static_load_path(preset("set2").with_overrides({"live_load": "vertical"})).warnings == ()
