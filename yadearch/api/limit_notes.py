"""What a compliant march's answer carries beside its du: the static engine's answer on the same blocks
and joints (the compliant model the march estimates) and the warnings a reader must see, kept in the
result (`LimitResult.warnings`, its JSON) and printed by `yadearch limit`."""

from __future__ import annotations

from dataclasses import replace

from yadearch.case.config import ArchCase
from yadearch.case.numerics_section import NO_INCREMENTS_CHECK
from yadearch.errors import YadearchError
from yadearch.solve.compliant import VALID_MARGIN_FRACTION
from yadearch.solve.limit_result import LimitResult

MARCH_STATIC_TOLERANCE = 0.02  # the march estimates the static engine's compliant model; further apart is said
STATIC_SAID = "static engine (same blocks and joints):"
WHY_STATIC = "the static engine solves the compliant model itself (docs/validation-compliant.md)"


def with_static_answer(result: LimitResult, case: ArchCase) -> LimitResult:
    """`result` (a compliant march) with the static engine's answer on the same blocks and joints beside
    it: the compliant model the march estimates, solved in seconds (no run folder, no increments check)."""
    from yadearch.static.simulate import simulate_static

    static = case.with_overrides({"numerics.engine": "static", "numerics.increments_check": NO_INCREMENTS_CHECK})
    try:
        summary = simulate_static(static, None, log=lambda _line: None)
    except YadearchError as exc:
        return replace(result, static_outcome=f"failed: {exc}")
    return replace(
        result,
        static_outcome=str(summary.path_outcome),
        static_du_mm=summary.du_mm,
        static_du_first_mm=summary.du_first_mm,
        static_hinges=tuple(h.label for h in summary.hinges_at_collapse),
    )


def with_warnings(result: LimitResult, case: ArchCase) -> LimitResult:
    """`result` with the warnings of a compliant march: joints so soft that a fold margin passes
    VALID_MARGIN_FRACTION of the joint, and a static engine's answer further than MARCH_STATIC_TOLERANCE."""
    said = []
    largest = result.compliant_largest_margin_mm
    if largest is not None and largest > VALID_MARGIN_FRACTION * case.geometry.thickness_mm:
        said.append(
            f"a joint folded {largest:.2f} mm from its edge, more than {VALID_MARGIN_FRACTION:.0%} of the joint: "
            "joints this soft deform the whole arch, which the compliant march ignores (docs/validation.md)"
        )
    gap = static_gap(result)
    if gap is not None:
        said.append(gap)
    return replace(result, warnings=tuple(said))


def static_gap(result: LimitResult) -> str | None:
    """The warning where the compliant march and the static engine part (None where they agree)."""
    if result.static_outcome is None or result.static_outcome.startswith("failed"):
        return None
    if result.static_du_mm is None:
        stood = result.du_mm is not None and result.static_outcome == "stands"
        return f"the compliant march collapses where the static engine stands; {WHY_STATIC}" if stood else None
    if result.du_mm is None:
        where = f"the static engine collapses at {result.static_du_mm:.2f} mm"
        return f"{where} where the compliant march stands; {WHY_STATIC}"
    gap = result.du_mm / result.static_du_mm - 1.0
    if abs(gap) <= MARCH_STATIC_TOLERANCE:
        return None
    return f"the compliant march is {gap:+.1%} from the static engine ({result.static_du_mm:.2f} mm); {WHY_STATIC}"


def static_line(result: LimitResult) -> str:
    """The static engine's answer beside a compliant march, in one line."""
    if result.static_du_mm is None:
        return f"{STATIC_SAID} {result.static_outcome}" + ("" if result.static_outcome == "stands" else ", no du")
    du, first = result.static_du_mm, result.static_du_first_mm
    first_text = "" if first in (None, du) else f", du_first {first:.2f} mm"
    line = f"{STATIC_SAID} du = {du:.2f} mm{first_text} on {' '.join(result.static_hinges or ())}"
    if result.du_mm is not None and abs(result.du_mm / du - 1.0) <= MARCH_STATIC_TOLERANCE:
        line += f"; the march {result.du_mm / du - 1.0:+.1%} from it"
    return line
