"""Nothing a user types can crash, hang or write outside `--out` (no YADE: every probe is refused
before a simulation starts): a table of bad inputs through the command line, and property-based
cases and TOML structures that give a valid case or one clean error, never a traceback."""

from __future__ import annotations

import math
import tomllib
from dataclasses import fields

import pytest
from conftest import REPO
from hypothesis import given, settings
from hypothesis import strategies as st

from yadearch.case.config import case_from_dict, parameter_docs
from yadearch.case.plan import plan_run
from yadearch.case.sections import SECTIONS
from yadearch.cli.commands import main
from yadearch.errors import YadearchError

NUMERIC = [
    f"{name}.{f.name}"
    for name, section in SECTIONS.items()
    for f in fields(section)
    if f.type in ("int", "float", int, float)
]
VALID_NEGATIVE = (
    "loading.support_direction_deg",  # -1 deg is a valid direction
    "loading.rotation_pivot_dx_mm",
    "loading.rotation_pivot_dy_mm",  # a pivot anywhere
    "imperfections.face_angle_mrad",
    "imperfections.face_bump_mm",  # signed defects
    "imperfections.voussoir_offset_mm",
    "imperfections.keystone_offset_mm",
    "imperfections.left_support_angle_mrad",
    "imperfections.right_support_angle_mrad",
    "imperfections.voussoir_thickness_mm",
)
BAD_VALUES = ["-1", "nan", "inf", "-inf", "1e300", "'text'", "true"]
DERIVED = [  # inside each value's range, absurd together: refused from the plan, before YADE
    ("support_rate_mm_per_s=1e-9", "max_steps"),
    ("gravity_ramp_periods=1e6", "gravity ramp"),
    ("thickness_mm=400", "internal_radius_mm"),
    ("support_acceleration_mm_per_s2=1e-9", "max_steps"),
    ("hold_max_s=100", "max_steps"),
    ("kn_N_per_mm3=1e5", "max_steps"),
    ("max_steps=10", "max_steps"),
    ("edge_radius_mm=20", "edge_radius_mm"),
    ("keystone_offset_mm=30", "keystone_offset_mm"),
    ("voussoir_length_sd_mm=20", "voussoir_length_sd_mm"),
    ("voussoir_thickness_mm=-15", "voussoir_thickness_mm"),
    ("du_tolerance_mm=1", "du_tolerance_mm"),
    ("first_increment_mm=5", "first_increment_mm"),
]


def probes() -> list[list[str]]:
    """Command lines that must each end in one line and exit code 1 (over 100 of them)."""
    lines = [
        ["run", "--preset", "set2", "--set", f"{q}={v}"]
        for q in NUMERIC
        for v in BAD_VALUES
        if not (v == "-1" and q in VALID_NEGATIVE)
    ]
    lines += [["run", "--preset", "set2", "--set", s] for s, _ in DERIVED]
    lines += [
        ["run", "--kn", "abc"],
        ["run", "--bogus"],
        ["run", "--preset", "set9"],
        ["run", "--preset", "set1", "--case", "x.toml"],
        ["run", "--set", "nokey"],
        ["run", "--set", "no_such_parameter=1"],
        ["run", "--case", "/nonexistent/case.toml"],
        ["run", "--set", "edge_radius_mm=1", "--set", "contact_model=cgal"],
        ["run", "--set", "edge_shape=square"],
        ["run", "--set", "movement=wobble"],
        ["run", "--set", "moving_support=middle"],
        ["limit", "--set", "moving_support=both"],
        [
            "run",
            "--set",
            "support_motion=rotation",
            "--set",
            "rotation_pivot_dx_mm=10.644",
            "--set",
            "rotation_pivot_dy_mm=5.541",
        ],
        ["sweep", "--preset", "set2", "--out", "OUT/s"],
        ["sweep", "--kn", "1:2:cubic:3", "--out", "OUT/s"],
        ["sweep", "--kn", "0:1:log:3", "--out", "OUT/s"],
        ["sweep", "--param", "kn_N_per_mm3", "--out", "OUT/s"],
        ["calibrate", "--preset", "set1", "--target-du", "nan", "--out", "OUT/c.json"],
        ["calibrate", "--preset", "set1", "--target-du", "-5", "--out", "OUT/c.json"],
        ["calibrate", "--preset", "set1", "--target-du", "48", "--kn-min", "5", "--kn-max", "1", "--out", "OUT/c.json"],
        ["report", "OUT/not-a-run", "--out", "OUT/r"],
        ["limit", "--set", "friction_deg=95"],
        ["run", "--preset", "set2", "--engine", "static", "--out", "OUT/" + "x" * 250],
        # campaigns: every run of a grid checked before the first starts (nothing runs)
        ["sweep", "--preset", "set2", "--param", "n_voussoirs=a,b", "--out", "OUT/s"],
        ["montecarlo", "--preset", "set2", "--samples", "2", "--param", "face_bump_mm=a,b", "--out", "OUT/m"],
        ["robustness", "--kn", "abc", "--out", "OUT/r"],
        ["robustness", "--kn", "-1", "--out", "OUT/r"],
        ["sweep", "--preset", "set2", "--kn", "-1:1:lin:3", "--out", "OUT/s"],
        ["sweep", "--preset", "set2", "--kn", "1,inf", "--out", "OUT/s"],
        ["sweep", "--preset", "set2", "--kn", "nan:1:log:3", "--out", "OUT/s"],
        ["sweep", "--preset", "set2", "--kn", "1:2:log:10000000", "--out", "OUT/s"],
        ["montecarlo", "--preset", "set2", "--samples", "2", "--param", "face_bump_sd_mm=-1,0.1", "--out", "OUT/m"],
        ["montecarlo", "--preset", "set2", "--samples", "2", "--seed", "4294967295", "--out", "OUT/m"],
        ["montecarlo", "--preset", "set2", "--samples", "100000000", "--out", "OUT/m"],
        ["sensitivity", "--preset", "set2", "--base-points", "100", "--out", "OUT/s"],
        ["sensitivity", "--preset", "set2", "--factor", "kn_N_per_mm3=1", "--out", "OUT/s"],
        ["sensitivity", "--preset", "set2", "--factor", "nothing=1:2", "--out", "OUT/s"],
        ["sensitivity", "--preset", "set2", "--factor", "friction_deg=40:95", "--out", "OUT/s"],
        ["sensitivity", "--preset", "set2", "--factor", "kn_N_per_mm3=0:5:log", "--out", "OUT/s"],
        ["sensitivity", "--preset", "set2", "--check-runs", "-1", "--out", "OUT/s"],
        # views of a run: no run folder, an unknown format, no --vtk, a run from before states.npz
        ["animate", "OUT/not-a-run"],
        ["animate", f"{REPO}/reports/set1", "--format", "avi"],
        ["animate", f"{REPO}/reports/limit"],
        ["export", f"{REPO}/reports/set2"],
        ["export", "OUT/not-a-run", "--vtk"],
        ["export", f"{REPO}/reports/kn-sweep/kn100", "--vtk"],
    ]
    shapes = [
        ["shape=oval"],
        ["joint_orientation=skew"],
        ["shape=pointed", "pointed_radius_over_span=0.4"],
        ["shape=elliptical", "rise_mm=400"],
        ["shape=three_centred", "rise_mm=300"],
        ["shape=three_centred", "rise_mm=50", "thickness_mm=40"],
        ["embrace_deg=180", "joint_orientation=vertical"],
        ["shape=pointed", "joint_orientation=vertical"],
    ]
    for command in ("run", "limit"):  # arches that cannot be built, refused before YADE or an LP
        lines += [[command, "--preset", "set2", *(a for s in settings for a in ("--set", s))] for settings in shapes]
    return lines


class SimulationStarted(Exception):
    """A probe got as far as starting a simulation: it was not refused."""


@pytest.fixture(autouse=True)
def no_simulation(monkeypatch):
    """Every probe must be refused before a YADE process starts; one that is not fails the test."""
    from yadearch.engine import process

    def refuse(*args, **kwargs):
        raise SimulationStarted(f"a simulation was started: {args[0] if args else kwargs}")

    monkeypatch.setattr(process, "_run_child", refuse)


def test_there_are_over_a_hundred_probes():
    assert len(probes()) > 100


@pytest.mark.parametrize("argv", probes(), ids=lambda a: " ".join(a)[:60])
def test_a_bad_input_ends_in_one_line_and_exit_code_1(argv, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    argv = [a.replace("OUT", str(tmp_path / "out")) for a in argv]
    if argv[0] == "run" and "--out" not in argv:
        argv += ["--out", str(tmp_path / "out" / "run")]
    code = main(argv)
    err = capsys.readouterr().err.strip()
    assert code == 1, err
    assert err.startswith("error: ") and "\n" not in err and "Traceback" not in err
    assert not (tmp_path / "out" / "run" / "summary.json").exists()
    assert {p.name for p in tmp_path.iterdir()} <= {"out"}  # nothing written outside --out


def test_derived_quantities_are_named_in_the_refusal():
    for setting, words in DERIVED:
        key, value = setting.split("=")
        case = case_from_dict({})
        with pytest.raises(YadearchError) as error:
            plan_run(case.replace(**{key: float(value)}))
        assert words is None or words in str(error.value), (setting, str(error.value))


TOML_SCALARS = st.one_of(st.integers(-(10**6), 10**6), st.floats(allow_nan=True), st.booleans(), st.text(max_size=5))
SECTION_NAMES = st.sampled_from(["geometry", "material", "interface", "loading", "numerics", "name", "other"])
KEYS = st.sampled_from([q.split(".")[1] for q, _, _ in parameter_docs()] + ["unknown_key"])
SECTION_VALUES = st.one_of(
    TOML_SCALARS,
    st.lists(TOML_SCALARS, max_size=2),
    st.dictionaries(KEYS, st.one_of(TOML_SCALARS, st.lists(TOML_SCALARS, max_size=2)), max_size=4),
)


@settings(max_examples=300, deadline=None)
@given(st.dictionaries(SECTION_NAMES, SECTION_VALUES, max_size=4))
def test_any_case_structure_is_a_valid_case_or_one_clean_error(data):
    try:
        case = case_from_dict(data)
        plan_run(case)
    except YadearchError as exc:
        assert str(exc) and "\n" not in str(exc)
        return
    for section in ("geometry", "material", "interface", "loading", "numerics"):
        for value in vars(getattr(case, section)).values():
            assert not isinstance(value, float) or math.isfinite(value)


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=80))
def test_any_toml_text_is_a_case_or_one_clean_error(text):
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError:
        return  # load_case reports these in one line (tested in test_case.py)
    try:
        plan_run(case_from_dict(data))
    except YadearchError as exc:
        assert "\n" not in str(exc)


@pytest.mark.parametrize("kn", [0.1, 1.0, 5.2, 100.0, 1000.0])
def test_the_whole_studied_kn_range_fits_the_default_step_budget(kn):
    plan = plan_run(case_from_dict({}).replace(kn_N_per_mm3=kn))
    assert plan.worst_case_steps < case_from_dict({}).numerics.max_steps


def test_limit_says_when_kn_plays_no_part(tmp_path, capsys, monkeypatch):
    """The note comes before the analysis (stood in for here: the message is what is tested)."""
    from yadearch.solve import limit

    def analysis_started(*args, **kwargs):
        raise YadearchError("analysis started")

    monkeypatch.setattr(limit, "limit_analysis", analysis_started)
    assert main(["limit", "--preset", "set2", "--kn", "100", "--out", str(tmp_path)]) == 1
    err = capsys.readouterr().err
    assert err.startswith("note: --kn 100 plays no part in the rigid-block analysis (rigid joints); add --compliant")
    assert main(["limit", "--preset", "set2", "--kn", "100", "--compliant", "--out", str(tmp_path)]) == 1
    assert "note" not in capsys.readouterr().err
