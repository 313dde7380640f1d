"""The speed benchmark (`scripts/benchmark.py`, docs/speed.md): the DEM's runs and steps
(`dem_runs`, `dem_speed`), the static engine's (`static_engine`), run folders' weight (`run_files`),
the whole DEM invocation (`report`), and the targets with a PASS or FAIL line each (`verdicts`)."""
