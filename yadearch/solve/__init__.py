"""Rigid-block solvers of the arch in pure numpy/scipy (no YADE): the kn -> infinity reference."""
