"""Property: on random nested launch trees (groups, includes, args, remaps, params) archlog and
roslaunch agree: both reject the tree, or both load the same nodes, remaps and parameters."""

from __future__ import annotations

import tempfile
from pathlib import Path
from xml.sax.saxutils import quoteattr

from conftest import ROOT, requires_ros
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from support.launch_oracle import archlog_view, roslaunch_view

pytestmark = requires_ros()

NAMES = st.sampled_from(["a", "b", "cam", "base"])
TOPICS = st.sampled_from(["scan", "odom", "/cmd_vel", "~out", "ns/in"])
VALUES = st.sampled_from(["1", "2.5", "true", "x", "1_0", " 7 ", "[1, 2]"])
ARGS = ["robot", "rate", "flag"]


def attr(**values: str) -> str:
    return " ".join(f"{k.rstrip('_')}={quoteattr(v)}" for k, v in values.items())


@st.composite
def value_text(draw) -> str:
    """A plain value, or one built from an arg (which may be undeclared: both sides must reject)."""
    if draw(st.booleans()):
        return draw(VALUES)
    return f"$(arg {draw(st.sampled_from(ARGS))})" + draw(st.sampled_from(["", "_x"]))


@st.composite
def element(draw, depth: int, includes: list[str]) -> str:
    kinds = ["node"] * 4 + ["remap", "remap", "arg", "param"] + (["group", "group", "include"] if depth < 3 else [])
    kind = draw(st.sampled_from(kinds))
    if kind == "node":
        inner = "".join(draw(st.lists(st.one_of(
            TOPICS.flatmap(lambda t: TOPICS.map(lambda u: f"<remap {attr(from_=t, to=u)}/>")),
            st.tuples(NAMES, value_text()).map(lambda p: f"<param {attr(name=p[0], value=p[1])}/>")), max_size=2)))
        extra = draw(st.sampled_from(["", ' ns="sub"', ' args="scan:=/s _gain:=3"', ' args="__name:=renamed"']))
        return f'<node pkg="demo" type="t" name="{draw(NAMES)}"{extra}>{inner}</node>'
    if kind == "remap":
        return f"<remap {attr(from_=draw(TOPICS), to=draw(TOPICS))}/>"
    if kind == "arg":
        key = draw(st.sampled_from(["default", "value"]))
        return f"<arg {attr(name=draw(st.sampled_from(ARGS + ['local'])), **{key: draw(VALUES)})}/>"
    if kind == "param":
        return f"<param {attr(name=draw(st.sampled_from(['p', '~priv', 'g/q'])), value=draw(value_text()))}/>"
    children = "".join(draw(st.lists(element(depth + 1, includes), min_size=1, max_size=4)))
    if kind == "group":
        ns = draw(st.sampled_from(["", ' ns="g1"', ' ns="/abs"', ' ns="$(arg robot)"']))
        cond = draw(st.sampled_from(["", ' if="$(arg flag)"', ' unless="false"']))
        return f"<group{ns}{cond}>{children}</group>"
    name = f"inc{len(includes)}.launch"
    includes.append(f"<launch>{draw(declarations())}{children}</launch>")
    passed = "".join(f"<arg {attr(name=a, value=draw(VALUES))}/>" for a in draw(st.sets(st.sampled_from(ARGS))))
    mode = draw(st.sampled_from(["", ' pass_all_args="true"', ' ns="inc"']))
    return f'<include file="$(dirname)/{name}"{mode}>{passed}</include>'


@st.composite
def declarations(draw) -> str:
    """Arg declarations at the top of a file; usually all of them, with defaults."""
    declared = draw(st.sampled_from([ARGS, ARGS, ARGS, ARGS[:2], []]))
    return "".join(f"<arg {attr(name=a, default=draw(st.sampled_from(['r1', '5', 'true', 'false'])))}/>"
                   for a in declared)


@st.composite
def launch_tree(draw) -> tuple[str, list[str], dict[str, str]]:
    includes: list[str] = []
    body = draw(declarations()) + "".join(draw(st.lists(element(0, includes), min_size=2, max_size=6)))
    cli = {a: draw(VALUES) for a in draw(st.sets(st.sampled_from(ARGS)))}
    return f"<launch>{body}</launch>", includes, cli


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(launch_tree())
def test_random_launch_trees_agree_with_roslaunch(tree: tuple[str, list[str], dict[str, str]]) -> None:
    main, includes, cli = tree
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        (folder / "main.launch").write_text(main)
        for index, text in enumerate(includes):
            (folder / f"inc{index}.launch").write_text(text)
        packages = [folder, ROOT / "corpus" / "launch" / "_pkgs"]
        theirs = roslaunch_view([folder / "main.launch"], cli, packages)
        ours = archlog_view([folder / "main.launch"], cli, packages)
    if theirs.error:
        assert ours.error, f"roslaunch rejects ({theirs.error}) but archlog does not:\n{main}\n{includes}"
        return
    assert ours.error is None, (ours.diagnostics, main, includes)
    assert ours.nodes == theirs.nodes, (main, includes, cli)
    assert ours.params == theirs.params, (main, includes, cli)
