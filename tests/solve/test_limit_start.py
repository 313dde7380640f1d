"""The rigid march started on a named linkage (`limit_analysis(start_hinges=...)`, `yadearch limit
--start-hinges`): the LP's own linkage gives the LP's answer, another admissible one is followed from
rest (non-uniqueness of the rigid three-hinge linkage, docs/atlas.md), and a linkage the rigid arch
cannot take is refused in one line."""

from __future__ import annotations

import pytest

import yadearch.api as ya
from yadearch.case.config import preset
from yadearch.cli.commands import main
from yadearch.errors import ArgumentTypeError, CaseError
from yadearch.solve.limit import limit_analysis

# the closing semicircle of docs/atlas.md at t/R 0.25: its thrust line grazes the intrados at joints 22-23
# and 34-35, so two three-hinge linkages are admissible rigid equilibria from the first steps on
CLOSING_SEMICIRCLE = {"embrace_deg": 180.0, "support_direction_deg": 180.0, "thickness_mm": 75.0}


def test_the_lps_own_linkage_named_gives_the_lps_answer():
    case = preset("set2").with_overrides({"n_voussoirs": 15})
    own = limit_analysis(case, mirror=False)
    first = " ".join(f"{h.interface}{h.side}" for h in own.hinge_history if h.from_mm == 0.0)
    named = limit_analysis(case, start_hinges=first)
    assert named.start_hinges == tuple(first.split())
    assert named.du_mm == own.du_mm and named.collapse_hinges == own.collapse_hinges


def test_hinges_may_come_as_a_list_and_other_types_are_refused_in_one_line():
    case = preset("set2").with_overrides({"n_voussoirs": 15})
    named = limit_analysis(case, start_hinges=["3i 10e", "16E"])
    assert named.start_hinges == ("3I", "10E", "16E")
    for wrong in (b"3I 10E 16E", 5):
        with pytest.raises(ArgumentTypeError, match="start_hinges must be three hinge labels"):
            limit_analysis(case, start_hinges=wrong)
    with pytest.raises(ArgumentTypeError, match="start_mm must be a number"):
        ya.limit(case, start_hinges="3I 10E 16E", start_mm="5")


def test_another_admissible_linkage_is_followed_from_rest_and_ends_elsewhere():
    case = preset("set2").with_overrides(CLOSING_SEMICIRCLE)
    own = limit_analysis(case, mirror=False)
    named = limit_analysis(case, start_hinges="1E 35I 56E")
    assert [f"{h.interface}{h.side}" for h in named.hinge_history[:3]] == ["1E", "35I", "56E"]
    assert all(h.from_mm == 0.0 for h in named.hinge_history[:3])
    assert "35I" not in " ".join(f"{h.interface}{h.side}" for h in own.hinge_history[:3])
    # both are admissible rigid paths; they part by more than the bisection's width
    assert named.du_mm is not None and own.du_mm is not None and abs(named.du_mm - own.du_mm) > 1.0
    assert named.mirror_du_rigid_mm is None  # its hinges name this branch: the mirror image is not solved


@pytest.mark.parametrize(
    "hinges, words",
    [
        ("1E 9I", "three hinges on distinct interfaces of 1..16"),
        ("1E 9X 16E", "three hinges"),
        ("0E 9I 16E", "1..16"),
        ("1E 1I 16E", "distinct"),
        ("1E 2E 3E", "without blocks passing through each other"),
        ("2I 10E 16E", "no admissible equilibrium on these hinges"),
        ("1E 9I 16E", "without blocks passing through each other"),  # the LP's 3I 10E 16E with sides swapped
        ("1I 9E 16I", "without blocks passing through each other"),
    ],
)
def test_a_linkage_the_rigid_arch_cannot_take_is_refused_in_one_line(hinges, words, capsys):
    case = preset("set2").with_overrides({"n_voussoirs": 15})
    with pytest.raises(CaseError, match=words):
        limit_analysis(case, start_hinges=hinges)
    args = ["limit", "--preset", "set2", "--set", "n_voussoirs=15", "--start-hinges", hinges, "--out", "/dev/null/x"]
    assert main(args) != 0
    err = capsys.readouterr().err.strip()
    assert err.startswith("error: start_hinges") and "\n" not in err and "Traceback" not in err


def test_a_linkage_admissible_only_further_on_is_followed_from_where_it_is_placed():
    # the semicircle of t/R 0.25 moved down and in (docs/atlas.md): the static engine ends on 10I 39I 56E
    # from about 102 mm; rigid blocks placed on it there collapse a few millimetres on (measured 108.94 mm)
    geometry = {"embrace_deg": 180.0, "thickness_mm": 75.0, "support_direction_deg": -135.0}
    case = preset("set2").with_overrides(geometry)
    placed = limit_analysis(case, start_hinges="10I 39I 56E", start_mm=102.5)
    assert placed.start_mm == 102.5 and [h.from_mm for h in placed.hinge_history[:3]] == [102.5] * 3
    assert placed.du_mm is not None and 102.5 < placed.du_mm < 120.0
    with pytest.raises(CaseError, match="no admissible equilibrium on these hinges 10 mm along them"):
        limit_analysis(case, start_hinges="10I 39I 56E", start_mm=10.0)
    with pytest.raises(CaseError, match="give start_hinges too"):
        limit_analysis(case, start_mm=5.0)
    with pytest.raises(CaseError, match=r"start_mm must be in \[0, 150\) mm, got -1"):
        limit_analysis(case, start_hinges="10I 39I 56E", start_mm=-1.0)


def test_on_the_deformable_arch_s_own_linkage_the_compliant_march_meets_the_static_engine():
    # the semicircle of docs/validation-movements.md spreading: the deformable arch hinges at 12I and 45I,
    # which rigid blocks admit only from about 2 mm on; placed there, the compliant march at kn 10 000
    # meets the static engine (measured 14.41 against 14.40 mm), where on its own rigid linkage it gave 15.20
    from yadearch.static.simulate import simulate_static

    spreading = {"embrace_deg": 180.0, "thickness_mm": 40.0, "support_direction_deg": 0.0, "kn_N_per_mm3": 10000.0}
    case = preset("set2").with_overrides(spreading)
    static = simulate_static(case.with_overrides({"engine": "static"}), None, log=lambda line: None)
    march = limit_analysis(case, compliant=True, start_hinges="12I 28E 45I", start_mm=2.0)
    assert static.du_mm is not None and march.du_mm is not None
    assert march.du_mm == pytest.approx(static.du_mm, rel=0.01)
    assert {"12I", "45I"} <= set(march.collapse_hinges) and "12I" in static.hinge_labels
