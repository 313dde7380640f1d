"""Pure-Python solvers (no YADE): rigid-block limit analysis (limit*, rigid) and loading-path logic (path)."""
