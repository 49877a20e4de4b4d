"""Model ports whose type follows another topic's (`type: {like: NAME}`: topic_tools' relays), and
model ports that exist only under a command-line condition (rostopic's subcommands, rosbag record's
--publish), also when the node's source is read."""

from __future__ import annotations

from pathlib import Path

from archlog.analysis import analyse
from archlog.diagnostics import DiagnosticSink
from archlog.rules.engine import Engine
from archlog.rules.ruleset import load_rules
from archlog.system.node_models import load_models
from archlog.values import ParamRef, Unknown

PACKAGE_XML = ("<package format='2'><name>{}</name><version>0.1.0</version><description>d</description>"
               "<maintainer email='dev@example.com'>m</maintainer><license>MIT</license></package>")
STAMPED_BASE = """#!/usr/bin/env python3
import rospy
from geometry_msgs.msg import TwistStamped
rospy.init_node('base')
rospy.Subscriber('cmd_vel', TwistStamped, print)
"""


def _package(root: Path, name: str, scripts: dict[str, str]) -> Path:
    pkg = root / "src" / name
    (pkg / "scripts").mkdir(parents=True)
    (pkg / "package.xml").write_text(PACKAGE_XML.format(name))
    for script, text in scripts.items():
        (pkg / "scripts" / script).write_text(text)
        (pkg / "scripts" / script).chmod(0o755)
    return pkg


def _analyse(tmp_path: Path, launch: str, scripts: dict[str, str] | None = None):
    pkg = _package(tmp_path, "demo", scripts or {"base.py": STAMPED_BASE})
    (pkg / "demo.launch").write_text(f"<launch>{launch}</launch>")
    return analyse([tmp_path], [str(pkg / "demo.launch")], {}, [])


def _publishers(analysis) -> dict[tuple[str, str], str]:
    """(node, topic) -> type, `?(...)` for an unknown one."""
    return {(str(n), str(t)): str(ty) for _p, n, t, ty in analysis.store.rows("publisher")}


def _rule_ids(analysis) -> list[str]:
    return [f.rule.id for f in Engine(load_rules([])).run(analysis.store)[1]]


def test_a_relay_chain_carries_the_type_its_feeder_publishes(tmp_path: Path) -> None:
    """rostopic pub feeds a relay, whose output feeds a throttle (a relay of a relay, listed before
    it) and a mux: each output gets the type, resolved in the node's namespace and through its remaps,
    and the stamped subscriber at the end is a type mismatch."""
    analysis = _analyse(tmp_path, """
  <node pkg="topic_tools" type="throttle" name="throttle" args="messages safe 5.0 base/cmd_vel"/>
  <group ns="robot">
    <node pkg="topic_tools" type="relay" name="relay" args="input /safe"><remap from="input" to="/teleop"/></node>
  </group>
  <node pkg="topic_tools" type="mux" name="mux" args="muxed /safe /other"/>
  <node pkg="rostopic" type="rostopic" name="cmd" args="pub -r 10 /teleop geometry_msgs/Twist '{}'"/>
  <node pkg="demo" type="base.py" name="base" ns="base"/>""")
    assert _publishers(analysis) == {
        ("/cmd", "/teleop"): "geometry_msgs/Twist", ("/robot/relay", "/safe"): "geometry_msgs/Twist",
        ("/throttle", "/base/cmd_vel"): "geometry_msgs/Twist", ("/mux", "/muxed"): "geometry_msgs/Twist",
        ("/mux", "/mux/selected"): "std_msgs/String"}
    assert _rule_ids(analysis) == ["AL101"]
    assert analysis.diagnostics.items == []


def test_without_a_publisher_of_known_type_the_type_stays_unknown(tmp_path: Path) -> None:
    """Nothing feeds the input (or two relays feed each other): the output's type is unknown, never
    guessed, and a subscriber of some type on it is no mismatch; publishers that disagree leave it
    unknown too."""
    analysis = _analyse(tmp_path, """
  <node pkg="topic_tools" type="relay" name="a" args="ping pong"/>
  <node pkg="topic_tools" type="relay" name="b" args="pong ping"/>
  <node pkg="topic_tools" type="drop" name="drop" args="mixed 1 2 /base/cmd_vel"/>
  <node pkg="rostopic" type="rostopic" name="twist" args="pub /mixed geometry_msgs/Twist '{}'"/>
  <node pkg="rostopic" type="rostopic" name="stamped" args="pub /mixed geometry_msgs/TwistStamped '{}'"/>
  <node pkg="demo" type="base.py" name="base" ns="base"/>""")
    types = _publishers(analysis)
    assert types[("/a", "/pong")] == "?(the type of /ping (no publisher of a known type))"
    assert types[("/b", "/ping")] == "?(the type of /pong (no publisher of a known type))"
    assert types[("/drop", "/base/cmd_vel")] == \
        "?(the type of /mixed (its publishers disagree: geometry_msgs/Twist, geometry_msgs/TwistStamped))"
    assert _rule_ids(analysis) == []  # the stamped subscriber of the drop's output is no mismatch


ROSTOPIC_PACKAGE = """import sys
import rospy
def rostopicmain(argv=None):
    argv = rospy.myargv(argv or sys.argv)
    rospy.init_node('rostopic', anonymous=True)
    if argv[1] == 'pub':
        rospy.Publisher(argv[2], rospy.AnyMsg, queue_size=100)
"""


def test_rostopic_ports_follow_its_subcommand_and_options(tmp_path: Path) -> None:
    """rostopic's script only calls its package, so its source resolves no port and its model is
    used: pub publishes its topic with its type (the value of -r is no argument), echo and hz
    subscribe, list has no port."""
    pkg = _package(tmp_path, "rostopic", {"rostopic": "#!/usr/bin/env python3\nimport rostopic\nrostopic.rostopicmain()\n"})
    (pkg / "src" / "rostopic").mkdir(parents=True)
    (pkg / "src" / "rostopic" / "__init__.py").write_text(ROSTOPIC_PACKAGE)
    analysis = _analyse(tmp_path, """
  <node pkg="rostopic" type="rostopic" name="pub" args="pub -r 10 --latch chatter std_msgs/String 'data: hi'"/>
  <node pkg="rostopic" type="rostopic" name="hz" ns="robot" args="hz -w 5 chatter /scan"/>
  <node pkg="rostopic" type="rostopic" name="echo" args="echo --filter 'm.data' /chatter"/>
  <node pkg="rostopic" type="rostopic" name="list" args="list"/>""")
    assert _publishers(analysis) == {("/pub", "/chatter"): "std_msgs/String"}
    assert sorted((str(n), str(t)) for _p, n, t, _ty in analysis.store.rows("subscriber")) == [
        ("/echo", "/chatter"), ("/robot/hz", "/robot/chatter"), ("/robot/hz", "/scan")]
    assert {origin for _n, origin in analysis.store.rows("node_source")} == {"model"}


RECORD = """#!/usr/bin/env python3
import sys
import rospy
from std_msgs.msg import Empty, String
rospy.init_node('record')
options = parse(sys.argv)
if options.publish:
    rospy.Publisher('begin_write', String, queue_size=1, latch=True)
if options.snapshot:
    rospy.Subscriber('snapshot_trigger', Empty, print)
if options.trigger:
    rospy.Publisher('snapshot_trigger', Empty, queue_size=1)
"""


def test_a_sources_ports_follow_the_models_command_line_conditions(tmp_path: Path) -> None:
    """A source read in place of the model (as many ports) keeps a port the model creates only under
    a command-line option when the instance has it, and loses one the model says never exists."""
    _package(tmp_path, "rosbag", {"record": RECORD})
    analysis = _analyse(tmp_path, """
  <node pkg="rosbag" type="record" name="plain" args="-O x.bag /chatter"/>
  <node pkg="rosbag" type="record" name="announced" args="--publish -O y.bag /chatter"/>""")
    assert [str(n) for n, _origin in analysis.store.rows("node_source")] == ["/plain", "/announced"]
    assert {origin for _n, origin in analysis.store.rows("node_source")} == {"python"}
    assert _publishers(analysis) == {("/announced", "/begin_write"): "std_msgs/String"}
    assert {(str(n), str(t)) for _p, n, t, _ty in analysis.store.rows("subscriber")} == {
        ("/plain", "/chatter"), ("/announced", "/chatter")}


def test_command_line_conditions_and_followed_types_are_checked(tmp_path: Path) -> None:
    """Each broken entry is reported at its line (a list parameter cannot name the topic a type
    follows, an option is spelt with its dash, an argv condition needs `equals`, `never` a reason)."""
    model = tmp_path / "m.yaml"
    bad = ["{name: out, type: {like: {each: ~inputs}}}", "{name: a, type: std_msgs/Empty, if: {option: [publish]}}",
           "{name: b, type: std_msgs/Empty, if: {argv: '{1}'}}", "{name: c, type: std_msgs/Empty, if: {never: ''}}"]
    model.write_text("models:\n" + "".join(f"  - package: x\n    executable: y{i}\n    publishers:\n      - {entry}\n"
                                          for i, entry in enumerate(bad)))
    sink = DiagnosticSink()
    assert load_models(model, "m.yaml", sink) == []
    assert [(d.line, d.code) for d in sink.items] == [(5, "model-schema"), (9, "model-schema"),
                                                      (13, "model-schema"), (17, "model-schema")]
    model.write_text("package: x\nexecutable: y\nvalued_options: [-r]\npublishers:\n"
                     "  - {name: out, type: {like: {param: ~input, default: in}}}\n"
                     "  - {name: d, type: {like: /in}, if: {argv: '{1}', equals: [pub, echo]}}\n")
    (summary, _instance), = load_models(model, "m.yaml", sink)
    assert len(sink.items) == 4 and summary.valued_options == ("-r",) and len(summary.argv_ports) == 1
    port, = summary.ports
    assert isinstance(port.type, Unknown) and port.type_of == (ParamRef("~input", "in", "", "m.yaml", 5),)
