"""The imperfection study of `scripts/imperfection_study.py` (`reports/imperfections/`): the accurate
arch (set 2's kn) with each kind of explicit defect at rising amplitudes, its campaigns, figures and
report (imperfections.md): the amplitude that brings the median du to set 1's experiment, the
equivalent kn of every amplitude and the hinge positions against set 1's."""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.analysis.samples import collapse_displacement, du_statistics
from yadearch.case import reference
from yadearch.case.config import ArchCase, preset
from yadearch.plotting.montecarlo import amplitude_panels_figure, campaign_figures
from yadearch.results.rundir import read_summary
from yadearch.results.summary import RunSummary
from yadearch.studies.campaigns.executors import open_pool
from yadearch.studies.campaigns.table import label_hinges
from yadearch.studies.dem_settings import NO_DEM_SETTINGS, with_dem_settings
from yadearch.studies.imperfections.matching import (
    STAYED,
    TOWARD_CROWN,
    TOWARD_SPRINGING,
    Study,
    amplitude_for,
    equivalent_kn,
    hinge_agreement,
    hinge_shifts,
    level_rows,
    paired_amplitude_interval,
    paired_medians,
    table_markdown,
)
from yadearch.studies.imperfections.plan import BASE_PRESET, FINAL, MATCH, SEED, STUDIES
from yadearch.studies.montecarlo import MONTECARLO_FILE, run_montecarlo

SET1_EXPERIMENT_HINGES = {"A": 13, "B": 32, "C": 56, "D": 1}  # the paper's Table 1 (docs/validation.md)
SET1_A_FORMED = 12  # set 1's experiment: A formed at 12, then moved to 13 before collapse
UNITS = {
    "edge_radius_mm": "mm",
    "face_angle_sd_mrad": "mrad",
    "face_bump_sd_mm": "mm",
    "keystone_offset_mm": "mm",
    "voussoir_offset_sd_mm": "mm",
    "right_support_angle_mrad": "mrad",
    "voussoir_length_sd_mm": "mm",
    "voussoir_thickness_sd_mm": "mm",
}
AXIS_LABELS = {
    "edge_radius_mm": "edge radius (mm)",
    "face_angle_sd_mrad": "face angle s.d. (mrad)",
    "face_bump_sd_mm": "face bump s.d. (mm)",
    "keystone_offset_mm": "keystone offset (mm)",
    "voussoir_offset_sd_mm": "voussoir offset s.d. (mm)",
    "right_support_angle_mrad": "right support askew (mrad)",
    "voussoir_length_sd_mm": "voussoir length s.d. (mm)",
    "voussoir_thickness_sd_mm": "voussoir thickness s.d. (mm)",
}
PERFECT_RUN = Path("reports/set2")  # the perfect arch with set 2's joints (`yadearch reproduce`)
SET1_RUN = Path("reports/set1")  # the paper's low-kn model of set 1
REPORT = "imperfections.md"
PANEL_NOTES = {"stiff": ", kn 100", "final": ", final (200 seeds)", "match": ", seeds 1-40"}  # tell like panels apart
FIGURE = "du_vs_amplitude"
HISTORY_FILE = "snapshots.json"  # a run folder's hinge history, which hinge_shifts reads (not committed)


def study_case(study: Study, dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS) -> ArchCase:
    """The base case of one campaign (every run of the study is the DEM's): the accurate arch with the
    campaign's fixed settings and the study's `dem_settings`."""
    return with_dem_settings(preset(BASE_PRESET).with_overrides(study.fixed), dem_settings)


def run_study(study: Study, out: Path, jobs: int, dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS) -> pd.DataFrame:
    """Run (or resume) one campaign of the study (its DEM runs with `dem_settings`) and draw its figures;
    its montecarlo table."""
    with open_pool(jobs) as pool:
        table = run_montecarlo(study_case(study, dem_settings), out / study.name, pool, study.samples, SEED, study.axes)
    draw(table, study, out)
    return table


def draw(table: pd.DataFrame, study: Study, out: Path) -> None:
    """A campaign's figures (du distribution against the perfect arch's du and set 1's experiment,
    hinge positions, du against the amplitude)."""
    perfect = read_summary(PERFECT_RUN).collapsed_du_mm() if study.perfect_du_mm is None else study.perfect_du_mm
    references = [(perfect, "perfect arch"), (reference.SETS["set1"]["experimental"]["du_mm"], "set 1, experiment")]
    try:
        campaign_figures(table, out / study.name, [study.parameter], references)
    except ValueError as exc:
        print(f"{study.name}: no figure ({exc})")


def spread(interfaces: list[int]) -> str:
    """A hinge spread over interfaces as the paper writes it, e.g. "29-32"."""
    return f"{interfaces[0]}-{interfaces[-1]}" if len(interfaces) > 1 else str(interfaces[0])


def report(out: Path, sweep: pd.DataFrame, perfect_du_mm: float, arguments: str = "") -> str:
    """The study's Markdown (and its figure) from every campaign folder that holds a table; `arguments`
    name the DEM's settings in its command."""
    target = reference.SETS["set1"]["experimental"]["du_mm"]
    kn = reference.SETS["set2"]["kn_N_per_mm3"]
    set1_summary = read_summary(SET1_RUN)
    lines = [
        "# Imperfections instead of a low kn",
        "",
        f"Base: the paper's arch with set 2's accurate joints (kn {kn} N/mm³; the perfect arch gives "
        f"{perfect_du_mm:.2f} mm, `{PERFECT_RUN}`). Each kind of defect is raised until the median du "
        f"reaches set 1's experiment, {target} mm. Equivalent kn: the kn at which the perfect arch's du "
        "(`reports/kn-sweep`, interpolated in log kn) equals the median. Regenerate: "
        f"`.venv/bin/python scripts/imperfection_study.py{arguments}`.",
        "",
    ]
    panels = []
    for study in STUDIES:
        path = out / study.name / MONTECARLO_FILE
        if not path.is_file():
            continue
        table = pd.read_csv(path)
        perfect = perfect_du_mm if study.perfect_du_mm is None else study.perfect_du_mm
        panels.append(
            (table, study.parameter, f"{AXIS_LABELS[study.parameter]}{PANEL_NOTES.get(study.name, '')}", perfect)
        )
        rows = level_rows(study, table, sweep)
        amplitude = amplitude_for([{"level": 0.0, "median_du_mm": perfect}, *rows], target)
        unit = UNITS[study.parameter]
        lines += [f"## {study.title} (`{study.parameter}`, {study.samples} sample(s) a level)", ""]
        lines += table_markdown(rows, unit) + [""]
        if study is MATCH:  # one level: its amplitude for set 1 comes from the paired comparison below
            lines.append("The amplitude for set 1's du: below, compared with the final campaign seed by seed.")
        else:
            lines.append(
                f"Median du = {target} mm at {study.parameter} ≈ {amplitude:.3g} {unit}."
                if not math.isnan(amplitude)
                else f"No level brackets {target} mm."
            )
        lines.append("")
    lines += final_section(out, set1_summary)
    lines += match_section(out, sweep, target)
    experiment, model = reference.SETS["set1"]["experimental"], reference.SETS["set1"]["numerical"]
    lines += [
        "## Set 1 for comparison",
        "",
        f"- experiment: du {experiment['du_mm']} mm, A at {experiment['hinge_A'][0]} I (formed at 12, moved "
        f"one voussoir toward the crown before collapse), B {experiment['hinge_B'][0]} E, C 56 E, D 1 E;",
        f"- paper FE with kn {reference.SETS['set1']['kn_N_per_mm3']} N/mm³: du {model['du_mm']} mm, "
        f"A {spread(model['hinge_A'])} I, "
        f"B {spread(model['hinge_B'])} E;",
        f"- this project's low-kn model (`{SET1_RUN}`): du {set1_summary.du_mm:.2f} mm on {set1_summary.hinge_labels}.",
        "",
    ]
    if panels:
        amplitude_panels_figure(panels, out / FIGURE, target, f"set 1 experiment, {target} mm")
        lines += [f"![du against each amplitude]({FIGURE}.png)", ""]
    return "\n".join(lines)


def _du_line(table: pd.DataFrame) -> str:
    """The final campaign's du in one sentence: median, its 95 % interval, the band, what failed."""
    stats = du_statistics(collapse_displacement(table))  # an arch that cannot stand: du 0
    failed = table[table["status"] == "failed"]
    reasons = "; ".join(f"{row.folder}: {row.reason}" for row in failed.itertuples())
    return (
        f"Median du {stats['median']:.2f} mm (95 % interval of the median {stats['median_low']:.2f}-"
        f"{stats['median_high']:.2f} mm), 5-95 % of the samples {stats['low']:.2f}-{stats['high']:.2f} mm, "
        f"set 1's experiment {reference.SETS['set1']['experimental']['du_mm']} mm."
        + (f" Failed: {reasons}." if reasons else "")
    )


def final_section(out: Path, set1_summary: RunSummary) -> list[str]:
    """How the final campaign's hinges compare with set 1's experiment, beside the low-kn model's."""
    path = out / FINAL.name / MONTECARLO_FILE
    if not path.is_file():
        return []
    table = pd.read_csv(path)
    done = int((table["status"] == "done").sum())
    shares = hinge_agreement(table, SET1_EXPERIMENT_HINGES)
    labelled = label_hinges(set1_summary, preset(BASE_PRESET).geometry.n_voussoirs)
    model = {label: labelled[f"hinge_{label}"] for label in SET1_EXPERIMENT_HINGES}
    lines = [
        f"## The final campaign against set 1's experiment ({done} of {FINAL.samples} samples)",
        "",
        f"`{FINAL.parameter}` = {FINAL.levels[0]:g} mm, seeds {SEED}-{SEED + FINAL.samples - 1} "
        f"(`{out / FINAL.name}`; `--only {FINAL.name}` resumes it). {_du_line(table)} Share of the "
        "samples whose hinge sits within one interface of the experiment's:",
        "",
        "| hinge | experiment | samples within ±1 | low-kn model |",
        "|---|---|---|---|",
    ]
    for label, interface in SET1_EXPERIMENT_HINGES.items():
        own = model.get(label)
        lines.append(f"| {label} | {interface} | {shares[label]:.0%} | {'—' if own is None else own} |")
    lines += ["", *migration_lines(out, table)]
    lines += [
        "",
        f"![du of the final campaign]({FINAL.name}/du_distribution.png)",
        f"![hinges of the final campaign]({FINAL.name}/hinge_positions.png)",
        "",
    ]
    return lines


def migration_lines(out: Path, table: pd.DataFrame) -> list[str]:
    """Which way hinge A moved between its formation and the collapse, in the final campaign and in
    the low-kn model (set 1's experiment: formed at 12, one voussoir toward the crown before collapse)."""
    folders = [out / FINAL.name / f for f in table.loc[table["status"] == "done", "folder"]]
    if not all((folder / HISTORY_FILE).is_file() for folder in folders):
        return [
            "Hinge A between its formation and the collapse: not tabulated, the samples' histories "
            f"({HISTORY_FILE}) are not committed (the campaign writes them; docs/validation-imperfections.md "
            "has the shares measured when it ran)."
        ]
    shifts = hinge_shifts(folders, "A")
    if shifts.empty:
        return []
    share = shifts["way"].value_counts(normalize=True)
    experiment_like = ((shifts["formed"] == SET1_A_FORMED) & (shifts["final"] == SET1_A_FORMED + 1)).mean()
    model = hinge_shifts([SET1_RUN], "A")
    own = (
        "no hinge A"
        if model.empty
        else (f"formed at {model.loc[0, 'formed']}, at {model.loc[0, 'final']} at collapse ({model.loc[0, 'way']})")
    )
    return [
        f"Hinge A between its formation and the collapse ({len(shifts)} samples): "
        + ", ".join(f"{way} {share.get(way, 0.0):.0%}" for way in (STAYED, TOWARD_CROWN, TOWARD_SPRINGING))
        + f"; formed at {SET1_A_FORMED} and ended at {SET1_A_FORMED + 1} as in set 1's experiment: "
        f"{experiment_like:.0%}. The low-kn model's A: {own}."
    ]


def match_section(out: Path, sweep: pd.DataFrame, target: float) -> list[str]:
    """The amplitude that brings the median du to set 1's, from the final and the match campaigns
    compared on their common seeds (the same face profiles at two amplitudes)."""
    paths = [out / s.name / MONTECARLO_FILE for s in (FINAL, MATCH)]
    if not all(p.is_file() for p in paths):
        return []
    tables = [pd.read_csv(p) for p in paths]
    rows = paired_medians(tables, FINAL.parameter)
    amplitude = amplitude_for(rows, target)
    low, high = paired_amplitude_interval(tables, FINAL.parameter, target)
    equivalent = ", ".join(
        f"{r['median_du_mm']:.2f} mm at {r['level']:g} mm (equivalent kn "
        f"{equivalent_kn(r['median_du_mm'], sweep):.3g} N/mm³)"
        for r in rows
    )
    found = (
        f"median du = {target} mm at `{FINAL.parameter}` ≈ {amplitude:.3f} mm (95 % bootstrap interval over "
        f"the seeds {low:.3f}-{high:.3f} mm)"
        if not math.isnan(amplitude)
        else f"the two levels do not bracket {target} mm"
    )
    return [
        f"## The amplitude that matches set 1, sample for sample ({rows[0]['samples']} seeds)",
        "",
        f"The match campaign (`{out / MATCH.name}`, `--only {MATCH.name}`) runs seeds {SEED}-"
        f"{SEED + MATCH.samples - 1} at {MATCH.levels[0]:g} mm: the same face profiles as the final "
        f"campaign's first seeds, scaled. On the seeds finished in both: {equivalent}; {found}.",
        "",
    ]
