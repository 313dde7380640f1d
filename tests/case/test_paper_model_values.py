"""A new arch does not take the paper's 1:10 model's material and joints unawares: the run says which
values it took from the defaults (case.paper.paper_model_values), in its log, summary and warnings."""

from __future__ import annotations

import json

import pytest

from yadearch.analysis.mechanism import run_warnings
from yadearch.case.config import DEFAULT_NAME, ArchCase, case_from_dict, preset
from yadearch.case.paper import off_the_paper, paper_model_values
from yadearch.cli.options import resolve_case
from yadearch.errors import CaseError
from yadearch.results.summary import RunSummary

SEMICIRCLE = {"geometry.embrace_deg": 180.0, "geometry.thickness_mm": 45.0}


def test_the_papers_arch_takes_its_own_values():
    assert paper_model_values(preset("set1")) is None
    assert paper_model_values(preset("set2")) is None
    assert paper_model_values(ArchCase()) is None


def test_another_arch_on_the_defaults_is_told_which_values_it_took():
    taken = paper_model_values(ArchCase().with_overrides(SEMICIRCLE))
    assert taken == {
        "material.density_g_per_cm3": 1.64,
        "material.friction_deg": 41.2,
        "interface.kn_N_per_mm3": 5.2,
        "interface.ks_over_kn": 0.5,
    }


def test_values_the_user_gives_are_not_listed():
    own = ArchCase().with_overrides({**SEMICIRCLE, "density_g_per_cm3": 2.1, "kn_N_per_mm3": 100.0})
    assert set(paper_model_values(own) or {}) == {"material.friction_deg", "interface.ks_over_kn"}
    given = own.with_overrides({"friction_deg": 35.0, "ks_over_kn": 0.4})
    assert paper_model_values(given) is None


def test_the_warning_names_each_value_and_where_to_give_it():
    summary = RunSummary(
        du_mm=None,
        hinges_at_collapse=(),
        steps=0,
        wall_s=0.0,
        paper_model_values={"material.density_g_per_cm3": 1.64, "interface.kn_N_per_mm3": 5.2},
    )
    (warning,) = [w for w in run_warnings(summary) if "1:10" in w]
    assert "material.density_g_per_cm3 1.64" in warning and "interface.kn_N_per_mm3 5.2" in warning
    assert "[material]" in warning and "\n" not in warning


def test_a_static_run_of_another_arch_records_and_logs_what_it_took(tmp_path):
    from yadearch.static.simulate import simulate_static

    lines: list[str] = []
    case = ArchCase(name="semi").with_overrides(
        {**SEMICIRCLE, "engine": "static", "n_voussoirs": 15, "max_support_displacement_mm": 2.0}
    )
    summary = simulate_static(case, tmp_path / "run", log=lines.append)
    assert summary.paper_model_values == paper_model_values(case)
    assert any("1:10" in line and "interface.kn_N_per_mm3 5.2" in line for line in lines)
    written = json.loads((tmp_path / "run" / "summary.json").read_text())
    assert RunSummary.from_json(written).paper_model_values == summary.paper_model_values


def test_a_preset_changed_off_the_papers_arch_is_not_named_for_it():
    """`replace` (the API) and `--set` (the command line) alike: a pointed arch made from set 2 is filed as
    "custom", set 2 at another kn stays set 2, and a name given or a case's own name is kept."""
    assert preset("set2").replace(shape="pointed", span_mm=600.0).name == DEFAULT_NAME
    assert preset("set2").replace(kn_N_per_mm3=10.0).name == "set2"
    assert preset("set2").replace(live_load="vertical", support_direction_deg=0.0).name == "set2"  # its arch, loaded
    assert preset("set2").replace(embrace_deg=180.0, name="mine").name == "mine"
    own = preset("set2").with_overrides({"name": "bridge", **SEMICIRCLE})
    assert off_the_paper(own, named=False).name == "bridge"
    assert resolve_case("set2", None, None, ("shape=pointed", "span_mm=600")).name == DEFAULT_NAME
    assert resolve_case("set2", None, 100.0, ()).name == "set2"


def test_a_parameter_written_above_the_sections_is_told_where_it_goes():
    with pytest.raises(CaseError, match=r"thickness_mm is a parameter of \[geometry\], not a section"):
        case_from_dict({"thickness_mm": 30.0})
