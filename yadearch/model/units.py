"""Conversion from the paper's units (mm, N/mm^3, g/cm^3, MPa, deg) to SI, in one place."""

import math
from typing import TypeVar

import numpy as np

Length = TypeVar("Length", float, np.ndarray)  # a number or an array of them, in and out

MM = 1e-3  # m per mm
N_PER_MM3 = 1e9  # (N/m^3) per (N/mm^3)
G_PER_CM3 = 1e3  # (kg/m^3) per (g/cm^3)
MPA = 1e6  # Pa per MPa
MRAD = 1e-3  # rad per mrad


def mm(value_mm: Length) -> Length:
    """Millimetres to metres."""
    return value_mm * MM


def to_mm(value_m: Length) -> Length:
    """Metres to millimetres."""
    return value_m / MM


def stiffness_per_volume(value_n_per_mm3: float) -> float:
    """Interface stiffness N/mm^3 (stress per relative displacement) to N/m^3."""
    return value_n_per_mm3 * N_PER_MM3


def density(value_g_per_cm3: float) -> float:
    """g/cm^3 to kg/m^3."""
    return value_g_per_cm3 * G_PER_CM3


def pressure(value_mpa: float) -> float:
    """MPa to Pa."""
    return value_mpa * MPA


def radians(value_deg: float) -> float:
    return math.radians(value_deg)


def mrad(value_mrad: Length) -> Length:
    """Milliradians to radians."""
    return value_mrad * MRAD


def to_mrad(value_rad: Length) -> Length:
    """Radians to milliradians."""
    return value_rad / MRAD
