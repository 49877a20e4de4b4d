"""ROS name resolution as roscpp/rospy do it."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from archlog import names


def test_resolve_relative_global_private() -> None:
    assert names.resolve("scan", "/robot1", "/robot1/laser") == "/robot1/scan"
    assert names.resolve("/scan", "/robot1", "/robot1/laser") == "/scan"
    assert names.resolve("~scan", "/robot1", "/robot1/laser") == "/robot1/laser/scan"
    assert names.resolve("a/b", "/", "/n") == "/a/b"


def test_remaps_resolve_in_node_context_and_later_wins() -> None:
    remaps = names.resolve_remaps([("scan", "base_scan"), ("~out", "/x"), ("scan", "/front/scan")], "/r", "/r/n")
    assert remaps == {"/r/scan": "/front/scan", "/r/n/out": "/x"}
    assert names.remap("/r/scan", remaps) == "/front/scan"
    assert names.remap("/r/other", remaps) == "/r/other"


def test_validity() -> None:
    assert names.is_valid("/a/b_c") and names.is_valid("~private") and names.is_valid("rel")
    assert not names.is_valid("1abc") and not names.is_valid("/a//b") and not names.is_valid("a-b")


segment = st.from_regex(r"[a-z][a-z0-9_]{0,5}", fullmatch=True)


@given(st.lists(segment, min_size=1, max_size=4), st.lists(segment, max_size=3))
def test_join_is_canonical_and_associative(ns: list[str], rel: list[str]) -> None:
    namespace = "/" + "/".join(ns)
    joined = names.join(namespace, "/".join(rel))
    assert joined.startswith("/") and "//" not in joined and (joined == "/" or not joined.endswith("/"))
    assert names.join(names.join("/", ns[0]), "/".join(ns[1:] + rel)) == joined
    assert names.namespace_of(names.join(namespace, "leaf")) == namespace
