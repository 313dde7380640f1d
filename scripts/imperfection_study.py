"""The imperfection study: the accurate arch (set 2's kn) with explicit voussoir defects, each kind's
amplitude raised until the median du reaches set 1's experiment (48.9 mm), the equivalent kn of every
amplitude (from the kn sweep) and the hinge positions against set 1's.

    .venv/bin/python scripts/imperfection_study.py [--out reports/imperfections] [--jobs 2]
        [--sweep reports/kn-sweep] [--only edge,angle] [--report-only] [--dem-set numerics.KEY=VALUE ...]

Every campaign resumes where it stopped (run folders of the same case are reused), so the study can
be extended or interrupted; the report (imperfections.md) is rewritten from what is finished.
--dem-set gives every run (all are the DEM's) a numerical setting and names it in the report's command
(give it with --report-only too, or the command loses it).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import pandas as pd

from yadearch.atomic import write_text_atomically
from yadearch.results.rundir import read_summary
from yadearch.studies.campaigns.runner import RESULTS_FILE
from yadearch.studies.dem_settings import add_dem_set_option, dem_arguments, dem_settings_of
from yadearch.studies.imperfections.plan import STUDIES
from yadearch.studies.imperfections.report import PERFECT_RUN, REPORT, draw, report, run_study
from yadearch.studies.montecarlo import write_montecarlo


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="reports/imperfections")
    parser.add_argument("--jobs", type=int, default=2, help="runs at once (one core each)")
    parser.add_argument("--sweep", default="reports/kn-sweep", help="campaign folder of the perfect arch's kn sweep")
    parser.add_argument("--only", default="", help="comma-separated study names to run (default: all)")
    parser.add_argument("--report-only", action="store_true", help="write the report from finished runs")
    add_dem_set_option(parser)
    args = parser.parse_args()
    dem_settings = dem_settings_of(parser, args)
    out = Path(args.out)
    chosen = [s for s in STUDIES if not args.only or s.name in args.only.split(",")]
    for study in chosen:
        if not args.report_only:
            run_study(study, out, args.jobs, dem_settings)
        elif (out / study.name / RESULTS_FILE).is_file():  # a stopped campaign: tabulate what is finished
            table = write_montecarlo(pd.read_csv(out / study.name / RESULTS_FILE), out / study.name, study.axes)
            draw(table, study, out)
    perfect_du_mm = read_summary(PERFECT_RUN).collapsed_du_mm()
    text = report(out, pd.read_csv(Path(args.sweep) / "results.csv"), perfect_du_mm, dem_arguments(dem_settings))
    write_text_atomically(out / REPORT, text)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
