"""Hostile files (issue 15): every file archlog reads stays inside the analysed paths, is a
regular file under its size cap, and is decoded without raising.

Each generated case points one of archlog's read paths (launch <param textfile>, <rosparam file>,
<include>, rviz -d, ROS 2 parameter files, FileContent, open() in Python launch files, C++
#include) at something it must not read: the secret file outside the workspace by absolute path,
`..` path, symlink or symlinked folder, /proc/self/environ, devices, a FIFO, a folder, a symlink
loop, a file over the cap. Each run must finish quickly with no canary in its report, no
traceback, and the sandbox's diagnostic code at the line that named the file.
"""

from __future__ import annotations

import json
import os
import textwrap
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import pytest
from support.hostile import Outside, problems, run_check

CATKIN_XML = """<?xml version="1.0"?>
<package format="2"><name>{name}</name><version>0.0.1</version><description>d</description>
<maintainer email="dev@example.com">m</maintainer><license>MIT</license>
<buildtool_depend>catkin</buildtool_depend><depend>roscpp</depend></package>
"""
AMENT_XML = """<?xml version="1.0"?>
<package format="3"><name>{name}</name><version>0.0.1</version><description>d</description>
<maintainer email="dev@example.com">m</maintainer><license>MIT</license>
<buildtool_depend>ament_cmake</buildtool_depend><export><build_type>ament_cmake</build_type></export></package>
"""
CMAKE = """cmake_minimum_required(VERSION 3.0.2)
project(demo)
find_package(catkin REQUIRED COMPONENTS roscpp)
add_executable(node src/node.cpp)
"""


@dataclass
class Target:
    """A file a case names, and the diagnostic code archlog must give for it."""

    path: str
    code: str


def _write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text).lstrip())
    return path


def _package(ws: Path, name: str = "demo", manifest: str = CATKIN_XML) -> Path:
    package = ws / name
    _write(package / "package.xml", manifest.format(name=name))
    return package


# -- what the read paths are pointed at -----------------------------------------------------
def _config(pkg: Path, name: str) -> Path:
    """pkg/config/NAME, its folder made."""
    (pkg / "config").mkdir(exist_ok=True)
    return pkg / "config" / name


def absolute(_pkg: Path, out: Outside) -> Target:
    return Target(str(out.secret_file), "outside-workspace")


def dotdot(pkg: Path, out: Outside) -> Target:
    folder = pkg / "config"  # the path goes through it: it must exist for ../ to resolve
    folder.mkdir(exist_ok=True)
    return Target(f"{folder}/{os.path.relpath(out.secret_file, folder)}", "outside-workspace")


def symlink(pkg: Path, out: Outside) -> Target:
    link = _config(pkg, "link.yaml")
    link.symlink_to(out.secret_file)
    return Target(str(link), "outside-workspace")


def symlinked_folder(pkg: Path, out: Outside) -> Target:
    (pkg / "shared").symlink_to(out.root, target_is_directory=True)
    return Target(str(pkg / "shared" / out.secret_file.name), "outside-workspace")


def environ(_pkg: Path, _out: Outside) -> Target:
    return Target("/proc/self/environ", "outside-workspace")


def dev_zero(_pkg: Path, _out: Outside) -> Target:
    return Target("/dev/zero", "outside-workspace")


def dev_urandom(_pkg: Path, _out: Outside) -> Target:
    return Target("/dev/urandom", "outside-workspace")


def zero_link(pkg: Path, _out: Outside) -> Target:
    link = _config(pkg, "zero.yaml")
    link.symlink_to("/dev/zero")
    return Target(str(link), "outside-workspace")


def fifo(pkg: Path, _out: Outside) -> Target:
    pipe = _config(pkg, "pipe.yaml")
    os.mkfifo(pipe)
    return Target(str(pipe), "not-a-file")


def directory(pkg: Path, _out: Outside) -> Target:
    folder = _config(pkg, "folder.yaml")
    folder.mkdir()
    return Target(str(folder), "not-a-file")


def loop(pkg: Path, _out: Outside) -> Target:
    link = _config(pkg, "loop.yaml")
    link.symlink_to(link.name)
    return Target(str(link), "not-a-file")


def too_large(pkg: Path, _out: Outside) -> Target:
    big = _config(pkg, "big.yaml")
    with big.open("wb") as handle:
        handle.truncate(9 << 20)  # sparse: over every size cap
    return Target(str(big), "too-large")


TARGETS: list[Callable[[Path, Outside], Target]] = [absolute, dotdot, symlink, symlinked_folder, environ, dev_zero,
                                                    dev_urandom, zero_link, fifo, directory, loop, too_large]


def _diagnostics(out: Outside) -> set[tuple[str, int, str]]:
    report = json.loads((out.root / "report.json").read_text())
    return {(d["file"], d["line"], d["code"]) for d in report["diagnostics"]}


def _check(ws: Path, out: Outside, *options: str) -> set[tuple[str, int, str]]:
    """The run's diagnostics (file, line, code), once the run is judged clean."""
    run = run_check(ws, out, *options, fmt="json")
    assert problems(run, out) == []
    return _diagnostics(out)


# -- the cases ------------------------------------------------------------------------------
@pytest.mark.parametrize("target", TARGETS, ids=lambda t: t.__name__)
def test_launch_and_cpp_reads(tmp_path: Path, target: Callable[[Path, Outside], Target]) -> None:
    """ROS 1 launch (textfile, rosparam, include, rviz), a C++ #include and ROS 2 Python launch
    (open(), FileContent, parameter files, include) name the target: each is refused there."""
    ws, out = tmp_path / "ws", Outside(tmp_path / "outside")
    pkg = _package(ws)
    aim = target(pkg, out)
    _write(pkg / "CMakeLists.txt", CMAKE)
    _write(pkg / "src" / "node.cpp", f"""
        #include <ros/ros.h>
        #include "{aim.path}"
        int main(int argc, char** argv) {{
          ros::init(argc, argv, "node");
          ros::NodeHandle nh;
          ros::Publisher pub = nh.advertise<std_msgs::String>("chatter", 10);
        }}
        """)
    _write(pkg / "launch" / "all.launch", f"""
        <launch>
          <param name="text" textfile="{aim.path}"/>
          <rosparam file="{aim.path}"/>
          <include file="{aim.path}"/>
          <node pkg="rviz" type="rviz" name="rviz" args="-d {aim.path}"/>
          <node pkg="demo" type="node" name="node"/>
        </launch>
        """)
    _write(pkg / "launch" / "all.launch.py", f"""
        from launch import LaunchDescription
        from launch.actions import IncludeLaunchDescription
        from launch.launch_description_sources import PythonLaunchDescriptionSource
        from launch.substitutions import FileContent
        from launch_ros.actions import Node

        def generate_launch_description():
            name = open("{aim.path}").read()
            return LaunchDescription([
                Node(package="demo", executable="a", name="a", parameters=["{aim.path}"]),
                Node(package="demo", executable="b", name="b", parameters=[{{"x": FileContent("{aim.path}")}}]),
                IncludeLaunchDescription(PythonLaunchDescriptionSource("{aim.path}")),
                Node(package="demo", executable="c", name=name),
            ])
        """)
    found = _check(ws, out, "--launch", str(pkg / "launch" / "all.launch"),
                   "--launch", str(pkg / "launch" / "all.launch.py"))
    launch, python = "demo/launch/all.launch", "demo/launch/all.launch.py"
    assert {(launch, line, aim.code) for line in (2, 3, 4, 5)} <= found
    assert ("demo/src/node.cpp", 2, aim.code) in found
    assert {(python, line, aim.code) for line in (8, 10, 11, 12)} <= found


@pytest.mark.parametrize("fmt", ["text", "sarif"])
def test_no_leak_in_any_format(tmp_path: Path, fmt: str) -> None:
    """The same refusals, reported as text and SARIF, never quote the secret."""
    ws, out = tmp_path / "ws", Outside(tmp_path / "outside")
    pkg = _package(ws)
    aims = [absolute(pkg, out), symlink(pkg, out), environ(pkg, out)]
    elements = "".join(f'<param name="t{k}" textfile="{a.path}"/><rosparam file="{a.path}"/>'
                       f'<node pkg="rviz" type="rviz" name="rviz{k}" args="-d {a.path}"/>\n' for k, a in enumerate(aims))
    _write(pkg / "launch" / "all.launch", f"<launch>\n{elements}</launch>\n")
    run = run_check(ws, out, "--launch", str(pkg / "launch" / "all.launch"), fmt=fmt)
    assert problems(run, out) == []
    assert run.output.count("outside-workspace") >= 9


def test_named_launch_file_linked_out(tmp_path: Path) -> None:
    """The launch file CI names is, in the pull request, a symlink to the secret: not read."""
    ws, out = tmp_path / "ws", Outside(tmp_path / "outside")
    link = _package(ws) / "launch" / "main.launch.yaml"
    link.parent.mkdir()
    link.symlink_to(out.secret_file)
    assert ("demo/launch/main.launch.yaml", 1, "outside-workspace") in _check(ws, out, "--launch", str(link))


def test_existence_outside_is_not_probed(tmp_path: Path) -> None:
    """os.path.exists and Path.is_file on a file outside: unknown, whatever the machine holds."""
    ws, out = tmp_path / "ws", Outside(tmp_path / "outside")
    launch = _write(_package(ws) / "launch" / "probe.launch.py", f"""
        import os
        from pathlib import Path
        from launch import LaunchDescription
        from launch_ros.actions import Node

        def generate_launch_description():
            here = os.path.exists("{out.secret_file}") or Path("{out.secret_file}").is_file()
            return LaunchDescription([Node(package="demo", executable="a", name="found" if here else "absent")])
        """)
    assert ("demo/launch/probe.launch.py", 8, "node-name") in _check(ws, out, "--launch", str(launch))


def test_ros2_frontends_and_params(tmp_path: Path) -> None:
    """ROS 2 XML and YAML launch files: an included file and parameter files outside, a FIFO."""
    ws, out = tmp_path / "ws", Outside(tmp_path / "outside")
    pkg = _package(ws, "demo2", AMENT_XML)
    pipe = fifo(pkg, out)
    _write(pkg / "launch" / "main.launch.xml", f"""
        <launch>
          <include file="{out.secret_file}"/>
          <node pkg="demo2" exec="a" name="a"><param from="{out.secret_file}"/></node>
          <node pkg="demo2" exec="b" name="b"><param from="{pipe.path}"/></node>
          <include file="$(dirname)/main.launch.yaml"/>
        </launch>
        """)
    _write(pkg / "launch" / "main.launch.yaml", f"""
        launch:
        - include:
            file: "{pipe.path}"
        - node:
            pkg: demo2
            exec: c
            name: c
            param:
            - from: "{out.secret_file}"
        """)
    found = _check(ws, out, "--launch", str(pkg / "launch" / "main.launch.xml"))
    xml, yml = "demo2/launch/main.launch.xml", "demo2/launch/main.launch.yaml"
    assert {(xml, 2, "outside-workspace"), (xml, 3, "outside-workspace"), (xml, 4, "not-a-file"),
            (yml, 3, "not-a-file"), (yml, 9, "outside-workspace")} <= found


def test_sources_and_build_files_outside(tmp_path: Path) -> None:
    """Sources symlinked out, CMake folders and include folders outside, a compile database that
    force-includes the secret: nothing of the secret is read."""
    ws, out = tmp_path / "ws", Outside(tmp_path / "outside")
    pkg = _package(ws)
    (out.root / "sub").mkdir()
    (out.root / "sub" / "CMakeLists.txt").write_text(f"add_executable({out.secret} x.cpp)\n")
    _write(pkg / "CMakeLists.txt", CMAKE + f"""
        add_executable(linked src/linked.cpp)
        add_subdirectory({out.root / "sub"})
        include_directories({out.root})
        catkin_install_python(PROGRAMS scripts/linked.py DESTINATION bin)
        """)
    _write(pkg / "src" / "node.cpp", '#include "secret.yaml"\nint main() {}\n')
    (pkg / "src" / "linked.cpp").symlink_to(out.secret_file)
    (pkg / "scripts").mkdir()
    (pkg / "scripts" / "linked.py").symlink_to(out.secret_file)
    _write(ws / "compile_commands.json", json.dumps([{
        "directory": str(pkg), "file": "src/node.cpp",
        "arguments": ["c++", "-include", str(out.secret_file), f"-I{out.root}", "-c", "src/node.cpp"]}]))
    found = _check(ws, out)
    assert {("demo/src/linked.cpp", 1, "outside-workspace"), ("demo/scripts/linked.py", 1, "outside-workspace"),
            ("demo/CMakeLists.txt", 7, "outside-workspace")} <= found


def test_xml_external_entities(tmp_path: Path) -> None:
    """An external entity naming the secret, in ROS 1 and ROS 2 XML launch files and in a plugin
    description, is never loaded (an include naming it would print it)."""
    ws, out = tmp_path / "ws", Outside(tmp_path / "outside")
    pkg = _package(ws)
    doctype = f'<?xml version="1.0"?>\n<!DOCTYPE launch [<!ENTITY x SYSTEM "file://{out.secret_file}">]>\n'
    _write(pkg / "launch" / "one.launch", doctype + '<launch><include file="&x;"/></launch>\n')
    _write(pkg / "launch" / "two.launch.xml", doctype + '<launch><include file="&x;"/></launch>\n')
    _write(pkg / "plugins.xml", doctype.replace("launch", "library") + '<library path="&x;"/>\n')
    (pkg / "package.xml").write_text(CATKIN_XML.format(name="demo").replace(
        "</package>", '<export><nodelet plugin="${prefix}/plugins.xml"/></export></package>'))
    found = _check(ws, out, "--launch", str(pkg / "launch" / "one.launch"), "--launch",
                   str(pkg / "launch" / "two.launch.xml"))
    assert {("demo/launch/one.launch", 3, "launch-xml"), ("demo/launch/two.launch.xml", 3, "launch-xml")} <= found


def test_walks_stay_inside(tmp_path: Path) -> None:
    """Folders symlinked to / or outside, and symlink loops, in the places the workspace walk
    and the script, source and header searches look."""
    ws, out = tmp_path / "ws", Outside(tmp_path / "outside")
    pkg = _package(ws)
    _write(pkg / "CMakeLists.txt", CMAKE + "include_directories(include)\n")
    _write(pkg / "src" / "node.cpp", '#include "demo/node.h"\nint main() {}\n')
    (pkg / "include").mkdir()
    (pkg / "include" / "demo").symlink_to("/", target_is_directory=True)
    (pkg / "nodes").symlink_to("/", target_is_directory=True)
    (pkg / "scripts").mkdir()
    (pkg / "scripts" / "a").symlink_to("b")
    (pkg / "scripts" / "b").symlink_to("a")
    (pkg / "scripts" / "self").symlink_to("self")
    (pkg / "msg").symlink_to(out.root, target_is_directory=True)
    (out.root / "Secret.msg").write_text(f"string {out.secret}\n")
    (ws / "elsewhere").symlink_to(out.root, target_is_directory=True)
    _package(out.root, "outside_pkg")
    (ws / "loop").symlink_to(ws / "loop")
    (ws / "looped").mkdir()
    (ws / "looped" / "package.xml").symlink_to("package.xml")
    (pkg / "src" / "loop.cpp").symlink_to("loop.cpp")
    (pkg / "CMakeLists.txt").write_text((pkg / "CMakeLists.txt").read_text() + "add_executable(looped src/loop.cpp)\n")
    found = _check(ws, out)
    assert ("demo/msg/Secret.msg", 1, "outside-workspace") in found
    assert {("looped/package.xml", 1, "not-a-file"), ("demo/src/loop.cpp", 1, "not-a-file")} <= found
    assert not any(file.startswith("elsewhere") for file, _line, _code in found)


BAD = b"\xff\xfe\x80 \xc3\x28"


def test_invalid_utf8_everywhere(tmp_path: Path) -> None:
    """Bytes that are not UTF-8 in every kind of file archlog decodes: no UnicodeDecodeError."""
    ws, out = tmp_path / "ws", Outside(tmp_path / "outside")
    pkg = _package(ws)
    (pkg / "package.xml").write_bytes(CATKIN_XML.format(name="demo").encode().replace(b"<description>d",
                                                                                    b"<description>d" + BAD))
    (pkg / "CMakeLists.txt").write_bytes(CMAKE.encode() + b"# " + BAD + b"\n")
    (pkg / "setup.cfg").write_bytes(b"[options.entry_points]\n# " + BAD + b"\nconsole_scripts =\n  t = demo.t:main\n")
    (pkg / "setup.py").write_bytes(b"# " + BAD + b"\nfrom setuptools import setup\nsetup()\n")
    (pkg / "src").mkdir()
    (pkg / "src" / "node.cpp").write_bytes(b"// " + BAD + b"\nint main() {}\n")
    (pkg / "config").mkdir()
    (pkg / "config" / "params.yaml").write_bytes(b"a: 1\n# " + BAD + b"\nb: \"" + BAD + b"\"\n")
    (pkg / "config" / "ros2.yaml").write_bytes(b"/**:\n  ros__parameters:\n    # " + BAD + b"\n    x: \""
                                               + BAD + b"\"\n")
    (pkg / "config" / "view.rviz").write_bytes(b"Visualization Manager:\n  Displays: []\n# " + BAD + b"\n")
    (pkg / "config" / "robot.urdf").write_bytes(b"<robot name='r'><!-- " + BAD + b" --></robot>\n")
    (pkg / "model.yaml").write_bytes(b"# " + BAD + b"\npackage: x\nexecutable: y\n")
    (ws / "archlog.toml").write_bytes(b"# " + BAD + b"\n")
    (pkg / "launch").mkdir()
    (pkg / "launch" / "bad.launch").write_bytes(b"<launch>\n  <!-- " + BAD + b" -->\n</launch>\n")
    (pkg / "launch" / "all.launch").write_bytes(b"""<launch>
  <include file="$(find demo)/launch/bad.launch"/>
  <param name="robot_description" textfile="$(find demo)/config/robot.urdf"/>
  <rosparam file="$(find demo)/config/params.yaml"/>
  <node pkg="rviz" type="rviz" name="rviz" args="-d $(find demo)/config/view.rviz"/>
  <node pkg="demo" type="node" name="node"/>
  <include file="$(find demo)/launch/two.launch.yaml"/>
</launch>
""")
    (pkg / "launch" / "two.launch.yaml").write_bytes(b"# " + BAD + b"\nlaunch:\n- node:\n    pkg: demo\n"
                                                     b"    exec: a\n    param:\n    - from: " + str(pkg).encode()
                                                     + b"/config/ros2.yaml\n")
    found = _check(ws, out, "--launch", str(pkg / "launch" / "all.launch"), "--model", str(pkg / "model.yaml"))
    assert ("demo/launch/bad.launch", 2, "launch-xml") in found  # as roslaunch, which rejects it too
    assert not {code for _f, _l, code in found} & {"not-a-file", "param-file", "model-yaml", "rviz-config",
                                                   "package-xml", "setup-cfg", "setup-py", "launch-yaml"}


def test_includes_through_macros_and_nul_bytes(tmp_path: Path) -> None:
    """An #include that takes a macro naming a FIFO or the secret, and strings with NUL bytes in
    a Python launch file and a compile database."""
    ws, out = tmp_path / "ws", Outside(tmp_path / "outside")
    pkg = _package(ws)
    pipe = fifo(pkg, out)
    _write(pkg / "CMakeLists.txt", CMAKE)
    _write(pkg / "src" / "node.cpp", f"""
        #define PIPE "{pipe.path}"
        #define STR(x) #x
        #define SECRET(x) STR(x)
        #include PIPE
        #include SECRET({out.secret_file})
        #define CAT(a, b) a##b
        #include SECRET(CAT(fi, fo).h)
        int main() {{}}
        """)
    os.mkfifo(pkg / "src" / "fifo.h")  # named by no string: only token pasting makes its name
    _write(ws / "compile_commands.json", json.dumps([{"directory": str(pkg), "file": "src/node.cpp",
                                                      "arguments": ["c++", "-I/tmp\0", "-c", "src/node.cpp"]}]))
    _write(pkg / "launch" / "nul.launch.py", """
        from launch import LaunchDescription
        from launch_ros.actions import Node

        def generate_launch_description():
            return LaunchDescription([Node(package="demo", executable="node", name=open("a\\0b").read())])
        """)
    found = _check(ws, out, "--launch", str(pkg / "launch" / "nul.launch.py"))
    assert {("demo/src/node.cpp", 4, "not-a-file"), ("demo/src/node.cpp", 5, "outside-workspace"),
            ("demo/src/node.cpp", 7, "not-a-file"),
            ("demo/launch/nul.launch.py", 5, "not-a-file")} <= found
