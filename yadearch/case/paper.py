"""Whether a case is the paper's arch and test (its geometry, blocks, material, settlement of the
right support, perfect joints) at any kn: only then do the paper's numbers belong beside its results
(figures, reports)."""

from __future__ import annotations

from functools import cache
from typing import Any

from yadearch.case import reference
from yadearch.case.comparison import as_ran
from yadearch.case.config import DEFAULT_NAME, ArchCase, preset
from yadearch.case.materials import MATERIAL_KEY, MATERIALS, PRESET_FIELD
from yadearch.case.shape import SIZES

PAPER_SECTIONS = ("geometry", "material", "loading", "imperfections", "loads")  # what makes a run the paper's case
NOT_PHYSICAL = {"max_support_displacement_mm"}  # a run's stopping point, not part of the arch or its loading
# the material and joint values a case takes from the paper's 1:10 model when it does not give its own
MODEL_VALUES = (
    ("material", "density_g_per_cm3"),
    ("material", "friction_deg"),
    ("interface", "kn_N_per_mm3"),
    ("interface", "ks_over_kn"),
)


def paper_mismatch(case: dict[str, Any]) -> str | None:
    """How a case (as its case.toml's dictionary) differs from the paper's arch, material, loading and
    perfect joints (the first difference, e.g. "geometry.n_voussoirs 10, paper 55"); None if it is the
    paper's case."""
    ran, paper = as_ran(case), as_ran(preset(next(iter(reference.SETS))).to_dict())
    unread = {key for sizes in SIZES.values() for key in sizes} - set(SIZES.get(ran["geometry"]["shape"], ()))
    for section in PAPER_SECTIONS:
        for key, value in paper[section].items():
            if section == "geometry" and key in unread:  # a size this shape does not read: not the arch
                continue
            if key not in NOT_PHYSICAL and ran[section][key] != value:
                return f"{section}.{key} {ran[section][key]!r}, paper {value!r}"
    return None


def is_paper_arch(case: ArchCase) -> bool:
    """Whether `case` is the paper's case at any kn (`paper_mismatch`)."""
    return paper_mismatch(case.to_dict()) is None


def off_the_paper(case: ArchCase, named: bool) -> ArchCase:
    """`case`, named DEFAULT_NAME where it still carries a preset's name but its geometry is no longer the
    paper's arch and no name was given (`named`): a new arch is not filed, reported or compared as the
    paper's. The paper's arch under another kn, material, movement or load keeps the preset's name."""
    if named or case.name not in reference.SETS:
        return case
    if case.to_dict()["geometry"] == preset(case.name).to_dict()["geometry"]:
        return case
    return case.with_overrides({"name": DEFAULT_NAME})


def paper_model_values(case: ArchCase) -> dict[str, Any] | None:
    """On an arch whose geometry is not the paper's, the material and joint parameters still at the
    paper's 1:10 model's values (the defaults), by qualified name: a new arch must not take them
    unawares. None for the paper's geometry, or when the case gives every one of them."""
    ran, model = case.to_dict(), _model_case()
    if ran["geometry"] == model["geometry"]:
        return None
    named = MATERIALS[ran[MATERIAL_KEY][PRESET_FIELD]].values() if ran[MATERIAL_KEY][PRESET_FIELD] else {}
    taken = {
        f"{section}.{key}": ran[section][key]
        for section, key in MODEL_VALUES
        if ran[section][key] == model[section][key] and not (section == MATERIAL_KEY and key in named)
    }
    return taken or None


@cache
def _model_case() -> dict[str, Any]:
    """The default case (the paper's 1:10 model) as its dictionary, made once: every run compares with it."""
    return ArchCase().to_dict()


def model_values_text(taken: dict[str, Any]) -> str:
    """The warning for `paper_model_values`' answer, one line."""
    values = ", ".join(f"{name} {value:g}" for name, value in taken.items())
    named = any(name.startswith(f"{MATERIAL_KEY}.") for name in taken)
    return (
        f"this arch is not the paper's but has the paper's 1:10 model's values (the defaults): {values}; "
        "unless they are your arch's too, give its own in the case file ([material], [interface]) or with --set"
        + (", or name a material (--set material=NAME, docs/materials.md)" if named else "")
    )
