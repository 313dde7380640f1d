"""Campaigns of runs (sweeps, calibration, robustness) on local processes or dask (no YADE in this process)."""
