"""Analysis of a run folder: hinges and how they formed, the collapse mechanism, du (pure Python);
`yadearch.analysis.run` reads a run (pandas), the other modules need only its summary."""
