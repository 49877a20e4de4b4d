"""Hostile inputs that grow with a size (tests/support/hostile_classes.py): each class is read in
time that grows no faster than the input, or grows until the budget stops it with a
`budget-exceeded` diagnostic at the file:line that crossed it, the rest still read."""

from __future__ import annotations

import resource
import time
from collections.abc import Callable
from pathlib import Path

import pytest
from support import hostile_classes as hostile

from archlog import budget
from archlog.analysis import analyse
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.ros1 import LaunchInterpreter
from archlog.extract.workspace.cmake import commands
from archlog.extract.workspace.index import Workspace
from archlog.facts.similarity import near_names
from archlog.rules.engine import Engine
from archlog.rules.ruleset import load_rules


def _cmake(files: hostile.Files) -> str:
    return files["demo/CMakeLists.txt"]


@pytest.mark.parametrize("generate", [hostile.cmake_brackets, hostile.cmake_bracket_comments])
def test_brackets_that_never_close_are_read_in_linear_time(generate: Callable[[int], hostile.Files]) -> None:
    seconds = {}
    for count in (2_000, 20_000, 100_000):
        begin = time.process_time()
        found = commands(_cmake(generate(count)))
        seconds[count] = time.process_time() - begin
        assert [c.name for c in found].count("set") == count  # each opener read as CMake's reader would
    assert seconds[100_000] < 5.0 and seconds[100_000] < 200 * max(seconds[2_000], 0.01), seconds


def test_bracket_levels_that_never_close_stop_at_the_character_budget() -> None:
    """Openers of ever more `=`, none closed: each level is searched for once, and the searches are
    paid for; more levels than the budget pays for stop at the line of the opener that crossed it."""
    crossed: list[int] = []
    for levels in (10, 100, 1_000):
        text = "project(demo)\n" + "".join(f"set(A{k} [{'=' * k}[x)\n" for k in range(1, levels + 1))
        with budget.active({"characters": 1_000_000}):
            found = commands(text, on_budget=lambda line, _message: crossed.append(line))
        if crossed:
            break
        assert len(found) == levels + 1
    assert levels == 1_000 and crossed and 2 <= crossed[0] <= levels + 1 and len(found) < levels + 1


def test_a_folder_adding_itself_is_read_once(tmp_path: Path) -> None:
    hostile.write(tmp_path, hostile.cmake_self_subdirectory(10))
    sink = DiagnosticSink()
    begin = time.process_time()
    workspace = Workspace([tmp_path], sink)
    assert time.process_time() - begin < 2.0
    assert workspace.executable("demo", "node") is not None
    lines = {d.line for d in sink.items if d.code == "cmake-subdirectory"}
    assert lines == set(range(5, 15)), lines  # every add_subdirectory(.) of the file, each skipped


def _launch(root: Path, files: hostile.Files, limits: dict[str, int]) -> tuple[int, list[tuple[str, int]]]:
    """The node count and the budget-exceeded diagnostics of the workspace's launch file."""
    hostile.write(root, files)
    sink = DiagnosticSink()
    with budget.active(limits):
        config = LaunchInterpreter(Workspace([root], sink), sink).load([root / hostile.launch_of(files)], {})
    return len(config.nodes), [(Path(d.file).name, d.line) for d in sink.items if d.code == "budget-exceeded"]


def test_a_python_dag_of_actions_grows_until_the_node_budget_stops_it(tmp_path: Path) -> None:
    for levels in range(2, 41, 3):
        count, crossed = _launch(tmp_path / str(levels), hostile.python_dag(levels), {"nodes": 1_000})
        if 2 ** levels <= 1_000:
            assert (count, crossed) == (2 ** levels, [])
        else:
            assert count == 1_000 and crossed == [("demo.launch.py", 7)]  # the Node action that crossed
            break
    assert levels == 11


def test_remapped_nodes_grow_until_the_node_budget_stops_them(tmp_path: Path) -> None:
    for nodes in (100, 400, 1_600):
        count, crossed = _launch(tmp_path / str(nodes), hostile.ros1_remapped(nodes), {"nodes": 1_000})
        if nodes <= 1_000:
            assert (count, crossed) == (nodes, [])
    assert count == 1_000 and crossed == [("demo.launch", 2 + 4 * 1_000)]  # the first node past the limit


def test_remapped_nodes_whose_topics_dangle_are_analysed_in_linear_time(tmp_path: Path) -> None:
    """Nodes each publishing and hearing a name of its own, all of one type: AL103 pairs dangling
    ends only on a key they share (a generic type's ends must end alike), AL104 only with heard
    topics, and the near-miss groups are each looked up alone; 3,000 such nodes took 64 s CPU when
    every publisher was joined with every subscriber."""
    seconds = {}
    for nodes in (300, 3_000):
        root = tmp_path / str(nodes)
        files = hostile.ros1_remapped_dangling(nodes)
        hostile.write(root, files)
        before = _cpu()
        analysis = analyse([root], [str(root / hostile.launch_of(files))], {}, [])
        _ctl, findings = Engine(load_rules([])).run(analysis.store)
        seconds[nodes] = _cpu() - before
        assert analysis.store.count("node") == nodes and findings == []
    assert seconds[3_000] < 15.0 and seconds[3_000] < 25 * seconds[300], seconds


def test_near_names_of_many_numbered_instances_take_linear_time() -> None:
    """Names of one node per namespace (two numbered segments each, all distinct): words of different
    numbers are never near, so they are never compared."""
    seconds = {}
    for count in (500, 5_000):
        names = [f"/s{i}/n{i}/chatter" for i in range(count)] + [f"/out/c{i}" for i in range(count)]
        begin = time.process_time()
        assert near_names(names, names) == []
        seconds[count] = time.process_time() - begin
    assert seconds[5_000] < 5.0, seconds


def test_an_xml_include_fan_grows_until_the_node_budget_stops_it(tmp_path: Path) -> None:
    """Each file including the next twice: 2**levels nodes, until the node budget stops them at the
    include that crossed it (the rest of the run is linear in the nodes: AL301 pairs each later
    node with the first of its name only)."""
    for levels in range(2, 31, 4):
        count, crossed = _launch(tmp_path / str(levels), hostile.xml_include_fan(levels), {"nodes": 1_000})
        if 2 ** levels <= 1_000:
            assert (count, crossed) == (2 ** levels, [])
        else:
            assert count == 1_000 and crossed == [(f"l{levels}.launch.xml", 2)]  # the node that crossed
            break
    assert levels == 10


def test_concatenated_alternatives_grow_until_the_budget_stops_them(tmp_path: Path) -> None:
    """A C++ topic added together from parts of six values each: one part is six names; from two
    parts on (36 combinations, more than one value's 16 alternatives) the port is a budget-exceeded
    diagnostic at the call, and the file's other publisher is still read."""
    for parts in (1, 2, 12):
        root = tmp_path / str(parts)
        files = hostile.cpp_concatenation(parts)
        hostile.write(root, files)
        before = _cpu()
        analysis = analyse([root], [str(root / hostile.launch_of(files))], {}, [])
        seconds = _cpu() - before
        crossed = [(Path(d.file).name, d.line) for d in analysis.diagnostics.items if d.code == "budget-exceeded"]
        names = {str(row[2]) for row in analysis.store.rows("publisher")}
        assert "/honest" in names
        call = 7 + 6 * parts + 1  # the create_publisher line
        assert crossed == ([] if parts == 1 else [("talker.cpp", call)]), (parts, crossed)
        assert seconds < 10.0, (parts, seconds)


def _cpu() -> float:
    """CPU seconds of this process and of its children that ended (the C++ workers)."""
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime
