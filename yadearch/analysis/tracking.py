"""Hinges through a run's history: which hinges exist at every record, when each formed (`order`),
the paper's positional label of each (A-D, `model.hinges.paper_labels`), and whether a hinge migrated.

Single-state detection is `yadearch.model.hinges.hinges_at` (rotation above a threshold, spread hinges
reported at their peak). A hinge *forms* when it is detected and its joint has opened: soft joints
rotate elastically by compressing one edge long before a hinge opens, so rotation alone would date
hinges by the joint stiffness rather than by the mechanism.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from yadearch.analysis.history import JointHistory
from yadearch.model.hinges import Hinge, hinges_at, paper_labels

if TYPE_CHECKING:
    import pandas as pd

ROTATION_THRESHOLD_MRAD = 2.0  # runner's default: 0.05 mm across a 24 mm joint
OPENING_THRESHOLD_MM = 0.02  # a hinge has formed once its joint has opened this much
MAX_JUMP_INTERFACES = 5  # a hinge is followed back to hinges of its side at most this many interfaces away


@dataclass(frozen=True)
class Migration:
    """A hinge's peak moved out of its own spread to another interface at `delta_mm`."""

    delta_mm: float
    from_interface: int
    to_interface: int


@dataclass
class HingeTrack:
    """One hinge of the final state followed back through the history.

    `per_record[r]` is the hinge detected at record r (None if absent), `opening_mm[r]` its opening
    (NaN if absent); `formed_record` is the first record of the final unbroken run in which the hinge
    is detected and open.
    """

    side: str
    per_record: list[Hinge | None]
    opening_mm: np.ndarray
    formed_record: int
    paper_label: str = ""  # the paper's positional letter (A-D, model.hinges.paper_labels); "" if none
    order: int = 0  # 1 for the first hinge to form, 2 for the next...
    migrations: list[Migration] = field(default_factory=list)

    @property
    def final(self) -> Hinge:
        return self.hinge_at(-1)

    def hinge_at(self, record: int) -> Hinge:
        """The hinge detected at `record`: always one at the last record and from `formed_record` on
        (the hinge is open there); an error where the hinge is absent."""
        hinge = self.per_record[record]
        if hinge is None:
            raise ValueError(f"the {self.side} hinge tracked here is not detected at record {record}")
        return hinge

    @property
    def interface(self) -> int:
        return self.final.interface

    @property
    def rotation_mrad(self) -> np.ndarray:
        """|hinge rotation| at every record (mrad), NaN where the hinge is absent."""
        return np.array([np.nan if h is None else abs(h.rotation) * 1e3 for h in self.per_record])


def format_interfaces(interfaces: tuple[int, ...] | list[int]) -> str:
    """The paper's notation for a (spread) hinge: "29-30-31-32"."""
    return "-".join(str(k) for k in interfaces)


def hinges_per_record(history: JointHistory, threshold_rad: float) -> list[list[Hinge]]:
    """`hinges_at` applied to every record of the history."""
    return [hinges_at(history.rotation[r], threshold_rad) for r in range(history.n_records)]


def _follow_back(finals: list[Hinge], detected: list[list[Hinge]], max_jump: int) -> list[list[Hinge | None]]:
    """Every final hinge followed from the last record backwards: at each record, a detected hinge
    belongs to the nearest track of its side within `max_jump` interfaces, and each track takes the
    strongest hinge that belongs to it (so a hinge overtaken by a new one migrates there)."""
    n = len(detected)
    tracks: list[list[Hinge | None]] = [[None] * (n - 1) + [h] for h in finals]
    positions = [h.interface for h in finals]
    for r in range(n - 2, -1, -1):
        owned: list[list[Hinge]] = [[] for _ in finals]
        for hinge in detected[r]:
            near = [
                (abs(hinge.interface - p), t)
                for t, p in enumerate(positions)
                if finals[t].side == hinge.side and abs(hinge.interface - p) <= max_jump
            ]
            if near:
                owned[min(near)[1]].append(hinge)
        for t, candidates in enumerate(owned):
            if candidates:
                strongest = max(candidates, key=lambda h: abs(h.rotation))
                tracks[t][r] = strongest
                positions[t] = strongest.interface
    return tracks


def _formed_record(present: np.ndarray) -> int:
    """Start of the final unbroken run of True (the last record if it is False)."""
    r = len(present) - 1
    while r > 0 and present[r - 1] and present[r]:
        r -= 1
    return r


def _migrations(per_record: list[Hinge | None], deltas: np.ndarray, start: int) -> list[Migration]:
    """Jumps of the hinge's peak out of the spread it had at the previous record where it was seen;
    a spread hinge whose peak drifts within its own spread has not migrated."""
    moves: list[Migration] = []
    previous: Hinge | None = None
    for r in range(start, len(per_record)):
        hinge = per_record[r]
        if hinge is None:
            continue
        if previous is not None and hinge.interface not in previous.interfaces:
            moves.append(Migration(float(deltas[r]), previous.interface, hinge.interface))
        previous = hinge
    return moves


def track_hinges(
    history: JointHistory,
    rotation_threshold_mrad: float = ROTATION_THRESHOLD_MRAD,
    opening_threshold_mm: float = OPENING_THRESHOLD_MM,
    max_jump: int = MAX_JUMP_INTERFACES,
    moving_support: str = "right",
) -> list[HingeTrack]:
    """The hinges of the final record, each followed back, dated, numbered in order of formation
    (hinges forming at the same record: left to right) and labelled A-D by position as the paper
    does; returned in order of formation."""
    detected = hinges_per_record(history, rotation_threshold_mrad * 1e-3)
    tracks = []
    finals = detected[-1]  # each track ends on its final hinge
    for final, per_record in zip(finals, _follow_back(finals, detected, max_jump), strict=True):
        opening = np.array(
            [
                np.nan if h is None else history.hinge_opening_mm(r, h.interfaces, h.side)
                for r, h in enumerate(per_record)
            ]
        )
        present = np.nan_to_num(opening) >= opening_threshold_mm
        formed = _formed_record(present)
        tracks.append(
            HingeTrack(
                final.side, per_record, opening, formed, migrations=_migrations(per_record, history.delta_mm, formed)
            )
        )
    tracks.sort(key=lambda t: (t.formed_record, t.interface))
    labels = paper_labels(
        [(t.interface, t.side, t.final.rotation) for t in tracks], history.n_interfaces, moving_support
    )
    for order, track in enumerate(tracks, start=1):
        track.order = order
        track.paper_label = labels.get((track.interface, track.side), "")
    return tracks


def sequence(tracks: list[HingeTrack]) -> str:
    """Pivot sides left to right, the paper's "E-I-E-E"."""
    return "-".join(t.side for t in sorted(tracks, key=lambda t: t.interface))


def formation_steps(tracks: list[HingeTrack], deltas: np.ndarray) -> list[tuple[str, float, str]]:
    """(label, delta at formation, sequence of the hinges formed so far) in order of formation."""
    return [(t.paper_label, float(deltas[t.formed_record]), sequence(tracks[: k + 1])) for k, t in enumerate(tracks)]


def hinge_table(
    history: JointHistory, tracks: list[HingeTrack], rotation_threshold_mrad: float = ROTATION_THRESHOLD_MRAD
) -> pd.DataFrame:
    """Every hinge at every record: delta, interface (peak), spread, side, rotation, opening and the
    label of the final hinge it belongs to (empty for hinges that do not last to collapse)."""
    labels = {
        (r, seen.interface): t.paper_label
        for t in tracks
        for r in range(history.n_records)
        if (seen := t.per_record[r]) is not None
    }
    rows = []
    for r, hinges in enumerate(hinges_per_record(history, rotation_threshold_mrad * 1e-3)):
        for h in hinges:
            rows.append(
                {
                    "stage": history.stage[r],
                    "step": int(history.step[r]),
                    "delta_mm": float(history.delta_mm[r]),
                    "label": labels.get((r, h.interface), ""),
                    "interface": h.interface,
                    "interfaces": format_interfaces(h.interfaces),
                    "side": h.side,
                    "rotation_mrad": abs(h.rotation) * 1e3,
                    "opening_mm": history.hinge_opening_mm(r, h.interfaces, h.side),
                }
            )
    columns = ["stage", "step", "delta_mm", "label", "interface", "interfaces", "side", "rotation_mrad", "opening_mm"]
    import pandas as pd  # the table of one run's analysis: a run's warnings need only its summary

    return pd.DataFrame(rows, columns=columns)
