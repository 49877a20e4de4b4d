"""Parameter facts: what a node's declarations say (type, required, read-only, bounds, choices), which node a
configured parameter is for and the type of its value, the nodes whose parameters are dynamic, and the
declared names near a configured one that nothing declares."""

from __future__ import annotations

from archlog.extract.summary import ParamSpec
from archlog.facts.similarity import distance
from archlog.facts.store import FactStore
from archlog.system.link import System

_SCALAR_TYPES: tuple[tuple[type, str], ...] = ((bool, "bool"), (int, "integer"), (float, "double"), (str, "string"))


def add_param_spec(store: FactStore, port: str, spec: ParamSpec) -> None:
    """The facts of one declaration (a param_read port)."""
    if spec.type:
        store.add("param_type", port, spec.type)
    if spec.required:
        store.add("param_required", port)
    if spec.read_only:
        store.add("param_read_only", port)
    for op, bound in spec.bounds:
        store.add("param_bound", port, op, bound)
    for choice in spec.choices:
        store.add("param_choice", port, choice)


def value_type(value: object) -> str:
    """The ROS 2 parameter type of a configured value; "" when it has none (a mapping, an empty or mixed list)."""
    scalar = next((name for kind, name in _SCALAR_TYPES if type(value) is kind), "")
    if scalar or not isinstance(value, list) or not value:
        return scalar
    kinds = {value_type(item) for item in value}
    return f"{kinds.pop()}_array" if len(kinds) == 1 and kinds <= {"bool", "integer", "double", "string"} else ""


def add_parameters(store: FactStore, system: System) -> None:
    """param_of, param_value_type and params_dynamic facts of a linked system."""
    owners = _owners_by_prefix({i.launch.name for i in system.instances})
    for name, (value, _elem) in system.config.params.items():
        if (kind := value_type(value)) != "":
            store.add("param_value_type", name, kind)
        owner = _owner(name, owners)
        if owner is not None:
            store.add("param_of", name, owner, name[len(owner.rstrip("/")) + 1:])
    for elem, why in system.config.params_unknown:
        store.add("param_set_unknown", elem.id, why)
        store.locate(elem.id, elem.file, elem.line)
    for instance in system.instances:
        if instance.summary is not None and instance.summary.params_dynamic:
            store.add("params_dynamic", instance.launch.name, instance.summary.params_dynamic)


def _owners_by_prefix(nodes: set[str]) -> dict[str, str]:
    """Each node name by the prefix a parameter of it starts with (the name without trailing slashes, then one)."""
    owners: dict[str, str] = {}
    for node in sorted(nodes, key=len):  # of two names with one prefix, the longer wins, as in _owner
        owners[node.rstrip("/") + "/"] = node
    return owners


def _owner(name: str, owners: dict[str, str]) -> str | None:
    """The innermost (longest) node name whose prefix the parameter name starts with."""
    found = [owners[name[:end + 1]] for end, char in enumerate(name) if char == "/" and name[:end + 1] in owners]
    return max(found, key=len, default=None)


def add_param_near(store: FactStore, threshold: float) -> None:
    """param_near facts: for a parameter the configuration sets for a node that neither declares nor reads it
    (nor a namespace above it), the node's parameter names within the near-miss threshold. Only nodes whose
    parameter names are all known (no unknown name, not dynamic) are compared."""
    reads: dict[str, set[str]] = {}
    unsure = {str(row[0]) for row in store.rows("params_dynamic")}
    for _port, node, name, _default in store.rows("param_read"):
        if isinstance(name, str):
            reads.setdefault(str(node), set()).add(name)
        else:
            unsure.add(str(node))
    for param, node, _local in store.rows("param_of"):
        param, node = str(param), str(node)
        known = reads.get(node, set())
        if node in unsure or any(param == read or param.startswith(read.rstrip("/") + "/") for read in known):
            continue
        for read in sorted(known):
            if (score := distance(param, read)) < threshold:
                store.add("param_near", param, read, round(score * 1000))
