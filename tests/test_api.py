"""The Python API on a synthetic run folder (no YADE): typed results, the paper's hinge labels, the
equilibrium points of the loading, figures written into the run folder."""

from __future__ import annotations

import pytest
from synthetic_runs import make_run

import yadearch as ya
from yadearch.errors import CampaignError, RunFolderError


def test_the_api_is_one_namespace_imported_on_first_use():
    for name in ("preset", "run", "open_run", "sweep", "montecarlo", "calibrate", "limit"):
        assert callable(getattr(ya, name))
    with pytest.raises(AttributeError):
        ya.not_a_function  # noqa: B018


def test_a_case_is_replaced_by_bare_parameter_names():
    case = ya.preset("set2").replace(kn_N_per_mm3=10.0, damping=0.3)
    assert case.interface.kn_N_per_mm3 == 10.0 and case.numerics.damping == 0.3
    assert ya.preset("set2").interface.kn_N_per_mm3 == 5.2  # the preset itself is untouched


def test_an_opened_run_gives_du_and_hinges_with_the_papers_labels(tmp_path):
    summary = make_run(tmp_path / "run")
    result = ya.open_run(tmp_path / "run")
    assert result.du_mm == summary.du_mm and result.du_first_mm == summary.du_first_mm and result.collapsed
    assert [(h.label, h.paper_label) for h in result.hinges] == [("1E", "D"), ("12I", "A"), ("30E", "B"), ("56E", "C")]


def test_the_loading_curve_holds_only_equilibrium_points_in_increasing_displacement(tmp_path):
    make_run(tmp_path / "run")
    curve = ya.open_run(tmp_path / "run").loading_curve()
    assert set(curve["stage"]) <= {"selfweight", "equilibrium"}
    assert curve["delta_mm"].is_monotonic_increasing


def test_figures_go_into_the_run_folder(tmp_path):
    make_run(tmp_path / "run")
    paths = ya.open_run(tmp_path / "run").write_figures()
    for pdf, png in paths.values():
        assert pdf.parent == tmp_path / "run" / "figures" and pdf.stat().st_size > 0 and png.stat().st_size > 0


def test_the_collapse_is_drawn_into_a_given_axes_or_a_new_figure(tmp_path):
    from matplotlib.figure import Figure

    make_run(tmp_path / "run")
    result = ya.open_run(tmp_path / "run")
    own = result.plot_collapse()
    assert isinstance(own, Figure) and own.axes[0].get_aspect() == 1.0
    fig = Figure()
    ax_left, ax_right = fig.subplots(1, 2)
    assert result.plot_collapse(ax=ax_right) is fig
    assert not ax_left.collections and [len(c.get_paths()) for c in ax_right.collections] == [57, 57]  # outlines


def test_a_result_lists_the_references_it_stands_on(tmp_path):
    make_run(tmp_path / "paper")
    make_run(tmp_path / "coarse", paper_arch=False)
    assert ya.open_run(tmp_path / "paper").references[0].startswith("Effect of geometrical imperfections")
    coarse = ya.open_run(tmp_path / "coarse").references
    assert len(coarse) == 1 and "Yade" in coarse[0]


@pytest.mark.parametrize("bad", [None, {"kn_N_per_mm3": 1.0}, 3.5])
def test_the_api_refuses_what_is_not_a_case_naming_the_argument(bad, tmp_path):
    with pytest.raises(TypeError, match="case must be an ArchCase"):
        ya.run(bad, out=tmp_path / "run")
    with pytest.raises(TypeError, match="case must be an ArchCase"):
        ya.limit(bad)


def test_a_preset_name_stands_for_its_case_and_an_unknown_engine_is_refused(tmp_path):
    assert ya.limit("set2").du_rigid_mm == pytest.approx(ya.limit(ya.preset("set2")).du_rigid_mm)
    with pytest.raises(ValueError, match="engine must be one of dem, static, got 'fast'"):
        ya.run("set2", out=tmp_path / "run", engine="fast")


def test_the_static_engine_runs_through_the_api_and_says_so(tmp_path):
    """A 9-voussoir arch at kn 5.2 settles to 122.29 mm on 1E 2I 6E 10E (the DEM: 122.21 mm)."""
    case = ya.preset("set2").with_overrides({"n_voussoirs": 9})
    res = ya.run(case, out=tmp_path / "static", engine="static", figures=False)
    assert res.engine == "static" and res.summary.unused_parameters["damping"] == case.numerics.damping
    assert res.du_mm == pytest.approx(122.21, rel=0.01)
    assert [str(h) for h in res.hinges] == ["1E", "2I", "6E", "10E"]
    assert (res.loading_curve()["min_stiffness_N_per_m"].dropna() > 0).all()


@pytest.mark.parametrize(
    "call, error, message",
    [
        (lambda out: ya.sweep("set2", out, kn_N_per_mm3=[]), ValueError, "kn_N_per_mm3: no values to run"),
        (
            lambda out: ya.sweep("set2", out, kn_N_per_mm3=5.2),
            TypeError,
            "kn_N_per_mm3: give a list of values, got 5.2",
        ),
        (
            lambda out: ya.sweep("set2", out, kn_N_per_mm3=[1.0, -1.0]),
            ValueError,
            r"run kn-1: kn_N_per_mm3 must be in \(0, 100000\], got -1.0; nothing was run",
        ),
        (
            lambda out: ya.montecarlo("set2", out, samples=0),
            ValueError,
            r"samples must be an integer in \[1, 100000\], got 0",
        ),
        (
            lambda out: ya.montecarlo("set2", out, samples=3, face_bump_sd_mm=[-1.0]),
            ValueError,
            r"face_bump_sd_mm must be in \[0, 1000\], got -1.0",
        ),
        (lambda out: ya.sensitivity("set2", out, base_points=12), ValueError, "base_points must be .*a power of two"),
        (lambda out: ya.capacity("set2", out, step_deg=7), CampaignError, "step_deg must divide 180"),
        (lambda out: ya.report([], out), RunFolderError, "at least one run folder"),
    ],
)
def test_campaigns_refuse_bad_arguments_before_anything_runs(call, error, message, tmp_path):
    with pytest.raises(error, match=message):
        call(tmp_path / "out")
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").rglob("summary.json"))


def test_an_arch_that_cannot_stand_is_told_with_the_parameters_that_decide_it(tmp_path):
    from yadearch.errors import RunFailedError

    case = ya.preset("set2").with_overrides({"n_voussoirs": 9, "friction_deg": 0.0})
    with pytest.raises(
        RunFailedError,
        match=r"does not stand under its own weight .*thickness_mm 24, "
        r"internal_radius_mm 300, embrace_deg 125, n_voussoirs 9, friction_deg 0, kn 5.2 N/mm3",
    ):
        ya.run(case, out=tmp_path / "run", engine="static")


def test_a_case_files_path_is_a_case_and_a_monte_carlo_draws_something(tmp_path):
    """`ya.run("my_arch.toml")` reads the file (it was taken for a preset's name); a Monte Carlo with no
    standard deviation to draw from is refused before it runs the same arch again and again."""
    from yadearch.api.runs import as_case

    path = tmp_path / "my_arch.toml"
    path.write_text(ya.preset("set2").replace(n_voussoirs=15, name="mine").to_toml())
    assert as_case(str(path)).name == "mine" and as_case(path).geometry.n_voussoirs == 15
    with pytest.raises(CampaignError, match="no imperfection is drawn at random"):
        ya.montecarlo("set2", tmp_path / "mc", samples=3, engine="static")


def test_a_limit_march_s_progress_names_the_mirror_image_s_march(monkeypatch, capsys):
    """`limit` solves the mirror image after the case's march: its positions start again from rest, and
    its progress lines say whose they are (eighth user trial: the position seemed to go backwards)."""
    from yadearch.api import runs

    monkeypatch.setattr(runs, "PROGRESS_EVERY_S", 0.0)
    runs.position_lines("arch", 150.0)(80.0)
    runs.position_lines("arch", 150.0, mirrored=True)(5.0)
    lines = capsys.readouterr().out.splitlines()
    assert ["(the mirror image)" in line for line in lines] == [False, True]
