"""Campaigns: a grid of runs planned (`grid`), run resumably on an executor (`runner`, `executors`:
local processes or dask), failures kept with their reason (`failures`), each invocation's wall time
(`sessions`) and the results table (`table`)."""
