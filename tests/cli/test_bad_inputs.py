"""Nothing a user types can crash, hang or write outside `--out` (no YADE: every probe is refused
before a simulation starts): a table of bad inputs through the command line, and property-based
cases and TOML structures that give a valid case or one clean error, never a traceback."""

from __future__ import annotations

import json
import math
import shutil
import tomllib
from dataclasses import fields
from pathlib import Path

import pytest
from conftest import REPO
from hypothesis import example, given, settings
from hypothesis import strategies as st

from yadearch.case.config import case_from_dict
from yadearch.case.plan import plan_run
from yadearch.case.sections import SECTIONS, parameter_docs
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
    "loads.load_inclination_deg",  # a load leaning 1 deg toward the left
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
        ["run", "--set", "material=basalt"],
        ["run", "--set", "material.preset=basalt"],
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
        ["report", f"{REPO}/reports/set2", f"{REPO}/reports/set2/", "--out", "OUT/r"],  # one run twice
        ["piers", "--preset", "set2", "--height-mm", "100", "--width-mm", "10", "--out", "OUT/p.toml"],
        ["piers", "--preset", "set2", "--height-mm", "0", "--width-mm", "60", "--out", "OUT/p.toml"],
        ["limit", "--set", "friction_deg=95"],
        ["limit", "--preset", "set2", "--kn", "3"],
        ["limit", "--preset", "set2", "--set", "numerics.damping=0.3"],
        ["loads", "--preset", "set2", "--set", "kn_N_per_mm3=3"],
        ["loads", "--preset", "set2", "--engine", "static", "--set", "damping=0.3"],
        ["run", "--preset", "set2", "--engine", "static", "--out", "OUT/" + "x" * 250],
        # campaigns: every run of a grid checked before the first starts (nothing runs)
        ["sweep", "--preset", "set2", "--param", "n_voussoirs=a,b", "--out", "OUT/s"],
        ["sweep", "--preset", "set2", "--engine", "static", "--param", "damping=0.1,0.3", "--out", "OUT/s"],
        ["montecarlo", "--preset", "set2", "--samples", "2", "--param", "face_bump_mm=a,b", "--out", "OUT/m"],
        ["robustness", "--kn", "abc", "--out", "OUT/r"],
        ["robustness", "--kn", "-1", "--out", "OUT/r"],
        ["robustness", "--engine", "static", "--variant", "timestep_x0.5", "--variant", "damping_x2", "--out", "OUT/r"],
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
        # one parameter given two ways, the last would win unsaid: refused (user trial)
        ["run", "--preset", "set2", "--engine", "static", "--kn", "10", "--set", "kn_N_per_mm3=20"],
        [
            "run",
            "--preset",
            "set2",
            "--engine",
            "static",
            "--set",
            "movement=spreading",
            "--set",
            "support_direction_deg=-90",
        ],
        ["run", "--preset", "set2", "--engine", "static", "--no-check", "--set", "numerics.increments_check=halved"],
        ["run", "--preset", "set2", "--engine", "static", "--set", "numerics.engine=dem"],  # the last won unsaid
        ["run", "--preset", "set2", "--engine", "static", "--set", "span_mm=900"],  # a size the shape does not read
        ["sweep", "--table", "IN/short_row.csv", "--engine", "static", "--out", "OUT/t"],
        ["loads", "--preset", "set2", "--kn", "100", "--set", "live_load=vertical", "--out", "OUT/l"],  # rigid blocks
        # the third user trial: loads' options and parameters that do not go together (were read silently)
        ["loads", "--preset", "set2", "--set", "live_load=vertical", "--positions", "3", "--after-mm", "20"],
        ["loads", "--preset", "set2", "--set", "live_load=vertical", "--residual", "2", "--after-mm", "10"],
        ["loads", "--preset", "set2", "--set", "live_load=vertical", "--residual", "2", "--engine", "dem"],
        ["loads", "--preset", "set2", "--set", "live_load=vertical", "--residual", "0"],
        ["loads", "--preset", "set2", "--set", "live_load=vertical", "--no-descending"],
        ["loads", "--preset", "set2", "--set", "live_load=vertical", "--set", "load_voussoir=10", "--positions", "3"],
        ["loads", "--preset", "set2", "--set", "live_load=horizontal_acceleration", "--positions", "3"],
        ["loads", "--preset", "set2", "--set", "live_load=vertical", "--set", "held_load_N=4"],
        ["loads", "--preset", "set2", "--set", "live_load=horizontal_acceleration", "--set", "load_width_mm=100"],
        ["loads", "--preset", "set2", "--set", "live_load=vertical", "--set", "load_shape=rising"],
        # views of a run: no run folder, an unknown format, no --vtk, a run from before states.npz
        ["animate", "OUT/not-a-run"],
        ["animate", f"{REPO}/reports/set1", "--format", "avi"],
        ["animate", f"{REPO}/reports/limit"],
        ["export", f"{REPO}/reports/set2"],
        ["export", "OUT/not-a-run", "--vtk"],
        ["export", "RUNS/summary_only", "--vtk"],
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
    return lines + names_and_folders() + bounds() + damaged_inputs()


# the third round (issue 42): names and output folders, the bounds of every size and time, damaged inputs
BAD_OUTS = ["", " ", ".", "..", "/", "//", "OUT/x/..", "OUT/x/.", "OUT/a\x01b", "OUT/.hidden", "OUT/" + "y" * 300]
OUT_COMMANDS = [  # every command's output folder or file, with what else it needs to get that far
    ["run", "--preset", "set2", "--engine", "static", "--out"],
    ["reproduce", "--out"],
    ["limit", "--preset", "set2", "--out"],
    ["report", f"{REPO}/reports/set2", "--out"],
    ["sweep", "--kn", "1,2", "--engine", "static", "--out"],
    ["montecarlo", "--samples", "2", "--engine", "static", "--out"],
    ["robustness", "--kn", "5.2", "--out"],
    ["capacity", "--engine", "static", "--out"],
    ["sensitivity", "--engine", "static", "--out"],
    ["calibrate", "--target-du", "48", "--out"],
    ["calibrate", "--target-du", "48", "--out", "OUT/c.json", "--runs-dir"],
    ["animate", f"{REPO}/reports/set2", "--out"],
    ["export", f"{REPO}/reports/set2", "--vtk", "--out"],
]
BAD_NAMES = ["", " ", ".", "..", "../../x", "a/b", "/abs", ".hidden", "a\tb", "a\nb", "z" * 300]
OPTION_BOUNDS = {  # option: refused values, with the command that takes it
    ("sweep", "--jobs"): ["0", "-1", "2.5", "abc", "1e3", "nan", "2000", "0_2"],
    ("sweep", "--timeout-min"): ["nan", "inf", "-inf", "-1", "0", "0_5", "abc", "1e9"],
    ("montecarlo", "--samples"): ["0", "-1", "1000000", "1.5", "10_0", "nan"],
    ("montecarlo", "--seed"): ["-1", "4294967296", "x", "1.5"],
    ("sensitivity", "--base-points"): ["0", "7", "100", "1073741824", "64.0", "-64"],
    ("sensitivity", "--check-runs"): ["-1", "51", "x", "1.5"],
    ("capacity", "--step-deg"): ["0", "-15", "1e-9", "7", "91", "nan", "inf", "0_5", "x"],
    ("calibrate", "--target-du"): ["0", "-1", "nan", "inf", "1e5", "x", "4_8"],
    ("calibrate", "--tolerance-mm"): ["0", "-1", "nan", "inf"],
    ("calibrate", "--kn-min"): ["0", "-1", "nan", "1e6", "0_1"],
    ("calibrate", "--kn-max"): ["0", "-1", "inf", "1e6"],
    ("calibrate", "--max-runs"): ["2", "0", "101", "x", "5.5"],
    ("limit", "--max-snap-mm"): ["0", "-1", "nan", "inf", "1e9"],
    ("run", "--kn"): ["0_3", "1__2", "0x10", "5,2"],
    ("reproduce", "--jobs"): ["0", "3.0", "-2"],
}
COMMAND_BASE = {
    "sweep": ["sweep", "--kn", "1,2", "--engine", "static", "--out", "OUT/s"],
    "montecarlo": ["montecarlo", "--samples", "2", "--engine", "static", "--out", "OUT/m"],
    "sensitivity": ["sensitivity", "--engine", "static", "--out", "OUT/s"],
    "capacity": ["capacity", "--engine", "static", "--out", "OUT/c"],
    "calibrate": ["calibrate", "--target-du", "48", "--out", "OUT/c.json"],
    "limit": ["limit", "--out", "OUT/l"],
    "run": ["run", "--engine", "static"],
    "reproduce": ["reproduce", "--out", "OUT/r"],
}


def names_and_folders() -> list[list[str]]:
    """Every command's output path that is empty, special, hidden, too long or leaves --out; bad run names."""
    lines = [[*command, out] for command in OUT_COMMANDS for out in BAD_OUTS]
    lines += [["run", "--preset", "set2", "--engine", "static", "--name", name] for name in BAD_NAMES]
    lines += [["run", "--preset", "set2", "--set", f"name={name!r}"] for name in ("..", "a/b", ".x", "")]
    return lines


def bounds() -> list[list[str]]:
    """Every size and time option past its bound (and numbers Python reads but a person does not write)."""
    lines = [
        [*COMMAND_BASE[command], option, value]
        for (command, option), values in OPTION_BOUNDS.items()
        for value in values
    ]
    lines += [
        ["sweep", "--kn", "1", "--param", "kn_N_per_mm3=2", "--out", "OUT/s"],
        ["sweep", "--param", "damping=0.1", "--param", "numerics.damping=0.2", "--out", "OUT/s"],
        ["calibrate", "--target-du", "48", "--kn-min", "5", "--kn-max", "5", "--out", "OUT/c.json"],
        ["sensitivity", "--base-points", "65536", "--out", "OUT/s"],  # 65536 x 14 runs: past the campaign bound
        ["montecarlo", "--samples", "60000", "--param", "face_bump_mm=0.1,0.2", "--out", "OUT/m"],
    ]
    return lines


def damaged_inputs() -> list[list[str]]:
    """Tables and case files that are binary, repeat a column, have a longer row or nothing; damaged run folders."""
    lines = [["sweep", "--table", f"IN/{name}", "--out", "OUT/s"] for name in TABLES]
    lines += [["run", "--case", f"IN/{name}"] for name in CASES]
    lines += [[command, f"RUNS/{name}", *extra] for name in DAMAGED for command, *extra in VIEWS]
    return lines


TABLES = {
    "binary.csv": bytes(range(256)),
    "latin1.csv": "kn_N_per_mm3,run\n1,caf\xe9\n".encode("latin-1"),
    "twice.csv": b"kn_N_per_mm3,interface.kn_N_per_mm3\n1,2\n",
    "bare_twice.csv": b"\xef\xbb\xbfdamping,damping\n0.1,0.2\n",
    "long_row.csv": b"kn_N_per_mm3\n1,2\n",
    "short_row.csv": b"kn_N_per_mm3,thickness_mm\n5,24\n10\n",
    "empty.csv": b"",
    "header_only.csv": b"kn_N_per_mm3\n",
    "nul.csv": b"kn_N_per_mm3\n1\x00\n",
    "bom_unknown.csv": b"\xef\xbb\xbfnothing\n1\n",
    "bad_name.csv": b"kn_N_per_mm3,run\n1,../../x\n",
}
CASES = {
    "binary.toml": bytes(range(256)),
    "bom_bad.toml": b"\xef\xbb\xbf[interface]\nkn_N_per_mm3 = -1\n",
    "bom_unknown.toml": b"\xef\xbb\xbf[nothing]\n",
    "name.toml": b'name = "../x"\n',
    "name_control.toml": b'name = "a\\u0007b"\n',
}
DAMAGED = (
    "states_cut",
    "du_text",
    "du_nan",
    "du_negative",
    "du_inf",
    "outcome_unknown",
    "hinges_bad",
    "bracket_bad",
    "steps_text",
)
VIEWS = [
    ("report", "--out", "OUT/r"),
    ("animate", "--format", "gif", "--out", "OUT/m.gif"),
    ("export", "--vtk", "--out", "OUT/v"),
]


@pytest.fixture(scope="module")
def damaged_runs(tmp_path_factory) -> Path:
    """Copies of the committed set 2 run, each damaged in one way (the folders DAMAGED names), and one
    with only its summary, case and log (a campaign's summary-only run)."""
    root = tmp_path_factory.mktemp("damaged")
    summary = json.loads((REPO / "reports/set2/summary.json").read_text())
    changes = {
        "du_text": {"du_mm": "48.9"},
        "du_nan": {"du_mm": math.nan},
        "du_negative": {"du_mm": -1.0},
        "du_inf": {"du_mm": math.inf},
        "outcome_unknown": {"outcome": "exploded"},
        "hinges_bad": {"hinges_at_collapse": [{"interface": 0, "side": "X"}]},
        "bracket_bad": {"du_bracket_mm": [90.0, 80.0]},
        "steps_text": {"steps": "many"},
    }
    for name in DAMAGED:
        folder = root / name
        folder.mkdir()
        for file in ("case.toml", "series.csv", "joints.csv", "snapshots.json", "states.npz", "run.log"):
            shutil.copy(REPO / "reports/set2" / file, folder / file)
        (folder / "summary.json").write_text(json.dumps({**summary, **changes.get(name, {})}))
    data = (root / "states_cut" / "states.npz").read_bytes()
    (root / "states_cut" / "states.npz").write_bytes(data[: len(data) // 2])
    (root / "summary_only").mkdir()  # a campaign's run, as its committed folders are: no states to view
    for file in ("case.toml", "summary.json", "run.log"):
        shutil.copy(REPO / "reports/set2" / file, root / "summary_only" / file)
    return root


class SimulationStarted(Exception):
    """A probe got as far as starting a simulation: it was not refused."""


@pytest.fixture(autouse=True)
def no_simulation(monkeypatch):
    """Every probe must be refused before a YADE process starts; one that is not fails the test."""
    from yadearch.launch import process

    def refuse(*args, **kwargs):
        raise SimulationStarted(f"a simulation was started: {args[0] if args else kwargs}")

    monkeypatch.setattr(process, "run_child", refuse)


def test_there_are_over_a_hundred_probes():
    assert len(probes()) > 100
    assert len(names_and_folders() + bounds() + damaged_inputs()) >= 150  # issue 42's third round


@pytest.mark.parametrize("argv", probes(), ids=lambda a: " ".join(a)[:60])
def test_a_bad_input_ends_in_one_line_and_exit_code_1(argv, tmp_path, capsys, monkeypatch, damaged_runs):
    monkeypatch.chdir(tmp_path)
    inputs = tmp_path / "in"
    inputs.mkdir()
    for name, data in {**TABLES, **CASES}.items():
        (inputs / name).write_bytes(data)
    before = {p: p.stat().st_mtime_ns for p in damaged_runs.rglob("*")}
    argv = [a.replace("OUT", str(tmp_path / "out")).replace("IN/", f"{inputs}/") for a in argv]
    argv = [a.replace("RUNS/", f"{damaged_runs}/") for a in argv]
    if argv[0] == "run" and "--out" not in argv and "--name" not in argv:
        argv += ["--out", str(tmp_path / "out" / "run")]
    code = main(argv)
    err = capsys.readouterr().err.strip()
    assert code == 1, err
    assert err.startswith("error: ") and "\n" not in err and "Traceback" not in err
    assert not (tmp_path / "out" / "run" / "summary.json").exists()
    assert {p.name for p in tmp_path.iterdir()} <= {"out", "in"}  # nothing written outside --out
    assert {p.name for p in inputs.iterdir()} == set(TABLES) | set(CASES)
    assert {p: p.stat().st_mtime_ns for p in damaged_runs.rglob("*")} == before  # nor into the runs read


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
@example({"material": {"preset": [False]}})  # a named material that is not a name (found by this test)
@example({"geometry": {"shape": "measured", "extrados_points_mm": [[0.5, 1.0, 2.0]]}})
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


def test_limit_refuses_kn_without_compliant_before_the_analysis(tmp_path, capsys, monkeypatch):
    """The rigid analysis reads no kn: --kn alone is refused in one line before anything runs; with
    --compliant it is read (the analysis, stood in for here, starts)."""
    from yadearch.solve import limit

    def analysis_started(*args, **kwargs):
        raise YadearchError("the analysis started")

    monkeypatch.setattr(limit, "limit_analysis", analysis_started)
    assert main(["limit", "--preset", "set2", "--kn", "100", "--out", str(tmp_path)]) == 1
    err = capsys.readouterr().err
    assert err.startswith("error: --kn 100 plays no part in the rigid-block analysis (rigid joints); add --compliant")
    assert err.count("\n") == 1
    assert main(["limit", "--preset", "set2", "--kn", "100", "--compliant", "--out", str(tmp_path)]) == 1
    assert capsys.readouterr().err.startswith("error: the analysis started")


def test_the_rigid_load_capacity_refuses_the_fills_spring_in_one_line(capsys):
    """Rigid blocks mobilise the fill's passive pressure at once: u_p is the static engine's and the DEM's."""
    args = ["loads", "--preset", "set2", "--set", "live_load=vertical", "--set", "fill_depth_mm=50"]
    args += ["--set", "fill_passive_coefficient=1", "--set", "fill_passive_displacement_mm=2"]
    assert main(args) == 1
    err = capsys.readouterr().err
    assert err.startswith("error: --set fill_passive_displacement_mm plays no part in the rigid-block analysis")
    assert err.count("\n") == 1
