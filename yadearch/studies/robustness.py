"""The robustness study: du and the hinges must not move with the numerics.

At each kn the set 2 arch runs with the default numerics ("base") and with each numerical variant
(time step, loading increments, damping, the support's rate, the runaway bound, the equilibrium
tolerance, each halved and doubled where it can be, a gentler start, and the DEM's path read the other
way, at the holds' own states or at the static model's equilibria) and with higher friction.
A numerical variant may move du and du_first by at most `TOLERANCE` of the base and must keep the
mechanism (hinges A-D each within one interface); friction may move du only where the run shows a
joint sliding.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case.config import ArchCase
from yadearch.case.numerics_section import SCENE_PATH_STATES, STATIC_PATH_STATES
from yadearch.errors import CampaignError
from yadearch.results.summary import STATIC
from yadearch.static.records import DEM_ONLY_NUMERICS
from yadearch.studies.campaigns.executors import Pool
from yadearch.studies.campaigns.runner import RESULTS_FILE, run_campaign

KN_VALUES = (0.1, 0.25, 1.0, 5.2, 17.78)  # kn 100 costs 8 min a DEM run: ask for it with kn_values
TOLERANCE = 0.01  # largest relative change of du (and du_first) a numerical variant may cause
HINGE_SHIFT = 1  # interfaces a hinge may move between variants
SLIDING_MM = 0.01  # accumulated joint slip that counts as sliding (mm)
ROBUSTNESS_FILE = "robustness.csv"
SUMMARY_FILE = "robustness.md"
FRICTION_VARIANTS = ("friction_60", "friction_80")

Variant = Callable[[ArchCase], dict[str, Any]]


def _scaled(*names: str, factor: float) -> Variant:
    """A variant that multiplies the numerics `names` by `factor` (rounded to 6 significant digits)."""
    return lambda c: {name: float(f"{factor * getattr(c.numerics, name):.6g}") for name in names}


def _path_read(case: ArchCase, states: str) -> dict[str, Any]:
    """The DEM's path read at `states` (`numerics.support_path_states`): nothing to change where `case`
    reads it so already ('auto' included)."""
    return {} if case.numerics.path_states == states else {"support_path_states": states}


VARIANTS: dict[str, Variant] = {
    "base": lambda c: {},
    "timestep_x0.5": _scaled("timestep_safety", factor=0.5),
    "increment_x0.5": _scaled("first_increment_mm", "max_increment_mm", factor=0.5),
    "increment_x2": _scaled("first_increment_mm", "max_increment_mm", factor=2.0),
    "damping_x0.5": _scaled("damping", "hold_damping", factor=0.5),
    "damping_x2": _scaled("damping", "hold_damping", factor=2.0),
    "rate_x0.5": _scaled("support_rate_mm_per_s", "support_acceleration_mm_per_s2", factor=0.5),
    "rate_x2": _scaled("support_rate_mm_per_s", "support_acceleration_mm_per_s2", factor=2.0),
    "runaway_x0.5": _scaled("runaway_thickness_ratio", factor=0.5),
    "runaway_x2": _scaled("runaway_thickness_ratio", factor=2.0),
    "tolerance_x0.5": _scaled("equilibrium_tolerance", "still_speed_mm_per_s", factor=0.5),
    "tolerance_x2": _scaled("equilibrium_tolerance", "still_speed_mm_per_s", factor=2.0),
    "ramp": lambda c: {
        "support_acceleration_mm_per_s2": 0.25 * c.numerics.support_acceleration_mm_per_s2,
        "first_increment_mm": 0.5 * c.numerics.first_increment_mm,
    },
    # the DEM's path read at the static model's equilibria or at the holds' own states (docs/numerics.md):
    # the one the base case does not read already runs
    "path_states_static": lambda c: _path_read(c, STATIC_PATH_STATES),
    "path_states_scene": lambda c: _path_read(c, SCENE_PATH_STATES),
    "friction_60": lambda c: {"friction_deg": 60.0},
    "friction_80": lambda c: {"friction_deg": 80.0},
}


def study_rows(
    base: ArchCase,
    kn_values: tuple[float, ...] = KN_VALUES,
    variants: tuple[str, ...] = tuple(VARIANTS),
    log: Callable[[str], None] = print,
) -> list[dict[str, Any]]:
    """The campaign rows: one run per kn and variant, named `kn<kn>_<variant>`; the variants that change
    nothing the engine reads are named in `log` and not run (CampaignError if none is left)."""
    unknown = sorted(set(variants) - set(VARIANTS))
    if unknown:
        raise CampaignError(f"variant must be one of {', '.join(VARIANTS)}, got {', '.join(unknown)}")
    chosen = applicable(base, tuple(dict.fromkeys(("base", *variants))))  # every variant is read against base
    dropped = [name for name in variants if name not in chosen]
    if dropped:
        reasons: dict[str, list[str]] = {}
        for name in dropped:
            reasons.setdefault(_unchanged_reason(base, name), []).append(name)
        said = "; ".join(f"variant {', '.join(names)}: {reason}" for reason, names in reasons.items())
        if len(chosen) == 1:
            usable = ", ".join(name for name in applicable(base, tuple(VARIANTS)) if name != "base")
            raise CampaignError(f"{said}; with it choose among {usable}")
        log(f"{said}: not run")
    return [
        {"run": f"kn{kn:g}_{name}", "kn_N_per_mm3": kn, **overrides}
        for kn in kn_values
        for name, overrides in chosen.items()
    ]


def applicable(base: ArchCase, variants: tuple[str, ...]) -> dict[str, dict[str, Any]]:
    """Each variant's overrides as `base`'s engine reads them: for the static engine without the
    DEM-only numerics (time step, damping, the support's acceleration), and a variant left with
    nothing to change dropped, or one that sets what `base` has already (the path states it reads):
    it would be reported as passing a test it never took."""
    chosen = {name: VARIANTS[name](base) for name in variants}
    if base.numerics.engine == STATIC:
        chosen = {name: {k: v for k, v in o.items() if k not in DEM_ONLY_NUMERICS} for name, o in chosen.items()}
    return {name: o for name, o in chosen.items() if name == "base" or (o and base.with_overrides(o) != base)}


def _unchanged_reason(base: ArchCase, name: str) -> str:
    """Why variant `name` changes nothing on `base`, in the words of `study_rows`' line."""
    if base.numerics.engine == STATIC and set(VARIANTS[name](base)) <= set(DEM_ONLY_NUMERICS):
        return "only DEM numerics, which the static engine ignores"
    return "sets only what the case has already"


def run_study(
    base: ArchCase,
    out: Path,
    pool: Pool,
    kn_values: tuple[float, ...] = KN_VALUES,
    variants: tuple[str, ...] = tuple(VARIANTS),
    timeout_s: float | None = None,
    progress: bool = True,
) -> pd.DataFrame:
    """Run (or resume) the study into `out`, then write robustness.csv and robustness.md there."""
    rows = study_rows(base, kn_values, variants, log=print if progress else lambda _: None)
    results = run_campaign(base, rows, out, pool, timeout_s=timeout_s, progress=progress)
    table = robustness_table(results)
    write_csv_atomically(out / ROBUSTNESS_FILE, table)
    write_text_atomically(out / SUMMARY_FILE, summary_markdown(table))
    return table


def robustness_table(results: pd.DataFrame) -> pd.DataFrame:
    """One row per run with the study's columns, each variant compared with its kn's base."""
    table = results.assign(variant=results["run"].str.split("_", n=1).str[1])
    base = table[table["variant"] == "base"].set_index("kn_N_per_mm3")
    rows = []
    for _, row in table.iterrows():
        kn = row["kn_N_per_mm3"]
        ref = base.loc[kn] if kn in base.index else None
        du_base = ref["du_mm"] if ref is not None else math.nan
        first_base = ref.get("du_first_mm", math.nan) if ref is not None else math.nan
        first = row.get("du_first_mm", math.nan)
        rows.append(
            {
                "kn_N_per_mm3": kn,
                "variant": row["variant"],
                "du_mm": row["du_mm"],
                "hinges": row["hinges"],
                "max_slip_mm": row.get("max_slip_mm", math.nan),
                "max_friction_use": row.get("max_friction_use", math.nan),
                "friction_interface": row.get("friction_interface"),
                "steps": row["steps"],
                "wall_s": row["wall_s"],
                "status": row["status"],
                "du_rel_to_base": (row["du_mm"] - du_base) / du_base if du_base else math.nan,
                "du_first_mm": first,
                "du_first_rel_to_base": (first - first_base) / first_base if first_base else math.nan,
                "same_hinges": same_mechanism(row, ref) if ref is not None else None,
            }
        )
    return pd.DataFrame(rows)


def same_mechanism(row: pd.Series, ref: pd.Series, shift: int = HINGE_SHIFT) -> bool:
    """Whether two runs collapse by the same mechanism: the paper's hinges A-D (`hinge_A`...`hinge_D`
    columns, interfaces) each within `shift`, where the runs have them; else the whole hinge lists
    (`same_hinge_set`). The collapse state lists every joint open where a block has run away, so a
    longer runaway bound opens more joints of the same mechanism."""
    letters = [f"hinge_{k}" for k in "ABCD"]
    if all(c in row.index and c in ref.index for c in letters):
        pairs = [(row[c], ref[c]) for c in letters]
        if all(pd.notna(a) and pd.notna(b) for a, b in pairs):
            return all(abs(int(a) - int(b)) <= shift for a, b in pairs)
    return same_hinge_set(row["hinges"], ref["hinges"], shift)


def same_hinge_set(a: str, b: str, shift: int = HINGE_SHIFT) -> bool:
    """Whether two hinge strings ("1E 9I 29E 56E") name as many hinges, on the same sides in the
    same order, each within `shift` interfaces of the other's."""
    if not isinstance(a, str) or not isinstance(b, str):
        return False
    ha, hb = a.split(), b.split()
    return len(ha) == len(hb) and all(
        x[-1] == y[-1] and abs(int(x[:-1]) - int(y[:-1])) <= shift for x, y in zip(ha, hb)
    )


def verdicts(table: pd.DataFrame) -> pd.DataFrame:
    """Per kn: the base du, the largest relative move of du among the numerical variants, whether
    they all kept the hinges, and what friction did (with the base run's largest slip)."""
    rows = []
    for kn, group in table.groupby("kn_N_per_mm3", sort=True):
        numeric = group[~group["variant"].isin(FRICTION_VARIANTS)]
        base = group[group["variant"] == "base"]
        friction = group[group["variant"].isin(FRICTION_VARIANTS)]
        spread = float(numeric["du_rel_to_base"].abs().max())
        first_spread = (
            float(numeric["du_first_rel_to_base"].abs().max()) if "du_first_rel_to_base" in numeric else math.nan
        )
        hinges_kept = bool(numeric["same_hinges"].fillna(False).all())
        done = bool((numeric["status"] == "done").all())
        slid = bool((base["max_slip_mm"] > SLIDING_MM).any())
        friction_move = float(friction["du_rel_to_base"].abs().max()) if len(friction) else math.nan
        friction_ok = slid or not friction_move > TOLERANCE
        tested = len(group) > len(base)  # a study of the base runs alone passes no test
        rows.append(
            {
                "kn_N_per_mm3": kn,
                "base_du_mm": float(base["du_mm"].iloc[0]) if len(base) else math.nan,
                "base_hinges": base["hinges"].iloc[0] if len(base) else "",
                "base_du_first_mm": float(base["du_first_mm"].iloc[0])
                if "du_first_mm" in base and len(base)
                else math.nan,
                "numerics_spread": spread,
                "du_first_spread": first_spread,
                "hinges_kept": hinges_kept,
                "friction_move": friction_move,
                "base_max_slip_mm": float(base["max_slip_mm"].max()),
                "verdict": "NOT TESTED"
                if not tested
                else "PASS"
                if done and spread <= TOLERANCE and not first_spread > TOLERANCE and hinges_kept and friction_ok
                else "FAIL",
            }
        )
    return pd.DataFrame(rows)


def summary_markdown(table: pd.DataFrame) -> str:
    """The study as Markdown: the verdict per kn, then every run."""
    lines = [
        "# Robustness of du to the numerics",
        "",
        f"Target: every numerical variant within {TOLERANCE:.0%} of the base du and du_first (the first "
        "loss of stability), with the same mechanism (hinges A-D) "
        f"(+-{HINGE_SHIFT} interface); friction may move du only where a joint slides "
        f"(> {SLIDING_MM} mm accumulated slip). Regenerate: `yadearch robustness --out "
        "reports/robustness`.",
        "",
        "| kn (N/mm3) | base du (mm) | base du_first (mm) | base hinges | numerics spread: du "
        "| du_first | hinges kept | friction moves du | base max slip (mm) | verdict |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for _, v in verdicts(table).iterrows():
        lines.append(
            f"| {v.kn_N_per_mm3:g} | {v.base_du_mm:.2f} | {v.base_du_first_mm:.2f} | {v.base_hinges} "
            f"| {v.numerics_spread:.2%} | {v.du_first_spread:.2%} "
            f"| {'yes' if v.hinges_kept else 'no'} | {v.friction_move:.2%} "
            f"| {v.base_max_slip_mm:.3g} | {v.verdict} |"
        )
    lines += [
        "",
        "| kn | variant | du (mm) | vs base | du_first (mm) | vs base | hinges | max slip (mm) "
        "| max T/(N tan phi) (interface) | steps | wall (s) |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for _, r in table.iterrows():
        lines.append(
            f"| {r.kn_N_per_mm3:g} | {r.variant} | {r.du_mm:.2f} | {r.du_rel_to_base:+.2%} "
            f"| {r.du_first_mm:.2f} | {r.du_first_rel_to_base:+.2%} | {r.hinges} "
            f"| {r.max_slip_mm:.3g} | {r.max_friction_use:.3f} ({r.friction_interface}) "
            f"| {r.steps} | {r.wall_s:.0f} |"
        )
    return "\n".join(lines) + "\n"


def read_study(out: Path) -> pd.DataFrame:
    """The study's table as written by `run_study` (robustness.csv), or rebuilt from results.csv."""
    path = Path(out) / ROBUSTNESS_FILE
    return pd.read_csv(path) if path.is_file() else robustness_table(pd.read_csv(Path(out) / RESULTS_FILE))
