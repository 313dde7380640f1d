"""The case: everything that defines one run, in the paper's units, typed, validated, TOML round-trip.

User-facing numbers carry their unit in the name (mm, N/mm^3, deg, g/cm^3, MPa, s); `yadearch.units`
converts them to SI in one place. Every field is overridable from TOML or the CLI.
"""

from __future__ import annotations

import dataclasses
import math
import tomllib
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Any

import tomli_w

from yadearch.errors import CaseError


def _num(low: float | None = None, high: float | None = None, *, low_open: bool = False,
         high_open: bool = False, doc: str = "") -> dict[str, Any]:
    """Field metadata: the accepted range of a number and a one-line description."""
    return {"low": low, "high": high, "low_open": low_open, "high_open": high_open, "doc": doc}


@dataclass
class GeometryConfig:
    """Segmental arch of trapezoidal voussoirs on two rigid support blocks."""

    n_voussoirs: int = field(default=55, metadata=_num(2, 1000, doc="number of voussoirs"))
    embrace_deg: float = field(default=125.0, metadata=_num(0, 180, low_open=True,
                                                             doc="angle of embrace (deg)"))
    internal_radius_mm: float = field(default=300.0, metadata=_num(0, low_open=True,
                                                                   doc="intrados radius (mm)"))
    thickness_mm: float = field(default=24.0, metadata=_num(0, low_open=True,
                                                            doc="radial thickness (mm)"))
    depth_mm: float = field(default=120.0, metadata=_num(0, low_open=True,
                                                         doc="out-of-plane depth (mm)"))
    support_length_mm: float = field(default=36.0, metadata=_num(0, low_open=True,
                                     doc="extent of each support block beyond its springing face (mm)"))


@dataclass
class MaterialConfig:
    """Block material (paper §2): density, joint friction, and the blocks' own elasticity."""

    density_g_per_cm3: float = field(default=1.64, metadata=_num(0, low_open=True,
                                                                 doc="block density (g/cm^3)"))
    friction_deg: float = field(default=41.2, metadata=_num(0, 90, high_open=True,
                                                            doc="joint friction angle (deg)"))
    young_MPa: float = field(default=941.0, metadata=_num(0, low_open=True,
                             doc="block Young's modulus (MPa); used only if block_elasticity"))
    block_elasticity: bool = field(default=False, metadata={"doc": "fold the block's axial "
                                   "stiffness young/width in series into kn (off: rigid blocks)"})


@dataclass
class InterfaceConfig:
    """Dry-joint interface: no-tension Winkler normal stiffness kn and shear stiffness ks = ratio*kn."""

    kn_N_per_mm3: float = field(default=5.2, metadata=_num(0, low_open=True,
                                doc="interface normal stiffness (N/mm^3)"))
    ks_over_kn: float = field(default=0.5, metadata=_num(0, low_open=True,
                              doc="shear-to-normal stiffness ratio (paper: 0.5)"))


@dataclass
class LoadingConfig:
    """Self-weight, then a monotonic displacement of the right support."""

    gravity_m_per_s2: float = field(default=9.81, metadata=_num(0, low_open=True,
                                    doc="gravitational acceleration (m/s^2)"))
    settlement_direction_deg: float = field(default=-90.0, metadata=_num(-180, 180,
                                            doc="direction of the support motion from +x (deg); "
                                                "-90 = vertical settlement"))
    max_settlement_mm: float = field(default=150.0, metadata=_num(0, low_open=True,
                                     doc="stop without collapse beyond this support displacement (mm)"))


@dataclass
class NumericsConfig:
    """Numerical settings. None of them is physics: du must not depend on them (scripts/convergence.py)."""

    settlement_rate_mm_per_s: float = field(default=80.0, metadata=_num(0, low_open=True,
                                            doc="support speed during continuous loading (mm/s)"))
    rate_reference_kn_N_per_mm3: float = field(default=0.0, metadata={**_num(
        0, doc="joints stiffer than this (N/mm^3) load more slowly: the support speed is "
        "settlement_rate x sqrt(this / kn); 0 = no scaling (the default: with loading by "
        "equilibrium increments, kn 100 gives du 108.21 mm unscaled and 108.84 mm at 10, the same "
        "hinges, in 13 % fewer steps)"), "predates": 0.0})
    support_acceleration_mm_per_s2: float = field(default=640.0, metadata={**_num(
        0, doc="acceleration and braking of the support at the start and end of each move (mm/s^2); "
        "0 = instantaneous. The same at any kn: it sets the inertial load of the moving arch (640 = "
        "0.065 g)"), "predates": 0.0})
    damping: float = field(default=0.2, metadata=_num(0, 1, high_open=True,
                           doc="YADE local (non-viscous) damping coefficient"))
    hold_damping: float = field(default=0.2, metadata=_num(0, 1, high_open=True,
                                doc="YADE local damping during the equilibrium holds that decide du; "
                                "fixed apart from `damping`, because it decides how fast a creeping "
                                "near-critical arch moves and so the hold's verdict"))
    timestep_safety: float = field(default=0.6, metadata=_num(0, 1, low_open=True,
                                   doc="time step as a fraction of the critical step of a joint"))
    threads: int = field(default=1, metadata=_num(1, 256, doc="OpenMP threads of the YADE process "
                         "(they speed up CGAL contacts, x1.8 with 2, not joint elements, x0.15-0.93 "
                         "with 2; runs are bit-reproducible with 1 only)"))
    contact_model: str = field(default="joint", metadata={
        "choices": ("joint", "cgal"), "predates": "cgal",
        "doc": "how the dry joints are computed: 'joint' = zero-thickness joint elements integrated "
        "exactly in numpy (33x the steps/s), 'cgal' = YADE's polyhedra intersection and volumetric "
        "law; the same Winkler law either way"})
    equilibrium_tolerance: float = field(default=1e-3, metadata=_num(0, 1, low_open=True,
                                         doc="YADE unbalanced force (mean resultant / mean contact force) below which the arch is in equilibrium"))
    gravity_ramp_periods: float = field(default=200.0, metadata=_num(0, doc="gravity grows from 0 to "
                                        "full over this many periods of a voussoir vibrating on its "
                                        "joints (pi x critical time step), equally gentle at any kn; a "
                                        "sudden load overshoots"))
    selfweight_max_s: float = field(default=2.0, metadata=_num(0, low_open=True,
                                    doc="simulated time allowed for the self-weight stage (s)"))
    hold_max_s: float = field(default=2.0, metadata=_num(0, low_open=True,
                              doc="simulated time allowed to find equilibrium at a fixed support (s); "
                              "a near-critical arch can creep for longer than 0.5 s before it settles "
                              "(kn 1.778: no equilibrium from 43 mm with 0.5 s, equilibrium to 72.36 "
                              "mm with 2 s)"))
    hold_min_s: float = field(default=0.1, metadata=_num(0, doc="simulated time a hold lasts at least "
                                                          "before it may end in equilibrium (s)"))
    still_speed_mm_per_s: float = field(default=0.5, metadata=_num(0, low_open=True,
                                        doc="blocks slower than this are at rest (mm/s)"))
    settle_speed_mm_per_s: float = field(default=0.01, metadata={**_num(
        0, low_open=True, doc="before du is bracketed, its lower state relaxes until every block is "
        "slower than this (mm/s): a state accepted while still creeping fails every move near "
        "collapse"), "predates": 1e9})
    runaway_mm: float = field(default=1.0, metadata=_num(0, low_open=True,
                              doc="block displacement at a fixed support that means no equilibrium (mm)"))
    first_increment_mm: float = field(default=2.0, metadata={**_num(
        0, low_open=True, doc="support displacement of the first loading increment (mm); each "
        "increment ends in a relaxation to equilibrium"), "predates": 0.0})
    max_increment_mm: float = field(default=5.0, metadata=_num(0, low_open=True,
                                    doc="largest loading increment (mm), reached while the arch "
                                    "follows the support"))
    increment_growth: float = field(default=1.5, metadata=_num(1, doc="factor on the increment after "
                                    "one that ended in equilibrium"))
    du_tolerance_mm: float = field(default=0.1, metadata=_num(0, low_open=True,
                                   doc="width of the bracket that locates du (mm)"))
    hinge_rotation_mrad: float = field(default=2.0, metadata=_num(0, low_open=True,
                                       doc="relative joint rotation that counts as a hinge (mrad)"))
    series_every_steps: int = field(default=200, metadata=_num(1, doc="steps between time-series rows"))
    progress_every_s: float = field(default=10.0, metadata=_num(0, low_open=True,
                                    doc="wall seconds between progress lines"))


SECTIONS: dict[str, type] = {
    "geometry": GeometryConfig,
    "material": MaterialConfig,
    "interface": InterfaceConfig,
    "loading": LoadingConfig,
    "numerics": NumericsConfig,
}


@dataclass
class ArchCase:
    """One run: an arch, its joints, its loading and the numerics that solve it."""

    name: str = "custom"
    geometry: GeometryConfig = field(default_factory=GeometryConfig)
    material: MaterialConfig = field(default_factory=MaterialConfig)
    interface: InterfaceConfig = field(default_factory=InterfaceConfig)
    loading: LoadingConfig = field(default_factory=LoadingConfig)
    numerics: NumericsConfig = field(default_factory=NumericsConfig)

    @property
    def ks_N_per_mm3(self) -> float:
        return self.interface.kn_N_per_mm3 * self.interface.ks_over_kn

    @property
    def settlement_speed_mm_per_s(self) -> float:
        """Support speed of the continuous loading and of the du search's moves (mm/s)."""
        return support_speed(self.numerics.settlement_rate_mm_per_s,
                             self.numerics.rate_reference_kn_N_per_mm3, self.interface.kn_N_per_mm3)

    def validate(self) -> "ArchCase":
        """Check every number against its accepted range; raise CaseError naming the first bad one."""
        for section_name in SECTIONS:
            section = getattr(self, section_name)
            for f in fields(section):
                _check_value(f"{section_name}.{f.name}", f, getattr(section, f.name))
        return self

    def to_dict(self) -> dict[str, Any]:
        return dataclasses.asdict(self)

    def to_toml(self) -> str:
        return tomli_w.dumps(self.to_dict())

    def with_overrides(self, overrides: dict[str, Any]) -> "ArchCase":
        """A copy with `{"section.key": value}` (or bare unique keys such as `kn_N_per_mm3`) replaced."""
        data = self.to_dict()
        for key, value in overrides.items():
            section, name = _resolve_key(key)
            if section is None:
                data[name] = value
            else:
                data[section][name] = value
        return case_from_dict(data)


def support_speed(rate: float, reference_kn: float, kn: float) -> float:
    """Support speed (mm/s): `rate`, slowed by sqrt(reference_kn / kn) for joints stiffer than
    `reference_kn` (0 = no scaling)."""
    return rate * math.sqrt(reference_kn / kn) if 0 < reference_kn < kn else rate


def _resolve_key(key: str) -> tuple[str | None, str]:
    """Map `section.key` or a bare key unique across sections to (section, key)."""
    if key == "name":
        return None, key
    if "." in key:
        section, name = key.split(".", 1)
        if section not in SECTIONS or name not in {f.name for f in fields(SECTIONS[section])}:
            raise CaseError(f"unknown parameter {key!r}")
        return section, name
    owners = [s for s, cls in SECTIONS.items() if key in {f.name for f in fields(cls)}]
    if not owners:
        raise CaseError(f"unknown parameter {key!r}; see `yadearch params` for the list")
    return owners[0], key


def _check_value(qualified: str, f: dataclasses.Field, value: Any) -> None:
    name = qualified.split(".")[-1]
    if "choices" in f.metadata:
        if value not in f.metadata["choices"]:
            raise CaseError(f"{name} must be one of {', '.join(f.metadata['choices'])}, got {value!r}")
        return
    if f.type in ("bool", bool):
        if not isinstance(value, bool):
            raise CaseError(f"{name} must be true or false, got {value!r}")
        return
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise CaseError(f"{name} must be a number, got {value!r}")
    if f.type in ("int", int) and int(value) != value:
        raise CaseError(f"{name} must be an integer, got {value!r}")
    if not math.isfinite(value):
        raise CaseError(f"{name} must be finite, got {value!r}")
    meta = f.metadata
    low, high = meta.get("low"), meta.get("high")
    if low is not None and (value <= low if meta["low_open"] else value < low):
        raise CaseError(f"{name} must be {_range_text(meta)}, got {value!r}")
    if high is not None and (value >= high if meta["high_open"] else value > high):
        raise CaseError(f"{name} must be {_range_text(meta)}, got {value!r}")


def _range_text(meta: dict[str, Any]) -> str:
    low, high = meta.get("low"), meta.get("high")
    if high is None:
        return f"{'>' if meta['low_open'] else '>='} {low:g}"
    if low is None:
        return f"{'<' if meta['high_open'] else '<='} {high:g}"
    left = "(" if meta["low_open"] else "["
    right = ")" if meta["high_open"] else "]"
    return f"in {left}{low:g}, {high:g}{right}"


def case_from_dict(data: dict[str, Any]) -> ArchCase:
    """Build and validate a case from nested dicts (TOML layout); unknown keys are errors."""
    unknown = set(data) - set(SECTIONS) - {"name"}
    if unknown:
        raise CaseError(f"unknown section(s) {sorted(unknown)}; accepted: {sorted(SECTIONS)}")
    kwargs: dict[str, Any] = {"name": str(data.get("name", "custom"))}
    for section_name, cls in SECTIONS.items():
        values = dict(data.get(section_name, {}))
        names = {f.name for f in fields(cls)}
        bad = set(values) - names
        if bad:
            raise CaseError(f"unknown parameter(s) {sorted(bad)} in [{section_name}]")
        for f in fields(cls):
            if f.name in values and f.type in ("int", int) and isinstance(values[f.name], float):
                if values[f.name].is_integer():
                    values[f.name] = int(values[f.name])
        kwargs[section_name] = cls(**values)
    return ArchCase(**kwargs).validate()


def as_ran(data: dict[str, Any]) -> dict[str, Any]:
    """What a stored case.toml (`data`) ran with, comparable across versions: a parameter the run
    predates takes the value that reproduces the behaviour it had ("predates" in its metadata, else
    its default), and the support speed replaces the parameters it derives from, so that a run
    whose speed they do not change stays comparable."""
    filled: dict[str, Any] = {"name": data.get("name", "custom")}
    for section_name, cls in SECTIONS.items():
        stored, defaults = data.get(section_name, {}), cls()
        filled[section_name] = {
            f.name: stored.get(f.name, f.metadata.get("predates", getattr(defaults, f.name)))
            for f in fields(cls)}
    numerics = filled["numerics"]
    numerics["settlement_speed_mm_per_s"] = support_speed(
        numerics["settlement_rate_mm_per_s"], numerics["rate_reference_kn_N_per_mm3"],
        filled["interface"]["kn_N_per_mm3"])
    del numerics["settlement_rate_mm_per_s"], numerics["rate_reference_kn_N_per_mm3"]
    return filled


def load_case(path: str | Path) -> ArchCase:
    """Read a case from a TOML file (missing keys take the defaults of the `set2` arch)."""
    path = Path(path)
    try:
        data = tomllib.loads(path.read_text())
    except FileNotFoundError:
        raise CaseError(f"case file {str(path)!r} does not exist") from None
    except tomllib.TOMLDecodeError as exc:
        raise CaseError(f"case file {str(path)!r} is not valid TOML: {exc}") from None
    return case_from_dict(data)


PRESETS: dict[str, dict[str, Any]] = {
    # Paper §3: kn calibrated to each voussoir set; ks = 0.5 kn; all else shared.
    "set1": {"name": "set1", "interface": {"kn_N_per_mm3": 0.25}},
    "set2": {"name": "set2", "interface": {"kn_N_per_mm3": 5.2}},
}


def preset(name: str) -> ArchCase:
    """The paper's arch with the kn of voussoir set 1 or 2."""
    if name not in PRESETS:
        raise CaseError(f"preset must be one of {sorted(PRESETS)}, got {name!r}")
    return case_from_dict(PRESETS[name])


def parameter_docs() -> list[tuple[str, str, str]]:
    """(qualified name, default, description) of every parameter, for `yadearch params`."""
    rows = []
    for section_name, cls in SECTIONS.items():
        for f in fields(cls):
            rows.append((f"{section_name}.{f.name}", repr(f.default), f.metadata.get("doc", "")))
    return rows
