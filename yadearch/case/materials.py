"""Named block materials a case can start from (`[material] preset`, `--set material=NAME`): a dry
joint's density and friction for common voussoir materials, each value from a published source
(docs/materials.md has the table with every citation). No joint stiffness: kn depends on the joints'
scale and finish, and no source gives a dry joint's kn for these materials, so a case gives its own."""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass
from typing import Any

from yadearch.errors import CaseError

MATERIAL_KEY = "material"  # --set material=NAME: a named material stands for its [material] values
PRESET_FIELD = "preset"


@dataclass(frozen=True)
class MaterialPreset:
    """A material's dry-joint values (g/cm3, degrees) and where they come from (docs/materials.md)."""

    density_g_per_cm3: float
    friction_deg: float
    source: str

    def values(self) -> dict[str, float]:
        return {"density_g_per_cm3": self.density_g_per_cm3, "friction_deg": self.friction_deg}


MATERIALS: dict[str, MaterialPreset] = {
    "paper_model": MaterialPreset(1.64, 41.2, "the reference paper's 1:10 composite blocks (case/reference.py)"),
    "granite": MaterialPreset(2.65, 33.0, "density 2.6-2.7 (Alden); friction 33 deg dry (Barton 1973)"),
    "limestone": MaterialPreset(2.6, 34.0, "density 2.3-2.7 (Alden); friction 34 deg dry (Barton 1973)"),
    "sandstone": MaterialPreset(2.4, 31.0, "density 2.2-2.8 (Alden); friction 31 deg dry (Barton 1973)"),
    "concrete_block": MaterialPreset(2.4, 38.66, "density 2.4 (BOCA); friction coefficient 0.8 dry (PCI)"),
    "pla_printed": MaterialPreset(
        1.264, 20.8, "solid PLA 1.264 (datasheet, ASTM D792); friction coefficient 0.38 (Santana et al. 2020)"
    ),
}
PRESET_CHOICES = ("", *MATERIALS)  # "" : no named material, the case's own values


def material_preset(name: str) -> MaterialPreset:
    """The named material, or a one-line refusal naming the accepted names."""
    if not isinstance(name, str) or name not in MATERIALS:
        raise CaseError(f"material.preset must be one of {', '.join(MATERIALS)}, got {name!r}")
    return MATERIALS[name]


def fill_from_preset(material: dict[str, Any], given: Collection[str]) -> dict[str, Any]:
    """A case's [material] table with its named material's values, except those `given` by the user
    (a case file's own keys, or the keys set beside the preset)."""
    name = material.get(PRESET_FIELD, "")
    if not name:
        return material
    values = material_preset(name).values()
    return {**material, **{key: value for key, value in values.items() if key not in given}}


def material_text(material: dict[str, Any], defaults: bool = False) -> str:
    """Where a case's density and friction come from, for a run's log: its named material, the defaults
    (`defaults`: another arch left at the paper's 1:10 model's values) or its own."""
    name = material.get(PRESET_FIELD, "")
    values = f"density {material['density_g_per_cm3']:g} g/cm3, friction {material['friction_deg']:g} deg"
    if not name:
        source = "the defaults" if defaults else "the case's own"
        return f"material: {source} ({values})"
    preset = MATERIALS[name]
    changed = [key for key, value in preset.values().items() if material[key] != value]
    return f"material: {name} ({values}; {preset.source}" + (f"; given: {', '.join(changed)})" if changed else ")")
