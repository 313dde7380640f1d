"""The live-load validation study (reports/loads, `scripts/loads_validation.py`): the rigid-block load
multiplier (solve.load_lp) against the mechanism method (solve.mechanisms) on small arches, and what it
says of the paper's arch and of semicircles: the influence line of a point load's capacity, the
collapse acceleration against t/R, the residual capacity after a settlement."""

from __future__ import annotations

from collections.abc import Callable, Iterable

import pandas as pd

from yadearch.case.config import ArchCase, preset
from yadearch.errors import CaseError, RunFailedError
from yadearch.model import units
from yadearch.results.summary import PATH
from yadearch.solve.limit_lp import weight_load
from yadearch.solve.load_lp import live_forces, load_analysis, load_capacity
from yadearch.solve.mechanisms import mechanism_multiplier
from yadearch.solve.rigid import at_rest, rigid_arch
from yadearch.solve.static_path import StaticLoading
from yadearch.studies.loads.static import static_row

CHECK_FRICTION_DEG = 80.0  # the mechanism method knows no sliding: friction high enough not to slide
SEMICIRCLE_RADIUS_MM = 300.0  # intrados radius of the semicircles (as the paper's model)
POSITIONS = tuple(round(0.05 * k, 2) for k in range(1, 20))  # of the span: the influence line
T_OVER_R = (0.11, 0.12, 0.14, 0.16, 0.18, 0.2, 0.22, 0.25, 0.3)
SETTLEMENT_FRACTIONS = (0.0, 0.25, 0.5, 0.75)  # of the static du: the residual capacity


def check_cases() -> list[ArchCase]:
    """Small arches (tens of blocks, so that every four-hinge mechanism can be tried)."""
    semicircle = {"embrace_deg": 180.0, "n_voussoirs": 13, "friction_deg": CHECK_FRICTION_DEG}
    segmental = {"n_voussoirs": 15, "friction_deg": CHECK_FRICTION_DEG}
    cases = [
        ArchCase(name=f"semicircle_t{t:g}_acceleration").with_overrides(
            {**semicircle, "thickness_mm": t, "live_load": "horizontal_acceleration"}
        )
        for t in (40.0, 50.0, 60.0, 70.0, 80.0)
    ]
    cases += [
        ArchCase(name=f"segmental_point_{x:g}").with_overrides(
            {**segmental, "live_load": "vertical", "load_position_over_span": x}
        )
        for x in (0.1, 0.2, 0.3, 0.4)
    ]
    cases.append(
        ArchCase(name="segmental_spread_0.3_100mm").with_overrides(
            {**segmental, "live_load": "vertical", "load_position_over_span": 0.3, "load_width_mm": 100.0}
        )
    )
    return cases


def mechanism_check(cases: Iterable[ArchCase]) -> pd.DataFrame:
    """Per case: the LP's multiplier and hinges beside the least four-hinge mechanism's."""
    rows = []
    for case in cases:
        arch = rigid_arch(case)
        live = live_forces(case, arch)
        lp = load_capacity(arch, live)
        kinematic, pivots = mechanism_multiplier(arch, -weight_load(arch, at_rest(arch)).reshape(-1, 3), live)
        rows.append(
            {
                "case": case.name,
                "lp_multiplier": lp.multiplier,
                "mechanism_multiplier": kinematic,
                "relative_difference": lp.multiplier / kinematic - 1.0,
                "lp_hinges": lp.hinge_labels,
                "mechanism_hinges": " ".join(p.label for p in pivots),
            }
        )
    return pd.DataFrame(rows)


def influence_line(base: ArchCase, positions: Iterable[float] = POSITIONS) -> pd.DataFrame:
    """A concentrated load's capacity (N) against its position over the span."""
    rows = []
    for x in positions:
        found = load_analysis(base.with_overrides({"live_load": "vertical", "load_position_over_span": x}))
        rows.append({"position_over_span": x, "collapse_load_N": found.multiplier, "hinges": found.hinge_labels})
    return pd.DataFrame(rows)


def semicircle_accelerations(ratios: Iterable[float] = T_OVER_R, n_voussoirs: int = 55) -> pd.DataFrame:
    """The collapse acceleration (g) of semicircles of t/R (R the centre-line radius) under their weight."""
    rows = []
    for ratio in ratios:
        case = ArchCase(name=f"semicircle_{ratio:g}").with_overrides(
            {
                "embrace_deg": 180.0,
                "n_voussoirs": n_voussoirs,
                "thickness_mm": semicircle_thickness_mm(ratio),
                "live_load": "horizontal_acceleration",
            }
        )
        found = load_analysis(case)
        rows.append({"t_over_R": ratio, "collapse_acceleration_g": found.multiplier, "hinges": found.hinge_labels})
    return pd.DataFrame(rows)


def semicircle_thickness_mm(t_over_r: float) -> float:
    """The ring thickness of a semicircle of intrados radius SEMICIRCLE_RADIUS_MM whose t/R is `t_over_r`
    (R the centre-line radius: t / (r + t/2))."""
    return 2.0 * SEMICIRCLE_RADIUS_MM * t_over_r / (2.0 - t_over_r)


def residual_capacities(
    base: ArchCase, fractions: Iterable[float] = SETTLEMENT_FRACTIONS, on_row: Callable[[dict], None] | None = None
) -> pd.DataFrame:
    """The live load after the base case's support movement to fractions of its static du (the end
    of its path at its own kn): on the static path (first loss, collapse) and by rigid blocks in the
    rigid march's state there (the load that first moves them: their open hinges are pins); `on_row`
    is given each row as it is made (a large arch's take tens of seconds)."""
    du = static_du_mm(base)
    rows = []
    for fraction in fractions:
        at_mm = fraction * du
        static = static_row(base, at_mm)  # with the rigid answer of the same state
        rows.append(
            {"settlement_over_du": fraction, "settlement_mm": at_mm, "rigid_first_motion": static["rigid_capacity"],
             "rigid_hinges": static["rigid_hinges"], "static_first_loss": static["static_first_loss"],
             "static_capacity": static["static_capacity"], "static_hinges": static["static_hinges"],
             "unit": static["unit"]}
        )  # fmt: skip
        if on_row is not None:
            on_row(rows[-1])
    return pd.DataFrame(rows)


def static_du_mm(case: ArchCase) -> float:
    """The end of the case's support-movement path on the static engine (mm); an error where it has
    none to take fractions of: the arch stands to the movement's end, or the path is unresolved."""
    loading = StaticLoading.of(case)
    loading.selfweight()
    path = loading.follow()
    if path.collapsed:
        return units.to_mm(path.du)
    if path.unresolved:
        raise RunFailedError(
            f"the support movement's static path is unresolved past {units.to_mm(path.lower):.2f} mm: no du to "
            "take the settlements from"
        )
    if case.loading.support_motion == PATH:  # a prescribed path ends where it ends
        raise CaseError(
            f"the arch stands to the end of its prescribed path ({units.to_mm(path.lower):g} mm): no du to take "
            "the settlements from"
        )
    raise CaseError(
        f"loading.max_support_displacement_mm = {case.loading.max_support_displacement_mm:g}: the arch stands to "
        "the end of its support movement, no du to take the settlements from; set it larger to follow the path further"
    )


def paper_arch() -> ArchCase:
    """The paper's arch and material (set 2's preset, kn 5.2 N/mm3 on the static path)."""
    return preset("set2")
