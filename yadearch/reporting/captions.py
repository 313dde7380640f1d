"""The report's figure captions: what each figure of a run shows, in words that fit the run (its engine,
its movement, whether it collapsed)."""

from __future__ import annotations

from yadearch.results.summary import STATIC, RunSummary

CAPTIONS = {
    "strip": "Four states of the run at one scale: after the self-weight, at a third and two thirds of "
    "du, and at collapse; open hinges marked with the paper's letters, the line of the joints' "
    "contact-force resultants (the thrust line) in red, the undeformed outline dashed.",
    "collapse": "The arch at collapse (at the upper end of du's bracket, where {how} a block "
    "the runaway bound{bound}), drawn to scale over its undeformed outline (dashed); hinges "
    "labelled A-D by position as in the paper, with interface and pivot side.",
    "reactions": "Forces of the supports on the arch against δ, the driven support's displacement "
    "along its movement; faded past du, where the arch is already moving.",
    "hinges": "Opening (gap at the edge opposite the pivot) and rotation of each hinge against δ; dots "
    "mark formation, the last point is the collapse state.",
    "crown": "Displacement of the crown voussoir against δ (from the unloaded geometry, self-weight "
    "included); faded past du.",
    "stability": "Smallest eigenvalue of the free blocks' tangent stiffness at each equilibrium state "
    "against δ: positive while the state is stable, falling toward zero as du (a fold "
    "of the equilibrium path) approaches.",
}
FINAL_STATE_CAPTION = (
    "The arch at the end of the run (no collapse), drawn to scale over its undeformed "
    "outline (dashed); hinges labelled A-D by position as in the paper, with interface and "
    "pivot side."
)


def figure_caption(name: str, summary: RunSummary) -> str:
    """The caption of the run's figure `name` (CAPTIONS; the final state's where the run stands)."""
    if name != "collapse":
        return CAPTIONS[name]
    return CAPTIONS[name].format(**_collapse_words(summary)) if summary.collapsed else FINAL_STATE_CAPTION


def _collapse_words(summary: RunSummary) -> dict[str, str]:
    """How a run's collapse state was reached, for the collapse figure's caption: the static engine's
    descent or the DEM's hold at a fixed support, and the runaway bound (mm) where the summary has it."""
    bound = (summary.relaxations or {}).get("runaway_mm")
    how = "the descent at a fixed support moved" if summary.engine == STATIC else "the hold at a fixed support moved"
    return {"how": how, "bound": f", {bound:g} mm" if bound is not None else ""}
