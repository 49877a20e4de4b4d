"""The extraction cache: a run with nothing changed gives what the first run gave (summaries and
diagnostics) without parsing again, and a change to an input parses again."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from archlog import budget
from archlog.diagnostics import DiagnosticSink
from archlog.extract.cpp import extract, msg_headers
from archlog.extract.python import node
from archlog.extract.workspace.index import Workspace

PY2 = '''#!/usr/bin/env python
import rospy
from std_msgs.msg import String
rospy.init_node("old")
pub = rospy.Publisher("chatter", String, queue_size=1)
print "started"
'''


@pytest.fixture(autouse=True)
def fresh_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    folder = tmp_path / "cache"
    monkeypatch.setenv("ARCHLOG_CACHE_DIR", str(folder))
    return folder


def _extract(path: Path) -> tuple[node.NodeSummary, list]:
    sink = DiagnosticSink()
    summary = node.extract_python(path, "demo", "old.py", "scripts/old.py", sink)
    return summary, sink.items


def test_python_result_comes_from_the_cache_with_its_diagnostics(tmp_path: Path,
                                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    script = tmp_path / "old.py"
    script.write_text(PY2)
    first, found = _extract(script)
    assert [p.name for p in first.ports] == ["chatter"]
    assert [d.code for d in found] == ["python2"]

    def parse_again(*_args: object) -> None:
        raise AssertionError("parsed again although nothing changed")

    monkeypatch.setattr(node, "_read_guarded", parse_again)
    again, found_again = _extract(script)
    assert again == first
    assert found_again == found


def test_python_result_is_read_again_after_a_change(tmp_path: Path) -> None:
    script = tmp_path / "old.py"
    script.write_text(PY2)
    _extract(script)
    script.write_text(PY2.replace('"chatter"', '"talk"'))
    changed, _found = _extract(script)
    assert [p.name for p in changed.ports] == ["talk"]


def test_python_result_is_kept_per_budget(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Values fold within the budget's limits, so a result under other limits is not reused."""
    script = tmp_path / "old.py"
    script.write_text(PY2)
    _extract(script)
    calls = []
    real = node._read_guarded
    monkeypatch.setattr(node, "_read_guarded", lambda *args: calls.append(1) or real(*args))
    with budget.active({"alternatives": 3}):
        _extract(script)
    assert calls == [1]


MSG_PACKAGE = '''<?xml version="1.0"?>
<package format="2">
  <name>demo_msgs</name>
  <version>0.1.0</version>
  <description>d</description>
  <maintainer email="a@b.c">a</maintainer>
  <license>MIT</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
'''


@pytest.mark.skipif(not (msg_headers.DEBIAN_PYTHON.is_file() and msg_headers.TEMPLATES.is_dir()),
                    reason="needs gencpp from Debian")
def test_message_definition_errors_are_reported_again_from_the_cache(tmp_path: Path) -> None:
    package = tmp_path / "src" / "demo_msgs"
    (package / "msg").mkdir(parents=True)
    (package / "package.xml").write_text(MSG_PACKAGE)
    (package / "msg" / "Good.msg").write_text("string data\n")
    (package / "msg" / "Box.msg").write_text("nowhere_msgs/Thing thing\n")
    runs = []
    for _ in range(2):
        sink = DiagnosticSink()
        out = msg_headers.generated_headers(Workspace([tmp_path / "src"], sink), sink)
        assert out is not None and (out / "demo_msgs" / "Good.h").is_file()
        runs.append([(d.file, d.code) for d in sink.items if d.code == "msg-definition"])
    assert runs[0] == [("demo_msgs/msg/Box.msg", "msg-definition")]
    assert runs[1] == runs[0]


CPP = '''#include <ros/ros.h>
#include <std_msgs/String.h>
#include "local.h"
#include <demo_missing/header.h>
int main(int c, char** v) { ros::init(c, v, "talker"); ros::NodeHandle nh;
  ros::Publisher p = nh.advertise<std_msgs::String>(TOPIC, 1); }
'''


def test_cpp_result_comes_from_the_cache_until_a_header_changes(tmp_path: Path,
                                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    source, header = tmp_path / "talker.cpp", tmp_path / "local.h"
    source.write_text(CPP)
    header.write_text('#define TOPIC "chatter"\n')
    env = extract.CppEnvironment([])

    def run() -> tuple[list[str], list[str]]:
        sink = DiagnosticSink()
        summary = extract.extract_cpp([source], "demo", "talker", env, {source: "talker.cpp"}, sink)
        return [str(p.name) for p in summary.ports], [d.code for d in sink.items]

    first = run()
    assert first == (["chatter"], ["cpp-compile"])  # the missing header, reported from the cache too
    real = extract._parse_guarded
    parsed = []
    monkeypatch.setattr(extract, "_parse_guarded", lambda *args: parsed.append(1) or real(*args))
    assert run() == first and parsed == []
    header.write_text('#define TOPIC "talk"\n')
    os.utime(header, ns=(header.stat().st_atime_ns, header.stat().st_mtime_ns + 10**9))
    assert run() == (["talk"], ["cpp-compile"]) and parsed == [1]


def test_cpp_cache_travels_to_a_fresh_checkout(tmp_path: Path, fresh_cache: Path,
                                               monkeypatch: pytest.MonkeyPatch) -> None:
    """CI: the cache folder is saved after one run and restored on a new runner, whose checkout
    has the same files with new mtimes (and inodes); nothing is parsed again there."""
    files = {"src/talker.cpp": CPP, "include/local.h": '#define TOPIC "chatter"\n'}

    def checkout() -> Path:
        root = tmp_path / "ws"
        shutil.rmtree(root, ignore_errors=True)
        for name, text in files.items():
            (root / name).parent.mkdir(parents=True, exist_ok=True)
            (root / name).write_text(text)
            os.utime(root / name, ns=(10**18, 10**18))  # as a checkout on another day would
        return root

    def run() -> tuple[list[str], list[str]]:
        root = tmp_path / "ws"
        source = root / "src" / "talker.cpp"
        env = extract.CppEnvironment([root / "include"], roots=[root])
        sink = DiagnosticSink()
        summary = extract.extract_cpp([source], "demo", "talker", env, {source: "src/talker.cpp"}, sink)
        return [str(p.name) for p in summary.ports], [d.code for d in sink.items]

    checkout()
    os.utime(tmp_path / "ws" / "include" / "local.h", ns=(5 * 10**17, 5 * 10**17))
    first = run()
    assert first == (["chatter"], ["cpp-compile"])
    saved = tmp_path / "saved-cache"
    shutil.copytree(fresh_cache, saved)  # the CI cache action's save, then a new runner's restore
    shutil.rmtree(fresh_cache)
    shutil.copytree(saved, fresh_cache)
    checkout()
    real = extract._parse_guarded
    parsed = []
    monkeypatch.setattr(extract, "_parse_guarded", lambda *args: parsed.append(1) or real(*args))
    assert run() == first and parsed == []
    files["include/local.h"] = '#define TOPIC "talk"\n'  # a pull request changes a header
    checkout()
    assert run() == (["talk"], ["cpp-compile"]) and parsed == [1]
