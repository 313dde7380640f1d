"""The critical position of a concentrated load (studies/loads/critical.py): the influence line's least
refined between its samples' neighbours, as a bridge assessment asks (it sampled k / (N + 1) only, and a
tandem's least sat at the first sample: sixth user trial); a symmetric arch names both mirror positions."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

import yadearch as ya
from yadearch.studies.loads.critical import POSITION_TOLERANCE, over_joint_positions, with_critical

SAMPLES = [k / 10 for k in range(1, 10)]
JOINTS = [(k + 0.5) / 40 for k in range(40)]  # positions over a 40-joint arch's joints, say


def _line(capacity) -> tuple[pd.DataFrame, callable]:
    def row_at(x: float) -> dict:
        return {"position_over_span": x, "collapse_load_N": capacity(x)}

    return pd.DataFrame([row_at(x) for x in SAMPLES]), row_at


def test_the_least_is_found_between_the_samples_and_marked():
    table, row_at = _line(lambda x: 1.0 + (x - 0.33) ** 2)
    found = with_critical(table, row_at, JOINTS)
    refined = found[~found["sampled"]]
    assert len(refined) == 1 and refined["position_over_span"].iloc[0] == pytest.approx(
        0.33, abs=2 * POSITION_TOLERANCE
    )
    assert found["position_over_span"].is_monotonic_increasing and found["sampled"].sum() == len(SAMPLES)


def test_a_least_beyond_the_first_sample_is_searched_to_the_springing():
    table, row_at = _line(lambda x: 1.0 + (x - 0.04) ** 2)
    refined = with_critical(table, row_at, JOINTS).query("not sampled")
    assert refined["position_over_span"].iloc[0] == pytest.approx(0.04, abs=2 * POSITION_TOLERANCE)


def test_a_symmetric_line_names_both_mirror_positions_and_no_collapse_refines_nothing():
    table, row_at = _line(lambda x: 1.0 + (abs(x - 0.5) - 0.17) ** 2)
    refined = with_critical(table, row_at, JOINTS).query("not sampled")["position_over_span"].tolist()
    assert refined == pytest.approx([0.33, 0.67], abs=2 * POSITION_TOLERANCE)
    table, row_at = _line(lambda x: float("inf"))
    assert with_critical(table, row_at, JOINTS)["sampled"].all()


def test_the_paper_arch_is_weakest_to_a_load_over_a_joint_and_below_every_sample():
    """Rigid blocks: the capacity dips wherever the load stands over a joint (the hinge under it); the
    critical position of the paper's arch is a joint's extrados (0.368 of the span, 8.557 N, and its
    mirror), below the least of 9 samples (9.034 N at 0.3) and of a scan every 0.002 of the span."""
    case = ya.preset("set2").replace(live_load="vertical")
    line = ya.load_influence(case, 9)
    critical = line[~line["sampled"]]
    assert critical["position_over_span"].tolist() == pytest.approx([0.3682, 0.6318], abs=1e-4)
    x = float(critical["position_over_span"].iloc[0])
    assert min(abs(p - x) for p in over_joint_positions(case)) < POSITION_TOLERANCE
    least = float(critical["collapse_load_N"].iloc[0])
    assert least == pytest.approx(ya.loads(case.replace(load_position_over_span=x)).multiplier, rel=1e-12)
    scan = [ya.loads(case.replace(load_position_over_span=float(p))).multiplier for p in np.arange(0.30, 0.40, 0.002)]
    assert least < min(scan) < line.loc[line["sampled"], "collapse_load_N"].min()
