"""yadearch: masonry arches on moving supports, simulated with YADE's polyhedral discrete elements.

The public API (`yadearch.api`): `preset`, `movement`, `run`, `open_run`, `sweep`, `montecarlo`, `calibrate`,
`capacity`, `sensitivity`, `limit`, imported on first use so that `import yadearch` stays light (no pandas, no YADE)."""

__version__ = "0.1.0"

_API = ("preset", "movement", "run", "open_run", "sweep", "montecarlo", "calibrate", "capacity", "sensitivity", "limit",
        "RunResult", "HingeAtCollapse")
__all__ = ["__version__", *_API]


def __getattr__(name: str):
    if name in _API:
        from yadearch import api

        return getattr(api, name)
    raise AttributeError(f"module 'yadearch' has no attribute {name!r}")
