"""Options shared by the commands (one declaration each) and the case they describe."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import click

from yadearch.case.materials import MATERIAL_KEY, MATERIALS, PRESET_FIELD
from yadearch.cli.param_types import NUMBER, argument_type

if TYPE_CHECKING:
    from yadearch.case.config import ArchCase

# The modules a case or an option's check needs are imported when a command runs, not when the
# command line starts: `yadearch run` imports no campaign, study or plotting module (docs/speed.md).

PRESETS = ("set1", "set2")
ENGINES = ("dem", "static")
RIGID = "rigid"  # the rigid-block analyses (`limit`, `loads --engine rigid`): no joint stiffness, no numerics
ENGINE_META = "yadearch_engine"  # where --engine leaves its choice for `resolve_case` (click's context)
FURTHER = " (loading.max_support_displacement_mm; set it larger to follow the path further)"  # a path that stood


def stood_text(max_displacement_mm: float, motion: str) -> str:
    """What a run whose arch stood to the end of its movement says in place of du, with the setting
    that follows the movement further (none for a prescribed path: it ends where it ends)."""
    from yadearch.results.summary import PATH

    return f"no collapse up to {max_displacement_mm:g} mm" + (FURTHER if motion != PATH else "")


def resolve_case(
    preset_name: str | None, case_file: str | None, kn: float | None, settings: tuple[str, ...]
) -> ArchCase:
    """The case from a preset or a TOML file, with `--kn` and `--set key=value` overrides applied."""
    from yadearch.case.config import load_case, preset
    from yadearch.case.paper import off_the_paper
    from yadearch.case.plan import static_only_refusal
    from yadearch.case.support import MOVEMENT_KEY, movement_overrides
    from yadearch.results.summary import STATIC
    from yadearch.studies.campaigns.grid import parse_scalar

    if preset_name and case_file:
        raise click.UsageError("give either --preset or --case, not both")
    case = load_case(case_file) if case_file else preset(preset_name or "set2")
    overrides: dict[str, Any] = {}
    named_movement: dict[str, Any] = {}
    for item in settings:
        if "=" not in item:
            raise click.UsageError(f"--set expects key=value, got {item!r}")
        key, value = item.split("=", 1)
        if key.strip() == MOVEMENT_KEY:  # a named movement stands for its [loading] parameters
            named_movement = movement_overrides(value.strip())
            continue
        if key.strip() == MATERIAL_KEY:  # a named material stands for its [material] values
            overrides[f"{MATERIAL_KEY}.{PRESET_FIELD}"] = value.strip()
            continue
        overrides[key.strip()] = parse_scalar(value)
    _refuse_twice(overrides, named_movement, kn)
    overrides.update(named_movement)
    if kn is not None:
        overrides["interface.kn_N_per_mm3"] = kn
    context = click.get_current_context(silent=True)
    engine = context.meta.get(ENGINE_META) if context is not None else None
    if engine is not None:
        set_engine = next((key for key in overrides if key.split(".")[-1] == "engine"), None)
        if set_engine is not None and overrides[set_engine] != engine:
            raise click.UsageError(f"--engine {engine} and --set {set_engine}={overrides[set_engine]}; keep one")
        overrides["numerics.engine"] = engine
    resolved = off_the_paper(case.with_overrides(overrides), named="name" in overrides) if overrides else case
    if resolved.numerics.engine == STATIC:
        _refuse_dem_numerics(list(overrides))
    refused = static_only_refusal(resolved.numerics)  # none with the static engine
    if refused:
        raise click.UsageError(refused)
    return resolved


def _refuse_twice(overrides: dict[str, Any], named_movement: dict[str, Any], kn: float | None) -> None:
    """UsageError where one parameter is given two ways (--kn and --set kn_N_per_mm3; a named movement
    and one of the parameters it stands for), whichever comes last would otherwise win unsaid."""
    given = {key.split(".")[-1]: key for key in overrides}
    if kn is not None and "kn_N_per_mm3" in given:
        key = given["kn_N_per_mm3"]
        raise click.UsageError(f"kn is given twice: --kn {kn:g} and --set {key}={overrides[key]}; keep one")
    clash = next((given[key.split(".")[-1]] for key in named_movement if key.split(".")[-1] in given), None)
    if clash is not None:
        raise click.UsageError(
            f"--set {clash} and --set movement=... both set the support's movement; give the movement by "
            "name or by its parameters, not both"
        )


def _refuse_dem_numerics(keys: list[str]) -> None:
    """UsageError naming the first of `keys` that only the DEM reads."""
    from yadearch.static.records import dem_only_keys

    ignored = dem_only_keys(keys)
    if ignored:
        raise click.UsageError(
            f"--set {ignored[0]} is not used by the static engine (it solves each state as a static "
            "equilibrium: no time step, damping, rate or contact model); drop it or use --engine dem"
        )


PASSIVE_DISPLACEMENT_KEY = "fill_passive_displacement_mm"  # the fill's spring, which rigid blocks do not have


MARCH_NUMERICS = ("snap_thickness_ratio", "runaway_thickness_ratio")  # what the rigid march reads as the engines do


def refuse_unread(
    settings: tuple[str, ...],
    kn: float | None,
    engine: str,
    compliant: bool = False,
    can_comply: bool = True,
    reads: tuple[str, ...] = (),
) -> None:
    """UsageError in one line when --set (or --kn) names a parameter `engine` does not read: the
    rigid-block analysis reads no numerics but those it `reads` (the march: MARCH_NUMERICS), no fill
    spring and, unless `compliant`, no joint stiffness (the hint names --compliant where the command
    has it, `can_comply`); the static engine reads no DEM numerics."""
    from yadearch.case.config import parameter_section
    from yadearch.case.support import MOVEMENT_KEY
    from yadearch.results.summary import STATIC

    if engine == STATIC:
        _refuse_dem_numerics([item.split("=", 1)[0].strip() for item in settings])
    if engine != RIGID:
        return
    if kn is not None and not compliant:
        instead = (
            "add --compliant for the du a run at that kn should find" if can_comply else "use --engine static or dem"
        )
        raise click.UsageError(
            f"--kn {kn:g} plays no part in the rigid-block analysis (rigid joints); {instead}, or drop it"
        )
    for item in settings:
        key = item.split("=", 1)[0].strip()
        if key in (MOVEMENT_KEY, MATERIAL_KEY):  # a named movement or material: parameters rigid blocks read
            continue
        section = parameter_section(key)
        if section == "numerics" and key.split(".")[-1] in reads:
            continue
        if section == "numerics" or (section == "interface" and not compliant):
            why = "a numerical setting of the engines" if section == "numerics" else "the joints are rigid"
            raise click.UsageError(f"--set {key} plays no part in the rigid-block analysis ({why}); drop it")
        if key.split(".")[-1] == PASSIVE_DISPLACEMENT_KEY:
            raise click.UsageError(
                f"--set {key} plays no part in the rigid-block analysis (it mobilises the fill's passive "
                "pressure at once); drop it, or use --engine static or dem for the fill's spring"
            )


def figures_option(what: str) -> Callable[[Any], Any]:
    """--figures/--no-figures (drawn by default), the same on every command that draws: `what` it draws."""
    return click.option(
        "--figures/--no-figures",
        default=True,
        show_default=True,
        help=f"draw {what} (PDF and PNG); --no-figures writes the tables and reports only",
    )


def _keep_engine(context: click.Context, _: click.Parameter, value: str | None) -> None:
    if value is not None:
        context.meta[ENGINE_META] = value


def case_options(with_kn: bool, with_engine: bool = True) -> Callable[[Any], Any]:
    """--preset/--case/--set (and --kn, for commands about one case; --engine, for commands that
    run cases): the case a command starts from."""
    options = [
        click.option(
            "--preset",
            "preset_name",
            type=click.Choice(PRESETS),
            help="paper arch with the kn of voussoir set 1 (0.25 N/mm3) or set 2 (5.2 N/mm3)",
        ),
        click.option("--case", "case_file", type=click.Path(dir_okay=False), help="case TOML file"),
        click.option(
            "--set",
            "settings",
            multiple=True,
            metavar="KEY=VALUE",
            help="override any parameter, e.g. --set numerics.damping=0.3 (see `yadearch params`); "
            "--set movement=NAME picks a named support movement (settlement, spreading, closing, "
            "inclined, symmetric_spreading, abutment_tilt, settle_then_spread), --set material=NAME a named "
            f"material's density and friction ({', '.join(MATERIALS)}; docs/materials.md)",
        ),
    ]
    if with_kn:
        options.insert(2, click.option("--kn", type=NUMBER, help="interface normal stiffness kn (N/mm3)"))
    if with_engine:
        options.append(
            click.option(
                "--engine",
                type=click.Choice(ENGINES),
                expose_value=False,
                callback=_keep_engine,
                help="solver: dem (YADE, the default of the case) or static (Newton's method on the same blocks "
                "and joints, seconds; docs/theory.md)",
            )
        )

    def decorate(func: Any) -> Any:
        for option in reversed(options):
            func = option(func)
        return func

    return decorate


def pool_options(func: Any) -> Any:
    """--jobs/--scheduler/--timeout-min: where and how long runs may execute."""
    func = click.option(
        "--timeout-min", type=argument_type("timeout_s"), help="fail a run that takes longer than this (minutes)"
    )(func)
    func = click.option(
        "--scheduler", metavar="ADDRESS", help="run on this dask.distributed scheduler (e.g. tcp://host:8786)"
    )(func)
    return click.option(
        "--jobs", type=argument_type("jobs"), help="runs at once on this machine [default: one per core]"
    )(func)


def drawing_pool_options(what: str) -> Callable[[Any], Any]:
    """`pool_options` and `figures_option(what)`: a campaign that runs cases and draws `what`."""

    def decorate(func: Any) -> Any:
        return pool_options(figures_option(what)(func))

    return decorate


def timeout_s(timeout_min: float | None) -> float | None:
    """--timeout-min in seconds (None: no limit)."""
    from yadearch.api.arguments import ARGUMENTS

    return None if timeout_min is None else ARGUMENTS["timeout_s"].scale * timeout_min
