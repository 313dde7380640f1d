"""Load, then movement (issue 44): a static run holds a live load while its support moves
(`loads.held_load_N`, `held_acceleration_g`): the load is grown on the load path after the self-weight,
then kept. The supports carry the weight and the load at every equilibrium; no load gives the run without
one (a live load of which nothing is held is listed unused); a heavier load shortens du; a load above
the arch's capacity, or a DEM run that holds nothing of its live load, is refused in one line."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest

from yadearch.case.config import preset
from yadearch.cli.commands import main
from yadearch.solve.load_path import static_load_path

SMALL = {"n_voussoirs": 15, "live_load": "vertical", "load_position_over_span": 0.25}
BALANCE = 1e-6  # relative: the static equilibria are solved to round-off


def _run(tmp_path, name: str, *settings: str) -> tuple[int, dict, pd.DataFrame | None]:
    out = tmp_path / name
    args = ["run", "--preset", "set2", "--engine", "static", "--no-figures", "--out", str(out)]
    for key, value in {**SMALL, "name": name}.items():
        args += ["--set", f"{key}={value}"]
    for setting in settings:
        args += ["--set", setting]
    code = main(args)
    if code != 0:
        return code, {}, None
    return code, json.loads((out / "summary.json").read_text()), pd.read_csv(out / "series.csv")


def test_a_held_load_is_carried_at_every_state_and_shortens_du(tmp_path):
    _, bare, _ = _run(tmp_path, "bare", "live_load=none")
    _, light, _ = _run(tmp_path, "light", "held_load_N=0.5")
    _, heavy, series = _run(tmp_path, "heavy", "held_load_N=4")
    assert series is not None
    weight = bare["selfweight"]["arch_weight_N"]
    moving = series[series["stage"] == "equilibrium"]
    carried = moving["left_Ry_N"] + moving["right_Ry_N"]
    assert ((carried - (weight + 4.0)).abs() < BALANCE * weight).all()
    assert (moving["unbalanced"] < BALANCE).all()
    assert heavy["loading"]["held_live_load"] == "4 N vertical at 0.25 of the span"
    assert "held_live_load" not in bare["loading"]
    _, none_held, _ = _run(tmp_path, "none_held", "held_load_N=0")  # the live load named, nothing of it held
    assert none_held["du_mm"] == bare["du_mm"] and "live_load" in none_held["unused_parameters"]
    assert heavy["du_mm"] < bare["du_mm"]
    assert light["du_mm"] == pytest.approx(bare["du_mm"], rel=0.1)  # a small load moves du little


def test_a_load_the_arch_does_not_carry_or_that_the_dem_would_hold_is_refused_in_one_line(tmp_path, capsys):
    capacity = static_load_path(preset("set2").with_overrides(SMALL)).capacity
    for settings, words in (
        ([f"held_load_N={1.5 * capacity:.3f}", "numerics.engine=static"], "loads.held_load_N = "),
        (["numerics.engine=dem"], "with nothing of it held: a DEM run holds"),
    ):
        args = ["run", "--preset", "set2", "--out", str(tmp_path / "refused"), "--no-figures"]
        for key, value in SMALL.items():
            args += ["--set", f"{key}={value}"]
        for setting in settings:
            args += ["--set", setting]
        assert main(args) != 0
        message = capsys.readouterr().err.strip()  # the run's own log lines go to standard output
        assert words in message and len(message.splitlines()) == 1, message


def test_the_collapse_figure_draws_the_held_load_where_its_block_carried_it(tmp_path):
    """The run's collapse figure did not show the load it held (sixth user trial): an arrow now ends just
    above the load's point as its voussoir carried it to the collapse, and says the load."""
    from matplotlib.patches import FancyArrow

    from yadearch.analysis.blocks import block_centroids, case_geometry, placed_points
    from yadearch.analysis.run import analyse_run, load_run
    from yadearch.case.config import case_from_dict
    from yadearch.case.mechanics import live_load
    from yadearch.model.loads import live_load_points
    from yadearch.plotting.run_figures import collapse_figure

    _run(tmp_path, "held", "held_load_N=4")
    run = load_run(tmp_path / "held")
    figure = collapse_figure(run, analyse_run(run))
    ax = figure.axes[0]
    arrows = [p for p in ax.patches if isinstance(p, FancyArrow)]
    assert len(arrows) == 1 and any(t.get_text() == "held load 4 N" for t in ax.texts)
    geometry = case_geometry(run.case)
    points = live_load_points(geometry, block_centroids(geometry), 0 * block_centroids(geometry)[:, 0],
                              live_load(case_from_dict(run.case), geometry))  # fmt: skip
    carried = placed_points(geometry, run.snapshots["collapse"], points.block, points.point) * 1e3
    tip = arrows[0].get_xy()  # the arrow's outline: its head is the lowest vertex
    head = tip[np.argmin(tip[:, 1])]
    assert head[0] == pytest.approx(carried[:, 0].mean(), abs=0.5)
    assert 0.0 < head[1] - carried[:, 1].mean() < 0.02 * geometry.span * 1e3
