"""Named materials (case/materials.py, docs/materials.md): a name gives a case its density and
friction unless the case gives them, the run says which it used, and a rigid arch's du does not
depend on its density (self-weight alone: every force scales with it)."""

from __future__ import annotations

import pytest

from yadearch.case.comparison import as_ran
from yadearch.case.config import case_from_dict, preset
from yadearch.case.materials import MATERIALS, material_text
from yadearch.case.paper import paper_model_values
from yadearch.errors import CaseError
from yadearch.solve.limit import limit_analysis

SEMICIRCLE = {"geometry.embrace_deg": 180.0, "geometry.thickness_mm": 60.0}  # stands on rigid blocks


def test_a_named_material_gives_its_values_unless_the_case_gives_them():
    granite = MATERIALS["granite"]
    case = preset("set2").with_overrides({"material.preset": "granite"})
    assert (case.material.density_g_per_cm3, case.material.friction_deg) == (granite.density_g_per_cm3, 33.0)
    beside = preset("set2").with_overrides({"material.preset": "granite", "friction_deg": 36.0})
    assert (beside.material.density_g_per_cm3, beside.material.friction_deg) == (2.65, 36.0)
    from_file = case_from_dict({"material": {"preset": "limestone", "density_g_per_cm3": 2.2}})
    assert (from_file.material.density_g_per_cm3, from_file.material.friction_deg) == (2.2, 34.0)
    assert "given: density_g_per_cm3" in material_text(from_file.to_dict()["material"])


def test_a_materials_name_is_not_part_of_the_arch():
    """The same values with or without the name are the same case (a run folder is reused)."""
    named = preset("set2").with_overrides({"material.preset": "sandstone"})
    plain = preset("set2").with_overrides({"density_g_per_cm3": 2.4, "friction_deg": 31.0})
    assert as_ran(named.to_dict()) == as_ran(plain.to_dict())


def test_an_unknown_material_is_refused_in_one_line():
    """(and on the command line: tests/cli/test_bad_inputs.py)"""
    with pytest.raises(CaseError, match=r"^material.preset must be one of paper_model, granite, .*got 'basalt'$"):
        preset("set2").with_overrides({"material.preset": "basalt"})


def test_a_new_arch_with_a_named_material_is_warned_about_its_joints_only():
    case = preset("set2").with_overrides({**SEMICIRCLE, "material.preset": "limestone"})
    assert sorted(paper_model_values(case)) == ["interface.kn_N_per_mm3", "interface.ks_over_kn"]


def test_a_rigid_arch_du_does_not_depend_on_its_density():
    """The rigid march on the paper's arch in limestone and at the paper's density with limestone's
    friction: the same du (113.54 mm) and hinges (self-weight alone, every force scales with the density)."""
    stone = preset("set2").with_overrides({"material.preset": "limestone"})
    light = stone.with_overrides({"material.preset": "", "density_g_per_cm3": 1.64})
    heavy, paper = limit_analysis(stone), limit_analysis(light)
    assert heavy.du_mm is not None and heavy.du_mm == pytest.approx(113.54, abs=0.01)
    assert heavy.du_mm == pytest.approx(paper.du_mm, rel=1e-9)
    assert heavy.collapse_hinges == paper.collapse_hinges
