"""Axis labels and legend entries of case parameters in the paper's style: a readable name and its
unit in parentheses ("face bump s.d. (mm)", "$k_n$ (N/mm³)"), from the parameter's name, whose suffix
carries its unit (`yadearch params`), instead of the raw name."""

from __future__ import annotations

UNIT_SUFFIXES = (  # a parameter's unit from its name's suffix, the longest suffix first
    ("_N_per_mm3", "N/mm³"),
    ("_g_per_cm3", "g/cm³"),
    ("_mm_per_s2", "mm/s²"),
    ("_mm_per_s", "mm/s"),
    ("_m_per_s2", "m/s²"),
    ("_mrad", "mrad"),
    ("_deg", "°"),
    ("_MPa", "MPa"),
    ("_mm", "mm"),
    ("_N", "N"),
    ("_g", "g"),
    ("_s", "s"),
)
NAMES = {  # names the paper writes as symbols
    "kn": "$k_n$",
    "ks_over_kn": "$k_s/k_n$",
    "n_voussoirs": "voussoirs",
    "t_over_R": "$t/R$",
}
WORDS = {"sd": "s.d.", "dx": "Δx", "dy": "Δy"}  # abbreviations in a name, as a label writes them


def split_unit(column: str) -> tuple[str, str]:
    """(name without its unit suffix, unit or "") of a parameter or column name (any section prefix dropped)."""
    bare = column.rsplit(".", 1)[-1]
    for suffix, unit in UNIT_SUFFIXES:
        if bare.endswith(suffix) and len(bare) > len(suffix):
            return bare[: -len(suffix)], unit
    return bare, ""


def parameter_name(column: str) -> str:
    """The readable name of a parameter, without its unit: "face bump s.d.", "$k_n$"."""
    name, _ = split_unit(column)
    return NAMES.get(name, " ".join(WORDS.get(word, word) for word in name.split("_")))


def parameter_label(column: str) -> str:
    """An axis label: the readable name and the unit in parentheses ("face bump s.d. (mm)")."""
    unit = split_unit(column)[1]
    return f"{parameter_name(column)} ({unit})" if unit else parameter_name(column)


def parameter_setting(column: str, value: object) -> str:
    """A legend entry for one value of a parameter: "$k_n$ = 5.2 N/mm³", "shape = pointed"."""
    unit = split_unit(column)[1]
    shown = f"{value:g}" if isinstance(value, float) else str(value)
    return f"{parameter_name(column)} = {shown}" + (f" {unit}" if unit else "")
