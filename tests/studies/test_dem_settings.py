"""A study's DEM settings (`--dem-set` of the study scripts): parsed, checked, applied to the DEM's runs
alone and named in the report's command."""

from __future__ import annotations

import argparse

import pytest

from yadearch.case.config import ArchCase
from yadearch.case.numerics_section import SCENE_PATH_STATES, STATIC_PATH_STATES
from yadearch.errors import YadearchError
from yadearch.studies.dem_settings import (
    add_dem_set_option,
    dem_arguments,
    dem_settings_of,
    parse_dem_settings,
    with_dem_settings,
)
from yadearch.studies.loads.passive import _path_readings, passive_case


def test_the_settings_read_back_from_the_arguments_a_report_names_them_with():
    settings = parse_dem_settings(["numerics.support_path_states=static", "numerics.damping = 0.4"])
    assert settings == {"numerics.support_path_states": "static", "numerics.damping": 0.4}
    assert parse_dem_settings(dem_arguments(settings).split(" --dem-set ")[1:]) == settings
    case = with_dem_settings(ArchCase(), settings)
    assert case.numerics.support_path_states == STATIC_PATH_STATES
    assert case.numerics.damping == 0.4
    assert with_dem_settings(case, {}) is case


@pytest.mark.parametrize(
    "item, named",
    [
        ("interface.kn_N_per_mm3=5", "numerics.KEY=VALUE"),
        ("numerics.engine=static", "other than the engine"),
        ("numerics.damping", "numerics.KEY=VALUE"),
        ("numerics.support_path_states=both", "support_path_states"),
        ("numerics.no_such_setting=1", "no_such_setting"),
    ],
)
def test_a_setting_that_is_not_a_dem_numerical_one_is_refused_in_one_line(item, named):
    with pytest.raises(YadearchError) as refused:
        parse_dem_settings([item])
    message = str(refused.value)
    assert named in message and "\n" not in message


def test_a_script_ends_a_bad_setting_with_a_usage_error_not_a_traceback(capsys):
    parser = argparse.ArgumentParser(prog="study")
    add_dem_set_option(parser)
    with pytest.raises(SystemExit) as ended:
        dem_settings_of(parser, parser.parse_args(["--dem-set", "numerics.engine=static"]))
    assert ended.value.code == 2
    assert "study: error: --dem-set expects numerics.KEY=VALUE" in capsys.readouterr().err


@pytest.mark.parametrize(
    "own, other", [(SCENE_PATH_STATES, STATIC_PATH_STATES), (STATIC_PATH_STATES, SCENE_PATH_STATES)]
)
def test_the_settling_dem_is_read_its_own_way_then_the_other_named_for_it(own, other):
    case = passive_case("paper", 1.0, live_load="none", name="settling").with_overrides(
        {"numerics.engine": "dem", "numerics.support_path_states": own}
    )
    (first, first_case), (second, second_case) = _path_readings(case)
    assert (first, first_case) == (own, case)
    assert second == other and second_case.numerics.support_path_states == other
    assert second_case.name == f"settling_{other}_states"
    static = case.with_overrides({"numerics.engine": "static"})
    assert _path_readings(static) == [("", static)]
