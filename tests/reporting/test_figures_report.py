"""Figures and the report on a small synthetic run folder written with rundir.write_run (no YADE):
files are produced, and the report's numbers are summary.json's."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from click.testing import CliRunner
from synthetic_runs import make_run

from yadearch.analysis.blocks import case_geometry, snapshot_outlines
from yadearch.analysis.run import analyse_run, load_run
from yadearch.cli.commands import report
from yadearch.errors import YadearchError
from yadearch.plotting import run_figures as figures
from yadearch.reporting.paper_match import match_reference
from yadearch.reporting.report import write_report
from yadearch.results.summary import RunSummary


@pytest.fixture(scope="module")
def written(tmp_path_factory) -> tuple[Path, dict, str]:
    root = tmp_path_factory.mktemp("report")
    summary = make_run(root / "runs" / "set2")
    path = write_report([root / "runs" / "set2"], root / "out")
    return root, summary, path.read_text()


def table_row(markdown: str, first_cell: str) -> list[str]:
    line = next(l for l in markdown.splitlines() if l.startswith(f"| {first_cell} |"))
    return [cell.strip() for cell in line.strip("|").split("|")]


def test_report_numbers_are_those_of_summary_json(written):
    _, summary, markdown = written
    du = f"{summary.du_mm:.2f}"
    assert table_row(markdown, "du (mm)")[3] == du
    row = table_row(markdown, "set2")  # run | engine | movement | du | hinges | paper set | ...
    assert [row[1], row[3], row[5]] == ["dem", du, "set2"]
    hinges = summary.hinge_labels
    assert f"- hinges at collapse: {hinges}" in markdown
    assert row[4] == hinges
    run_hinges = {table_row(markdown, f"hinge {x}")[3].split(" (")[0] for x in "ABC"}
    assert run_hinges <= {f"{h.interface} {h.side}" for h in summary.hinges_at_collapse}
    assert "**Note:**" not in markdown  # the analysis agrees with summary.json


def test_report_compares_with_the_matching_paper_set(written):
    _, summary, markdown = written
    assert "### Comparison with the paper (set2" in markdown
    row = table_row(markdown, "du (mm)")
    assert row[1:3] == ["91.5", "91.8"]
    assert row[5].startswith(f"{summary.du_mm - 91.8:+.2f}")
    assert "asymmetric four-hinge mechanism, E-I-E-E, D at the left support" in markdown


def test_report_shows_provenance_and_links_every_figure(written):
    root, summary, markdown = written
    for key in ("yade_version", "yadearch_version", "git_revision", "steps"):
        assert f"| {key} | {getattr(summary, key)} |" in markdown
    assert "## References\n\n1. Effect of geometrical imperfections" in markdown and "Yade Documentation" in markdown
    links = re.findall(r"\]\((set2/[^)]+)\)", markdown)
    assert {Path(l).suffix for l in links} == {".png", ".pdf", ".csv"}
    for link in links:
        assert (root / "out" / link).stat().st_size > 0


def test_every_figure_is_a_non_empty_pdf_and_png(tmp_path):
    make_run(tmp_path / "run")
    run = load_run(tmp_path / "run")
    analysis = analyse_run(run)
    written = [
        figures.plot_collapse(run, analysis, tmp_path / "f" / "collapse"),
        figures.plot_reactions(run, analysis, tmp_path / "f" / "reactions"),
        figures.plot_hinge_openings(run, analysis, tmp_path / "f" / "hinges"),
        figures.plot_crown_displacement(run, analysis, tmp_path / "f" / "crown"),
        figures.plot_stability(run, analysis, tmp_path / "f" / "stability"),
    ]
    for pdf, png in written:
        assert pdf.read_bytes()[:4] == b"%PDF" and pdf.stat().st_size > 1000
        assert png.read_bytes()[:4] == b"\x89PNG" and png.stat().st_size > 1000


def test_the_selfweight_snapshot_puts_every_block_in_place(tmp_path):
    make_run(tmp_path / "run")
    run = load_run(tmp_path / "run")
    geometry = case_geometry(run.case)
    for block, outline in zip(geometry.blocks, snapshot_outlines(geometry, run.snapshots["selfweight"])):
        assert outline == pytest.approx(block[:4, :2], abs=1e-12)


def test_a_run_matching_neither_set_gets_figures_and_its_own_numbers(tmp_path):
    summary = make_run(tmp_path / "k1", name="stiff", kn=1.0)
    markdown = write_report([tmp_path / "k1"], tmp_path / "out").read_text()
    assert "No reference: its name and kn are neither set's" in markdown
    assert "Comparison with the paper" not in markdown
    assert table_row(markdown, "stiff")[3] == f"{summary.du_mm:.2f}"
    assert (tmp_path / "out" / "k1" / "figures" / "collapse.png").stat().st_size > 0  # as in a run folder


def test_a_run_of_another_arch_is_not_compared_with_the_paper_whatever_its_name(tmp_path):
    make_run(tmp_path / "set2", name="set2", paper_arch=False)
    markdown = write_report([tmp_path / "set2"], tmp_path / "out").read_text()
    assert "No reference: its case is not the paper's (geometry.n_voussoirs 10, paper 55)" in markdown
    assert "Comparison with the paper" not in markdown
    # nothing of the paper in a report of other arches: no reference line, no paper columns, no empty list
    assert "Reference:" not in markdown and "paper set" not in markdown and "## References\n\n1. " in markdown
    assert "- arch: segmental arch, 10 voussoirs" in markdown


def _named(name: str, kn: float | None = None) -> RunSummary:
    return RunSummary(name=name, kn_N_per_mm3=kn, du_mm=None, hinges_at_collapse=(), steps=0, wall_s=0.0)


def test_runs_of_the_paper_case_are_matched_by_kn_not_by_name():
    case = {"geometry": {"n_voussoirs": 55}}
    assert match_reference(case, _named("set1", 0.5)) is None  # a set-1 name at another kn
    assert match_reference(case, _named("set1", 0.25)) == "set1"
    assert match_reference(case, _named("mine", 5.2)) == "set2"
    assert match_reference(case, _named("mine", 0.25)) == "set1"
    assert match_reference(case, _named("mine", 1.0)) is None
    for other in (
        {"geometry": {"thickness_mm": 20.0}},
        {"loading": {"support_direction_deg": 0.0}},
        {"material": {"density_g_per_cm3": 2.0}},
        {"imperfections": {"edge_radius_mm": 1.0}},
    ):
        assert match_reference(other, _named("set2", 5.2)) is None
    assert match_reference({"loading": {"max_support_displacement_mm": 120.0}}, _named("x", 5.2)) == "set2"


def test_a_path_that_is_not_a_run_folder_is_a_one_line_error(tmp_path):
    with pytest.raises(YadearchError, match=re.escape(str(tmp_path / "nope"))):
        write_report([tmp_path / "nope"], tmp_path / "out")
    result = CliRunner().invoke(report, [str(tmp_path), "--out", str(tmp_path / "out")])
    assert isinstance(result.exception, YadearchError) and str(tmp_path) in str(result.exception)
    assert not (tmp_path / "out").exists()


def test_the_report_command_writes_the_report(tmp_path):
    make_run(tmp_path / "run")
    result = CliRunner().invoke(report, [str(tmp_path / "run"), "--out", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    assert result.output.strip() == f"report -> {tmp_path / 'out' / 'report.md'}"


def test_a_figure_saved_twice_gives_the_same_bytes(tmp_path):
    """Regenerated evidence differs only where its content does: no creation date in the PDF."""
    written = []
    for name in ("first", "second"):
        fig = figures.new_figure(5.0)
        fig.add_subplot().plot([0.0, 1.0], [1.0, 0.0])
        written.append(figures.save_figure(fig, tmp_path / name))
    (pdf1, png1), (pdf2, png2) = written
    assert pdf1.read_bytes() == pdf2.read_bytes() and png1.read_bytes() == png2.read_bytes()


def test_two_runs_of_one_name_get_headings_a_reader_can_tell_apart(tmp_path):
    make_run(tmp_path / "a", name="mine")
    make_run(tmp_path / "b", name="mine")
    markdown = write_report([tmp_path / "a", tmp_path / "b"], tmp_path / "out").read_text()
    assert "## mine (a)" in markdown and "## mine (b)" in markdown
    assert "| mine (a) |" in markdown and "| mine (b) |" in markdown  # the overview's rows too (seventh trial)


def test_a_report_names_the_numerics_a_run_changed_from_their_defaults():
    """A run with the runaway bound halved read in its report like a default one (seventh user trial);
    the engine is said elsewhere and the increments check leaves the answer alone."""
    from yadearch.reporting.run_words import numerics_text

    given = {"runaway_thickness_ratio": 0.25, "engine": "static", "increments_check": "halved", "damping": 0.2}
    assert numerics_text({"numerics": given}) == "runaway_thickness_ratio 0.25 (default 0.5)"
    assert numerics_text({"numerics": {"damping": 0.2}}) == "" and numerics_text({}) == ""
