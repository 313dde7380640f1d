"""What a run will do, checked before YADE starts: a valid arch, a finite time step, a gravity ramp
that fits the self-weight stage, and a worst-case number of steps within the step budget. Each
refusal is one line naming the parameter, its value and what would be accepted. And what the rigid-block
analysis does not read of a case (`unread_by_rigid_blocks`)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.case.held import held_multiplier, require_live_load
from yadearch.case.imperfect import amplitudes, arch_imperfections, check_contact_model
from yadearch.case.mechanics import arch_geometry, contact_stiffness, critical_timestep, live_load
from yadearch.case.numerics_section import (
    JOINT_CONTACTS,
    LEAST_BRACKET,
    NO_INCREMENTS_CHECK,
    SCENE_PATH_STATES,
    STATIC_ENGINE,
    STATIC_PATH_STATES,
    NumericsConfig,
)
from yadearch.case.support import case_movement, support_acceleration_mm_per_s2
from yadearch.errors import CaseError
from yadearch.model import units
from yadearch.model.geometry import ArchGeometry
from yadearch.model.imperfections import MAX_EDGE_FRACTION
from yadearch.model.loads import NONE

SETTLE_HOLDS = 10  # settling holds a run may need (one per bracket end retried), for the worst case
BISECTIONS_MARGIN = 10  # increments beyond the bisection count, for retries after discarded states


@dataclass(frozen=True)
class RunPlan:
    """The numbers a run is built from: time step (s), gravity ramp (s), and the worst-case
    simulated time (s) and steps of the whole run."""

    dt_s: float
    gravity_ramp_s: float
    worst_case_s: float
    worst_case_steps: float


def plan_run(case: ArchCase) -> RunPlan:
    """The time step, gravity ramp and worst-case steps of `case`; CaseError if it cannot run (the
    static engine has no time step: its plan checks the arch, the movement and the increments)."""
    num = case.numerics
    if not num.du_tolerance_mm < num.first_increment_mm <= num.max_increment_mm:
        raise CaseError(
            f"numerics.du_tolerance_mm = {num.du_tolerance_mm:g}, first_increment_mm = "
            f"{num.first_increment_mm:g} and max_increment_mm = {num.max_increment_mm:g} must "
            "grow in that order (the tolerance below the first increment, that at most the largest)"
        )
    held_multiplier(case)  # refuses a held value of another kind of live load
    if case.loads.live_load != NONE and num.engine != "static":
        if held_multiplier(case) == 0.0:
            raise CaseError(
                f"loads.live_load = {case.loads.live_load!r} with nothing of it held: a DEM run holds "
                "loads.held_load_N or held_acceleration_g while its support moves; the load's capacity is "
                "`yadearch loads --engine dem`"
            )
        if num.contact_model != JOINT_CONTACTS:
            raise CaseError(
                f"numerics.contact_model = {num.contact_model!r}: a DEM run holding a live load needs the joint "
                "elements (numerics.contact_model = 'joint')"
            )
    if case.loads.fill_depth_mm > 0.0 and num.contact_model != JOINT_CONTACTS:
        raise CaseError(
            f"numerics.contact_model = {num.contact_model!r}: backfill (loads.fill_depth_mm = "
            f"{case.loads.fill_depth_mm:g}) needs the joint elements (numerics.contact_model = 'joint')"
        )
    if num.support_path_states == STATIC_PATH_STATES and num.contact_model != JOINT_CONTACTS:
        raise CaseError(
            f"numerics.support_path_states = {STATIC_PATH_STATES!r} reads the joint elements' static model, "
            f"which CGAL contacts (numerics.contact_model = {num.contact_model!r}) do not have; use "
            f"{SCENE_PATH_STATES!r} or contact_model 'joint'"
        )
    geometry = arch_geometry(case)  # refuses an arch that cannot be built (case/shape.py)
    live_load(case, geometry)  # refuses further loads that could never stand on the arch, or beside no vertical load
    _check_imperfections(case, geometry)
    movement = case_movement(case, geometry)  # refuses a movement that cannot be followed (a pivot on the path's point)
    if num.engine == "static":
        if num.contact_model != JOINT_CONTACTS:
            raise CaseError(
                f"numerics.contact_model = {num.contact_model!r} is the DEM's; the static engine "
                "evaluates the joint elements only (numerics.contact_model = 'joint')"
            )
        return RunPlan(math.nan, 0.0, 0.0, 0.0)  # no time stepping: nothing else to plan
    dt = num.timestep_safety * critical_timestep(case, geometry, contact_stiffness(case, geometry))
    if not math.isfinite(dt) or dt <= 0.0:
        raise CaseError(
            f"the time step from interface.kn_N_per_mm3 = {case.interface.kn_N_per_mm3:g} "
            f"and material.density_g_per_cm3 = {case.material.density_g_per_cm3:g} is "
            f"{dt:g} s; both must give a finite, positive step"
        )
    ramp_s = num.gravity_ramp_periods * math.pi * dt / num.timestep_safety
    if ramp_s > num.selfweight_max_s:
        raise CaseError(
            f"numerics.gravity_ramp_periods = {num.gravity_ramp_periods:g} makes the gravity "
            f"ramp {ramp_s:.3g} s, longer than numerics.selfweight_max_s = "
            f"{num.selfweight_max_s:g} s; lower the first or raise the second"
        )
    accel = support_acceleration_mm_per_s2(case, movement)
    worst_s = num.selfweight_max_s + ramp_s + _loading_worst_case_s(case, accel) + SETTLE_HOLDS * num.hold_max_s
    steps = worst_s / dt
    if steps > num.max_steps:
        raise CaseError(
            f"this case could take up to {steps:.3g} steps (time step {dt:.3g} s, up to "
            f"{worst_s:.3g} s simulated), over numerics.max_steps = {num.max_steps:.3g}; "
            "check the loading speed, increments and hold times, or raise max_steps"
        )
    return RunPlan(dt, ramp_s, worst_s, steps)


def check_dem_load(case: ArchCase) -> None:
    """Refuse, before YADE starts, a live-load case the DEM cannot follow: no live load or CGAL contacts
    (the load's stability test needs the joint elements)."""
    require_live_load(case)
    if case.numerics.contact_model != JOINT_CONTACTS:
        raise CaseError(
            f"numerics.contact_model = {case.numerics.contact_model!r}: the DEM's load path needs the joint "
            "elements (numerics.contact_model = 'joint')"
        )
    live_load(case, arch_geometry(case))  # refuses further loads that could never stand on the arch
    # the load grows apart
    unloaded = {"live_load": NONE, "further_loads": [], "load_inclination_deg": 0.0, "load_dispersal": "none"}
    plan_run(case.with_overrides(unloaded))  # the time step and the run's other checks


def _check_imperfections(case: ArchCase, geometry: ArchGeometry) -> None:
    """Imperfections need the joint elements, and a worn edge or an offset face must leave part of the
    joint shared."""
    imp = case.imperfections
    amps = amplitudes(case)
    if amps.perfect:
        return
    if not amps.perfect_faces:  # dimension errors only change the blocks, which CGAL contacts also take
        check_contact_model(case.numerics.contact_model)
    largest_mm = MAX_EDGE_FRACTION * units.to_mm(min(joint.length for joint in geometry.joints))
    if imp.edge_radius_mm > largest_mm:
        raise CaseError(
            f"imperfections.edge_radius_mm = {imp.edge_radius_mm:g} must be at most "
            f"{largest_mm:.3g} mm ({MAX_EDGE_FRACTION:g} of the joint length)"
        )
    drawn = arch_imperfections(case, geometry)
    assert drawn is not None
    shift = np.abs(drawn.defects.right_offset - drawn.defects.left_offset)
    if np.any(shift > 2.0 * MAX_EDGE_FRACTION * drawn.lengths):
        raise CaseError(
            f"imperfections.voussoir_offset_mm = {imp.voussoir_offset_mm:g}, voussoir_offset_sd_mm "
            f"= {imp.voussoir_offset_sd_mm:g} and keystone_offset_mm = {imp.keystone_offset_mm:g} "
            f"offset two faces by up to {units.to_mm(float(shift.max())):.3g} mm; at most "
            f"{2 * MAX_EDGE_FRACTION:g} of the joint length "
            f"({units.to_mm(float(drawn.lengths.min())):.3g} mm)"
        )


def _loading_worst_case_s(case: ArchCase, accel_mm_per_s2: float) -> float:
    """Simulated time of the loading if every increment ran its full move and its longest hold."""
    num = case.numerics
    largest = max(num.max_increment_mm, num.first_increment_mm)
    growing = (
        math.ceil(math.log(largest / num.first_increment_mm) / math.log(num.increment_growth))
        if num.increment_growth > 1.0
        else math.ceil(case.loading.max_support_displacement_mm / num.first_increment_mm)
    )
    least_bracket_mm = num.du_tolerance_mm * (LEAST_BRACKET if num.du_tolerance_ratio else 1.0)  # PathSettings.bracket
    increments = (
        growing
        + math.ceil(case.loading.max_support_displacement_mm / largest)
        + math.ceil(math.log2(largest / least_bracket_mm))
        + BISECTIONS_MARGIN
    )
    return increments * (_move_s(largest, case.support_speed_mm_per_s, accel_mm_per_s2) + num.hold_max_s)


def _move_s(distance_mm: float, speed_mm_per_s: float, accel_mm_per_s2: float) -> float:
    """Duration of a trapezoidal move (accelerate, cruise, brake; accel 0 = instantaneous)."""
    if accel_mm_per_s2 <= 0.0:
        return distance_mm / speed_mm_per_s
    ramp_mm = speed_mm_per_s**2 / accel_mm_per_s2  # both ramps together
    if ramp_mm >= distance_mm:
        return 2.0 * math.sqrt(distance_mm / accel_mm_per_s2)
    return 2.0 * speed_mm_per_s / accel_mm_per_s2 + (distance_mm - ramp_mm) / speed_mm_per_s


def static_only_refusal(numerics: NumericsConfig) -> str | None:
    """The one line refusing a static-only setting of `numerics` in a DEM run (None: nothing to refuse,
    or the static engine): the increments check solves a static path twice, the DEM's path is not."""
    if numerics.engine == STATIC_ENGINE or numerics.increments_check == NO_INCREMENTS_CHECK:
        return None
    return (
        f"numerics.increments_check = {numerics.increments_check!r} is read by the static engine only (the DEM "
        f"does not solve its path twice); use {NO_INCREMENTS_CHECK!r} or the static engine"
    )


RIGID_UNREAD_SECTIONS = ("numerics", "interface")  # rigid blocks: no numerics, rigid joints
RIGID_UNREAD_LOADS = ("fill_passive_displacement_mm",)  # the fill's spring: rigid blocks mobilise it at once


def unread_by_rigid_blocks(case: ArchCase) -> list[str]:
    """The parameters `case` sets off their defaults that the rigid-block analysis does not read
    (numerics, joint stiffness, the fill's spring), by qualified name: a case file's are listed, not
    refused (a command line's --set is refused)."""
    ran, default = case.to_dict(), ArchCase().to_dict()
    unread = [
        f"{section}.{key}"
        for section in RIGID_UNREAD_SECTIONS
        for key, value in ran[section].items()
        if value != default[section][key]
    ]
    return unread + [f"loads.{key}" for key in RIGID_UNREAD_LOADS if ran["loads"][key] != default["loads"][key]]
