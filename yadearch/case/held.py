"""The live load a support-movement run holds (`loads.held_load_N`, `held_acceleration_g`) and what a
capacity, which grows the live load from nothing, refuses in one line."""

from __future__ import annotations

from yadearch.case.config import ArchCase
from yadearch.case.mechanics import load_place
from yadearch.errors import CaseError
from yadearch.model.loads import ACCELERATION, NONE, UNITS, VERTICAL

HELD_SETTINGS = {VERTICAL: "held_load_N", ACCELERATION: "held_acceleration_g"}  # each live load's held value


def held_multiplier(case: ArchCase) -> float:
    """The live load a run holds while its support moves, in its multiplier's unit (N for a vertical
    load, g for an acceleration; 0: none); CaseError for a held value of another kind of live load."""
    loads = case.loads
    for kind, name in HELD_SETTINGS.items():
        if getattr(loads, name) > 0.0 and loads.live_load != kind:
            raise CaseError(
                f"loads.{name} = {getattr(loads, name):g} holds a {kind.replace('_', ' ')} load, but "
                f"loads.live_load is {loads.live_load!r}; set live_load = {kind!r} or {name} = 0"
            )
    return float(getattr(loads, HELD_SETTINGS[loads.live_load])) if loads.live_load in HELD_SETTINGS else 0.0


def refuse_held(case: ArchCase) -> None:
    """CaseError for a held live load in a case whose live load grows from nothing (a capacity)."""
    for name in HELD_SETTINGS.values():
        if getattr(case.loads, name) > 0.0:
            raise CaseError(
                f"loads.{name} = {getattr(case.loads, name):g} holds the live load while the support moves "
                "(`yadearch run`, `limit`); a capacity grows it from nothing: set it to 0"
            )


def refuse_fixed_place(case: ArchCase) -> None:
    """CaseError for a case whose live load the influence line cannot move across the span: an
    acceleration, or a load put over one voussoir."""
    if case.loads.live_load == ACCELERATION:
        raise CaseError(
            "loads.live_load = 'horizontal_acceleration': the influence line moves a vertical load across the "
            "span; set live_load = 'vertical' (or 'none')"
        )
    if case.loads.load_voussoir:
        raise CaseError(
            f"loads.load_voussoir = {case.loads.load_voussoir} puts the load over one voussoir; the influence "
            "line moves it across the span: set load_voussoir = 0"
        )


def unheld(case: ArchCase) -> ArchCase:
    """`case` without the live load a run holds: the load paths grow the load from nothing, and the
    self-weight's diagnosis and the residual capacity's movement are made without it."""
    return case.with_overrides({name: 0.0 for name in HELD_SETTINGS.values()})


def held_load_text(case: ArchCase) -> str:
    """The live load a run holds during its movement, in words for summary.json ('' without one)."""
    held = held_multiplier(case)
    if held == 0.0:
        return ""
    loads = case.loads
    where = f" {load_place(case)}" if loads.live_load == VERTICAL else ""
    return f"{held:g} {UNITS[loads.live_load]} {loads.live_load.replace('_', ' ')}{where}"


def require_live_load(case: ArchCase) -> None:
    """CaseError for a case without a live load where one must grow."""
    if case.loads.live_load == NONE:
        raise CaseError("loads.live_load is 'none': say which load grows ('vertical' or 'horizontal_acceleration')")
