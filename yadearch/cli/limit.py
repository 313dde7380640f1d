"""`yadearch limit`: the rigid-block limit analysis of a case under its support movement (no YADE), or
with compliant hinges the du a run at the case's kn should find; imported when invoked (cli.lazy)."""

from __future__ import annotations

import click

from yadearch.cli.options import (
    MARCH_NUMERICS,
    RIGID,
    case_options,
    figures_option,
    refuse_unread,
    resolve_case,
    stood_text,
)
from yadearch.cli.param_types import OUT_FOLDER, argument_type


@click.command()
@case_options(with_kn=True, with_engine=False)
@click.option(
    "--out",
    type=OUT_FOLDER,
    default="runs/limit",
    show_default=True,
    help="folder that receives NAME.json, NAME.pdf and NAME.png",
)
@click.option(
    "--max-snap-mm",
    type=argument_type("max_snap_mm"),
    default=None,
    help="count a hinge snap that moves a block further than this (mm) as collapse, as a DEM "
    "run counts a block running away (default: every snap that ends in equilibrium is "
    "survived)",
)
@click.option(
    "--compliant",
    is_flag=True,
    help="let the joints fold at the margin the case's kn allows (compliant hinges): the du a DEM "
    "run of that stiffness should find, written as NAME_compliant-knKN.json",
)
@click.option(
    "--start-hinges",
    default=None,
    metavar="'1E 35I 56E'",
    help="leave rest on these three hinges (e.g. another engine's) instead of the linkage the kinematic "
    "LP picks; refused unless the rigid arch holds an admissible equilibrium on them",
)
@click.option(
    "--start-mm",
    type=argument_type("start_mm"),
    default=0.0,
    show_default=True,
    help="with --start-hinges: place the arch this far (mm) along those hinges from rest and march on from there",
)
@figures_option("the thrust-line figure")
def limit(
    preset_name: str | None,
    case_file: str | None,
    kn: float | None,
    settings: tuple[str, ...],
    out: str,
    max_snap_mm: float | None,
    compliant: bool,
    start_hinges: str | None,
    start_mm: float,
    figures: bool,
) -> None:
    """Rigid-block limit analysis, no YADE: du_rigid, hinges, thrust-line figure (kn only with --compliant)."""
    from yadearch.analysis.mechanism import near_bound
    from yadearch.api.limit_notes import StaticAnswer
    from yadearch.api.runs import limit as limit_analysis
    from yadearch.api.runs import limit_files
    from yadearch.case.imperfect import amplitudes

    refuse_unread(settings, kn, RIGID, compliant, reads=MARCH_NUMERICS)
    case = resolve_case(preset_name, case_file, kn, settings)
    if compliant:  # a march of LPs with the fold margins at every step: seconds to tens of seconds, said first
        kn_text = f"{case.interface.kn_N_per_mm3:g} N/mm^3"
        click.echo(f"{case.name}: the compliant march at kn {kn_text} (up to tens of seconds) ...")
    result = limit_analysis(
        case,
        compliant=compliant,
        max_snap_mm=max_snap_mm,
        out=out,
        start_hinges=start_hinges,
        start_mm=start_mm,
        figures=figures,
    )
    path, _ = limit_files(case, compliant, out, result.start_hinges, result.start_mm)
    stood = result.du_rigid_mm is None
    loading = case.loading
    du = (
        stood_text(loading.max_support_displacement_mm, loading.support_motion)
        if stood
        else f"{result.du_rigid_mm:.2f} mm"
    )
    quantity = f"du (compliant march, kn {case.interface.kn_N_per_mm3:g} N/mm^3)" if compliant else "du_rigid"
    new = f" (new: {' '.join(result.new_at_collapse)})" if result.new_at_collapse else ""
    if result.start_hinges:
        where = f"{result.start_mm:g} mm along" if result.start_mm else "from rest on"
        new += f", {where} {' '.join(result.start_hinges)}"
    mechanism = "hinges at the end:" if stood else f"{result.collapse_mode} on"
    click.echo(
        f"{case.name}: {quantity} = {du}, {mechanism} {' '.join(result.collapse_hinges)}"
        f"{new}, {result.n_lp} LPs, {result.wall_s:.1f} s -> {path}"
    )
    snaps = ", ".join(f"{s.at_mm:.2f} mm ({s.largest_move_mm:.2f} mm)" for s in result.snaps)
    first = "none" if result.du_first_mm is None else f"{result.du_first_mm:.2f} mm"
    if snaps:
        click.echo(
            f"du_first = {first} (the first snap past the {result.snap_floor_mm:.3g} mm floor, or the collapse); "
            f"snaps survived at (largest block move): {snaps}"
        )
    elif result.du_mm is not None:
        click.echo(f"du_first = du = {result.du_mm:.2f} mm: no snap before the collapse")
    beside = StaticAnswer.beside(result)
    if beside is not None:
        click.echo(beside.line(result.du_mm))
    for warning in result.warnings:
        click.echo(f"warning: {warning}")
    bound_mm = result.runaway_thicknesses * case.geometry.thickness_mm
    near = [(snap, said) for snap in result.snaps if (said := near_bound(snap.largest_move_mm, bound_mm))]
    if near:
        snap, said = near[0]
        click.echo(f"warning: the snap at {snap.at_mm:.2f} mm moved a block {snap.largest_move_mm:.2f} mm, {said}")
    if result.closest_edge_joint is not None:
        click.echo(
            f"nearest edge: joint {result.closest_edge_joint} beside a hinge held its thrust "
            f"{result.closest_edge_mm:.3f} mm from its corner (at {result.closest_edge_at_mm:.2f} mm); a joint of "
            f"finite kn shares the hinge within its fold margin{'' if compliant else ' (--compliant)'}"
        )
    if result.mirror_collapse_mode is not None:
        mirrored = "no collapse" if result.mirror_du_rigid_mm is None else f"{result.mirror_du_rigid_mm:.2f} mm"
        hinges = " ".join(result.mirror_collapse_hinges or ())
        same = (
            result.mirror_collapse_hinges == result.collapse_hinges and result.mirror_du_rigid_mm == result.du_rigid_mm
        )
        click.echo(
            "mirrored: the same branch (the keystone's tie decided alike both ways)"
            if same
            else f"mirrored (the keystone's other joint): {quantity} = {mirrored} ({result.mirror_collapse_mode}"
            f"{' on ' + hinges if hinges else ''})"
        )
    if not amplitudes(case).flat_aligned_faces:
        click.echo(
            "note: the rigid analysis takes the voussoirs' dimension errors and worn edges but not the "
            "faces' angles, bumps or offsets: its du is that of flat, aligned faces",
            err=True,
        )
