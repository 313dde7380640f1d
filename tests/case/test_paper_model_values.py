"""A new arch does not take the paper's 1:10 model's material and joints unawares: the run says which
values it took from the defaults (case.paper.paper_model_values), in its log, summary and warnings."""

from __future__ import annotations

import json

from yadearch.analysis.mechanism import run_warnings
from yadearch.case.config import ArchCase, preset
from yadearch.case.paper import paper_model_values
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
