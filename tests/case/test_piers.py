"""An arch on its piers (case/piers.py, `ya.on_piers`; docs/movements.md, "An arch on its piers"): the
paper's arch on piers 100 mm tall. Wide piers do not move, so the rigid du is that of the arch on fixed
supports; narrow piers overturn about their outer toe under the arch's thrust, and du falls; the static
engine rises toward the rigid answer as the joints stiffen, and its supports carry arch and piers."""

from __future__ import annotations

import pytest
from click.testing import CliRunner

import yadearch as ya
from yadearch.case.config import load_case, preset
from yadearch.case.mechanics import arch_geometry
from yadearch.cli.commands import cli
from yadearch.errors import CampaignError, CaseError
from yadearch.solve.limit import limit_analysis
from yadearch.solve.static_path import StaticLoading
from yadearch.static.records import StaticRecords
from yadearch.static.simulate import simulate_static

HEIGHT_MM = 100.0
WIDE_MM, NARROW_MM = 200.0, 60.0
HINGE_ROTATION = 1e-3  # rad; the records need one, the reactions do not depend on it


def quiet(_: str) -> None:
    """A run's progress lines, unwanted here."""


@pytest.fixture(scope="module")
def narrow():
    return ya.on_piers("set2", HEIGHT_MM, NARROW_MM)


def test_wide_piers_are_fixed_supports():
    """The rigid march on wide piers: the arch's du on fixed supports to 1e-6, on the same joints of the
    ring (each label one further: the pier's base joint is joint 1)."""
    fixed, wide = limit_analysis(preset("set2")), limit_analysis(ya.on_piers("set2", HEIGHT_MM, WIDE_MM))
    assert wide.du_mm == pytest.approx(fixed.du_mm, rel=1e-6)
    shifted = [f"{int(label[:-1]) + 1}{label[-1]}" for label in fixed.collapse_hinges]
    assert list(wide.collapse_hinges) == shifted


def test_narrow_piers_overturn_and_the_static_engine_rises_toward_the_rigid_du(narrow):
    """Narrow piers: the left pier turns about its outer toe (hinge 1E) and du falls to about a third of
    the fixed supports'; the static du rises with kn and ends within 3 % of the rigid march at 10 000."""
    rigid = limit_analysis(narrow)
    assert "1E" in rigid.collapse_hinges and rigid.du_mm < 0.5 * limit_analysis(preset("set2")).du_mm
    static = [simulate_static(narrow.replace(kn_N_per_mm3=kn), None, log=quiet).du_mm for kn in (5.2, 100.0, 10_000.0)]
    assert static[0] < static[1] < static[2] < rigid.du_mm
    assert static[2] == pytest.approx(rigid.du_mm, rel=0.03)


def test_the_supports_carry_the_arch_and_its_piers(narrow):
    loading = StaticLoading.of(narrow)
    row = StaticRecords(loading.arch, HINGE_ROTATION).series_columns(loading.selfweight())
    weight = float(loading.arch.weight[1:-1].sum())
    assert row["left_Ry_N"] + row["right_Ry_N"] == pytest.approx(weight, rel=1e-6)
    assert narrow.geometry.thickness_mm == preset("set2").geometry.thickness_mm  # the ring's, not the piers'


def test_piers_too_narrow_or_out_of_range_are_refused_in_one_line():
    with pytest.raises(CaseError, match=r"^pier_width_mm must be more than 21.29 mm for this arch .*got 10.0$"):
        ya.on_piers("set2", HEIGHT_MM, 10.0)
    with pytest.raises(CampaignError, match=r"^pier_height_mm must be a number in \(0, 100000\], got -1.0$"):
        ya.on_piers("set2", -1.0, NARROW_MM)


def test_the_command_line_writes_the_case_on_its_piers(tmp_path):
    """`yadearch piers` writes the case file that `ya.on_piers` makes, in one line of output."""
    out = tmp_path / "on_piers.toml"
    result = CliRunner().invoke(
        cli, ["piers", "--preset", "set2", "--height-mm", "100", "--width-mm", "60", "--out", str(out)]
    )
    assert result.exit_code == 0 and len(result.output.strip().splitlines()) == 1
    assert load_case(out) == ya.on_piers("set2", HEIGHT_MM, NARROW_MM)


def test_a_case_on_piers_says_so_and_takes_no_second_pair(narrow):
    """The piers are recorded (geometry.piers_mm): the report calls the arch an arch on piers (it said
    'surveyed arch of 57 voussoirs'), its failure to stand names the piers, and piers on piers are
    refused (they stacked silently; fourth user trial)."""
    from yadearch.reporting.run_words import arch_text
    from yadearch.solve.standing import why_not_standing

    assert narrow.geometry.piers_mm == [[HEIGHT_MM, NARROW_MM]]
    assert arch_text(narrow.to_dict()).endswith(f"on piers {HEIGHT_MM:g} mm tall and {NARROW_MM:g} mm wide")
    assert arch_text(narrow.to_dict()).startswith("arch of 55 voussoirs")
    with pytest.raises(CaseError, match=r"^the case is on piers already \(100 mm tall, 60 mm wide"):
        ya.on_piers(narrow, HEIGHT_MM, NARROW_MM)
    thin = narrow.with_overrides({"geometry.thickness_mm": 24.0, "material.friction_deg": 5.0})
    assert "or its piers (60 mm wide) too narrow" in why_not_standing(thin)
    with pytest.raises(CaseError, match="geometry.piers_mm is for shape 'measured' only"):
        arch_geometry(preset("set2").with_overrides({"geometry.piers_mm": [[100.0, 60.0]]}))


def test_piers_too_narrow_to_stand_are_named_by_the_limit_analysis():
    """Piers 22 mm wide (the case accepts more than 21.29 mm) cannot carry the thrust at rest; the
    message said only "too thin, or too little friction" (fifth user trial)."""
    from yadearch.solve.rigid import LimitError

    with pytest.raises(LimitError, match=r"at rest: .* or its piers \(22 mm wide\) too narrow for its thrust$"):
        limit_analysis(ya.on_piers("set2", HEIGHT_MM, 22.0))
