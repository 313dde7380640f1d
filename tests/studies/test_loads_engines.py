"""The engines' comparison on live loads names each case as a reader would (its figure's rows)."""

from __future__ import annotations

from yadearch.studies.loads.engines import case_label, engine_cases


def test_every_case_has_its_own_label_naming_its_arch_load_and_history():
    labels = [case_label(case, after_mm) for case, after_mm in engine_cases()]
    assert len(set(labels)) == len(labels)
    assert "paper's arch: load at 0.25 span, after 44 mm settlement" in labels
    assert "paper's arch: load at 0.25 span, kn 0.25 N/mm\u00b3" in labels
    assert "semicircle, t 40 mm: horizontal acceleration" in labels
    assert all("_" not in label for label in labels)  # no identifiers
