"""Extraction on CodeQL-style fixtures, compared with their .expected files: rospy/rclpy in
corpus/python (and, in corpus/python_packages, a ROS package folder each: its one script, read with
the package's modules it calls), roscpp in corpus/cpp_ros1, rclcpp in corpus/cpp_ros2 (a file registering a
component, or exporting a nodelet, is read as that class: only it is the node), and executables
of several roscpp files in corpus/cpp_ros1_files (a folder each, its files read together as one
executable, or as the first class its files export in name order).

`pytest --update-goldens` rewrites the .expected files that differ (then review the diff)."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import pytest
from conftest import ROOT
from support.describe import describe
from support.goldens import compare_text

from archlog.diagnostics import DiagnosticSink
from archlog.extract.cpp.extract import CppEnvironment, extract_cpp
from archlog.extract.python.node import extract_python
from archlog.extract.summary import NodeSummary
from archlog.extract.workspace.executables import exported_plugins, registered_components

FOLDERS = ("python", "python_packages", "cpp_ros1", "cpp_ros2", "cpp_ros1_files")
FIXTURES = sorted(p for folder in FOLDERS for p in (ROOT / "corpus" / folder).iterdir() if p.suffix != ".expected")


@lru_cache(maxsize=1)
def cpp_environment() -> CppEnvironment:
    return CppEnvironment([], None, [])


def extract(fixture: Path, sink: DiagnosticSink) -> NodeSummary:
    if fixture.parent.name == "python_packages":
        script = next((fixture / "scripts").iterdir())
        return extract_python(script, "fixtures", script.name, script.relative_to(fixture).as_posix(), sink,
                              lambda path: path.relative_to(fixture).as_posix())
    if fixture.suffix == ".cpp" or fixture.is_dir():
        linked = sorted(fixture.glob("lib/*.cpp")) if fixture.is_dir() else []
        files = (sorted(fixture.glob("*.cpp")) if fixture.is_dir() else [fixture]) + linked
        classes = [c for f in files for c in [c for c, _line in registered_components(f.read_text())]
                   + exported_plugins(f)]
        shown = {f: f"{fixture.name}/{f.relative_to(fixture)}" if fixture.is_dir() else f.name for f in files}
        return extract_cpp(files, "fixtures", fixture.name, cpp_environment(), shown, sink,
                           classes[0] if classes else None, linked)
    return extract_python(fixture, "fixtures", fixture.name, fixture.name, sink)


def test_enough_fixtures() -> None:
    names = [p.name for p in FIXTURES]
    assert sum(n.startswith("rclpy_") for n in names) >= 10
    assert sum(n.startswith("rospy_") for n in names) >= 4
    assert sum(n.startswith("rclcpp_") for n in names) >= 10
    assert sum(n.startswith("roscpp_") for n in names) >= 6


@pytest.mark.parametrize("fixture", FIXTURES, ids=lambda p: p.name)
def test_fixture_matches_expected(fixture: Path, update_goldens: bool) -> None:
    sink = DiagnosticSink()
    got = describe(extract(fixture, sink), sink.items)
    diff = compare_text(fixture.with_name(fixture.name + ".expected"), got, update_goldens)
    assert not diff, diff
