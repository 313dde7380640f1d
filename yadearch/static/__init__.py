"""The static engine: each support position solved as a static equilibrium by Newton's method (no
YADE); `python -m yadearch.static.simulate CASE OUT` runs one case to a run folder."""
