"""The rows of a campaign: parameter values from the command line or a CSV table, grids of them,
and the deterministic run name of each row (`kn_N_per_mm3=0.1` -> `kn0.1`)."""

from __future__ import annotations

import csv
import hashlib
import itertools
import json
import math
import os
import re
import tomllib
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from yadearch.case.bounds import MAX_RUNS
from yadearch.case.config import unknown_parameter
from yadearch.case.materials import MATERIAL_KEY, PRESET_FIELD
from yadearch.case.sections import parameter_docs
from yadearch.case.support import MOVEMENT_KEY
from yadearch.errors import ArgumentTypeError, CampaignError, CaseError, YadearchError

TEXT_ENCODING = "utf-8-sig"  # UTF-8, with or without the byte-order mark Excel's "CSV UTF-8" writes
RUN_COLUMN = "run"  # optional column of an explicit table: the run's name
NAME_COLUMNS = (RUN_COLUMN, "name", "description")  # each names the runs (yade-batch's is description)
MAX_TAG = 64
MAX_RUNS_VARIABLE = "YADEARCH_MAX_RUNS"
_UNIT_SUFFIXES = ("_N_per_mm3", "_mm_per_s", "_g_per_cm3", "_m_per_s2", "_mm", "_deg", "_MPa", "_s")
_BARE_NAMES = {q.split(".")[-1]: q for q, _, _ in parameter_docs()}

NAMED_KEYS = (MOVEMENT_KEY, MATERIAL_KEY)  # columns that stand for several parameters


def check_campaign_size(runs: int) -> None:
    """Refuse a campaign of more than MAX_RUNS runs (or the bound set in YADEARCH_MAX_RUNS)."""
    bound = int(os.environ.get(MAX_RUNS_VARIABLE, MAX_RUNS))
    if runs > bound:
        raise CampaignError(
            f"campaign of {runs} runs exceeds the bound of {bound}; set {MAX_RUNS_VARIABLE} to raise it"
        )


def parse_scalar(text: str) -> Any:
    """A value in TOML scalar syntax (numbers, true/false, quoted strings), else the bare string."""
    try:
        return tomllib.loads(f"v = {text.strip()}")["v"]
    except tomllib.TOMLDecodeError:
        return text.strip()


def round_sig(value: float, digits: int = 4) -> float:
    """`value` rounded to `digits` significant figures (so generated values name folders cleanly)."""
    return float(f"{value:.{digits}g}")


def parse_values(spec: str) -> list[Any]:
    """Values of one parameter: `v1,v2,...`, or `start:stop:log:n` / `start:stop:lin:n` (n values,
    rounded to 4 significant figures; integers stay integers)."""
    parts = spec.split(":")
    if len(parts) == 1:
        values = [parse_scalar(v) for v in spec.split(",") if v.strip()]
        if not values:
            raise YadearchError(f"no values in {spec!r}")
        return values
    if len(parts) != 4 or parts[2] not in ("log", "lin"):
        raise YadearchError(f"range {spec!r} must read start:stop:log:n or start:stop:lin:n")
    start, stop, count = parse_scalar(parts[0]), parse_scalar(parts[1]), parse_scalar(parts[3])
    if (
        not all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in (start, stop))
        or not isinstance(count, int)
        or count < 1
    ):
        raise YadearchError(f"range {spec!r}: start and stop must be finite numbers and n a positive integer")
    check_campaign_size(count)
    if parts[2] == "log":
        if start <= 0 or stop <= 0:
            raise YadearchError(f"log range {spec!r} needs positive start and stop")
        return [round_sig(v) for v in np.geomspace(start, stop, count)]
    values = np.linspace(start, stop, count)
    if isinstance(start, int) and isinstance(stop, int) and np.allclose(values, np.round(values)):
        return [int(v) for v in np.round(values)]
    return [round_sig(v) for v in values]


def named_overrides(overrides: dict[str, Any]) -> dict[str, Any]:
    """`overrides` with a named movement (`movement`: its [loading] parameters) and a named material
    (`material`: material.preset) spelt out, as `--set movement=NAME` and `--set material=NAME` read."""
    from yadearch.case.support import movement_overrides

    spelt = {k: v for k, v in overrides.items() if k not in NAMED_KEYS}
    named: dict[str, Any] = {}
    if MATERIAL_KEY in overrides:
        named[f"{MATERIAL_KEY}.{PRESET_FIELD}"] = str(overrides[MATERIAL_KEY]).strip()
    if MOVEMENT_KEY in overrides:
        named.update(movement_overrides(str(overrides[MOVEMENT_KEY]).strip()))
    given = {key.split(".")[-1]: key for key in spelt}
    clash = next((given[key.split(".")[-1]] for key in named if key.split(".")[-1] in given), None)
    if clash is not None:
        raise CaseError(
            f"{clash} is given beside a named {' and '.join(k for k in NAMED_KEYS if k in overrides)} that sets it "
            "too; give it by name or by its parameters, not both"
        )
    return spelt | named


def check_parameter(key: str, numeric: bool = False) -> None:
    """Raise CaseError unless `key` names a case parameter (`section.key` or a bare key) or, unless a
    `numeric` one is wanted (a factor of the sensitivity study), a named movement or material."""
    if numeric and key in NAMED_KEYS:
        raise CaseError(f"{key} names a choice, not a number; vary the parameters it stands for")
    qualified = {q for q, _, _ in parameter_docs()}
    if key not in qualified and key not in _BARE_NAMES and key not in NAMED_KEYS:
        raise unknown_parameter(key, [*qualified, *_BARE_NAMES, *NAMED_KEYS])


def qualified_name(key: str) -> str:
    """`section.key` of a case parameter given bare or qualified."""
    return _BARE_NAMES.get(key, key)


def grid(params: dict[str, list[Any]]) -> list[dict[str, Any]]:
    """Every combination of the values of `params` (last parameter varies fastest)."""
    for key, values in params.items():
        check_parameter(key)
        if isinstance(values, (str, bytes)) or not hasattr(values, "__len__"):
            raise ArgumentTypeError(f"{key}: give a list of values, got {values!r:.40}")
        if len(values) == 0:
            raise CampaignError(f"{key}: no values to run")
    check_campaign_size(math.prod(len(values) for values in params.values()))
    keys = list(params)
    return [dict(zip(keys, combo)) for combo in itertools.product(*(params[k] for k in keys))]


def read_table(path: str | Path) -> list[dict[str, Any]]:
    """Rows of an explicit CSV campaign table: one column per parameter (an empty cell keeps the base
    value), optionally one column naming each run (`run`, `name` or yade-batch's `description`).
    UTF-8 with or without a byte-order mark (Excel's "CSV UTF-8"); anything else, a repeated column
    or a row longer or shorter than the header is one line."""
    path = Path(path)
    if not path.is_file():
        raise CampaignError(f"campaign table {str(path)!r} does not exist")
    try:
        with path.open(newline="", encoding=TEXT_ENCODING) as f:
            reader = csv.DictReader(f)
            header = reader.fieldnames or []
            _check_header(path, header)
            rows = []
            for line, row in enumerate(reader, start=2):
                if None in row:
                    raise CampaignError(f"campaign table {str(path)!r}: row {line} has more cells than the header")
                if None in row.values():  # a short row; an empty cell (a comma with nothing) keeps the base value
                    given = sum(v is not None for v in row.values())
                    raise CampaignError(
                        f"campaign table {str(path)!r}: row {line} has {given} of the header's {len(header)} cells; "
                        "leave a cell empty (e.g. '10,') to keep the base value"
                    )
                rows.append(
                    {
                        (RUN_COLUMN if k in NAME_COLUMNS else k): (v if k in NAME_COLUMNS else parse_scalar(v))
                        for k, v in row.items()
                        if v is not None and v.strip()
                    }
                )
    except UnicodeDecodeError as exc:
        raise CampaignError(
            f"campaign table {str(path)!r} is not UTF-8 text (byte {exc.start}); save it as CSV (UTF-8)"
        ) from None
    except csv.Error as exc:
        raise CampaignError(f"campaign table {str(path)!r} is not a readable CSV table ({exc})") from None
    if not rows:
        raise CampaignError(f"campaign table {str(path)!r} has no rows")
    return rows


def _check_header(path: Path, header: Sequence[str]) -> None:
    """Every column a case parameter (or one naming the runs), each once (also under its bare and
    qualified names)."""
    naming = [key for key in header if key in NAME_COLUMNS]
    if len(naming) > 1:
        raise CampaignError(
            f"campaign table {str(path)!r} names its runs twice (columns {', '.join(map(repr, naming))}); keep one"
        )
    for key in header:
        if key not in NAME_COLUMNS:
            check_parameter(key)
    seen: dict[str, str] = {}
    for key in header:
        qualified = qualified_name(key)
        if qualified in seen:
            raise CampaignError(
                f"campaign table {str(path)!r} gives {qualified} twice (columns {seen[qualified]!r} and "
                f"{key!r}); keep one"
            )
        seen[qualified] = key


def short_name(key: str) -> str:
    """A parameter's name in run tags: the bare name without its unit (`kn_N_per_mm3` -> `kn`)."""
    bare = key.split(".")[-1]
    for suffix in _UNIT_SUFFIXES:
        if bare.endswith(suffix):
            return bare[: -len(suffix)]
    return bare


def _format(value: Any) -> str:
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, float):
        return f"{value:.6g}"
    return str(value)


def run_tag(overrides: dict[str, Any]) -> str:
    """Deterministic, readable run name from the overrides (`kn0.1_n_voussoirs15`); long or odd
    names are cut and get a short hash of the overrides so that they stay unique."""
    tag = "_".join(f"{short_name(k)}{_format(v)}" for k, v in overrides.items())
    safe = re.sub(r"[^A-Za-z0-9._+-]", "-", tag)
    if safe == tag and len(tag) <= MAX_TAG:
        return tag
    digest = hashlib.sha1(json.dumps(overrides, sort_keys=True, default=str).encode()).hexdigest()[:8]
    return f"{safe[: MAX_TAG - 9]}-{digest}"
