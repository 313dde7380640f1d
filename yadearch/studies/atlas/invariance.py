"""Whether the atlas's answers are facts of the arches (issue 41, docs/atlas.md): every arch of the
atlas at the paper's set 2 stiffness and at a stiff one, on the static engine, with each numerical
setting halved and doubled (the increments, the bracket, the runaway bound and the snap floor); the
largest move of du and du_first from the default, its setting, and the outcomes that change; and the
increments refined further (x0.25, x0.125), to tell a default that has not converged from an answer
that hangs on the path's branch."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.markdown import markdown_table
from yadearch.model.hinges import HINGE_CHANGES, hinge_change
from yadearch.studies.atlas.grid import geometries
from yadearch.studies.campaigns.grid import RUN_COLUMN

INVARIANCE_KNS_N_PER_MM3 = (5.2, 100.0)  # set 2's joints and stiff ones (the stiffest take 10x as long)
FACTORS = (0.5, 2.0)  # each setting halved and doubled
SETTINGS = {  # a setting's name in the table: the numerics it scales together
    "increments": ("first_increment_mm", "max_increment_mm"),
    "bracket": ("du_tolerance_mm", "du_tolerance_ratio"),
    "runaway": ("runaway_thickness_ratio",),
    "snap_floor": ("snap_thickness_ratio",),
}
REFINED = (0.25, 0.125)  # the increments refined further: where does the answer go as they shrink?
TOLERANCE = 0.01  # the standard: a result that moves by more than 1 % is not a result yet
BASE = "base"
INVARIANCE_COMMAND = ".venv/bin/python scripts/atlas.py --invariance"
KIND = "collapse_kind"  # the collapse's kind (four-hinge mechanism, snap-through, ...) where the results have it
HINGES = "hinges"  # the hinges at collapse ("1E 12I 28E 56E") where the results have them ...
VOUSSOIRS = "n_voussoirs"  # ... and the voussoir count, which numbers the mirror image's joints


def variants(base: ArchCase) -> dict[str, dict[str, float]]:
    """Each variant's name and its numerics overrides: the default, then every setting x FACTORS."""
    chosen: dict[str, dict[str, float]] = {BASE: {}}
    for setting, keys in SETTINGS.items():
        for factor in FACTORS:
            chosen[f"{setting}_x{factor:g}"] = {key: getattr(base.numerics, key) * factor for key in keys}
    for factor in REFINED:
        chosen[refined(factor)] = {key: getattr(base.numerics, key) * factor for key in SETTINGS["increments"]}
    return chosen


def refined(factor: float) -> str:
    """The name of the variant with the increments x `factor` (one of REFINED)."""
    return f"increments_x{factor:g}"


def invariance_rows(base: ArchCase) -> list[dict[str, Any]]:
    """The campaign: every atlas arch at each INVARIANCE_KNS stiffness with every variant."""
    return [
        {**row, RUN_COLUMN: f"{row[RUN_COLUMN]}-{name}", **overrides}
        for geometry in geometries()
        for kn in INVARIANCE_KNS_N_PER_MM3
        for row in (geometry.row(kn),)
        for name, overrides in variants(base).items()
    ]


def relative_move(value: float, reference: float) -> float:
    """|value - reference| / reference; NaN where either is missing or the reference is 0."""
    if math.isnan(value) or math.isnan(reference) or reference == 0.0:
        return math.nan
    return abs(value - reference) / reference


def invariance_table(results: pd.DataFrame) -> pd.DataFrame:
    """One row an arch and stiffness: its default outcome, du and du_first, the largest relative move
    of each over the variants and the variant that makes it, and the variants whose outcome differs."""
    split = results[RUN_COLUMN].str.rsplit("-", n=1, expand=True)
    runs = results.assign(case=split[0], variant=split[1])
    rows = []
    for case, group in runs.groupby("case", sort=False):
        base = group[group["variant"] == BASE].iloc[0]
        others = group[~group["variant"].isin([BASE, *map(refined, REFINED)])]
        row: dict[str, Any] = {
            "case": case,
            "kn_N_per_mm3": base["kn_N_per_mm3"],
            "outcome": base["outcome"],
            "du_mm": base["du_mm"],
            "du_first_mm": base["du_first_mm"],
        }
        for column in ("du_mm", "du_first_mm"):
            moves = {v: relative_move(x, base[column]) for v, x in zip(others["variant"], others[column])}
            finite = {v: m for v, m in moves.items() if not math.isnan(m)}
            worst = max(finite, key=lambda variant: finite[variant]) if finite else ""
            row[f"{column}_spread"] = finite.get(worst, math.nan)
            row[f"{column}_by"] = worst
        row["outcome_changed_by"] = " ".join(others.loc[others["outcome"] != base["outcome"], "variant"])
        if KIND in group:
            row["kind_changed_by"] = _kind_changed_by(others, base)
        if HINGES in group and VOUSSOIRS in group:
            row["hinges_changed_by"] = _hinges_changed_by(others, base)
        row.update(_refinement(group, base))
        refinements = group[group["variant"].isin(list(map(refined, REFINED)))]
        row["outcome_refined_by"] = " ".join(refinements.loc[refinements["outcome"] != base["outcome"], "variant"])
        rows.append(row)
    return pd.DataFrame(rows)


def _kind_changed_by(others: pd.DataFrame, base: pd.Series) -> str:
    """The variants that collapse too, as a collapse of another kind than the default's ("" where the
    default does not collapse)."""
    if base["outcome"] != "collapse":
        return ""
    collapsed = others[others["outcome"] == "collapse"]
    return " ".join(collapsed.loc[collapsed[KIND].fillna("") != (base[KIND] or ""), "variant"])


def _hinges_changed_by(others: pd.DataFrame, base: pd.Series) -> str:
    """The variants that collapse on other hinges than the default's, each with how they differ
    ("bracket_x0.5 (the mirror image)"; `model.hinges.hinge_change`); "" where the default stands."""
    if base["outcome"] != "collapse":
        return ""
    last_interface = int(base[VOUSSOIRS]) + 1
    collapsed = others[others["outcome"] == "collapse"]
    changes = {
        variant: hinge_change(str(base[HINGES]), str(hinges), last_interface)
        for variant, hinges in zip(collapsed["variant"], collapsed[HINGES].fillna(""))
    }
    return " ".join(f"{variant} ({change})" for variant, change in changes.items() if change != HINGE_CHANGES[0])


def held_within(arches: pd.DataFrame, spread: str) -> int:
    """How many of `arches` keep their answer within TOLERANCE under every variant (`spread`, the column
    of its largest move; none measured counts as held)."""
    return int((arches[spread].fillna(0.0) <= TOLERANCE).sum())


def _refinement(group: pd.DataFrame, base: pd.Series) -> dict[str, float]:
    """du and du_first with the increments refined (NaN where that variant was not run or does not
    collapse), and the default's relative distance from the finest."""
    row: dict[str, float] = {}
    by_variant = group.set_index("variant")
    for column in ("du_mm", "du_first_mm"):
        for factor in REFINED:
            name = refined(factor)
            collapsed = name in by_variant.index and by_variant.loc[name, "outcome"] == "collapse"
            row[f"{column}_x{factor:g}"] = float(by_variant.loc[name, column]) if collapsed else math.nan
        row[f"{column}_from_finest"] = relative_move(base[column], row[f"{column}_x{min(REFINED):g}"])
    return row


def invariance_markdown(table: pd.DataFrame, command: str = INVARIANCE_COMMAND, comparison: Sequence[str] = ()) -> str:
    """invariance.md: how many arches keep du and du_first within 1 % under every variant, and each
    exception with the variant that moves it; the study made by `command`, and for one made with another
    default its `comparison` with the default's study (`floor_comparison`, `bracket_comparison`)."""
    collapsed = table[table["outcome"] == "collapse"]
    held = {column: held_within(collapsed, f"{column}_spread") for column in ("du_mm", "du_first_mm")}
    changed = table[table["outcome_changed_by"].fillna("") != ""]
    lines = [
        "# The atlas's answers against the numerics (static engine)",
        "",
        f"Regenerate with `{command}` (docs/atlas.md). Every arch of "
        f"the atlas at kn {', '.join(f'{k:g}' for k in INVARIANCE_KNS_N_PER_MM3)} N/mm³ with each setting "
        f"halved and doubled ({', '.join(SETTINGS)}): {len(table)} arches, {len(collapsed)} collapse by "
        "default.",
        "",
        f"- du within {TOLERANCE * 100:g} % under every variant: {held['du_mm']} of {len(collapsed)}.",
        f"- du_first within {TOLERANCE * 100:g} %: {held['du_first_mm']} of {len(collapsed)}.",
        f"- outcome changed by a variant: {len(changed)} arches.",
        *_kind_lines(collapsed),
        *_hinge_lines(collapsed),
        "",
    ]
    outside = collapsed[
        (collapsed["du_mm_spread"] > TOLERANCE) | (collapsed["du_first_mm_spread"] > TOLERANCE)
    ].sort_values("du_first_mm_spread", ascending=False)
    if not outside.empty:
        lines += ["## Moved by more than 1 %", ""]
        lines += markdown_table(
            ["case", "du (mm)", "du spread", "by", "du_first (mm)", "du_first spread", "by"],
            [
                [
                    r["case"],
                    f"{r['du_mm']:.2f}",
                    f"{r['du_mm_spread']:.2%}",
                    r["du_mm_by"],
                    f"{r['du_first_mm']:.2f}",
                    f"{r['du_first_mm_spread']:.2%}",
                    r["du_first_mm_by"],
                ]
                for _, r in outside.iterrows()
            ],
        )
    lines += _refinement_markdown(collapsed)
    lines += comparison
    if not changed.empty:
        lines += ["", "## Outcome changed", ""]
        lines += markdown_table(
            ["case", "default outcome", "changed by"],
            [[r["case"], r["outcome"], r["outcome_changed_by"]] for _, r in changed.iterrows()],
        )
    return "\n".join(lines) + "\n"


def _kind_lines(collapsed: pd.DataFrame) -> list[str]:
    """How many collapses change their kind under some variant, and under each setting's (none without
    the kinds in the results)."""
    if "kind_changed_by" not in collapsed:
        return []
    changed = collapsed["kind_changed_by"].fillna("")
    by_setting = {
        setting: int(changed.map(lambda names: any(n.startswith(f"{setting}_x") for n in names.split())).sum())
        for setting in SETTINGS
    }
    counts = ", ".join(f"{setting} {count}" for setting, count in by_setting.items())
    return [f"- collapse kind changed by a variant: {int((changed != '').sum())} of {len(collapsed)} ({counts})."]


def _hinge_lines(collapsed: pd.DataFrame) -> list[str]:
    """How many collapses list other hinges under some variant, by their largest change (HINGE_CHANGES:
    a mirror image is a symmetric problem's tie, a joint away the same linkage; none without them)."""
    if "hinges_changed_by" not in collapsed:
        return []
    largest = (
        collapsed["hinges_changed_by"]
        .fillna("")
        .map(lambda text: max((HINGE_CHANGES.index(c) for c in HINGE_CHANGES[1:] if f"({c})" in text), default=0))
    )
    counts = ", ".join(f"{int((largest == i).sum())} {change}" for i, change in enumerate(HINGE_CHANGES) if i)
    return [
        f"- hinges at collapse changed by a variant: {int((largest > 0).sum())} of {len(collapsed)}; at most to "
        f"{counts} (`hinges_changed_by`)."
    ]


def _refinement_markdown(collapsed: pd.DataFrame) -> list[str]:
    """The section on the refined increments: how many defaults are within 1 % of the finest, whether
    the two finest agree (converged), and each default that is not."""
    finest, next_finest = f"x{min(REFINED):g}", f"x{max(REFINED):g}"
    lines = ["", f"## The increments refined ({', '.join(f'x{f:g}' for f in REFINED)})", ""]
    for column, name in (("du_mm", "du"), ("du_first_mm", "du_first")):
        both = collapsed.dropna(subset=[f"{column}_{finest}"])
        near = int((both[f"{column}_from_finest"] <= TOLERANCE).sum())
        settled = int(
            (
                both.apply(lambda r: relative_move(r[f"{column}_{next_finest}"], r[f"{column}_{finest}"]), axis=1)
                <= TOLERANCE
            ).sum()
        )
        lines.append(
            f"- {name}: the default within {TOLERANCE * 100:g} % of the increments {finest} in {near} of "
            f"{len(both)}; {next_finest} and {finest} within {TOLERANCE * 100:g} % of each other in {settled}."
        )
    changed = collapsed[collapsed["outcome_refined_by"].fillna("") != ""]
    names = ", ".join(changed["case"]) or "none"
    lines.append(f"- collapses whose outcome the refined increments change: {len(changed)} ({names}).")
    apart = collapsed[collapsed["du_first_mm_from_finest"] > TOLERANCE].sort_values(
        "du_first_mm_from_finest", ascending=False
    )
    if not apart.empty:
        lines += ["", f"du_first more than {TOLERANCE * 100:g} % from the increments {finest}:", ""]
        lines += markdown_table(
            ["case", "du (mm)", "du_first (mm)", *(f"du_first x{f:g}" for f in REFINED), "default from finest"],
            [
                [
                    r["case"],
                    f"{r['du_mm']:.2f}",
                    f"{r['du_first_mm']:.2f}",
                    *(f"{r[f'du_first_mm_x{f:g}']:.2f}" for f in REFINED),
                    f"{r['du_first_mm_from_finest']:.2%}",
                ]
                for _, r in apart.iterrows()
            ],
        )
    return lines
