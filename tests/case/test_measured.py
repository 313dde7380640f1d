"""A surveyed arch (geometry.shape 'measured', `ya.measured_case`, `yadearch survey`): the paper's arch
given as its own surveyed joints is the same arch (blocks to round-off, du and hinges on the static
engine, the rigid limit); a ring of varying thickness builds and stands; bad surveys are refused in
one line."""

from __future__ import annotations

import numpy as np
import pytest
from surveys import surveyed_blocks, surveyed_joints, thicker_at_the_haunches

from yadearch.api.measured import measured_case
from yadearch.case.config import preset
from yadearch.case.mechanics import arch_geometry
from yadearch.cli.commands import main
from yadearch.errors import CaseError
from yadearch.solve.limit import limit_analysis
from yadearch.solve.static_path import StaticLoading

SMALL = {"geometry.n_voussoirs": 15}


def _du(case) -> tuple[float, list]:
    loading = StaticLoading.of(case.with_overrides({"numerics.engine": "static"}))
    loading.selfweight()
    path = loading.follow()
    return path.du, loading.fold_mode(path.upper).labels


def test_the_paper_arch_surveyed_is_the_paper_arch():
    base = preset("set2").with_overrides(SMALL)
    surveyed = measured_case(surveyed_joints(base), base=base)
    for a, b in zip(arch_geometry(base).blocks, arch_geometry(surveyed).blocks):
        assert np.abs(a - b).max() < 1e-12
    assert surveyed.geometry.n_voussoirs == 15 and surveyed.geometry.thickness_mm == pytest.approx(24.0, rel=1e-12)
    assert _du(surveyed) == _du(base)
    assert limit_analysis(surveyed).du_rigid_mm == pytest.approx(
        limit_analysis(base, mirror=False).du_rigid_mm, rel=1e-9
    )


def test_a_ring_thicker_at_the_haunches_builds_and_stands():
    base = preset("set2").with_overrides(SMALL)
    thick = measured_case(thicker_at_the_haunches(base), base=base)
    lengths = [j.length for j in arch_geometry(thick).joints]
    assert max(lengths) == pytest.approx(1.5 * min(lengths), rel=0.05)
    du, _ = _du(thick)
    assert du > _du(base)[0]  # thicker haunches carry the settlement further


def test_bad_surveys_are_refused_in_one_line(tmp_path, capsys):
    base = preset("set2").with_overrides(SMALL)
    joints = surveyed_joints(base)
    with pytest.raises(CaseError, match="missing y_extrados_mm"):
        measured_case(joints.drop(columns="y_extrados_mm"))
    with pytest.raises(CaseError, match="needs 3 joints at least"):
        measured_case(joints.head(2))
    with pytest.raises(CaseError, match="give the joints left to right"):
        measured_case(joints.iloc[::-1].reset_index(drop=True))
    swapped = joints.rename(columns={"x_intrados_mm": "x_extrados_mm", "x_extrados_mm": "x_intrados_mm",
                                     "y_intrados_mm": "y_extrados_mm", "y_extrados_mm": "y_intrados_mm"})  # fmt: skip
    with pytest.raises(CaseError, match="the extrados above"):
        measured_case(swapped)
    with pytest.raises(CaseError, match=r"joints are 0.024 mm long on average .* read in mm"):  # given in metres
        measured_case(joints / 1000.0)
    with pytest.raises(CaseError, match="n_voussoirs must be 15 for 16 measured joints"):
        arch_geometry(measured_case(joints, base=base).with_overrides({"geometry.n_voussoirs": 14}))
    survey_file = tmp_path / "joints.csv"
    joints.to_csv(survey_file, index=False)
    assert main(["survey", str(survey_file), "--preset", "set2", "--out", str(tmp_path / "arch.toml")]) == 0
    assert "15 voussoirs between 16 measured joints" in capsys.readouterr().out
    assert main(["run", "--case", str(tmp_path / "arch.toml"), "--engine", "static", "--no-figures",
                 "--out", str(tmp_path / "run")]) == 0  # fmt: skip


def test_a_survey_of_blocks_is_the_arch_its_joints_make(tmp_path):
    """The paper's arch given block by block (each voussoir's four corners, the supports marked, in any
    order) is the same arch; with the corners off by up to 0.2 mm (a survey's gaps) each joint corner is
    the mean of its two blocks' and the arch stays within those 0.2 mm; read from a JSON file too."""
    import json

    base = preset("set2").with_overrides(SMALL)
    exact = measured_case(surveyed_blocks(base), base=base)
    for a, b in zip(arch_geometry(base).blocks, arch_geometry(exact).blocks):
        assert np.abs(a - b).max() < 1e-12
    assert _du(exact) == _du(base)
    path = tmp_path / "survey.json"
    path.write_text(json.dumps(surveyed_blocks(base, gap_mm=0.2, seed=3)))
    gapped = measured_case(path, base=base)
    joints = np.array(gapped.geometry.joint_points_mm) - np.array(exact.geometry.joint_points_mm)
    assert 0.0 < np.abs(joints).max() <= 0.2


@pytest.mark.parametrize(
    ("change", "said"),
    [
        (lambda s: _voussoir(s).update(corners=_out_of_order(_voussoir(s)["corners"])), "not a convex polygon of 5"),
        (lambda s: [b.pop("support", None) for b in s["blocks"]], "mark exactly one block 'support': 'left'"),
        (
            lambda s: s.update(joint_tolerance_mm=1e-9) or s.update(blocks=_gapped(s["blocks"])),
            r"with no block; the nearest, \S+, is [\d.]+ mm off",
        ),
        (lambda s: _voussoir(s).update(corners="abc"), "needs 'corners'"),
    ],
    ids=["corners out of order", "no supports", "gaps beyond the tolerance", "no corners"],
)
def test_a_survey_of_blocks_that_makes_no_ring_is_refused_in_one_line(change, said):
    base = preset("set2").with_overrides(SMALL)
    survey = surveyed_blocks(base)
    change(survey)
    with pytest.raises(CaseError, match=said) as error:
        measured_case(survey, base=base)
    assert "\n" not in str(error.value)


def _voussoir(survey: dict) -> dict:
    """The survey's first block that is not a support."""
    return next(b for b in survey["blocks"] if "support" not in b)


def _gapped(blocks: list) -> list:
    """`blocks` with every corner moved 0.01 mm: no two neighbours share a corner to 1e-9 mm."""
    return [{**b, "corners": (np.asarray(b["corners"]) + 0.01 * (k + 1)).tolist()} for k, b in enumerate(blocks)]


def _out_of_order(corners: list) -> list:
    """A voussoir's four corners with a fifth, beyond its extrados, listed between its intrados corners."""
    a_in, b_in, b_out, a_out = np.asarray(corners)
    beyond = (b_out + a_out) / 2.0 + (b_out + a_out - a_in - b_in) / 2.0
    return [a_in.tolist(), beyond.tolist(), b_in.tolist(), b_out.tolist(), a_out.tolist()]


def test_a_survey_file_is_read_as_a_spreadsheet_writes_it_and_its_sizes_stay_surveyed(tmp_path, capsys):
    """Found in a user trial: a non-numeric or empty cell is named by row and column, not a traceback;
    a header with spaces after its commas is read; a file of one column hints at its separator; the
    case `survey` writes leaves the increments check to `run` (on); a surveyed arch's thickness and
    joints' orientation, set by its survey, are refused when changed by hand."""
    base = preset("set2").with_overrides(SMALL)
    joints = surveyed_joints(base)
    bad = joints.astype(object)
    bad.iloc[1, 0] = "abc"
    with pytest.raises(CaseError, match="row 3, column x_intrados_mm: 'abc' is not a number"):
        measured_case(bad)
    spaced = tmp_path / "spaced.csv"
    spaced.write_text(joints.to_csv(index=False).replace(",", ", "))
    assert measured_case(spaced, base=base).geometry.n_voussoirs == 15
    semicolons = tmp_path / "semicolons.csv"
    semicolons.write_text(joints.to_csv(index=False, sep=";"))
    with pytest.raises(CaseError, match="is the file separated by commas"):
        measured_case(semicolons)
    out = tmp_path / "arch.toml"
    assert main(["survey", str(spaced), "--preset", "set2", "--out", str(out)]) == 0
    assert "increments_check" not in out.read_text()
    case = measured_case(spaced, base=base)
    for key in ("geometry.thickness_mm", "geometry.joint_orientation"):
        value = 100.0 if key.endswith("_mm") else "vertical"
        with pytest.raises(CaseError, match=f"{key} of a surveyed arch is .*survey it again"):
            case.with_overrides({key: value})


def test_a_surveyed_case_surveyed_again_takes_the_new_surveys_thickness():
    base = preset("set2").with_overrides(SMALL)
    first = measured_case(surveyed_joints(base), base=base)
    again = measured_case(thicker_at_the_haunches(base), base=first)
    assert again.geometry.thickness_mm > first.geometry.thickness_mm
