"""Statistics of a set of runs of one arch (Monte Carlo samples, a study's level): du's median with
a distribution-free interval and its band, how often each paper hinge forms where, and du for
statistics in which an arch that cannot stand under its own weight carries nothing."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
from scipy.stats import binom

from yadearch.case.reference import HINGE_SIDES
from yadearch.errors import CANNOT_STAND
from yadearch.model.hinges import PAPER_LABELS

BAND = (0.05, 0.95)  # the quantiles of du's band
MEDIAN_CONFIDENCE = 0.95  # of the interval that brackets the median du
COMMON_SHARE = 0.5  # a hinge without a paper letter is shown where at least this share of the samples form it


def du_statistics(du: pd.Series) -> dict[str, float]:
    """Count, median, band, mean and the median's confidence interval of the finished samples' du (mm)."""
    values = du.dropna().to_numpy(dtype=float)
    if values.size == 0:
        return {
            "n": 0,
            "median": math.nan,
            "low": math.nan,
            "high": math.nan,
            "mean": math.nan,
            "median_low": math.nan,
            "median_high": math.nan,
        }
    low, high = np.quantile(values, BAND)
    median_low, median_high = median_interval(values)
    return {
        "n": int(values.size),
        "median": float(np.median(values)),
        "low": float(low),
        "high": float(high),
        "mean": float(values.mean()),
        "median_low": median_low,
        "median_high": median_high,
    }


def median_interval(values: np.ndarray, confidence: float = MEDIAN_CONFIDENCE) -> tuple[float, float]:
    """Distribution-free interval that holds the true median with at least `confidence`: the order
    statistics whose ranks the binomial(n, 1/2) law puts around the middle; nan if n is too small."""
    n = len(values)
    rank = int(binom.ppf((1.0 - confidence) / 2.0, n, 0.5))  # lower order statistic, 1-based
    if n == 0 or rank < 1:
        return math.nan, math.nan
    ordered = np.sort(values)
    return float(ordered[rank - 1]), float(ordered[n - rank])


def hinge_frequencies(table: pd.DataFrame) -> pd.DataFrame:
    """How often each of the hinges A-D formed at each interface: one row a (label, interface)."""
    rows = []
    done = table[table["status"] == "done"]
    for label in PAPER_LABELS:
        counts = done[f"hinge_{label}"].dropna().astype(int).value_counts()
        for interface, count in sorted(counts.items()):
            rows.append(
                {
                    "hinge": label,
                    "interface": interface,
                    "count": int(count),
                    "share": count / len(done) if len(done) else math.nan,
                }
            )
    return pd.DataFrame(rows, columns=["hinge", "interface", "count", "share"])


def unlettered_hinges(table: pd.DataFrame) -> pd.DataFrame:
    """How often each hinge without a paper letter (a second intrados hinge, a fifth hinge) formed at
    each interface and side: one row an (interface, side), as `hinge_frequencies` counts the lettered."""
    done = table[table["status"] == "done"]
    counts: dict[tuple[int, str], int] = {}
    for row in done.itertuples():
        lettered = {(getattr(row, f"hinge_{label}"), HINGE_SIDES[f"hinge_{label}"]) for label in PAPER_LABELS}
        hinges = getattr(row, "hinges", "")
        for token in (hinges if isinstance(hinges, str) else "").split():
            hinge = (int(token[:-1]), token[-1])
            if hinge not in lettered:
                counts[hinge] = counts.get(hinge, 0) + 1
    rows = [
        {"interface": i, "side": side, "count": n, "share": n / len(done)} for (i, side), n in sorted(counts.items())
    ]
    return pd.DataFrame(rows, columns=["interface", "side", "count", "share"])


def collapse_displacement(runs: pd.DataFrame) -> pd.Series:
    """du (mm) of each run, on the runs' index, for statistics and indices: 0 for an arch that cannot
    stand under its own weight (it carries no settlement), nan for a run that failed otherwise or stood
    to the end of its path."""
    collapsed = runs["collapsed"] == True if "collapsed" in runs else runs["du_mm"].notna()  # noqa: E712
    reasons = runs["reason"].fillna("") if "reason" in runs else pd.Series("", index=runs.index)
    done = (runs["status"] == "done") & collapsed
    fell = (runs["status"] == "failed") & reasons.str.contains(CANNOT_STAND, regex=False)
    du = np.where(done, runs["du_mm"], np.where(fell, 0.0, np.nan)).astype(float)
    return pd.Series(du, index=runs.index, name="du_mm")
