"""The live-load validation study (reports/loads): rigid-block limit analysis against the mechanism
method and its results on the paper's arch and semicircles (`rigid`), and the static engine's load
paths beside it (`static`)."""
