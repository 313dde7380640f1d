"""What a stored case ran with, comparable across versions (pure): the parameters a run predates at the
value that reproduces its behaviour (`as_ran`, for reusing run folders), and without them (`fingerprinted`,
for the short fingerprints of campaigns' records and caches)."""

from __future__ import annotations

import math
from dataclasses import fields
from typing import Any

from yadearch.case.config import DEFAULT_NAME, current_names, support_speed
from yadearch.case.materials import MATERIAL_KEY, PRESET_FIELD
from yadearch.case.numerics_section import SCENE_PATH_STATES, STATIC_ENGINE, resolved_path_states
from yadearch.case.sections import SECTIONS
from yadearch.case.support import capped_acceleration


def as_ran(data: dict[str, Any]) -> dict[str, Any]:
    """What a stored case.toml (`data`) ran with, comparable across versions: a parameter the run
    predates takes the value that reproduces the behaviour it had ("predates" in its metadata, else
    its default), and the support speed and acceleration replace the parameters they derive from,
    so that a run whose speed or acceleration they do not change stays comparable, and the DEM's path
    reading is the one it resolves to (none for the static engine); what the folder
    keeps (`numerics.run_files`) and whether a static run checked itself (`numerics.increments_check`,
    which leaves its answer alone) are left out."""
    filled: dict[str, Any] = {"name": data.get("name", DEFAULT_NAME)}
    for section_name, cls in SECTIONS.items():
        stored, defaults = current_names(section_name, data.get(section_name, {})), cls()
        filled[section_name] = {
            f.name: stored.get(f.name, f.metadata.get("predates", getattr(defaults, f.name))) for f in fields(cls)
        }
    numerics = filled["numerics"]
    numerics["support_speed_mm_per_s"] = support_speed(
        numerics["support_rate_mm_per_s"], numerics["rate_reference_kn_N_per_mm3"], filled["interface"]["kn_N_per_mm3"]
    )
    del numerics["support_rate_mm_per_s"], numerics["rate_reference_kn_N_per_mm3"]
    del numerics["run_files"], numerics["increments_check"]  # what the folder keeps, a check beside the answer
    # the states the DEM's path read ('auto' resolved); the static engine reads none: the value before the setting
    numerics["support_path_states"] = (
        SCENE_PATH_STATES
        if numerics["engine"] == STATIC_ENGINE
        else resolved_path_states(numerics["support_path_states"], numerics["contact_model"])
    )
    del filled[MATERIAL_KEY][PRESET_FIELD]  # a material's name: its values are in the case
    loading = filled["loading"]  # the acceleration a run used; a turn or a path counted as horizontal
    share = (
        abs(math.cos(math.radians(loading["support_direction_deg"])))
        if loading["support_motion"] == "translation"
        else 1.0
    )
    numerics["support_acceleration_mm_per_s2"] = capped_acceleration(
        numerics["support_acceleration_mm_per_s2"], numerics.pop("support_horizontal_acceleration_mm_per_s2"), share
    )
    return filled


def fingerprinted(data: dict[str, Any]) -> dict[str, Any]:
    """`as_ran(data)` without the parameters at the value a case written before them takes ("predates"
    in their metadata): what a fingerprint of a case hashes, so that a later version's new parameter
    leaves the fingerprints of the cases it does not change as they were."""
    filled = as_ran(data)
    for section_name, cls in SECTIONS.items():
        section = filled[section_name]
        for f in fields(cls):
            if "predates" in f.metadata and f.name in section and section[f.name] == f.metadata["predates"]:
                del section[f.name]
    return filled
