"""The sensitivity study of any case as campaigns (either engine): the one-at-a-time runs and the
Sobol sample, resumable, then the tables, figures and report (`yadearch sensitivity`,
`ya.sensitivity`; docs/validation-imperfections.md, "What du is sensitive to")."""

from __future__ import annotations

import time
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.analysis.samples import collapse_displacement
from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case.config import ArchCase
from yadearch.case.numerics_section import SUMMARY_RUN_FILES
from yadearch.launch.process import STATIC_ENGINE
from yadearch.markdown import markdown_table
from yadearch.plotting.sensitivity import convergence_figure, indices_figure, tornado_figure
from yadearch.studies.campaigns.executors import Pool
from yadearch.studies.campaigns.runner import run_campaign
from yadearch.studies.dem_settings import NO_DEM_SETTINGS
from yadearch.studies.sensitivity.checks import check_count, checks_markdown, run_checks
from yadearch.studies.sensitivity.indices import (
    PAPER_FACTORS,
    STABLE_TO,
    Factor,
    change_scale,
    check_base_points,
    check_factors,
    convergence,
    fitted_rows,
    sample_sizes,
    sobol_indices,
    sobol_rows,
    stable_base_points,
    tornado_rows,
    tornado_table,
)

TORNADO_RUNS = "tornado_runs"
SOBOL_RUNS = "runs"
TORNADO_TABLE = "tornado.csv"
INDICES_TABLE = "indices.csv"
CONVERGENCE_TABLE = "convergence.csv"
CHECKS_TABLE = "checks.csv"
SAMPLES_TABLE = "samples.csv"
REPORT = "sensitivity.md"
TORNADO_FIGURE = "tornado"
INDICES_FIGURE = "indices"
CONVERGENCE_FIGURE = "convergence"
# a first look within 10 minutes on two cores (docs/validation-imperfections.md); its report says what N would be stable
DEFAULT_BASE_POINTS = 128


@dataclass(frozen=True)
class SensitivityResult:
    """The study as Python objects: the tornado table, the indices on nested samples up to N base
    points, their convergence (largest index change at each doubling), the Sobol sample's runs, and
    the checks by the other engine."""

    tornado: pd.DataFrame
    indices: pd.DataFrame
    convergence: pd.DataFrame
    samples: pd.DataFrame
    checks: pd.DataFrame  # the one-at-a-time runs made again on the other engine (`sensitivity_check`)

    @property
    def shift(self) -> float:
        """The largest change of an index from N/2 to N base points."""
        return float(self.convergence["largest_change"].iloc[-1])

    @property
    def stable(self) -> bool:
        return self.shift <= STABLE_TO

    @property
    def stable_base_points(self) -> int:
        """The sample that would make the indices stable, extrapolated (`sensitivity.stable_base_points`)."""
        return stable_base_points(self.convergence)


def run_sensitivity(
    base: ArchCase,
    out: Path,
    pool: Pool,
    base_points: int = DEFAULT_BASE_POINTS,
    factors: tuple[Factor, ...] = PAPER_FACTORS,
    timeout_s: float | None = None,
    progress: bool = True,
    check_runs: int = 0,
    figures: bool = True,
    check_settings: Mapping[str, Any] = NO_DEM_SETTINGS,
) -> SensitivityResult:
    """Run (or resume) the one-at-a-time runs in OUT/tornado_runs, Saltelli's sample of `base_points`
    in OUT/runs (its folders keep only their summaries, numerics.run_files; static runs keep no
    folders, `campaigns.lean`) and the `check_runs`
    one-at-a-time runs that move du most again on the other engine (with `check_settings`) in OUT/check_runs; write the
    tables, figures and sensitivity.md; return the result."""
    check_base_points(base_points)
    check_factors(base, factors)
    check_count(check_runs)
    out = Path(out)
    started = time.time()
    # a static run's failure (an arch that cannot stand) is deterministic: it is not made again
    retry = base.numerics.engine != STATIC_ENGINE

    def campaign(case: ArchCase, rows: list[dict], folder: str, folders: bool = True) -> pd.DataFrame:
        return run_campaign(
            case, rows, out / folder, pool, timeout_s=timeout_s, progress=progress, retry_failed=retry, folders=folders
        )

    tornado_results = campaign(base, tornado_rows(base, factors), TORNADO_RUNS)
    # thousands of runs of which only du is read: their folders keep only the summary, and static
    # runs keep none (their rows in OUT/runs/batches, `campaigns.lean`)
    lean = base.with_overrides({"numerics.run_files": SUMMARY_RUN_FILES})
    samples = campaign(lean, sobol_rows(factors, base_points), SOBOL_RUNS, folders=False)
    tornado = tornado_table(base, factors, tornado_results)
    checks = run_checks(base, tornado_results, factors, check_runs, out, pool, timeout_s, progress, check_settings)
    du = collapse_displacement(samples)
    indices = pd.concat([sobol_indices(factors, du, n) for n in sample_sizes(base_points)], ignore_index=True)
    result = SensitivityResult(tornado, indices, convergence(indices), samples, checks)
    if checks.empty:  # a table of checks is the last invocation's, like the report
        (out / CHECKS_TABLE).unlink(missing_ok=True)
    else:
        write_csv_atomically(out / CHECKS_TABLE, checks)
    write_csv_atomically(out / TORNADO_TABLE, tornado)
    write_csv_atomically(out / INDICES_TABLE, indices)
    write_csv_atomically(out / CONVERGENCE_TABLE, result.convergence)
    write_csv_atomically(out / SAMPLES_TABLE, samples)
    if figures:
        draw_figures(out, tornado, indices, result.convergence, factors)
    text = sensitivity_markdown(base, factors, result, time.time() - started, pool.slots)
    if not figures:  # no links to figures not drawn (or to a resumed folder's older ones)
        text = "\n".join(line for line in text.split("\n") if not line.startswith("![")) + "\n"
    write_text_atomically(out / REPORT, text)
    return result


def draw_figures(
    out: Path, tornado: pd.DataFrame, indices: pd.DataFrame, table: pd.DataFrame, factors: tuple[Factor, ...]
) -> None:
    """The study's three figures in `out`: the tornado, the indices and their convergence (`table`)."""
    tornado_figure(tornado, out / TORNADO_FIGURE)
    indices_figure(indices, {f.name: f.label for f in factors}, out / INDICES_FIGURE)
    convergence_figure(
        table, STABLE_TO, change_scale(table), int(fitted_rows(table)["base_points"].iloc[0]), out / CONVERGENCE_FIGURE
    )


def redraw_figures(out: Path, factors: tuple[Factor, ...] = PAPER_FACTORS) -> None:
    """The figures again from the tables a study wrote in `out` (a change of the figures, no run)."""
    out = Path(out)
    tornado, indices, table = (pd.read_csv(out / name) for name in (TORNADO_TABLE, INDICES_TABLE, CONVERGENCE_TABLE))
    draw_figures(out, tornado, indices, table, factors)


def sensitivity_markdown(
    base: ArchCase, factors: tuple[Factor, ...], result: SensitivityResult, wall_s: float, slots: int
) -> str:
    """sensitivity.md: the factors and ranges, the tornado, the indices at both sample sizes, whether
    they are stable, and what the runs cost."""
    samples = result.samples
    done = samples[samples["status"] == "done"]
    fell = int(((samples["status"] == "failed") & (collapse_displacement(samples) == 0.0)).sum())
    largest = result.indices["base_points"].max()
    fine = result.indices[result.indices["base_points"] == largest].set_index("factor")
    coarse = result.indices[result.indices["base_points"] == largest // 2].set_index("factor")
    lines = [
        f"# What du is sensitive to: {base.name}",
        "",
        f"{base.numerics.engine} engine; base case du = {result.tornado['du_base_mm'].iloc[0]:.2f} mm. "
        "Each factor is drawn over its plausible range (uniform; kn log-uniform; counts and seeds over "
        "integers); the imperfection draw is the seed of the random defects.",
        "",
        "## One at a time (tornado)",
        "",
        *markdown_table(
            ["factor", "base", "range", "du at low (mm)", "du at high (mm)", "swing (mm)"],
            (
                [r.label, f"{r.base:g}", f"{r.low:g}-{r.high:g}", f"{r.du_low_mm:.2f}", f"{r.du_high_mm:.2f}"]
                + [f"{r.swing_mm:.2f}"]
                for r in result.tornado.itertuples()
            ),
        ),
    ]
    lines += [
        "",
        f"![tornado]({TORNADO_FIGURE}.png)",
        "",
        *checks_markdown(result.checks, base.numerics.engine),
        "## Sobol indices (all factors at once)",
        "",
        f"Saltelli's sample with SALib: {largest} base points x {len(factors) + 2} runs = {len(samples)} runs, "
        f"{len(done)} done; {int(fine['used_points'].iloc[0])} base points with every run done enter the "
        f"estimate. {fell} runs found an arch that cannot stand under its own weight (du = 0 in the "
        f"estimate), {int((samples['status'] == 'failed').sum()) - fell} failed otherwise, "
        f"{int((~done['collapsed'].astype(bool)).sum())} stood to the end of the path (both left out).",
        "",
        *markdown_table(
            ["factor", "S1", "ST", f"S1 at {largest // 2}", f"ST at {largest // 2}"],
            (
                [label, f"{f.S1:.3f} ± {f.S1_conf:.3f}", f"{f.ST:.3f} ± {f.ST_conf:.3f}", f"{c.S1:.3f}", f"{c.ST:.3f}"]
                for label, f, c in (
                    (factor.label, fine.loc[factor.name], coarse.loc[factor.name])
                    for factor in sorted(factors, key=lambda f: -fine.loc[f.name, "ST"])
                )
            ),
        ),
    ]
    verdict = "stable" if result.stable else "NOT stable"
    needed = result.stable_base_points
    needed_runs = f"{needed} base points ({needed * (len(factors) + 2)} runs)"
    fitted = fitted_rows(result.convergence)
    first = int(fitted["base_points"].iloc[0])
    fit = f"fitted from {first} base points up" if len(fitted) > 1 else f"from the one change at {first} base points"
    lines += [
        "",
        f"Largest change of an index as the sample doubles: {result.shift:.3f} ({verdict}: "
        f"target {STABLE_TO}). ± is SALib's bootstrap 95 % interval.",
        "",
        f"![Sobol indices]({INDICES_FIGURE}.png)",
        "",
        "## Convergence",
        "",
        "The indices on the nested samples (each the first half of the next): the largest change of any "
        "index since the half-size sample, and the indices' mean bootstrap half-width.",
        "",
        *markdown_table(
            ["base points", "runs", "largest change", "mean ±"],
            (
                [f"{r.base_points}", f"{r.base_points * (len(factors) + 2)}", f"{r.largest_change:.3f}"]
                + [f"{r.mean_half_width:.3f}"]
                for r in result.convergence.itertuples()
            ),
        ),
        "",
        (
            f"The last doubling moved no index by more than {STABLE_TO}. The changes are Monte Carlo errors "
            f"and not monotone: fitted as 1/sqrt(N) {fit}, they stay below {STABLE_TO} from about {needed_runs}."
            if result.stable
            else f"If the largest change falls as 1/sqrt(N), as a Monte Carlo error does ({fit}), the indices are "
            f"stable to {STABLE_TO} at about {needed_runs}."
        ),
        "",
        f"![convergence]({CONVERGENCE_FIGURE}.png)",
        "",
        f"Cost: {done['wall_s'].sum():.0f} s of runs ({len(done)} runs, median {done['wall_s'].median():.2f} s); "
        f"this invocation {wall_s:.0f} s on {slots} process(es) (runs already in the folder are reused).",
        "",
    ]
    return "\n".join(lines)
