"""ROS graph name resolution, as roscpp's ros::names and rospy's rosgraph.names do it."""

from __future__ import annotations

from collections.abc import Mapping


def canonical(name: str) -> str:
    """Collapse repeated slashes and drop a trailing slash (but keep the root '/')."""
    parts = [p for p in name.split("/") if p]
    prefix = "/" if name.startswith("/") else ""
    return prefix + "/".join(parts) if parts else prefix


def join(namespace: str, name: str) -> str:
    """Join a namespace and a relative name; a global name ignores the namespace."""
    if name.startswith("/"):
        return canonical(name)
    return canonical(f"{namespace or '/'}/{name}" if name else namespace or "/")


def namespace_of(name: str) -> str:
    """The namespace a resolved node name lives in: '/a/b' -> '/a', '/b' -> '/'."""
    head = canonical(name).rsplit("/", 1)[0]
    return head or "/"


def resolve(name: str, namespace: str, node_name: str) -> str:
    """Resolve a graph name for a node named `node_name` in `namespace` (no remapping)."""
    if name.startswith("~"):
        return join(node_name, name[1:].lstrip("/"))
    return join(namespace, name)


def remap(resolved: str, remaps: Mapping[str, str]) -> str:
    """Apply resolved remappings to a resolved name (exact match, as ROS does)."""
    return remaps.get(resolved, resolved)


def resolve_remaps(pairs: list[tuple[str, str]], namespace: str, node_name: str) -> dict[str, str]:
    """Resolve `from:=to` pairs in the node's context; later pairs override earlier ones."""
    return {resolve(src, namespace, node_name): resolve(dst, namespace, node_name) for src, dst in pairs}


def is_valid(name: str) -> bool:
    """A legal ROS 1 graph name: [~/]?[A-Za-z][\\w]*(/[A-Za-z_][\\w]*)* (roslib's rules)."""
    body = name[1:] if name[:1] in "~/" else name
    if not body:
        return name == "/"
    segments = body.split("/")
    if not segments[0][:1].isalpha() and not (name[:1] in "~/" and segments[0][:1] == "_"):
        return False
    return all(s and (s[0].isalpha() or s[0] == "_") and s.replace("_", "").isalnum() for s in segments)
