"""One yadearch run per line of a yade-batch table, for YADE users:

    yade-batch scripts/yade_batch_table.txt scripts/yade_batch_script.py     # from the repository root

Each line gives `preset`, `out` (the campaign folder) and case parameters by name (e.g. kn_N_per_mm3);
the run folder is OUT/<name>, named as `yadearch sweep` names the same run, so `yadearch sweep` with
the same grid and --out afterwards reruns nothing and collects results.csv (and the kn figure). A
finished folder is skipped; a failed run leaves failed.json with its reason.

yade-batch starts every job with the `yade` launcher, which opens TCP ports 9000 (Python console) and
21000 (info socket) on the machine. `yadearch sweep` avoids that: it imports YADE as a library in a
plain Python process per run (and runs on a dask cluster with --scheduler).
"""

import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(sys.argv[0]).resolve().parents[1]))  # this checkout, for the launcher's python

from yade import utils  # noqa: E402  (the launcher provides YADE)

from yadearch.dem.simulate import simulate  # noqa: E402
from yadearch.errors import YadearchError  # noqa: E402
from yadearch.results.rundir import is_complete  # noqa: E402
from yadearch.studies.campaigns.failures import record_failure  # noqa: E402
from yadearch.studies.campaigns.runner import batch_run  # noqa: E402

utils.readParamsFromTable(noTableOk=True, unknownOk=True, preset="set2", out="runs/yade-batch")
from yade.params import table  # noqa: E402  (written by readParamsFromTable)

case, folder = batch_run({k: v for k, v in vars(table).items() if not k.startswith("_")})
if is_complete(folder):
    print(f"{folder} is complete; skipped")
else:
    started = time.time()
    try:
        simulate(case, folder)
    except YadearchError as exc:
        record_failure(folder, case, str(exc), time.time() - started)
        sys.exit(f"error: {exc}")
