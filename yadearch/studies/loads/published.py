"""The rigid-block LP against published results for the semicircular arch (docs/loads.md): under its own
weight, the least friction at which it stands at all and the friction below which its least thickness
rises above the no-sliding one, from Cocchetti and Rizzi (2020), Frattura ed Integrità Strutturale 51,
356-375, doi:10.3221/IGF-ESIS.51.26 (p. 370: a complete semicircle, radial joints); under a point load,
the worked example of Stockdale et al. (2018), SoftwareX 7, 174-179, doi:10.1016/j.softx.2018.05.006."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pandas as pd

from yadearch.case.config import ArchCase, preset
from yadearch.model import units
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.standing import stands
from yadearch.studies.loads.rigid import semicircle_thickness_mm

SLIDING_FRICTION_DEG = 17.1824  # mu_ms = 0.309215: below it no thickness stands (purely sliding modes)
MIXED_FRICTION_DEG = 21.5952  # mu_rm = 0.395832: below it the least thickness rises (sliding at the shoulders)
SLIDING_LEAST_T_OVER_R = 0.200637  # the least t/R at the sliding friction
THICK_T_OVER_R = (0.21, 0.25, 0.30)  # rings thicker than that: the least friction is the sliding one
FRICTIONS_DEG = (17.5, 19.0, 21.0, 21.4, 21.8, 25.0, 41.2)  # the least t/R against friction
N_VOUSSOIRS = 55
FRICTION_TOLERANCE_DEG = 0.005  # bisection brackets
T_OVER_R_TOLERANCE = 1e-5
# Stockdale et al. (2018): a semicircle of 27 equal voussoirs with radial joints, intrados radius 1.806 m,
# t/R 0.1661 over the intrados radius, depth 0.25 m, 1530 kg/m3, no sliding; a vertical point load at the
# extrados end of the 8th joint from the left springing; its collapse load by their calculator (KCLC) and
# by an independent virtual-power construction
POINT_LOAD_RADIUS_MM = 1806.0
POINT_LOAD_T_OVER_R = 0.1661
POINT_LOAD_DEPTH_MM = 250.0
POINT_LOAD_DENSITY_G_PER_CM3 = 1.53
POINT_LOAD_VOUSSOIRS = 27
POINT_LOAD_JOINT = 8  # counted from the left springing's joint (0): this project's joint 9
NO_SLIDING_FRICTION_DEG = 80.0  # the published example allows no sliding
PUBLISHED_POINT_LOAD_N = {"KCLC": 2751.0, "virtual powers": 2756.0}


def semicircle(t_over_r: float, friction_deg: float, n_voussoirs: int = N_VOUSSOIRS) -> ArchCase:
    """A complete semicircle with radial joints, t/R its thickness over its centre-line radius."""
    return preset("set2").with_overrides(
        {
            "embrace_deg": 180.0,
            "n_voussoirs": n_voussoirs,
            "thickness_mm": semicircle_thickness_mm(t_over_r),
            "friction_deg": friction_deg,
        }
    )


def least(holds: Callable[[float], bool], low: float, high: float, tolerance: float) -> float:
    """The least value in [low, high] at which `holds` (monotone: false below, true above), to `tolerance`;
    ValueError if the bracket does not hold it (a bound would pass for a result)."""
    if holds(low) or not holds(high):
        raise ValueError(f"the least value is not bracketed by [{low:g}, {high:g}]")
    while high - low > tolerance:
        middle = 0.5 * (low + high)
        low, high = (low, middle) if holds(middle) else (middle, high)
    return high


def least_friction_deg(t_over_r: float, n_voussoirs: int = N_VOUSSOIRS) -> float:
    """The least friction angle at which the semicircle of `t_over_r` stands (rigid LP)."""
    return least(lambda phi: stands(semicircle(t_over_r, phi, n_voussoirs)), 10.0, 45.0, FRICTION_TOLERANCE_DEG)


def least_t_over_r(friction_deg: float, n_voussoirs: int = N_VOUSSOIRS) -> float:
    """The least t/R at which the semicircle stands with `friction_deg` (rigid LP)."""
    return least(lambda t: stands(semicircle(t, friction_deg, n_voussoirs)), 0.09, 0.4, T_OVER_R_TOLERANCE)


def friction_table() -> pd.DataFrame:
    """Each published value beside the LP's, `solved_for` naming the column the LP computed (the other
    is given): the least friction of rings thicker than the sliding least t/R, the friction where the
    least t/R starts to rise, the least t/R just above the sliding friction, and the least t/R against
    friction (published as a curve only, the source's Fig. 7: no values to set beside it)."""
    least_t = {phi: least_t_over_r(phi) for phi in FRICTIONS_DEG}  # each bisected once
    no_sliding = least_t[FRICTIONS_DEG[-1]]
    rising = least_friction_deg(no_sliding + 2 * T_OVER_R_TOLERANCE)  # just thicker than the no-sliding least
    near_sliding = SLIDING_FRICTION_DEG + 2 * FRICTION_TOLERANCE_DEG
    rows = [
        {"check": "least friction to stand", "solved_for": "friction", "friction_deg": least_friction_deg(t),
         "t_over_R": t, "published_friction_deg": SLIDING_FRICTION_DEG, "published_t_over_R": None}
        for t in THICK_T_OVER_R
    ]  # fmt: skip
    rows.append(
        {"check": "least t/R starts to rise", "solved_for": "friction", "friction_deg": rising,
         "t_over_R": no_sliding, "published_friction_deg": MIXED_FRICTION_DEG, "published_t_over_R": None}
    )  # fmt: skip
    rows.append(
        {"check": "least t/R just above the sliding friction", "solved_for": "t/R", "friction_deg": near_sliding,
         "t_over_R": least_t_over_r(near_sliding), "published_friction_deg": SLIDING_FRICTION_DEG,
         "published_t_over_R": SLIDING_LEAST_T_OVER_R}
    )  # fmt: skip
    rows += [
        {"check": "least t/R", "solved_for": "t/R", "friction_deg": phi, "t_over_R": t,
         "published_friction_deg": None, "published_t_over_R": None}
        for phi, t in least_t.items()
    ]  # fmt: skip
    return pd.DataFrame(rows)


def point_load_arch() -> ArchCase:
    """Stockdale et al.'s semicircle with its point load on the extrados end of their joint 8."""
    thickness = POINT_LOAD_T_OVER_R * POINT_LOAD_RADIUS_MM
    angle = math.pi * POINT_LOAD_JOINT / POINT_LOAD_VOUSSOIRS  # from the left springing
    x_from_left = POINT_LOAD_RADIUS_MM - (POINT_LOAD_RADIUS_MM + thickness) * math.cos(angle)
    return ArchCase(name="stockdale_2018_point_load").with_overrides(
        {
            "embrace_deg": 180.0,
            "internal_radius_mm": POINT_LOAD_RADIUS_MM,
            "thickness_mm": thickness,
            "depth_mm": POINT_LOAD_DEPTH_MM,
            "density_g_per_cm3": POINT_LOAD_DENSITY_G_PER_CM3,
            "n_voussoirs": POINT_LOAD_VOUSSOIRS,
            "friction_deg": NO_SLIDING_FRICTION_DEG,
            "live_load": "vertical",
            "load_position_over_span": x_from_left / (2.0 * POINT_LOAD_RADIUS_MM),
            "load_width_mm": 0.0,
        }
    )


def point_load_table() -> pd.DataFrame:
    """The LP's collapse load of `point_load_arch` (N) and hinges beside each published value, with the
    weight of the arch here (straight-faced polygons) and of the source's circular sectors (N)."""
    case = point_load_arch()
    found = load_analysis(case)
    radii = units.mm(
        np.array([case.geometry.internal_radius_mm, case.geometry.internal_radius_mm + case.geometry.thickness_mm])
    )
    sectors = 0.5 * math.pi * float(np.diff(radii**2)[0]) * units.mm(case.geometry.depth_mm)
    sector_weight = sectors * case.material.density_g_per_cm3 * 1000.0 * case.loading.gravity_m_per_s2
    return pd.DataFrame(
        {"method": method, "published_N": published, "lp_N": found.multiplier,
         "relative_difference": found.multiplier / published - 1.0, "lp_hinges": found.hinge_labels,
         "arch_weight_N": found.arch_weight_N, "sector_arch_weight_N": sector_weight}
        for method, published in PUBLISHED_POINT_LOAD_N.items()
    )  # fmt: skip
