"""What a compliant march's answer carries beside its du: the static engine's answer on the same blocks
and joints (the compliant model the march estimates) and the warnings a reader must see, kept in the
result (`LimitResult.warnings`, its JSON) and printed by `yadearch limit`."""

from __future__ import annotations

from dataclasses import dataclass, replace

from yadearch.case.config import ArchCase
from yadearch.case.numerics_section import NO_INCREMENTS_CHECK
from yadearch.errors import YadearchError
from yadearch.solve.compliant import VALID_MARGIN_FRACTION
from yadearch.solve.limit_result import LimitResult
from yadearch.solve.rigid import MarchStopped

MARCH_STATIC_TOLERANCE = 0.02  # the march estimates the static engine's compliant model; further apart is said
STATIC_SAID = "static engine (same blocks and joints):"
WHY_STATIC = "the static engine solves the compliant model itself (docs/validation-compliant.md)"


@dataclass(frozen=True)
class StaticAnswer:
    """The static engine's answer to a case: its outcome (collapse, stands, unresolved, or "failed: why"),
    du, du_first (mm) and the hinges at collapse."""

    outcome: str
    du_mm: float | None = None
    du_first_mm: float | None = None
    hinges: tuple[str, ...] = ()

    @classmethod
    def of(cls, case: ArchCase) -> StaticAnswer:
        """Solved in seconds: no run folder, no increments check."""
        from yadearch.static.simulate import simulate_static

        static = case.with_overrides({"numerics.engine": "static", "numerics.increments_check": NO_INCREMENTS_CHECK})
        try:
            summary = simulate_static(static, None, log=lambda _line: None)
        except YadearchError as exc:
            return cls(f"failed: {exc}")
        hinges = tuple(h.label for h in summary.hinges_at_collapse)
        return cls(str(summary.path_outcome), summary.du_mm, summary.du_first_mm, hinges)

    @classmethod
    def beside(cls, result: LimitResult) -> StaticAnswer | None:
        """The answer a compliant march's result keeps (None: not solved)."""
        if result.static_outcome is None:
            return None
        hinges = result.static_hinges or ()
        return cls(result.static_outcome, result.static_du_mm, result.static_du_first_mm, hinges)

    @property
    def failed(self) -> bool:
        """The static engine did not answer (its self-weight, or a solver, failed)."""
        return self.outcome.startswith("failed")

    def line(self, march_du_mm: float | None) -> str:
        """In one line, with the march's distance from it where they agree (`MARCH_STATIC_TOLERANCE`)."""
        if self.du_mm is None:
            return f"{STATIC_SAID} {self.outcome}" + ("" if self.outcome == "stands" else ", no du")
        first = "" if self.du_first_mm in (None, self.du_mm) else f", du_first {self.du_first_mm:.2f} mm"
        hinges = f" on {' '.join(self.hinges)}" if self.hinges else ""
        line = f"{STATIC_SAID} du = {self.du_mm:.2f} mm{first}{hinges}"
        if march_du_mm is not None and abs(march_du_mm / self.du_mm - 1.0) <= MARCH_STATIC_TOLERANCE:
            line += f"; the march {march_du_mm / self.du_mm - 1.0:+.1%} from it"
        return line

    def gap(self, march_du_mm: float | None) -> str | None:
        """The warning where a march's du (None: it stood) and this answer part; None where they agree."""
        if self.failed or (self.du_mm is None and self.outcome != "stands"):
            return None
        if self.du_mm is None:
            return (
                None
                if march_du_mm is None
                else f"the compliant march collapses where the static engine stands; {WHY_STATIC}"
            )
        if march_du_mm is None:
            return f"the static engine collapses at {self.du_mm:.2f} mm where the compliant march stands; {WHY_STATIC}"
        gap = march_du_mm / self.du_mm - 1.0
        if abs(gap) <= MARCH_STATIC_TOLERANCE:
            return None
        return f"the compliant march is {gap:+.1%} from the static engine ({self.du_mm:.2f} mm); {WHY_STATIC}"


def with_static_answer(result: LimitResult, case: ArchCase) -> LimitResult:
    """`result` (a compliant march) with the static engine's answer on the same blocks and joints beside it."""
    answer = StaticAnswer.of(case)
    return replace(
        result,
        static_outcome=answer.outcome,
        static_du_mm=answer.du_mm,
        static_du_first_mm=answer.du_first_mm,
        static_hinges=None if answer.failed else answer.hinges,
    )


def failed_march(error: MarchStopped, case: ArchCase) -> MarchStopped:
    """A compliant march's failure with the static engine's answer on the same blocks and joints beside
    it, where that engine has one (the march estimates the compliant model; the static engine solves it)."""
    answer = StaticAnswer.of(case)
    return error if answer.failed else MarchStopped(f"{error}; {answer.line(None)}")


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
    answer = StaticAnswer.beside(result)
    gap = None if answer is None else answer.gap(result.du_mm)
    return replace(result, warnings=(*said, *([gap] if gap else [])))
