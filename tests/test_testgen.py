"""`archlog testgen` (issue 20): message strategies drawn from real .msg definitions, the generated
files, and the generated tests run against the corpus/testgen systems on Debian's ROS 1: each
planted defect is found and shrunk to at most 3 input messages, each fixed twin passes."""

from __future__ import annotations

import importlib.util
import json
import math
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
from conftest import finding_keys, requires_ros, run_case
from hypothesis import given, settings
from hypothesis import strategies as st
from support.testgen_corpus import CORPUS, ROOT, Outcome, prepare, run_generated, systems

from archlog.diagnostics import DiagnosticSink
from archlog.extract.workspace.index import Workspace
from archlog.testgen.msgspec import message_specs, parse_msg
from archlog.testgen.ros2 import Ros2Machine, Ros2Session, message_class, run_command, to_json, to_message
from archlog.testgen.runtime import check_log
from archlog.testgen.settings import SettingsError, load_settings
from archlog.testgen.strategies import INTS, Strategies

SPECS = message_specs(Workspace([CORPUS / "empty_array" / "buggy"], DiagnosticSink()),
                      dict.fromkeys(["sensor_msgs/NavSatFix", "sensor_msgs/LaserScan", "geometry_msgs/PoseStamped"],
                                    ("test", 1)), DiagnosticSink())


def test_specs_follow_nested_types_from_share_dirs() -> None:
    assert {"sensor_msgs/NavSatStatus", "std_msgs/Header", "geometry_msgs/Pose", "geometry_msgs/Point"} <= set(SPECS)
    assert ["position_covariance", "float64", 9] in SPECS["sensor_msgs/NavSatFix"]["fields"]
    assert SPECS["sensor_msgs/NavSatStatus"]["constants"]["STATUS_NO_FIX"] == ["int8", -1]


def test_a_bad_line_is_a_diagnostic_with_its_line() -> None:
    sink = DiagnosticSink()
    spec = parse_msg("int32 ok\nfloat64[ broken\n", "pkg", "pkg/msg/Bad.msg", sink)
    assert spec["fields"] == [["ok", "int32", None]]
    assert [(d.file, d.line, d.code) for d in sink.items] == [("pkg/msg/Bad.msg", 2, "testgen-message")]


def _walk(value: object, spec: dict, specs: dict) -> None:
    """Every drawn field has its builtin type's exact range and its array's size."""
    assert set(value) == {name for name, _b, _s in spec["fields"]}  # type: ignore[arg-type]
    for name, base, size in spec["fields"]:
        field = value[name]  # type: ignore[index]
        items = field if size is not None else [field]
        if size is not None and size >= 0:
            assert len(items) == size
        for item in items:
            if base in INTS:
                assert INTS[base][0] <= item <= INTS[base][1]
            elif base in ("float32", "float64"):
                assert isinstance(item, float)
            elif base in ("time", "duration"):
                assert 0 <= item["nsecs"] <= 999_999_999 if "nsecs" in item else -1 <= item["now"] <= 0
            elif base in specs:
                _walk(item, specs[base], specs)


@settings(max_examples=60, deadline=None)
@given(st.data())
def test_drawn_messages_fit_their_definitions(data: st.DataObject) -> None:
    strategies = Strategies(SPECS, load_settings(None))
    for type_ in ("sensor_msgs/NavSatFix", "sensor_msgs/LaserScan", "geometry_msgs/PoseStamped"):
        _walk(data.draw(strategies.message(type_)), SPECS[type_], SPECS)


def test_field_settings_bound_fix_and_enumerate(tmp_path: Path) -> None:
    path = tmp_path / "t.toml"
    path.write_text('[fields."sensor_msgs/NavSatStatus".status]\nenum = true\n'
                    '[fields."sensor_msgs/NavSatFix".latitude]\nmin = -90\nmax = 90\n'
                    '[fields."sensor_msgs/NavSatFix".altitude]\nfixed = 5.0\n')
    strategies = Strategies(SPECS, load_settings(path))

    @settings(max_examples=40, deadline=None)
    @given(strategies.message("sensor_msgs/NavSatFix"))
    def check(fix: dict) -> None:
        assert fix["status"]["status"] in (-1, 0, 1, 2)
        assert -90 <= fix["latitude"] <= 90 and not math.isnan(fix["latitude"])
        assert fix["altitude"] == 5.0

    check()


def test_float_specials_are_drawn_by_default() -> None:
    seen: set[str] = set()
    strategy = Strategies(SPECS, load_settings(None)).message("sensor_msgs/NavSatFix")

    @settings(max_examples=300, deadline=None)
    @given(strategy)
    def collect(fix: dict) -> None:
        for value in [fix["latitude"], fix["longitude"], fix["altitude"], *fix["position_covariance"]]:
            seen.add("nan" if math.isnan(value) else "inf" if math.isinf(value) else "-0" if str(value) == "-0.0" else "")

    collect()
    assert {"nan", "inf"} <= seen


def test_unknown_setting_names_its_line(tmp_path: Path) -> None:
    path = tmp_path / "t.toml"
    path.write_text("[testgen]\nsettle = 0.5\nspeed = 3\n")
    with pytest.raises(SettingsError, match=r"t\.toml:3: unknown setting: speed"):
        load_settings(path)


def test_an_exception_logged_by_a_callback_fails_unless_switched_off(tmp_path: Path) -> None:
    """rospy's "bad callback" ERROR (with its traceback) fails the callbacks property; an ERROR
    without a traceback does not; `callbacks = false` in the settings turns the property off."""
    text = ("bad callback: <bound method Monitor.on_voltage>\nTraceback (most recent call last):\n"
            '  File "monitor.py", line 16, in on_voltage\nValueError: cannot convert float NaN to integer\n')
    event = {"ev": "log", "node": "/battery_monitor", "t": 0.0, "text": text}
    with pytest.raises(AssertionError, match="/battery_monitor raised in a callback: ValueError: cannot convert"):
        check_log(load_settings(None), event)
    check_log(load_settings(None), {**event, "text": "battery voltage out of range"})
    path = tmp_path / "t.toml"
    path.write_text("[properties]\ncallbacks = false\n")
    check_log(load_settings(path), event)


def test_generation_keeps_the_users_properties(tmp_path: Path) -> None:
    variant = CORPUS / "nan_command" / "buggy"
    command = [sys.executable, "-m", "archlog", "testgen", str(variant), "--launch", "base_safety/launch/limiter.launch",
               "--output", str(tmp_path)]
    first = subprocess.run(command, capture_output=True, text=True, check=True)
    assert "wrote" in first.stdout and (tmp_path / "limiter_properties.py").is_file()
    generated = (tmp_path / "test_limiter.py").read_text()
    assert 'def publish_teleop_cmd_vel(self, msg):' in generated and '"geometry_msgs/Twist"' in generated
    (tmp_path / "limiter_properties.py").write_text("# mine\n")
    subprocess.run(command, capture_output=True, text=True, check=True)
    assert (tmp_path / "limiter_properties.py").read_text() == "# mine\n"


def test_unknown_node_is_a_usage_error(tmp_path: Path) -> None:
    result = subprocess.run([sys.executable, "-m", "archlog", "testgen", str(CORPUS / "nan_command" / "buggy"),
                             "--launch", "base_safety/launch/limiter.launch", "--nodes", "/nobody",
                             "--output", str(tmp_path)], capture_output=True, text=True)
    assert result.returncode == 2 and "no node /nobody" in result.stderr and "Traceback" not in result.stderr


@pytest.mark.parametrize("system", systems(), ids=lambda p: p.name)
def test_static_rules_cannot_tell_the_twins_apart(system: Path) -> None:
    """The planted defects are behavioral: the rules report the same (rule, subject) on both twins."""
    keys = [{(rule, subject) for rule, _f, _l, subject in finding_keys(run_case(system / v)[1])} for v in ("buggy", "clean")]
    assert keys[0] == keys[1]


# -- ROS 2: the generated module against a stand-in of rclpy and rosidl's message classes ----------

ROS2_SYSTEM = ROOT / "corpus" / "ros2" / "yaml_remap_near_miss" / "clean"
STANDIN = Path(__file__).resolve().parent / "support" / "ros2_standin"


@pytest.fixture
def ros2_module(tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    """The test generated for the ROS 2 velocity smoother in isolation, imported with the stand-in."""
    subprocess.run([sys.executable, "-m", "archlog", "testgen", str(ROS2_SYSTEM), "--launch",
                    "teleop/launch/teleop.launch.yaml", "--nodes", "/robot1/smoother", "--output", str(tmp_path)],
                   check=True, capture_output=True, text=True)
    monkeypatch.syspath_prepend(str(STANDIN))
    for name in [m for m in sys.modules if m.split(".")[0] in ("rclpy", "geometry_msgs", "std_msgs", "builtin_interfaces")]:
        monkeypatch.delitem(sys.modules, name)
    spec = importlib.util.spec_from_file_location("test_teleop_generated", tmp_path / "test_teleop.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_ros2_module_uses_rclpy_and_the_ros2_message_classes(ros2_module) -> None:
    machine = ros2_module.TeleopMachine
    assert issubclass(machine, Ros2Machine) and machine.rclpy is sys.modules["rclpy"]
    twist = sys.modules["geometry_msgs.msg"].Twist
    assert machine.classes == {"geometry_msgs/msg/Twist": twist}
    assert hasattr(machine, "publish_robot1_cmd_vel")
    assert ros2_module.MODEL["inputs"] == {"/robot1/cmd_vel": "geometry_msgs/msg/Twist"}
    assert ros2_module.MODEL["outputs"] == {"/robot1/cmd_vel_smoothed": "geometry_msgs/msg/Twist"}
    command = run_command(ros2_module.MODEL["commands"][0], {"/robot1/smoother/max_step": 0.5})
    assert command is not None  # the entry point, under this Python: no ros2cli needed
    assert command[:3] == [sys.executable, "-c", "import sys; from teleop.velocity_smoother import main as main; "
                                                 "sys.exit(main())"]
    assert command[3:] == ["--ros-args", "-r", "__node:=smoother",
                       "-r", "__ns:=/robot1", "-r", "/robot1/cmd_vel_in:=/robot1/cmd_vel",
                       "-r", "/robot1/cmd_vel_out:=/robot1/cmd_vel_smoothed", "-p", "max_step:=0.5"]


def test_ros2_strategies_draw_what_the_message_classes_accept(ros2_module) -> None:
    """Every drawn Twist becomes a message the rosidl-style setters accept, and reads back the same;
    the session publishes it with the stand-in's rclpy."""
    session = Ros2Session(ros2_module.MODEL, ros2_module.rclpy, ros2_module.TeleopMachine.classes)
    session.start()
    twist = ros2_module.TeleopMachine.classes["geometry_msgs/msg/Twist"]
    drawn: list[dict] = []

    @settings(max_examples=50, deadline=None)
    @given(ros2_module.STRATEGIES.message("geometry_msgs/msg/Twist"))
    def check(msg: dict) -> None:
        sent = to_message(msg, twist, now=100.0)
        assert isinstance(sent, twist) and json.dumps(to_json(sent), sort_keys=True) == json.dumps(msg, sort_keys=True)
        session.send({"op": "publish", "topic": "/robot1/cmd_vel", "msg": msg})
        drawn.append(msg)

    try:
        check()
    finally:
        session.close()
    assert session.events.empty()  # no value was refused
    assert len(session.publishers["/robot1/cmd_vel"].published) == len(drawn) == 50


def test_ros2_syntax_bounds_and_defaults() -> None:
    """ROS 2 .msg syntax: bounded strings and arrays are drawn within their bound, a default value
    after the name is read as a field, nested and time types get ROS 2 names."""
    sink = DiagnosticSink()
    spec = parse_msg("string<=3 name\nint32[<=2] ids\nfloat64 speed 0.5\ntime at\nPoint target\n", "nav",
                     "nav/msg/Goal.msg", sink, ros2=True)
    assert sink.items == []
    assert spec["fields"] == [["name", "string", None], ["ids", "int32", -1], ["speed", "float64", None],
                              ["at", "builtin_interfaces/msg/Time", None], ["target", "nav/msg/Point", None]]
    assert spec["bounds"] == {"name": 3, "ids": 2}
    specs = {"nav/msg/Goal": {**spec, "fields": spec["fields"][:3]}}

    @settings(max_examples=50, deadline=None)
    @given(Strategies(specs, load_settings(None)).message("nav/msg/Goal"))
    def check(goal: dict) -> None:
        assert len(goal["name"]) <= 3 and len(goal["ids"]) <= 2

    check()


def test_ros2_specs_and_header_stamps() -> None:
    """ROS 2 names: nested types as pkg/msg/Name, Header without seq, a stamp near the moment of sending."""
    specs = message_specs(Workspace([ROS2_SYSTEM], DiagnosticSink()),
                          {"geometry_msgs/msg/PoseWithCovarianceStamped": ("test", 1)}, DiagnosticSink())
    assert specs["std_msgs/msg/Header"]["fields"] == [["stamp", "builtin_interfaces/msg/Time", None],
                                                    ["frame_id", "string", None]]
    assert ["covariance", "float64", 36] in specs["geometry_msgs/msg/PoseWithCovariance"]["fields"]
    sys.path.insert(0, str(STANDIN))
    try:
        stamped = message_class("geometry_msgs/msg/PoseWithCovarianceStamped")  # the stand-in's

        @settings(max_examples=30, deadline=None)
        @given(Strategies(specs, load_settings(None)).message("geometry_msgs/msg/PoseWithCovarianceStamped"))
        def check(msg: dict) -> None:
            built = to_message(msg, stamped, now=1000.0)
            assert 999 <= built.header.stamp.sec <= 1000 and len(built.pose.covariance) == 36

        check()
    finally:
        sys.path.remove(str(STANDIN))
        for name in [m for m in sys.modules if m.split(".")[0] in ("geometry_msgs", "std_msgs", "builtin_interfaces")]:
            del sys.modules[name]


# -- the generated tests against the running corpus systems (Debian's ROS 1) -------------------

def _ros(test):
    for mark in requires_ros():
        test = mark(test)
    return test


BUDGET = {"examples": 12, "steps": 5, "shrink_seconds": 8}  # for a buggy system; a fixed twin runs 2 examples
REPLAYED = "zero_division"  # its replay file is run again with `archlog replay` (roscpp: quick to start)
COVERED = "guarded_division"  # its fixed twin's line coverage is in the report


@pytest.mark.parametrize("system", systems(), ids=lambda p: p.name)
@_ros
def test_generated_test_finds_the_defect_and_passes_the_fixed_twin(system: Path, tmp_path: Path) -> None:
    """Both twins at once (each on its own master; they mostly wait on the nodes)."""
    def buggy_run() -> tuple[Path, Outcome]:
        out, _case = prepare(system / "buggy", tmp_path / "buggy")
        return out, run_generated(out, BUDGET["examples"], seed=0, shrink_seconds=BUDGET["shrink_seconds"],
                                  steps=BUDGET["steps"])

    def clean_run() -> Outcome:
        out, _case = prepare(system / "clean", tmp_path / "clean")
        return run_generated(out, 2, seed=0, steps=BUDGET["steps"])

    with ThreadPoolExecutor(2) as pool:
        clean_future = pool.submit(clean_run)
        out, buggy = buggy_run()
        clean = clean_future.result()
    assert not buggy.passed and buggy.replay is not None, buggy.output
    assert buggy.messages() <= 3, buggy.replay
    assert clean.passed, clean.output
    if system.name == COVERED:  # a rospy node: roslaunch ran it under coverage.py
        assert 0 < clean.coverage["/fill_ratio"][0] <= clean.coverage["/fill_ratio"][1], clean.output
    if system.name == REPLAYED:
        replay = next((out / "replay").glob("*.json"))
        result = subprocess.run([sys.executable, "-m", "archlog", "replay", str(replay)], capture_output=True, text=True,
                                timeout=120)
        assert result.returncode == 1 and "reproduced: node(s) died" in result.stdout, result.stdout + result.stderr


def test_a_process_of_several_nodes_is_started_once_without_renaming_them() -> None:
    """`__node` would give every node of the process one name; each node's parameters are passed."""
    process = {"name": "/talker", "nodes": ["/talker", "/listener"], "pkg": "chat", "exe": "both", "remaps": [],
               "params": {"/listener/rate": 2.0, "/other/rate": 3.0}, "script": "/ws/chat/both.py"}
    command = run_command(process, {"/talker/greeting": "hi"})
    assert command is not None
    assert command[command.index("--ros-args"):] == ["--ros-args", "-r", "__ns:=/", "-p", "rate:=2.0",
                                                     "-p", "greeting:=hi"]


def test_a_recovered_port_of_unknown_type_matches_the_live_type() -> None:
    """The code chose the type at run time (archlog recovered ""): not a difference of the interface;
    a known type that differs still is."""
    from archlog.observe import Architecture, compare
    from archlog.testgen.runtime import _typed_as_seen

    want = Architecture(frozenset({"/mover"}), frozenset({("/mover", "/cmd_vel", ""),
                                                          ("/mover", "/odom_out", "nav_msgs/Odometry")}),
                        frozenset(), frozenset())
    seen = Architecture(frozenset({"/mover"}), frozenset({("/mover", "/cmd_vel", "geometry_msgs/msg/Twist"),
                                                          ("/mover", "/odom_out", "std_msgs/String")}), frozenset(), frozenset())
    row = compare(_typed_as_seen(want, seen), seen)["publishers"]
    assert row["only_recovered"] == [["/mover", "/odom_out", "nav_msgs/Odometry"]]
    assert row["only_observed"] == [["/mover", "/odom_out", "std_msgs/String"]]
