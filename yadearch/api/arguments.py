"""The API's arguments that are not case parameters (jobs, timeouts, sample sizes, search bounds), each
with its type and accepted range in one table: every API function checks its arguments against it
before anything starts, and the command line's options are built from the same rows, so both agree."""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, fields
from typing import Any

from yadearch.case.bounds import MAX_CHECKS, MAX_RUNS, MAX_STEP_DEG, MAX_TARGET_DU_MM, MIN_BASE_POINTS, MIN_STEP_DEG
from yadearch.case.sections import InterfaceConfig
from yadearch.errors import ArgumentTypeError, CampaignError

FIGURE_PROCESSES = 2  # a run's figures are drawn by one process or by two (plotting.parallel)
MAX_JOBS = 1024  # runs at once on one machine; a cluster is reached through a scheduler instead
MAX_TIMEOUT_S = 30 * 24 * 3600.0  # 30 days: longer is no limit (and overflows the wait's timer)
MAX_CALIBRATION_RUNS = 100  # a root search that needs more runs has no root to find
SEED_MAX = 2**32 - 1  # numpy's seeds
SECONDS_PER_MINUTE = 60.0
MAX_PIER_MM = 1e5  # 100 m: each arch then bounds its piers by its span (`case.piers.on_piers`)
_KN = next(f.metadata for f in fields(InterfaceConfig) if f.name == "kn_N_per_mm3")


@dataclass(frozen=True)
class Argument:
    """One argument: its type (int, float or bool), range, whether None is accepted, and the command
    line's option for it with that option's unit (`scale` API units per option unit)."""

    name: str
    kind: type
    low: float | None = None
    high: float | None = None
    low_open: bool = False
    optional: bool = False
    option: str | None = None
    scale: float = 1.0
    power_of_two: bool = False

    def accepted(self, scale: float = 1.0, none: bool = True) -> str:
        """What is accepted, in words (in option units when `scale` is the option's; saying that
        None is, when it is and `none`)."""
        kind = {int: "an integer", float: "a number", bool: "true or false"}[self.kind]
        if self.kind is bool:
            return kind
        low = None if self.low is None else _number(self.low / scale, self.kind)
        high = None if self.high is None else _number(self.high / scale, self.kind)
        if low is not None and high is not None:
            span = f" in {'(' if self.low_open else '['}{low}, {high}]"
        elif low is not None:
            span = f" {'>' if self.low_open else '>='} {low}"
        else:
            span = f" <= {high}" if high is not None else ""
        extra = ", a power of two" if self.power_of_two else ""
        return f"{kind}{span}{extra}{' (or None)' if self.optional and none else ''}"

    def refusal(self, value: Any) -> type[Exception] | None:
        """The error `value` (in API units) earns: ArgumentTypeError for a wrong type, CampaignError
        for a value out of range; None if it is accepted."""
        if value is None:
            return None if self.optional else ArgumentTypeError
        if self.kind is bool:
            return None if isinstance(value, bool) else ArgumentTypeError
        wanted = numbers.Integral if self.kind is int else numbers.Real
        if isinstance(value, bool) or not isinstance(value, wanted):
            return ArgumentTypeError
        value = float(value)
        if not math.isfinite(value):
            return CampaignError
        if self.low is not None and (value <= self.low if self.low_open else value < self.low):
            return CampaignError
        if self.high is not None and value > self.high:
            return CampaignError
        if self.power_of_two and int(value) & (int(value) - 1):
            return CampaignError
        return None


ARGUMENTS = {
    a.name: a
    for a in (
        Argument("jobs", int, 1, MAX_JOBS, optional=True, option="--jobs"),
        Argument("figure_jobs", int, 1, FIGURE_PROCESSES),
        Argument(
            "timeout_s",
            float,
            0,
            MAX_TIMEOUT_S,
            low_open=True,
            optional=True,
            option="--timeout-min",
            scale=SECONDS_PER_MINUTE,
        ),
        Argument("samples", int, 1, MAX_RUNS, option="--samples"),
        Argument("seed", int, 0, SEED_MAX, option="--seed"),
        Argument(
            "base_points", int, MIN_BASE_POINTS, MAX_RUNS, optional=True, option="--base-points", power_of_two=True
        ),
        Argument("check_runs", int, 0, MAX_CHECKS, option="--check-runs"),
        Argument("step_deg", float, MIN_STEP_DEG, MAX_STEP_DEG, option="--step-deg"),
        Argument("target_du_mm", float, 0, MAX_TARGET_DU_MM, low_open=True, option="--target-du"),
        Argument("tolerance_mm", float, 0, MAX_TARGET_DU_MM, low_open=True, option="--tolerance-mm"),
        Argument("kn_min", float, _KN["low"], _KN["high"], low_open=_KN["low_open"], option="--kn-min"),
        Argument("kn_max", float, _KN["low"], _KN["high"], low_open=_KN["low_open"], option="--kn-max"),
        Argument("max_runs", int, 3, MAX_CALIBRATION_RUNS, option="--max-runs"),
        Argument("max_snap_mm", float, 0, MAX_TARGET_DU_MM, low_open=True, optional=True, option="--max-snap-mm"),
        Argument("after_mm", float, 0, MAX_TARGET_DU_MM, option="--after-mm"),
        Argument("start_mm", float, 0, MAX_TARGET_DU_MM, option="--start-mm"),
        Argument("descend_to", float, 0, 1, optional=True, option="--descend-to"),
        Argument("pier_height_mm", float, 0, MAX_PIER_MM, low_open=True, option="--height-mm"),
        Argument("pier_width_mm", float, 0, MAX_PIER_MM, low_open=True, option="--width-mm"),
        Argument("compliant", bool),
        Argument("rerun", bool),
        Argument("overwrite", bool),
        Argument("figures", bool),
        Argument("quiet", bool),
        Argument("static_beside", bool),
        Argument("retry_failed", bool),
        Argument("rigid", bool),
        Argument("static", bool),
    )
}


def check_arguments(**values: Any) -> None:
    """Refuse, before anything starts, the first argument outside its type or range (`ARGUMENTS`):
    ArgumentTypeError (a TypeError) for a wrong type, CampaignError (a ValueError) for a value out
    of range, each naming the argument, the value and what is accepted."""
    for name, value in values.items():
        argument = ARGUMENTS[name]
        error = argument.refusal(value)
        if error is not None:
            raise error(f"{name} must be {argument.accepted()}, got {_shown(value)}")


def _number(value: float, kind: type) -> str:
    """A bound in words: an integer's in full, a number's to six figures."""
    return str(int(value)) if kind is int else f"{value:g}"


def _shown(value: Any) -> str:
    """A refused value as the message shows it: its repr, with its type when that is the problem."""
    shown = f"{value!r:.40}"
    return shown if value is None or isinstance(value, (int, float)) else f"{type(value).__name__} {shown}"
