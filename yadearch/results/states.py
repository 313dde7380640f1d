"""Every recorded state of a run in one array file (states.npz): the support displacement, stage and
step of each state and the block poses (centroid position and rotation), so that any state can be
drawn, animated or exported after the run; on a live load's path also each state's load multiplier and
its unit. The states are those of joints.csv, in its order."""

from __future__ import annotations

import zipfile
import zlib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from yadearch.atomic import write_atomically
from yadearch.errors import RunFolderError
from yadearch.solve.stages import PATH_STAGES

STATES_FILE = "states.npz"
STATE_KEYS = ("stage", "step", "delta_mm", "pos_m", "rot_rad")
LOAD_DIGITS = 4  # significant digits of a state's load in its label (as the command line prints loads)
LOAD_COLUMN = "live_load"  # a load path's tables and exports: each state's multiplier (live_load_N or _g)


def state_entry(
    stage: str, step: int, delta_mm: float, pos: np.ndarray, rot: np.ndarray, load: tuple[float, str] | None = None
) -> dict[str, Any]:
    """One recorded state: `pos` (n_blocks, 2 or 3; m, only x and y kept) and `rot` (n_blocks; rad);
    on a live load's path its `load` (the multiplier, its unit)."""
    entry: dict[str, Any] = {
        "stage": stage,
        "step": int(step),
        "delta_mm": float(delta_mm),
        "pos_m": np.asarray(pos, float)[:, :2].copy(),
        "rot_rad": np.asarray(rot, float).copy(),
    }
    if load is not None:
        entry["load"], entry["load_unit"] = float(load[0]), load[1]
    return entry


def write_states(path: Path, states: list[dict[str, Any]]) -> None:
    """Write the states as one compressed array file, atomically (with their loads where they have one)."""
    arrays = {
        "stage": np.array([s["stage"] for s in states], dtype=str),
        "step": np.array([s["step"] for s in states], dtype=np.int64),
        "delta_mm": np.array([s["delta_mm"] for s in states], dtype=float),
        "pos_m": np.array([s["pos_m"] for s in states], dtype=float),
        "rot_rad": np.array([s["rot_rad"] for s in states], dtype=float),
    }
    if "load" in states[0]:
        arrays["load"] = np.array([s["load"] for s in states], dtype=float)
        arrays["load_unit"] = np.array(states[0]["load_unit"])

    def save(temporary: Path) -> None:
        with temporary.open("wb") as handle:  # a file object: numpy would add .npz to a name
            np.savez_compressed(handle, **arrays)

    write_atomically(path, save)


@dataclass(frozen=True)
class RunStates:
    """A run's recorded states as arrays, one row a state (the self-weight state first, or a live load's
    path's start, the collapse last when the arch collapsed)."""

    stage: np.ndarray  # str: selfweight, equilibrium, collapse, ... (docs/numerics.md)
    step: np.ndarray
    delta_mm: np.ndarray  # the support displacement of each state (mm; on a live load's path the one it holds)
    pos_m: np.ndarray  # (n_states, n_blocks, 2): block centroids (m); block 0 and -1 are the supports
    rot_rad: np.ndarray  # (n_states, n_blocks): block rotations (rad, anticlockwise)
    load: np.ndarray | None = None  # a live load's path: each state's multiplier (load_unit); None: a support's
    load_unit: str = ""

    def __len__(self) -> int:
        return len(self.stage)

    def path(self) -> np.ndarray:
        """Indices of the loading path: the self-weight state, each equilibrium, then the collapse."""
        return np.flatnonzero(np.isin(self.stage, PATH_STAGES))

    def nearest(self, delta_mm: float) -> int:
        """Index of the path state whose support displacement is nearest `delta_mm`."""
        path = self.path()
        return int(path[np.argmin(np.abs(self.delta_mm[path] - delta_mm))])

    def place(self, index: int) -> str:
        """Where state `index` is on its path, as a frame says it: its load ("load 3.21 N", "load 0.12 g")
        on a live load's path, else its support displacement ("δ = 1.20 mm")."""
        if self.load is not None:
            return f"load {self.load[index]:.{LOAD_DIGITS}g} {self.load_unit}"
        return f"δ = {self.delta_mm[index]:.2f} mm"

    def snapshot(self, index: int) -> dict[str, Any]:
        """State `index` in snapshots.json's form (for the drawing helpers of `analysis.blocks`)."""
        return {
            "delta_mm": float(self.delta_mm[index]),
            "step": int(self.step[index]),
            "pos_m": self.pos_m[index],
            "rot_rad": self.rot_rad[index],
        }


def read_states(path: Path) -> RunStates | None:
    """The states of the run folder `path`; None for a run written before states were recorded."""
    file = Path(path) / STATES_FILE
    if not file.is_file():
        return None
    try:
        with np.load(file) as data:
            arrays = {key: data[key] for key in STATE_KEYS}
            load: dict[str, Any] = {"load": data["load"], "load_unit": str(data["load_unit"])} if "load" in data else {}
            return RunStates(**arrays, **load)
    except (OSError, ValueError, KeyError, EOFError, zipfile.BadZipFile, zlib.error) as exc:
        raise RunFolderError(
            f"{file} cannot be read ({exc or type(exc).__name__}): it was cut short or changed; run the case again"
        ) from None
