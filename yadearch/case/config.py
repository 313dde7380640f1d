"""The case: everything that defines one run, in the paper's units, typed, validated, TOML round-trip.

User-facing numbers carry their unit in the name (mm, N/mm^3, deg, g/cm^3, MPa, s); `yadearch.units`
converts them to SI in one place. Every field is overridable from TOML or the CLI.
"""

from __future__ import annotations

import dataclasses
import difflib
import math
import tomllib
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Any

import tomli_w

from yadearch.case.fields import accepted_text, range_text
from yadearch.case.materials import MATERIAL_KEY, PRESET_FIELD, fill_from_preset
from yadearch.case.names import check_name
from yadearch.case.sections import (
    RENAMED,
    RETIRED,
    SECTIONS,
    GeometryConfig,
    ImperfectionsConfig,
    InterfaceConfig,
    LoadingConfig,
    LoadsConfig,
    MaterialConfig,
    NumericsConfig,
)
from yadearch.case.shape import refuse_unread_sizes
from yadearch.errors import CaseError

SPELLING_CUTOFF = 0.8  # difflib's similarity from which an unknown parameter is taken for a misspelling
TEXT_ENCODING = "utf-8-sig"  # UTF-8, with or without the byte-order mark some editors (Excel, Notepad) write


DEFAULT_NAME = "custom"  # the name of a case that gives none, and of a preset's arch changed off the paper's


@dataclass
class ArchCase:
    """One run: an arch, its joints, its loading and the numerics that solve it."""

    name: str = DEFAULT_NAME
    geometry: GeometryConfig = field(default_factory=GeometryConfig)
    material: MaterialConfig = field(default_factory=MaterialConfig)
    interface: InterfaceConfig = field(default_factory=InterfaceConfig)
    loading: LoadingConfig = field(default_factory=LoadingConfig)
    numerics: NumericsConfig = field(default_factory=NumericsConfig)
    imperfections: ImperfectionsConfig = field(default_factory=ImperfectionsConfig)
    loads: LoadsConfig = field(default_factory=LoadsConfig)

    @property
    def ks_N_per_mm3(self) -> float:
        return self.interface.kn_N_per_mm3 * self.interface.ks_over_kn

    @property
    def support_speed_mm_per_s(self) -> float:
        """Support speed of the continuous loading and of the du search's moves (mm/s)."""
        return support_speed(
            self.numerics.support_rate_mm_per_s, self.numerics.rate_reference_kn_N_per_mm3, self.interface.kn_N_per_mm3
        )

    def validate(self) -> ArchCase:
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

    def replace(self, **overrides: Any) -> ArchCase:
        """A copy with parameters replaced by bare name, e.g. `replace(kn_N_per_mm3=10)`; a preset changed
        off the paper's arch without a `name` is named DEFAULT_NAME (`case.paper.off_the_paper`)."""
        from yadearch.case.paper import off_the_paper  # paper.py builds on this module

        return off_the_paper(self.with_overrides(overrides), named="name" in overrides)

    def with_overrides(self, overrides: dict[str, Any]) -> ArchCase:
        """A copy with `{"section.key": value}` (or bare unique keys such as `kn_N_per_mm3`) replaced."""
        data = self.to_dict()
        given, changed = set(), set()
        for key, value in overrides.items():
            section, name = _resolve_key(key)
            if section is None:
                data[name] = value
            else:
                if section == "geometry" and data[section][name] != value:
                    changed.add(name)
                data[section][name] = value
                given.add((section, name))
        if (MATERIAL_KEY, PRESET_FIELD) in given:  # a material named here replaces the values not set beside it
            data[MATERIAL_KEY] = fill_from_preset(
                data[MATERIAL_KEY], {name for section, name in given if section == MATERIAL_KEY}
            )
        refuse_unread_sizes(data["geometry"]["shape"], changed)  # a size changed that the shape does not read
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
        name = RENAMED.get((section, name), name)
        _refuse_retired(section, name)
        if section not in SECTIONS or name not in {f.name for f in fields(SECTIONS[section])}:
            raise unknown_parameter(key, (f"{s}.{f.name}" for s, cls in SECTIONS.items() for f in fields(cls)))
        return section, name
    key = next((new for (_, old), new in RENAMED.items() if old == key), key)
    for section, name in RETIRED:
        if name == key:
            _refuse_retired(section, name)
    owners = [s for s, cls in SECTIONS.items() if key in {f.name for f in fields(cls)}]
    if not owners:
        raise unknown_parameter(key, (f.name for cls in SECTIONS.values() for f in fields(cls)))
    return owners[0], key


def unknown_parameter(key: str, names: Iterable[str]) -> CaseError:
    """The error for a parameter `key` the case does not have, naming the closest of `names` where one
    is near (a misspelling)."""
    close = difflib.get_close_matches(key, list(names), n=1, cutoff=SPELLING_CUTOFF)
    hint = f" (did you mean {close[0]!r}?)" if close else ""
    return CaseError(f"unknown parameter {key!r}{hint}; see `yadearch params` for the list")


def parameter_section(key: str) -> str | None:
    """The section of parameter `key` (`section.name` or a bare name unique across sections; None for
    the case's name); CaseError for an unknown or retired one."""
    return _resolve_key(key)[0]


def _refuse_retired(section: str, name: str) -> None:
    """A parameter of a former version set by a user: one line saying what replaced it."""
    if (section, name) in RETIRED:
        raise CaseError(f"{section}.{name} is no longer a parameter: {RETIRED[section, name]}")


def _check_value(qualified: str, f: dataclasses.Field, value: Any) -> None:
    name = qualified.split(".")[-1]
    if "table_columns" in f.metadata:
        _check_table(name, f.metadata["table_columns"], value)
        return
    if "choices" in f.metadata:
        if value not in f.metadata["choices"]:
            raise CaseError(f"{name} must be one of {', '.join(f.metadata['choices'])}, got {value!r}")
        return
    if f.type in ("bool", bool):
        if not isinstance(value, bool):
            raise CaseError(f"{name} must be true or false, got {value!r}")
        return
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        kind = "an integer" if f.type in ("int", int) else "a number"
        accepted = accepted_text(f.metadata)  # a number's range here: choices and tables are checked above
        raise CaseError(f"{name} must be {kind}{' ' + accepted if accepted else ''}, got {value!r}")
    if not math.isfinite(value):
        raise CaseError(f"{name} must be finite, got {value!r}")
    if f.type in ("int", int) and int(value) != value:
        raise CaseError(f"{name} must be an integer, got {value!r}")
    meta = f.metadata
    low, high = meta.get("low"), meta.get("high")
    if low is not None and (value <= low if meta["low_open"] else value < low):
        raise CaseError(f"{name} must be {range_text(meta)}, got {value!r}")
    if high is not None and (value >= high if meta["high_open"] else value > high):
        raise CaseError(f"{name} must be {range_text(meta)}, got {value!r}")


def _check_table(name: str, columns: tuple[str, ...], rows: Any) -> None:
    """A table parameter: a list of rows of finite numbers, one per column."""
    shape = f"a list of [{', '.join(columns)}] rows"
    if not isinstance(rows, list | tuple):
        raise CaseError(f"{name} must be {shape}, got {rows!r:.60}")
    for k, row in enumerate(rows, start=1):
        if (
            not isinstance(row, list | tuple)
            or len(row) != len(columns)
            or any(isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v) for v in row)
        ):
            raise CaseError(f"{name} must be {shape}; row {k} is {row!r:.60}")


def case_from_dict(data: dict[str, Any]) -> ArchCase:
    """Build and validate a case from nested dicts (TOML layout); unknown keys are errors."""
    unknown = set(data) - set(SECTIONS) - {"name"}
    if unknown:
        first = sorted(unknown)[0]
        owners = [section for section, cls in SECTIONS.items() if first in {f.name for f in fields(cls)}]
        if owners:  # a parameter written above every section: say where it goes
            raise CaseError(f"{first} is a parameter of [{owners[0]}], not a section: put it under [{owners[0]}]")
        raise CaseError(f"unknown section(s) {sorted(unknown)}; accepted: {sorted(SECTIONS)}")
    name = data.get("name", DEFAULT_NAME)
    if not isinstance(name, str):
        raise CaseError(f"name must be a plain folder name, got {type(name).__name__} {name!r:.40}")
    check_name(name)
    kwargs: dict[str, Any] = {"name": name}
    for section_name, cls in SECTIONS.items():
        section = data.get(section_name, {})
        if not isinstance(section, dict):
            raise CaseError(
                f"[{section_name}] must be a table of parameters (key = value lines), "
                f"got {type(section).__name__} {section!r:.40}"
            )
        values = current_names(section_name, section)
        if section_name == MATERIAL_KEY:  # a named material gives the values the case does not
            values = fill_from_preset(values, given=set(values))
        names = {f.name for f in fields(cls)}
        bad = sorted(set(values) - names)
        if len(bad) == 1:
            raise unknown_parameter(f"{section_name}.{bad[0]}", (f"{section_name}.{n}" for n in names))
        if bad:  # every one named at once: a file with several typos is mended in one go
            raise CaseError(f"unknown parameters {bad} in [{section_name}]; see `yadearch params` for the list")
        for f in fields(cls):
            if f.name in values and f.type in ("int", int) and isinstance(values[f.name], float):
                if values[f.name].is_integer():
                    values[f.name] = int(values[f.name])
        kwargs[section_name] = cls(**values)
    return ArchCase(**kwargs).validate()


def current_names(section_name: str, values: Mapping[str, Any]) -> dict[str, Any]:
    """A section's parameters with former names (`RENAMED`) replaced by today's; both at once is an error."""
    current = {key: value for key, value in values.items() if (section_name, key) not in RETIRED}
    for (section, old), new in RENAMED.items():
        if section == section_name and old in current:
            if new in current:
                raise CaseError(f"[{section}] gives both {old} and {new}, its new name; keep {new}")
            current[new] = current.pop(old)
    return current


def with_current_names(data: Mapping[str, Any]) -> dict[str, Any]:
    """A stored case (nested dicts) with every former parameter name replaced by today's."""
    return {
        key: current_names(key, value) if key in SECTIONS and isinstance(value, Mapping) else value
        for key, value in data.items()
    }


def load_case(path: str | Path) -> ArchCase:
    """Read a case from a TOML file (missing keys take the defaults of the `set2` arch)."""
    path = Path(path)
    try:
        data = tomllib.loads(path.read_text(encoding=TEXT_ENCODING))
    except FileNotFoundError:
        raise CaseError(f"case file {str(path)!r} does not exist") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise CaseError(f"case file {str(path)!r} cannot be read: {exc}") from None
    except tomllib.TOMLDecodeError as exc:
        raise CaseError(f"case file {str(path)!r} is not valid TOML: {exc}") from None
    return case_from_dict(data)


PRESETS: dict[str, dict[str, Any]] = {
    # The reference paper (case/reference.py, PAPER and its source), §3: kn calibrated to each voussoir
    # set; ks = 0.5 kn; all else shared.
    "set1": {"name": "set1", "interface": {"kn_N_per_mm3": 0.25}},
    "set2": {"name": "set2", "interface": {"kn_N_per_mm3": 5.2}},
}


def preset(name: str) -> ArchCase:
    """The paper's arch with the kn of voussoir set 1 or 2."""
    if name not in PRESETS:
        raise CaseError(f"preset must be one of {sorted(PRESETS)}, got {name!r}")
    return case_from_dict(PRESETS[name])
