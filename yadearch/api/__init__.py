"""The Python API: cases, runs, campaigns and the rigid-block limit analysis as functions returning
typed results, for notebooks and scripts; every command of the command line is a client of one.

    import yadearch as ya
    case = ya.preset("set2").replace(kn_N_per_mm3=10)
    res = ya.run(case, out="runs/k10")
    res.du_mm, res.hinges, res.loading_curve(), res.write_figures()
"""

from yadearch.api.campaigns import calibrate, capacity, montecarlo, robustness, sensitivity, sweep
from yadearch.api.live_loads import load_influence, load_path, loads
from yadearch.api.measured import measured_case
from yadearch.api.results import HingeAtCollapse, RunResult, open_run
from yadearch.api.runs import as_case, limit, movement, preset, report, reproduce, run, with_engine

__all__ = [
    "preset",
    "movement",
    "as_case",
    "with_engine",
    "run",
    "reproduce",
    "report",
    "open_run",
    "limit",
    "loads",
    "load_influence",
    "load_path",
    "measured_case",
    "sweep",
    "montecarlo",
    "calibrate",
    "robustness",
    "capacity",
    "sensitivity",
    "RunResult",
    "HingeAtCollapse",
]
