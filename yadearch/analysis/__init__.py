"""Analysis of a run folder: hinges and how they formed, the collapse mechanism, du (pure Python)."""

from yadearch.analysis.run import RunAnalysis, Thresholds, analyse_history, analyse_run, load_run

__all__ = ["RunAnalysis", "Thresholds", "analyse_history", "analyse_run", "load_run"]
