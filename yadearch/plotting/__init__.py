"""Figures of the pure-Python solvers (no YADE, no run folder needed)."""
