"""A campaign's progress bar: its runs done out of all, starting where a killed or finished campaign
left off, and one line saying how many finished runs it kept."""

from __future__ import annotations

from pathlib import Path

from tqdm import tqdm


def campaign_bar(out: Path, total: int, todo: int, progress: bool) -> tqdm:
    """The bar of a campaign in `out` of `total` runs with `todo` still to make; where some were kept
    from an earlier invocation (a resumed campaign), a line says so before the bar starts."""
    kept = total - todo
    if progress and kept:
        tqdm.write(f"{out.name}: {kept} of {total} runs already made in {out} kept ({todo} to make)")
    return tqdm(total=total, initial=kept, unit="run", disable=not progress, desc=out.name, dynamic_ncols=True)
