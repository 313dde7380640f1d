"""The imperfection study (docs/validation-imperfections.md, "Imperfections instead of a low kn"): how large each
kind of voussoir defect must be to bring the accurate arch's du down to set 1's, the kn that the
low-kn model would need for the same median du, and where the hinges then form.

Pure: it reads campaign tables (montecarlo.csv, the kn sweep's results.csv) and writes Markdown;
`scripts/imperfection_study.py` runs the campaigns.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from yadearch.analysis.run import analyse_run, load_run
from yadearch.analysis.samples import collapse_displacement, du_statistics, hinge_frequencies
from yadearch.analysis.tracking import HingeTrack

BOOTSTRAP_RESAMPLES = 2000  # resamples of the seeds for the interval of a paired amplitude


@dataclass(frozen=True)
class Study:
    """One campaign of the study: an imperfection amplitude swept over `levels`, `samples` seeds
    at each level, on the base case with the `fixed` settings (any case parameter, e.g. kn)."""

    name: str
    title: str
    parameter: str
    levels: tuple[float, ...]
    samples: int
    fixed: dict[str, Any] = field(default_factory=dict)
    perfect_du_mm: float | None = None  # du of its perfect arch when `fixed` changes it (None: the base case's)

    @property
    def axes(self) -> dict[str, list[Any]]:
        return {self.parameter: list(self.levels)}


def equivalent_kn(du_mm: float, sweep: pd.DataFrame) -> float:
    """The smallest kn (N/mm3) at which the perfect arch's du(kn), interpolated linearly in log kn
    between the sweep's points, reaches `du_mm`; nan outside the sweep's range of du."""
    done = sweep[(sweep["status"] == "done") & sweep["du_mm"].notna()].sort_values("kn_N_per_mm3")
    log_kn = np.log(done["kn_N_per_mm3"].to_numpy(dtype=float))
    du = done["du_mm"].to_numpy(dtype=float)
    if math.isnan(du_mm) or du.size == 0:
        return math.nan
    if du_mm <= du[0]:
        return float(np.exp(log_kn[0])) if du_mm == du[0] else math.nan
    for k in range(1, du.size):
        if du[k - 1] < du_mm <= du[k]:
            share = (du_mm - du[k - 1]) / (du[k] - du[k - 1])
            return float(np.exp(log_kn[k - 1] + share * (log_kn[k] - log_kn[k - 1])))
    return math.nan


def modal_hinges(table: pd.DataFrame) -> str:
    """Each hinge's most frequent interface and its share of the samples, e.g. "A 11 (67 %), B 27"."""
    frequencies = hinge_frequencies(table)
    parts = []
    for label, rows in frequencies.groupby("hinge", sort=True):
        listed = ", ".join(
            f"{r.interface} ({r.share:.0%})" for r in rows.sort_values("count", ascending=False).head(2).itertuples()
        )
        parts.append(f"{label} {listed}")
    return "; ".join(parts) or "—"


def level_rows(study: Study, table: pd.DataFrame, sweep: pd.DataFrame) -> list[dict[str, Any]]:
    """Per level of a study: samples, median du and its band, equivalent kn, hinge positions."""
    rows = []
    for level in study.levels:
        group = table[np.isclose(table[study.parameter].astype(float), level)]
        done = group[group["status"] == "done"]
        stats = du_statistics(pd.Series(collapse_displacement(group)))  # an arch that cannot stand: du 0
        rows.append(
            {
                "study": study.name,
                "parameter": study.parameter,
                "level": level,
                "samples": stats["n"],
                "median_du_mm": stats["median"],
                "low_du_mm": stats["low"],
                "high_du_mm": stats["high"],
                "equivalent_kn_N_per_mm3": equivalent_kn(stats["median"], sweep),
                "hinges": modal_hinges(done),
            }
        )
    return rows


def amplitude_for(rows: list[dict[str, Any]], target_du_mm: float) -> float:
    """The amplitude at which the median du reaches `target_du_mm`, interpolated linearly between
    the levels that bracket it (du falls as the amplitude grows); nan if none does."""
    levels = [(r["level"], r["median_du_mm"]) for r in rows if not math.isnan(r["median_du_mm"])]
    for (a0, du0), (a1, du1) in zip(levels, levels[1:]):
        if du1 <= target_du_mm <= du0 and du0 != du1:
            return a0 + (du0 - target_du_mm) / (du0 - du1) * (a1 - a0)
    return math.nan


def paired_du(tables: list[pd.DataFrame], parameter: str) -> pd.DataFrame:
    """du (mm) of the seeds finished at every level, one row a seed and one column a level: a seed's
    draws scale with the amplitude, so the levels compare the same defect pattern sample for sample."""
    done = pd.concat(tables, ignore_index=True)
    done = done[done["status"] == "done"]
    wide = done.pivot_table(index="seed", columns=done[parameter].astype(float), values="du_mm")
    return wide.dropna()


def _level_medians(wide: pd.DataFrame) -> list[dict[str, Any]]:
    """Median du of each level (column) of a seed-by-level table, with the number of seeds."""
    return [{"level": float(a), "samples": len(wide), "median_du_mm": float(wide[a].median())} for a in wide.columns]


def paired_medians(tables: list[pd.DataFrame], parameter: str) -> list[dict[str, Any]]:
    """Median du per level over the seeds finished at every level (`paired_du`)."""
    return _level_medians(paired_du(tables, parameter))


def paired_amplitude_interval(
    tables: list[pd.DataFrame], parameter: str, target_du_mm: float, resamples: int = BOOTSTRAP_RESAMPLES, seed: int = 0
) -> tuple[float, float]:
    """A 95 % bootstrap interval (seeds resampled with replacement) of the amplitude at which the
    paired median du reaches `target_du_mm`; resamples that do not bracket it are left out."""
    wide = paired_du(tables, parameter)
    rng = np.random.default_rng(seed)
    found = []
    for _ in range(resamples):
        found.append(amplitude_for(_level_medians(wide.iloc[rng.integers(0, len(wide), len(wide))]), target_du_mm))
    found = [a for a in found if not math.isnan(a)]
    if not found:
        return math.nan, math.nan
    low, high = np.percentile(found, [2.5, 97.5])
    return float(low), float(high)


def table_markdown(rows: list[dict[str, Any]], unit: str) -> list[str]:
    """A study's levels as a Markdown table."""
    lines = [
        f"| amplitude ({unit}) | samples | median du (mm) | 5-95 % (mm) | equivalent kn (N/mm³) "
        "| hinges (interface, share) |",
        "|---|---|---|---|---|---|",
    ]
    for r in rows:
        kn = r["equivalent_kn_N_per_mm3"]
        lines.append(
            f"| {r['level']:g} | {r['samples']} | {r['median_du_mm']:.2f} | {r['low_du_mm']:.2f}-"
            f"{r['high_du_mm']:.2f} | {'—' if math.isnan(kn) else f'{kn:.3g}'} | {r['hinges']} |"
        )
    return lines


def hinge_agreement(table: pd.DataFrame, observed: dict[str, int], tolerance: int = 1) -> dict[str, float]:
    """Per paper hinge (A-D), the share of finished samples whose hinge sits within `tolerance`
    interfaces of the `observed` one (e.g. set 1's experiment); nan without samples."""
    done = table[table["status"] == "done"]
    shares = {}
    for label, interface in observed.items():
        column = done[f"hinge_{label}"]
        shares[label] = float(((column - interface).abs() <= tolerance).mean()) if len(done) else math.nan
    return shares


TOWARD_CROWN, TOWARD_SPRINGING, STAYED = "toward the crown", "toward the springing", "stayed"


def hinge_shift(tracks: list[HingeTrack], label: str, n_interfaces: int) -> tuple[int, int, str] | None:
    """Where a run's hinge `label` (A-D) formed, where it was at collapse, and which way it moved
    between them (the experiment's A formed at 12 and moved toward the crown); None without it."""
    track = next((t for t in tracks if t.paper_label == label), None)
    if track is None:
        return None
    formed, final = track.hinge_at(track.formed_record).interface, track.interface
    crown = (n_interfaces + 1) / 2
    way = STAYED if formed == final else TOWARD_CROWN if abs(final - crown) < abs(formed - crown) else TOWARD_SPRINGING
    return formed, final, way


def hinge_shifts(folders: list[Path], label: str) -> pd.DataFrame:
    """`hinge_shift` of every finished run folder: folder, formed, final, way."""
    rows = []
    for folder in folders:
        analysis = analyse_run(load_run(folder))
        shift = hinge_shift(analysis.tracks, label, analysis.history.n_interfaces)
        if shift is not None:
            rows.append(dict(zip(("folder", "formed", "final", "way"), (folder.name, *shift), strict=True)))
    return pd.DataFrame(rows, columns=["folder", "formed", "final", "way"])
