"""The rigid LP against published closed forms of the semicircle under its own weight (Cocchetti and
Rizzi 2020, doi:10.3221/IGF-ESIS.51.26, p. 370; docs/loads.md): the least friction at which it stands
at all, the same for every ring thick enough, and the friction below which sliding at the shoulders
raises its least thickness."""

from __future__ import annotations

import pytest

from yadearch.studies.loads import published as p


@pytest.mark.parametrize("t_over_r", [0.25, 0.30])
def test_below_the_published_sliding_friction_no_thickness_stands(t_over_r):
    # measured: 17.182 deg at t/R 0.21, 0.25 and 0.30 (55 voussoirs)
    assert p.least_friction_deg(t_over_r) == pytest.approx(p.SLIDING_FRICTION_DEG, abs=0.02)


def test_sliding_raises_the_least_thickness_only_below_the_published_friction():
    no_sliding = p.least_t_over_r(41.2)
    assert p.least_t_over_r(22.0) == pytest.approx(no_sliding, abs=2 * p.T_OVER_R_TOLERANCE)
    assert p.least_t_over_r(21.0) > 1.05 * no_sliding  # measured 0.11763 against 0.10736
    # where it starts to rise: measured 21.570 deg; the continuous ring's 21.5952 (finite joints: a hair lower)
    assert p.least_friction_deg(no_sliding + 2 * p.T_OVER_R_TOLERANCE) == pytest.approx(p.MIXED_FRICTION_DEG, abs=0.1)
