"""One run with the static engine: `python -m yadearch.static.simulate CASE.toml OUT_DIR`, the run
folder written exactly as a DEM run writes it (no YADE). Exit code 0: complete; 1: failed."""

from __future__ import annotations

import dataclasses
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from yadearch.case.config import ArchCase, load_case
from yadearch.case.held import held_load_text, held_multiplier
from yadearch.case.materials import material_text
from yadearch.case.mechanics import runaway_length, standing_parameters
from yadearch.case.numerics_section import HALVED_INCREMENTS_CHECK
from yadearch.case.paper import model_values_text, paper_model_values
from yadearch.case.support import path_end_mm
from yadearch.errors import CANNOT_STAND, YadearchError
from yadearch.model import units
from yadearch.model.loads import NONE, UNITS
from yadearch.results.check_text import check_line
from yadearch.results.provenance import STARTED_FORMAT, provenance
from yadearch.results.run_log import stamped_log
from yadearch.results.rundir import LOG_FILE, final_folder, write_run
from yadearch.results.summary import STATIC, STATIC_REVISION, HingeRef, RunSummary, collapse_fields, loading_info
from yadearch.solve.mirror import mirror_hinges
from yadearch.solve.path import PathStep, bracket_text
from yadearch.solve.stages import Stage
from yadearch.solve.standing import why_not_standing
from yadearch.solve.static_path import StaticLoading
from yadearch.solve.static_state import StaticEngineError
from yadearch.static.increments_check import increments_check
from yadearch.static.records import DEM_ONLY_NUMERICS, StaticRecords

INTERRUPTED_EXIT = 130


def criterion_text(case: ArchCase) -> str:
    """The static loading protocol and collapse criterion with this case's numbers."""
    n = case.numerics
    runaway_mm = units.to_mm(runaway_length(case))
    return (
        f"Loading by support increments (first {n.first_increment_mm} mm, growing x{n.increment_growth} "
        f"up to {n.max_increment_mm} mm after each equilibrium), each solved as a static equilibrium by "
        "Newton's method from a predictor through the last states (continuation), or, where that fails, "
        "the fold located by bisection and a descent at the fixed support position that releases energy "
        "as a damped hold would. Equilibrium: residual forces at round-off and the free blocks' tangent "
        "stiffness positive definite. No equilibrium: the descent moves a block "
        f"{n.runaway_thickness_ratio} ring thickness ({runaway_mm:g} mm); a descent that settles is a snap "
        "survived, one that finds neither is retried, then unresolved (no du). After a failed increment "
        "the increment halves (bisection); du = midpoint of the bracket [last support displacement in "
        f"equilibrium; first without], {bracket_text(n)}; du_first = the first fold "
        f"or snap on the path (a state {n.snap_thickness_ratio} ring thickness off its branch's prediction)."
    )


def simulate_static(case: ArchCase, out: Path | None, log: Callable[[str], None] = print) -> RunSummary:
    """Run `case` with the static engine and write its run folder to `out` (none if `out` is None: a
    campaign that keeps only its results table, `static.pool.solve_batch`); returns the summary."""
    wall0 = time.time()
    started = time.strftime(STARTED_FORMAT)
    num = case.numerics
    loading = StaticLoading.of(case)
    arch = loading.arch
    end_mm = path_end_mm(case, arch.movement)
    records = StaticRecords(arch, num.hinge_rotation_mrad * 1e-3, keep_tables=num.keeps_tables)
    unused = {key: getattr(num, key) for key in DEM_ONLY_NUMERICS}
    if case.loads.live_load != NONE and held_multiplier(case) == 0.0:
        unused["live_load"] = f"{case.loads.live_load} (none of it held: held_load_N, held_acceleration_g 0)"
    log(
        f"[{case.name}] static engine: kn={case.interface.kn_N_per_mm3} N/mm3, ks={case.ks_N_per_mm3} N/mm3, "
        f"{arch.n_blocks} blocks; not used by this engine: {', '.join(unused)}"
    )
    taken = paper_model_values(case)
    defaults = any(key.startswith("material.") for key in taken or {})
    log(f"[{case.name}] {material_text(dataclasses.asdict(case.material), defaults)}")
    if taken:
        log(f"[{case.name}] warning: {model_values_text(taken)}")
    solver_start = time.time()
    selfweight = _selfweight(case, loading, records, log)
    if held_multiplier(case) > 0.0:
        from yadearch.solve.load_path import hold_the_live_load  # a held load's solver, for such runs only

        records.held = hold_the_live_load(loading, case)
        records.add(loading.accepted[0])  # the loaded arch before its support moves: the path's first state
        unit = UNITS[case.loads.live_load]
        log(f"[{case.name}] the live load held at {records.held:g} {unit} (iterations {loading.iterations})")

    said_snaps = 0  # the snaps survived that the log has said, as the DEM's log says them

    def say_snaps() -> None:
        nonlocal said_snaps
        for snap in loading.snaps[said_snaps:]:
            low, high = snap["fold_mm"]
            log(f"[{case.name}] a snap between {low:.3f} and {high:.3f} mm: a block moved {snap['move_mm']:.3f} mm")
        said_snaps = len(loading.snaps)

    def progress(step: PathStep) -> None:
        wall = time.time() - wall0
        say_snaps()
        log(
            f"[{case.name}] increment {units.to_mm(step.start):7.3f} -> {units.to_mm(step.target):7.3f} mm: "
            f"{step.verdict} (iterations {loading.iterations}, {loading.iterations / wall:6.0f} it/s, "
            f"wall {wall:.1f} s)"
        )

    start = loading.accepted[0]  # the path's first state, where the increments check starts again
    path = loading.follow(on_step=progress)
    say_snaps()
    for state in loading.accepted[1:]:
        records.add(state)
    hinges_last = records.hinges(loading.accepted[-1]) if len(loading.accepted) > 1 else []
    hinges = hinges_last
    if path.collapsed:
        collapse = loading.collapse_state(path.upper)
        records.add(collapse, label=Stage.COLLAPSE)
        hinges = records.hinges(collapse)
    mode = loading.fold_mode(path.upper) if path.collapsed else None
    mode_hinges = mode.labels if mode is not None else None
    refs = tuple(HingeRef.of(h) for h in hinges) if path.collapsed else ()
    solver_wall = time.time() - solver_start
    check = None
    if num.increments_check == HALVED_INCREMENTS_CHECK:
        check = increments_check(loading, start, path, loading.first_loss, mode_hinges)
        width = units.to_mm(path.upper - path.lower) if path.collapsed else None
        log(f"[{case.name}] {check_line(check, bracket_mm=width)}")
    summary = RunSummary(
        name=case.name,
        started=started,
        engine=STATIC,
        engine_revision=STATIC_REVISION,
        kn_N_per_mm3=case.interface.kn_N_per_mm3,
        ks_N_per_mm3=case.ks_N_per_mm3,
        kn_effective_N_per_mm3=arch.law.kn / units.N_PER_MM3,
        contact_model="joint",
        loading=loading_info(case.loading, end_mm, held_load_text(case)),
        collapse_criterion=criterion_text(case),
        unused_parameters=unused,
        paper_model_values=taken,
        selfweight=selfweight,
        imperfections=arch.imperfections.summary() if arch.imperfections is not None else None,
        **collapse_fields(path, arch.movement, loading.first_loss),
        collapse_kind=mode.kind if mode is not None else None,
        collapse_mode_hinges=mode_hinges,
        mirror_hinges=mirror_hinges(case, arch.movement, [h.label for h in refs]),
        mirror_mode_hinges=mirror_hinges(case, arch.movement, mode_hinges),
        increments=len(path.steps),
        equilibria=len(path.equilibria),
        hinges_last_equilibrium=[h.to_json() for h in hinges_last],
        friction=records.friction,
        relaxations={
            "runaway_mm": units.to_mm(loading.runaway),
            "snap_floor_mm": units.to_mm(loading.snap_floor),  # a landing this far from the prediction is a snap
            "delta_mm": [units.to_mm(s.lam) for s in loading.accepted[1:]],
            "increment_mm": _increments_mm(loading),
            "move_mm": [units.to_mm(s.move) for s in loading.accepted[1:]],
        },
        snaps=loading.snaps,
        increments_check=check,
        descents=loading.descents,
        descent_retries=loading.retries,
        hinges_at_collapse=refs,
        hinges_detail=[h.to_json() for h in hinges],
        iterations=loading.iterations,
        steps=loading.iterations,
        joint_evaluations=loading.solver.evaluations,
        solver_wall_s=solver_wall,  # the path's (the increments check has its own)
        wall_s=time.time() - wall0,
        **provenance(None),
    )
    if out is not None:
        write_run(
            out,
            case.to_toml(),
            records.series,
            records.joints,
            records.snapshots,
            summary,
            arch.imperfections.table() if arch.imperfections is not None else None,
            records.states,
            tables=num.keeps_tables,
        )
    du, first = summary.du_mm, summary.du_first_mm
    log(
        f"[{case.name}] done ({summary.outcome}): du={'none' if du is None else f'{du:.2f} mm'} "
        f"du_first={'none' if first is None else f'{first:.2f} mm'} "
        f"hinges={summary.hinge_text or '-'} iterations={loading.iterations} "
        f"wall={summary.wall_s:.2f} s" + (f" -> {final_folder(out)}" if out is not None else "")
    )
    return summary


def selfweight_failure(error: StaticEngineError, case: ArchCase) -> str:
    """The one line for a self-weight the static engine could not find: with the arch's standing
    parameters and why it may not stand where it fell, as it is where the solver gave up."""
    if not str(error).startswith(CANNOT_STAND):
        return f"{error} ({standing_parameters(case)})"
    return f"{error} ({standing_parameters(case)}); {why_not_standing(case)}"


def _selfweight(
    case: ArchCase, loading: StaticLoading, records: StaticRecords, log: Callable[[str], None]
) -> dict[str, Any]:
    """The self-weight state, recorded, and summary.json's `selfweight` entry."""
    try:
        state = loading.selfweight()
    except StaticEngineError as exc:
        raise YadearchError(selfweight_failure(exc, case)) from None
    records.add(state, label=Stage.SELFWEIGHT)
    row = records.series_columns(state)
    weight = float(loading.arch.weight[1:-1].sum())
    fill = -float(loading.arch.dead[:, 1].sum())  # the backfill's weight on the voussoirs
    info = {
        "steps": loading.iterations,
        "unbalanced": row["unbalanced"],
        "arch_weight_N": weight,
        "vertical_reaction_sum_N": row["left_Ry_N"] + row["right_Ry_N"],
        "horizontal_reaction_sum_N": row["left_Rx_N"] + row["right_Rx_N"],
        "thrust_N": abs(row["left_Rx_N"]),
        "crown_settlement_mm": -row["crown_dy_mm"],
        "gravity_ramps": loading.ramps,
        **({"fill_weight_N": fill} if fill else {}),
    }
    log(
        f"[{case.name}] self-weight equilibrium after {loading.iterations} iterations: reactions "
        f"{info['vertical_reaction_sum_N']:.3f} N for a weight of {weight:.3f} N"
        + (f" and {fill:.3f} N of backfill" if fill else "")
        + f", thrust {info['thrust_N']:.3f} N"
    )
    return info


def _increments_mm(loading: StaticLoading) -> list[float]:
    lams = [s.lam for s in loading.accepted]
    return [units.to_mm(b - a) for a, b in zip(lams, lams[1:])]


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 2:
        print("usage: python -m yadearch.static.simulate CASE.toml OUT_DIR", file=sys.stderr)
        return 2
    out = Path(argv[1])
    out.mkdir(parents=True, exist_ok=True)
    with (out / LOG_FILE).open("w") as log_file:
        log = stamped_log(log_file)

        try:
            simulate_static(load_case(argv[0]), out, log)
        except YadearchError as exc:
            print(f"error: {exc}", file=sys.stderr)
            log_file.write(f"FAILED: {exc}\n")
            return 1
        except KeyboardInterrupt as exc:
            print(f"error: interrupted ({exc or 'SIGINT'})", file=sys.stderr)
            log_file.write(f"INTERRUPTED: {exc or 'SIGINT'}\n")
            return INTERRUPTED_EXIT
    return 0


if __name__ == "__main__":
    sys.exit(main())
