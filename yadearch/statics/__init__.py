"""The static engine: each support position solved as a static equilibrium by Newton's method (no YADE)."""
