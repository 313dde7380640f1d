"""summary.json as one type: what a run of either engine found (du, its bracket, the hinges), how it
was loaded and what it cost. Written and read only through `RunSummary` (docs/usage.md, "The run
folder"); the keys are the dataclass's fields, so the file stays flat and readable by hand."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from typing import Any

from yadearch.case.numerics_section import STATIC_ENGINE
from yadearch.case.sections import LoadingConfig
from yadearch.errors import RunFolderError
from yadearch.model import units
from yadearch.model.hinges import paper_labels, same_hinges
from yadearch.model.movement import Movement
from yadearch.solve.path import PathResult
from yadearch.solve.stages import Outcome

DEM, STATIC = "dem", STATIC_ENGINE  # the engines that write run folders
# The static engine's revision, raised with every change of its results: a static run made by another
# one is made again instead of reused (`reuse.outdated`). What each revision changed: CHANGELOG.md.
STATIC_REVISION = 14
TRANSLATION = "translation"
ROTATION = "rotation"
PATH = "path"
# written only when set: engine-specific figures and what older runs lack
OPTIONAL_KEYS = frozenset(
    {
        "support_speed_mm_per_s",
        "imperfections",
        "unused_parameters",
        "increments_check",
        "paper_model_values",
        "relaxations",
        "snaps",
        "descents",
        "descent_retries",
        "collapse_verdict",
        "outcome",
        "du_first_mm",
        "du_first_bracket_mm",
        "collapse_kind",
        "collapse_mode_hinges",
        "mirror_hinges",
        "mirror_mode_hinges",
        "du_components_mm",
        "du_rotation_mrad",
        "iterations",
        "joint_evaluations",
        "solver_wall_s",
        "steps_by_stage",
        "dt_s",
        "steps_per_s",
        "profile",
        "table_rows",
        "engine_revision",
    }
)
RENAMED_KEYS = {"settlement_speed_mm_per_s": "support_speed_mm_per_s"}  # former key: today's, read alike


@dataclass(frozen=True)
class HingeRef:
    """A hinge named by its interface (1 = the left support's) and the face it pivots on (I or E)."""

    interface: int
    side: str

    @property
    def label(self) -> str:
        """The hinge as the tables print it, e.g. "30E"."""
        return f"{self.interface}{self.side}"

    def __str__(self) -> str:
        return self.label

    def to_json(self) -> dict[str, Any]:
        return {"interface": self.interface, "side": self.side}

    @classmethod
    def of(cls, hinge: Any) -> HingeRef:
        """The reference of anything with an interface and a side (a model Hinge, a JSON record)."""
        if isinstance(hinge, dict):
            return cls(int(hinge["interface"]), str(hinge["side"]))
        return cls(int(hinge.interface), str(hinge.side))


@dataclass(frozen=True)
class LoadingInfo:
    """Which support moved, how (a translation's direction, a rotation's pivot and sense, a path's
    rows), and how far the path was allowed to go."""

    moving_support: str
    max_displacement_mm: float
    direction_deg: float | None = None  # a translation's; None for a rotation or a path
    motion: str = TRANSLATION  # runs written before rotations and paths moved it in a straight line
    held_live_load: str = ""  # the live load held on the arch while the support moved ('' without one)
    pivot_mm: tuple[float, float] | None = None  # a rotation's pivot from the right springing's intrados
    rotation_sense: str = ""  # a rotation's, seen from the front
    path_mm_mrad: tuple[tuple[float, ...], ...] | None = None  # a path's rows (dx, dy, rotation)

    def to_json(self) -> dict[str, Any]:
        """summary.json's `loading`: only the fields its motion has (no `held_live_load` without one)."""
        return {k: v for k, v in dataclasses.asdict(self).items() if v not in ("", None)}


@dataclass(kw_only=True)
class RunSummary:
    """One run's summary.json; every field a reader may use, typed, in the file's order. Engine-specific
    figures are None for the other engine and for runs written before they existed."""

    name: str = ""
    started: str = ""
    engine: str = DEM  # runs written before the static engine existed are DEM runs
    kn_N_per_mm3: float | None = None
    ks_N_per_mm3: float | None = None
    kn_effective_N_per_mm3: float | None = None
    support_speed_mm_per_s: float | None = None
    contact_model: str | None = None
    loading: LoadingInfo | None = None
    collapse_criterion: str = ""
    unused_parameters: dict[str, Any] | None = None
    paper_model_values: dict[str, Any] | None = None  # case.paper: the 1:10 model's values a new arch took
    selfweight: dict[str, Any] = field(default_factory=dict)
    imperfections: dict[str, Any] | None = None
    increments: int = 0
    equilibria: int = 0
    last_equilibrium_mm: float | None = None
    hinges_last_equilibrium: list[dict[str, Any]] = field(default_factory=list)
    friction: dict[str, Any] = field(default_factory=dict)
    relaxations: dict[str, Any] | None = None
    snaps: list[Any] | None = None
    # the static engine's path again with the increments halved (numerics.increments_check): its
    # outcome, du and du_first, their relative moves and whether the answer is resolved
    increments_check: dict[str, Any] | None = None
    descents: int | None = None
    descent_retries: int | None = None  # static: descents that found nothing and went on
    collapsed: bool = False
    outcome: str | None = None  # Outcome: collapse, stands, unresolved (None: a run older than it)
    du_mm: float | None
    du_bracket_mm: tuple[float, float] | None = None
    du_first_mm: float | None = None  # the first loss of stability on the path (a fold or a snap)
    du_first_bracket_mm: tuple[float, float] | None = None
    collapse_verdict: str | None = None
    collapse_kind: str | None = None  # solve.collapse_mode.CollapseKind: mechanism, snap-through, fill-held, sliding
    collapse_mode_hinges: list[str] | None = None  # joints that turn in the fold's softest mode
    # where the problem is its own mirror image (solve.mirror): both lists mirrored, as much the answer
    mirror_hinges: list[str] | None = None
    mirror_mode_hinges: list[str] | None = None
    du_components_mm: tuple[float, float] | None = None
    du_rotation_mrad: float | None = None
    hinges_at_collapse: tuple[HingeRef, ...]
    hinges_detail: list[dict[str, Any]] = field(default_factory=list)
    iterations: int | None = None
    steps: int
    joint_evaluations: int | None = None
    solver_wall_s: float | None = None
    steps_by_stage: dict[str, int] | None = None
    dt_s: float | None = None
    wall_s: float
    steps_per_s: float | None = None
    profile: dict[str, Any] | None = None
    yade_version: str | None = None
    yadearch_version: str | None = None
    git_revision: str | None = None
    table_rows: dict[str, int] | None = None
    engine_revision: int | None = None  # the static engine's (solve.static_path.REVISION)

    def collapsed_du_mm(self) -> float:
        """du (mm) of a run that must have collapsed (a reference, a baseline); RunFolderError otherwise."""
        if self.du_mm is None:
            raise RunFolderError(f"run {self.name or '(unnamed)'} did not collapse: it has no du")
        return float(self.du_mm)

    @property
    def path_outcome(self) -> str:
        """How the path ended (Outcome), for runs older than the field too."""
        if self.outcome is not None:
            return self.outcome
        return Outcome.COLLAPSE if self.collapsed else Outcome.STANDS

    @property
    def hinge_labels(self) -> str:
        """The hinges at collapse as "1E 12I 30E 56E" ("" if none)."""
        return " ".join(h.label for h in self.hinges_at_collapse)

    @property
    def hinge_text(self) -> str:
        """The hinges at collapse with their mirror image where that is as much the answer ("" if none)."""
        mirror = f" (or the mirror image {' '.join(self.mirror_hinges)})" if self.mirror_hinges else ""
        return self.hinge_labels + mirror if self.hinge_labels else ""

    @property
    def hinge_rotations_mrad(self) -> dict[HingeRef, float | None]:
        """Each hinge's rotation at the recorded state (mrad), from the detailed hinge records."""
        return {HingeRef.of(h): h.get("rotation_mrad") for h in self.hinges_detail}

    def paper_labels(self, n_interfaces: int) -> dict[HingeRef, str | None]:
        """Each hinge at collapse with the paper's positional letter (A-D; None for a hinge left
        over), `model.hinges.paper_labels` deciding which is which."""
        rotation = self.hinge_rotations_mrad
        moving = self.loading.moving_support if self.loading is not None else "right"
        labels = paper_labels(
            [(h.interface, h.side, rotation.get(h) or 0.0) for h in self.hinges_at_collapse], n_interfaces, moving
        )
        return {h: labels.get((h.interface, h.side)) for h in self.hinges_at_collapse}

    def same_mechanism(self, other: RunSummary) -> bool:
        """Whether both runs ended on the same hinges, each within the other's spread
        (`model.hinges.same_hinges`)."""
        return same_hinges(self._hinge_records(), other._hinge_records())

    def _hinge_records(self) -> list[dict[str, Any]]:
        return self.hinges_detail or [h.to_json() for h in self.hinges_at_collapse]

    @property
    def cost(self) -> str:
        """What the run cost in the engine's own unit: "N steps" or "static engine, N iterations"."""
        return f"static engine, {self.iterations} iterations" if self.engine == STATIC else f"{self.steps} steps"

    def to_json(self) -> dict[str, Any]:
        """The summary.json object: every field in order, engine-specific ones only when set."""
        out: dict[str, Any] = {}
        for f in dataclasses.fields(self):
            value = getattr(self, f.name)
            if value is None and f.name in OPTIONAL_KEYS:
                continue
            if f.name == "hinges_at_collapse":
                value = [h.to_json() for h in value]
            elif isinstance(value, LoadingInfo):
                value = value.to_json()
            elif isinstance(value, tuple):
                value = list(value)
            out[f.name] = value
        return out

    @classmethod
    def from_json(cls, data: dict[str, Any]) -> RunSummary:
        """A summary.json object read back (unknown keys, such as the completeness marker, ignored;
        runs written before a key existed get its default)."""
        known = {f.name for f in dataclasses.fields(cls)}
        data = {RENAMED_KEYS.get(key, key): value for key, value in data.items()}
        values = {key: value for key, value in data.items() if key in known}
        values["hinges_at_collapse"] = tuple(HingeRef.of(h) for h in data.get("hinges_at_collapse") or [])
        if isinstance(data.get("loading"), dict):
            values["loading"] = LoadingInfo(**data["loading"])
        for key in ("du_bracket_mm", "du_components_mm", "du_first_bracket_mm"):
            if data.get(key) is not None:
                values[key] = tuple(data[key])
        return cls(**values)


def collapse_fields(
    path: PathResult, movement: Movement, first_loss: tuple[float, float] | None = None
) -> dict[str, Any]:
    """A followed path's outcome as RunSummary fields: du, its bracket and verdict, its components,
    the first loss of stability (`first_loss`, a bracket in m: the first fold or snap; du's own
    bracket where the path lost stability only at its end), or only the last stable state if the arch
    stood to the end or the solver did not resolve it."""
    lower = units.to_mm(path.lower)
    fields: dict[str, Any] = {"outcome": path.outcome, "last_equilibrium_mm": lower}
    if first_loss is not None:
        fields["du_first_mm"] = units.to_mm(0.5 * (first_loss[0] + first_loss[1]))
        fields["du_first_bracket_mm"] = (units.to_mm(first_loss[0]), units.to_mm(first_loss[1]))
    if path.unresolved:
        return {**fields, "collapsed": False, "du_mm": None, "collapse_verdict": path.upper_verdict}
    if not path.collapsed:
        return {**fields, "collapsed": False, "du_mm": None}
    if first_loss is None:
        fields["du_first_mm"] = units.to_mm(path.du)
        fields["du_first_bracket_mm"] = (lower, units.to_mm(path.upper))
    dx, dy = movement.components(path.du)
    return {
        **fields,
        "collapsed": True,
        "du_mm": units.to_mm(path.du),
        "du_bracket_mm": (lower, units.to_mm(path.upper)),
        "collapse_verdict": path.upper_verdict,
        "du_components_mm": (units.to_mm(dx), units.to_mm(dy)),
        "du_rotation_mrad": 1e3 * movement.rotation(path.du),
    }


def loading_info(loading: LoadingConfig, max_displacement_mm: float, held: str = "") -> LoadingInfo:
    """The case's loading as the summary records it (`held`: the live load held, in words)."""
    motion = loading.support_motion
    rotation = motion == ROTATION
    return LoadingInfo(
        moving_support=loading.moving_support,
        motion=motion,
        direction_deg=loading.support_direction_deg if motion == TRANSLATION else None,
        max_displacement_mm=max_displacement_mm,
        held_live_load=held,
        pivot_mm=(loading.rotation_pivot_dx_mm, loading.rotation_pivot_dy_mm) if rotation else None,
        rotation_sense=loading.rotation_sense if rotation else "",
        path_mm_mrad=tuple(tuple(map(float, row)) for row in loading.path_mm_mrad) if motion == PATH else None,
    )
