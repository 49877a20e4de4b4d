"""Workspace indexing: packages, executables from CMake, setup.py/setup.cfg and scripts."""

from __future__ import annotations

from pathlib import Path

from catkin_pkg.package import parse_package

from archlog.diagnostics import DiagnosticSink
from archlog.extract.summary import NodeSummary
from archlog.extract.workspace.index import Workspace
from archlog.extract.workspace.packages import share_dirs
from archlog.system.rosrun import rosrun_config

MANIFEST = ("<package format='2'><name>{}</name><version>0.1.0</version><description>d</description>"
            "<maintainer email='dev@example.com'>m</maintainer><license>MIT</license></package>")


def package(root: Path, name: str, files: dict[str, str], executable: tuple[str, ...] = ()) -> Path:
    folder = root / "src" / name
    for rel, text in {"package.xml": MANIFEST.format(name), **files}.items():
        (folder / rel).parent.mkdir(parents=True, exist_ok=True)
        (folder / rel).write_text(text)
    for rel in executable:
        (folder / rel).chmod(0o755)
    return folder


def test_executables_from_every_source(tmp_path: Path) -> None:
    package(tmp_path, "drivers", {
        "CMakeLists.txt": "project(drivers)\nset(NODE ${PROJECT_NAME}_node)\nadd_executable(${NODE} src/a.cpp)\n"
                          "set_target_properties(${NODE} PROPERTIES OUTPUT_NAME driver)\n"
                          "include_directories(include extra/include)\nadd_subdirectory(gpu)\n"
                          "catkin_install_python(PROGRAMS scripts/relay.py DESTINATION bin)\n"
                          "install(PROGRAMS scripts/env_run DESTINATION bin)\n",
        "gpu/CMakeLists.txt": "cuda_add_executable(gpu_node main.cu helper.cpp)\n",
        "scripts/relay.py": "import rospy\n", "scripts/env_run": "#!/bin/bash\nexec \"$@\"\n",
        "scripts/tool": "#!/usr/bin/env python3\nimport rospy\n",
        "scripts/not_executable": "#!/usr/bin/env python3\n",
    }, executable=("scripts/tool",))
    package(tmp_path, "py_pkg", {
        "setup.py": "from setuptools import setup\nsetup(name='py_pkg', entry_points={'console_scripts': "
                    "['talker = py_pkg.talker:main']})\n",
        "setup.cfg": "[options.entry_points]\nconsole_scripts =\n    listener = py_pkg.listener:main\n",
        "py_pkg/__init__.py": "", "py_pkg/listener.py": "import rclpy\n",
        # an entry point's module with a __main__ block of its own is still one executable
        "py_pkg/talker.py": "import rclpy\ndef main():\n    rclpy.init()\nif __name__ == '__main__':\n    main()\n",
        "py_pkg/standalone.py": "import rclpy\nif __name__ == '__main__':\n    rclpy.init()\n",
        "py_pkg/util.py": "import rclpy\n",
    })
    package(tmp_path, "ignored", {"CATKIN_IGNORE": "", "CMakeLists.txt": "add_executable(x x.cpp)\n"})
    sink = DiagnosticSink()
    ws = Workspace([tmp_path], sink)
    assert set(ws.packages) == {"drivers", "py_pkg"} and sink.items == []
    drivers = ws.packages["drivers"]
    found = {name: (e.lang, [s.name for s in e.sources]) for name, e in drivers.executables.items()}
    assert found == {"driver": ("cpp", ["a.cpp"]), "gpu_node": ("cpp", ["main.cu", "helper.cpp"]),
                     "relay.py": ("python", ["relay.py"]), "env_run": ("other", ["env_run"]),
                     "tool": ("python", ["tool"])}
    assert [p.relative_to(drivers.path).as_posix() for p in drivers.include_dirs] == ["include", "extra/include"]
    py = {name: e.sources[0].name for name, e in ws.packages["py_pkg"].executables.items()}
    assert py == {"talker": "talker.py", "listener": "listener.py", "standalone.py": "standalone.py"}


def test_find_prefers_the_workspace_then_installed_packages(tmp_path: Path) -> None:
    package(tmp_path, "std_msgs", {})
    ws = Workspace([tmp_path], DiagnosticSink())
    assert ws.find("std_msgs") == tmp_path / "src" / "std_msgs"
    assert ws.find("nav_msgs") == Path("/usr/share/nav_msgs")
    assert ws.find("no_such_package_anywhere") is None


def test_bad_manifests_are_diagnostics(tmp_path: Path) -> None:
    package(tmp_path, "a", {})
    (tmp_path / "src" / "copy").mkdir(parents=True)
    (tmp_path / "src" / "copy" / "package.xml").write_text(MANIFEST.format("a"))
    (tmp_path / "src" / "broken").mkdir()
    (tmp_path / "src" / "broken" / "package.xml").write_text("<package><name>broken</name>")
    sink = DiagnosticSink()
    ws = Workspace([tmp_path], sink)
    assert set(ws.packages) == {"a", "broken"}
    assert sorted(d.code for d in sink.items) == ["duplicate-package", "package-xml"]


def test_cmake_loops_lists_and_skipped_function_bodies(tmp_path: Path) -> None:
    package(tmp_path, "loops", {
        "CMakeLists.txt": "project(loops)\nset(NODES talker listener)\nlist(APPEND NODES relay)\n"
                          "foreach(node ${NODES})\n  add_executable(${node}_node src/${node}.cpp)\nendforeach()\n"
                          "foreach(i RANGE 1 2)\n  add_executable(worker${i} src/worker.cpp)\nendforeach()\n"
                          "function(helper name)\n  add_executable(${name} src/never.cpp)\nendfunction()\n"
                          "if(WIN32)\n  add_executable(win_only src/win.cpp)\nendif()\n",
    })
    ws = Workspace([tmp_path], DiagnosticSink())
    assert sorted(ws.packages["loops"].executables) == ["listener_node", "relay_node", "talker_node", "win_only",
                                                         "worker1", "worker2"]
    assert ws.packages["loops"].executables["relay_node"].sources[0].name == "relay.cpp"


def test_ros2_components_ament_executables_and_cmake_functions(tmp_path: Path) -> None:
    package(tmp_path, "fleet", {
        "CMakeLists.txt": (
            "project(fleet)\nfind_package(ament_cmake REQUIRED)\n"
            "function(fleet_node target)\n  cmake_parse_arguments(ARG \"\" \"FOLDER\" \"EXTRA\" ${ARGN})\n"
            "  add_executable(${target} src/${ARG_FOLDER}/${target}.cpp ${ARG_EXTRA})\n"
            "  install(TARGETS ${target} DESTINATION lib/${PROJECT_NAME})\nendfunction()\n"
            "fleet_node(dispatcher FOLDER tasks EXTRA src/common.cpp)\n"
            "add_executable(monitor src/monitor.cpp)\ninstall(TARGETS monitor DESTINATION lib/${PROJECT_NAME})\n"
            "add_library(fleet_components SHARED src/odometer.cpp src/common.cpp)\n"
            "rclcpp_components_register_node(fleet_components PLUGIN \"fleet::Odometer\" EXECUTABLE odometer)\n"
            "rclcpp_components_register_nodes(fleet_components \"fleet::Charger\")\n"),
        "src/tasks/dispatcher.cpp": "", "src/common.cpp": "", "src/monitor.cpp": "", "src/odometer.cpp": "",
        "src/extra/probe.cpp": "#include <rclcpp_components/register_node_macro.hpp>\n\n"
                               "RCLCPP_COMPONENTS_REGISTER_NODE(fleet::Probe)\n",
    })
    executables = Workspace([tmp_path], DiagnosticSink()).packages["fleet"].executables
    found = {name: (exe.cls, [s.name for s in exe.sources], exe.line) for name, exe in executables.items()}
    assert found == {
        "dispatcher": (None, ["dispatcher.cpp", "common.cpp"], 8),
        "monitor": (None, ["monitor.cpp"], 9),
        "fleet::Odometer": ("fleet::Odometer", ["odometer.cpp", "common.cpp"], 12),
        "odometer": ("fleet::Odometer", ["odometer.cpp", "common.cpp"], 12),
        "fleet::Charger": ("fleet::Charger", ["odometer.cpp", "common.cpp"], 13),
        "fleet::Probe": ("fleet::Probe", ["probe.cpp"], 3),
    }
    # rosrun runs the programs: the component's EXECUTABLE is one, the components themselves are not
    summaries = {("fleet", name): NodeSummary("fleet", name, "cpp") for name in executables}
    config = rosrun_config(summaries, Workspace([tmp_path], DiagnosticSink()), DiagnosticSink())
    assert sorted(node.type for node in config.nodes) == ["dispatcher", "monitor", "odometer"]


def test_ament_executables_get_the_sources_of_the_libraries_they_link(tmp_path: Path) -> None:
    manifest = MANIFEST.format("depot").replace("</license>", "</license><buildtool_depend>ament_cmake</buildtool_depend>")
    package(tmp_path, "depot", {
        "package.xml": manifest,
        "CMakeLists.txt": "project(depot)\nadd_library(depot_core src/loader.cpp src/scheduler.cpp src/geometry.cpp)\n"
                          "add_executable(loader src/loader_main.cpp)\ntarget_link_libraries(loader PRIVATE depot_core)\n",
        "src/loader_main.cpp": "int main() { auto node = std::make_shared<depot::Loader>(); }\n",
        "src/loader.cpp": "Loader::Loader(const rclcpp::NodeOptions & options)\n: Node(\"loader\", options) {}\n",
        "src/scheduler.cpp": "Scheduler::Scheduler()\n: rclcpp::Node(\"scheduler\") {}\n",
        "src/geometry.cpp": "double area() { return 1.0; }\n",
    })
    loader = Workspace([tmp_path], DiagnosticSink()).packages["depot"].executables["loader"]
    assert [s.name for s in loader.sources] == ["loader_main.cpp", "loader.cpp", "geometry.cpp"]



def test_catkin_executables_read_the_libraries_of_their_package_they_link(tmp_path: Path) -> None:
    """A ROS 1 node whose code sits in a library of its own package (transitively); a library
    source exporting a nodelet whose class the node never names is not its code (one it loads by
    plugin name runs under its own name: test_nodelets); a source named without its
    extension is found as CMake finds it, and a missing one is kept (reported when it is read)."""
    package(tmp_path, "tracking", {
        "CMakeLists.txt": "project(tracking)\nadd_library(core src/core.cpp)\n"
                          "add_library(${PROJECT_NAME}_ros src/ros.cpp src/debayer.cpp src/rectify.cpp)\n"
                          "target_link_libraries(${PROJECT_NAME}_ros core ${catkin_LIBRARIES})\n"
                          "add_executable(tracker src/main)\ntarget_link_libraries(tracker tracking_ros)\n"
                          "add_executable(lost src/gone)\n",
        "package.xml": MANIFEST.format("tracking").replace(
            "</package>", "<export><nodelet plugin='${prefix}/nodelets.xml'/></export></package>"),
        "nodelets.xml": "<library path='lib/libtracking_ros'><class name='tracking/debayer' type='t::Debayer' "
                        "base_class_type='nodelet::Nodelet'/><class name='tracking/rectify' type='t::Rectify' "
                        "base_class_type='nodelet::Nodelet'/></library>",
        "src/main.cpp": 'int main() { loader.load("tracking/rectify"); t::Debayer d; }\n', "src/ros.cpp": "",
        "src/core.cpp": "",
        "src/debayer.cpp": "PLUGINLIB_EXPORT_CLASS(t::Debayer, nodelet::Nodelet)\n",
        "src/rectify.cpp": "PLUGINLIB_EXPORT_CLASS(t::Rectify, nodelet::Nodelet)\n",
    })
    sink = DiagnosticSink()
    exes = Workspace([tmp_path], sink).packages["tracking"].executables
    assert [s.name for s in exes["tracker"].sources] == ["main.cpp", "ros.cpp", "core.cpp", "debayer.cpp"]
    assert [s.name for s in exes["tracker"].linked] == ["ros.cpp", "core.cpp", "debayer.cpp"]
    assert [s.name for s in exes["lost"].sources] == ["gone"]


def test_catkin_library_sources_of_classes_the_node_never_names_are_not_its_code(tmp_path: Path) -> None:
    """tf2_ros's library defines Buffer, TransformListener and StaticTransformBroadcaster:
    static_transform_publisher, which names only the broadcaster, does not subscribe /tf; a source
    defining a class named by another source it reads is read too (transitively)."""
    package(tmp_path, "tfkit", {
        "CMakeLists.txt": "project(tfkit)\nadd_library(tfkit src/buffer.cpp src/listener.cpp src/static.cpp "
                          "src/util.cpp)\nadd_executable(static_publisher src/main.cpp)\n"
                          "target_link_libraries(static_publisher tfkit)\n",
        "package.xml": MANIFEST.format("tfkit"),
        "src/main.cpp": "int main() { tfkit::StaticBroadcaster b; }\n",
        "src/static.cpp": "StaticBroadcaster::StaticBroadcaster() { Util u; }\n",
        "src/util.cpp": "Util::Util() {}\n",
        "src/buffer.cpp": "Buffer::Buffer() {}\n",
        "src/listener.cpp": "Listener::Listener(Buffer& b) {}\n",
    })
    exe = Workspace([tmp_path], DiagnosticSink()).packages["tfkit"].executables["static_publisher"]
    assert [s.name for s in exe.sources] == ["main.cpp", "static.cpp", "util.cpp"]
    assert [s.name for s in exe.linked] == ["static.cpp", "util.cpp"]


def test_a_package_version_comes_from_the_package_xml_find_would_use(tmp_path: Path) -> None:
    package(tmp_path, "actionlib", {})  # the workspace's copy comes before the installed one
    package(tmp_path, "local_nav", {"package.xml": MANIFEST.format("local_nav").replace("0.1.0", "1.16.7")})
    installed = next(d / "tf2" for d in share_dirs() if (d / "tf2" / "package.xml").is_file())
    workspace = Workspace([tmp_path], DiagnosticSink())
    assert workspace.version("actionlib") == "0.1.0" and workspace.version("local_nav") == "1.16.7"
    assert workspace.version("tf2") == parse_package(str(installed / "package.xml")).version
    assert workspace.version("no_such_package") is None
