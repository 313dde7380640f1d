"""The rigid LP against a published point-load collapse (Stockdale et al. 2018, SoftwareX 7, 174-179,
doi:10.1016/j.softx.2018.05.006; docs/loads.md): a 27-voussoir semicircle loaded at the extrados end of a
joint collapses at 2.751 kN (their calculator) or 2.756 kN (virtual powers) on four hinges, one of them at
the loaded joint."""

from __future__ import annotations

import pytest

from yadearch.studies.loads import published as p

# the source's voussoirs are circular sectors, these straight-faced polygons weigh 0.23 % less
POLYGON_TOLERANCE = 0.005


def test_the_lp_carries_the_published_point_load_on_a_hinge_at_the_loaded_joint():
    table = p.point_load_table()  # measured: 2746.6 N, 4I 9E 21I 28E
    for row in table.itertuples():
        assert row.lp_N == pytest.approx(row.published_N, rel=POLYGON_TOLERANCE), row.method
        assert row.lp_N < row.published_N  # lighter blocks, a lower collapse load
    hinges = table["lp_hinges"].iloc[0].split()
    assert len(hinges) == 4
    assert any(h.rstrip("IE") == str(p.POINT_LOAD_JOINT + 1) for h in hinges)  # the load point turns
    weight_ratio = table["arch_weight_N"].iloc[0] / table["sector_arch_weight_N"].iloc[0]
    assert 1.0 - POLYGON_TOLERANCE < weight_ratio < 1.0
