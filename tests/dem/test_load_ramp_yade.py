"""The DEM's live-load path (dem/load_ramp.py) on a small arch against the static engine's, the same
blocks and joints: a point load at 0.3 of the span of a 15-voussoir segmental arch (kn 5.2 N/mm3). The
DEM finds the static capacity within 1 % on the same four hinges (reports/loads/engines: -0.04 %), and
at every equilibrium of its path the supports carry the weight and the load to the holds' tolerance."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from conftest import needs_yade

from yadearch.api import open_run
from yadearch.case.config import ArchCase, preset
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.load_path import static_load_path

pytestmark = [needs_yade, pytest.mark.yade]

POINT = {
    "n_voussoirs": 15,
    "friction_deg": 80.0,
    "live_load": "vertical",
    "load_position_over_span": 0.3,
    "interface.kn_N_per_mm3": 5.2,
    "progress_every_s": 1e9,
}
ENGINES_TOLERANCE = 0.01  # the two engines' capacities (docs/loads.md)


def test_the_dem_load_path_finds_the_static_capacity_and_hinges():
    from yadearch.dem.load_ramp import dem_load_path

    case = ArchCase(name="segmental_point").with_overrides(POINT)
    static = static_load_path(case)
    dem, records, defects = dem_load_path(case, log=lambda line: None)
    assert dem.outcome == static.outcome == "collapse"
    assert math.isclose(dem.capacity, static.capacity, rel_tol=ENGINES_TOLERANCE), (dem.capacity, static.capacity)
    assert dem.hinges == static.hinges
    assert dem.first_loss == dem.capacity  # no snap on the way: the path folds once, as the static one does
    # a hold accepts a mean block resultant below numerics.equilibrium_tolerance x the mean joint force
    # (here below the weight): summed over the voussoirs, the reactions balance the weight and the load
    # within n_voussoirs x tolerance x weight (measured: 0.18 N of 31.43 N at most, the bound 0.47 N)
    weight = load_analysis(case).arch_weight_N
    balance = case.geometry.n_voussoirs * case.numerics.equilibrium_tolerance
    carried = dem.curve["vertical_reactions_N"] - dem.curve["multiplier"]
    assert (abs(carried / weight - 1.0) < balance).all(), carried.tolist()
    assert (abs(dem.curve["horizontal_reactions_N"]) < balance * weight).all()
    # its states from the load's start, each with its load: the curve's equilibria, then the collapse
    path = [s for s in records.states if s["stage"] in ("selfweight", "equilibrium", "collapse")]
    assert [s["stage"] for s in path[:1] + path[-1:]] == ["selfweight", "collapse"] and defects is None
    assert [s["load"] for s in path[:-1]] == dem.curve["multiplier"].tolist()


def test_near_the_peak_the_dem_first_loses_stability_where_the_static_path_folds():
    """A 13-voussoir semicircle 50 mm thick tilted by a growing horizontal acceleration. Measuring its
    holds themselves, the DEM saw blocks move 0.63-0.64 mm between load steps 0.0001 g apart near the
    peak, more than the snap floor (0.5 mm), and put its first loss at 0.1151 g (-2.6 %): near the peak
    a hold's force tolerance over the path's smallest stiffness is that long. Measured at the static
    model's equilibria the holds sit in (dem/load_ramp.py), its first loss is the static path's fold
    (measured 0.11816 g against 0.11816 g)."""
    from yadearch.dem.load_ramp import dem_load_path

    case = ArchCase(name="semicircle_t50_acceleration").with_overrides(
        {
            "embrace_deg": 180.0,
            "n_voussoirs": 13,
            "friction_deg": 80.0,
            "thickness_mm": 50.0,
            "live_load": "horizontal_acceleration",
            "interface.kn_N_per_mm3": 5.2,
            "progress_every_s": 1e9,
        }
    )
    static = static_load_path(case)
    dem, _, _ = dem_load_path(case, log=lambda line: None)
    assert math.isclose(dem.first_loss, static.first_loss, rel_tol=ENGINES_TOLERANCE), (
        dem.first_loss,
        static.first_loss,
    )
    assert math.isclose(dem.capacity, static.capacity, rel_tol=ENGINES_TOLERANCE)
    assert dem.hinges == static.hinges


def test_a_dem_run_holding_a_load_settles_where_the_static_engine_does(tmp_path):
    """Load, then movement: the same arch with 4 N held at 0.3 of the span while its right support
    settles; the DEM's du within 1 % of the static engine's on the same hinges (measured 66.74 against
    66.74 mm; set 2 with 4 N at the quarter span: 56.59 against 56.59 mm)."""
    from yadearch.api import run

    held = {**POINT, "held_load_N": 4.0}
    base = ArchCase(name="held").with_overrides({k: v for k, v in held.items() if k != "progress_every_s"})
    static = run(base.with_overrides({"numerics.engine": "static"}), out=tmp_path / "static", figures=False)
    dem = run(base.with_overrides({"numerics.engine": "dem"}), out=tmp_path / "dem", figures=False)
    assert dem.summary.loading.held_live_load == "4 N vertical at 0.3 of the span"
    assert math.isclose(dem.summary.du_mm, static.summary.du_mm, rel_tol=ENGINES_TOLERANCE)
    assert dem.summary.hinge_labels == static.summary.hinge_labels
    for result in (static, dem):  # the loaded arch before its support moves is the path's first state
        start = result.series[result.series["stage"] == "equilibrium"].iloc[0]
        carried = start["left_Ry_N"] + start["right_Ry_N"] - result.summary.selfweight["arch_weight_N"]
        assert start["delta_mm"] == 0.0 and math.isclose(carried, 4.0, rel_tol=1e-2)


def test_the_command_runs_the_dem_load_path_in_a_child_and_writes_its_files(tmp_path, capsys):
    """`yadearch loads --engine dem`: the path in a child process, its JSON, curve, log and figure in
    OUT, the answer said in one line beside the rigid one, and its states in OUT/NAME_load_path/ as a
    run folder (each with its load, the collapse last) that the movie and ParaView export read."""
    import json

    from yadearch.cli.commands import main

    settings = [f"{k}={v}" for k, v in POINT.items() if k != "progress_every_s"]
    args = ["loads", "--preset", "set2", "--engine", "dem", "--out", str(tmp_path)]
    for setting in settings:
        args += ["--set", setting]
    assert main(args) == 0
    lines = capsys.readouterr().out.strip().splitlines()
    said = next((line for line in lines if "DEM: collapse at" in line), "\n".join(lines))
    assert "rigid blocks:" in said and lines[-1].startswith("warning: this arch is not the paper's"), said
    written = json.loads((tmp_path / "custom_load_path.json").read_text())
    static = static_load_path(preset("set2").with_overrides(POINT))
    assert written["engine"] == "dem" and written["steps"] > 0
    assert math.isclose(written["collapse_multiplier"], static.capacity, rel_tol=ENGINES_TOLERANCE)
    assert {"csv", "json", "log", "pdf", "png"} <= {p.suffix[1:] for p in tmp_path.glob("custom_load_path.*")}
    run = open_run(tmp_path / "custom_load_path")
    states, curve = run.folder.states, pd.read_csv(tmp_path / "custom_load_path.csv")
    path = states.path()
    assert states.load_unit == "N" and states.stage[path[0]] == "selfweight" and states.stage[path[-1]] == "collapse"
    assert np.allclose(states.load[path[:-1]], curve["multiplier"], rtol=1e-5)  # the curve CSV: 6 figures
    assert run.summary.engine == "dem" and run.summary.hinge_labels == " ".join(written["hinges_at_collapse"])
    assert len(list(run.export_vtk(tmp_path / "vtk").parent.glob("*.vtu"))) >= len(path)
