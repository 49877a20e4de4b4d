"""Namespace facts: the namespace and last segment of every resolved name, the namespace of every
node, and the scope of every parameter (the node whose private namespace holds it, or global)."""

from __future__ import annotations

from archlog.facts.schema import RELATIONS
from archlog.facts.store import FactStore
from archlog.names import namespace_of

ADDED = ("node_namespace", "name_namespace", "name_leaf", "param_scope")
_PARAMS = ("param", "param_read", "param_write")


def add_namespaces(store: FactStore) -> None:
    """node_namespace, name_namespace, name_leaf and param_scope rows for the names already in `store`."""
    used: set[str] = set()
    for relation in (r for r in RELATIONS if r.name not in ADDED):
        for index in (i for i, c in enumerate(relation.columns) if c.type == "name"):
            used.update(c for row in store.rows(relation.name) if isinstance(c := row[index], str) and c[:1] == "/")
    for name in sorted(used - {"/"}):
        store.add("name_namespace", name, namespace_of(name))
        store.add("name_leaf", name, name.rsplit("/", 1)[-1])
    nodes = {str(row[0]) for row in store.rows("node")}
    for node in sorted(nodes):
        store.add("node_namespace", node, namespace_of(node))
    params = {c for rel in _PARAMS for row in store.rows(rel)
              if isinstance(c := row[0 if rel == "param" else 2], str) and c[:1] == "/"}
    for param in sorted(params):
        store.add("param_scope", param, _owner(param, nodes))


def _owner(param: str, nodes: set[str]) -> str:
    """The node whose private namespace (~) holds `param` (the innermost one), or "global"."""
    namespace = namespace_of(param)
    while namespace != "/":
        if namespace in nodes:
            return namespace
        namespace = namespace_of(namespace)
    return "global"
