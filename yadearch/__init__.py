"""yadearch: masonry arches on moving supports, simulated with YADE's polyhedral discrete elements.

The public API (`yadearch.api`): `preset`, `movement`, `run`, `reproduce`, `report`, `open_run`, `sweep`,
`montecarlo`, `calibrate`, `robustness`, `capacity`, `sensitivity`, `limit`, `loads`, `load_influence`,
`load_path`, `residual_curve`, `measured_case`, `on_piers` (and `RunResult`, `Factor`), imported on first use so that
`import yadearch` stays light (no pandas, no YADE); type checkers and IDEs see them through the
TYPE_CHECKING import below."""

from typing import TYPE_CHECKING

__version__ = "0.1.0"

if TYPE_CHECKING:
    from yadearch.api import (
        Factor,
        HingeAtCollapse,
        RunResult,
        calibrate,
        capacity,
        limit,
        load_influence,
        load_path,
        loads,
        measured_case,
        montecarlo,
        movement,
        on_piers,
        open_run,
        preset,
        report,
        reproduce,
        residual_curve,
        robustness,
        run,
        sensitivity,
        sweep,
    )

__all__ = [
    "__version__",
    "preset",
    "movement",
    "run",
    "reproduce",
    "report",
    "open_run",
    "sweep",
    "montecarlo",
    "calibrate",
    "robustness",
    "capacity",
    "sensitivity",
    "limit",
    "loads",
    "load_influence",
    "load_path",
    "residual_curve",
    "measured_case",
    "on_piers",
    "RunResult",
    "HingeAtCollapse",
    "Factor",
]


def __getattr__(name: str):
    if name in __all__:
        from yadearch import api

        return getattr(api, name)
    raise AttributeError(f"module 'yadearch' has no attribute {name!r}")


def __dir__() -> list[str]:
    """The API's names for tab completion (they are imported on first use, so not yet in the module)."""
    return sorted(__all__)
