"""`yadearch loads`: the live load an arch carries at collapse by the rigid-block limit analysis (a thin
client of `ya.loads`)."""

from __future__ import annotations

import math

import click
import pandas as pd
from click.core import ParameterSource

from yadearch import api
from yadearch.api.live_loads import RESIDUAL_POINTS_RANGE, loads_file
from yadearch.case.config import ArchCase
from yadearch.case.mechanics import load_place
from yadearch.case.paper import model_values_text, paper_model_values
from yadearch.case.plan import unread_by_rigid_blocks
from yadearch.cli.check import check_option, with_increments_check
from yadearch.cli.options import RIGID, case_options, figures_option, refuse_unread, resolve_case
from yadearch.cli.param_types import OUT_FOLDER, argument_type
from yadearch.errors import RunFailedError
from yadearch.markdown import per_width
from yadearch.results.check_text import check_line, unresolved_warning
from yadearch.solve.descending import DESCEND_TO
from yadearch.solve.load_lp import LoadCapacity
from yadearch.solve.load_path import BRANCH, DESCENDING
from yadearch.solve.load_path_result import LoadPath
from yadearch.solve.stages import Outcome

STATIC, DEM = "static", "dem"
LOAD_ENGINES = (RIGID, STATIC, DEM)
ENGINE_NAMES = {STATIC: "static engine", DEM: "DEM"}
DEFAULT = ParameterSource.DEFAULT
TIED_LOADS = 1e-3  # influence-line capacities within this fraction of the least are named beside it


@click.command()
@case_options(with_kn=True, with_engine=False)
@click.option(
    "--out",
    type=OUT_FOLDER,
    default="runs/loads",
    show_default=True,
    help="folder that receives the answer: NAME_loads.json (rigid), NAME_load_path.json/.csv and its states "
    "NAME_load_path/ (static, dem)",
)
@click.option(
    "--engine",
    "load_engine",
    type=click.Choice(LOAD_ENGINES),
    default=RIGID,
    show_default=True,
    help="rigid: rigid-block limit analysis (under a second); static: the load grown to collapse on the "
    "static engine's path (the DEM's blocks and joints, seconds): first loss of stability, collapse, the "
    "load-displacement curve (NAME_load_path.csv/.json and figure; its states in NAME_load_path/ for `yadearch "
    "animate` and `export`), beside the rigid answer; dem: the same "
    "path in YADE by load ramps relaxed to equilibrium, past the peak the load driven by its displacement "
    "through a stiff spring (minutes; its states too)",
)
@click.option(
    "--after-mm",
    type=argument_type("after_mm"),
    default=0.0,
    show_default=True,
    help="apply the load after the case's support movement to this displacement (mm): the residual capacity",
)
@click.option(
    "--residual",
    type=int,
    default=None,
    help="instead: the residual capacity curve, the live load's capacity after the support movement to N "
    "fractions of its static du (0, 1/N, ... ; 4: 0, 25, 50, 75 %), static and rigid, written as "
    "NAME_residual.csv and its figure",
)
@click.option(
    "--descending/--no-descending",
    default=True,
    show_default=True,
    help="follow the load-displacement curve past its peak (static engine: arc length; DEM: displacement "
    "control; docs/loads.md)",
)
@click.option(
    "--descend-to",
    type=argument_type("descend_to"),
    default=DESCEND_TO,
    show_default=True,
    help="the descending branch ends when the load has fallen to this fraction of the capacity",
)
@click.option(
    "--positions",
    type=int,
    default=None,
    help="also the influence line: a concentrated load's capacity at this many points across the span "
    "(2-200, by the --engine), written as NAME_influence.csv and its figure",
)
@figures_option("the collapse, the load path or the influence line")
@check_option
def loads(
    preset_name: str | None,
    case_file: str | None,
    kn: float | None,
    settings: tuple[str, ...],
    out: str,
    load_engine: str,
    after_mm: float,
    descending: bool,
    descend_to: float,
    positions: int | None,
    residual: int | None,
    figures: bool,
    check: bool | None,
) -> None:
    """A live load's capacity: the load (N) or acceleration (g) at collapse with the self-weight held, and
    its mechanism ([loads] of the case, or --set live_load=...), by rigid-block limit analysis, on the
    static engine's path, or on the DEM's (YADE); --after-mm first moves the support."""
    _refuse_pairs(load_engine, after_mm, positions, residual)
    refuse_unread(settings, kn, STATIC if residual is not None else load_engine, can_comply=False)
    case = resolve_case(preset_name, case_file, kn, settings)
    if residual is not None:
        _residual(case, residual, out, figures)
    else:
        path_check = check, case_file, settings
        _capacity(case, out, load_engine, after_mm, descend_to if descending else None, positions, figures, path_check)
    _warn_model_values(case, joints_read=load_engine != RIGID or residual is not None)


def _capacity(
    case: ArchCase,
    out: str,
    load_engine: str,
    after_mm: float,
    descend_to: float | None,
    positions: int | None,
    figures: bool,
    path_check: tuple[bool | None, str | None, tuple[str, ...]],
) -> None:
    """The capacity in one line (and the influence line's with `positions`) by `load_engine`; a static
    path checked with its increments halved as `path_check` (--check, the case file, --set) says."""
    if positions is not None:
        table = api.load_influence(case, positions, out=out, engine=load_engine, figures=figures)
        click.echo(
            f"{case.name}: influence line at {positions} positions: {_least(table)} -> {out}/{case.name}_influence.csv"
        )
        if case.loads.live_load == "none":
            return
    what = _what(case) + (f" after {after_mm:g} mm of support movement" if after_mm else "")
    if load_engine in (STATIC, DEM):
        if load_engine == STATIC:  # one path: checked with the increments halved unless told otherwise
            case = with_increments_check(case.with_overrides({"numerics.engine": STATIC}), *path_check)
        _on_path(case, out, after_mm, what, load_engine, descend_to, figures)
        return
    result = api.loads(case, out=out, after_mm=after_mm, figures=figures)
    unused = unread_by_rigid_blocks(case)
    if unused:  # a case file's (a --set of them is refused): said, not read
        click.echo(f"{case.name}: not used by rigid blocks: {', '.join(unused)}")
    outcome = _rigid_outcome(result, case.geometry.depth_mm)
    if after_mm and math.isfinite(result.multiplier):  # the settled rigid arch's open hinges are pins
        outcome = outcome.replace("collapse at", "rigid blocks first move at", 1)
        outcome += " (the settled arch's open hinges act as pins: no figure; --engine static follows it to collapse)"
    if math.isnan(result.multiplier):  # as a run of an arch that cannot stand: an error, its answer written
        raise RunFailedError(f"{case.name}: {what}: {outcome} -> {loads_file(case, out)}")
    click.echo(f"{case.name}: {what}: {outcome} -> {loads_file(case, out)}")


def _warn_model_values(case: ArchCase, joints_read: bool) -> None:
    """The warning a run gives (`case.paper.paper_model_values`): a new arch that takes the 1:10 model's
    material, or its joints where the engine reads them (`joints_read`), says so after its answer."""
    taken = {
        name: value
        for name, value in (paper_model_values(case) or {}).items()
        if joints_read or not name.startswith("interface.")
    }
    if taken:
        click.echo(f"warning: {model_values_text(taken)}")


def _least(table: pd.DataFrame) -> str:
    """The influence line's least capacity and where (tied mirror positions named together), in words."""
    least = table["collapse_load_N"].min()
    if not math.isfinite(least):
        return "no collapse at any position (the load carried however large, or no answer)"
    weakest = table[table["collapse_load_N"] <= least * (1.0 + TIED_LOADS)]  # a symmetric arch: mirror positions
    where = [f"{p:.3g}" for p in weakest["position_over_span"]]
    refined = "refined between the positions; " if "sampled" in weakest and not weakest["sampled"].all() else ""
    return (
        f"least {least:.4g} N at {' and '.join(where)} of the span ({refined}{weakest['hinges'].iloc[0]} at {where[0]})"
    )


def _refuse_pairs(engine: str, after_mm: float, positions: int | None, residual: int | None) -> None:
    """UsageError in one line for options that do not go together (or that the engine does not read)."""
    given = click.get_current_context().get_parameter_source
    low, high = RESIDUAL_POINTS_RANGE
    if residual is not None and not low <= residual <= high:  # the API names its argument `points`
        raise click.UsageError(f"--residual must be an integer in [{low}, {high}], got {residual}")
    if residual is not None and (after_mm or positions is not None):
        other = "--after-mm" if after_mm else "--positions"
        raise click.UsageError(f"--residual makes its own settlements, at rest and after; drop {other}")
    if residual is not None and engine != STATIC and given("load_engine") != DEFAULT:
        raise click.UsageError(f"--residual runs the static engine, the rigid blocks beside it; drop --engine {engine}")
    if positions is not None and after_mm:
        raise click.UsageError("--positions: the influence line is of the arch at rest; drop --after-mm")
    flags = {"descending": "--descending/--no-descending", "descend_to": "--descend-to"}
    unread = [flag for name, flag in flags.items() if given(name) != DEFAULT]
    if engine == RIGID and unread:
        raise click.UsageError(f"{unread[0]} follows an engine's path past its peak; rigid blocks have none (--engine)")


def _residual(case: ArchCase, points: int, out: str, figures: bool) -> None:
    """The residual capacity curve, said one settlement a line as it is made."""

    def said(row: dict) -> None:
        click.echo(
            f"after {row['settlement_mm']:6.2f} mm ({row['settlement_over_du']:.0%} of du): collapse "
            f"{row['static_capacity']:.4g} {row['unit']} on {row['static_hinges']} (first loss "
            f"{row['static_first_loss']:.4g}), rigid blocks first move at {row['rigid_first_motion']:.4g}"
        )

    click.echo(f"{case.name}: the support movement's static path to du, then the live load after {points} settlements")
    api.residual_curve(case, points, out=out, figures=figures, on_row=said)
    click.echo(f"-> {out}/{case.name}_residual.csv")


def _on_path(
    case: ArchCase, out: str, after_mm: float, what: str, engine: str, descend_to: float | None, figures: bool
) -> None:
    """An engine's load path, said in one line beside the rigid answer."""
    path = api.load_path(case, out=out, after_mm=after_mm, engine=engine, descend_to=descend_to, figures=figures)
    unit = path.unit
    if path.outcome == Outcome.COLLAPSE:
        first = f", first loss of stability at {path.first_loss:.4g} {unit}" if path.first_loss < path.capacity else ""
        kind = f" ({path.kind})" if path.kind else ""
        width = f" ({per_width(path.capacity, case.geometry.depth_mm)})" if unit == "N" else ""
        capacity = f"{path.capacity:.4g} {unit}{width}"
        outcome = f"collapse at {capacity} on {' '.join(path.hinges)}{kind}{first}{_descent(path)}"
    elif path.outcome == Outcome.UNRESOLVED:
        outcome = f"unresolved: no equilibrium nor runaway found past {path.reach:.4g} {unit} (no capacity)"
    else:
        outcome = f"no collapse up to {path.reach:.4g} {unit}"
    if math.isfinite(path.rigid):  # after a movement, the settled arch's open hinges are pins: its first motion
        rigid = f"{'first move at ' if after_mm else ''}{path.rigid:.4g} {unit} on {' '.join(path.rigid_hinges)}"
    else:
        rigid = f"none ({path.rigid_note})" if path.rigid_note else "no collapse however large"
    states = f" and its states {out}/{case.name}_load_path/ (yadearch animate, export)"
    click.echo(
        f"{case.name}: {what}: {ENGINE_NAMES[engine]}: {outcome}; rigid blocks: {rigid} "
        f"-> {out}/{case.name}_load_path.json{states}"
    )
    for warning in path.warnings:
        click.echo(f"warning: {warning}")
    if path.increments_check is not None:
        answers = (("capacity", "capacity", unit), ("first loss", "first_loss", unit))
        said = check_line(path.increments_check, answers)
        click.echo(f"warning: {said}" if unresolved_warning(path.increments_check) else said)


def _descent(path: LoadPath) -> str:
    """The descending branch in words ("" where none was traced)."""
    past = path.curve[path.curve[BRANCH] == DESCENDING] if BRANCH in path.curve else path.curve.iloc[:0]
    if past.empty:
        return ""
    end = past.iloc[-1]
    return (
        f"; past the peak down to {end.multiplier:.4g} {path.unit} at {end.load_displacement_mm:.3g} mm of the "
        f"load's displacement ({path.descent_end}; turning on {' '.join(path.descent_hinges)})"
    )


def _what(case: ArchCase) -> str:
    """The live load in words."""
    what = case.loads.live_load.replace("_", " ")
    if case.loads.live_load == "vertical":
        width = f", spread over {case.loads.load_width_mm:g} mm" if case.loads.load_width_mm else ""
        what += f" load {load_place(case)}{width}"
    else:
        what += f" toward the {case.loads.acceleration_toward}"
    return what


def _rigid_outcome(result: LoadCapacity, depth_mm: float) -> str:
    """The rigid analysis's answer in words (a load in N also per metre of the arch's `depth_mm`)."""
    if math.isnan(result.multiplier):
        outcome = "the arch does not stand under its own weight"
    elif math.isinf(result.multiplier):
        outcome = "no collapse however large (its thrust line stays within the ring; rigid blocks do not crush)"
    else:
        share = ""
        if result.unit == "N":
            with_fill = result.arch_weight_N + result.fill_weight_N
            fill = f", {result.multiplier / with_fill:.3f} of arch and fill" if result.fill_weight_N else ""
            width = per_width(result.multiplier, depth_mm)
            share = f" ({width}; {result.multiplier / result.arch_weight_N:.3f} of the arch's weight{fill})"
        joints = [str(k) for k in result.sliding]
        listed = f"{', '.join(joints[:-1])} and {joints[-1]}" if len(joints) > 1 else "".join(joints)
        slides = f", sliding at {listed}" if joints else ""
        outcome = f"collapse at {result.multiplier:.4g} {result.unit}{share} on {result.hinge_labels}{slides}"
    return outcome
