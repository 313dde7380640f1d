"""The benchmark's DEM invocation: set 1 and set 2 (and kn 100) run or read, set 2 against its slow
reference, the optional speed measurements, the campaigns' recorded wall times and the static engine,
gathered into one report (the keys of reports/benchmark.json) with a verdict per target."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from yadearch.case.config import preset
from yadearch.results.summary import RunSummary
from yadearch.studies.benchmark.dem_runs import (
    RUN_KEYS,
    campaign_status,
    limit_measurement,
    montecarlo_wall_s,
    run_line,
    slow_reference,
    stored,
    timed_run,
)
from yadearch.studies.benchmark.dem_speed import (
    CONTACT_MODELS,
    loading_measurement,
    step_breakdown,
    threads_measurement,
)
from yadearch.studies.benchmark.static_engine import StaticCampaigns, static_measurement
from yadearch.studies.benchmark.verdicts import TARGET_SWEEP_POINTS, Verdict, dem_verdicts, measured_at
from yadearch.studies.campaigns.sessions import campaign_core_s, campaign_wall_s

STIFF_KN_N_PER_MM3 = 100.0  # the stiffest case of the sweep


@dataclass(frozen=True)
class BenchmarkPlan:
    """What one invocation measures (the script's options): where its runs go, which stored run
    folders stand in for runs, the campaign folders to read, and the optional measurements."""

    runs: Path
    reference: str | None = None  # stored slow reference of set 2
    set1_run: str | None = None
    set2_run: str | None = None
    stiff_run: str | None = None
    stiff: bool = False  # run kn 100 too
    sweep: str | None = None  # campaign folder of the dense kn sweep
    montecarlo: str | None = None  # campaign folder of a Monte Carlo study
    measure_mm: float = 0.0  # set 2's loading timed, runner against bare O.run (0: not)
    threads_steps: int = 0  # steps timed with 1 and 2 OpenMP threads (0: not)
    breakdown_steps: int = 0  # steps a step's parts are timed over (0: not)


def benchmark_runs(plan: BenchmarkPlan) -> tuple[dict[str, RunSummary | None], RunSummary]:
    """Set 1, set 2 (and kn 100) and set 2's slow reference, run or read, each printed."""
    cases = {"set1": preset("set1"), "set2": preset("set2")}
    if plan.stiff or plan.stiff_run:
        cases["stiff"] = preset("set2").with_overrides({"kn_N_per_mm3": STIFF_KN_N_PER_MM3})
        cases["stiff"].name = "kn100"
    given = {"set1": plan.set1_run, "set2": plan.set2_run, "stiff": plan.stiff_run}
    results: dict[str, RunSummary | None] = {}
    for name, case in cases.items():
        folder = given[name]
        summary = results[name] = stored(folder) if folder else timed_run(case, plan.runs / name)
        if summary is not None:
            print(run_line(f"{name} ({summary.name})", summary), flush=True)
    reference = (
        stored(plan.reference)
        if plan.reference
        else timed_run(slow_reference(cases["set2"]), plan.runs / "set2_slow_reference")
    )
    if reference is None or results["set2"] is None:
        raise SystemExit("the set 2 run or its slow reference failed: nothing to compare")
    print(run_line("slow reference", reference))
    return results, reference


def run_benchmark(plan: BenchmarkPlan, static: StaticCampaigns | None = None) -> tuple[dict[str, Any], list[Verdict]]:
    """Measure what `plan` asks (and the static engine through `static`'s campaigns, if given): the
    report and its verdicts, the speed-ups printed."""
    results, reference = benchmark_runs(plan)
    s2, stiff = results["set2"], results.get("stiff")
    assert s2 is not None  # benchmark_runs stops without it
    du, du_ref = s2.du_mm, reference.du_mm
    rel = abs(du - du_ref) / du_ref if du is not None and du_ref else None
    measured = (
        {model: loading_measurement(plan.measure_mm, s2.steps, model) for model in CONTACT_MODELS}
        if plan.measure_mm
        else None
    )
    contact_model = s2.contact_model or CONTACT_MODELS[0]
    model_speedup = measured["joint"]["steps_per_s"] / measured["cgal"]["steps_per_s"] if measured else None
    limit = limit_measurement(preset("set2"))
    breakdown = step_breakdown(plan.breakdown_steps) if plan.breakdown_steps else None
    sweep_wall = campaign_wall_s(Path(plan.sweep)) if plan.sweep else None
    sweep = campaign_status(Path(plan.sweep)) if plan.sweep else None
    montecarlo = campaign_status(Path(plan.montecarlo)) if plan.montecarlo else None
    report = {
        **{f"{n}_{k}": getattr(results[n], k, None) for n in results for k in RUN_KEYS},
        "stiff_name": stiff.name if stiff is not None else None,
        "set2_du_reference_mm": du_ref,
        "set2_du_rel_diff": rel,
        "set2_same_hinges": s2.same_mechanism(reference),
        "set2_reference_wall_s": reference.wall_s,
        "set2_speedup_vs_reference": reference.wall_s / s2.wall_s,
        "driver_overhead_ratio": measured[contact_model]["driver_overhead_ratio"] if measured else None,
        "loading_measurement": measured,
        "set2_profile": s2.profile,
        "joint_over_cgal_steps_per_s": model_speedup,
        "threads": threads_measurement(plan.threads_steps) if plan.threads_steps else None,
        "sweep_wall_s": sweep_wall,
        "sweep_folder": plan.sweep,
        "sweep": sweep,
        "limit_wall_s": limit["wall_s"],
        "du_rigid_mm": limit["du_rigid_mm"],
        "kn100_wall_s": stiff.wall_s if stiff is not None else None,
        "sweep25_wall_s": sweep_wall if sweep is not None and sweep["done"] >= TARGET_SWEEP_POINTS else None,
        "montecarlo200_wall_s": montecarlo_wall_s(montecarlo),
        "montecarlo_folder": plan.montecarlo,
        "montecarlo": montecarlo,
        "montecarlo_wall_s": campaign_wall_s(Path(plan.montecarlo)) if plan.montecarlo else None,
        "montecarlo_core_s": campaign_core_s(Path(plan.montecarlo)) if plan.montecarlo else None,
        "step_breakdown_us": breakdown["step_breakdown_us"] if breakdown else None,
        "step_us": breakdown["step_us"] if breakdown else None,
        "integrator_ratio": breakdown["integrator_ratio"] if breakdown else None,
        "measured": measured_at(),
    }
    verdicts = dem_verdicts(report, contact_model)
    if static is not None:
        figures, static_verdicts = static_measurement(plan.runs / "static", s2, stiff, static)
        report.update(figures)
        verdicts += static_verdicts
    print(
        f"set 2: {report['set2_speedup_vs_reference']:.1f}x faster than the slow reference ({reference.wall_s:.0f} s)"
    )
    if model_speedup:
        print(
            f"joint elements / CGAL polyhedra, steps/s on the same {plan.measure_mm:g} mm of set 2: "
            f"{model_speedup:.1f}x"
        )
    return report, verdicts
