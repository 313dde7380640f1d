"""amplitudes.md: set 1 from imperfections of measured size, from the study's tables (per level, the
matching amplitudes, the hinges there, the DEM confirmations); `scripts/imperfection_amplitudes.py`
writes them."""

from __future__ import annotations

import math

import pandas as pd

from yadearch.studies.imperfections.amplitudes import LEVEL, PLAUSIBLE

COMMAND = ".venv/bin/python scripts/imperfection_amplitudes.py"


def _match_text(match: pd.Series, target: float) -> str:
    if math.isnan(match.amplitude):
        return f"no amplitude up to the largest brings the median du down to {target} mm"
    low, high = PLAUSIBLE[match.kind][0]
    verdict = "plausible" if low <= match.amplitude <= high else "NOT plausible"
    return (
        f"median du = {target} mm at {match.amplitude:.3g} {match.unit} (95 % bootstrap interval over the seeds "
        f"{match.low:.3g}-{match.high:.3g}); {verdict} for set 1 ({low:g}-{high:g}: {PLAUSIBLE[match.kind][1]})"
    )


def amplitudes_markdown(
    levels: pd.DataFrame,
    matches: pd.DataFrame,
    hinges: pd.DataFrame,
    confirmations: pd.DataFrame,
    perfect_du_mm: float,
    target: float,
    figure: str,
    kept: bool = False,
    arguments: str = "",
) -> str:
    """The study's report: per kind its levels, the matching amplitude and whether it is plausible,
    the hinges at the nearest level against set 1's experiment, then the DEM confirmations (`kept`: read
    back from an earlier run, not made by this one); `arguments` name the DEM's settings in its command."""
    lines = [
        "# Set 1 from imperfections of measured size",
        "",
        f"The accurate arch (set 2's kn, static engine; perfect arch {perfect_du_mm:.2f} mm) with each kind of "
        f"defect at several amplitudes, the same seeds at every level. Target: set 1's experiment, {target} mm. "
        "An arch that cannot stand under its own weight counts as du = 0. Regenerate: "
        f"`{COMMAND}{arguments}`.",
        "",
    ]
    for match in matches.itertuples():
        rows = levels[levels["kind"] == match.kind]
        lines += [
            f"## {match.kind}: {match.title}",
            "",
            f"Amplitude in {match.unit}; {_match_text(match, target)}. "
            f"Static campaign: {match.static_wall_s:.0f} s on two cores (over its sessions).",
            "",
            "| amplitude | samples | cannot stand | median du (mm) | median's 95 % interval | 5-95 % band |",
            "|---|---|---|---|---|---|",
        ]
        lines += [
            f"| {r[LEVEL]:g} | {r.samples} | {r.cannot_stand} | {r.median_du_mm:.2f} | {r.median_low_mm:.2f}-"
            f"{r.median_high_mm:.2f} | {r.low_du_mm:.2f}-{r.high_du_mm:.2f} |"
            for _, r in rows.iterrows()
        ]
        at = hinges[hinges["kind"] == match.kind]
        lines += [
            "",
            f"Hinges at amplitude {match.level:g} against set 1's experiment:",
            "",
            "| hinge | experiment | samples within one interface | most frequent interfaces |",
            "|---|---|---|---|",
        ]
        lines += [f"| {r.hinge} | {r.experiment} | {r.within_one:.0%} | {r.most_frequent} |" for r in at.itertuples()]
        lines.append("")
    if not confirmations.empty:
        source = " (kept from the last run with the DEM, confirmations.csv)" if kept else ""
        lines += [
            f"## DEM confirmations (same seeds){source}",
            "",
            "| kind | amplitude | seeds | static median (mm) | DEM median (mm) | DEM - static | within 3 % "
            "| DEM time (s) | static time (s) |",
            "|---|---|---|---|---|---|---|---|---|",
        ]
        lines += [
            f"| {r.kind} | {r[LEVEL]:g} | {r.seeds} | {r.static_median_du_mm:.2f} | {r.dem_median_du_mm:.2f} "
            f"| {r.difference_pct:+.2f} % | {'yes' if r.within else 'NO'} | {r.dem_wall_s:.0f} | "
            f"{r.static_wall_s:.0f} |"
            for _, r in confirmations.iterrows()
        ]
        lines.append("")
    lines += [f"![median du against each amplitude]({figure}.png)", ""]
    return "\n".join(lines)
