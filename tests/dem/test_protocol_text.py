"""A DEM run's summary.json says how its support path read its states (`numerics.support_path_states`):
a run says which numerics it used (docs/numerics.md, "Collapse")."""

from __future__ import annotations

from yadearch.case.config import preset
from yadearch.dem.simulate import criterion_text


def test_the_loading_protocol_names_the_states_the_path_compares():
    scene = criterion_text(preset("set2").with_overrides({"support_path_states": "scene"}).numerics)
    static = criterion_text(preset("set2").with_overrides({"support_path_states": "static"}).numerics)
    assert "each as its hold leaves it" in scene and "static model's stable equilibrium" not in scene
    assert "each read at the static model's stable equilibrium its hold sits in" in static


def test_the_default_auto_reading_is_named_as_the_one_it_makes():
    auto = preset("set2")
    assert auto.numerics.support_path_states == "auto"
    assert "static model's stable equilibrium" in criterion_text(auto.numerics)
    assert "each as its hold leaves it" in criterion_text(auto.with_overrides({"contact_model": "cgal"}).numerics)


def test_the_protocol_names_a_relative_bracket_only_where_it_is_set():
    from yadearch.static.simulate import criterion_text as static_criterion_text

    relative = preset("set2").with_overrides({"du_tolerance_ratio": 0.005})
    for text in (criterion_text(relative.numerics), static_criterion_text(relative)):
        assert "narrowed to < 0.1 mm and 0.5 % of its upper end" in text
    assert "of its upper end" not in criterion_text(preset("set2").numerics)
