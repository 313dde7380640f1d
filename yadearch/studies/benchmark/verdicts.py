"""The benchmark's targets (docs/speed.md) and their verdicts: one PASS or FAIL line per target with
its measured figures, decided from the figures the benchmark writes to its JSON report."""

from __future__ import annotations

import json
import time
from pathlib import Path
from typing import Any, NamedTuple

from yadearch.atomic import write_text_atomically

TARGET_SET2_WALL_S = 10.0  # docs/speed.md: the second round's targets
TARGET_STIFF_WALL_S = 60.0  # any kn from 0.1 to 100, measured at the stiffest
TARGET_SWEEP_WALL_S = 10 * 60.0
TARGET_SWEEP_POINTS = 25
TARGET_MONTECARLO_SAMPLES = 200
TARGET_MONTECARLO_WALL_S = 20 * 60.0  # 200 set-2-like imperfect samples on 2 cores
CAMPAIGN_CORES = 2  # the cores the campaigns' targets are stated for
TARGET_LIMIT_WALL_S = 10.0
TARGET_OVERHEAD = 1.05
TARGET_DU_REL = 0.01
TARGET_STEP_US = 20.0  # a step's aim: the distance to YADE's bare explicit step


class Verdict(NamedTuple):
    """A target, whether the measurement meets it, and the figures that say so."""

    target: str
    met: bool
    detail: str

    def line(self) -> str:
        """The printed line: PASS or FAIL, the target and its figures."""
        return f"{'PASS' if self.met else 'FAIL'}  {self.target}: {self.detail}"


def print_verdicts(verdicts: list[Verdict]) -> None:
    """One PASS or FAIL line per target with its measured figures."""
    for verdict in verdicts:
        print(verdict.line())


def measured_at() -> str:
    """The report's time stamp (local time, to the second)."""
    return time.strftime("%Y-%m-%dT%H:%M:%S")


def write_report(path: Path, report: dict[str, Any]) -> None:
    """The benchmark's figures as indented JSON, written whole or not at all (`atomic`)."""
    write_text_atomically(path, json.dumps(report, indent=2) + "\n")


def dem_verdicts(report: dict[str, Any], contact_model: str) -> list[Verdict]:
    """The DEM targets met or not by the figures of a benchmark report (`report.run_benchmark`), whose
    loading measurement, if any, counts the driver overhead of `contact_model`."""
    wall, rel, same = report["set2_wall_s"], report["set2_du_rel_diff"], report["set2_same_hinges"]
    overhead, measured = report["driver_overhead_ratio"], report["loading_measurement"]
    stiff_wall, limit_wall = report["kn100_wall_s"], report["limit_wall_s"]
    return [
        Verdict(
            f"set 2 wall <= {TARGET_SET2_WALL_S:g} s",
            wall <= TARGET_SET2_WALL_S,
            f"{wall:.0f} s ({wall / TARGET_SET2_WALL_S:.1f}x the target)",
        ),
        Verdict(
            "set 2 du within 1 % of the slow reference, same hinges",
            rel is not None and rel <= TARGET_DU_REL and same,
            f"{report['set2_du_mm']:.2f} vs {report['set2_du_reference_mm']:.2f} mm ({rel:.2%}), hinges "
            f"{'same' if same else 'differ'}"
            if rel is not None
            else "no du",
        ),
        Verdict(
            "driver overhead <= 5 %",
            overhead is not None and overhead <= TARGET_OVERHEAD,
            f"runner / bare O.run of the same scene and steps = {overhead:.3f} ({contact_model} contacts; "
            f"CGAL: {measured['cgal']['driver_overhead_ratio']:.3f})"
            if measured
            else "not measured (--measure-mm)",
        ),
        Verdict(
            f"kn 100 <= {TARGET_STIFF_WALL_S:g} s",
            stiff_wall is not None and stiff_wall <= TARGET_STIFF_WALL_S,
            f"{stiff_wall:.0f} s ({stiff_wall / TARGET_STIFF_WALL_S:.1f}x the target), du "
            f"{report['stiff_du_mm']:.2f} mm"
            if stiff_wall is not None
            else "not run (--stiff)",
        ),
        Verdict(
            "rigid limit analysis <= 10 s",
            limit_wall <= TARGET_LIMIT_WALL_S,
            f"{limit_wall:.1f} s ({limit_wall / TARGET_LIMIT_WALL_S:.2f}x the target), du_rigid "
            f"{report['du_rigid_mm']:.2f} mm",
        ),
        _sweep_verdict(report["sweep"], report["sweep_wall_s"]),
        _montecarlo_verdict(report["montecarlo"]),
        Verdict(
            f"a step <= {TARGET_STEP_US:g} us",
            report["step_us"] is not None and report["step_us"] <= TARGET_STEP_US,
            f"{report['step_us']:.0f} us, {report['integrator_ratio']:.0f}x YADE's bare integrator on the same scene"
            if report["step_us"] is not None
            else "not measured",
        ),
    ]


def _sweep_verdict(sweep: dict[str, Any] | None, wall: float | None) -> Verdict:
    """The dense kn sweep's wall time in its recorded sessions (`dem_runs.campaign_status`)."""
    return Verdict(
        f"{TARGET_SWEEP_POINTS}-point sweep <= {TARGET_SWEEP_WALL_S / 60:g} min on {CAMPAIGN_CORES} cores",
        sweep is not None
        and wall is not None
        and wall <= TARGET_SWEEP_WALL_S
        and sweep["failed"] == 0
        and sweep["done"] >= TARGET_SWEEP_POINTS,
        f"{wall / 60:.1f} min in its recorded sessions ({wall / TARGET_SWEEP_WALL_S:.1f}x the "
        f"target), {sweep['done']} done, {sweep['failed']} failed; the runs' own wall times add up to "
        f"{sweep['run_wall_s'] / 60:.1f} min"
        if sweep is not None and wall is not None
        else "no sweep folder given (sweep_wall_s null)",
    )


def _montecarlo_verdict(montecarlo: dict[str, Any] | None) -> Verdict:
    """A Monte Carlo campaign's samples' own wall times over the cores (`dem_runs.montecarlo_wall_s`)."""
    target = (
        f"{TARGET_MONTECARLO_SAMPLES} Monte Carlo samples <= {TARGET_MONTECARLO_WALL_S / 60:g} min on "
        f"{CAMPAIGN_CORES} cores"
    )
    if montecarlo is None:
        return Verdict(target, False, "no Monte Carlo folder given (--montecarlo)")
    tried = montecarlo["done"] + montecarlo["failed"]
    per_sample_s = montecarlo["run_wall_s"] / max(1, tried)
    return Verdict(
        target,
        tried >= TARGET_MONTECARLO_SAMPLES and montecarlo["run_wall_s"] / CAMPAIGN_CORES <= TARGET_MONTECARLO_WALL_S,
        f"{montecarlo['done']} samples done ({montecarlo['failed']} failed), "
        f"{per_sample_s:.0f} s a sample beside another: {TARGET_MONTECARLO_SAMPLES} take about "
        f"{per_sample_s * TARGET_MONTECARLO_SAMPLES / CAMPAIGN_CORES / 60:.0f} min on {CAMPAIGN_CORES} cores",
    )
