"""A rospy script's ports in its package's own modules (imports.py): read when the script calls
them, cached with them, never outside the sandbox, and a module that does not parse is said."""

from __future__ import annotations

from pathlib import Path

from archlog import sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.python.node import extract_python
from archlog.extract.summary import NodeSummary

SCRIPT = "#!/usr/bin/env python3\nimport rospy\nfrom talker_pkg.talk import Talker\nrospy.init_node('talker')\nTalker()\n"
MODULE = "import rospy\nfrom std_msgs.msg import String\n\n\nclass Talker:\n    def __init__(self):\n" \
         "        rospy.Publisher('{topic}', String, queue_size=1)\n"


def package(root: Path, topic: str = "chatter") -> Path:
    (root / "scripts").mkdir(parents=True)
    (root / "src" / "talker_pkg").mkdir(parents=True)
    (root / "package.xml").write_text("<package format='2'><name>talker_pkg</name></package>")
    (root / "src" / "talker_pkg" / "__init__.py").write_text("")
    (root / "src" / "talker_pkg" / "talk.py").write_text(MODULE.format(topic=topic))
    (root / "scripts" / "talker").write_text(SCRIPT)
    return root / "scripts" / "talker"


def extract(script: Path, sink: DiagnosticSink | None = None) -> NodeSummary:
    return extract_python(script, "talker_pkg", "talker", "scripts/talker", sink or DiagnosticSink(),
                          lambda path: path.relative_to(script.parent.parent).as_posix())


def test_a_changed_module_is_read_again(tmp_path: Path) -> None:
    script = package(tmp_path / "talker_pkg")
    assert [(p.name, p.file, p.line) for p in extract(script).ports] == \
        [("chatter", "src/talker_pkg/talk.py", 7)]
    module = tmp_path / "talker_pkg" / "src" / "talker_pkg" / "talk.py"
    module.write_text(MODULE.format(topic="babble"))
    assert [p.name for p in extract(script).ports] == ["babble"]


def test_a_module_outside_the_sandbox_is_not_read(tmp_path: Path) -> None:
    script = package(tmp_path / "talker_pkg")
    with sandbox.active(sandbox.Sandbox((script.parent.resolve(),))):
        assert extract(script).ports == []


def test_a_module_that_does_not_parse_is_an_error(tmp_path: Path) -> None:
    script = package(tmp_path / "talker_pkg")
    (tmp_path / "talker_pkg" / "src" / "talker_pkg" / "talk.py").write_text("<<<<<<< HEAD\nclass Talker(:\n")
    sink = DiagnosticSink()
    summary = extract(script, sink)
    assert summary.ports == [] and summary.incomplete == "src/talker_pkg/talk.py: does not parse"
    [error] = sink.items
    assert (error.file, error.code, error.severity) == ("src/talker_pkg/talk.py", "python-syntax", "error")


def test_a_python2_module_is_repaired(tmp_path: Path) -> None:
    script = package(tmp_path / "talker_pkg")
    module = tmp_path / "talker_pkg" / "src" / "talker_pkg" / "talk.py"
    module.write_text(MODULE.format(topic="chatter") + "        print 'started'\n")
    sink = DiagnosticSink()
    assert [p.name for p in extract(script, sink).ports] == ["chatter"]
    assert [(d.file, d.line, d.code) for d in sink.items] == [("src/talker_pkg/talk.py", 8, "python2")]


def test_a_script_whose_node_is_set_up_in_a_module_archlog_does_not_follow_is_partial(tmp_path: Path) -> None:
    script = package(tmp_path / "talker_pkg")
    script.write_text("#!/usr/bin/env python3\nimport talker_pkg.talk\ntalker_pkg.talk.main()\n")
    summary = extract(script)
    assert summary.ports == []
    assert summary.incomplete is not None and summary.incomplete.startswith("scripts/talker:1: sets up no ROS node")


def test_a_node_without_ports_is_not_partial(tmp_path: Path) -> None:
    script = package(tmp_path / "talker_pkg")
    script.write_text("#!/usr/bin/env python3\nimport rospy\nrospy.init_node('idle')\nrospy.spin()\n")
    summary = extract(script)
    assert (summary.ports, summary.incomplete, summary.default_name) == ([], None, "idle")


def test_a_name_the_module_only_imports_from_elsewhere_leaves_the_node_partial(tmp_path: Path) -> None:
    script = package(tmp_path / "talker_pkg")
    (tmp_path / "talker_pkg" / "src" / "talker_pkg" / "talk.py").write_text("from talker_pkg.impl import Talker\n")
    summary = extract(script)
    assert summary.ports == [] and summary.incomplete == \
        "src/talker_pkg/talk.py:1: Talker not defined here (imported from elsewhere?): its ROS code is not read"
