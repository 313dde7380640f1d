"""Whether a case is the paper's arch and test (its geometry, blocks, material, settlement of the
right support, perfect joints) at any kn: only then do the paper's numbers belong beside its results
(figures, reports)."""

from __future__ import annotations

from typing import Any

from yadearch.case import reference
from yadearch.case.config import ArchCase, as_ran, preset

PAPER_SECTIONS = ("geometry", "material", "loading", "imperfections")  # what makes a run the paper's case
NOT_PHYSICAL = {"max_support_displacement_mm"}  # a run's stopping point, not part of the arch or its loading


def paper_mismatch(case: dict[str, Any]) -> str | None:
    """How a case (as its case.toml's dictionary) differs from the paper's arch, material, loading and
    perfect joints (the first difference, e.g. "geometry.n_voussoirs 10, paper 55"); None if it is the
    paper's case."""
    ran, paper = as_ran(case), as_ran(preset(next(iter(reference.SETS))).to_dict())
    for section in PAPER_SECTIONS:
        for key, value in paper[section].items():
            if key not in NOT_PHYSICAL and ran[section][key] != value:
                return f"{section}.{key} {ran[section][key]!r}, paper {value!r}"
    return None


def is_paper_arch(case: ArchCase) -> bool:
    """Whether `case` is the paper's case at any kn (`paper_mismatch`)."""
    return paper_mismatch(case.to_dict()) is None
