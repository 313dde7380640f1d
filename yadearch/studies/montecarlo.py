"""Monte Carlo campaigns of imperfect arches: one run per seed (and per amplitude level, when
amplitudes are swept), resumable like any campaign, then the distribution of du and of the hinges.

Sample i of a campaign seeded S draws its joints' defects from seed S + i, so a campaign extended
from 100 to 200 samples keeps its first 100 runs. docs/usage.md shows the command.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import fields
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.analysis.samples import (
    BAND,
    COMMON_SHARE,
    MEDIAN_CONFIDENCE,
    collapse_displacement,
    du_statistics,
    hinge_frequencies,
    unlettered_hinges,
)
from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case.config import ArchCase
from yadearch.case.imperfections_section import ImperfectionsConfig
from yadearch.errors import CampaignError
from yadearch.model.hinges import PAPER_LABELS
from yadearch.results.rundir import finished_summary
from yadearch.studies.campaigns.executors import Pool
from yadearch.studies.campaigns.grid import RUN_COLUMN, check_campaign_size, grid, run_tag
from yadearch.studies.campaigns.runner import run_campaign

SEED_KEY = "imperfections.seed"
MONTECARLO_FILE = "montecarlo.csv"
SUMMARY_FILE = "montecarlo.md"


def check_drawn(base: ArchCase, levels: Mapping[str, Sequence[float]]) -> None:
    """CampaignError in one line where no imperfection of `base` or of its amplitude `levels` is drawn at
    random (every standard deviation 0): every sample would be the same arch."""
    drawn = [f.name for f in fields(ImperfectionsConfig) if "_sd_" in f.name]
    if any(getattr(base.imperfections, name) for name in drawn):
        return
    if any(key.split(".")[-1] in drawn and any(v for v in values) for key, values in levels.items()):
        return
    raise CampaignError(
        "no imperfection is drawn at random (every imperfections.*_sd_* is 0): every sample would be the same "
        "arch; give a standard deviation: --set face_bump_sd_mm=0.1 on the command line, "
        "case.replace(face_bump_sd_mm=0.1) in Python"
    )


def sample_rows(samples: int, seed: int, axes: dict[str, list[Any]] | None = None) -> list[dict[str, Any]]:
    """The campaign's rows: `samples` seeds from `seed` at every combination of the swept `axes`,
    named `<amplitudes>_s<seed>` (or `s<seed>` without axes)."""
    if samples < 1:
        raise CampaignError(f"samples must be >= 1, got {samples}")
    check_campaign_size(samples * (len(grid(axes)) if axes else 1))
    rows = []
    for level in grid(axes) if axes else [{}]:
        tag = run_tag(level) if level else ""
        for i in range(samples):
            rows.append({**level, SEED_KEY: seed + i, RUN_COLUMN: f"{tag}_s{seed + i}" if tag else f"s{seed + i}"})
    return rows


def run_montecarlo(
    base: ArchCase,
    out: Path,
    pool: Pool,
    samples: int,
    seed: int,
    axes: dict[str, list[Any]] | None = None,
    timeout_s: float | None = None,
    progress: bool = True,
) -> pd.DataFrame:
    """Run (or resume) the campaign into `out`, then write montecarlo.csv (results with each
    sample's imperfection summary) and montecarlo.md; returns the table."""
    out = Path(out)
    results = run_campaign(base, sample_rows(samples, seed, axes), out, pool, timeout_s=timeout_s, progress=progress)
    return write_montecarlo(results, out, axes, about_text(base, samples, seed))


def about_text(base: ArchCase, samples: int, seed: int) -> str:
    """What a campaign samples, in a line: the case, its engine, the defects drawn and the seeds."""
    drawn = [
        f"{f.name} {getattr(base.imperfections, f.name):g}" for f in fields(ImperfectionsConfig) if "_sd_" in f.name
    ]
    drawn = [d for d in drawn if not d.endswith(" 0")]
    return (
        f"Case {base.name!r} ({base.numerics.engine} engine, {base.geometry.shape} arch of {base.geometry.n_voussoirs} "
        f"voussoirs); standard deviations drawn: {', '.join(drawn) or 'those of the swept levels'}; seeds "
        f"{seed}-{seed + samples - 1}."
    )


def write_montecarlo(
    results: pd.DataFrame, out: Path, axes: dict[str, list[Any]] | None, about: str = ""
) -> pd.DataFrame:
    """montecarlo.csv and montecarlo.md of a campaign from its results table (finished or not: a
    stopped campaign's results.csv lists its unfinished samples as pending; `about`: what it samples);
    returns the table."""
    table = with_imperfections(results, out)
    write_csv_atomically(out / MONTECARLO_FILE, table)
    write_text_atomically(out / SUMMARY_FILE, summary_markdown(table, levels(table, axes), about))
    return table


def with_imperfections(results: pd.DataFrame, out: Path) -> pd.DataFrame:
    """The campaign's results with each finished run's imperfection summary (summary.json)."""
    extra = []
    for _, row in results.iterrows():
        summary = finished_summary(out / row["folder"])
        extra.append((summary.imperfections if summary else None) or {})
    return pd.concat([results.reset_index(drop=True), pd.DataFrame(extra)], axis=1)


def levels(table: pd.DataFrame, axes: dict[str, list[Any]] | None) -> list[str]:
    """The table's columns of the swept amplitudes (empty without axes)."""
    return [key.split(".")[-1] for key in axes or {} if key.split(".")[-1] in table.columns]


def outcomes_text(du: pd.Series) -> str:
    """How the samples ended, from their du (`collapse_displacement`: 0 cannot stand, NaN no du)."""
    fell, missing = int((du == 0.0).sum()), int(du.isna().sum())
    return (
        f"{len(du)} samples: {len(du) - fell - missing} collapsed, {fell} cannot stand under their own weight "
        f"(du 0 in the statistics), {missing} without a du (failed, unresolved or standing to the path's end)"
    )


def summary_markdown(table: pd.DataFrame, level_columns: list[str], about: str = "") -> str:
    """The campaign as Markdown (`about`: what was sampled, a line under the title): du's distribution
    (per amplitude level; an arch that cannot stand counts as du 0, as in the sensitivity study) and the
    hinge positions."""
    low, high = (f"{q:.0%}" for q in BAND)
    du = collapse_displacement(table)  # an arch that cannot stand: 0
    lines = [
        "# Monte Carlo of imperfect arches",
        "",
        *([about, ""] if about else []),
        f"{outcomes_text(du)}.",
        "",
        f"| {' | '.join(level_columns) + ' | ' if level_columns else ''}samples | median du (mm) "
        f"| median's {MEDIAN_CONFIDENCE:.0%} interval (mm) | {low}-{high} band (mm) | mean (mm) |",
        "|" + "---|" * (len(level_columns) + 5),
    ]
    keys = (
        table[level_columns].drop_duplicates().sort_values(level_columns).itertuples(index=False)
        if level_columns
        else [()]
    )
    for key in keys:
        level = pd.Series(
            tuple(key), index=level_columns, dtype=object
        )  # aligned on the columns (a tuple is deprecated)
        group = table[(table[level_columns] == level).all(axis=1)] if level_columns else table
        stats = du_statistics(du[group.index])
        prefix = "".join(f"{value:g} | " for value in key)
        interval = (
            f"{stats['median_low']:.2f}-{stats['median_high']:.2f}" if math.isfinite(stats["median_low"]) else "—"
        )  # too few samples for it
        lines.append(
            f"| {prefix}{stats['n']} | {stats['median']:.2f} | {interval} | {stats['low']:.2f}-{stats['high']:.2f} "
            f"| {stats['mean']:.2f} |"
        )
    collapsed = table[(table["status"] == "done") & table["du_mm"].notna()]  # as the hinge figure counts them
    lines += ["", f"Hinge positions (interface: share of the {len(collapsed)} samples that collapsed):", ""]
    frequencies = hinge_frequencies(collapsed)
    for label in PAPER_LABELS:
        rows = frequencies[frequencies["hinge"] == label]
        listed = ", ".join(f"{r.interface}: {r.share:.0%}" for r in rows.itertuples())
        lines.append(f"- {label}: {listed or 'none'}")
    others = unlettered_hinges(collapsed)
    if len(others):
        common = others[others["share"] >= COMMON_SHARE]
        listed = ", ".join(f"{r.interface}{r.side}: {r.share:.0%}" for r in common.itertuples()) or "none"
        rest = len(others) - len(common)
        rare = (
            f"; {rest} other position{'s' * (rest > 1)}, each in under {COMMON_SHARE:.0%} of the samples"
            if rest
            else ""
        )
        lines.append(f"- without a letter (a second intrados hinge, a fifth hinge): {listed}{rare}")
    return "\n".join(lines) + "\n"
