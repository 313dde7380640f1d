"""Hinges of one state from the joints' relative rotations, in pure numpy.

A joint's hinge rotation is (extrados opening - intrados opening) / joint length: positive when the
extrados opens (or the intrados is the more compressed edge), i.e. the joint pivots about its
intrados: an I hinge; negative: an E hinge (the paper labels a hinge by the side of its pivot).
Rotation rather than opening, because soft joints rotate by compressing one edge before the other
opens. Adjacent joints rotating the same way form one spread hinge, reported with its peak.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Hinge:
    """One hinge: interfaces it spans (1-based), its peak interface, pivot side, peak rotation (rad)."""

    interfaces: tuple[int, ...]
    interface: int
    side: str
    rotation: float

    @property
    def label(self) -> str:
        """The hinge as the paper names it: its peak interface and pivot side ("12I")."""
        return f"{self.interface}{self.side}"

    def to_json(self) -> dict:
        return {
            "interface": self.interface,
            "side": self.side,
            "interfaces": list(self.interfaces),
            "rotation_mrad": abs(self.rotation) * 1e3,
        }


def hinge_rotation(opening_intrados: np.ndarray, opening_extrados: np.ndarray, joint_length: float) -> np.ndarray:
    """Signed hinge rotation of every joint (rad): > 0 pivots about the intrados (I)."""
    return (np.asarray(opening_extrados) - np.asarray(opening_intrados)) / joint_length


SPREAD_FRACTION = 0.5  # joints beside a hinge's peak rotating at least this fraction of it belong to it


def hinges_at(rotation: np.ndarray, threshold: float) -> list[Hinge]:
    """Hinges, left to right: runs of adjacent joints whose |rotation| exceeds `threshold` (rad)
    with the same sign, each reported at its peak; the hinge spans the contiguous joints around the
    peak that rotate at least SPREAD_FRACTION of it (the paper's "29-30-31-32")."""
    return [_spread_hinge(rotation, first, last, None) for first, last in _same_sign_runs(rotation, threshold)]


def hinge_zones(turn: np.ndarray, fraction: float) -> list[Hinge]:
    """The hinges of a motion as zones, left to right: runs of adjacent joints turning the same way,
    each turning the segments either side of it by the run's summed turn, kept where that sum is at
    least `fraction` of the largest run's (a soft ring's hinge spreads over joints that each turn a
    little); each reported at its peak with its spread, as `hinges_at` does, its rotation the sum."""
    runs = [(first, last, float(np.sum(turn[first : last + 1]))) for first, last in _same_sign_runs(turn, 0.0)]
    largest = max((abs(total) for _, _, total in runs), default=0.0)
    return [_spread_hinge(turn, a, b, total) for a, b, total in runs if abs(total) >= fraction * largest]


def _same_sign_runs(rotation: np.ndarray, threshold: float) -> list[tuple[int, int]]:
    """The first and last index (0-based) of each run of adjacent joints whose |rotation| exceeds
    `threshold` with the same sign."""
    sides = [None if abs(r) <= threshold else r > 0 for r in rotation]
    runs, k = [], 0
    while k < len(sides):
        if sides[k] is None:
            k += 1
            continue
        end = k
        while end + 1 < len(sides) and sides[end + 1] == sides[k]:
            end += 1
        runs.append((k, end))
        k = end + 1
    return runs


def _spread_hinge(rotation: np.ndarray, k: int, end: int, total: float | None) -> Hinge:
    """The hinge of the run k..end at its peak, spanning the joints around the peak that rotate at
    least SPREAD_FRACTION of it; its rotation the peak's, or `total` where given."""
    peak = max(range(k, end + 1), key=lambda m: abs(rotation[m]))
    first, last = peak, peak
    while first > k and abs(rotation[first - 1]) >= SPREAD_FRACTION * abs(rotation[peak]):
        first -= 1
    while last < end and abs(rotation[last + 1]) >= SPREAD_FRACTION * abs(rotation[peak]):
        last += 1
    side = "I" if rotation[peak] > 0 else "E"
    value = float(rotation[peak]) if total is None else total
    return Hinge(tuple(range(first + 1, last + 2)), peak + 1, side, value)


def same_hinges(a: list[dict], b: list[dict]) -> bool:
    """Whether two runs collapsed on the same hinges, given their summaries' `hinges_detail` (or
    `hinges_at_collapse`): as many, on the same sides in the same order, each one's peak interface
    inside the other's spread. A hinge spread over adjacent joints whose peak moves within the
    spread is the same hinge (the paper reports such a hinge as the range, e.g. 11-12 I)."""
    if len(a) != len(b):
        return False
    return all(
        x["side"] == y["side"]
        and x["interface"] in y.get("interfaces", [y["interface"]])
        and y["interface"] in x.get("interfaces", [x["interface"]])
        for x, y in zip(a, b)
    )


def mirror_hinge_labels(labels: list[str] | tuple[str, ...], last_interface: int) -> list[str]:
    """Hinge labels ("9I", "28E") of an arch's mirror image in the arch's own numbering: interface k
    faces `last_interface` + 1 - k across the crown, a pivot keeps its side; left to right."""
    mirrored = [(last_interface + 1 - int(label[:-1]), label[-1]) for label in labels]
    return [f"{interface}{side}" for interface, side in sorted(mirrored)]


HINGE_CHANGES = ("the same", "the mirror image", "a joint away", "another count", "another mechanism")
# how one run's hinges differ from another's, from the least change to the most (`hinge_change`)
SAME_MECHANISM = HINGE_CHANGES[:3]  # changes that keep the mechanism: a tie's mirror image, a hinge a joint away


def hinge_change(reference: str, other: str, last_interface: int) -> str:
    """How `other`'s hinges ("1E 12I 28E 56E") differ from `reference`'s, one of HINGE_CHANGES: the
    same; the mirror image (a symmetric problem's tie, which the path's increments decide); each hinge
    at most a joint away on its side (of the hinges or of their mirror image); another count; another
    mechanism."""
    ours, theirs = reference.split(), other.split()
    mirrored = mirror_hinge_labels(theirs, last_interface)
    if ours == theirs:
        return HINGE_CHANGES[0]
    if ours == mirrored:
        return HINGE_CHANGES[1]
    if _within_a_joint(ours, theirs) or _within_a_joint(ours, mirrored):
        return HINGE_CHANGES[2]
    return HINGE_CHANGES[3] if len(ours) != len(theirs) else HINGE_CHANGES[4]


def _within_a_joint(a: list[str], b: list[str]) -> bool:
    """As many hinges, left to right on the same sides, each at most one interface from its partner."""
    return len(a) == len(b) and all(x[-1] == y[-1] and abs(int(x[:-1]) - int(y[:-1])) <= 1 for x, y in zip(a, b))


PAPER_LABELS = ("A", "B", "C", "D")  # the paper's positional hinge labels, assigned by `paper_labels`


def paper_labels(
    hinges: list[tuple[int, str, float]], last_interface: int, moving_support: str = "right"
) -> dict[tuple[int, str], str]:
    """The paper's positional labels of a collapse mechanism's hinges, given as (interface, side,
    rotation): D = the extrados hinge at the fixed support, C = the extrados hinge at the moving one
    (interface 1 or `last_interface`: the paper moves the right one, `moving_support` says which),
    A = the intrados hinge, B = the remaining extrados hinge (the most rotated where there are
    several); hinges left over get no label."""
    fixed, moving = (last_interface, 1) if moving_support == "left" else (1, last_interface)

    def most_rotated(candidates: list[tuple[int, str, float]]) -> tuple[int, str] | None:
        best = max(candidates, key=lambda h: abs(h[2]), default=None)
        return None if best is None else (best[0], best[1])

    labels: dict[tuple[int, str], str] = {}
    if any(h[:2] == (fixed, "E") for h in hinges):
        labels[(fixed, "E")] = "D"
    if any(h[:2] == (moving, "E") for h in hinges):
        labels[(moving, "E")] = "C"
    intrados = most_rotated([h for h in hinges if h[1] == "I"])
    if intrados:
        labels[intrados] = "A"
    extrados = most_rotated([h for h in hinges if h[1] == "E" and h[0] not in (1, last_interface)])
    if extrados:
        labels[extrados] = "B"
    return labels
