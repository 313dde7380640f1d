"""One simulation in this process: `python -m yadearch.dem.simulate CASE.toml OUT_DIR`.

Each run gets its own process (YADE keeps one global scene per interpreter; a crash must not take a
campaign down). Exit code 0: run folder complete; 1: the run failed (reason in run.log and stderr).
"""

from __future__ import annotations

import dataclasses
import os
import shutil
import signal
import sys
import time
from pathlib import Path

from yadearch.case.config import ArchCase, NumericsConfig, load_case
from yadearch.case.held import held_load_text
from yadearch.case.materials import material_text
from yadearch.case.numerics_section import STATIC_PATH_STATES
from yadearch.case.paper import model_values_text, paper_model_values
from yadearch.case.support import path_end_mm
from yadearch.errors import YadearchError
from yadearch.model import units
from yadearch.results.provenance import STARTED_FORMAT, provenance
from yadearch.results.run_log import stamped_log
from yadearch.results.rundir import LOG_FILE, final_folder, write_run
from yadearch.results.summary import DEM, RunSummary, loading_info

PR_SET_PDEATHSIG = 1  # linux/prctl.h
SCRATCH_RECORD = ".yade_scratch"  # in the staging folder: where YADE's temporary folder is
INTERRUPTED_EXIT = 130  # the shell's code for a run stopped by a signal, not by a failure


def simulate(case: ArchCase, out: Path) -> RunSummary:
    """Run `case` to collapse and write its run folder to `out`; returns the summary."""
    from yadearch.dem.runner import Runner
    from yadearch.dem.yade_env import import_yade, scratch_folder

    out.mkdir(parents=True, exist_ok=True)
    log_file = (out / LOG_FILE).open("w")

    log = stamped_log(log_file)

    import_yade(case.numerics.threads)
    import yade.config

    (out / SCRATCH_RECORD).write_text(f"{scratch_folder()}\n")  # the parent removes it if this process is killed
    log(
        f"[{case.name}] kn={case.interface.kn_N_per_mm3} N/mm3, ks={case.ks_N_per_mm3} N/mm3, "
        f"support speed={case.support_speed_mm_per_s:.4g} mm/s, damping={case.numerics.damping}, "
        f"contacts={case.numerics.contact_model}"
    )
    taken = paper_model_values(case)
    defaults = any(key.startswith("material.") for key in taken or {})
    log(f"[{case.name}] {material_text(dataclasses.asdict(case.material), defaults)}")
    if taken:
        log(f"[{case.name}] warning: {model_values_text(taken)}")
    origin = provenance(str(yade.config.version))  # now: the code that runs was imported at start
    runner = Runner(case, log=log)
    log(f"[{case.name}] dt={runner.scene.dt:.3e} s, {len(runner.scene.body_ids)} bodies")
    started = time.strftime(STARTED_FORMAT)
    imperfections = runner.scene.imperfections
    found = runner.run()
    summary = dataclasses.replace(
        found,
        name=case.name,
        started=started,
        engine=DEM,
        kn_N_per_mm3=case.interface.kn_N_per_mm3,
        ks_N_per_mm3=case.ks_N_per_mm3,
        kn_effective_N_per_mm3=runner.scene.stiffness.kn / units.N_PER_MM3,
        support_speed_mm_per_s=case.support_speed_mm_per_s,
        contact_model=case.numerics.contact_model,
        loading=loading_info(case.loading, path_end_mm(case, runner.movement), held_load_text(case)),
        collapse_criterion=criterion_text(case.numerics),
        imperfections=imperfections.summary() if imperfections is not None else None,
        paper_model_values=taken,
        **origin,
    )
    write_run(
        out,
        case.to_toml(),
        runner.records.series,
        runner.records.joints,
        runner.records.snapshots,
        summary,
        imperfections.table() if imperfections else None,
        runner.records.states,
        tables=case.numerics.keeps_tables,
    )
    du = summary.du_mm
    log(
        f"[{case.name}] done: du={'none' if du is None else f'{du:.2f} mm'} hinges={summary.hinge_text or '-'} "
        f"steps={summary.steps} wall={summary.wall_s:.0f} s -> {final_folder(out)}"
    )
    log_file.close()
    return summary


def criterion_text(n: NumericsConfig) -> str:
    """The loading protocol and collapse criterion with this case's numbers, for summary.json."""
    from yadearch.dem.loading import NEAR_EQUILIBRIUM_HOLDS
    from yadearch.solve.falls import MAX_DESCENT_GOES
    from yadearch.solve.path import bracket_text

    return (
        "Loading by support increments (first {0} mm, growing x{1} up to {2} mm after each "
        "equilibrium), each from the last equilibrium state: a move (the largest at the support speed, "
        "shorter ones slower in proportion, so that every move lasts as long), then "
        "a relaxation with the support held and the blocks started from rest. Equilibrium: after "
        f"{n.hold_min_s} s, unbalanced force < {n.equilibrium_tolerance} and all blocks slower "
        f"than {n.still_speed_mm_per_s} mm/s, the static tangent at the blocks' poses positive "
        "definite, and Newton's method on the static model (the same blocks and joints, from the "
        f"blocks' poses and shear forces) moving no block more than {n.snap_thickness_ratio} ring thickness "
        f"to a stable equilibrium (else held on, up to {NEAR_EQUILIBRIUM_HOLDS} times, each until the "
        "blocks are slower than "
        f"{n.settle_speed_mm_per_s} mm/s, after the whole {n.hold_max_s} s where the static model finds no "
        "stable equilibrium). A relaxation that ends off that equilibrium, moves a block more than "
        f"{n.snap_thickness_ratio} ring thickness beyond its increment's reach, or leaves one that far "
        "from the parabola through the "
        f"branch's last three equilibria ({_path_states_text(n)}) has passed a fold: the fold is bisected "
        "to the tolerance by "
        "relaxations that do none of these, and the snap made from just before it, held on while "
        f"the static model still moves the blocks (up to {MAX_DESCENT_GOES} holds). "
        "No equilibrium: a "
        f"block moves > {n.runaway_thickness_ratio} ring "
        f"thickness. A hold that finds neither in {n.hold_max_s} s goes on once; then the increment is "
        "unresolved (no du, never a collapse). Relaxations run at local damping "
        f"{n.hold_damping}. After a failed increment the increment halves (bisection); du = "
        "midpoint of the bracket [last support displacement in equilibrium; first without, "
        f"reached from that state], {bracket_text(n)}."
    ).format(n.first_increment_mm, n.increment_growth, n.max_increment_mm)


def _path_states_text(n: NumericsConfig) -> str:
    """How the path reads its states (`numerics.support_path_states`), in the protocol's words."""
    if n.path_states == STATIC_PATH_STATES:
        return "each read at the static model's stable equilibrium its hold sits in, a branch started along its tangent"
    return "each as its hold leaves it"


def die_with_parent() -> None:
    """Ask Linux to send this process SIGTERM when its parent dies (a killed campaign must not leave
    its runs going on); elsewhere a no-op."""
    try:
        import ctypes

        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(PR_SET_PDEATHSIG, signal.SIGTERM)
    except (OSError, AttributeError):
        return
    if os.getppid() == 1:  # the parent died before prctl took effect
        os.kill(os.getpid(), signal.SIGTERM)


def _interrupt(signum: int, frame: object) -> None:
    raise KeyboardInterrupt(signal.Signals(signum).name)


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 2:
        print("usage: python -m yadearch.dem.simulate CASE.toml OUT_DIR", file=sys.stderr)
        return 2
    signal.signal(signal.SIGTERM, _interrupt)
    die_with_parent()
    try:
        simulate(load_case(argv[0]), Path(argv[1]))
    except YadearchError as exc:
        print(f"error: {exc}", file=sys.stderr)
        with (Path(argv[1]) / LOG_FILE).open("a") as f:
            f.write(f"FAILED: {exc}\n")
        return 1
    except KeyboardInterrupt as exc:
        print(f"error: interrupted ({exc or 'SIGINT'})", file=sys.stderr)
        with (Path(argv[1]) / LOG_FILE).open("a") as f:
            f.write(f"INTERRUPTED: {exc or 'SIGINT'}\n")
        _exit_now(INTERRUPTED_EXIT)
    return 0


def _exit_now(code: int) -> None:
    """End an interrupted simulation at once: Python's finalisation with YADE loaded (its scene and its
    simulation thread) takes about a second, which a campaign stopped by SIGTERM would wait for. YADE's
    temporary folder is removed here, as its exit handler would have."""
    sys.stdout.flush()
    sys.stderr.flush()
    if "yade" in sys.modules:
        from yadearch.dem.yade_env import scratch_folder

        shutil.rmtree(scratch_folder(), ignore_errors=True)
    os._exit(code)


if __name__ == "__main__":
    sys.exit(main())
