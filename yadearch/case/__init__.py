"""The case a user describes: its parameter sections, presets, TOML, and the quantities derived from it."""
