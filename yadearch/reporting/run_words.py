"""A run in words for its report: the arch it solved and how its support moved (a report of an arch that
is not the paper's must say what it was)."""

from __future__ import annotations

from typing import Any

from yadearch.case.comparison import as_ran
from yadearch.case.config import ArchCase
from yadearch.case.support import MOVEMENT_PRESETS
from yadearch.results.summary import TRANSLATION, LoadingInfo, RunSummary

SAID_ELSEWHERE = {
    "engine",
    "run_files",
    "increments_check",
}  # said in other words (the engine), or no answer rests on them

# the named movements that translate a support (`--set movement=NAME`), by (support, direction in deg)
NAMED_TRANSLATIONS = {
    (preset["loading.moving_support"], preset["loading.support_direction_deg"]): name
    for name, preset in MOVEMENT_PRESETS.items()
    if preset["loading.support_motion"] == TRANSLATION
}


def arch_text(case: dict[str, Any]) -> str:
    """The arch of a run's case (case.toml's dictionary, filled as it ran: an older file lacks newer keys):
    its shape, voussoirs, ring and size."""
    g = as_ran(case)["geometry"]
    shape, ring = g["shape"], f"{g['n_voussoirs']} voussoirs, ring {g['thickness_mm']:g} mm"
    if shape == "measured" and g["piers_mm"]:  # an arch put on piers (`yadearch piers`)
        (height, width), *_ = g["piers_mm"]
        arch = f"arch of {len(g['joint_points_mm']) - 3} voussoirs, ring {g['thickness_mm']:.3g} mm"
        return f"{arch}, on piers {height:g} mm tall and {width:g} mm wide"
    if shape == "measured":  # a survey: its joints' corners
        blocks = len(g["joint_points_mm"]) - 1
        return f"arch of {blocks} blocks given by its joints' corners, ring {g['thickness_mm']:.3g} mm"
    if shape == "segmental":
        return f"segmental arch, {ring}, intrados radius {g['internal_radius_mm']:g} mm, embrace {g['embrace_deg']:g}°"
    size = f"span {g['span_mm']:g} mm" + (f", rise {g['rise_mm']:g} mm" if shape != "pointed" else "")
    return f"{shape.replace('_', '-')} arch, {ring}, {size}"


def numerics_text(case: dict[str, Any]) -> str:
    """The numerical settings a run's case (its case.toml) gives other than the defaults, as "name value
    (default d)"; "" where it keeps them all (a setting the case predates counts as kept)."""
    defaults = ArchCase().to_dict()["numerics"]
    given = case.get("numerics", {})
    return ", ".join(
        f"{name} {given[name]} (default {value})"
        for name, value in defaults.items()
        if name not in SAID_ELSEWHERE and name in given and given[name] != value
    )


def movement_text(summary: RunSummary) -> str:
    """How the run's support moved: which, how (a translation's direction, named where it has a name)."""
    loading = summary.loading
    if loading is None:
        return "support movement not recorded"
    support = "both supports" if loading.moving_support == "both" else f"{loading.moving_support} support"
    held = f", {loading.held_live_load} held on the arch" if loading.held_live_load else ""
    if loading.motion != TRANSLATION:
        return f"{support}: {loading.motion}" + _motion_detail(loading) + held
    direction = 180.0 if loading.direction_deg == -180.0 else loading.direction_deg  # closing either way
    named = NAMED_TRANSLATIONS.get((loading.moving_support, direction))
    return f"{support} moving at {loading.direction_deg:g}°" + (f" ({named})" if named else "") + held


def _motion_detail(loading: LoadingInfo) -> str:
    """A rotation's sense and pivot, a path's rows, as the summary recorded them (older runs: none)."""
    if loading.pivot_mm is not None:
        dx, dy = loading.pivot_mm
        return f" {loading.rotation_sense} about a pivot ({dx:g}, {dy:g}) mm from the springing's intrados"
    if loading.path_mm_mrad is not None:
        return f" of {len(loading.path_mm_mrad)} rows (dx mm, dy mm, rotation mrad)"
    return ""
