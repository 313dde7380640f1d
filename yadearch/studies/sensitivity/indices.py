"""What du is sensitive to: one factor at a time over its plausible range (the tornado), and Sobol's
variance-based indices over all the ranges at once, sampled and estimated with SALib (Saltelli's
scheme, first-order and total indices; docs/validation-imperfections.md, "What du is sensitive to").

The Sobol sample of 2N base points starts with the sample of N (a scrambled Sobol sequence extends),
and each run is named by its base point, so doubling N reruns nothing: the campaign resumes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd

from yadearch.analysis.samples import collapse_displacement
from yadearch.case.bounds import MIN_BASE_POINTS
from yadearch.case.config import ArchCase
from yadearch.errors import CampaignError
from yadearch.studies.campaigns.grid import RUN_COLUMN, check_parameter, qualified_name, round_sig

SAMPLE_SEED = 20261126  # scrambling of the Sobol sequence (fixed: the same sample on every machine)
BOOTSTRAP_RESAMPLES = 200  # SALib's bootstrap of the indices' confidence intervals
CONFIDENCE = 0.95
STABLE_TO = 0.02  # indices stable when no index moves more than this as the sample doubles
MIN_ESTIMATE_POINTS = 4  # complete base points an estimate needs at least
CONVERGENCE_FROM = 32  # the smallest sample of the convergence table (base points), when N allows it
FIT_FROM = 128  # the changes fitted to estimate the sample that stability needs start at this size
VALUE_DIGITS = 6  # significant figures of a sampled factor value (run tables stay readable)
SEED_KEY = "imperfections.seed"
BASE_RUN = "base"  # the one-at-a-time study's run of the base case
MAX_SEED = 100_000


@dataclass(frozen=True)
class Factor:
    """One uncertain input: a case parameter, its plausible range (paper units), and how it is
    sampled in it (uniform, log-uniform, or uniform over integers)."""

    key: str
    label: str
    low: float
    high: float
    log: bool = False
    integer: bool = False
    in_tornado: bool = True  # the imperfection draw (a seed) has no one-at-a-time effect

    @property
    def name(self) -> str:
        return self.key.split(".")[-1]

    def value(self, u: float) -> float | int:
        """The factor's value at the fraction `u` (0-1) of its range."""
        if self.log:
            return round_sig(
                math.exp(math.log(self.low) + u * (math.log(self.high) - math.log(self.low))), VALUE_DIGITS
            )
        if self.integer:
            return int(min(self.high, math.floor(self.low + u * (self.high - self.low + 1))))
        return round_sig(self.low + u * (self.high - self.low), VALUE_DIGITS)


# The paper's arch (docs/validation-imperfections.md gives the reasons for each range): stiffness from the softest
# set to near-rigid joints, the geometry within a hand-milled model's tolerances, the defects up to
# what the imperfection study found for set 1.
PAPER_FACTORS = (
    Factor("interface.kn_N_per_mm3", "joint normal stiffness kn (N/mm³)", 0.25, 100.0, log=True),
    Factor("interface.ks_over_kn", "shear-to-normal stiffness ks/kn", 0.25, 1.0),
    Factor("material.friction_deg", "friction angle (°)", 35.0, 45.0),
    Factor("geometry.thickness_mm", "ring thickness (mm)", 23.0, 25.0),
    Factor("geometry.embrace_deg", "embrace (°)", 122.5, 127.5),
    Factor("material.density_g_per_cm3", "density (g/cm³)", 1.5, 1.8),
    Factor("geometry.n_voussoirs", "voussoir count", 45, 65, integer=True),
    Factor("imperfections.face_bump_sd_mm", "face out-of-flatness, sd (mm)", 0.0, 0.2),
    Factor("imperfections.edge_radius_mm", "worn edge radius (mm)", 0.0, 2.0),
    Factor("imperfections.face_angle_sd_mrad", "face angle error, sd (mrad)", 0.0, 4.0),
    Factor("imperfections.voussoir_offset_sd_mm", "voussoir offset, sd (mm)", 0.0, 0.5),
    Factor(SEED_KEY, "imperfection draw (seed)", 1, MAX_SEED, integer=True, in_tornado=False),
)


def parse_factor(text: str) -> Factor:
    """A factor from `NAME=LOW:HIGH`, `NAME=LOW:HIGH:log` or `NAME=LOW:HIGH:int` (the command line's
    --factor); NAME is a case parameter, bare or `section.key`."""
    name, _, spec = text.partition("=")
    parts = spec.split(":")
    if not name.strip() or len(parts) not in (2, 3) or (len(parts) == 3 and parts[2] not in ("log", "int")):
        raise CampaignError(f"factor {text!r} must read NAME=LOW:HIGH, NAME=LOW:HIGH:log or NAME=LOW:HIGH:int")
    check_parameter(name.strip(), numeric=True)
    try:
        low, high = float(parts[0]), float(parts[1])
    except ValueError:
        raise CampaignError(f"factor {text!r}: LOW and HIGH must be numbers") from None
    key = qualified_name(name.strip())
    kind = parts[2] if len(parts) == 3 else ""
    return Factor(
        key, key.split(".")[-1], low, high, log=kind == "log", integer=kind == "int", in_tornado=key != SEED_KEY
    )


def as_factor(item: Factor | str) -> Factor:
    """A factor given as a Factor, as the command line's text (`parse_factor`), or as the name of one
    of PAPER_FACTORS (its plausible range); CampaignError in one line for anything else."""
    named = {f.name: f for f in PAPER_FACTORS} | {f.key: f for f in PAPER_FACTORS}
    if isinstance(item, Factor) or (isinstance(item, str) and item.strip() in named):
        return item if isinstance(item, Factor) else named[item.strip()]
    if isinstance(item, str) and "=" in item:
        return parse_factor(item)
    raise CampaignError(
        f"factor {item!r} must be a Factor, 'NAME=LOW:HIGH[:log|:int]' or one of the paper's factors "
        f"({', '.join(f.name for f in PAPER_FACTORS)})"
    )


def check_factors(base: ArchCase, factors: tuple[Factor, ...]) -> None:
    """Refuse factors whose range is empty, does not contain the case's own value (a tornado swings about
    it) or whose end values the case does not accept, before anything runs (one line naming the factor)."""
    if len({f.key for f in factors}) != len(factors):
        raise CampaignError("sensitivity factors: a parameter is listed twice")
    for factor in factors:
        if not factor.low < factor.high:
            raise CampaignError(
                f"sensitivity factor {factor.key}: low {factor.low:g} must be below high {factor.high:g}"
            )
        if factor.log and factor.low <= 0:
            raise CampaignError(f"sensitivity factor {factor.key}: a log range needs low > 0, got {factor.low:g}")
        for end in (factor.low, factor.high):
            base.with_overrides({factor.key: factor.value(0.0) if end == factor.low else factor.value(1.0)})
        value = base_value(base, factor)
        if factor.in_tornado and not factor.low <= value <= factor.high:
            raise CampaignError(
                f"sensitivity factor {factor.key}: its range {factor.low:g}-{factor.high:g} does not contain the "
                f"case's {value:g} (the default factors are the paper's arch's); give this arch's own with "
                "--factor NAME=LOW:HIGH (factors=...)"
            )


def base_value(base: ArchCase, factor: Factor) -> Any:
    """The factor's value in the base case."""
    section, name = factor.key.split(".")
    return getattr(getattr(base, section), name)


def tornado_rows(base: ArchCase, factors: tuple[Factor, ...]) -> list[dict[str, Any]]:
    """The one-at-a-time runs: the base case, then each factor at the low and the high end of its range."""
    rows: list[dict[str, Any]] = [{RUN_COLUMN: BASE_RUN}]
    for factor in factors:
        if factor.in_tornado:
            rows += [
                {factor.key: factor.value(0.0), RUN_COLUMN: f"{factor.name}_low"},
                {factor.key: factor.value(1.0), RUN_COLUMN: f"{factor.name}_high"},
            ]
    return rows


def tornado_table(base: ArchCase, factors: tuple[Factor, ...], results: pd.DataFrame) -> pd.DataFrame:
    """du at each end of each factor's range beside the base du, largest swing first; an end where the
    arch cannot stand counts as du 0, as in the indices (it had no bar and sorted last)."""
    du = dict(zip(results[RUN_COLUMN], collapse_displacement(results)))
    rows = []
    for factor in factors:
        if factor.in_tornado:
            low, high = du.get(f"{factor.name}_low", math.nan), du.get(f"{factor.name}_high", math.nan)
            rows.append(
                {
                    "factor": factor.name,
                    "label": factor.label,
                    "base": base_value(base, factor),
                    "low": factor.value(0.0),
                    "high": factor.value(1.0),
                    "du_low_mm": low,
                    "du_high_mm": high,
                    "du_base_mm": du.get(BASE_RUN, math.nan),
                    "swing_mm": abs(high - low),
                }
            )
    return pd.DataFrame(rows).sort_values("swing_mm", ascending=False, na_position="last").reset_index(drop=True)


def salib_problem(factors: tuple[Factor, ...]) -> dict[str, Any]:
    """SALib's problem on the unit cube (each factor's fraction of its range; `Factor.value` maps it)."""
    return {"num_vars": len(factors), "names": [f.name for f in factors], "bounds": [[0.0, 1.0]] * len(factors)}


def check_base_points(base_points: int) -> None:
    """Saltelli's scheme needs a power of two of base points (Sobol sequences balance only there)."""
    if base_points < MIN_BASE_POINTS or base_points & (base_points - 1):
        raise CampaignError(f"base_points must be a power of two >= {MIN_BASE_POINTS}, got {base_points}")


def sobol_rows(factors: tuple[Factor, ...], base_points: int) -> list[dict[str, Any]]:
    """Saltelli's sample of `base_points` x (factors + 2) runs, named b<point>_<column>."""
    from SALib.sample import sobol as sobol_sample

    check_base_points(base_points)
    unit = sobol_sample.sample(salib_problem(factors), base_points, calc_second_order=False, seed=SAMPLE_SEED)
    block = len(factors) + 2
    return [
        {
            **{f.key: f.value(float(u)) for f, u in zip(factors, point)},
            RUN_COLUMN: f"b{row // block:05d}_{row % block:02d}",
        }
        for row, point in enumerate(unit)
    ]


def sobol_indices(factors: tuple[Factor, ...], du_mm: np.ndarray, base_points: int) -> pd.DataFrame:
    """First-order and total Sobol indices of du from the first `base_points` blocks of the sample
    (in sample order); blocks with a failed or standing run are left out and counted."""
    from SALib.analyze import sobol as sobol_analyze

    block = len(factors) + 2
    values = np.asarray(du_mm, dtype=float)[: base_points * block].reshape(-1, block)
    complete = values[np.isfinite(values).all(axis=1)]
    if len(complete) < MIN_ESTIMATE_POINTS:
        raise CampaignError(f"only {len(complete)} of {len(values)} base points have every run done")
    if np.ptp(complete) == 0.0:  # SALib would divide by a zero variance
        raise CampaignError(
            f"du is {complete.flat[0]:g} mm in every run of the sample (0: none stands): no variance for the "
            "indices to share; check that the factors' ranges fit this arch (sensitivity.csv, the runs' reasons)"
        )
    result = sobol_analyze.analyze(
        salib_problem(factors),
        complete.ravel(),
        calc_second_order=False,
        num_resamples=BOOTSTRAP_RESAMPLES,
        conf_level=CONFIDENCE,
        seed=SAMPLE_SEED,
    )
    return pd.DataFrame(
        {
            "base_points": base_points,
            "used_points": len(complete),
            "factor": [f.name for f in factors],
            "S1": result["S1"],
            "S1_conf": result["S1_conf"],
            "ST": result["ST"],
            "ST_conf": result["ST_conf"],
        }
    )


def index_shift(coarse: pd.DataFrame, fine: pd.DataFrame) -> float:
    """The largest change of any first-order or total index between two sample sizes."""
    joined = coarse.merge(fine, on="factor", suffixes=("_coarse", "_fine"))
    return float(
        max(
            (joined["S1_coarse"] - joined["S1_fine"]).abs().max(), (joined["ST_coarse"] - joined["ST_fine"]).abs().max()
        )
    )


def sample_sizes(base_points: int) -> list[int]:
    """The nested samples the indices are estimated on: every power of two from CONVERGENCE_FROM
    (or N/2 if smaller) up to N, each the first part of the next."""
    size, sizes = base_points, list[int]()
    while size >= min(CONVERGENCE_FROM, base_points // 2):
        sizes.insert(0, size)
        size //= 2
    return sizes


def convergence(indices: pd.DataFrame) -> pd.DataFrame:
    """Per sample size after the first: the largest change of an index since the half-size sample and
    the mean half-width of the indices' bootstrap intervals."""
    sizes = sorted(indices["base_points"].unique())
    rows = []
    for coarse, fine in zip(sizes, sizes[1:]):
        at = indices[indices["base_points"] == fine]
        rows.append(
            {
                "base_points": fine,
                "largest_change": index_shift(indices[indices["base_points"] == coarse], at),
                "mean_half_width": float(np.mean([at["S1_conf"].mean(), at["ST_conf"].mean()])),
            }
        )
    return pd.DataFrame(rows)


def fitted_rows(table: pd.DataFrame) -> pd.DataFrame:
    """The rows of the convergence `table` the Monte Carlo rate is fitted to: from FIT_FROM base points
    up (the last one if the sample is smaller)."""
    fitted = table[table["base_points"] >= FIT_FROM]
    return table.tail(1) if fitted.empty else fitted


def change_scale(table: pd.DataFrame) -> float:
    """c in largest change = c / sqrt(N), the Monte Carlo rate, fitted (in logs) to the changes of
    `fitted_rows`."""
    fitted = fitted_rows(table)
    return float(np.exp(np.mean(np.log(fitted["largest_change"] * np.sqrt(fitted["base_points"])))))


def stable_base_points(table: pd.DataFrame) -> int:
    """The sample (a power of two of base points) at which the largest change would fall to STABLE_TO
    at the fitted Monte Carlo rate (`change_scale`)."""
    needed = (change_scale(table) / STABLE_TO) ** 2
    return int(2 ** math.ceil(math.log2(max(needed, 1.0))))
