"""Explicit imperfections instead of a low kn: the amplitude study (`amplitudes`), the search for the
amplitude that matches the paper's set 1 (`matching`) and their report (`report`)."""
