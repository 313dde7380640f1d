"""Case presets, TOML round trip, overrides and one-line validation errors."""

import pytest

from yadearch.case.config import case_from_dict, load_case, preset
from yadearch.case.plan import plan_run
from yadearch.cli.commands import main
from yadearch.errors import CaseError


def test_presets_carry_the_paper_values():
    s1, s2 = preset("set1"), preset("set2")
    assert (s1.interface.kn_N_per_mm3, s2.interface.kn_N_per_mm3) == (0.25, 5.2)
    assert s1.ks_N_per_mm3 == pytest.approx(0.125) and s2.ks_N_per_mm3 == pytest.approx(2.6)
    g = s2.geometry
    assert (g.n_voussoirs, g.embrace_deg, g.internal_radius_mm, g.thickness_mm, g.depth_mm) == (
        55,
        125.0,
        300.0,
        24.0,
        120.0,
    )
    assert (s2.material.density_g_per_cm3, s2.material.friction_deg) == (1.64, 41.2)


def test_toml_round_trip(tmp_path):
    case = preset("set1").with_overrides({"numerics.damping": 0.3, "n_voussoirs": 11})
    path = tmp_path / "c.toml"
    path.write_text(case.to_toml())
    again = load_case(path)
    assert again == case
    assert again.geometry.n_voussoirs == 11 and again.numerics.damping == 0.3


@pytest.mark.parametrize(
    "override, message",
    [
        ({"kn_N_per_mm3": -1}, "kn_N_per_mm3 must be in (0, 100000], got -1"),
        ({"embrace_deg": 200}, "embrace_deg must be in (0, 180], got 200"),
        ({"n_voussoirs": 2.5}, "n_voussoirs must be an integer, got 2.5"),
        ({"damping": 1.0}, "damping must be in [0, 1), got 1.0"),
        ({"friction_deg": "steep"}, "friction_deg must be a number in [0, 90), got 'steep'"),
    ],
)
def test_bad_values_give_one_line_errors(override, message):
    with pytest.raises(CaseError) as info:
        preset("set2").with_overrides(override)
    assert str(info.value) == message


def test_unknown_keys_are_refused():
    with pytest.raises(CaseError, match="unknown parameter"):
        preset("set2").with_overrides({"kn": 3})
    with pytest.raises(CaseError, match="unknown parameter"):
        case_from_dict({"interface": {"kn": 3}})


def test_a_misspelt_parameter_is_named_with_the_one_meant():
    """Sixth user trial: a misspelling got no suggestion (and a case file's section no pointer to params)."""
    with pytest.raises(CaseError, match=r"^unknown parameter 'load_positon_over_span' \(did you mean 'load_position_"):
        preset("set2").with_overrides({"load_positon_over_span": 0.3})
    with pytest.raises(
        CaseError, match=r"'geometry.thicknes_mm' \(did you mean 'geometry.thickness_mm'\?\); see `yadearch"
    ):
        case_from_dict({"geometry": {"thicknes_mm": 30.0}})
    with pytest.raises(CaseError, match=r"^unknown parameter 'geometry.bogus'; see `yadearch params` for the list$"):
        preset("set2").with_overrides({"geometry.bogus": 1})
    with pytest.raises(CaseError, match=r"^unknown parameters \['a', 'b'\] in \[geometry\]; see `yadearch params`"):
        case_from_dict({"geometry": {"a": 1, "b": 2}})


def test_cli_reports_bad_input_in_one_line_without_traceback(capsys):
    code = main(["run", "--preset", "set2", "--kn", "-1"])
    err = capsys.readouterr().err
    assert code != 0
    assert err.strip() == "error: kn_N_per_mm3 must be in (0, 100000], got -1.0"


def test_cli_reports_a_missing_case_file(capsys, tmp_path):
    code = main(["run", "--case", str(tmp_path / "nope.toml")])
    assert code != 0
    assert "does not exist" in capsys.readouterr().err


def test_cli_says_in_one_line_when_yade_is_missing(capsys, monkeypatch, tmp_path):
    import yadearch.dem.yade_env

    monkeypatch.setattr(yadearch.dem.yade_env, "YADE_PY_DIRS", (str(tmp_path / "nowhere"),))
    code = main(["run", "--preset", "set1", "--out", str(tmp_path / "run")])
    err = capsys.readouterr().err.strip()
    assert code == 1
    assert err.startswith("error: YADE is not installed") and "\n" not in err


def test_cli_says_in_one_line_when_this_python_cannot_load_debians_yade(capsys, monkeypatch, tmp_path):
    import numpy

    monkeypatch.setattr(numpy, "__version__", "2.4.6")  # a pip install's numpy, not Debian's 1.24
    code = main(["run", "--preset", "set1", "--out", str(tmp_path / "run")])
    err = capsys.readouterr().err.strip()
    assert code == 1
    assert "numpy 2.4.6" in err and "scripts/setup.sh" in err and "\n" not in err


def test_support_speed_falls_as_one_over_sqrt_kn_above_the_reference_stiffness():
    case = preset("set2")  # 80 mm/s, no reference stiffness by default
    assert case.with_overrides({"kn_N_per_mm3": 40.0}).support_speed_mm_per_s == 80.0
    scaled = case.with_overrides({"rate_reference_kn_N_per_mm3": 10.0})
    assert scaled.support_speed_mm_per_s == 80.0  # kn 5.2: below the reference, unchanged
    assert scaled.with_overrides({"kn_N_per_mm3": 40.0}).support_speed_mm_per_s == pytest.approx(40.0)


def test_former_parameter_names_are_read_as_todays(tmp_path):
    """Case files, overrides and stored runs written with settlement_* names mean support_*."""
    old = tmp_path / "old.toml"
    old.write_text(
        "[loading]\nsettlement_direction_deg = -45.0\nmax_settlement_mm = 80.0\n"
        "[numerics]\nsettlement_rate_mm_per_s = 20.0\n"
    )
    case = load_case(old)
    assert (
        case.loading.support_direction_deg,
        case.loading.max_support_displacement_mm,
        case.numerics.support_rate_mm_per_s,
    ) == (-45.0, 80.0, 20.0)
    assert preset("set2").with_overrides({"loading.settlement_direction_deg": 0.0}).loading.support_direction_deg == 0.0
    assert preset("set2").replace(settlement_direction_deg=-30.0).loading.support_direction_deg == -30.0
    both = tmp_path / "both.toml"
    both.write_text("[loading]\nsettlement_direction_deg = -45.0\nsupport_direction_deg = -40.0\n")
    with pytest.raises(CaseError, match="both settlement_direction_deg and support_direction_deg"):
        load_case(both)


def test_the_dems_static_path_states_need_the_joint_elements():
    """Reading a support's path at the static model's equilibria needs that model: CGAL contacts are refused
    in one line naming both settings (docs/numerics.md)."""
    case = preset("set2").with_overrides({"numerics.support_path_states": "static", "numerics.contact_model": "cgal"})
    with pytest.raises(CaseError, match="support_path_states = 'static' .*contact_model = 'cgal'"):
        plan_run(case)
    plan_run(case.with_overrides({"numerics.contact_model": "joint"}))


def test_auto_path_states_read_the_static_model_where_there_is_one():
    """'auto' reads the support's path at the static equilibria with the joint elements, at the holds' own
    states with CGAL contacts (no static model there, and no refusal)."""
    auto = preset("set2").with_overrides({"numerics.support_path_states": "auto"})
    assert auto.numerics.path_states == "static"
    cgal = auto.with_overrides({"numerics.contact_model": "cgal"})
    assert cgal.numerics.path_states == "scene"
    plan_run(cgal)
    for named in ("scene", "static"):
        assert auto.with_overrides({"numerics.support_path_states": named}).numerics.path_states == named


def test_a_wrong_type_is_told_the_range_and_a_whole_bound_is_written_in_full():
    with pytest.raises(CaseError, match=r"n_voussoirs must be an integer in \[2, 1000\], got True"):
        preset("set2").replace(n_voussoirs=True)
    with pytest.raises(CaseError, match=r"seed must be in \[0, 4294967295\], got -1"):
        preset("set2").replace(seed=-1)


def test_a_size_the_shape_does_not_read_is_refused_when_changed():
    """span_mm on the segmental paper arch built the paper's arch unchanged (fourth user trial): a size
    changed that the shape does not read is one line naming the shape's own; set unchanged, or read by
    the shape the same overrides give, it passes."""
    with pytest.raises(CaseError, match=r"geometry.span_mm is not read by shape 'segmental', which is sized by "):
        preset("set2").with_overrides({"span_mm": 900.0})
    assert preset("set2").with_overrides({"span_mm": 600.0}).geometry.span_mm == 600.0  # as it was
    pointed = preset("set2").with_overrides({"shape": "pointed", "span_mm": 900.0})
    with pytest.raises(CaseError, match="geometry.embrace_deg is not read by shape 'pointed'"):
        pointed.with_overrides({"embrace_deg": 150.0})
