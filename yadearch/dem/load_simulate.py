"""One live load's path in YADE in this process: `python -m yadearch.dem.load_simulate CASE.toml OUT_DIR
AFTER_MM DESCENT` (DESCENT the descending branch's `model.load_control.DisplacementControl` as JSON, or
`none`: the path stops at its limit point), writing OUT_DIR/NAME_load_path.json, .csv and .log and the
folder of its states, OUT_DIR/NAME_load_path/ (`results.load_path`). Exit code 0: written; 1: the run
failed (reason on stderr and in the log)."""

from __future__ import annotations

import json
import sys
from pathlib import Path

from yadearch.case.config import load_case
from yadearch.errors import YadearchError
from yadearch.model.load_control import DisplacementControl
from yadearch.results.load_path import load_path_file, write_load_path, write_load_path_folder
from yadearch.results.run_log import stamped_log

NOT_TRACED = "none"  # the DESCENT of a path that stops at its limit point


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 4:
        print("usage: python -m yadearch.dem.load_simulate CASE.toml OUT_DIR AFTER_MM DESCENT", file=sys.stderr)
        return 2
    from yadearch.dem.load_ramp import dem_load_path
    from yadearch.dem.simulate import die_with_parent
    from yadearch.dem.yade_env import import_yade

    die_with_parent()
    case, out, after_mm = load_case(argv[0]), Path(argv[1]), float(argv[2])
    descent = None if argv[3] == NOT_TRACED else DisplacementControl(**json.loads(argv[3]))
    out.mkdir(parents=True, exist_ok=True)
    with load_path_file(out, case.name, ".log").open("w") as log_file:
        log = stamped_log(log_file)

        try:
            import_yade(case.numerics.threads)
            result, records, defects = dem_load_path(case, after_mm, log, descent)
        except YadearchError as exc:
            log(f"FAILED: {exc}")
            print(f"error: {exc}", file=sys.stderr)
            return 1
        write_load_path_folder(
            out, result, case, records.series, records.joints, records.snapshots, records.states, defects
        )
        write_load_path(out, result, case)
    return 0


if __name__ == "__main__":
    sys.exit(main())
