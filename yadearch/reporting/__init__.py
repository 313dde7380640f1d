"""The Markdown report of run folders."""
