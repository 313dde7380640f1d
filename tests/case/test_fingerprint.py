"""A case's fingerprint (the lean campaigns' batch records, the capacity map's rigid cache) stays the same
when a later version adds a parameter, as a case.toml written before it reads the same: a killed campaign
resumes after an upgrade instead of refusing or re-running its records; any value that changes what a run
computes changes it."""

from __future__ import annotations

import json

from yadearch.case.comparison import as_ran, fingerprinted
from yadearch.case.config import preset
from yadearch.studies.capacity.campaign import rigid_key

ADDED_LATER = {
    "geometry": ("intrados_points_mm", "extrados_points_mm"),
    "loads": ("load_dispersal", "load_dispersal_deg"),
}


def _key(data: dict) -> str:
    return json.dumps(fingerprinted(data), sort_keys=True)


def test_parameters_added_later_leave_the_fingerprint_alone():
    case = preset("set2").with_overrides({"kn_N_per_mm3": 100.0, "live_load": "vertical"})
    now = case.to_dict()
    before = {section: dict(values) if isinstance(values, dict) else values for section, values in now.items()}
    for section, names in ADDED_LATER.items():
        for name in names:
            del before[section][name]
    assert _key(before) == _key(now)


def test_what_a_run_computes_changes_the_fingerprint():
    case = preset("set2")
    for change in ({"kn_N_per_mm3": 100.0}, {"load_dispersal_deg": 20.0}, {"thickness_mm": 30.0}):
        assert _key(case.with_overrides(change).to_dict()) != _key(case.to_dict())
    assert rigid_key(case.with_overrides({"thickness_mm": 30.0})) != rigid_key(case)
    assert rigid_key(case.with_overrides({"kn_N_per_mm3": 100.0})) == rigid_key(case)  # kn: not the rigid limit's


def _reading(engine: str, states: str, contact_model: str = "joint") -> dict:
    """A stored case of set 2 on `engine` whose DEM path reads `states` with `contact_model`."""
    overrides = {"numerics.engine": engine, "numerics.support_path_states": states}
    return preset("set2").with_overrides({**overrides, "numerics.contact_model": contact_model}).to_dict()


def test_a_path_reading_compares_as_what_it_resolves_to():
    """'auto' is 'static' with the joint elements and 'scene' with CGAL contacts, so a DEM run made with
    either named reuses its folder under the default; the static engine reads no DEM path at all."""
    assert as_ran(_reading("dem", "auto")) == as_ran(_reading("dem", "static"))
    assert as_ran(_reading("dem", "auto")) != as_ran(_reading("dem", "scene"))
    assert as_ran(_reading("dem", "auto", "cgal")) == as_ran(_reading("dem", "scene", "cgal"))
    assert _key(_reading("static", "auto")) == _key(_reading("static", "scene")) == _key(_reading("static", "static"))
