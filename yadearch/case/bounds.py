"""The accepted ranges of the study and campaign arguments, in a module light enough for the CLI and the
API to check arguments before any study (and pandas, numba) is imported."""

MAX_TARGET_DU_MM = 10_000.0  # the largest support displacement a case accepts (loading.max_support_displacement_mm)
MAX_RUNS = 100_000  # a larger campaign is refused (a typo in a grid), unless MAX_RUNS_VARIABLE raises it
MAX_STEP_DEG = 90  # a capacity map's direction step: coarser than this a map would not show the half-plane
MIN_STEP_DEG = 0.1  # finer is 1801+ directions a map, more than the figure can show
MAX_CHECKS = 50  # a sensitivity study's engine checks; more is a campaign of its own (`yadearch sweep --engine ...`)
MIN_BASE_POINTS = 8  # a Sobol sample's size at least; its first half gives the coarse indices
