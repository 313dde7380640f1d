"""The Python API: cases, runs, campaigns and the rigid-block limit analysis as functions returning
typed results, for notebooks and scripts; every command of the command line is a client of one.

    import yadearch as ya
    case = ya.preset("set2").replace(kn_N_per_mm3=10)
    res = ya.run(case, out="runs/k10")
    res.du_mm, res.hinges, res.loading_curve(), res.write_figures()

Each name is imported from its module on first use (`__getattr__` below), so that importing one
module of the API (a command's, or `yadearch.api.runs` for a single run) does not import every
other one and theirs (pandas, matplotlib, the studies); type checkers see the TYPE_CHECKING imports.
"""

from importlib import import_module
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from yadearch.api.campaigns import Factor, calibrate, capacity, montecarlo, robustness, sensitivity, sweep
    from yadearch.api.live_loads import load_influence, load_path, loads, residual_curve
    from yadearch.api.measured import measured_case, on_piers
    from yadearch.api.results import HingeAtCollapse, RunResult, open_run
    from yadearch.api.runs import as_case, limit, movement, preset, report, reproduce, run, with_engine

_MODULES = {  # the module of each name
    "campaigns": ("Factor", "calibrate", "capacity", "montecarlo", "robustness", "sensitivity", "sweep"),
    "live_loads": ("load_influence", "load_path", "loads", "residual_curve"),
    "measured": ("measured_case", "on_piers"),
    "results": ("HingeAtCollapse", "RunResult", "open_run"),
    "runs": ("as_case", "limit", "movement", "preset", "report", "reproduce", "run", "with_engine"),
}
_MODULE_OF = {name: module for module, names in _MODULES.items() for name in names}

__all__ = [
    "Factor",
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
    "residual_curve",
    "measured_case",
    "on_piers",
    "sweep",
    "montecarlo",
    "calibrate",
    "robustness",
    "capacity",
    "sensitivity",
    "RunResult",
    "HingeAtCollapse",
]


def __getattr__(name: str) -> Any:
    module = _MODULE_OF.get(name)
    if module is None:
        raise AttributeError(f"module 'yadearch.api' has no attribute {name!r}")
    return getattr(import_module(f"yadearch.api.{module}"), name)


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
