"""Set 1 from imperfections of measured size: each kind of voussoir defect the model has, and one
combination of them, drawn at several amplitudes with many seeds, to find the amplitude at which the
accurate arch's median du falls to set 1's experiment (docs/validation-imperfections.md, "Set 1 from imperfections
of measured size").

A kind scales a fixed pattern of case parameters by its amplitude (`Kind.overrides`), so one
amplitude means the same thing in every sample; sample i of every level uses seed FIRST_SEED + i,
so the levels compare the same defect pattern, scaled. An arch that cannot stand under its own
weight counts as du = 0 (`montecarlo.collapse_displacement`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd

from yadearch.analysis.samples import collapse_displacement, du_statistics, hinge_frequencies
from yadearch.studies.campaigns.grid import RUN_COLUMN, round_sig
from yadearch.studies.imperfections.matching import amplitude_for, paired_amplitude_interval
from yadearch.studies.montecarlo import SEED_KEY

FIRST_SEED = 1
LEVEL = "amplitude"  # the column of a campaign table that holds each run's amplitude
AMPLITUDE_DIGITS = 6


@dataclass(frozen=True)
class Kind:
    """One kind of defect: case parameters at amplitude 1 (`unit`), scaled together by each level."""

    name: str
    title: str
    unit: dict[str, float]
    levels: tuple[float, ...]
    amplitude_unit: str  # what the amplitude is measured in, e.g. "mm" or "x the combination"

    @property
    def axis_label(self) -> str:
        """The amplitude as an axis label: "bump s.d. (mm)" from the unit "mm (sd)"."""
        unit, _, measure = self.amplitude_unit.partition(" (")
        measure = measure.rstrip(")").replace("sd", "s.d.")
        return f"{self.name} {measure} ({unit})" if measure else f"{self.name} ({unit})"

    def overrides(self, level: float) -> dict[str, float]:
        """The case parameters at amplitude `level`."""
        return {f"imperfections.{key}": round_sig(level * value, AMPLITUDE_DIGITS) for key, value in self.unit.items()}


# Amplitudes: from below what a careful maker achieves to beyond what the DEM study found for set 1
# (docs/validation-imperfections.md gives the measured sizes these are read against).
KINDS = (
    Kind(
        "bump",
        "faces not flat (out-of-flatness, random per joint)",
        {"face_bump_sd_mm": 1.0},
        (0.05, 0.1, 0.14, 0.18, 0.22, 0.26),
        "mm (sd)",
    ),
    Kind(
        "edge",
        "worn edges (rounded, size varying between edges by a quarter)",
        {"edge_radius_mm": 1.0, "edge_radius_sd_mm": 0.25},
        (1.0, 2.0, 2.5, 3.0, 4.0),
        "mm (mean radius)",
    ),
    Kind(
        "angle",
        "faces not parallel (random per joint)",
        {"face_angle_sd_mrad": 1.0},
        (2.0, 4.0, 8.0, 16.0, 32.0),
        "mrad (sd)",
    ),
    Kind(
        "offset",
        "voussoirs set off their neighbours (random per voussoir)",
        {"voussoir_offset_sd_mm": 1.0},
        (0.25, 0.5, 1.0, 1.5, 2.0, 3.0),
        "mm (sd)",
    ),
    Kind(
        "dimensions",
        "voussoirs longer or shorter and thicker or thinner (random per voussoir)",
        {"voussoir_length_sd_mm": 1.0, "voussoir_thickness_sd_mm": 1.0},
        (0.05, 0.1, 0.2, 0.3, 0.4),
        "mm (sd)",
    ),
    Kind(
        "combined",
        "all of them at once: bumps 0.05, edges 0.75 (sd 0.19), angles 2 mrad, offsets, lengths "
        "and thicknesses 0.15 mm at amplitude 1",
        {
            "face_bump_sd_mm": 0.05,
            "edge_radius_mm": 0.75,
            "edge_radius_sd_mm": 0.1875,
            "face_angle_sd_mrad": 2.0,
            "voussoir_offset_sd_mm": 0.15,
            "voussoir_length_sd_mm": 0.15,
            "voussoir_thickness_sd_mm": 0.15,
        },
        (0.5, 1.0, 1.5, 2.0, 3.0),
        "x the pattern",
    ),
)


# What a hand-made set like set 1 plausibly has (aluminium matrices milled by hand, blocks cast in a
# deformable silicone mould, not vibrated; set 2's CNC matrices: +-0.05 mm): the range of each
# kind's amplitude, and why (docs/validation-imperfections.md).
PLAUSIBLE = {
    "bump": ((0.05, 0.25), "faces cast against a deformable mould, not vibrated: bulges and pits of a few tenths"),
    "edge": ((0.5, 2.0), "the paper's 'less sharp corners'; 3 mm would round off a quarter of a 24 mm face"),
    "angle": ((1.0, 8.0), "manual milling to about +-0.1 mm across a 24 mm face is about 4 mrad"),
    "offset": ((0.1, 0.5), "voussoirs placed by hand against their neighbours"),
    "dimensions": (
        (0.1, 0.5),
        "manual milling and the casting's shrinkage (above 0.45 mm the errors, summed "
        "along the arch, move a joint half-way to its neighbour: no arch)",
    ),
    "combined": ((1.0, 2.5), "each part within its own plausible range from amplitude 1 to 2.5"),
}


def kind_rows(kind: Kind, samples: int, levels: tuple[float, ...] | None = None) -> list[dict[str, Any]]:
    """The campaign's rows: `samples` seeds at each level (the kind's own levels unless given)."""
    rows = []
    for level in levels or kind.levels:
        for i in range(samples):
            rows.append(
                {**kind.overrides(level), SEED_KEY: FIRST_SEED + i, RUN_COLUMN: f"a{level:g}_s{FIRST_SEED + i}"}
            )
    return rows


def with_levels(kind: Kind, results: pd.DataFrame) -> pd.DataFrame:
    """A campaign's results with each run's amplitude (LEVEL), seed, and du for the statistics
    (`du_stat_mm`: 0 where the arch cannot stand under its own weight)."""
    table = results.copy()
    table[LEVEL] = table[RUN_COLUMN].str.extract(r"^a([^_]+)_s")[0].astype(float)
    table["seed"] = table[RUN_COLUMN].str.extract(r"_s(\d+)$")[0].astype(int)
    table["du_stat_mm"] = collapse_displacement(table)
    return table


def level_summary(kind: Kind, table: pd.DataFrame) -> pd.DataFrame:
    """Per level: samples, how many cannot stand, median du with its 95 % interval, 5-95 % band."""
    rows = []
    for level, group in table.groupby(LEVEL, sort=True):
        stats = du_statistics(group["du_stat_mm"])
        rows.append(
            {
                "kind": kind.name,
                LEVEL: level,
                "samples": stats["n"],
                "cannot_stand": int((group["du_stat_mm"] == 0.0).sum()),
                "median_du_mm": stats["median"],
                "median_low_mm": stats["median_low"],
                "median_high_mm": stats["median_high"],
                "low_du_mm": stats["low"],
                "high_du_mm": stats["high"],
            }
        )
    return pd.DataFrame(rows)


@dataclass(frozen=True)
class Match:
    """The amplitude at which a kind's median du reaches the target, and its 95 % bootstrap interval
    over the seeds (nan where no two levels bracket the target)."""

    amplitude: float
    low: float
    high: float


def matching_amplitude(summary: pd.DataFrame, table: pd.DataFrame, target_du_mm: float, perfect_du_mm: float) -> Match:
    """Where the median du (linear between levels, from the perfect arch at amplitude 0) reaches
    `target_du_mm`, with the bootstrap interval of the seeds' paired medians."""
    rows = [{"level": 0.0, "median_du_mm": perfect_du_mm}] + [
        {"level": r[LEVEL], "median_du_mm": r.median_du_mm} for _, r in summary.iterrows()
    ]
    amplitude = amplitude_for(rows, target_du_mm)
    if math.isnan(amplitude):
        return Match(math.nan, math.nan, math.nan)
    paired = table.assign(du_mm=table["du_stat_mm"], status="done")
    low, high = paired_amplitude_interval([paired], LEVEL, target_du_mm)
    return Match(amplitude, low, high)


def nearest_level(summary: pd.DataFrame, amplitude: float) -> float:
    """The swept level closest to `amplitude` (the largest level where it is nan)."""
    levels = summary[LEVEL].to_numpy(dtype=float)
    return float(levels.max() if math.isnan(amplitude) else levels[np.abs(levels - amplitude).argmin()])


def hinge_table(table: pd.DataFrame, level: float, observed: dict[str, int]) -> pd.DataFrame:
    """At one level: each paper hinge's most frequent interfaces and the share within one interface of
    `observed` (the experiment's)."""
    group = table[np.isclose(table[LEVEL], level) & (table["status"] == "done")]
    frequencies = hinge_frequencies(group)
    rows = []
    for label, interface in observed.items():
        found = frequencies[frequencies["hinge"] == label].sort_values("count", ascending=False)
        near = int(((group[f"hinge_{label}"].dropna() - interface).abs() <= 1).sum())
        rows.append(
            {
                "hinge": label,
                "experiment": interface,
                "within_one": near / len(group) if len(group) else math.nan,
                "most_frequent": ", ".join(f"{r.interface} ({r.share:.0%})" for r in found.head(3).itertuples()),
            }
        )
    return pd.DataFrame(rows)
