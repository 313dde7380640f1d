"""A campaign's progress bar: its runs done out of all, starting where a killed or finished campaign
left off, and one line saying how many finished runs it kept."""

from __future__ import annotations

import sys
from pathlib import Path

from tqdm import tqdm

TERMINAL_INTERVAL_S = 0.1  # tqdm's own: a bar redrawn in place
LOG_INTERVAL_S = 10.0  # a log or a pipe keeps every redraw: one every 10 s, so the last is not doubled


def campaign_bar(out: Path, total: int, todo: int, progress: bool) -> tqdm:
    """The bar of a campaign in `out` of `total` runs with `todo` still to make; where some were kept
    from an earlier invocation (a resumed campaign), a line says so before the bar starts."""
    kept = total - todo
    if progress and kept:
        tqdm.write(f"{out.name}: {kept} of {total} runs already made in {out} kept ({todo} to make)")
    interval = TERMINAL_INTERVAL_S if sys.stderr.isatty() else LOG_INTERVAL_S
    return tqdm(
        total=total,
        initial=kept,
        unit="run",
        disable=not progress,
        desc=out.name,
        dynamic_ncols=True,
        mininterval=interval,
    )
