"""`yadearch report RUN [RUN ...] --out DIR`: a Markdown report per set of runs with the paper's
Table 1 comparison, hinge formation, mechanism, figures and provenance.

Every number about a run's outcome (du, hinges at collapse) is taken from its summary.json; the
analysis adds how the hinges formed. Runs are matched to the paper's sets by name or kn.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from yadearch.analysis.mechanism import run_warnings
from yadearch.analysis.run import RunAnalysis, analyse_run, load_run
from yadearch.analysis.tracking import format_interfaces
from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case import reference
from yadearch.case.paper import paper_mismatch
from yadearch.markdown import seconds_text
from yadearch.plotting.run_figures import write_figures
from yadearch.reporting import load_report
from yadearch.reporting.captions import figure_caption
from yadearch.reporting.paper_match import (
    hinge_text,
    interface_difference,
    match_hinges,
    match_reference,
)
from yadearch.reporting.run_words import arch_text, movement_text, numerics_text
from yadearch.results.rundir import FIGURES_DIR, RunFolder
from yadearch.results.summary import DEM

REPORT_FILE = "report.md"
HINGE_ROWS = ("hinge_A", "hinge_B", "hinge_C")


@dataclass
class ReportedRun:
    """A run, its analysis, its reference set (None if it matches neither) and its figure folder."""

    run: RunFolder
    analysis: RunAnalysis
    reference_name: str | None
    folder: str
    figures: list[str]
    title: str = ""  # its heading: the run's name, with its folder where two runs share the name


# What each `numerics.contact_model` is, for the report (runs from before the option used CGAL).
CONTACT_MODEL_NAMES = {"joint": "zero-thickness joint elements", "cgal": "YADE's CGAL polyhedra contacts"}


ENGINE_NAMES = {
    "dem": "the DEM (YADE, explicit dynamics relaxed to equilibrium)",
    "static": "the static engine (Newton's method on the same blocks and joints)",
}


def table_one(reported: ReportedRun) -> list[str]:
    """The paper's Table 1 for this run's set: experimental, numerical, this run and differences."""
    if reported.reference_name is None:
        raise ValueError(f"{reported.run.path} matches none of the paper's sets: it has no Table 1")
    ref = reference.SETS[reported.reference_name]
    summary = reported.run.summary
    order = {t.interface: t.order for t in reported.analysis.tracks}
    rows = [(row, ref["numerical"][row], reference.HINGE_SIDES[row]) for row in HINGE_ROWS]
    rows.append(("hinge_D", [reference.HINGE_D_INTERFACE], reference.HINGE_SIDES["hinge_D"]))
    pairs = match_hinges(summary.hinges_at_collapse, rows)
    lines = [
        "| | paper experimental | paper numerical | this run | run − exp. | run − num. |",
        "|---|---|---|---|---|---|",
    ]
    for row, _, side in rows:
        exp = ref["experimental"].get(row, [reference.HINGE_D_INTERFACE])
        num = ref["numerical"].get(row, [reference.HINGE_D_INTERFACE])
        hinge = pairs[row]
        if hinge is None:
            run_text, d_exp, d_num = "—", "—", "—"
        else:
            formed = order.get(hinge.interface)
            run_text = f"{hinge.interface} {hinge.side}" + (f" (formed #{formed})" if formed else "")
            d_exp, d_num = interface_difference(hinge.interface, exp), interface_difference(hinge.interface, num)
        name = row.replace("hinge_", "hinge ") + ("¹" if row == "hinge_D" else "")
        lines.append(f"| {name} | {hinge_text(exp, side)} | {hinge_text(num, side)} | {run_text} | {d_exp} | {d_num} |")
    du = summary.du_mm
    exp_du, num_du = ref["experimental"]["du_mm"], ref["numerical"]["du_mm"]
    if du is None:
        lines.append(f"| du (mm) | {exp_du:.1f} | {num_du:.1f} | no collapse | — | — |")
    else:
        lines.append(
            f"| du (mm) | {exp_du:.1f} | {num_du:.1f} | {du:.2f} | {du - exp_du:+.2f} "
            f"({(du - exp_du) / exp_du:+.1%}) | {du - num_du:+.2f} ({(du - num_du) / num_du:+.1%}) |"
        )
    lines += [
        "",
        "Hinges are interfaces numbered 1..n+1 from the left support, I/E the pivot side; the "
        "paper's A, B, C are paired with the run's hinge of the same side nearest to them, and "
        "#k says it was the k-th hinge to form. Differences are in interfaces "
        "(0 = inside the paper's range). ¹ D is named in the paper's text, not in its Table 1.",
    ]
    return lines


def formation_table(analysis: RunAnalysis) -> list[str]:
    """Each hinge at collapse, in order of formation: its paper label, where, when it formed, how far
    it opened."""
    deltas = analysis.history.delta_mm
    lines = [
        "| formed | hinge | interface | spread | side | formed at δ (mm) | peak when formed "
        "| opening at collapse (mm) | rotation at collapse (mrad) | migrations |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for t in analysis.tracks:
        moves = "; ".join(f"{m.from_interface} → {m.to_interface} at {m.delta_mm:.2f} mm" for m in t.migrations)
        lines.append(
            f"| #{t.order} | {t.paper_label or '—'} | {t.interface} | "
            f"{format_interfaces(t.final.interfaces)} | {t.side} | "
            f"{deltas[t.formed_record]:.2f} | {t.hinge_at(t.formed_record).interface} | "
            f"{t.opening_mm[-1]:.3f} | {abs(t.final.rotation) * 1e3:.1f} | {moves or '—'} |"
        )
    return lines


def run_section(reported: ReportedRun) -> list[str]:
    """The Markdown section of one run."""
    run, analysis = reported.run, reported.analysis
    summary = run.summary
    du = summary.du_mm
    hinges = summary.hinge_text or "—"
    lines = [
        f"## {reported.title or summary.name or run.path.name}",
        "",
        f"- run folder: `{run.path}`",
        f"- kn = {summary.kn_N_per_mm3} N/mm3, ks = {summary.ks_N_per_mm3} N/mm3, "
        f"joints computed by {CONTACT_MODEL_NAMES.get(summary.contact_model or 'cgal')}",
        f"- solved by {ENGINE_NAMES[summary.engine]}",
        *([f"- numerics not at their defaults: {changed}"] if (changed := numerics_text(run.case)) else []),
        f"- du = {'no collapse' if du is None else f'{du:.2f} mm'}"
        + (
            f" (bracket {summary.du_bracket_mm[0]:.2f}–{summary.du_bracket_mm[1]:.2f} mm)"
            if summary.du_bracket_mm
            else ""
        ),
        f"- arch: {arch_text(run.case)}; {movement_text(summary)}",
        f"- hinges at collapse: {hinges}",
        f"- mechanism: {analysis.mechanism}"
        + (
            f" (the fold's motion: {summary.collapse_kind} on {' '.join(summary.collapse_mode_hinges or [])})"
            if summary.collapse_kind
            else ""
        ),
        "- formation: "
        + (
            ", then ".join(
                f"{label or '(unlabelled)'} at {delta:.2f} mm ({seq})" for label, delta, seq in analysis.formation
            )
            or "—"
        ),
        "- sliding joints: "
        + (
            ", ".join(
                f"{s.interface} (|V|/(μN) = {s.shear_ratio:.2f}"
                + (f", slip {s.slip_mm:.2f} mm)" if s.slip_mm is not None else ")")
                for s in analysis.sliding
            )
            or "none"
        ),
        "",
    ]
    for warning in run_warnings(summary):
        lines += [f"**Warning:** {warning}.", ""]
    own = [(t.interface, t.side) for t in sorted(analysis.tracks, key=lambda t: t.interface)]
    if own != [(h.interface, h.side) for h in summary.hinges_at_collapse] and summary.collapsed:
        lines += [
            f"**Note:** the analysis finds hinges {' '.join(f'{k}{s}' for k, s in own)} at collapse, "
            "summary.json lists the ones above (different hinge threshold?).",
            "",
        ]
    if reported.reference_name:
        ref = reference.SETS[reported.reference_name]
        lines += (
            [
                f"### Comparison with the paper ({reported.reference_name}: {ref['description']}, "
                f"kn = {ref['kn_N_per_mm3']} N/mm3)",
                "",
            ]
            + table_one(reported)
            + ["", f"Paper, sequence at collapse: {ref['sequence_at_collapse']}.", ""]
        )
    else:
        mismatch = paper_mismatch(run.case)
        why = f"its case is not the paper's ({mismatch})" if mismatch else "its name and kn are neither set's"
        lines += [f"No reference: {why}; no comparison with the paper.", ""]
    th = analysis.thresholds
    lines += (
        ["### Hinges and how they formed", ""]
        + formation_table(analysis)
        + [
            "",
            f"A hinge is a run of joints rotating more than {th.rotation_mrad:g} mrad the same way, "
            f"reported at its peak with the joints rotating at least half as much (spread); it has formed "
            f"once it is also open by {th.opening_mm:g} mm, for good. The first column is the order of "
            "formation; the letters name the hinges by position, as the paper does (D the extrados hinge "
            "at the fixed support, C at the driven one, A the intrados hinge, B the other extrados hinge). "
            f"Every hinge at every recorded δ: [hinges.csv]({reported.folder}/hinges.csv).",
            "",
        ]
    )
    lines += ["### Figures", ""]
    for name in reported.figures:
        caption = figure_caption(name, summary)
        lines += [
            f"![{name}]({reported.folder}/{FIGURES_DIR}/{name}.png)",
            "",
            f"*{caption}* ([PDF]({reported.folder}/{FIGURES_DIR}/{name}.pdf))",
            "",
        ]
    lines += ["### Provenance", "", "| | |", "|---|---|"]
    for key in ("engine", "yade_version", "yadearch_version", "git_revision", "steps", "wall_s"):
        value = getattr(summary, key)
        if value is not None:  # a static run has no YADE version
            lines.append(f"| {key} | {seconds_text(value) if key == 'wall_s' else value} |")
    return lines + [""]


def overview(reported: list[ReportedRun]) -> list[str]:
    """One line per run: its engine, movement, du and hinges, and where some run is the paper's case, its
    reference set and the paper's du."""
    paper = any(r.reference_name for r in reported)
    columns = ["run", "engine", "movement", "du (mm)", "hinges at collapse"]
    columns += ["paper set", "paper numerical du (mm)", "paper experimental du (mm)"] if paper else []
    lines = ["| " + " | ".join(columns) + " |", "|---" * len(columns) + "|"]
    for r in reported:
        s = r.run.summary
        du = "no collapse" if s.du_mm is None else f"{s.du_mm:.2f}"
        cells = [r.title or s.name or r.run.path.name, s.engine, movement_text(s), du, s.hinge_labels or "—"]
        if paper:
            ref = reference.SETS.get(r.reference_name or "", {})
            cells += [r.reference_name or "—"]
            cells += [str(ref[k]["du_mm"]) if ref else "—" for k in ("numerical", "experimental")]
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def _folder_name(name: str, path: Path, taken: set[str]) -> str:
    """Sub-folder of the report for a run's figures: the run folder's own name (unique)."""
    base = str(path.resolve().name or name).replace("/", "_")
    name, k = base, 2
    while name in taken:
        name, k = f"{base}-{k}", k + 1
    taken.add(name)
    return name


def write_report(run_paths: Sequence[str | Path], out: str | Path) -> Path:
    """Analyse every run (a support movement's run folder or a live load's path folder), write its
    figures and hinge table under `out`, and `out`/report.md."""
    out = Path(out)
    load_paths = load_report.checked_load_paths(run_paths)  # every path checked before anything is written
    runs = [load_run(p) for p in run_paths if not load_report.is_load_path_folder(p)]
    taken: set[str] = set()
    reported = []
    for run in runs:
        analysis = analyse_run(run)
        folder = _folder_name(run.summary.name, run.path, taken)
        figures = write_figures(run, analysis, out / folder / FIGURES_DIR)
        write_csv_atomically(out / folder / "hinges.csv", analysis.hinges)
        reported.append(ReportedRun(run, analysis, match_reference(run.case, run.summary), folder, list(figures)))
    names = [r.run.summary.name for r in reported]
    for r in reported:  # two runs of one name get two headings a reader can tell apart
        r.title = f"{r.run.summary.name} ({r.folder})" if names.count(r.run.summary.name) > 1 else ""
    loads = [load_report.report_load(p, out, _folder_name(p.name, p, taken)) for p in load_paths]
    paper_case = any(r.reference_name for r in reported)
    lines = ["# yadearch report", "", *([f"Reference: *{reference.PAPER}*.", ""] if paper_case else [])]
    lines += overview(reported) + [""] if reported else []
    lines += ["## Live loads", "", *load_report.load_overview(loads), ""] if loads else []
    for r in reported:
        lines += run_section(r)
    for load in loads:
        lines += load_report.load_section(load)
    cited = reference.references_for(
        dem=any(r.run.summary.engine == DEM for r in reported) or any(x.answer["engine"] == DEM for x in loads),
        paper_case=paper_case,
    )
    if cited:
        lines += ["## References", ""] + [f"{k}. {text}" for k, text in enumerate(cited, start=1)] + [""]
    path = out / REPORT_FILE
    write_text_atomically(path, "\n".join(lines))
    return path
