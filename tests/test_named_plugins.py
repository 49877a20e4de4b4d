"""pluginlib classes a ROS 2 node's parameters name (system/named_plugins.py): found through the plugin
descriptions the workspace exports, read, and their ports the host's; a class not found stays a hole."""

from __future__ import annotations

import shutil
from pathlib import Path

from archlog.analysis import Analysis, analyse
from archlog.diagnostics import DiagnosticSink
from archlog.extract.workspace.index import Workspace
from archlog.rules.engine import Engine
from archlog.rules.ruleset import load_rules

CASE = Path(__file__).resolve().parent.parent / "corpus" / "ros2" / "plugin_service_from_params" / "clean"
LAUNCH = ["task_host/launch/tasks.launch.py"]
PARAMS = Path("src/task_host/config/tasks.yaml")


def _case(tmp_path: Path, params: str | None = None) -> Path:
    shutil.copytree(CASE / "src", tmp_path / "src")
    if params is not None:
        (tmp_path / PARAMS).write_text(params)
    return tmp_path


def _services(result: Analysis, node: str) -> set[str]:
    return {name for _id, owner, name, _type in result.store.rows("service_server") if owner == node}


def test_plugin_classes_are_found_through_the_description_cmake_exports(tmp_path: Path) -> None:
    workspace = Workspace([_case(tmp_path)], DiagnosticSink())
    found = workspace.plugin_class("task_plugins::DockTask")
    assert found is not None and found.cls == "task_plugins::DockTask"
    assert [s.name for s in found.sources] == ["dock_task.cpp"]
    assert workspace.plugin_class("task_plugins::Missing") is None
    assert not workspace.packages["task_plugins"].executables  # a plugin class is no executable of its own


def test_the_named_class_serves_on_the_host_node_and_its_load_is_read(tmp_path: Path) -> None:
    result = analyse([_case(tmp_path)], LAUNCH, {}, [])
    assert "/robot/start_docking" in _services(result, "/robot/task_server")
    assert result.store.rows("plugin_hole") == []
    _ctl, findings = Engine(load_rules([])).run(result.store)
    assert [f.rule.id for f in findings] == []


def test_a_single_name_parameter_names_one_plugin(tmp_path: Path) -> None:
    params = ('/robot/task_server:\n  ros__parameters:\n    task_plugins: []\n    docking_task: "docking"\n'
              '    docking:\n      plugin: "task_plugins::DockTask"\n')
    result = analyse([_case(tmp_path, params)], LAUNCH, {}, [])
    assert "/robot/start_docking" in _services(result, "/robot/task_server")


def test_a_class_no_description_declares_stays_a_hole(tmp_path: Path) -> None:
    params = ('/robot/task_server:\n  ros__parameters:\n    task_plugins: ["docking"]\n'
              '    docking:\n      plugin: "task_plugins::UndockTask"\n')
    result = analyse([_case(tmp_path, params)], LAUNCH, {}, [])
    assert _services(result, "/robot/task_server") & {"/robot/start_docking"} == set()
    assert [node for _hole, node, _why in result.store.rows("plugin_hole")] == ["/robot/task_server"]
    notes = [d.message for d in result.diagnostics.items if d.code == "plugin-no-model"]
    assert notes == ["/robot/task_server loads the pluginlib class task_plugins::UndockTask (docking.plugin), which "
                     "no plugin description of the workspace declares; the ports it creates are unknown"]
    _ctl, findings = Engine(load_rules([])).run(result.store)
    assert [(f.rule.id, f.severity) for f in findings] == [("AL201", "note")]  # "unless the part not read ..."


def test_parameters_for_another_node_name_load_nothing(tmp_path: Path) -> None:
    """A parameter file key that does not match the node (rcl's rule: `task_server` is not
    /robot/task_server) gives it no plugins: the load stays a hole."""
    params = ('task_server:\n  ros__parameters:\n    task_plugins: ["docking"]\n'
              '    docking:\n      plugin: "task_plugins::DockTask"\n')
    result = analyse([_case(tmp_path, params)], LAUNCH, {}, [])
    assert _services(result, "/robot/task_server") & {"/robot/start_docking"} == set()
    assert len(result.store.rows("plugin_hole")) == 1
