"""What a rigid-block limit analysis returns: the hinge history, the collapse, and the last admissible
state (contact forces, thrust line, reactions, block placements), JSON-ready."""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from yadearch.atomic import write_text_atomically
from yadearch.case.config import ArchCase
from yadearch.case.reference import references_for
from yadearch.model import units
from yadearch.solve.limit_lp import Statics
from yadearch.solve.rigid import EXTRADOS, INTRADOS, RigidArch


@dataclass(frozen=True)
class HingeRecord:
    """A hinge (1-based interface, pivot side I/E) rotating from `from_mm` to `to_mm` of support
    displacement (None: still rotating at the end). `jump_mm`: the largest block movement at a
    fixed support with which it took over from another hinge (0 if it formed without one)."""

    interface: int
    side: str
    from_mm: float
    to_mm: float | None = None
    jump_mm: float = 0.0

    @property
    def label(self) -> str:
        return f"{self.interface}{self.side}"


@dataclass(frozen=True)
class SnapRecord:
    """A limit point the march survived: at support displacement `at_mm` the three-hinge path lost
    its equilibrium and the hinges re-seated at the fixed support (the weights falling all the way)
    into a new admissible equilibrium, moving no block further than `largest_move_mm`; the hinges
    followed before (`hinges_before`) and after (`hinges_after`), e.g. "2I 41E 56E"."""

    at_mm: float
    largest_move_mm: float
    hinges_before: str
    hinges_after: str


@dataclass(frozen=True)
class InterfaceForce:
    """Contact forces on the right block of one interface (N): corner normal forces, shear along the
    joint (intrados -> extrados), where they act (mm), and the friction used |T| / (tan(phi) N)."""

    interface: int
    n_intrados: float
    n_extrados: float
    shear: float
    normal: tuple[float, float]
    intrados_mm: tuple[float, float]
    extrados_mm: tuple[float, float]
    thrust_mm: tuple[float, float]
    friction_use: float


@dataclass(frozen=True)
class LimitResult:
    """The rigid-block limit of one case and its last admissible state (see `solve.limit`)."""

    name: str
    # the end of the quasi-static path: the last support displacement from which the hinges, moving
    # at the fixed support, re-seat into an admissible equilibrium (None: standing at the largest
    # displacement tried); du_rigid_mm is the same number under its older name
    du_mm: float | None
    # the first limit point: where the three-hinge path first loses its equilibrium by a snap that
    # moves a block further than the snap floor (numerics.snap_thickness_ratio ring thicknesses, as the
    # static engine and the DEM count a snap) or by the collapse; None: none met. du_first_mm <= du_mm
    du_first_mm: float | None
    du_rigid_mm: float | None  # = du_mm, its older name (a compliant march's du too: not the rigid blocks' there)
    collapse_mode: str  # "hinging", "snap" (a hinge snap beyond max_snap_mm), "sliding", or "none"
    hinge_history: tuple[HingeRecord, ...]
    collapse_hinges: tuple[str, ...]  # hinges of the collapse mechanism, left to right, e.g. "9I"
    new_at_collapse: tuple[str, ...]  # its hinges not rotating before: the fourth hinge, usually
    forces: tuple[InterfaceForce, ...]
    reactions_N: dict[str, tuple[float, float]]  # force of each support on the arch (x, y)
    max_friction_use: float
    max_friction_interface: int
    rotation_rad: tuple[float, ...]  # per block (0 = left support) at the last admissible state
    shift_mm: tuple[tuple[float, float], ...]  # per block: X -> R(rotation) X + shift
    support_direction_deg: float
    snaps: tuple[SnapRecord, ...]  # the limit points survived, in order
    runaway_thicknesses: float  # a re-seating moving a block further than this many ring thicknesses runs away
    # for comparing with a DEM run: a snap moving a block further (mm) is the collapse, as the run's
    # runaway distance (None: every snap that re-seats within the runaway bound is survived)
    max_snap_mm: float | None
    snap_collapse_mm: float | None  # the largest block movement of the snap that was the collapse
    snap_floor_mm: float  # a snap moving no block further is no loss of stability (du_first), as in every engine
    step_mm: float
    tolerance_mm: float
    compliant_kn_N_per_mm3: float | None  # the joints fold at this kn's margin (None: rigid)
    compliant_largest_margin_mm: float | None  # the largest fold margin the march met
    n_lp: int
    wall_s: float
    # the mirror image's du (moving support swapped): on an odd number of voussoirs a support that
    # turns or moves vertically meets a tie between the keystone's two joints, which the march
    # breaks toward the left one
    mirror_du_rigid_mm: float | None = None
    mirror_collapse_mode: str | None = None  # the mirror image's collapse_mode, "failed: why", None: not solved
    mirror_collapse_hinges: tuple[str, ...] | None = None  # the mirror image's, in this case's numbering
    # the closed joint beside an open hinge whose thrust came nearest the hinge side's corner at the march's
    # steps (e.g. "40E"), that distance and where: a joint of finite kn shares the hinge within its fold margin,
    # so a small distance says the rigid answer's linkage hangs on it (docs/theory.md)
    closest_edge_joint: str | None = None
    closest_edge_mm: float | None = None
    closest_edge_at_mm: float | None = None
    start_hinges: tuple[str, ...] | None = None  # the linkage named to leave rest on (None: the LP's)
    start_mm: float | None = None  # ... placed this far along it from rest (0: from rest)
    # beside a compliant march, the static engine on the same blocks and joints (the compliant model it
    # estimates): outcome (collapse, stands, unresolved, or "failed: why"), du, du_first and hinges
    static_outcome: str | None = None
    static_du_mm: float | None = None
    static_du_first_mm: float | None = None
    static_hinges: tuple[str, ...] | None = None
    warnings: tuple[str, ...] = ()  # what a reader of this answer must know (a compliant march: `api.limit_notes`)

    def __repr__(self) -> str:
        """The answer in a few lines (a notebook shows it; every field stays an attribute)."""
        hinges = " ".join(self.collapse_hinges)
        first = "" if self.du_first_mm in (None, self.du_mm) else f", du_first {self.du_first_mm:.2f} mm"
        answer = (
            f"stands, hinges at the end {hinges}"
            if self.du_mm is None
            else f"du {self.du_mm:.2f} mm{first}, {self.collapse_mode} on {hinges}"
        )
        kind = "compliant march" if self.compliant_kn_N_per_mm3 is not None else "rigid march"
        lines = [f"LimitResult({self.name}, {kind}: {answer})"]
        if self.static_outcome is not None:
            static = "no du" if self.static_du_mm is None else f"du {self.static_du_mm:.2f} mm"
            lines.append(f"  static engine beside it: {self.static_outcome}, {static}")
        return "\n".join([*lines, *(f"  warning: {w}" for w in self.warnings)])

    @property
    def references(self) -> list[str]:
        """The methods this result stands on: the rigid-block LP and its incremental use for settlements."""
        return references_for(dem=False, limit_analysis=True)

    def to_json(self) -> dict:
        """A JSON-ready dict of every field, and the references."""
        return {**asdict(self), "references": self.references}


def interface_forces(arch: RigidArch, statics: Statics) -> tuple[tuple[InterfaceForce, ...], dict]:
    """Per-interface forces of an equilibrium, and the supports' reactions on the arch (N)."""
    c, forces = statics.contacts, []

    def mm(point: np.ndarray) -> tuple[float, float]:
        return units.to_mm(float(point[0])), units.to_mm(float(point[1]))

    for k in range(arch.n_joints):
        n_i, n_e = (float(v) for v in statics.normal[k])
        total = n_i + n_e
        p_i, p_e = c.point[k, INTRADOS], c.point[k, EXTRADOS]
        thrust = p_i + (n_e / total if total > 0 else 0.5) * (p_e - p_i)
        use = abs(statics.shear[k]) / (arch.tan_phi * total) if total > 0 else 0.0
        forces.append(
            InterfaceForce(
                k + 1,
                n_i,
                n_e,
                float(statics.shear[k]),
                (float(c.normal[k, 0]), float(c.normal[k, 1])),
                mm(p_i),
                mm(p_e),
                mm(thrust),
                float(use),
            )
        )
    resultant = [
        statics.normal[k].sum() * c.normal[k] + statics.shear[k] * c.tangent[k] for k in (0, arch.n_joints - 1)
    ]
    return tuple(forces), {
        "left": tuple(float(v) for v in resultant[0]),
        "right": tuple(float(v) for v in -resultant[1]),
    }


def write_result_json(result: LimitResult, case: ArchCase, path: Path) -> Path:
    """The result and the case it solved, as indented JSON, written atomically."""
    text = json.dumps({**result.to_json(), "case": case.to_dict()}, indent=1) + "\n"
    return write_text_atomically(path, text)
