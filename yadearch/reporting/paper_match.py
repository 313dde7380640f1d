"""Which runs are the paper's case and which of its sets they reproduce, and how their hinges pair
with the paper's Table 1 (`yadearch report`)."""

from __future__ import annotations

import math
from typing import Any

from yadearch.analysis.tracking import format_interfaces
from yadearch.case import reference
from yadearch.case.paper import paper_mismatch
from yadearch.results.summary import HingeRef, RunSummary

KN_MATCH_RELATIVE = 1e-6  # a run's kn equals a set's within this relative difference


def match_reference(case: dict[str, Any], summary: RunSummary) -> str | None:
    """The paper set a run reproduces: only a run of the paper's case (`paper_mismatch`) at a set's kn
    (N/mm3); its name plays no part (a run named set1 at kn 0.5 is not the paper's set 1)."""
    if paper_mismatch(case) is not None:
        return None
    kn = summary.kn_N_per_mm3
    for name, ref in reference.SETS.items():
        if kn is not None and math.isclose(kn, ref["kn_N_per_mm3"], rel_tol=KN_MATCH_RELATIVE):
            return name
    return None


def hinge_text(interfaces: list[int], side: str) -> str:
    """A paper hinge as the report writes it, e.g. "28-30 E"."""
    return f"{format_interfaces(interfaces)} {side}"


def interface_difference(run_interface: int, paper: list[int]) -> str:
    """Interfaces between the run's hinge and the paper's (0 inside a spread hinge's range)."""
    below, above = run_interface - min(paper), run_interface - max(paper)
    gap = 0 if below >= 0 >= above else (below if below < 0 else above)
    return f"{gap:+d}" if gap else "0"


def match_hinges(
    summary_hinges: tuple[HingeRef, ...], paper_rows: list[tuple[str, list[int], str]]
) -> dict[str, HingeRef | None]:
    """Each paper hinge (row, interfaces, side) paired with the run's hinge of the same side nearest
    to it; a run hinge is used once, rows in the order given."""
    free = list(summary_hinges)
    pairs: dict[str, HingeRef | None] = {}
    for row, interfaces, side in paper_rows:
        same = [h for h in free if h.side == side]
        best = min(same, key=lambda h: min(abs(h.interface - k) for k in interfaces), default=None)
        pairs[row] = best
        if best is not None:
            free.remove(best)
    return pairs
