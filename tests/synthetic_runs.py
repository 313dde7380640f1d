"""Synthetic runs shared by the tests that need no YADE: a joints.csv history with hinges built in
(`BuiltRun`), and complete run folders written with rundir.write_run (`make_run`)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from yadearch.analysis.blocks import block_centroids, case_geometry
from yadearch.analysis.run import Thresholds, analyse_history
from yadearch.results.rundir import STIFFNESS_COLUMN, write_run
from yadearch.results.summary import HingeRef, RunSummary

JOINT_MM = 24.0
FRICTION_DEG = 41.2
MU = math.tan(math.radians(FRICTION_DEG))
SQUEEZE_MM = 0.02  # both edges of every joint overlap this much under the thrust
GROWTH_MRAD_PER_MM = 4.0
RUNAWAY_MM = 2.0  # the collapse record shows the arch this far past du


@dataclass
class BuiltHinge:
    """A hinge built into a synthetic history: weights per interface, pivot side, delta it opens at;
    `preload_mrad` rotates the joint by compression alone from the start (soft joints);
    `fades_mm` (start, end) lets it close again (for migrations)."""

    weights: dict[int, float]
    side: str
    opens_mm: float
    preload_mrad: float = 0.0
    fades_mm: tuple[float, float] | None = None

    def rotation_mrad(self, delta: float) -> float:
        if delta < self.opens_mm:
            grown = 0.3 * delta / self.opens_mm
        else:
            grown = 0.5 + GROWTH_MRAD_PER_MM * (delta - self.opens_mm)
        if self.fades_mm is not None:
            start, end = self.fades_mm
            grown *= float(np.clip((end - delta) / (end - start), 0.0, 1.0))
        return grown


@dataclass
class BuiltRun:
    hinges: list[BuiltHinge]
    n_interfaces: int = 11
    du_mm: float = 30.0
    record_every_mm: float = 0.5
    sliding: dict[int, float] = field(default_factory=dict)  # interface -> |shear| / (mu normal)

    def records(self) -> list[tuple[str, float, float]]:
        """(stage, recorded delta, delta that sets the state): self-weight, the loading's equilibria
        below du (as the runner records them), the collapse record just past du showing the
        run-away arch."""
        loading = np.arange(1, int(self.du_mm / self.record_every_mm)) * self.record_every_mm
        return (
            [("selfweight", 0.0, 0.0)]
            + [("equilibrium", d, d) for d in loading]
            + [("collapse", self.du_mm + 0.05, self.du_mm + RUNAWAY_MM)]
        )

    def joints(self) -> pd.DataFrame:
        rows = []
        for step, (stage, delta, state) in enumerate(self.records()):
            for k in range(1, self.n_interfaces + 1):
                intrados = extrados = -SQUEEZE_MM
                for h in self.hinges:
                    w = h.weights.get(k, 0.0)
                    squeeze, gap = w * h.preload_mrad * 1e-3 * JOINT_MM, w * h.rotation_mrad(state) * 1e-3 * JOINT_MM
                    if h.side == "I":
                        intrados, extrados = intrados - squeeze, extrados + gap
                    else:
                        intrados, extrados = intrados + gap, extrados - squeeze
                normal = 20.0
                ratio = self.sliding.get(k, 0.2) if stage == "collapse" else 0.2
                rows.append(
                    {
                        "stage": stage,
                        "step": 100 * step,
                        "delta_mm": delta,
                        "interface": k,
                        "rotation_rad": (intrados - extrados) / JOINT_MM,
                        "opening_intrados_mm": intrados,
                        "opening_extrados_mm": extrados,
                        "force_position": 0.5,
                        "normal_force_N": normal,
                        "shear_force_N": -ratio * MU * normal,
                    }
                )
        return pd.DataFrame(rows)

    def analyse(self, thresholds: Thresholds = Thresholds(), slip_mm: np.ndarray | None = None):
        return analyse_history(self.joints(), JOINT_MM, FRICTION_DEG, self.du_mm, True, slip_mm, thresholds)


def paper_like_run() -> BuiltRun:
    """I hinge at 4, spread E hinge 6-7-8-9 (peak 7), E at the right support (rotated by compression
    from the start), then E at the left support only at collapse: E-I-E-E, D at the left support."""
    return BuiltRun(
        [
            BuiltHinge({4: 1.0}, "I", opens_mm=5.0),
            BuiltHinge({6: 0.6, 7: 1.0, 8: 0.8, 9: 0.55}, "E", opens_mm=12.0),
            BuiltHinge({11: 1.0}, "E", opens_mm=20.0, preload_mrad=3.0),
            BuiltHinge({1: 1.0}, "E", opens_mm=30.5),
        ]
    )


CASE_TOML = """name = "{name}"

[geometry]
n_voussoirs = {voussoirs}
embrace_deg = 125.0
internal_radius_mm = 300.0
thickness_mm = 24.0
depth_mm = 120.0
support_length_mm = 36.0

[material]
friction_deg = 41.2

[interface]
kn_N_per_mm3 = {kn}

[numerics]
hinge_rotation_mrad = 2.0
"""


def placed(case: dict, delta_mm: float) -> dict:
    """A snapshot with the right support settled by delta and the voussoirs following linearly."""
    pos0 = block_centroids(case_geometry(case))
    share = np.linspace(0.0, 1.0, len(pos0))
    pos = pos0 - np.outer(share, [0.0, delta_mm * 1e-3])
    return {
        "delta_mm": delta_mm,
        "step": 1,
        "pos_m": pos.tolist(),
        "rot_rad": (2e-4 * delta_mm * share).tolist(),
        "hinges": [],
    }


def series_rows(built: BuiltRun) -> list[dict]:
    rows = []
    for stage, deltas in (
        ("selfweight", [0.0, 0.0]),
        ("equilibrium", np.arange(0.5, built.du_mm, 0.5)),
        ("increment", [built.du_mm + 3, built.du_mm - 1, built.du_mm + 1]),
        ("collapse", [built.du_mm + 0.05]),
    ):
        for d in deltas:
            rows.append(
                {
                    "stage": stage,
                    "step": len(rows),
                    "time_s": 0.01 * len(rows),
                    "delta_mm": d,
                    "left_Rx_N": 12.0,
                    "left_Ry_N": 15.8 - 0.02 * d,
                    "right_Rx_N": -12.0,
                    "right_Ry_N": 15.8 + 0.02 * d,
                    "crown_dx_mm": 0.2 * d,
                    "crown_dy_mm": -2 - 0.6 * d,
                    "kinetic_J": 1e-5,
                    "unbalanced": 1e-3,
                    "max_block_speed_mm_per_s": 0.1,
                    STIFFNESS_COLUMN: 50.0 * (1 - d / built.du_mm) if stage == "equilibrium" else None,
                }
            )
    return rows


PAPER_HINGES = [
    {"interface": 1, "side": "E"},
    {"interface": 12, "side": "I"},
    {"interface": 30, "side": "E"},
    {"interface": 56, "side": "E"},
]
COARSE_HINGES = [
    {"interface": 1, "side": "E"},
    {"interface": 4, "side": "I"},
    {"interface": 7, "side": "E"},
    {"interface": 11, "side": "E"},
]


def paper_arch_run() -> BuiltRun:
    """paper_like_run's four hinges on the paper's 55-voussoir arch: 12I, 29-32E (peak 30), 56E, 1E."""
    return BuiltRun(
        [
            BuiltHinge({12: 1.0}, "I", opens_mm=5.0),
            BuiltHinge({29: 0.6, 30: 1.0, 31: 0.8, 32: 0.55}, "E", opens_mm=12.0),
            BuiltHinge({56: 1.0}, "E", opens_mm=20.0, preload_mrad=3.0),
            BuiltHinge({1: 1.0}, "E", opens_mm=30.5),
        ],
        n_interfaces=56,
    )


def make_run(folder: Path, name: str = "set2", kn: float = 5.2, paper_arch: bool = True) -> RunSummary:
    """A complete run folder of the paper's arch (hinges 1E 12I 30E 56E), or of a 10-voussoir one
    (1E 4I 7E 11E); returns its summary."""
    import tomllib

    built = paper_arch_run() if paper_arch else paper_like_run()
    case_toml = CASE_TOML.format(name=name, kn=kn, voussoirs=55 if paper_arch else 10)
    case = tomllib.loads(case_toml)
    summary = RunSummary(
        name=name,
        du_mm=built.du_mm + 0.0123,
        collapsed=True,
        du_bracket_mm=(built.du_mm - 0.02, built.du_mm + 0.05),
        hinges_at_collapse=tuple(HingeRef.of(h) for h in (PAPER_HINGES if paper_arch else COARSE_HINGES)),
        kn_N_per_mm3=kn,
        ks_N_per_mm3=kn / 2,
        steps=12345,
        wall_s=67.8,
        yade_version="2023.02a",
        yadearch_version="0.1.0",
        git_revision="abc123",
    )
    snapshots = {"selfweight": placed(case, 0.0), "collapse": placed(case, built.du_mm + 0.05)}
    write_run(folder, case_toml, series_rows(built), built.joints().to_dict("records"), snapshots, summary)
    return summary
