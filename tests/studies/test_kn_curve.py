"""The kn curve's jump finder on tables whose jumps are known (pure), and one bisection round on the
static engine (a 9-voussoir arch, seconds)."""

from __future__ import annotations

import pandas as pd

from yadearch.studies.kn_curve import BRACKET_RATIO, find_jumps, hinge_moves, jumps_table


def _table(rows: list[tuple[float, float | None, int, int]]) -> pd.DataFrame:
    """Runs (kn, du or None for an arch that does not stand, hinge A, hinge B)."""
    return pd.DataFrame(
        [
            {
                "kn_N_per_mm3": kn,
                "du_mm": du,
                "status": "failed" if du is None else "done",
                "collapsed": du is not None,
                "hinge_A": a,
                "hinge_B": b,
                "hinges": "" if du is None else f"1E {a}I {b}E 56E",
            }
            for kn, du, a, b in rows
        ]
    )


def test_a_jump_is_a_change_of_du_and_a_hinge_move_alone_is_listed_apart():
    table = _table(
        [(0.05, None, 12, 28), (0.1, 15.0, 12, 28), (0.2, 15.2, 12, 29), (0.4, 15.3, 12, 29), (0.8, 20.0, 11, 29)]
    )
    jumps = jumps_table(table)
    assert list(jumps["kn_below"]) == [0.05, 0.4]
    assert jumps["what"].iloc[0] == "the arch starts to stand under its own weight"
    assert jumps["what"].iloc[1] == "A 12 -> 11"
    moves = hinge_moves(table)
    assert list(moves["what"]) == ["B 28 -> 29"]


def test_adjacent_brackets_of_a_steep_stretch_are_one_row():
    table = _table([(1.0, 10.0, 9, 29), (1.01, 11.0, 9, 29), (1.02, 12.0, 9, 29), (2.0, 12.1, 9, 29)])
    jumps = jumps_table(table)
    assert len(jumps) == 1 and jumps["kn_below"].iloc[0] == 1.0 and jumps["kn_above"].iloc[0] == 1.02
    assert jumps["what"].iloc[0].startswith("a steep stretch")


def test_a_bracket_narrower_than_the_target_is_located():
    table = _table([(2.0, 73.0, 10, 29), (2.0 * BRACKET_RATIO * 0.999, 84.0, 9, 28)])
    assert all(j.ratio <= BRACKET_RATIO for j in find_jumps(table))


def test_bisection_on_the_static_engine_narrows_a_jump_of_hinge_a(tmp_path):
    """A 9-voussoir arch between kn 0.3 and 30: whatever jumps its du makes are bracketed to 1 %."""
    from yadearch.case.config import preset
    from yadearch.studies.campaigns.executors import local_pool
    from yadearch.studies.campaigns.runner import run_campaign
    from yadearch.studies.kn_curve import bisect_jumps

    base = preset("set2").with_overrides({"n_voussoirs": 9, "numerics.engine": "static"})
    with local_pool(2) as pool:
        grid = run_campaign(
            base, [{"kn_N_per_mm3": kn} for kn in (0.3, 3.0, 30.0)], tmp_path / "grid", pool, progress=False
        )
        table = bisect_jumps(base, grid, tmp_path, pool, log=lambda line: None)
    assert (table["status"] == "done").all()
    assert all(j.ratio <= BRACKET_RATIO for j in find_jumps(table))
    by_kn = table.set_index("kn_N_per_mm3")["du_mm"]
    assert by_kn[30.0] > by_kn[3.0] > by_kn[0.3]  # stiffer joints carry the support further (measured:
    # 73.8, 120.4, 126.2 mm on this arch)
