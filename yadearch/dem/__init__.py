"""The DEM engine, the only layer that imports YADE: the scene, the contact models, stepping and the
loading protocol; `python -m yadearch.dem.simulate CASE OUT` runs one case to a run folder."""
