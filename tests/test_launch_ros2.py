"""ROS 2 launch files: the XML, YAML and Python dialects read into one LaunchConfig."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest
from conftest import ROOT

from archlog import sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.model import LaunchConfig, LaunchNode
from archlog.extract.launch.ros1 import LaunchInterpreter
from archlog.extract.workspace.index import Workspace
from archlog.values import Unknown

WS = ROOT / "corpus" / "launch_ros2" / "ws"
PACKAGE_XML = """<?xml version="1.0"?>
<package format="3"><name>{name}</name><version>0.0.1</version><description>d</description>
<maintainer email="dev@example.com">m</maintainer><license>MIT</license></package>
"""


def load(tmp_path: Path, files: dict[str, str], main: str, args: dict[str, str] | None = None
         ) -> tuple[LaunchConfig, DiagnosticSink]:
    """Write `files` (dedented) under tmp_path and launch `main`; a `pkg/...` path makes a package."""
    for name, content in files.items():
        path = tmp_path / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(content).lstrip())
        if "/" in name and not (tmp_path / name.split("/")[0] / "package.xml").exists():
            (tmp_path / name.split("/")[0] / "package.xml").write_text(PACKAGE_XML.format(name=name.split("/")[0]))
    sink = DiagnosticSink()
    config = LaunchInterpreter(Workspace([tmp_path], sink), sink).load([tmp_path / main], args or {})
    return config, sink


def by_name(config: LaunchConfig) -> dict[str, LaunchNode]:
    return {n.name or f"<{n.type}>": n for n in config.nodes}


def remaps(node: LaunchNode) -> list[tuple[str, str]]:
    return [(a, b) for a, b, _ in node.remaps]


def params(node: LaunchNode) -> list[tuple[str, str, object]]:
    return [(pattern, name, value) for pattern, name, value, _ in node.parameters]


def codes(sink: DiagnosticSink) -> list[tuple[str, int, str]]:
    return [(Path(d.file).name, d.line, d.code) for d in sink.items]


def view(config: LaunchConfig) -> list[tuple]:
    """What a dialect must agree on: every node with its names, remaps, parameters and context."""
    return [(n.pkg, n.type, n.name, n.namespace, n.plugin, n.manager, n.condition, n.args, remaps(n), params(n),
             len(n.chain)) for n in config.nodes]


# -- the three dialects ---------------------------------------------------------------------
def test_the_three_dialects_of_one_system_agree() -> None:
    views = {}
    for suffix in ("xml", "yaml", "py"):
        sink = DiagnosticSink()
        path = WS / "demo_bringup" / "launch" / f"system.launch.{suffix}"
        views[suffix] = view(LaunchInterpreter(Workspace([WS], sink), sink).load([path], {}))
        assert sorted(d.code for d in sink.items) == ["env-default", "launch-arg-unknown", "launch-condition"], \
            sink.items
    assert views["xml"] == views["yaml"] == views["py"]


def test_the_demo_system_as_launch_would_start_it() -> None:
    sink = DiagnosticSink()
    config = LaunchInterpreter(Workspace([WS], sink), sink).load([WS / "demo_bringup/launch/system.launch.xml"], {})
    nodes = by_name(config)
    assert list(nodes) == ["/demo/talker", "/demo/sub/listener2", "/abs/absolute_listener", "/r1/driver",
                           "/r2/driver", "/r2_monitor", "/sim_clock", "/camera_talker", "/env_talker",
                           "/eval_talker", "/containers/comp", "/ctalker", "/cl/clistener"]
    talker = nodes["/demo/talker"]
    assert (talker.namespace, remaps(talker)) == ("/demo", [("chatter", "talk"), ("topic", "chatter")])
    assert params(talker)[:3] == [("", "use_sim_time", False), ("", "rate", 2), ("", "qos.depth", 5)]
    assert ("talker", "qos.reliability", "reliable") in params(talker)
    assert ("/**/driver", "gains", [1.0, 0.5, 0.25]) in params(talker)  # every entry of the file is kept
    assert remaps(nodes["/demo/sub/listener2"]) == [("chatter", "talk")]  # set_remap reaches the whole group
    assert remaps(nodes["/abs/absolute_listener"]) == []  # ... and no further
    driver = nodes["/r2/driver"]
    assert params(driver)[-1] == ("", "robot_name", "r2") and len(driver.chain) == 1
    assert nodes["/camera_talker"].condition.startswith('if="$(var camera)"')
    component = nodes["/ctalker"]
    assert (component.kind, component.manager, component.namespace) == \
        (("composition", "composition::Talker"), "/containers/comp", "")
    assert nodes["/cl/clistener"].manager == "/containers/comp"
    assert nodes["/demo/talker"].elem.file == "demo_bringup/launch/system.launch.xml"
    assert nodes["/demo/talker"].parameters[4][3].file == "demo_bringup/config/params.yaml"


@pytest.mark.parametrize("outer, inner", [("xml", "py"), ("yaml", "xml"), ("py", "yaml")])
def test_a_dialect_includes_another(tmp_path: Path, outer: str, inner: str) -> None:
    child = {
        "py": """
            from launch import LaunchDescription
            from launch.actions import DeclareLaunchArgument
            from launch.substitutions import LaunchConfiguration
            from launch_ros.actions import Node
            def generate_launch_description():
                return LaunchDescription([DeclareLaunchArgument('who', default_value='nobody'),
                                          Node(package='p', executable='e', name=LaunchConfiguration('who'))])
            """,
        "xml": """
            <launch>
              <arg name="who" default="nobody"/>
              <node pkg="p" exec="e" name="$(var who)"/>
            </launch>
            """,
        "yaml": """
            launch:
            - arg: {name: who, default: nobody}
            - node: {pkg: p, exec: e, name: $(var who)}
            """,
    }[inner]
    target = f"$(find-pkg-share pkg)/child.{inner}"
    source = {"py": "PythonLaunchDescriptionSource", "xml": "XMLLaunchDescriptionSource",
              "yaml": "YAMLLaunchDescriptionSource"}[inner]
    parent = {
        "xml": f'<launch><include file="{target}"><arg name="who" value="alice"/></include></launch>',
        "yaml": f"launch:\n- include:\n    file: {target}\n    arg: [{{name: who, value: alice}}]\n",
        "py": f"""
            from launch import LaunchDescription
            from launch.actions import IncludeLaunchDescription
            from launch.launch_description_sources import PythonLaunchDescriptionSource
            from launch_ros.substitutions import FindPackageShare
            from launch_xml.launch_description_sources import XMLLaunchDescriptionSource
            from launch_yaml.launch_description_sources import YAMLLaunchDescriptionSource
            def generate_launch_description():
                source = {source}([FindPackageShare('pkg'), '/child.{inner}'])
                return LaunchDescription([IncludeLaunchDescription(source, launch_arguments={{'who': 'alice'}})])
            """,
    }[outer]
    config, sink = load(tmp_path, {f"pkg/child.{inner}": child, f"main.{outer}": parent}, f"main.{outer}")
    assert [n.name for n in config.nodes] == ["/alice"] and sink.items == []


# -- XML and YAML constructs ----------------------------------------------------------------
def test_xml_node_attributes_params_and_remaps(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"pkg/cfg.yaml": """
        talker:
          ros__parameters:
            rate: 5
        """, "main.xml": """
        <launch>
          <node pkg="demo" exec="talker" name="t" namespace="ns" args="--flag 'two words'" ros_args="-p x:=1"
                launch-prefix="gdb -ex run" output="screen" respawn="true">
            <param name="int" value="2"/>
            <param name="text" value="2" type="str"/>
            <param name="list" value="1,2,3" value-sep=","/>
            <param name="yaml_list" value="[a, b]"/>
            <param name="outer"><param name="inner"><param name="leaf" value="true"/></param></param>
            <param from="$(find-pkg-share pkg)/cfg.yaml"/>
            <remap from="a" to="b"/>
            <env name="X" value="1"/>
          </node>
        </launch>
        """}, "main.xml")
    node = config.nodes[0]
    assert (node.pkg, node.type, node.name, node.namespace) == ("demo", "talker", "/ns/t", "/ns")
    assert node.args == "--flag 'two words'"
    assert params(node) == [("", "x", 1), ("", "int", 2), ("", "text", "2"), ("", "list", [1, 2, 3]),
                            ("", "yaml_list", ["a", "b"]), ("", "outer.inner.leaf", True), ("talker", "rate", 5)]
    assert remaps(node) == [("a", "b")] and sink.items == []
    assert node.parameters[-1][3].file == "pkg/cfg.yaml" and node.parameters[-1][3].line == 3


def test_yaml_frontend_entities(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"main.yaml": """
        launch:
        - let: {name: base, value: robot}
        - group:
            scoped: "false"
            children:
            - push_ros_namespace: {namespace: $(var base)}
        - node:
            pkg: demo
            exec: talker
            name: t
            param:
            - {name: typed, value: 3}
            - {name: text, value: "3"}
            - {name: flag, value: true}
            - {name: nested, param: [{name: leaf, value: [1.5, 2.5]}]}
            remap:
            - {from: chatter, to: $(var base)_chatter}
        """}, "main.yaml")
    node = config.nodes[0]
    assert (node.name, node.namespace) == ("/robot/t", "/robot")  # the unscoped group's push stays
    assert params(node) == [("", "typed", 3), ("", "text", "3"), ("", "flag", True), ("", "nested.leaf", [1.5, 2.5])]
    assert remaps(node) == [("chatter", "robot_chatter")] and sink.items == []


def test_namespaces_follow_launch_ros(tmp_path: Path) -> None:
    config, _ = load(tmp_path, {"main.xml": """
        <launch>
          <group>
            <push-ros-namespace namespace="a"/>
            <push-ros-namespace namespace="b"/>
            <node pkg="p" exec="e" name="relative" namespace="c"/>
            <node pkg="p" exec="e" name="absolute" namespace="/top"/>
            <node pkg="p" exec="e" name="pushed"/>
            <node pkg="p" exec="e"/>
            <group>
              <push-ros-namespace namespace="/reset"/>
              <node pkg="p" exec="e" name="reset"/>
            </group>
          </group>
          <node pkg="p" exec="e" name="outside"/>
          <node pkg="p" exec="e" name="slashes" namespace="x/"/>
        </launch>
        """}, "main.xml")
    assert [(n.name, n.namespace) for n in config.nodes] == [
        ("/a/b/c/relative", "/a/b/c"), ("/top/absolute", "/top"), ("/a/b/pushed", "/a/b"), ("", "/a/b"),
        ("/reset/reset", "/reset"), ("/outside", ""), ("/x/slashes", "/x")]


def test_scoping_of_groups_includes_and_set_remap(tmp_path: Path) -> None:
    """Groups are scoped unless scoped="false"; includes are not scoped (what they set stays);
    set_remap and set_parameter reach the nodes after them in their scope."""
    config, sink = load(tmp_path, {"child.xml": """
        <launch>
          <arg name="leaked" default="from_child"/>
          <set_remap from="x" to="child_x"/>
        </launch>
        """, "main.xml": """
        <launch>
          <group>
            <let name="scoped" value="no"/>
            <set_remap from="a" to="group_a"/>
            <set_parameter name="p" value="1"/>
            <node pkg="p" exec="e" name="in_group"/>
          </group>
          <group scoped="false"><let name="kept" value="yes"/></group>
          <include file="$(dirname)/child.xml"/>
          <node pkg="p" exec="e" name="$(var leaked)_$(var kept)_$(var scoped default)"/>
        </launch>
        """}, "main.xml")
    nodes = by_name(config)
    assert remaps(nodes["/in_group"]) == [("a", "group_a")] and params(nodes["/in_group"]) == [("", "p", 1)]
    after = nodes["/from_child_yes_default"]
    assert remaps(after) == [("x", "child_x")] and params(after) == [] and sink.items == []
    assert [(src, dst) for _, src, dst in config.scope_remaps] == [("/a", "/group_a"), ("/x", "/child_x")]


def test_set_remap_in_a_group_shares_the_enclosing_scopes_list_as_in_launch(tmp_path: Path) -> None:
    """launch copies the configurations of a scoped group shallowly: once the enclosing scope has
    a set_remap, one in the group appends to the same list and stays after the group (as launch does)."""
    config, _ = load(tmp_path, {"main.xml": """
        <launch>
          <set_remap from="outer" to="o"/>
          <group><set_remap from="inner" to="i"/></group>
          <node pkg="p" exec="e" name="after"/>
          <group><set_remap from="fresh" to="f"/></group>
        </launch>
        """}, "main.xml")
    assert remaps(config.nodes[0]) == [("outer", "o"), ("inner", "i")]


def test_conditions(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"main.xml": """
        <launch>
          <arg name="yes" default="True"/>
          <arg name="unknown"/>
          <node pkg="p" exec="e" name="if_true" if="$(var yes)"/>
          <node pkg="p" exec="e" name="unless_true" unless="$(var yes)"/>
          <node pkg="p" exec="e" name="one" if="1"/>
          <node pkg="p" exec="e" name="maybe" if="$(var unknown)"/>
          <group unless="$(var unknown)"><node pkg="p" exec="e" name="maybe_not"/></group>
          <node pkg="p" exec="e" name="eq" if="$(equals $(var yes) true)"/>
          <node pkg="p" exec="e" name="bad" if="yes please"/>
          <node pkg="p" exec="e" name="last"/>
        </launch>
        """}, "main.xml")
    nodes = by_name(config)
    assert list(nodes) == ["/if_true", "/one", "/maybe", "/maybe_not", "/eq", "/last"]
    assert nodes["/maybe"].condition.startswith('if="$(var unknown)"')
    assert nodes["/maybe_not"].condition.startswith('unless="$(var unknown)"')
    assert ("main.xml", 10, "launch-subst") in codes(sink)


def test_undecided_conditions_on_one_unknown_argument_are_tried(tmp_path: Path) -> None:
    config, _ = load(tmp_path, {"main.xml": """
        <launch>
          <arg name="lidar"/>
          <node pkg="p" exec="e" name="spin" if="$(eval '\\'$(var lidar)\\' == \\'spin\\'')"/>
          <node pkg="p" exec="e" name="solid" unless="$(eval '\\'$(var lidar)\\' == \\'spin\\'')"/>
          <node pkg="p" exec="e" name="unknown_kind" if="$(var lidar)"/>
        </launch>
        """}, "main.xml")
    nodes = by_name(config)
    assert nodes["/spin"].when == {"lidar#1": frozenset({"spin"})}
    assert "spin" not in (nodes["/solid"].when or {}).get("lidar#1", {"spin"})
    assert nodes["/unknown_kind"].when == {"lidar#1": frozenset({"true", "1"})}


def test_substitutions(tmp_path: Path) -> None:
    with sandbox.active(sandbox.Sandbox(None, {"ARCHLOG_TEST_ROBOT": "robby"})):
        config, sink = load(tmp_path, {"robot_pkg/dummy.txt": "x", "main.xml": """
        <launch>
          <arg name="pkg" default="robot_pkg"/>
          <node pkg="p" exec="e" name="$(env ARCHLOG_TEST_ROBOT)_$(env ARCHLOG_TEST_UNSET fallback)">
            <param name="share" value="$(find-pkg-share $(var pkg))"/>
            <param name="file" value="$(dirname)/x.yaml"/>
            <param name="sum" value="$(eval '1 + 2')"/>
            <param name="quoted" value="$(eval &quot;'$(var pkg)'.upper()&quot;)"/>
            <param name="anon" value="$(anon a) $(anon a) $(anon b)"/>
            <param name="missing_pkg" value="$(find-pkg-share nowhere)"/>
            <param name="command" value="$(command 'xacro robot.urdf.xacro')"/>
            <param name="content" value="$(file-content '$(find-pkg-share robot_pkg)/dummy.txt')"/>
            <param name="device" value="$(file-content /dev/zero)"/>
          </node>
        </launch>
        """}, "main.xml")
    node = config.nodes[0]
    values = {name: value for _, name, value in params(node)}
    assert node.name == "/robby_fallback"
    assert values["share"] == str(tmp_path / "robot_pkg") and values["file"] == f"{tmp_path}/x.yaml"
    assert (values["sum"], values["quoted"]) == (3, "ROBOT_PKG")
    first, second, third = str(values["anon"]).split()
    assert first == second != third
    assert isinstance(values["missing_pkg"], Unknown) and "nowhere" in values["missing_pkg"].expr
    assert isinstance(values["command"], Unknown) and values["command"].line == 10
    assert values["content"] == "x" and isinstance(values["device"], Unknown)
    assert sorted(codes(sink)) == [("main.xml", 3, "env-default"), ("main.xml", 12, "not-a-file")]  # no /dev/zero
    assert any("ARCHLOG_TEST_UNSET" in d.message for d in sink.items)


def test_components_in_xml(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"main.xml": """
        <launch>
          <node_container pkg="rclcpp_components" exec="component_container_mt" name="box" namespace="ns">
            <composable_node pkg="composition" plugin="composition::Talker" name="talker" namespace="inner">
              <remap from="chatter" to="talk"/>
              <param name="rate" value="2"/>
              <extra_arg name="use_intra_process_comms" value="true"/>
            </composable_node>
            <composable_node pkg="composition" plugin="composition::Server" name="off" if="false"/>
          </node_container>
          <group>
            <push-ros-namespace namespace="pushed"/>
            <load_composable_node target="ns/box">
              <composable_node pkg="composition" plugin="composition::Listener" name="listener"/>
            </load_composable_node>
          </group>
        </launch>
        """}, "main.xml")
    nodes = by_name(config)
    assert list(nodes) == ["/ns/box", "/inner/talker", "/pushed/listener"]
    talker = nodes["/inner/talker"]
    assert (talker.pkg, talker.type, talker.plugin, talker.manager) == \
        ("composition", "composition::Talker", "composition::Talker", "/ns/box")
    assert talker.kind == ("composition", "composition::Talker")
    assert remaps(talker) == [("chatter", "talk")] and params(talker) == [("", "rate", 2)]
    assert nodes["/pushed/listener"].manager == "/ns/box" and sink.items == []


# -- Python ---------------------------------------------------------------------------------
PY_HEADER = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, GroupAction, IncludeLaunchDescription, OpaqueFunction,
                            SetLaunchConfiguration, TimerAction)
from launch.conditions import IfCondition, LaunchConfigurationEquals, LaunchConfigurationNotEquals, UnlessCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution, PythonExpression, TextSubstitution
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes, Node, PushROSNamespace, SetParameter
from launch_ros.actions import PushRosNamespace, SetRemap
from launch_ros.descriptions import ComposableNode, ParameterValue
from launch_ros.substitutions import FindPackageShare
"""


def python(body: str) -> str:
    return PY_HEADER + textwrap.dedent(body)


def test_python_nodes_parameters_and_remaps(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"pkg/config/p.yaml": "/**:\n  ros__parameters:\n    shared: 1\n",
                                   "main.launch.py": python("""
        def generate_launch_description():
            config = os.path.join(get_package_share_directory('pkg'), 'config', 'p.yaml')
            rate = LaunchConfiguration('rate')
            return LaunchDescription([
                DeclareLaunchArgument('rate', default_value='10'),
                Node(package='demo', executable='talker', name='talker', namespace='ns',
                     parameters=[{'rate': rate, 'name': 'text', 'nested': {'a': 1, 'b': [1, 2.5]},
                                  'typed': ParameterValue(rate, value_type=str)},
                                 config, PathJoinSubstitution([FindPackageShare('pkg'), 'config', 'p.yaml'])],
                     remappings=[('chatter', 'talk'), ('in', [rate, '_in'])],
                     arguments=['--verbose', rate], ros_arguments=['-r', 'extra:=remapped']),
            ])
        """)}, "main.launch.py")
    node = config.nodes[0]
    assert (node.name, node.namespace, node.args) == ("/ns/talker", "/ns", "--verbose 10")
    assert params(node) == [("", "rate", 10), ("", "name", "text"), ("", "nested.a", 1), ("", "nested.b", [1.0, 2.5]),
                            ("", "typed", "10"), ("/**", "shared", 1), ("/**", "shared", 1)]
    assert remaps(node) == [("extra", "remapped"), ("chatter", "talk"), ("in", "10_in")]
    lines = [elem.line for _, _, elem in node.remaps]
    assert lines == [lines[0], 23, 23] and node.elem.line == 19 and sink.items == []


def test_python_description_built_with_add_action_helpers_loops_and_comprehensions(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"main.launch.py": python("""
        ROBOTS = ['r1', 'r2']

        def robot_node(name, suffix='driver'):
            return Node(package='demo', executable='driver', name=f'{name}_{suffix}', namespace=name)

        def generate_launch_description():
            ld = LaunchDescription()
            for robot in ROBOTS:
                ld.add_action(robot_node(robot))
            ld.add_action(GroupAction([robot_node(n, suffix='camera') for n in ROBOTS if n != 'r2']))
            names = {'a': 'x', 'b': 'y'}
            for key, value in names.items():
                ld.add_action(Node(package='demo', executable='e', name=key + value))
            return ld
        """)}, "main.launch.py")
    assert [n.name for n in config.nodes] == ["/r1/r1_driver", "/r2/r2_driver", "/r1/r1_camera", "/ax", "/by"]
    assert [n.elem.line for n in config.nodes][:3] == [22, 22, 23]  # reported at the helper's call
    assert sink.items == []


def test_python_arguments_conditions_and_expressions(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"main.launch.py": python("""
        def generate_launch_description():
            mode = LaunchConfiguration('mode')
            return LaunchDescription([
                DeclareLaunchArgument('mode', default_value='sim'),
                DeclareLaunchArgument('rviz', default_value='false'),
                DeclareLaunchArgument('hardware'),
                Node(package='p', executable='e', name='sim_only', condition=LaunchConfigurationEquals('mode', 'sim')),
                Node(package='p', executable='e', name='real_only',
                     condition=LaunchConfigurationNotEquals('mode', 'sim')),
                Node(package='p', executable='e', name='rviz', condition=IfCondition(LaunchConfiguration('rviz'))),
                Node(package='p', executable='e', name='no_rviz', condition=UnlessCondition(LaunchConfiguration('rviz'))),
                Node(package='p', executable='e', name='expr',
                     condition=IfCondition(PythonExpression(["'", mode, "' == 'sim' and not ", 'False']))),
                Node(package='p', executable='e', name='hw', condition=IfCondition(LaunchConfiguration('hardware'))),
                SetLaunchConfiguration('derived', [mode, TextSubstitution(text='_x')]),
                Node(package='p', executable='e', name=LaunchConfiguration('derived')),
            ])
        """)}, "main.launch.py", {"rviz": "true"})
    nodes = by_name(config)
    assert list(nodes) == ["/sim_only", "/rviz", "/expr", "/hw", "/sim_x"]
    assert nodes["/hw"].condition.startswith('if="$(var hardware)"')
    assert [d.code for d in sink.items] == ["launch-arg-unknown", "launch-condition"]


def test_python_groups_namespaces_scope_actions_and_includes(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {
        "pkg/launch/child.launch.py": python("""
            def generate_launch_description():
                return LaunchDescription([
                    DeclareLaunchArgument('robot'),
                    Node(package='p', executable='e', name=[LaunchConfiguration('robot'), '_node']),
                ])
            """),
        "main.launch.py": python("""
            def generate_launch_description():
                child = PathJoinSubstitution([FindPackageShare('pkg'), 'launch', 'child.launch.py'])
                return LaunchDescription([
                    GroupAction([
                        PushRosNamespace('one'),
                        SetRemap(src='scan', dst='base_scan'),
                        SetParameter(name='use_sim_time', value=True),
                        IncludeLaunchDescription(PythonLaunchDescriptionSource(child),
                                                 launch_arguments={'robot': 'alpha'}.items()),
                    ]),
                    GroupAction([PushROSNamespace('two')], scoped=False),
                    IncludeLaunchDescription(PythonLaunchDescriptionSource(child), launch_arguments={'robot': 'beta'}),
                    TimerAction(period=2.0, actions=[Node(package='p', executable='e', name='late')]),
                ])
            """)}, "main.launch.py")
    nodes = by_name(config)
    assert list(nodes) == ["/one/alpha_node", "/two/beta_node", "/two/late"]
    alpha = nodes["/one/alpha_node"]
    assert remaps(alpha) == [("scan", "base_scan")] and params(alpha) == [("", "use_sim_time", True)]
    assert alpha.chain[0].file == "main.launch.py" and alpha.elem.file == "pkg/launch/child.launch.py"
    assert remaps(nodes["/two/beta_node"]) == [] and sink.items == []


def test_python_components(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"main.launch.py": python("""
        from my_robot.components import make_component
        def generate_launch_description():
            container = ComposableNodeContainer(
                name='box', namespace='', package='rclcpp_components', executable='component_container',
                composable_node_descriptions=[
                    ComposableNode(package='composition', plugin='composition::Talker', name='talker',
                                   remappings=[('chatter', 'talk')], parameters=[{'rate': 2}]),
                    ComposableNode(package='composition', plugin='composition::Server',
                                   condition=IfCondition('false')),
                    make_component(),
                ])
            load = LoadComposableNodes(target_container=container, composable_node_descriptions=[
                ComposableNode(package='composition', plugin='composition::Listener', name='listener',
                               namespace='ns')])
            by_name = LoadComposableNodes(target_container='/box', composable_node_descriptions=[
                ComposableNode(package='composition', plugin='composition::Client')])
            return LaunchDescription([container, load, by_name])
        """)}, "main.launch.py")
    assert [(n.name, n.type, n.manager) for n in config.nodes] == [
        ("/box", "component_container", None), ("/talker", "composition::Talker", "/box"),
        ("/ns/listener", "composition::Listener", "/box"), ("", "composition::Client", "/box")]
    assert config.nodes[1].kind == ("composition", "composition::Talker")
    assert codes(sink) == [("main.launch.py", 16, "launch-unknown")] and "make_component" in sink.items[0].message


def test_python_opaque_functions(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"main.launch.py": python("""
        from some_package.helpers import make_nodes

        def launch_setup(context, *args, **kwargs):
            count = int(LaunchConfiguration('count').perform(context))
            prefix = context.launch_configurations['prefix']
            nodes = [Node(package='p', executable='e', name=f'{prefix}_{i}') for i in range(count)]
            if LaunchConfiguration('extra').perform(context) == 'true':
                nodes.append(Node(package='p', executable='e', name='extra'))
            return nodes

        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument('count', default_value='2'),
                DeclareLaunchArgument('prefix', default_value='worker'),
                DeclareLaunchArgument('extra'),
                OpaqueFunction(function=launch_setup),
                OpaqueFunction(function=make_nodes),
            ])
        """)}, "main.launch.py")
    assert [n.name for n in config.nodes] == ["/worker_0", "/worker_1", "/extra"]
    assert config.nodes[2].condition.startswith("if LaunchConfiguration('extra').perform(context) == 'true'")
    assert codes(sink) == [("main.launch.py", 28, "launch-arg-unknown"), ("main.launch.py", 21, "launch-condition"),
                           ("main.launch.py", 30, "launch-unknown")]


def test_python_what_cannot_be_read_is_reported_not_dropped(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"main.launch.py": python("""
        import xacro
        from my_robot.launch_tools import robot_nodes

        def generate_launch_description():
            description = xacro.process_file('robot.urdf.xacro').toxml()
            ld = LaunchDescription([
                Node(package='robot_state_publisher', executable='robot_state_publisher',
                     parameters=[{'robot_description': description}]),
                robot_nodes(),
                Node(package='p', executable='e', name=os.environ['ARCHLOG_SURELY_UNSET']),
            ])
            while True:
                ld.add_action(Node(package='p', executable='never'))
            return ld
        """)}, "main.launch.py")
    assert [(n.type, n.name) for n in config.nodes] == [("robot_state_publisher", ""), ("e", "")]
    value = params(config.nodes[0])[0][2]
    assert isinstance(value, Unknown) and "xacro.process_file" in value.expr
    assert codes(sink) == [("main.launch.py", 23, "env-not-given"), ("main.launch.py", 25, "launch-unknown"),
                           ("main.launch.py", 22, "launch-unknown"), ("main.launch.py", 23, "launch-unknown")]


def test_python_for_each_calls_its_function_per_yaml_item(tmp_path: Path) -> None:
    """launch 3.x's ForEach: the input split at ';', each item a YAML mapping of keyword arguments."""
    config, sink = load(tmp_path, {"main.launch.py": python("""
        from launch.actions import ForEach

        def robot(name='', pose={}):
            return [GroupAction([PushRosNamespace(name),
                                 Node(package='p', executable='driver', name='driver',
                                      parameters=[{'x': pose.get('x', 0.0)}])])]

        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument('robots', default_value="{name: r1, pose: {x: 1.5}}; {name: r2}"),
                ForEach(LaunchConfiguration('robots'), function=robot),
                ForEach(LaunchConfiguration('robots'), function=robot_from_elsewhere),
                ForEach('[1, 2]', function=robot),
            ])
        """)}, "main.launch.py")
    assert [(n.name, params(n)) for n in config.nodes] == [("/r1/driver", [("", "x", 1.5)]),
                                                            ("/r2/driver", [("", "x", 0.0)])]
    assert codes(sink) == [("main.launch.py", 25, "launch-unknown"), ("main.launch.py", 26, "launch-unknown")]


def test_python_execute_process_of_a_package_executable_is_a_node(tmp_path: Path) -> None:
    """ExecuteProcess with ExecutableInPackage or `ros2 run` starts a node (launch_ros's scope
    actions do not reach it: only its own command line names it); any other process is left out."""
    config, sink = load(tmp_path, {"main.launch.py": python("""
        from launch.actions import ExecuteProcess
        from launch.substitutions import FindExecutable
        from launch_ros.substitutions import ExecutableInPackage

        def generate_launch_description():
            return LaunchDescription([
                PushRosNamespace('scoped'),
                ExecuteProcess(cmd=[ExecutableInPackage(package='mon', executable='pub'), 'small',
                                    '--ros-args', '-r', '__node:=small_pub', '-r', 'data:=small_data']),
                ExecuteProcess(cmd=[FindExecutable(name='ros2'), 'run', 'mon', 'sub', '--ros-args', '-r',
                                    '__ns:=/watch']),
                ExecuteProcess(cmd=['ros2', 'run', 'mon', 'sub']),
                ExecuteProcess(cmd=['rviz2', '-d', 'view.rviz']),
            ])
        """)}, "main.launch.py")
    assert [(n.pkg, n.type, n.name, n.namespace, remaps(n)) for n in config.nodes] == [
        ("mon", "pub", "/small_pub", "", [("data", "small_data")]), ("mon", "sub", "", "/watch", []),
        ("mon", "sub", "", "", [])]
    assert config.nodes[0].args == "small --ros-args -r __node:=small_pub -r data:=small_data"
    assert codes(sink) == [("main.launch.py", 26, "launch-process")]


# -- parameter files ------------------------------------------------------------------------
def test_parameter_file_layouts(tmp_path: Path) -> None:
    from archlog.extract.launch.ros2_params import load_param_file

    path = tmp_path / "params.yaml"
    path.write_text(textwrap.dedent("""
        /**:
          ros__parameters:
            use_sim_time: true
        ns:
          talker:
            ros__parameters:
              qos: {depth: 5, history: keep_last}
              topics: [a, b]
        /**/listener:
          ros__parameters: {rate: 2.5}
        "*":
          ros__parameters:
            any: x
        empty:
          ros__parameters:
        """).lstrip())
    sink = DiagnosticSink()
    assert load_param_file(path, "params.yaml", sink) == [
        ("/**", "use_sim_time", True, 3), ("ns/talker", "qos.depth", 5, 7), ("ns/talker", "qos.history", "keep_last", 7),
        ("ns/talker", "topics", ["a", "b"], 8), ("/**/listener", "rate", 2.5, 10), ("*", "any", "x", 13)]
    assert sink.items == []


@pytest.mark.parametrize("pattern, node, expected", [
    ("/**", "/talker", True), ("/**", "/a/b/talker", True), ("talker", "/talker", True),
    ("talker", "/ns/talker", False), ("/ns/talker", "/ns/talker", True), ("ns/talker", "/ns/talker", True),
    ("/**/talker", "/talker", True), ("/**/talker", "/a/b/talker", True), ("/**/talker", "/a/listener", False),
    ("*", "/talker", True), ("*", "/ns/talker", False), ("/ns/*", "/ns/talker", True), ("/ns/*", "/ns/a/b", False),
    ("/*/talker", "/ns/talker", True), ("/*/talker", "/talker", False), ("/ns/**", "/ns/a/b", True),
    ("/talk", "/talker", False), ("/bad[", "/bad", False),
])
def test_node_keys_match_as_rclcpp_matches_them(pattern: str, node: str, expected: bool) -> None:
    from archlog.extract.launch.ros2_params import matches

    assert matches(pattern, node) is expected


def test_nav2_rewritten_yaml(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"pkg/params.yaml": """
        controller_server:
          ros__parameters:
            use_sim_time: false
            autostart: false
            plugin: KEEPOUT
        """, "main.launch.py": python("""
        from launch_ros.descriptions import ParameterFile
        from nav2_common.launch import RewrittenYaml

        def generate_launch_description():
            params = RewrittenYaml(source_file=os.path.join(get_package_share_directory('pkg'), 'params.yaml'),
                                   root_key='robot', param_rewrites={'use_sim_time': 'true'},
                                   value_rewrites={'KEEPOUT': LaunchConfiguration('mode', default='on')})
            return LaunchDescription([
                Node(package='nav2_controller', executable='controller_server',
                     parameters=[ParameterFile(params, allow_substs=True)]),
            ])
        """)}, "main.launch.py")
    assert params(config.nodes[0]) == [("robot/controller_server", "use_sim_time", True),
                                       ("robot/controller_server", "autostart", False),
                                       ("robot/controller_server", "plugin", "on")]
    assert sink.items == []


# -- bad input ------------------------------------------------------------------------------
@pytest.mark.parametrize("name, content, line, code", [
    ("main.xml", "<launch>\n  <node pkg='p' exec='e'>\n</launch>\n", 3, "launch-xml"),
    ("main.yaml", "launch:\n- node: {pkg: p\n- node: {}\n", 3, "launch-yaml"),
    ("main.yaml", "nodes:\n- node: {pkg: p, exec: e}\n", 1, "launch-yaml"),
    ("main.launch.py", "def generate_launch_description(:\n    pass\n", 1, "launch-python"),
    ("main.launch.py", "X = 1\n", 1, "launch-python"),
])
def test_unreadable_files_are_diagnostics(tmp_path: Path, name: str, content: str, line: int, code: str) -> None:
    config, sink = load(tmp_path, {name: content}, name)
    assert config.nodes == [] and codes(sink) == [(name, line, code)]


def test_bad_elements_are_diagnostics_and_the_run_goes_on(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"params.yaml": "talker:\n  ros__parameters:\n    x: [1\n", "main.xml": """
        <launch>
          <include file="$(dirname)/missing.launch.xml"/>
          <node pkg="p" exec="e" name="$(nosuch thing)"/>
          <node pkg="p" exec="e" name="$(var"/>
          <frobnicate/>
          <node pkg="p" name="no_exec"/>
          <node pkg="p" exec="e" name="bad/name"/>
          <node pkg="p" exec="e" name="with_bad_params"><param from="$(dirname)/params.yaml"/></node>
          <node pkg="p" exec="e" name="survivor"/>
        </launch>
        """}, "main.xml")
    assert [n.name for n in config.nodes] == ["/with_bad_params", "/survivor"]
    assert codes(sink) == [("main.xml", 4, "launch-invalid"), ("main.xml", 5, "launch-tag"),
                           ("main.xml", 6, "launch-invalid"), ("main.xml", 2, "launch-include"),
                           ("main.xml", 3, "launch-subst"), ("main.xml", 7, "launch-invalid"),
                           ("params.yaml", 4, "param-file")]


def test_group_forwarding_and_keep(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"main.xml": """
        <launch>
          <arg name="outer" default="o"/>
          <group forwarding="false">
            <keep name="kept" value="$(var outer)_k"/>
            <node pkg="p" exec="e" name="$(var kept)_$(var outer default)"/>
          </group>
          <node pkg="p" exec="e" name="$(var outer)_$(var kept default)"/>
        </launch>
        """}, "main.xml")
    assert [n.name for n in config.nodes] == ["/o_k_default", "/o_default"] and sink.items == []


def test_python_that_would_run_away_is_cut_short(tmp_path: Path) -> None:
    deep = "+".join(["1"] * 5000)
    config, sink = load(tmp_path, {"deep.launch.py": f"X = {deep}\n", "main.launch.py": python("""
        def forever():
            return forever()

        def setup(context, *args):
            return setup(context)

        def generate_launch_description():
            nothing = forever()
            text = 'a' * 10 ** 9
            numbers = [i for i in range(10 ** 9)]
            return LaunchDescription([
                OpaqueFunction(function=setup, args=nothing),
                Node(package='p', executable='e', name='still_here'),
                IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join(os.path.dirname(__file__),
                                                                                    'deep.launch.py'))),
            ])
        """)}, "main.launch.py")
    assert [n.name for n in config.nodes] == ["/still_here"]
    assert codes(sink) == [("main.launch.py", 22, "budget-exceeded"), ("main.launch.py", 18, "launch-unknown"),
                           ("deep.launch.py", 1, "budget-exceeded")]


def test_parameter_files_of_composable_nodes_are_applied_by_launch(tmp_path: Path) -> None:
    """launch_ros applies a file to a composable node itself: `/**`, then the node's own
    namespace/name key override it; other wildcards do not apply. A plain node keeps every entry."""
    config, sink = load(tmp_path, {"p.yaml": """
        /**:
          ros__parameters: {rate: 1, shared: 0}
        /ns:
          /worker:
            ros__parameters: {rate: 2}
        /**/worker:
          ros__parameters: {ignored: true}
        """, "main.xml": """
        <launch>
          <node_container pkg="rclcpp_components" exec="component_container" name="box" namespace="/">
            <composable_node pkg="p" plugin="p::Worker" name="worker" namespace="ns">
              <param from="$(dirname)/p.yaml"/>
            </composable_node>
          </node_container>
          <node pkg="p" exec="worker" name="worker" namespace="ns"><param from="$(dirname)/p.yaml"/></node>
        </launch>
        """}, "main.xml")
    component, node = config.nodes[1], config.nodes[2]
    assert params(component) == [("", "rate", 1), ("", "shared", 0), ("", "rate", 2)]
    assert params(node) == [("/**", "rate", 1), ("/**", "shared", 0), ("/ns/worker", "rate", 2),
                            ("/**/worker", "ignored", True)]
    assert sink.items == []


def test_python_reads_the_files_it_opens(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"pkg/config/nodes.yaml": "ns: robot\nnodes: [{name: a}, {name: b}]\n",
                                   "main.launch.py": python("""
        import yaml
        from pathlib import Path

        def launch_setup(context):
            path = Path(get_package_share_directory('pkg')) / 'config' / 'nodes.yaml'
            with open(path) as stream:
                spec = yaml.safe_load(stream)
            return [Node(package='p', executable='e', name=n['name'], namespace=f"{spec['ns']}", parameters=[
                        {'source': str(path.parent), 'raw': path.read_text().splitlines()[0]}])
                    for n in spec['nodes']]

        def generate_launch_description():
            return LaunchDescription([OpaqueFunction(function=launch_setup)])
        """)}, "main.launch.py")
    assert [n.name for n in config.nodes] == ["/robot/a", "/robot/b"]
    assert params(config.nodes[0]) == [("", "source", str(tmp_path / "pkg" / "config")), ("", "raw", "ns: robot")]
    assert sink.items == []


def test_a_namespace_that_is_not_known_skips_the_nodes_it_would_hold(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"main.yaml": """
        launch:
        - arg: {name: robot}
        - group:
            children:
            - push-ros-namespace: {namespace: $(var robot)}
            - node: {pkg: p, exec: e, name: inside}
            - node: {pkg: p, exec: e, name: absolute, namespace: /fixed}
        - node: {pkg: p, exec: e, name: outside}
        """}, "main.yaml")
    assert [n.name for n in config.nodes] == ["/fixed/absolute", "/outside"]
    assert codes(sink) == [("main.yaml", 2, "launch-arg-unknown"), ("main.yaml", 6, "launch-unknown")]
    assert "launch argument 'robot' is not known" in sink.items[1].message
